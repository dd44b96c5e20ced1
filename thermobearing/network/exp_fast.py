"""Compiled step path of ``exprb43`` for small dense networks (the BM-1 case).

Same method, formulas and energy audit as
:class:`thermobearing.network.exponential.ExpRosenbrock43` (Hochbruck, Ostermann &
Schweitzer 2009, method exprb43; see the module docstring of :mod:`.exponential` for the
stage equations, the error estimate ``6 h phi4(h A) a3`` and the discrete energy balance),
and the same step-size control except after a rejection (:func:`run_segment`), with the
per-step work reorganised so that a 4-node step costs a few microseconds of compiled code
around the (Python) heat-source calls:

- **one compiled kernel per stage** (linearisation + stage 2; stage 3; completion +
  error estimate + energy-audit terms + dense-output coefficients), the stages computed
  in the eigenbasis (forcing projected once, one phi table per step) and the stage data
  kept in per-run workspaces, instead of ~60 small numpy operations per step;
- **symmetric linear part**: when K is symmetric (no oil stream through more than one
  node) and dq/dT is diagonal, ``A = C^-1 J`` is similar to the symmetric
  ``S = C^-1/2 J C^-1/2`` (Golub & Van Loan 2013, sec. 8.7, the symmetric-definite
  problem ``J x = lambda C x``), so ``A = V diag(lambda) V^-1`` with ``V = C^-1/2 Q`` and
  ``V^-1 = Q^T C^1/2`` from ``S = Q diag(lambda) Q^T`` (cyclic Jacobi up to 12 nodes,
  LAPACK ``eigh`` above): real arithmetic, an orthogonal basis (never defective), no
  inverse and no condition check. Otherwise the general eigendecomposition of
  :mod:`.exponential` (real or complex; near-defective bases refused);
- **fewer heat calls**: the step-end heat q(y_{n+1}) is the next step's q_n, and with
  ``heat_with_jacobian`` (``(t, T) -> (q, dq/dT)`` in one call) the step start needs one
  call for both. The last step of a segment (ending at a breakpoint, where the source
  jumps) calls no step-end heat at all: the rate recorded there is the derivative of the
  step's own continuous solution, ``C y'(h) = f_n + J (y_{n+1} - y_n) + G(h)``;
- **dense output stored in flat arrays** (eigenvalues, eigenvectors and the projected
  forcing ``M = V^-1 C^-1 [c_0 .. c_3]`` per step), evaluated for any number of sample
  times in one compiled call.

The compiled kernels are in :mod:`.exp_kernels`; this module holds the Python segment loop
(step-size control, restarts at breakpoints, recording) and the dense-output store.

Applies when the network is dense (<= ``assemble.DENSE_LIMIT`` nodes), has no
zero-capacity nodes and the steps are adaptive; the general path in :mod:`.exponential`
handles the rest. Temperature-dependent conductances (e.g. air convection) are assembled
at each step start, held in the linear part over the step, and their drift enters the
stage remainders, exactly as the general path does (:meth:`.assemble.Assembler.drift`). Units:
times [s], temperatures [K], heat [W], conductances [W/K], capacities [J/K], energies [J].
"""

from __future__ import annotations

import math

import numpy as np

from .exp_kernels import (  # noqa: F401  (_jacobi_eigh: re-exported for tests and users)
    _fk_dense,
    _jacobi_eigh,
    _project,
    _ws_finish,
    _ws_stage2,
    _ws_stage3,
    _ws_start_sym,
)
from .exponential import _drift_booking, _nb_scaled_jacobian, diagonalise_or_refuse
from .stepper_core import _NewtonFailure, stage_drift
from .steppers import STEP_UNDERFLOW, clip_step, stepper_failure


