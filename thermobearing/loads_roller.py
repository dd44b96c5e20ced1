"""Quasi-static load distribution of a radially loaded cylindrical roller bearing.

Harris & Kotzalas (2007; vol. 1, internal load distribution; vol. 2, high-speed operation)
treat a cylindrical roller bearing under a radial load ``F_r``
with diametral clearance ``P_d``: the inner ring moves by ``delta_r`` and the roller at
azimuth ``psi_j`` is squeezed by

    delta_j = delta_x cos(psi_j) + delta_y sin(psi_j) - P_d / 2          (interference)

shared between its inner and outer contacts, ``delta_j = delta_ij + delta_oj``. Each roller
is in radial equilibrium

    Q_oj - Q_ij = F_j                                                   (1)

where ``F_j`` is the outward body force on the roller: the centrifugal force
``F_c = m_r (d_m / 2) omega_c^2`` (Harris & Kotzalas vol. 2; paper 000 eq. 20,
``F_omega``) plus, in a whirling squeeze-film damper, the radial component of the inertial
force ``-m_r e_ddot`` of paper 000 eqs. 3-4. Each contact is a line contact with the
load-deflection law ``Q = K delta^n`` (Palmgren: n = 10/9, ``K`` from
:func:`thermobearing.hertz.line_contact_stiffness`). The ring equilibrium

    sum_j Q_ij (cos psi_j, sin psi_j) = (F_r, 0)                        (2)

is solved by Newton on the two ring displacements ``(delta_x, delta_y)`` with the roller
equilibrium (1) solved inside (bisection per roller, vectorised); the Jacobian is analytic
(series stiffness of the two contacts). The radial load acts along ``psi = 0``.

Reference: Harris TA, Kotzalas MN (2007) Rolling Bearing Analysis, 5th ed. (vol. 1: load
distribution; vol. 2: high-speed operation) [harris_kotzalas2007]; paper 000 (Li et al.
2018) eqs. 1-4 and 20-25 [li2018_nu214_skidding].
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .errors import ConvergenceError, InputError, check_finite, check_positive

#: Palmgren's line-contact load-deflection exponent (Harris & Kotzalas 2007 vol. 1).
LINE_CONTACT_EXPONENT = 10.0 / 9.0


@dataclass(frozen=True)
class RollerLoadDistribution:
    """Result of :func:`roller_load_distribution` (SI).

    Attributes
    ----------
    azimuth : (Z,) roller azimuths psi_j [rad], 0 = direction of the radial load.
    inner_load, outer_load : (Z,) contact normal loads Q_ij, Q_oj [N].
    inner_deflection, outer_deflection : (Z,) contact approaches [m] (0 where unloaded).
    interference : (Z,) delta_j = delta_r . e_j - P_d/2 [m] (negative: a gap).
    body_force : (Z,) outward radial body force F_j on each roller [N].
    ring_displacement : (2,) inner-ring displacement (delta_x, delta_y) [m].
    loaded : (Z,) bool, True where the inner contact carries load.
    residual : |sum Q_ij e_j - F| [N] at the solution.
    iterations : Newton iterations.
    """

    azimuth: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    inner_deflection: np.ndarray
    outer_deflection: np.ndarray
    interference: np.ndarray
    body_force: np.ndarray
    ring_displacement: np.ndarray
    loaded: np.ndarray
    residual: float
    iterations: int

    @property
    def n_loaded(self) -> int:
        """Number of rollers whose inner contact carries load."""
        return int(np.count_nonzero(self.loaded))

    @property
    def loaded_fraction(self) -> float:
        """Fraction of the rollers whose inner contact carries load (0..1) [-]."""
        return self.n_loaded / self.azimuth.size


def _power(x: np.ndarray, n: float) -> np.ndarray:
    return np.where(x > 0.0, np.abs(x) ** n, 0.0)


def split_roller_interference(
    interference: np.ndarray,
    body_force: np.ndarray,
    k_inner: float,
    k_outer: float,
    exponent: float = LINE_CONTACT_EXPONENT,
) -> tuple[np.ndarray, np.ndarray]:
    """Share each roller's interference between its inner and outer contact.

    Solves ``K_o (delta_j - s)_+^n - K_i s_+^n = F_j`` for the inner approach ``s`` (eq. 1 of
    the module docstring), vectorised by bisection; the left side falls monotonically in
    ``s`` so the root is unique whenever one of the contacts is closed.

    Parameters
    ----------
    interference : (Z,) delta_j [m].
    body_force : (Z,) outward radial force on each roller F_j [N].
    k_inner, k_outer : contact stiffness K in Q = K delta^n [N/m^n].
    exponent : n [-].

    Returns
    -------
    (inner_deflection, outer_deflection) : (Z,) arrays [m], each >= 0.

    Reference: Harris & Kotzalas (2007) vol. 2 (roller equilibrium with centrifugal
    force).
    """
    d = np.asarray(interference, dtype=float)
    f = np.broadcast_to(np.asarray(body_force, dtype=float), d.shape)
    n = exponent
    # Bracket: the body force alone closes the outer contact by (F/K_o)^(1/n) and the inner
    # one by (-F/K_i)^(1/n); the root lies in [d - (F+/K_o)^(1/n) - slack, d + ...].
    so = (np.maximum(f, 0.0) / k_outer) ** (1.0 / n)
    si = (np.maximum(-f, 0.0) / k_inner) ** (1.0 / n)
    lo = np.minimum(d - so, -si) - 1e-12
    hi = np.maximum(d + si, 0.0) + 1e-12
    # g(lo) >= 0 >= g(hi); safeguarded Newton (bisection when the step leaves the bracket)
    tol = 1e-13 * np.maximum(np.maximum(np.abs(d), so), si) + 1e-22
    x = 0.5 * (lo + hi)
    for _ in range(200):
        do_ = d - x
        g = k_outer * _power(do_, n) - k_inner * _power(x, n) - f
        dg = -(n * k_outer * _power(do_, n - 1.0) + n * k_inner * _power(x, n - 1.0))
        pos = g > 0.0
        lo = np.where(pos, x, lo)
        hi = np.where(pos, hi, x)
        with np.errstate(divide="ignore", invalid="ignore"):
            xn = x - g / dg
        bad = ~np.isfinite(xn) | (xn <= lo) | (xn >= hi)
        xn = np.where(bad, 0.5 * (lo + hi), xn)
        step = np.abs(xn - x)
        x = xn
        if np.all((step <= tol) | (hi - lo <= tol)):
            break
    lo = hi = x
    s = 0.5 * (lo + hi)
    # Both contacts open (F = 0 with a gap): no load either side.
    inner = np.maximum(s, 0.0)
    outer = np.maximum(d - s, 0.0)
    both_open = (f == 0.0) & (d <= 0.0)
    inner = np.where(both_open, 0.0, inner)
    outer = np.where(both_open, 0.0, outer)
    return inner, outer


def _backtrack(evaluate, dx: float, dy: float, step: np.ndarray, norm: float):
    """Halve the Newton step until the force residual norm falls (at most 40 halvings);
    returns the new ring displacement, the evaluation there and its residual norm."""
    lam = 1.0
    for _ in range(40):
        cand = evaluate(dx + lam * step[0], dy + lam * step[1])
        cn = float(np.hypot(*cand[5]))
        if cn < norm or lam < 1e-6:
            break
        lam *= 0.5
    return dx + lam * step[0], dy + lam * step[1], cand, cn


def check_azimuth_spans_load(azimuth: np.ndarray, radial_load: float) -> None:
    """InputError unless the rollers' azimuths can carry a radial load along psi = 0.

    The inner-ring contacts only push (Q_ij >= 0), so the ring equilibrium
    sum_j Q_ij (cos psi_j, sin psi_j) = (F_r, 0) (eq. (2) of the module docstring) has a
    solution only where the load direction lies in the cone of the roller directions: the
    angular gap between the nearest roller on either side of psi = 0 must be below pi (or a
    roller sits at psi = 0). Rollers all on one side (14 azimuths within 1.67-4.61 rad) made
    the ring's Newton push it to an infinite displacement and return a non-converged state
    (residual = F_r; earlier a ConvergenceError with a 680 m step). ``azimuth`` [rad] (Z,),
    ``radial_load`` [N]; a zero load needs no roller.
    """
    if not radial_load > 0.0:
        return
    ccw = np.mod(np.asarray(azimuth, dtype=float), 2.0 * math.pi)
    ahead = float(np.min(ccw))  # nearest roller counter-clockwise of psi = 0 [rad]
    behind = float(np.min(np.mod(-ccw, 2.0 * math.pi)))  # nearest clockwise [rad]
    if ahead == 0.0 or behind == 0.0 or ahead + behind < math.pi:
        return
    raise InputError(
        "azimuth", np.round(np.asarray(azimuth, dtype=float), 4).tolist(),
        f"roller azimuths [rad] on both sides of the load direction psi = 0 within less than "
        f"pi of each other (here the nearest rollers are {ahead:.4g} rad ahead of it and "
        f"{behind:.4g} rad behind, a gap of {ahead + behind:.4g} rad >= pi): the inner-ring "
        f"contacts only push, so no roller set can carry F_r = {radial_load:g} N along "
        "psi = 0")


def roller_load_distribution(
    n_rollers: int,
    diametral_clearance: float,
    radial_load: float,
    k_inner: float,
    k_outer: float,
    *,
    body_force: float | np.ndarray = 0.0,
    azimuth: np.ndarray | None = None,
    exponent: float = LINE_CONTACT_EXPONENT,
    x0: tuple[float, float] | None = None,
    rtol: float = 1e-10,
    max_iter: int = 100,
) -> RollerLoadDistribution:
    """Load distribution of a cylindrical roller bearing with clearance and body forces.

    Parameters
    ----------
    n_rollers : Z [-].
    diametral_clearance : P_d [m] (>= 0; negative preload is not supported here).
    radial_load : F_r [N] (>= 0), acting along psi = 0.
    k_inner, k_outer : line-contact stiffness K with Q = K delta^n [N/m^n].
    body_force : outward radial force on each roller [N] (centrifugal force plus the
        radial part of the whirl inertia force), scalar or (Z,).
    azimuth : (Z,) roller azimuths [rad]; default 2 pi j / Z (a roller under the load).
    exponent : n [-] (10/9, Palmgren).
    x0 : initial ring displacement (delta_x, delta_y) [m] (warm start).
    rtol : tolerance on the force residual relative to max(F_r, K (P_d/2)^n * 1e-6) [-];
        the iteration also stops at the force resolution of the per-roller split (its
        approach tolerance times the contact stiffness plus the round-off of
        Q_i = Q_o - F_j, which sub-micronewton loads reach).

    Returns
    -------
    RollerLoadDistribution

    Raises
    ------
    InputError : bad input.  ConvergenceError : Newton failed (with residual and state).

    Reference: Harris & Kotzalas (2007) vol. 1 (radially loaded roller bearing with
    clearance), vol. 2 (centrifugal force); paper 000 eqs. 20 and 23.
    """
    if int(n_rollers) != n_rollers or n_rollers < 3:
        raise InputError("n_rollers", n_rollers, "an integer >= 3")
    z = int(n_rollers)
    check_positive("diametral_clearance", diametral_clearance, allow_zero=True)
    check_positive("radial_load", radial_load, allow_zero=True)
    check_positive("k_inner", k_inner)
    check_positive("k_outer", k_outer)
    if azimuth is None:
        psi = 2.0 * math.pi * np.arange(z) / z
    else:
        psi = np.asarray(azimuth, dtype=float)
        if psi.shape != (z,):
            raise InputError("azimuth", psi.shape, f"an array of shape ({z},)")
    check_finite("azimuth", psi)
    check_azimuth_spans_load(psi, radial_load)
    fb = np.broadcast_to(np.asarray(body_force, dtype=float), (z,)).copy()
    check_finite("body_force", fb)
    n = exponent
    half = 0.5 * diametral_clearance
    cos, sin = np.cos(psi), np.sin(psi)

    def evaluate(dx: float, dy: float):
        interf = dx * cos + dy * sin - half
        di, do = split_roller_interference(interf, fb, k_inner, k_outer, n)
        qi = k_inner * _power(di, n)
        qo = k_outer * _power(do, n)
        res = np.array([np.sum(qi * cos) - radial_load, np.sum(qi * sin)])
        # series stiffness dQ_i/d(delta_j) where both contacts are closed
        ki = n * k_inner * _power(di, n - 1.0)
        ko = n * k_outer * _power(do, n - 1.0)
        kser = np.where((ki > 0) & (ko > 0), ki * ko / np.maximum(ki + ko, 1e-300), 0.0)
        # inner closed, outer open (roller pulled onto the inner ring): Q_i = -F, no stiffness
        jac = np.array([[np.sum(kser * cos * cos), np.sum(kser * cos * sin)],
                        [np.sum(kser * sin * cos), np.sum(kser * sin * sin)]])
        return interf, di, do, qi, qo, res, jac, kser

    def resolution(cand) -> float:
        """Force resolution [N] of the ring balance at an evaluation: the split's approach
        tolerance (1e-13 |delta_j| + 1e-22 m, :func:`split_roller_interference`) times
        the contact stiffness, and the round-off of Q_i = Q_o - F_j, summed over the
        rollers (x 4). Loads of micronewtons on many rollers reach it (Z = 44 without
        clearance at 1e-7 N: 1e-15 N, above rtol F_r)."""
        interf, qi, qo, kser = cand[0], cand[3], cand[4], cand[7]
        eps = np.finfo(float).eps
        return 4.0 * float(np.sum(kser * (1e-13 * np.abs(interf) + 1e-22)
                                  + eps * (qi + qo + np.abs(fb)) * (qi > 0.0)))

    scale = max(radial_load, 1e-6 * k_inner * max(half, 1e-9) ** n, 1e-9)
    if radial_load == 0.0 and x0 is None:
        dx, dy = 0.0, 0.0
    elif x0 is not None:
        dx, dy = float(x0[0]), float(x0[1])
    else:
        # first guess: Stribeck's Q_max = 4.08 F_r / Z without clearance; with clearance only
        # a few rollers carry the load, take F_r / 2
        qmax = radial_load / 2.0 if half > 0 else 4.08 * radial_load / z
        dser = (qmax / k_inner) ** (1 / n) + (qmax / k_outer) ** (1 / n)
        dx, dy = half + dser, 0.0
    it = 0
    interf, di, do, qi, qo, res, jac, kser = evaluate(dx, dy)
    norm = float(np.hypot(*res))
    while norm > rtol * scale + resolution((interf, di, do, qi, qo, res, jac, kser)):
        if it >= max_iter:
            raise ConvergenceError("roller_load_distribution", norm, "Newton did not converge",
                                   {"delta_x": dx, "delta_y": dy, "iterations": it})
        it += 1
        if radial_load == 0.0 and not np.any(qi > 0.0):
            break
        n_closed = int(np.count_nonzero(qi > 0.0))
        if n_closed == 0:
            # no closed inner contact: move along the load to the first closure
            close_at = (np.maximum(fb, 0.0) / k_outer) ** (1.0 / n)
            c_safe = np.where(cos > 1e-3, cos, 1.0)
            need = np.where(cos > 1e-3, (half + close_at - dy * sin) / c_safe, np.inf)
            dx = max(float(np.min(need)), dx) * (1.0 + 1e-9) + 1e-13
            interf, di, do, qi, qo, res, jac, kser = evaluate(dx, dy)
            norm = float(np.hypot(*res))
            continue
        if n_closed == 1 or abs(np.linalg.det(jac)) <= 1e-12 * float(np.trace(jac)) ** 2:
            # one contact (rank-1 Jacobian): slide at right angles to it, towards the
            # roller that can cancel the residual, until that roller closes
            j = int(np.argmax(qi))
            nvec = np.array([-sin[j], cos[j]])
            if abs(float(res @ nvec)) <= 0.5 * rtol * scale:
                # residual along the one contact: 1-D Newton along it
                evec = np.array([cos[j], sin[j]])
                kjj = float(evec @ jac @ evec)
                jac = kjj * np.outer(evec, evec) + np.outer(nvec, nvec) * kjj
                dx, dy, cand, norm = _backtrack(evaluate, dx, dy, -np.linalg.solve(jac, res),
                                                norm)
                interf, di, do, qi, qo, res, jac, kser = cand
                continue
            direction = nvec * (1.0 if float(-res @ nvec) >= 0.0 else -1.0)
            along = cos * direction[0] + sin * direction[1]
            close_at = (np.maximum(fb, 0.0) / k_outer) ** (1.0 / n)
            a_safe = np.where(along > 1e-9, along, 1.0)
            dist = np.where((along > 1e-9) & (qi <= 0.0), (close_at - interf) / a_safe, np.inf)
            tmin = float(np.min(dist))
            if np.isfinite(tmin) and tmin > 0.0:
                tmin = tmin * (1.0 + 1e-9) + 1e-13
                dx, dy = dx + tmin * direction[0], dy + tmin * direction[1]
                interf, di, do, qi, qo, res, jac, kser = evaluate(dx, dy)
                norm = float(np.hypot(*res))
                continue
            jac = jac + np.eye(2) * 1e-9 * float(np.trace(jac))
        dx, dy, cand, norm = _backtrack(evaluate, dx, dy, -np.linalg.solve(jac, res), norm)
        interf, di, do, qi, qo, res, jac, kser = cand
    if not (math.isfinite(dx) and math.isfinite(dy)):
        # a non-finite ring displacement makes the force resolution NaN and ended the loop
        # as if converged: never return that state
        raise ConvergenceError("roller_load_distribution", norm,
                               "the ring displacement left the finite range",
                               {"delta_x": dx, "delta_y": dy, "iterations": it})
    return RollerLoadDistribution(
        azimuth=psi, inner_load=qi, outer_load=qo, inner_deflection=di, outer_deflection=do,
        interference=interf, body_force=fb, ring_displacement=np.array([dx, dy]),
        loaded=qi > 0.0, residual=norm, iterations=it,
    )


def roller_film_load_distribution(
    n_rollers: int,
    diametral_clearance: float,
    radial_load: float,
    inner_film: Callable[[np.ndarray], np.ndarray],
    outer_film: Callable[[np.ndarray], np.ndarray],
    k_inner: float,
    k_outer: float,
    *,
    body_force: float | np.ndarray = 0.0,
    azimuth: np.ndarray | None = None,
    exponent: float = LINE_CONTACT_EXPONENT,
    x0: tuple[float, float] | None = None,
    q0: np.ndarray | None = None,
    rtol: float = 1e-10,
    max_iter: int = 60,
) -> RollerLoadDistribution:
    """Load distribution with the lubricant films in the clearance (flooded or starved).

    Where the films are as thick as the radial clearance (light load, high speed, viscous
    oil: paper 000's NU214 has P_d/2 = 12.5 um and films of 4-30 um), the dry distribution of
    :func:`roller_load_distribution` is not consistent with the films it is used with. Here
    each roller fills its radial gap with its two films: with the inner load Q_ij, the outer
    load Q_oj = Q_ij + F_j (roller equilibrium (1) of the module docstring) and the
    contact approaches delta = (Q/K)^(1/n),

        h_i(Q_ij) + h_o(Q_oj) - delta_i(Q_ij) - delta_o(Q_oj) = P_d/2 - delta_r . e_j     (3)

    The left side falls monotonically with Q_ij (films thin, approaches grow) from +inf
    (a flooded film carries a vanishing load at a large thickness) to -inf, so with flooded
    films every roller carries a film load (no unloaded zone); (3) is solved by bisection in
    ln Q_ij for all rollers at once and the ring equilibrium (2) by Newton on
    (delta_x, delta_y) with a finite-difference Jacobian and backtracking. A film of limited
    thickness (starved inlet: at most the available oil layer) may not fill a wide gap even
    unloaded; such a roller gets Q_ij = 0 (``loaded`` False): it rides on its outer film, the
    load zone of the paper's dry model reappears where the gap is wider than the films.

    Parameters
    ----------
    n_rollers, diametral_clearance, radial_load, k_inner, k_outer, body_force, azimuth,
    exponent, x0 : as :func:`roller_load_distribution` (SI).
    inner_film, outer_film : ``film(Q (Z,) [N]) -> h (Z,) [m]``, the central film thickness
        of each roller's inner / outer contact at normal load Q (entrainment speeds, viscosity
        and geometry bound in), decreasing in Q. The roller skidding solver passes the same
        film formula its traction uses (Moes 1992 by default, rigid-isoviscous to EHL).
    q0 : (Z,) inner loads of a nearby solution [N] (warm start of the per-roller roots).
    rtol : tolerance on the force residual relative to max(F_r, 1e-3 sum Q_ij) [-].

    Returns
    -------
    RollerLoadDistribution (``interference`` = delta_r . e_j - P_d/2, the negative rigid gap;
    ``loaded`` = Q_ij > 0, all True with flooded films; deflections = the Hertz approaches).

    Reference: Harris & Kotzalas (2007) vol. 1 load distribution with clearance, extended by
    the central film thicknesses of both contacts (the lubricated-contact approach of
    Hamrock et al. 2004, ch. on EHL of rectangular conjunctions); paper 000 eqs. 20/23.
    """
    if int(n_rollers) != n_rollers or n_rollers < 3:
        raise InputError("n_rollers", n_rollers, "an integer >= 3")
    z = int(n_rollers)
    check_positive("diametral_clearance", diametral_clearance, allow_zero=True)
    check_positive("radial_load", radial_load, allow_zero=True)
    check_positive("k_inner", k_inner)
    check_positive("k_outer", k_outer)
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None \
        else np.asarray(azimuth, dtype=float)
    if psi.shape != (z,):
        raise InputError("azimuth", psi.shape, f"an array of shape ({z},)")
    check_finite("azimuth", psi)
    check_azimuth_spans_load(psi, radial_load)
    fb = np.broadcast_to(np.asarray(body_force, dtype=float), (z,)).copy()
    check_finite("body_force", fb)
    half = 0.5 * diametral_clearance
    cos, sin = np.cos(psi), np.sin(psi)
    inv_n = 1.0 / exponent

    guess = [None if q0 is None else np.log(np.maximum(np.asarray(q0, dtype=float), 1e-300))]

    def inner_loads(dx: float, dy: float) -> np.ndarray:
        gap = half - (dx * cos + dy * sin)
        qmin = np.maximum(-fb, 0.0) * (1.0 + 1e-12) + 1e-9  # keeps Q_o = Q_i + F_j > 0

        def excess0(t: np.ndarray) -> np.ndarray:  # (3) minus the gap, falls with t = ln Q_i
            q = np.exp(t)
            qo = q + fb
            return (np.asarray(inner_film(q)) + np.asarray(outer_film(qo))
                    - (q / k_inner) ** inv_n - (qo / k_outer) ** inv_n - gap)

        # a film of limited thickness (starved inlet) may not fill the gap even unloaded:
        # that roller has no inner film load (it rides on its outer film); its equation is
        # replaced by a root just above ln(qmin) and its load set to 0 below
        t_min = np.log(qmin)
        open_gap = excess0(t_min) <= 0.0

        def excess(t: np.ndarray) -> np.ndarray:
            if not np.any(open_gap):
                return excess0(t)
            return np.where(open_gap, t_min + 1e-6 - t, excess0(np.where(open_gap, t_min, t)))

        bracketed = False
        if guess[0] is not None and guess[0].shape == (z,):
            # warm start: a bracket of a factor 1.5 around the previous root
            lo = np.maximum(guess[0] - 0.4, np.log(qmin))
            hi = np.maximum(guess[0] + 0.4, lo + 0.4)  # (a previous Q = 0: open gap)
            f_lo, f_hi = excess(lo), excess(hi)
            bracketed = bool(np.all(f_lo > 0.0) and np.all(f_hi < 0.0))
        if not bracketed:
            lo = np.log(qmin)
            hi = np.full(z, math.log(1e8))
            for _ in range(26):  # bisection to a bracket of ~6e-7 in ln Q
                mid = 0.5 * (lo + hi)
                thick = excess(mid) > 0.0  # films too thick for the gap: more load
                lo = np.where(thick, mid, lo)
                hi = np.where(thick, hi, mid)
            f_lo, f_hi = excess(lo), excess(hi)
        # Illinois (regula falsi) to round-off inside the bracket
        last = np.zeros(z)  # +1: lo moved last, -1: hi moved last
        for _ in range(40):
            den = f_lo - f_hi
            t = np.where(den > 0.0, lo + f_lo * (hi - lo) / np.where(den > 0, den, 1.0),
                         0.5 * (lo + hi))
            f_t = excess(t)
            pos = f_t > 0.0
            # Illinois: halve the value at the end that stays for a second time
            f_hi = np.where(pos, np.where(last > 0, 0.5 * f_hi, f_hi), f_t)
            f_lo = np.where(pos, f_t, np.where(last < 0, 0.5 * f_lo, f_lo))
            lo = np.where(pos, t, lo)
            hi = np.where(pos, hi, t)
            last = np.where(pos, 1.0, -1.0)
            if float(np.max(np.abs(f_t))) <= 1e-16 or float(np.max(hi - lo)) <= 1e-13:
                break  # gap closed to 1e-16 m
        t = np.where(np.abs(f_lo) < np.abs(f_hi), lo, hi)
        guess[0] = t
        return np.where(open_gap, 0.0, np.exp(t))

    def residual(dx: float, dy: float) -> tuple[np.ndarray, np.ndarray]:
        q = inner_loads(dx, dy)
        return q, np.array([np.sum(q * cos) - radial_load, np.sum(q * sin)])

    dx, dy = (0.0, 0.0) if x0 is None else (float(x0[0]), float(x0[1]))
    q, res = residual(dx, dy)
    norm = float(np.hypot(*res))
    # elastic approach of a roller carrying about 4 F_r / Z (Stribeck) through both
    # contacts in series, plus the outer approach under the body force (it widens the inner
    # gaps): the displacement scale of the soft spring below when the clearance is smaller
    # (else F / (P_d/2) took steps of 1e-9 m for a ring that had to move 1e-4 m: 60
    # iterations did not reach the load at P_d = 1e-9 m with films thinner than the gap)
    k_series = (k_inner ** -inv_n + k_outer ** -inv_n) ** -exponent
    approach = ((4.0 * radial_load / (z * k_series)) ** inv_n
                + (max(float(np.max(fb)), 0.0) / k_outer) ** inv_n)
    it = 0
    while norm > rtol * max(radial_load, 1e-3 * float(np.sum(q)), 1e-9):
        if it >= max_iter:
            raise ConvergenceError("roller_film_load_distribution", norm,
                                   "Newton did not converge",
                                   {"delta_x": dx, "delta_y": dy, "iterations": it})
        it += 1
        h = 1e-4 * max(half, 1e-7)
        _, rx = residual(dx + h, dy)
        _, ry = residual(dx, dy + h)
        jac = np.column_stack([(rx - res) / h, (ry - res) / h])
        # singular Jacobian where the films leave gaps open (starved films: the ring rests
        # on one roller, or on none yet): add a soft spring F / (P_d/2) so that the step
        # moves the ring towards the load, and accept a step over a flat residual
        k_ref = max(radial_load, 1e-3 * float(np.sum(q)), 1e-9) / max(half, approach, 1e-9)
        flat = abs(float(np.linalg.det(jac))) <= 1e-10 * max(float(np.max(np.abs(jac))),
                                                              k_ref) ** 2
        step = -np.linalg.solve(jac + k_ref * np.eye(2) if flat else jac, res)
        lam = 1.0
        for _ in range(40):
            qn, rn = residual(dx + lam * step[0], dy + lam * step[1])
            nn = float(np.hypot(*rn))
            if nn < norm or (flat and nn <= norm) or lam < 1e-6:
                break
            lam *= 0.5
        dx, dy, q, res, norm = dx + lam * step[0], dy + lam * step[1], qn, rn, nn
    qo = q + fb
    return RollerLoadDistribution(
        azimuth=psi, inner_load=q, outer_load=qo, inner_deflection=(q / k_inner) ** inv_n,
        outer_deflection=(qo / k_outer) ** inv_n, interference=dx * cos + dy * sin - half,
        body_force=fb, ring_displacement=np.array([dx, dy]), loaded=q > 0.0,
        residual=norm, iterations=it,
    )


def roller_body_force(
    roller_mass: float,
    pitch_diameter: float,
    cage_speed: float,
    azimuth: np.ndarray,
    whirl_acceleration: tuple[float, float] = (0.0, 0.0),
) -> np.ndarray:
    """Outward radial body force on each roller [N].

    ``F_j = m_r (d_m/2) omega_c^2 - m_r a_w . e_j`` with ``e_j = (cos psi_j, sin psi_j)``:
    the centrifugal force of the orbiting roller (paper 000 ``F_omega``; Harris & Kotzalas
    vol. 2) plus the d'Alembert force of the bearing-centre acceleration ``a_w``
    (paper 000 eqs. 3-4, ``a_w = (e_x'', e_y'')``) in the frame that moves with the outer
    ring.

    Parameters
    ----------
    roller_mass : m_r [kg].  pitch_diameter : d_m [m].  cage_speed : omega_c [rad/s].
    azimuth : (Z,) psi_j [rad].  whirl_acceleration : (a_x, a_y) [m/s^2].
    """
    psi = np.asarray(azimuth, dtype=float)
    ax, ay = whirl_acceleration
    return roller_mass * (0.5 * pitch_diameter * cage_speed**2
                          - (ax * np.cos(psi) + ay * np.sin(psi)))
