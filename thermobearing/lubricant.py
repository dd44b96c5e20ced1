"""Lubricant physics: viscosity vs temperature and pressure, density, thermal properties.

Every law is a registered, vectorised pure function (SI in, SI out); :class:`Lubricant`
ties a chosen set of laws to one oil and :func:`load_lubricant` builds one from
``configs/lubricants/<NAME>.toml``.

Families (registries):

- ``viscosity_temperature``: ASTM D341 (Walther), Vogel, the exponential (Reynolds) law
  used for oil 4109 in paper 001, and the isothermal model of paper 000.
- ``pressure_viscosity``: Barus and Roelands (paper 000 eq. 9 form).
- ``pressure_viscosity_coefficient``: correlations alpha(viscosity) for oils without a
  measured alpha.
- ``lubricant_thermal``: c_p and k from CoolProp (incompressible fluid library) or from
  the Cragoe correlations for petroleum oils, or constants from a paper's table.

Units: T [K], p [Pa], nu [m^2/s], eta [Pa s], rho [kg/m^3], c_p [J/(kg K)], k [W/(m K)].
"""

from __future__ import annotations

import math
import tomllib
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .errors import (
    InputError,
    UnknownNameError,
    ValidityWarning,
    check_finite,
    check_positive,
    check_temperature,
)
from .lubricant_properties import (
    LUBRICANT_THERMAL,
    PRESSURE_VISCOSITY_COEFFICIENT,
    AirProperties,
    ArrayLike,
    _out,
    air_properties,
    alpha_gold_paraffinic,
    alpha_mineral_asme_fit,
    astm_d1250_lube_density,
    constant_properties,
    coolprop_properties,
    cragoe_properties,
    dowson_higginson_density,
    linear_expansion_density,
)
from .registry import Registry
from .units import to_si

__all__ = [
    "LUBRICANT_THERMAL", "PRESSURE_VISCOSITY", "PRESSURE_VISCOSITY_COEFFICIENT",
    "VISCOSITY_TEMPERATURE", "AirProperties", "Lubricant", "air_properties",
    "alpha_from_roelands_index", "alpha_gold_paraffinic", "alpha_mineral_asme_fit",
    "astm_d1250_lube_density", "barus_viscosity", "constant_properties",
    "coolprop_properties", "cragoe_properties", "d341_inverse_z", "d341_z",
    "dowson_higginson_density", "exponential_viscosity", "isothermal_viscosity",
    "linear_expansion_density", "load_lubricant", "lubricant_config_dir",
    "lubricant_from_dict", "preset_names", "roelands_asymptotic_isoviscous_alpha",
    "roelands_index_from_alpha", "roelands_viscosity", "vogel_viscosity",
    "walther_constants", "walther_kinematic_viscosity",
]

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
    Raises :class:`InputError` unless both viscosities are > 0, T1 != T2 and the oil
    thins with temperature (nu at the higher temperature is the lower one).
    """
    check_positive("nu1", nu1)
    check_positive("nu2", nu2)
    check_temperature("T1", T1)
    check_temperature("T2", T2)
    if T1 == T2:
        raise InputError("T2", T2, f"a temperature different from T1 = {T1} K")
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
    parameters={"a": "Pa*s", "b": "K", "c": "K"},
    validity="T > c; fitted range of the three constants",
    summary="Vogel: eta = a exp(b / (T - c))",
)
def vogel_viscosity(T: ArrayLike, a: float, b: float, c: float) -> ArrayLike:
    """Dynamic viscosity by Vogel's equation (Vogel 1921; Vogel-Fulcher-Tammann).

    .. math:: \\eta = a\\,\\exp\\left(\\frac{b}{T - c}\\right)

    Parameters
    ----------
    T : temperature [K]; must exceed ``c``.
    a : viscosity scale [Pa s]; b : [K]; c : divergence temperature [K].

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
        raise InputError("pressure", p, "a pressure for which exp(alpha p) stays finite")
    return _out(out)


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
        raise InputError("eta0", eta0, "a viscosity above Roelands' 6.31e-5 Pa s")
    pa = np.asarray(p, dtype=float)
    if np.any(pa <= -p0):
        raise InputError("pressure", p, f"a pressure above -p0 = {-p0:g} Pa")
    expo = (np.log(eta0a) + ROELANDS_LN_ETA_INF) * ((1.0 + pa / p0) ** np.asarray(z) - 1.0)
    with np.errstate(over="ignore"):
        out = eta0a * np.exp(expo)
    if not np.all(np.isfinite(out)):
        raise InputError("pressure", p, "a pressure for which the Roelands viscosity is finite")
    return _out(out)


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
        raise InputError("eta0", eta0, "a viscosity above Roelands' 6.31e-5 Pa s")
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
    alpha* is below the initial slope z S / p0.

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
    upper_gamma = special.gammaincc(a, s) * special.gamma(a)
    inv = p0 * np.exp(s) / (za * s**a) * upper_gamma
    return _out(1.0 / inv)


