"""Force models of the ball skidding solver, built from the heat-source physics (owner F).

The solver must balance exactly the forces whose power the heat sources report, so every
drag model here is a thin adapter around the functions of :mod:`thermobearing.heat_sources`
(one code path):

- raceway traction: :func:`thermobearing.contact_traction.integrate` with a traction law of
  :mod:`thermobearing.traction` (default ``eyring_limiting_shear`` with a smooth cap, film
  thickness from :func:`thermobearing.film.hamrock_dowson_1977_central`);
- ball churning drag: paper 002 eq. 10 (``heat_sources.churning.drag_force``, the
  ``churning_elements`` source with ``form="harris"``) in the oil-air mixture of volume
  fraction X (Parker's correlation of ``heat_sources.churning.parker_oil_fraction`` with a
  calibratable constant, or a fixed fraction);
- cage: churning (paper 002 eq. 15, ``churning_cage``) plus the cage-guide land torque
  (paper 002 eq. 5, ``heat_sources.cage_guide`` when present);
- inner ring churning (paper 002 eq. 17, ``churning_inner_ring``) for the shaft torque;
- ball-pocket friction coefficient mu_p (paper 002 eq. 19, ``heat_sources.pocket``).

:func:`heat_context_options` returns the matching ``HeatContext.options`` so that running the
registered heat sources on the solver's :class:`~thermobearing.state.KinematicState` gives,
to round-off, the solver's own heat (the energy test of issue 5).
"""

from __future__ import annotations

import importlib
import math
import warnings
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..errors import InputError, ValidityWarning
from .ball import BallModels

__all__ = ["BallParameters", "default_ball_models", "heat_context_options"]


@dataclass(frozen=True)
class BallParameters:
    """Parameters of the ball force models that paper 002 does not give (SI).

    Attributes
    ----------
    limiting_shear_coefficient : Lambda of the Eyring/limiting-shear traction law [-].
    eyring_stress : tau0 [Pa].
    pocket_friction : ball-pocket friction coefficient [-].
    drag_coefficient : c_d of the ball drag, paper 002 eq. 10 [-] (0.45: sphere plateau).
    parker_constant : K of Parker's oil-fraction correlation [-] (1.46e7 recalled).
    oil_fraction : fixed oil volume fraction X [-] (overrides Parker when not None).
    n_major, n_minor : quadrature nodes of the contact integration.
    source : where the values come from ("default", "calibrated: ...").
    """

    limiting_shear_coefficient: float = 0.07
    eyring_stress: float = 5.0e6
    pocket_friction: float = 0.1
    drag_coefficient: float = 0.45
    parker_constant: float = 1.46e7
    oil_fraction: float | None = None
    n_major: int = 8
    n_minor: int = 4
    source: str = "default"
    extra: dict = field(default_factory=dict)

    def with_(self, **changes: Any) -> BallParameters:
        return replace(self, **changes)


def _oil_fraction(bearing, supply, speed: float, params: BallParameters) -> float:
    from ..heat_sources.churning import oil_bath_fraction, parker_oil_fraction

    if params.oil_fraction is not None:
        return float(params.oil_fraction)
    if supply is None:
        raise InputError("supply", None, "an OilSupply (or BallParameters.oil_fraction)")
    if supply.method == "oil_bath":
        return float(oil_bath_fraction(supply.level, 0.5 * bearing.outer_raceway_diameter,
                                       0.5 * bearing.pitch_diameter))
    if supply.method == "grease":
        return 0.0
    return parker_oil_fraction(supply.flow_rate, speed, bearing.pitch_diameter,
                               params.parker_constant)


def heat_context_options(bearing, supply, speed: float, params: BallParameters) -> dict:
    """``HeatContext.options`` matching the solver's force models (see module docstring)."""
    x = _oil_fraction(bearing, supply, speed, params)
    return {
        "raceway_traction": {"n_major": params.n_major, "n_minor": params.n_minor},
        "churning_elements": {"form": "harris", "drag_coefficient": params.drag_coefficient,
                              "oil_fraction": x, "oil_swirl": 0.0},
        "churning_cage": {"oil_fraction": x},
        "churning_inner_ring": {"oil_fraction": x},
        "cage_guide": {},
        "ball_pocket": {"friction_coefficient": params.pocket_friction},
    }


