"""Quasi-dynamic skidding / over-skidding solver of ball bearings (paper 002, QJ1044).

Steady state in the frame that turns with the cage. Every ball orbits with the cage (its
mean advance in the pocket is zero) and carries, per ball j, six unknowns

    x_j = (b_a, b_r, Omega_a, Omega_r, Omega_t, Q_p)

- ball-centre axial / radial position (b_a, b_r) [m] (the contact angles and loads follow from
  the raceway arcs of :mod:`thermobearing.loads`, every arc independent: two-, three- and
  four-point contact of a gothic-arch bearing come out of the geometry);
- the ball's angular velocity relative to the cage frame Omega [rad/s] in the local axes
  (a = bearing axis, r = radial, t = orbital direction), i.e. spin magnitude, attitude (pitch)
  angle beta = atan2(-Omega_r, Omega_a) and yaw angle (Omega_t, the "gyro-slip");
- the cage-pocket normal force Q_p [N] (positive: the cage pushes the ball forward);

and three global unknowns, the inner-ring displacements (delta_a, delta_r) [m] and the cage
speed omega_c [rad/s]. The force and moment balances per ball, the inner-ring force balance
and the cage torque balance (paper 002 Fig. 1(c), eqs. 5, 8, 9) are written out in
:mod:`~thermobearing.skidding.ball_residual`.

Nothing about over-skidding is imposed: the attitude angle, the contact angles (centrifugal
splitting of alpha_i / alpha_o, three-point contact against the outer shim angle) and the
rolling-direction slip all come out of these balances.

One job: drive the solve (:func:`solve_ball`): the race-control cold start
(:func:`race_control_guess`), warm starts, continuation in axial load from a well-loaded state
when a cold start fails (issue 5 item 4; in the load magnitude for loads far below the
centrifugal force, :mod:`~thermobearing.skidding.ball_load_continuation`), the errors and the
result. Failure raises
ConvergenceError with the residual norm and the state. The pieces live in their own modules,
re-exported here so that ``from thermobearing.skidding.ball import X`` keeps working:

* :mod:`~thermobearing.skidding.ball_residual`: :class:`BallModels`,
  :class:`ball_residual_system` (the equations), ``N_BALL``, ``N_GLOBAL``;
* :mod:`~thermobearing.skidding.ball_newton`: :func:`newton_block` (Newton with the
  structured finite-difference Jacobian and block elimination), :class:`JacobianBlocks`;
* :mod:`~thermobearing.skidding.ball_result`: :class:`BallSkiddingResult`, the result and
  kinematic-state building, :func:`theoretical_csr`.
"""

from __future__ import annotations

import math
import time

import numpy as np

from ..errors import ConvergenceError, InputError, check_finite, check_positive
from ..loads import ball_load_distribution
from .ball_coulomb import coulomb_traction_note
from .ball_load_continuation import (
    check_resolved_load,
    load_magnitude_continuation,
    start_scale,
)
from .ball_newton import (  # noqa: F401
    _CAP_G,
    _CAP_X,
    NEAR_ROOT_BELOW,
    JacobianBlocks,
    chord_polish,
    newton_block,
    trust_region,
)
from .ball_residual import N_BALL, N_GLOBAL, BallModels, ball_residual_system
from .ball_result import (  # noqa: F401  (private helpers re-exported)
    BallSkiddingResult,
    _kinematic_state,
    _result,
    theoretical_csr,
)
from .ball_round_off import accept_at_round_off
from .ball_seat import seated_newton

__all__ = [
    "N_BALL",
    "N_GLOBAL",
    "BallModels",
    "BallSkiddingResult",
    "JacobianBlocks",
    "ball_residual_system",
    "load_step_fraction",
    "newton_block",
    "race_control_guess",
    "solve_ball",
    "theoretical_csr",
]


#: load change (fraction of the larger load, :func:`load_step_fraction`) above which
#: :func:`solve_ball` starts cold although given a guess. Measured (QJ1044, Z = 16, 30 and 80
#: degC oil, 300-3000 r/min, 1 kN radial, from the BM-5 quick map's converged points to axial
#: loads 0-30x theirs, 590 pairs, CPU best of two): the warm start is cheaper below a
#: fraction of ~0.7 and dearer above (0.4-0.5: warm 1.9 ms against cold 3.6 ms; 0.8-0.85:
#: 5.7 / 4.0 ms; 0.95-1: 6.5 / 3.4 ms: a warm start that gives up after its 25 iterations
#: pays for both); above 0.75, 190 of the pairs, warm 5.7 ms and cold 3.8 ms on average.
#: In evaluations alone the cold start wins from ~0.5, but its load distribution costs CPU
#: that the evaluations do not count. Both land on the same state (CSR within 3.2e-10
#: relative). A collinear load ratio of 4 (or 1/4) is a fraction of 0.75.
COLD_LOAD_STEP = 0.75


