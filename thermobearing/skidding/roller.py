"""Skidding of a cylindrical roller bearing: the Z + 1 equations of paper 000 (solve driver).

Li, Chen, Zhang, Wang (2018), seed ``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding],
after Harris (1966) [harris1966_roller_skidding; harris_kotzalas2007]. Unknowns: the spin
speed ``omega_r,j`` of every roller and the cage speed ``omega_c``.

One job: drive the solve (:func:`solve_roller` from a bearing and lubricant,
:func:`solve_model` for a prepared model): starts, the outer fixed point of the centrifugal
loads (and of the film-supported ring), the fallback, the errors and the result. The pieces
live in their own modules, re-exported here so that ``from thermobearing.skidding.roller
import X`` keeps working:

* :mod:`~thermobearing.skidding.roller_model`: :class:`RollerModel`, :func:`build_model`,
  :func:`default_traction_law`, the model options (unloaded zone, ring support);
* :mod:`~thermobearing.skidding.roller_residual`: :func:`evaluate`, the equations
  (paper eqs. 12-15, 20-32);
* :mod:`~thermobearing.skidding.roller_loads`: the load distribution at a cage speed
  (dry load zone or film-supported ring);
* :mod:`~thermobearing.skidding.roller_solvers`: Newton with the arrow Jacobian and the
  bracketed fallback, :func:`initial_guess`;
* :mod:`~thermobearing.skidding.roller_result`: :class:`RollerSkiddingResult`;
* :mod:`~thermobearing.skidding.roller_diagnostics`: :func:`cage_force_balance`;
* :mod:`~thermobearing.skidding.roller_maxwell` and
  :mod:`~thermobearing.skidding.roller_pressure`: the Hertz-zone shear options of
  :func:`build_model` (``fluid_shear_modulus``: Maxwell film, Johnson & Tevaarwerk 1977;
  ``film_pressure="regime_min"``: the rigid-regime film pressure instead of p_H).

Failure raises :class:`~thermobearing.errors.ConvergenceError` with the residual and the
state; so does a state without any inner-ring contact (no drive).

Slip (paper eqs. 39-40): s_f = 1 - n / n_m, n_m = n_i (1 - D/d_m)/2.
"""

from __future__ import annotations

import math
from inspect import signature
from typing import Any

import numpy as np

from ..errors import (
    ConvergenceError,
    InputError,
    UnknownNameError,
    check_finite,
    check_positive,
    check_range,
)
from ..loads_roller import LINE_CONTACT_EXPONENT, roller_load_distribution
from .roller_diagnostics import CageForceBalance, cage_force_balance
from .roller_loads import _gapped, _load_distribution
from .roller_model import (
    DEFAULT_POCKET_CLEARANCE_FRACTION,
    RING_SUPPORT_MODELS,
    UNLOADED_ZONE_MODELS,
    RollerModel,
    _film_for,  # noqa: F401  (re-exported: private helper kept importable)
    build_model,
    default_traction_law,
)
from .roller_residual import _Eval, evaluate  # noqa: F401  (_Eval re-exported)
from .roller_result import RollerSkiddingResult
from .roller_solvers import (  # noqa: F401
    _force_scale,
    _nested,
    _newton,
    _newton_floor,
    _roller_speeds,
    initial_guess,
)

#: ``method`` values of :func:`solve_model`
SOLVE_METHODS = ("newton", "bracketed")

#: the 0.8 cold guess, when Newton takes no step from it, is retried (after the round-off
#: acceptance, before the best iterate) with its rollers this fraction below rolling on the
#: outer race. The guess puts them on the cusp of the thermal reduction at zero slide
#: (gupta_1992's |SRR|^0.83: an unloaded roller's residual rises as |d|^0.83 either side of
#: its speed, the forward differences see one branch and the Newton step is no descent
#: direction). D1842926 at 8000 r/min, 1000 N, 20 degC then converges as "cold_0.8_lag" in
#: 0.28 s of CPU (the bracketed fallback took 1.85 s) to the bracketed state within 1.6e-13,
#: and at 140 degC (was "best_iterate", 3.5e-9 off in CSR) within 5.5e-14; the 8 cold-oil
#: NU 206 points that end in the slide solve after the bracketed one spend 0.1-0.2 s more on
#: the retry (benchmarks/bm_roller_cold.py's 180 points: the other 178 states and paths
#: unchanged to the bit)
COLD_LAG = 1e-6

#: relative force tolerance of the dry ring balance the solver calls (the ``rtol`` default of
#: :func:`thermobearing.loads_roller.roller_load_distribution`, which
#: :func:`~thermobearing.skidding.roller_loads._load_distribution` leaves at its default)
RING_BALANCE_RTOL = float(signature(roller_load_distribution).parameters["rtol"].default)


