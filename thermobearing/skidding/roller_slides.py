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
with its spin) and the cage equation falls with delta, as in the speed form: every roller's
balance and the cage equation are solved in a bracket to adjacent floats of the unknown
(:func:`_bracketed_roots`: false position, bisection in t = asinh(V_i / v_0) and
tau = asinh(delta / delta_0) as the safeguard), so that slides and offsets are resolved
relative to their own size down to v_0 = 1e-40 m/s (delta_0 = 1e-40 omega), not to the ulp
of the speeds. The rollers start around their slides at the nearest offset already solved,
the cage bracket around the start's offset (e.g. the refused Newton iterate's).
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


def _warm_bracket(eq: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray,
                  guess: np.ndarray, width: float = 1e-6
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Brackets (a, b, eq(a), eq(b)) (Z,) [m/s, N] of the roots of the rising ``eq(y)``
    inside [lo, hi] (eq(lo) <= 0 < eq(hi) taken as given, as :func:`_bracketed_roots` does; their
    values are NaN), started around ``guess`` (Z,) [m/s] (the slides of a nearby cage
    offset): in t = asinh(y / v_0), t_g -+ ``width`` (at least 16 spacings of t_g), then 16
    times as wide per round on the side of the root (one evaluation per round, every roller
    at its own probe; rollers already bracketed are halved by it), clipped to [lo, hi].

    In t a half-width w is a relative change of the slide of about w (|y| >> v_0), so a
    guess off by a factor F costs about log_16 F rounds."""
    v0 = SLIDE_SCALE
    t_min, t_max = np.arcsinh(lo / v0), np.arcsinh(hi / v0)
    t_g = np.clip(np.arcsinh(np.asarray(guess, dtype=float) / v0), t_min, t_max)
    w = np.maximum(width, 16.0 * np.spacing(np.abs(t_g)))
    a, b = np.maximum(t_g - w, t_min), np.minimum(t_g + w, t_max)
    # both ends of the first bracket (a clipped end is taken as given, value NaN)
    f_a = np.where(a > t_min, eq(v0 * np.sinh(a)), np.nan)
    f_b = np.where(b < t_max, eq(v0 * np.sinh(b)), np.nan)
    for _ in range(40):
        below = f_a > 0.0  # the root is below a
        above = ~(f_b > 0.0) & (b < t_max) & ~below  # eq(b) <= 0: the root is above b
        if not (np.any(below) or np.any(above)):
            break
        width_t = b - a
        new_a = np.maximum(a - 16.0 * width_t, t_min)
        new_b = np.minimum(b + 16.0 * width_t, t_max)
        probe = np.where(below, new_a, np.where(above, new_b, 0.5 * (a + b)))
        f = eq(v0 * np.sinh(probe))
        # expanding below: the old a (eq > 0) is the new b; above: the old b (eq <= 0) the
        # new a; bracketed: the probe halves the bracket
        inside = ~below & ~above
        lower = inside & ~(f > 0.0)
        upper = inside & (f > 0.0)
        a, b, f_a, f_b = (
            np.where(below, new_a, np.where(above, b, np.where(lower, probe, a))),
            np.where(below, a, np.where(above, new_b, np.where(upper, probe, b))),
            np.where(below, np.where(new_a > t_min, f, np.nan),
                     np.where(above, f_b, np.where(lower, f, f_a))),
            np.where(below, f_a, np.where(above, np.where(new_b < t_max, f, np.nan),
                                          np.where(upper, f, f_b))))
    else:
        return lo, hi, np.full(lo.shape, np.nan), np.full(hi.shape, np.nan)
    return (np.where(a > t_min, v0 * np.sinh(a), lo), np.where(b < t_max, v0 * np.sinh(b), hi),
            f_a, f_b)


def _bracketed_roots(eq: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray,
                     active: np.ndarray, guess: np.ndarray | None = None,
                     width: float = 1e-6, ends: tuple[np.ndarray, np.ndarray] | None = None,
                     scale: float = SLIDE_SCALE) -> np.ndarray:
    """Roots (Z,) of the rising ``eq(y)`` bracketed by [lo, hi] (eq(lo) <= 0 < eq(hi)) for
    the ``active`` entries, all at once, each to the sign change of ``eq`` between adjacent
    floats of y (the midpoint of that pair).

    Each bracket shrinks by one evaluation per step (all entries in one call of ``eq``):
    by false position in y with the Anderson-Bjoerck weight on an end kept twice in a row
    where both ends' values are known, else (and whenever two such steps have not halved
    the bracket in t = asinh(y / ``scale``)) by bisection: in t while the bracket spans more
    than a factor 2 or holds 0 (slides from 1e-40 to 1 m/s), in y inside a narrower one;
    until the two ends are adjacent floats. The sign-change pair of a monotone ``eq`` is
    the same for any bracket and path. Bisection alone took one step per bit (53 in t over
    the full range, then ~12 in y, ~65 evaluations per roller solve); false position takes
    a few from a bracket ~1e-3 wide relative (the balances are smooth in the slides: a cold
    film shears as a Newtonian one at these slides). ``guess`` (Z,): start from brackets
    around it (:func:`_warm_bracket`, ``width`` in t); ``ends``: (eq(lo), eq(hi)) when
    known (NaN: not known)."""
    v0 = scale
    if guess is not None and np.all(np.isfinite(guess)):
        a, b, f_a, f_b = _warm_bracket(eq, lo, hi, guess, width)
    else:
        a, b = np.array(lo, dtype=float), np.array(hi, dtype=float)
        f_a, f_b = ((np.full(a.shape, np.nan), np.full(b.shape, np.nan)) if ends is None
                    else (np.array(ends[0], dtype=float), np.array(ends[1], dtype=float)))
    kept = np.zeros(a.shape)  # +1: b was replaced last (a kept), -1: a was replaced last
    n_fp = np.zeros(a.shape, dtype=int)  # false-position steps since the reference width
    w_ref = np.arcsinh(b / v0) - np.arcsinh(a / v0)
    for _ in range(400):
        done = ~active | (b - a <= np.spacing(np.maximum(np.abs(a), np.abs(b))))
        if np.all(done):
            break
        y_mid = 0.5 * (a + b)
        t_a, t_b = np.arcsinh(a / v0), np.arcsinh(b / v0)
        t_mid = v0 * np.sinh(0.5 * (t_a + t_b))
        narrow = ((a > 0.0) & (b < 2.0 * a)) | ((b < 0.0) & (a > 2.0 * b))
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            fp = a - f_a * (b - a) / (f_b - f_a)
        # after a step that moved one end, past the false-position point by as much as it is
        # from that end (when that is inside the bracket): converging from one side, false
        # position leaves the far end, and the bracket, where they are; this lands beyond
        # the root and closes the bracket
        over = np.where(kept < 0.0, fp + (fp - a), np.where(kept > 0.0, fp - (b - fp), fp))
        fp = np.where((over > a) & (over < b), over, fp)
        # at least one float inside either end (f(a) = 0 exactly puts the point on a)
        fp = np.clip(fp, np.nextafter(a, np.inf), np.nextafter(b, -np.inf))
        use_fp = (np.isfinite(fp) & (f_a <= 0.0) & (f_b > 0.0) & (fp > a) & (fp < b)
                  & (n_fp < 2))
        bis = np.where(~narrow & (t_mid > a) & (t_mid < b), t_mid, y_mid)
        probe = np.where(done, y_mid, np.where(use_fp, fp, bis))
        f = eq(probe)
        up = (f > 0.0) & ~done
        dn = ~(f > 0.0) & ~done
        # Illinois: the end kept a second time in a row has its value halved (the next
        # point moves towards it: false position alone converges from one side and leaves
        # the far end, and the bracket, where they are)
        f_a = np.where(up & (kept > 0.0), 0.5 * f_a, f_a)
        f_b = np.where(dn & (kept < 0.0), 0.5 * f_b, f_b)
        a, f_a = np.where(dn, probe, a), np.where(dn, f, f_a)
        b, f_b = np.where(up, probe, b), np.where(up, f, f_b)
        kept = np.where(up, 1.0, np.where(dn, -1.0, kept))
        # two false-position steps that have not halved the bracket (in t): the next one
        # bisects
        width_now = np.arcsinh(b / v0) - np.arcsinh(a / v0)
        n_fp = np.where(use_fp & ~done, n_fp + 1, 0)
        halved = width_now <= 0.5 * w_ref
        n_fp = np.where(halved, 0, n_fp)
        w_ref = np.where(halved | ~use_fp, width_now, w_ref)
    return 0.5 * (a + b)


def _roller_slides(model: RollerModel, omega: float, delta: float, inner_load: np.ndarray,
                   fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float],
                   guess: np.ndarray | None = None, width: float = 1e-6
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Inner and outer slides (V_i, V_o) (Z,) [m/s] solving every roller's moment balance at
    the cage offset ``delta`` (:func:`_bracketed_roots`, which the balance rises with): first in V_i
    over the slides of spins from 1e-12 omega to twice the larger rolling spin (started
    around ``guess`` (Z,), the inner slides of a nearby offset, when given); then, for
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

    v_i = _bracketed_roots(eq_i, np.full(z, u_ri - top * half_d),
                  np.full(z, u_ri - 1e-12 * omega * half_d), np.ones(z, dtype=bool), guess, width)
    v_o = shift + v_i
    outer = np.abs(v_o) < np.abs(v_i)
    if not np.any(outer):
        return v_i, v_o
    pad = 8.0 * np.spacing(np.abs(v_i)) + 8.0 * np.spacing(abs(shift))
    lo_o, hi_o = v_o - pad, v_o + pad

    def eq_o(y: np.ndarray) -> np.ndarray:
        return evaluate_slides(model, omega, np.where(outer, y - shift, v_i), delta,
                               inner_load, fb, psi, acc, np.where(outer, y, v_o))[0].roller_eq

    f_lo, f_hi = eq_o(lo_o), eq_o(hi_o)
    ok = outer & (f_lo <= 0.0) & (f_hi > 0.0)
    if np.any(ok):
        y = _bracketed_roots(eq_o, lo_o, hi_o, ok, ends=(f_lo, f_hi))
        v_o = np.where(ok, y, v_o)
        v_i = np.where(ok, y - shift, v_i)
    return v_i, v_o


class _CageOffset:
    """The cage equation [N] of one load distribution as a function of the cage offset delta
    [rad/s], every roller put in moment balance there (:func:`_roller_slides`); memoised
    (the bracket search and the root finder may come back to an offset, the final state
    takes the root's slides) and warm-started: each roller's root finder starts around its
    slide at the known offset nearest in asinh(delta / d0) (:func:`_warm_bracket`), as wide
    as 4 times that distance in asinh."""

    def __init__(self, model: RollerModel, omega: float, inner_load: np.ndarray,
                 fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float], d0: float,
                 guess: np.ndarray | None = None) -> None:
        self.args = (model, omega)
        self.load_args = (inner_load, fb, psi, acc)
        self.d0 = d0
        self.guess = guess
        self.known: dict[float, tuple[float, np.ndarray, np.ndarray]] = {}

    def slides(self, delta: float) -> tuple[float, np.ndarray, np.ndarray]:
        """(cage equation [N], V_i (Z,), V_o (Z,) [m/s]) at the offset ``delta``."""
        delta = float(delta)
        if delta in self.known:
            return self.known[delta]
        guess, width = self.guess, 1e-6
        if self.known:
            t = math.asinh(delta / self.d0)
            near = min(self.known, key=lambda k: abs(math.asinh(k / self.d0) - t))
            guess = self.known[near][1]
            width = 4.0 * abs(math.asinh(near / self.d0) - t)
        model, omega = self.args
        v_i, v_o = _roller_slides(model, omega, delta, *self.load_args, guess, width)
        f = evaluate_slides(model, omega, v_i, delta, *self.load_args, v_o)[0].cage_eq
        self.known[delta] = (f, v_i, v_o)
        return self.known[delta]

    def __call__(self, delta: float) -> float:
        return self.slides(delta)[0]

    def rising(self, delta: np.ndarray) -> np.ndarray:
        """Minus the cage equation at the offset ``delta`` (1,) (it rises with delta)."""
        return -np.array([self(float(delta[0]))])

    def of_tau(self, tau: float) -> float:
        """The cage equation at delta = d0 sinh(tau)."""
        return self.slides(self.d0 * math.sinh(tau))[0]


def _offset_bracket(cage: Callable[[float], float], tau0: float, width: float,
                    tau_lo: float, tau_hi: float) -> tuple[float, float, float, float]:
    """A bracket (a, b, f(a), f(b)) in tau of the falling cage equation ``cage(tau)``:
    tau0 -+ ``width``, 16 times as wide per round on the side of the root, clipped to
    [tau_lo, tau_hi]; the caller checks the sign change (f(a) > 0 > f(b))."""
    a, b = max(tau0 - width, tau_lo), min(tau0 + width, tau_hi)
    f_a, f_b = cage(a), cage(b)
    for _ in range(24):
        if f_a > 0.0 > f_b or (a <= tau_lo and b >= tau_hi):
            break
        w = b - a
        if not f_a > 0.0:  # the root is below a
            a, b, f_b = max(a - 16.0 * w, tau_lo), a, f_a
            f_a = cage(a)
        else:  # f(b) >= 0: the root is above b
            a, b, f_a = b, min(b + 16.0 * w, tau_hi), f_b
            f_b = cage(b)
    return a, b, f_a, f_b


#: half-width in tau = asinh(delta / d0) of the first cage bracket around a known offset
#: (a relative change of the offset of about 1e-3)
OFFSET_WIDTH = 1e-3


def _start_tau(delta0: float, wc_th: float, d0: float) -> tuple[float, float]:
    """(tau0, half-width) of the first cage bracket from the offset ``delta0`` [rad/s] of a
    start (e.g. a stalled Newton iterate): around asinh(delta0 / d0), 1e-3 wide; an offset
    within 8 ulps of the epicyclic speed says only that the root is that near pure rolling
    (its sign and size are below the speeds' round-off): around 0, as wide as 8 ulps."""
    ulps = 8.0 * float(np.spacing(abs(wc_th)))
    if abs(delta0) <= ulps:
        return 0.0, math.asinh(ulps / d0)
    return math.asinh(delta0 / d0), OFFSET_WIDTH


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
    range or the loads do not settle within the 4 passes.

    The cage offset: bracketed in tau = asinh(delta / d0) (d0 = 1e-40 omega) around the
    start's offset (:func:`_start_tau`, :func:`_offset_bracket`; the whole cage-speed range
    without ``wc0``), later passes around the previous pass's root, then solved to adjacent
    floats of delta by :func:`_bracketed_roots` (false position in delta with bisection in
    tau as the safeguard) with the rollers warm-started (:class:`_CageOffset`).
    """
    csr_th = model.theoretical_cage_speed_ratio
    wc_th = csr_th * omega
    d0 = SLIDE_SCALE * omega
    tau_lo = math.asinh((1e-6 * csr_th * omega - wc_th) / d0)
    tau_hi = math.asinh((min(0.999, 1.5 * csr_th) * omega - wc_th) / d0)
    ld = ld0
    wc_guess = wc_th if wc0 is None else float(wc0)
    # the first cage bracket: the whole range without a start, else around the start's
    # offset; later passes (loads at the new cage speed) around the previous root
    start = None if wc0 is None else _start_tau(wc_guess - wc_th, wc_th, d0)
    guess = None  # the roller slides of the previous pass's root
    found = None
    done = False
    for _outer in range(4):
        ld, fb = loads(wc_guess, tuple(ld.ring_displacement))
        mg = _gapped(model, ld)
        cage = _CageOffset(mg, omega, ld.inner_load, fb, psi, acc, d0, guess)
        if start is None:
            a, b, f_a, f_b = tau_lo, tau_hi, cage.of_tau(tau_lo), cage.of_tau(tau_hi)
        else:
            a, b, f_a, f_b = _offset_bracket(cage.of_tau, *start, tau_lo, tau_hi)
        if not (f_a > 0.0 > f_b):
            return None
        # the cage equation falls with delta: the root of -cage, from the bracket's values
        d_a, d_b = d0 * math.sinh(a), d0 * math.sinh(b)
        delta = float(_bracketed_roots(cage.rising,
                                       np.array([d_a]), np.array([d_b]),
                                       np.ones(1, dtype=bool),
                                       ends=(np.array([-f_a]), np.array([-f_b])),
                                       scale=d0)[0])
        _f, v_i, v_o = cage.slides(delta)
        e, x = evaluate_slides(mg, omega, v_i, delta, ld.inner_load, fb, psi, acc, v_o)
        found = (x, e, ld)
        done = abs(x[-1] - wc_guess) <= 1e-8 * omega
        wc_guess = float(x[-1])
        start, guess = (math.asinh(delta / d0), OFFSET_WIDTH), v_i
        if done:
            break
    if not done:
        return None  # the loads did not settle at the cage speed within 4 passes
    x, e, ld = found
    res = np.append(e.roller_eq, e.cage_eq)
    scale = (force_scale(ld.inner_load) if force_scale is not None
             else max(float(np.max(ld.inner_load, initial=0.0)), 1e-3))
    return x, e, float(np.linalg.norm(res)) / scale, ld
