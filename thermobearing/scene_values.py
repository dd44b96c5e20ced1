"""Values of the scene's TOML tables: strict keys, tables, required keys, unit strings to SI
floats (finite) and SI floats back to unit strings for :meth:`Scene.to_toml`.

Every error is an :class:`~thermobearing.errors.InputError` naming the scene field, the value
and what is allowed. Shared by :mod:`thermobearing.scene`, its section modules
(:mod:`thermobearing.scene_sections`, :mod:`thermobearing.scene_schedule`) and
:mod:`thermobearing.scene_checks`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from .errors import InputError
from .units import format_quantity, quantity_unit, to_si


def _check_keys(section: str, data: Mapping[str, Any], allowed: Sequence[str]) -> None:
    for key in data:
        if key not in allowed:
            raise InputError(f"{section}.{key}", data[key], "a known key: " + ", ".join(allowed))


def _table(field_name: str, value: Any) -> Mapping[str, Any]:
    """``value`` if it is a TOML table, else InputError naming the field."""
    if not isinstance(value, Mapping):
        raise InputError(field_name, value, "a table (key = value pairs)")
    return value


def _quantity(raw: Any, kind: str, field: str) -> float:
    """``to_si`` that also refuses NaN / inf (a bare ``nan`` is a float TOML allows)."""
    value = to_si(raw, kind, field=field)
    if not math.isfinite(value):
        raise InputError(field, raw, "a finite number with a unit")
    return value


def _unit_of(raw: Any, kind: str, default: str) -> str:
    """The unit a scene value was written in (``"500 N"`` -> ``"N"``), so that the scene is
    written back and read by a sweep's bare numbers in the user's unit; ``default`` for a
    bare number or a unit that does not convert to ``kind`` (a temperature difference,
    an offset unit)."""
    unit = quantity_unit(raw)
    if unit is None:
        return default
    try:
        to_si(f"1 {unit}", kind)
    except InputError:
        return default
    return unit


def _require(section: str, data: Mapping[str, Any], key: str) -> Any:
    if key not in data:
        raise InputError(f"{section}.{key}", None, "a value (this key is required)")
    return data[key]


def _fmt(value: float, unit: str) -> str | float:
    """SI float -> unit string for TOML output, exact enough to round-trip."""
    if unit in ("", "-"):
        return value
    return format_quantity(value, unit, digits=12)
