"""Hertz contact: elliptical point contact (exact and closed-form) and line contact.

Conventions (contract): ``effective_modulus`` is E' = 2 / ((1-v1^2)/E1 + (1-v2^2)/E2) (Hamrock's,
twice Johnson's E*). Reduced radii R_x (rolling direction) and R_y (transverse). The contact
ellipse has semi-major axis ``a`` and semi-minor axis ``b``; for R_y >= R_x (every ball-raceway
contact) ``a`` lies along y (transverse, along the groove) and ``b`` along x (rolling); if
R_x > R_y (e.g. some roller-end/rib contacts) the major axis lies along x instead.
Ellipticity k = a/b >= 1.

Exact solution (Hamrock & Brewe 1983; Harris & Kotzalas 2007 vol. 1, Hertz contact chapter):
with the radius ratio alpha_r = R_big/R_small, k solves

    alpha_r = (k^2 E(m) - K(m)) / (K(m) - E(m)),     m = 1 - 1/k^2          (ellipticity eq.)

(K, E the complete elliptic integrals of the first and second kind with parameter m,
:func:`scipy.special.ellipk`, :func:`scipy.special.ellipe`), and with
R = 1/(1/R_x + 1/R_y):

    a = (6 k^2 E W R / (pi E'))^(1/3),   b = (6 E W R / (pi k E'))^(1/3),
    delta = K (9/(2 E R) (W/(pi k E'))^2)^(1/3),   p_max = 3 W / (2 pi a b).

Closed form of Hamrock & Brewe (1983): k = alpha_r^(2/pi), E = 1 + (pi/2 - 1)/alpha_r,
K = pi/2 + (pi/2 - 1) ln(alpha_r). The older Brewe & Hamrock (1977) fits (k = 1.0339
alpha_r^0.636, E = 1.0003 + 0.5968/alpha_r, K = 1.5277 + 0.6023 ln alpha_r), used by paper 003
eqs. 7-9, are available as ``method="brewe_hamrock_1977"``.

Measured errors against the exact solution over 1 <= R_y/R_x <= 100 (tests/unit/test_hertz.py):
Hamrock-Brewe 1983: a 2.6 %, b 1.2 %, p_max 1.7 %, approach 4.1 % (at 100; 3 % up to 50),
k 3.7 % (near 10). Brewe-Hamrock 1977 fits: a 4.2 %, b 2.0 %, p_max 2.2 %, approach 5.4 % (at
R_y/R_x = 1), k 6.3 % (at 100).

Line contact (Hamrock, Schmid & Jacobson 2004 ch. 17; Johnson 1985 section 4.2): load per unit
length w' = W / l, half-width b = (8 w' R_x / (pi E'))^(1/2), p_max = 2 w'/(pi b) = E' b / (4 R_x).
Approach of a roller between two races: Palmgren's empirical steel formula
delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N; Palmgren 1959, as quoted by Harris & Kotzalas 2007), i.e.
Q = K_l delta^(10/9) with K_l = 8.06e4 l^(8/9) (N, mm).
"""

from __future__ import annotations

import functools
import math
import warnings
from typing import Any, NamedTuple

import numba
import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk, ellipkm1

from .errors import ConvergenceError, InputError, ValidityWarning, as_floats, check_positive

__all__ = [
    "HERTZ_SMALL_CONTACT", "POINT_METHODS", "LineContact", "PointContact", "SlicedRollerContact",
    "crown_drop", "ellipticity", "ellipticity_residual", "line_contact", "line_contact_stiffness",
    "palmgren_approach", "point_contact", "point_contact_stiffness", "sliced_roller_contact",
]

POINT_METHODS = ("exact", "hamrock_brewe", "brewe_hamrock_1977")
_Q = math.pi / 2.0 - 1.0
_STEEL_E_PRIME = 2.28e11  # E' of a steel-steel pair [Pa]: E = 207.5 GPa, v = 0.3


class PointContact(NamedTuple):
    """Elliptical Hertz contact (arrays broadcast over the load).

    a : semi-major axis [m]; b : semi-minor axis [m]; max_pressure : p_0 [Pa];
    approach : mutual approach of distant points delta [m]; ellipticity : k = a/b [-];
    first_kind, second_kind : complete elliptic integrals K, E used [-].
    """

    a: Any
    b: Any
    max_pressure: Any
    approach: Any
    ellipticity: Any
    first_kind: Any
    second_kind: Any


