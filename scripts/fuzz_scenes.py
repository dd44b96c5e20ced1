"""Fuzz whole scenes: seeded random but physically sensible scenes through the whole chain.

Each case is a scene built from the shipped presets (``configs/bearings/*.toml``,
``configs/lubricants/*.toml``) and the catalogue / spindle bearings under ``examples/``,
with random speeds (0, creeping, very low, up to a plausible n d_m for the oil supply and a
few above it), radial and axial loads (0, tiny, typical, up to about the static rating C0;
axial loads only where the bearing kind carries them), oil supplies (jet, circulation, oil
bath with a level, oil-air; flows from tiny to large), inlet / ambient / initial
temperatures in -20..120 degC (cold starts from -40 degC), kinematics models (skidding,
race control, none with the global_friction source), outputs (film only, kinematics,
losses, short transients and steady temperatures) and network
templates with their required parameters. Each runs as ``Simulation(scene).run()`` under a
per-case time limit (and every ``--cli-every``-th case also as ``thermobearing run SCENE
--out DIR``, which exercises the writers and the report), and is classified:

``OK``
    finished; every table holds finite numbers where numbers are expected, no negative
    power, no temperature at or below 0 K, warnings readable.
``REFUSED``
    a clean refusal: ``InputError`` / ``UnknownNameError`` whose message names its field,
    or ``ConvergenceError`` with a finite residual. A refusal whose field is no key of a
    scene (``eta0``, ``dt``: the user cannot tell what to change) is marked ``(not a scene
    field)`` in its message and worth a look.
``TIMEOUT``
    not finished within ``--time-limit`` seconds (not counted as a defect; listed).
``DEFECT``
    any other exception, a NaN / inf where a number is expected, a negative power, a
    temperature at or below absolute zero, a garbled warning, a refusal that does not name
    its field or a convergence error without a finite residual.

The summary table lists every case; each defect's reproducer TOML is printed and written
(with those of the refusals and timeouts) to ``DIR/case_<n>.toml`` (``--out DIR``, else a temporary
folder). ``--only 3,17`` reruns cases of the same seed and count. Each case runs in a
worker process (one at a time), killed at the time limit and replaced.

Widenings of the generator (a seed's cases change with each; the runs quoted in README
are of the generator of their date):

- 2026-11-23, later: up to three bearings, with per-bearing ``load_share`` tables
  (locating / floating, lever-arm radial splits, reversed thrust); the rib_friction source
  on cylindrical roller bearings with ribs on both rings (``ribbed_ring = "both"``
  override, race control, an axial load up to 20 % of the radial, reduced or coupled model,
  default or listed sources); creeping speeds (1e-3 to 0.05 r/min) and steps above the
  supply's plausible n d_m (up to ``HIGH_SPEED_FACTOR``); cold starts (machine, air and oil
  at -40 to -10 degC); ``[schedule] file`` CSV protocols (random column order and units, a
  column left to the defaults, BOM, CRLF) and ``[measured]`` rig CSV files (comma or
  semicolon with decimal commas, minutes or hh:mm:ss, empty / OVL / -999 dropouts), both
  written beside the reproducers (``DIR/case_<n>_protocol.csv``, ``_measured.csv``);
  diametral clearance overrides (0 to 4x the preset's), the race-control option
  ``control``, ``churning_heat_to = "paper002"``, the network steppers tr_bdf2 /
  backward_euler / crank_nicolson, ``[outputs] interval`` and ``[checks]`` thresholds.
  The summary line of a case lists those drawn (``share``, ``rib``, ``cold``, ``file``,
  ``meas``, ``clear``, ``ctrl``, ``p002``, ``stepper``, ``interval``, ``checks``).
  Rib scenes put the both-rib override and a listed rib_friction mostly on bearings with
  rib geometry (the CRB preset); an NU-type bearing beside it mostly floats (axial share 0).

Usage::

    python scripts/fuzz_scenes.py --seed 1 --n 150 --time-limit 60 --out fuzz_out
"""

from __future__ import annotations

import argparse
import math
import multiprocessing
import re
import subprocess
import sys
import tempfile
import time
import traceback
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pandas.api.types import is_bool_dtype, is_numeric_dtype

ROOT = Path(__file__).resolve().parents[1]

#: n d_m [mm r/min] up to which each supply is drawn: typical catalogue reference speeds of
#: oil-bath, circulating-oil and jet / oil-air lubricated bearings (the spindle example runs
#: 1.44e6, the paper 001 and 003 rollers 2.0e6 and 1.9e6)
NDM_LIMIT = {"oil_bath": 0.5e6, "circulation": 0.8e6, "jet": 2.1e6, "oil_air": 2.1e6}
#: ISO 76 static-rating factor f0 of radial ball bearings lies between about 12 and 17
#: (ISO 76 Table 1, by D cos(alpha) / d_m); the lower end sets the fuzz range of loads
F0_BALL = 12.3
#: ISO 76 radial roller bearings: C0 = 44 (1 - D cos(alpha) / d_m) i Z L_we D [N, mm]
K_ROLLER = 44.0
#: h of the templates' oil and air convection drawn from these ranges [W/(m^2 K)]
#: (paper 002 gives 50-1500 for the oil; free to forced air 5-50)
H_OIL_RANGE = (50.0, 1500.0)
H_AIR_RANGE = (5.0, 50.0)

