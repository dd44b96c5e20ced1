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

Applies when the network is dense (<= ``assemble.DENSE_LIMIT`` nodes), has no
zero-capacity nodes and no temperature-dependent conductances, and the steps are
adaptive; the general path in :mod:`.exponential` handles the rest. Units: times [s],
temperatures [K], heat [W], conductances [W/K], capacities [J/K], energies [J].
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .exponential import (
    _nb_diagonalise,
    _nb_phi_row,
    _nb_remainder,
    _nb_scaled_jacobian,
)
from .steppers import _NewtonFailure

_COND_MAX = 1e8


# ------------------------------------------------------------ compiled kernels
@numba.njit(cache=True)
def _phi_tab(lam, tau, kmax):  # pragma: no cover - compiled
    """tab[i, k] = phi_k(tau lambda_i), k = 0..kmax, in the dtype of lambda (real for a
    real spectrum: no complex arithmetic on symmetric networks)."""
    n = lam.shape[0]
    zero = 0.0 * lam[0]
    tab = np.zeros((n, kmax + 1)) + zero
    row = np.zeros(kmax + 1) + zero
    for i in range(n):
        _nb_phi_row(tau * lam[i], kmax, row)
        for k in range(kmax + 1):
            tab[i, k] = row[k]
    return tab


@numba.njit(cache=True)
def _project(W, v):  # pragma: no cover - compiled
    """W v: a forcing [W] in the eigenbasis, scaled by C^-1 [K/s]."""
    n = W.shape[0]
    out = np.zeros(n) + 0.0 * W[0, 0]
    for i in range(n):
        acc = out[i]
        for j in range(v.shape[0]):
            acc += W[i, j] * v[j]
        out[i] = acc
    return out


@numba.njit(cache=True)
def _back(V, y0, acc):  # pragma: no cover - compiled
    """y0 + Re(V acc) [K]."""
    n = y0.shape[0]
    out = np.empty(n)
    for r in range(n):
        v = 0.0 * acc[0]
        for e in range(acc.shape[0]):
            v += V[r, e] * acc[e]
        out[r] = y0[r] + v.real
    return out


@numba.njit(cache=True)
def _fk_stage2(lam, V, W, y0, wf, c1, td, h):  # pragma: no cover - compiled
    """U2 = y(h/2) for the forcing f_n (+ c_1 s/h): y_n + V [tau phi1(tau lam) W f_n
    (+ tau theta phi2(tau lam) W c_1)], tau = h/2, theta = 1/2 [K]. ``wf`` = W f_n."""
    tau = 0.5 * h
    tab = _phi_tab(lam, tau, 2)
    acc = tau * tab[:, 1] * wf
    if td:
        acc = acc + (0.5 * tau) * tab[:, 2] * _project(W, c1)
    return _back(V, y0, acc)


_JACOBI_MAX_N = 12  # above this, LAPACK's eigh (O(n^3) with a smaller constant) is used


@numba.njit(cache=True)
def _jacobi_eigh(S):  # pragma: no cover - compiled
    """(w, Q) with S = Q diag(w) Q^T for a small symmetric S: cyclic Jacobi method.

    Golub & Van Loan (2013), Matrix Computations, 4th ed., Algorithms 8.5.1 (the 2x2
    symmetric Schur decomposition: tau = (s_qq - s_pp) / (2 s_pq), t = sign(tau) /
    (|tau| + sqrt(1 + tau^2)), c = 1/sqrt(1 + t^2), s = t c) and 8.5.3 (cyclic sweeps).
    A pair (p, q) is rotated only while |s_pq| > 1e-16 sqrt(|s_pp s_qq|), the stopping
    rule of Demmel & Veselic (1992), SIAM J. Matrix Anal. Appl. 13(4), 1204-1245, under
    which the small eigenvalues (the slow thermal modes) are found to high relative
    accuracy; quadratic convergence: 4-6 sweeps at n = 4. ~1-2 us for n = 4, against
    ~10 us through LAPACK (dsyevd) with numba's per-call workspace handling.
    """
    n = S.shape[0]
    A = S.copy()
    Q = np.eye(n)
    for _sweep in range(60):
        rotated = False
        for p in range(n - 1):
            for q in range(p + 1, n):
                apq = A[p, q]
                if abs(apq) <= 1e-16 * math.sqrt(abs(A[p, p] * A[q, q])):
                    continue
                rotated = True
                tau = (A[q, q] - A[p, p]) / (2.0 * apq)
                if tau >= 0.0:
                    t = 1.0 / (tau + math.sqrt(1.0 + tau * tau))
                else:
                    t = -1.0 / (-tau + math.sqrt(1.0 + tau * tau))
                c = 1.0 / math.sqrt(1.0 + t * t)
                sn = t * c
                for k in range(n):  # A J
                    akp = A[k, p]
                    akq = A[k, q]
                    A[k, p] = c * akp - sn * akq
                    A[k, q] = sn * akp + c * akq
                for k in range(n):  # J^T (A J)
                    apk = A[p, k]
                    aqk = A[q, k]
                    A[p, k] = c * apk - sn * aqk
                    A[q, k] = sn * apk + c * aqk
                A[p, q] = 0.0
                A[q, p] = 0.0
                for k in range(n):  # Q J
                    qkp = Q[k, p]
                    qkq = Q[k, q]
                    Q[k, p] = c * qkp - sn * qkq
                    Q[k, q] = sn * qkp + c * qkq
        if not rotated:
            break
    w = np.empty(n)
    for i in range(n):
        w[i] = A[i, i]
    return w, Q