class LineContact(NamedTuple):
    """Line (or crowned-roller) contact.

    half_width : b [m] in the rolling direction; max_pressure : p_0 [Pa]; approach : delta [m];
    contact_length : loaded length [m] (the effective length, or 2a of the elliptical contact of
    a crowned roller at light load); point_regime : True where the crowned contact is still
    elliptical (2a < l).
    """

    half_width: Any
    max_pressure: Any
    approach: Any
    contact_length: Any
    point_regime: Any


# ---------------------------------------------------------------------------
# ellipticity
# ---------------------------------------------------------------------------
#: below this parameter m = 1 - 1/k^2 the ellipticity equation is evaluated by its series
_SERIES_M = 0.05


def _radius_ratio_series(m: float) -> float:
    """alpha_r(k) = (k^2 E - K)/(K - E) for small m = 1 - 1/k^2, cancellation-free.

    With K = (pi/2) sum c_n^2 m^n, E = (pi/2) sum c_n^2 m^n / (1 - 2n), c_n = (2n)!/(4^n n!^2)
    (Abramowitz & Stegun 17.3.11-12): k^2 E - K = (E - (1 - m) K)/(1 - m) and K - E have
    vanishing m^0 terms, which the series drops exactly:
    alpha_r = sum_{n>=1} (c_n^2 (1/(1-2n) - 1) + c_{n-1}^2) m^(n-1)
              / ((1 - m) sum_{n>=1} c_n^2 (2n/(2n-1)) m^(n-1)) -> 1 + 3m/4 as m -> 0.
    """
    num = 0.0
    den = 0.0
    c_prev2 = 1.0          # c_0^2
    power = 1.0            # m^(n-1)
    for n in range(1, 80):
        c2 = c_prev2 * ((2.0 * n - 1.0) / (2.0 * n)) ** 2
        num += (c2 * (1.0 / (1.0 - 2.0 * n) - 1.0) + c_prev2) * power
        den += c2 * (2.0 * n / (2.0 * n - 1.0)) * power
        c_prev2 = c2
        power *= m
        if power < 1e-18:
            break
    return num / ((1.0 - m) * den)


#: above this ellipticity K(m) is evaluated from the complementary parameter 1/k^2
_LONG_K = 1e4


def _first_kind(k: Any) -> Any:
    """K(m) at m = 1 - 1/k^2 [-]; from p = 1/k^2 by scipy's ellipkm1 for k > 1e4, where m
    rounds towards 1 (k > 1e8: m == 1, K = inf, and radius ratios above 1e13 gave NaN)."""
    k = np.asarray(k, dtype=float)
    p = 1.0 / k**2
    return np.where(k > _LONG_K, ellipkm1(p), ellipk(1.0 - p))[()]


def ellipticity_residual(k: float, radius_ratio: float) -> float:
    """Residual of the exact ellipticity equation, (k^2 E - K) - alpha_r (K - E) (scaled).

    Divided by (K - E) so that the residual is alpha_r(k) - alpha_r [-]. Near a circle
    (m = 1 - 1/k^2 < 0.05) by the series of :func:`_radius_ratio_series`: the closed form
    divides two differences that vanish with m (relative round-off eps/m), which put a
    noise of 1.4e-7 on alpha_r at k = 1 + 1e-9 and made radius ratios 1 + 1.4e-7 .. 1 + 3.3e-6
    fail their 1e-10 residual check (ConvergenceError).
    """
    m = 1.0 - 1.0 / k**2
    if m < _SERIES_M:
        return _radius_ratio_series(m) - radius_ratio
    big_k, big_e = float(_first_kind(k)), float(ellipe(m))
    return (k**2 * big_e - big_k) / (big_k - big_e) - radius_ratio


