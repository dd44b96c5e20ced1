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
from typing import Any

import numpy as np
import pandas as pd

from .errors import InputError
from .units import from_si

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
    diameter [mm], rolling elements (number x diameter [mm]), nominal contact angle [deg]
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
            row["rolling elements"] = (f"{b.n_elements} x {1e3 * b.element_diameter:.4g} mm"
                                       + (" balls" if hasattr(b, "ball_diameter")
                                          else " rollers"))
            angle = getattr(b, "contact_angle", None)
            if angle is not None and hasattr(b, "ball_diameter"):
                row["contact angle [deg]"] = round(math.degrees(angle), 2)
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
    parts.append(f"ambient {env.ambient_temperature - _KELVIN:.4g} degC, initial "
                 f"temperature {env.initial_temperature - _KELVIN:.4g} degC")
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
                "thermal network reached at the end of that step (the time column).")
    if "steady_temperatures" in tables:
        return ("The losses of each step are evaluated at that step's steady-state "
                "temperatures (table steady_temperatures).")
    t0 = scene.environment.initial_temperature - _KELVIN
    return (f"No thermal network ran (the outputs ask for no temperatures): the losses "
            f"are evaluated with every component and the oil at the scene's initial "
            f"temperature, {t0:.4g} degC. Warmer oil has a lower viscosity and lower "
            f"viscous losses; add \"temperatures\" to [outputs] want for the losses at the "
            f"operating temperature.")


def oil_temperatures(losses: pd.DataFrame, tables: dict[str, pd.DataFrame],
                     scene: Any) -> pd.Series:
    """The oil temperature [K] each row of ``losses`` was evaluated at: the bearing's oil
    node (``<bearing>.oil``) at the row's time (transient) or of the row's step (steady),
    else the scene's initial temperature (no network ran)."""
    t0 = scene.environment.initial_temperature
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
    [kN]``, ``axial load [kN]``, ``oil [degC]``, ``this run [W]``, ``<model> [W]``,
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
                               "oil [degC]": p["T"] - _KELVIN, "this run [W]": p["total"]}
        b = bearings.get(name)
        for model in CATALOGUE_MODELS:
            if b is None or (name, model) in refused:
                continue
            opts = {"oil_level": level} if (model == "skf_four_term" and level) else {}
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
            row[f"this run vs {label} [%]"] = (100.0 * (p["total"] / res.power - 1.0)
                                               if res.power > 0 else math.nan)
        rows.append(row)
    if at_rest:
        notes.append("steps at rest (0 r/min) left out: no loss in the run nor in the "
                     "models (steps " + ", ".join(str(s) for s in at_rest) + ")")
    return pd.DataFrame(rows), notes
