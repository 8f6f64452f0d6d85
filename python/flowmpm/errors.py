"""The engine's two kinds of failure as Python exceptions.

The engine reports a bad case as one line, `FILE:LINE: KEY: what was
expected, got what` (or `--set KEY=VALUE: KEY: ...` for a value set on the
command line, and Case.set's), exit status 1: CaseError. A run that fails
after it started (a particle leaving the grid, a blow-up, a full disk;
exit status 2) or is interrupted (130): SimulationError.
"""
import re

_KEY = re.compile(r'([A-Za-z0-9_\-\[\]."~]+): (.*)', re.S)


class FlowmpmError(Exception):
    """Any failure the engine reports."""


class CaseError(FlowmpmError, ValueError):
    """A case the engine (or Case.set) rejects. Attributes: `file` and
    `line` (where the value is; None where it is not in a file, e.g. set by
    Case.set), `key` (dotted, as "bodies[0].velocity"; None where the
    message is about no one key), `message` (what was expected and what was
    given) and `text` (the engine's whole message)."""

    def __init__(self, message, file=None, line=None, key=None, text=None):
        self.file, self.line, self.key, self.message = file, line, key, message
        if text is None:
            where = f"{file}:{line}" if file and line else file
            text = ": ".join(str(p) for p in (where, key, message) if p)
        self.text = text
        super().__init__(text)

    @classmethod
    def from_engine(cls, text, case_file):
        """The engine's message about `case_file`, split into its parts."""
        file = line = None
        rest = text
        if text.startswith("--set "):
            _, _, rest = text.partition(": ")
        elif case_file and text.startswith(case_file + ":"):
            file, rest = case_file, text[len(case_file) + 1:]
            m = re.match(r"(\d+): ", rest)
            if m:
                line, rest = int(m.group(1)), rest[m.end():]
            else:
                rest = rest.lstrip()
        m = _KEY.fullmatch(rest)
        key, message = (m.group(1), m.group(2)) if m else (None, rest)
        return cls(message, file=file, line=line, key=key, text=text)


class SimulationError(FlowmpmError, RuntimeError):
    """A run that failed after it started, or was interrupted. Attributes:
    `message` (the engine's), `status` (its exit status: 2 failed, 130
    interrupted) and `output` (the output directory; its run.log says
    more)."""

    def __init__(self, message, status=None, output=None):
        self.message, self.status, self.output = message, status, output
        super().__init__(message)