def smallest_radial_load(model: RollerModel) -> float:
    """Smallest radial load F_min [N] the dry ring balance (``ring_support="contacts"``)
    resolves for a bearing with clearance; 0 without clearance or on films.

    :func:`~thermobearing.loads_roller.roller_load_distribution` stops when its force
    residual is within rtol * max(F_r, 1e-6 K (P_d/2)^n, 1e-9) N (rtol =
    :data:`RING_BALANCE_RTOL`, K the inner line-contact stiffness [N/m^n], n = 10/9). For
    F_r <= F_min = rtol * max(1e-6 K (P_d/2)^n, 1e-9) the load itself is within that
    tolerance: the balance returns at its start, unresolved (without body forces one roller
    carries half the load, residual 0.5 F_r; with the centrifugal force of the rollers, which
    holds them off the inner ring by more than the start's approach, no roller closes and
    the cage speed is undetermined). At 1.5 F_min it iterates to a loaded roller (NU214,
    P_d = 25 um: F_min = 6.1e-13 N, 1.5 F_min solves; 5e-27 N ended as 'did not converge
    (residual inf): no roller touches the inner ring'). Units: N."""
    half = 0.5 * model.diametral_clearance
    if model.ring_support != "contacts" or half <= 0.0:
        return 0.0
    scale = max(1e-6 * model.k_inner * max(half, 1e-9) ** LINE_CONTACT_EXPONENT, 1e-9)
    return RING_BALANCE_RTOL * scale


def _check_radial_load(model: RollerModel, radial_load: float) -> None:
    """InputError naming the load before any solve when the dry ring balance
    (``ring_support="contacts"``) cannot put a roller on the inner ring: an input the model
    cannot take, not a solver failure.

    - F_r = 0 (this solver takes no axial load, so the bearing is unloaded): the centrifugal
      force holds every roller on the outer ring, none touches the inner ring, the model has
      no traction to drive the cage and the cage speed is undetermined (before: the solve's
      ConvergenceError 'no roller touches the inner ring', residual inf, with or without
      clearance). The film-supported ring (``ring_support="films"``) carries the rollers on
      its clearance films and solves at 0 N, so it is left alone.
    - 0 < F_r <= :func:`smallest_radial_load`: below the force resolution of the balance."""
    if radial_load == 0.0 and model.ring_support == "contacts":
        raise InputError(
            "radial_load and axial_load", "0 N and 0 N",
            "a radial load > 0 N: unloaded, the centrifugal force holds every roller on the "
            "outer ring, none touches the inner ring and the roller skidding solver (paper "
            "000, ring_support 'contacts') has no traction to drive the cage; an axial load "
            "is carried by the ribs of a ribbed bearing, which this solver does not model "
            "(axial_load = 0 only; thermobearing.rib books the rib contact)")
    f_min = smallest_radial_load(model)
    if 0.0 < radial_load <= f_min:
        raise InputError(
            "radial_load", f"{radial_load:g} N",
            f"a radial load above {f_min:.3g} N, the force resolution of the dry ring "
            f"balance with P_d = {model.diametral_clearance * 1e6:.4g} um of clearance "
            f"({RING_BALANCE_RTOL:g} of 1e-6 K (P_d/2)^(10/9)): below it no roller closes on "
            "the inner ring and the cage speed is undetermined")

__all__ = [
    "DEFAULT_POCKET_CLEARANCE_FRACTION",
    "RING_SUPPORT_MODELS",
    "UNLOADED_ZONE_MODELS",
    "CageForceBalance",
    "RollerModel",
    "RollerSkiddingResult",
    "SOLVE_METHODS",
    "as_warm_start",
    "build_model",
    "cage_force_balance",
    "default_traction_law",
    "evaluate",
    "initial_guess",
    "smallest_radial_load",
    "solve_model",
    "solve_roller",
]