# ------------------------------------------------------------ dense output store
class DenseStore:
    """Per-run arrays of the dense output: step start t0 [s], size h [s], start state y0 [K],
    eigenvalues [1/s], eigenvectors and projected forcing [K/s] (real for a symmetric
    network, else complex; :meth:`make_complex` converts when a complex spectrum appears).
    Grown by doubling."""

    __slots__ = ("count", "t0", "h", "y0", "lam", "V", "M")

    def __init__(self, n: int, real: bool = False, capacity: int = 64) -> None:
        dt = float if real else complex
        self.count = 0
        self.t0 = np.empty(capacity)
        self.h = np.empty(capacity)
        self.y0 = np.empty((capacity, n))
        self.lam = np.zeros((capacity, n), dtype=dt)
        self.V = np.zeros((capacity, n, n), dtype=dt)
        self.M = np.zeros((capacity, n, 4), dtype=dt)

    def make_complex(self) -> None:
        """Switch the spectral arrays to complex (values kept)."""
        for name in ("lam", "V", "M"):
            setattr(self, name, getattr(self, name).astype(complex))

    def reserve(self) -> int:
        """Index of the next row (grown if full)."""
        j = self.count
        if j == len(self.t0):
            for name in ("t0", "h", "y0", "lam", "V", "M"):
                a = getattr(self, name)
                setattr(self, name, np.concatenate([a, np.empty_like(a)]))
        return j


class StorePiece:
    """Dense output of one step of the compiled exprb43 path on [t0, t0 + h]."""

    __slots__ = ("store", "j", "t0", "h")

    def __init__(self, store: DenseStore, j: int, t0: float, h: float) -> None:
        self.store, self.j, self.t0, self.h = store, j, t0, h

    @property
    def y0(self) -> np.ndarray:
        return self.store.y0[self.j]

    def __call__(self, t: np.ndarray) -> np.ndarray:
        """Temperatures [K] at times t (within the step), shape (len(t), n)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        st = self.store
        return _fk_dense(st.lam, st.V, st.M, st.y0, st.t0, st.h,
                         np.full(len(t), self.j, dtype=np.int64), t)

    @staticmethod
    def sample_batch(pieces: tuple, t: np.ndarray) -> np.ndarray:
        """Temperatures [K] at times t from a run's pieces in one compiled call."""
        store = pieces[0].store if type(pieces[0]) is StorePiece else None
        if (store is not None and store.count == len(pieces) and pieces[-1].j == store.count - 1
                and all(type(p) is StorePiece and p.store is store for p in pieces)):
            # the pieces are the store's rows 0..count-1 in time order (one run)
            starts = store.t0[:store.count]
            k = np.searchsorted(starts, t, side="right") - 1
            np.clip(k, 0, store.count - 1, out=k)
            return _fk_dense(store.lam, store.V, store.M, store.y0, store.t0, store.h, k, t)
        starts = np.array([p.t0 for p in pieces])
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(starts) - 1)
        out = np.empty((len(t), len(pieces[0].y0)))
        for j in np.unique(k):
            sel = k == j
            out[sel] = pieces[j](t[sel])
        return out


# ------------------------------------------------------------ the segment loop
def applies(driver) -> bool:
    """Whether the compiled path can run this driver's network (see the module docstring)."""
    core = driver.core
    return driver.dt is None and core.sys.dense and not core.has_alg and core.n > 0


def _general_start(core, K, jq, y0, q0):
    """Step start on a non-symmetric network (or a full dq/dT): the general
    eigendecomposition of exponential.py (real, else complex; defective bases refused)."""
    if not (math.isfinite(q0.sum()) and math.isfinite(jq.sum())):
        return (False, *(None,) * 6)
    JqM = np.diag(jq) if jq.ndim == 1 else np.ascontiguousarray(jq)
    A = _nb_scaled_jacobian(K - JqM, core.invC)
    if not math.isfinite(A.sum()):
        raise _NewtonFailure(math.inf, "non-finite Jacobian")
    lam, V, W = diagonalise_or_refuse(A, np.zeros((0, 0)), core.invC, False)
    f0 = core.sys.s - K @ y0 + q0
    wf = _project(W, f0)
    return True, lam, V, W, JqM, f0, wf