# ---------------------------------------------------------------------------
# the Lubricant
# ---------------------------------------------------------------------------
def _frozen(mapping: Mapping[str, Any]) -> tuple:
    return tuple(sorted((k, repr(v)) for k, v in mapping.items()))


_MEMO_SIZE = 4096


def _memo_scalar(method: Callable[..., Any]) -> Callable[..., Any]:
    """Memoise a property method for scalar arguments, per lubricant instance.

    The transient re-evaluates the same few oil properties at the same node temperatures
    many times per chunk (every heat source, every finite-difference column); for scalar
    (T, p) the result is a float and is kept in the instance's bounded memo. Array
    arguments, and calls that raise a warning (which must reach every caller), bypass it.
    """
    name = method.__name__

    def wrapper(self: Lubricant, *args: Any, **kwargs: Any) -> Any:
        if kwargs or not all(isinstance(a, (float, int)) and not isinstance(a, bool)
                             for a in args):
            return method(self, *args, **kwargs)
        key = (name, *args)
        memo = self._memo
        hit = memo.get(key)
        if hit is not None:
            return hit
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            value = method(self, *args)
        for w in caught:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
        if not caught and isinstance(value, float):
            if len(memo) >= _MEMO_SIZE:
                memo.clear()
            memo[key] = value
        return value

    wrapper.__name__ = name
    wrapper.__qualname__ = method.__qualname__
    wrapper.__doc__ = method.__doc__
    return wrapper