def solve_model(
    model: RollerModel,
    omega: float,
    radial_load: float,
    *,
    azimuth: np.ndarray | None = None,
    whirl_acceleration: tuple[float, float] = (0.0, 0.0),
    x0: np.ndarray | None = None,
    tol: float = 1e-9,
    max_iter: int = 60,
    load_x0: tuple[float, float] | None = None,
    fallback: bool = True,
    radial_acceleration: np.ndarray | None = None,
    method: str = "newton",
) -> RollerSkiddingResult:
    """Solve the Z + 1 equations for a prepared :class:`RollerModel` (see :func:`solve_roller`).

    ``method``: "newton" (default): the Newton attempts (warm start, cold guesses, pure
    rolling, the best iterate; a stalled iterate within every equation's round-off floor is
    accepted), the bracketed solve only when they all fail. "bracketed": no Newton attempt;
    the bracketed solve (Brent on the cage equation over its whole range, every roller
    bisected over its whole range, then a Newton polish) from the loads at the cold guess
    (0.8 of the epicyclic cage speed) -- the robust path the solver took before the
    round-off acceptance, slow (seconds per point) but with no start to depend on; the
    reference of ``benchmarks/bm_roller_cold.py``. It ignores ``x0``.
    ``fallback=False`` skips the (slow, robust) slide-variable and bracketed solves when
    Newton fails and raises the ConvergenceError at once.

    A state beyond ``tol`` (round-off or bracketed) is accepted only when its shaft power and
    dissipation agree to ``ENERGY_TOLERANCE`` (1e-6 relative, :func:`_state_energy_gap`):
    under heavy load in cold oil the film is so viscous that one ulp of a sliding speed
    carries hundreds of N of traction; the speeds are then right to round-off but the
    tractions balance nothing (CRB 50x75x16, 20 kN, ISO VG 46 at 20 degC, 5000 r/min:
    residual 0.21 of the roller load, shaft power 12.2 kW against 1.3 kW booked). Such a
    state (and a bracketed root that fails or is refused so) goes to the slide-variable
    solve (:mod:`~thermobearing.skidding.roller_slides`,
    method "slides": the sliding speeds as unknowns, resolved far below the speeds'
    round-off; there 1.2 kW = 1.2 kW to 2e-16, residual 1e-17).

    ``radial_acceleration`` (Z,) [m/s^2]: the whirl acceleration in each roller's radial
    balance (eqs. 20/23) when it is not the projection of ``whirl_acceleration`` (see
    :class:`~thermobearing.skidding.whirl.Whirl`); the tangential balance (eqs. 21/24)
    always uses the projection.
    """
    if method not in SOLVE_METHODS:
        raise UnknownNameError("roller skidding method", method, SOLVE_METHODS)
    _check_radial_load(model, radial_load)
    z = model.n_rollers
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None else np.asarray(azimuth, float)
    if x0 is not None and np.size(x0) != z + 1:
        # another bearing's state (a D1842926 start for the NU214 raised
        # IndexError deep in the residual)
        raise InputError("x0", f"{np.size(x0)} values",
                         f"{z + 1} values (omega_r of the {z} rollers, omega_c) of this bearing, "
                         "e.g. a previous result of the same bearing")

    last_q: list[np.ndarray | None] = [None]

    def loads(wc: float, ring: Any, wr: np.ndarray | None = None) -> tuple[Any, np.ndarray]:
        ld, fbw = _load_distribution(model, omega, radial_load, wc, wr, psi,
                                     whirl_acceleration, ring, last_q[0], radial_acceleration)
        last_q[0] = ld.inner_load
        return ld, fbw

    # Attempts, in order (each a start and the finite-difference step of its Newton, as a
    # fraction of the inner speed):
    # - a warm start, first with the fine step 1e-10, then with the default 1e-7: near pure
    #   rolling under load the tractions saturate within a slip of ~1e-7, the default step
    #   spans the saturation and Newton stalls, creeping through up to 60 x 30 line-search
    #   evaluations (a catalogue NU 206 protocol at 2 kN spent half its CPU so);
    # - the cold guesses at 0.8 and 0.4 of the epicyclic cage speed (default step), as before;
    # - pure rolling with the fine step: where those fail under load (the cage equation jumps
    #   across pure rolling) the solution is within ~1e-8 of it (NU 206, 2 kN, 22-27 degC:
    #   converges in 0.1-0.5 s of CPU to the state the bracketed fallback found in 6-12 s);
    # - when Newton took no step from the 0.8 cold guess (its rollers exactly on the cusp of
    #   the thermal reduction at zero slide, see COLD_LAG), that guess with the rollers
    #   COLD_LAG below outer-race rolling, after the round-off acceptance ("cold_0.8_lag");
    # - the best iterate so far with the fine step.
    # Near pure rolling under heavy load one ulp of the speeds can change the residual by
    # more than tol allows (NU214, 45 kN, 8000 r/min: the cage equation changes by 0.14 N per
    # 1e-12 of the cage speed): before the last attempt the best iterate is accepted when
    # every equation's residual is within 4 of its round-off floor (method
    # "newton_round_off"; the bracketed fallback accepts its root within 4 floors of the norm).
    # The bracketed fallback runs only when all of them fail; it starts around the best
    # iterate (benchmarks/bm_roller_cold.py, 180 cold points: 20 took it, 5-12 s of CPU
    # each; now 12 converge as "newton_round_off" in 0.2-0.8 s, 8 by the bracketed solve in
    # 1.3-2.7 s, all to the former states within 3e-14).
    if method == "bracketed":
        return _bracketed_only(model, omega, radial_load, loads, psi, whirl_acceleration, tol,
                               max_iter, load_x0)
    attempts = [(x0, 1e-10, "warm"), (x0, 1e-7, "warm")] if x0 is not None else []
    attempts += [(initial_guess(model, omega, c), 1e-7, f"cold_{c:g}") for c in (0.8, 0.4)]
    attempts.append((initial_guess(model, omega, 1.0), 1e-10, "pure_rolling"))
    best = None
    films = model.ring_support == "films"
    i_attempt = 0
    polished = False
    floor = math.inf  # round-off floor at the best iterate (0: Newton met tol)
    rejected: list[tuple[str, float, float]] = []  # (method, norm, energy gap) refused
    slid = False  # the slide-variable solve was tried
    steps = 0  # Newton steps of every pass and start (the result's ``iterations``)
    lagged: list[tuple[np.ndarray, float, str]] = []  # cold guesses Newton left unmoved
    while i_attempt < len(attempts):
        start, fd_step, start_name = attempts[i_attempt]
        i_attempt += 1
        x = np.array(start, dtype=float)
        ring = load_x0
        for _outer in range(60 if films else 8):
            ld, fb_whirl = loads(x[z], ring, x[:z])
            if ld.n_loaded == 0:
                raise ConvergenceError(
                    "roller_skidding", math.inf,
                    "no roller touches the inner ring (radial load "
                    f"{radial_load:g} N with clearance): the model has no traction to drive the "
                    "cage (paper 000 neglects the hydrodynamic drive across the clearance), so "
                    "the cage speed is undetermined",
                    {"radial_load": radial_load, "inner_speed": omega})
            ring = tuple(ld.ring_displacement)
            x_old = x.copy()
            x, e, norm, it, ok = _newton(_gapped(model, ld), omega, x, ld.inner_load, fb_whirl,
                                         psi, whirl_acceleration, tol=tol, max_iter=max_iter,
                                         fd_step=fd_step)
            steps += it
            if not ok or float(np.max(np.abs(x - x_old))) <= 1e-8 * omega:
                break
        if not ok and start_name == "cold_0.8" and np.array_equal(x, start):
            # Newton took no step from the cold guess: its rollers roll exactly on the outer
            # race, the cusp of the thermal reduction's |SRR|^0.83 (gupta_1992, the default;
            # COLD_LAG). The same guess with the rollers COLD_LAG below outer-race rolling
            # is tried after the round-off acceptance, before the best iterate.
            lag = np.array(start, dtype=float)
            lag[:z] *= 1.0 - COLD_LAG
            lagged.append((lag, fd_step, f"{start_name}_lag"))
        if best is None or norm < best[2]:
            best = (x, e, norm, it, ok, ld)
            best_start = start_name
        if ok:
            break
        if i_attempt == len(attempts) and not polished:
            polished = True
            state, floor = _round_off_state(model, omega, best, loads, psi, whirl_acceleration,
                                            tol)
            if state is not None:
                gap = _state_energy_gap(model, omega, psi, state, whirl_acceleration, tol)
                if gap <= ENERGY_TOLERANCE:
                    best, method = state, "newton_round_off"
                    break
                rejected.append(("newton_round_off", state[2], gap))
                # a stuck film (module roller_slides): solve in the slides at once
                slid = True
                state = (_slide_state(model, omega, loads, psi, whirl_acceleration, tol, best)
                         if fallback else None)
                if state is not None:
                    best, method, best_start, floor = state, "slides", "slides", 0.0
                    break
            attempts.extend(lagged)
            attempts.append((best[0], 1e-10, "best_iterate"))
    if best[4] and method == "newton":
        floor = 0.0  # Newton met tol
    if not best[4] and fallback:
        # robust fallback: roller equations by vectorised bisection inside a bracketed
        # (Brent) solve of the cage equation, then a Newton polish
        x, e, norm, it, ok, ld, floor = _nested(model, omega, loads, psi, whirl_acceleration,
                                                tol, max_iter, best[5], float(best[0][z]),
                                                best[0][:z])
        steps += it
        if ok and floor > 0.0:
            gap = _state_energy_gap(model, omega, psi, (x, e, norm, it, ok, ld),
                                    whirl_acceleration, tol)
            if gap > ENERGY_TOLERANCE:
                ok = False
                rejected.append(("bracketed", norm, gap))
        if ok:
            best = (x, e, norm, it, ok, ld)
            method = "bracketed"
            best_start = "bracketed"
        elif x is not None and e is not None and norm < best[2]:
            best = (x, e, norm, it, ok, ld)
        if not ok and not slid:
            # the bracketed root failed or was refused: the slides as unknowns
            state = _slide_state(model, omega, loads, psi, whirl_acceleration, tol, best)
            if state is not None:
                best, method, best_start, floor = state, "slides", "slides", 0.0
    best = (*best[:3], steps, *best[4:])
    x, e, norm, it, ok, ld = best
    if not ok:
        refused = "".join(
            f"; the {name} state (residual {r_norm:.3g}) was refused: shaft power and "
            f"dissipation differ by {r_gap:.3g} of the larger (allowed "
            f"{ENERGY_TOLERANCE:g}), its tractions balance nothing"
            for name, r_norm, r_gap in rejected)
        raise ConvergenceError(
            "roller_skidding", norm, "Newton with line search stalled, the slide-variable "
            "solve and the bracketed fallback failed" + refused,
            {"cage_speed": x[z], "cage_speed_ratio": x[z] / omega, "radial_load": radial_load,
             "inner_speed": omega, "roller_speed_mean": float(np.mean(x[:z])),
             "iterations": it, "round_off_floor": floor})
    return _result(model, omega, psi, best, method, best_start, i_attempt, floor, tol)


