"""Which bearing, which operating points, at which temperatures: the report's context.

:func:`bearing_table` and :func:`operating_points` describe a scene for the reader of a
report (bearing designation, envelope and internal geometry, lubricant and oil supply, the
schedule); :func:`oil_temperatures` says at which oil temperature each row of the losses
table was evaluated, and :func:`catalogue_crosscheck` sets the run's total loss beside the
whole-bearing estimates of the SKF four-term and Palmgren models
(:mod:`thermobearing.global_friction`, catalogue-level cross-checks) at the same speed,
loads and oil temperature. No physics of its own: the estimates are the package's.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .errors import InputError
from .simulation_chain import crosscheck_options
from .units import from_si

#: the run's total as the frictional moment of the catalogues, M = P / omega [N mm]
TORQUE = "this run M = P / omega [N mm]"
#: the same of a sweep case: the sweep's cross-check names its columns "this case ..."
#: (a row is one case; "this run" in a sweep report read as the whole sweep)
CASE_TORQUE = "this case M = P / omega [N mm]"

#: the global models set beside the run's total (registered names of GLOBAL_FRICTION) and
#: their names in the report's columns
CATALOGUE_MODELS = {"skf_four_term": "SKF four-term", "palmgren": "Palmgren M0 + M1"}
_KELVIN = 273.15


def load_scene_bearings(scene: Any) -> tuple[dict[str, Any], list[str]]:
    """Bearing name -> bearing object (``geometry.load_bearing`` with the scene's
    overrides), and one note per bearing that could not be read (the error's text)."""
    from .geometry import load_bearing

    out: dict[str, Any] = {}
    notes: list[str] = []
    for spec in scene.bearings:
        src = spec.preset or str(scene.resolve_path(spec.path))
        try:
            out[spec.name] = load_bearing(src, overrides=dict(spec.overrides) or None)
        except InputError as exc:
            notes.append(f"bearing {spec.name}: not readable for the report ({exc})")
    return out, notes


def load_scene_lubricant(scene: Any) -> Any:
    """The scene's lubricant (preset or file) as the run loaded it."""
    from . import load_lubricant

    spec = scene.lubricant
    return load_lubricant(spec.get("preset") or str(scene.resolve_path(spec["path"])))


def bearing_table(scene: Any, bearings: dict[str, Any]) -> pd.DataFrame:
    """One row per bearing of the scene: designation, type, d x D x B [mm], pitch
    diameter [mm], rolling elements (number x diameter [mm], rollers also their length),
    nominal contact angle [deg]
    (ball bearings) and cage guidance."""
    rows = []
    for spec in scene.bearings:
        b = bearings.get(spec.name)
        row: dict[str, Any] = {"bearing": spec.name,
                               "designation": (getattr(b, "name", "") if b is not None
                                               else "") or spec.preset or str(spec.path)}
        if b is not None:
            row["type"] = str(getattr(b, "kind", type(b).__name__)).replace("_", " ")
            row["d x D x B [mm]"] = " x ".join(
                f"{1e3 * getattr(b, a):g}" for a in ("bore", "outer_diameter", "width"))
            row["pitch diameter [mm]"] = round(1e3 * b.pitch_diameter, 3)
            length = getattr(b, "roller_length", None)
            # a roller's length beside its diameter (a designer compares both; the NU 214
            # read "18 x 13 mm rollers")
            size = (f"{1e3 * b.element_diameter:.4g} mm" if length is None else
                    f"{1e3 * b.element_diameter:.4g} x {1e3 * length:.4g} mm")
            row["rolling elements"] = (f"{b.n_elements} x {size}"
                                       + (" balls" if hasattr(b, "ball_diameter")
                                          else " rollers (diameter x length)"))
            angle = getattr(b, "contact_angle", None)
            if angle is not None and hasattr(b, "ball_diameter"):
                row["nominal contact angle [deg]"] = round(math.degrees(angle), 2)
            cage = getattr(b, "cage", None)
            if cage is not None:
                row["cage guided on"] = str(getattr(cage, "guidance", "")).replace("_", " ")
        if spec.overrides:
            row["scene overrides"] = ", ".join(f"{k} = {v}" for k, v in spec.overrides.items())
        rows.append(row)
    return pd.DataFrame(rows)


def supply_text(scene: Any, lubricant: Any | None) -> str:
    """One sentence on the lubricant, the oil supply and the surroundings."""
    s = scene.supply
    lub = scene.lubricant.get("preset") or scene.lubricant.get("path")
    parts = [f"lubricant {lub}"]
    if lubricant is not None:
        nu40 = 1e6 * lubricant.kinematic_viscosity(40.0 + _KELVIN)
        nu_in = 1e6 * lubricant.kinematic_viscosity(s.inlet_temperature)
        parts[0] += (f" (kinematic viscosity {nu40:.3g} mm^2/s at 40 degC, {nu_in:.3g} "
                     f"mm^2/s at the inlet {s.inlet_temperature - _KELVIN:.4g} degC)")
    supply = f"supply {s.method.replace('_', ' ')}"
    if s.flow:
        unit = getattr(s, "flow_unit", "L/min")  # the scene's own unit (mm^3/h for oil-air)
        supply += (f", {from_si(s.flow, unit):.4g} {unit.replace('**', '^')} at "
                   f"{s.inlet_temperature - _KELVIN:.4g} degC")
    if s.level is not None:
        supply += f", oil level {1e3 * s.level:.4g} mm"
    parts.append(supply)
    env = scene.environment
    ambient = f"ambient {env.ambient_temperature - _KELVIN:.4g} degC"
    network = (bool(set(scene.outputs.want) & {"temperatures", "energy"})
               or scene.outputs.mode == "steady")
    if getattr(env, "initial_given", True):
        parts.append(f"{ambient}, initial temperature "
                     f"{env.initial_temperature - _KELVIN:.4g} degC")
    elif network:
        parts.append(f"{ambient}, initial temperature {env.initial_temperature - _KELVIN:.4g}"
                     " degC (the ambient: the scene sets none)")
    else:
        # a losses-only scene without an initial temperature runs at a fed supply's inlet
        # ('initial temperature 25 degC' stood beside losses evaluated at the 40 degC inlet)
        from .unheated import unheated_temperature

        t0, source = unheated_temperature(scene)
        where = ("the inlet temperature" if source == "supply.inlet_temperature"
                 else "the ambient")
        parts.append(f"{ambient}; no initial temperature set and no thermal network: parts "
                     f"and oil at {where}, {t0 - _KELVIN:.4g} degC")
    return "; ".join(parts)


def operating_points(scene: Any) -> pd.DataFrame:
    """The schedule: one row per step with its duration [min], speed [rpm] and radial and
    axial load [kN] (the speed rounded as in the result tables)."""
    from .simulation_tables import set_value

    return pd.DataFrame([{"step": i, "duration [min]": st.duration / 60.0,
                          "speed [rpm]": set_value(from_si(st.speed, "rpm")),
                          "radial load [kN]": st.radial_load / 1e3,
                          "axial load [kN]": st.axial_load / 1e3}
                         for i, st in enumerate(scene.schedule.steps)])


def loss_temperature_note(tables: dict[str, pd.DataFrame], scene: Any) -> str:
    """At which temperatures the losses of the run were evaluated, in words."""
    if "temperatures" in tables:
        return ("The losses of each step are evaluated at the node temperatures the "
                "thermal network reached at the end of that step (the time [s] column of "
                "losses.csv).")
    if "steady_temperatures" in tables:
        return ("The losses of each step are evaluated at that step's steady-state "
                "temperatures (table steady_temperatures).")
    from .unheated import unheated_temperature

    t0, source = unheated_temperature(scene)
    what = ("the oil supply's inlet temperature (the scene sets no initial temperature)"
            if source == "supply.inlet_temperature" else "the scene's initial temperature")
    return (f"No thermal network ran (the outputs ask for no temperatures): the losses "
            f"are evaluated with every component and the oil at {what}, "
            f"{t0 - _KELVIN:.4g} degC. Warmer oil has a lower viscosity and lower "
            f"viscous losses; add \"temperatures\" to [outputs] want for the losses at the "
            f"operating temperature.")


def oil_temperatures(losses: pd.DataFrame, tables: dict[str, pd.DataFrame],
                     scene: Any) -> pd.Series:
    """The oil temperature [K] each row of ``losses`` was evaluated at: the bearing's oil
    node (``<bearing>.oil``) at the row's time (transient) or of the row's step (steady),
    else the temperature of a run without a network (no network ran:
    :func:`thermobearing.unheated.unheated_temperature`)."""
    from .unheated import unheated_temperature

    t0, _ = unheated_temperature(scene)
    out = pd.Series(t0, index=losses.index, dtype=float)
    temps, steady = tables.get("temperatures"), tables.get("steady_temperatures")
    for name, g in losses.groupby("bearing") if "bearing" in losses else [(None, losses)]:
        cols = ([f"{name}.oil [degC]"] if name is not None else []) + ["oil [degC]"]
        if temps is not None and "time [s]" in g:
            col = next((c for c in cols if c in temps), None)
            if col is not None:
                out[g.index] = _KELVIN + np.interp(g["time [s]"].to_numpy(float),
                                                   temps["time [s]"].to_numpy(float),
                                                   temps[col].to_numpy(float))
        elif steady is not None and "step" in steady and "step" in g:
            col = next((c for c in cols if c in steady), None)
            if col is not None:
                by_step = steady.set_index("step")[col]
                out[g.index] = _KELVIN + g["step"].map(by_step).to_numpy(float)
    return out


def catalogue_crosscheck(losses: pd.DataFrame, tables: dict[str, pd.DataFrame], scene: Any,
                         bearings: dict[str, Any], lubricant: Any
                         ) -> tuple[pd.DataFrame, list[str]]:
    """The run's total loss per operating point and bearing beside the SKF four-term and
    Palmgren estimates (:func:`thermobearing.global_friction.global_friction`) at the same
    speed, loads, lubrication method and oil temperature (:func:`oil_temperatures`), with
    the difference of the run's total from each [%].

    Returns the table (columns ``step``, ``bearing``, ``speed [rpm]``, ``radial load
    [kN]``, ``axial load [kN]``, ``oil [degC]``, ``this run [W]``, ``this run M = P / omega
    [N mm]`` (the moment a catalogue's friction calculator gives), ``<model> [W]``,
    ``this run vs <model> [%]``, the models named as in :data:`CATALOGUE_MODELS`) and one
    note per model a bearing cannot be estimated with (the model's error, e.g. a
    designation without a series). Steps at rest (0 r/min) are left out, with a note."""
    from .global_friction import global_friction

    needed = ("step", "bearing", "speed [rpm]", "radial load [kN]", "axial load [kN]",
              "power [W]")
    missing = [c for c in needed if c not in losses]
    if missing:
        raise InputError("losses table columns", list(losses.columns),
                         "the columns " + ", ".join(repr(c) for c in missing))
    frame = losses.assign(_T=oil_temperatures(losses, tables, scene))
    points = frame.groupby(["step", "bearing"], sort=False).agg(
        speed=("speed [rpm]", "first"), radial=("radial load [kN]", "first"),
        axial=("axial load [kN]", "first"), T=("_T", "first"), total=("power [W]", "sum"))
    level = scene.supply.level
    cross = crosscheck_options(scene)  # SKF series / C0 named by the scene
    rows, notes = [], []
    refused: set[tuple[str, str]] = set()
    at_rest: list[Any] = []
    for (step, name), p in points.iterrows():
        if float(p["speed"]) == 0.0:
            # a stop of the protocol: no loss in the run nor in either model, no ratio
            if step not in at_rest:
                at_rest.append(step)
            continue
        row: dict[str, Any] = {"step": step, "bearing": name, "speed [rpm]": p["speed"],
                               "radial load [kN]": p["radial"], "axial load [kN]": p["axial"],
                               "oil [degC]": p["T"] - _KELVIN, "this run [W]": p["total"],
                               # the frictional moment a catalogue quotes, M = P / omega
                               TORQUE: 1e3 * p["total"] / (float(p["speed"]) * math.pi / 30.0)}
        b = bearings.get(name)
        for model in CATALOGUE_MODELS:
            if b is None or (name, model) in refused:
                continue
            opts = ({**cross, **({"oil_level": level} if level else {})}
                    if model == "skf_four_term" else {})
            try:
                res = global_friction(model, b, lubricant, float(p["T"]),
                                      float(p["speed"]) * 2.0 * math.pi / 60.0,
                                      1e3 * float(p["radial"]), 1e3 * float(p["axial"]),
                                      lubrication=scene.supply.method, **opts)
            except InputError as exc:
                refused.add((name, model))
                notes.append(f"{model} for bearing {name}: not applicable ({exc})")
                continue
            label = CATALOGUE_MODELS[model]
            row[f"{label} [W]"] = float(res.power)
            row[f"this run vs {label} [%]"] = (_percent(p["total"], res.power)
                                               if res.power > 0 else math.nan)
        rows.append(row)
    notes += _self_comparison_notes(losses)
    notes += cylindrical_thrust_notes(
        bearings, {str(name) for (_, name), p in points.iterrows()
                   if float(p["axial"]) != 0.0 and float(p["speed"]) != 0.0})
    if at_rest:
        notes.append("steps at rest (0 r/min) left out: no loss in the run nor in the "
                     "models (steps " + ", ".join(str(s) for s in at_rest) + ")")
    return pd.DataFrame(rows), notes


def _percent(value: float, reference: float) -> float:
    """100 (value / reference - 1) [%], with the round-off of an identical pair
    (|difference| below 1e-9 %) written as 0 rather than 2.2e-14."""
    pct = 100.0 * (float(value) / float(reference) - 1.0)
    return 0.0 if abs(pct) < 1e-9 else pct


def cylindrical_thrust_notes(bearings: Mapping[str, Any], thrust: set[str]) -> list[str]:
    """A note per cylindrical roller bearing of ``bearings`` whose name is in ``thrust``
    (bearings that carry an axial load at a turning point): Palmgren's M1 of a cylindrical
    roller bearing takes P1 = F_r (:func:`thermobearing.global_friction.
    palmgren_equivalent_load`), so its estimate does not move with the thrust the ribs
    carry, while the SKF four-term sliding term has S1 d_m^0.9 F_a (an NUP 214 at 1500
    r/min: Palmgren 133 W at 0.5, 1 and 2 kN axial beside the run's 135-281 W, read as
    the run being 1-110 % high without a word)."""
    names = [n for n, b in bearings.items()
             if n in thrust and getattr(b, "kind", None) == "cylindrical"]
    if not names:
        return []
    return [f"Palmgren M0 + M1 of the cylindrical roller bearing {', '.join(names)} takes "
            "the radial load only (P1 = F_r): the friction of the ribs that carry its axial "
            "load is not in it, so it does not change with the axial load; the SKF "
            "four-term sliding term has the axial load (S1 d_m^0.9 F_a)"]


def _self_comparison_notes(losses: pd.DataFrame) -> list[str]:
    """A note when the run's loss is itself a catalogue model (the ``global_friction``
    source, the fidelity ladder's L0 rung): the cross-check then compares that model with
    itself and with the other one, not a physics chain with the catalogue."""
    if "source" not in losses or set(losses["source"]) != {"global_friction"}:
        return []
    models = sorted({str(c).split()[0] for c in losses.get("component", [])
                     if str(c).split() and str(c).split()[0] in CATALOGUE_MODELS})
    named = " and ".join(CATALOGUE_MODELS[m] for m in models) or "a catalogue model"
    return [f"this run's loss is the global_friction source ({named}, kinematics "
            f"\"none\", the L0 rung): its row beside {named} compares the model with "
            f"itself (0 %); run the skidding or race-control chain for a comparison with "
            f"the physics"]


def _wants_network(scene: Any) -> bool:
    """True when the scene's losses are evaluated at temperatures a thermal network
    computes (``temperatures`` or ``energy`` asked: the chain's ``network`` link,
    :func:`thermobearing.simulation_chain._needs`; a steady mode without them runs no
    network either), not at the temperature of a run without one."""
    return bool(set(scene.outputs.want) & {"temperatures", "energy"})


def sweep_catalogue_crosscheck(base: Any, records: list[dict[str, Any]],
                               total: str = "mean total loss [W]"
                               ) -> tuple[pd.DataFrame, list[str]]:
    """Each sweep case's total loss beside the SKF four-term and Palmgren estimates of its
    bearings (:func:`thermobearing.global_friction.global_friction`) at its speeds, loads,
    lubrication method and oil temperature, averaged over its protocol as the sweep's
    ``total`` is (steps weighted by their duration, every bearing with its load share),
    with the difference of the case's total from each [%].

    ``base``: the sweep's base scene; ``records``: the case records of ``cases.jsonl``
    (``case``, ``params`` as set, ``result``). The oil temperature is known for a case
    whose losses were evaluated at the scene's initial temperature (no thermal network:
    ``temperatures`` not in its outputs and not steady) and for a steady case with one
    operating point (each bearing's steady oil node, :func:`_case_oil_temperatures`); for
    the others the table is empty and a note says why. Returns the table (``case``, the swept
    values as set, ``oil [degC]``, ``this case [W]``, :data:`CASE_TORQUE` of a case whose
    every step turns at one speed, ``<model> [W]``, ``this case vs <model> [%]``)
    and the notes (a model a bearing cannot be estimated with, once each)."""
    from .global_friction import global_friction
    from .scene import Scene
    from .sweep_params import assign_path

    rows: list[dict[str, Any]] = []
    notes: list[str] = []
    resting: list[str] = []
    refused: set[tuple[str, str]] = set()
    cache: dict[str, tuple[dict[str, Any], Any]] = {}
    base_dict = base.to_dict()
    for rec in records:
        d = _deep_copy(base_dict)
        for path, value in rec.get("params", {}).items():
            assign_path(d, path, value)
        base_dir = getattr(base, "base_dir", None)
        scene = Scene.from_dict(d, base_dir=Path(base_dir) if base_dir else None)
        result = rec.get("result", {})
        oil = _case_oil_temperatures(scene, result)
        if oil is None:
            return pd.DataFrame(), [
                "no catalogue cross-check: the cases' losses are evaluated at the "
                "temperatures of their thermal network, which the sweep summary does not "
                "keep per step; a losses-only base scene (outputs without "
                "\"temperatures\") is compared at its initial temperature, a steady one "
                "with one operating point at its steady oil temperature"]
        key = repr((d.get("bearings"), d.get("lubricant")))
        if key not in cache:
            bearings, bnotes = load_scene_bearings(scene)
            notes += [n for n in bnotes if n not in notes]
            cache[key] = (bearings, load_scene_lubricant(scene))
        bearings, lubricant = cache[key]
        thrust = {spec.name for spec in scene.bearings for step in scene.schedule.steps
                  if step.axial_load * spec.axial_share != 0.0 and step.speed != 0.0}
        notes += [n for n in cylindrical_thrust_notes(bearings, thrust) if n not in notes]
        level = scene.supply.level
        cross = crosscheck_options(scene)
        sums = {m: 0.0 for m in CATALOGUE_MODELS}
        ok = {m: True for m in CATALOGUE_MODELS}
        duration = 0.0
        turning = any(step.speed != 0.0 for step in scene.schedule.steps)
        if not turning:
            resting.append(str(rec.get("case")))
        for step in scene.schedule.steps:
            duration += step.duration
            if step.speed == 0.0:
                continue  # at rest: no loss in the case nor in the models
            for spec in scene.bearings:
                b = bearings.get(spec.name)
                for model in CATALOGUE_MODELS:
                    if b is None or (spec.name, model) in refused:
                        ok[model] = False
                        continue
                    opts = ({**cross, **({"oil_level": level} if level else {})}
                            if model == "skf_four_term" else {})
                    try:
                        res = global_friction(model, b, lubricant, oil[spec.name],
                                              step.speed,
                                              step.radial_load * spec.radial_share,
                                              abs(step.axial_load * spec.axial_share),
                                              lubrication=scene.supply.method, **opts)
                    except InputError as exc:
                        refused.add((spec.name, model))
                        ok[model] = False
                        notes.append(f"{model} for bearing {spec.name}: not applicable "
                                     f"({exc})")
                        continue
                    sums[model] += float(res.power) * step.duration
        this = result.get(total)
        temps = sorted({round(t - _KELVIN, 6) for t in oil.values()})
        row: dict[str, Any] = {"case": rec.get("case"), **rec.get("params", {}),
                               "oil [degC]": (temps[0] if len(temps) == 1 else
                                              " / ".join(f"{t:.4g}" for t in temps)),
                               "this run [W]": this}
        # the frictional moment a catalogue quotes, M = P / omega, of a case that turns at
        # one speed (with a stop or several speeds the protocol mean has no one omega)
        speeds = {s.speed for s in scene.schedule.steps}
        if (len(speeds) == 1 and next(iter(speeds)) > 0.0
                and isinstance(this, (int, float)) and math.isfinite(this)):
            row[TORQUE] = 1e3 * float(this) / next(iter(speeds))
        for model, label in CATALOGUE_MODELS.items():
            if not ok[model] or duration <= 0.0 or not turning:
                # a case at rest throughout has no estimate to set beside its 0 W (it read
                # "SKF four-term 0 W" for a bearing the model refuses at every speed)
                continue
            est = sums[model] / duration
            row[f"{label} [W]"] = est
            row[f"this run vs {label} [%]"] = (
                _percent(this, est)
                if isinstance(this, (int, float)) and est > 0 else math.nan)
        rows.append(row)
    if resting:
        notes.append("cases at rest throughout (0 r/min) have no catalogue estimate: no loss "
                     "in the run nor in the models (" + ", ".join(resting) + ")")
    table = pd.DataFrame(rows)
    if TORQUE in table:
        # beside the run's total (a first case at rest, without a moment, put the column
        # after the models')
        cols = [c for c in table.columns if c != TORQUE]
        at = cols.index("this run [W]") + 1
        table = table[[*cols[:at], TORQUE, *cols[at:]]]
    return table.rename(columns=lambda c: "this case" + c[len("this run"):]
                        if str(c).startswith("this run") else c), notes


def _case_oil_temperatures(scene: Any, result: Mapping[str, Any]) -> dict[str, float] | None:
    """Bearing name -> the oil temperature [K] a sweep case's losses were evaluated at: the
    initial temperature when no network ran; in a steady case with one operating point its
    steady oil node (the summary's ``final <bearing>.oil [degC]``); None otherwise (a
    transient, or several steady points: the summary keeps only the last)."""
    names = [b.name for b in scene.bearings]
    if not _wants_network(scene):
        from .unheated import unheated_temperature

        return dict.fromkeys(names, unheated_temperature(scene)[0])
    if scene.outputs.mode != "steady" or len(scene.schedule.steps) != 1:
        return None
    out = {}
    for n in names:
        value = result.get(f"final {n}.oil [degC]")
        if not isinstance(value, (int, float)) or not math.isfinite(value):
            return None
        out[n] = float(value) + _KELVIN
    return out


def _deep_copy(d: Any) -> Any:
    import copy

    return copy.deepcopy(d)
