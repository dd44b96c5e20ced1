"""Two-level preconditioner of the line-contact EHL Newton step: banded near, coarse far field.

The Newton matrix (see :mod:`thermobearing.ehl.solver`) is ``A = diag(da) + diag(beta) (S + B K)``
with ``S`` and ``B`` banded (offsets -2..+1) and ``K`` the dense log-kernel influence matrix.
The far field of ``K`` is not small (a banded truncation leaves GMRES with tens of
iterations), but it is smooth. Split ``K = Kn + Ks`` (:func:`.kernel.smooth_kernel`): the near
part ``Kn`` vanishes beyond ``width`` nodes, and the smooth part is represented on a coarse grid
of spacing ``width/2`` and linearly interpolated, ``Ks ~ Pi Kc Pi^T`` (the idea of multilevel
multi-integration, Brandt & Lubrecht 1990, J. Comput. Phys. 90:348-370; Venner & Lubrecht
2000, *Multilevel Methods in Lubrication*, ch. 8). Then

    A ~ Mb + U V,   Mb = diag(da) + diag(beta) (S + B Kn)  (banded),
                    U = diag(beta) B Pi  (n x nc),  V = Kc Pi^T  (nc x n),

and the preconditioner applies the exact inverse of that approximation by the
Sherman-Morrison-Woodbury formula (Hager 1989, SIAM Review 31:221-239)::

    (Mb + U V)^-1 r = y - Z (I + V Z)^-1 V y,    y = Mb^-1 r,  Z = Mb^-1 U.

Setup: one banded LU (half-band ``width + 2``), ``nc`` banded back-substitutions and one
``nc x nc`` LU, ``nc ~ 2 n / width``; each application: one banded back-substitution and
``O(n nc)`` work. The bordered load-balance row and the ``H0`` column are eliminated by a
Schur complement, as for the purely banded preconditioner before. Inside a Newton solve the
far-field part (``Z`` and the coarse LU) is built once per grid and kept while GMRES converges
fast; the banded near field is refactored at every iteration (:meth:`refresh_near`).
Measured on BM-6: spectral radius of ``I - M^-1 A`` 0.08 at M = 100, L = 20 on
512 nodes, 2-3 GMRES iterations per Newton step (1279 -> 278 GMRES iterations over the 9
cases at N = 1024 against the banded preconditioner of half-band n/8). One
compiled call per application (:func:`_bordered_solve`; the coarse LU solve folded into
``W = (I + V Z)^-1 Kc`` at setup) instead of ~15 numpy / LAPACK-wrapper calls.
"""

from __future__ import annotations

import numba
import numpy as np
from scipy.linalg import lapack, toeplitz
from scipy.sparse import csr_matrix

from ..errors import ConvergenceError
from . import reynolds
from .kernel import smooth_kernel


@numba.njit(cache=True)
def _band_solve_rows(lu, piv, kl, ku, B):
    """Solve ``A X = B`` in place for many right-hand sides with the ``dgbtrf`` factors of A.

    The same operations as LAPACK ``dgbtrs`` (row interchanges and unit-lower multipliers,
    then the banded upper-triangular back-substitution), but with ``B`` stored row-major so
    the innermost loop runs over the right-hand sides (contiguous, vectorised). ``dgbtrs``
    on the 1022 x 129 right-hand sides of a 1024-node grid took 5 ms, most of the setup.
    ``piv`` is 0-based as SciPy returns it.
    """
    m, nr = B.shape
    kd = kl + ku
    for j in range(m - 1):
        lm = min(kl, m - 1 - j)
        p = piv[j]
        if p != j:
            for c in range(nr):
                tmp = B[p, c]
                B[p, c] = B[j, c]
                B[j, c] = tmp
        for i in range(1, lm + 1):
            f = lu[kd + i, j]
            if f != 0.0:
                for c in range(nr):
                    B[j + i, c] -= f * B[j, c]
    for j in range(m - 1, -1, -1):
        d = 1.0 / lu[kd, j]
        for c in range(nr):
            B[j, c] *= d
        for i in range(max(0, j - kd), j):
            f = lu[kd + i - j, j]
            if f != 0.0:
                for c in range(nr):
                    B[i, c] -= f * B[j, c]
    return B


