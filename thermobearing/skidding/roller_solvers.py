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
equation (:func:`_nested`), started around the best Newton iterate; a stalled iterate within
the round-off floor of every equation (:func:`_newton_floor`) needs no fallback, provided
its shaft power equals its dissipation to 1e-6 (else the film is stuck below one ulp of the
slides and :mod:`~thermobearing.skidding.roller_slides` solves in the slides). The outer
fixed point for the centrifugal loads and the errors
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


def _force_scale(model: RollerModel, omega: float, inner_load: np.ndarray) -> float:
    """Force [N] scaling Newton's residual norm: the largest inner load, or 5 % of a roller's
    centrifugal force at the inner speed when larger (light loads, high speed)."""
    return max(float(np.max(inner_load, initial=0.0)),
               model.roller_mass * 0.5 * model.pitch_diameter * omega**2 * 0.05, 1e-3)


def _newton(model: RollerModel, omega: float, x0: np.ndarray, inner_load: np.ndarray,
            fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float], *, tol: float,
            max_iter: int, fd_step: float = 1e-7) -> tuple[np.ndarray, _Eval, float, int, bool]:
    """Newton with the arrow-structured FD Jacobian and backtracking. x = (omega_r, omega_c).

    ``fd_step``: forward-difference step as a fraction of the inner-ring speed. Near pure
    rolling under load the Hertz-zone tractions saturate within a slip of order 1e-7, so the
    default step spans the saturation and the secant Jacobian stalls Newton; 1e-10 resolves
    it (:func:`~thermobearing.skidding.roller.solve_model` retries with it before the
    bracketed fallback).

    Stall rule: Newton stops when ten iterations have not lowered the norm by 10 % (the line
    search then accepts steps of ~1e-4 relative decrease: measured, a catalogue NU 206 at
    6 kN and 20 degC crept through 60 such iterations at ~15 evaluations each without
    leaving 2.1e-3)."""
    z = model.n_rollers
    force_scale = _force_scale(model, omega, inner_load)

    def ev(x: np.ndarray) -> tuple[_Eval, np.ndarray, np.ndarray]:
        e = evaluate(model, omega, x[:z], x[z], inner_load, fb, psi, acc)
        r = np.append(e.roller_eq, e.cage_eq) / force_scale
        return e, r, e.cage_terms

    x = np.array(x0, dtype=float)
    e, r, pk = ev(x)
    norm = float(np.linalg.norm(r))
    it = 0
    history = [norm]
    h = fd_step * omega
    while norm > tol and it < max_iter:
        if it >= 10 and norm > 0.9 * history[it - 10]:
            break
        it += 1
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
        history.append(norm)
    return x, e, norm, it, norm <= tol


def initial_guess(model: RollerModel, omega: float, cage_ratio: float | None = None) -> np.ndarray:
    """Cage at ``cage_ratio`` (default 0.8 of the theoretical CSR), rollers rolling on the
    outer race (paper 000's unloaded-zone assumption)."""
    csr = model.theoretical_cage_speed_ratio * (0.8 if cage_ratio is None else cage_ratio)
    wc = csr * omega
    wr = (model.pitch_diameter + model.roller_diameter) / model.roller_diameter * wc
    return np.append(np.full(model.n_rollers, wr), wc)


