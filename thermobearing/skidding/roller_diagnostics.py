"""Diagnostic of the roller skidding model: the cage force balance at a given cage speed.

One job: :func:`cage_force_balance` splits the cage equation of paper 000 (eq. 32; Li, Chen,
Zhang, Wang 2018, seed ``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding]) into the drive
of the rollers with an inner contact and the drag of the others, at a prescribed (e.g.
published) cage speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

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
    check_positive("speed", omega)
    check_positive("cage_speed", cage_speed)
    z = model.n_rollers
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None else np.asarray(azimuth, float)
    wr = None
    for _ in range(60 if model.ring_support == "films" else 1):
        # film support: loads and spins by fixed point (contraction ~0.2 per step)
        ld, fbw = _load_distribution(model, omega, radial_load, cage_speed, wr, psi,
                                     whirl_acceleration)
        mg = _gapped(model, ld)
        wr_new, e = _balanced_rollers(mg, omega, cage_speed, ld.inner_load, fbw, psi,
                                      whirl_acceleration)
        done = wr is not None and float(np.max(np.abs(wr_new - wr))) <= 1e-9 * omega
        wr = wr_new
        if done:
            break
    loaded = ld.inner_load > 0.0
    drive = float(np.sum(e.cage_terms[loaded]))
    drag = -float(np.sum(e.cage_terms[~loaded]))
    return CageForceBalance(cage_speed=float(cage_speed), drive=drive, drag=drag,
                            residual=float(e.cage_eq), n_loaded=int(np.count_nonzero(loaded)),
                            roller_speed=wr)


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
