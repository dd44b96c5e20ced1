"""Compiled node loops of the discrete line-contact Reynolds residual and its Jacobian pieces.

One code path (numba, ``cache=True``) for :meth:`thermobearing.ehl.solver.LineProblem.evaluate`
and the banded preconditioner assembly; the equations and their discretisation are documented
in :mod:`thermobearing.ehl.solver` (paper 000, seed ``000_3b5ca6eed61dd596.txt``, eqs. 7-11,
dimensionless; Venner & Lubrecht 2000 for the conservative Poiseuille flux with face values
``eps_{i+1/2} = (eps_i + eps_{i+1})/2`` and the second-order upwind wedge term).

The numpy version of the same arithmetic (about forty array operations per call) cost
0.24 ms on 128 nodes and 0.43 ms on 1024 nodes per evaluation, mostly interpreter and
temporary-array overhead: that was a third of a Newton iteration on the coarse grids.
All quantities are dimensionless (``P = p/p_H``, ``H = h R/b^2``, ``X = x/b``).
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True)
def residual(P, H, eta, rho, f_e, f_r, lam, dx, w0, w1, w2, inv_dt, q_old):
    """Reynolds residual at the interior nodes (paper 000 eq. 7, discretised).

    Parameters
    ----------
    P, H : pressure and film at all ``n`` nodes [-].
    eta, rho : ``eta/eta0`` and ``rho/rho0`` at the nodes [-].
    f_e, f_r : thermal factors on ``eps`` and on the wedge density [-] (1 if isothermal).
    lam : ``12 u_m eta0 R^2/(b^3 p_H)`` [-].
    dx : node spacing [-]; w0, w1, w2 : upwind wedge weights of the interior rows [1/-].
    inv_dt : ``1/dt`` of the backward-Euler squeeze term, 0 for the steady problem [-].
    q_old : ``f_r rho H`` at the previous time level (any array if ``inv_dt == 0``) [-].

    Returns
    -------
    R : (n-2,) residual ``d/dX(eps dP/dX) - d(rho_t H)/dX (- squeeze)`` [-].
    eps : (n,) ``f_e rho H^3/(eta lam)`` [-].
    """
    n = P.shape[0]
    m = n - 2
    dx2 = dx * dx
    eps = np.empty(n)
    q = np.empty(n)
    for k in range(n):
        eps[k] = f_e[k] * rho[k] * H[k] ** 3 / (eta[k] * lam)
        q[k] = f_r[k] * rho[k] * H[k]
    R = np.empty(m)
    flux_l = 0.5 * (eps[0] + eps[1]) * (P[1] - P[0]) / dx2
    for r in range(m):
        flux_r = 0.5 * (eps[r + 1] + eps[r + 2]) * (P[r + 2] - P[r + 1]) / dx2
        qm2 = q[r - 1] if r >= 1 else 0.0
        wedge = w0[r] * q[r + 1] + w1[r] * q[r] + w2[r] * qm2
        if inv_dt != 0.0:
            wedge += (q[r + 1] - q_old[r + 1]) * inv_dt
        R[r] = flux_r - flux_l - wedge
        flux_l = flux_r
    return R, eps


@numba.njit(cache=True)
def jacobian_pieces(P, H, eps, eta, deta, rho, drho, f_r, dx, w0, w1, w2, inv_dt, k0, k1, k2):
    """Banded pieces of ``dR/dP`` (see :meth:`.solver.LineProblem.evaluate`).

    ``dR_i/dP_j = S_ij + sum_k B_ik K_kj``: ``S`` holds the local dependence on ``P`` (offsets
    -2..+1), ``B`` the dependence on the film ``H_k`` (k = i-2..i+1), ``K`` the influence
    matrix with leading coefficients ``k0, k1, k2``. Returns ``s`` and ``b`` as (4, n-2)
    arrays (rows: offsets -2, -1, 0, +1), ``b_sum`` (the ``H0`` column) and ``scale`` (the
    magnitude of the Jacobian diagonal, used to scale the Fischer-Burmeister rows).
    """
    n = P.shape[0]
    m = n - 2
    dx2 = dx * dx
    s = np.empty((4, m))
    b = np.empty((4, m))
    b_sum = np.empty(m)
    scale = np.empty(m)
    for r in range(m):
        i = r + 1  # node of the row
        dpl = (P[i] - P[i - 1]) / dx2
        dpr = (P[i + 1] - P[i]) / dx2
        epl = 0.5 * (eps[i - 1] + eps[i])
        epr = 0.5 * (eps[i] + eps[i + 1])
        # d R / d ln eps_k, k = i-1, i, i+1 (face value derivative 0.5 eps_k)
        e_m = -dpl * 0.5 * eps[i - 1]
        e_0 = dpr * 0.5 * eps[i] - dpl * 0.5 * eps[i]
        e_p = dpr * 0.5 * eps[i + 1]
        w0r = w0[r] + inv_dt
        dl_m = drho[i - 1] / rho[i - 1] - deta[i - 1] / eta[i - 1]
        dl_0 = drho[i] / rho[i] - deta[i] / eta[i]
        dl_p = drho[i + 1] / rho[i + 1] - deta[i + 1] / eta[i + 1]
        s[1, r] = epl / dx2 + e_m * dl_m - w1[r] * f_r[i - 1] * drho[i - 1] * H[i - 1]
        s[2, r] = -(epl + epr) / dx2 + e_0 * dl_0 - w0r * f_r[i] * drho[i] * H[i]
        s[3, r] = epr / dx2 + e_p * dl_p
        if r >= 1:
            s[0, r] = -w2[r] * f_r[i - 2] * drho[i - 2] * H[i - 2]
            b[0, r] = -w2[r] * f_r[i - 2] * rho[i - 2]
        else:
            s[0, r] = 0.0
            b[0, r] = 0.0
        b[1, r] = e_m * 3.0 / H[i - 1] - w1[r] * f_r[i - 1] * rho[i - 1]
        b[2, r] = e_0 * 3.0 / H[i] - w0r * f_r[i] * rho[i]
        b[3, r] = e_p * 3.0 / H[i + 1]
        b_sum[r] = b[0, r] + b[1, r] + b[2, r] + b[3, r]
        diag = s[2, r] + b[2, r] * k0 + (b[1, r] + b[3, r]) * k1 + b[0, r] * k2
        scale[r] = abs(diag) + 1e-300
    return s, b, b_sum, scale


@numba.njit(cache=True)
def banded_values(s, b, kd, row_scale, diag_add, kl, ku):
    """LAPACK band storage of ``diag(row_scale) (S + B Kn) + diag(diag_add)`` (interior rows).

    ``kd[o + kl, d]`` is the near-field influence coefficient linking film offset
    ``d - 2`` (d = 0..3 for offsets -2..+1) to pressure offset ``o`` (o = -kl..ku);
    ``A[i, j]`` is stored at ``ab[kl + ku + i - j, j]`` (``dgbtrf`` layout, ``kl`` extra rows).
    """
    m = s.shape[1]
    nb = kl + ku + 1
    # built as the transpose of a C-ordered array: the returned view is Fortran-ordered, the
    # layout LAPACK works on (SciPy would copy a C-ordered band matrix before dgbtrf)
    abt = np.zeros((m, 2 * kl + ku + 1))
    ab = abt.T
    for i in range(m):
        for r in range(nb):
            o = r - kl
            j = i + o
            if j < 0 or j >= m:
                continue
            v = kd[r, 0] * b[0, i] + kd[r, 1] * b[1, i] + kd[r, 2] * b[2, i] + kd[r, 3] * b[3, i]
            if -2 <= o <= 1:
                v += s[o + 2, i]
            v *= row_scale[i]
            if o == 0:
                v += diag_add[i]
            abt[j, kl + ku - o] = v
    return ab


@numba.njit(cache=True)
def dense_jacobian(s, b, K):
    """Full ``dR/dP = S + B K`` over the interior nodes (the dense Newton baseline).

    Row ``r`` (node ``i = r + 1``) has film coefficients ``b[k, r]`` on nodes ``i + k - 2``
    (k = 0..3) and local coefficients ``s[k, r]`` on the interior pressure ``r + k - 2``; the
    film at node ``q`` depends on the interior pressure ``c`` (node ``c + 1``) through
    ``K[|q - c - 1|]``.
    """
    m = s.shape[1]
    J = np.zeros((m, m))
    for r in range(m):
        for k in range(4):
            q = r + k - 1  # node of film offset k - 2
            bk = b[k, r]
            if q < 0 or bk == 0.0:
                continue
            for c in range(m):
                J[r, c] += bk * K[abs(q - c - 1)]
        for k in range(4):
            c = r + k - 2
            if 0 <= c < m:
                J[r, c] += s[k, r]
    return J


@numba.njit(cache=True)
def fischer_burmeister(a, b):
    """Fischer-Burmeister function ``phi = a + b - sqrt(a^2 + b^2)`` and its partial
    derivatives (Fischer 1992, Optimization 24:269-284); at ``a = b = 0`` the element
    ``1 - 1/sqrt(2)`` of the generalized Jacobian is used for both. ``phi = 0`` iff
    ``a >= 0, b >= 0, a b = 0`` (the complementarity form of the Reynolds cavitation
    condition, :mod:`thermobearing.ehl.solver`)."""
    n = a.shape[0]
    phi = np.empty(n)
    da = np.empty(n)
    db = np.empty(n)
    c = 1.0 - 1.0 / np.sqrt(2.0)
    for i in range(n):
        r = np.sqrt(a[i] * a[i] + b[i] * b[i])
        phi[i] = a[i] + b[i] - r
        if r < 1e-300:
            da[i] = c
            db[i] = c
        else:
            da[i] = 1.0 - a[i] / r
            db[i] = 1.0 - b[i] / r
    return phi, da, db


@numba.njit(cache=True)
def newton_matvec(v, Kv, s, b, beta, da, col_h0, dx):
    """Product of the bordered semismooth-Newton matrix with ``v`` (interior pressures, then
    the ``H0`` entry), given ``Kv = K v`` at all ``n`` nodes (the deformation of the interior
    pressures; DC-FFT, :class:`thermobearing.ehl.kernel.LogKernel`).

    Rows ``da_r v_r + beta_r ((S v)_r + (B K v)_r) + col_h0_r v_m`` (``S``, ``B`` the banded
    pieces of :func:`jacobian_pieces`, offsets -2..+1 on interior pressures and node films),
    and the load-balance row ``dx sum(v_r)`` (trapezoidal rule of paper 000 eq. 11).
    """
    m = v.shape[0] - 1
    out = np.empty(m + 1)
    vh = v[m]
    total = 0.0
    for r in range(m):
        acc = s[2, r] * v[r]
        if r >= 1:
            acc += s[1, r] * v[r - 1]
        if r >= 2:
            acc += s[0, r] * v[r - 2]
        if r + 1 < m:
            acc += s[3, r] * v[r + 1]
        # films at nodes r-1..r+2 (node of row r is r + 1)
        if r >= 1:
            acc += b[0, r] * Kv[r - 1]
        acc += b[1, r] * Kv[r] + b[2, r] * Kv[r + 1] + b[3, r] * Kv[r + 2]
        out[r] = da[r] * v[r] + beta[r] * acc + col_h0[r] * vh
        total += v[r]
    out[m] = dx * total
    return out


@numba.njit(cache=True)
def window_jacobian(s, b, K, r0, r1):
    """Block ``dR/dP`` of the interior rows and columns ``r0 <= r, c < r1`` (the same entries
    as :func:`dense_jacobian`, only the window; for the local smoothing of the exit spike,
    :func:`thermobearing.ehl.solver.smooth_spike`)."""
    w = r1 - r0
    J = np.zeros((w, w))
    for r in range(r0, r1):
        for k in range(4):
            q = r + k - 1  # node of film offset k - 2
            bk = b[k, r]
            if q < 0 or bk == 0.0:
                continue
            for c in range(r0, r1):
                J[r - r0, c - r0] += bk * K[abs(q - c - 1)]
        for k in range(4):
            c = r + k - 2
            if r0 <= c < r1:
                J[r - r0, c - r0] += s[k, r]
    return J
