"""Isothermal numerical EHL of a line contact: dimensionless (Moes M, L) and dimensional front ends.

The discrete problem and the Newton solvers are in :mod:`thermobearing.ehl.solver`; this module
picks the domain and grids, runs nested iteration (a robust implicit time march to the steady
state on a coarse grid, then Newton on finer grids -- n/2 and n, below n/2 every other power
of two -- from the interpolated solution, smoothed locally at the exit spike first,
:func:`thermobearing.ehl.solver.smooth_spike`), estimates the discretisation error from the
last two grids, and returns dimensional profiles, films, pressures and the traction split of
paper 000 eq. 5.

Conventions (contract): E' = 2/((1-v1^2)/E1 + (1-v2^2)/E2); entrainment speed
``u_m = (u1 + u2)/2``; slide-to-roll ratio ``(u1 - u2)/u_m``. Dimensionless groups (Hamrock):
``U = eta0 u_m/(E' R)``, ``W = w'/(E' R)`` (w' load per unit length), ``G = alpha E'``; Moes:
``M = W (2U)^-1/2``, ``L = G (2U)^1/4``, ``H_Moes = (h/R)(2U)^-1/2``. Hertz:
``b = R sqrt(8W/pi)``, ``p_H = E' sqrt(W/(2 pi))``. Then ``lam = 3 pi^2/(8 M^2)``,
``alpha p_H = L sqrt(M/(2 pi))`` and ``H_Moes = (8M/pi) h R/b^2``.

References: paper 000 (seed ``000_3b5ca6eed61dd596.txt``) eqs. 5, 7-11; Venner & Lubrecht,
Multilevel Methods in Lubrication (2000); Moes (1992).
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass, field

import numpy as np

from ..errors import (
    ConvergenceError,
    InputError,
    ValidityWarning,
    check_positive,
    check_range,
)
from .solver import (
    LineProblem,
    NewtonReport,
    Rheology,
    newton_solve,
    smooth_spike,
    time_march,
)

#: Range of the Moes parameters over which the solver is tested (BM-6 and unit tests).
M_RANGE = (0.002, 3000.0)
L_RANGE = (0.0, 40.0)
#: relative change of the maximum pressure between the last two grids above which
#: ``solve_dimensionless`` warns that the pressure peak is not grid-converged [-]
MAX_PRESSURE_CHANGE = 0.1
#: Newton iterations allowed from the Hertz/Moes initial guess before the coarse-grid time
#: march takes over (BM-6: heavy loads converge directly in 6-12 iterations,
#: M = 10 does not converge at all without the march).
DIRECT_START_ITERATIONS = 15
#: Levels with at most this many nodes use the dense Newton (LU of the full matrix).
DENSE_LEVEL_MAX = 384
#: Newton tolerances on max |F| (scaled Fischer-Burmeister residuals, ~ a pressure change in
#: units of p_H): ``FINE_TOL`` on the finest grid, ``COARSE_TOL`` on the n/2 grid (it enters
#: the Richardson estimate, a difference of >= 1e-4 relative), ``FEED_TOL`` on the grids
#: below, which only give the next grid its start (whose Newton re-adjusts the exit spike
#: anyway). The discretisation error of the films is >= 1e-4 (relative) at the BM-6
#: resolutions; against 1e-8 / 1e-6 / 1e-6 these values change h_c, h_min and
#: p_max of the BM-6 cases by < 1e-6 (relative) and the error estimate in its 4th digit, and
#: save the last (quadratic) Newton iteration of each level (BM-6, N = 1024: 205 -> 183
#: Newton iterations over the 9 cases).
FINE_TOL = 1e-7
COARSE_TOL = 1e-5
FEED_TOL = 1e-3
#: Start every level above the first from the interpolated solution smoothed locally at its
#: largest residual (:func:`thermobearing.ehl.solver.smooth_spike`).
SMOOTH_SPIKE = True
_POINTER = (
    "use a closed-form film model instead (thermobearing.film: moes_line_central, "
    "dowson_higginson_minimum, pan_hamrock_minimum)"
)


@dataclass(frozen=True)
class LineEHLSolution:
    """Solution of a line-contact EHL problem (SI unless marked dimensionless).

    Attributes
    ----------
    x : node coordinates in the rolling direction [m] (0 at the Hertz centre).
    pressure : film pressure [Pa].
    film : film thickness [m].
    viscosity : viscosity at the nodes [Pa s] (film mean in the thermal case).
    central_film, minimum_film : film at x = 0 and its minimum [m].
    max_pressure : maximum pressure [Pa].
    hertz_half_width, hertz_pressure : b [m], p_H [Pa].
    M, L : Moes parameters [-].
    n : number of nodes; dx : node spacing [m].
    error_estimate : Richardson estimate of the relative error of ``central_film`` from the
        last two grids (second order) [-].
    max_pressure_change : relative change of the maximum pressure between the last two
        grids [-] (NaN with one grid). The film converges at second order everywhere, but a
        pressure spike (Barus piezoviscous-rigid regime: small M, large L; the outlet spike
        of heavy loads) need not: above ``MAX_PRESSURE_CHANGE`` a ``ValidityWarning`` says
        that ``max_pressure`` is not grid-converged (the films are).
    central_film_extrapolated : ``h_c`` Richardson-extrapolated from the last two grids [m].
    entrainment_speed : u_m [m/s].
    report : Newton statistics; seconds : wall time [s].
    X, P, H : dimensionless profiles (x/b, p/p_H, h R/b^2).
    """

    x: np.ndarray
    pressure: np.ndarray
    film: np.ndarray
    viscosity: np.ndarray
    central_film: float
    minimum_film: float
    max_pressure: float
    hertz_half_width: float
    hertz_pressure: float
    M: float
    L: float
    n: int
    dx: float
    error_estimate: float
    central_film_extrapolated: float
    entrainment_speed: float
    reduced_radius: float
    report: NewtonReport
    seconds: float
    X: np.ndarray = field(repr=False)
    P: np.ndarray = field(repr=False)
    H: np.ndarray = field(repr=False)
    max_pressure_change: float = math.nan

    @property
    def central_film_moes(self) -> float:
        """Central film in Moes' scaling ``H = (h_c/R)(2U)^-1/2`` [-]."""
        return 8.0 * self.M / math.pi * float(np.interp(0.0, self.X, self.H))

    def traction(
        self, slide_to_roll: float, limiting_shear_coefficient: float | None = None
    ) -> Traction:
        """Film force per unit length on surface 1 in the rolling direction (paper 000 eq. 5).

        ``T = -int (h/2) dp/dx dx + (u2 - u1) int eta/h dx``: the first (Poiseuille, rolling)
        term, the second (Couette, sliding) term, with ``u2 - u1 = -SRR u_m``. Newtonian: at
        Hertzian pressures the Couette stress ``eta du/h`` is unbounded in practice, so an
        optional limiting shear stress ``tau_L = limiting_shear_coefficient * p`` (Bair & Winer
        1979 form, ``tau_L/p`` about 0.05-0.1) caps it node by node. In the cavitated outlet
        the Couette term is scaled by the film fill fraction (mass conservation of the
        rupture flux).

        Parameters
        ----------
        slide_to_roll : (u1 - u2)/u_m [-].
        limiting_shear_coefficient : tau_L/p [-], or None for the Newtonian law.

        Returns
        -------
        Traction : per-unit-length forces [N/m] (multiply by the contact length).
        """
        x, p, h, eta = self.x, self.pressure, self.film, self.viscosity
        du = -float(slide_to_roll) * self.entrainment_speed  # u2 - u1
        dpdx = np.gradient(p, x)
        poise = -float(np.trapezoid(0.5 * h * dpdx, x))
        # fill fraction after the rupture point (last pressurised node)
        pos = np.nonzero(p > 0)[0]
        fill = np.ones_like(h)
        if pos.size:
            k = pos[-1] + 1
            if k < h.size:
                fill[k:] = np.minimum(1.0, h[k] / h[k:])
        tau = eta * du / h
        if limiting_shear_coefficient is not None:
            lim = limiting_shear_coefficient * np.maximum(p, 0.0)
            tau = np.where(p > 0, np.sign(tau) * np.minimum(np.abs(tau), lim), tau)
        couette = float(np.trapezoid(tau * fill, x))
        return Traction(poise, couette, poise + couette)


