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
from .roller_residual import evaluate
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
    put in moment balance (eqs. 28/31, bisection), the loads follow from the load
    distribution with the centrifugal force at that cage speed (eqs. 20/23), and the cage
    equation (eq. 32, energy-consistent form,
    :mod:`~thermobearing.skidding.roller_residual`) is split into the part of
    the rollers with an inner contact (``drive``) and of those without (``drag``). At the
    solved cage speed ``residual`` is 0; at a published cage speed it is the force the model
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
        wr_new = _roller_speeds(mg, omega, cage_speed, ld.inner_load, fbw, psi,
                                whirl_acceleration)
        done = wr is not None and float(np.max(np.abs(wr_new - wr))) <= 1e-9 * omega
        wr = wr_new
        if done:
            break
    e = evaluate(mg, omega, wr, cage_speed, ld.inner_load, fbw, psi, whirl_acceleration)
    loaded = ld.inner_load > 0.0
    drive = float(np.sum(e.cage_terms[loaded]))
    drag = -float(np.sum(e.cage_terms[~loaded]))
    return CageForceBalance(cage_speed=float(cage_speed), drive=drive, drag=drag,
                            residual=float(e.cage_eq), n_loaded=int(np.count_nonzero(loaded)),
                            roller_speed=wr)
