"""Validation runner of the rib contact / roller dynamics (paper 003 trends, Figs. 7-12).

Case ``paper003_pv_slip_trends``: Zhang et al. 2021 (seed ``003_743e023ae6e45686.txt``),
sections 9-10 and conclusions (1)-(5). The paper gives no tabulated PV or slip numbers
(only figures whose data are not in the text), so the case checks the *trends* it states as
ratios and slopes, and the locations of the PV minima against rib angle (0.55 deg) and end-
face crown radius (550 mm). The unbalance, axial-clearance, pocket-clearance, rib-angle and
crown-radius trends use the coupled integration of all rollers and the cage (spins and cage
speed as degrees of freedom,
:func:`thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`, the paper's eqs.
18-19; ``coupled_warmup_orbits`` and ``coupled_orbits`` warm-up and statistics orbits;
``coupled_settle``: the points without unbalance warm up until the orbit-mean cage speed
has settled to that fraction (its orbit-to-orbit change and its creep's extrapolated
remainder, no turning point; simulate_coupled ``settle``), case SOURCE.md "Cage settling";
``coupled_table_retries``: a table-path run that enters the cage runaway first tries that
many other table-path trajectories, then the evaluate path, as the rib heat source does,
default :data:`~thermobearing.skidding.roller_dynamics_heat.DEFAULT_TABLE_RETRIES`; case
SOURCE.md "Table retries in the runner"), as
do the load and speed trends, with the reduced model's values beside them (``reduced_*``,
:func:`thermobearing.skidding.roller_dynamics.simulate_reduced`, quasi-static spins). PV
statistics: time mean (gated), mean over the time in contact (``pv_contact_*``) and peak
(``pv_peak_*``). The reduced model is compared with the coupled one (``reduced_vs_full_*``)
and with the one-roller full model (``reduced_vs_one_roller_*``), with the costs; the
axially free inner ring (eq. 20 line 1) is a report sensitivity (``ring_axial_*``).

Ensembles: with an unbalance the coupled motion is a chaotic rib rattle, so one trajectory's
time mean is one draw. Every point with unbalance is run once per step count of
``coupled_trajectories`` (the base points of the unbalance rows, warm-up
``coupled_base_warmup_orbits``) or ``coupled_sweep_trajectories`` (the sweeps' points), each
step count a decorrelated trajectory; a row is its formula evaluated at the ensemble means
and ``<row>_stderr`` its first-order standard error
(:mod:`thermobearing.validation.ensemble`). The points without unbalance settle to a steady
state and run once. The range gates are those of ``reference.csv``, applied to the ensemble
value; a trajectory that runs away on every path is left out of its point's ensemble and
counted (``coupled_trajectories_failed``). Case SOURCE.md, "Ensembles of the chaotic points".
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ConvergenceError, InputError, ValidityWarning
from ..units import to_si
from . import RUNNERS
from .ensemble import PointEnsemble, delta_method

#: the per-trajectory quantities of a coupled point kept for the ensemble statistics
_POINT_KEYS = ("pv_left", "pv_right", "pv_contact_left", "pv_contact_right", "pv_peak_left",
               "pv_peak_right", "slip_speed", "cost_s")

#: fewest steps per spin period of a trajectory: simulate_coupled's default, the step at
#: which the case's accuracy statements were measured (SOURCE.md)
MIN_TRAJECTORY_STEPS = 400


def _list(inputs: dict[str, Any], key: str, kind: str) -> list[float]:
    if key not in inputs:
        raise InputError(f"inputs.{key}", None, f"a list of {kind} quantities")
    return [to_si(v, kind, field=f"inputs.{key}") for v in inputs[key]]


def parabolic_minimum(x: Any, y: Any) -> float:
    """Abscissa of the minimum of sampled ``y(x)``: vertex of the parabola through the
    smallest sample and its two neighbours (the end sample if the minimum is at an end);
    NaN when a sample is missing (a point that did not run)."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    if not np.all(np.isfinite(y)):
        return math.nan
    i = int(np.argmin(y))
    if i == 0 or i == len(x) - 1:
        return float(x[i])
    c = np.polyfit(x[i - 1:i + 2], y[i - 1:i + 2], 2)
    if c[0] <= 0:
        return float(x[i])
    return float(np.clip(-c[1] / (2 * c[0]), x[i - 1], x[i + 1]))