@dataclass(frozen=True)
class Traction:
    """Film force per unit length on surface 1 (paper 000 eq. 5) [N/m]."""

    poiseuille: float
    couette: float
    total: float


class GridResolutionError(ConvergenceError):
    """The nested-grid solve converged but its Richardson estimate of the central-film error
    exceeds ``max_grid_error``: more nodes would help (callers may retry on a finer grid)."""


def _inlet_scale(M: float, L: float) -> float:
    """``sqrt(2 H)`` in Hertz half-widths, H the Moes film in solver units: the length over
    which the rigid gap doubles, i.e. the inlet/outlet scale of a lightly loaded contact."""
    return math.sqrt(2.0 * moes_dimensionless(M, L) * math.pi / (8.0 * M))


def default_domain(M: float, L: float = 0.0) -> tuple[float, float]:
    """Inlet and outlet of the domain in Hertz half-widths for given M, L.

    Heavily loaded contacts build pressure close to the Hertz zone; light loads (M < 5) have
    the inlet length of a rigid contact, a multiple of ``c = sqrt(2 R h)/b`` (Martin's
    pressure decays as 1/x^2 upstream): the domain is ``[-30 c, 2 c]`` there (checked against
    Martin's rigid-isoviscous film, 2.448/M in Moes' scaling, in the tests).
    """
    if M >= 50.0:
        return -2.5, 1.5
    if M >= 5.0:
        return -4.5, 1.5
    c = _inlet_scale(M, L)
    return -max(8.0, 30.0 * c), max(2.0, 2.0 * c)