def load_step_fraction(guess, radial_load: float, axial_load: float) -> float:
    """|F_new - F_old| / max(|F_old|, |F_new|) [-] of the load vectors F = (F_r, F_a) [N] of
    the warm start ``guess`` (a :class:`BallSkiddingResult` of :func:`solve_ball`, its loads
    read from its residual system) and of the new point; 0.0 when the guess carries no
    system or both loads are zero (no step to judge). Between 0 (the same loads) and 2 (a
    reversed load)."""
    system = guess.extra.get("system") if guess is not None else None
    if system is None:
        return 0.0
    fr0, fa0 = float(system.Fr), float(system.Fa)
    big = max(math.hypot(fr0, fa0), math.hypot(radial_load, axial_load))
    if not big > 0.0:
        return 0.0
    return math.hypot(radial_load - fr0, axial_load - fa0) / big


# ---------------------------------------------------------------------------------------------
# initial state from the load distribution and race control
# ---------------------------------------------------------------------------------------------
def race_control_guess(bearing, speed, radial_load, axial_load, n_balls=None):
    """Ball positions from :func:`ball_load_distribution` and outer-race-control spin.

    The spin vector follows the primer's (K1)-(K2) with the outer-race-control attitude
    tan(beta) = sin(alpha_o)/(cos(alpha_o) + gamma') (primer section 2.3), gamma' = D/d_m.
    """
    D = float(bearing.ball_diameter)
    dm = float(bearing.pitch_diameter)
    a0 = float(bearing.contact_angle)
    wm0 = 0.5 * speed * (1.0 - D * np.cos(a0) / dm)
    try:
        ld = ball_load_distribution(bearing, radial_load, axial_load, speed, orbital_speed=wm0,
                                    n_balls=n_balls)
    except ConvergenceError:
        # only a starting point: a looser tolerance will do (property tests:
        # SKF6304 at 46 r/min, Fr = 9.1 kN, Fa = 2.5 kN crawled at 3e-5 N against a 5e-6 N
        # tolerance -- the unloaded balls are held by centrifugal contacts of ~1e-4 N)
        ld = ball_load_distribution(bearing, radial_load, axial_load, speed,
                                    orbital_speed=wm0, n_balls=n_balls, tol=1e-6)
    ai, ao = ld.inner_contact_angle, ld.outer_contact_angle
    g = D / dm
    beta = np.arctan2(np.sin(ao), np.cos(ao) + g) * (1.0 if axial_load >= 0 else -1.0)
    ao = ao * (1.0 if axial_load >= 0 else -1.0)
    ai = ai * (1.0 if axial_load >= 0 else -1.0)
    T = np.tan(beta)
    ci, co = np.cos(ai), np.cos(ao)
    si, so = np.sin(ai), np.sin(ao)
    num = (1 - g * ci) * (co + T * so)
    wm = speed * num / (num + (1 + g * co) * (ci + T * si))
    wR = -speed / (g * np.cos(beta) * ((co + T * so) / (1 + g * co) + (ci + T * si) / (1 - g * ci)))
    # Omega = wR (cos beta, 0, -sin beta) in (a, r=z', t) -> components (a, r, t)
    X = np.zeros((ld.ball_x.size, N_BALL))
    X[:, 0], X[:, 1] = ld.ball_x, ld.ball_r
    X[:, 2] = wR * np.cos(beta)
    X[:, 3] = -wR * np.sin(beta)
    G = np.array([ld.delta_a, ld.delta_r, float(np.mean(wm))])
    return X, G, ld


