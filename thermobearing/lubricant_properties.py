"""Lubricant property correlations: pressure-viscosity coefficient, density, c_p, k, air.

Pure, vectorised functions used by :mod:`thermobearing.lubricant` (which re-exports them);
split out of that module to keep both readable. Units: T [K], p [Pa], eta [Pa s],
nu [m^2/s], rho [kg/m^3], c_p [J/(kg K)], k [W/(m K)].
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from .errors import (
    InputError,
    ValidityWarning,
    check_finite,
    check_positive,
    check_temperature,
)
from .registry import Registry

ArrayLike = float | np.ndarray

#: upper end of ASTM D341's stated range, 1e6 cSt [m^2/s]
_D341_MAX_NU = 1.0
#: lower end of ASTM D341's stated range, 0.21 cSt [m^2/s]
_D341_MIN_NU = 0.21e-6
#: 15 degC densities of ASTM D1250 Table 54D (lubricating oils) [kg/m^3]
_D1250_DENSITY_RANGE = (800.0, 1164.0)

PRESSURE_VISCOSITY_COEFFICIENT: Registry[Callable[..., ArrayLike]] = Registry(
    "pressure_viscosity_coefficient", "correlations for alpha from the atmospheric viscosity"
)
LUBRICANT_THERMAL: Registry[Callable[..., tuple[ArrayLike, ArrayLike]]] = Registry(
    "lubricant_thermal", "specific heat and thermal conductivity of a lubricant vs T"
)


def _out(x: np.ndarray) -> ArrayLike:
    """0-d arrays -> float; arrays unchanged."""
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


# ---------------------------------------------------------------------------
# pressure-viscosity coefficient correlations
# ---------------------------------------------------------------------------
#: lowest atmospheric viscosity [Pa s] of the data an eta-based alpha fit was fitted to (its
#: registered validity). A Roelands oil whose z comes from such a fit keeps below it the z of
#: this viscosity (:meth:`thermobearing.lubricant.Lubricant.roelands_index`): the fit's
#: z = alpha p0 / (ln eta0 + 9.67) rises without bound as eta0 nears Roelands' 6.31e-5 Pa s
#: and the viscosity at a fixed high pressure then rises with temperature.
ALPHA_FIT_LOWEST_VISCOSITY = {"asme1953_mineral_fit": 2.4e-3}
#: atmospheric viscosities [Pa s] of the data an eta-based alpha fit was fitted to, low and
#: high end (its registered validity; :func:`thermobearing.lubricant_range.
#: data_temperature_range` turns them into the oil's temperatures)
ALPHA_FIT_VISCOSITY_RANGE = {"asme1953_mineral_fit": (2.4e-3, 2.0)}

@PRESSURE_VISCOSITY_COEFFICIENT.register(
    "asme1953_mineral_fit",
    references=["stachowiak2005", "asme1953_pressure_viscosity"],
    parameters={"eta": "Pa*s"},
    validity="mineral oils, 2.4 mPa s <= eta <= 2000 mPa s, 30-100 degC; rms scatter 10 %, "
    "max 20 % against the 38 points fitted",
    summary="alpha = 12.71e-9 (eta/mPa s)^0.1604 1/Pa, fit to Stachowiak Table 2.3",
)
def alpha_mineral_asme_fit(eta: ArrayLike) -> ArrayLike:
    """Pressure-viscosity coefficient of a mineral oil from its atmospheric viscosity.

    alpha [1/Pa] = 12.71e-9 (eta [mPa s])^0.1604

    Least-squares fit in log-log (done for this package) to the 38 (eta, alpha) pairs of
    the thirteen mineral oils at 30, 60 and 100 degC in Stachowiak & Batchelor,
    *Engineering Tribology*, Table 2.3 (adapted there from the ASME Pressure-Viscosity
    Report, 1953). Residuals: rms 9.9 %, max 19.6 %. ``eta`` at the same temperature.

    Parameters
    ----------
    eta : dynamic viscosity at atmospheric pressure [Pa s].

    Returns
    -------
    alpha [1/Pa].
    """
    check_positive("eta", eta)
    e = np.asarray(eta, dtype=float) * 1e3
    if np.any(e < 1.0) or np.any(e > 5000.0):
        warnings.warn(
            "ASME-table alpha fit used outside 1-5000 mPa s", ValidityWarning, stacklevel=2
        )
    return _out(12.71e-9 * e**0.1604)


@PRESSURE_VISCOSITY_COEFFICIENT.register(
    "gold2001_paraffinic",
    references=["gold2001"],
    parameters={"nu": "m**2/s"},
    validity="paraffinic mineral oils; constants recalled (s = 9.904, t = 0.139), not "
    "checked against the original; gives ~26 % lower alpha than the ASME 1953 data",
    summary="Gold et al. 2001: alpha = s nu^t (1/GPa, nu in mm^2/s), paraffinic mineral oils",
)
def alpha_gold_paraffinic(nu: ArrayLike) -> ArrayLike:
    """Gold et al. (2001) alpha = s nu^t for paraffinic mineral oils [1/Pa].

    alpha [1/GPa] = 9.904 (nu [mm^2/s])^0.1390. The constants are as recalled from the
    literature and could not be checked against Gold et al.; on the mineral
    oils of Stachowiak Table 2.3 this form gives alpha about 26 % lower than the table (a
    test documents the offset). Not used by the presets.
    """
    check_positive("nu", nu)
    return _out(9.904e-9 * (np.asarray(nu, dtype=float) * 1e6) ** 0.1390)


# ---------------------------------------------------------------------------
# density
# ---------------------------------------------------------------------------
def dowson_higginson_density(rho0: ArrayLike, p: ArrayLike) -> ArrayLike:
    """Density at pressure by Dowson and Higginson (paper 000 eq. 10).

    .. math:: \\rho = \\rho_0\\left(1 + \\frac{0.6\\times10^{-9} p}{1 + 1.7\\times10^{-9} p}\\right)

    p [Pa] gauge, rho0 [kg/m^3]. Tends to 1.353 rho0 as p -> infinity. Defined for
    p > -1/1.7e-9 Pa; negative pressures below -1e8 Pa are rejected.
    """
    check_positive("rho0", rho0)
    check_finite("pressure", p)
    pa = np.asarray(p, dtype=float)
    if np.any(pa < -1e8):
        raise InputError("pressure", p, "a pressure >= -1e8 Pa")
    return _out(np.asarray(rho0) * (1.0 + 0.6e-9 * pa / (1.0 + 1.7e-9 * pa)))


def linear_expansion_density(
    T: ArrayLike, rho_ref: float, T_ref: float, expansion: float
) -> ArrayLike:
    """Density vs temperature by a linear volumetric law, rho = rho_ref (1 - a (T - T_ref)).

    ``expansion`` a [1/K] is the oil's volumetric expansion coefficient (about 6.4e-4
    1/K for mineral oils, 6.5e-4 1/K in the TEHL density law of Yang & Wen that paper 001
    cites as Ref. 22). Raises InputError if the density would not be positive.
    """
    check_temperature("temperature", T)
    rho = rho_ref * (1.0 - expansion * (np.asarray(T, dtype=float) - T_ref))
    if np.any(rho <= 0):
        raise InputError("temperature", T, "temperatures at which the linear density law is > 0")
    return _out(rho)


def astm_d1250_lube_density(T: ArrayLike, rho15: float) -> ArrayLike:
    """Density of a lubricating oil vs temperature by the ASTM D1250 / API MPMS 11.1 volume
    correction for lubricating oils (Table 54D, group D; ISO 91-1).

    rho(T) = rho15 exp[-a15 dt (1 + 0.8 a15 dt)],  a15 = K0/rho15^2 + K1/rho15

    with K0 = 0, K1 = 0.6278 kg/(m^3 degC) for lubricating oils, Delta t = t - 15 degC and
    rho15 [kg/m^3] at 15 degC. For rho15 = 876 kg/m^3, alpha15 = 7.17e-4 1/K.
    Tables valid from -18 to 150 degC for densities 800-1164 kg/m^3.
    """
    check_temperature("temperature", T)
    check_positive("rho15", rho15)
    a15 = 0.6278 / rho15
    dt = np.asarray(T, dtype=float) - 288.15
    return _out(rho15 * np.exp(-a15 * dt * (1.0 + 0.8 * a15 * dt)))


# ---------------------------------------------------------------------------
# thermal properties
# ---------------------------------------------------------------------------
#: stated temperature ranges [K] of the thermal correlations (their registered validity;
#: :func:`thermobearing.lubricant_range.data_temperature_range`)
THERMAL_TEMPERATURE_RANGE = {"cragoe": (273.15, 473.15)}


@LUBRICANT_THERMAL.register(
    "cragoe",
    references=["cragoe1929"],
    parameters={"density15": "kg/m**3"},
    validity="petroleum oils, 0-200 degC, specific gravity 0.75-0.96",
    summary="Cragoe (NBS 1929): c_p and k of petroleum oils from T and 15 degC density",
)
def cragoe_properties(T: ArrayLike, density15: float) -> tuple[ArrayLike, ArrayLike]:
    """Specific heat and thermal conductivity of petroleum oils (Cragoe 1929).

    .. math:: c_p = \\frac{1685 + 3.39\\,t}{\\sqrt{d}}\\ \\mathrm{J/(kg\\,K)},\\qquad
              k = \\frac{0.1172}{d}(1 - 5.4\\times10^{-4} t)\\ \\mathrm{W/(m\\,K)}

    t in degC, d the specific gravity at 15.6 degC (here density15 / 999.0). These are the
    SI forms of c = (0.388 + 0.00045 t_F)/sqrt(d) Btu/(lb F) and
    k = 0.813/d (1 - 0.0003 (t_F - 32)) Btu in/(h ft^2 F) (NBS Misc. Publ. 97).

    Returns
    -------
    (c_p [J/(kg K)], k [W/(m K)]).
    """
    check_temperature("temperature", T)
    check_positive("density15", density15)
    t = np.asarray(T, dtype=float) - 273.15
    d = density15 / 999.0
    cp = (1685.0 + 3.39 * t) / math.sqrt(d)
    k = 0.1172 / d * (1.0 - 5.4e-4 * t)
    return _out(cp), _out(k)


@LUBRICANT_THERMAL.register(
    "coolprop",
    references=["coolprop"],
    parameters={},
    validity="the fluid's range in CoolProp (INCOMP::PNF: 263-588 K); clamped with a warning",
    summary="CoolProp incompressible-fluid c_p and k (e.g. INCOMP::PNF mineral heat-transfer oil)",
)
def coolprop_properties(T: ArrayLike, fluid: str = "INCOMP::PNF") -> tuple[ArrayLike, ArrayLike]:
    """c_p [J/(kg K)] and k [W/(m K)] of ``fluid`` from CoolProp at 1 atm.

    INCOMP::PNF is a hydrotreated mineral heat-transfer oil; at 313 K it gives
    c_p = 1941 J/(kg K) (Cragoe: 1945 for 875 kg/m^3; at 373 K 2247 vs 2163, PNF rises
    faster) and k = 0.104 W/(m K), about 20 % below Cragoe and typical lubricating-oil data
    (~0.13). Temperatures outside the
    fluid's range are clamped to it with a ValidityWarning.
    """
    import CoolProp.CoolProp as CP

    check_temperature("temperature", T)
    t = np.asarray(T, dtype=float)
    try:
        tmin = CP.PropsSI("Tmin", "T", 300.0, "P", 101325.0, fluid)
        tmax = CP.PropsSI("Tmax", "T", 300.0, "P", 101325.0, fluid)
    except ValueError as exc:
        raise InputError("thermal.fluid", fluid, f"a fluid known to CoolProp ({exc})") from None
    if np.any(t < tmin) or np.any(t > tmax):
        warnings.warn(
            f"{fluid} is tabulated for {tmin:g}-{tmax:g} K; temperature clamped",
            ValidityWarning,
            stacklevel=2,
        )
    tc = np.clip(t, tmin, tmax)
    cp = np.asarray(CP.PropsSI("C", "T", tc, "P", 101325.0, fluid), dtype=float)
    k = np.asarray(CP.PropsSI("L", "T", tc, "P", 101325.0, fluid), dtype=float)
    return _out(cp.reshape(t.shape)), _out(k.reshape(t.shape))


@LUBRICANT_THERMAL.register(
    "constant",
    references=["shi2015_tehl_roller"],
    parameters={"specific_heat": "J/(kg*K)", "thermal_conductivity": "W/(m*K)"},
    validity="near the temperature at which the values were given",
    summary="Constant c_p and k (e.g. paper 001 Table 2 for oil 4109)",
)
def constant_properties(
    T: ArrayLike, specific_heat: float, thermal_conductivity: float
) -> tuple[ArrayLike, ArrayLike]:
    """c_p and k held constant (as paper 001 Table 2 gives them for oil 4109)."""
    check_temperature("temperature", T)
    shape = np.asarray(T, dtype=float)
    return (
        _out(np.full_like(shape, specific_heat)),
        _out(np.full_like(shape, thermal_conductivity)),
    )


class AirProperties(NamedTuple):
    """Properties of dry air (SI)."""

    density: ArrayLike  #: kg/m^3
    dynamic_viscosity: ArrayLike  #: Pa s
    thermal_conductivity: ArrayLike  #: W/(m K)
    specific_heat: ArrayLike  #: J/(kg K)
    prandtl: ArrayLike  #: -


#: the 1-atm air table (``scripts/make_air_table.py``, from CoolProp): pressure [Pa], and
#: the file with temperature [K] and density, viscosity, conductivity, c_p columns
AIR_TABLE_PRESSURE = 101325.0
_AIR_TABLE_FILE = Path(__file__).resolve().parent / "data" / "air_1atm.csv"


@functools.lru_cache(maxsize=1)
def _air_table() -> tuple[np.ndarray, ...]:
    """(T, rho, mu, k, c_p) columns of the 1-atm air table."""
    data = np.loadtxt(_AIR_TABLE_FILE, delimiter=",", comments="#", skiprows=2)
    return tuple(np.ascontiguousarray(data[:, j]) for j in range(5))


#: temperatures [K] of :func:`air_properties` (air is liquid below ~79 K at 1 atm; CoolProp's
#: air model starts at 60 K, its pseudo-pure model has no two-phase states) and what an error
#: outside them allows
AIR_T_RANGE = (100.0, 2000.0)
AIR_T_ALLOWED = "100 K to 2000 K for air (a gas at 1 atm; the range of its CoolProp model)"


def air_properties(T: ArrayLike, p: ArrayLike = 101325.0) -> AirProperties:
    """Dry-air properties (Lemmon et al. 2000 pseudo-pure air, CoolProp), vectorised.

    At 1 atm between 100 and 1500 K the values are interpolated (linearly, 0.5 K spacing)
    in a table made from CoolProp (``thermobearing/data/air_1atm.csv``,
    ``scripts/make_air_table.py``; within 1e-5 relative of CoolProp, tested): importing
    CoolProp costs ~5 s, more than a whole default protocol. Other pressures and
    temperatures call CoolProp.

    Parameters
    ----------
    T : temperature [K], 100-2000 K (air is liquid below ~79 K at 1 atm; CoolProp's air
        model starts at 60 K, its pseudo-pure model has no two-phase states).
    p : absolute pressure [Pa], > 0.

    Returns
    -------
    AirProperties(density, dynamic_viscosity, thermal_conductivity, specific_heat, prandtl).
    """
    check_temperature("temperature", T)
    check_positive("pressure", p)
    t, pp = np.broadcast_arrays(np.asarray(T, dtype=float), np.asarray(p, dtype=float))
    if np.any(t < AIR_T_RANGE[0]) or np.any(t > AIR_T_RANGE[1]):
        raise InputError("temperature", T, AIR_T_ALLOWED)
    tab = _air_table()
    if np.all(pp == AIR_TABLE_PRESSURE) and np.all(t <= tab[0][-1]):
        rho, mu, k, cp = (np.interp(t, tab[0], col) for col in tab[1:])
        return AirProperties(_out(rho), _out(mu), _out(k), _out(cp), _out(mu * cp / k))
    import CoolProp.CoolProp as CP

    vals = [
        np.asarray(CP.PropsSI(k, "T", t.ravel(), "P", pp.ravel(), "Air"), dtype=float).reshape(
            t.shape
        )
        for k in ("D", "V", "L", "C", "Prandtl")
    ]
    return AirProperties(*(_out(v) for v in vals))


def check_liquid_temperature(lubricant: Any, field: str, temperature: float,
                             hint: str = "") -> None:
    """An :class:`InputError` naming ``field`` unless ``lubricant`` is liquid at
    ``temperature`` [K] as far as its viscosity law can say: above 0 K, the law finite there,
    and for ASTM D341 within the 1e6 cSt that end its stated range (colder, the oil is below
    its pour point and the solvers fail later with errors about contact pressures).
    ``hint`` is appended to what is allowed; the value is shown in K and degC."""
    t = float(temperature)
    shown = f"{t:g} K ({t - 273.15:g} degC)"
    if not t > 0.0:
        raise InputError(field, shown, "a temperature above absolute zero" + hint)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        try:
            nu = float(lubricant.kinematic_viscosity(t))
        except InputError:
            raise InputError(field, shown, (
                f"a temperature at which the {lubricant.viscosity_law} viscosity law of "
                f"{lubricant.name} is finite (it overflows here){hint}")) from None
    if lubricant.viscosity_law == "astm_d341" and nu > _D341_MAX_NU:
        raise InputError(field, shown, (
            f"a temperature at which {lubricant.name} is liquid: its ASTM D341 viscosity "
            f"there is {nu * 1e6:.3g} cSt, beyond the law's 1e6 cSt range (the oil is "
            f"below its pour point){hint}"))
    for prop in (lubricant.density, lubricant.specific_heat):
        # the oil's density and thermal laws (c_p, k) where the network evaluates them: an
        # inlet at 5000 degC (Cragoe's k < 0 above ~1850 degC) was refused later by the
        # network build, as "set by [network] parameters", naming no [supply] field
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ValidityWarning)
                prop(t)
        except InputError as exc:
            raise InputError(field, shown, f"{exc.allowed}{hint}") from None
