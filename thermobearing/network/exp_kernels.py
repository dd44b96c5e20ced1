"""Compiled (numba) kernels of the small-network exprb43 path (:mod:`.exp_fast`).

Stage kernels of the exponential Rosenbrock method exprb43 (Hochbruck, Ostermann &
Schweitzer 2009, SIAM J. Numer. Anal. 47(1), 786-803; formulas in the module docstring of
:mod:`.exponential`) written in the eigenbasis of the linearised network, the cyclic Jacobi
eigensolver for the symmetric form C^-1/2 J C^-1/2, the dense-output evaluation and the
workspace wrappers the Python segment loop of :mod:`.exp_fast` calls. Units: times [s],
temperatures [K], heat [W], conductances [W/K], capacities [J/K], energies [J].
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .exponential import _nb_phi_row, _nb_remainder

# ------------------------------------------------------------ compiled kernels
# the phi orders as int64 constants, not literals: Literal[int](2) and Literal[int](5) would
# compile _phi_tab and _nb_phi_row once per value (exponential._I0)
_K2, _K4, _K5 = np.int64(2), np.int64(4), np.int64(5)


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
    tab = _phi_tab(lam, tau, _K2)
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
    tab = _phi_tab(lam, h, _K5)
    acc = h * tab[:, 1] * (wf + wd2)
    if td:
        acc = acc + h * tab[:, 2] * _project(W, c1)
    return D2, wd2, tab, _back(V, y0, acc)


@numba.njit(cache=True)
def _fk_finish(lam, V, W, JqM, y0, f0, q0, wf, wd2, tab, c1, td, h, U3, q3, D2, atol, rtol,
               K, C, flow, flow0, s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t, dcol
               ):  # pragma: no cover - compiled
    """Step completion: (y_{n+1} [K], scaled error, generated, to_boundaries, to_streams,
    stored [J], rate at the step end from the step's own solution [K/s], dcol . I [J]).

    In the eigenbasis (m_k = W c_k): m_0 = W f_n, m_1 = W c_1 (td), m_2 = 8 W D2 - W D3,
    m_3 = 2 W D3 - 8 W D2 (exponential.py: a2, a3 of the interpolated remainder);
    y_{n+1} = y_n + V h [phi1 m_0 + phi2 m_1 + 2 phi3 m_2 + 6 phi4 m_3] (phi_k at h lambda,
    ``tab``); error estimate V h 6 phi4 m_3 in the max norm of |e| / (atol + rtol
    |y_{n+1}|); I = int_0^h (y - y_n) ds = V h^2 [phi2 m_0 + phi3 m_1 + 2 phi4 m_2 +
    6 phi5 m_3]. For an accepted step (err <= 1) the energy-audit terms (module docstring
    of exponential.py; flows linear in y: to_b = flow[0] y_bar - flow0[0], to_s =
    flow[1] y_bar - flow0[1]) and, when ``j >= 0``, the dense-output row j of the store
    (step start t [s], h, y_n and the spectral data).

    Temperature-dependent conductances: the caller adds their drift to q2 and q3
    (``Assembler.drift``) and their derivative D (``Assembler.drift_jacobian``) to dq/dT,
    so both are part of the step, and moves their share of the generated heat to the
    boundaries (``exp_fast._drift_booking`` and ``dcol . I``, dcol the column sums of D).
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
        return y1, err, 0.0, 0.0, 0.0, 0.0, rate, 0.0
    integral = _back(V, np.zeros(n), (h * h) * (ph2 * wf + ph3 * wc1 + 2.0 * ph4 * m2
                                                + 6.0 * tab[:, 5] * m3))
    gen = 0.0
    stored = 0.0
    d_int = 0.0
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
        d_int += dcol[i] * integral[i]
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
    return y1, err, gen, h * fb, h * fs, stored, rate, d_int


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
            _nb_phi_row(tau * s_lam[j, e], _K4, ph)
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
               s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t, dcol
               ):  # pragma: no cover - compiled
    """_fk_finish on the workspaces: (y_{n+1} [K], err, generated, to_boundaries,
    to_streams, stored [J], dcol . I [J]); the step-end rate [K/s] goes to vw[5]."""
    n = y0.shape[0]
    y1, err, gen, to_b, to_s, stored, rate, d_int = _fk_finish(
        Bw[:, 0], Bw[:, 1:n + 1], Bw[:, n + 1:2 * n + 1], Jw, y0, vw[0], q0,
        Bw[:, 2 * n + 1], Bw[:, 2 * n + 2], tw, c1, td, h, U3, q3, vw[2], atol, rtol, K, C,
        flow, flow0, s_lam, s_V, s_M, s_t0, s_h, s_y0, j, t, dcol)
    for i in range(n):
        vw[5, i] = rate[i]
    return y1, err, gen, to_b, to_s, stored, d_int