def _resolution_width(M: float, L: float) -> float:
    """Width that must carry 24 nodes: the Hertz zone, or the inlet scale if that is wider."""
    return 2.0 if M >= 5.0 else max(2.0, _inlet_scale(M, L))


def nodes_for(M: float, n: int = 512, L: float = 0.0) -> int:
    """Smallest power-of-two multiple of ``n`` with 32 nodes across the resolution width."""
    x_in, x_out = default_domain(M, L)
    need = 32.0 * (x_out - x_in) / _resolution_width(M, L) + 1.0
    out = int(n)
    while out < need:
        out *= 2
    return out


def _initial_guess(prob: LineProblem, hc_guess: float) -> tuple[np.ndarray, float]:
    X = prob.x
    P = np.sqrt(np.maximum(1.0 - X**2, 0.0))
    base = prob.x2 + prob.kernel.apply(P)
    return P, hc_guess - float(np.interp(0.0, X, base))


def start_grid(M: float) -> int:
    """Nodes of the start grid (the coldest solve) for Moes load ``M``.

    The start grid must resolve the exit spike well enough for the time march / Newton to
    converge, and every node there costs a dense Newton iteration. Measured (N =
    1024, L in {2, 5, 10, 20}): 64 nodes converge for 5 <= M <= 50 and save 10-40 % against
    128 (M = 10, L = 20: 72 against 114 ms), fail from M = 100; 128 nodes fail for M = 200
    and 250 with L <= 5 (as with the earlier solver), 256 converge for 120 <= M <= 250; M >= 300
    starts on 512 nodes as before. A start that fails is retried on twice the nodes (see
    :func:`solve_dimensionless`).
    """
    if M >= 300.0:
        return 512
    if M >= 120.0:
        return 256
    if 5.0 <= M < 50.0:
        return 64
    return 128


