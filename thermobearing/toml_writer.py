"""A small TOML writer for scene documents (:meth:`thermobearing.scene.Scene.to_toml`, the
calibration files): top-level values, tables, arrays of named tables in the long form
(``[[bearings]]``) and a schedule's ``steps`` one per line. Reading goes through
:mod:`tomllib` (:mod:`thermobearing.toml_files` for the preset files).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Any

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")
"""TOML 1.0 bare keys: ASCII letters, ASCII digits, underscores and dashes only."""

_ESCAPES = {"\\": "\\\\", '"': '\\"', "\b": "\\b", "\t": "\\t", "\n": "\\n",
            "\f": "\\f", "\r": "\\r"}


def _escape_char(c: str) -> str:
    """One character of a TOML basic string: the short escapes, ``\\uXXXX`` for the other
    control characters (U+0000..U+001F and U+007F may not appear raw, TOML 1.0 "String")."""
    if c in _ESCAPES:
        return _ESCAPES[c]
    if ord(c) < 0x20 or ord(c) == 0x7F:
        return f"\\u{ord(c):04X}"
    return c


def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else
                                                 ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return '"' + "".join(_escape_char(c) for c in v) + '"'
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, list | tuple):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _toml_key(k: str) -> str:
    """A bare key when TOML allows one (ASCII only: ``str.isalnum`` also takes "ä", "µ",
    "²", which TOML refuses bare), else a quoted key."""
    return k if _BARE_KEY.fullmatch(k) else _toml_value(k)


def dumps_toml(data: Mapping[str, Any]) -> str:
    """Small TOML writer for scene documents (tables, arrays of tables, inline values)."""
    lines: list[str] = []
    scalars = {k: v for k, v in data.items() if not _is_table(v) and not _is_table_array(v)}
    for k, v in scalars.items():
        lines.append(f"{_toml_key(k)} = {_toml_value(v)}")
    for k, v in data.items():
        if _is_table_array(v):
            for item in v:
                lines.append("")
                lines.append(f"[[{_toml_key(k)}]]")
                for kk, vv in item.items():
                    lines.append(f"{_toml_key(kk)} = {_toml_value(vv)}")
        elif _is_table(v):
            lines.append("")
            lines.append(f"[{_toml_key(k)}]")
            for kk, vv in v.items():
                if kk == "steps" and isinstance(vv, list):
                    lines.append(f"{kk} = [")
                    lines.extend(f"  {_toml_value(x)}," for x in vv)
                    lines.append("]")
                else:
                    lines.append(f"{_toml_key(kk)} = {_toml_value(vv)}")
    return "\n".join(lines) + "\n"


def _is_table(v: Any) -> bool:
    return isinstance(v, Mapping)


def _is_table_array(v: Any) -> bool:
    """An array of named tables (``[[bearings]]``) is written in the long form."""
    return (isinstance(v, list) and bool(v)
            and all(isinstance(x, Mapping) and "name" in x for x in v))
