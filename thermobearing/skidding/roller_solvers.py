"""Numerical solvers of the Z + 1 roller skidding equations (paper 000).

One job: find the roller and cage speeds that zero the residuals of
:func:`thermobearing.skidding.roller_residual.evaluate` (Li, Chen, Zhang, Wang 2018, seed
``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding]) at a fixed load distribution.

Numerics: Newton-Raphson on the Z + 1 equations with a structured finite-difference
Jacobian (roller blocks are scalar and coupled only through the cage: an "arrow" matrix,
two extra residual evaluations per iteration, eliminated in O(Z)), backtracking line
search, warm starts (:func:`initial_guess`). When Newton stalls (heavy loads: the tractions
saturate within a tiny slip and the cage equation jumps across pure rolling) a bracketed
fallback solves each roller's moment balance by bisection inside a Brent solve of the cage
equation (:func:`_nested`). The outer fixed point for the centrifugal loads and the errors
are in :func:`thermobearing.skidding.roller.solve_model`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .roller_loads import _gapped
from .roller_model import RollerModel
from .roller_residual import _Eval, evaluate


def _newton(model: RollerModel, omega: float, x0: np.ndarray, inner_load: np.ndarray,
            fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float], *, tol: float,
            max_iter: int, fd_step: float = 1e-7) -> tuple[np.ndarray, _Eval, float, int, bool]:
    """Newton with the arrow-structured FD Jacobian and backtracking. x = (omega_r, omega_c).

    ``fd_step``: forward-difference step as a fraction of the inner-ring speed. Near pure
    rolling under load the Hertz-zone tractions saturate within a slip of order 1e-7, so the
    default step spans the saturation and the secant Jacobian stalls Newton; 1e-10 resolves
    it (:func:`~thermobearing.skidding.roller.solve_model` retries with it before the
    bracketed fallback)."""
    z = model.n_rollers
    force_scale = max(float(np.max(inner_load, initial=0.0)),
                      model.roller_mass * 0.5 * model.pitch_diameter * omega**2 * 0.05, 1e-3)

    def ev(x: np.ndarray) -> tuple[_Eval, np.ndarray, np.ndarray]:
        e = evaluate(model, omega, x[:z], x[z], inner_load, fb, psi, acc)
        r = np.append(e.roller_eq, e.cage_eq) / force_scale
        return e, r, e.cage_terms

    x = np.array(x0, dtype=float)
    e, r, pk = ev(x)
    norm = float(np.linalg.norm(r))
    it = 0
    while norm > tol and it < max_iter:
        it += 1
        h = fd_step * omega
        xp = x.copy()
        xp[:z] += h
        _, rp, pkp = ev(xp)
        diag = (rp[:z] - r[:z]) / h
        c_row = (pkp - pk) / (h * force_scale)
        xq = x.copy()
        xq[z] += h
        _, rq, _ = ev(xq)
        b_col = (rq[:z] - r[:z]) / h
        d_cc = (rq[z] - r[z]) / h
        diag = np.where(np.abs(diag) > 1e-300, diag, 1e-300)
        denom = d_cc - np.sum(c_row * b_col / diag)
        if not np.isfinite(denom) or denom == 0.0:
            break
        dwc = (-r[z] + np.sum(c_row * r[:z] / diag)) / denom
        dwr = (-r[:z] - b_col * dwc) / diag
        step = np.append(dwr, dwc)
        # keep the cage inside (0, omega) and the rollers turning forward
        lam = 1.0
        limit = 0.5 * omega
        big = np.max(np.abs(step) / limit)
        if big > 1.0:
            lam = 1.0 / big
        accepted = False
        for _ in range(30):
            xn = x + lam * step
            if 0.0 < xn[z] < omega and np.all(xn[:z] > 0.0):
                en, rn, pkn = ev(xn)
                nn = float(np.linalg.norm(rn))
                if np.isfinite(nn) and nn < (1.0 - 1e-4 * lam) * norm:
                    accepted = True
                    break
            lam *= 0.5
        if not accepted:
            break
        x, e, r, pk, norm = xn, en, rn, pkn, nn
    return x, e, norm, it, norm <= tol


def initial_guess(model: RollerModel, omega: float, cage_ratio: float | None = None) -> np.ndarray:
    """Cage at ``cage_ratio`` (default 0.8 of the theoretical CSR), rollers rolling on the
    outer race (paper 000's unloaded-zone assumption)."""
    csr = model.theoretical_cage_speed_ratio * (0.8 if cage_ratio is None else cage_ratio)
    wc = csr * omega
    wr = (model.pitch_diameter + model.roller_diameter) / model.roller_diameter * wc
    return np.append(np.full(model.n_rollers, wr), wc)


def _roller_speeds(model: RollerModel, omega: float, wc: float, inner_load: np.ndarray,
                   fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float]) -> np.ndarray:
    """Roller spins solving each roller's moment balance at a given cage speed (bisection).

    The moment balance falls monotonically with the roller's own spin (the tractions fall,
    the pocket friction rises), and the rollers couple only through the cage speed, so all
    rollers are bracketed at once.
    """
    d_m, d = model.pitch_diameter, model.roller_diameter
    top = 2.0 * max((d_m - d) / d * (omega - wc), (d_m + d) / d * wc) + 1e-9 * omega
    lo = np.full(model.n_rollers, 1e-12 * omega)
    hi = np.full(model.n_rollers, top)
    for _ in range(56):  # bracket width 2^-56 ~ 1.4e-17 of the top speed
        mid = 0.5 * (lo + hi)
        r = evaluate(model, omega, mid, wc, inner_load, fb, psi, acc).roller_eq
        lo = np.where(r > 0.0, mid, lo)
        hi = np.where(r > 0.0, hi, mid)
    return 0.5 * (lo + hi)