# ---------------------------------------------------------------------------------------------
def solve_ball(bearing, models: BallModels, speed: float, radial_load: float,
               axial_load: float, *, n_balls: int | None = None,
               guess: BallSkiddingResult | None = None, tol: float = 1e-9,
               max_iter: int = 150, continuation: bool = True,
               theoretical_reference=None, warm_iterations: int = 25,
               energy_tol: float = 2e-9, energy_polish: int = 2,
               warm_refresh: float = 0.0, cold_fallback: bool = True,
               cold_load_step: float = COLD_LOAD_STEP) -> BallSkiddingResult:
    """Solve the ball/cage/ring equilibrium at one operating point.

    Parameters
    ----------
    bearing : BallBearing.
    models : BallModels (traction law, drag, cage torque, pocket friction).
    speed : inner-ring speed [rad/s] (> 0; outer ring fixed).
    radial_load, axial_load : [N] on the inner ring.
    n_balls : override Z (benchmarks).
    guess : previous result for a warm start (its unknowns and its Jacobian, rescaled, as
        the first chord Jacobian).
    warm_iterations : iterations allowed from the warm start before the cold start.
    tol : tolerance on the scaled residual norm (forces / F_s, moments / (F_s D/2)).
    continuation : (A cold start, or a warm one, that fails with balls touching nothing is
        first restarted from its last iterate with those balls seated on their arcs,
        :func:`~thermobearing.skidding.ball_seat.seated_newton`, ``extra["fallback"] =
        "seat"``.) On a cold-start failure under a load far below one ball's centrifugal
        force (below F_s / sqrt(10)), continue in the load magnitude from F_s along the
        same load direction (:mod:`~thermobearing.skidding.ball_load_continuation`,
        ``"load_continuation"``); else, or if that fails, continue from a higher axial
        load, and if that fails, in speed from a slow state (:func:`_speed_continuation`,
        ``extra["fallback"] = "speed_continuation"``). (A cold start
        that reaches the iteration limit below a residual of 1e-2 first gets a second budget
        of Newton iterations from its last iterate, ``extra["fallback"] = "newton_restart"``;
        one whose damped Newton stalls there gets the trust-region fallback
        :func:`~thermobearing.skidding.ball_newton.trust_region`, ``"trust_region"``, and if
        that fails too, Newton iterations without the stall rule from the best iterate,
        ``"newton_restart"``; a state reached by the continuation is marked
        ``"continuation"``.)
    energy_tol, energy_polish : a converged state whose energy identity |T_shaft omega_i -
        sum heat| / sum heat is above ``energy_tol`` gets up to ``energy_polish`` more chord
        steps (each kept only if it lowers the residual; the identity is required to 1e-8).
    cold_fallback : with ``guess``, a warm start that fails starts cold (default); False:
        it raises (the steps of :func:`_speed_continuation` after the first).
    cold_load_step : with ``guess`` and ``cold_fallback``, start cold instead when the load
        vector moved by more than this fraction of the larger of the two loads since the
        guess (:func:`load_step_fraction`; default :data:`COLD_LOAD_STEP`, math.inf: always
        warm); ``extra["start"] = "cold_load_step"`` then says so.
    warm_refresh : warm starts: refresh the Jacobian analytically when the chord steps would
        need more than this many further evaluations (see
        :func:`~thermobearing.skidding.ball_newton.newton_block`; 0, the default: only when a
        chord / Broyden step contracts by less than half -- measured faster on the BM-5 maps).

    Returns
    -------
    BallSkiddingResult

    Raises ConvergenceError (residual inf) without solving when there is no external load, or
    when the load is nonzero but below 10 x tol x F_s, the force resolution of the solve
    (:func:`~thermobearing.skidding.ball_load_continuation.check_resolved_load`).
    """
    if not (math.isfinite(speed) and speed > 0.0 and math.isfinite(radial_load)
            and radial_load >= 0.0 and math.isfinite(axial_load)):
        # the checks that name the bad input (skipped when the plain tests above pass)
        check_positive("speed", speed)
        check_positive("radial_load", radial_load, allow_zero=True)
        check_finite("axial_load", axial_load)
    if not (isinstance(tol, int | float) and 0.0 < tol < 1.0):
        raise InputError("tol", tol, "a tolerance on the scaled residual norm in (0, 1)")
    if isinstance(max_iter, bool) or not isinstance(max_iter, int | np.integer) or max_iter < 1:
        raise InputError("max_iter", max_iter, "a whole number of Newton iterations >= 1")
    if not (isinstance(cold_load_step, int | float) and cold_load_step >= 0.0):
        raise InputError("cold_load_step", cold_load_step,
                         "a load-change fraction >= 0 (math.inf: always warm)")
    if radial_load == 0.0 and axial_load == 0.0:
        # no external load (clearance >= 0): the inner ring carries no contact load in
        # equilibrium, so nothing drives the balls or the cage (the SKF6304
        # "converged" here to CSR = 0 or -0 with every ball parked in the outer groove)
        raise ConvergenceError(
            "skidding.ball", math.inf,
            "no external load: no ball touches the inner ring (with clearance >= 0 nothing "
            "presses the balls against it), nothing drives the cage, CSR undefined in this "
            "model", {"radial_load": 0.0, "axial_load": 0.0, "speed": speed})
    if guess is not None and not isinstance(guess, BallSkiddingResult):
        # (a roller result raised AttributeError)
        raise InputError("guess", type(guess).__name__,
                         "a BallSkiddingResult of an earlier solve (warm start) or None")
    if guess is not None and guess.ball_x.size != int(n_balls or bearing.n_balls):
        # another bearing's (or ball count's) state cannot start this one: cold start (a
        # QJ1044 result given to the SKF6304 raised UnboundLocalError)
        guess = None
    start = None
    if (guess is not None and cold_fallback
            and load_step_fraction(guess, radial_load, axial_load) > cold_load_step):
        # a warm start across a large load change costs more than the cold start
        # (COLD_LOAD_STEP); the warm-only steps of the continuations (cold_fallback False)
        # keep their guess
        guess, start = None, "cold_load_step"
    t0 = time.perf_counter()
    prev = guess.extra.get("system") if guess is not None else None
    if (prev is not None and prev.bearing is bearing and prev.models is models
            and prev.speed == float(speed) and prev.Z == int(n_balls or bearing.n_balls)):
        # same bearing, models, speed and Z: the previous system at the new loads
        system = prev.reloaded(radial_load, axial_load)
    else:
        system = ball_residual_system(bearing, models, speed, radial_load, axial_load, n_balls)
    check_resolved_load(system.F_s, tol, radial_load, axial_load, speed)
    iters = 0
    fallback = None
    if guess is not None and guess.ball_x.size == system.Z:
        X0 = guess.unknowns[0].copy()
        G0 = guess.unknowns[1].copy()
        # the same speed: the previous state exactly (the system may know its residual)
        G0[2] = (guess.cage_speed if float(speed) == guess.inner_speed
                 else guess.cage_speed_ratio * speed)
        if float(speed) != guess.inner_speed:
            X0[:, 2:5] *= speed / guess.inner_speed
        try:
            # a warm start that needs many iterations is further from the solution than
            # the race-control cold start (measured: a 0 -> 2 kN axial step of the QJ1044
            # took 47 warm iterations, 10 cold): give it a budget, then start cold. 25
            # (was 15): the default scene's 2 -> 4 kN step converges warm in 24 iterations
            # (209 evaluations, ~105 ms CPU) where 15 warm + a cold start cost 257
            # evaluations plus the at-speed load distribution (~210 ms CPU)
            X, G, nrm, iters = newton_block(system, X0, G0, tol=tol,
                                            max_iter=min(max_iter, warm_iterations),
                                            jacobian=guess.extra.get("jacobian"),
                                            give_up=(6, 0.5), warm_refresh=warm_refresh)
        except ConvergenceError as err:
            # floating balls (ball_seat) first: the steps of the speed continuation of a
            # lightly loaded bearing whose cage nearly stops (7014C at 4925 r/min, 0.005 N
            # radial, -20 degC ISO VG32) gave up warm with every unloaded ball off its arc
            seated = seated_newton(system, err, tol=tol, max_iter=max_iter,
                                   newton=newton_block)
            if seated is not None:
                X, G, nrm, more = seated
                iters = int(err.state.get("iteration", 0)) + more
                fallback = "seat"
            elif not cold_fallback:
                # a warm step of the speed continuation (no cold start behind it): Newton
                # without the give-up and stall rules from its last iterate, then the
                # acceptance at the round-off floor of its residual (ball_round_off), else
                # the error (_warm_step_fallbacks)
                X, G, nrm, iters, fallback, round_off = _warm_step_fallbacks(
                    system, err, tol, max_iter)
            else:
                guess = None
    if guess is None:
        X0, G0, ld0 = race_control_guess(bearing, speed, radial_load, axial_load, n_balls)
        if not np.any(ld0.inner_load > 0.0):
            # a load below the load distribution's force tolerance (a few uN) under the
            # centrifugal force: the at-speed distribution leaves the inner ring untouched
            # (with a nonzero load it rests on some ball in equilibrium): the continuation in
            # load magnitude from F_s, else the error
            X, G, nrm, iters, fallback, round_off = _unsupported_ring(
                bearing, models, speed, radial_load, axial_load, n_balls, tol, max_iter,
                continuation, system)
        else:
            X = None
    if guess is None and X is None:
        try:
            X, G, nrm, iters = newton_block(system, X0, G0, tol=tol, max_iter=max_iter,
                                            stall_after=25)
        except ConvergenceError as err:
            seated = seated_newton(system, err, tol=tol, max_iter=max_iter,
                                   newton=newton_block)
            if seated is None:
                try:
                    X, G, nrm, iters, fallback, round_off = _cold_fallbacks(
                        bearing, models, speed, radial_load, axial_load, n_balls, tol,
                        max_iter, continuation, system, err)
                except ConvergenceError as final:
                    # say why when the cold oil makes the traction a Coulomb step at the
                    # quadrature nodes (ball_coulomb): the 6206 at -38 degC in ISO VG46. Judged
                    # at the race-control start (a failed iterate may spin its balls at
                    # 1e6 rad/s, with entrainment speeds to match)
                    note = (coulomb_traction_note(system, X0, G0) if continuation else None)
                    if note is None:
                        raise
                    raise ConvergenceError("skidding.ball", final.residual,
                                           f"{note} (every fallback failed: {final})",
                                           dict(final.state)) from None
            else:
                # balls that touch nothing (ball_seat: a cage that nearly stops leaves the
                # unloaded balls floating inside the outer groove) seated on their arc
                X, G, nrm, more = seated
                iters = int(err.state.get("iteration", max_iter)) + more
                fallback = "seat"
    own_reference = theoretical_reference is None
    if own_reference and guess is not None:
        # CSR_th depends on the loads and the geometry only (a zero-speed load
        # distribution): reuse the warm start's when they are the same
        key = guess.extra.get("theoretical_key")
        if key is not None and key[0] is bearing and key[1:] == (float(radial_load),
                                                                   float(axial_load),
                                                                   system.Z):
            theoretical_reference = guess.theoretical_cage_speed_ratio
    res = _result(system, X, G, nrm, iters, time.perf_counter() - t0, theoretical_reference)
    for _ in range(energy_polish):
        # the energy identity (shaft torque x speed = total heat, issue 5: 1e-8) closes with
        # the residual; where the scaled tolerance leaves it loose (low speed, high load:
        # 7e-8 measured at 300 r/min, 40 kN, hot oil) a chord step tightens it
        gap = abs(res.shaft_torque * res.inner_speed - res.heat["total"])
        if not gap > energy_tol * abs(res.heat["total"]):
            break
        X, G, nrm, taken = chord_polish(system, X, G, system.last_jacobian)
        if not taken:
            break
        iters += 1
        res = _result(system, X, G, nrm, iters, time.perf_counter() - t0,
                      res.theoretical_cage_speed_ratio)
    if fallback is not None:
        res.extra["fallback"] = fallback
    if start is not None:
        res.extra["start"] = start
    if fallback == "round_off":
        res.extra["round_off_floor"] = round_off
    if own_reference:
        res.extra["theoretical_key"] = (bearing, float(radial_load), float(axial_load),
                                        system.Z)
    return res


