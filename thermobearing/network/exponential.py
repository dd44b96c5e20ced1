"""Exponential Rosenbrock stepper ``exprb43`` for the thermal network.

Method
------
Hochbruck, Ostermann & Schweitzer (2009), "Exponential Rosenbrock-type methods", SIAM J.
Numer. Anal. 47(1), 786-803, method ``exprb43`` (4th order, embedded 3rd order); also
Hochbruck & Ostermann (2010), Acta Numerica 19 (exponential Rosenbrock methods). At every
step the network equation ``C dT/dt = f(t, T) = -K T + s + q(t, T)`` is linearised at (t_n, y_n)::

    C y' = f_n + J (y - y_n) + v s + g_n(t_n + s, y),   J = -K + dq/dT,  v = dq/dt,
    g_n = q(t_n + s, y) - q_n - dq/dT (y - y_n) - v s   (the nonlinear remainder, O(|y - y_n|^2))

The linear part is integrated *exactly* (matrix exponential and phi functions of the small
dense Jacobian), so stiffness costs nothing; the step size is limited only by the
nonlinearity of the heat sources and their time dependence. With G(s) a polynomial
interpolant of g_n along the step, the stage and step values are the exact solution of
``C y' = f_n + J (y - y_n) + G(s)`` at s = tau::

    y(tau) - y_n = sum_k k! tau theta^k phi_{k+1}(tau A) c_k,   theta = tau / h,
    G(s) = sum_{k>=1} c_k (s/h)^k,  c_0 = f_n                   (variation of constants)

exprb43 (HOS 2009; the weights below are re-derived here, and verified by the observed
order 4 in tests/unit/network/test_network_exponential.py):
U2 = y_n + (h/2) phi1(h/2 A) F_n;  U3 = y_n + h phi1(h A) (F_n + D2);
y_{n+1} = y_n + h phi1 F_n + h (16 phi3 - 48 phi4) D2 + h (-2 phi3 + 12 phi4) D3,
D_i = g_n(U_i). These weights are exactly the quadratic-plus-cubic interpolant
G(s) = a2 (s/h)^2 + a3 (s/h)^3 through G(h/2) = D2, G(h) = D3: a2 = 8 D2 - D3,
a3 = 2 D3 - 8 D2 (so 2 phi3 a2 + 6 phi4 a3 reproduces the weights above). The embedded
3rd-order solution drops the cubic term; the error estimate is therefore
``e = 6 h phi4(h A) a3`` (O(h^4): step control with exponent 1/4). For a heat source with
continuous time dependence (``heat_time_dependent=True``) v is a one-sided difference
quotient of q in t (one extra heat evaluation per step) and enters as c_1 = v h; for a
source piecewise constant in t (restarted at the breakpoints) v = 0.

Dense output is the same formula at any tau in (0, h]: exact for the linear network,
the interpolated remainder otherwise (no Hermite interpolation across fast transients).

Linear algebra
--------------
A = C^-1 J (reduced, below) is diagonalised once per step, ``A = V diag(lambda) V^-1``
(``numpy.linalg.eig``; eigenvalues may be complex for the upwind stream coupling: the
arithmetic is then complex and the real part is taken), and phi_k(tau lambda) are
evaluated elementwise (recurrence phi_{k+1}(z) = (phi_k(z) - 1/k!) / z for |z| >= 1,
Taylor series below). The eigendecomposition is O(n^3) per step: intended for the small
dense networks of a bearing (4 to ~120 nodes); TR-BDF2 is the stepper for large sparse
ones. An ill-conditioned eigenvector basis (cond(V) > 1e8, a near-defective matrix) is
refused: the step fails, the driver retries with smaller steps and finally raises a
ConvergenceError whose message names ``tr_bdf2``, the stepper for such a network.
The per-stage work runs in numba-compiled kernels (``cache=True``: compiled once per
machine, ~5 s the first time) because numpy's per-call overhead would dominate at n = 4.
Adaptive runs on dense networks without zero-capacity nodes take the compiled segment
loop of :mod:`.exp_fast` (same method; symmetric networks by a cyclic Jacobi eigensolver);
:meth:`ExpRosenbrock43.step` below serves the rest (fixed steps, zero-capacity nodes,
sparse networks).

Temperature-dependent conductances (e.g. free convection to the air): K_n = K(y_n) and
s_n are held in the linear part over the step, the conductances' own temperature
derivatives D (:meth:`.assemble.Assembler.drift_jacobian`) are added to dq/dT so that the
linear part is the exact linearisation, and the drift
d(U) = (s(U) - K(U) U) - (s_n - K_n U) (:meth:`.assemble.Assembler.drift`) is added to the
heat at the stage values U2 and U3, so the step integrates the exact right-hand side and
its error estimate sees the drift. Measured on the seven-node template at fixed steps
against Radau: 8.5e-6 / 1.2e-6 / 1.5e-7 / 1.8e-8 K at 300 / 150 / 75 / 37.5 s (order ~3;
the air properties are tabulated linearly); without D 1.9e-5 / 6.6e-6 / 1.9e-6 / 4.9e-7 K
(order 2), and with the conductances held over the step and only a linear drift forcing
added (before) the global error fell like the inverse step count. On the default rig
scene at rtol 1e-7: 6.7e-7 K against a tight LSODA reference with 64 + 7 steps (held:
4.1e-6 K with 92 + 22).

Zero-capacity (algebraic) nodes a are eliminated per step by the Schur complement of the
linearised equations: 0 = r_a(s) + J_ad dy_d + J_aa dy_a gives
dy_a = -J_aa^-1 (r_a + J_ad dy_d), and the capacity nodes d obey
C_d dy_d' = (r_d - J_da J_aa^-1 r_a) + (J_dd - J_da J_aa^-1 J_ad) dy_d.

Discrete energy balance (exact for this method)
-----------------------------------------------
Integrating the linearised equation over the step, summed over all nodes,
sum C (y_{n+1} - y_n) = h sum f_n + sum J I + sum int G, I = int_0^h (y - y_n) ds
= h^2 sum_k k! phi_{k+2}(h A) c_k. With J = -K + dq/dT and the identity
-sum(-K y + s) = (heat to boundaries) + (heat to streams) (linear in y, see assemble):

    generated  = h sum q_n + sum (dq/dT I) + sum int G ds   [int G = h sum_k c_k/(k+1)]
    to_bounds  = h Q_b(y_bar),  to_streams = h Q_s(y_bar),  y_bar = y_n + I / h

and generated - stored - to_bounds - to_streams = 0 up to round-off in the exponential.
The drift of temperature-dependent conductances is part of G and their derivative D part
of dq/dT; summed over the nodes both are minus the change of the heat to the boundaries,
so their integrals are moved from the generated column to the boundary column
(:func:`_drift_booking` and the column sums of D times I; the balance is unchanged).
``generated`` is the method's own quadrature of q along its continuous solution (it
differs from the exact integral of q by the local error).

Positivity: for a linear network the step is the exact flow exp(h A), whose matrix is
non-negative (A is a Metzler matrix: C^-1 times minus an M-matrix), so no temperature
leaves the bounds at any step size; with temperature-dependent sources the interpolated
remainder can perturb this by the local error (tested at dt = 600 s).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from .stepper_core import stage_drift
from .steppers import STEPPERS, _Core, _Method, _NewtonFailure, _Trial

_FACT = (1.0, 1.0, 2.0, 6.0, 24.0, 120.0, 720.0)
_INV_FACT = np.array([1.0 / math.factorial(k) for k in range(30)])
_COND_MAX = 1e8


def phi_functions(z: np.ndarray, kmax: int) -> list[np.ndarray]:
    """[phi_0(z), ..., phi_kmax(z)] elementwise (real or complex z, any shape).

    phi_0 = exp(z), phi_{k+1}(z) = (phi_k(z) - 1/k!) / z (the recurrence of Hochbruck &
    Ostermann 2010) for |z| >= 1; below, where that recurrence cancels, phi_kmax from its
    Taylor series sum_j z^j / (j + kmax)! (17 terms: truncation < 1e-16 relative) and the
    stable downward recurrence phi_k = z phi_{k+1} + 1/k!.
    """
    z = np.asarray(z)
    small = np.abs(z) < 1.0
    n_small = int(np.count_nonzero(small))
    out: list = [None] * (kmax + 1)
    if n_small:
        acc = _INV_FACT[kmax + 16] * z + _INV_FACT[kmax + 15]
        for j in range(14, -1, -1):
            acc = acc * z + _INV_FACT[kmax + j]
        ser = [None] * (kmax + 1)
        ser[kmax] = acc
        for k in range(kmax - 1, -1, -1):
            ser[k] = z * ser[k + 1] + _INV_FACT[k]
        if n_small == small.size:
            return ser
    with np.errstate(over="ignore", invalid="ignore"):
        zs = np.where(small, 1.0, z) if n_small else z
        out[0] = np.exp(zs)
        for k in range(1, kmax + 1):
            out[k] = (out[k - 1] - _INV_FACT[k - 1]) / zs
    if n_small:
        out = [np.where(small, a, b) for a, b in zip(ser, out, strict=True)]
    return out


# ------------------------------------------------------------ compiled kernels
# One call per stage keeps the per-step cost at a few microseconds for small networks
# (numpy's per-call overhead would dominate at n = 4). Same formulas as phi_functions.
# Integer arguments passed from compiled code go as these int64 constants: a literal 0
# would be typed Literal[int](0) and compile the callee once per value and once more for
# the Python callers' int64.
_I0, _I1, _I6 = np.int64(0), np.int64(1), np.int64(6)
@numba.njit(cache=True)
def _nb_phi_row(z, kmax, out):  # pragma: no cover - compiled
    """out[k] = phi_k(z), k = 0..kmax, for one complex z."""
    if abs(z) < 1.0:
        acc = _NB_INV_FACT[kmax + 16] * z + _NB_INV_FACT[kmax + 15]
        for j in range(14, -1, -1):
            acc = acc * z + _NB_INV_FACT[kmax + j]
        out[kmax] = acc
        for k in range(kmax - 1, -1, -1):
            out[k] = z * out[k + 1] + _NB_INV_FACT[k]
    else:
        out[0] = np.exp(z)
        for k in range(1, kmax + 1):
            out[k] = (out[k - 1] - _NB_INV_FACT[k - 1]) / z


@numba.njit(cache=True)
def _nb_combine(lam, V, W, cs, use, tau, h, shift):  # pragma: no cover - compiled
    """Reduced increment sum_k k! tau theta^k phi_{k+1+shift}(tau lam) (W c_k), mapped back
    by V; ``shift`` = 1 gives the time integral h^2 sum_k k! phi_{k+2}(h lam) W c_k / tau
    times tau (i.e. pass tau = h)."""
    nd = lam.shape[0]
    n = W.shape[1]
    ph = np.empty(7, dtype=np.complex128)
    acc = np.zeros(nd, dtype=np.complex128)
    th = tau / h
    for i in range(nd):
        _nb_phi_row(tau * lam[i], _I6, ph)
        tot = 0.0j
        fk = 1.0
        thk = 1.0
        for k in range(cs.shape[0]):
            if k > 0:
                fk *= k
                thk *= th
            if use[k]:
                m = 0.0j
                for j in range(n):
                    m += W[i, j] * cs[k, j]
                if shift == 0:
                    tot += fk * tau * thk * ph[k + 1] * m
                else:
                    tot += fk * tau * tau * ph[k + 2] * m
        acc[i] = tot
    out = np.empty(nd)
    for r in range(nd):
        v = 0.0j
        for i in range(nd):
            v += V[r, i] * acc[i]
        out[r] = v.real
    return out


@numba.njit(cache=True)
def _nb_increment(lam, V, W, cs, use, tau, h, shift, d, a, Jaa_inv, Jad):  # pragma: no cover
    """Full-state increment (shift 0: y(tau) - y_n; shift 1: int_0^h (y - y_n) ds with
    tau = h): the capacity nodes from _nb_combine, the zero-capacity nodes lifted by
    dy_a = -J_aa^-1 (r_a + J_ad dy_d)."""
    dd = _nb_combine(lam, V, W, cs, use, tau, h, shift)
    na = a.shape[0]
    if na == 0:
        return dd
    n = W.shape[1]
    out = np.empty(n)
    for i in range(d.shape[0]):
        out[d[i]] = dd[i]
    th = tau / h
    r = np.zeros(na)
    for j in range(na):
        wk = 1.0
        for k in range(cs.shape[0]):
            if k > 0:
                wk *= th
            if use[k]:
                r[j] += (wk if shift == 0 else h / (k + 1)) * cs[k, a[j]]
        for i in range(d.shape[0]):
            r[j] += Jad[j, i] * dd[i]
    for j in range(na):
        v = 0.0
        for m in range(na):
            v -= Jaa_inv[j, m] * r[m]
        out[a[j]] = v
    return out


@numba.njit(cache=True)
def _nb_final(lam, V, W, cs, use, h, d, a, Jaa_inv, Jad, y0, atol, rtol):  # pragma: no cover
    """(y_{n+1}, scaled error norm, int_0^h (y - y_n) ds) of an exprb43 step."""
    y1 = y0 + _nb_increment(lam, V, W, cs, use, h, h, _I0, d, a, Jaa_inv, Jad)
    est_use = np.zeros(4, dtype=np.bool_)
    est_use[3] = True
    est = _nb_increment(lam, V, W, cs, est_use, h, h, _I0, d, a, Jaa_inv, Jad)
    err = 0.0
    for i in range(y1.shape[0]):
        e = abs(est[i]) / (atol + rtol * abs(y1[i]))
        if not e <= err:  # also catches NaN
            err = e
    integral = _nb_increment(lam, V, W, cs, use, h, h, _I1, d, a, Jaa_inv, Jad)
    return y1, err, integral


@numba.njit(cache=True)
def _nb_dense(lam, V, W, cs, use, taus, h, d, a, Jaa_inv, Jad):  # pragma: no cover
    """Full-state increments y(tau) - y_n at several tau (rows)."""
    n = W.shape[1]
    out = np.zeros((taus.shape[0], n))
    for p in range(taus.shape[0]):
        if taus[p] != 0.0:
            # element loop: a row assignment from an array compiles numba's shape-mismatch
            # message code (seconds)
            inc = _nb_increment(lam, V, W, cs, use, taus[p], h, _I0, d, a, Jaa_inv, Jad)
            for i in range(n):
                out[p, i] = inc[i]
    return out


@numba.njit(cache=True)
def _nb_diagonalise(A, M, invC, use_M):  # pragma: no cover - compiled
    """(lambda, V, W = V^-1 M, cond_1(V)) of A = V diag(lambda) V^-1 (real or complex
    A: numba's real eig raises ValueError when the spectrum is complex, and the caller
    retries in complex arithmetic). Without zero-capacity nodes M = diag(invC)."""
    lam, V = np.linalg.eig(A)
    Vi = np.linalg.inv(V)
    n = A.shape[0]
    if use_M:
        W = Vi @ M
    else:
        W = Vi * invC.reshape(1, -1)
    c1 = 0.0
    c2 = 0.0
    for j in range(n):
        s1 = 0.0
        s2 = 0.0
        for i in range(n):
            s1 += abs(V[i, j])
            s2 += abs(Vi[i, j])
        c1 = max(c1, s1)
        c2 = max(c2, s2)
    return lam, V, W, c1 * c2


@numba.njit(cache=True)
def _nb_remainder(U, qU, q0, JqM, y0, c1, frac):  # pragma: no cover - compiled
    """g_n = q(U) - q_n - dq/dT (U - y_n) - frac c_1 [W]."""
    n = U.shape[0]
    r = np.empty(n)
    for i in range(n):
        v = qU[i] - q0[i] - frac * c1[i]
        for j in range(n):
            v -= JqM[i, j] * (U[j] - y0[j])
        r[i] = v
    return r


@numba.njit(cache=True)
def _nb_stage2(lam, V, W, d, a, Jaa_inv, Jad, y0, f0, c1, td, h):  # pragma: no cover
    """U2 = y_n + (y(h/2) - y_n) for the forcing f_n (+ c_1 s/h)."""
    cs = np.zeros((4, y0.shape[0]))
    cs[0] = f0
    cs[1] = c1
    use = np.zeros(4, dtype=np.bool_)
    use[0] = True
    use[1] = td
    return y0 + _nb_increment(lam, V, W, cs, use, 0.5 * h, h, _I0, d, a, Jaa_inv, Jad)


@numba.njit(cache=True)
def _nb_stage3(lam, V, W, d, a, Jaa_inv, Jad, y0, f0, c1, td, h, U2, q2, q0,
               JqM):  # pragma: no cover - compiled
    """(D2, U3): D2 = g_n(U2); U3 = y_n + (y(h) - y_n) for the forcing f_n + D2 (+ c_1 s/h)."""
    D2 = _nb_remainder(U2, q2, q0, JqM, y0, c1, 0.5 if td else 0.0)
    cs = np.zeros((4, y0.shape[0]))
    cs[0] = f0 + D2
    cs[1] = c1
    use = np.zeros(4, dtype=np.bool_)
    use[0] = True
    use[1] = td
    return D2, y0 + _nb_increment(lam, V, W, cs, use, h, h, _I0, d, a, Jaa_inv, Jad)


@numba.njit(cache=True)
def _nb_finish(lam, V, W, d, a, Jaa_inv, Jad, y0, f0, c1, td, h, U3, q3, q0, JqM, D2,
               atol, rtol):  # pragma: no cover - compiled
    """(y_{n+1}, err, cs, use, generated - h sum q_n [J], y_bar): the step completion,
    its error estimate and the terms of the discrete energy balance (module docstring).
    Temperature-dependent conductances: the caller has added their drift to q2 and q3
    (``Assembler.drift``) and books its share of ``generated`` to the boundaries
    (:func:`_drift_booking`)."""
    n = y0.shape[0]
    D3 = _nb_remainder(U3, q3, q0, JqM, y0, c1, 1.0 if td else 0.0)
    cs = np.zeros((4, n))
    cs[0] = f0
    cs[1] = c1
    use = np.ones(4, dtype=np.bool_)
    use[1] = td
    for i in range(n):
        cs[2, i] = 8.0 * D2[i] - D3[i]
        cs[3, i] = 2.0 * D3[i] - 8.0 * D2[i]
    y1, err, integral = _nb_final(lam, V, W, cs, use, h, d, a, Jaa_inv, Jad, y0, atol, rtol)
    gen = 0.0
    for i in range(n):
        gen += h * (cs[2, i] / 3.0 + cs[3, i] / 4.0)
        if td:
            gen += h * c1[i] / 2.0
        for j in range(n):
            gen += JqM[i, j] * integral[j]
    ybar = y0 + integral / h
    return y1, err, cs, use, gen, ybar


@numba.njit(cache=True)
def _nb_dense_batch(lams, Vs, Ws, css, uses, y0s, t0s, hs, k, t):  # pragma: no cover
    """Dense output at times t, t[i] in step k[i] (no zero-capacity nodes)."""
    n = y0s.shape[1]
    out = np.empty((t.shape[0], n))
    d = np.arange(n)
    a = np.zeros(0, dtype=np.int64)
    e0 = np.zeros((0, 0))
    e1 = np.zeros((0, n))
    for i in range(t.shape[0]):
        j = k[i]
        tau = min(max(t[i] - t0s[j], 0.0), hs[j])
        if tau == 0.0:
            for r in range(n):          # element loops, as in _nb_dense
                out[i, r] = y0s[j, r]
        else:
            inc = _nb_increment(lams[j], Vs[j], Ws[j], css[j], uses[j], tau, hs[j], _I0, d, a,
                                e0, e1)
            for r in range(n):
                out[i, r] = y0s[j, r] + inc[r]
    return out


@numba.njit(cache=True)
def _nb_flows(y, bnd_index, bnd_G, bnd_T, str_last, str_W, str_Tin):  # pragma: no cover
    """(heat rate to the boundaries, heat rate carried by the streams) [W] at state y:
    System.to_boundaries and System.to_streams in one call."""
    to_b = 0.0
    for i in range(bnd_index.shape[0]):
        to_b += bnd_G[i] * (y[bnd_index[i]] - bnd_T[i])
    to_s = 0.0
    for i in range(str_last.shape[0]):
        to_s += str_W[i] * (y[str_last[i]] - str_Tin[i])
    return to_b, to_s


@numba.njit(cache=True)
def _nb_scaled_jacobian(KmJ, invC):  # pragma: no cover - compiled
    """A = C^-1 J = -diag(1/C) (K - dq/dT) [1/s]."""
    n = KmJ.shape[0]
    A = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            A[i, j] = -KmJ[i, j] * invC[i]
    return A


_NB_INV_FACT = np.array([1.0 / math.factorial(k) for k in range(30)])
_EMPTY2 = np.zeros((0, 0))



def diagonalise_or_refuse(A: np.ndarray, M: np.ndarray, invC: np.ndarray, has_m: bool
                          ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lam, V, W) of the scaled Jacobian ``A`` (:func:`_nb_diagonalise`): real, else complex
    (a complex spectrum comes from upwind stream coupling); a basis with cond(V) > 1e8 (a
    near-defective Jacobian, e.g. equal nodes on an oil stream without conduction) raises
    ``_NewtonFailure`` so that the caller can fall back to ``tr_bdf2``."""
    try:
        lam, V, W, cond = _nb_diagonalise(A, M, invC, has_m)
    except ValueError:  # complex spectrum
        try:
            lam, V, W, cond = _nb_diagonalise(A.astype(complex), M.astype(complex),
                                              invC.astype(complex), has_m)
        except (ValueError, np.linalg.LinAlgError):
            cond = math.inf
    except np.linalg.LinAlgError:
        cond = math.inf
    if not cond <= _COND_MAX:
        raise _NewtonFailure(math.inf, f"near-defective Jacobian (cond(V) = {cond:.1e}); "
                                       "use method='tr_bdf2' for this network")
    # V C-contiguous (LAPACK's eig gives it in Fortran order), as the symmetric path's: the
    # stage kernels then compile for one layout (the same values)
    return lam, np.ascontiguousarray(V), W