def _bracketed_only(model: RollerModel, omega: float, radial_load: float, loads: Any,
                    psi: np.ndarray, acc: tuple[float, float], tol: float, max_iter: int,
                    load_x0: tuple[float, float] | None) -> RollerSkiddingResult:
    """``solve_model(method="bracketed")``: :func:`_nested` over the whole cage-speed range
    (no start around a Newton iterate) from the loads at the cold guess (0.8 of the
    epicyclic cage speed, rollers rolling on the outer race)."""
    z = model.n_rollers
    cold = initial_guess(model, omega, 0.8)
    ld0, _ = loads(float(cold[z]), load_x0, cold[:z])
    if ld0.n_loaded == 0:
        raise ConvergenceError(
            "roller_skidding", math.inf,
            f"no roller touches the inner ring (radial load {radial_load:g} N with clearance):"
            " the cage speed is undetermined", {"radial_load": radial_load, "inner_speed": omega})
    x, e, norm, it, ok, ld, floor = _nested(model, omega, loads, psi, acc, tol, max_iter, ld0,
                                            wc_loads=float(cold[z]))
    if ok and floor > 0.0 and _state_energy_gap(model, omega, psi, (x, e, norm, it, ok, ld),
                                                acc, tol) > ENERGY_TOLERANCE:
        state = _slide_state(model, omega, loads, psi, acc, tol, (x, e, norm, it, ok, ld))
        if state is not None:
            return _result(model, omega, psi, state, "slides", "slides", 0, 0.0, tol)
        ok = False
    if not ok:
        raise ConvergenceError(
            "roller_skidding", norm, "the bracketed solve (method='bracketed') failed: no sign "
            "change of the cage equation, Brent did not converge or the root is beyond 4 "
            "round-off floors",
            {"radial_load": radial_load, "inner_speed": omega, "round_off_floor": floor,
             "cage_speed": float(x[z])})
    return _result(model, omega, psi, (x, e, norm, it, ok, ld), "bracketed", "bracketed", 0,
                   floor, tol)


