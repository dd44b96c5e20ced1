"""Sunnersjo's varying-compliance model (2-DOF ring on massless balls), the reference model
paper 004 (Luo et al. 2022, seed ``../shared/seeds/004_0105d7aba121b014.txt``, section 4.1 and
Table 2) validates its cage-slip model against. Split out of :mod:`thermobearing.vibration`
(which re-exports :func:`simulate_sunnersjo`); same parameters (:class:`VibrationParameters`).

Sunnersjo C.S. (1978) Varying compliance vibrations of rolling bearings. J. Sound Vib. 58:
363-373 (ref. [4] of paper 004).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numba
import numpy as np

from .errors import InputError, check_positive

if TYPE_CHECKING:
    from .vibration import VibrationParameters

__all__ = ["simulate_sunnersjo"]


@numba.njit(cache=True)
def _sunnersjo_rhs(t, y, k, gap, m, c, load, wc, z, dy):
    fx = load - c * y[2]
    fy = -c * y[3]
    for j in range(z):
        th = 2.0 * math.pi * j / z + wc * t
        d = y[0] * math.cos(th) + y[1] * math.sin(th) - gap
        if d > 0.0:
            q = k * d * math.sqrt(d)
            fx -= q * math.cos(th)
            fy -= q * math.sin(th)
    dy[0] = y[2]
    dy[1] = y[3]
    dy[2] = fx / m
    dy[3] = fy / m


@numba.njit(cache=True)
def _sunnersjo_run(y, h, sub, n_settle, n_rec, k, gap, m, c, load, wc, z, ax):
    k1 = np.empty(4)
    k2 = np.empty(4)
    k3 = np.empty(4)
    k4 = np.empty(4)
    tmp = np.empty(4)
    t = 0.0
    for i in range(n_settle + n_rec):
        if i >= n_settle:
            _sunnersjo_rhs(t, y, k, gap, m, c, load, wc, z, k1)
            ax[i - n_settle] = k1[2]
        for _ in range(sub):
            _sunnersjo_rhs(t, y, k, gap, m, c, load, wc, z, k1)
            for q in range(4):
                tmp[q] = y[q] + 0.5 * h * k1[q]
            _sunnersjo_rhs(t + 0.5 * h, tmp, k, gap, m, c, load, wc, z, k2)
            for q in range(4):
                tmp[q] = y[q] + 0.5 * h * k2[q]
            _sunnersjo_rhs(t + 0.5 * h, tmp, k, gap, m, c, load, wc, z, k3)
            for q in range(4):
                tmp[q] = y[q] + h * k3[q]
            _sunnersjo_rhs(t + h, tmp, k, gap, m, c, load, wc, z, k4)
            for q in range(4):
                y[q] += h / 6.0 * (k1[q] + 2.0 * k2[q] + 2.0 * k3[q] + k4[q])
            t += h


def simulate_sunnersjo(params: VibrationParameters, shaft_speed: float, radial_load: float,
                       *, duration: float = 0.5, settle_time: float = 0.05,
                       sampling_rate: float = 100_000.0, max_step: float = 1e-5) -> np.ndarray:
    """Inner-ring x acceleration [m/s^2] of Sunnersjo's varying-compliance model.

    Sunnersjo 1978 (ref. [4] of paper 004, the model paper 004 validates against in its
    Table 2): the ring (mass m_i, damping c) on massless balls at pure-rolling cage speed,
    Q_j = K (x cos theta_j + y sin theta_j - P_d)^1.5 with the series constant
    K = (K_i^-2/3 + K_o^-2/3)^-3/2 and the same total radial play P_d as the full model
    (eqs. 13-14 of paper 004 put P_d/2 at each contact). RK4 at ``max_step`` [s]: without
    ball masses the stiffest mode is the ring's, far inside RK4's stability bound.
    """
    check_positive("shaft_speed", shaft_speed)
    check_positive("radial_load", radial_load)
    # as vibration.simulate (a negative settle time ran silently, a zero duration returned
    # an empty record, a zero rate or step raised ZeroDivisionError)
    check_positive("duration", duration)
    check_positive("settle_time", settle_time, allow_zero=True)
    check_positive("sampling_rate", sampling_rate)
    check_positive("max_step", max_step)
    if int(round(duration * sampling_rate)) < 4:
        raise InputError("duration", duration, f"at least 4 samples at {sampling_rate:g} Hz")
    k = (params.inner_stiffness ** (-2 / 3) + params.outer_stiffness ** (-2 / 3)) ** -1.5
    dt_out = 1.0 / sampling_rate
    sub = max(1, math.ceil(dt_out / max_step * (1 - 1e-12)))
    n_settle = int(round(settle_time * sampling_rate))
    n_rec = int(round(duration * sampling_rate))
    ax = np.empty(n_rec)
    _sunnersjo_run(np.zeros(4), dt_out / sub, sub, n_settle, n_rec, k, params.radial_clearance,
                   params.inner_ring_mass, params.support_damping, radial_load,
                   params.theoretical_cage_speed_ratio * shaft_speed, params.n_balls, ax)
    return ax
