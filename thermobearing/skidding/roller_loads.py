"""Roller load distribution at a given cage speed, for the skidding residual (paper 000).

One job: the radial equilibrium of paper 000 (eqs. 20/23, Li, Chen, Zhang, Wang 2018, seed
``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding]) with the centrifugal force and the
whirl inertia at the current cage speed, for either ring support of
:func:`thermobearing.skidding.roller_model.build_model`: a dry load zone
(:func:`thermobearing.loads_roller.roller_load_distribution`, Harris) or the film-supported
ring (:func:`thermobearing.loads_roller.roller_film_load_distribution`), plus the inner gaps
a load distribution leaves for the clearance film.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from ..loads_roller import (
    LINE_CONTACT_EXPONENT,
    roller_body_force,
    roller_film_load_distribution,
    roller_load_distribution,
)
from .roller_fluid import starved_film
from .roller_model import RollerModel


def _gapped(model: RollerModel, ld: Any) -> RollerModel:
    """The model with the inner gaps -delta_j of a load distribution (clearance film)."""
    if not model.clearance_film:
        return model
    return dataclasses.replace(model, inner_gap=-np.asarray(ld.interference, dtype=float))


def _load_distribution(model: RollerModel, omega: float, radial_load: float, wc: float,
                       wr: np.ndarray | None, psi: np.ndarray, acc: tuple[float, float],
                       ring: Any = None, q0: np.ndarray | None = None,
                       radial_acceleration: np.ndarray | None = None
                       ) -> tuple[Any, np.ndarray]:
    """Load distribution at cage speed ``wc`` (and roller spins ``wr`` for film support) and
    the body force without the centrifugal term (see :func:`evaluate`).

    ``radial_acceleration`` (Z,) [m/s^2], when given, replaces the projection of the
    bearing-centre acceleration ``acc`` on each roller's radial direction in the body force
    (the whirl reading of :class:`thermobearing.skidding.whirl.Whirl`).
    """
    z = model.n_rollers
    if radial_acceleration is None:
        fb_total = roller_body_force(model.roller_mass, model.pitch_diameter, wc, psi, acc)
    else:
        fb_total = model.roller_mass * (0.5 * model.pitch_diameter * wc**2
                                        - np.asarray(radial_acceleration, dtype=float))
    if model.ring_support == "films":
        d_m, d = model.pitch_diameter, model.roller_diameter
        spin = np.full(z, (d_m + d) / d * wc) if wr is None else np.asarray(wr, dtype=float)
        u_roll = 0.5 * d * spin
        # entrainment speeds as closed_form_contact_forces forms them (same film, same h)
        ue_i = np.maximum(0.5 * np.abs(0.5 * (d_m - d) * (omega - wc) + u_roll), 1e-6)
        ue_o = np.maximum(0.5 * np.abs(0.5 * (d_m + d) * wc + u_roll), 1e-6)
        length = model.length
        # the film the contact forces use (flooded, or starved by the inlet oil layer)
        film_i = starved_film(model.film_inner, model.radius_inner, model.eta0, model.oil_layer)
        film_o = starved_film(model.film_outer, model.radius_outer, model.eta0, model.oil_layer)
        ld = roller_film_load_distribution(
            z, model.diametral_clearance, radial_load,
            lambda q: film_i(ue_i, q / length),
            lambda q: film_o(ue_o, q / length), model.k_inner, model.k_outer,
            body_force=fb_total, azimuth=psi, exponent=LINE_CONTACT_EXPONENT, x0=ring, q0=q0)
    else:
        ld = roller_load_distribution(z, model.diametral_clearance, radial_load, model.k_inner,
                                      model.k_outer, body_force=fb_total, azimuth=psi,
                                      exponent=LINE_CONTACT_EXPONENT, x0=ring)
    return ld, fb_total - model.roller_mass * 0.5 * model.pitch_diameter * wc**2
