"""One small Registry class: families of interchangeable models, looked up by name.

The lookup *is* the dispatch: a scene names a model (``film = "hamrock_dowson_1977"``),
the registry returns the callable; there is no second if/elif chain that could drift.
Each entry carries the citation keys of its source, the unit of every documented
parameter and its validity range, so ``thermobearing models`` can list them and a run
can list the citations of the models it used.

Registries are created at import time of the module that owns the family and are
filled by decorators in that module; after import they are not changed.
"""

from __future__ import annotations

import importlib
import math
import pkgutil
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, Generic, TypeVar

from .errors import InputError, UnknownNameError

T = TypeVar("T")

_INTERVAL = re.compile(r"^\s*([\[(])\s*([^,\s]+)\s*,\s*([^\]\)\s]+)\s*([\])])\s*$")


@dataclass(frozen=True)
class Interval:
    """Allowed range of a numeric parameter, written in interval notation: ``"[0, 1]"``,
    ``"(0, inf)"``, ``"[2, 256]"`` (bounds in the parameter's SI unit; ``inf`` allowed).

    Attributes
    ----------
    low, high : bounds; low_closed, high_closed : whether the bound itself is allowed.
    text : the interval as written (for messages).
    """

    low: float
    high: float
    low_closed: bool
    high_closed: bool
    text: str

    @classmethod
    def parse(cls, text: str) -> Interval:
        """``"[a, b]"``, ``"(a, b]"``... -> Interval; ValueError on any other form."""
        m = _INTERVAL.match(text)
        if m is None:
            raise ValueError(f"not an interval: {text!r} (write e.g. '[0, 1]' or '(0, inf)')")
        low, high = float(m.group(2)), float(m.group(3))
        if not low <= high:
            raise ValueError(f"empty interval {text!r}")
        return cls(low, high, m.group(1) == "[", m.group(4) == "]", text.strip())

    def contains(self, value: float) -> bool:
        """Whether ``value`` lies in the interval (NaN never does)."""
        if not (value >= self.low if self.low_closed else value > self.low):
            return False
        return value <= self.high if self.high_closed else value < self.high

    def check(self, field_name: str, value: Any, unit: str = "-") -> None:
        """Raise :class:`InputError` naming ``field_name`` unless ``value`` is a number in
        the interval."""
        try:
            x = float(value)
        except (TypeError, ValueError):
            x = math.nan
        if not self.contains(x):
            what = f"a number in {self.text}" + ("" if unit in ("-", "") else f" [{unit}]")
            raise InputError(field_name, value, what)


@dataclass(frozen=True)
class Entry(Generic[T]):
    """One registered model.

    Attributes
    ----------
    name : lookup name used in scenes and configs.
    obj : the registered function or class.
    references : citation keys (see :mod:`thermobearing.citations`).
    parameters : documented parameter name -> SI unit string (``"-"`` if dimensionless).
    validity : validity range in words (``"1 <= k <= 8, 0.3 < U*1e11 < 100"``).
    summary : one line on what the model is.
    limits : documented parameter name -> allowed :class:`Interval` of a numeric value.
    """

    name: str
    obj: T
    references: tuple[str, ...]
    parameters: Mapping[str, str] = field(default_factory=dict)
    validity: str = ""
    summary: str = ""
    limits: Mapping[str, Interval] = field(default_factory=dict)

    def check_parameter(self, key: str, value: Any, field_name: str) -> None:
        """Check a given value of parameter ``key`` against its documented interval (if
        any); the error names ``field_name``. Strings (names of forms, models) are left
        to the model."""
        lim = self.limits.get(key)
        if lim is not None and not isinstance(value, str):
            lim.check(field_name, value, self.parameters.get(key, "-"))


class Registry(Generic[T]):
    """A named family of models.

    Parameters
    ----------
    family : the family name as scenes write it (``"film"``, ``"traction"``...).
    description : one line on what the family does.
    """

    def __init__(self, family: str, description: str = "") -> None:
        self.family = family
        self.description = description
        self._entries: dict[str, Entry[T]] = {}

    def register(
        self,
        name: str,
        *,
        references: tuple[str, ...] | list[str],
        parameters: Mapping[str, str] | None = None,
        validity: str = "",
        summary: str = "",
        limits: Mapping[str, str] | None = None,
    ) -> Callable[[T], T]:
        """Decorator that registers ``obj`` under ``name``; returns ``obj`` unchanged.

        ``limits``: documented parameter -> allowed interval in SI (``"[0, 1]"``,
        ``"(0, inf)"``), checked where a scene sets the parameter."""
        if not references:
            raise ValueError(f"registry {self.family!r}: model {name!r} needs references")
        parsed = {k: Interval.parse(v) for k, v in (limits or {}).items()}
        unknown = sorted(set(parsed) - set(parameters or {}))
        if unknown:
            raise ValueError(f"registry {self.family!r}: model {name!r} limits undocumented "
                             f"parameters {unknown}")

        def decorator(obj: T) -> T:
            if name in self._entries:
                raise ValueError(f"registry {self.family!r}: {name!r} registered twice")
            doc = (getattr(obj, "__doc__", None) or "").strip().splitlines()
            self._entries[name] = Entry(
                name=name,
                obj=obj,
                references=tuple(references),
                parameters=dict(parameters or {}),
                validity=validity,
                summary=summary or (doc[0] if doc else ""),
                limits=parsed,
            )
            return obj

        return decorator

    def entry(self, name: str) -> Entry[T]:
        """The entry registered as ``name``; the error lists the known names."""
        try:
            return self._entries[name]
        except KeyError:
            raise UnknownNameError(f"{self.family} model", name, self._entries) from None

    def get(self, name: str) -> T:
        """The registered object (function or class) for ``name``."""
        return self.entry(name).obj

    __getitem__ = get

    def names(self) -> list[str]:
        """Registered names, sorted."""
        return sorted(self._entries)

    def entries(self) -> list[Entry[T]]:
        """All entries, sorted by name."""
        return [self._entries[n] for n in self.names()]

    def __contains__(self, name: object) -> bool:
        return name in self._entries

    def __iter__(self) -> Iterator[str]:
        return iter(self.names())

    def __len__(self) -> int:
        return len(self._entries)

    def __repr__(self) -> str:
        return f"Registry({self.family!r}, {len(self)} models)"


def all_registries() -> dict[str, Registry[Any]]:
    """Import every module of the package and return its registries by family.

    Walks the package so that a new module with a new registry is found without
    editing a list here.
    """
    import thermobearing

    found: dict[str, Registry[Any]] = {}
    for info in pkgutil.walk_packages(thermobearing.__path__, prefix="thermobearing."):
        if info.name.startswith("thermobearing.commands"):
            continue
        module = importlib.import_module(info.name)
        for value in vars(module).values():
            if isinstance(value, Registry):
                existing = found.get(value.family)
                if existing is not None and existing is not value:
                    raise RuntimeError(f"two registries claim the family {value.family!r}")
                found[value.family] = value
    return dict(sorted(found.items()))
