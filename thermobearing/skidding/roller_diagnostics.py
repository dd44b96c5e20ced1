"""Diagnostic of the roller skidding model: the cage force balance at a given cage speed.

One job: the cage equation of paper 000 (eq. 32; Li, Chen, Zhang, Wang 2018, seed
``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding]) at a prescribed (e.g. published) cage
speed with every roller in moment balance: :func:`cage_force_balance` splits it into the
drive of the rollers with an inner contact and the drag of the others,
:func:`cage_force_terms` into the fluid forces of each roller (Couette, Poiseuille and
pressure shares of both contacts, pocket friction, inertia).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import check_positive
from .roller_loads import _gapped, _load_distribution
from .roller_model import RollerModel
from .roller_residual import _Eval, evaluate, exact_slides_supported
from .roller_slides import _roller_slides, evaluate_slides
from .roller_solvers import _roller_speeds


@dataclass(frozen=True)
class CageForceBalance:
    """Pocket forces at a prescribed cage speed (see :func:`cage_force_balance`) [N].

    Attributes
    ----------
    cage_speed : the prescribed omega_c [rad/s].
    drive : sum of the cage-equation terms of the rollers with an inner contact [N].
    drag : minus the sum over the rollers without one [N] (positive: they hold the cage back).
    residual : the cage equation, drive - drag + (M_oil - T_c)/(d_m/2) [N] (> 0: the cage
        would speed up; M_oil the oil moments on the cage of a model with ``drag``,
        whose roller drag is inside each roller's term).
    n_loaded : rollers with an inner contact.  roller_speed : (Z,) [rad/s].
    """

    cage_speed: float
    drive: float
    drag: float
    residual: float
    n_loaded: int
    roller_speed: np.ndarray


def cage_force_balance(model: RollerModel, omega: float, radial_load: float, cage_speed: float,
                       *, azimuth: np.ndarray | None = None,
                       whirl_acceleration: tuple[float, float] = (0.0, 0.0)
                       ) -> CageForceBalance:
    """Drive of the loaded rollers and drag of the others at a prescribed cage speed.

    Diagnostic of the Z + 1 equations of paper 000: at ``cage_speed`` [rad/s] every roller is
    put in moment balance (eqs. 28/31; in the sliding speeds where the contact forces take
    them, :func:`_balanced_rollers`), the loads follow from the load
    distribution with the centrifugal force at that cage speed (eqs. 20/23), and the cage
    equation (eq. 32, energy-consistent form,
    :mod:`~thermobearing.skidding.roller_residual`) is split into the part of
    the rollers with an inner contact (``drive``) and of those without (``drag``). At the
    solved cage speed ``residual`` is 0 to what one ulp of the cage speed changes it by
    (under heavy load in cold oil the root's offset from the epicyclic speed can be below
    that ulp and the cage equation step by hundreds of N between adjacent floats: the
    catalogue NU 206 at 13 kN, 30000 r/min, ISO VG 68 at 20 degC, +261 N and -50 N at the
    two floats around its root); at a published cage speed it is the force the model
    lacks (< 0) or has in excess (> 0) to run there. omega [rad/s], radial_load [N].
    """
    ld, wr, e = _balanced_state(model, omega, radial_load, cage_speed, azimuth,
                                whirl_acceleration)
    loaded = ld.inner_load > 0.0
    drive = float(np.sum(e.cage_terms[loaded]))
    drag = -float(np.sum(e.cage_terms[~loaded]))
    return CageForceBalance(cage_speed=float(cage_speed), drive=drive, drag=drag,
                            residual=float(e.cage_eq), n_loaded=int(np.count_nonzero(loaded)),
                            roller_speed=wr)


@dataclass(frozen=True)
class CageForceTerms:
    """Fluid and body forces on each roller in the cage equation (see
    :func:`cage_force_terms`); every field (Z,) [N], along the roller's orbit (+: forward)
    unless said otherwise.

    Attributes
    ----------
    inner_shear, outer_shear : total shear of the film on the roller surface (Couette minus
        Poiseuille, along the race's axis of each contact as the residual books it) [N].
    inner_couette, outer_couette : their Couette parts (eqs. 5/33-34, second term) [N].
    inner_poiseuille, outer_poiseuille : their Poiseuille parts, >= 0 against the
        entrainment (eqs. 5/33-34, first term) [N].
    inner_pressure, outer_pressure : the roller's share (1 -+ D/d_m) of the rolling force
        Q_x, along the entrainment of its contact (eqs. 27/35), >= 0 [N].
    pocket_friction : pocket-film friction f_d (eqs. 37-38), >= 0 [N].
    body : whirl inertia and oil drag on the roller centre along its orbit [N].
    cage_terms : each roller's term of the cage equation (eq. 32, energy-consistent form) [N].
    moment_imbalance : inner_shear + outer_shear - f_d sign(omega_r), each roller's moment
        balance (eqs. 28/31) from these forces [N]: 0 to round-off in balance.
    reduced : the cage term with the outer shear eliminated by the moment balance,
        ``2 inner_shear + inner_pressure - outer_pressure - (1 + D/d_m) f_d + body`` [N]
        (equals ``cage_terms + moment_imbalance`` exactly): in balance the cage runs where
        twice the inner shear of the rollers pays for the outer rolling force, the pocket
        friction and the inner pressure share's deficit.
    inner_load, outer_load : Q_i, Q_o [N].
    """

    inner_shear: np.ndarray
    outer_shear: np.ndarray
    inner_couette: np.ndarray
    outer_couette: np.ndarray
    inner_poiseuille: np.ndarray
    outer_poiseuille: np.ndarray
    inner_pressure: np.ndarray
    outer_pressure: np.ndarray
    pocket_friction: np.ndarray
    body: np.ndarray
    cage_terms: np.ndarray
    moment_imbalance: np.ndarray
    reduced: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray


def cage_force_terms(model: RollerModel, omega: float, radial_load: float, cage_speed: float,
                     *, azimuth: np.ndarray | None = None,
                     whirl_acceleration: tuple[float, float] = (0.0, 0.0)) -> CageForceTerms:
    """Each roller's forces in the cage equation at a prescribed cage speed, rollers in
    moment balance (the state of :func:`cage_force_balance`).

    With the moment balance (eqs. 28/31) S_i + S_o = f_d sign(omega_r) the pocket force of
    eqs. 27/30, F_d = S_i + s_i Q_xi - S_o - s_o Q_xo + body, becomes
    ``2 S_i + s_i Q_xi - s_o Q_xo - f_d + body`` (S the shear on the roller, s_i, s_o = 1 -+
    D/d_m the roller's pressure shares, eq. 35's factor), and the cage term (eq. 32 in the
    energy-consistent form) adds ``-(D/d_m) f_d``: the outer Couette and Poiseuille shears
    drop out, and with the Poiseuille shear Q_x/2 on each surface (closed-form drag) the
    inner rolling force enters only as ``-(2 D/d_m) P_i``. omega, cage_speed [rad/s],
    radial_load [N]; forces [N].
    """
    z = model.n_rollers
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None else np.asarray(azimuth, float)
    ld, wr, e = _balanced_state(model, omega, radial_load, cage_speed, psi, whirl_acceleration)
    fi, fo = e.inner, e.outer
    half_d = 0.5 * model.roller_diameter
    share_i, share_o = model.radius_inner / half_d, model.radius_outer / half_d
    s_i, s_o = fi.shear_force, fo.shear_force
    p_i = share_i * fi.rolling_force * fi.entrainment_sign
    p_o = share_o * fo.rolling_force * fo.entrainment_sign
    fric = np.asarray(e.friction, dtype=float)
    f_signed = fric * np.sign(wr + 1e-300)
    ax, ay = whirl_acceleration
    body = -model.roller_mass * (-ax * np.sin(psi) + ay * np.cos(psi))
    if model.drag is not None:
        body = body + model.drag.element_force(cage_speed)
    ratio = model.roller_diameter / model.pitch_diameter
    return CageForceTerms(
        inner_shear=s_i, outer_shear=s_o, inner_couette=fi.traction, outer_couette=fo.traction,
        inner_poiseuille=fi.poiseuille, outer_poiseuille=fo.poiseuille, inner_pressure=p_i,
        outer_pressure=p_o, pocket_friction=fric, body=body, cage_terms=e.cage_terms,
        moment_imbalance=s_i + s_o - f_signed,
        reduced=2.0 * s_i + p_i - p_o - f_signed - ratio * fric + body,
        inner_load=np.asarray(ld.inner_load, dtype=float), outer_load=np.asarray(e.q_o, float))


def _balanced_state(model: RollerModel, omega: float, radial_load: float, cage_speed: float,
                    azimuth: np.ndarray | None, acc: tuple[float, float]
                    ) -> tuple[Any, np.ndarray, _Eval]:
    """Load distribution, roller spins (Z,) [rad/s] in moment balance and the equations at
    a prescribed cage speed (film support: loads and spins by fixed point)."""
    check_positive("speed", omega)
    check_positive("cage_speed", cage_speed)
    z = model.n_rollers
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None else np.asarray(azimuth, float)
    wr = None
    for _ in range(60 if model.ring_support == "films" else 1):
        # film support: loads and spins by fixed point (contraction ~0.2 per step)
        ld, fbw = _load_distribution(model, omega, radial_load, cage_speed, wr, psi, acc)
        mg = _gapped(model, ld)
        wr_new, e = _balanced_rollers(mg, omega, cage_speed, ld.inner_load, fbw, psi, acc)
        done = wr is not None and float(np.max(np.abs(wr_new - wr))) <= 1e-9 * omega
        wr = wr_new
        if done:
            break
    return ld, wr, e


def _balanced_rollers(model: RollerModel, omega: float, cage_speed: float,
                      inner_load: np.ndarray, fb: np.ndarray, psi: np.ndarray,
                      acc: tuple[float, float]) -> tuple[np.ndarray, _Eval]:
    """Roller spins (Z,) [rad/s] in moment balance at ``cage_speed`` and the equations there.

    In the sliding speeds (:func:`~thermobearing.skidding.roller_slides._roller_slides`,
    the cage offset from the epicyclic speed taken from ``cage_speed``) when the model's
    contact forces take exact slides: under heavy load in cold oil a loaded roller's film
    carries hundreds of N within one ulp of the surface speeds, and spins bisected to
    adjacent floats leave tractions that balance nothing (measured, catalogue NU 206,
    13 kN, 30000 r/min, ISO VG 68 at 20 degC: at the solved cage speed the cage equation
    was 409 N with a drive of 522 N, against ~1e-14 N in the slides). Else the spins by
    bisection (:func:`~thermobearing.skidding.roller_solvers._roller_speeds`)."""
    if exact_slides_supported(model):
        d_m, d = model.pitch_diameter, model.roller_diameter
        # the offset as slide_speeds defines it, so that its cage speed is ``cage_speed``
        delta = cage_speed - 0.5 * (d_m - d) * omega / d_m
        v_i, v_o = _roller_slides(model, omega, delta, inner_load, fb, psi, acc)
        e, x = evaluate_slides(model, omega, v_i, delta, inner_load, fb, psi, acc, v_o)
        return x[:-1], e
    wr = _roller_speeds(model, omega, cage_speed, inner_load, fb, psi, acc)
    return wr, evaluate(model, omega, wr, cage_speed, inner_load, fb, psi, acc)