class _Linearization:
    """Reduced, diagonalised linearisation at one step start (t_n, y_n)."""

    __slots__ = ("lam", "V", "W", "Jq", "JqM", "d", "a", "Jaa_inv", "Jad", "y0", "t", "n",
                 "dcol")

    def __init__(self, core: _Core, t: float, y0: np.ndarray) -> None:
        KmJ = core.KmJ
        if not isinstance(KmJ, np.ndarray):
            KmJ = KmJ.toarray()
        Jq = self.Jq = core.Jq
        if Jq is None:
            self.JqM = np.zeros((core.n, core.n))
        else:
            self.JqM = np.diag(Jq) if Jq.ndim == 1 else np.ascontiguousarray(Jq)
        self.dcol = None
        if core.asm.temperature_dependent:
            # the conductances' own derivatives D are in core.KmJ (the exact linearisation,
            # _Core._k_minus_j); they are part of JqM for the remainders too, and their
            # column sums book the heat they move
            D = core.asm.drift_jacobian(y0)
            if not isinstance(D, np.ndarray):  # a sparse network's system
                D = D.toarray()
            self.JqM = self.JqM + D
            self.dcol = D.sum(axis=0)
        self.t = t
        self.y0 = y0
        self.n = core.n
        invC = core.invC
        if core.has_alg:
            J = -KmJ  # W/K
            d = np.flatnonzero(core.diff)
            a = np.flatnonzero(core.alg)
            try:
                Jaa_inv = np.linalg.inv(J[np.ix_(a, a)])
            except np.linalg.LinAlgError:
                raise _NewtonFailure(math.inf, "singular zero-capacity block") from None
            Jad = J[np.ix_(a, d)]
            X = J[np.ix_(d, a)] @ Jaa_inv  # (nd, na)
            S = J[np.ix_(d, d)] - X @ Jad
            M = np.zeros((len(d), core.n))
            M[np.arange(len(d)), d] = 1.0
            M[:, a] = -X
            M *= invC[d][:, None]
            A = S * invC[d][:, None]
            self.d, self.a, self.Jaa_inv, self.Jad = d, a, Jaa_inv, Jad
        else:
            M = None
            A = _nb_scaled_jacobian(KmJ, invC)
            self.d = np.arange(core.n)
            self.a = np.zeros(0, dtype=np.int64)
            self.Jaa_inv = np.zeros((0, 0))
            self.Jad = np.zeros((0, core.n))
        if not math.isfinite(A.sum()):
            raise _NewtonFailure(math.inf, "non-finite Jacobian")
        if A.shape[0]:
            lam, V, W = diagonalise_or_refuse(A, M if M is not None else _EMPTY2, invC,
                                              M is not None)
        else:
            lam = np.zeros(0)
            V = np.zeros((0, 0))
            W = np.zeros((0, core.n))
        self.lam = lam
        self.V = V
        self.W = W

    def increment(self, tau: float, h: float, cs: np.ndarray, use: np.ndarray) -> np.ndarray:
        """y(tau) - y_n for the forcing sum_k cs[k] (s/h)^k [W] (rows with use[k])."""
        return _nb_increment(self.lam, self.V, self.W, cs, use, tau, h, 0, self.d, self.a,
                             self.Jaa_inv, self.Jad)