@numba.njit(cache=True)
def _band_solve_vec(lu, piv, kl, ku, b):
    """Solve ``A x = b`` for one right-hand side with the ``dgbtrf`` factors of A (returns a
    new array). The operations of LAPACK ``dgbtrs`` (as :func:`_band_solve_rows`), compiled
    so that the preconditioner application is one call without wrapper overhead."""
    m = b.shape[0]
    x = b.copy()
    kd = kl + ku
    for j in range(m - 1):
        lm = min(kl, m - 1 - j)
        p = piv[j]
        if p != j:
            tmp = x[p]
            x[p] = x[j]
            x[j] = tmp
        xj = x[j]
        if xj != 0.0:
            for i in range(1, lm + 1):
                x[j + i] -= lu[kd + i, j] * xj
    for j in range(m - 1, -1, -1):
        x[j] /= lu[kd, j]
        xj = x[j]
        if xj != 0.0:
            for i in range(max(0, j - kd), j):
                x[i] -= lu[kd + i - j, j] * xj
    return x


@numba.njit(cache=True)
def _two_level_solve(lu, piv, kl, ku, idx, t, W, Z, r):
    """``(Mb + U V)^-1 r`` by Sherman-Morrison-Woodbury (module docstring): ``y = Mb^-1 r``,
    ``c = W Pi^T y`` with ``W = (I + V Z)^-1 Kc`` precomputed, ``y - Z c``. ``idx``, ``t``:
    the coarse cell and weight of every interior fine node (linear interpolation ``Pi``)."""
    y = _band_solve_vec(lu, piv, kl, ku, r)
    m = y.shape[0]
    nc = W.shape[0]
    rc = np.zeros(nc)
    for i in range(m):
        rc[idx[i]] += (1.0 - t[i]) * y[i]
        rc[idx[i] + 1] += t[i] * y[i]
    return y - Z @ (W @ rc)


@numba.njit(cache=True)
def _bordered_solve(lu, piv, kl, ku, idx, t, W, Z, zc, fz, dx, r):
    """The bordered preconditioner (interior rows, then the load-balance row): the ``H0``
    column ``zc = M^-1 col_h0`` and ``fz = dx sum(zc)`` eliminate the border (Schur
    complement), see :meth:`TwoLevelPreconditioner.__call__`."""
    m = r.shape[0] - 1
    z = _two_level_solve(lu, piv, kl, ku, idx, t, W, Z, r[:m])
    d = (dx * np.sum(z) - r[m]) / fz
    out = np.empty(m + 1)
    for i in range(m):
        out[i] = z[i] - zc[i] * d
    out[m] = d
    return out


@numba.njit(cache=True)
def _assemble_u(b, beta, idx, t, nc):
    """``U = diag(beta) B Pi`` (m x nc): row r (fine node r + 1) has film coefficients
    ``b[k, r]`` on nodes ``r + k - 1`` (k = 0..3, offsets -2..+1; the node -1 of the first
    row does not exist), each spread on two coarse nodes by the interpolation weights."""
    m = beta.shape[0]
    U = np.zeros((m, nc))
    for r in range(m):
        for k in range(4):
            node = r + k - 1
            if node < 0:
                continue
            c = beta[r] * b[k, r]
            U[r, idx[node]] += c * (1.0 - t[node])
            U[r, idx[node] + 1] += c * t[node]
    return U


class _Grids:
    """Fine/coarse geometry of the split for one grid size (kept on the problem)."""

    def __init__(self, n: int, dx: float, width: int) -> None:
        self.width = int(width)
        self.coeffs_near = None  # set by TwoLevelPreconditioner (needs the kernel)
        self.kd = None  # near-field coefficients by band offset (set on first use)
        self.kl = self.ku = 0
        nc = int(np.ceil(2.0 * (n - 1) / width)) + 1
        hk = (n - 1) / (nc - 1)  # coarse spacing in fine node spacings
        pos = np.arange(n) / hk
        idx = np.minimum(pos.astype(int), nc - 2)
        t = pos - idx
        self.nc, self.idx, self.t = nc, idx, t
        ks = smooth_kernel(np.arange(nc) * hk, dx, width)
        self.kc = toeplitz(ks)
        m = n - 2
        rows = np.concatenate((np.arange(m), np.arange(m)))
        cols = np.concatenate((idx[1:-1], idx[1:-1] + 1))
        vals = np.concatenate((1.0 - t[1:-1], t[1:-1]))
        # Pi^T restricted to the interior fine nodes (the unknowns), sparse (nc x m)
        self.pt = csr_matrix((vals, (cols, rows)), shape=(nc, m))
        self._ii, self._ti = idx[1:-1], t[1:-1]