SUPPLIES = ("jet", "circulation", "oil_bath", "oil_air")
#: first words of the fields a refusal may name: the scene's tables, the bearing and
#: lubricant files' keys, and the checks' own wording ("schedule step 0 ...", "SKF ...")
SCENE_FIELD_HEADS = {"title", "source", "bearings", "lubricant", "supply", "environment",
                     "schedule", "models", "network", "solver", "outputs", "checks",
                     "measured", "bearing", "SKF", "scene"}
#: a few steps run above the supply's plausible n d_m, up to this factor of it
HIGH_SPEED_FACTOR = 1.6
#: cold starts: ambient, initial and inlet temperatures drawn in this range [degC]
COLD_RANGE = (-40.0, -10.0)
TEMPLATES = ("four_node_paper002", "seven_node")
GARBLED = (re.compile(r"\bnan\b", re.I), re.compile(r"\binf\b"), re.compile(r"np\.float"),
           re.compile(r"\{[a-z_]*\}"), re.compile(r"\bNone\b"), re.compile(r"[\x00-\x08]"),
           re.compile(r"<[a-zA-Z_.]+ object at"), re.compile(r"\.\.\s*$"))


@dataclass(frozen=True)
class BearingEntry:
    """A bearing the generator draws: how a scene names it and the data the ranges need."""

    spec: dict[str, Any]
    label: str
    kind: str
    bore: float  # [m]
    outer: float  # [m]
    width: float  # [m]
    pitch: float  # [m]
    c0: float  # [N], ISO 76 estimate (fuzz range only)
    ribbed_ring: str | None
    clearance: float  # [m], the preset's diametral clearance
    rib_geometry: bool  # end-face crown radius and rib height given (rib_friction runs)


def bearing_catalogue() -> list[BearingEntry]:
    """The shipped bearing presets and the example catalogue bearings."""
    from thermobearing.geometry import load_bearing, preset_names

    sources: list[tuple[dict[str, Any], str]] = [({"preset": n}, n) for n in preset_names()]
    for path in sorted((ROOT / "examples").glob("*.toml")):
        text = path.read_text(encoding="utf-8")
        if re.search(r"^kind\s*=", text, re.M):  # a bearing file, not a scene
            sources.append(({"path": str(path)}, path.stem))
    out = []
    for spec, label in sources:
        b = load_bearing(spec.get("preset") or spec["path"])
        cos_a = math.cos(float(getattr(b, "contact_angle", 0.0)))
        if hasattr(b, "ball_diameter"):
            d, z = b.ball_diameter * 1e3, b.n_balls
            c0 = F0_BALL * z * d**2 * cos_a
        else:
            d, z = b.roller_diameter * 1e3, b.n_rollers
            c0 = (K_ROLLER * (1 - d * cos_a / (b.pitch_diameter * 1e3)) * z
                  * b.roller_effective_length * 1e3 * d * cos_a)
        out.append(BearingEntry(spec, label, b.kind, b.bore, b.outer_diameter, b.width,
                                b.pitch_diameter, c0, getattr(b, "ribbed_ring", None),
                                float(b.diametral_clearance),
                                getattr(b, "end_face_crown_radius", None) is not None
                                and getattr(b, "rib_height", None) is not None))
    return out


def lubricant_names() -> list[str]:
    return sorted(p.stem for p in (ROOT / "configs" / "lubricants").glob("*.toml"))


# ----------------------------------------------------------------------------- generator
def _log_uniform(rng: np.random.Generator, lo: float, hi: float) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def _speed(rng: np.random.Generator, limit_rpm: float) -> float:
    r = rng.random()
    if r < 0.1:
        return 0.0
    if r < 0.15:
        return _log_uniform(rng, 1e-3, 0.05)  # creeping: a turning gear, a hand turn
    if r < 0.25:
        return _log_uniform(rng, 0.05, 20.0)
    if r < 0.3:
        return _log_uniform(rng, limit_rpm, HIGH_SPEED_FACTOR * limit_rpm)
    return _log_uniform(rng, 20.0, limit_rpm)


def _load(rng: np.random.Generator, c0: float, zero_ok: bool = True) -> float:
    r = rng.random()
    if r < 0.15 and zero_ok:
        return 0.0
    if r < 0.3:
        return _log_uniform(rng, 1e-3, 10.0)
    if r < 0.85:
        return _log_uniform(rng, 0.005 * c0, 0.15 * c0)
    return _log_uniform(rng, 0.15 * c0, 1.0 * c0)


def _q(value: float, unit: str, digits: int = 6) -> str:
    return f"{value:.{digits}g} {unit}"