@numba.njit(cache=True)
def _fk_start_sym(K, s, jq, rs, y0, q0, c1, td, h):  # pragma: no cover - compiled
    """Step start on a symmetric network: (ok, lambda, V, W, dq/dT matrix, f_n, W f_n, U2);
    ok = q_n and dq/dT are finite.

    S = -C^-1/2 (K - diag(jq)) C^-1/2 = Q diag(lambda) Q^T (cyclic Jacobi up to 12 nodes,
    LAPACK ``eigh`` above), V = C^-1/2 Q,
    W = V^-1 C^-1 = Q^T C^-1/2; ``rs`` = C^-1/2 [(J/K)^-1/2], ``jq`` = diagonal dq/dT [W/K].
    """
    n = y0.shape[0]
    chk = 0.0
    for i in range(n):
        chk += q0[i] + jq[i]
    ok = math.isfinite(chk)
    f0 = np.empty(n)
    S = np.empty((n, n))
    JqM = np.zeros((n, n))
    for i in range(n):
        v = s[i] + q0[i]
        for j in range(n):
            v -= K[i, j] * y0[j]
            S[i, j] = -K[i, j] * rs[i] * rs[j]
        f0[i] = v
        S[i, i] += jq[i] * rs[i] * rs[i]
        JqM[i, i] = jq[i]
    if not ok:  # a non-finite heat or Jacobian: nothing to decompose
        S[:, :] = 0.0
    if n <= _JACOBI_MAX_N:
        lam, Q = _jacobi_eigh(S)
    else:
        lam, Q = np.linalg.eigh(S)
    V = np.empty((n, n))
    W = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            V[i, j] = rs[i] * Q[i, j]
            W[j, i] = Q[i, j] * rs[i]
    wf = _project(W, f0)
    U2 = _fk_stage2(lam, V, W, y0, wf, c1, td, h)
    return ok, lam, V, W, JqM, f0, wf, U2


@numba.njit(cache=True)
def _fk_stage3(lam, V, W, JqM, y0, wf, c1, td, h, U2, q2, q0):  # pragma: no cover
    """(D2 [W], W D2, phi table at h lambda (k = 0..5), U3 [K]): D2 = g_n(U2);
    U3 = y(h) for the forcing f_n + D2 (+ c_1 s/h) = y_n + V [h phi1 W (f_n + D2)
    (+ h phi2 W c_1)]."""
    D2 = _nb_remainder(U2, q2, q0, JqM, y0, c1, 0.5 if td else 0.0)
    wd2 = _project(W, D2)
    tab = _phi_tab(lam, h, 5)
    acc = h * tab[:, 1] * (wf + wd2)
    if td:
        acc = acc + h * tab[:, 2] * _project(W, c1)
    return D2, wd2, tab, _back(V, y0, acc)