class TwoLevelPreconditioner:
    """Near/far split preconditioner of one Newton matrix (see the module docstring).

    Parameters
    ----------
    prob : :class:`thermobearing.ehl.solver.LineProblem`.
    st : its ``evaluate`` output at the current iterate (Jacobian pieces).
    beta, da : the Fischer-Burmeister row factors ``d phi/d R`` and ``d phi/d P`` [-].
    col_h0 : the ``H0`` column of the Newton matrix [-].
    width : near-field half-width in nodes (coarse spacing ``width/2``).
    """

    def __init__(self, prob, st: dict, beta: np.ndarray, da: np.ndarray, col_h0: np.ndarray,
                 width: int = 16) -> None:
        n, m = prob.n, prob.n - 2
        width = int(min(max(width, 4), max(4, (n - 1) // 4)))
        key = ("two_level", width)
        g = prob.cache.get(key)
        if g is None:
            g = _Grids(n, prob.dx, width)
            kn = prob.kernel.coeffs[:width] - smooth_kernel(np.arange(width), prob.dx, width)
            g.coeffs_near = np.concatenate((kn, np.zeros(2)))
            prob.cache[key] = g
        self._prob, self._width = prob, width
        self._factor_near(st, beta, da, g)
        lu, piv, kl, ku = self._band
        U = _assemble_u(np.asarray(st["b"]), beta, g.idx, g.t, g.nc)
        Z = _band_solve_rows(lu, piv, kl, ku, U)
        C = g.kc @ (g.pt @ Z)
        C[np.diag_indices_from(C)] += 1.0
        # W = (I + V Z)^-1 Kc: the coarse solve folded into one nc x nc matrix
        _lu, _piv, W, info = lapack.dgesv(C, g.kc)
        if info != 0:
            raise ConvergenceError("ehl.newton", float("nan"), "singular coarse correction")
        self._W = np.ascontiguousarray(W)
        self._Z, self._g, self._m = Z, g, m
        self._dx = prob.dx
        self._zc = self.solve_interior(col_h0)
        self._fz = prob.dx * float(np.sum(self._zc))

    def _factor_near(self, st: dict, beta: np.ndarray, da: np.ndarray, g: _Grids) -> None:
        if g.kd is None:  # near-field coefficients in the layout of reynolds.banded_values
            band = self._width - 1
            kl, ku = band + 2, band + 1
            offs = np.arange(-kl, ku + 1)
            dist = np.abs(np.array([-2, -1, 0, 1])[None, :] - offs[:, None])
            kn = g.coeffs_near
            g.kd = np.where(dist <= band, kn[np.minimum(dist, len(kn) - 1)], 0.0)
            g.kl, g.ku = kl, ku
        ab = reynolds.banded_values(np.asarray(st["s"]), np.asarray(st["b"]), g.kd, beta, da,
                                    g.kl, g.ku)
        lu, piv, info = lapack.dgbtrf(ab, g.kl, g.ku, overwrite_ab=True)
        if info != 0:
            raise ConvergenceError("ehl.newton", float("nan"), "singular banded preconditioner")
        self._band = (lu, piv, g.kl, g.ku)

    def refresh_near(self, st: dict, beta: np.ndarray, da: np.ndarray,
                     col_h0: np.ndarray) -> None:
        """Refactor the banded near field at a new Newton iterate and keep the far-field
        (coarse) correction of the last full setup: the cheap part follows the local changes
        (exit spike, rupture point), the costly ``nc`` back-substitutions are lagged."""
        self._factor_near(st, beta, da, self._g)
        self._zc = self.solve_interior(col_h0)
        self._fz = self._dx * float(np.sum(self._zc))

    def solve_interior(self, r: np.ndarray) -> np.ndarray:
        """``(Mb + U V)^-1 r`` for a vector over the interior nodes (compiled,
        :func:`_two_level_solve`)."""
        lu, piv, kl, ku = self._band
        g = self._g
        return _two_level_solve(lu, piv, kl, ku, g._ii, g._ti, self._W, self._Z,
                                np.ascontiguousarray(r, dtype=float))

    def __call__(self, r: np.ndarray) -> np.ndarray:
        """Apply the bordered preconditioner to ``r`` (interior residuals, then load balance)."""
        lu, piv, kl, ku = self._band
        g = self._g
        return _bordered_solve(lu, piv, kl, ku, g._ii, g._ti, self._W, self._Z, self._zc,
                               self._fz, self._dx, np.ascontiguousarray(r, dtype=float))
