"""Closed-form EHL film thickness (point and line contacts), thermal reduction, film parameter.

All inputs SI. Dimensionless groups in Hamrock's notation (Hamrock, Schmid & Jacobson 2004,
``hamrock2004``):

    U = eta_0 u / (E' R_x),  G = alpha E',  W = w / (E' R_x^2) (point),  W' = w / (l E' R_x) (line)

with u the entrainment (mean) speed (u_1 + u_2)/2 and E' the effective modulus (Hamrock's
convention, twice Johnson's E*). Zero entrainment speed gives h = 0; zero load gives h = +inf
(the power laws diverge as W -> 0; callers mask unloaded contacts). Every formula warns with
:class:`~thermobearing.errors.ValidityWarning` when used outside the range its authors fitted it
over (the range is stated in each docstring and in the registry entry); the value is still
returned -- the point of the warning is that the user knows.

Registries: :data:`FILM` (isothermal film formulas, all returning a thickness [m] from the
same keyword set where possible) and :data:`THERMAL_FILM` (inlet shear-heating reduction factors
phi_T in (0, 1], multiply an isothermal film by it).

Paper 001 (``shi2015_tehl_roller``, section 4.1 and Fig. 6) compares Hamrock-Dowson with a TEHL
solution for the D1842926 roller bearing at 13218 r/min: H-D overestimates because it ignores
inlet heating; the Wilson-Sheu correction narrows but does not close the gap (> 40 %). The
validation case ``paper001_film_closed_form`` reproduces the first half of that statement.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import Any

import numba
import numpy as np

from .errors import InputError, ValidityWarning, as_floats, check_finite, check_positive
from .registry import Registry

FILM: Registry[Callable[..., Any]] = Registry(
    "film", "closed-form isothermal EHL film thickness (point and line contacts)")
THERMAL_FILM: Registry[Callable[..., Any]] = Registry(
    "thermal_film", "inlet shear-heating reduction factor phi_T of an isothermal EHL film")

_POINT_PARAMS = {
    "entrainment_speed": "m/s", "dynamic_viscosity": "Pa*s",
    "pressure_viscosity_coefficient": "1/Pa", "load": "N", "reduced_radius_x": "m",
    "reduced_radius_y": "m", "ellipticity": "-", "effective_modulus": "Pa",
}
_LINE_PARAMS = {
    "entrainment_speed": "m/s", "dynamic_viscosity": "Pa*s",
    "pressure_viscosity_coefficient": "1/Pa", "load": "N", "length": "m",
    "reduced_radius_x": "m", "effective_modulus": "Pa",
}

#: Hamrock & Dowson (1977) Part III: 34 cases with k from 1 to 8, U varied over "nearly two
#: orders of magnitude", W over "one order of magnitude", bronze/steel/silicon-nitride solids with
#: mineral oils (the paper's abstract). The numeric bounds below are approximate (the case table
#: itself was not available): U 1e-12..1e-10, W 3.7e-7..7.4e-6, G 2000..8000.
HD1977_RANGE = {"k": (1.0, 8.0), "U": (1e-12, 1e-10), "W": (0.3686e-6, 7.371e-6),
                "G": (2000.0, 8000.0)}
#: the registry's validity text of both Hamrock-Dowson (1977) formulas
_HD1977_VALIDITY = ("1 <= k <= 8, 1e-12 <= U <= 1e-10, 3.7e-7 <= W <= 7.4e-6, 2000 <= G <= 8000 "
                    "(isothermal, fully flooded, Newtonian)")
#: Pan & Hamrock (1989) line-contact ranges: approximate bounds of their numerical solutions
#: (recalled, not checked against the paper).
PH1989_RANGE = {"U": (1e-12, 1e-9), "W": (0.5e-5, 0.5e-3), "G": (1000.0, 8000.0)}
#: Dowson & Higginson (1966) line-contact ranges as fitted by the authors for steel rollers
#: (W' about 1e-5..1e-4, U about 1e-12..1e-10, G 2500..5000).
DH1966_RANGE = {"U": (1e-12, 1e-10), "W": (1e-5, 1e-4), "G": (2500.0, 5000.0)}


def _warn_range(model: str, stacklevel: int = 3,
                **groups: tuple[Any, tuple[float, float]]) -> None:
    """ValidityWarning naming ``model`` for every group (value, (low, high)) outside its fitted
    range (zero U / W are handled, not extrapolated, and not counted). ``stacklevel`` 3 points
    the warning at the caller of the film function that calls this one directly."""
    out = []
    for name, (value, (lo, hi)) in groups.items():
        v = np.asarray(value, dtype=float).ravel()
        if name in ("W", "U"):  # unloaded / stationary contacts are handled, not extrapolated
            v = v[v > 0]
        if v.size and (np.min(v) < lo * (1 - 1e-9) or np.max(v) > hi * (1 + 1e-9)):
            out.append(f"{name} in [{np.min(v):.3g}, {np.max(v):.3g}] outside [{lo:.3g}, {hi:.3g}]")
    if out:
        warnings.warn(f"{model}: " + "; ".join(out), ValidityWarning, stacklevel=stacklevel)


def _common(entrainment_speed: Any, dynamic_viscosity: Any, pressure_viscosity_coefficient: Any,
            load: Any, reduced_radius_x: Any, effective_modulus: Any
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    u = as_floats("entrainment_speed", entrainment_speed)
    check_positive("entrainment_speed", np.abs(u), allow_zero=True)
    check_positive("dynamic_viscosity", dynamic_viscosity)
    check_positive("pressure_viscosity_coefficient", pressure_viscosity_coefficient,
                   allow_zero=True)
    check_positive("load", load, allow_zero=True)
    check_positive("reduced_radius_x", reduced_radius_x)
    check_positive("effective_modulus", effective_modulus)
    ep = np.asarray(effective_modulus, dtype=float)
    rx = np.asarray(reduced_radius_x, dtype=float)
    big_u = np.asarray(dynamic_viscosity, dtype=float) * np.abs(u) / (ep * rx)
    big_g = np.asarray(pressure_viscosity_coefficient, dtype=float) * ep
    return big_u, big_g, np.asarray(load, dtype=float), rx, ep


def hamrock_dowson_ellipticity(reduced_radius_x: Any, reduced_radius_y: Any) -> Any:
    """k = 1.03 (R_y/R_x)^0.64, the approximation used in Hamrock & Dowson (1977) Part III."""
    check_positive("reduced_radius_x", reduced_radius_x)
    check_positive("reduced_radius_y", reduced_radius_y)
    ratio = np.asarray(reduced_radius_y, dtype=float) / np.asarray(reduced_radius_x, dtype=float)
    return (1.03 * ratio**0.64)[()]


def _k(reduced_radius_x: Any, reduced_radius_y: Any, ellipticity: Any) -> np.ndarray:
    if (reduced_radius_y is None) == (ellipticity is None):
        raise InputError("reduced_radius_y/ellipticity", (reduced_radius_y, ellipticity),
                         "exactly one of reduced_radius_y or ellipticity")
    if ellipticity is not None:
        check_positive("ellipticity", ellipticity)
        return np.asarray(ellipticity, dtype=float)
    return np.asarray(hamrock_dowson_ellipticity(reduced_radius_x, reduced_radius_y))


def _point_groups(model: str, entrainment_speed: Any, dynamic_viscosity: Any,
                  pressure_viscosity_coefficient: Any, load: Any, reduced_radius_x: Any,
                  reduced_radius_y: Any, ellipticity: Any, effective_modulus: Any
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Checked groups (U, G, W, R_x [m], k) of a point contact for a Hamrock-Dowson (1977)
    formula: U = eta_0 u / (E' R_x), G = alpha E', W = w / (E' R_x^2) (Hamrock et al. 2004),
    k given or 1.03 (R_y/R_x)^0.64; warns (named ``model``) outside :data:`HD1977_RANGE`."""
    big_u, big_g, w, rx, ep = _common(entrainment_speed, dynamic_viscosity,
                                      pressure_viscosity_coefficient, load, reduced_radius_x,
                                      effective_modulus)
    k = _k(reduced_radius_x, reduced_radius_y, ellipticity)
    big_w = w / (ep * rx**2)
    _warn_range(model, stacklevel=4, k=(k, HD1977_RANGE["k"]), U=(big_u, HD1977_RANGE["U"]),
                W=(big_w, HD1977_RANGE["W"]), G=(big_g, HD1977_RANGE["G"]))
    return big_u, big_g, big_w, rx, k