class ExpPiece:
    """Dense output of one exprb43 step on [t0, t0 + h] (exact for the linearised step)."""

    @staticmethod
    def sample_batch(pieces: tuple, t: np.ndarray) -> np.ndarray:
        """Temperatures [K] at times t from a run's pieces (right-continuous at a step
        start), evaluated in one compiled call when no zero-capacity nodes are present."""
        starts = np.array([p.t0 for p in pieces])
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(starts) - 1)
        if any(len(p.lin.a) for p in pieces):
            out = np.empty((len(t), len(pieces[0].y0)))
            for j in np.unique(k):
                sel = k == j
                out[sel] = pieces[j](t[sel])
            return out
        cplx = any(np.iscomplexobj(p.lin.lam) for p in pieces)
        dt = complex if cplx else float
        lams = np.array([p.lin.lam for p in pieces], dtype=dt)
        Vs = np.array([p.lin.V for p in pieces], dtype=dt)
        Ws = np.array([p.lin.W for p in pieces], dtype=dt)
        css = np.array([p.cs for p in pieces])
        uses = np.array([p.use for p in pieces])
        y0s = np.array([p.y0 for p in pieces])
        hs = np.array([p.h for p in pieces])
        return _nb_dense_batch(lams, Vs, Ws, css, uses, y0s, starts, hs, k, t)

    __slots__ = ("t0", "h", "y0", "lin", "cs", "use")

    def __init__(self, t0, h, y0, lin, cs, use) -> None:
        self.t0, self.h, self.y0, self.lin, self.cs, self.use = t0, h, y0, lin, cs, use

    def __call__(self, t: np.ndarray) -> np.ndarray:
        """Temperatures [K] at times t (within the step), shape (len(t), n)."""
        tau = np.clip(np.asarray(t, dtype=float) - self.t0, 0.0, self.h)
        lin = self.lin
        return self.y0 + _nb_dense(lin.lam, lin.V, lin.W, self.cs, self.use, tau, self.h,
                                   lin.d, lin.a, lin.Jaa_inv, lin.Jad)