@numba.njit(cache=True)
def _fk_finish(lam, V, W, JqM, y0, f0, q0, wf, wd2, tab, c1, td, h, U3, q3, D2, atol, rtol,
               K, C, flow, flow0, s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t
               ):  # pragma: no cover - compiled
    """Step completion: (y_{n+1} [K], scaled error, generated, to_boundaries, to_streams,
    stored [J], rate at the step end from the step's own solution [K/s]).

    In the eigenbasis (m_k = W c_k): m_0 = W f_n, m_1 = W c_1 (td), m_2 = 8 W D2 - W D3,
    m_3 = 2 W D3 - 8 W D2 (exponential.py: a2, a3 of the interpolated remainder);
    y_{n+1} = y_n + V h [phi1 m_0 + phi2 m_1 + 2 phi3 m_2 + 6 phi4 m_3] (phi_k at h lambda,
    ``tab``); error estimate V h 6 phi4 m_3 in the max norm of |e| / (atol + rtol
    |y_{n+1}|); I = int_0^h (y - y_n) ds = V h^2 [phi2 m_0 + phi3 m_1 + 2 phi4 m_2 +
    6 phi5 m_3]. For an accepted step (err <= 1) the energy-audit terms (module docstring
    of exponential.py; flows linear in y: to_b = flow[0] y_bar - flow0[0], to_s =
    flow[1] y_bar - flow0[1]) and, when ``j >= 0``, the dense-output row j of the store
    (step start t [s], h, y_n and the spectral data).
    """
    n = y0.shape[0]
    D3 = _nb_remainder(U3, q3, q0, JqM, y0, c1, 1.0 if td else 0.0)
    wd3 = _project(W, D3)
    m2 = 8.0 * wd2 - wd3
    m3 = 2.0 * wd3 - 8.0 * wd2
    wc1 = _project(W, c1) if td else 0.0 * wf
    ph1 = tab[:, 1]
    ph2 = tab[:, 2]
    ph3 = tab[:, 3]
    ph4 = tab[:, 4]
    y1 = _back(V, y0, h * (ph1 * wf + ph2 * wc1 + 2.0 * ph3 * m2 + 6.0 * ph4 * m3))
    est = _back(V, np.zeros(n), (6.0 * h) * ph4 * m3)
    err = 0.0
    for i in range(n):
        e = abs(est[i]) / (atol + rtol * abs(y1[i]))
        if not e <= err:  # also catches NaN
            err = e
    rate = np.zeros(n)
    if err > 1.0 or not math.isfinite(err):
        return y1, err, 0.0, 0.0, 0.0, 0.0, rate
    integral = _back(V, np.zeros(n), (h * h) * (ph2 * wf + ph3 * wc1 + 2.0 * ph4 * m2
                                                + 6.0 * tab[:, 5] * m3))
    gen = 0.0
    stored = 0.0
    fb = -flow0[0]
    fs = -flow0[1]
    for i in range(n):
        cs2 = 8.0 * D2[i] - D3[i]
        cs3 = 2.0 * D3[i] - 8.0 * D2[i]
        gen += h * (q0[i] + cs2 / 3.0 + cs3 / 4.0)
        v = f0[i] + cs2 + cs3  # C y'(h) = f_n + (dq/dT - K)(y_{n+1} - y_n) + G(h)
        if td:
            gen += h * c1[i] / 2.0
            v += c1[i]
        for m in range(n):
            gen += JqM[i, m] * integral[m]
            v += (JqM[i, m] - K[i, m]) * (y1[m] - y0[m])
        rate[i] = v / C[i]
        stored += C[i] * (y1[i] - y0[i])
        ybar = y0[i] + integral[i] / h
        fb += flow[0, i] * ybar
        fs += flow[1, i] * ybar
    if j >= 0:
        s_t0[j] = t
        s_h[j] = h
        for e in range(n):
            s_y0[j, e] = y0[e]
            s_lam[j, e] = lam[e]
            for r in range(n):
                s_V[j, r, e] = V[r, e]
            s_M[j, e, 0] = wf[e]
            s_M[j, e, 1] = wc1[e]
            s_M[j, e, 2] = m2[e]
            s_M[j, e, 3] = m3[e]
    return y1, err, gen, h * fb, h * fs, stored, rate


@numba.njit(cache=True)
def _fk_dense(s_lam, s_V, s_M, s_y0, s_t0, s_h, idx, t):  # pragma: no cover - compiled
    """Temperatures [K] at times t[i] from stored step idx[i] (right-continuous at a start):
    y_n + V sum_k k! tau theta^k phi_{k+1}(tau lambda) M[:, k], theta = tau / h.
    Real arithmetic for a real store (symmetric networks), complex otherwise."""
    n = s_y0.shape[1]
    out = np.empty((t.shape[0], n))
    zero = 0.0 * s_lam[0, 0]  # 0 of the store's dtype
    ph = np.zeros(5) + zero
    acc = np.zeros(n) + zero
    for p in range(t.shape[0]):
        j = idx[p]
        tau = min(max(t[p] - s_t0[j], 0.0), s_h[j])
        if tau == 0.0:
            for r in range(n):
                out[p, r] = s_y0[j, r]
            continue
        th = tau / s_h[j]
        for e in range(n):
            _nb_phi_row(tau * s_lam[j, e], 4, ph)
            acc[e] = tau * (ph[1] * s_M[j, e, 0] + th * ph[2] * s_M[j, e, 1]
                            + 2.0 * th * th * ph[3] * s_M[j, e, 2]
                            + 6.0 * th * th * th * ph[4] * s_M[j, e, 3])
        for r in range(n):
            v = zero
            for e in range(n):
                v += s_V[j, r, e] * acc[e]
            out[p, r] = s_y0[j, r] + v.real
    return out