def _roller_speeds(model: RollerModel, omega: float, wc: float, inner_load: np.ndarray,
                   fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float],
                   guess: np.ndarray | None = None) -> np.ndarray:
    """Roller spins solving each roller's moment balance at a given cage speed (bisection).

    The moment balance falls monotonically with the roller's own spin (the tractions fall,
    the pocket friction rises), and the rollers couple only through the cage speed, so all
    rollers are bracketed at once, from (1e-12 omega, ``top``) down to a width of
    ``top`` 2^-56 (~1.4e-17 of the top speed). ``guess`` (Z,) [rad/s]: the spins of a nearby
    state (e.g. the previous cage iterate); each roller's bracket then starts at
    guess +- 1e-9 omega and widens 16-fold per round (either way, clipped to the full
    bracket) until it holds the sign change: ~26 residual evaluations instead of 56 for the
    same final width. The bisection also ends when every bracket is down to two adjacent
    floats (spins above ~2^-56 ``top`` / 2^-52, the usual case: the last halvings cannot
    move it).
    """
    d_m, d = model.pitch_diameter, model.roller_diameter
    top = 2.0 * max((d_m - d) / d * (omega - wc), (d_m + d) / d * wc) + 1e-9 * omega
    bottom = 1e-12 * omega
    lo = np.full(model.n_rollers, bottom)
    hi = np.full(model.n_rollers, top)

    def eq(w: np.ndarray) -> np.ndarray:
        return evaluate(model, omega, w, wc, inner_load, fb, psi, acc).roller_eq

    if guess is not None and np.all(np.isfinite(guess)):
        g = np.clip(np.asarray(guess, dtype=float), bottom, top)
        a = np.maximum(g - 1e-9 * omega, bottom)
        b = np.minimum(g + 1e-9 * omega, top)
        for _ in range(16):
            r_a, r_b = eq(a), eq(b)
            below = ~(r_a > 0.0) & (a > bottom)  # root below a
            above = (r_b > 0.0) & ~below & (b < top)  # root above b
            if not (np.any(below) or np.any(above)):
                break
            width = b - a
            a, b = (np.where(below, np.maximum(a - 16.0 * width, bottom),
                             np.where(above, b, a)),
                    np.where(below, a, np.where(above, np.minimum(b + 16.0 * width, top), b)))
        else:
            below = above = np.ones(model.n_rollers, dtype=bool)
        ok = ~(below | above)
        lo, hi = np.where(ok, a, lo), np.where(ok, b, hi)
    width_end = top * 2.0**-56
    for _ in range(56):
        # done at the final width, or where the bracket is down to adjacent floats
        if np.all(hi - lo <= np.maximum(width_end, np.spacing(hi))):
            break
        mid = 0.5 * (lo + hi)
        r = eq(mid)
        lo = np.where(r > 0.0, mid, lo)
        hi = np.where(r > 0.0, hi, mid)
    return 0.5 * (lo + hi)


def _cage_bracket(cage: Callable[[float], float], wc0: float | None, lo_c: float,
                  hi_c: float) -> tuple[float, float, float, float]:
    """A bracket (lo, hi, f(lo), f(hi)) of the falling cage equation: from ``wc0`` first, else
    the full (lo_c, hi_c).

    ``wc0`` is one end and the other is 1e-12 of it away on the side of the root (above when
    f(wc0) > 0); while the sign change is missing the bracket moves on, 16 times as wide per
    round, clipped to (lo_c, hi_c). A Newton iterate stalled near pure rolling is within a
    few 1e-12 of the root. Measured (benchmarks/bm_roller_cold.py points, cold starts): the
    catalogue NU 206 at 6 kN / 500 r/min / 20 degC and 13 kN / 2000 r/min / 60 degC, whose
    iterates are 2.0e-13 and 1.5e-12 of the cage speed below the root, take 6 and 7 cage
    evaluations (bracket and brentq) against 11 and 8 for a bracket of +- 1e-10 around
    ``wc0``: 334 and 373 residual evaluations per bracketed solve instead of 474 and 405,
    832 and 872 per cold solve instead of 972 and 904; CPU of the bracketed solve alone
    0.250 / 0.280 s against 0.353 / 0.307 s (medians of 20 alternated pairs, pair ratios
    1.40x and 1.09x), of the cold solve 1.15x and 1.04x (medians of 20 pairs, load ~2).
    Five heavy points accepted at the round-off floor (NU 206 13 kN at 20 degC, NU214
    45 kN), forced through the bracketed solve: 242-478 residual evaluations instead of
    292-698. The root is the same to 1.1e-15 (CSR and roller speeds). These counts include
    brentq's second evaluation of the two ends; :func:`_nested` takes those values from the
    bracket instead (2 cage evaluations fewer, see there). Both together, at the 8 NU 206
    points of the full benchmark that take the bracketed solve (6 kN at 20 degC and 13 kN
    at 60 degC, 500-30000 r/min): 776-901 residual evaluations per cold solve instead of
    879-1065, CPU 1.09-1.28x (medians of 6 alternated pairs per point, 1.20x in total),
    states within 1.1e-14."""
    if wc0 is not None and lo_c < wc0 < hi_c:
        f0 = cage(wc0)
        if f0 > 0.0:
            a, f_a = wc0, f0
            b = min(wc0 + 1e-12 * wc0, hi_c)
            f_b = cage(b)
        else:
            b, f_b = wc0, f0
            a = max(wc0 - 1e-12 * wc0, lo_c)
            f_a = cage(a)
        for _ in range(10):
            if f_a > 0.0 > f_b:
                return a, b, f_a, f_b
            width = b - a
            if not f_a > 0.0:
                a, b, f_b = max(a - 16.0 * width, lo_c), a, f_a
                f_a = cage(a)
            else:
                a, b, f_a = b, min(b + 16.0 * width, hi_c), f_b
                f_b = cage(b)
    return lo_c, hi_c, cage(lo_c), cage(hi_c)


