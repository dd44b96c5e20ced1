"""Viscosity laws of lubricants: temperature (ASTM D341 / Walther, Vogel, exponential,
isothermal) and pressure (Barus, Roelands), each a registered, vectorised pure function (SI in,
SI out), plus Roelands' constants and the alpha <-> Roelands-index conversions.
:class:`thermobearing.lubricant.Lubricant` ties a chosen law of each family to one oil; the
names are re-exported by :mod:`thermobearing.lubricant`.

Families (registries):

- ``viscosity_temperature``: ASTM D341 (Walther), Vogel, the exponential (Reynolds) law
  used for oil 4109 in paper 001, and the isothermal model of paper 000.
- ``pressure_viscosity``: Barus and Roelands (paper 000 eq. 9 form).

Units: T [K], p [Pa], nu [m^2/s], eta [Pa s].
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable

import numpy as np

from .errors import (
    InputError,
    ValidityWarning,
    check_finite,
    check_positive,
    check_temperature,
)
from .lubricant_properties import _D341_MAX_NU, _D341_MIN_NU, ArrayLike, _out
from .registry import Registry

VISCOSITY_TEMPERATURE: Registry[Callable[..., ArrayLike]] = Registry(
    "viscosity_temperature", "viscosity of a lubricant vs temperature at atmospheric pressure"
)
PRESSURE_VISCOSITY: Registry[Callable[..., ArrayLike]] = Registry(
    "pressure_viscosity", "viscosity vs pressure at constant temperature"
)

#: Roelands' constants (Roelands 1966; Hamrock 2004 ch. 4): eta_inf = 6.31e-5 Pa s,
#: -ln(eta_inf) = 9.67, p0 = 1.96e8 Pa (1/p0 = 5.1e-9 1/Pa, paper 000 eq. 9).
ROELANDS_LN_ETA_INF = 9.67
ROELANDS_ETA_INF = math.exp(-ROELANDS_LN_ETA_INF)
ROELANDS_P0 = 1.96e8

#: Which quantity each viscosity-temperature law returns.
_VT_OUTPUT = {
    "astm_d341": "kinematic",
    "vogel": "dynamic",
    "exponential": "dynamic",
    "isothermal": "dynamic",
}


# ---------------------------------------------------------------------------
# viscosity vs temperature
# ---------------------------------------------------------------------------
def d341_z(nu_cst: ArrayLike) -> ArrayLike:
    """ASTM D341-09 transformed viscosity Z(nu) = nu + 0.7 + exp(-1.47 - 1.84 nu - 0.51 nu^2).

    ``nu_cst`` in mm^2/s (cSt). The exponential term extends the chart to 0.21 cSt; it is
    below 1e-3 cSt for nu >= 2 cSt. Z is strictly increasing in nu (dZ/dnu >= 0.57).
    Reference: ASTM D341-09, Standard Practice for Viscosity-Temperature Charts.
    """
    nu = np.asarray(nu_cst, dtype=float)
    return _out(nu + 0.7 + np.exp(-1.47 - 1.84 * nu - 0.51 * nu**2))


def d341_inverse_z(z: ArrayLike) -> ArrayLike:
    """Inverse of :func:`d341_z`: nu [cSt] from Z, solved by Newton to machine precision.

    ASTM D341-09 gives an explicit back-transform,
    nu = (Z - 0.7) - exp(-0.7487 - 3.295 (Z-0.7) + 0.6119 (Z-0.7)^2 - 0.3193 (Z-0.7)^3),
    which is only approximately the inverse of the forward transform; it is used here as
    the starting point and refined by Newton so that a D341 fit reproduces its data points
    exactly.
    """
    if type(z) is float:
        return _d341_inverse_z_scalar(z)
    zz = np.asarray(z, dtype=float)
    y = zz - 0.7
    nu = y - np.exp(-0.7487 - 3.295 * y + 0.6119 * y**2 - 0.3193 * y**3)
    nu = np.maximum(nu, 0.0)
    for _ in range(30):
        e = np.exp(-1.47 - 1.84 * nu - 0.51 * nu**2)
        f = nu + 0.7 + e - zz
        df = 1.0 - (1.84 + 1.02 * nu) * e
        step = f / df
        nu = nu - step
        if np.all(np.abs(step) <= 1e-15 * np.maximum(1.0, np.abs(nu))):
            break
    return _out(nu)


def _d341_inverse_z_scalar(z: float) -> float:
    """:func:`d341_inverse_z` for one float: the same start and Newton iteration in plain
    float arithmetic (the transient evaluates the oil viscosity at node temperatures one at
    a time)."""
    y = z - 0.7
    nu = max(y - math.exp(-0.7487 - 3.295 * y + 0.6119 * y**2 - 0.3193 * y**3), 0.0)
    for _ in range(30):
        e = math.exp(-1.47 - 1.84 * nu - 0.51 * nu**2)
        step = (nu + 0.7 + e - z) / (1.0 - (1.84 + 1.02 * nu) * e)
        nu = nu - step
        if abs(step) <= 1e-15 * max(1.0, abs(nu)):
            break
    return nu


@VISCOSITY_TEMPERATURE.register(
    "astm_d341",
    references=["astm_d341"],
    parameters={"A": "-", "B": "-"},
    validity="0.21 cSt <= nu <= 1e6 cSt; liquid petroleum products and most synthetics "
    "between their cloud point and initial boiling point",
    summary="ASTM D341 (Walther): log10 log10 Z = A - B log10 T, Z = nu + 0.7 + ... [cSt, K]",
)
def walther_kinematic_viscosity(T: ArrayLike, A: float, B: float) -> ArrayLike:
    """Kinematic viscosity by ASTM D341 (the Ubbelohde-Walther chart equation).

    .. math:: \\log_{10}\\log_{10} Z = A - B \\log_{10} T,\\qquad
              Z = \\nu + 0.7 + e^{-1.47 - 1.84\\nu - 0.51\\nu^2}

    with nu in cSt and T in K (ASTM D341-09 eq. 1-2; Walther 1931).

    Parameters
    ----------
    T : temperature [K], scalar or array, > 0.
    A, B : chart constants [-] (from :func:`walther_constants`).

    Returns
    -------
    Kinematic viscosity [m^2/s]. Never NaN: T <= 0 raises :class:`InputError`.
    """
    check_temperature("temperature", T)
    if type(T) in (float, int, np.float64):
        z = 10.0 ** (10.0 ** (A - B * math.log10(T)))
        nu = d341_inverse_z(float(z))
        if nu < 0.21:
            warnings.warn(f"ASTM D341 used below 0.21 cSt ({nu:.3g} cSt): outside its range",
                          ValidityWarning, stacklevel=2)
        return nu * 1e-6
    t = np.asarray(T, dtype=float)
    log_log_z = A - B * np.log10(t)
    z = 10.0 ** (10.0**log_log_z)
    nu = np.asarray(d341_inverse_z(z))
    if np.any(nu < 0.21):
        warnings.warn(
            f"ASTM D341 used below 0.21 cSt (min {float(np.min(nu)):.3g} cSt): outside its range",
            ValidityWarning,
            stacklevel=2,
        )
    return _out(nu * 1e-6)


def walther_constants(
    nu1: float, T1: float, nu2: float, T2: float
) -> tuple[float, float]:
    """Constants (A, B) of ASTM D341 through two (T [K], nu [m^2/s]) points.

    Solves log10 log10 Z_i = A - B log10 T_i for i = 1, 2 (two linear equations).
    Raises :class:`InputError` unless both viscosities are within the law's range
    (0.21 to 1e6 cSt), T1 != T2 and the oil thins with temperature (nu at the higher
    temperature is the lower one).
    """
    check_positive("nu1", nu1)
    check_positive("nu2", nu2)
    check_temperature("T1", T1)
    check_temperature("T2", T2)
    if T1 == T2:
        raise InputError("T2", T2, f"a temperature different from T1 = {T1} K")
    for name, nu in (("nu1", nu1), ("nu2", nu2)):
        # log10 log10 Z needs Z > 1: below ~0.3 cSt Z < 1 and math.log10 raised a bare
        # "math domain error" (a lubricant file with nu100 = "1e-9 mm**2/s")
        if not _D341_MIN_NU <= nu <= _D341_MAX_NU:
            raise InputError(name, nu, "a kinematic viscosity within ASTM D341's range, "
                             "0.21 to 1e6 cSt (2.1e-7 to 1 m^2/s)")
    (tl, nl), (th, nh) = sorted([(T1, nu1), (T2, nu2)])
    if not nh < nl:
        raise InputError(
            f"viscosity at {th:g} K",
            nh,
            f"a value below the viscosity at {tl:g} K ({nl:g} m^2/s): oil thins as it heats",
        )
    y1 = math.log10(math.log10(float(d341_z(nu1 * 1e6))))
    y2 = math.log10(math.log10(float(d341_z(nu2 * 1e6))))
    x1, x2 = math.log10(T1), math.log10(T2)
    B = (y1 - y2) / (x2 - x1)
    A = y1 + B * x1
    return A, B


@VISCOSITY_TEMPERATURE.register(
    "vogel",
    references=["vogel1921"],
    parameters={"a": "Pa*s", "b": "delta_degC", "c": "K"},
    validity="T > c; fitted range of the three constants",
    summary="Vogel: eta = a exp(b / (T - c))",
)
def vogel_viscosity(T: ArrayLike, a: float, b: float, c: float) -> ArrayLike:
    """Dynamic viscosity by Vogel's equation (Vogel 1921; Vogel-Fulcher-Tammann).

    .. math:: \\eta = a\\,\\exp\\left(\\frac{b}{T - c}\\right)

    Parameters
    ----------
    T : temperature [K]; must exceed ``c``.
    a : viscosity scale [Pa s].
    b : temperature difference [K] (``b / (T - c)`` is a ratio of two differences): a
        lubricant file's ``b = "1000 degC"`` or ``"1000 K"`` is 1000 K, not 1273.15 K
        (``lubricant._SECTION_UNITS`` reads it as a difference; registry unit
        ``delta_degC``).
    c : divergence temperature [K] (an absolute temperature: ``"-123.15 degC"`` is 150 K).

    Returns
    -------
    Dynamic viscosity [Pa s].
    """
    check_temperature("temperature", T)
    t = np.asarray(T, dtype=float)
    if np.any(t <= c):
        raise InputError("temperature", T, f"values above Vogel's c = {c:g} K")
    return _out(a * np.exp(b / (t - c)))


@VISCOSITY_TEMPERATURE.register(
    "exponential",
    references=["shi2015_tehl_roller", "hamrock2004"],
    parameters={"eta0": "Pa*s", "beta": "1/K", "T0": "K"},
    validity="a few tens of K around T0 (the law is too steep far from T0)",
    summary="Reynolds exponential law eta = eta0 exp(-beta (T - T0)) (paper 001 Table 2)",
)
def exponential_viscosity(T: ArrayLike, eta0: float, beta: float, T0: float) -> ArrayLike:
    """Dynamic viscosity by the exponential (Reynolds) temperature law.

    .. math:: \\eta = \\eta_0\\,e^{-\\beta (T - T_0)}

    Paper 001 (Shi & Wang 2015, Table 2) gives eta0 = 0.033 Pa s and the
    viscosity-temperature coefficient beta = 0.032 1/degC for oil 4109; Hamrock 2004
    (ch. 4) lists this law as Reynolds' equation.

    Parameters
    ----------
    T : temperature [K]; eta0 : viscosity at T0 [Pa s]; beta : [1/K]; T0 : [K].

    Returns
    -------
    Dynamic viscosity [Pa s].
    """
    check_temperature("temperature", T)
    t = np.asarray(T, dtype=float)
    return _out(eta0 * np.exp(-beta * (t - T0)))


@VISCOSITY_TEMPERATURE.register(
    "isothermal",
    references=["li2018_nu214_skidding"],
    parameters={"eta0": "Pa*s"},
    validity="isothermal analyses only (paper 000 gives no temperature dependence)",
    summary="Isothermal model of paper 000: eta = eta0 at every temperature",
)
def isothermal_viscosity(T: ArrayLike, eta0: float) -> ArrayLike:
    """Dynamic viscosity of an isothermal analysis: eta(T) = eta0 [Pa s].

    Paper 000 (Li et al. 2018, Table 1 and Table 3) gives only eta0 = 0.06/0.08/0.10 Pa s
    and solves an isothermal EHL problem. This law reproduces that assumption; a thermal
    run with such an oil ignores heating of the oil, which the loader flags as estimated.
    """
    check_temperature("temperature", T)
    return _out(np.full_like(np.asarray(T, dtype=float), eta0))


# ---------------------------------------------------------------------------
# viscosity vs pressure
# ---------------------------------------------------------------------------
@PRESSURE_VISCOSITY.register(
    "barus",
    references=["barus1893", "hamrock2004"],
    parameters={"alpha": "1/Pa"},
    validity="p up to ~0.5 GPa; overestimates viscosity at higher pressure",
    summary="Barus: eta = eta0 exp(alpha p)",
)
def barus_viscosity(eta0: ArrayLike, alpha: ArrayLike, p: ArrayLike) -> ArrayLike:
    """Viscosity at pressure by Barus' law.

    .. math:: \\eta = \\eta_0 e^{\\alpha p}

    Parameters
    ----------
    eta0 : viscosity at atmospheric pressure [Pa s].
    alpha : pressure-viscosity coefficient [1/Pa].
    p : gauge pressure [Pa].

    Returns
    -------
    Dynamic viscosity [Pa s] (broadcast of the inputs). Overflow raises InputError.
    """
    check_positive("eta0", eta0)
    check_finite("alpha", alpha)
    check_finite("pressure", p)
    with np.errstate(over="ignore"):
        out = np.asarray(eta0, dtype=float) * np.exp(np.asarray(alpha) * np.asarray(p))
    if not np.all(np.isfinite(out)):
        p_bad, (e_bad, a_bad) = _first_overflow(out, p, eta0, alpha)
        raise InputError("pressure", f"{p_bad:.6g} Pa",
                         f"a pressure for which exp(alpha p) stays finite (eta0 = {e_bad:.4g} "
                         f"Pa s, alpha = {a_bad:.4g} 1/Pa)")
    return _out(out)


def _first_overflow(out: np.ndarray, p: ArrayLike, *params: ArrayLike
                    ) -> tuple[float, tuple[float, ...]]:
    """The first pressure [Pa] whose viscosity ``out`` is not finite, with the law's
    parameters there: an error names one value, not the caller's whole pressure grid."""
    out = np.asarray(out, dtype=float)
    i = int(np.flatnonzero(~np.isfinite(out.ravel()))[0])
    shape = out.shape

    def at(x: ArrayLike) -> float:
        return float(np.broadcast_to(np.asarray(x, dtype=float), shape).ravel()[i]) \
            if shape else float(np.asarray(x, dtype=float))

    return at(p), tuple(at(x) for x in params)