class _Context:
    """Per-build constants of the compiled path (a driver's network at one revision)."""

    __slots__ = ("sym", "rs", "flow", "flow0", "zeros", "empty", "empty_rows", "ws")

    @classmethod
    def of(cls, asm, sys_, C: np.ndarray) -> _Context:
        """A context with fresh workspaces; the constant parts are computed once per
        assembler (i.e. per network revision) and shared (read-only)."""
        base = getattr(asm, "_exp_fast_context", None)
        if base is None or base.flow.shape[1] != len(C):
            base = cls(sys_, C)
            asm._exp_fast_context = base
            return base
        ctx = cls.__new__(cls)
        for name in ("sym", "rs", "flow", "flow0", "zeros", "empty", "empty_rows"):
            setattr(ctx, name, getattr(base, name))
        ctx.ws = cls._workspaces(len(C))
        return ctx

    @staticmethod
    def _workspaces(n: int) -> dict:
        """Stage workspaces (see _ws_start_sym), real and complex."""
        return {dt: (np.zeros((n, 2 * n + 3), dtype=dt), np.zeros((n, n)),
                     np.zeros((6, n)), np.zeros((n, 6), dtype=dt))
                for dt in (float, complex)}

    def __init__(self, sys_, C: np.ndarray) -> None:
        n = len(C)
        K = sys_.K
        # (temperature-dependent edges are stamped symmetrically or onto the diagonal, so
        # the symmetry of K does not depend on the temperatures it was assembled at)
        self.sym = bool(np.array_equal(K, K.T))
        self.rs = 1.0 / np.sqrt(C)  # C^-1/2 [(J/K)^-1/2]
        self.flow, self.flow0 = _flows(sys_, n)
        self.zeros = np.zeros(n)
        self.empty = (np.zeros((0, n)), np.zeros((0, n, n)), np.zeros((0, n, 4)))
        self.empty_rows = (np.zeros(0), np.zeros(0), np.zeros((0, n)))
        self.ws = self._workspaces(n)