def _nested(model: RollerModel, omega: float, loads: Callable[..., Any], psi: np.ndarray,
            acc: tuple[float, float], tol: float, max_iter: int, ld0: Any,
            wc0: float | None = None, wr0: np.ndarray | None = None,
            wc_loads: float | None = None
            ) -> tuple[np.ndarray, _Eval, float, int, bool, Any, float]:
    """Bracketed fallback: Brent on the cage equation with bisected roller spins.

    ``wc0``, ``wr0``: the cage and roller speeds of the best Newton iterate: the cage bracket
    starts at ``wc0`` (:func:`_cage_bracket`) and each roller bisection around the spins
    of the previous cage iterate (:func:`_roller_speeds`); the root is the same (the cage
    equation falls monotonically with the cage speed), found with ~10x fewer residual
    evaluations. The outer fixed point on the centrifugal loads ends when Brent's root is
    within 1e-8 omega of the cage speed the loads were computed at. Without ``wc0`` the
    bracket is the whole cage-speed range and the first loads are taken at ``wc_loads``
    (e.g. the cold guess; default the bottom of the range).

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
    spins = [None if wr0 is None else np.array(wr0, dtype=float)]
    for _outer in range(4):
        start = first if first is not None else wc_loads
        wc_guess = (start if start is not None and 0 < start < omega else lo_c) \
            if wc is None else wc
        ld, fb = loads(wc_guess, tuple(ld.ring_displacement))
        mg = _gapped(model, ld)
        known: dict[float, tuple[float, np.ndarray]] = {}

        def cage(w: float, ld: Any = ld, fb: np.ndarray = fb, mg: RollerModel = mg,
                 known: dict[float, tuple[float, np.ndarray]] = known) -> float:
            # brentq evaluates the ends of the bracket again: their values are kept
            # (NU 206 points of _cage_bracket: 278 / 317 residual evaluations per bracketed
            # solve instead of 334 / 373, CPU 1.19x / 1.15x alone and 1.09x / 1.05x for the
            # cold solve, medians of 20 alternated pairs; the same state to the last bit)
            if w in known:
                f, spins[0] = known[w]
                return f
            wr = _roller_speeds(mg, omega, w, ld.inner_load, fb, psi, acc, spins[0])
            spins[0] = wr
            f = evaluate(mg, omega, wr, w, ld.inner_load, fb, psi, acc).cage_eq
            known[w] = (f, wr)
            return f

        a, b, f_a, f_b = _cage_bracket(cage, wc_guess if first is not None else None,
                                       lo_c, hi_c)
        if not (f_a > 0.0 > f_b):
            break
        wc_new, info = brentq(cage, a, b, xtol=1e-15 * omega, rtol=8.9e-16, maxiter=200,
                              full_output=True, disp=False)
        if not info.converged:
            wc = None
            break
        done = abs(wc_new - wc_guess) <= 1e-8 * omega
        wc = wc_new
        if done:
            break
    if wc is None:
        x = np.append(np.zeros(z), 0.0)
        return x, None, math.inf, 0, False, ld, math.inf
    model = _gapped(model, ld)
    wr = _roller_speeds(model, omega, wc, ld.inner_load, fb, psi, acc, spins[0])
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
    # is, only when it is within that round-off floor (NU214 at 100 kN: with an xtol of
    # 1e-10 omega Brent left 0.18, which a looser rule accepted; with 1e-15 omega 4e-6)
    floor = _round_off_floor(model, omega, wr, wc, ld.inner_load, fb, psi, acc) / force_scale
    return x, e, norm, it, norm <= max(tol, 4.0 * floor), ld, floor


def _newton_floor(model: RollerModel, omega: float, wr: np.ndarray, wc: float,
                  inner_load: np.ndarray, fb: np.ndarray, psi: np.ndarray,
                  acc: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Round-off floor of each equation [N] ((Z + 1,), rollers then cage) at the cage speed
    ``wc`` of a stalled Newton iterate, and the roller spins solving their moment balances
    at ``wc`` (Z,) [rad/s]: (spins, floors).

    The rollers are re-solved at ``wc`` by bisection (started around the iterate's spins
    ``wr``) and :func:`_round_off_changes` is taken there, so the floor measures the local
    stiffness only and not the iterate's own residual. Near pure rolling under heavy load
    the cage equation changes by ~0.1 N per 1e-12 of the cage speed (NU214, 45 kN,
    8000 r/min): one ulp of the speeds changes the residual by more than ``tol`` allows,
    Newton stalls within a few ulps of the root, and its iterate is as good as the bracketed
    root when every equation is within a few of its own floor. Per equation, not the norm:
    a catalogue NU 206 at 13 kN, 20 degC had a Newton iterate whose norm was within the
    floor of the stiff loaded rollers while its unloaded rollers turned 60x too fast.
    """
    wr_root = _roller_speeds(model, omega, wc, inner_load, fb, psi, acc, wr)
    return wr_root, _round_off_changes(model, omega, wr_root, wc, inner_load, fb, psi, acc)