def _supply(rng: np.random.Generator, b: BearingEntry) -> dict[str, Any]:
    method = str(rng.choice(SUPPLIES))
    out: dict[str, Any] = {"method": method}
    if method == "oil_air":
        out["flow"] = _q(_log_uniform(rng, 1.0, 3000.0), "mm**3/h")
    elif method == "oil_bath":
        # from dry (0) to above the bore: the level from the lowest point of the outer race
        level = 0.0 if rng.random() < 0.15 else float(rng.uniform(0.0, 0.6 * b.outer)) * 1e3
        out["level"] = _q(level, "mm")
        if rng.random() < 0.3:
            out["flow"] = _q(_log_uniform(rng, 0.001, 2.0), "L/min")
    else:
        out["flow"] = _q(_log_uniform(rng, 0.002, 60.0), "L/min")
    if rng.random() < 0.8:
        out["inlet_temperature"] = _q(rng.uniform(-20.0, 120.0), "degC", 4)
    return out


def _models(rng: np.random.Generator, entries: list[BearingEntry], kind: str
            ) -> dict[str, Any]:
    if kind == "none":
        model = str(rng.choice(["skf_four_term", "palmgren"]))
        return {"kinematics": "none", "heat_sources": ["global_friction"],
                "heat_source_options": {"global_friction": {"model": model}}}
    models: dict[str, Any] = {"kinematics": kind}
    if any(e.label == "CRB_50x75x16" for e in entries) and rng.random() < 0.7:
        # the coupled rib dynamics cost ~2 s CPU per state: mostly the reduced model
        models["heat_source_options"] = {"rib_friction": {"model": "reduced"}}
    return models


def _outputs(rng: np.random.Generator, kin: str) -> tuple[dict[str, Any], str]:
    kinds = ["film", "kinematics", "losses", "transient", "steady_temperatures"]
    weights = [0.12, 0.18, 0.25, 0.3, 0.15]
    if kin == "none":
        kinds, weights = ["losses", "transient", "steady_temperatures"], [0.3, 0.45, 0.25]
    pick = str(rng.choice(kinds, p=np.array(weights) / sum(weights)))
    want = {"film": ["film"], "kinematics": ["kinematics"],
            "losses": ["kinematics", "losses"] if kin != "none" else ["losses"],
            "transient": ["temperatures", "losses", "energy"],
            "steady_temperatures": ["temperatures", "losses"]}[pick]
    mode = "transient" if pick == "transient" else "steady"
    return {"mode": mode, "want": want}, pick


def _network(rng: np.random.Generator, entries: list[BearingEntry]) -> dict[str, Any]:
    big = max(entries, key=lambda e: e.outer)
    params: dict[str, Any] = {
        "housing_outer_diameter": _q(big.outer * rng.uniform(1.2, 3.0) * 1e3, "mm"),
        "housing_length": _q(big.width * rng.uniform(1.0, 3.0) * 1e3, "mm"),
    }
    if rng.random() < 0.5:
        params["shaft_diameter"] = _q(min(e.bore for e in entries) * 1e3, "mm")
        params["shaft_length"] = _q(rng.uniform(0.05, 1.0) * 1e3, "mm")
    if rng.random() < 0.4:
        params["h_oil"] = _q(_log_uniform(rng, *H_OIL_RANGE), "W/(m**2*K)")
    if rng.random() < 0.4:
        params["h_air"] = _q(_log_uniform(rng, *H_AIR_RANGE), "W/(m**2*K)")
    net: dict[str, Any] = {"template": str(rng.choice(TEMPLATES)), "parameters": params}
    if len(entries) > 1 and rng.random() < 0.6:
        net["shaft_link"] = {"spacing": _q(rng.uniform(0.5, 10.0) * big.width * 1e3, "mm")}
    return net


def _load_shares(rng: np.random.Generator, picks: list[BearingEntry], roller_skidding: bool
                 ) -> list[dict[str, float] | None]:
    """Per-bearing ``load_share`` tables of a multi-bearing scene: a locating / floating
    arrangement (axial on one bearing), a lever-arm split of the radial load, a reversed
    axial share; None keeps the default (all of each load)."""
    out: list[dict[str, float] | None] = []
    locating = int(rng.integers(0, len(picks)))
    for i, e in enumerate(picks):
        if rng.random() < 0.4:
            out.append(None)
            continue
        share: dict[str, float] = {}
        r = rng.random()
        if r < 0.1 and not (roller_skidding and e.kind == "cylindrical"):
            share["radial"] = 0.0
        elif r < 0.8:
            share["radial"] = round(float(rng.uniform(0.05, 1.0)), 3)
        if e.kind != "cylindrical":
            a = rng.random()
            share["axial"] = (1.0 if i == locating else 0.0) if a < 0.6 else (
                -1.0 if a < 0.75 else round(float(rng.uniform(-1.0, 1.0)), 3))
        elif rng.random() < 0.7:
            share["axial"] = 0.0
        out.append(share or None)
    return out