_USE_F = np.array([True, False, False, False])
_USE_FV = np.array([True, True, False, False])
_USE_ALL = np.array([True, False, True, True])
def _drift_booking(h: float, db2: float, db3: float) -> float:
    """Heat [J] the drift part of the step's remainder interpolant carries to the
    boundaries: G(s) = a2 (s/h)^2 + a3 (s/h)^3 with a2 = 8 D2 - D3, a3 = 2 D3 - 8 D2
    (module docstring of :mod:`.exponential`) integrates to h (a2/3 + a3/4); summed over
    the nodes the drift's D_i sum to -db. The step's books count that integral as
    generated heat: adding this to both generated and to-boundaries moves it to the
    boundary column (the balance is unchanged)."""
    return h * ((8.0 * db2 - db3) / 3.0 + (2.0 * db3 - 8.0 * db2) / 4.0)


_USE_ALL_V = np.array([True, True, True, True])


@STEPPERS.register("exprb43", references=["hochbruck2009_exprb", "hochbruck_ostermann2010"],
                   parameters={"rtol": "-", "atol": "K"},
                   validity="dense networks (O(n^3) per step, n <~ 120); exact on the "
                            "linear network, order 4 in the heat-source nonlinearity; "
                            "zero-capacity nodes by Schur elimination")
