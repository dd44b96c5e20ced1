"""Parsed TOML configuration files, memoised by file identity.

A scene builds its bearings, lubricant and calibration from the preset files in ``configs/``
every time a :class:`~thermobearing.simulation.Simulation` is made; a sweep makes hundreds of
them from the same few files. :func:`read_toml` reads the file's bytes on every call and
parses them once per (path, content), handing each caller its own deep copy: an edited file
is parsed again whatever its timestamp says and no caller can change what another one gets.
(The key was (path, modification time, size) before session 23: a rewrite of the same size
within the file system's timestamp granularity, 1-2 s on FAT / HFS+ and a clock tick on
Linux before multigrain timestamps, or a copy keeping the mtime (``cp -p``, ``rsync -t``)
returned the old contents.)
"""

from __future__ import annotations

import copy
import functools
import tomllib
from pathlib import Path
from typing import Any

from .text_files import toml_text_of

__all__ = ["read_toml"]


@functools.lru_cache(maxsize=64)
def _parsed(path: str, data: bytes) -> dict[str, Any]:
    """The parsed contents ``data`` of the file ``path`` (never handed out directly)."""
    return tomllib.loads(toml_text_of(data))


def read_toml(path: str | Path) -> dict[str, Any]:
    """The contents of the TOML file ``path`` as a new dict (tomllib's types).

    Raises ``OSError`` when the file cannot be read and ``tomllib.TOMLDecodeError`` when it
    is not valid TOML, as :func:`tomllib.loads` does, or not UTF-8 text (a byte-order mark
    is skipped; UTF-16 with its mark is read: :func:`thermobearing.text_files.toml_text`);
    the callers turn these into :class:`~thermobearing.errors.InputError` naming their
    field.
    """
    p = Path(path).resolve()
    return copy.deepcopy(_parsed(str(p), p.read_bytes()))
