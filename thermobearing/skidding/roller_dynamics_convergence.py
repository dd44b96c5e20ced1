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
SETTLE_MAX_ORBITS = 12.0
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
           "SETTLE_MAX_ORBITS", "SLIDE_FLOOR", "block_heat_slide", "window_converged"]
