"""EHL rolling resistance of elliptical (ball-race) contacts, with inlet reduction factors.

One job: the hydrodynamic rolling (inlet / Poiseuille) force F_R of a lubricated point
contact and the factors that reduce it at speed, as pure functions (SI in and out). The
skidding solver of ball bearings (:mod:`thermobearing.skidding.ball_residual_kernels`) and
the ``ehl_rolling_resistance`` heat source (:mod:`thermobearing.heat_sources.raceway`) both
evaluate the force through :func:`contact_rolling_force` (compiled, one code path), so the
heat is exactly the power of the force the solver balances.

Force (isothermal, fully flooded), Harris & Kotzalas (2007), *Advanced Concepts of Bearing
Technology*, the hydrodynamic rolling force of a ball-raceway contact:

    F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47
    U = eta0 u / (E' R_x),  G = alpha E',  W = Q / (E' R_x^2),  k = a/b = (R_y/R_x)^(2/pi)

u the entrainment (mean surface) speed, E' the effective modulus in Hamrock's convention
(as :mod:`thermobearing.film`), k the ellipticity of the Hertz ellipse by Hamrock & Brewe's
closed form (the one the ball solver's Hertz ellipse uses). The coefficient and exponents are
**recalled, not verified** against the book (the print was not available here); the
exponents put F_R close to the film's own scaling (h ~ U^0.67, Hamrock-Dowson 1977), which is
what an inlet (Poiseuille) force of an EHL film should follow: F_R ~ p_inlet-gradient x h x
width. Dimensional form: F_R = 2.86 k^0.348 (alpha E')^0.022 (eta0 u)^0.66 Q^0.47
E'^-0.13 R_x^0.4.

Reduction factors (multiply F_R; ``REDUCTIONS``):

- ``"thermal"``: inlet shear heating, Gupta et al. (1992) phi_T (the formula of
  :func:`thermobearing.film.gupta_1992`, checked equal in the tests) with the thermal loading
  L = beta eta0 u^2 / k_f, slide-to-roll S = |V|/u and p_h/E'. phi_T is a *film* factor; read
  as an effective inlet viscosity eta_T with h(eta_T) = phi_T h(eta0), i.e. eta_T/eta0 =
  phi_T^(1/0.67) (h ~ eta0^0.67), the force scales by phi_T^(0.66/0.67) (F_R ~ eta0^0.66).
  This mapping is this module's assumption; the line-contact models of the heat source
  (:mod:`thermobearing.heat_sources.raceway`, ``thermal_reduction``) read phi_T the same way
  with Dowson-Higginson's exponent 0.7: eq. 35 x phi_T, Martin's rigid film x phi_T^(5/7).
- ``"skf"``: the SKF 2004 model's bearing-level factors phi_ish phi_rs (SKF catalogue
  "The SKF model for calculating the frictional moment", as implemented in
  :func:`thermobearing.global_friction.skf_four_term`): phi_ish = 1/(1 + 1.84e-9 (n d_m)^1.28
  nu^0.64) (inlet shear heating), phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d))))
  (kinematic replenishment / starvation; K_rs = 3e-8 oil bath / jet / circulation, 6e-8
  grease / oil-air), catalogue units (n r/min, nu mm^2/s, d, D, d_m mm). SKF fits them to its
  own rolling term G_rr (nu n)^0.6, not to an EHL inlet force: applying them to F_R is a
  model choice, stated as such.
- ``"thermal_starvation"``: phi_T^(0.66/0.67) (per contact) x phi_rs (bearing).

All speeds, loads and radii SI; forces in N.
"""

from __future__ import annotations

import math
from typing import Any

import numba
import numpy as np

from .errors import InputError, UnknownNameError, check_positive

__all__ = [
    "MODELS", "REDUCTIONS", "contact_rolling_force", "gupta_thermal_factor",
    "harris_rolling_force", "kernel_parameters", "rolling_force_array",
    "skf_inlet_shear_factor", "skf_replenishment_factor", "supply_factor",
]

#: rolling-force models: "none" (no rolling resistance), "harris" (point contact, above)
MODELS = ("none", "harris")
#: reduction factors of the rolling force (module docstring)
REDUCTIONS = ("none", "thermal", "skf", "thermal_starvation")