def _result(model: RollerModel, omega: float, psi: np.ndarray, best: tuple[Any, ...],
            method: str, start: str, attempts: int, floor: float, tol: float
            ) -> RollerSkiddingResult:
    """The :class:`RollerSkiddingResult` of a converged state ``best`` = (x, eval, norm,
    iterations, ok, load distribution); ``method``, ``start``, ``attempts`` and ``floor`` go
    to its extras, with ``round_off_equations`` and ``residual_note`` (what the norm means:
    :func:`_residual_note`; see the class docstring)."""
    x, e, norm, it, _ok, ld = best
    z = model.n_rollers
    residual = np.append(e.roller_eq, e.cage_eq)
    scale = float(np.linalg.norm(residual)) / norm if norm > 0.0 else 1.0
    at_floor = tuple(int(i) for i in np.flatnonzero(np.abs(residual) > tol * scale))
    csr = x[z] / omega
    csr_th = model.theoretical_cage_speed_ratio
    return RollerSkiddingResult(
        inner_speed=omega, cage_speed=float(x[z]), cage_speed_ratio=float(csr),
        theoretical_cage_speed_ratio=csr_th, slip=float(1.0 - csr / csr_th),
        roller_speed=x[:z].copy(), azimuth=psi, inner_load=ld.inner_load, outer_load=e.q_o,
        inner_sliding_speed=e.v_i, outer_sliding_speed=e.v_o,
        inner_entrainment_speed=e.ue_i, outer_entrainment_speed=e.ue_o,
        inner=e.inner, outer=e.outer, pocket_normal_force=e.pocket, pocket_friction=e.friction,
        converged=True, residual_norm=norm, iterations=it,
        residual=residual, temperature=model.temperature,
        eta0=model.eta0, extras={"ring_displacement": ld.ring_displacement, "method": method,
                                 "start": start, "attempts": attempts,
                                 "round_off_floor": floor,
                                 "round_off_equations": at_floor,
                                 "residual_note": _residual_note(residual, scale, norm, floor,
                                                                 tol, at_floor, z),
                                 "n_loaded": ld.n_loaded, "contact_length": model.length,
                                 "radius_inner": model.radius_inner,
                                 "radius_outer": model.radius_outer,
                                 "roller_diameter": model.roller_diameter,
                                 "raceway_radius_inner": 0.5 * (model.pitch_diameter
                                                                - model.roller_diameter),
                                 "pitch_diameter": model.pitch_diameter,
                                 "cage_drag_torque": model.cage_drag_torque,
                                 "thermal_reduction": model.thermal_reduction,
                                 "drag": (None if model.drag is None
                                          else model.drag.state(omega, float(x[z])))},
    )