def _finish(h: np.ndarray, big_u: np.ndarray, big_w: np.ndarray) -> Any:
    """Zero load -> +inf (the power laws diverge as W -> 0: no EHL conjunction to size);
    zero entrainment speed -> 0. Never NaN."""
    h = np.where(big_w > 0, h, np.inf)
    return np.where(big_u > 0, h, 0.0)[()]


@FILM.register(
    "hamrock_dowson_1977_central", references=["hamrock_dowson1977"],
    parameters=_POINT_PARAMS,
    validity=_HD1977_VALIDITY)
def hamrock_dowson_1977_central(entrainment_speed: Any, dynamic_viscosity: Any,
                                pressure_viscosity_coefficient: Any, load: Any,
                                reduced_radius_x: Any, reduced_radius_y: Any = None, *,
                                ellipticity: Any = None, effective_modulus: Any) -> Any:
    """Hamrock-Dowson (1977) central film thickness of an elliptical EHL contact [m].

    h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k))

    Parameters
    ----------
    entrainment_speed : u = (u_1 + u_2)/2 [m/s]; 0 gives h = 0.
    dynamic_viscosity : eta_0 at inlet temperature, ambient pressure [Pa*s].
    pressure_viscosity_coefficient : alpha [1/Pa].
    load : normal load w [N].
    reduced_radius_x, reduced_radius_y : R_x (rolling), R_y (transverse) [m]; or give
    ellipticity : k = a/b [-] instead of R_y (k = 1.03 (R_y/R_x)^0.64 otherwise).
    effective_modulus : E' [Pa].

    Reference: Hamrock & Dowson, ASME J. Lubr. Technol. 99 (1977) 264-276 (Part III), eq. for
    H_c; fitted for 1 <= k <= 8 and the U, W, G ranges in :data:`HD1977_RANGE`.
    """
    big_u, big_g, big_w, rx, k = _point_groups(
        "hamrock_dowson_1977_central", entrainment_speed, dynamic_viscosity,
        pressure_viscosity_coefficient, load, reduced_radius_x, reduced_radius_y, ellipticity,
        effective_modulus)
    return _hd1977_central_core(big_u, big_g, big_w, rx, k)


