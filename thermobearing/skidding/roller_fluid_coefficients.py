"""Rigid-isoviscous (Martin) line-contact coefficients, flooded and starved.

The load, Poiseuille and Couette coefficients of a rigid cylinder on a plane with an
isoviscous film and Reynolds outlet conditions, from the Reynolds equation on an inlet that
starts at ``X_in`` (``-inf`` = fully flooded, Martin 1916: k_w = 2.448), and the starved film
of a finite inlet oil layer. Used by the roller drag (:mod:`~thermobearing.skidding.
roller_fluid`), the pocket film (:mod:`~thermobearing.skidding.roller_pocket_film`), the
rolling-force heat source and the rigid-regime pressure. Reference: Hamrock et al. 2004
[hamrock2004]; Martin 1916 [martin1916_gear_lubrication]. SI units.
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
from scipy import integrate as sint
from scipy import optimize as sopt


def _pi_function(x: float, xm: float, hs: float) -> float:
    """Pi(X) = int_{X_m}^{X} (H - H*)/H^3 dX' in closed form (X = tan g)."""

    def f2(g: float) -> float:
        return 0.5 * g + 0.25 * math.sin(2 * g)

    def f4(g: float) -> float:
        return 3.0 / 8.0 * g + 0.25 * math.sin(2 * g) + math.sin(4 * g) / 32.0

    gm = -math.pi / 2 if math.isinf(xm) else math.atan(xm)
    g = math.atan(x)
    return (f2(g) - f2(gm)) - hs * (f4(g) - f4(gm))


@functools.lru_cache(maxsize=512)
def starved_coefficients(inlet: float) -> tuple[float, float, float, float]:
    """Rigid-isoviscous cylinder-on-plane coefficients with the inlet meniscus at X_m.

    With X = x / sqrt(2 R h0), H = 1 + X^2 and the Reynolds equation
    ``dp/dx = 6 eta U (h - h*)/h^3`` (U = u1 + u2), p = 0 at the inlet meniscus
    X_m = ``inlet`` (< 0; ``-inf`` = fully flooded) and p = dp/dx = 0 at the outlet X*:

    * load per unit length      ``w = k_w eta U R / h0``       (flooded k_w = 2.448, Martin)
    * pressure force on the cylinder along the entrainment ``Q_x = k_q eta U sqrt(R/h0)``
      per unit length (each surface gets the Poiseuille force ``Q_x/2`` against U)
    * Couette integral ``int_fluid dx / h = k_c sqrt(R/h0)`` (full film from X_m to X*, then
      the cavitated film of thickness h* spread over the gap: integrand h*/h^2).

    Returns (k_w, k_q, k_c, X*). Reference: Martin 1916; Hamrock et al. 2004 (rigid
    cylinder, Reynolds boundary condition); paper 000 eqs. 5, 37-38 (coefficient 2.447).
    """
    xm = float(inlet)
    if not xm < 0.0:
        raise ValueError("inlet meniscus X_m must be < 0")

    def at_outlet(xs: float) -> float:
        return _pi_function(xs, xm, 1.0 + xs * xs)

    xs = sopt.brentq(at_outlet, 1e-12, 1.5, xtol=1e-14)
    hs = 1.0 + xs * xs
    lo = -np.inf if math.isinf(xm) else xm
    int_pi = sint.quad(lambda x: _pi_function(x, xm, hs), lo, xs, limit=200)[0]
    int_pix = sint.quad(lambda x: _pi_function(x, xm, hs) * x, lo, xs, limit=200)[0]
    # p = 6 eta U sqrt(2R) h0^-1.5 Pi ; w = 12 eta U R/h0 int Pi
    k_w = 12.0 * int_pi
    # Q_x = -(1/R) int p x dx = -12 sqrt(2) eta U sqrt(R/h0) int Pi X dX
    k_q = -12.0 * math.sqrt(2.0) * int_pix
    couette = (sint.quad(lambda x: 1.0 / (1.0 + x * x), lo, xs)[0]
               + sint.quad(lambda x: hs / (1.0 + x * x) ** 2, xs, np.inf)[0])
    k_c = math.sqrt(2.0) * couette
    return k_w, k_q, k_c, xs


def martin_coefficients() -> tuple[float, float, float, float]:
    """Fully flooded rigid-isoviscous coefficients (k_w, k_q, k_c, X*), see
    :func:`starved_coefficients`; k_w = 2.448 is Martin's (1916) load coefficient."""
    return starved_coefficients(-math.inf)


@functools.lru_cache(maxsize=1)
def _starved_table() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """ln(-X_m) grid and k_w, k_q on it (for vectorised interpolation)."""
    lnx = np.linspace(math.log(1e-3), math.log(300.0), 120)
    kw = np.empty_like(lnx)
    kq = np.empty_like(lnx)
    for i, v in enumerate(lnx):
        kw[i], kq[i], _, _ = starved_coefficients(-math.exp(v))
    return lnx, kw, kq


def rigid_starved_film(load_per_length: Any, sum_speed: Any, radius: float, eta0: float,
                       oil_layer: float | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rigid-isoviscous film h0 [m], load and rolling-force coefficients with starvation.

    The inlet meniscus sits where the gap equals the available oil layer ``oil_layer``
    (total of both surfaces) [m]: ``h0 (1 + X_m^2) = h_oil``; the load balance
    ``w = k_w(X_m) eta0 U R / h0`` is solved for h0 (bisection in ln h0, vectorised).
    ``oil_layer=None``: fully flooded (Martin). Returns (h0, k_w, k_q).
    """
    w = np.asarray(load_per_length, dtype=float)
    u = np.abs(np.asarray(sum_speed, dtype=float))
    k_w0, k_q0, _, _ = martin_coefficients()
    w_safe = np.where(w > 0, w, 1.0)
    h_flood = k_w0 * eta0 * u * radius / w_safe
    if oil_layer is None:
        return h_flood, np.full(w.shape, k_w0), np.full(w.shape, k_q0)
    lnx, kw_t, kq_t = _starved_table()

    def coeffs(h0: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ratio = np.maximum(oil_layer / h0 - 1.0, 1e-300)
        lx = 0.5 * np.log(ratio)
        kw = np.where(lx > lnx[-1], k_w0, np.interp(lx, lnx, kw_t, left=0.0))
        kq = np.where(lx > lnx[-1], k_q0, np.interp(lx, lnx, kq_t, left=0.0))
        return kw, kq

    lo = np.log(np.minimum(h_flood, oil_layer) * 1e-6)
    hi = np.full(w.shape, math.log(oil_layer))
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        h0 = np.exp(mid)
        kw, _ = coeffs(h0)
        too_thin = kw * eta0 * u * radius / h0 > w_safe  # carries more than w: thicken
        lo = np.where(too_thin, mid, lo)
        hi = np.where(too_thin, hi, mid)
    h0 = np.exp(0.5 * (lo + hi))
    kw, kq = coeffs(h0)
    return h0, kw, kq