class ExpRosenbrock43(_Method):
    """Exponential Rosenbrock exprb43: exact linear network, 4th order nonlinearity.

    Hochbruck, Ostermann & Schweitzer (2009) method exprb43 with its embedded 3rd-order
    solution; linear part by eigendecomposition of the small dense Jacobian, exact dense
    output; see the module docstring for the formulas, the zero-capacity elimination and
    the discrete energy balance.
    """

    order = 4
    error_order = 3
    name = "exprb43"
    trial_first_step = True

    def __init__(self) -> None:
        self._lin: _Linearization | None = None
        self._zeros = np.zeros(0)

    def step(self, core, t, h, y0, f0, q0):
        lin = self._lin
        if lin is None or lin.y0 is not y0 or lin.t != t or core.KmJ is None:
            if not (core.jac_y is y0 and core.jac_t == t and core.KmJ is not None):
                core.refresh_jacobian(t, y0, q0)
            lin = self._lin = _Linearization(core, t, y0)
        sys_ = core.sys
        if core.asm.temperature_dependent:  # f_n with the conductances at y_n
            f0 = sys_.s - sys_.K @ y0 + q0
        td = core.time_dependent and core.heat is not None
        if td:  # c1 = h dq/dt, one-sided difference inside the segment
            dt_fd = 1e-7 * max(h, 1e-3 * abs(t), 1e-6)
            c1 = (core.q(t + dt_fd, y0) - q0) * (h / dt_fd)
        else:
            c1 = self._zeros if len(self._zeros) == core.n else np.zeros(core.n)
            self._zeros = c1
        L = (lin.lam, lin.V, lin.W, lin.d, lin.a, lin.Jaa_inv, lin.Jad)
        U2 = _nb_stage2(*L, y0, f0, c1, td, h)
        q2 = core.q(t + 0.5 * h, U2)
        drift = core.asm.temperature_dependent
        if drift:  # the conductances' drift enters the stage remainders D2 and D3
            d2, db2 = stage_drift(core.asm, sys_, U2)
            q2 = q2 + d2
        D2, U3 = _nb_stage3(*L, y0, f0, c1, td, h, U2, q2, q0, lin.JqM)
        q3 = core.q(t + h, U3)
        if drift:
            d3, db3 = stage_drift(core.asm, sys_, U3)
            q3 = q3 + d3
        y1, err, cs, use, gen, ybar = _nb_finish(*L, y0, f0, c1, td, h, U3, q3, q0, lin.JqM,
                                                 D2, core.atol, core.rtol)
        if not math.isfinite(err):  # NaN or inf anywhere in y1 makes err non-finite
            raise _NewtonFailure(math.inf, "non-finite exponential step")
        if err > 1.0 and core.adaptive:
            return _Trial(y1, None, None, err, 0.0, 0.0, 0.0)  # rejected: no more work
        f1, q1 = core.f(t + h, y1)
        gen += h * float(q0.sum())
        fb, fs = _nb_flows(ybar, sys_.bnd_index, sys_.bnd_G, sys_.bnd_T, sys_.str_last,
                           sys_.str_W, sys_.str_Tin)
        to_b = h * fb
        to_s = h * fs
        if drift:  # the drift's share of generated goes to the boundaries
            dcol = lin.dcol
            yb = (_drift_booking(h, db2 + float(dcol @ (U2 - y0)), db3 + float(dcol @ (U3 - y0)))
                  - h * float(dcol @ (ybar - y0)))
            gen += yb
            to_b += yb
        return _Trial(y1, f1, q1, err, gen, to_b, to_s, ExpPiece(t, h, y0, lin, cs, use))
