"""A sweep's results (docs/guide/sweeps.md): sweep.csv joined with each
case's summary.json into one table, and its speed against its error."""
import csv
import json
import math
import os
import tomllib

import numpy as np

from .tables import columns_of, make_table

# sweep.csv's columns after the varied keys, before the error norms.
_RUN_COLUMNS = ("status", "particles", "steps", "wall_seconds", "particle_steps_per_second", "rank")


def sweep_directory(sweep_file):
    """Where `flowmpm sweep SWEEP_FILE` writes without --output: the sweep
    file's `output`, else results/sweeps/<its stem> (relative to the
    working directory)."""
    with open(sweep_file, "rb") as f:
        named = tomllib.load(f).get("output")
    return named or os.path.join("results", "sweeps", os.path.splitext(os.path.basename(sweep_file))[0])


def _summary_columns(summary):
    """summary.json's values as flat columns: its numbers and strings by
    name, `errors.<norm>`, `measures.<name>`, and per body
    `<body>.stress_xx` ... and `<body>.strain_xx` ... (timeseries.csv's names)."""
    flat = {}
    for key, value in summary.items():
        if isinstance(value, dict):
            for name, v in value.items():
                flat[f"{key}.{name}"] = v
        elif key == "bodies":
            for body in value:
                for what in ("stress", "strain"):
                    for component, v in body.get(f"mean_{what}", {}).items():
                        flat[f"{body['name']}.{what}_{component}"] = v
        else:
            flat[key] = value
    return flat


def pareto_front(seconds, error):
    """The indices of the points no other point beats in both time and
    error (the fastest first): each is more accurate than every faster one."""
    order = sorted(range(len(seconds)), key=lambda i: (seconds[i], error[i]))
    front, best = [], math.inf
    for i in order:
        if error[i] < best:
            front.append(i)
            best = error[i]
    return front


class Sweep:
    """The results of a sweep: its output directory holds sweep.csv and
    cases/NNN/. Attributes: `directory`; `keys` (the varied keys);
    `errors` (the error norms' columns); `table`: one row per case, the
    columns of sweep.csv (`case` as its folder's name, the varied keys,
    status, particles, steps, wall_seconds in s, particle_steps_per_second,
    the error norms, message) then those of the case's summary.json that
    sweep.csv lacks (see _summary_columns); a pandas DataFrame, or a numpy
    structured array without pandas."""

    def __init__(self, path, use_pandas=None):
        """`path`: the sweep's output directory, or its sweep file (the
        directory it names)."""
        path = os.fspath(path)
        self.directory = sweep_directory(path) if path.endswith(".toml") else path
        with open(os.path.join(self.directory, "sweep.csv"), newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        header = rows[0]
        first_run_column = header.index("status")
        self.keys = header[1:first_run_column]
        self.errors = [c for c in header[first_run_column:-1] if c not in _RUN_COLUMNS]
        columns = {name: [row[i] if i < len(row) else "" for row in rows[1:]] for i, name in enumerate(header)}
        summaries = []
        for case in columns["case"]:
            try:
                with open(os.path.join(self.directory, "cases", case, "summary.json"), encoding="utf-8") as f:
                    summaries.append(_summary_columns(json.load(f)))
            except FileNotFoundError:
                summaries.append({})  # a case that failed before it wrote one
        for summary in summaries:
            for name in summary:
                if name not in columns:
                    columns[name] = [s.get(name) for s in summaries]
        self.table = make_table(columns, use_pandas, text=("case", "message") + tuple(self.keys))

    def column(self, name):
        """One column of the table as a numpy array."""
        if name not in columns_of(self.table):
            raise KeyError(f"no column {name!r}; the columns are {', '.join(columns_of(self.table))}")
        return np.asarray(self.table[name])

    def plot_speed_vs_error(self, error=None, ax=None, path=None):
        """Draws each completed case's error (the column `error`: an error
        norm; default the sweep's only one) against its wall time (the step
        loop, s), log-log, labelled by its varied keys, and the Pareto front:
        the cases no other case beats in both. Returns the matplotlib Axes;
        with `path`, also saves the figure there. Needs matplotlib (Debian's
        python3-matplotlib)."""
        try:
            import matplotlib.pyplot as plt
        except ImportError:
            raise ImportError("plot_speed_vs_error needs matplotlib (Debian's python3-matplotlib)") from None
        if error is None:
            if len(self.errors) != 1:
                raise ValueError(f"name the error column: the sweep has {self.errors or 'no error norms'}")
            error = self.errors[0]
        status = self.column("status")
        seconds = self.column("wall_seconds").astype(float)
        values = self.column(error).astype(float)
        shown = [i for i in range(len(status))
                 if status[i] == "completed" and seconds[i] > 0 and values[i] > 0 and math.isfinite(values[i])]
        if not shown:
            raise ValueError(f"no completed case with a positive {error!r} to plot")
        if ax is None:
            ax = plt.figure(figsize=(6.4, 4.8)).gca()
        x, y = seconds[shown], values[shown]
        ax.loglog(x, y, "o", color="0.6", label="cases")
        for xi, yi, i in zip(x, y, shown):
            label = ", ".join(f"{self.column(k)[i]}" for k in self.keys)
            ax.annotate(label, (xi, yi), textcoords="offset points", xytext=(4, 4), fontsize=7)
        front = pareto_front(list(x), list(y))
        ax.loglog(x[front], y[front], "o-", color="C0", drawstyle="steps-post", label="Pareto front")
        ax.set_xlabel("wall time of the step loop (s)")
        ax.set_ylabel(f"error: {error}")
        ax.set_title(", ".join(self.keys) if self.keys else os.path.basename(self.directory))
        ax.legend()
        if path is not None:
            ax.figure.savefig(path, dpi=100, bbox_inches="tight")
        return ax

    def __repr__(self):
        return f"<flowmpm.Sweep {self.directory}: {len(self.column('case'))} cases, varied {self.keys}>"