def _rib_scene(rng: np.random.Generator, picks: list[BearingEntry]
               ) -> tuple[dict[str, Any], list[dict[str, Any] | None]] | None:
    """The rib_friction source on a cylindrical roller bearing with end-face geometry,
    ribs on both rings (NUP-type) and an axial load (race control: the roller skidding
    solver refuses axial loads): models and per-bearing overrides, or None."""
    if not any(e.ribbed_ring is not None for e in picks) or rng.random() > 0.5:
        return None
    sources = ["raceway_traction", "churning_elements", "churning_cage",
               "churning_inner_ring", "cage_guide", "pocket_friction", "rib_friction"]
    opts: dict[str, Any] = {}
    if rng.random() < 0.6 and any(e.rib_geometry for e in picks):
        opts["model"] = "reduced"  # the coupled dynamics cost ~2 s CPU per state
    models: dict[str, Any] = {"kinematics": "race_control"}
    if rng.random() < (0.3 if all(e.rib_geometry for e in picks) else 0.05):
        # else the default sources, which hold rib_friction where the geometry has it (a
        # list on a bearing without it is refused: now and then, for the message)
        models["heat_sources"] = sources
    if opts:
        models["heat_source_options"] = {"rib_friction": opts}
    # the both-rib override on bearings with rib geometry; on one without it (NU214,
    # D1842926: rib_friction left out, the thrust refused or booked nowhere) rarely
    overrides = [{"ribbed_ring": "both"} if e.ribbed_ring is not None
                 and rng.random() < (0.85 if e.rib_geometry else 0.15) else None
                 for e in picks]
    return models, overrides


def _schedule_file(rng: np.random.Generator, steps: list[dict[str, Any]], path: Path
                   ) -> dict[str, Any]:
    """Write the steps as a CSV protocol (``[schedule] file``): columns in random order and
    units (s / min, rpm / r/min, N / kN), sometimes one column left to a ``[schedule]``
    default, sometimes a UTF-8 BOM (a spreadsheet export) or CRLF line ends."""
    cols = {"duration": [("s", 1.0), ("min", 1 / 60)],
            "speed": [("rpm", 1.0), ("r/min", 1.0)],
            "radial_load": [("N", 1.0), ("kN", 1e-3)],
            "axial_load": [("N", 1.0), ("kN", 1e-3)]}
    units = {"duration": "s", "speed": "rpm", "radial_load": "N", "axial_load": "N"}
    values = [{k: float(st[k].split()[0]) for k in cols} for st in steps]
    table: dict[str, Any] = {}
    order = [str(k) for k in rng.permutation(list(cols))]
    if rng.random() < 0.3:
        # one column left out: its value comes from the [schedule] defaults
        key = order.pop()
        table[key if key != "duration" else "step_duration"] = _q(values[0][key], units[key])
    head, rows = [], [[] for _ in values]
    for key in order:
        unit, f = cols[key][int(rng.integers(0, 2))]
        head.append(f"{key} [{unit}]")
        for row, v in zip(rows, values, strict=True):
            row.append(f"{v[key] * f:.6g}")
    nl = "\r\n" if rng.random() < 0.2 else "\n"
    text = nl.join([",".join(head)] + [",".join(r) for r in rows]) + nl
    bom = "\ufeff" if rng.random() < 0.2 else ""
    path.write_text(bom + text, encoding="utf-8", newline="")
    table["file"] = str(path)
    return table


def _measured_file(rng: np.random.Generator, names: list[str], duration: float,
                   t0: float, path: Path) -> dict[str, Any]:
    """A synthetic rig CSV for ``[measured]`` (a smooth warm-up from ``t0`` [degC], not a
    model result): comma or semicolon with decimal commas, time in min or ``hh:mm:ss``,
    a few dropouts (empty, ``OVL``, ``-999`` listed in missing_values), mapped to the
    bearings' housing nodes."""
    n = int(rng.integers(3, 40))
    t = np.linspace(0.0, duration, n)
    sensors = {f"TC{i + 1} {nm}": f"{nm}.housing" for i, nm in enumerate(names)}
    semicolon = rng.random() < 0.4
    sep, dec = (";", ",") if semicolon else (",", ".")
    clock = rng.random() < 0.3
    head = ["Time" if clock else "time [min]", *sensors]
    lines = [sep.join(head)]
    for ti in t:
        cells = [(f"{int(ti // 3600):02d}:{int(ti % 3600 // 60):02d}:{int(ti % 60):02d}"
                  if clock else f"{ti / 60:.4f}".replace(".", dec))]
        for _ in sensors:
            r = rng.random()
            if r < 0.04:
                cells.append("")
            elif r < 0.07:
                cells.append("OVL")
            elif r < 0.1:
                cells.append("-999")
            else:
                v = t0 + 20.0 * (1 - math.exp(-ti / 600.0)) + rng.normal(0.0, 0.2)
                cells.append(f"{v:.2f}".replace(".", dec))
        lines.append(sep.join(cells))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return {"file": str(path), "time_column": head[0], "unit": "degC",
            "columns": sensors, "missing_values": [-999]}