def _unsupported_ring(bearing, models, speed, radial_load, axial_load, n_balls, tol, max_iter,
                      continuation, system):
    """The cold start of :func:`solve_ball` when the at-speed load distribution puts no ball
    on the inner ring under a nonzero load (below its force tolerance, ~5e-6 N, against the
    centrifugal force): the continuation in load magnitude from F_s
    (:mod:`~thermobearing.skidding.ball_load_continuation`). Returns (X, G, residual norm,
    iterations, fallback name, round-off floor or None); raises ConvergenceError saying so."""
    err = ConvergenceError(
        "skidding.ball", float("inf"),
        "no ball touches the inner ring in the load distribution at speed (centrifugal force "
        "holds every ball in the outer groove and the load is below that distribution's "
        "force tolerance): no start for the cage's drive",
        {"radial_load": radial_load, "axial_load": axial_load, "speed": speed})
    if not (continuation and start_scale(system.F_s, radial_load, axial_load) > 1.0):
        raise err
    try:
        path, iters = load_magnitude_continuation(
            solve_ball, bearing, models, speed, radial_load, axial_load, n_balls, tol,
            max_iter, system.F_s, err)
    except ConvergenceError as failed:
        raise ConvergenceError("skidding.ball", failed.residual, str(failed),
                               dict(failed.state)) from None
    system.last_jacobian = path.extra.get("jacobian")
    fallback, round_off = "load_continuation", None
    if path.extra.get("fallback") == "round_off":
        fallback, round_off = "round_off", path.extra.get("round_off_floor")
    X, G = (u.copy() for u in path.unknowns)
    return X, G, path.residual_norm, iters, fallback, round_off