@dataclass(frozen=True)
class Lubricant:
    """One lubricant: its laws and their parameters (all SI).

    Attributes
    ----------
    name, source : identification and where the numbers come from.
    viscosity_law : key of :data:`VISCOSITY_TEMPERATURE`; ``viscosity_parameters`` its
        arguments (astm_d341: A, B; vogel: a, b, c; exponential: eta0, beta, T0;
        isothermal: eta0).
    pressure_law : "barus" or "roelands"; ``pressure_parameters`` holds ``alpha`` [1/Pa]
        or ``z`` [-] (Roelands), optional ``p0`` [Pa] and ``reference_temperature`` [K]
        (temperature at which a given alpha holds, for converting it to z).
    alpha_correlation : key of :data:`PRESSURE_VISCOSITY_COEFFICIENT` used when neither
        alpha nor z is given: alpha(T) follows the viscosity.
    density_reference [kg/m^3] at density_reference_temperature [K];
        density_temperature_law "linear" (with thermal_expansion [1/K]) or
        "astm_d1250_lube" (reference temperature must be 15 degC);
        density_pressure_law "dowson_higginson" or "incompressible".
    thermal_model : key of :data:`LUBRICANT_THERMAL`; thermal_parameters its arguments.
    kind : "mineral", "ester", ... (informative).
    estimated : field -> reasoning, for values not taken from a source.
    """

    name: str
    source: str
    viscosity_law: str
    viscosity_parameters: Mapping[str, float]
    density_reference: float
    density_reference_temperature: float = 288.15
    thermal_expansion: float = 6.4e-4
    density_pressure_law: str = "dowson_higginson"
    density_temperature_law: str = "linear"
    pressure_law: str = "roelands"
    pressure_parameters: Mapping[str, float] = field(default_factory=dict)
    alpha_correlation: str | None = None
    thermal_model: str = "cragoe"
    thermal_parameters: Mapping[str, Any] = field(default_factory=dict)
    kind: str = "mineral"
    estimated: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_memo", {})
        law = VISCOSITY_TEMPERATURE.entry(self.viscosity_law)
        missing = set(law.parameters) - set(self.viscosity_parameters)
        extra = set(self.viscosity_parameters) - set(law.parameters)
        if missing or extra:
            raise InputError(
                f"{self.name}.viscosity_parameters",
                dict(self.viscosity_parameters),
                f"exactly the parameters {sorted(law.parameters)} of {self.viscosity_law}",
            )
        for key, val in self.viscosity_parameters.items():
            check_finite(f"{self.name}.viscosity.{key}", val)
        for key in ("eta0", "a", "T0"):
            if key in self.viscosity_parameters:
                check_positive(f"{self.name}.viscosity.{key}", self.viscosity_parameters[key])
        check_positive(f"{self.name}.density", self.density_reference)
        check_temperature(f"{self.name}.density_reference_temperature",
                          self.density_reference_temperature)
        check_finite(f"{self.name}.thermal_expansion", self.thermal_expansion)
        if not 0.0 <= self.thermal_expansion < 5e-3:
            raise InputError(f"{self.name}.thermal_expansion", self.thermal_expansion,
                             "a value in [0, 5e-3) 1/K")
        if self.density_temperature_law not in ("linear", "astm_d1250_lube"):
            raise UnknownNameError(f"{self.name}.density_temperature_law",
                                   self.density_temperature_law, ["linear", "astm_d1250_lube"])
        if (self.density_temperature_law == "astm_d1250_lube"
                and abs(self.density_reference_temperature - 288.15) > 1e-9):
            raise InputError(f"{self.name}.density_reference_temperature",
                             self.density_reference_temperature,
                             "15 degC (288.15 K) with the astm_d1250_lube law")
        if self.density_pressure_law not in ("dowson_higginson", "incompressible"):
            raise UnknownNameError(f"{self.name}.density_pressure_law",
                                   self.density_pressure_law,
                                   ["dowson_higginson", "incompressible"])
        PRESSURE_VISCOSITY.entry(self.pressure_law)
        pp = dict(self.pressure_parameters)
        allowed = {"alpha", "z", "p0", "reference_temperature"}
        for key in pp:
            if key not in allowed:
                raise UnknownNameError(f"{self.name}.pressure_viscosity", key, allowed)
        if self.alpha_correlation is not None:
            PRESSURE_VISCOSITY_COEFFICIENT.entry(self.alpha_correlation)
        n_given = ("alpha" in pp) + ("z" in pp) + (self.alpha_correlation is not None)
        if n_given != 1:
            raise InputError(f"{self.name}.pressure_viscosity", pp,
                             "exactly one of alpha, z or alpha_correlation")
        if "z" in pp and self.pressure_law != "roelands":
            raise InputError(f"{self.name}.pressure_viscosity.z", pp["z"],
                             "z only with the roelands law")
        for key in ("alpha", "z", "p0"):
            if key in pp:
                check_positive(f"{self.name}.pressure_viscosity.{key}", pp[key])
        if "reference_temperature" in pp:
            check_temperature(f"{self.name}.pressure_viscosity.reference_temperature",
                              pp["reference_temperature"])
        LUBRICANT_THERMAL.entry(self.thermal_model)

    def __hash__(self) -> int:  # mappings are not hashable; hash their sorted items
        return hash((
            self.name, self.viscosity_law, _frozen(self.viscosity_parameters),
            self.density_reference, self.density_reference_temperature, self.thermal_expansion,
            self.density_pressure_law, self.density_temperature_law, self.pressure_law,
            _frozen(self.pressure_parameters),
            self.alpha_correlation, self.thermal_model, _frozen(self.thermal_parameters),
        ))

    # -- viscosity ----------------------------------------------------------
    def _vt(self, T: ArrayLike) -> ArrayLike:
        return VISCOSITY_TEMPERATURE.get(self.viscosity_law)(T, **self.viscosity_parameters)

    @_memo_scalar
    def kinematic_viscosity(self, T: ArrayLike) -> ArrayLike:
        """Kinematic viscosity [m^2/s] at atmospheric pressure, T [K] (vectorised)."""
        v = self._vt(T)
        if _VT_OUTPUT[self.viscosity_law] == "kinematic":
            return v
        return _out(np.asarray(v) / np.asarray(self.density(T)))

    def _eta_atm(self, T: ArrayLike) -> ArrayLike:
        v = self._vt(T)
        if _VT_OUTPUT[self.viscosity_law] == "dynamic":
            return v
        return _out(np.asarray(v) * np.asarray(self.density(T)))

    @property
    def _p0(self) -> float:
        return float(self.pressure_parameters.get("p0", ROELANDS_P0))

    @_memo_scalar
    def roelands_index(self, T: ArrayLike) -> ArrayLike:
        """Roelands pressure-viscosity index z [-] at T [K].

        A given z is constant (Roelands' model); a given alpha is converted once at its
        ``reference_temperature`` (default 313.15 K) by z = alpha p0 / (ln eta0 + 9.67),
        Hamrock 2004 ch. 4; with an alpha correlation z follows alpha(T). For a Barus oil
        this is the Roelands index with the same initial slope.
        """
        pp = self.pressure_parameters
        if "z" in pp:
            return _out(np.full_like(np.asarray(T, dtype=float), pp["z"]))
        if "alpha" in pp:
            if self.pressure_law == "barus":
                return roelands_index_from_alpha(pp["alpha"], self._eta_atm(T), self._p0)
            tref = float(pp.get("reference_temperature", 313.15))
            z = float(roelands_index_from_alpha(pp["alpha"], self._eta_atm(tref), self._p0))
            return _out(np.full_like(np.asarray(T, dtype=float), z))
        alpha = self._alpha_correlated(T)
        return roelands_index_from_alpha(alpha, self._eta_atm(T), self._p0)

    def _alpha_correlated(self, T: ArrayLike) -> ArrayLike:
        assert self.alpha_correlation is not None
        entry = PRESSURE_VISCOSITY_COEFFICIENT.entry(self.alpha_correlation)
        if "nu" in entry.parameters:
            return entry.obj(self.kinematic_viscosity(T))
        return entry.obj(self._eta_atm(T))

    @_memo_scalar
    def pressure_viscosity_coefficient(
        self, T: ArrayLike, definition: str = "initial_slope"
    ) -> ArrayLike:
        """Pressure-viscosity coefficient alpha [1/Pa] for film formulas, T [K].

        ``definition="initial_slope"`` (default): d(ln eta)/dp at p = 0; for a Roelands oil
        alpha = z (ln eta0 + 9.67)/p0 (Hamrock 2004 ch. 4), which reproduces paper 000's
        G = alpha E' = 5000. ``definition="asymptotic_isoviscous"``: Blok's alpha*
        (:func:`roelands_asymptotic_isoviscous_alpha`), smaller than the initial slope for Roelands.
        """
        if definition not in ("initial_slope", "asymptotic_isoviscous"):
            raise UnknownNameError("definition", definition,
                                   ["initial_slope", "asymptotic_isoviscous"])
        pp = self.pressure_parameters
        t = np.asarray(T, dtype=float)
        check_temperature("temperature", t)
        if self.pressure_law == "barus":
            if "alpha" in pp:
                return _out(np.full_like(t, pp["alpha"]))
            return self._alpha_correlated(t)
        if definition == "initial_slope":
            if self.alpha_correlation is not None:
                return self._alpha_correlated(t)
            z = self.roelands_index(t)
            return alpha_from_roelands_index(z, self._eta_atm(t), self._p0)
        return roelands_asymptotic_isoviscous_alpha(
            self._eta_atm(t), self.roelands_index(t), self._p0
        )

    @_memo_scalar
    def dynamic_viscosity(self, T: ArrayLike, p: ArrayLike = 0.0) -> ArrayLike:
        """Dynamic viscosity [Pa s] at T [K] and gauge pressure p [Pa] (vectorised, broadcast)."""
        if type(p) is float and p == 0.0 and type(T) is float:  # the common scalar call
            return float(self._eta_atm(T))
        check_finite("pressure", p)
        eta0 = self._eta_atm(T)
        if np.all(np.asarray(p) == 0.0):
            return _out(np.broadcast_to(np.asarray(eta0), np.broadcast(eta0, p).shape).copy())
        if self.pressure_law == "barus":
            return barus_viscosity(eta0, self.pressure_viscosity_coefficient(T), p)
        return roelands_viscosity(eta0, p, self.roelands_index(T), self._p0)

    # -- density and thermal ------------------------------------------------
    @_memo_scalar
    def density(self, T: ArrayLike, p: ArrayLike = 0.0) -> ArrayLike:
        """Density [kg/m^3] at T [K], p [Pa]: temperature law, then Dowson-Higginson.

        The pressure factor is paper 000 eq. 10 (:func:`dowson_higginson_density`).
        """
        if self.density_temperature_law == "astm_d1250_lube":
            rho = astm_d1250_lube_density(T, self.density_reference)
        else:
            rho = linear_expansion_density(T, self.density_reference,
                                           self.density_reference_temperature,
                                           self.thermal_expansion)
        if type(p) is float and p == 0.0 and np.ndim(rho) == 0:
            return float(rho)  # at gauge pressure 0 every pressure law gives rho(T)
        if self.density_pressure_law == "incompressible":
            check_finite("pressure", p)
            return _out(np.broadcast_to(np.asarray(rho), np.broadcast(rho, p).shape).copy())
        return dowson_higginson_density(rho, p)

    def _thermal(self, T: ArrayLike) -> tuple[ArrayLike, ArrayLike]:
        params = dict(self.thermal_parameters)
        if self.thermal_model == "cragoe":
            params.setdefault("density15", float(self.density(288.15)))
        return LUBRICANT_THERMAL.get(self.thermal_model)(T, **params)

    @_memo_scalar
    def specific_heat(self, T: ArrayLike) -> ArrayLike:
        """Specific heat c_p [J/(kg K)] at T [K]."""
        return self._thermal(T)[0]

    @_memo_scalar
    def thermal_conductivity(self, T: ArrayLike) -> ArrayLike:
        """Thermal conductivity k [W/(m K)] at T [K]."""
        return self._thermal(T)[1]

    # -- construction ---------------------------------------------------------
    @classmethod
    def from_viscosities(
        cls,
        nu40: float,
        nu100: float,
        density15: float,
        *,
        name: str = "custom",
        source: str = "user input",
        T1: float = 313.15,
        T2: float = 373.15,
        thermal_expansion: float = 6.4e-4,
        density_temperature_law: str = "astm_d1250_lube",
        pressure_law: str = "roelands",
        alpha: float | None = None,
        z: float | None = None,
        alpha_correlation: str | None = None,
        thermal_model: str = "cragoe",
        thermal_parameters: Mapping[str, Any] | None = None,
        kind: str = "mineral",
        estimated: Mapping[str, str] | None = None,
    ) -> Lubricant:
        """A lubricant whose nu(T) is the ASTM D341 line through (T1, nu40) and (T2, nu100).

        nu40, nu100 [m^2/s] at T1 = 40 degC and T2 = 100 degC by default; density15
        [kg/m^3] at 15 degC; density vs temperature by ASTM D1250 for lubricating oils unless
        ``density_temperature_law="linear"``. Without alpha, z or alpha_correlation the mineral-oil
        correlation ``asme1953_mineral_fit`` is used. nu100 >= nu40 raises InputError.
        """
        A, B = walther_constants(nu40, T1, nu100, T2)
        pp: dict[str, float] = {}
        if alpha is not None:
            pp["alpha"] = alpha
        if z is not None:
            pp["z"] = z
        if alpha is None and z is None and alpha_correlation is None:
            alpha_correlation = "asme1953_mineral_fit"
        return cls(
            name=name,
            source=source,
            viscosity_law="astm_d341",
            viscosity_parameters={"A": A, "B": B},
            density_reference=density15,
            density_reference_temperature=288.15,
            thermal_expansion=thermal_expansion,
            density_temperature_law=density_temperature_law,
            pressure_law=pressure_law,
            pressure_parameters=pp,
            alpha_correlation=alpha_correlation,
            thermal_model=thermal_model,
            thermal_parameters=dict(thermal_parameters or {}),
            kind=kind,
            estimated=dict(estimated or {}),
        )