def make_scene(rng: np.random.Generator, catalogue: list[BearingEntry],
               lubricants: list[str], files: Path | None = None
               ) -> tuple[dict[str, Any], dict[str, str]]:
    """One random scene as a TOML document (a dict) and a short description of it.
    ``files``: the stem under which a case's CSV files (schedule, measured) are written
    (``files.with_name(stem + "_protocol.csv")``); None: no file-based draws."""
    u = rng.random()
    n_bear = 1 if u < 0.7 else (2 if u < 0.92 else 3)
    picks = [catalogue[int(i)] for i in rng.integers(0, len(catalogue), n_bear)]
    kin = str(rng.choice(["skidding", "race_control", "none"], p=[0.5, 0.35, 0.15]))
    rib = _rib_scene(rng, picks) if kin != "none" else None
    if rib is not None:
        kin = "race_control"
    supply = _supply(rng, picks[0])
    ndm = NDM_LIMIT[supply["method"]]
    limit_rpm = min(ndm / (e.pitch * 1e3) for e in picks)
    c0 = min(e.c0 for e in picks)
    roller = any(e.kind == "cylindrical" for e in picks)
    outputs, what = _outputs(rng, kin)
    n_steps = int(rng.integers(1, 4)) if what == "transient" else int(rng.integers(1, 3))
    steps = []
    # the roller skidding solver refuses a turning step without radial load (README)
    radial_needed = roller and kin == "skidding"
    for _ in range(n_steps):
        step: dict[str, Any] = {"speed": _q(_speed(rng, limit_rpm), "rpm"),
                                "radial_load": _q(_load(rng, c0, not radial_needed), "N")}
        # cylindrical roller bearings without a rib pair take no axial load; with the rib
        # pair of a rib scene, a thrust up to ~20 % of the radial load
        if rib is not None and roller:
            step["axial_load"] = _q(float(step["radial_load"].split()[0])
                                    * rng.uniform(0.0, 0.2), "N")
        else:
            step["axial_load"] = _q(0.0 if roller else _load(rng, c0), "N")
        step["duration"] = _q(_log_uniform(rng, 2.0, 600.0), "s")
        steps.append(step)
    cold = rng.random() < 0.12
    if cold:
        # a cold start: machine, oil and air below freezing, then the schedule's speeds
        amb = float(rng.uniform(*COLD_RANGE))
        supply["inlet_temperature"] = _q(amb + rng.uniform(0.0, 5.0), "degC", 4)
    else:
        amb = float(rng.uniform(-20.0, 120.0))
    env: dict[str, Any] = {"ambient_temperature": _q(amb, "degC", 4)}
    if cold or rng.random() < 0.6:
        env["initial_temperature"] = _q(amb if cold else rng.uniform(-20.0, 120.0),
                                        "degC", 4)
    names = ["a", "b", "c"][:n_bear]
    bearings = [{"name": n, **e.spec} for n, e in zip(names, picks, strict=True)]
    if n_bear > 1:
        for b, share in zip(bearings, _load_shares(rng, picks, radial_needed), strict=True):
            if share is not None:
                b["load_share"] = share
    if rib is not None:
        for b, over, e in zip(bearings, rib[1], picks, strict=True):
            if over is not None:
                b["overrides"] = over
            elif e.kind == "cylindrical" and rng.random() < 0.9:
                # an NU-type bearing beside the ribbed one floats: no thrust share
                b["load_share"] = {**b.get("load_share", {}), "axial": 0.0}
    schedule: dict[str, Any] = {"steps": steps}
    if files is not None and rng.random() < 0.15:
        schedule = _schedule_file(rng, steps, files.with_name(files.name + "_protocol.csv"))
    doc: dict[str, Any] = {
        "title": "fuzz case",
        "bearings": bearings,
        "lubricant": {"preset": str(rng.choice(lubricants))},
        "supply": supply,
        "environment": env,
        "schedule": schedule,
        "models": rib[0] if rib is not None else _models(rng, picks, kin),
        "outputs": outputs,
    }
    if what in ("transient", "steady_temperatures"):
        doc["network"] = _network(rng, picks)
        if what == "transient":
            doc["solver"] = {"chunk": _q(_log_uniform(rng, 5.0, 120.0), "s")}
            if files is not None and rng.random() < 0.2:
                total = sum(_duration_s(st) for st in steps)
                t0 = float(env.get("initial_temperature", env["ambient_temperature"])
                           .split()[0])
                doc["measured"] = _measured_file(
                    rng, names, total, t0, files.with_name(files.name + "_measured.csv"))
    desc = {"bearings": "+".join(e.label for e in picks), "kinematics": kin,
            "outputs": what, "supply": supply["method"],
            "speeds": ",".join(s["speed"].split()[0] for s in steps)}
    extras = [k for k, on in (("share", any("load_share" in b for b in bearings)),
                              ("rib", rib is not None), ("cold", cold),
                              ("file", "file" in schedule), ("meas", "measured" in doc)) if on]
    extras += _options(rng, doc, picks, kin)
    desc["extras"] = ",".join(extras)
    return doc, desc