# kernel parameter layout (float array): model on (1/0), eta0 [Pa s], alpha [1/Pa], E' [Pa],
# constant (bearing-level) factor [-], thermal on (1/0), L coefficient beta eta0 / k_f [s^2/m^2]
(K_ON, K_ETA, K_ALPHA, K_EP, K_FACTOR, K_THERMAL, K_LCOEF) = range(7)
N_KERNEL = 7
#: exponent mapping the film's thermal factor onto the rolling force (module docstring)
THERMAL_EXPONENT = 0.66 / 0.67


@numba.njit(cache=True, error_model="numpy")
def _harris_nb(u: float, q: float, rx: float, ry: float, eta0: float, alpha: float,
               ep: float) -> float:
    """F_R of Harris & Kotzalas (module docstring) [N]; 0 for u <= 0 or Q <= 0."""
    if not (u > 0.0 and q > 0.0):
        return 0.0
    k_el = (ry / rx) ** (2.0 / math.pi)
    big_u = eta0 * u / (ep * rx)
    big_w = q / (ep * rx * rx)
    g = alpha * ep
    gg = g ** 0.022 if g > 0.0 else 0.0
    return 2.86 * ep * rx * rx * k_el ** 0.348 * gg * big_u ** 0.66 * big_w ** 0.47


@numba.njit(cache=True, error_model="numpy")
def _gupta_nb(u: float, s: float, ph: float, lcoef: float) -> float:
    """Gupta et al. (1992) phi_T at L = lcoef u^2, S = s, p_h/E' = ph, clipped at 0.05 --
    the formula of :func:`thermobearing.film.gupta_1992` [-]."""
    big_l = lcoef * u * u
    if big_l <= 0.0:
        return 1.0
    sp = s ** 0.83 if s > 0.0 else 0.0
    phi = (1.0 - 13.2 * ph * big_l ** 0.42) / (1.0 + 0.213 * (1.0 + 2.23 * sp)
                                               * big_l ** 0.64)
    return max(phi, 0.05)


@numba.njit(cache=True, error_model="numpy")
def contact_rolling_force(ue: float, vy: float, q: float, p0: float, rx: float, ry: float,
                          kp: np.ndarray) -> float:
    """Rolling force F_R [N] of one contact with its reductions -- the one code path of the
    ball solver and the heat source.

    ue entrainment speed [m/s] (sign ignored), vy sliding speed [m/s], q normal load [N],
    p0 Hertz pressure [Pa], rx, ry reduced radii [m], kp :func:`kernel_parameters`.
    F_R = factor x phi_T^(0.66/0.67) x Harris F_R (module docstring); 0 when kp is "none".
    """
    if kp[K_ON] == 0.0:
        return 0.0
    u = abs(ue)
    f = _harris_nb(u, q, rx, ry, kp[K_ETA], kp[K_ALPHA], kp[K_EP]) * kp[K_FACTOR]
    if kp[K_THERMAL] != 0.0 and f > 0.0:
        phi = _gupta_nb(u, abs(vy) / u, p0 / kp[K_EP], kp[K_LCOEF])
        f *= phi ** THERMAL_EXPONENT
    return f


@numba.njit(cache=True)
def _rolling_force_rows(ue, vy, q, p0, rx, ry, kp):
    out = np.empty(ue.size)
    for i in range(ue.size):
        out[i] = contact_rolling_force(ue[i], vy[i], q[i], p0[i], rx[i], ry[i], kp)
    return out


def rolling_force_array(entrainment_speed, sliding_speed, normal_load, max_pressure,
                        reduced_radius_x, reduced_radius_y, kernel_params) -> np.ndarray:
    """:func:`contact_rolling_force` over arrays (broadcast) [N]."""
    arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (
        entrainment_speed, sliding_speed, normal_load, max_pressure, reduced_radius_x,
        reduced_radius_y)))
    flat = [np.ascontiguousarray(a).ravel() for a in arrays]
    kp = np.ascontiguousarray(kernel_parameters_checked(kernel_params))
    return _rolling_force_rows(*flat, kp).reshape(arrays[0].shape)


def kernel_parameters_checked(kp) -> np.ndarray:
    kp = np.asarray(kp, dtype=float)
    if kp.shape != (N_KERNEL,) or not np.all(np.isfinite(kp)):
        raise InputError("rolling resistance kernel parameters", kp,
                         f"{N_KERNEL} finite values (rolling_resistance.kernel_parameters)")
    return kp