# Workspace wrappers: the Python loop passes per-run workspaces (basis Bw = [lambda | V |
# W | W f_n | W D2], dq/dT matrix Jw, state rows vw = [f_n, -, D2, -, -, rate], phi table
# tw) between the stages, so that only the arrays the heat source needs (U2, U3, y_{n+1})
# cross the Python boundary: boxing a new numpy array there costs ~0.3-0.5 us each.
@numba.njit(cache=True)
def _ws_start_sym(K, s, jq, rs, y0, q0, c1, td, h, Bw, Jw, vw):  # pragma: no cover
    """_fk_start_sym into the workspaces; returns (ok, U2 [K])."""
    n = y0.shape[0]
    ok, lam, V, W, JqM, f0, wf, U2 = _fk_start_sym(K, s, jq, rs, y0, q0, c1, td, h)
    for i in range(n):
        Bw[i, 0] = lam[i]
        Bw[i, 2 * n + 1] = wf[i]
        vw[0, i] = f0[i]
        for k in range(n):
            Bw[i, 1 + k] = V[i, k]
            Bw[i, 1 + n + k] = W[i, k]
            Jw[i, k] = JqM[i, k]
    return ok, U2


@numba.njit(cache=True)
def _ws_stage2(y0, c1, td, h, Bw):  # pragma: no cover - compiled
    """U2 [K] of a retried step from the stored basis."""
    n = y0.shape[0]
    return _fk_stage2(Bw[:, 0], Bw[:, 1:n + 1], Bw[:, n + 1:2 * n + 1], y0, Bw[:, 2 * n + 1],
                      c1, td, h)


@numba.njit(cache=True)
def _ws_stage3(y0, c1, td, h, U2, q2, q0, Bw, Jw, vw, tw):  # pragma: no cover - compiled
    """_fk_stage3 on the workspaces; returns U3 [K]."""
    n = y0.shape[0]
    D2, wd2, tab, U3 = _fk_stage3(Bw[:, 0], Bw[:, 1:n + 1], Bw[:, n + 1:2 * n + 1], Jw, y0,
                                  Bw[:, 2 * n + 1], c1, td, h, U2, q2, q0)
    for i in range(n):
        vw[2, i] = D2[i]
        Bw[i, 2 * n + 2] = wd2[i]
        for k in range(tab.shape[1]):
            tw[i, k] = tab[i, k]
    return U3


@numba.njit(cache=True)
def _ws_finish(y0, q0, q3, U3, c1, td, h, atol, rtol, K, C, flow, flow0, Bw, Jw, vw, tw,
               s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t):  # pragma: no cover - compiled
    """_fk_finish on the workspaces: (y_{n+1} [K], err, generated, to_boundaries,
    to_streams, stored [J]); the step-end rate [K/s] goes to vw[5]."""
    n = y0.shape[0]
    y1, err, gen, to_b, to_s, stored, rate = _fk_finish(
        Bw[:, 0], Bw[:, 1:n + 1], Bw[:, n + 1:2 * n + 1], Jw, y0, vw[0], q0,
        Bw[:, 2 * n + 1], Bw[:, 2 * n + 2], tw, c1, td, h, U3, q3, vw[2], atol, rtol, K, C,
        flow, flow0, s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t)
    for i in range(n):
        vw[5, i] = rate[i]
    return y1, err, gen, to_b, to_s, stored


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
    return (driver.dt is None and core.sys.dense and not core.has_alg
            and not core.asm.temperature_dependent and core.n > 0)