def _residual_note(residual: np.ndarray, scale: float, norm: float, floor: float, tol: float,
                   at_floor: tuple[int, ...], z: int) -> str:
    """What ``residual_norm`` means for this state, in words (``extras["residual_note"]``).

    Within ``tol``: the distance from the root in the scaled residual. Beyond it (a state
    accepted at the round-off floor): the equations ``at_floor`` (indices < Z: roller moment
    balances, Z: the cage) change by about their residual when a speed moves by one ulp --
    a loaded roller rolling on a raceway at a slide of a few ulps of its surface speed, where
    the saturated traction steps by up to mu Q between neighbouring floats -- so the norm
    measures that step of the equations in double precision, not a distance from the root
    (measured: catalogue NU 206, 13 kN, 20 degC, ISO VG 68, 2000 and 30000 r/min: norm 0.10
    and 0.11 of the 4.7 kN roller load, 110-410 N on the two most loaded rollers and the
    cage; the state equals the bracketed solve's to 1e-15, benchmarks/bm_roller_cold.py).
    """
    if not at_floor:
        return f"residual norm {norm:.3g} <= tol {tol:g}: within the tolerance"
    names = ", ".join("cage" if i == z else f"roller {i}" for i in at_floor)
    worst = float(np.max(np.abs(residual[list(at_floor)])))
    return (f"residual norm {norm:.3g} > tol {tol:g} at the round-off floor {floor:.3g}: "
            f"{names} (up to {worst:.3g} N, force scale {scale:.4g} N) change by about that "
            "much per one-ulp change of the speeds (saturated traction near pure rolling); "
            "the norm is that step, not a distance from the root")


def _round_off_state(model: RollerModel, omega: float, best: tuple[Any, ...],
                     loads: Any, psi: np.ndarray, acc: tuple[float, float], tol: float
                     ) -> tuple[tuple[Any, ...] | None, float]:
    """The best Newton iterate (or its cage speed with the rollers bisected there, whichever
    has the smaller norm), with the loads of its own cage speed, when every one of its
    equations is within 4 round-off floors of that equation (or within ``tol`` of the force
    scale; :func:`~thermobearing.skidding.roller_solvers._newton_floor`): (state, floor), or
    (None, floor) when it is not. ``floor``: the norm of the per-equation floors scaled as
    Newton's norm (inf: nothing to measure)."""
    x = best[0]
    if not np.all(np.isfinite(x)):
        return None, math.inf
    z = model.n_rollers
    ring = tuple(best[5].ring_displacement)
    ld, fb = loads(float(x[z]), ring, x[:z])
    if ld.n_loaded == 0:
        return None, math.inf
    mg = _gapped(model, ld)
    scale = _force_scale(model, omega, ld.inner_load)
    wc = float(x[z])
    wr_root, changes = _newton_floor(mg, omega, x[:z], wc, ld.inner_load, fb, psi, acc)
    floor = float(np.linalg.norm(changes)) / scale
    accepted = None
    # candidates: the iterate, and its cage speed with the rollers bisected there (Newton's
    # line search on the norm can leave the smooth equations of unloaded rollers unsolved
    # while the stiff loaded ones dominate; film-supported rings: loads follow the spins)
    for wr in (x[:z],) if model.ring_support == "films" else (x[:z], wr_root):
        e = evaluate(mg, omega, wr, wc, ld.inner_load, fb, psi, acc)
        res = np.append(e.roller_eq, e.cage_eq)
        norm = float(np.linalg.norm(res)) / scale
        if (np.all(np.abs(res) <= np.maximum(4.0 * changes, tol * scale / math.sqrt(z + 1)))
                and norm <= max(tol, 4.0 * floor)
                and (accepted is None or norm < accepted[2])):
            accepted = (np.append(wr, wc), e, norm, best[3], True, ld)
    return accepted, floor