def _flows(sys_, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The energy audit's linear forms of an assembled system: the heat rates to the
    boundaries and to the streams are sum G_b (T_i - T_b) = flow[0] T - flow0[0] and
    sum W (T_last - T_in) = flow[1] T - flow0[1] [W]."""
    flow = np.empty((2, n))
    flow[0] = np.bincount(sys_.bnd_index, weights=sys_.bnd_G, minlength=n)
    flow[1] = np.bincount(sys_.str_last, weights=sys_.str_W, minlength=n)
    flow0 = np.array([float(sys_.bnd_G @ sys_.bnd_T), float(sys_.str_W @ sys_.str_Tin)])
    return flow, flow0


def _with_drift_jacobian(jq: np.ndarray, D: np.ndarray) -> np.ndarray:
    """dq/dT plus the conductances' own derivatives D (``Assembler.drift_jacobian``):
    diagonal (n,) when both are (boundary edges only), else the full (n, n) matrix."""
    off = D.copy()
    np.fill_diagonal(off, 0.0)
    if jq.ndim == 1 and not off.any():
        return jq + np.diagonal(D)
    return (np.diag(jq) if jq.ndim == 1 else jq) + D


def _start_values(driver, heat, heat_jacobian, heat_with_jacobian, t, tt, T, n, zeros):
    """(q [W], dq/dT [W/K], heat evaluations) at a step start; dq/dT (n,) or (n, n).
    Finiteness of both is checked by the step-start kernels (``ok`` of _fk_start_sym)."""
    core = driver.core
    if heat is None:
        return zeros, zeros, 0
    if heat_with_jacobian is not None:
        r, jq = heat_with_jacobian(tt, T)
        calls = 1
    else:
        r = heat(tt, T)
        calls = 1
        if core.jacobian_mode == "none":
            jq = zeros
        elif heat_jacobian is not None:
            jq = heat_jacobian(tt, T)
        else:
            if type(r) is not np.ndarray or r.shape != (n,):
                r = driver.network.heat_vector(r)
            core.refresh_jacobian(t, T, r)  # finite differences (counts its own calls)
            core.stats["jacobians"] -= 1  # counted by the caller
            jq = core.Jq if core.Jq is not None else zeros
    if type(r) is not np.ndarray or r.shape != (n,):
        r = driver.network.heat_vector(r)
    if type(jq) is not np.ndarray or jq.dtype != np.float64:
        jq = np.asarray(jq, dtype=float)
    if jq.shape not in ((n,), (n, n)):  # (finiteness: checked by the step-start kernels)
        from ..errors import InputError

        raise InputError("heat_jacobian", jq.shape,
                         f"a finite ({n},) diagonal or ({n}, {n}) matrix")
    return r, jq, calls


def _fail(driver, exc, t, h, y):
    """:func:`.steppers.stepper_failure` of a Newton failure ``exc`` at time t, step h."""
    return stepper_failure(driver.method_name, exc.residual, exc.reason, t, h, y)


def run_segment(driver, t0: float, t1: float, y0: np.ndarray, heat, heat_jacobian,
                heat_with_jacobian, rec, td: bool) -> np.ndarray:
    """One smooth segment [t0, t1]: :func:`run_segments` with two edges."""
    return run_segments(driver, (t0, t1), y0, heat, heat_jacobian, heat_with_jacobian, rec,
                        td)


def run_segments(driver, edges, y0: np.ndarray, heat, heat_jacobian, heat_with_jacobian,
                 rec, td: bool) -> np.ndarray:
    """Integrate over consecutive smooth segments [edges[k], edges[k+1]] (restarting at
    each edge: q is re-evaluated there, a step never crosses one) with the compiled exprb43
    path; returns the state at edges[-1]; records into ``rec`` like the generic driver loop
    (steppers._Driver.segment), whose per-segment set-up is done here once per run.

    Step-size control as in the generic loop (first trial step the whole segment, capped
    at 4x the last segment's first step; growth min(5, max(0.2, 0.9 err^-1/4)) outside
    [1, 1.2]) except after a rejection: the error estimate e ~ h^4 holds only in the
    asymptotic range, and a trial step that spans the fast transient after a load step is
    far outside it (measured on BM-1: cutting 180 s -> 77 s lowered the estimate only from
    19 to 14, an apparent order ~0.4). So the first rejection assumes order 1
    (fac = max(0.1, min(0.9 e^-1/4, 0.9 / e))), and a further rejection from the same
    start uses the order the last two estimates showed, p = log(e_prev/e)/log(h_prev/h)
    clipped to [1, 4] (fac = min(1/2, max(0.1, 0.9 e^-1/p))). BM-1, 4 nodes: 31 + 4
    rejected steps at rtol 3e-4 instead of 31 + 7 (heat calls 101 instead of 107).
    """
    if driver.network._revision != driver.asm.revision:
        driver._build()
    core = driver.core
    core.time_dependent = td
    core.set_heat(heat, heat_jacobian)
    n = core.n
    # temperature-dependent conductances: K(T) and s(T) are assembled at each step start
    # and held in the linear part over the step, as the generic driver does
    # (core.update_system); their drift enters the stage remainders (Assembler.drift)
    tdep = core.asm.temperature_dependent
    if tdep:
        core.update_system(y0)
    sys_ = core.sys
    K, s, C = sys_.K, sys_.s, core.C
    stats = core.stats
    ctx = driver.fast_info
    if ctx is None:
        ctx = driver.fast_info = _Context.of(driver.asm, sys_, C)
    sym, rs, flow, flow0, zeros = ctx.sym, ctx.rs, ctx.flow, ctx.flow0, ctx.zeros
    dcol = zeros  # column sums of the conductances' Jacobian part (see _with_drift_jacobian)
    if heat is not None and heat_with_jacobian is None and heat_jacobian is None \
            and core.jacobian_mode not in ("none", "fd", "fd_diagonal"):
        from ..errors import InputError

        raise InputError("jacobian", core.jacobian_mode, "'fd', 'fd_diagonal' or 'none'")
    atol, rtol = core.atol, core.rtol
    store = None
    if rec.active:
        store = rec.fast_store
        if store is None or store.y0.shape[1] != n:
            store = rec.fast_store = DenseStore(n, real=sym)
    s_lam, s_V, s_M = ctx.empty
    s_t0, s_h, s_y0 = ctx.empty_rows
    n_heat = 0
    n_jac = 0
    facmax, max_step, min_step = driver.facmax, driver.max_step, driver.min_step
    accepted = rejected = failures = 0
    shp = (n,)
    ws_real = ctx.ws[float]
    Bw, Jw, vw, tw = ws_real
    hwj = heat_with_jacobian if heat is not None else None
    if store is not None:
        s_lam, s_V, s_M = store.lam, store.V, store.M
        s_t0, s_h, s_y0 = store.t0, store.h, store.y0
    net = driver.network
    y = y0
    try:
        for k_seg in range(len(edges) - 1):
            t0, t1 = edges[k_seg], edges[k_seg + 1]
            if k_seg and net._revision != driver.asm.revision:
                # the network was edited during the run (by the heat function): the generic
                # driver rebuilds and re-enters, one segment at a time
                for a, b in zip(edges[k_seg:-1], edges[k_seg + 1:], strict=True):
                    y = driver.segment(a, b, y, heat, heat_jacobian, rec, td, heat_with_jacobian)
                return y
            core.t_end = t1
            t_left = core.t_end_left = math.nextafter(t1, -math.inf)  # seen from the left
            try:
                q0, jq, calls = _start_values(driver, heat, heat_jacobian, heat_with_jacobian,
                                              t0, t0, y, n, zeros)
            except _NewtonFailure as exc:
                raise _fail(driver, exc, t0, 0.0, y) from None
            n_heat += calls
            n_jac += 1
            t = t0
            if driver.first_step is not None:
                h = min(driver.first_step, t1 - t0)
            else:
                h = min(t1 - t0, max_step)
                if driver.h_first is not None:
                    h = min(h, 4.0 * driver.h_first)
            first_in_segment = True
            rejected_in_row = False
            err_prev = h_prev = 0.0  # the last rejected trial from the same start
            pending_rate = not rec.started  # the run's first point needs its rate
            if not rec.started:
                rec.started = True
                if rec.active:
                    rec.t.append(t0)
                    rec.y.append(y.copy())
            tiny = 1e-12 * max(1.0, abs(t1))
            lin = False
            sym_now = sym and jq.ndim == 1
            c1 = zeros
            while t < t1 - tiny:
                h, last = clip_step(t, h, t1)
                try:
                    if td:  # c1 = h dq/dt, one-sided difference inside the segment
                        dt_fd = 1e-7 * max(h, 1e-3 * abs(t), 1e-6)
                        tq = t + dt_fd
                        r = heat(tq if tq < t1 else t_left, y)
                        n_heat += 1
                        if type(r) is not np.ndarray or r.shape != shp:
                            r = net.heat_vector(r)
                        c1 = (r - q0) * (h / dt_fd)
                    if not lin:
                        jq_lin = jq
                        if tdep:
                            core.update_system(y)
                            sys_ = core.sys
                            K, s = sys_.K, sys_.s
                            flow, flow0 = _flows(sys_, n)
                            # the conductances' own derivatives complete the Jacobian
                            Dn = driver.asm.drift_jacobian(y)
                            dcol = Dn.sum(axis=0)
                            jq_lin = _with_drift_jacobian(jq, Dn)
                            sym_now = sym and jq_lin.ndim == 1
                        if sym_now:
                            Bw, Jw, vw, tw = ws_real
                            ok, U2 = _ws_start_sym(K, s, jq_lin, rs, y, q0, c1, td, h, Bw, Jw,
                                                   vw)
                        else:
                            ok, lam, V, W, JqM, f0, wf = _general_start(core, K, jq_lin, y, q0)
                        if not ok:
                            raise _fail(driver, _NewtonFailure(
                                math.inf, f"heat source returned a non-finite value at t={t}"),
                                t, h, y)
                        if not sym_now:
                            if lam.dtype.kind == "c":
                                Bw, Jw, vw, tw = ctx.ws[complex]
                                if store is not None:
                                    if store.lam.dtype.kind != "c":
                                        store.make_complex()
                                    s_lam, s_V, s_M = store.lam, store.V, store.M
                                else:
                                    s_lam, s_V, s_M = (a.astype(complex) for a in ctx.empty)
                            else:
                                Bw, Jw, vw, tw = ws_real
                            Bw[:, 0] = lam
                            Bw[:, 1:n + 1] = V
                            Bw[:, n + 1:2 * n + 1] = W
                            Bw[:, 2 * n + 1] = wf
                            Jw[:, :] = JqM
                            vw[0] = f0
                            U2 = _ws_stage2(y, c1, td, h, Bw)
                        lin = True
                        if pending_rate and rec.active:
                            rec.r.append(vw[0] / C)
                        pending_rate = False
                    else:
                        U2 = _ws_stage2(y, c1, td, h, Bw)
                    if heat is None:
                        q2 = q3 = zeros
                    else:
                        tq = t + 0.5 * h
                        q2 = heat(tq if tq < t1 else t_left, U2)
                        if type(q2) is not np.ndarray or q2.shape != shp:
                            q2 = net.heat_vector(q2)
                    if tdep:  # the conductances' drift enters the stage remainder D2
                        d2, db2 = stage_drift(driver.asm, sys_, U2)
                        q2 = q2 + d2
                    U3 = _ws_stage3(y, c1, td, h, U2, q2, q0, Bw, Jw, vw, tw)
                    if heat is not None:
                        tq = t + h
                        q3 = heat(tq if tq < t1 else t_left, U3)
                        if type(q3) is not np.ndarray or q3.shape != shp:
                            q3 = net.heat_vector(q3)
                        n_heat += 2
                    if tdep:  # ... and D3
                        d3, db3 = stage_drift(driver.asm, sys_, U3)
                        q3 = q3 + d3
                    if store is not None:
                        j = store.count
                        if j == len(s_t0):  # full (or first use): grow, refresh the views
                            store.reserve()
                            s_lam, s_V, s_M = store.lam, store.V, store.M
                            s_t0, s_h, s_y0 = store.t0, store.h, store.y0
                    else:
                        j = -1
                    y1, err, gen, to_b, to_s, stored, d_int = _ws_finish(
                        y, q0, q3, U3, c1, td, h, atol, rtol, K, C, flow, flow0, Bw, Jw, vw, tw,
                        s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t, dcol)
                    if tdep:  # the drift's share of generated goes to the boundaries
                        yb = _drift_booking(h, db2 + float(dcol @ (U2 - y)),
                                            db3 + float(dcol @ (U3 - y))) - d_int
                        gen += yb
                        to_b += yb
                    if not math.isfinite(err):
                        raise _NewtonFailure(math.inf, "non-finite exponential step")
                except _NewtonFailure as exc:
                    failures += 1
                    h_new = h / 4.0
                    if h_new < min_step:
                        raise _fail(driver, exc, t, h, y) from None
                    h = h_new
                    continue
                if err > 1.0:
                    rejected += 1
                    fac = max(0.1, 0.9 * err ** -0.25)
                    if rejected_in_row:
                        fac = min(fac, 0.5)
                        if err_prev > err:  # the order the estimate actually showed
                            p_eff = min(4.0, max(1.0, math.log(err_prev / err)
                                                 / math.log(h_prev / h)))
                            fac = min(fac, max(0.1, 0.9 * err ** (-1.0 / p_eff)))
                    else:  # first rejection: assume no better than first order (see above)
                        fac = min(fac, max(0.1, 0.9 / err))
                    err_prev, h_prev = err, h
                    rejected_in_row = True
                    h = h * fac
                    if h < min_step:
                        raise stepper_failure(driver.method_name, err, STEP_UNDERFLOW, t, h, y)
                    continue
                # accept
                rejected_in_row = False
                if first_in_segment:
                    driver.h_first = h
                    first_in_segment = False
                accepted += 1
                t_start = t
                t = t1 if last else t + h
                rec.rows.append((t, gen, stored, to_b, to_s))
                if store is not None:
                    store.count = j + 1
                    rec.pieces.append(StorePiece(store, j, t_start, h))
                    rec.t.append(t)
                    rec.y.append(y1)
                    if last:
                        rec.r.append(vw[5].copy())
                y = y1
                if not last:
                    if hwj is not None:  # the common case inline (see _start_values)
                        q0, jq = hwj(t, y)
                        if type(q0) is not np.ndarray or q0.shape != shp:
                            q0 = net.heat_vector(q0)
                        if type(jq) is not np.ndarray or jq.dtype != np.float64:
                            jq = np.asarray(jq, dtype=float)
                        if jq.shape != shp and jq.shape != (n, n):
                            from ..errors import InputError

                            raise InputError("heat_jacobian", jq.shape,
                                             f"a finite ({n},) diagonal or ({n}, {n}) matrix")
                        n_heat += 1
                    else:
                        try:
                            q0, jq, calls = _start_values(driver, heat, heat_jacobian,
                                                          heat_with_jacobian, t, t, y, n, zeros)
                        except _NewtonFailure as exc:
                            raise _fail(driver, exc, t, h, y) from None
                        n_heat += calls
                    n_jac += 1
                    sym_now = sym and jq.ndim == 1
                    lin = False
                    pending_rate = True
                driver.h_last = h
                fac = facmax if err == 0.0 else min(facmax, max(0.2, 0.9 * err ** -0.25))
                if not 1.0 <= fac <= 1.2:
                    h = h * fac
                if h > max_step:
                    h = max_step
            if pending_rate and rec.active:  # (a segment ended by the tolerance guard)
                if tdep:
                    core.update_system(y)
                f, _ = core.f(t, y)
                rec.r.append(f * core.invC)
    finally:
        stats["steps"] += accepted
        stats["rejected"] += rejected
        stats["newton_failures"] += failures
        stats["heat_evaluations"] += n_heat
        stats["jacobians"] += n_jac
    return y
