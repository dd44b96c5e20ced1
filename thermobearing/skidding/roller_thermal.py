"""Inlet shear heating of the roller skidding solver's rolling force (option ``thermal_reduction``).

One job: the film thermal-reduction factor phi_T of a roller-raceway line contact as the
roller skidding solver needs it, a function of the contact's entrainment speed, slide-to-roll
ratio and Hertz pressure at the solve's fixed lubricant and temperature
(:func:`inlet_heating_factor`), and the option's default and check
(:func:`resolve_thermal_reduction`, :func:`default_thermal_reduction`).

The factor is the one the line-contact rolling-resistance heat source applies
(``heat_sources.raceway.ehl_rolling_resistance``, option ``thermal_reduction``, default
``heat_sources.raceway.DEFAULT_THERMAL_REDUCTION``): the ``film.THERMAL_FILM`` entry of that
name (Gupta et al. 1992 by default,

    phi_T = (1 - 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64),
    L = beta eta0 u^2 / k_f,

Gupta, Cheng, Zhu, Forster, Schrand, Tribol. Trans. 35 (1992) 269-274, as quoted by Harris &
Kotzalas 2007), with the temperature-viscosity coefficient beta = -d ln eta / dT by the same
central difference (+-0.5 K) and the oil's thermal conductivity k_f at the contact
temperature. It is read, as there, as an effective inlet viscosity

    eta_T = eta0 phi_T^(1/0.7)        (``heat_sources.raceway.DH_VISCOSITY_EXPONENT``)

(Dowson-Higginson's film and paper 000 eq. 35's force both go as (eta0 u)^0.7), at which
the rolling force Q_x of :func:`~thermobearing.skidding.roller_fluid.
closed_form_contact_forces` is evaluated: eq. 35 falls by phi_T, Martin's rigid-isoviscous
force (~ eta0^0.5) by phi_T^(5/7). The film thickness and the Couette shear keep eta0.
A skidding state carries the reduced forces (kinematic state extras
``raceway_rolling_force``, the name in ``raceway_rolling_thermal_reduction``) and the heat
source books them, so the energy identity (shaft power = booked heat) holds with either
setting.

Measured (NU 214, 10 kN, ISO VG 46 at 50 degC, jet 2 L/min, skidding at a fixed 323.15 K,
2026-11-24), "none" -> "gupta_1992": rolling loss 144.8 -> 131.4 / 489.2 -> 397.0 /
1039.7 -> 755.9 / 1867.9 -> 1223.6 / 3037.7 -> 1809.2 W and total 239.4 -> 224.6 /
860.7 -> 757.6 / 1846.5 -> 1520.5 / 3315.8 -> 2577.8 / 5272.0 -> 3902.5 W at 2000 / 4000 /
6000 / 8000 / 10000 r/min (the rolling loss falls by 0.907 / 0.812 / 0.727 / 0.655 / 0.596,
race control's by 0.914 / 0.826 / 0.747 / 0.678 / 0.618); the cage speed ratio stays
within 2e-6 of the epicyclic 0.433333 either way. Newton with the
finite-difference arrow Jacobian, which differentiates the factor with the rest of the
residual, takes 14 / 12 / 12 / 10 / 9 steps against 16 / 12 / 16 / 17 / 16 isothermal.

Inputs SI: u [m/s] the mean surface (entrainment) speed (|u_race + u_roller|/2), S = |V|/u
[-], p_h [Pa]; temperature [K]; E' [Pa].
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from typing import Any

import numpy as np

from ..errors import InputError, ValidityWarning

#: a roller-raceway thermal factor: (u [m/s], S [-], p_h [Pa]) -> phi_T [-], arrays over rollers
InletHeating = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]


def default_thermal_reduction() -> str:
    """The solver's ``thermal_reduction`` when none is named: the line-contact
    rolling-resistance heat source's default, ``heat_sources.raceway.
    DEFAULT_THERMAL_REDUCTION`` ("gupta_1992"), the one name both read (read at each call),
    so ``skidding.solve`` called directly and a scene's heat source apply the same rolling
    force. Paper 000's validation cases name "none" (its eq. 35 is isothermal)."""
    from ..heat_sources.raceway import DEFAULT_THERMAL_REDUCTION

    return str(DEFAULT_THERMAL_REDUCTION)


def viscosity_exponent() -> float:
    """Exponent of eta0 u in Dowson-Higginson's film and eq. 35's force (0.7): phi_T is the
    inlet viscosity factor phi_T^(1/0.7) (``heat_sources.raceway.DH_VISCOSITY_EXPONENT``)."""
    from ..heat_sources.raceway import DH_VISCOSITY_EXPONENT

    return float(DH_VISCOSITY_EXPONENT)