@PRESSURE_VISCOSITY.register(
    "roelands",
    references=["roelands1966", "li2018_nu214_skidding", "hamrock2004"],
    parameters={"z": "-", "p0": "Pa"},
    validity="p up to ~1-1.5 GPa; eta0 > 6.31e-5 Pa s",
    summary="Roelands: eta = eta0 exp{(ln eta0 + 9.67)[(1 + p/p0)^z - 1]} (paper 000 eq. 9)",
)
def roelands_viscosity(
    eta0: ArrayLike, p: ArrayLike, z: ArrayLike, p0: float = ROELANDS_P0
) -> ArrayLike:
    """Viscosity at pressure by Roelands' equation, as written in paper 000 eq. 9.

    .. math:: \\eta = \\eta_0 \\exp\\{(\\ln\\eta_0 + 9.67)[(1 + p/p_0)^z - 1]\\}

    with p0 = 1.96e8 Pa (paper 000 writes 1/p0 = 5.1e-9 1/Pa) and eta0 in Pa s. Paper 000
    prints the exponent as 2; that is the pressure-viscosity index z (about 0.6 for its oil,
    see :func:`roelands_index_from_alpha`); with 2 the viscosity would be ~1e60 times
    eta0 at 1 GPa.

    Parameters
    ----------
    eta0 : viscosity at atmospheric pressure [Pa s], > 6.31e-5 Pa s.
    p : gauge pressure [Pa], > -p0.
    z : Roelands pressure-viscosity index [-].
    p0 : Roelands' pressure constant [Pa].

    Returns
    -------
    Dynamic viscosity [Pa s].
    """
    check_finite("pressure", p)
    check_finite("z", z)
    eta0a = np.asarray(eta0, dtype=float)
    check_finite("eta0", eta0a)
    if np.any(eta0a <= ROELANDS_ETA_INF):
        # the smallest value, not a thermal EHL film's whole 512 x 11 grid
        raise InputError("eta0", _smallest(eta0a), "a viscosity above Roelands' 6.31e-5 Pa s "
                         "(the oil's viscosity at ambient pressure; below it the oil is too "
                         "hot for the law)")
    pa = np.asarray(p, dtype=float)
    if np.any(pa <= -p0):
        raise InputError("pressure", p, f"a pressure above -p0 = {-p0:g} Pa")
    expo = (np.log(eta0a) + ROELANDS_LN_ETA_INF) * ((1.0 + pa / p0) ** np.asarray(z) - 1.0)
    with np.errstate(over="ignore"):
        out = eta0a * np.exp(expo)
    if not np.all(np.isfinite(out)):
        p_bad, (e_bad, z_bad) = _first_overflow(out, pa, eta0a, z)
        raise InputError("pressure", f"{p_bad:.6g} Pa",
                         "a pressure for which the Roelands viscosity is finite (eta0 = "
                         f"{e_bad:.4g} Pa s, z = {z_bad:.4g}: the viscosity overflows there)")
    return _out(out)