def _options(rng: np.random.Generator, doc: dict[str, Any], picks: list[BearingEntry],
             kin: str) -> list[str]:
    """Options a scene rarely changes, each drawn now and then: a bearing's diametral
    clearance (0 to 4x the preset's), the race that controls the spin under race control,
    where the churning heat goes, the network stepper, the output interval and the
    ``[checks]`` thresholds. Returns the short names of those drawn."""
    drawn = []
    for b, e in zip(doc["bearings"], picks, strict=True):
        if rng.random() < 0.1:
            over = b.setdefault("overrides", {})
            over["diametral_clearance"] = _q(float(rng.uniform(0.0, 4.0)) * e.clearance * 1e3,
                                             "mm")
            drawn.append("clear")
    models = doc["models"]
    if kin == "race_control" and rng.random() < 0.4:
        models["control"] = str(rng.choice(["outer_race", "inner_race", "pure_rolling"]))
        drawn.append("ctrl")
    if kin != "none" and rng.random() < 0.15:
        models["churning_heat_to"] = "paper002"
        drawn.append("p002")
    if "solver" in doc and rng.random() < 0.25:
        # crank_nicolson (fixed step, refused by a scene) now and then, for its message
        doc["solver"]["stepper"] = str(rng.choice(["tr_bdf2", "backward_euler",
                                                   "crank_nicolson"], p=[0.45, 0.45, 0.1]))
        drawn.append("stepper")
    if doc["outputs"]["mode"] == "transient" and rng.random() < 0.2:
        doc["outputs"]["interval"] = _q(_log_uniform(rng, 1.0, 300.0), "s")
        drawn.append("interval")
    if rng.random() < 0.1:
        doc["checks"] = {"skid_limit": _q(rng.uniform(0.5, 20.0), "%", 3),
                         "contact_stress_limit": _q(rng.uniform(1500.0, 4500.0), "MPa", 4),
                         "min_film_parameter": round(float(rng.uniform(0.5, 3.0)), 2)}
        drawn.append("checks")
    return drawn


def _duration_s(step: dict[str, Any]) -> float:
    value, unit = step["duration"].split()
    return float(value) * {"s": 1.0, "min": 60.0}[unit]


# ------------------------------------------------------------------------------ checks
class CaseTimeout(Exception):
    """The case ran longer than the time limit."""


def garbled(text: str) -> str | None:
    """The pattern a warning text matches that marks it garbled (None: readable)."""
    if not text.strip():
        return "empty text"
    for pat in GARBLED:
        if pat.search(text):
            return pat.pattern
    return None


def classify_error(exc: BaseException) -> tuple[str, str]:
    """Outcome and message of a run stopped by ``exc``."""
    from thermobearing.errors import ConvergenceError, InputError

    msg = str(exc)
    if isinstance(exc, CaseTimeout):
        return "TIMEOUT", "time limit (wall seconds)"
    if isinstance(exc, InputError):
        if not exc.field or exc.field not in msg:
            return "DEFECT", f"refusal does not name its field: {msg}"
        if "array(" in msg or "\n" in msg:
            return "DEFECT", f"refusal prints an internal array: {msg[:300]}"
        head = re.split(r"[.\[ ]", str(exc.field), maxsplit=1)[0]
        if head not in SCENE_FIELD_HEADS:
            # clean, but the field is no key of the scene (``eta0``, ``operating.axial_load``,
            # ``dt``): the user cannot tell what to change; listed in the summary
            return "REFUSED", f"(not a scene field) {msg}"
        return "REFUSED", msg
    if isinstance(exc, ConvergenceError):
        if not math.isfinite(float(exc.residual)):
            return "DEFECT", f"convergence error without a finite residual: {msg}"
        return "REFUSED", msg
    tb = traceback.extract_tb(exc.__traceback__)
    where = f"{Path(tb[-1].filename).name}:{tb[-1].lineno}" if tb else "?"
    return "DEFECT", f"{type(exc).__name__} at {where}: {msg}"


def _nan_allowed(table: str, column: str, row: Any, no_contacts_model: bool) -> bool:
    """Where an empty (NaN) cell is the documented value, not a defect.
    ``no_contacts_model``: the scene's kinematics model computes no contacts ("none")."""
    at_rest = float(row.get("speed [rpm]", 1.0)) == 0.0
    unloaded = (float(row.get("radial load [kN]", 1.0)) == 0.0
                and float(row.get("axial load [kN]", 1.0)) == 0.0)
    no_contacts = not float(row.get("max contact pressure [MPa]", math.nan)) > 0.0
    if table == "kinematics" and column.endswith("contact angle [deg]"):
        return True  # ball rings without a loaded contact; no column for rollers
    if table == "kinematics" and column == "max contact pressure [MPa]" and (
            no_contacts_model or (at_rest and unloaded)):
        return True  # no contacts solved (kinematics "none"), none at rest without load
    if table == "kinematics" and column == "min film parameter [-]" and (at_rest
                                                                       or no_contacts):
        return True  # no film at rest; no loaded contact, no film parameter
    if table == "kinematics" and at_rest and column in (
            "cage speed ratio [-]", "over-skidding [%]"):
        return True  # README: at rest the cage speed ratio is left empty
    if table == "film" and at_rest and column in ("central film [um]", "film parameter [-]",
                                                  "closed-form central film [um]"):
        return True
    return False


def _zero_pressure_under_load(df: Any) -> str | None:
    """A loaded, turning or resting bearing whose kinematics row gives 0 MPa (a number
    where the model computed no contact)."""
    need = ("max contact pressure [MPa]", "radial load [kN]", "axial load [kN]")
    if df is None or not all(c in df for c in need):
        return None
    loaded = (df["radial load [kN]"] > 0) | (df["axial load [kN]"] > 0)
    bad = df[loaded & (df["max contact pressure [MPa]"] == 0.0)]
    if bad.empty:
        return None
    r = bad.iloc[0]
    return (f"kinematics[max contact pressure [MPa]] = 0 under {r['radial load [kN]']:.4g} "
            f"kN radial, {r['axial load [kN]']:.4g} kN axial (bearing {r['bearing']})")


