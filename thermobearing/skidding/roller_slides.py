"""Roller skidding equations solved in the sliding speeds (paper 000, stiff cold films).

One job: the bracketed solve of the Z + 1 equations of
:func:`thermobearing.skidding.roller_residual.evaluate` (Li, Chen, Zhang, Wang 2018, seed
``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding], eqs. 12-15 and 20-32) with the
sliding speeds as unknowns instead of the roller and cage speeds.

Why: the kinematics (paper 000 eqs. 12-15) give the slides as differences of surface speeds,
V_i = (d_m - D)/2 (omega - omega_c) - D/2 omega_r, which in double precision are multiples
of one ulp of the surface speed (1.8e-15 m/s at 8 m/s). Under heavy load in cold viscous oil
the Hertz-zone film is so viscous (eta(p) of 1e15 Pa s and more) that its Newtonian traction
reaches hundreds of N within one such ulp: measured, CRB 50x75x16 at 20 kN, ISO VG 46 at
20 degC, 5000 r/min: 198 N on the most loaded roller at V_i = 1.8e-15 m/s and 0 N at
V_i = 0. No speed pair then zeroes the equations; the best one leaves residuals of 0.2 of
the largest roller load and tractions that balance nothing (shaft power 11.5 kW against a
dissipation of 0.64 kW).

Unknowns here: each roller's inner slide V_i,j and the cage speed's offset from the
epicyclic speed, delta = omega_c - omega_c,th with omega_c,th = (1 - D/d_m)/2 omega. Then,
exactly in the variables, V_o,j = u_ro - u_roller = d_m delta + V_i,j, and the speeds follow
(omega_r = (u_ri - V_i)/(D/2), omega_c = omega_c,th + delta) for the smooth terms (loads,
entrainment, pocket film, drags). Each roller's moment balance rises with its V_i (it falls
with its spin) and the cage equation falls with delta, as in the speed form: every roller is
bisected in t = asinh(V_i / v_0) and the cage equation is solved by Brent in
tau = asinh(delta / delta_0), so that slides and offsets are resolved relative to their own
size down to v_0 = 1e-40 m/s (delta_0 = 1e-40 omega), not to the ulp of the speeds.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .roller_loads import _gapped
from .roller_model import RollerModel
from .roller_residual import _Eval, evaluate

#: slide [m/s] and cage-offset scale (fraction of omega) of the asinh unknowns
SLIDE_SCALE = 1e-40


def slide_speeds(model: RollerModel, omega: float, v_i: np.ndarray, delta: float
                 ) -> tuple[np.ndarray, float, np.ndarray]:
    """(omega_r (Z,) [rad/s], omega_c [rad/s], V_o (Z,) [m/s]) of the inner slides ``v_i``
    [m/s] and the cage offset ``delta`` = omega_c - omega_c,th [rad/s] (module docstring)."""
    d_m, d = model.pitch_diameter, model.roller_diameter
    r_i = 0.5 * (d_m - d)
    wc = r_i * omega / d_m + delta
    u_ri = r_i * (omega - wc)
    return (u_ri - v_i) / (0.5 * d), wc, d_m * delta + v_i


def evaluate_slides(model: RollerModel, omega: float, v_i: np.ndarray, delta: float,
                    inner_load: np.ndarray, fb: np.ndarray, psi: np.ndarray,
                    acc: tuple[float, float], v_o: np.ndarray | None = None
                    ) -> tuple[_Eval, np.ndarray]:
    """:func:`~thermobearing.skidding.roller_residual.evaluate` at the slides (eval, x)
    with x = (omega_r, omega_c). ``v_o`` (Z,) [m/s]: the outer slides where they are known
    more exactly than d_m delta + v_i (rollers stuck on the outer race while the inner
    contact slides); None: that sum."""
    wr, wc, v_sum = slide_speeds(model, omega, v_i, delta)
    v_o = v_sum if v_o is None else np.asarray(v_o, dtype=float)
    e = evaluate(model, omega, wr, wc, inner_load, fb, psi, acc, slides=(v_i, v_o))
    return e, np.append(wr, wc)


def _bisect(eq: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray,
            active: np.ndarray) -> np.ndarray:
    """Roots (Z,) of the rising ``eq(y)`` bracketed by [lo, hi] (eq(lo) <= 0 < eq(hi)) for
    the ``active`` entries, all at once: bisection in t = asinh(y / v_0) to adjacent floats
    of t, then in y itself inside that bracket (t resolves y only to spacing(t) relative,
    1.4e-14 at |t| ~ 92) to adjacent floats of y."""
    v0 = SLIDE_SCALE
    t_lo, t_hi = np.arcsinh(lo / v0), np.arcsinh(hi / v0)
    for _ in range(200):
        if np.all(~active | (t_hi - t_lo <= np.spacing(np.maximum(np.abs(t_lo),
                                                                   np.abs(t_hi))))):
            break
        mid = 0.5 * (t_lo + t_hi)
        up = eq(v0 * np.sinh(mid)) > 0.0
        t_hi, t_lo = np.where(up, mid, t_hi), np.where(up, t_lo, mid)
    a = np.maximum(v0 * np.sinh(t_lo), lo)
    b = np.minimum(v0 * np.sinh(t_hi), hi)
    for _ in range(80):
        if np.all(~active | (b - a <= np.spacing(np.maximum(np.abs(a), np.abs(b))))):
            break
        mid = 0.5 * (a + b)
        up = eq(mid) > 0.0
        b, a = np.where(up, mid, b), np.where(up, a, mid)
    return 0.5 * (a + b)


def _roller_slides(model: RollerModel, omega: float, delta: float, inner_load: np.ndarray,
                   fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float]
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Inner and outer slides (V_i, V_o) (Z,) [m/s] solving every roller's moment balance at
    the cage offset ``delta`` (:func:`_bisect`, which the balance rises with): first in V_i
    over the slides of spins from 1e-12 omega to twice the larger rolling spin; then, for
    the rollers whose outer slide is the smaller (stuck on the outer race while the inner
    contact slides, where V_o = d_m delta + V_i cancels to the ulp of V_i), again in V_o
    around that root."""
    d_m, d = model.pitch_diameter, model.roller_diameter
    half_d = 0.5 * d
    z = model.n_rollers
    _, wc, _ = slide_speeds(model, omega, np.zeros(1), delta)
    u_ri = 0.5 * (d_m - d) * (omega - wc)
    top = 2.0 * max((d_m - d) / d * (omega - wc), (d_m + d) / d * wc) + 1e-9 * omega
    shift = d_m * delta  # V_o - V_i

    def eq_i(v_i: np.ndarray) -> np.ndarray:
        return evaluate_slides(model, omega, v_i, delta, inner_load, fb, psi,
                               acc)[0].roller_eq

    v_i = _bisect(eq_i, np.full(z, u_ri - top * half_d),
                  np.full(z, u_ri - 1e-12 * omega * half_d), np.ones(z, dtype=bool))
    v_o = shift + v_i
    outer = np.abs(v_o) < np.abs(v_i)
    if not np.any(outer):
        return v_i, v_o
    pad = 8.0 * np.spacing(np.abs(v_i)) + 8.0 * np.spacing(abs(shift))
    lo_o, hi_o = v_o - pad, v_o + pad

    def eq_o(y: np.ndarray) -> np.ndarray:
        return evaluate_slides(model, omega, np.where(outer, y - shift, v_i), delta,
                               inner_load, fb, psi, acc, np.where(outer, y, v_o))[0].roller_eq

    ok = outer & (eq_o(lo_o) <= 0.0) & (eq_o(hi_o) > 0.0)
    if np.any(ok):
        y = _bisect(eq_o, lo_o, hi_o, ok)
        v_o = np.where(ok, y, v_o)
        v_i = np.where(ok, y - shift, v_i)
    return v_i, v_o


