"""Running-mean convergence of the coupled roller dynamics' rib heat (where to stop).

The coupled all-roller + cage integration of paper 003 eqs. 18-19 (Zhang et al. 2021, seed
``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear];
:func:`~thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`) used to run a
fixed 2 warm-up + 3 statistics cage orbits per operating state. Without an unbalance (every
scene's default) the motion settles to a steady state within about one orbit (measured,
CRB 50x75x16: the roller-mean rib heat of quarter-orbit blocks is constant to 1e-4 from
0.75 orbit on at 2544 r/min / 18.9 kN and from 1.5 orbits on at 20000 r/min / 3 kN), so
most of that window repeated the same number. With ``converge`` = a relative tolerance
the integration is cut into blocks of 1/:data:`BLOCKS_PER_ORBIT` orbit; after each block
(from :data:`MIN_BLOCKS` blocks on) the later half of the blocks so far is the candidate
statistics window (the earlier half the warm-up: the "half discard" rule of steady-state
simulation output analysis), and the run stops when, for the roller-mean rib heat and the
roller-mean rib slide speed alike, (:func:`window_converged`)

* the means of the window's two halves differ by at most ``tol`` x the window mean (no
  drift left from the start transient), and
* twice the standard error of the window mean from its block means, 2 s / sqrt(n), is at
  most ``tol`` x the window mean.

If that never happens within the fixed window's length (warm-up + statistics orbits), the
result is that of the fixed window exactly (same trajectory, same samples). The chaotic
impacting motion with an unbalance (block-to-block scatter ~5 % of the heat at paper 003's
base case) meets a 0.5 % test only after ~40 orbits, so it runs the fixed window: the
criterion never ends a run early on a chance agreement of few blocks (the standard-error
test with >= 2 blocks). Units: SI.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import check_range
from ..rib import SIGN_REGULARISATION, rib_forces, rib_sliding_speed, squeeze_forces

#: warm-up settling test of simulate_coupled (roller_dynamics_coupled notes, "Cage
#: settling"): largest relative change of the orbit-mean cage speed from one warm-up orbit
#: to the next
DEFAULT_SETTLE = 1e-3
#: most warm-up orbits the settling test may run (then the window starts unsettled)
SETTLE_MAX_ORBITS = 16.0
#: settling test (:func:`creep_settled`): a cage speed that turned (the two half-orbit-lag
#: changes of opposite signs) passes only if both together are at most this fraction of the
#: tolerance (the settled motion's orbit-mean jitter; a turning point of the creep is larger)
SETTLE_JITTER = 0.1
#: blocks per cage orbit of the convergence test
BLOCKS_PER_ORBIT = 4
#: fewest blocks before the test is tried (one orbit; the window is then its later half)
MIN_BLOCKS = 4
#: absolute floors of the test [W], [m/s]: a heat or a slide of exactly 0 is converged
HEAT_FLOOR = 1e-9
SLIDE_FLOOR = 1e-9


def window_converged(blocks: np.ndarray, tol: float, floor: float = 0.0) -> bool:
    """True if the block means ``blocks`` (n >= 2, a statistics window) have converged to
    ``tol`` (relative): |mean(second half) - mean(first half)| <= tol |mean| + floor and
    2 std(blocks, ddof=1) / sqrt(n) <= tol |mean| + floor (module notes)."""
    check_range("tol", tol, 0.0, 1.0)
    b = np.asarray(blocks, float)
    n = b.size
    if n < 2 or not np.all(np.isfinite(b)):
        return False
    mean = float(np.mean(b))
    bound = tol * abs(mean) + floor
    drift = abs(float(np.mean(b[n // 2:])) - float(np.mean(b[:n // 2])))
    se = float(np.std(b, ddof=1)) / math.sqrt(n)
    return drift <= bound and 2.0 * se <= bound


def cage_mode_ratio(force_slope: float, cage_inertia: float, roller_mass: float,
                    n_rollers: int, pitch_radius: float, lag: float) -> float:
    """Decay ratio over ``lag`` [s] of the cage's orbital mode (roller_dynamics_heat notes,
    "Why the cage creeps"; ours): exp(-lag D / I) with the damping D = -r sum_j dF_d,j /
    d omega_c [N m s] of the raceways' net orbital forces' slope with the cage speed
    ``force_slope`` = sum_j dF_d,j / d omega_c [N s/rad] at pitch radius r =
    ``pitch_radius`` [m], and the inertia of the cage and the rollers it carries, I = J_c +
    Z m_r r^2 (``cage_inertia`` J_c [kg m^2], ``roller_mass`` m_r [kg], ``n_rollers`` Z).
    0 where D <= 0 (no damping from the raceways: no estimate). The unloaded rollers' drag
    is left out, so the mode decays faster than this (paper 003 base case, 400 K: estimated
    I/D = 14 ms, measured e-folding 8 ms): a floor of the creep's measured ratio that can
    only lengthen the warm-up."""
    inertia = cage_inertia + n_rollers * roller_mass * pitch_radius**2
    damping = -pitch_radius * force_slope
    if not (damping > 0.0 and inertia > 0.0 and lag >= 0.0):
        return 0.0
    return math.exp(-lag * damping / inertia)


def creep_settled(w_a: float, w_b: float, w_c: float, tol: float,
                  ratio_floor: float = 0.0) -> bool:
    """Warm-up settling test of the coupled dynamics' cage (roller_dynamics_coupled notes,
    "Cage settling"; ours, no paper equation). ``w_a``, ``w_b``, ``w_c`` [rad/s]: mean cage
    speeds over three one-orbit windows, each starting half an orbit after the previous one
    (``w_a`` and ``w_c`` two consecutive orbits); ``tol`` [-] relative. With d1 = w_b - w_a,
    d2 = w_c - w_b (the changes over half an orbit's lag) the cage has settled when

    * |w_c - w_a| <= tol |w_c| (the orbit-to-orbit change), and
    * the creep is geometric and decaying, d1 d2 >= 0 and |d2| < |d1|, with its remaining
      change beyond ``w_c``, |d2| q / (1 - q), q = max(d2 / d1, ``ratio_floor``) (sum of
      the geometric series of the half-orbit-lag changes; the floor a slowest decay the
      creep can have, :func:`cage_mode_ratio` over half an orbit: a slow mode under a
      faster decay does not show in three windows), at most tol |w_c|; or, the two changes
      of opposite signs
      (a turning point of the cage speed, or the settled motion's jitter), |d1| + |d2| <=
      :data:`SETTLE_JITTER` tol |w_c|.

    The orbit-to-orbit change alone passes falsely at a turning point (the orbit means on
    either side of a minimum agree) and, for a slow creep (q near 1), leaves up to tol q /
    (1 - q) of it; a change that grows (|d2| >= |d1|, same sign) never passes.
    """
    check_range("tol", tol, 0.0, 1.0)
    check_range("ratio_floor", ratio_floor, 0.0, 1.0)
    vals = (w_a, w_b, w_c)
    if not all(math.isfinite(v) for v in vals):
        return False
    bound = tol * abs(w_c)
    d1, d2 = w_b - w_a, w_c - w_b
    if abs(w_c - w_a) > bound:
        return False
    if d1 * d2 >= 0.0 and abs(d2) < abs(d1):
        q = max(d2 / d1, ratio_floor)
        if q >= 1.0:
            return False
        return abs(d2) * q / (1.0 - q) <= bound
    if d1 * d2 < 0.0 or (d1 == 0.0 and d2 == 0.0):
        return abs(d1) + abs(d2) <= SETTLE_JITTER * bound
    return False


def block_heat_slide(m: Any, samples: np.ndarray, cage_speed: np.ndarray
                     ) -> tuple[float, float]:
    """(roller- and sample-mean rib heat of one roller, both faces [W]; roller- and
    sample-mean |v_i - v_r| [m/s]) of coupled-dynamics samples (time x Z x 8 states: X, X',
    alpha, alpha', z, z', psi, omega; X relative to the inner ring) at the cage speeds
    ``cage_speed`` [rad/s] (time). The heat is the work rate of the rib forces as the
    response books it (:func:`thermobearing.rib.rib_forces` with the integrator's sign
    regularisation, the squeeze film's dissipation with ``m.rib_squeeze``), here at the
    model's quasi-static cage speed (a convergence test, not the booked value); the slide
    is that of :func:`thermobearing.rib.rib_sliding_speed` (unskewed contact point)."""
    g = m.geom
    x, xd, a, ad, spin = (samples[:, :, i] for i in (0, 1, 2, 3, 7))
    rf = rib_forces(g, a, x, inner_speed=m.inner_speed, cage_speed=m.cage_speed,
                    roller_spin=spin, skew_rate=ad, axial_speed=xd,
                    friction_coefficient=m.rib_friction,
                    mixture_viscosity=m.mixture_viscosity, smooth_sign=SIGN_REGULARISATION,
                    with_pressure=False)
    heat = rf.heat_left + rf.heat_right
    if getattr(m, "rib_squeeze", False):
        _, _, sq_l, sq_r = squeeze_forces(g, a, x, ad, xd, m.mixture_viscosity,
                                          m.squeeze_floor)
        heat = heat + sq_l + sq_r
    slide = np.abs(rib_sliding_speed(g, m.inner_speed, cage_speed[:, None], spin))
    return float(np.mean(heat)), float(np.mean(slide))


__all__ = ["BLOCKS_PER_ORBIT", "DEFAULT_SETTLE", "HEAT_FLOOR", "MIN_BLOCKS",
           "SETTLE_JITTER", "SETTLE_MAX_ORBITS", "SLIDE_FLOOR", "block_heat_slide",
           "cage_mode_ratio", "creep_settled", "window_converged"]
