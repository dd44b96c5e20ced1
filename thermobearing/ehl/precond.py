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
Measured on BM-6 (session 4): spectral radius of ``I - M^-1 A`` 0.08 at M = 100, L = 20 on
512 nodes, 2-3 GMRES iterations per Newton step (1279 -> 278 GMRES iterations over the 9
cases at N = 1024 against the banded preconditioner of half-band n/8).
"""

from __future__ import annotations

import numba
import numpy as np
from scipy.linalg import lapack, toeplitz
from scipy.sparse import csr_matrix

from ..errors import ConvergenceError
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


class _Grids:
    """Fine/coarse geometry of the split for one grid size (kept on the problem)."""

    def __init__(self, n: int, dx: float, width: int) -> None:
        self.width = int(width)
        self.coeffs_near = None  # set by TwoLevelPreconditioner (needs the kernel)
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

    def restrict(self, y: np.ndarray) -> np.ndarray:
        """``Pi^T y`` for one vector over the interior nodes (two weighted bincounts)."""
        return (np.bincount(self._ii, (1.0 - self._ti) * y, self.nc)
                + np.bincount(self._ii + 1, self._ti * y, self.nc))


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
        # U = diag(beta) B Pi (m x nc): row r (fine node r+1) touches nodes r-1..r+2
        U = np.zeros((m, g.nc))
        rows = np.arange(m)
        for coef, off in zip(st["b"], (-1, 0, 1, 2), strict=True):
            node = np.maximum(rows + off, 0)
            c = beta * coef
            if off == -1:
                c = c.copy()
                c[0] = 0.0
            U[rows, g.idx[node]] += c * (1.0 - g.t[node])
            U[rows, g.idx[node] + 1] += c * g.t[node]
        Z = _band_solve_rows(lu, piv, kl, ku, U)
        C = g.kc @ (g.pt @ Z)
        C[np.diag_indices_from(C)] += 1.0
        clu, cpiv, info = lapack.dgetrf(C)
        if info != 0:
            raise ConvergenceError("ehl.newton", float("nan"), "singular coarse correction")
        self._coarse = (clu, cpiv)
        self._Z, self._g, self._m = Z, g, m
        self._dx = prob.dx
        self._zc = self.solve_interior(col_h0)
        self._fz = prob.dx * float(np.sum(self._zc))

    def _factor_near(self, st: dict, beta: np.ndarray, da: np.ndarray, g: _Grids) -> None:
        ab, kl, ku = self._prob.banded_jacobian_r(st, self._width - 1, beta, da,
                                                  coeffs=g.coeffs_near)
        lu, piv, info = lapack.dgbtrf(ab, kl, ku)
        if info != 0:
            raise ConvergenceError("ehl.newton", float("nan"), "singular banded preconditioner")
        self._band = (lu, piv, kl, ku)

    def refresh_near(self, st: dict, beta: np.ndarray, da: np.ndarray,
                     col_h0: np.ndarray) -> None:
        """Refactor the banded near field at a new Newton iterate and keep the far-field
        (coarse) correction of the last full setup: the cheap part follows the local changes
        (exit spike, rupture point), the costly ``nc`` back-substitutions are lagged."""
        self._factor_near(st, beta, da, self._g)
        self._zc = self.solve_interior(col_h0)
        self._fz = self._dx * float(np.sum(self._zc))

    def solve_interior(self, r: np.ndarray) -> np.ndarray:
        """``(Mb + U V)^-1 r`` for a vector over the interior nodes."""
        lu, piv, kl, ku = self._band
        y, _ = lapack.dgbtrs(lu, kl, ku, r, piv)
        c = self._g.kc @ self._g.restrict(y)
        c, _ = lapack.dgetrs(*self._coarse, c)
        return y - self._Z @ c

    def __call__(self, r: np.ndarray) -> np.ndarray:
        """Apply the bordered preconditioner to ``r`` (interior residuals, then load balance)."""
        m = self._m
        z = self.solve_interior(r[:m])
        d = (self._dx * np.sum(z) - r[m]) / self._fz
        out = np.empty(m + 1)
        out[:m] = z - self._zc * d
        out[m] = d
        return out