def check_results(results: Any, no_contacts_model: bool = False) -> list[str]:
    """The defects in a finished run's tables and warnings (``no_contacts_model``: the
    scene's kinematics model is "none", which solves no contacts)."""
    from thermobearing.coupled import RUNAWAY_TEMPERATURE

    problems = []
    for name, df in results.tables.items():
        for col in df.columns:
            values = df[col]
            if not is_numeric_dtype(values) or is_bool_dtype(values):
                continue
            arr = values.to_numpy(dtype=float)
            bad = ~np.isfinite(arr)
            for i in np.flatnonzero(bad):
                row = df.iloc[int(i)]
                if np.isnan(arr[i]) and _nan_allowed(name, col, row, no_contacts_model):
                    continue
                problems.append(f"{name}[{col}] row {int(i)} = {arr[i]}")
                break
            if col == "power [W]" and np.any(arr < -1e-9):
                problems.append(f"{name}: negative power {np.nanmin(arr):.3g} W")
            if col.endswith("[degC]") and np.any(arr <= -273.15):
                problems.append(f"{name}[{col}] at or below absolute zero: "
                                f"{np.nanmin(arr):.6g} degC")
            if col.endswith("[degC]") and np.any(arr > RUNAWAY_TEMPERATURE - 273.15):
                # a transient stops there as a thermal runaway; a table beyond it is a
                # result no run should give
                problems.append(f"{name}[{col}] above the runaway limit "
                                f"{RUNAWAY_TEMPERATURE - 273.15:.0f} degC: "
                                f"{np.nanmax(arr):.6g} degC")
    zero = _zero_pressure_under_load(results.tables.get("kinematics"))
    if zero:
        problems.append(zero)
    for w in results.warnings:
        why = garbled(str(w))
        if why:
            problems.append(f"garbled warning ({why}): {str(w)[:200]}")
    return problems


@dataclass
class Case:
    index: int
    desc: dict[str, str]
    toml: str
    outcome: str = ""
    message: str = ""
    seconds: float = 0.0
    notes: list[str] = field(default_factory=list)


def _run_here(case: Case) -> None:
    """Load and run the case's scene in this process; fill its outcome."""
    from thermobearing.scene import loads_scene
    from thermobearing.simulation import Simulation

    t0 = time.process_time()
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            scene = loads_scene(case.toml, base_dir=ROOT)
            results = Simulation(scene, progress=False).run()
        problems = check_results(results, scene.models.get("kinematics") == "none")
        leaked = sorted({f"{w.category.__name__}: {w.message}" for w in caught
                         if not issubclass(w.category, DeprecationWarning)})
        case.notes.extend(leaked)
        if problems:
            case.outcome, case.message = "DEFECT", "; ".join(problems)
        else:
            case.outcome = "OK"
    except Exception as exc:  # noqa: BLE001 -- every failure is classified
        case.outcome, case.message = classify_error(exc)
    finally:
        case.seconds = time.process_time() - t0


def _worker(conn: Any) -> None:
    """Run the cases sent through ``conn`` one after the other (compiled kernels stay
    loaded between cases); answer each with its outcome."""
    while True:
        case = conn.recv()
        if case is None:
            return
        _run_here(case)
        conn.send((case.outcome, case.message, case.seconds, case.notes))


def import_package() -> None:
    """Import every module of the package in this process before the first worker is
    forked: the workers share one snapshot of the code (a module imported lazily in a later
    worker would be read from the working tree as it is then)."""
    import importlib
    import pkgutil

    import thermobearing

    for info in pkgutil.walk_packages(thermobearing.__path__, "thermobearing."):
        importlib.import_module(info.name)


class Runner:
    """One worker process (forked: it inherits the imported package) that runs the cases
    one at a time; a case over the time limit is killed with its worker (compiled loops do
    not return to the interpreter for a signal) and the next case starts a fresh one."""

    def __init__(self) -> None:
        self._ctx = multiprocessing.get_context("fork")
        self._proc: Any = None
        self._conn: Any = None

    def _start(self) -> None:
        self._conn, child = self._ctx.Pipe()
        self._proc = self._ctx.Process(target=_worker, args=(child,), daemon=True)
        self._proc.start()
        child.close()

    def run(self, case: Case, time_limit: float) -> None:
        if self._proc is None or not self._proc.is_alive():
            self._start()
        self._conn.send(case)
        if self._conn.poll(time_limit):
            try:
                case.outcome, case.message, case.seconds, case.notes = self._conn.recv()
                return
            except EOFError:
                case.outcome = "DEFECT"
                case.message = f"the run's process died (exit code {self._proc.exitcode})"
                self._proc = None
                return
        self._proc.kill()
        self._proc.join()
        self._proc = None
        case.outcome, case.message = classify_error(CaseTimeout())
        case.seconds = time_limit

    def close(self) -> None:
        if self._proc is not None and self._proc.is_alive():
            self._conn.send(None)
            self._proc.join(5)