def _levels(n: int, cn: int) -> list[int]:
    """Nested grids from the start grid ``cn`` to ``n``: n/2 and n (the Richardson pair),
    below n/2 every other power of two (each level's Newton re-adjusts the exit spike in a
    few iterations whatever the jump, so skipping every other coarse level saves its solve;
    BM-6, N = 1024: 128 -> 512 -> 1024 is ~25 % faster than 128 -> 256 -> 512 -> 1024)."""
    levels = [n]
    if n // 2 >= cn:
        levels.append(n // 2)
        while levels[-1] // 4 >= cn:
            levels.append(levels[-1] // 4)
        if levels[-1] > cn:
            levels.append(cn)
    return levels[::-1]


def _cold_start(prob: LineProblem, M: float, L: float, linear: str,
                tol: float) -> tuple[np.ndarray, float, NewtonReport]:
    """Solve on the start grid from the Hertz pressure and the Moes film: steady Newton first
    (heavy loads converge directly in 6-12 iterations), the implicit time march if that
    fails (M around 10 does not converge without it)."""
    P0, H00 = _initial_guess(prob, moes_dimensionless(M, L) * math.pi / (8 * M))
    try:
        return newton_solve(prob, P0, H00, linear=linear, tol=tol,
                            max_iter=DIRECT_START_ITERATIONS)
    except ConvergenceError:
        return time_march(prob, P0, H00, linear=linear, dt0=0.2, dt_final=1e3, tol=tol)


def moes_dimensionless(M: float, L: float) -> float:
    """Moes central film H(M, L) evaluated through :func:`thermobearing.film.moes_line_central`."""
    from ..film import moes_line_central

    # any dimensional case with these M, L: unit E', R, length; U = 1e-10
    two_u = 2e-10
    w = M * math.sqrt(two_u)
    g = L / two_u**0.25
    h = moes_line_central(
        two_u / 2, 1.0, g, w, 1.0, 1.0, effective_modulus=1.0
    ) if L > 0 else moes_line_central(two_u / 2, 1.0, 1e-30, w, 1.0, 1.0, effective_modulus=1.0)
    return float(h) / math.sqrt(two_u)


def solve_dimensionless(
    M: float,
    L: float,
    *,
    n: int = 1024,
    rheology: Rheology | None = None,
    domain: tuple[float, float] | None = None,
    coarse_n: int | None = None,
    linear: str = "krylov",
    max_grid_error: float = 0.05,
    f_e: np.ndarray | None = None,
    f_r: np.ndarray | None = None,
    initial: tuple[np.ndarray, np.ndarray, float] | None = None,
    reference: tuple[float, float, float, float] = (1.0, 1.0, 1.0, 1.0),
) -> LineEHLSolution:
    """Solve the isothermal line-contact EHL problem for Moes parameters ``M``, ``L``.

    Parameters
    ----------
    M, L : Moes load and lubricant parameters [-] (``M_RANGE``, ``L_RANGE``).
    n : number of nodes on the finest grid (>= 64).
    rheology : :class:`Rheology`; default Barus with ``alpha p_H = L sqrt(M/(2 pi))``,
        incompressible (the setting of Moes' fit).
    domain : (x_in, x_out) in Hertz half-widths; default :func:`default_domain`.
    coarse_n : start grid (default :func:`start_grid`: 64 to 512 nodes by M; a default start
        that fails, on the start grid or on a later level, is retried on twice the nodes
        while that is at most n/2). The nested
        grids are the start grid, then every other power of two below n/2, then n/2 and n
        (the Richardson pair), e.g. 128 -> 512 -> 1024.
    linear : ``"krylov"`` (fast) or ``"dense"`` (baseline) Newton linear solver.
    max_grid_error : raise if the Richardson error estimate of h_c exceeds this [-].
    f_e, f_r : thermal factors at the finest-grid nodes (see :mod:`.solver`), or None.
    initial : (X, P, H0) of a previous solution to start from (skips the time march).
    reference : (R [m], b [m], p_H [Pa], eta0 [Pa s]) to make the outputs dimensional; the
        default 1's give dimensionless outputs (x = X, p = P, h = H R/b^2 ...).

    Raises
    ------
    InputError : M or L outside the tested range, or n too small for the Hertz zone.
    ConvergenceError : Newton / time march failure, or the grid error estimate above
        ``max_grid_error``; the message gives M, L, the residual and a pointer to the
        closed-form models.
    """
    check_range("M", M, *M_RANGE, unit="(Moes load parameter; " + _POINTER + ")")
    check_range("L", L, *L_RANGE, unit="(Moes lubricant parameter; " + _POINTER + ")")
    x_in, x_out = domain if domain is not None else default_domain(M, L)
    nodes_in_zone = _resolution_width(M, L) * (n - 1) / (x_out - x_in)
    if n < 64 or nodes_in_zone < 24:
        raise InputError("n", n, f"at least 64 nodes and 24 across the Hertz zone (or the inlet "
                         f"scale of a light load; see nodes_for) ({_POINTER})")
    if rheology is None:
        rheology = Rheology(law="barus", alpha_bar=L * math.sqrt(M / (2 * math.pi)),
                            compressible=False)
    lam = 3.0 * math.pi**2 / (8.0 * M**2)
    t0 = time.perf_counter()
    levels = _levels(n, coarse_n or start_grid(M))
    xs_fine = np.linspace(x_in, x_out, n)

    def factors(nk: int, arr: np.ndarray | None) -> np.ndarray | None:
        if arr is None:
            return None
        return np.interp(np.linspace(x_in, x_out, nk), xs_fine, arr)

    hc_levels: list[float] = []
    hm_levels: list[float] = []
    pm_levels: list[float] = []
    its = lin = local = 0
    P = H0 = X = None
    state = {"M": M, "L": L}
    try:
        k = 0
        while k < len(levels):
            nk = levels[k]
            prob = LineProblem(nk, x_in, x_out, lam, rheology, factors(nk, f_e), factors(nk, f_r))
            lin_k = "dense" if nk <= DENSE_LEVEL_MAX else linear
            # coarse levels only feed the next grid (and the Richardson estimate, whose
            # discretisation difference is >= 1e-4): see FINE_TOL / COARSE_TOL / FEED_TOL
            tol_k = FINE_TOL if nk == n else (COARSE_TOL if 2 * nk >= n else FEED_TOL)
            if k == 0:
                if initial is not None:
                    Xi, Pi, H0i = initial
                    Pg = np.interp(prob.x, Xi, Pi)
                    try:
                        P, H0, rep = newton_solve(prob, Pg, H0i, linear=lin_k, tol=tol_k)
                    except ConvergenceError:
                        P, H0, rep = time_march(prob, Pg, H0i, linear=lin_k, dt0=0.2, tol=tol_k)
                else:
                    try:
                        P, H0, rep = _cold_start(prob, M, L, lin_k, tol_k)
                    except ConvergenceError:
                        if coarse_n is None and initial is None and 2 * nk <= n // 2:
                            levels = _levels(n, 2 * nk)  # start again on a finer grid
                            continue
                        raise
            else:
                Pg = np.interp(prob.x, X, P)
                Ps = Pg
                if SMOOTH_SPIKE:
                    Ps, n_loc = smooth_spike(prob, Pg, H0)
                    local += n_loc
                try:
                    try:
                        try:
                            P, H0, rep = newton_solve(prob, Ps, H0, linear=lin_k, tol=tol_k)
                        except ConvergenceError:
                            if Ps is Pg:
                                raise
                            # the smoothing is a shortcut: retry from the interpolated start
                            P, H0, rep = newton_solve(prob, Pg, H0, linear=lin_k, tol=tol_k)
                    except ConvergenceError:
                        P, H0, rep = time_march(prob, Pg, H0, linear=lin_k, dt0=0.5,
                                                tol=tol_k)
                except ConvergenceError:
                    # a coarse default start can converge and still hand the next level a
                    # spike it cannot follow (M = 39, L = 1.3: 64 -> 256 nodes fails, a
                    # 128-node start converges): start again on twice the start grid
                    start = levels[0]
                    if coarse_n is None and initial is None and 2 * start <= n // 2:
                        levels = _levels(n, 2 * start)
                        k, its, lin, local, X = 0, 0, 0, 0, None
                        hc_levels.clear()
                        hm_levels.clear()
                        pm_levels.clear()
                        continue
                    raise
            its += rep.iterations
            lin += rep.linear_iterations
            X = prob.x
            H = prob.film(P, H0)
            hc_levels.append(float(np.interp(0.0, X, H)))
            hm_levels.append(float(H.min()))
            pm_levels.append(float(P.max()))
            k += 1
    except ConvergenceError as err:
        raise ConvergenceError(
            "ehl.line", err.residual,
            f"line-contact EHL failed for M={M:.4g}, L={L:.4g}: {err}; {_POINTER}",
            {"M": M, "L": L, "n": n},
        ) from err
    seconds = time.perf_counter() - t0
    if len(hc_levels) >= 2:
        diff = hc_levels[-1] - hc_levels[-2]
        hc_ex = hc_levels[-1] + diff / 3.0
        err_est = abs(diff / 3.0) / abs(hc_ex)
    else:
        hc_ex, err_est = hc_levels[-1], math.nan
    if len(hc_levels) < 2:
        # one grid only (n at most the start grid, e.g. 512 nodes for M >= 300): there is no
        # Richardson pair to estimate the error with (the message said "error nan%")
        raise GridResolutionError(
            "ehl.line", math.inf,
            f"grid too coarse: n={n} is the only grid solved for M={M:.4g}, L={L:.4g} (the "
            f"start grid is {levels[0]} nodes), so the central-film error cannot be "
            f"estimated; n >= {2 * levels[0]} gives the Richardson pair; {_POINTER}", state,
        )
    if not (math.isfinite(err_est) and err_est <= max_grid_error):
        raise GridResolutionError(
            "ehl.line", err_est,
            f"grid too coarse: estimated central-film error {err_est:.1%} > {max_grid_error:.0%}"
            f" at n={n} for M={M:.4g}, L={L:.4g}; increase n or {_POINTER}", state,
        )
    p_change = (abs(pm_levels[-1] - pm_levels[-2]) / pm_levels[-1]
                if len(pm_levels) >= 2 and pm_levels[-1] > 0 else math.nan)
    if p_change > MAX_PRESSURE_CHANGE:
        warnings.warn(ValidityWarning(
            f"ehl.line: the maximum pressure is not grid-converged at n={n} for M={M:.4g}, "
            f"L={L:.4g}: it changed by {p_change:.0%} between the last two grids "
            f"({pm_levels[-2]:.3g} -> {pm_levels[-1]:.3g} p_H); the films are converged "
            f"(central-film error {err_est:.1e}); refine n for the pressure peak"), stacklevel=2)
    R, b, pH, eta0 = reference
    eta, _ = rheology.viscosity(P)
    H = prob.film(P, H0)
    scale_h = b * b / R
    return LineEHLSolution(
        x=X * b, pressure=P * pH, film=H * scale_h, viscosity=eta * eta0,
        central_film=hc_levels[-1] * scale_h, minimum_film=hm_levels[-1] * scale_h,
        max_pressure=float(P.max()) * pH, hertz_half_width=b, hertz_pressure=pH,
        M=M, L=L, n=n, dx=prob.dx * b, error_estimate=err_est,
        central_film_extrapolated=hc_ex * scale_h, entrainment_speed=state.get("u", 0.0),
        reduced_radius=R, report=NewtonReport(its, rep.residual, lin, True, local), seconds=seconds,
        X=X, P=P, H=H, max_pressure_change=p_change,
    )


@dataclass(frozen=True)
class LineContactCase:
    """Dimensional line contact and its dimensionless groups (SI).

    Attributes: load_per_length w' [N/m], radius R [m], effective_modulus E' [Pa],
    entrainment_speed u_m [m/s], viscosity eta0 [Pa s], alpha [1/Pa], roelands_z [-] or None,
    U, W, G, M, L [-], half_width b [m], hertz_pressure p_H [Pa].
    """

    load_per_length: float
    radius: float
    effective_modulus: float
    entrainment_speed: float
    viscosity: float
    alpha: float
    roelands_z: float | None
    U: float
    W: float
    G: float
    M: float
    L: float
    half_width: float
    hertz_pressure: float

    def rheology(self, compressible: bool = True) -> Rheology:
        """Roelands (if ``roelands_z``) or Barus viscosity; Dowson-Higginson density."""
        if self.roelands_z is not None:
            return Rheology(law="roelands", roelands_a=math.log(self.viscosity) + 9.67,
                            roelands_z=self.roelands_z, hertz_pressure=self.hertz_pressure,
                            compressible=compressible)
        return Rheology(law="barus", alpha_bar=self.alpha * self.hertz_pressure,
                        hertz_pressure=self.hertz_pressure, compressible=compressible)


def line_contact_case(
    load_per_length: float,
    radius: float,
    effective_modulus: float,
    entrainment_speed: float,
    viscosity: float,
    *,
    alpha: float | None = None,
    roelands_z: float | None = None,
) -> LineContactCase:
    """Build the dimensionless groups of a line contact.

    Parameters
    ----------
    load_per_length : w' [N/m]; radius : reduced radius R_x [m]; effective_modulus : E' [Pa];
    entrainment_speed : u_m = (u1+u2)/2 [m/s]; viscosity : eta0 at the inlet [Pa s];
    alpha : pressure-viscosity coefficient [1/Pa] (Barus, or the Roelands-equivalent
        ``z (ln eta0 + 9.67)/p0`` if only ``roelands_z`` is given);
    roelands_z : Roelands index z [-]; if given the Roelands law (paper 000 eq. 9) is used.
    """
    for name, v in (("load_per_length", load_per_length), ("radius", radius),
                    ("effective_modulus", effective_modulus),
                    ("entrainment_speed", entrainment_speed), ("viscosity", viscosity)):
        check_positive(name, v)
    if alpha is None and roelands_z is None:
        raise InputError("alpha", None, "alpha [1/Pa] or roelands_z must be given")
    if alpha is None:
        alpha = roelands_z * (math.log(viscosity) + 9.67) / 1.96e8
    check_positive("alpha", alpha, allow_zero=True)
    U = viscosity * entrainment_speed / (effective_modulus * radius)
    W = load_per_length / (effective_modulus * radius)
    G = alpha * effective_modulus
    M = W / math.sqrt(2 * U)
    L = G * (2 * U) ** 0.25
    b = radius * math.sqrt(8 * W / math.pi)
    pH = effective_modulus * math.sqrt(W / (2 * math.pi))
    return LineContactCase(load_per_length, radius, effective_modulus, entrainment_speed,
                           viscosity, alpha, roelands_z, U, W, G, M, L, b, pH)


def solve_line_contact(
    load_per_length: float,
    radius: float,
    effective_modulus: float,
    entrainment_speed: float,
    viscosity: float,
    *,
    alpha: float | None = None,
    roelands_z: float | None = None,
    compressible: bool = True,
    n: int = 1024,
    linear: str = "krylov",
    max_grid_error: float = 0.05,
    domain: tuple[float, float] | None = None,
) -> LineEHLSolution:
    """Isothermal Newtonian EHL of a line contact, dimensional front end.

    Parameters as :func:`line_contact_case`; ``compressible`` applies Dowson-Higginson
    (paper 000 eq. 10); ``n`` nodes on the finest grid. See :func:`solve_dimensionless` for
    the errors raised. Returns a :class:`LineEHLSolution` in SI units.
    """
    case = line_contact_case(load_per_length, radius, effective_modulus, entrainment_speed,
                             viscosity, alpha=alpha, roelands_z=roelands_z)
    sol = solve_dimensionless(
        case.M, case.L, n=n if domain is not None else nodes_for(case.M, n, case.L),
        rheology=case.rheology(compressible), linear=linear,
        max_grid_error=max_grid_error, domain=domain,
        reference=(radius, case.half_width, case.hertz_pressure, viscosity),
    )
    return _with_speed(sol, entrainment_speed)


def _with_speed(sol: LineEHLSolution, u: float) -> LineEHLSolution:
    from dataclasses import replace

    return replace(sol, entrainment_speed=float(u))