def _warm_step_fallbacks(system, err, tol, max_iter):
    """A failed warm start without a cold start behind it (the steps of
    :func:`_speed_continuation`): one budget (``max_iter``) of Newton without the give-up and
    stall rules from its last iterate (``err.iterate``), then the acceptance at the round-off
    floor (:func:`~thermobearing.skidding.ball_round_off.accept_at_round_off`). Returns (X,
    G, residual norm, iterations, fallback name, round-off floor or None); raises ``err``.

    Measured: 7014C at 4925 r/min, 100 N radial, -20 degC ISO VG100 (the cage at 6.5 % of
    the shaft) -- warm steps that gave up after 6 iterations converge within the budget,
    others stop at their round-off floor (the loaded balls' spin moments in the steep
    cold-oil traction: 3.8e-9 against a floor of 2.5e-7); the point converges (it stopped at
    1.0e-7). Four budgets also rescued 7014C at 0.005 N radial in -20 degC ISO VG100 (417
    iterations on one step) but doubled the CPU of points that end at the round-off floor
    anyway (SKF6304 at 10012 r/min, -14 degC ISO VG46: 1.1 s before, 3.5 s with one budget,
    7 s with four). The budget's Newton takes the regularised step near a root
    (``near_root_below``, :mod:`~thermobearing.skidding.ball_damped_step`): the steps of that
    7014C (0.005 N radial, -20 degC, ISO VG32 and VG100; the cage at 2e-5 / 3e-6 of the
    shaft) crawled at ratio 0.94 with the step cap cut by the free spins of the balls held
    by 1e-8 N centrifugal contacts, and the continuation stopped at 8.4e-7 / 7.4e-6; with it
    each step converges in a few iterations (the point in ~1.4 / 0.8 s of CPU)."""
    last = getattr(err, "iterate", None)
    errors = [err]
    if last is not None and last[2] < 1e-2:
        try:
            X, G, nrm, more = newton_block(system, last[0], last[1], tol=tol,
                                           max_iter=max_iter, stall_after=0,
                                           near_root_below=NEAR_ROOT_BELOW)
            return X, G, nrm, int(err.state.get("iteration", 0)) + more, "newton_restart", None
        except ConvergenceError as err2:
            errors.append(err2)
    found = accept_at_round_off(system, tol, errors)
    if found is None:
        raise err
    X, G, nrm, round_off, system.last_jacobian = found
    return X, G, nrm, int(err.state.get("iteration", 0)), "round_off", round_off