def _smallest(eta0: np.ndarray) -> str:
    """An error's value of an ``eta0`` grid: its smallest entry, and how many it had."""
    return (f"{float(np.min(eta0)):.4g} Pa s"
            + (f" (the smallest of {eta0.size} values)" if eta0.size > 1 else ""))


def roelands_index_from_alpha(
    alpha: ArrayLike, eta0: ArrayLike, p0: float = ROELANDS_P0
) -> ArrayLike:
    """Roelands index z with the same initial slope d(ln eta)/dp at p = 0 as Barus' alpha.

    .. math:: z = \\frac{\\alpha\\,p_0}{\\ln\\eta_0 + 9.67}

    (Hamrock 2004, ch. 4, relation between Roelands' z and alpha.) Example, paper 000:
    alpha = G/E' = 5000/2.28e11 = 2.193e-8 1/Pa and eta0 = 0.08 Pa s give z = 0.602.
    """
    eta0a = np.asarray(eta0, dtype=float)
    if np.any(eta0a <= ROELANDS_ETA_INF):
        # the smallest value, not the caller's whole grid (a thermal EHL film's 512 x 11
        # temperatures printed as an array)
        raise InputError("eta0", _smallest(eta0a), "a viscosity above Roelands' 6.31e-5 Pa s "
                         "(the oil's viscosity at ambient pressure; below it the oil is too "
                         "hot for the law)")
    return _out(np.asarray(alpha) * p0 / (np.log(eta0a) + ROELANDS_LN_ETA_INF))


