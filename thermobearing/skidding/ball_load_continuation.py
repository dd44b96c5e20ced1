"""Continuation in the load magnitude for a lightly loaded ball bearing (a skidding fallback).

One job: solve the ball skidding state at the loads (F_r, F_a) from a state at the same load
direction but a load of the order of one ball's centrifugal force, s (F_r, F_a) with s > 1,
stepping s down geometrically to 1, every step warm from the last
(:func:`load_magnitude_continuation`, a fallback of :func:`~thermobearing.skidding.ball.
solve_ball` for loads below the solver's force scale F_s, i.e. below one ball's centrifugal
force at the epicyclic cage speed, or 10 N).

Why: the race-control cold start puts the cage at the epicyclic speed and seats every ball in
the outer groove under its centrifugal force m omega_c^2 d_m/2. Under an external load far
below that force the inner contacts carry almost nothing, the drive of the cage is of the
order of the load and the cage nearly stops (QJ1044, 35 degC ISO VG46, 1871 r/min: CSR 4e-4
at 1 N radial, 5e-7 at 1 mN, proportional to the load). Along the cold start's path to that
state the centrifugal force vanishes, so every ball that is not clamped between the rings
floats a few hundred nanometres inside the outer groove, and the ball that carries the radial
load (pressed outward by the inner ring, touching no outer arc) moves with the inner ring in a
direction nothing resists: the Jacobian is singular along it, the capped Newton steps crawl and
stall (QJ1044 at 1871 r/min, 1 mN radial, F_a = 0: stalled at 4.3e-6, i.e. the whole 1 mN
unbalanced on that ball; the continuations in axial load and speed ended at 4.3e-6 and 1.6e3).
From a converged state at a larger load of the same direction every ball is seated, and a
step of a factor sqrt(10) in the load changes the state by little: measured on that point,
from 1 N down to 1e-5 N every warm step converges in 4-13 iterations.

Units: SI (N, rad/s).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from ..errors import ConvergenceError

__all__ = ["RESOLUTION_FACTOR", "STEP_FACTOR", "check_resolved_load",
           "load_magnitude_continuation", "start_scale"]

#: ratio of consecutive load magnitudes along the path (a failed step is split
#: geometrically, at most ``halvings`` times in a row)
STEP_FACTOR = math.sqrt(10.0)

#: smallest external load the solver resolves, in units of its force resolution tol F_s (each
#: scaled force row is met to ``tol``, i.e. to tol F_s newtons). Measured on the QJ1044 at 1871
#: r/min, F_a = 0, 35 degC ISO VG46 (tol F_s = 2.3e-7 N), stepping the radial load down warm:
#: the CSR stays proportional to the load down to 1e-7 N (5.85e-11; 5.69e-11 extrapolated
#: from 1e-5 N) and stops responding below (3.2e-8 N to 1e-12 N all return the state of 3e-8
#: N, CSR 1.9e-11, after 0-1 iterations); 10 keeps a decade of margin
RESOLUTION_FACTOR = 10.0


def check_resolved_load(force_scale: float, tol: float, radial_load: float,
                        axial_load: float, speed: float) -> None:
    """Raise ConvergenceError when the external load |(F_r, F_a)| [N] is nonzero but below
    :data:`RESOLUTION_FACTOR` x tol x ``force_scale`` (the solver's F_s [N]): the balances are
    met to tol F_s per row, so such a load would not be resolved (the state would be that of
    a larger load, or of none)."""
    mag = math.hypot(radial_load, axial_load)
    floor = RESOLUTION_FACTOR * tol * force_scale
    if 0.0 < mag < floor:
        raise ConvergenceError(
            "skidding.ball", math.inf,
            f"external load {mag:.3g} N below the solver's force resolution: the force "
            f"balances are met to tol x F_s = {tol * force_scale:.3g} N per row (F_s = "
            f"{force_scale:.3g} N, one ball's centrifugal force at the epicyclic cage speed or "
            f"10 N), and a load under {RESOLUTION_FACTOR:g} x that ({floor:.3g} N) is not "
            "resolved (under such loads the cage nearly stops, its speed proportional to the "
            "load); a smaller tol lowers this bound",
            {"radial_load": radial_load, "axial_load": axial_load, "speed": speed})


def start_scale(force_scale: float, radial_load: float, axial_load: float) -> float:
    """s_0 such that s_0 |(F_r, F_a)| = ``force_scale`` [N] (the solver's F_s, one ball's
    centrifugal force at the epicyclic cage speed or 10 N) when the load is below it by more
    than one step (:data:`STEP_FACTOR`); else 1 (no continuation: that includes the path's
    own start, solved with every other fallback, and a zero load, no direction to follow)."""
    mag = math.hypot(radial_load, axial_load)
    if not (mag > 0.0 and force_scale > STEP_FACTOR * mag):
        return 1.0
    return force_scale / mag


def load_magnitude_continuation(solve: Callable[..., Any], bearing: Any, models: Any,
                                speed: float, radial_load: float, axial_load: float,
                                n_balls: int | None, tol: float, max_iter: int,
                                force_scale: float, err: ConvergenceError, *,
                                halvings: int = 3) -> tuple[Any, int]:
    """The state at (``radial_load``, ``axial_load``) [N] by continuation in the load
    magnitude from ``force_scale`` [N] (module docstring). ``solve`` is
    :func:`~thermobearing.skidding.ball.solve_ball` (passed in to keep the import graph
    flat): the first load is solved cold with all its fallbacks (seating, Newton restarts,
    trust region, the continuations in axial load and speed; not this one, its load is not
    below ``force_scale``), every next one warm only
    (``cold_fallback=False``); a failed step is split at the geometric mean of the last
    converged scale and its own, at most ``halvings`` times in a row. ``err``: the cold
    start's error, named in the error raised when the path fails.

    Returns (the BallSkiddingResult at the target loads, total Newton iterations of the
    path). Raises ConvergenceError naming the load scale where the path stopped (with the
    best iterate at the target loads, if any, as ``iterate``)."""
    s0 = start_scale(force_scale, radial_load, axial_load)
    if s0 <= 1.0:
        raise err
    n = max(1, math.ceil(math.log(s0) / math.log(STEP_FACTOR)))
    scales = list(np.geomspace(s0, 1.0, n + 1))
    scales[-1] = 1.0
    res = None
    last_s = None
    split = 0
    total = 0
    while scales:
        s = float(scales[0])
        try:
            res = solve(bearing, models, speed, s * radial_load, s * axial_load,
                        n_balls=n_balls, guess=res, tol=tol, max_iter=max_iter,
                        continuation=res is None, cold_fallback=res is None)
        except ConvergenceError as e:
            if last_s is not None and split < halvings:
                split += 1
                scales.insert(0, math.sqrt(last_s * s))
                continue
            failed = ConvergenceError(
                "skidding.ball", e.residual,
                f"continuation in load magnitude stopped at {s:.4g} x the loads "
                f"(radial {s * radial_load:.4g} N, axial {s * axial_load:.4g} N): {e}; "
                f"before it: {err}", dict(e.state))
            it = getattr(e, "iterate", None)
            if s == 1.0 and it is not None:
                failed.iterate = it
            raise failed from None
        split = 0
        last_s = s
        total += res.iterations
        scales.pop(0)
    return res, total