def _refine_offset(cage: Callable[[float], float], tau: float, d0: float) -> float:
    """The cage offset [rad/s] of Brent's root ``tau`` in asinh(delta / d0), refined by Brent
    in delta itself (``cage(delta)``) between d0 sinh(tau -+ 4 spacings) when they bracket
    the root on one side of pure rolling (tau resolves delta only to spacing(tau) relative,
    1.4e-14 for |tau| ~ 92, i.e. a cage far from the epicyclic speed); else d0 sinh(tau)."""
    from scipy.optimize import brentq

    step = 4.0 * np.spacing(abs(tau))
    a, b = d0 * math.sinh(tau - step), d0 * math.sinh(tau + step)
    if a * b <= 0.0 or not (cage(a) > 0.0 > cage(b)):
        return d0 * math.sinh(tau)
    root, info = brentq(cage, a, b, xtol=1e-300, rtol=4.0 * np.finfo(float).eps,
                        maxiter=200, full_output=True, disp=False)
    return float(root) if info.converged else d0 * math.sinh(tau)


def solve_slides(model: RollerModel, omega: float, loads: Callable[..., Any], psi: np.ndarray,
                 acc: tuple[float, float], ld0: Any, wc0: float | None = None,
                 force_scale: Callable[[np.ndarray], float] | None = None
                 ) -> tuple[np.ndarray, _Eval, float, Any] | None:
    """Roller and cage speeds from the slide-variable bracketed solve (module docstring).

    ``loads(omega_c, ring)`` -> (load distribution, body force without the centrifugal
    term); ``ld0``: the distribution to start from, at the cage speed ``wc0`` (default the
    epicyclic speed). The load distribution follows the cage speed as a fixed point (at most
    4 passes, until the cage speed moves by less than 1e-8 omega). ``force_scale(inner
    loads)`` [N] scales the returned norm (default the largest inner load).

    Returns (x = (omega_r, omega_c), eval with the exact slides, scaled residual norm, load
    distribution), or None when the cage equation has no sign change over the cage-speed
    range, Brent fails or the loads do not settle within the 4 passes.
    """
    from scipy.optimize import brentq

    csr_th = model.theoretical_cage_speed_ratio
    wc_th = csr_th * omega
    d0 = SLIDE_SCALE * omega
    tau_lo = math.asinh((1e-6 * csr_th * omega - wc_th) / d0)
    tau_hi = math.asinh((min(0.999, 1.5 * csr_th) * omega - wc_th) / d0)
    ld = ld0
    wc_guess = wc_th if wc0 is None else float(wc0)
    found = None
    done = False
    for _outer in range(4):
        ld, fb = loads(wc_guess, tuple(ld.ring_displacement))
        mg = _gapped(model, ld)

        def cage_at(delta: float, mg: RollerModel = mg, ld: Any = ld,
                    fb: np.ndarray = fb) -> float:
            v_i, v_o = _roller_slides(mg, omega, delta, ld.inner_load, fb, psi, acc)
            return evaluate_slides(mg, omega, v_i, delta, ld.inner_load, fb, psi, acc,
                                   v_o)[0].cage_eq

        def cage(tau: float, cage_at: Callable[[float], float] = cage_at) -> float:
            return cage_at(d0 * math.sinh(tau))

        if not (cage(tau_lo) > 0.0 > cage(tau_hi)):
            return None
        tau, info = brentq(cage, tau_lo, tau_hi, xtol=1e-300, rtol=4.0 * np.finfo(float).eps,
                           maxiter=400, full_output=True, disp=False)
        if not info.converged:
            return None
        delta = _refine_offset(cage_at, tau, d0)
        v_i, v_o = _roller_slides(mg, omega, delta, ld.inner_load, fb, psi, acc)
        e, x = evaluate_slides(mg, omega, v_i, delta, ld.inner_load, fb, psi, acc, v_o)
        found = (x, e, ld)
        done = abs(x[-1] - wc_guess) <= 1e-8 * omega
        wc_guess = float(x[-1])
        if done:
            break
    if not done:
        return None  # the loads did not settle at the cage speed within 4 passes
    x, e, ld = found
    res = np.append(e.roller_eq, e.cage_eq)
    scale = (force_scale(ld.inner_load) if force_scale is not None
             else max(float(np.max(ld.inner_load, initial=0.0)), 1e-3))
    return x, e, float(np.linalg.norm(res)) / scale, ld