# ---------------------------------------------------------------------------
# loading presets
# ---------------------------------------------------------------------------
def lubricant_config_dir() -> Path:
    """``configs/lubricants`` at the repository root."""
    import thermobearing

    return Path(thermobearing.__file__).resolve().parents[1] / "configs" / "lubricants"


def preset_names() -> list[str]:
    """Names of the lubricant presets."""
    folder = lubricant_config_dir()
    return sorted(p.stem for p in folder.glob("*.toml")) if folder.is_dir() else []


_TOP_KEYS = {"name", "source", "kind", "viscosity", "pressure_viscosity", "density",
             "thermal", "estimated"}
_SECTION_UNITS: dict[str, dict[str, str]] = {
    "viscosity": {"law": "", "nu40": "m**2/s", "nu100": "m**2/s", "T1": "K", "T2": "K",
                  "eta0": "Pa*s", "beta": "1/K", "T0": "K", "a": "Pa*s", "b": "K", "c": "K",
                  "A": "", "B": "", "source": ""},
    "pressure_viscosity": {"law": "", "alpha": "1/Pa", "z": "", "p0": "Pa",
                           "reference_temperature": "K", "alpha_correlation": "",
                           "source": ""},
    "density": {"value": "kg/m**3", "reference_temperature": "K", "expansion": "1/K",
                "pressure_law": "", "temperature_law": "", "source": ""},
    "thermal": {"model": "", "fluid": "", "specific_heat": "J/(kg*K)",
                "thermal_conductivity": "W/(m*K)", "source": ""},
}