def _nested(model: RollerModel, omega: float, loads: Callable[..., Any], psi: np.ndarray,
            acc: tuple[float, float], tol: float, max_iter: int, ld0: Any,
            wc0: float | None = None) -> tuple[np.ndarray, _Eval, float, int, bool, Any, float]:
    """Bracketed fallback: Brent on the cage equation with bisected roller spins.

    Returns (x, eval, norm, iterations, ok, load distribution, floor): ``floor`` is the
    scaled residual norm one-ulp changes of the speeds make at the bracketed root
    (:func:`_round_off_floor` / force scale; 0 when the Newton polish met ``tol``). A
    bracketed state is ``ok`` when its norm is below max(tol, 4 floor).
    """
    from scipy.optimize import brentq

    z = model.n_rollers
    ld, fb = ld0, None
    wc = None
    first = wc0
    csr_th = model.theoretical_cage_speed_ratio
    lo_c, hi_c = 1e-6 * csr_th * omega, min(0.999, 1.5 * csr_th) * omega
    for _outer in range(4):
        wc_guess = (first if first is not None and 0 < first < omega else lo_c) \
            if wc is None else wc
        ld, fb = loads(wc_guess, tuple(ld.ring_displacement))
        mg = _gapped(model, ld)

        def cage(w: float, ld: Any = ld, fb: np.ndarray = fb, mg: RollerModel = mg) -> float:
            wr = _roller_speeds(mg, omega, w, ld.inner_load, fb, psi, acc)
            return evaluate(mg, omega, wr, w, ld.inner_load, fb, psi, acc).cage_eq

        f_lo, f_hi = cage(lo_c), cage(hi_c)
        if not (f_lo > 0.0 > f_hi):
            break
        wc_new, info = brentq(cage, lo_c, hi_c, xtol=1e-15 * omega, rtol=8.9e-16, maxiter=200,
                              full_output=True, disp=False)
        if not info.converged:
            wc = None
            break
        done = wc is not None and abs(wc_new - wc) <= 1e-8 * omega
        wc = wc_new
        if done:
            break
    if wc is None:
        x = np.append(np.zeros(z), 0.0)
        return x, None, math.inf, 0, False, ld, math.inf
    model = _gapped(model, ld)
    wr = _roller_speeds(model, omega, wc, ld.inner_load, fb, psi, acc)
    x = np.append(wr, wc)
    xp, e, norm, it, ok = _newton(model, omega, x, ld.inner_load, fb, psi, acc, tol=tol,
                                  max_iter=max_iter)
    if ok:
        return xp, e, norm, it, ok, ld, 0.0
    e = evaluate(model, omega, wr, wc, ld.inner_load, fb, psi, acc)
    force_scale = max(float(np.max(ld.inner_load, initial=0.0)), 1e-3)
    norm = float(np.linalg.norm(np.append(e.roller_eq, e.cage_eq))) / force_scale
    # bracketed to round-off (Brent to a few ulps of the cage speed, rollers bisected to the
    # last bit): the residual left is what the stiffness of saturated tractions makes of
    # round-off changes of the speeds (heavy loads: near pure rolling the tractions change
    # by kN over 1e-11 of the inner speed). Accepted, with the residual norm reported as it
    # is, only when it is within that round-off floor (robustness session 10: Brent's old
    # xtol of 1e-10 omega left 0.18 at 100 kN on the NU214 and that was accepted; now 4e-6)
    floor = _round_off_floor(model, omega, wr, wc, ld.inner_load, fb, psi, acc) / force_scale
    return x, e, norm, it, norm <= max(tol, 4.0 * floor), ld, floor


def _round_off_floor(model: RollerModel, omega: float, wr: np.ndarray, wc: float,
                     inner_load: np.ndarray, fb: np.ndarray, psi: np.ndarray,
                     acc: tuple[float, float]) -> float:
    """Residual norm [N] that one-ulp changes of the speeds make at (wr, wc): the size of the
    residual change when the cage speed (rollers re-solved) or every roller speed moves to
    its neighbouring float -- the smallest residual a bracketing solve can promise there."""
    e0 = evaluate(model, omega, wr, wc, inner_load, fb, psi, acc)
    r0 = np.append(e0.roller_eq, e0.cage_eq)
    worst = 0.0
    for direction in (-np.inf, np.inf):
        w = float(np.nextafter(wc, direction))
        wr_w = _roller_speeds(model, omega, w, inner_load, fb, psi, acc)
        ew = evaluate(model, omega, wr_w, w, inner_load, fb, psi, acc)
        worst = max(worst, float(np.linalg.norm(np.append(ew.roller_eq, ew.cage_eq) - r0)))
        er = evaluate(model, omega, np.nextafter(wr, direction), wc, inner_load, fb, psi, acc)
        worst = max(worst, float(np.linalg.norm(np.append(er.roller_eq, er.cage_eq) - r0)))
    return worst