def resolve_thermal_reduction(name: str | None, supported: bool, drag_model: str) -> str:
    """The solver's ``thermal_reduction``: ``None`` is :func:`default_thermal_reduction`
    for a drag model whose rolling force takes it (``supported``, the closed-form one and
    its Hertz-zone variants) and "none" for one that integrates its own (isothermal) film
    pressure; a ``film.THERMAL_FILM`` name otherwise. InputError / UnknownNameError name the
    option, the value and what is allowed."""
    from ..film import THERMAL_FILM

    if name is None:
        return default_thermal_reduction() if supported else "none"
    if not isinstance(name, str):
        raise InputError("thermal_reduction", name,
                         "a name of film.THERMAL_FILM: " + ", ".join(THERMAL_FILM.names()))
    THERMAL_FILM.entry(name)  # unknown names raise, listing the known ones
    if name != "none" and not supported:
        raise InputError("thermal_reduction", name,
                         f"'none' with drag_model={drag_model!r} (its rolling force is the "
                         "pressure of its own film solution; the inlet-heating reduction "
                         "applies to the closed-form rolling force)")
    return name


def temperature_viscosity_coefficient(lubricant: Any, temperature: float) -> float:
    """beta = -d ln eta / dT [1/K] of the lubricant at ``temperature`` [K] by the central
    difference over +-0.5 K (the rolling-resistance heat source's difference)."""
    t = float(temperature)
    return float(-(np.log(float(np.asarray(lubricant.dynamic_viscosity(t + 0.5))))
                   - np.log(float(np.asarray(lubricant.dynamic_viscosity(t - 0.5))))))


def inlet_heating_factor(name: str, lubricant: Any, temperature: float, eta0: float,
                         effective_modulus: float) -> InletHeating | None:
    """phi_T(u, S, p_h) of the ``film.THERMAL_FILM`` entry ``name`` (module docstring) at the
    lubricant's beta and k_f at ``temperature`` [K] and the inlet viscosity eta0 [Pa s];
    None for "none". Evaluated inside the solve without the film functions' range warnings
    (the iterates pass states far from the solution); :func:`check_state_range` warns on
    the solved state."""
    if name == "none":
        return None
    from ..film import THERMAL_FILM

    func = THERMAL_FILM.get(name)
    beta = temperature_viscosity_coefficient(lubricant, temperature)
    k_f = float(np.asarray(lubricant.thermal_conductivity(float(temperature))))
    e_prime = float(effective_modulus)
    eta = float(eta0)

    def phi(u: np.ndarray, s: np.ndarray, p_h: np.ndarray) -> np.ndarray:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            out = func(entrainment_speed=u, dynamic_viscosity=eta,
                       temperature_viscosity_coefficient=beta, thermal_conductivity=k_f,
                       slide_to_roll=s, max_pressure=p_h, effective_modulus=e_prime)
        return np.asarray(out, dtype=float) * np.ones(np.shape(u))

    phi.spec = {"name": name, "beta": beta, "thermal_conductivity": k_f,  # type: ignore
                "eta0": eta, "effective_modulus": e_prime}
    return phi


def check_state_range(factor: InletHeating | None,
                      contacts: list[tuple[Any, Any, Any, Any]]) -> None:
    """The factor's own fitted-range warnings (``film.THERMAL_FILM``, ValidityWarning) on
    the loaded contacts of a solved state, at the oil data ``factor`` was built with
    (:func:`inlet_heating_factor`; nothing for None): ``contacts`` is a list of (load [N],
    entrainment speed [m/s], sliding speed [m/s], Hertz pressure [Pa]) arrays, one per
    raceway."""
    spec = getattr(factor, "spec", None)
    if spec is None:
        return
    from ..film import THERMAL_FILM

    for q, ue, v, p_h in contacts:
        loaded = np.asarray(q, float) > 0.0
        if not np.any(loaded):
            continue
        u = np.maximum(np.abs(np.asarray(ue, float)[loaded]), 1e-6)
        THERMAL_FILM.get(spec["name"])(
            entrainment_speed=u, dynamic_viscosity=spec["eta0"],
            temperature_viscosity_coefficient=spec["beta"],
            thermal_conductivity=spec["thermal_conductivity"],
            slide_to_roll=np.abs(np.asarray(v, float)[loaded]) / u,
            max_pressure=np.asarray(p_h, float)[loaded],
            effective_modulus=spec["effective_modulus"])