def _section(data: dict, name: str, where: str) -> dict[str, Any]:
    raw = data.get(name, {})
    if not isinstance(raw, dict):
        raise InputError(f"{where}.{name}", raw, "a TOML table")
    units = _SECTION_UNITS[name]
    out: dict[str, Any] = {}
    for key, val in raw.items():
        if key not in units:
            raise UnknownNameError(f"{where}.{name} key", key, units)
        unit = units[key]
        if unit and key != "source":
            out[key] = to_si(val, unit, field=f"{where}.{name}.{key}")
        elif key in ("A", "B", "z"):
            out[key] = to_si(val, "dimensionless", field=f"{where}.{name}.{key}")
        else:
            out[key] = val
    return out


def lubricant_from_dict(data: Mapping[str, Any], where: str = "lubricant") -> Lubricant:
    """Build a :class:`Lubricant` from a parsed TOML mapping (unknown keys are errors)."""
    for key in data:
        if key not in _TOP_KEYS:
            raise UnknownNameError(f"{where} key", key, _TOP_KEYS)
    for req in ("name", "source", "viscosity", "density"):
        if req not in data:
            raise InputError(f"{where}.{req}", None, "a required entry")
    vis = _section(dict(data), "viscosity", where)
    pv = _section(dict(data), "pressure_viscosity", where)
    den = _section(dict(data), "density", where)
    th = _section(dict(data), "thermal", where)
    est = dict(data.get("estimated", {}))
    law = vis.pop("law", "astm_d341")
    vis.pop("source", None)
    if "value" not in den:
        raise InputError(f"{where}.density.value", None, "a density, e.g. \"870 kg/m^3\"")
    common = {
        "name": str(data["name"]),
        "source": str(data["source"]),
        "kind": str(data.get("kind", "mineral")),
        "estimated": est,
        "density_reference": den["value"],
        "density_reference_temperature": den.get("reference_temperature", 288.15),
        "thermal_expansion": den.get("expansion", 6.4e-4),
        "density_pressure_law": den.get("pressure_law", "dowson_higginson"),
        "density_temperature_law": den.get("temperature_law", "linear"),
        "pressure_law": pv.pop("law", "roelands"),
        "alpha_correlation": pv.pop("alpha_correlation", None),
        "thermal_model": th.pop("model", "cragoe"),
    }
    pv.pop("source", None)
    th.pop("source", None)
    common["pressure_parameters"] = pv
    common["thermal_parameters"] = th
    if law == "astm_d341" and ("nu40" in vis or "nu100" in vis):
        if not {"nu40", "nu100"} <= set(vis):
            raise InputError(f"{where}.viscosity", vis, "both nu40 and nu100")
        T1, T2 = vis.get("T1", 313.15), vis.get("T2", 373.15)
        A, B = walther_constants(vis["nu40"], T1, vis["nu100"], T2)
        params: dict[str, float] = {"A": A, "B": B}
    else:
        params = {k: float(v) for k, v in vis.items()}
    return Lubricant(viscosity_law=law, viscosity_parameters=params, **common)


def load_lubricant(name_or_path: str | Path) -> Lubricant:
    """Load a lubricant preset (``"ISO_VG46"``) or a TOML file path.

    An unknown preset name raises :class:`UnknownNameError` listing the presets.
    """
    path = Path(name_or_path)
    if path.suffix != ".toml" or not path.is_file():
        candidate = lubricant_config_dir() / f"{name_or_path}.toml"
        if not candidate.is_file():
            raise UnknownNameError("lubricant preset", str(name_or_path), preset_names())
        path = candidate
    try:
        with path.open("rb") as fh:
            data = tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("lubricant file", str(path), f"valid TOML ({exc})") from None
    return lubricant_from_dict(data, where=f"lubricant[{path.stem}]")
