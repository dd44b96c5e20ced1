"""The sweep runner: run a scene given as TOML text and reduce it to a few named numbers
(:func:`summarize_scene`), and the reading of result names of earlier versions
(:func:`current_result_names`, for the stores of sweep folders written before a rename).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import numpy as np
import pandas as pd

from .operating_checks import CheckLog
from .scene import loads_scene
from .simulation_tables import over_skidding_range

#: the protocol mean of the scene's total loss (all bearings)
MEAN_TOTAL_LOSS = "mean total loss [W]"


def current_result_name(name: str, steady: bool = False) -> str:
    """A summary result name as this version writes it, from the name an earlier version
    wrote (unchanged when it is current). Earlier sweep folders (``cases.jsonl``,
    ``summary.csv``) hold ``total loss [W]`` and ``total loss <bearing> [W]`` (the
    protocol means, now ``mean total loss ...``) and ``rise <node> [K]``: final minus the
    initial temperature in a transient scene (now ``rise over initial <node> [K]``), the
    steady temperature minus the ambient in a steady scene (``steady``: now ``rise over
    ambient <node> [K]``)."""
    if name.startswith("total loss") and name.endswith("[W]"):
        return "mean " + name
    if name.startswith("rise ") and name.endswith(" [K]") and not name.startswith(
            ("rise over initial ", "rise over ambient ")):
        return ("rise over ambient " if steady else "rise over initial ") + name[5:]
    return name


def current_result_names(result: Mapping[str, Any], steady: bool = False
                         ) -> dict[str, Any]:
    """``result`` (one case's summary) with its names as this version writes them
    (:func:`current_result_name`); a current name wins over an old one for the same
    quantity."""
    out: dict[str, Any] = {}
    for key, value in result.items():
        new = current_result_name(key, steady)
        if new == key or new not in result:
            out[new] = value
    return out


def flagged_step_counts(logs: Iterable[CheckLog]) -> dict[str, int]:
    """How many schedule steps each operating check flags at any bearing: the union over
    the bearings' :meth:`.CheckLog.flagged_step_indices`, so that a step flagged at two
    bearings counts once (the per-bearing steps are the results metadata's
    ``flagged_steps``). Keys ``"skid"``, ``"stress"``, ``"film"`` [-]."""
    union: dict[str, set[int]] = {"skid": set(), "stress": set(), "film": set()}
    for log in logs:
        for key, steps in log.flagged_step_indices().items():
            union[key].update(steps)
    return {key: len(steps) for key, steps in union.items()}


def summarize_scene(scene_toml: str) -> dict[str, float]:
    """Sweep runner: run a scene and reduce it to a few numbers.

    Returns, with the unit in each name:

    * ``mean total loss [W]``: the scene's power loss (all bearings) averaged over the
      protocol, each step weighted by its duration; ``max total loss [W]`` the largest
      step; one ``<source> [W]`` per heat source (all bearings, the same average); with
      more than one bearing also ``mean total loss <bearing> [W]`` each. (Earlier versions
      named the mean ``total loss [W]``, and before that gave plain means over the steps
      of the first bearing only, which their names did not say.)
    * ``max / min over-skidding [%]`` (signed, 100 (CSR / CSR_th - 1) as in the kinematics
      table: negative where the cage lags, so a maximum below zero means every step
      skids; over every solved state, also those re-solved within a step, which the
      table's one row per step does not show:
      :func:`.simulation_tables.over_skidding_range`), ``max contact pressure [MPa]`` and ``min film
      parameter [-]`` of the solved states (:mod:`.operating_checks`; Lambda when the bearing
      gives its roughness; neither when the kinematics model computes no contacts), and
      ``steps over skid limit [-]``, ``steps over stress limit [-]``, ``steps under film
      limit [-]`` (the scene's ``[checks]`` thresholds: the schedule steps flagged at any
      bearing, each step once however many bearings it flags,
      :func:`flagged_step_counts`; earlier versions summed the counts over the bearings,
      so that a 3-step protocol on two bearings showed 6), so that a sweep of the
      thresholds shows what they flag;
    * with the ``rib_friction`` source (its ``rib`` table): ``max rib end-face PV [MPa m/s]``,
      ``max rib thrust PV [MPa m/s]``, ``max rib slip speed [m/s]``, ``max rib heat [W]``
      (:func:`rib_results`);
    * film-only scenes: ``min central film [um]``, ``min minimum film [um]`` and ``min film
      parameter [-]`` of the film table;
    * with a network: ``final <node> [degC]`` and ``rise over initial <node> [K]`` (final
      minus the node's temperature at the start, the scene's initial temperature, not the
      largest rise on the way; a scene whose inlet oil is warmer than that counts the
      difference in the rise too); a steady scene (``mode = "steady"``) gives its last
      operating point's steady temperatures and ``rise over ambient <node> [K]``, their
      rise above the ambient temperature (a steady state has no start).
    """
    from .simulation import Simulation

    scene = loads_scene(scene_toml)
    sim = Simulation(scene, progress=False)
    res = sim.run()
    out: dict[str, float] = {}
    durations = {i: float(st.duration) for i, st in enumerate(scene.schedule.steps)}
    losses = res.tables.get("losses")
    if losses is not None and not losses.empty:
        def averaged(frame: pd.DataFrame) -> tuple[pd.DataFrame, pd.Series]:
            per = frame.groupby(["step", "source"])["power [W]"].sum().unstack(fill_value=0.0)
            w = np.array([durations.get(int(i), 0.0) for i in per.index])
            w = w / w.sum() if w.sum() > 0 else np.full(len(per), 1.0 / len(per))
            return per, pd.Series(w, index=per.index)

        per, w = averaged(losses)
        total = per.sum(axis=1)
        out[MEAN_TOTAL_LOSS] = float((total * w).sum())
        out["max total loss [W]"] = float(total.max())
        for src in per.columns:
            out[f"{src} [W]"] = float((per[src] * w).sum())
        names = list(dict.fromkeys(losses["bearing"]))
        if len(names) > 1:
            for name in names:
                per_b, w_b = averaged(losses[losses["bearing"] == name])
                out[f"mean total loss {name} [W]"] = float((per_b.sum(axis=1) * w_b).sum())
    rib = res.tables.get("rib")
    if rib is not None and not rib.empty:
        out.update(rib_results(rib))
    kin = res.tables.get("kinematics")
    span = None if kin is None or kin.empty else over_skidding_range(kin, sim.checks)
    if span is not None:
        out["max over-skidding [%]"], out["min over-skidding [%]"] = span
    states = [c for log in sim.checks.values() for cs in log.steps.values() for c in cs]
    if states:
        # NaN: a state whose model computes no contacts (kinematics "none")
        pressures = [c.max_pressure for c in states if not np.isnan(c.max_pressure)]
        if pressures:
            out["max contact pressure [MPa]"] = max(pressures) / 1e6
        films = [c.film_parameter for c in states if c.film_parameter is not None]
        if films:
            out["min film parameter [-]"] = min(films)
        counts = flagged_step_counts(sim.checks.values())
        out["steps over skid limit [-]"] = float(counts["skid"])
        out["steps over stress limit [-]"] = float(counts["stress"])
        out["steps under film limit [-]"] = float(counts["film"])
    film = res.tables.get("film")
    if film is not None and not film.empty and kin is None:
        for col, key in (("central film [um]", "min central film [um]"),
                         ("minimum film [um]", "min minimum film [um]"),
                         ("film parameter [-]", "min film parameter [-]")):
            if col in film:
                out[key] = float(film[col].min())
    temps = res.tables.get("temperatures")
    if temps is not None and not temps.empty:
        for c in temps.columns:
            if c.endswith("[degC]"):
                out[f"final {c}"] = float(temps[c].iloc[-1])
                out[f"rise over initial {c.replace('[degC]', '[K]')}"] = float(
                    temps[c].iloc[-1] - temps[c].iloc[0])
    steady = res.tables.get("steady_temperatures")
    if (temps is None or temps.empty) and steady is not None and not steady.empty:
        # a steady scene: its last operating point's steady state, above the ambient
        ambient = scene.environment.ambient_temperature - 273.15
        for c in steady.columns:
            if c.endswith("[degC]"):
                out[f"final {c}"] = float(steady[c].iloc[-1])
                out[f"rise over ambient {c.replace('[degC]', '[K]')}"] = float(
                    steady[c].iloc[-1] - ambient)
    return out


def _span(values: pd.Series, fmt: str) -> str:
    """``lo-hi`` of the finite ``values`` in format ``fmt`` (one value when they agree;
    ``n/a`` when none is finite)."""
    v = values.to_numpy(dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return "n/a"
    lo, hi = format(float(v.min()), fmt), format(float(v.max()), fmt)
    return lo if lo == hi else f"{lo}-{hi}"


def rib_summary_lines(rib: pd.DataFrame) -> list[str]:
    """The terminal summary's lines of a run's ``rib`` table
    (:func:`.simulation_tables.rib_columns`), one per bearing: the model that booked the
    rib heat, mu, the thrust share per roller and its PV, the end faces' time-mean PV where
    roller dynamics ran, the slip speed (paper 003 eq. 25) and the rib heat, each as the
    range over the table's rows (steps)."""
    lines = []
    for name, rows in rib.groupby("bearing", sort=False):
        models = list(dict.fromkeys(f"{m} model" + ("" if d != "none" else
                                                    ", no roller dynamics")
                                    for m, d in zip(rows["rib model"], rows["roller dynamics"],
                                                    strict=True)))
        parts = [f"mu {_span(rows['friction coefficient [-]'], '.3g')}"]
        thrust = rows["thrust normal force [N]"].to_numpy(dtype=float)
        if np.any(thrust > 0):
            parts.append(f"thrust share {_span(rows['thrust normal force [N]'], '.3g')} N per "
                         f"roller at PV {_span(rows['thrust PV [MPa m/s]'], '.4g')} MPa m/s")
        faces = [rows[f"{side} face PV [MPa m/s]"] for side in ("left", "right")]
        if any(np.any(np.isfinite(f.to_numpy(dtype=float))) for f in faces):
            parts.append("end-face PV of the dynamics left / right "
                         + " / ".join(_span(f, ".4g") for f in faces) + " MPa m/s")
        parts.append(f"slip speed {_span(rows['slip speed [m/s]'], '.3g')} m/s")
        parts.append(f"rib heat {_span(rows['rib heat [W]'], '.3g')} W")
        lines.append(f"rib contact {name} ({'; '.join(models)}): " + ", ".join(parts)
                     + " (rib.csv)")
    return lines


def rib_results(rib: pd.DataFrame) -> dict[str, float]:
    """A sweep's numbers of a run's ``rib`` table (all bearings and steps): ``max rib face PV
    [MPa m/s]`` (the larger end face's time-mean PV of the roller dynamics; absent when none
    ran), ``max rib thrust PV [MPa m/s]``, ``max rib slip speed [m/s]`` (paper 003 eq. 25)
    and ``max rib heat [W]``."""
    out: dict[str, float] = {}
    faces = rib[["left face PV [MPa m/s]", "right face PV [MPa m/s]"]].to_numpy(dtype=float)
    if np.any(np.isfinite(faces)):
        out["max rib end-face PV [MPa m/s]"] = float(np.nanmax(faces))
    for col, key in (("thrust PV [MPa m/s]", "max rib thrust PV [MPa m/s]"),
                     ("slip speed [m/s]", "max rib slip speed [m/s]"),
                     ("rib heat [W]", "max rib heat [W]")):
        v = rib[col].to_numpy(dtype=float)
        if np.any(np.isfinite(v)):
            out[key] = float(np.nanmax(v))
    return out