def harris_rolling_force(entrainment_speed, normal_load, reduced_radius_x, reduced_radius_y,
                         viscosity, pressure_viscosity, effective_modulus) -> np.ndarray:
    """Isothermal, fully flooded hydrodynamic rolling force F_R of a ball-race contact [N].

    F_R = 2.86 E' R_x^2 k^0.348 G^0.022 U^0.66 W^0.47 (Harris & Kotzalas 2007, recalled;
    module docstring), U = eta0 u / (E' R_x), G = alpha E', W = Q / (E' R_x^2),
    k = (R_y/R_x)^(2/pi).

    Parameters
    ----------
    entrainment_speed : u = (u_1 + u_2)/2 [m/s] (magnitude used).
    normal_load : Q [N].  reduced_radius_x, reduced_radius_y : R_x, R_y [m].
    viscosity : eta0 at the inlet [Pa s].  pressure_viscosity : alpha [1/Pa].
    effective_modulus : E' [Pa] (Hamrock convention).
    """
    check_positive("viscosity", viscosity)
    check_positive("pressure_viscosity", pressure_viscosity, allow_zero=True)
    check_positive("effective_modulus", effective_modulus)
    check_positive("reduced_radius_x", reduced_radius_x)
    check_positive("reduced_radius_y", reduced_radius_y)
    check_positive("normal_load", normal_load, allow_zero=True)
    kp = kernel_parameters("harris", viscosity=float(viscosity),
                           pressure_viscosity=float(pressure_viscosity),
                           effective_modulus=float(effective_modulus))
    return rolling_force_array(entrainment_speed, 0.0, normal_load, 0.0, reduced_radius_x,
                               reduced_radius_y, kp)


def gupta_thermal_factor(entrainment_speed, slide_to_roll, max_pressure, effective_modulus,
                         viscosity, temperature_viscosity_coefficient,
                         thermal_conductivity) -> np.ndarray:
    """Gupta et al. (1992) inlet shear-heating film factor phi_T [-] (compiled form of
    :func:`thermobearing.film.gupta_1992`, clipped at 0.05 as there, without its range
    warnings): phi_T = (1 - 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64),
    L = beta eta0 u^2 / k_f. Speeds m/s, pressures Pa, eta0 Pa s, beta 1/K, k_f W/(m K)."""
    lcoef = (float(temperature_viscosity_coefficient) * float(viscosity)
             / float(thermal_conductivity))
    u, s, p = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (
        entrainment_speed, slide_to_roll, max_pressure)))
    ph = p / float(effective_modulus)
    out = np.array([_gupta_nb(abs(a), abs(b), c, lcoef) for a, b, c in zip(
        u.ravel(), s.ravel(), ph.ravel(), strict=True)])
    return out.reshape(u.shape)


def skf_inlet_shear_factor(speed: float, pitch_diameter: float,
                           kinematic_viscosity: float) -> float:
    """SKF 2004 inlet shear heating factor phi_ish [-] (module docstring).

    phi_ish = 1/(1 + 1.84e-9 (n d_m)^1.28 nu^0.64) with n [r/min], d_m [mm], nu [mm^2/s];
    arguments SI: speed [rad/s], pitch_diameter [m], kinematic_viscosity [m^2/s]."""
    n = abs(float(speed)) * 30.0 / math.pi
    dm = float(pitch_diameter) * 1e3
    nu = float(kinematic_viscosity) * 1e6
    return 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)


def skf_replenishment_factor(speed: float, kinematic_viscosity: float, bore: float,
                             outer_diameter: float, kz: float, method: str) -> float:
    """SKF 2004 kinematic replenishment / starvation factor phi_rs [-] (module docstring).

    phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))), catalogue units (n r/min,
    nu mm^2/s, d, D mm); K_rs = 6e-8 for ``method`` "grease" / "oil_air", else 3e-8;
    K_Z the SKF bearing-type constant (``global_friction.SKF_KZ``). Arguments SI."""
    n = abs(float(speed)) * 30.0 / math.pi
    nu = float(kinematic_viscosity) * 1e6
    d, big_d = float(bore) * 1e3, float(outer_diameter) * 1e3
    if not big_d > d > 0.0:
        raise InputError("bearing bore / outer_diameter", (bore, outer_diameter),
                         "0 < bore < outer diameter [m]")
    k_rs = 6e-8 if method in ("grease", "oil_air") else 3e-8
    return math.exp(-k_rs * nu * n * (d + big_d) * math.sqrt(kz / (2.0 * (big_d - d))))


