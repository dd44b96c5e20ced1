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
                    acc: tuple[float, float]) -> tuple[_Eval, np.ndarray]:
    """:func:`~thermobearing.skidding.roller_residual.evaluate` at the slides (eval, x)
    with x = (omega_r, omega_c)."""
    wr, wc, v_o = slide_speeds(model, omega, v_i, delta)
    e = evaluate(model, omega, wr, wc, inner_load, fb, psi, acc, slides=(v_i, v_o))
    return e, np.append(wr, wc)


def _roller_slides(model: RollerModel, omega: float, delta: float, inner_load: np.ndarray,
                   fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float]) -> np.ndarray:
    """Inner slides (Z,) [m/s] solving every roller's moment balance at the cage offset
    ``delta``: bisection of all rollers at once in t = asinh(V_i / v_0) over the slides of
    spins from 1e-12 omega to twice the larger rolling spin, down to adjacent floats of t."""
    d_m, d = model.pitch_diameter, model.roller_diameter
    half_d = 0.5 * d
    _, wc, _ = slide_speeds(model, omega, np.zeros(1), delta)
    u_ri = 0.5 * (d_m - d) * (omega - wc)
    top = 2.0 * max((d_m - d) / d * (omega - wc), (d_m + d) / d * wc) + 1e-9 * omega
    v0 = SLIDE_SCALE
    lo = np.full(model.n_rollers, math.asinh((u_ri - top * half_d) / v0))
    hi = np.full(model.n_rollers, math.asinh((u_ri - 1e-12 * omega * half_d) / v0))
    for _ in range(200):
        if np.all(hi - lo <= np.spacing(np.maximum(np.abs(lo), np.abs(hi)))):
            break
        mid = 0.5 * (lo + hi)
        r = evaluate_slides(model, omega, v0 * np.sinh(mid), delta, inner_load, fb, psi,
                            acc)[0].roller_eq
        # the balance rises with V_i: a positive residual puts the root below mid
        hi = np.where(r > 0.0, mid, hi)
        lo = np.where(r > 0.0, lo, mid)
    return v0 * np.sinh(0.5 * (lo + hi))


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
    range or Brent fails.
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
    for _outer in range(4):
        ld, fb = loads(wc_guess, tuple(ld.ring_displacement))
        mg = _gapped(model, ld)

        def cage(tau: float, mg: RollerModel = mg, ld: Any = ld, fb: np.ndarray = fb) -> float:
            delta = d0 * math.sinh(tau)
            v_i = _roller_slides(mg, omega, delta, ld.inner_load, fb, psi, acc)
            return evaluate_slides(mg, omega, v_i, delta, ld.inner_load, fb, psi,
                                   acc)[0].cage_eq

        if not (cage(tau_lo) > 0.0 > cage(tau_hi)):
            return None
        tau, info = brentq(cage, tau_lo, tau_hi, xtol=1e-300, rtol=4.0 * np.finfo(float).eps,
                           maxiter=400, full_output=True, disp=False)
        if not info.converged:
            return None
        delta = d0 * math.sinh(tau)
        v_i = _roller_slides(mg, omega, delta, ld.inner_load, fb, psi, acc)
        e, x = evaluate_slides(mg, omega, v_i, delta, ld.inner_load, fb, psi, acc)
        found = (x, e, ld)
        done = abs(x[-1] - wc_guess) <= 1e-8 * omega
        wc_guess = float(x[-1])
        if done:
            break
    x, e, ld = found
    res = np.append(e.roller_eq, e.cage_eq)
    scale = (force_scale(ld.inner_load) if force_scale is not None
             else max(float(np.max(ld.inner_load, initial=0.0)), 1e-3))
    return x, e, float(np.linalg.norm(res)) / scale, ld