def _hd1977_central_core(big_u: Any, big_g: Any, big_w: Any, rx: Any, k: Any) -> Any:
    """H_c of Hamrock-Dowson 1977 from the dimensionless groups (unchecked) [m]."""
    with np.errstate(divide="ignore"):
        h = rx * 2.69 * big_u**0.67 * big_g**0.53 * np.where(big_w > 0, big_w, 1.0) ** -0.067 * (
            1.0 - 0.61 * np.exp(-0.73 * k))
    return _finish(h, big_u, big_w)


def _hd1977_central_unchecked(entrainment_speed: Any, dynamic_viscosity: float,
                              pressure_viscosity_coefficient: float, load: Any,
                              reduced_radius_x: Any, reduced_radius_y: Any,
                              effective_modulus: float) -> Any:
    """:func:`hamrock_dowson_1977_central` without input checks or range warnings [m].

    For hot loops (the ball skidding residual) whose inputs were validated once: float
    arrays, speed and load >= 0, radii > 0, viscosity and E' > 0. Same formula and code
    (:func:`_hd1977_central_core`) as the public function.
    """
    ep = effective_modulus
    rx = reduced_radius_x
    big_u = dynamic_viscosity * np.abs(entrainment_speed) / (ep * rx)
    big_g = pressure_viscosity_coefficient * ep
    big_w = load / (ep * rx**2)
    k = 1.03 * (reduced_radius_y / rx) ** 0.64
    return _hd1977_central_core(big_u, big_g, big_w, rx, k)