def supply_factor(reduction: str, bearing: Any, speed: float, kinematic_viscosity: float,
                  method: str) -> float:
    """The bearing-level (constant) part of a reduction [-]: phi_ish phi_rs for "skf",
    phi_rs for "thermal_starvation", 1 otherwise. ``bearing`` has kind, bore,
    outer_diameter, pitch_diameter (SI); speed [rad/s]; nu [m^2/s]; method the supply's."""
    if reduction not in REDUCTIONS:
        raise UnknownNameError("rolling_resistance_reduction", reduction, REDUCTIONS)
    if reduction in ("none", "thermal"):
        return 1.0
    from .global_friction import SKF_KZ

    kz = SKF_KZ.get(getattr(bearing, "kind", ""), SKF_KZ["deep_groove"])
    rs = skf_replenishment_factor(speed, kinematic_viscosity, bearing.bore,
                                  bearing.outer_diameter, kz, method)
    if reduction == "thermal_starvation":
        return rs
    return rs * skf_inlet_shear_factor(speed, bearing.pitch_diameter, kinematic_viscosity)


def kernel_parameters(model: str, *, viscosity: float = 0.0, pressure_viscosity: float = 0.0,
                      effective_modulus: float = 0.0, reduction: str = "none",
                      factor: float = 1.0, temperature_viscosity_coefficient: float = 0.0,
                      thermal_conductivity: float = 1.0) -> np.ndarray:
    """Parameter array of :func:`contact_rolling_force` (SI).

    model : "none" | "harris".  viscosity eta0 [Pa s], pressure_viscosity alpha [1/Pa] and
    effective_modulus E' [Pa] at the contact inlet.  reduction : one of ``REDUCTIONS``
    ("thermal" and "thermal_starvation" need beta = -d ln eta/dT [1/K] and the oil's
    thermal_conductivity [W/(m K)]).  factor : the bearing-level factor of the reduction
    (:func:`supply_factor`), 1 for "none" / "thermal".
    """
    if model not in MODELS:
        raise UnknownNameError("rolling_resistance", model, MODELS)
    if reduction not in REDUCTIONS:
        raise UnknownNameError("rolling_resistance_reduction", reduction, REDUCTIONS)
    kp = np.zeros(N_KERNEL)
    if model == "none":
        return kp
    check_positive("rolling resistance viscosity", viscosity)
    check_positive("rolling resistance pressure_viscosity", pressure_viscosity,
                   allow_zero=True)
    check_positive("rolling resistance effective_modulus", effective_modulus)
    check_positive("rolling resistance factor", factor, allow_zero=True)
    kp[K_ON] = 1.0
    kp[K_ETA] = viscosity
    kp[K_ALPHA] = pressure_viscosity
    kp[K_EP] = effective_modulus
    kp[K_FACTOR] = factor
    if reduction in ("thermal", "thermal_starvation"):
        check_positive("rolling resistance temperature_viscosity_coefficient",
                       temperature_viscosity_coefficient, allow_zero=True)
        check_positive("rolling resistance thermal_conductivity", thermal_conductivity)
        kp[K_THERMAL] = 1.0
        kp[K_LCOEF] = temperature_viscosity_coefficient * viscosity / thermal_conductivity
    return kp


def lubricant_kernel_parameters(model: str, reduction: str, lubricant: Any,
                                temperature: float, effective_modulus: float,
                                factor: float = 1.0) -> np.ndarray:
    """:func:`kernel_parameters` with the lubricant's properties at ``temperature`` [K]:
    eta0, alpha, beta = -d ln eta/dT by a central difference (+-0.5 K, as the roller
    rolling-resistance source) and k_f. The solver and the heat source both build their
    parameters here."""
    if model == "none":
        return kernel_parameters("none")
    t = float(temperature)
    eta = float(lubricant.dynamic_viscosity(t))
    alpha = float(lubricant.pressure_viscosity_coefficient(t))
    beta = -(math.log(float(lubricant.dynamic_viscosity(t + 0.5)))
             - math.log(float(lubricant.dynamic_viscosity(t - 0.5))))
    k_oil = float(lubricant.thermal_conductivity(t))
    return kernel_parameters(model, viscosity=eta, pressure_viscosity=alpha,
                             effective_modulus=float(effective_modulus), reduction=reduction,
                             factor=float(factor), temperature_viscosity_coefficient=beta,
                             thermal_conductivity=k_oil)