def _pv(row: dict[str, float]) -> float:
    return row["pv_left"] + row["pv_right"]


def _pvp(row: dict[str, float]) -> float:
    """Peak PV over the run, both faces summed [Pa m/s]."""
    return row["pv_peak_left"] + row["pv_peak_right"]


def _pvc(row: dict[str, float]) -> float:
    """PV averaged over the time each face is in contact, both faces summed [Pa m/s]."""
    return row["pv_contact_left"] + row["pv_contact_right"]


def trajectory_steps(inputs: dict[str, Any], key: str) -> list[int]:
    """The steps per spin period of each trajectory of an unbalance point (case input
    ``key``; K = its length): distinct whole numbers >= :data:`MIN_TRAJECTORY_STEPS`, at
    most 32. Absent: one trajectory at the integrator's default step (the runner before the
    ensembles)."""
    steps = inputs.get(key, [MIN_TRAJECTORY_STEPS])
    allowed = (f"a list of 1 to 32 distinct whole numbers of steps per spin period, each "
               f">= {MIN_TRAJECTORY_STEPS}")
    if (not isinstance(steps, list) or not 1 <= len(steps) <= 32
            or any(isinstance(v, bool) or not isinstance(v, int) for v in steps)
            or any(v < MIN_TRAJECTORY_STEPS for v in steps) or len(set(steps)) != len(steps)):
        raise InputError(f"inputs.{key}", steps, allowed)
    return list(steps)


def point_of(rows: list[dict[str, float]], *, deterministic: bool) -> PointEnsemble:
    """The :class:`~thermobearing.validation.ensemble.PointEnsemble` of one point's finished
    runs (their :data:`_POINT_KEYS`; no runs: a point without a value)."""
    return PointEnsemble({k: np.array([float(r[k]) for r in rows]) for k in _POINT_KEYS},
                         deterministic=deterministic)


@RUNNERS.register("paper003_pv_slip_trends",
                  references=["zhang2021_abnormal_wear", "archard1953", "gear1971_dae"])
