"""Bearing geometry: ball and cylindrical-roller bearings, their cage, and derived quantities.

Everything is SI (m, kg, rad). Presets live in ``configs/bearings/<NAME>.toml`` and are read by
:func:`load_bearing`, which converts unit strings with :func:`thermobearing.units.to_si` and
rejects unknown keys.

This module is the public entry point; the pieces live in one module each and are re-exported
here:

- :mod:`thermobearing.geometry_common`: kind names, :class:`CharacteristicFrequencies`,
  envelope checks, epicyclic kinematics (gamma, cage speed ratio, characteristic frequencies).
- :mod:`thermobearing.geometry_cage`: :class:`CageGeometry`.
- :mod:`thermobearing.geometry_thermal`: operating clearance from component temperatures
  (:data:`STEEL_EXPANSION`).
- :mod:`thermobearing.geometry_ball`: :class:`BallBearing` (reduced radii, four-point arcs).
- :mod:`thermobearing.geometry_roller`: :class:`RollerBearing`.
- :mod:`thermobearing.bearing_config`: reading the presets (wrapped below).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from .geometry_ball import BallBearing
from .geometry_cage import CAGE_GUIDANCE, CageGeometry
from .geometry_common import BALL_KINDS, RACES, ROLLER_KINDS, CharacteristicFrequencies
from .geometry_roller import RollerBearing
from .geometry_thermal import STEEL_EXPANSION

__all__ = [
    "BALL_KINDS",
    "CAGE_GUIDANCE",
    "RACES",
    "ROLLER_KINDS",
    "STEEL_EXPANSION",
    "BallBearing",
    "Bearing",
    "CageGeometry",
    "CharacteristicFrequencies",
    "RollerBearing",
    "bearing_from_dict",
    "configs_dir",
    "load_bearing",
    "preset_names",
]

Bearing = BallBearing | RollerBearing


# ---------------------------------------------------------------------------
# loading presets (implementation in :mod:`thermobearing.bearing_config`)
# ---------------------------------------------------------------------------
def configs_dir() -> Path:
    """The repository's ``configs`` folder."""
    from .bearing_config import configs_dir as _f

    return _f()


def preset_names() -> list[str]:
    """Names of the bearing presets in ``configs/bearings``."""
    from .bearing_config import preset_names as _f

    return _f()


def bearing_from_dict(data: Mapping[str, Any], *, origin: str = "bearing") -> Bearing:
    """Build a bearing from a config mapping (unit strings allowed); unknown keys are errors."""
    from .bearing_config import bearing_from_dict as _f

    return _f(data, origin=origin)


def load_bearing(name_or_path: str | Path,
                 overrides: Mapping[str, Any] | None = None) -> Bearing:
    """Load a bearing from a preset name (``"QJ1044"``) or a TOML path.

    ``overrides`` replaces top-level keys (unit strings allowed, e.g.
    ``{"diametral_clearance": "0.1 mm"}``) before the bearing is built. For a four-point preset
    with a gothic-arch offset, overriding only the clearance keeps the offset and lets the
    contact angle follow (as :meth:`BallBearing.with_clearance`). Unknown keys, unknown presets
    and bad values raise :class:`~thermobearing.errors.InputError`.
    """
    from .bearing_config import load_bearing as _f

    return _f(name_or_path, overrides)