@numba.njit(cache=True)
def _hd1977_central_nb(entrainment_speed: float, dynamic_viscosity: float,
                       pressure_viscosity_coefficient: float, load: float,
                       reduced_radius_x: float, reduced_radius_y: float,
                       effective_modulus: float) -> float:
    """Compiled scalar fast path of :func:`_hd1977_central_unchecked` for compiled callers
    (the ball skidding residual) [m]: Hamrock & Dowson 1977 central film
    H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)), k = 1.03 (R_y/R_x)^0.64,
    U = eta0 |u| / (E' R_x), G = alpha E', W = Q / (E' R_x^2); +inf at zero load, 0 at zero
    speed. Unchecked; the public functions are unchanged."""
    ep = effective_modulus
    rx = reduced_radius_x
    big_u = dynamic_viscosity * abs(entrainment_speed) / (ep * rx)
    big_g = pressure_viscosity_coefficient * ep
    big_w = load / (ep * rx**2)
    if not big_u > 0:
        return 0.0
    if not big_w > 0:
        return math.inf
    k = 1.03 * (reduced_radius_y / rx) ** 0.64
    return (rx * 2.69 * big_u**0.67 * big_g**0.53 * big_w**-0.067
            * (1.0 - 0.61 * math.exp(-0.73 * k)))


@FILM.register(
    "hamrock_dowson_1977_minimum", references=["hamrock_dowson1977"],
    parameters=_POINT_PARAMS,
    validity=_HD1977_VALIDITY)
def hamrock_dowson_1977_minimum(entrainment_speed: Any, dynamic_viscosity: Any,
                                pressure_viscosity_coefficient: Any, load: Any,
                                reduced_radius_x: Any, reduced_radius_y: Any = None, *,
                                ellipticity: Any = None, effective_modulus: Any) -> Any:
    """Hamrock-Dowson (1977) minimum film thickness of an elliptical EHL contact [m].

    h_min / R_x = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k))

    Parameters as :func:`hamrock_dowson_1977_central`. Reference: Hamrock & Dowson (1977)
    Part III, eq. for H_min; same fitted range.
    """
    big_u, big_g, big_w, rx, k = _point_groups(
        "hamrock_dowson_1977_minimum", entrainment_speed, dynamic_viscosity,
        pressure_viscosity_coefficient, load, reduced_radius_x, reduced_radius_y, ellipticity,
        effective_modulus)
    h = rx * 3.63 * big_u**0.68 * big_g**0.49 * np.where(big_w > 0, big_w, 1.0) ** -0.073 * (
        1.0 - np.exp(-0.68 * k))
    return _finish(h, big_u, big_w)