def paper003_pv_slip_trends(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """PV and slip trends of paper 003 (unbalance, load, speed, clearances, rib, crown)."""
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding import roller_dynamics as rd

    bearing = load_bearing(inputs.get("bearing", "CRB_50x75x16"))
    lub = load_lubricant(inputs.get("lubricant", "MIL_PRF_23699"))
    temperature = to_si(inputs.get("temperature", "80 degC"), "temperature",
                        field="inputs.temperature")
    m_lo, m_hi = _list(inputs, "unbalance", "mass")
    slide = inputs.get("slide", "offset")
    pocket_dof = bool(inputs.get("pocket_dof", True))
    cache: dict = {}
    out: dict[str, float] = {}

    def sweep(parameter: str, values: list[float], masses: list[float],
              spin: str = "skidding") -> list[dict]:
        return rd.pv_slip_map(bearing, lub, parameter, values, masses,
                              temperature=temperature, cache=cache, spin=spin, slide=slide,
                              pocket_dof=pocket_dof)

    def reduced_or_none(parameter: str, values: list[float]) -> list[dict] | None:
        """Reduced-model sweep for the ``reduced_*`` report rows; None (rows left out, shown
        as "no value" by validate) when its quasi-static rib coupling does not converge
        (seen with slide="radial_plane" at large pocket clearance)."""
        try:
            return sweep(parameter, values, [m_hi])
        except ConvergenceError:
            return None

    from ..skidding.roller_dynamics_coupled import simulate_coupled

    orbits = float(inputs.get("coupled_orbits", 1.5))
    warm = float(inputs.get("coupled_warmup_orbits", orbits))
    # warm-up of the base points with unbalance (the gated unbalance rows): long enough to
    # leave the cage's start-up overshoot out of the window (SOURCE.md "Ensembles of the
    # chaotic points"); default the sweeps' warm-up
    base_warm = inputs.get("coupled_base_warmup_orbits", warm)
    if (isinstance(base_warm, bool) or not isinstance(base_warm, (int, float))
            or not 0.0 <= base_warm <= 50.0):
        raise InputError("inputs.coupled_base_warmup_orbits", base_warm,
                         "a number of cage orbits in [0, 50]")
    base_warm = float(base_warm)
    # warm-up settling of the points without unbalance (deterministic motion that settles to
    # a steady state; SOURCE.md "Cage settling"): None = the fixed warm-up
    settle = inputs.get("coupled_settle")
    if settle is not None and not (isinstance(settle, (int, float)) and 0.0 < settle < 1.0):
        raise InputError("inputs.coupled_settle", settle, "a relative tolerance in (0, 1)")

    from ..skidding.roller_dynamics_heat import DEFAULT_TABLE_RETRIES

    retries = inputs.get("coupled_table_retries", DEFAULT_TABLE_RETRIES)
    if (isinstance(retries, bool) or not isinstance(retries, int) or not 0 <= retries <= 10):
        raise InputError("inputs.coupled_table_retries", retries,
                         "a whole number of table-path retries in [0, 10]")

    def settle_for(mass: float) -> float | None:
        """The warm-up settling tolerance of a point: ``coupled_settle`` without unbalance;
        None (fixed warm-up) with one, whose chaotic motion has no steady cage speed to
        settle to (its window's offset is the trajectory scatter, SOURCE.md)."""
        return None if settle is None or mass > 0.0 else float(settle)
    base_key = (round(rd.PAPER003_BASE["speed"], 6), round(rd.PAPER003_BASE["radial_load"], 6))

    # the ensembles of the chaotic (unbalance) points: one trajectory per step count
    # (SOURCE.md "Ensembles of the chaotic points"); points without unbalance settle to a
    # steady state and run once, at the first step count of the base ensemble
    base_steps = trajectory_steps(inputs, "coupled_trajectories")
    sweep_steps = trajectory_steps(inputs, "coupled_sweep_trajectories")

    failures: list[str] = []
    failed_points: list[str] = []

    def failed(what: str, exc: ConvergenceError) -> None:
        """A trajectory whose coupled motion runs away on both traction paths (the model's
        runaway regime, roller_dynamics_coupled module notes): left out of its point's
        ensemble (the point's statistics are those of the trajectories that did not run
        away, as the table retries already condition them); a point without any finished
        trajectory has no value (the rows that need it show none and fail)."""
        failures.append(f"{what}: {exc}")
        warnings.warn(f"paper003: {what}: {exc}", ValidityWarning, stacklevel=3)

    def ensemble(what: str, mass: float, run: Any, steps: list[int]) -> PointEnsemble:
        """The point's ensemble: ``run(n)`` -> a row of :data:`_POINT_KEYS`, once per step
        count n of ``steps`` (mass > 0) or once at the base ensemble's first (no unbalance:
        deterministic)."""
        steps_list = base_steps[:1] if mass <= 0.0 else steps
        rows = []
        for steps in steps_list:
            try:
                rows.append(run(steps))
            except ConvergenceError as exc:
                failed(f"{what}, {steps} steps per spin period", exc)
        if not rows:
            failed_points.append(what)
        return point_of(rows, deterministic=mass <= 0.0 and bool(rows))

    def coupled(mass: float, steps: list[int], warmup: float, **rib: float) -> PointEnsemble:
        """All rollers + cage integrated (paper eqs. 18-19) at the base case, ``warmup``
        orbits discarded (the points without unbalance: the sweeps' warm-up and settling)."""
        m = rd.build_model(bearing, lub, rd.PAPER003_BASE["speed"],
                           rd.PAPER003_BASE["radial_load"], mass, temperature=temperature,
                           quasi_static=cache.get(base_key), rib={"slide": slide, **rib},
                           pocket_dof=pocket_dof, coupling="none")

        def run(steps: int) -> dict[str, float]:
            r = simulate_coupled(m, bearing, lub, n_orbits=orbits,
                                 warmup_orbits=warmup if mass > 0.0 else warm,
                                 steps_per_period=steps, settle=settle_for(mass),
                                 table_retries=retries)
            return {k: getattr(r, k) for k in _POINT_KEYS}

        return ensemble(f"coupled base point, unbalance {mass * 1e3:g} g, {rib}", mass, run,
                        steps)

    def coupled_sweep(parameter: str, values: list[float],
                      masses: list[float] | None = None) -> list[PointEnsemble]:
        points = []
        for value in values:  # one point at a time: a runaway point leaves the others
            for mass in ([m_hi] if masses is None else masses):
                def run(steps: int, value: float = value, mass: float = mass) -> dict:
                    return rd.pv_slip_map(
                        bearing, lub, parameter, [value], [mass], temperature=temperature,
                        cache=cache, slide=slide, pocket_dof=pocket_dof, model="coupled",
                        coupling="none",
                        coupled_options={"n_orbits": orbits, "warmup_orbits": warm,
                                         "steps_per_period": steps,
                                         "settle": settle_for(mass),
                                         "table_retries": retries})[0]

                points.append(ensemble(f"coupled {parameter} = {value:g} (SI), unbalance "
                                       f"{mass * 1e3:g} g", mass, run, sweep_steps))
        return points

    def det(rows: list[dict]) -> list[PointEnsemble]:
        """The reduced model's rows as one-run deterministic points."""
        return [point_of([r], deterministic=True) for r in rows]

    def put(name: str, f: Any, points: list[PointEnsemble], stderr: bool) -> None:
        """Row ``name`` = f(the points' ensemble means); with ``stderr`` also
        ``name + "_stderr"``, its first-order standard error (ensemble module)."""
        value, se = delta_method(f, points)
        out[name] = value
        if stderr:
            out[name + "_stderr"] = se

    def unbalance_rows(base: list[PointEnsemble], prefix: str) -> None:
        se = prefix == ""
        p0, p1, p2 = base
        put(prefix + "pv_ratio_unbalance_high_vs_low", lambda p: _pv(p[0]) / _pv(p[1]),
            [p2, p1], se)
        put(prefix + "slip_ratio_unbalance_high_vs_low",
            lambda p: p[0]["slip_speed"] / p[1]["slip_speed"], [p2, p1], se)
        put(prefix + "slip_ratio_unbalance_high_vs_none",
            lambda p: p[0]["slip_speed"] / p[1]["slip_speed"], [p2, p0], se)

        def right_left(p: list[dict[str, float]]) -> float:
            return p[0]["pv_right"] / p[0]["pv_left"]

        put(prefix + "pv_right_over_left_high_unbalance", right_left, [p2], se)
        put(prefix + "pv_right_over_left_low_unbalance", right_left, [p1], se)
        put(prefix + "pv_contact_ratio_unbalance_high_vs_low",
            lambda p: _pvc(p[0]) / _pvc(p[1]), [p2, p1], False)
        put(prefix + "pv_contact_right_over_left_high_unbalance",
            lambda p: p[0]["pv_contact_right"] / p[0]["pv_contact_left"], [p2], False)
        put(prefix + "base_pv_high_unbalance", lambda p: _pv(p[0]) / 2.0, [p2], se)
        put(prefix + "base_slip_speed_high_unbalance", lambda p: p[0]["slip_speed"], [p2],
            se)

    # unbalance at the base case (Fig. 7 at 3000 N): PV and slip grow, unbalance side larger;
    # gated rows from the coupled all-roller + cage integration, the reduced model's beside
    reduced_base = sweep("radial_load", [rd.PAPER003_BASE["radial_load"]], [0.0, m_lo, m_hi])
    unbalance_rows(det(reduced_base), "reduced_")
    coupled_base = [coupled(mass, base_steps, base_warm) for mass in (0.0, m_lo, m_hi)]
    unbalance_rows(coupled_base, "")

    # radial load (Fig. 7, no unbalance): slip falls and flattens above 5000 N; speed
    # (Fig. 8, 0.11 g): PV and slip rise (coupled gated, reduced beside)
    loads = _list(inputs, "radial_loads", "force")
    i5 = int(np.argmin(np.abs(np.asarray(loads) - 5000.0)))
    speeds = _list(inputs, "speeds", "angular_speed")
    rs = reduced_or_none("speed", speeds)
    for prefix, pts_l, pts_s in (
            ("reduced_", det(sweep("radial_load", loads, [0.0])),
             None if rs is None else det(rs)),
            ("", coupled_sweep("radial_load", loads, [0.0]), coupled_sweep("speed", speeds))):
        se = prefix == ""
        put(prefix + "slip_ratio_load_low_vs_5000N",
            lambda p: p[0]["slip_speed"] / p[i5]["slip_speed"], pts_l, False)
        put(prefix + "slip_flattening_above_5000N",
            lambda p: (abs(p[-1]["slip_speed"] - p[i5]["slip_speed"])
                       / max(abs(p[0]["slip_speed"] - p[i5]["slip_speed"]), 1e-12)),
            pts_l, False)
        if pts_s is not None:
            put(prefix + "pv_ratio_speed_high_vs_low",
                lambda p: _pv(p[-1]) / max(_pv(p[0]), 1e-30), pts_s, se)
            put(prefix + "slip_ratio_speed_high_vs_low",
                lambda p: p[-1]["slip_speed"] / p[0]["slip_speed"], pts_s, se)

    # axial clearance (Fig. 9): PV rises, slip falls, both flatten above 0.05 mm (gated rows
    # from the coupled integration, the reduced model's beside)
    ca = _list(inputs, "axial_clearances", "length")
    j5 = int(np.argmin(np.abs(np.asarray(ca) - 0.05e-3)))
    ra = reduced_or_none("axial_clearance", ca)
    for prefix, pts in (("reduced_", None if ra is None else det(ra)),
                        ("", [coupled(m_hi, sweep_steps, warm, axial_clearance=v) for v in ca])):
        if pts is None:
            continue
        se = prefix == ""
        for name, stat in (("pv", _pv), ("pv_contact", _pvc), ("pv_peak", _pvp)):
            put(f"{prefix}{name}_ratio_axial_clearance_0.05_vs_min",
                lambda p, stat=stat: stat(p[j5]) / stat(p[0]), pts, se and name == "pv")
            put(f"{prefix}{name}_flattening_above_0.05mm",
                lambda p, stat=stat: (abs(stat(p[-1]) - stat(p[j5]))
                                      / max(abs(stat(p[j5]) - stat(p[0])), 1e-12)),
                pts, se and name == "pv")
        put(prefix + "slip_ratio_axial_clearance_min_vs_0.05",
            lambda p: p[0]["slip_speed"] / p[j5]["slip_speed"], pts, se)

    # sensitivity (report): the inner ring free axially (paper 003 eq. 20 line 1) over the
    # first, 0.05 mm and last axial clearances
    ring_points = []
    for v in (ca[0], ca[j5], ca[-1]):
        mr = rd.build_model(bearing, lub, rd.PAPER003_BASE["speed"],
                            rd.PAPER003_BASE["radial_load"], m_hi, temperature=temperature,
                            quasi_static=cache.get(base_key),
                            rib={"slide": slide, "axial_clearance": v},
                            pocket_dof=pocket_dof, coupling="none")

        def run_ring(steps: int, mr: Any = mr) -> dict[str, float]:
            r = simulate_coupled(mr, bearing, lub, n_orbits=orbits, warmup_orbits=warm,
                                 steps_per_period=steps, ring_axial=True,
                                 table_retries=retries)
            return {k: getattr(r, k) for k in _POINT_KEYS}

        ring_points.append(ensemble(f"coupled, free inner ring, axial clearance {v:g} m",
                                    m_hi, run_ring, sweep_steps))
    put("ring_axial_pv_ratio_axial_clearance_0.05_vs_min", lambda p: _pv(p[1]) / _pv(p[0]),
        ring_points, False)
    put("ring_axial_slip_ratio_axial_clearance_min_vs_0.05",
        lambda p: p[0]["slip_speed"] / p[1]["slip_speed"], ring_points, False)

    # pocket clearance (Fig. 10): both rise, flatten above ~0.35 mm (coupled gated, reduced
    # beside)
    cp = _list(inputs, "pocket_clearances", "length")
    k35 = int(np.argmin(np.abs(np.asarray(cp) - 0.35e-3)))
    rp = reduced_or_none("pocket_clearance", cp)
    for prefix, pts in (("reduced_", None if rp is None else det(rp)),
                        ("", coupled_sweep("pocket_clearance", cp))):
        if pts is None:
            continue
        se = prefix == ""
        put(prefix + "pv_ratio_pocket_0.35_vs_min", lambda p: _pv(p[k35]) / _pv(p[0]), pts,
            se)
        put(prefix + "slip_ratio_pocket_0.35_vs_min",
            lambda p: p[k35]["slip_speed"] / p[0]["slip_speed"], pts, se)
        put(prefix + "pv_flattening_above_0.35mm",
            lambda p: (abs(_pv(p[-1]) - _pv(p[k35]))
                       / max(abs(_pv(p[k35]) - _pv(p[0])), 1e-12)), pts, se)

    # rib angle (Fig. 11) and crown radius (Fig. 12): PV minima, slip rising (coupled gated,
    # reduced beside)
    for key, par, kind in (("rib_angles", "rib_angle", "angle"),
                           ("crown_radii", "crown_radius", "length")):
        vals = _list(inputs, key, kind)
        rr = reduced_or_none(par, vals)
        for prefix, pts in (("reduced_", None if rr is None else det(rr)),
                            ("", coupled_sweep(par, vals))):
            if pts is None:
                continue
            for name, stat in (("pv", _pv), ("pv_contact", _pvc), ("pv_peak", _pvp)):
                row = f"{prefix}{name}_minimum_{par}"
                put(row, lambda p, stat=stat, x=vals: parabolic_minimum(
                    x, [stat(r) for r in p]),
                    pts, prefix == "" and name == "pv")
                if row + "_stderr" in out and out[row] in (vals[0], vals[-1]):
                    # the minimum at a sweep end is that sample (no vertex): no local
                    # sensitivity to propagate, its standard error is not defined
                    out[row + "_stderr"] = math.nan
            put(f"{prefix}slip_ratio_{par}_last_vs_first",
                lambda p: p[-1]["slip_speed"] / p[0]["slip_speed"], pts, False)
        # sensitivity: every roller at its pure-rolling spin (SOURCE.md, point 3)
        rows = sweep(par, vals, [m_hi], spin="rolling")
        out[f"pv_minimum_{par}_rolling_spin"] = parabolic_minimum(vals, [_pv(r) for r in rows])

    # cost of one base-case point: coupled (all rollers + cage, the "full" model of the
    # 10 % requirement; CPU per trajectory), one-roller full (prescribed spins) and reduced
    m = rd.build_model(bearing, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                       m_hi, temperature=temperature, quasi_static=cache.get(base_key),
                       rib={"slide": slide}, pocket_dof=pocket_dof)
    full = rd.simulate_full(m)
    red = rd.simulate_reduced(m)
    cpl = coupled_base[2].mean()
    out["coupled_points_failed"] = float(len(failed_points))
    out["coupled_trajectories_failed"] = float(len(failures))
    out["coupled_trajectories_per_point"] = float(len(base_steps))
    out["coupled_sweep_trajectories_per_point"] = float(len(sweep_steps))
    out["cost_coupled_s"] = cpl["cost_s"]
    out["cost_full_s"] = full.cost_s
    out["cost_reduced_s"] = red.cost_s
    out["reduced_vs_full_pv"] = (red.pv_left + red.pv_right) / _pv(cpl)
    out["reduced_vs_full_slip"] = red.slip_speed / cpl["slip_speed"]
    out["reduced_vs_one_roller_pv"] = ((red.pv_left + red.pv_right)
                                       / (full.pv_left + full.pv_right))
    out["reduced_vs_one_roller_slip"] = red.slip_speed / full.slip_speed
    # reduced model on lagged spins (spin inertia along the orbit, rd.lagged_spins) against
    # the coupled model
    lag = []
    for mass in (m_lo, m_hi):
        mm = rd.build_model(bearing, lub, rd.PAPER003_BASE["speed"],
                            rd.PAPER003_BASE["radial_load"], mass, temperature=temperature,
                            quasi_static=cache.get(base_key), rib={"slide": slide},
                            pocket_dof=pocket_dof, spin="lagged")
        lag.append(rd.simulate_reduced(mm))
    out["lagged_vs_full_pv"] = (lag[1].pv_left + lag[1].pv_right) / _pv(cpl)
    out["lagged_vs_full_slip"] = lag[1].slip_speed / cpl["slip_speed"]
    out["lagged_slip_ratio_unbalance_high_vs_low"] = lag[1].slip_speed / lag[0].slip_speed
    return out
