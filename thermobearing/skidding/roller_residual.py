"""Residuals of the Z + 1 skidding equations of a cylindrical roller bearing (paper 000).

One job: evaluate the roller and cage equations at given roller and cage speeds
(:func:`evaluate`). Li, Chen, Zhang, Wang (2018), seed ``000_3b5ca6eed61dd596.txt``
[li2018_nu214_skidding], after Harris (1966) [harris1966_roller_skidding;
harris_kotzalas2007]. Unknowns: the spin speed ``omega_r,j`` of every roller and the cage
speed ``omega_c``. Equations (paper eqs. 12-15, 20-32):

* kinematics (eqs. 12-15), in the cage frame, along each contact's race velocity:
  inner  u_race = (d_m - D)/2 (omega - omega_c),  outer  u_race = (d_m + D)/2 omega_c,
  roller surface speed u_roller = D/2 omega_r (both contacts), sliding V = u_race - u_roller;
* roller moment about its axis (eqs. 22/25, 28/31):  S_i + S_o - f_d = 0, where S is the
  shear force (Couette + Poiseuille, eq. 5/33-34) of a contact on the roller surface and
  f_d the pocket-film friction (eq. 38; one or both pocket faces, ``pocket_film``);
* roller force along the orbit (eqs. 21/24): the pocket normal force
  F_d = (S_i + (1 - D/d_m) Q_xi) - (S_o + (1 + D/d_m) Q_xo) - m_r a_t,j  (Q_x the rolling
  resultant of the film pressure, eq. 35, of which the roller takes the share R_x/(D/2);
  a_t the tangential whirl acceleration, eqs. 3-4), + F_oil with the oil drag of the model
  (``model.drag``, :mod:`thermobearing.skidding.roller_drag`: paper 002 eq. 10 on the roller
  centre against the orbit; none in paper 000);
* cage (eq. 32): sum_j F_d,j = (D/d_m) sum_j f_d,j + (T_c - M_oil) / (d_m/2). Paper 000
  writes sum F_d = 0; the radial pocket friction f_d acts D/2 beside the roller centre and
  retards the cage on either pocket face, and without it the energy balance (shaft power =
  the dissipation, :attr:`RollerSkiddingResult.power_loss`) does not close.
  ``cage_drag_torque`` T_c [N m] is an optional constant drag (default 0, as the paper);
  M_oil the oil moments on the cage with the model's drag (churning, paper 002 eq. 15, and
  a guide land, eq. 5).

Radial equilibrium (eqs. 20/23) with the centrifugal force and the whirl inertia gives the
contact loads (:mod:`thermobearing.skidding.roller_loads`); the outer loads follow the cage
speed here. The unloaded-zone model (``unloaded_zone``) is described in
:mod:`thermobearing.skidding.roller_model`.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from .roller_fluid import (
    LineContactForces,
    clearance_film_forces,
    pocket_forces,
    pocket_forces_two_faces,
)
from .roller_model import RollerModel


@dataclass(frozen=True)
class _Eval:
    roller_eq: np.ndarray  # (Z,) moment balances / (D/2) [N]
    pocket: np.ndarray  # (Z,) F_d [N]
    cage_eq: float  # sum F_d - T_c/(d_m/2) [N]
    inner: LineContactForces
    outer: LineContactForces
    friction: np.ndarray
    v_i: np.ndarray
    v_o: np.ndarray
    ue_i: np.ndarray
    ue_o: np.ndarray
    q_o: np.ndarray
    cage_terms: np.ndarray  # (Z,) per-roller parts of the cage equation [N]


def evaluate(model: RollerModel, omega: float, omega_r: np.ndarray, omega_c: float,
             inner_load: np.ndarray, body_force_const: np.ndarray, azimuth: np.ndarray,
             whirl_acceleration: tuple[float, float],
             slides: tuple[np.ndarray, np.ndarray] | None = None) -> _Eval:
    """Residuals of the Z + 1 equations (module docstring) at (omega_r, omega_c).

    ``body_force_const`` is the outward body force without the centrifugal term (whirl
    inertia) [N]; the centrifugal force m (d_m/2) omega_c^2 is added here so that the outer
    loads follow omega_c exactly.

    ``slides``: the sliding speeds (V_i, V_o) (Z,) [m/s] of the inner and outer contacts
    given exactly, consistent with (omega_r, omega_c) to the round-off of the speeds; the
    contact forces then take them instead of the differences u_race - u_roller, which are
    multiples of one ulp of the surface speeds (the slide-variable solve,
    :mod:`~thermobearing.skidding.roller_slides`; only for a drag model that accepts them,
    :func:`exact_slides_supported`). None: the differences.
    """
    d_m, d = model.pitch_diameter, model.roller_diameter
    half_d = 0.5 * d
    pocket_law = pocket_forces_two_faces if model.pocket_film == "two_faces" else pocket_forces
    q_o = inner_load + body_force_const + model.roller_mass * 0.5 * d_m * omega_c**2
    q_o = np.maximum(q_o, 0.0)
    u_ri = 0.5 * (d_m - d) * (omega - omega_c) * np.ones_like(omega_r)
    u_ro = 0.5 * (d_m + d) * omega_c * np.ones_like(omega_r)
    free = None
    if model.unloaded_zone == "outer_pure_rolling" and not model.clearance_film:
        # paper 000 sec. 1: outside the load zone the roller rolls purely on the outer race
        free = inner_load <= 0.0
        spin_in = omega_r
        omega_r = np.where(free, (d_m + d) / d * omega_c, omega_r)
    u_roll = half_d * omega_r
    common = dict(eta0=model.eta0, alpha=model.alpha, traction_law=model.traction_law,
                  temperature=model.temperature, rolling_force=model.rolling_force,
                  oil_layer=model.oil_layer)
    if model.inlet_heating is not None:
        # inlet shear heating of the rolling force (option thermal_reduction)
        common["inlet_heating"] = model.inlet_heating
    v_i, v_o = u_ri - u_roll, u_ro - u_roll
    exact_i: dict[str, np.ndarray] = {}
    exact_o: dict[str, np.ndarray] = {}
    if slides is not None:
        v_i = np.asarray(slides[0], dtype=float) * np.ones_like(omega_r)
        v_o = np.asarray(slides[1], dtype=float) * np.ones_like(omega_r)
        if free is not None:
            # rolling on the outer race: V_o = 0 and V_i = V_i - V_o (= -d_m (omega_c -
            # omega_c,th), exact in the given slides)
            v_i, v_o = np.where(free, v_i - v_o, v_i), np.where(free, 0.0, v_o)
        exact_i, exact_o = {"slide": v_i}, {"slide": v_o}
    fi = model.contact_forces(inner_load, model.length, model.radius_inner,
                              model.effective_modulus, u_ri, u_roll, film=model.film_inner,
                              **common, **exact_i)
    if model.clearance_film and model.inner_gap is not None:
        cf, w_h = clearance_film_forces(
            np.where(inner_load > 0.0, np.inf, model.inner_gap), model.length,
            model.radius_inner, u_ri, u_roll, model.eta0, model.clearance_film_floor,
            **exact_i)
        fi = fi.combined(cf)
        q_o = q_o + w_h
    fo = model.contact_forces(q_o, model.length, model.radius_outer, model.effective_modulus,
                              u_ro, u_roll, film=model.film_outer, **common, **exact_o)
    ax, ay = whirl_acceleration
    a_t = -ax * np.sin(azimuth) + ay * np.cos(azimuth)
    # oil drag on each roller centre along its orbit (paper 002 eq. 10), None without drag
    f_drag = None if model.drag is None else model.drag.element_force(omega_c)
    share_i, share_o = model.radius_inner / half_d, model.radius_outer / half_d
    if free is not None and np.any(free):
        # eqs. 30-31 with a rigid rolling constraint at the outer race: the outer shear on
        # the roller S_o equals the pocket friction f_d (eq. 31), the pocket force follows
        # from eq. 30, F_d = -(S_o + share_o Q_xo) - m a_t, and f_d depends on F_d
        # (eqs. 37-38): a contraction (df_d/dF_d ~ 0.1), solved by fixed point
        base = (-share_o * fo.rolling_force * fo.entrainment_sign
                - model.roller_mass * a_t)
        if f_drag is not None:
            base = base + f_drag
        s_o = np.zeros_like(base)
        for _ in range(8):
            s_o = pocket_law(base - s_o, omega_r, d, model.length, model.eta0,
                                model.pocket_clearance).friction
        fo = dataclasses.replace(fo, traction=np.where(
            free, s_o + fo.poiseuille * fo.entrainment_sign, fo.traction))
    pocket = fi.orbital_force(share_i) - fo.orbital_force(share_o) - model.roller_mass * a_t
    if f_drag is not None:
        pocket = pocket + f_drag
    fric = pocket_law(pocket, omega_r, d, model.length, model.eta0,
                         model.pocket_clearance).friction
    roller_eq = fi.shear_force + fo.shear_force - fric * np.sign(omega_r + 1e-300)
    if free is not None:
        # the constraint replaces the moment balance of a free roller (N per rad/s scale)
        roller_eq = np.where(free, (omega_r - spin_in) * model.roller_mass * omega * half_d,
                             roller_eq)
    # cage: pocket normal forces at d_m/2; the (radial) pocket friction acts at D/2 beside
    # the roller centre and retards the cage on either pocket face
    cage_terms = pocket - (d / d_m) * fric
    cage_moment = -model.cage_drag_torque
    if model.drag is not None:
        cage_moment += model.drag.cage_moment(omega, omega_c)
    cage_eq = float(np.sum(cage_terms)) + cage_moment / (0.5 * d_m)
    return _Eval(roller_eq, pocket, cage_eq, fi, fo, fric, v_i, v_o,
                 0.5 * (u_ri + u_roll), 0.5 * (u_ro + u_roll), q_o, cage_terms)


def exact_slides_supported(model: RollerModel) -> bool:
    """Whether :func:`evaluate` can pass exact slides to the model's contact forces: the
    closed-form drag model, with or without a traction curve, the Maxwell film
    (``fluid_shear_modulus``) or the ``film_pressure`` option (their Hertz-zone integral,
    :mod:`~thermobearing.skidding.roller_maxwell`, takes the exact slide too)."""
    return bool(getattr(model.contact_forces, "exact_slide", False))