def _cold_fallbacks(bearing, models, speed, radial_load, axial_load, n_balls, tol, max_iter,
                    continuation, system, err):
    """The fallbacks of a failed cold start (``err``) of :func:`solve_ball`, in order: Newton
    restarts / the trust region from its last iterate, the continuation in load magnitude
    (light loads only, :mod:`~thermobearing.skidding.ball_load_continuation`), in axial load,
    in speed, the acceptance at the round-off floor. Returns (X, G, residual norm, iterations,
    fallback name, round-off floor or None); raises the ConvergenceError of the last one that
    failed."""
    fallback = round_off = None
    # a Newton that stalled close to a root (residual below 1e-2): Powell's
    # trust-region method from its last iterate (one point of the BM-5
    # 20 x 20 map stalled at 1.9e-3 and converged this way); else, or if that fails,
    # the continuation in axial load
    last = getattr(err, "iterate", None)
    try:
        if last is None or not last[2] < 1e-2:
            raise err
        try:
            if "iteration" in err.state:   # a stall or failed line search
                raise err
            # the iteration limit reached while still converging (the
            # property tests: a deep-groove bearing under a radial load crawls along
            # the near-mechanism of its axial play -- SKF6304, 10 r/min, 1 kN, 40 degC
            # stood at 1.1e-6 after 150 iterations and converges in 208; at 5 kN in
            # 560: the unloaded balls at low speed are held only by a tiny centrifugal
            # contact, a nearly singular block): four more budgets of Newton
            # iterations from the last iterate (~0.3 ms each), before the fallbacks
            X, G, nrm, more = newton_block(system, last[0], last[1], tol=tol,
                                           max_iter=4 * max_iter, stall_after=25)
            iters, fallback = max_iter + more, "newton_restart"
        except ConvergenceError as err2:
            last2 = getattr(err2, "iterate", None)
            if last2 is not None and last2[2] < last[2]:
                last = last2
            more = 0
            try:
                X, G, nrm, _ = trust_region(system, last[0], last[1], tol=tol)
                fallback = "trust_region"
            except ConvergenceError:
                # a damped Newton that the stall rule stopped may still crawl to the
                # root: QJ1044, 2.3 N radial at 47 r/min in 18 degC oil (the cage
                # turns at 0.5 % of the shaft, the unloaded balls are held by
                # centrifugal contacts of ~1e-5 N) stalls at 1.2e-4 after 100
                # iterations and hybr stops at 8.9e-6, while the same Newton without
                # the stall rule converges in 305 more iterations (~0.1 s). Four
                # budgets of it, then the continuation
                X, G, nrm, more = newton_block(system, last[0], last[1], tol=tol,
                                               max_iter=4 * max_iter, stall_after=0)
                fallback = "newton_restart"
            iters = int(err.state.get("iteration", max_iter)) + more
    except ConvergenceError:
        if not continuation:
            # the steps of the continuations: the last iterate if it is a root to the
            # round-off floor of its evaluation (ball_round_off; 7014C at 4925/4 r/min,
            # 100 N radial, -20 degC ISO VG100: 3.8e-9 against a floor of 2.5e-7 from the
            # loaded balls' spin moments in the steep cold-oil traction), else the error
            found = accept_at_round_off(system, tol, (err,))
            if found is None:
                raise err from None
            X, G, nrm, round_off, system.last_jacobian = found
            return X, G, nrm, int(err.state.get("iteration", max_iter)), "round_off", round_off
        errors = [err]
        try:
            try:
                # a load far below one ball's centrifugal force (the solver's force scale
                # F_s): from F_s along the same load direction (ball_load_continuation)
                if start_scale(system.F_s, radial_load, axial_load) <= 1.0:
                    raise err
                path, iters = load_magnitude_continuation(
                    solve_ball, bearing, models, speed, radial_load, axial_load, n_balls,
                    tol, max_iter, system.F_s, err)
                X, G = (u.copy() for u in path.unknowns)
                nrm, system.last_jacobian = path.residual_norm, path.extra.get("jacobian")
                fallback = "load_continuation"
                if path.extra.get("fallback") == "round_off":
                    fallback, round_off = "round_off", path.extra.get("round_off_floor")
                return X, G, nrm, iters, fallback, round_off
            except ConvergenceError as err_mag:
                if err_mag is not err:
                    errors.append(err_mag)
            X, G, nrm, iters, system.last_jacobian = _continuation(
                bearing, models, speed, radial_load, axial_load, n_balls, tol,
                max_iter, err)
            fallback = "continuation"
        except ConvergenceError as err_load:
            try:
                X, G, nrm, iters, system.last_jacobian = _speed_continuation(
                    bearing, models, speed, radial_load, axial_load, n_balls, tol,
                    max_iter, err_load)
                fallback = "speed_continuation"
            except ConvergenceError as err_speed:
                # every fallback stopped just above the tolerance: accept the best
                # iterate at the target if its residual is at the round-off floor
                # of its evaluation (ball_round_off), else the error as before
                found = accept_at_round_off(system, tol, (*errors, err_speed))
                if found is None:
                    raise
                X, G, nrm, round_off, system.last_jacobian = found
                iters = int(err.state.get("iteration", max_iter))
                fallback = "round_off"
    return X, G, nrm, iters, fallback, round_off