@functools.lru_cache(maxsize=4096)
def _exact_k(radius_ratio: float) -> float:
    if radius_ratio - 1.0 < 1e-12:
        return 1.0
    # alpha_r(k) is monotonic increasing with alpha_r(1+) = 1; bracket k in (1, ~alpha_r]
    lo = 1.0 + 1e-13
    if ellipticity_residual(lo, radius_ratio) >= 0.0:  # ratio within 1.5e-13 of a circle
        return 1.0
    hi = max(2.0, radius_ratio ** (2.0 / math.pi) * 1.5)
    while ellipticity_residual(hi, radius_ratio) < 0.0:
        hi *= 2.0
        if hi > 1e8:
            raise ConvergenceError("hertz ellipticity", radius_ratio,
                                   "no bracket for the ellipticity", {"ratio": radius_ratio})
    k = brentq(ellipticity_residual, lo, hi, args=(radius_ratio,), xtol=1e-15, rtol=1e-15,
               maxiter=200)
    res = ellipticity_residual(k, radius_ratio)
    if abs(res) > 1e-10 * radius_ratio:
        raise ConvergenceError("hertz ellipticity", abs(res), "ellipticity equation",
                               {"ratio": radius_ratio, "k": k})
    return float(k)


def _exact_k_vectorised(ratio: np.ndarray) -> np.ndarray:
    """Vectorised Newton solve of the ellipticity equation (bracketed fallback per entry).

    Start: the Brewe-Hamrock fit k0 = 1.0339 alpha^0.636 (within about 6 % of the root for
    1 <= alpha <= 100). d alpha/dk from dK/dm = (E - (1-m) K)/(2 m (1-m)), dE/dm = (E - K)/(2m),
    dm/dk = 2/k^3. Entries that are near-circular (alpha < 1.001) or do not reach the 1e-10
    residual in 30 steps are solved by :func:`_exact_k` (brentq).
    """
    out = np.ones_like(ratio, dtype=float)
    work = ratio >= 1.001
    if np.any(work):
        r = ratio[work]
        k = np.maximum(1.0339 * r**0.636, 1.0 + 1e-6)
        # iterates of very long ellipses may overflow (k^3 beyond 1e308): those entries
        # end non-finite and go to the bracketed solve below
        with np.errstate(over="ignore", invalid="ignore"):
            k, res = _newton_k(k, r)
        sub = out[work]
        sub[:] = k
        bad = ~(np.abs(res) <= 1e-10 * r)
        if np.any(bad):
            sub[bad] = [_exact_k(float(x)) for x in r[bad]]
        out[work] = sub
    near = (ratio > 1.0 + 1e-12) & ~work
    if np.any(near):
        out[near] = [_exact_k(float(x)) for x in ratio[near]]
    return out


