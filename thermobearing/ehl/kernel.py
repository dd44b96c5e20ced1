"""Elastic deformation of a line contact: the log kernel, applied by DC-FFT or as a dense matrix.

Dimensionless film equation (paper 000, seed ``000_3b5ca6eed61dd596.txt``, eq. 8)::

    H(X) = H0 + X^2/2 - (1/pi) * integral P(S) ln|X - S| dS

with ``X = x/b``, ``P = p/p_H``, ``H = h R / b^2`` (Hertz half-width ``b``, Hertz pressure ``p_H``,
reduced radius ``R``). With piecewise-constant pressure on cells of width ``dx`` centred on the
nodes the influence coefficients are exact integrals of the kernel (Venner & Lubrecht 2000,
ch. 8)::

    K_k = -(1/pi) [ (k dx + dx/2)(ln|k dx + dx/2| - 1) - (k dx - dx/2)(ln|k dx - dx/2| - 1) ]

so that ``H_i = H0 + X_i^2/2 + sum_j K_|i-j| P_j``. The sum is a Toeplitz product; it is
applied by FFT on a zero-padded grid of length 2n ("discrete convolution, FFT", DC-FFT,
Liu, Wang & Liu 2000), which is exact for the linear (non-periodic) convolution.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.linalg import toeplitz


def influence_coefficients(n: int, dx: float) -> np.ndarray:
    """Coefficients ``K_k`` (k = 0..n-1) of the dimensionless line-contact log kernel.

    Parameters
    ----------
    n : number of grid nodes.
    dx : dimensionless node spacing (in Hertz half-widths) [-].

    Returns
    -------
    K : array (n,) [-], deformation at distance ``k dx`` per unit dimensionless pressure
        on one cell (sign: the deformation term as it enters ``H``).
    """
    k = np.arange(n, dtype=float) * dx
    xp = k + 0.5 * dx
    xm = np.abs(k - 0.5 * dx)
    with np.errstate(divide="ignore", invalid="ignore"):
        fp = xp * (np.log(xp) - 1.0)
        fm = np.where(xm > 0.0, xm * (np.log(np.where(xm > 0, xm, 1.0)) - 1.0), 0.0)
    # for k = 0 the second term is -(-dx/2)(ln(dx/2) - 1): odd extension of x(ln|x|-1)
    fm = np.where(k - 0.5 * dx < 0.0, -fm, fm)
    return -(fp - fm) / np.pi


class LogKernel:
    """Line-contact deformation operator on a uniform grid of ``n`` nodes.

    Parameters
    ----------
    n : number of nodes.
    dx : node spacing [-] (dimensionless, in Hertz half-widths).
    """

    def __init__(self, n: int, dx: float) -> None:
        self.n = int(n)
        self.dx = float(dx)
        self.coeffs = influence_coefficients(self.n, self.dx)
        m = 2 * self.n
        circ = np.zeros(m)
        circ[: self.n] = self.coeffs
        circ[self.n + 1 :] = self.coeffs[1:][::-1]
        self._m = m
        self._spectrum = np.fft.rfft(circ)
        self._dense: np.ndarray | None = None

    #: up to this many nodes the product is a cached dense matrix-vector product (BLAS):
    #: 4 us against 28 us for the two FFTs at 128 nodes, 12 against 32 us at 256
    DENSE_MAX = 256

    def apply(self, p: np.ndarray) -> np.ndarray:
        """Deformation ``sum_j K_|i-j| p_j`` at every node, by DC-FFT (O(n log n)), or by the
        cached dense matrix for ``n <= DENSE_MAX``."""
        if self.n <= self.DENSE_MAX:
            if self._dense is None:
                self._dense = self.dense()
            return self._dense @ p
        pad = np.zeros(self._m)
        pad[: self.n] = p
        return np.fft.irfft(np.fft.rfft(pad) * self._spectrum, self._m)[: self.n]

    def dense(self) -> np.ndarray:
        """The full ``n x n`` influence matrix (for the dense Newton baseline)."""
        return toeplitz(self.coeffs)

    def banded(self, width: int) -> np.ndarray:
        """Coefficients ``K_0..K_width`` (the near field used by the preconditioner)."""
        return self.coeffs[: width + 1].copy()


def smooth_kernel(k: np.ndarray, dx: float, width: float) -> np.ndarray:
    """Smooth part ``Ks`` of the influence coefficients, for a near/far split ``K = Kn + Ks``.

    ``Ks(k) = K(k)`` (the cell-integrated log kernel of :func:`influence_coefficients`,
    continued to real ``k``) for ``|k| >= width``; inside, the even quartic
    ``a0 + a2 k^2 + a4 k^4`` that matches ``K``, ``K'`` and ``K''`` at ``k = width`` (C2).
    The near part ``Kn = K - Ks`` then vanishes for ``|k| >= width`` (a band), and ``Ks`` is
    smooth on the scale ``width``, so it is represented to ``O((h/width)^2)`` by linear
    interpolation from a coarse grid of spacing ``h`` -- the idea of multilevel
    multi-integration (Brandt & Lubrecht 1990, J. Comput. Phys. 90:348-370; Venner &
    Lubrecht 2000, ch. 8), used here only inside a preconditioner.

    Parameters
    ----------
    k : distances in node spacings [-] (any real values).
    dx : dimensionless node spacing [-].
    width : split distance in node spacings [-] (> 1).

    Returns
    -------
    Ks : array like ``k`` [-] (the same units as the influence coefficients).
    """
    k = np.abs(np.asarray(k, dtype=float))
    w = float(width)

    def kfun(kk):
        xp = (kk + 0.5) * dx
        xm = (kk - 0.5) * dx
        return -(xp * (np.log(xp) - 1.0) - xm * (np.log(xm) - 1.0)) / np.pi

    # derivatives of K(k) in k: F(x) = x (ln x - 1), F' = ln x, F'' = 1/x, x = (k +- 1/2) dx
    f0 = kfun(w)
    f1 = -dx * (math.log((w + 0.5) * dx) - math.log((w - 0.5) * dx)) / math.pi
    f2 = -dx * (1.0 / (w + 0.5) - 1.0 / (w - 0.5)) / math.pi
    a4 = (f2 * w - f1) / (8.0 * w**3)
    a2 = 0.5 * (f2 - 12.0 * a4 * w * w)
    a0 = f0 - a2 * w * w - a4 * w**4
    out = a0 + k * k * (a2 + a4 * k * k)
    far = k >= w
    if np.any(far):
        out[far] = kfun(k[far])
    return out
