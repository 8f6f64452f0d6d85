"""A case file: read, look up and change keys as `--set` does, write.

Keys are those of `flowmpm run --set KEY=VALUE` (io/case/overrides.cpp):
dotted ("analysis.dt"), with array entries by index ("bodies.0.velocity",
or "bodies[0].velocity" as the engine's messages name them).
"""
import copy
import os
import re
import tomllib

from .errors import CaseError
from .toml_text import document_text, edited_text, value_text


def key_parts(key):
    """The parts of a key as --set splits it: "bodies[0].velocity" and
    "bodies.0.velocity" are both ["bodies", "0", "velocity"]."""
    parts = []
    for part in key.split("."):
        inner = []
        while part.endswith("]") and "[" in part:
            open_ = part.rindex("[")
            inner.insert(0, part[open_ + 1:-1])
            part = part[:open_]
        parts += [part] + inner
    return parts


def _walk(data, key, parts, create):
    """The table or array holding the last part, and the path to it (array
    entries as ints); with `create`, missing tables on the way are made, as
    --set makes them. Raises CaseError naming the key."""
    node, path = data, []
    for part in parts[:-1]:
        if isinstance(node, dict):
            if part not in node:
                if not create:
                    raise KeyError(key)
                node[part] = {}
            node, step = node[part], part
        elif isinstance(node, list):
            if not part.isdigit():
                raise CaseError(f"'{part}' must be an index into an array", key=key)
            if int(part) >= len(node):
                raise CaseError(f"index {part} is out of range ({len(node)} entries)", key=key)
            node, step = node[int(part)], int(part)
        else:
            raise CaseError(f"'{part}' is not a table", key=key)
        path.append(step)
    return node, path


class Case:
    """A case: its keys as nested dicts and lists (what tomllib reads), the
    file it came from, and the keys set since."""

    def __init__(self, data=None, path=None, text=None):
        """A case from a dict (`Case({"analysis": {...}, ...})`), or as
        Case.load makes it."""
        self.data = copy.deepcopy(data) if data is not None else {}
        self.path = os.fspath(path) if path is not None else None
        self._text = text
        self.changes = []  # (key, TOML text of the value), in order, as --set takes them
        self._changed_paths = []

    @classmethod
    def load(cls, path):
        """Reads a case file. Raises CaseError with the file and line where
        it is not valid TOML."""
        with open(path, encoding="utf-8") as f:
            text = f.read()
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as e:
            where = re.search(r" \(at line (\d+), column \d+\)", str(e))  # tomllib's only account of the line
            line = int(where.group(1)) if where else None
            message = str(e).replace(where.group(0), "") if where else str(e)
            raise CaseError(f"not valid TOML: {message}", file=os.fspath(path), line=line) from None
        return cls(data, path, text)

    @property
    def name(self):
        """The run's name: `name`, or the file's stem, as the engine takes it."""
        if "name" in self.data:
            return self.data["name"]
        return os.path.splitext(os.path.basename(self.path))[0] if self.path else "case"

    def __getitem__(self, key):
        """The value at `key`; KeyError where the case does not give it."""
        parts = key_parts(key)
        try:
            node, _ = _walk(self.data, key, parts, create=False)
            return node[int(parts[-1]) if isinstance(node, list) else parts[-1]]
        except (KeyError, IndexError, ValueError, TypeError, CaseError):
            raise KeyError(key) from None

    def __contains__(self, key):
        try:
            self[key]
            return True
        except KeyError:
            return False

    def get(self, key, default=None):
        """The value at `key`, or `default`."""
        try:
            return self[key]
        except KeyError:
            return default

    def set(self, key, value):
        """Sets `key` to `value` (a number, string, boolean, list or dict;
        numpy values too) as `--set KEY=VALUE` would: missing tables on the
        way are made, array entries are addressed by index. Returns the
        case, so that sets chain. The engine checks the value when the case
        is checked or run; a key that cannot be set so raises CaseError."""
        parts = key_parts(key)
        if not key or "=" in key or any(p == "" for p in parts):
            raise CaseError("expected a key such as analysis.dt or bodies.0.velocity", key=key)
        text = value_text(value, key)
        data = copy.deepcopy(self.data)  # unchanged where the key cannot be set
        node, path = _walk(data, key, parts, create=True)
        if not isinstance(node, dict):
            raise CaseError("the key's parent is not a table", key=key)
        # What the engine will read: TOML's value, not Python's (a tuple is an array).
        node[parts[-1]] = tomllib.loads("value = " + text)["value"]
        self.data = data
        self.changes.append((key, text))
        self._changed_paths.append(tuple(path + [parts[-1]]))
        return self

    def text(self):
        """The case as TOML: the file's text with the changes made in place,
        its comments kept (where an edit cannot be made in place, the whole
        case afresh), or for a case made in Python, written afresh."""
        if self._text is None:
            return document_text(self.data)
        return edited_text(self._text, self.data, self._changed_paths)

    def save(self, path):
        """Writes the case to `path` and makes it the case's file. Relative
        paths inside it (particle files) are then taken from its folder."""
        text = self.text()
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        self.path, self._text = os.fspath(path), text
        self.changes, self._changed_paths = [], []
        return self

    def set_options(self):
        """The changes since the case was read, as the engine's --set options."""
        options = []
        for key, text in self.changes:
            options += ["--set", f"{key}={text}"]
        return options

    def __repr__(self):
        where = self.path or "made in Python"
        return f"<flowmpm.Case {self.name!r} ({where}), {len(self.changes)} change(s)>"
