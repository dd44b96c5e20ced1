"""thermobearing: power losses, skidding and transient temperatures of rolling bearings.

Public entry points (stable):

- :func:`load_bearing` -- a bearing preset name (``"QJ1044"``) or a TOML path.
- :func:`load_lubricant` -- a lubricant preset name (``"ISO_VG46"``) or a TOML path.

Everything inside is SI (m, kg, s, K, N, Pa, W, rad); unit strings are accepted only in
configs and on the command line (see :mod:`thermobearing.units`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

if TYPE_CHECKING:  # pragma: no cover
    from .geometry import BallBearing, RollerBearing
    from .lubricant import Lubricant


def load_bearing(name_or_path: str, overrides: dict[str, Any] | None = None
                 ) -> BallBearing | RollerBearing:
    """Load a bearing from a preset name in ``configs/bearings`` or a TOML file path;
    ``overrides`` replaces top-level keys (unit strings allowed)."""
    from .geometry import load_bearing as _load

    return _load(name_or_path, overrides=overrides)


def load_lubricant(name_or_path: str) -> Lubricant:
    """Load a lubricant from a preset name in ``configs/lubricants`` or a TOML file path."""
    from .lubricant import load_lubricant as _load

    return _load(name_or_path)


def __getattr__(name: str) -> Any:  # lazy access to the main classes
    if name in ("BallBearing", "RollerBearing"):
        from . import geometry

        return getattr(geometry, name)
    if name == "Lubricant":
        from . import lubricant

        return lubricant.Lubricant
    raise AttributeError(name)