def _newton_k(k: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Newton iterations of :func:`_exact_k_vectorised` from ``k``: (k, residual)."""
    res = np.full_like(r, np.inf)
    for _ in range(30):
        m = 1.0 - 1.0 / k**2
        # 1 - m from 1/k^2 where m rounds towards 1 (long ellipses, _first_kind)
        one_m = np.where(k > _LONG_K, 1.0 / k**2, 1.0 - m)
        big_k, big_e = _first_kind(k), ellipe(m)
        diff = big_k - big_e
        alpha = (k**2 * big_e - big_k) / diff
        res = alpha - r
        if np.all(np.abs(res) <= 1e-12 * r):
            break
        dk_dm = (big_e - one_m * big_k) / (2.0 * m * one_m)
        de_dm = (big_e - big_k) / (2.0 * m)
        dm_dk = 2.0 / k**3
        num_d = 2.0 * k * big_e + k**2 * de_dm * dm_dk - dk_dm * dm_dk
        den_d = (dk_dm - de_dm) * dm_dk
        dalpha = (num_d * diff - (k**2 * big_e - big_k) * den_d) / diff**2
        step = res / dalpha
        k = np.maximum(k - step, 0.5 * (k + 1.0))  # never step below the circle
    return k, res


def ellipticity(radius_ratio: Any, method: str = "exact") -> tuple[Any, Any, Any]:
    """(k, K, E) for a radius ratio alpha_r = R_big/R_small >= 1 (vectorised).

    ``method``: "exact" (solves the ellipticity equation to 1e-10 relative), "hamrock_brewe"
    (1983 closed form) or "brewe_hamrock_1977" (curve fits).
    """
    ratio = np.asarray(radius_ratio, dtype=float)
    if np.any(~np.isfinite(ratio)) or np.any(ratio < 1.0 - 1e-12):
        raise InputError("radius_ratio", radius_ratio, "finite values >= 1 (R_big/R_small)")
    ratio = np.maximum(ratio, 1.0)
    if np.any(ratio > 1e200):  # k^2 overflows beyond (k ~ 1e101 at 1e200)
        raise InputError("radius_ratio", float(np.max(ratio)),
                         "a ratio <= 1e200 (a longer contact is a line contact: line_contact)")
    if method == "exact":
        ks = _exact_k_vectorised(ratio.ravel()).reshape(ratio.shape)
        m = 1.0 - 1.0 / ks**2
        return ks[()], np.asarray(_first_kind(ks))[()], ellipe(m)[()]
    if method == "hamrock_brewe":
        k, big_k, big_e = _hamrock_brewe_kke(ratio)
        return k[()], big_k[()], big_e[()]
    if method == "brewe_hamrock_1977":
        k = 1.0339 * ratio**0.636
        return (np.maximum(k, 1.0)[()], (1.5277 + 0.6023 * np.log(ratio))[()],
                (1.0003 + 0.5968 / ratio)[()])
    raise InputError("method", method, "one of " + ", ".join(POINT_METHODS))


def _hamrock_brewe_kke(ratio: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(k, K, E) of the Hamrock-Brewe 1983 closed form for radius ratios >= 1 (unchecked)."""
    k = ratio ** (2.0 / math.pi)
    return k, math.pi / 2 + _Q * np.log(ratio), 1.0 + _Q / ratio


# ---------------------------------------------------------------------------
# point contact
# ---------------------------------------------------------------------------
def _ellipse(w: np.ndarray, r: np.ndarray, k: np.ndarray, big_e: np.ndarray,
             ep: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Semi-axes a, b [m] and p_max [Pa] (0 at zero load) from W, R, k, E (unchecked)."""
    a = np.cbrt(6.0 * k**2 * big_e * w * r / (math.pi * ep))
    b = np.cbrt(6.0 * big_e * w * r / (math.pi * k * ep))
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.where(w > 0, 3.0 * w / (2.0 * math.pi * np.where(w > 0, a * b, 1.0)), 0.0)
    return a, b, p


@numba.njit(cache=True)
def _hamrock_brewe_point_nb(rx: float, ry: float, ep: float
                            ) -> tuple[float, float, float, float]:
    """Compiled scalar fast path (unchecked; rx, ry, ep > 0) of the Hamrock-Brewe 1983
    closed form used by :func:`_hamrock_brewe_kke` / :func:`_stiffness_from`: returns
    (R [m], k [-], E [-], K [N/m^1.5]) with 1/R = 1/rx + 1/ry, k = (R_big/R_small)^(2/pi),
    E = 1 + (pi/2 - 1)/ratio, script-K = pi/2 + (pi/2 - 1) ln(ratio) and
    K = pi k E' (2 E R / (9 script-K^3))^(1/2) (Q = K delta^1.5). For compiled callers
    (the ball skidding residual); the public functions are unchanged."""
    r = 1.0 / (1.0 / rx + 1.0 / ry)
    ratio = max(rx, ry) / min(rx, ry)
    k = ratio ** (2.0 / math.pi)
    big_k = math.pi / 2 + _Q * math.log(ratio)
    big_e = 1.0 + _Q / ratio
    return r, k, big_e, math.pi * k * ep * math.sqrt(2.0 * big_e * r / (9.0 * big_k**3))


@numba.njit(cache=True)
def _ellipse_nb(w: float, r: float, k: float, big_e: float,
                ep: float) -> tuple[float, float, float]:
    """Compiled scalar fast path of :func:`_ellipse` for compiled callers:
    a = (6 k^2 E W R / (pi E'))^(1/3), b = (6 E W R / (pi k E'))^(1/3) [m],
    p_max = 3 W / (2 pi a b) [Pa] (0 at zero load); unchecked (W >= 0)."""
    a = np.cbrt(6.0 * k**2 * big_e * w * r / (math.pi * ep))
    b = np.cbrt(6.0 * big_e * w * r / (math.pi * k * ep))
    p = 3.0 * w / (2.0 * math.pi * (a * b)) if w > 0 else 0.0
    return a, b, p


def _stiffness_from(r: Any, k: Any, big_k: Any, big_e: Any, ep: Any) -> Any:
    """K = pi k E' (2 E R / (9 K^3))^(1/2) [N/m^1.5] (unchecked)."""
    return math.pi * k * ep * np.sqrt(2.0 * big_e * r / (9.0 * big_k**3))


def _reduced_unchecked(rx: Any, ry: Any) -> tuple[Any, Any]:
    r = 1.0 / (1.0 / rx + 1.0 / ry)
    ratio = np.maximum(rx, ry) / np.minimum(rx, ry)
    return r, ratio


def _reduced(rx: Any, ry: Any) -> tuple[np.ndarray, np.ndarray]:
    rx_a = as_floats("rx", rx)
    ry_a = as_floats("ry", ry)
    check_positive("rx", rx_a)
    if np.any(np.isnan(ry_a)) or np.any(ry_a <= 0):
        raise InputError("ry", ry, "a value > 0 (inf for a cylinder)")
    return _reduced_unchecked(rx_a, ry_a)


def point_contact(load: Any, rx: Any, ry: Any, effective_modulus: Any,
                  method: str = "exact") -> PointContact:
    """Hertz elliptical contact of two bodies with reduced radii ``rx``, ``ry``.

    Parameters
    ----------
    load : normal load W [N] (>= 0; 0 gives zeros), any shape.
    rx, ry : reduced radii of curvature [m] in the rolling and transverse directions
        (1/R_x = 1/r_ax + 1/r_bx ...; both finite, > 0).
    effective_modulus : E' [Pa] (Hamrock convention).
    method : "exact" | "hamrock_brewe" | "brewe_hamrock_1977".

    Returns
    -------
    PointContact(a, b, max_pressure, approach, ellipticity, first_kind, second_kind).

    Notes
    -----
    Validity: linear elastic half-spaces, contact small against the radii, frictionless; a
    ValidityWarning when the half-width along x exceeds :data:`HERTZ_SMALL_CONTACT` R_x.
    References: Hamrock & Brewe 1983 (``hamrock_brewe1983``); Harris & Kotzalas 2007.
    """
    w = as_floats("load", load)
    check_positive("load", w, allow_zero=True)
    check_positive("effective_modulus", effective_modulus)
    if np.any(np.isinf(as_floats("rx", rx))) or np.any(np.isinf(as_floats("ry", ry))):
        raise InputError("ry", ry, "finite radii (use line_contact for a cylinder)")
    r, ratio = _reduced(rx, ry)
    k, big_k, big_e = ellipticity(ratio, method)
    ep = np.asarray(effective_modulus, dtype=float)
    a, b, p = _ellipse(w, r, k, big_e, ep)
    delta = big_k * np.cbrt(9.0 / (2.0 * big_e * r) * (w / (math.pi * k * ep)) ** 2)
    _warn_large_contact(np.where(np.asarray(rx) <= np.asarray(ry), b, a), rx, "point_contact")
    k_b = np.broadcast_to(k, np.shape(a)) if np.ndim(a) else k
    return PointContact(a[()], b[()], p[()], delta[()], np.asarray(k_b)[()],
                        np.broadcast_to(big_k, np.shape(a))[()] if np.ndim(a) else big_k,
                        np.broadcast_to(big_e, np.shape(a))[()] if np.ndim(a) else big_e)


def point_contact_stiffness(rx: Any, ry: Any, effective_modulus: Any,
                            method: str = "exact") -> Any:
    """Load-deflection constant K [N/m^1.5] with Q = K delta^1.5.

    K = pi k E' (2 E R / (9 K^3))^(1/2) (Hamrock & Brewe 1983; inverse of ``approach``).
    """
    check_positive("effective_modulus", effective_modulus)
    r, ratio = _reduced(rx, ry)
    k, big_k, big_e = ellipticity(ratio, method)
    out = _stiffness_from(r, k, big_k, big_e, np.asarray(effective_modulus, dtype=float))
    return np.asarray(out)[()]


# ---------------------------------------------------------------------------
# line contact
# ---------------------------------------------------------------------------
def palmgren_approach(load: Any, length: Any) -> Any:
    """Roller-raceway approach [m], delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N), steel on steel.

    Palmgren (1959) as quoted by Harris & Kotzalas 2007 vol. 1; valid for steel rollers
    and rings (E' about 2.28e11 Pa).
    """
    q = np.asarray(load, dtype=float)
    check_positive("load", q, allow_zero=True)
    check_positive("length", length)
    l_mm = np.asarray(length, dtype=float) * 1e3
    return (3.84e-5 * q**0.9 / l_mm**0.8 * 1e-3)[()]


def line_contact_stiffness(length: Any, effective_modulus: Any = _STEEL_E_PRIME) -> Any:
    """K_l [N/m^(10/9)] with Q = K_l delta^(10/9) from Palmgren's approach formula.

    K_l = 8.06e4 l^(8/9) in N, mm (Palmgren 1959 via Harris & Kotzalas 2007), converted to SI.
    Steel only: a different E' warns (:class:`ValidityWarning`) and is not corrected for.
    """
    check_positive("length", length)
    _warn_not_steel(effective_modulus)
    l_mm = np.asarray(length, dtype=float) * 1e3
    # Q = (delta_mm l_mm^0.8 / 3.84e-5)^(10/9), delta_mm = 1e3 delta_m
    return ((1e3 * l_mm**0.8 / 3.84e-5) ** (10.0 / 9.0))[()]


#: largest contact half-width in the rolling direction relative to the reduced radius R_x
#: for which the half-space (small-contact) assumption of Hertz is taken to hold. Hertz
#: requires the contact to be small against the radii (Johnson 1985 section 4.1: a << R);
#: 0.1 is this package's chosen guard, not a published bound. Bearing contacts reach it only
#: far beyond their ratings (SKF6304: ~15 kN on one ball, p_0 ~ 5.5 GPa).
HERTZ_SMALL_CONTACT = 0.1


def _warn_large_contact(half_width_x: Any, rx: Any, where: str) -> None:
    """ValidityWarning when the half-width along x exceeds HERTZ_SMALL_CONTACT R_x."""
    ratio = np.asarray(half_width_x, dtype=float) / np.asarray(rx, dtype=float)
    if np.any(ratio > HERTZ_SMALL_CONTACT):
        warnings.warn(
            f"{where}: contact half-width {float(np.max(ratio)):.3g} R_x is not small against "
            f"the radius (Hertz's half-space assumption; guard {HERTZ_SMALL_CONTACT} R_x): the "
            "load is far beyond the elastic small-contact range", ValidityWarning,
            stacklevel=3)


def _warn_not_steel(effective_modulus: Any) -> None:
    ep = np.asarray(effective_modulus, dtype=float)
    if np.any(np.abs(ep / _STEEL_E_PRIME - 1.0) > 0.15):
        warnings.warn(
            f"Palmgren's roller approach is an empirical steel-steel law; E' = "
            f"{float(np.max(ep)):.3g} Pa differs from steel ({_STEEL_E_PRIME:.3g} Pa)",
            ValidityWarning, stacklevel=3)


def line_contact(load: Any, length: Any, rx: Any, effective_modulus: Any, *,
                 crown_radius: float | None = None) -> LineContact:
    """Hertz line contact of a roller of effective ``length`` (optionally crowned).

    Parameters
    ----------
    load : normal load Q [N] (>= 0), any shape.
    length : effective (straight) contact length l [m].
    rx : reduced radius in the rolling direction [m].
    effective_modulus : E' [Pa].
    crown_radius : axial crown radius of a fully crowned roller [m] (None: straight). A
        crowned contact is elliptical (point contact with R_y = crown_radius) while its major
        axis 2a is shorter than ``length``. At higher load the contact is truncated at the
        roller ends, which neither formula describes: the untruncated ellipse under-states
        its pressure, half-width and approach (it spreads the load over more length) and so
        does the straight line contact (no crown drop); the result takes the larger p_0,
        the larger half-width b and the larger approach of the two, lower bounds that rise
        with the load (the line contact alone jumped down where 2a reaches ``length``, by
        18 % in p_0 and b and 32 % in the approach) and become the line contact's at 3-5x
        that load. p_0 and b are continuous there; the approach steps up where Palmgren's
        empirical approach exceeds the Hertz one (10 % at l = 4 mm, R_x = 20 mm, R_c = 50 mm,
        19 % with R_c = 30 mm).
        Edge stresses of a partially crowned roller are not modelled.

    Returns
    -------
    LineContact(half_width, max_pressure, approach, contact_length, point_regime)

    Notes
    -----
    b = (8 w' R_x/(pi E'))^(1/2), p_0 = 2 w'/(pi b), w' = Q/l (Hamrock et al. 2004, ch. 17;
    Johnson 1985 section 4.2). The approach is Palmgren's steel formula (see
    :func:`palmgren_approach`); the elastic approach of a 2-D line contact is not defined
    without the body sizes.
    """
    q = as_floats("load", load)
    check_positive("load", q, allow_zero=True)
    check_positive("length", length)
    check_positive("rx", rx)
    check_positive("effective_modulus", effective_modulus)
    length_a = np.asarray(length, dtype=float)
    ep = np.asarray(effective_modulus, dtype=float)
    rx_a = np.asarray(rx, dtype=float)
    w_line = q / length_a
    b = np.sqrt(8.0 * w_line * rx_a / (math.pi * ep))
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.where(q > 0, 2.0 * w_line / (math.pi * np.where(q > 0, b, 1.0)), 0.0)
    delta = palmgren_approach(q, length_a)
    contact_len = np.broadcast_to(length_a, np.shape(b)).astype(float)
    point_regime = np.zeros(np.shape(b), dtype=bool)
    if crown_radius is not None:
        check_positive("crown_radius", crown_radius)
        pc = point_contact(q, rx_a, crown_radius, ep)
        point_regime = np.asarray((2.0 * pc.a < length_a) & (q > 0))
        # beyond the switch the untruncated ellipse and the straight line contact both
        # under-state the truncated crowned contact (less area than the ellipse, a
        # crowned profile against a straight one): the larger of the two, continuous at
        # the switch (the line values alone fell there by 18 % in p_0 and b, 32 % in delta)
        b = np.where(point_regime, pc.b, np.maximum(b, pc.b))
        p = np.where(point_regime, pc.max_pressure, np.maximum(p, pc.max_pressure))
        delta = np.where(point_regime, pc.approach, np.maximum(delta, pc.approach))
        contact_len = np.where(point_regime, 2.0 * pc.a, contact_len)
    _warn_large_contact(b, rx_a, "line_contact")
    _warn_not_steel(ep)
    return LineContact(np.asarray(b)[()], np.asarray(p)[()], np.asarray(delta)[()],
                       np.asarray(contact_len)[()], np.asarray(point_regime)[()])


class SlicedRollerContact(NamedTuple):
    """Slice solution of a (partially) crowned roller on a raceway.

    approach : delta [m] at the roller centre plane; slice_centres : x_k [m] along the roller
    axis; slice_loads : q_k [N] (shape load.shape + (n,)); max_line_load : max q_k / w [N/m];
    max_pressure : p_0 of the most loaded slice from the line-contact formula [Pa];
    loaded_length : total width of the slices in contact [m].
    """

    approach: Any
    slice_centres: Any
    slice_loads: Any
    max_line_load: Any
    max_pressure: Any
    loaded_length: Any


def crown_drop(x: Any, straight_length: float, crown_radius: float | None) -> Any:
    """Profile drop [m] of a roller with a straight middle of ``straight_length`` and circular
    end crowns of radius ``crown_radius``: 0 for |x| <= l_s/2, (|x| - l_s/2)^2 / (2 R_c) beyond."""
    over = np.maximum(np.abs(np.asarray(x, dtype=float)) - 0.5 * straight_length, 0.0)
    if crown_radius is None:
        return np.where(over > 0, np.inf, 0.0)
    return over**2 / (2.0 * crown_radius)


def sliced_roller_contact(load: Any, total_length: float, straight_length: float,
                          crown_radius: float | None, rx: float, effective_modulus: float,
                          n_slices: int = 41) -> SlicedRollerContact:
    """Load-approach of a partially crowned roller by slicing (no tilt, no edge stress).

    The roller length ``total_length`` is cut into ``n_slices`` slices of width w; slice k at
    x_k carries q_k = (w / L) K_l(L) (delta - c(x_k))^(10/9) with c the crown drop
    (:func:`crown_drop`), L the total length and K_l Palmgren's roller constant
    (:func:`line_contact_stiffness`), so that a straight roller (l_s = L) reproduces Palmgren's
    law exactly (Palmgren's l^(8/9) length dependence is frozen at L); delta solves
    sum q_k = Q. Slices are elastically uncoupled (the usual slicing assumption, Harris &
    Kotzalas 2007 vol. 2), so edge stress concentrations are not resolved. The most loaded
    slice's pressure is the line-contact p_0 at its load per unit width.

    Parameters: load Q [N] (>= 0, any shape), total_length [m], straight_length [m] (<= total),
    crown_radius [m] (None: straight roller cut off at ``straight_length``), rx [m],
    effective_modulus E' [Pa], n_slices (an integer >= 5, odd or even: the slices are
    centred at x_k = (k + 1/2) w - L/2; an odd count puts the middle slice at x = 0, so a
    straight part shorter than a slice still carries the load, where an even count has no
    slice on it and an uncrowned roller is refused naming straight_length).
    """
    q = np.asarray(load, dtype=float)
    check_positive("load", q, allow_zero=True)
    check_positive("total_length", total_length)
    check_positive("straight_length", straight_length)
    if straight_length > total_length:
        raise InputError("straight_length", straight_length,
                         f"a value <= total_length = {total_length:.6g} m")
    if crown_radius is not None:
        check_positive("crown_radius", crown_radius)
    check_positive("rx", rx)
    check_positive("effective_modulus", effective_modulus)
    if isinstance(n_slices, bool) or not isinstance(n_slices, int) or n_slices < 5:
        raise InputError("n_slices", n_slices, "an integer >= 5")
    w = total_length / n_slices
    x = (np.arange(n_slices) + 0.5) * w - 0.5 * total_length
    c = crown_drop(x, straight_length, crown_radius)
    if crown_radius is None:
        # an uncrowned roller: a slice carries load when its centre is on the straight part,
        # a centre on its end within round-off (l_s / 2 = (k + 1/2) w) included; the bare
        # comparison in crown_drop let the round-off of x and l_s / 2 decide whether the two
        # end slices carried load (10 slices, l_s = 0.3 L: 3 slices loaded at one size, one
        # end slice in and the other out, 4 at another: approach (4/3)^0.9 = 1.30 times)
        c = np.where(np.abs(x) <= 0.5 * straight_length + 1e-12 * total_length, 0.0, np.inf)
    k_slice = float(line_contact_stiffness(total_length, effective_modulus)) * (
        w / total_length)
    finite = np.isfinite(c)

    def total(delta: float) -> float:
        return float(np.sum(k_slice * np.maximum(delta - c[finite], 0.0) ** (10.0 / 9.0)))

    if not np.any(finite):
        raise InputError("straight_length", straight_length,
                         f"a value that puts at least one of the {n_slices} slice centres "
                         f"(spacing {w:.6g} m) on the straight part of an uncrowned roller, "
                         "or an odd n_slices (its middle slice is at x = 0)")
    c_min = float(np.min(c[finite]))
    n_min = int(np.count_nonzero(c == c_min))
    flat = q.ravel()
    deltas = np.zeros_like(flat)
    for i, qi in enumerate(flat):
        if qi <= 0.0:
            continue
        # the slices at the smallest drop alone carry qi at this approach: total(hi) >= qi
        hi = c_min + (qi / (k_slice * n_min)) ** 0.9
        while total(hi) < qi:
            hi *= 2.0
        deltas[i] = brentq(lambda d, qi=qi: total(d) - qi, 0.0, hi, xtol=1e-300,
                           rtol=1e-14)
    delta = deltas.reshape(q.shape)
    gap = np.where(finite, np.maximum(delta[..., None] - np.where(finite, c, 0.0), 0.0), 0.0)
    slices = k_slice * gap ** (10.0 / 9.0)
    q_line_max = np.max(slices, axis=-1) / w
    b = np.sqrt(8.0 * q_line_max * rx / (math.pi * effective_modulus))
    with np.errstate(divide="ignore", invalid="ignore"):
        p0 = np.where(q_line_max > 0, 2.0 * q_line_max / (math.pi * np.where(b > 0, b, 1.0)),
                      0.0)
    loaded = np.count_nonzero(slices > 0, axis=-1) * w
    return SlicedRollerContact(delta[()], x, slices[()], q_line_max[()], p0[()], loaded[()])
