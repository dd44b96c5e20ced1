"""Newton driver of the ball skidding solver: damped Newton with block elimination.

One job: solve :class:`~thermobearing.skidding.ball_residual.ball_residual_system` from a
start (:func:`newton_block`). Numerics (issue 5 item 4): Newton with a structured Jacobian
(:class:`JacobianBlocks`), analytic (:mod:`~thermobearing.skidding.ball_jacobian`)
where the default compiled models run, else by forward differences -- the six per-ball
columns are perturbed for all balls at once (ball blocks are independent except through the
globals), three more evaluations give the global columns; the 6x6 ball blocks are eliminated
and the 3x3 Schur complement on the globals is solved; backtracking line search on the scaled
residual norm. Warm starts take chord / good-Broyden steps with the handed-over Jacobian in
one compiled loop (:func:`_chord_phase`). Failure raises ConvergenceError with the residual
norm and the state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import ConvergenceError, InputError
from .ball_damped_step import regularised_step
from .ball_jacobian import analytic_blocks, supports_analytic
from .ball_newton_kernels import (  # noqa: F401  (the compiled kernels, re-exported)
    _PH_DONE,
    _PH_HANDBACK,
    _PH_REFRESH,
    _block_step,
    _broyden_step,
    _chord_phase,
    _exact_torques,
    _factor_blocks,
    _fd_blocks,
    _inverse_small,
    _propose,
    _refresh_caches,
    _rescale_blocks,
    _rescale_factors,
    _residual_norm,
    _torque_model,
)
from .ball_residual import N_BALL, N_GLOBAL, _residual_one, ball_residual_system  # noqa: F401

__all__ = ["JacobianBlocks", "block_factors", "chord_polish", "newton_block", "trust_region"]

# largest Newton step per scaled unknown (positions in microns, spins / (omega_i d_m / D),
# pocket force / F_s; ring displacement in microns, cage speed / omega_i). Spins 0.5 (with
# 0.2, light-load cold starts crept at the cap, every damped step scaled to
# 1/5 of the Newton step by one ball's axial spin, with a fresh Jacobian each time (12 such
# iterations at 300 r/min, Fa = 0, hot oil). Measured on 540 cold starts (Z = 8/16/32,
# 300-3000 r/min x 10, Fa = 0 and 200 N-40 kN x 8, cold and hot oil, newton_block alone):
# 0.2: 2 failures, 52993 evaluations; 0.5: none, 45315; 1.0: failures (3 of 120 on the
# 5 x 5 maps).
_CAP_X = np.array([20.0, 20.0, 0.5, 0.5, 0.5, 5.0])
_CAP_G = np.array([20.0, 20.0, 0.1])
_NO_HIST = np.empty((0, 0))
#: residual norm below which the fallbacks' Newton tries the regularised step where the cap
#: would shorten a Newton step (``newton_block(near_root_below=...)``); the failed
#: continuation steps of the 7014C at 0.005 N radial in -20 degC oil stood at 8e-7 to 2e-5
NEAR_ROOT_BELOW = 1e-4


# ---------------------------------------------------------------------------------------------
# Newton with block elimination
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class JacobianBlocks:
    """Structured Jacobian of the scaled residual in the scaled unknowns.

    A (Z, 6, 6) ball blocks, B (Z, 6, 3) ball rows / global columns, C (Z, 3, 6) global
    rows / ball columns, Dg (3, 3); with the scales it was taken at (F_s, xs, gs) so that a
    later solve can reuse it as a chord Jacobian (:meth:`rescaled`). ``factors``: the
    block-elimination factors (A^-1, A^-1 B, C, S^-1) once a solve has computed them
    (:func:`block_factors`; empty before), kept with the blocks so that a warm start that
    hands them over does not factorise them again (the arrays are never modified).
    """

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    Dg: np.ndarray
    F_s: float
    xs: np.ndarray
    gs: np.ndarray
    Z: int
    factors: list = field(default_factory=list, compare=False, repr=False)

    def rescaled(self, system: ball_residual_system) -> JacobianBlocks:
        """The same physical Jacobian in the scaling of ``system``.

        Every residual row is divided by a multiple of F_s (forces F_s, moments F_s D/2,
        cage torque F_s d_m/2) and column c is multiplied by the unknown's scale, so
        J_new = J_old (F_s,old / F_s,new) (scale_new / scale_old) column by column. Factors
        already computed are rescaled with it (:func:`_rescale_factors`: equal to a new
        factorisation of the rescaled blocks to round-off).
        """
        xs, gs = system.scales()
        f = self.F_s / system.F_s
        if self.factors:
            Ainv, AiB, _, Sinv = self.factors[0]
            A, B, C, Dg, Ainv, AiB, Sinv = _rescale_factors(self.A, self.B, self.C, self.Dg,
                                                            Ainv, AiB, Sinv, f, xs, self.xs,
                                                            gs, self.gs)
            return JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, self.Z,
                                  [(Ainv, AiB, C, Sinv)])
        A, B, C, Dg = _rescale_blocks(self.A, self.B, self.C, self.Dg, f, xs, self.xs, gs,
                                      self.gs)
        return JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, self.Z)


def block_factors(blocks: JacobianBlocks) -> tuple | None:
    """(A^-1, A^-1 B, C, S^-1) of ``blocks`` for the block-elimination step
    (:func:`_factor_blocks`, :func:`_inverse_small`), computed once and kept on the blocks;
    None when a ball block or the Schur complement S is singular for Gauss-Jordan (the
    callers then report the ball block, or invert S otherwise)."""
    if blocks.factors:
        return blocks.factors[0]
    C = np.ascontiguousarray(blocks.C)
    Ainv, Ainv_B, S, ok = _factor_blocks(np.ascontiguousarray(blocks.A),
                                         np.ascontiguousarray(blocks.B), C,
                                         np.ascontiguousarray(blocks.Dg))
    if not ok:
        return None
    Sinv, ok = _inverse_small(S)
    if not ok:
        return None
    out = (Ainv, Ainv_B, C, Sinv)
    blocks.factors.append(out)
    return out


def _run_chord_phase(system, kargs, jac, X, G, R, Gc, Gk, nrm, hist, m, it, *, tol,
                     polish_ratio, polish_below, keep_ratio, refresh_rate, max_iter, give_up,
                     nrm0, last_ratio, polished):
    """:func:`_chord_phase` with the torque model (:func:`_torque_model`) fitted to the Python
    models' exact values at omega_c0 and omega_c0 + h (h = 1e-3 omega_c0; the churning torque
    and the drag term as powers of omega_c when both values have one sign, else linear; the
    guide torque linear), used within +-10 % of omega_c0, and the exact torques put back at
    the returned state (its residual and norm are then those of
    :meth:`ball_residual_system.evaluate`, and it becomes the system's last state). For the
    default models (paper 002 eqs. 5, 10, 12-15) the model is exact within one flow regime
    to round-off; for others, or across a regime change, the exact residual at the end is
    larger than the phase's and the Python loop goes on from there. The model is kept on the
    system (``_torque_fit``, shared with its ``reloaded`` copies) and reused while omega_c0 is
    within 5 % of the centre it was fitted at."""
    wc0 = float(G[2])
    held = system._torque_fit
    if held and abs(wc0 - held[0]) <= 0.05 * abs(held[0]):
        # the model of an earlier solve of this system (the same models and speed: a warm
        # start's system shares it, see ``reloaded``), centred within 5 % of wc0: exact for
        # the default models within a flow regime, so refitting would give the same model
        # (saves a Python torque evaluation per warm start)
        tq = held[1].copy()
        tq[8] = system.T_s
    else:
        h = 1e-3 * max(abs(wc0), 1e-3 * system.w_s)
        t0, t1 = system._cage_torques(wc0), system._cage_torques(wc0 + h)
        lr = math.log1p(h / wc0) if wc0 != 0.0 else 0.0

        def fit(a, b):
            # (value, exponent, 1.0) for a power law through both points, else (value,
            # slope, 0.0)
            if lr != 0.0 and a != 0.0 and b / a > 0.0:
                return a, math.log(b / a) / lr, 1.0
            return a, (b - a) / h, 0.0

        tc, pc, pw_c = fit(t0[0], t1[0])
        fd, pf, pw_f = fit(t0[3], t1[3])
        tq = np.array([wc0, 0.1 * abs(wc0), tc, pc, t0[1], (t1[1] - t0[1]) / h, fd, pf,
                       system.T_s, pw_c, pw_f])
        held[:] = [wc0, tq.copy()]
    give_n, give_f = give_up if give_up is not None else (-1, 0.0)
    (status, X, G, R, Gc, G0m, nrm_m, m, it, n_ev, last_ratio, polished, accepted, geo, film,
     tr, pocket, Fd) = _chord_phase(*jac, X, G, R, Gc, Gk, nrm, hist, m, *system.scales(),
                                    _CAP_X, _CAP_G, tol, polish_ratio, polish_below,
                                    keep_ratio, refresh_rate, it, max_iter, give_n, give_f,
                                    nrm0, last_ratio, polished, tq, *kargs)
    system.n_eval += n_ev
    if accepted:
        t = system._cage_torques(float(G[2]))
        R, Gk, Fd_exact, nrm = _exact_torques(R, Gc, X, Fd, t[3], system.F_s, system._g0a,
                                              system._g0r, -(t[0] + t[1]) / system.T_s)
        system.store_last(X, G, R, Gc, Gk, nrm, geo, film, tr, pocket, Fd_exact, t[4])
    return status, X, G, R, Gc, Gk, nrm, m, it, last_ratio, polished


def newton_block(system: ball_residual_system, X0: np.ndarray, G0: np.ndarray, *,
                 tol: float = 1e-9, max_iter: int = 60, fd_step: float = 1e-7,
                 max_step: float = 1.0, reuse_ratio: float = 0.25,
                 polish_ratio: float = 1e-2, give_up: tuple[int, float] | None = None,
                 jacobian: JacobianBlocks | None = None, broyden_warm: bool = True,
                 polish_below: float = 0.2e-9, broyden_reuse_ratio: float = 0.5,
                 stall_after: int = 0, analytic: bool = True, warm_refresh: float = 0.0,
                 compiled_chord: bool = True, near_root_below: float = 0.0):
    """Damped Newton on (X, G) with the structured finite-difference Jacobian.

    The Jacobian (6x6 ball blocks, ball-global couplings, 3x3 Schur complement) needs
    N_BALL + N_GLOBAL = 9 perturbed states whatever Z is; they are evaluated as one batch
    (:meth:`ball_residual_system.evaluate` on (9, Z, 6)). It is reused for the next step
    (chord / Shamanskii step) while the full step cut the residual norm below
    ``reuse_ratio`` times its previous value; a stale step that does not reduce the norm is
    discarded and the Jacobian refreshed (good-Broyden updates of the chord Jacobian were
    tried and removed: no fewer iterations on +2 % warm steps, and they stalled a Z = 32
    cold start that plain chord steps solve in 41 iterations). A solve that ends on a
    linearly converging chord step takes one more (``polish_ratio``) so that the residual, and with
    it the energy balance, ends well below ``tol``. ``give_up = (n, f)``: raise
    ConvergenceError when the residual norm is still above f times its start after n
    iterations (used for warm starts, which then restart cold). ``jacobian``: blocks of an
    earlier solve (warm start, rescaled to this system by :meth:`JacobianBlocks.rescaled`)
    used as the first chord Jacobian. The last fresh Jacobian is left in ``system.last_jacobian``.

    Warm starts (``jacobian`` given, ``broyden_warm``): while that handed-over Jacobian is in
    use, the chord steps are good-Broyden steps (:func:`_broyden_step`, Kelley's stored-step
    form; the chord iteration contracted only ~5x per step on +2 % load steps) and are kept
    while each cuts the norm below ``broyden_reuse_ratio`` (0.5, measured on the BM-5 quick
    map: 0.25 -> 0.5 saved 11 % of the evaluations of the +2 % steps in cold oil, 0.7 lost
    some again); a fresh Jacobian ends the Broyden phase. The polishing step is skipped
    when the norm is already below ``polish_below`` (the energy balance closes to ~1e-9).

    ``fd_step``: forward-difference step in scaled unknowns (1e-7; formerly 1e-6). With
    1e-6 some states got a Jacobian poor enough that Newton with a fresh Jacobian at every
    iterate converged only linearly (ratio 0.55: QJ1044, Z = 16, 600 r/min, 1 kN, hot oil),
    and the Z = 32 hot-oil cold starts at 300 r/min, 200 N and 0 N needed a load continuation
    that ended at the 150-iteration limit (one of them failed); with 1e-7 (and 1e-8) those
    converge quadratically, the 120 cold starts of the BM-5 5 x 5 maps (Z = 8, 16, 32, cold and
    hot oil) all converge without continuation, with 3-9 % fewer evaluations at Z = 8/16.

    ``stall_after``: raise ConvergenceError after that many consecutive damped steps shorter
    than 1e-2 of the Newton step that each lower a norm already below 1e-2 by less than 1 %
    (0: never; :func:`~thermobearing.skidding.ball.solve_ball` uses 25 for cold starts and
    then calls :func:`trust_region`; 8 cut two slow cold starts of the BM-5 maps that converge
    in 33 iterations, and 16 was the least that kept them). Every ConvergenceError for too
    many iterations, a failed line search or a stall carries the last iterate as
    ``err.iterate = (X, G, norm)``.

    ``analytic``: a fresh Jacobian is the analytic one of
    :func:`~thermobearing.skidding.ball_jacobian.analytic_blocks` (forward-mode derivatives
    through the compiled residual; about 2-3 residual evaluations of CPU instead of the
    batch of nine perturbed states) when the system's models have it, else the finite
    differences. Counted in ``system.n_jac``, not in ``n_eval``.

    ``warm_refresh`` (warm starts with the analytic Jacobian): after an accepted
    chord / Broyden step with contraction rho = |F_new| / |F_old|, the steps still needed at
    that rate are log(polish_below / |F_new|) / log(rho); when that exceeds ``warm_refresh``
    the handed-over Jacobian is dropped and an analytic one taken at the current iterate
    (Newton then converges in 1-2 evaluations). 0 disables it (the default of
    :func:`~thermobearing.skidding.ball.solve_ball`). Measured on the BM-5 maps (Z = 16, +2 %
    steps): it saves evaluations (5 x 5 map, a Jacobian counted as 2.3 evaluations: off 6.5 /
    6.35, 4: 6.1 / 5.9 cold / hot oil) but not CPU -- interleaved in one process, 4 cost 6-12 %
    more than off on the 20 x 20 map (1.24 / 1.02 against 1.11 / 0.93 ms) and 3-6 % more on the
    5 x 5 map: a refresh costs more than its 2-2.2 evaluations of kernel time (the Newton step
    after it and the torque models run outside the compiled chord loop).

    ``near_root_below`` (0: off; the fallbacks of :func:`~thermobearing.skidding.ball.
    solve_ball` use :data:`NEAR_ROOT_BELOW`): where the residual norm is below it and the
    per-unknown cap (``_CAP_X``, ``_CAP_G``) would shorten a fresh-Jacobian Newton step, the
    regularised step of :func:`~thermobearing.skidding.ball_damped_step.regularised_step` is
    tried first and kept if it at least halves the norm (else the capped line search as
    before). The cap protects cold starts from wild steps far from a root; close to one it
    throttled every step when unknowns the residual barely depends on asked for a large move
    (the spins of balls held by centrifugal contacts of ~1e-8 N when the cage nearly stops:
    see that module).

    Returns (X, G, residual_norm, iterations). Raises ConvergenceError.
    """
    xs, gs = system.scales()
    Z = system.Z
    X, G = X0.copy(), G0.copy()
    nb = N_BALL + N_GLOBAL
    norm_of = _residual_norm

    def jacobian_fd(X, G, R, Gc, Gk):
        blocks = analytic_blocks(system, X, G) if analytic else None
        if blocks is not None:
            system.n_jac += 1
            system.last_jacobian = blocks
            return factor(blocks, R, Gc, Gk, G)
        eye_x = np.zeros((N_BALL, 1, N_BALL))
        eye_x[np.arange(N_BALL), 0, np.arange(N_BALL)] = fd_step * xs
        eye_g = np.zeros((nb, N_GLOBAL))
        eye_g[N_BALL + np.arange(N_GLOBAL), np.arange(N_GLOBAL)] = fd_step * gs
        Xb = np.empty((nb, Z, N_BALL))
        Xb[:] = X
        Xb[:N_BALL] += eye_x
        Gb = G + eye_g
        Rb, Gcb, Gkb, _ = system.evaluate(Xb, Gb)
        A, B, C, Dg = _fd_blocks(Rb, Gcb, Gkb, R, Gc, Gk, fd_step)
        blocks = JacobianBlocks(A, B, C, Dg, system.F_s, xs, gs, Z)
        system.last_jacobian = blocks
        return factor(blocks, R, Gc, Gk, G)

    def factor(blocks, R, Gc, Gk, G):
        got = block_factors(blocks)
        if got is not None:
            return got
        C = np.ascontiguousarray(blocks.C)
        Ainv, Ainv_B, S, ok = _factor_blocks(np.ascontiguousarray(blocks.A),
                                             np.ascontiguousarray(blocks.B), C,
                                             np.ascontiguousarray(blocks.Dg))
        if not ok:
            raise ConvergenceError("skidding.ball", norm_of(R, Gc, Gk), "singular ball block",
                                   {"cage_speed": G[2]})
        try:
            Sinv = np.linalg.inv(S)
        except np.linalg.LinAlgError:
            Sinv = np.linalg.pinv(S)   # least-squares step of a singular Schur complement
        return Ainv, Ainv_B, C, np.ascontiguousarray(Sinv)

    can_analytic = analytic and supports_analytic(system)
    R, Gc, Gk, _ = system.evaluate(X, G)
    nrm = norm_of(R, Gc, Gk)
    it = 0
    jac = None
    if jacobian is not None and jacobian.Z == Z:
        system.last_jacobian = jacobian.rescaled(system)
        if nrm > tol:
            try:
                jac = factor(system.last_jacobian, R, Gc, Gk, G)
            except ConvergenceError:
                jac = None
    last_ratio, polished, nrm0 = 1.0, False, nrm
    crawl = 0
    # Broyden (good) updates of the warm start's chord Jacobian, in Kelley's stored-step
    # form: only while the Jacobian handed over from the previous solve is in use
    broyden = jac is not None and broyden_warm
    hist = np.empty((max_iter + 1, Z * N_BALL + N_GLOBAL)) if broyden else None
    m = 0                                     # steps in the Broyden history
    kargs = system.chord_kernel_args() if (broyden and compiled_chord) else None
    phases = 0
    last_good = None                          # last factorised Jacobian (singular fallback)
    while it < max_iter:
        if kargs is not None and broyden and jac is not None and phases < 2:
            # the chord / Broyden steps in one compiled loop (same rules; hands back to
            # this loop for anything else)
            phases += 1
            status, X, G, R, Gc, Gk, nrm, m, it, last_ratio, polished = _run_chord_phase(
                system, kargs, jac, X, G, R, Gc, Gk, nrm, hist, m, it, tol=tol,
                polish_ratio=polish_ratio, polish_below=polish_below,
                keep_ratio=broyden_reuse_ratio,
                refresh_rate=warm_refresh if can_analytic else 0.0, max_iter=max_iter,
                give_up=give_up, nrm0=nrm0, last_ratio=last_ratio, polished=polished)
            if status == _PH_REFRESH:
                jac = None
        if nrm <= tol:
            # a chord iteration converges linearly and stops just below tol,
            # where a Newton step would overshoot by orders of magnitude: one more step
            # with the current Jacobian (the energy balance closes with the residual)
            if polished or last_ratio < polish_ratio or jac is None or nrm <= polish_below:
                break
            polished = True
        if give_up is not None and it >= give_up[0] and nrm > give_up[1] * nrm0:
            err = ConvergenceError("skidding.ball", nrm, f"slow progress: residual still "
                                   f"{nrm / nrm0:.2f} x its start after {it} iterations",
                                   {"iteration": it, "cage_speed": G[2]})
            err.iterate = (X, G, nrm)     # for ball_seat.seated_newton (warm starts)
            raise err
        it += 1
        stale = jac is not None
        if jac is None:
            try:
                jac = jacobian_fd(X, G, R, Gc, Gk)
            except ConvergenceError as err:
                # a singular ball block at this iterate (property tests: SKF6304
                # at 100 r/min, 5 kN -- a ball of the unloaded zone, held by a centrifugal
                # contact of ~1e-3 N, loses it along the step): damped steps with the last
                # good factorisation; else hand the iterate to the caller's fallbacks
                err.iterate = (X, G, nrm)
                if last_good is None:
                    raise
                jac = last_good
            broyden = False
        last_good = jac
        dX, dG, big, Xf, Gf, degenerate = _propose(
            *jac, R, Gc, Gk, _CAP_X, _CAP_G, hist if broyden else _NO_HIST,
            m if broyden else 0, xs, gs, X, G)
        if degenerate:                    # degenerate update: plain chord step, new history
            m = 0
        lam = min(1.0, max_step / big) if big > 0 else 1.0
        if stale:
            # chord step: full step only (a step the cap would shorten refreshes
            # the Jacobian: measured, capped chord steps can stall a cold start), accepted
            # if it reduces the norm, else discarded and the Jacobian refreshed
            ok, nn = False, math.inf
            if lam == 1.0:
                try:
                    Rn, Gcn, Gkn, _ = system.evaluate(Xf, Gf)
                    nn = _residual_norm(Rn, Gcn, Gkn)
                    ok = math.isfinite(nn) and nn < nrm
                except (InputError, FloatingPointError, ValueError):
                    ok = False
            if ok:
                X, G, R, Gc, Gk = Xf, Gf, Rn, Gcn, Gkn
                if nn > (broyden_reuse_ratio if broyden else reuse_ratio) * nrm:
                    jac = None
                elif broyden and m < hist.shape[0]:
                    hist[m, :Z * N_BALL] = dX.ravel()
                    hist[m, Z * N_BALL:] = dG
                    m += 1
                if (broyden and warm_refresh and can_analytic and jac is not None
                        and nn > polish_below and 0.0 < nn < nrm
                        and math.log(polish_below / nn) < warm_refresh * math.log(nn / nrm)):
                    # the chord / Broyden steps at this contraction rate would need more than
                    # ``warm_refresh`` further evaluations: a fresh analytic Jacobian here
                    jac = None
                nrm, last_ratio = nn, nn / nrm
            else:
                jac = None
                it -= 1
            continue
        if lam < 1.0 and nrm < near_root_below and system.last_jacobian is not None:
            # close to a root: the regularised step if the cap is all that shortens it
            try:
                rX, rG = regularised_step(system.last_jacobian, R, Gc, Gk)
                Xr, Gr = X + rX * xs, G + rG * gs
                Rn, Gcn, Gkn, _ = system.evaluate(Xr, Gr)
                nn = norm_of(Rn, Gcn, Gkn)
            except (InputError, FloatingPointError, ValueError, np.linalg.LinAlgError):
                nn = math.inf
            if math.isfinite(nn) and nn <= 0.5 * nrm:
                X, G, R, Gc, Gk, nrm, last_ratio = Xr, Gr, Rn, Gcn, Gkn, nn, nn / nrm
                jac, crawl = None, 0
                continue
        while True:
            Xn = X + lam * dX * xs
            Gn = G + lam * dG * gs
            ok = True
            try:
                Rn, Gcn, Gkn, _ = system.evaluate(Xn, Gn)
                nn = norm_of(Rn, Gcn, Gkn)
                ok = math.isfinite(nn)
            except (InputError, FloatingPointError, ValueError):
                ok, nn = False, np.inf
            if ok and (nn < (1 - 1e-4 * lam) * nrm or lam < 1e-3):
                break
            lam *= 0.5
            if lam < 1e-6:
                break
        if not ok or lam < 1e-6:
            err = ConvergenceError("skidding.ball", nrm, "line search failed",
                                   {"iteration": it, "cage_speed": G[2]})
            err.iterate = (X, G, nrm)
            raise err
        if not (lam == 1.0 and nn < reuse_ratio * nrm):
            jac = None
        # stall close to a root: short damped steps that gain < 1 % each (measured at the
        # fallback point of :func:`trust_region`: 140 such iterations at 1.9e-3)
        crawl = crawl + 1 if (lam < 1e-2 and nn > 0.99 * nrm and nn < 1e-2) else 0
        X, G, R, Gc, Gk, nrm, last_ratio = Xn, Gn, Rn, Gcn, Gkn, nn, nn / nrm
        if stall_after and crawl >= stall_after:
            err = ConvergenceError("skidding.ball", nrm, f"stalled: {crawl} damped steps "
                                   "below 1e-2 of the Newton step, each gaining < 1 %",
                                   {"iteration": it, "cage_speed": G[2]})
            err.iterate = (X, G, nrm)
            raise err
    if not nrm <= tol:
        err = ConvergenceError("skidding.ball", nrm, f"no convergence in {max_iter} iterations",
                               {"cage_speed": G[2], "delta_a": G[0], "delta_r": G[1]})
        err.iterate = (X, G, nrm)       # the last iterate, for a fallback (solve_ball)
        raise err
    return X, G, nrm, it


def trust_region(system: ball_residual_system, X: np.ndarray, G: np.ndarray, *,
                 tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray, float, int]:
    """Powell's hybrid method (dogleg trust region with Broyden updates of a finite-difference
    Jacobian; MINPACK ``hybrd`` through :func:`scipy.optimize.root`, method "hybr") on the
    same scaled residual, from (X, G): the fallback of :func:`~thermobearing.skidding.ball.
    solve_ball` when the damped Newton of :func:`newton_block` stalls close to a root.

    Measured: at QJ1044 with Z = 16, 30 degC oil, 3000 r/min, Fa = 15.7 kN,
    Fr = 1 kN (a BM-5 20 x 20 map point) the damped Newton stalls at a scaled residual of
    1.9e-3 (the line search accepts steps of ~1e-3 of the Newton step: the finite-difference
    ball blocks of the balls near psi = 180 deg change by up to 44 % between steps 1e-6 and
    1e-7 in the spin columns, so the Newton direction is poor there), while hybr from the
    stalled iterate reaches 5e-12 in 663 evaluations with the ball unknowns practically
    unchanged. The cause is the model, not a bug: at those balls' 1.05-GPa contacts
    eta(p0)/h = 1.6e12 Pa s/m, so the Eyring stress saturates (tau0 = 5 MPa) within ~3 um/s
    of slip, and a quadrature node near the zero-slip line puts an asinh knee of that width
    into the residual (a spin step of 1e-7 scaled moves the slip by ~0.5 um/s). Returns
    (X, G, residual norm, evaluations); raises ConvergenceError when the result is not below
    ``tol`` (in this solver's norm)."""
    from scipy.optimize import root

    n = system.Z * N_BALL + N_GLOBAL

    def f(y):
        return system.full_residual(y, X, G)

    try:
        sol = root(f, np.zeros(n), method="hybr", options={"xtol": 1e-13, "maxfev": 100 * n})
        Xn, Gn = system.unscale(sol.x, X, G)
        R, Gc, Gk, _ = system.evaluate(Xn, Gn)
        nrm = _residual_norm(R, Gc, Gk)
    except (InputError, FloatingPointError, ValueError):
        nrm, sol = math.inf, None
    if not nrm <= tol:
        raise ConvergenceError("skidding.ball", nrm, "trust-region fallback (hybr) did not "
                               "reach the tolerance", {"cage_speed": G[2]})
    return Xn, Gn, nrm, int(sol.nfev)


def chord_polish(system: ball_residual_system, X: np.ndarray, G: np.ndarray,
                 blocks: JacobianBlocks) -> tuple[np.ndarray, np.ndarray, float, bool]:
    """One more chord step from a converged state (X, G) with the Jacobian ``blocks`` (at
    the scaling of ``system``): returns (X, G, residual norm, taken); the step is taken only
    when it lowers the scaled residual norm. Used by :func:`~thermobearing.skidding.ball.
    solve_ball` when the energy identity of a converged state is not yet tight enough."""
    R, Gc, Gk, _ = system.evaluate(X, G)
    nrm = _residual_norm(R, Gc, Gk)
    if blocks is None or blocks.Z != system.Z:
        return X, G, nrm, False
    got = block_factors(blocks)
    if got is None:
        return X, G, nrm, False
    Ainv, Ainv_B, C, Sinv = got
    xs, gs = system.scales()
    _, _, _, Xn, Gn, _ = _propose(Ainv, Ainv_B, C, Sinv, R, Gc, Gk,
                                  _CAP_X, _CAP_G, _NO_HIST, 0, xs, gs, X, G)
    try:
        Rn, Gcn, Gkn, _ = system.evaluate(Xn, Gn)
    except (InputError, FloatingPointError, ValueError):
        return X, G, nrm, False
    nn = _residual_norm(Rn, Gcn, Gkn)
    if math.isfinite(nn) and nn < nrm:
        return Xn, Gn, nn, True
    system.evaluate(X, G)          # the returned state is again the last one evaluated
    return X, G, nrm, False


_refresh_caches()
