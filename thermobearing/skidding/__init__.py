"""Skidding solvers: cage and element speeds from the traction / drag balance.

Public entry point: :func:`solve` dispatches on the bearing type

- :class:`~thermobearing.geometry.BallBearing` -> :func:`thermobearing.skidding.ball.solve_ball`
  (quasi-dynamic ball/cage/ring equilibrium with gyroscopic moment, four-point contact,
  over-skidding; seed paper 002);
- :class:`~thermobearing.geometry.RollerBearing` ->
  :func:`thermobearing.skidding.roller.solve_roller` (paper 000, Z + 1 equations, whirl).

All inputs SI: ``speed`` inner-ring speed [rad/s], loads [N], ``temperature`` [K].
"""

from __future__ import annotations

import numbers
from typing import Any

import numpy as np

from ..errors import InputError, check_finite, check_temperature

__all__ = ["solve"]


def _operating_value(field: str, value: Any, unit: str) -> float:
    """``value`` as a float: a Python or numpy real number or a 0-d array; anything else
    (a unit string, a list, an array of several values) is an :class:`InputError` naming
    ``field`` and its SI ``unit``."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        check_finite(field, float(value))
        return float(value)
    raise InputError(field, value, f"one real number in {unit} (a unit string converts with "
                     f"thermobearing.units.to_si(value, {unit!r}); one operating point per "
                     "call)")


def solve(bearing: Any, lubricant: Any, speed: float, radial_load: float, axial_load: float,
          temperature: float, *, supply: Any = None, params: Any = None, models: Any = None,
          guess: Any = None, n_balls: int | None = None, oil_temperature: float | None = None,
          **options: Any) -> Any:
    """Skidding state of a bearing at one operating point.

    Parameters
    ----------
    bearing : BallBearing or RollerBearing.
    lubricant : Lubricant.
    speed : inner-ring speed [rad/s] (outer ring fixed; 1800 r/min is 188.5 rad/s).
    radial_load, axial_load : [N].
    temperature : contact / oil temperature [K] (40 degC is 313.15 K).
    supply : :class:`thermobearing.state.OilSupply`; required for ball bearings (it sets the
        oil fraction of the drag models) unless ``params.oil_fraction`` is given. Roller
        bearings: with a supply the balance contains the oil drag of paper 002 (roller drag
        eq. 10, cage churning eq. 15, guide land eq. 5, inner-ring churning eq. 17 in the
        shaft torque; :mod:`thermobearing.skidding.roller_drag`), as the scene's heat
        sources book it; without one (paper 000's case) no oil drag. A ready
        ``drag=RollerDrag`` option overrides it.
    params : ball bearings: :class:`thermobearing.skidding.ball_models.BallParameters`
        (e.g. the calibrated set of ``configs/bearings/QJ1044.calibration.toml``). Roller
        bearings: None or a mapping with ``drag_coefficient`` (c_d of the roller drag,
        default 1.0) and ``parker_constant`` (default 1.46e7).
    models : ball bearings: ready-made :class:`~thermobearing.skidding.ball.BallModels`
        (overrides ``params``).
    guess : previous result of the same bearing (warm start).
    n_balls : ball bearings: override of the ball count (benchmarks).
    oil_temperature : churning temperature [K] (default ``temperature``).
    **options : passed to the type's solver (``tol``, ``max_iter``, roller model options...).

    Returns
    -------
    BallSkiddingResult (ball) or the roller solver's result; both carry ``cage_speed_ratio``,
    ``theoretical_cage_speed_ratio``, ``converged``, ``residual_norm`` and per-element speeds.
    """
    from ..geometry import BallBearing, RollerBearing
    from ..lubricant import Lubricant
    from ..state import OilSupply

    if not isinstance(lubricant, Lubricant):
        raise InputError("lubricant", type(lubricant).__name__,
                         "a Lubricant (thermobearing.lubricant.load_lubricant)")
    if supply is not None and not isinstance(supply, OilSupply):
        raise InputError("supply", supply, "an OilSupply (thermobearing.state.OilSupply) or None")
    speed = _operating_value("speed", speed, "rad/s")
    radial_load = _operating_value("radial_load", radial_load, "N")
    axial_load = _operating_value("axial_load", axial_load, "N")
    temperature = _operating_value("temperature", temperature, "K")
    check_temperature("temperature", temperature)
    if oil_temperature is not None:
        oil_temperature = _operating_value("oil_temperature", oil_temperature, "K")
        check_temperature("oil_temperature", oil_temperature)
    from ..lubricant import check_liquid_temperature

    for name, kelvin in (("temperature", temperature), ("oil_temperature", oil_temperature)):
        if kelvin is not None:  # the oil below its pour point: was a Roelands overflow error
            check_liquid_temperature(lubricant, name, kelvin)  # "at a contact pressure"
    _speed_plausibility(bearing, speed)
    if isinstance(bearing, BallBearing) or getattr(bearing, "kind", None) in (
            "deep_groove", "angular_contact", "four_point"):
        from .ball import solve_ball
        from .ball_models import default_ball_models

        if models is None:
            models = default_ball_models(bearing, lubricant, temperature=temperature,
                                         speed=speed, supply=supply, params=params,
                                         oil_temperature=oil_temperature)
        return solve_ball(bearing, models, speed, radial_load, axial_load, n_balls=n_balls,
                          guess=guess, **options)
    if isinstance(bearing, RollerBearing):
        from .roller import solve_roller

        if guess is not None:
            options.setdefault("x0", guess)
        if supply is not None and "drag" not in options:
            options["drag"] = _roller_drag(bearing, lubricant, supply, speed, temperature,
                                           oil_temperature, params)
        return solve_roller(bearing, lubricant, speed, radial_load, axial_load, temperature,
                            **options)
    raise InputError("bearing", type(bearing).__name__, "a BallBearing or a RollerBearing")


def _roller_drag(bearing: Any, lubricant: Any, supply: Any, speed: float, temperature: float,
                 oil_temperature: float | None, params: Any) -> Any:
    """The roller solver's oil drag (:func:`thermobearing.skidding.roller_drag.build_drag`)
    at the oil temperature (default ``temperature``) [K]; ``params``: None or a mapping of
    ``drag_coefficient`` and ``parker_constant``."""
    from collections.abc import Mapping

    from .roller_drag import build_drag

    given: dict[str, Any] = {}
    if params is not None:
        allowed = ("drag_coefficient", "parker_constant")
        if not isinstance(params, Mapping) or any(k not in allowed for k in params):
            raise InputError("params", params, "None or a mapping of " + ", ".join(allowed)
                             + " for a roller bearing")
        given = {k: _operating_value(f"params.{k}", v, "-") for k, v in params.items()}
    t_oil = temperature if oil_temperature is None else oil_temperature
    return build_drag(bearing, lubricant, supply, speed, t_oil, **given)


#: speed factor n d_m [mm r/min] above which no oil-lubricated rolling bearing runs (hybrid
#: spindle bearings on oil-air reach about 2.5-3e6; recalled catalogue limits, not a model
#: bound): a larger one is most likely a speed given in r/min where rad/s is asked
NDM_PLAUSIBLE = 4.0e6


def _speed_plausibility(bearing: Any, speed: float) -> None:
    """A ValidityWarning when the inner-ring speed [rad/s] gives a speed factor n d_m above
    :data:`NDM_PLAUSIBLE`: the solvers converge there (QJ1044 at 1800 rad/s: a cage speed
    ratio 29 % below CSR_th) but the number is most likely r/min passed as rad/s."""
    import math
    import warnings

    from ..errors import ValidityWarning

    dm = getattr(bearing, "pitch_diameter", None)
    if dm is None or not math.isfinite(speed):
        return
    n_rpm = abs(speed) * 30.0 / math.pi
    ndm = n_rpm * dm * 1e3
    if ndm > NDM_PLAUSIBLE:
        warnings.warn(ValidityWarning(
            f"skidding.solve: speed = {speed:g} rad/s ({n_rpm:.0f} r/min) gives n d_m = "
            f"{ndm:.3g} mm r/min, beyond any oil-lubricated rolling bearing "
            f"(~{NDM_PLAUSIBLE:.0e}); the speed is in rad/s: {speed:g} r/min would be "
            f"{speed * math.pi / 30.0:.4g} rad/s"),
            stacklevel=3)