def make_traction(lubricant, params: BallParameters):
    """The solver's default traction law (Eyring with limiting shear, smooth cap)."""
    from ..traction import make_traction_law

    return make_traction_law("eyring_limiting_shear", lubricant=lubricant,
                             limiting_shear_coefficient=params.limiting_shear_coefficient,
                             eyring_stress=params.eyring_stress, cap="smooth")


def default_ball_models(bearing, lubricant, *, temperature: float, speed: float, supply=None,
                        params: BallParameters | None = None,
                        oil_temperature: float | None = None) -> BallModels:
    """Build :class:`BallModels` for ``bearing`` from the heat-source physics.

    Parameters
    ----------
    bearing : BallBearing.  lubricant : Lubricant.
    temperature : contact (inlet) temperature for the traction law and the film [K].
    speed : inner-ring speed [rad/s] (Parker's oil fraction depends on it).
    supply : OilSupply (flow, method) for the oil fraction.
    params : BallParameters (default values when None).
    oil_temperature : oil temperature for churning [K] (default ``temperature``).
    """
    from ..film import hamrock_dowson_1977_central
    from ..heat_sources import churning as ch

    p = params or BallParameters()
    t_oil = float(oil_temperature if oil_temperature is not None else temperature)
    rho = float(lubricant.density(t_oil))
    eta_oil = float(lubricant.dynamic_viscosity(t_oil))
    nu = eta_oil / rho
    eta_c = float(lubricant.dynamic_viscosity(temperature))
    alpha_c = float(lubricant.pressure_viscosity_coefficient(temperature))
    E = bearing.effective_modulus
    x = _oil_fraction(bearing, supply, speed, p)
    rho_e = x * rho
    law = make_traction(lubricant, p)

    def film(u, Q, rx, ry):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            h = hamrock_dowson_1977_central(np.maximum(u, 1e-3), eta_c, alpha_c,
                                            np.maximum(Q, 1e-3), rx, ry, effective_modulus=E)
        return np.maximum(h, 1e-9)

    D = bearing.ball_diameter
    area = 0.25 * math.pi * D * D
    dm = bearing.pitch_diameter

    def ball_drag(u):
        return ch.drag_force(p.drag_coefficient, rho_e, area, u)

    cage = bearing.cage
    d_c = 0.5 * (cage.inner_diameter + cage.outer_diameter)
    d_in, d_out = bearing.inner_land_diameter, bearing.outer_land_diameter
    gap_c = max(0.25 * ((d_out - d_in) - (cage.outer_diameter - cage.inner_diameter)), 1e-4)
    guide = _cage_guide_torque(bearing, lubricant, t_oil)

    def cage_torque(wc):
        reg = ch.viscous_friction_coefficient(0.5 * d_c, wc, gap_c, nu)
        q = float(ch.cage_churning_power(rho_e, reg.mu_v, wc, cage.width, d_c))
        m = q / wc if wc != 0 else 0.0
        return m + (guide(wc) if guide is not None else 0.0)

    arc = D
    shoulder = max(0.5 * (bearing.width - D), 0.0)
    gap_i = max(0.5 * (cage.inner_diameter - d_in), 1e-4)

    def inner_torque(wi):
        reg = ch.viscous_friction_coefficient(0.5 * d_in, wi, gap_i, nu)
        q = float(ch.inner_ring_churning_power(rho_e, reg.mu_v, wi, arc, shoulder, d_in))
        return q / wi if wi != 0 else 0.0

    return BallModels(traction_law=law, pocket_friction=p.pocket_friction,
                      ball_drag=ball_drag, cage_torque=cage_torque,
                      inner_ring_torque=inner_torque, film_thickness=film,
                      temperature=float(temperature), n_major=p.n_major, n_minor=p.n_minor,
                      drag_radius=0.5 * dm,
                      parameters={"oil_fraction": x, "params": p,
                                  "cage_guide_model": guide is not None})


def _cage_guide_torque(bearing, lubricant, t_oil):
    """Cage-land drag torque callable from ``heat_sources.cage_guide`` if that module exists."""
    try:
        mod = importlib.import_module("thermobearing.heat_sources.cage_guide")
    except ImportError:
        return None
    fn = getattr(mod, "cage_guide_torque", None)
    if fn is None:
        return None

    def torque(wc):
        return float(fn(bearing, lubricant, t_oil, wc))

    return torque
