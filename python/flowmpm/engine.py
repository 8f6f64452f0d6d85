"""Running the engine: check a case, run it, run a sweep.

The program is the one the environment variable FLOWMPM names, else
build/flowmpm of this checkout, else flowmpm on PATH. Its log shows as it
runs (progress every 5 s) when the session is interactive (a terminal, the
Python prompt, Jupyter); otherwise it runs with --quiet and run.log keeps
the log.
"""
import copy
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import warnings
from pathlib import Path

from .case import Case
from .errors import CaseError, SimulationError
from .results import Results
from .sweep import Sweep, sweep_directory

# spdlog's pattern in apps/flowmpm.cpp: "[14:16:34.123] error message".
_LOG_LINE = re.compile(r"\[\d\d:\d\d:\d\d\.\d{3}\] (\w+) (.*)")


def program():
    """The flowmpm program: build/flowmpm of this checkout, else $FLOWMPM,
    else flowmpm on PATH. Raises FileNotFoundError saying where it looked."""
    built = Path(__file__).resolve().parents[2] / "build" / "flowmpm"
    if os.access(built, os.X_OK):
        return str(built)
    named = os.environ.get("FLOWMPM")
    if named:
        if not os.access(named, os.X_OK):
            raise FileNotFoundError(f"FLOWMPM={named}: not an executable file")
        return named
    on_path = shutil.which("flowmpm")
    if on_path:
        return on_path
    raise FileNotFoundError(f"no flowmpm program: {built} is not built (scripts/setup.sh builds it), FLOWMPM is "
                            "not set and none is on PATH")


def interactive():
    """Whether a person is watching: a terminal, the Python prompt or Jupyter."""
    return sys.stderr.isatty() or hasattr(sys, "ps1") or "ipykernel" in sys.modules


def _execute(arguments, show):
    """Runs the program; returns its exit status and its error messages.
    With `show`, its log is copied to stderr as it comes."""
    errors = []
    with subprocess.Popen([program()] + arguments, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          errors="replace") as process:
        try:
            for line in process.stderr:
                if show:
                    sys.stderr.write(line)
                    sys.stderr.flush()
                m = _LOG_LINE.match(line.rstrip("\n"))
                if m:
                    if m.group(1) in ("error", "critical"):
                        errors.append(m.group(2))
                elif line.strip():  # the command line's complaints, "flowmpm: ..."
                    errors.append(line.strip().removeprefix("flowmpm: "))
            status = process.wait()
        except KeyboardInterrupt:
            # The run stops after its step and keeps a checkpoint, as on Ctrl-C.
            process.send_signal(signal.SIGINT)
            process.wait()
            raise
    return status, errors


def _launch(arguments, progress, **options):
    """_execute with the options given (`threads=2`: --threads 2), and
    --quiet unless the log is shown (`progress`, default: interactive)."""
    show = interactive() if progress is None else progress
    for name, value in options.items():
        if value:
            arguments += [f"--{name}", str(value)]
    return _execute(arguments + ([] if show else ["--quiet"]), show)


def _case_of(case_or_path):
    if isinstance(case_or_path, Case):
        return copy.deepcopy(case_or_path)
    return Case.load(case_or_path)


def _with_sets(case, values):
    for key, value in (values or {}).items():
        case.set(key, value)
    return case


def _raise_case_error(errors, case_file):
    text = errors[0] if errors else "flowmpm stopped with exit status 1 and no message"
    raise CaseError.from_engine(text, case_file)


def check(case_or_path, set=None):
    """Validates a case as `flowmpm check` does (every check a run makes
    before it writes anything), with the `set` values ({key: value}) set.
    Returns None; raises CaseError with the engine's file, line, key and
    message."""
    case = _with_sets(_case_of(case_or_path), set)
    with tempfile.TemporaryDirectory() as scratch:
        if case.path is None:
            case.save(os.path.join(scratch, f"{case.name}.toml"))
        status, errors = _execute(["check", case.path] + case.set_options(), show=False)
        if status != 0:
            _raise_case_error(errors, case.path)


def output_directory(case):
    """Where a run of `case` writes without --output: output.directory, or
    results/<name> (relative to the working directory)."""
    return case.get("output.directory", os.path.join("results", case.name))


def run(case_or_path, output=None, threads=None, set=None, restart=None, progress=None):
    """Runs a case (a Case or a case file) and returns its Results.

    output: the output directory (default output.directory, or
    results/<name>); threads: worker threads (default all cores; results do
    not depend on it); set: {key: value} set for this run only, as --set;
    restart: an output directory whose checkpoint the run continues
    (instead of output); progress: show the engine's log (default: when
    the session is interactive). A case made in Python (no file) is first
    saved as case.toml in the output directory.

    Raises CaseError for a case the engine rejects (nothing is run) and
    SimulationError for a run that fails or is interrupted."""
    if output is not None and restart is not None:
        raise ValueError("run: give output or restart, not both (a restart writes into the directory it continues)")
    case = _with_sets(_case_of(case_or_path), set)
    directory = os.fspath(restart or output or output_directory(case))
    if case.path is None:
        os.makedirs(directory, exist_ok=True)
        case.save(os.path.join(directory, "case.toml"))
    arguments = ["run", case.path] + case.set_options()
    arguments += ["--restart", directory] if restart else ["--output", directory]
    status, errors = _launch(arguments, progress, threads=threads)
    if status == 1:
        _raise_case_error(errors, case.path)
    if status != 0:
        message = "; ".join(errors) or _ended(status, directory)
        raise SimulationError(message, status=status, output=directory)
    return Results(directory)


def _ended(status, directory):
    """How a run that left no message ended: its signal and summary.json's status."""
    how = f"killed by signal {-status}" if status < 0 else f"exit status {status}"
    try:
        with open(os.path.join(directory, "summary.json"), encoding="utf-8") as f:
            return f"flowmpm ended with {how}; summary.json says {json.load(f).get('status')!r}"
    except (OSError, ValueError):
        return f"flowmpm ended with {how}; see {os.path.join(directory, 'run.log')}"


def sweep(sweep_file, output=None, jobs=None, threads=None, progress=None):
    """Runs a sweep file as `flowmpm sweep` (cases already completed are
    skipped) and returns its Sweep. A case that failed is a row with status
    `failed` and its message (and a warning); a bad sweep file raises
    CaseError."""
    sweep_file = os.fspath(sweep_file)
    if output is None:
        output = sweep_directory(sweep_file)
    status, errors = _launch(["sweep", sweep_file, "--output", os.fspath(output)], progress, jobs=jobs,
                                threads=threads)
    if status == 1:
        _raise_case_error(errors, sweep_file)
    if status == 130:
        raise SimulationError("; ".join(errors) or "the sweep was interrupted", status=status, output=output)
    if status != 0:
        warnings.warn("; ".join(errors) or f"flowmpm sweep ended with status {status}", stacklevel=2)
    return Sweep(output)