def _general_start(core, K, jq, y0, q0):
    """Step start on a non-symmetric network (or a full dq/dT): the general
    eigendecomposition of exponential.py (real, else complex; defective bases refused)."""
    if not (math.isfinite(q0.sum()) and math.isfinite(jq.sum())):
        return (False, *(None,) * 6)
    JqM = np.diag(jq) if jq.ndim == 1 else np.ascontiguousarray(jq)
    A = _nb_scaled_jacobian(K - JqM, core.invC)
    if not math.isfinite(A.sum()):
        raise _NewtonFailure(math.inf, "non-finite Jacobian")
    empty = np.zeros((0, 0))
    try:
        lam, V, W, cond = _nb_diagonalise(A, empty, core.invC, False)
    except ValueError:  # complex spectrum (upwind stream coupling)
        try:
            lam, V, W, cond = _nb_diagonalise(A.astype(complex), empty.astype(complex),
                                              core.invC.astype(complex), False)
        except (ValueError, np.linalg.LinAlgError):
            cond = math.inf
    except np.linalg.LinAlgError:
        cond = math.inf
    if not cond <= _COND_MAX:
        raise _NewtonFailure(math.inf, f"near-defective Jacobian (cond(V) = {cond:.1e}); "
                                       "use method='tr_bdf2' for this network")
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
        self.sym = bool(np.array_equal(K, K.T))
        self.rs = 1.0 / np.sqrt(C)  # C^-1/2 [(J/K)^-1/2]
        # heat rates to the boundaries and to the streams are linear in the state:
        # sum G_b (T_i - T_b) = flow[0] T - flow0[0]; sum W (T_last - T_in) = flow[1] T - ...
        flow = np.zeros((2, n))
        np.add.at(flow[0], sys_.bnd_index, sys_.bnd_G)
        np.add.at(flow[1], sys_.str_last, sys_.str_W)
        self.flow = flow
        self.flow0 = np.array([float(sys_.bnd_G @ sys_.bnd_T),
                               float(sys_.str_W @ sys_.str_Tin)])
        self.zeros = np.zeros(n)
        self.empty = (np.zeros((0, n)), np.zeros((0, n, n)), np.zeros((0, n, 4)))
        self.empty_rows = (np.zeros(0), np.zeros(0), np.zeros((0, n)))
        self.ws = self._workspaces(n)


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
    from ..errors import ConvergenceError

    return ConvergenceError(f"network stepper {driver.method_name}", exc.residual,
                            exc.reason, {"time": t, "step_size": h, "temperatures": y})


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
    sys_ = core.sys
    K, s, C = sys_.K, sys_.s, core.C
    n = core.n
    stats = core.stats
    ctx = driver.fast_info
    if ctx is None:
        ctx = driver.fast_info = _Context.of(driver.asm, sys_, C)
    sym, rs, flow, flow0, zeros = ctx.sym, ctx.rs, ctx.flow, ctx.flow0, ctx.zeros
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
                if t + h >= t1 - 1e-3 * h:
                    h = t1 - t
                    last = True
                else:
                    last = False
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
                        if sym_now:
                            Bw, Jw, vw, tw = ws_real
                            ok, U2 = _ws_start_sym(K, s, jq, rs, y, q0, c1, td, h, Bw, Jw, vw)
                        else:
                            ok, lam, V, W, JqM, f0, wf = _general_start(core, K, jq, y, q0)
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
                    U3 = _ws_stage3(y, c1, td, h, U2, q2, q0, Bw, Jw, vw, tw)
                    if heat is not None:
                        tq = t + h
                        q3 = heat(tq if tq < t1 else t_left, U3)
                        if type(q3) is not np.ndarray or q3.shape != shp:
                            q3 = net.heat_vector(q3)
                        n_heat += 2
                    if store is not None:
                        j = store.count
                        if j == len(s_t0):  # full (or first use): grow, refresh the views
                            store.reserve()
                            s_lam, s_V, s_M = store.lam, store.V, store.M
                            s_t0, s_h, s_y0 = store.t0, store.h, store.y0
                    else:
                        j = -1
                    y1, err, gen, to_b, to_s, stored = _ws_finish(
                        y, q0, q3, U3, c1, td, h, atol, rtol, K, C, flow, flow0, Bw, Jw, vw, tw,
                        s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t)
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
                        from ..errors import ConvergenceError

                        raise ConvergenceError(
                            f"network stepper {driver.method_name}", err,
                            "step size underflow in error control",
                            {"time": t, "step_size": h, "temperatures": y})
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
                f, _ = core.f(t, y)
                rec.r.append(f * core.invC)
    finally:
        stats["steps"] += accepted
        stats["rejected"] += rejected
        stats["newton_failures"] += failures
        stats["heat_evaluations"] += n_heat
        stats["jacobians"] += n_jac
    return y
