"""Citation keys -> references.

References live in TOML files under ``thermobearing/data/citations/`` (one file per
topic, so that modules can add their sources without touching one shared list). Each
table is one key::

    [johnson1985]
    authors = "Johnson KL"
    title = "Contact Mechanics"
    venue = "Cambridge University Press"
    year = 1985

A run lists the citations of the models it used through :func:`cite`.
"""

from __future__ import annotations

import functools
import tomllib
from collections.abc import Iterable
from dataclasses import dataclass
from importlib import resources

from .errors import UnknownNameError


@dataclass(frozen=True)
class Reference:
    """One bibliographic reference."""

    key: str
    authors: str
    title: str
    venue: str = ""
    year: int | None = None
    doi: str = ""
    note: str = ""

    def format(self) -> str:
        """One-line human-readable form."""
        parts = [self.authors]
        if self.year:
            parts.append(f"({self.year})")
        parts.append(self.title + ".")
        if self.venue:
            parts.append(self.venue + ".")
        if self.doi:
            parts.append(f"doi:{self.doi}")
        if self.note:
            parts.append(f"[{self.note}]")
        return " ".join(parts)


@functools.lru_cache(maxsize=1)
def all_references() -> dict[str, Reference]:
    """Every known reference, by key (read once from the packaged TOML files)."""
    refs: dict[str, Reference] = {}
    folder = resources.files("thermobearing") / "data" / "citations"
    for item in sorted(folder.iterdir(), key=lambda p: p.name):
        if not item.name.endswith(".toml"):
            continue
        data = tomllib.loads(item.read_text(encoding="utf-8"))
        for key, fields in data.items():
            if key in refs:
                raise ValueError(f"citation key {key!r} defined twice ({item.name})")
            refs[key] = Reference(key=key, **fields)
    return refs


def reference(key: str) -> Reference:
    """The reference for ``key``; the error lists the known keys."""
    refs = all_references()
    try:
        return refs[key]
    except KeyError:
        raise UnknownNameError("citation key", key, refs) from None


def cite(keys: Iterable[str]) -> list[str]:
    """Formatted references for ``keys``, de-duplicated, in first-seen order."""
    seen: dict[str, None] = {}
    for k in keys:
        seen.setdefault(k, None)
    return [reference(k).format() for k in seen]