def _speed_continuation(bearing, models, speed, radial_load, axial_load, n_balls, tol,
                        max_iter, err, *, start_ratios=(0.25, 1.0 / 16.0, 1.0 / 40.0),
                        steps=12):
    """Continuation in the inner-ring speed, the last fallback (issue 5 item 4): from a
    slow state (``start_ratios`` of the speed; centrifugal force and gyroscopic moment
    scale with its square) up to the speed in ``steps`` geometric steps: the first solved
    cold (:func:`solve_ball` without the continuations), each next one warm from the last
    only; a failed step is halved (at most three times), then the next start ratio is
    tried. The force models stay those
    of the target speed along the path: the intermediate states are only the path, the
    returned state is solved at the target speed with its own models.

    Measured: QJ1044 at 1.9 N radial, 1511 r/min, 35 degC, and at -1.13 N axial, 3380
    r/min, 82 degC (the cage turns at 0.09 / 0.11 % of the shaft: every start and the
    continuation in axial load fail, the best at 3.3e-5 / 3.8e-3) converge in about 1 s of
    CPU each; the second only from a quarter of the speed (from a sixteenth its first, cold
    step stalls). Returns (X, G, residual norm, iterations,
    last Jacobian); raises a ConvergenceError naming the speed where the path stopped."""
    last_err = err
    best = None           # the best iterate at the target speed, for the caller's round-off
    for ratio in start_ratios:
        speeds = list(speed * np.geomspace(ratio, 1.0, steps))
        speeds[-1] = float(speed)
        res = None
        last_speed = None
        halvings = 0
        total = 0
        while speeds:
            w = float(speeds[0])
            try:
                # the first step from cold with the restarts and the trust region; the
                # others warm only (a failed one is halved, not restarted cold)
                step = solve_ball(bearing, models, w, radial_load, axial_load,
                                  n_balls=n_balls, guess=res, tol=tol, max_iter=max_iter,
                                  continuation=False, cold_fallback=res is None)
                if w == float(speed) and step.extra.get("fallback") == "round_off":
                    # a step may stop at its round-off floor on the way, not at the
                    # target: there the caller picks the best iterate of all its attempts
                    # and says so (SKF6304 at 10012 r/min, -14 degC ISO VG46: a warm step
                    # accepted 1.7e-5 where the cold start had reached 2.3e-9 when written;
                    # the point is accepted at 3.4e-6 now, tests/unit/skidding/
                    # test_ball_round_off.py)
                    e = ConvergenceError("skidding.ball", step.residual_norm,
                                         "the step at the target speed stopped at its "
                                         "round-off floor", {"speed": w})
                    e.iterate = (*step.unknowns, step.residual_norm)
                    raise e
                res = step
            except ConvergenceError as e:
                last_err = e
                it = getattr(e, "iterate", None)
                if w == float(speed) and it is not None and (best is None or it[2] < best[2]):
                    best = it
                if last_speed is not None and halvings < 3:
                    halvings += 1
                    speeds.insert(0, math.sqrt(last_speed * w))
                    continue
                res = None
                break
            last_speed = w
            total += res.iterations
            speeds.pop(0)
        if res is not None and not speeds:
            X, G = res.unknowns
            return X.copy(), G.copy(), res.residual_norm, total, res.extra.get("jacobian")
    failed = ConvergenceError("skidding.ball", last_err.residual,
                              f"continuation in speed failed too ({last_err}); before it: "
                              f"{err}", dict(last_err.state))
    if best is not None:
        failed.iterate = best
    raise failed from None