def run_cli(case: Case, out_dir: Path, time_limit: float) -> None:
    """``thermobearing run SCENE --out DIR --quiet``: exit 0 with a report, or 1 with an
    error line; anything else (a traceback, a missing report) is a defect."""
    scene_path = out_dir / f"case_{case.index:04d}.toml"
    scene_path.write_text(case.toml, encoding="utf-8")
    target = out_dir / f"case_{case.index:04d}_run"
    try:
        proc = subprocess.run([sys.executable, "-m", "thermobearing.cli", "run",
                               str(scene_path), "--out", str(target), "--quiet"],
                              capture_output=True, text=True, timeout=time_limit + 30,
                              cwd=ROOT)
    except subprocess.TimeoutExpired:
        case.notes.append("cli: time limit")
        return
    err = proc.stderr.strip().splitlines()
    if proc.returncode == 0:
        if not (target / "report.html").is_file():
            case.outcome, case.message = "DEFECT", "cli: exit 0 without report.html"
    elif proc.returncode == 1 and any("error:" in line for line in err):
        if case.outcome == "OK":
            case.outcome, case.message = "DEFECT", f"cli refused what the API ran: {err[-1]}"
    else:
        case.outcome = "DEFECT"
        case.message = f"cli exit {proc.returncode}: {' | '.join(err[-3:])}"


# -------------------------------------------------------------------------------- main
def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--n", type=int, default=100, help="number of cases (default 100)")
    parser.add_argument("--out", type=Path, default=None,
                        help="folder for the defects' reproducer TOML files and CLI runs")
    parser.add_argument("--time-limit", type=float, default=60.0,
                        help="wall seconds per case (default 60)")
    parser.add_argument("--cli-every", type=int, default=10,
                        help="also run every N-th case through `thermobearing run --out` "
                             "(0: never; default 10)")
    parser.add_argument("--only", type=str, default="",
                        help="comma list of case indices to run (reproduce a few)")
    args = parser.parse_args(argv)
    from thermobearing.scene import dumps_toml

    rng = np.random.default_rng(args.seed)
    catalogue, lubricants = bearing_catalogue(), lubricant_names()
    only = {int(x) for x in args.only.split(",") if x.strip()}
    out_dir = args.out or Path(tempfile.mkdtemp(prefix="fuzz_scenes_"))
    out_dir.mkdir(parents=True, exist_ok=True)
    cases = []
    import_package()
    runner = Runner()
    for i in range(args.n):
        doc, desc = make_scene(rng, catalogue, lubricants, out_dir / f"case_{i:04d}")
        if only and i not in only:
            continue
        case = Case(i, desc, dumps_toml(doc))
        runner.run(case, args.time_limit)
        if args.cli_every and i % args.cli_every == 0 and case.outcome != "TIMEOUT":
            run_cli(case, out_dir, args.time_limit)
        cases.append(case)
        print(f"{i:4d} {case.outcome:8s} {case.seconds:6.1f}s {desc['bearings']:>22s} "
              f"{desc['kinematics']:12s} {desc['outputs']:19s} {desc['supply']:11s} "
              f"{desc['speeds']:>20s} {desc['extras']:>16s}  {case.message[:90]}", flush=True)
    runner.close()
    print_summary(cases, out_dir)
    return 1 if any(c.outcome == "DEFECT" for c in cases) else 0


def print_summary(cases: list[Case], out_dir: Path) -> None:
    counts: dict[str, int] = {}
    for c in cases:
        counts[c.outcome] = counts.get(c.outcome, 0) + 1
    print("\noutcome   cases")
    for key in ("OK", "REFUSED", "TIMEOUT", "DEFECT"):
        print(f"{key:8s} {counts.get(key, 0):6d}")
    refusals: dict[str, int] = {}
    for c in cases:
        if c.outcome == "REFUSED":
            head = re.sub(r"[-+]?\d[\d.e+-]*", "#", c.message)[:110]
            refusals[head] = refusals.get(head, 0) + 1
    if refusals:
        print("\nrefusals (numbers replaced by #):")
        for head, k in sorted(refusals.items(), key=lambda kv: -kv[1]):
            print(f"  {k:4d}  {head}")
    leaked: dict[str, int] = {}
    for c in cases:
        for n in c.notes:
            leaked[n[:150]] = leaked.get(n[:150], 0) + 1
    if leaked:
        print("\nwarnings raised to the caller / CLI notes (count):")
        for text, k in sorted(leaked.items(), key=lambda kv: -kv[1])[:30]:
            print(f"  {k:4d}  {text}")
    for c in cases:
        if c.outcome == "OK":
            continue
        path = out_dir / f"case_{c.index:04d}.toml"
        path.write_text(c.toml, encoding="utf-8")
        if c.outcome == "DEFECT":
            print(f"\n=== DEFECT case {c.index} ({path}): {c.message}\n{c.toml}")
        elif c.outcome == "TIMEOUT":
            print(f"\n=== TIMEOUT case {c.index}: {path}")


if __name__ == "__main__":
    sys.exit(main())
