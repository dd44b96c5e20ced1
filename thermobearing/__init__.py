"""thermobearing: power losses, skidding and transient temperatures of rolling bearings.

Public entry points (stable):

- :func:`load_bearing` -- a bearing preset name (``"QJ1044"``) or a TOML path.
- :func:`load_lubricant` -- a lubricant preset name (``"ISO_VG46"``) or a TOML path.
- :class:`OilSupply` (:mod:`thermobearing.state`) -- method, flow [m^3/s], inlet [K].
- :func:`load_scene` / :func:`loads_scene` (:mod:`thermobearing.scene`) -- a scene from a
  preset name, a TOML path or TOML text; :class:`Simulation`
  (:mod:`thermobearing.simulation`) runs it: ``Simulation(scene).run()`` returns
  :class:`~thermobearing.results.Results` (``tables``: DataFrames with units in the column
  names; ``write(folder)``). ``scene.with_changes(supply=dataclasses.replace(scene.supply,
  flow=2.5e-4))`` changes a field in code; :func:`thermobearing.sweep.run_sweep` with
  :func:`thermobearing.sweep.parse_set` runs a sweep as ``thermobearing sweep`` does.

The physics, one module each: :func:`thermobearing.skidding.solve` (cage and element speeds of
one operating point), :mod:`thermobearing.hertz`, :mod:`thermobearing.film`,
:mod:`thermobearing.traction`, :mod:`thermobearing.global_friction`,
:mod:`thermobearing.ehl`, :mod:`thermobearing.vibration`, :mod:`thermobearing.signal`.

Everything inside is SI (m, kg, s, K, N, Pa, W, rad: 1800 r/min is 188.5 rad/s, 40 degC is
313.15 K); unit strings are accepted only in configs and on the command line (see
:mod:`thermobearing.units`).
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


#: lazily imported public names -> their module (importing the package stays cheap)
_LAZY = {"BallBearing": "geometry", "RollerBearing": "geometry", "Lubricant": "lubricant",
         "OilSupply": "state", "Scene": "scene", "load_scene": "scene",
         "loads_scene": "scene", "Simulation": "simulation", "Results": "results"}

__all__ = ["__version__", "load_bearing", "load_lubricant", *_LAZY]


def __getattr__(name: str) -> Any:  # lazy access to the main classes
    import importlib
    import importlib.util

    if name in _LAZY:
        return getattr(importlib.import_module(f".{_LAZY[name]}", __name__), name)
    if not name.startswith("_") and importlib.util.find_spec(f"{__name__}.{name}"):
        # thermobearing.skidding.solve(...) after a bare `import thermobearing`
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'thermobearing' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))