def _continuation(bearing, models, speed, radial_load, axial_load, n_balls, tol, max_iter,
                  err):
    """Continuation in axial load from a well-loaded state (issue 5 item 4).

    Each load step is warm-started from the last converged state; a step that fails is
    retried cold at its load (race-control start), then halved (at most three times) between
    the last converged load and it (QJ1044 at 199 r/min, 132.5 N radial, the
    warm step 251 -> 158 N axial failed at 1.9e-2 while a cold start at 160 N converges).
    No cap on the failed solves: capped at 4 or 8, the seeded random probe lost 5 or 1 of
    the QJ1044 points this recovers; a point that fails after all of them costs up to ~16 s
    of CPU (SKF6304 at 2.8x C0)."""
    Z = int(n_balls or bearing.n_balls)
    fc = bearing.ball_mass * (0.25 * speed) ** 2 * 0.5 * bearing.pitch_diameter
    F_hi = max(abs(axial_load), Z * fc * 4.0, 5000.0) * (1 if axial_load >= 0 else -1)
    loads = np.concatenate([[F_hi], F_hi * np.geomspace(1.0, 1e-3, 13)[1:], [0.0]])
    loads = loads[np.abs(loads) > abs(axial_load)]
    loads = list(np.append(loads, axial_load))
    X = G = None
    total = 0
    jac = None
    last_Fa = None
    halvings = 0
    while loads:
        Fa = float(loads[0])
        system = ball_residual_system(bearing, models, speed, radial_load, Fa, n_balls)
        starts = [] if X is None else [(X, G, jac)]
        starts.append(race_control_guess(bearing, speed, radial_load, Fa, n_balls)[:2] + (None,))
        e2 = None
        solved = False
        for X0, G0, j0 in starts:
            try:
                X1, G1, nrm, it = newton_block(system, X0, G0, tol=tol, max_iter=max_iter,
                                               jacobian=j0)
                solved = True
                break
            except ConvergenceError as e:
                e2 = e
                total += int(e.state.get("iteration", max_iter))
        if not solved:
            if last_Fa is not None and halvings < 3:
                halvings += 1
                loads.insert(0, 0.5 * (last_Fa + Fa))
                continue
            raise ConvergenceError("skidding.ball", e2.residual,
                                   f"continuation failed at axial load {Fa:.6g} N "
                                   f"(cold start: {err})", {**e2.state, "axial_load": Fa}) from None
        X, G, jac = X1, G1, system.last_jacobian
        last_Fa = Fa
        loads.pop(0)
        total += it
    return X, G, nrm, total, jac
