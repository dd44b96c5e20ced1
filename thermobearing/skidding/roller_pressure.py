"""Film pressure over the Hertz zone of a roller-raceway line contact, by lubrication regime.

One job: the pressure under which the Hertz-zone oil is sheared (its viscosity eta(p) sets the
Couette force of paper 000 eq. 5 / 33-34, Li et al. 2018, seed ``000_3b5ca6eed61dd596.txt``
[li2018_nu214_skidding]), for the option ``build_model(..., film_pressure="regime_min")`` of
the roller skidding solver.

The closed-form drag (:mod:`thermobearing.skidding.roller_fluid`) shears the Hertz zone
|x| < b at the semi-elliptic Hertz pressure. That is the pressure of an elastohydrodynamic
contact (Moes M >> 1). In the rigid regime (M < ~1: light loads, thick films, e.g. paper 000's
NU214 at 100-200 N, M ~ 0.1) the elastic flattening is much smaller than the film, the
pressure spreads over the rigid length sqrt(2 R h0) >> b and peaks far below p_H (paper 000's
own eqs. 7-11 give that pressure at those loads). Shearing the Hertz width at eta(p_H) then
adds a piezoviscous traction that the film does not carry, and it grows faster than the load.

Model: the Hertz-zone pressure keeps its semi-elliptic shape with the peak

    p_peak = min(p_H,  p_rig),   p_rig = 6 eta0 U sqrt(2R) h0^-1.5 Pi(-X*)

the smaller of the Hertz pressure and the peak of the rigid-isoviscous (Martin) pressure of
the same contact, U = u1 + u2, h0 = k_w eta0 U R / w (Martin, k_w = 2.448), Pi the closed-form
rigid-cylinder integral with the Reynolds outlet condition (Martin 1916; Hamrock, Schmid &
Jacobson 2004, ch. 8 [martin1916_gear_lubrication; hamrock2004]; the same closed form as
``roller_fluid._pi_function``), whose maximum is at X = -X*. Per contact, the same choice the
closed-form drag makes for the rolling force (min of rigid-isoviscous and Dowson-Higginson),
continuous where the two peaks are equal. A point-wise minimum of the two profiles would be
wrong in the EHL regime, where the rigid profile is much narrower than the Hertz zone and
vanishes over its outlet half. In the rigid regime the Hertz zone |x| < b lies well inside
the rigid length sqrt(2 R h0), where the rigid pressure is within a factor ~1.3 of its
peak (:func:`rigid_pressure` gives the profile).
x is measured along the entrainment from the
contact centre (the rigid pressure peaks upstream, at X = -X*). SI units.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .roller_fluid import martin_coefficients

#: Hertz-zone pressure models of the roller solver (``build_model(film_pressure=...)``)
FILM_PRESSURE_MODELS = ("hertz", "regime_min")


def _f2(g: np.ndarray) -> np.ndarray:
    return 0.5 * g + 0.25 * np.sin(2.0 * g)


def _f4(g: np.ndarray) -> np.ndarray:
    return 3.0 / 8.0 * g + 0.25 * np.sin(2.0 * g) + np.sin(4.0 * g) / 32.0


def martin_pi(x: Any) -> np.ndarray:
    """Pi(X) = int_{-inf}^{X} (H - H*)/H^3 dX', H = 1 + X^2, flooded inlet, Reynolds outlet
    at X* (0 for X >= X*, cavitated) [-]. With X = tan g the integral is closed form."""
    _, _, _, xs = martin_coefficients()
    hs = 1.0 + xs * xs
    xa = np.asarray(x, dtype=float)
    g = np.arctan(xa)
    g0 = -0.5 * math.pi
    pi = (_f2(g) - _f2(g0)) - hs * (_f4(g) - _f4(g0))
    return np.where(xa < xs, np.maximum(pi, 0.0), 0.0)


def rigid_pressure(x: Any, load_per_length: Any, sum_speed: Any, radius: float,
                   eta0: float) -> np.ndarray:
    """Rigid-isoviscous (Martin) film pressure at x [m] from the centre of the contact.

    p = 6 eta0 U sqrt(2R) h0^-1.5 Pi(x / sqrt(2 R h0)), h0 = k_w eta0 U R / w [Pa];
    load_per_length w [N/m], sum_speed U = u1 + u2 [m/s], radius R [m], eta0 [Pa s]
    (broadcast against x). Its integral over x is w (tested).
    """
    k_w = martin_coefficients()[0]
    w = np.asarray(load_per_length, dtype=float)
    u = np.abs(np.asarray(sum_speed, dtype=float))
    ok = (w > 0.0) & (u > 0.0)
    w_s = np.where(ok, w, 1.0)
    u_s = np.where(ok, u, 1.0)
    h0 = k_w * eta0 * u_s * radius / w_s
    c = np.sqrt(2.0 * radius * h0)
    p = 6.0 * eta0 * u_s * math.sqrt(2.0 * radius) * h0**-1.5 * martin_pi(np.asarray(x) / c)
    return np.where(ok, p, 0.0)


def rigid_peak_pressure(load_per_length: Any, sum_speed: Any, radius: float,
                        eta0: float) -> np.ndarray:
    """Peak of :func:`rigid_pressure` (at X = -X*) [Pa]; same arguments, 0 without load."""
    _, _, _, xs = martin_coefficients()
    k_w = martin_coefficients()[0]
    w = np.asarray(load_per_length, dtype=float)
    u = np.abs(np.asarray(sum_speed, dtype=float))
    ok = (w > 0.0) & (u > 0.0)
    h0 = k_w * eta0 * np.where(ok, u, 1.0) * radius / np.where(ok, w, 1.0)
    peak = 6.0 * eta0 * np.where(ok, u, 1.0) * math.sqrt(2.0 * radius) * h0**-1.5 \
        * float(martin_pi(-xs))
    return np.where(ok, peak, 0.0)


def hertz_zone_pressure(model: str, xb: np.ndarray, max_pressure: Any, half_width: Any,
                        load_per_length: Any, sum_speed: Any, radius: float, eta0: float
                        ) -> np.ndarray:
    """Film pressure at the points x = xb * b of the Hertz zone [Pa], shape (..., len(xb)).

    ``model``: "hertz" (semi-elliptic p_H sqrt(1 - (x/b)^2)) or "regime_min" (the same shape
    with the peak min(p_H, :func:`rigid_peak_pressure`), module docstring). xb in (-1, 1);
    max_pressure p_H [Pa], half_width b [m] (unused by the semi-ellipse, kept for the
    signature), load_per_length [N/m], sum_speed U = u1 + u2 [m/s], radius R_x [m],
    eta0 [Pa s].
    """
    if model not in FILM_PRESSURE_MODELS:
        from ..errors import InputError

        raise InputError("film_pressure", model, FILM_PRESSURE_MODELS)
    p_h = np.asarray(max_pressure, dtype=float)
    if model == "regime_min":
        p_h = np.minimum(p_h, rigid_peak_pressure(load_per_length, sum_speed, radius, eta0))
    return p_h[..., None] * np.sqrt(np.maximum(1.0 - xb**2, 0.0))
