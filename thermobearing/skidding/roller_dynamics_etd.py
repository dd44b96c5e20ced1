"""Exponential time differencing (ETDRK4) coefficients for the coupled roller dynamics.

The coupled all-roller model (:mod:`~thermobearing.skidding.roller_dynamics_coupled`) writes
each roller's spin equation with the raceway shear linearised about the refresh state w0,

    d omega / dt = lambda (omega - w0) + N(y),   lambda = (D/2) (dS/d omega) / J_p,

N holding everything else (the shear at w0, its cage-speed slope, the pocket-film friction,
the rib moment). With a mineral oil the film's Newtonian shear makes lambda large
(|lambda| ~ 3e7 1/s for the most loaded roller of a CRB 50x75x16 with ISO VG46 at 80 degC,
20000 r/min, against a step of ~1.8 us the rib contact needs: h |lambda| ~ 60, explicit RK4
is stable to 2.8). Cox and Matthews' ETDRK4 (Cox SM, Matthews PC, "Exponential time
differencing for stiff systems", J. Comput. Phys. 176 (2002) 430-455) integrates the linear
part exactly and the rest with fourth-order stages; for lambda = 0 it is classical RK4.
With z = lambda h and phi_k the phi-functions (phi_0 = e^z, phi_{k+1}(z) =
(phi_k(z) - 1/k!) / z), per component, with v = y - y_ref:

    a = E2 v + Q N(u),       b = E2 v + Q N(a),      c = E2 a + Q (2 N(b) - N(u)),
    v+ = E v + f1 N(u) + 2 f2 (N(a) + N(b)) + f3 N(c),

E = e^z, E2 = e^(z/2), Q = (h/2) phi_1(z/2), f1 = h (phi_1 - 3 phi_2 + 4 phi_3),
f2 = h (phi_2 - 2 phi_3), f3 = h (4 phi_3 - phi_2) (Cox & Matthews 2002, eq. 26, written
in phi-functions). phi-functions by their Taylor series for |z| < 1 (no cancellation) and
by the recurrence above otherwise. Units: lambda [1/s], h [s].
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: Taylor terms of the phi-functions for |z| < 1 (the 25th term is below 1e-25 there)
_SERIES_TERMS = 25


@njit(cache=True)
def phi_functions(z: float) -> tuple[float, float, float]:
    """(phi_1(z), phi_2(z), phi_3(z)) [-], phi_k(z) = sum_n z^n / (n + k)! (module notes);
    Taylor series for |z| < 1, the recurrence phi_{k+1} = (phi_k - 1/k!) / z beyond."""
    if abs(z) < 1.0:
        p1 = 0.0
        p2 = 0.0
        p3 = 0.0
        term = 1.0          # z^n / n!
        for n in range(_SERIES_TERMS):
            # z^n/(n+1)! = term/(n+1), z^n/(n+2)! = term/((n+1)(n+2)), ...
            t1 = term / (n + 1.0)
            t2 = t1 / (n + 2.0)
            p1 += t1
            p2 += t2
            p3 += t2 / (n + 3.0)
            term *= z / (n + 1.0)
        return p1, p2, p3
    e = math.exp(z)
    p1 = (e - 1.0) / z
    p2 = (p1 - 1.0) / z
    p3 = (p2 - 0.5) / z
    return p1, p2, p3


@njit(cache=True)
def etd_coefficients(lam: float, h: float) -> tuple[float, float, float, float, float,
                                                     float]:
    """(E, E2, Q, f1, f2, f3) of one ETDRK4 step of size ``h`` [s] for the linear rate
    ``lam`` [1/s] (module notes); lam = 0 gives RK4's (1, 1, h/2, h/6, h/6, h/6) exactly."""
    if lam == 0.0:
        return 1.0, 1.0, 0.5 * h, h / 6.0, h / 6.0, h / 6.0
    z = lam * h
    p1, p2, p3 = phi_functions(z)
    q1, _, _ = phi_functions(0.5 * z)
    return (math.exp(z), math.exp(0.5 * z), 0.5 * h * q1, h * (p1 - 3.0 * p2 + 4.0 * p3),
            h * (p2 - 2.0 * p3), h * (4.0 * p3 - p2))


@njit(cache=True)
def set_coefficients(coef: np.ndarray, q: int, lam: float, h: float) -> None:
    """Row ``q`` of the (n, 6) coefficient array ``coef`` := :func:`etd_coefficients`."""
    e, e2, qq, f1, f2, f3 = etd_coefficients(lam, h)
    coef[q, 0] = e
    coef[q, 1] = e2
    coef[q, 2] = qq
    coef[q, 3] = f1
    coef[q, 4] = f2
    coef[q, 5] = f3


__all__ = ["etd_coefficients", "phi_functions", "set_coefficients"]
