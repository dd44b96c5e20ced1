"""The temperatures a lubricant's property data cover.

A lubricant's properties come from laws whose sources state a range: the ASTM D341
viscosity law 0.21 cSt to 1e6 cSt, the ASME 1953 pressure-viscosity fit the 2.4 to
2000 mPa s of its data, Cragoe's c_p and k 0 to 200 degC. Past those ends the package
still evaluates the laws (a Roelands z is held, Cragoe's lines go on), so a scene whose oil
inlet lies there runs, with results that extrapolate the oil's data. This module turns the
stated ranges into one temperature interval per lubricant (:func:`data_temperature_range`)
and says when a scene temperature lies outside it (:func:`outside_data_note`). Below the
liquid range (ASTM D341 above 1e6 cSt) :func:`thermobearing.lubricant_properties.
check_liquid_temperature` refuses the temperature instead.

Units: T [K], eta [Pa s], nu [m^2/s].
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from .errors import ThermobearingError, ValidityWarning
from .lubricant_properties import (
    _D341_MAX_NU,
    _D341_MIN_NU,
    ALPHA_FIT_VISCOSITY_RANGE,
    THERMAL_TEMPERATURE_RANGE,
)

#: temperatures [K] scanned for the ends of a viscosity range: from well below the pour
#: point of any lubricant (-123 degC) to 627 degC, above the boiling range of mineral oils
_SCAN = (150.0, 900.0)
#: step [K] of that scan (the viscosity laws fall monotonically with temperature)
_SCAN_STEP = 5.0


@dataclass(frozen=True)
class DataRange:
    """Temperature interval [K] inside which every property law of a lubricant with a
    stated numeric range is inside that range; ``low`` is -inf and ``high`` +inf where no
    such law ends. ``low_reason`` / ``high_reason`` name the law that sets each end."""

    low: float
    high: float
    low_reason: str = ""
    high_reason: str = ""

    def contains(self, temperature: float) -> bool:
        """Whether ``temperature`` [K] lies inside the interval (ends included)."""
        return self.low <= temperature <= self.high

    def text(self) -> str:
        """The interval in degC with the laws that end it, e.g. ``-9.7 to 146 degC (below:
        ...; above: ...)``."""
        lo = f"{self.low - 273.15:.3g}" if math.isfinite(self.low) else "-inf"
        hi = f"{self.high - 273.15:.3g}" if math.isfinite(self.high) else "+inf"
        why = "; ".join(f"{side}: {reason}" for side, reason in
                        (("below", self.low_reason), ("above", self.high_reason)) if reason)
        return f"{lo} to {hi} degC" + (f" ({why})" if why else "")


def _value(fun: Any, temperature: float) -> float:
    """``fun(temperature)`` as a float, NaN where the law fails (overflows, not liquid)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        try:
            return float(fun(temperature))
        except (ThermobearingError, ArithmeticError, ValueError):
            return math.nan


def _crossing(fun: Any, target: float) -> float | None:
    """The temperature [K] at which the falling property ``fun(T)`` passes ``target``,
    inside :data:`_SCAN`, or None when it does not there. A 5 K scan brackets the crossing
    and bisection (in ln of the property) refines it to 1e-6 K."""
    t_a, t_b = _SCAN
    previous: tuple[float, float] | None = None
    t = t_a
    while t <= t_b:
        v = _value(fun, t)
        if math.isfinite(v) and v > 0.0:
            if previous is not None and (previous[1] - target) * (v - target) <= 0.0:
                lo, hi = previous[0], t
                g_lo = math.log(previous[1] / target)
                while hi - lo > 1e-6:
                    mid = 0.5 * (lo + hi)
                    g_mid = math.log(_value(fun, mid) / target)
                    if (g_lo > 0.0) == (g_mid > 0.0):
                        lo, g_lo = mid, g_mid
                    else:
                        hi = mid
                return 0.5 * (lo + hi)
            previous = (t, v)
        t += _SCAN_STEP
    return None


