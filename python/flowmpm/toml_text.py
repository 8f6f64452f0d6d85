"""TOML text: values as `--set` takes them, whole documents, and in-place edits.

Reading is Python's tomllib; this module writes. `value_text` gives one
value in TOML's inline syntax; `document_text` a whole case; `edited_text`
changes values inside an existing file's text, keeping its comments and
layout (a case.save after case.set).
"""
import json
import math
import re
import tomllib

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


def key_text(key):
    """A key as TOML writes it: bare where it can be, else quoted."""
    return key if _BARE_KEY.fullmatch(key) else _string_text(key)


def _string_text(text):
    # JSON's escapes are TOML's basic-string escapes; TOML also escapes DEL.
    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007f")


def plain(value):
    """A numpy scalar or array as the Python number or list it holds."""
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        return value.tolist()
    return value


def value_text(value, where="value"):
    """`value` (bool, int, float, str, list, tuple, dict; numpy scalars and
    arrays too) in TOML's inline syntax, e.g. `[154, 9]` or `{ y = 0.0 }`.
    Raises TypeError naming `where` for anything else."""
    value = plain(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return _string_text(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(value_text(v, f"{where}[{i}]") for i, v in enumerate(value)) + "]"
    if isinstance(value, dict):
        if not value:
            return "{}"
        return "{ " + ", ".join(f"{key_text(k)} = {value_text(v, f'{where}.{k}')}" for k, v in value.items()) + " }"
    raise TypeError(f"{where}: expected a number, string, boolean, list or dict, got {type(value).__name__}")


def _is_table_array(value):
    return isinstance(value, list) and bool(value) and all(isinstance(v, dict) for v in value)


def document_text(data):
    """A whole document: each table's plain keys, then its tables as [a.b]
    sections and its arrays of tables as [[a]] entries, whose own tables are
    written inline (`velocity = { y = 0.0 }`)."""
    lines = []

    def table(values, path, header):
        inline = header == "[["
        plain_keys = [k for k, v in values.items() if inline or not (isinstance(v, dict) or _is_table_array(v))]
        if path and (plain_keys or inline or not values):
            name = ".".join(key_text(p) for p in path)
            lines.extend(["", f"[[{name}]]" if inline else f"[{name}]"])
        for k in plain_keys:
            lines.append(f"{key_text(k)} = {value_text(values[k], '.'.join(path + [k]))}")
        if inline:
            return
        for k, v in values.items():
            if isinstance(v, dict):
                table(v, path + [k], "[")
            elif _is_table_array(v):
                for entry in v:
                    table(entry, path + [k], "[[")

    table(data, [], None)
    return "\n".join(lines).lstrip("\n") + "\n"


def _string_end(text, i):
    """The index after the string starting at text[i] (basic or literal,
    single- or multi-line)."""
    for quote in ('"""', "'''", '"', "'"):
        if text.startswith(quote, i):
            break
    i += len(quote)
    while i < len(text) and not text.startswith(quote, i):
        i += 2 if quote[0] == '"' and text[i] == "\\" else 1
    return i + len(quote)


def _value_end(text, i):
    """The index after the value starting at text[i], trailing blanks excluded."""
    depth, start = 0, i
    while i < len(text):
        c = text[i]
        if c in "\"'":
            i = _string_end(text, i)
            continue
        if c == "#" or (c == "\n" and depth == 0):
            if depth == 0:
                break
            i = text.find("\n", i) if c == "#" else i + 1
            i = len(text) if i < 0 else i
            continue
        depth += c in "[{"
        depth -= c in "]}"
        i += 1
    return start + len(text[start:i].rstrip())


def _key_parts(text, i, stop):
    """The dotted key at text[i:] up to the character `stop` ('=' or ']'):
    its parts and the index of `stop`."""
    parts = []
    while True:
        while text[i] in " \t":
            i += 1
        if text[i] in "\"'":
            end = _string_end(text, i)
            token = text[i:end]
            parts.append(json.loads(token) if token[0] == '"' else token[1:-1])
            i = end
        else:
            m = _BARE_KEY.match(text, i)
            if not m:
                raise ValueError(f"not a key at {text[i:i + 20]!r}")
            parts.append(m.group())
            i = m.end()
        while text[i] in " \t":
            i += 1
        if text[i] == ".":
            i += 1
            continue
        if text.startswith(stop, i):
            return parts, i
        raise ValueError(f"expected {stop!r} at {text[i:i + 20]!r}")


def _entries(text):
    """Where each header and key of a document is: (path, kind, start, end),
    paths with array entries as indices ("bodies", 0, "velocity"); for a key
    [start, end) is its value, for a header the header line."""
    entries = [((), "header", 0, 0)]
    arrays = {}  # array of tables -> entries so far
    current = ()
    i = 0

    def resolve(parts):
        path = ()
        for p in parts:
            path += (p,)
            if path in arrays:
                path += (arrays[path] - 1,)
        return path

    while i < len(text):
        c = text[i]
        if c in " \t\r\n":
            i += 1
        elif c == "#":
            i = text.find("\n", i)
            i = len(text) if i < 0 else i
        elif c == "[":
            double = text.startswith("[[", i)
            parts, close = _key_parts(text, i + (2 if double else 1), "]]" if double else "]")
            if double:
                array = resolve(parts[:-1]) + (parts[-1],)
                arrays[array] = arrays.get(array, 0) + 1
                current = array + (arrays[array] - 1,)
            else:
                current = resolve(parts)
            end = close + (2 if double else 1)
            entries.append((current, "header", i, end))
            i = end
        else:
            parts, equals = _key_parts(text, i, "=")
            start = equals + 1
            while text[start] in " \t":
                start += 1
            i = _value_end(text, start)
            entries.append((current + tuple(parts), "key", start, i))
    return entries


def _line_end(text, i):
    end = text.find("\n", i)
    return len(text) if end < 0 else end


def _edit(text, data, path):
    """`text` with the value at `path` made data's: the longest part of the
    path that the text gives a value replaced, or else a line added to the
    deepest table the text heads that holds it."""
    def value_at(p):
        node = data
        for part in p:
            node = node[part]
        return node

    entries = _entries(text)
    keys = {p: (start, end) for p, kind, start, end in entries if kind == "key"}
    for n in range(len(path), 0, -1):
        if path[:n] in keys:
            start, end = keys[path[:n]]
            return text[:start] + value_text(value_at(path[:n]), ".".join(map(str, path[:n]))) + text[end:]
    headers = [(p, k) for k, (p, kind, _, _) in enumerate(entries) if kind == "header" and path[: len(p)] == p]
    table, k = max(headers, key=lambda h: len(h[0]))
    rest = path[len(table):]
    if any(isinstance(part, int) for part in rest):
        raise ValueError(f"{path}: an array entry the text does not head")
    value = value_text(value_at(path), ".".join(map(str, path)))
    if len(rest) > 1 and not any(isinstance(part, int) for part in table):
        # A new table: a section of its own at the end.
        header = ".".join(key_text(part) for part in path[:-1])
        return text.rstrip("\n") + f"\n\n[{header}]\n{key_text(path[-1])} = {value}\n"
    line = ".".join(key_text(part) for part in rest) + " = " + value
    # After the table's last key, before the next header.
    end, has_keys = entries[k][3], False
    for _, kind, _, stop in entries[k + 1:]:
        if kind == "header":
            break
        end, has_keys = stop, True
    if k == 0 and not has_keys:  # the first root key: above the first header
        at = entries[1][2] if len(entries) > 1 else len(text)
        return text[:at] + ("\n" if at and text[at - 1] != "\n" else "") + line + "\n" + text[at:]
    at = _line_end(text, end)
    return text[:at] + "\n" + line + text[at:]


def edited_text(text, data, paths):
    """`text`, a TOML document, with the values at `paths` (as Case.set walks
    them) changed to `data`'s, keeping every comment and line it can; the
    whole document afresh (document_text) where the edit would not read
    back as `data`."""
    try:
        for path in paths:
            text = _edit(text, data, path)
        if tomllib.loads(text) == data:
            return text
    except (ValueError, KeyError, IndexError, TypeError, tomllib.TOMLDecodeError):
        pass
    return document_text(data)
