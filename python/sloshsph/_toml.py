"""Python values -> TOML text: case dicts written as case files, values written as --set texts."""

import math
import re

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k):
    if not isinstance(k, str):
        raise TypeError(f"case keys are strings, not {type(k).__name__}: {k!r}")
    return k if _BARE_KEY.match(k) else _string(k)


def _string(s):
    out = ['"']
    for ch in s:
        if ch == '"':
            out.append('\\"')
        elif ch == "\\":
            out.append("\\\\")
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif ch == "\r":
            out.append("\\r")
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def value(v):
    """One value as a TOML literal (what ``--set KEY=VALUE`` takes as VALUE)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if hasattr(v, "item") and callable(v.item) and getattr(v, "shape", None) == ():  # NumPy scalar
        return value(v.item())
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        text = repr(v)
        return text if any(c in text for c in ".e") else text + ".0"
    if isinstance(v, str):
        return _string(v)
    if hasattr(v, "tolist"):  # NumPy array
        return value(v.tolist())
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {value(x)}" for k, x in v.items()) + "}"
    raise TypeError(f"cannot write {type(v).__name__} as a TOML value: {v!r}")


def _is_table_array(v):
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(isinstance(x, dict) for x in v)


def _table(prefix, table, lines):
    scalars = [(k, v) for k, v in table.items() if not isinstance(v, dict) and not _is_table_array(v)]
    for k, v in scalars:
        lines.append(f"{_key(k)} = {value(v)}")
    for k, v in table.items():
        path = f"{prefix}.{_key(k)}" if prefix else _key(k)
        if isinstance(v, dict):
            lines.append("")
            lines.append(f"[{path}]")
            _table(path, v, lines)
        elif _is_table_array(v):
            for entry in v:
                lines.append("")
                lines.append(f"[[{path}]]")
                _table(path, entry, lines)


def dumps(case):
    """A dict of case tables (``{"tank": {"length": 0.6, ...}, "probes": {"gauge": [{...}]}}``) as TOML."""
    if not isinstance(case, dict):
        raise TypeError(f"a case is a dict of tables, not {type(case).__name__}")
    lines = []
    _table("", case, lines)
    return "\n".join(lines).lstrip("\n") + "\n"