def alpha_from_roelands_index(
    z: ArrayLike, eta0: ArrayLike, p0: float = ROELANDS_P0
) -> ArrayLike:
    """Initial-slope alpha [1/Pa] of a Roelands oil: alpha = z (ln eta0 + 9.67) / p0."""
    eta0a = np.asarray(eta0, dtype=float)
    if np.any(eta0a <= ROELANDS_ETA_INF):
        raise InputError("eta0", eta0, "a viscosity above Roelands' 6.31e-5 Pa s")
    return _out(np.asarray(z) * (np.log(eta0a) + ROELANDS_LN_ETA_INF) / p0)


def roelands_asymptotic_isoviscous_alpha(
    eta0: ArrayLike, z: ArrayLike, p0: float = ROELANDS_P0
) -> ArrayLike:
    """Blok's reciprocal asymptotic isoviscous pressure coefficient alpha* of a Roelands oil.

    .. math:: \\frac{1}{\\alpha^*} = \\int_0^\\infty \\frac{\\eta_0}{\\eta(p)}\\,dp
              = \\frac{p_0\\,e^{S}}{z\\,S^{1/z}}\\,\\Gamma\\!\\left(\\tfrac{1}{z}, S\\right),
              \\qquad S = \\ln\\eta_0 + 9.67

    Blok (1963) defines alpha* by the integral; the closed form (upper incomplete gamma
    function) follows from the substitution u = (1 + p/p0)^z (derived here; a test checks
    it against numerical quadrature). For a Barus oil alpha* = alpha; for a Roelands oil
    alpha* is below the initial slope z S / p0 when z <= 1 ((1 + p/p0)^z - 1 is concave in
    p, so eta rises slower than Barus' exp(z S p / p0)) and above it when z > 1 (z = 1.5,
    eta0 = 0.0188 Pa s: 4.55e-8 against 4.33e-8 1/Pa).

    Evaluated in logarithms, ln(1/alpha*) = ln p0 + S - ln z - ln(S) / z + ln Gamma(1/z) +
    ln Q(1/z, S) with Q the regularised upper incomplete gamma function: Gamma(1/z)
    overflows above 1/z = 171 (z < 0.0058, e.g. alpha = 1e-10 1/Pa of an oil with S = 7)
    and the product Gamma * Q was inf * 0 = NaN; alpha* is then astronomically small
    (1.9e-87 1/Pa at z = 0.01, eta0 = 0.05 Pa s) and underflows to 0 where it must.

    Parameters
    ----------
    eta0 : viscosity at atmospheric pressure [Pa s]; z : Roelands index [-]; p0 : [Pa].

    Returns
    -------
    alpha* [1/Pa].
    """
    from scipy import special

    eta0a = np.asarray(eta0, dtype=float)
    if np.any(eta0a <= ROELANDS_ETA_INF):
        raise InputError("eta0", eta0, "a viscosity above Roelands' 6.31e-5 Pa s")
    check_positive("z", z)
    za = np.asarray(z, dtype=float)
    s = np.log(eta0a) + ROELANDS_LN_ETA_INF
    a = 1.0 / za
    with np.errstate(divide="ignore"):     # Q(a, S) underflows to 0 only where a << S
        ln_q = np.log(special.gammaincc(a, s))
    ln_inv = math.log(p0) + s - np.log(za) - a * np.log(s) + special.gammaln(a) + ln_q
    return _out(np.exp(-ln_inv))