#: largest relative difference of shaft power and dissipation an accepted state beyond
#: ``tol`` may have (:func:`_state_energy_gap`)
ENERGY_TOLERANCE = 1e-6


def _state_energy_gap(model: RollerModel, omega: float, psi: np.ndarray,
                      state: tuple[Any, ...], acc: tuple[float, float], tol: float) -> float:
    """Relative gap |P_shaft - P_loss| / max(|P_shaft|, |P_loss|) of a state (x, eval, norm,
    iterations, ok, load distribution): ``shaft_torque * omega`` against
    ``power_loss["total"]`` of its :class:`RollerSkiddingResult`, which are equal when the
    Z + 1 equations hold (see :meth:`RollerSkiddingResult.booked_power`). 0 when the whirl
    accelerations of the rollers do not sum to zero (uneven azimuths under whirl: the
    inertia then does work the identity leaves out) or when both powers are 0."""
    a_t = -acc[0] * np.sin(psi) + acc[1] * np.cos(psi)
    if abs(float(np.sum(a_t))) > 1e-9 * max(float(np.sum(np.abs(a_t))), 1e-300):
        return 0.0
    res = _result(model, omega, psi, state, "check", "check", 0, 0.0, tol)
    shaft = res.shaft_torque * omega
    loss = res.power_loss["total"]
    big = max(abs(shaft), abs(loss))
    return abs(shaft - loss) / big if big > 0.0 else 0.0


def _slide_state(model: RollerModel, omega: float, loads: Any, psi: np.ndarray,
                 acc: tuple[float, float], tol: float, best: tuple[Any, ...]
                 ) -> tuple[Any, ...] | None:
    """The slide-variable solve (:func:`~thermobearing.skidding.roller_slides.solve_slides`)
    from the load distribution of ``best`` (x, eval, norm, iterations, ok, load
    distribution) as a state tuple, when the model's drag takes exact slides, the speeds
    are finite and the solve meets ``tol``; else None."""
    from .roller_residual import exact_slides_supported
    from .roller_slides import solve_slides

    x, ld = best[0], best[5]
    if not exact_slides_supported(model) or ld is None or not np.all(np.isfinite(x)):
        return None
    z = model.n_rollers
    out = solve_slides(model, omega, loads, psi, acc, ld, float(x[z]),
                       lambda q: _force_scale(model, omega, q))
    if out is None or not out[2] <= tol:
        return None
    xs, e, norm, ld_s = out
    return (xs, e, norm, best[3], True, ld_s)


def _check_option_names(options: dict[str, Any]) -> None:
    """UnknownNameError (listing the model options) for an option :func:`build_model` lacks."""
    import inspect

    known = [name for name, p in inspect.signature(build_model).parameters.items()
             if p.kind is inspect.Parameter.KEYWORD_ONLY]
    for key in options:
        if key not in known:
            raise UnknownNameError(f"roller skidding option {key!r}", key,
                                   ["whirl", "x0", "azimuth", "tol", "max_iter", *known])


def as_warm_start(guess: Any) -> np.ndarray | None:
    """(omega_r, omega_c) array from an array, a RollerSkiddingResult or a WhirlResult."""
    if guess is None:
        return None
    states = getattr(guess, "states", None)
    if states:
        guess = states[-1]
    if hasattr(guess, "roller_speed") and hasattr(guess, "cage_speed"):
        return np.append(np.asarray(guess.roller_speed, dtype=float), float(guess.cage_speed))
    allowed = "an array (omega_r..., omega_c) [rad/s] or a previous roller skidding result"
    try:
        arr = np.asarray(guess, dtype=float)
    except (TypeError, ValueError):
        # e.g. a ball bearing's result (TypeError from float())
        raise InputError("x0", type(guess).__name__, allowed) from None
    if arr.ndim != 1 or arr.size < 4 or not np.all(np.isfinite(arr)):
        raise InputError("x0", guess, allowed)
    return arr


