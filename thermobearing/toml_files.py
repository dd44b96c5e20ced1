"""Parsed TOML configuration files, memoised by file identity.

A scene builds its bearings, lubricant and calibration from the preset files in ``configs/``
every time a :class:`~thermobearing.simulation.Simulation` is made; a sweep makes hundreds of
them from the same few files. :func:`read_toml` parses a file once per (path, modification
time, size) and hands each caller its own deep copy, so an edited file is read again and no
caller can change what another one gets.
"""

from __future__ import annotations

import copy
import functools
import tomllib
from pathlib import Path
from typing import Any

from .text_files import toml_text

__all__ = ["read_toml"]


@functools.lru_cache(maxsize=64)
def _parsed(path: str, mtime_ns: int, size: int) -> dict[str, Any]:
    """The parsed file (the key carries the file's identity; never handed out directly)."""
    return tomllib.loads(toml_text(path))


def read_toml(path: str | Path) -> dict[str, Any]:
    """The contents of the TOML file ``path`` as a new dict (tomllib's types).

    Raises ``OSError`` when the file cannot be read and ``tomllib.TOMLDecodeError`` when it
    is not valid TOML, as :func:`tomllib.loads` does, or not UTF-8 text (a byte-order mark
    is skipped; UTF-16 with its mark is read: :func:`thermobearing.text_files.toml_text`);
    the callers turn these into :class:`~thermobearing.errors.InputError` naming their
    field.
    """
    p = Path(path).resolve()
    st = p.stat()
    return copy.deepcopy(_parsed(str(p), st.st_mtime_ns, st.st_size))