def _line_groups(model: str, ranges: dict[str, tuple[float, float]] | None,
                 entrainment_speed: Any, dynamic_viscosity: Any,
                 pressure_viscosity_coefficient: Any, load: Any, length: Any,
                 reduced_radius_x: Any, effective_modulus: Any
                 ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Checked groups (U, G, W', R_x [m]) of a line contact: U = eta_0 u / (E' R_x),
    G = alpha E', W' = w / (l E' R_x) (Hamrock et al. 2004, ch. 21); warns (named ``model``)
    where U, W' or G leave ``ranges`` (None: a formula without a fitted range)."""
    big_u, big_g, w, rx, ep = _common(entrainment_speed, dynamic_viscosity,
                                      pressure_viscosity_coefficient, load, reduced_radius_x,
                                      effective_modulus)
    check_positive("length", length)
    big_w = w / (np.asarray(length, dtype=float) * ep * rx)
    if ranges is not None:
        _warn_range(model, stacklevel=4, U=(big_u, ranges["U"]), W=(big_w, ranges["W"]),
                    G=(big_g, ranges["G"]))
    return big_u, big_g, big_w, rx


@FILM.register(
    "dowson_higginson_minimum", references=["dowson_higginson1966", "hamrock2004"],
    parameters=_LINE_PARAMS,
    validity="line contact, W' about 1e-5..1e-4, U about 1e-12..1e-10, G 2500..5000 "
             "(isothermal, fully flooded)")
def dowson_higginson_minimum(entrainment_speed: Any, dynamic_viscosity: Any,
                             pressure_viscosity_coefficient: Any, load: Any, length: Any,
                             reduced_radius_x: Any, *, effective_modulus: Any) -> Any:
    """Dowson-Higginson minimum film thickness of a line contact [m].

    h_min / R_x = 2.65 U^0.70 G^0.54 W'^-0.13, W' = w / (l E' R_x)

    Parameters: entrainment_speed [m/s], dynamic_viscosity [Pa*s],
    pressure_viscosity_coefficient [1/Pa], load w [N] over the effective length ``length`` [m],
    reduced_radius_x [m], effective_modulus E' [Pa].
    Reference: Dowson & Higginson, Elasto-Hydrodynamic Lubrication (SI ed., Pergamon 1977);
    Hamrock et al. 2004 ch. 21. Range: as fitted by the authors for steel rollers (see registry).
    """
    big_u, big_g, big_w, rx = _line_groups(
        "dowson_higginson_minimum", DH1966_RANGE, entrainment_speed, dynamic_viscosity,
        pressure_viscosity_coefficient, load, length, reduced_radius_x, effective_modulus)
    h = rx * 2.65 * big_u**0.70 * big_g**0.54 * np.where(big_w > 0, big_w, 1.0) ** -0.13
    return _finish(h, big_u, big_w)


@FILM.register(
    "pan_hamrock_minimum", references=["pan_hamrock1989"], parameters=_LINE_PARAMS,
    validity="line contact, 1e-12 <= U <= 1e-9, 5e-6 <= W' <= 5e-4, 1000 <= G <= 8000 "
             "(isothermal, Roelands viscosity, Dowson-Higginson density)")
def pan_hamrock_minimum(entrainment_speed: Any, dynamic_viscosity: Any,
                        pressure_viscosity_coefficient: Any, load: Any, length: Any,
                        reduced_radius_x: Any, *, effective_modulus: Any) -> Any:
    """Pan-Hamrock (1989) minimum film thickness of a line contact [m].

    h_min / R_x = 1.714 W'^-0.128 U^0.694 G^0.568

    Parameters as :func:`dowson_higginson_minimum`. Reference: Pan & Hamrock, ASME J. Tribol.
    111 (1989) 246-251; Hamrock et al. 2004 ch. 21.
    """
    big_u, big_g, big_w, rx = _line_groups(
        "pan_hamrock_minimum", PH1989_RANGE, entrainment_speed, dynamic_viscosity,
        pressure_viscosity_coefficient, load, length, reduced_radius_x, effective_modulus)
    h = rx * 1.714 * np.where(big_w > 0, big_w, 1.0) ** -0.128 * big_u**0.694 * big_g**0.568
    return _finish(h, big_u, big_w)


@FILM.register(
    "pan_hamrock_central", references=["pan_hamrock1989"], parameters=_LINE_PARAMS,
    validity="line contact, 1e-12 <= U <= 1e-9, 5e-6 <= W' <= 5e-4, 1000 <= G <= 8000")
def pan_hamrock_central(entrainment_speed: Any, dynamic_viscosity: Any,
                        pressure_viscosity_coefficient: Any, load: Any, length: Any,
                        reduced_radius_x: Any, *, effective_modulus: Any) -> Any:
    """Pan-Hamrock (1989) central film thickness of a line contact [m].

    h_c / R_x = 2.922 W'^-0.166 U^0.692 G^0.470

    Parameters as :func:`dowson_higginson_minimum`. Reference: Pan & Hamrock (1989).
    """
    big_u, big_g, big_w, rx = _line_groups(
        "pan_hamrock_central", PH1989_RANGE, entrainment_speed, dynamic_viscosity,
        pressure_viscosity_coefficient, load, length, reduced_radius_x, effective_modulus)
    h = rx * 2.922 * np.where(big_w > 0, big_w, 1.0) ** -0.166 * big_u**0.692 * big_g**0.470
    return _finish(h, big_u, big_w)


@FILM.register(
    "moes_line_central", references=["moes1992", "venner_lubrecht2000"],
    parameters=_LINE_PARAMS,
    validity="line contact, any M and L (asymptote interpolation); isothermal Newtonian, "
             "Roelands-type piezoviscosity represented by alpha (L = G (2U)^(1/4))")
def moes_line_central(entrainment_speed: Any, dynamic_viscosity: Any,
                      pressure_viscosity_coefficient: Any, load: Any, length: Any,
                      reduced_radius_x: Any, *, effective_modulus: Any) -> Any:
    """Moes (1992) central film thickness of a line contact [m] (asymptote interpolation).

    With M = W' (2U)^(-1/2), L = G (2U)^(1/4) and H = (h_c/R_x) (2U)^(-1/2):

        H_RI = 3 M^-1,  H_EI = 2.621 M^-1/5,  H_RP = 1.287 L^2/3,  H_EP = 1.311 M^-1/8 L^3/4
        s = 1.5 (1 + exp(-1.2 H_EI / H_RI))
        H = [ (H_RI^(7/3) + H_EI^(7/3))^(3s/7) + (H_RP^(-7/2) + H_EP^(-7/2))^(-2s/7) ]^(1/s)

    (2U uses the sum speed u_1 + u_2 = 2u). Parameters as :func:`dowson_higginson_minimum`.
    Reference: Moes, Optimum similarity analysis with applications to elastohydrodynamic
    lubrication, Wear 159 (1992) 57-66; Venner & Lubrecht, Multilevel Methods in Lubrication
    (Elsevier 2000), ch. 5. H_RI = 3/M is Moes' rigid-isoviscous asymptote of the central
    film; it is not Martin's (1916) minimum film, which in these variables is 2.448/M (the
    Reynolds-outlet solution, see ``skidding.roller_fluid.martin_coefficients``).
    The coefficients were written from memory of those sources (not re-read against them).
    Evidence that they are right: the tests check the formula's own limits and agreement with
    Dowson-Toyoda's central film within 5 %, and the numerical line-contact EHL solver
    (:mod:`thermobearing.ehl`, an independent code path) lands within 0.3-6.8 % of it for
    M = 10-300, L = 2-20 (validation case ``ehl_moes_line``).
    """
    big_u, big_g, big_w, rx = _line_groups(
        "moes_line_central", None, entrainment_speed, dynamic_viscosity,
        pressure_viscosity_coefficient, load, length, reduced_radius_x, effective_modulus)
    w_safe = np.where(big_w > 0, big_w, 1.0)
    two_u = np.where(big_u > 0, 2.0 * big_u, 1.0)
    m = w_safe * two_u**-0.5
    lam = big_g * two_u**0.25
    h_ri = 3.0 / m
    h_ei = 2.621 * m**-0.2
    # a vanishing lambda (L below ~1e-130) overflows h_rp**-3.5 to inf, whose power
    # -2s/7 is the right limit 0 (the piezoviscous asymptotes vanish): no warning
    with np.errstate(divide="ignore", over="ignore"):
        h_rp = 1.287 * lam ** (2.0 / 3.0)
        h_ep = 1.311 * m**-0.125 * lam**0.75
        s = 1.5 * (1.0 + np.exp(-1.2 * h_ei / h_ri))
        viscous = (h_ri ** (7 / 3) + h_ei ** (7 / 3)) ** (3 * s / 7)
        if np.all(lam > 0):
            piezo = (h_rp**-3.5 + h_ep**-3.5) ** (-2 * s / 7)
        else:  # isoviscous: the piezoviscous asymptotes vanish
            piezo = np.where(lam > 0, (np.where(lam > 0, h_rp, 1.0) ** -3.5
                                       + np.where(lam > 0, h_ep, 1.0) ** -3.5) ** (-2 * s / 7),
                             0.0)
    big_h = (viscous + piezo) ** (1.0 / s)
    h = rx * big_h * two_u**0.5
    return _finish(h, big_u, big_w)


# ---------------------------------------------------------------------------
# thermal reduction
# ---------------------------------------------------------------------------
_THERMAL_PARAMS = {
    "entrainment_speed": "m/s", "dynamic_viscosity": "Pa*s",
    "temperature_viscosity_coefficient": "1/K", "thermal_conductivity": "W/(m*K)",
    "slide_to_roll": "-", "max_pressure": "Pa", "effective_modulus": "Pa",
}


def thermal_loading(entrainment_speed: Any, dynamic_viscosity: Any,
                    temperature_viscosity_coefficient: Any, thermal_conductivity: Any) -> Any:
    """Thermal loading number L = beta eta_0 u^2 / k_f [-] (beta = -(1/eta) d eta/dT [1/K]).

    Cheng's / Murch-Wilson's inlet-heating parameter (Gupta et al. 1992; Wilson & Sheu 1983).
    """
    check_finite("entrainment_speed", entrainment_speed)  # NaN gave NaN silently
    check_positive("dynamic_viscosity", dynamic_viscosity)
    check_positive("temperature_viscosity_coefficient", temperature_viscosity_coefficient,
                   allow_zero=True)
    check_positive("thermal_conductivity", thermal_conductivity)
    u = np.asarray(entrainment_speed, dtype=float)
    return (np.asarray(temperature_viscosity_coefficient, dtype=float)
            * np.asarray(dynamic_viscosity, dtype=float) * u**2
            / np.asarray(thermal_conductivity, dtype=float))[()]


def _inlet_groups(entrainment_speed: Any, dynamic_viscosity: Any,
                  temperature_viscosity_coefficient: Any, thermal_conductivity: Any,
                  slide_to_roll: Any) -> tuple[np.ndarray, np.ndarray]:
    """Checked (L, S) of an inlet shear-heating correction: the thermal loading number
    L = beta eta_0 u^2 / k_f (:func:`thermal_loading`) and |slide-to-roll ratio| S [-]."""
    big_l = np.asarray(thermal_loading(entrainment_speed, dynamic_viscosity,
                                       temperature_viscosity_coefficient, thermal_conductivity))
    check_finite("slide_to_roll", slide_to_roll)
    return big_l, np.abs(np.asarray(slide_to_roll, dtype=float))


@THERMAL_FILM.register(
    "none", references=["hamrock2004"], parameters={},
    validity="isothermal inlet (low speed, low viscosity-temperature sensitivity)")
def no_thermal_reduction(**_: Any) -> float:
    """No inlet-heating correction: phi_T = 1 (the isothermal formulas as they are)."""
    return 1.0


@THERMAL_FILM.register(
    "wilson_sheu_1983", references=["wilson_sheu1983"],
    parameters={k: v for k, v in _THERMAL_PARAMS.items()
                if k not in ("max_pressure", "effective_modulus")},
    validity="0 <= L <= about 10, slide-to-roll 0..2 (fit to Newtonian inlet analyses)")
def wilson_sheu_1983(entrainment_speed: Any, dynamic_viscosity: Any,
                     temperature_viscosity_coefficient: Any, thermal_conductivity: Any,
                     slide_to_roll: Any = 0.0, **_: Any) -> Any:
    """Wilson-Sheu (1983) inlet shear-heating reduction factor phi_T [-].

    phi_T = 1 / (1 + 0.241 (1 + 14.8 S^0.83) L^0.64),   L = beta eta_0 u^2 / k_f

    with S = |u_1 - u_2| / u the slide-to-roll ratio. phi_T -> 1 as u -> 0. Paper 001 cites it
    (its ref. 14) and reports it still > 40 % above its TEHL film. Coefficients as quoted in
    the secondary literature (Harris & Kotzalas 2007 vol. 2); the original note (Trans. ASME
    J. Lubr. Technol. 105 (1983) 187-188) was not available to re-check them.
    """
    big_l, s = _inlet_groups(entrainment_speed, dynamic_viscosity,
                             temperature_viscosity_coefficient, thermal_conductivity,
                             slide_to_roll)
    _warn_range("wilson_sheu_1983", L=(big_l, (0.0, 10.0)), S=(s, (0.0, 2.0)))
    return (1.0 / (1.0 + 0.241 * (1.0 + 14.8 * s**0.83) * big_l**0.64))[()]


@THERMAL_FILM.register(
    "gupta_1992", references=["gupta1992"], parameters=_THERMAL_PARAMS,
    validity="0 <= L <= about 10, slide-to-roll 0..2, p_max/E' <= about 0.01")
def gupta_1992(entrainment_speed: Any, dynamic_viscosity: Any,
               temperature_viscosity_coefficient: Any, thermal_conductivity: Any,
               slide_to_roll: Any = 0.0, max_pressure: Any = 0.0,
               effective_modulus: Any = 2.28e11, **_: Any) -> Any:
    """Gupta et al. (1992) inlet shear-heating reduction factor phi_T [-].

    phi_T = (1 - 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64)

    with L = beta eta_0 u^2 / k_f, S the slide-to-roll ratio and p_h the Hertz pressure.
    phi_T -> 1 as u -> 0. Clipped below at 0.05 (the fit is not meant for the regime where the
    numerator vanishes; a ValidityWarning says so). Coefficients as quoted by Harris &
    Kotzalas (2007, vol. 2); original: Gupta, Cheng, Zhu, Forster, Schrand, Tribol. Trans. 35
    (1992) 269-274.
    """
    big_l, s = _inlet_groups(entrainment_speed, dynamic_viscosity,
                             temperature_viscosity_coefficient, thermal_conductivity,
                             slide_to_roll)
    check_positive("max_pressure", max_pressure, allow_zero=True)
    check_positive("effective_modulus", effective_modulus)
    ph = np.asarray(max_pressure, dtype=float) / np.asarray(effective_modulus, dtype=float)
    _warn_range("gupta_1992", L=(big_l, (0.0, 10.0)), S=(s, (0.0, 2.0)), p_over_E=(ph, (0, 0.01)))
    with np.errstate(invalid="ignore"):
        phi = (1.0 - 13.2 * ph * big_l**0.42) / (1.0 + 0.213 * (1.0 + 2.23 * s**0.83)
                                                 * big_l**0.64)
    # L -> inf (L overflows for absurd speeds): numerator ~ -L^0.42 or 1, denominator ~ L^0.64,
    # so phi -> 0 (clipped below); inf/inf would otherwise be NaN
    phi = np.where(np.isinf(big_l), 0.0, phi)
    if np.any(phi < 0.05):
        warnings.warn("gupta_1992: phi_T below 0.05 clipped (outside the fitted regime)",
                      ValidityWarning, stacklevel=2)
    return np.maximum(phi, 0.05)[()]


# ---------------------------------------------------------------------------
# film parameter
# ---------------------------------------------------------------------------
def composite_roughness(sigma1: Any, sigma2: Any) -> Any:
    """sigma = (sigma_1^2 + sigma_2^2)^(1/2) [m] (RMS roughnesses Rq of the two surfaces)."""
    check_positive("sigma1", sigma1, allow_zero=True)
    check_positive("sigma2", sigma2, allow_zero=True)
    return np.hypot(np.asarray(sigma1, dtype=float), np.asarray(sigma2, dtype=float))[()]


def film_parameter(h: Any, sigma1: Any, sigma2: Any) -> Any:
    """Lambda = h / (sigma_1^2 + sigma_2^2)^(1/2) [-] (Hamrock et al. 2004, ch. 3).

    h : film thickness [m] (usually h_min); sigma1, sigma2 : RMS roughness [m] (not both 0).
    Lambda < 1 boundary, 1-3 mixed, > 3 full-film lubrication (ibid.).
    """
    check_positive("h", h, allow_zero=True)
    sigma = np.asarray(composite_roughness(sigma1, sigma2))
    if np.any(sigma <= 0):
        raise InputError("sigma1/sigma2", (sigma1, sigma2), "at least one roughness > 0")
    return (np.asarray(h, dtype=float) / sigma)[()]


def equivalent_ellipticity_of_roller(half_width: Any, length: Any) -> Any:
    """k = l / (2 b): the aspect ratio of a roller's rectangular Hertz band [-].

    Used to apply the point-contact Hamrock-Dowson formulas to a roller (as the quasi-dynamic
    codes compared in paper 001 do); k > 8 is beyond their fitted range and warns there.
    """
    check_positive("half_width", half_width)
    check_positive("length", length)
    return (np.asarray(length, dtype=float) / (2.0 * np.asarray(half_width, dtype=float)))[()]


__all__ = [
    "FILM", "THERMAL_FILM", "hamrock_dowson_1977_central", "hamrock_dowson_1977_minimum",
    "dowson_higginson_minimum", "pan_hamrock_minimum", "pan_hamrock_central",
    "moes_line_central", "wilson_sheu_1983", "gupta_1992", "no_thermal_reduction",
    "thermal_loading", "film_parameter", "composite_roughness", "hamrock_dowson_ellipticity",
    "equivalent_ellipticity_of_roller",
]