def data_temperature_range(lubricant: Any) -> DataRange:
    """The temperatures [K] over which ``lubricant``'s property laws stay inside the ranges
    their sources state, as far as those are numbers:

    * ASTM D341 viscosity law (``viscosity_law = "astm_d341"``): 0.21 cSt <= nu <= 1e6 cSt
      (ASTM D341-20 sec. 1; the registered validity of ``astm_d341``);
    * an alpha correlation fitted to atmospheric viscosities
      (:data:`~thermobearing.lubricant_properties.ALPHA_FIT_VISCOSITY_RANGE`: the ASME 1953
      fit, 2.4 <= eta <= 2000 mPa s, the viscosities of its 38 data points, Stachowiak &
      Batchelor Table 2.3);
    * the thermal correlation (c_p, k) of the oil
      (:data:`~thermobearing.lubricant_properties.THERMAL_TEMPERATURE_RANGE`: Cragoe,
      0-200 degC, NBS Misc. Publ. 97).

    Laws without a numeric range (a constant c_p, a given alpha, an isothermal oil) do not
    end it. Returns a :class:`DataRange`; the viscosity ends are found by a 5 K scan of
    150-900 K refined by bisection."""
    ends: list[tuple[float, str, str]] = []   # (temperature, "low"/"high", reason)
    if getattr(lubricant, "viscosity_law", None) == "astm_d341":
        t = _crossing(lubricant.kinematic_viscosity, _D341_MAX_NU)
        if t is not None:
            ends.append((t, "low", "the ASTM D341 viscosity law, stated up to 1e6 cSt "
                                    "(colder: below the pour point)"))
        t = _crossing(lubricant.kinematic_viscosity, _D341_MIN_NU)
        if t is not None:
            ends.append((t, "high", "the ASTM D341 viscosity law, stated down to 0.21 cSt"))
    fit = getattr(lubricant, "alpha_correlation", None)
    if fit in ALPHA_FIT_VISCOSITY_RANGE:
        eta_lo, eta_hi = ALPHA_FIT_VISCOSITY_RANGE[fit]
        data = (f"the pressure-viscosity fit {fit}, whose data span {eta_lo * 1e3:g}-"
                f"{eta_hi * 1e3:g} mPa s")
        t = _crossing(lubricant.dynamic_viscosity, eta_hi)
        if t is not None:
            ends.append((t, "low", data))
        t = _crossing(lubricant.dynamic_viscosity, eta_lo)
        if t is not None:
            ends.append((t, "high", data))
    thermal = getattr(lubricant, "thermal_model", None)
    if thermal in THERMAL_TEMPERATURE_RANGE:
        t_lo, t_hi = THERMAL_TEMPERATURE_RANGE[thermal]
        stated = (f"the {thermal} c_p and k, stated for {t_lo - 273.15:g}-"
                  f"{t_hi - 273.15:g} degC")
        ends.append((t_lo, "low", stated))
        ends.append((t_hi, "high", stated))
    lows = [e for e in ends if e[1] == "low"]
    highs = [e for e in ends if e[1] == "high"]
    low = max(lows, default=(-math.inf, "low", ""))
    high = min(highs, default=(math.inf, "high", ""))
    return DataRange(low[0], high[0], low[2], high[2])


def outside_data_note(lubricant: Any, field: str, temperatures: float | Sequence[float],
                      data_range: DataRange | None = None) -> str | None:
    """A note naming the ``temperatures`` [K] of the scene field ``field`` (one value or
    several, e.g. a sweep's) that lie outside :func:`data_temperature_range` of
    ``lubricant`` (computed unless ``data_range`` is given), None when none does, e.g.
    ``supply.inlet_temperature = 200 degC is outside the temperatures ISO_VG46's property
    data cover, 0 to 146 degC (...): the results extrapolate its data there``."""
    rng = data_range if data_range is not None else data_temperature_range(lubricant)
    values = [temperatures] if isinstance(temperatures, (int, float)) else temperatures
    outside = sorted({float(t) for t in values if not rng.contains(float(t))})
    if not outside:
        return None
    name = getattr(lubricant, "name", "the oil")
    shown = ", ".join(f"{t - 273.15:.4g}" for t in outside)
    verb = "is" if len(outside) == 1 else "are"
    return (f"{field} = {shown} degC {verb} outside the temperatures {name}'s property "
            f"data cover, {rng.text()}: the results extrapolate its data there")