def _round_off_changes(model: RollerModel, omega: float, wr: np.ndarray, wc: float,
                       inner_load: np.ndarray, fb: np.ndarray, psi: np.ndarray,
                       acc: tuple[float, float]) -> np.ndarray:
    """Largest change of each residual [N] ((Z + 1,)) when the cage speed (rollers
    re-solved) or every roller speed moves to its neighbouring float (either way)."""
    e0 = evaluate(model, omega, wr, wc, inner_load, fb, psi, acc)
    r0 = np.append(e0.roller_eq, e0.cage_eq)
    worst = np.zeros_like(r0)
    for direction in (-np.inf, np.inf):
        w = float(np.nextafter(wc, direction))
        wr_w = _roller_speeds(model, omega, w, inner_load, fb, psi, acc, wr)
        ew = evaluate(model, omega, wr_w, w, inner_load, fb, psi, acc)
        worst = np.maximum(worst, np.abs(np.append(ew.roller_eq, ew.cage_eq) - r0))
        er = evaluate(model, omega, np.nextafter(wr, direction), wc, inner_load, fb, psi, acc)
        worst = np.maximum(worst, np.abs(np.append(er.roller_eq, er.cage_eq) - r0))
    return worst


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
        wr_w = _roller_speeds(model, omega, w, inner_load, fb, psi, acc, wr)
        ew = evaluate(model, omega, wr_w, w, inner_load, fb, psi, acc)
        worst = max(worst, float(np.linalg.norm(np.append(ew.roller_eq, ew.cage_eq) - r0)))
        er = evaluate(model, omega, np.nextafter(wr, direction), wc, inner_load, fb, psi, acc)
        worst = max(worst, float(np.linalg.norm(np.append(er.roller_eq, er.cage_eq) - r0)))
    return worst
