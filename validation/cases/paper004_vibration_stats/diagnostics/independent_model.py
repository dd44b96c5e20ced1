"""Diagnostics for paper004_vibration_stats (SOURCE.md, "Equation-by-equation check").

An independent, frictionless re-implementation of paper 004's lumped model (Luo et al. 2022,
seed ``../shared/seeds/004_0105d7aba121b014.txt``, eqs. 11-16 and 19-21; SI units), with the
parameters of ``thermobearing.vibration.paper004_parameters()``, RK4 at 5e-6 s, 0.05 s settling,
0.5 s record at 100 kHz. Friction is left out on purpose: at s_c = 0 it vanishes in the paper's
model, and part 2 replaces it by its mean y force. Run: ``python independent_model.py``.

Part 1, eq. 15 read literally: lambda_j = 1 only if BOTH delta_in and delta_out are > 0
(``joint``) against each contact switched on its own (``per_contact``, the library's form),
from the paper's start (ring and balls at rest at zero) and from balls resting on the outer
race (d_br = P_d/2 (1 + 1e-3)).

Part 2, load-line offset: the frictionless model at s_c = 5 % and 10 % with a constant extra
force F_y [N] on the ring. With friction, the full model's ring sits at a mean y offset (the
friction's mean y resultant); if the frictionless run with the same offset gives the same
statistics, friction changes them through that static offset (the load zone turns, which moves
the ball entry and exit events against each other), not through impulsive friction forces.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from thermobearing import vibration as V

P = V.paper004_parameters()
Z = P.n_balls
W = 2000.0                      # N, Table 2 case
WS = 2000.0 * math.pi / 30.0    # rad/s, 2000 r/min
H, SUB, N_SETTLE, N_REC = 5e-6, 2, 5000, 50000
PAR = np.array([P.inner_stiffness, P.outer_stiffness, P.radial_clearance, P.inner_ring_mass,
                P.ball_mass, P.support_damping, P.ball_damping, W])


@numba.njit(cache=True)
def _rhs(t, y, par, wc, fy_extra, joint, dy):
    ki, ko, pd, mi, mr, c, cb, w = par
    z = (y.size - 4) // 2
    fx = w - c * y[2]
    fy = fy_extra - c * y[3]
    for j in range(z):
        th = 2.0 * math.pi * j / z + wc * t                              # eq. 12
        cs = math.cos(th)
        sn = math.sin(th)
        d_in = y[0] * cs + y[1] * sn - y[4 + j] - 0.5 * pd               # eqs. 11, 13
        d_out = y[4 + j] - 0.5 * pd                                      # eq. 14
        if joint:                                                        # eq. 15 literally
            on = d_in > 0.0 and d_out > 0.0
            qi = ki * d_in ** 1.5 if on else 0.0
            qo = ko * d_out ** 1.5 if on else 0.0
        else:                                                            # each contact
            qi = ki * d_in ** 1.5 if d_in > 0.0 else 0.0
            qo = ko * d_out ** 1.5 if d_out > 0.0 else 0.0
        fx -= qi * cs                                                    # eqs. 17, 19
        fy -= qi * sn                                                    # eq. 20
        dy[4 + j] = y[4 + z + j]
        dy[4 + z + j] = (qi - qo - cb * y[4 + z + j]) / mr               # eq. 21
    dy[0] = y[2]
    dy[1] = y[3]
    dy[2] = fx / mi
    dy[3] = fy / mi


@numba.njit(cache=True)
def _run(y, par, wc, fy_extra, joint, ax, ys):
    k1 = np.empty_like(y)
    k2 = np.empty_like(y)
    k3 = np.empty_like(y)
    k4 = np.empty_like(y)
    t = 0.0
    for i in range(ax.size):
        _rhs(t, y, par, wc, fy_extra, joint, k1)
        ax[i] = k1[2]
        ys[i] = y[1]
        for _ in range(SUB):
            _rhs(t, y, par, wc, fy_extra, joint, k1)
            _rhs(t + 0.5 * H, y + 0.5 * H * k1, par, wc, fy_extra, joint, k2)
            _rhs(t + 0.5 * H, y + 0.5 * H * k2, par, wc, fy_extra, joint, k3)
            _rhs(t + H, y + H * k3, par, wc, fy_extra, joint, k4)
            y += H / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
            t += H


def run(slip: float = 0.0, fy_extra: float = 0.0, joint: bool = False,
        ball_start: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(recorded x acceleration [m/s^2], recorded y [m], final state)."""
    y = np.zeros(4 + 2 * Z)
    y[4:4 + Z] = ball_start
    ax = np.empty(N_SETTLE + N_REC)
    ys = np.empty_like(ax)
    wc = (1.0 - slip) * P.theoretical_cage_speed_ratio * WS
    _run(y, PAR, wc, fy_extra, joint, ax, ys)
    return ax[N_SETTLE:], ys[N_SETTLE:], y


def _stats(a: np.ndarray) -> str:
    if not np.all(np.isfinite(a)) or np.ptp(a) == 0.0:
        return "no finite varying record"
    st = V.statistics(a)
    return f"PTP {st.ptp:.2f} m/s^2, RMS {st.rms:.3f} m/s^2, kurtosis {st.kurtosis:.2f}"


def main() -> None:
    print("Part 1: eq. 15 (contact switch), s_c = 0")
    for joint in (False, True):
        for start in (0.0, 0.5 * P.radial_clearance * (1 + 1e-3)):
            a, _, y = run(joint=joint, ball_start=start)
            print(f"  {'joint' if joint else 'per_contact':11s} d_br(0) = {start * 1e6:4.2f} um:"
                  f" ring x at 0.275 s = {y[0] * 1e6:.4g} um; {_stats(a)}")
    print("Part 2: frictionless, extra constant F_y on the ring")
    for slip in (0.05, 0.10):
        for fy in (0.0, -10.0, -20.0, -30.0, -100.0, 10.0, 20.0, 30.0, 100.0):
            a, ys, _ = run(slip=slip, fy_extra=fy)
            print(f"  s_c = {slip:.2f}, F_y = {fy:6.1f} N: mean y = {ys.mean() * 1e6:6.3f} um;"
                  f" {_stats(a)}")


if __name__ == "__main__":
    main()