def solve_roller(
    bearing: Any,
    lubricant: Any,
    speed: float,
    radial_load: float,
    axial_load: float = 0.0,
    temperature: float = 313.15,
    *,
    whirl: Any = None,
    x0: np.ndarray | None = None,
    azimuth: np.ndarray | None = None,
    tol: float = 1e-9,
    max_iter: int = 60,
    **model_options: Any,
) -> Any:
    """Cage and roller speeds of a cylindrical roller bearing (paper 000 Z + 1 equations).

    Parameters
    ----------
    bearing : :class:`thermobearing.geometry.RollerBearing`.
    lubricant : :class:`thermobearing.lubricant.Lubricant`.
    speed : inner-ring speed omega [rad/s] (> 0; outer ring fixed).
    radial_load : F_r [N] (>= 0).
    axial_load : must be 0 (a cylindrical roller bearing carries no axial load here) [N].
    temperature : oil/contact temperature [K].
    whirl : None, or a :class:`thermobearing.skidding.whirl.Whirl` (paper 000 eqs. 1-4):
        the result is then a :class:`~thermobearing.skidding.whirl.WhirlResult` time series.
    x0 : warm start: an array (omega_r (Z,), omega_c) [rad/s], or a previous
        RollerSkiddingResult / WhirlResult (its last sample) of the same bearing.
    azimuth : (Z,) roller azimuths [rad] (default: a roller under the load).
    tol : tolerance on the residual norm scaled by the largest inner load [-].
    **model_options : passed to :func:`build_model` (viscosity, eyring_stress,
        limiting_shear_coefficient, traction_law, film_model, drag_model, pocket_clearance,
        cage_drag_torque, ring_support, unloaded_zone, fluid_shear_modulus, film_pressure,
        traction_curve, pocket_film, drag). Without ``drag`` (the default) the balance has
        no oil drag, as paper 000; ``skidding.solve`` with an oil supply builds one
        (:mod:`~thermobearing.skidding.roller_drag`).

    Returns
    -------
    RollerSkiddingResult (or WhirlResult when ``whirl`` is given).
    """
    check_positive("speed", speed)
    check_positive("radial_load", radial_load, allow_zero=True)
    check_finite("axial_load", axial_load)
    check_range("tol", tol, 0.0, 1.0, low_inclusive=False, high_inclusive=False)
    if isinstance(max_iter, bool) or not isinstance(max_iter, int | np.integer) or max_iter < 1:
        raise InputError("max_iter", max_iter, "a whole number of Newton iterations >= 1")
    if axial_load != 0.0:
        raise InputError("axial_load", axial_load,
                         "0 for a cylindrical roller bearing (roller-rib thrust is not modelled "
                         "in the skidding solver; see thermobearing.rib)")
    _check_option_names(model_options)
    x0 = as_warm_start(x0)
    model = build_model(bearing, lubricant, temperature, **model_options)
    if whirl is not None:
        from .whirl import solve_whirl

        return solve_whirl(model, speed, radial_load, whirl, x0=x0, tol=tol, max_iter=max_iter)
    result = solve_model(model, speed, radial_load, azimuth=azimuth, x0=x0, tol=tol,
                         max_iter=max_iter)
    if model.traction_curve is not None:
        _warn_curve_range(model.traction_curve, result)
    if model.inlet_heating is not None:
        # the inlet-heating factor's fitted range on the solved contacts (the solve
        # evaluates it without warnings: its iterates pass far-off states)
        from .roller_thermal import check_state_range

        check_state_range(model.inlet_heating,
                          [(result.inner_load, result.inner_entrainment_speed,
                            result.inner_sliding_speed, result.inner.max_pressure),
                           (result.outer_load, result.outer_entrainment_speed,
                            result.outer_sliding_speed, result.outer.max_pressure)])
    return result


def _warn_curve_range(curve: Any, result: Any) -> None:
    """ValidityWarning when a loaded raceway contact of the solution slides beyond the
    slide-to-roll ratio ``curve.s_max`` its traction curve's source exercises."""
    s_max = float(getattr(curve, "s_max", np.inf))
    worst = 0.0
    for q, v, ue in ((result.inner_load, result.inner_sliding_speed,
                      result.inner_entrainment_speed),
                     (result.outer_load, result.outer_sliding_speed,
                      result.outer_entrainment_speed)):
        loaded = np.asarray(q) > 0.0
        if np.any(loaded):
            s = np.abs(np.asarray(v)[loaded]) / np.maximum(np.asarray(ue)[loaded], 1e-6)
            worst = max(worst, float(np.max(s)))
    if worst > s_max:
        import warnings

        from ..errors import ValidityWarning

        warnings.warn(f"traction curve {getattr(curve, 'name', curve)!r}: contacts slide at "
                      f"|s| up to {worst:.3g}, beyond {s_max:g} exercised by its source "
                      "(the curve is extrapolated)", ValidityWarning, stacklevel=3)
