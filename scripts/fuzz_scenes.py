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
- 2026-11-23, later still: grease supplies (no flow, or ``flow = "0 L/min"``); the schedule
  as ``[schedule]`` defaults only (``dflt``) or an ``axial_load_steps`` sweep (``asteps``);
  hot machines (``hot``: ambient, initial and inlet at 120-180 degC); lubricant files of
  ISO VG 2 to 1500 mineral oils beside the reproducers (``DIR/case_<n>_oil.toml``, the
  grade in the summary, e.g. ``VG1000``); measured files in K or degF, tab separated, time
  in seconds, with an unmapped column or a units row; the same scene in other units
  (``units``: K / degF, kN / lbf, rad/s / rev/s / krpm, L/h, m / inch, min ...), whose SI
  values must equal those of the plain scene (``si_mismatch``); the command line
  ``check`` before and ``report`` after each ``--cli-every`` run, and every
  ``--sweep-every``-th case (default 5) that ran OK a ``thermobearing sweep`` of one ``--set`` with
  two values (flow, inlet temperature, speed, lubricant preset, skid limit or h_oil) and
  its ``report``; ``[models] calibration = "none"`` (``nocal``), the ball EHL rolling
  force ``ball_rolling_resistance`` with a reduction (``rr``), solver tolerances and
  ``max_step`` (``tol``); ``[outputs] want`` mixes (film, report or kinematics beside the
  others: a wanted film table must be there or the run must say why).
- 2026-11-23, session 17: fuzz oil files with other pressure laws (``VG5barus``: Barus with
  a given alpha; ``VG5alpha``: Roelands from an alpha at a reference temperature, as
  OIL_4109; ``VG5z``: a given Roelands z); ``[models] film`` (``film``: the closed-form
  point or line film models, now and then the other contact kind's); ``[solver]
  chunk_viscosity_limit`` (``cvl``); ``[checks]`` with a stress limit per bearing family
  or only some thresholds; a sweep whose two cases give the same numbers in every result
  column without the sweep calling the swept path unused is listed in the notes
  (``identical``: a setting ignored without a word, or one these outputs do not depend on);
  a documented numeric option of a default heat source (``srcopt``: cage_guide,
  churning_*, pocket_friction, raceway_traction) inside its registry interval, one in
  twelve outside it; table values that cannot be negative (films, film parameters,
  contact pressures, cage speed ratios) or a cage speed ratio above 1 are defects, as is
  any wanted output (not only the film) whose table is missing without an
  ``outputs.want`` warning naming it.
- 2026-11-23, session 18: boundary steps (``dur0``, ``rev``: a reversed speed, ``negload``,
  all refused naming the step's field; ``rest0``: a step at rest between turning ones);
  unit strings in unusual but valid spellings and number forms (``oddunits``: ``°C``,
  ``kilonewton``, ``rev/min``, ``dm^3/min``, ``µm``, ``W m^-2 K^-1``, ``1.5E+03``, ``+5``,
  ``.5``, ``1500rpm``), whose SI values must equal the plain scene's; measured files with
  ISO / dotted timestamps, separate date and time columns, Excel day numbers, Unix seconds
  or a strptime pattern, a ``time_zero`` offset, 1-2 rows, text dropout codes, the unit in
  each header or spelled as a logger does, in Windows-1252 or UTF-16; schedule CSV files
  in UTF-16; ``axial_load_steps`` with a step a million times too small (refused); one to
  three ``--set`` per sweep, each swept field's values checked as given; every
  ``--cage-every``-th case (default 4) ``thermobearing cage-speed`` on a generated
  vibration record of its first bearing (:func:`vibration_record`: CSV / TSV / npy / npz /
  wav, clean, weak, noise, constant, clipped, short, slow, aliased or with gaps), which must
  exit 0 with finite numbers, 3 or 1 with an error line; ``thermobearing calibrate
  --max-runs 2`` on each scene with a measured file that ran OK (``--calibrate``), whose
  calibrated scene must load and pass ``check``; ``--mutations`` (default 3) copies of
  each scene with one value replaced by another type, size or unit, or deleted, loaded and
  checked without a solve: anything but a refusal naming its field is a defect.
- 2026-11-24, session 19: the mutations also make a user's mistakes (:func:`typo_mutate`,
  :func:`structure_mutate`): unit typos meant as the unit they replace (``35 C``, ``°C``,
  ``degc``, ``1.8 kRPM``, ``1/min``, ``KN``, ``lbs``, ``l/min``, ``lpm``, ``mins``, ``m``
  for min ...), number typos (decimal comma, digit groups with comma / space / apostrophe /
  thin space, the minus sign U+2212, a doubled point, the letter O for a zero) and other
  separators (none, two spaces, no-break space, tab, underscore): a typo the scene accepts
  must read the value meant (:func:`_typo_misread`), else it must be refused naming its
  field; structural mistakes: a list element duplicated (a step, a heat source, a
  bearing), a table or list emptied, two quantities of one table swapped (start / stop,
  ambient / initial, two diameters), a list reversed, names and titles in other scripts, a
  number scaled by 1e-6 .. 1e6 in its unit. ``thermobearing check``'s own refusals are
  classified too (a field that is no scene key goes to the notes). ``--mutant-runs N``
  (default 1) solves up to N accepted user-made mutants of each case like a case (a defect
  is the case's, with the mutant as reproducer; refusals and timeouts are notes, their TOML
  written as ``DIR/case_<n>_mutant<k>.toml``); a mutant that keeps the physics (bearings,
  sources or outputs reversed, a bearing renamed) must keep the case's outcome (else a
  note).
- 2026-11-24, session 20: structural mutations of the kind ``extreme``: one number scaled by
  1e-300 .. 1e300 in its unit (:data:`EXTREME_FACTORS`; issue 6: 1e300 rpm was a bare
  OverflowError, 1e150 L/min a NaN in the stepper), refused naming its field or, accepted,
  solved like a case; the check step also evaluates the global_friction source
  (:func:`thermobearing.scene_checks.check_global_friction`, as ``thermobearing check``).

Usage::

    python scripts/fuzz_scenes.py --seed 1 --n 150 --time-limit 60 --out fuzz_out
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import multiprocessing
import re
import subprocess
import sys
import tempfile
import time
import tomllib
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
NDM_LIMIT = {"oil_bath": 0.5e6, "circulation": 0.8e6, "jet": 2.1e6, "oil_air": 2.1e6,
             "grease": 0.5e6}
#: ISO 76 static-rating factor f0 of radial ball bearings lies between about 12 and 17
#: (ISO 76 Table 1, by D cos(alpha) / d_m); the lower end sets the fuzz range of loads
F0_BALL = 12.3
#: ISO 76 radial roller bearings: C0 = 44 (1 - D cos(alpha) / d_m) i Z L_we D [N, mm]
K_ROLLER = 44.0
#: h of the templates' oil and air convection drawn from these ranges [W/(m^2 K)]
#: (paper 002 gives 50-1500 for the oil; free to forced air 5-50)
H_OIL_RANGE = (50.0, 1500.0)
H_AIR_RANGE = (5.0, 50.0)

SUPPLIES = ("jet", "circulation", "oil_bath", "oil_air", "grease")
SUPPLY_WEIGHTS = (0.24, 0.24, 0.24, 0.2, 0.08)
#: mineral-oil ISO VG grades outside the presets (ISO 3448 nu40 [mm^2/s] = the grade) with
#: a nu100 [mm^2/s] of about VI 95 (order of magnitude of paraffinic product data sheets;
#: fuzz inputs of the right size, not lubricant data)
EXTREME_GRADES = {2: 1.0, 5: 1.7, 10: 2.6, 15: 3.4, 150: 14.7, 220: 19.0, 320: 24.0,
                  460: 30.5, 680: 39.0, 1000: 50.0, 1500: 63.0}
#: hot machines: ambient, initial and inlet temperatures drawn in this range [degC]
HOT_RANGE = (120.0, 180.0)
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
#: closed-form film models ([models] film) of point (ball) and line (roller) contacts; the
#: numerical EHL models cost minutes of table building per case and are not drawn
POINT_FILMS = ("hamrock_dowson_1977_central", "hamrock_dowson_1977_minimum")
LINE_FILMS = ("pan_hamrock_central", "pan_hamrock_minimum", "moes_line_central",
              "dowson_higginson_minimum")
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
    method = str(rng.choice(SUPPLIES, p=SUPPLY_WEIGHTS))
    out: dict[str, Any] = {"method": method}
    if method == "grease":
        if rng.random() < 0.3:
            out["flow"] = "0 L/min"  # a grease fill: no flow (written or left out)
    elif method == "oil_air":
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
    if rng.random() < 0.2:
        # a mix as users write it: the film table (or the report) beside the others
        # (energy beside a steady run's outputs: no table, the run must say why)
        extra = str(rng.choice(["film", "report"] + (["kinematics"] if kin != "none"
                                                      else [])
                               + (["energy"] if pick == "steady_temperatures"
                                  else [])))
        if extra not in want:
            want = [*want, extra]
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


def both_ribs_override(spec: dict[str, Any]) -> dict[str, Any]:
    """``ribbed_ring = "both"`` (NUP-type), with a cage that clears the outer ribs when the
    preset's does not: the bearing check refuses a cage across them (CRB_50x75x16's 66 mm
    cage across the 65.515 mm bore d_o - 2 h_f); 0.5 mm below the rib bore."""
    from thermobearing.geometry import load_bearing

    b = load_bearing(spec.get("preset") or spec["path"])
    over: dict[str, Any] = {"ribbed_ring": "both"}
    h = getattr(b, "rib_height", None)
    if h is not None:
        bore = float(b.outer_raceway_diameter) - 2.0 * float(h)
        if b.cage.outer_diameter >= bore:
            over["cage"] = {"outer_diameter": f"{(bore - 5e-4) * 1e3:.6g} mm"}
    return over


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
    overrides = [both_ribs_override(e.spec) if e.ribbed_ring is not None
                 and rng.random() < (0.85 if e.rib_geometry else 0.15) else None
                 for e in picks]
    return models, overrides


#: the boundary draws of :func:`_edge_step` a scene refuses (its summary tags)
EDGE_REFUSED = frozenset({"dur0", "rev", "negload"})


def _edge_step(rng: np.random.Generator, steps: list[dict[str, Any]]) -> str:
    """A boundary value in one step (tag returned): a zero duration (``dur0``), a
    reversed speed (``rev``: the shaft turning the other way, written as a negative
    speed), a negative load (``negload``), or a step at rest without load between turning
    ones (``rest0``, which runs). The first three are refused naming the step's field."""
    i = int(rng.integers(0, len(steps)))
    kind = str(rng.choice(["dur0", "rev", "negload", "rest0"]))
    if kind == "dur0":
        steps[i]["duration"] = str(rng.choice(["0 s", "0 min", "0.0 s"]))
    elif kind == "rev":
        v = float(steps[i]["speed"].split()[0]) or 100.0
        steps[i]["speed"] = _q(-v, "rpm")
    elif kind == "negload":
        key = str(rng.choice(["radial_load", "axial_load"]))
        steps[i][key] = _q(-_log_uniform(rng, 1.0, 1000.0), "N")
    else:
        steps.insert(i, {"speed": "0 rpm", "radial_load": "0 N", "axial_load": "0 N",
                         "duration": _q(_log_uniform(rng, 1.0, 60.0), "s")})
    return kind


def _schedule_file(rng: np.random.Generator, steps: list[dict[str, Any]], path: Path
                   ) -> dict[str, Any]:
    """Write the steps as a CSV protocol (``[schedule] file``): columns in random order and
    units (s / min, rpm / r/min, N / kN), sometimes one column left to a ``[schedule]``
    default, sometimes a UTF-8 BOM (a spreadsheet export) or CRLF line ends, capitalised
    headers, the units in the cells under bare headers, or semicolons with decimal commas
    and points grouping thousands (``1.234,5``)."""
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
    in_cells = rng.random() < 0.15  # units in the cells, bare headers
    semicolon = rng.random() < 0.25  # decimal commas, points grouping thousands
    for key in order:
        unit, f = cols[key][int(rng.integers(0, 2))]
        name = key.capitalize() if rng.random() < 0.2 else key
        head.append(name if in_cells else f"{name} [{unit}]")
        for row, v in zip(rows, values, strict=True):
            cell = f"{v[key] * f:.6g}"
            if semicolon and "e" in cell:
                cell = cell.replace(".", ",")
            elif semicolon:
                whole, _, frac = cell.partition(".")
                sign = "-" if whole.startswith("-") else ""
                whole = f"{int(whole.lstrip('-')):,}".replace(",", ".")
                cell = sign + whole + ("," + frac if frac else "")
            row.append(f"{cell} {unit}" if in_cells else cell)
    sep = ";" if semicolon else ","
    nl = "\r\n" if rng.random() < 0.2 else "\n"
    text = nl.join([sep.join(head)] + [sep.join(r) for r in rows]) + nl
    bom = "\ufeff" if rng.random() < 0.2 else ""
    # now and then saved as Excel's "Unicode text" (UTF-16 with its mark)
    enc = "utf-16" if rng.random() < 0.08 else "utf-8"
    path.write_text((bom if enc == "utf-8" else "") + text, encoding=enc, newline="")
    table["file"] = str(path)
    return table


#: time layouts of a measured file's time column: (tag, weight)
TIME_LAYOUTS = (("min", 0.3), ("s", 0.12), ("clock", 0.14), ("iso", 0.1), ("dotted", 0.07),
                ("split", 0.07), ("excel", 0.08), ("unix", 0.06), ("pattern", 0.06))


def _time_cells(rng: np.random.Generator, layout: str, t: np.ndarray
                ) -> tuple[list[str], list[list[str]], list[str], dict[str, Any]]:
    """The time column(s) of a measured file in ``layout`` (see TIME_LAYOUTS): header
    name(s), one list of cells per row, the units-row cell(s) and the ``[measured]`` keys
    (time_column, time_format, time_zero) that read them back as seconds from t[0] = 0.
    Numbers in min or s may start at an offset (a logger started before the test) given
    as ``time_zero``; timestamps start at a random clock time (now and then just before
    midnight, so the file passes it) and read from their first row."""
    from datetime import datetime, timedelta

    start = datetime(2026, int(rng.integers(1, 13)), int(rng.integers(1, 29)),
                     23 if rng.random() < 0.2 else int(rng.integers(0, 23)),
                     int(rng.integers(0, 60)), int(rng.integers(0, 60)))
    stamps = [start + timedelta(seconds=float(ti)) for ti in t]
    keys: dict[str, Any] = {}
    if layout in ("min", "s"):
        f = 1 / 60 if layout == "min" else 1.0
        off = float(rng.uniform(1.0, 300.0)) if rng.random() < 0.25 else 0.0
        if off:
            keys["time_zero"] = f"{off * f:.4f}"
        name = "time [min]" if layout == "min" else "time [s]"
        return [name], [[f"{(ti + off) * f:.4f}"] for ti in t], [layout], {
            "time_column": name, **keys}
    if layout == "clock":
        cells = [[f"{int(ti // 3600):02d}:{int(ti % 3600 // 60):02d}:{int(ti % 60):02d}"]
                 for ti in t]
        return ["Time"], cells, ["hh:mm:ss"], {"time_column": "Time"}
    if rng.random() < 0.3:
        keys["time_zero"] = "first"
    if layout == "iso":
        sep = "T" if rng.random() < 0.4 else " "
        cells = [[d.isoformat(sep=sep, timespec="seconds")] for d in stamps]
        return ["Timestamp"], cells, [""], {"time_column": "Timestamp", **keys}
    if layout == "dotted":
        cells = [[d.strftime("%d.%m.%Y %H:%M:%S")] for d in stamps]
        return ["Datum/Uhrzeit"], cells, [""], {"time_column": "Datum/Uhrzeit", **keys}
    if layout == "split":
        cells = [[d.strftime("%Y-%m-%d"), d.strftime("%H:%M:%S")] for d in stamps]
        return ["Date", "Time"], cells, ["", ""], {"time_column": ["Date", "Time"], **keys}
    if layout == "excel":
        # serial day numbers: a date-named column is read as such without time_format
        days = [(d - datetime(1899, 12, 30)).total_seconds() / 86400.0 for d in stamps]
        cells = [[f"{x:.8f}"] for x in days]
        if rng.random() < 0.5:
            return ["Date"], cells, [""], {"time_column": "Date", **keys}
        return ["Stamp"], cells, [""], {"time_column": "Stamp", "time_format": "excel",
                                        **keys}
    if layout == "unix":
        secs = [(d - datetime(1970, 1, 1)).total_seconds() for d in stamps]
        return ["epoch"], [[f"{x:.1f}"] for x in secs], [""], {
            "time_column": "epoch", "time_format": "unix", **keys}
    cells = [[d.strftime("%Y%m%d-%H%M%S")] for d in stamps]
    return ["stamp"], cells, [""], {"time_column": "stamp", "time_format": "%Y%m%d-%H%M%S",
                                    **keys}


def _measured_file(rng: np.random.Generator, names: list[str], duration: float,
                   t0: float, path: Path) -> dict[str, Any]:
    """A synthetic rig CSV for ``[measured]`` (a smooth warm-up from ``t0`` [degC], not a
    model result), 1 to 39 rows: comma, tab or semicolon with decimal commas; the time in
    min or s (from an offset given as ``time_zero`` now and then), elapsed ``hh:mm:ss``,
    ISO or dotted timestamps, separate date and time columns, Excel day numbers, Unix seconds or a
    strptime pattern (:func:`_time_cells`); sensors in degC, K or degF (now and then the
    unit in each sensor's header brackets as loggers write it, ``[°C]``, ``(K)``); a few
    dropouts (empty, ``OVL``, ``-999`` or a text code listed in ``missing_values``), an
    unmapped column, a units row; mapped to the bearings' housing nodes."""
    n = int(rng.integers(3, 40)) if rng.random() < 0.9 else int(rng.integers(1, 3))
    t = np.linspace(0.0, duration, n)
    layout = str(rng.choice([k for k, _ in TIME_LAYOUTS],
                            p=np.array([w for _, w in TIME_LAYOUTS])
                            / sum(w for _, w in TIME_LAYOUTS)))
    r_sep = rng.random()
    sep, dec = (";", ",") if r_sep < 0.35 else ("\t", ".") if r_sep < 0.5 else (",", ".")
    if sep == "," and layout == "split" and rng.random() < 0.5:
        sep = ";"  # dates beside decimal points: any separator
    # the logger's unit (K, degF) and an unmapped column (the rig's speed) now and then
    unit = str(rng.choice(["degC", "K", "degF"], p=[0.7, 0.15, 0.15]))
    to_unit = {"degC": lambda v: v, "K": lambda v: v + 273.15,
               "degF": lambda v: v * 1.8 + 32.0}[unit]
    in_header = rng.random() < 0.15
    head_unit = {"degC": str(rng.choice(["[°C]", "[degC]", "(°C)"])),
                 "K": str(rng.choice(["[K]", "(K)"])),
                 "degF": str(rng.choice(["[°F]", "[degF]"]))}[unit]
    sensors = {(f"TC{i + 1} {nm} {head_unit}" if in_header else f"TC{i + 1} {nm}"):
               f"{nm}.housing" for i, nm in enumerate(names)}
    text_code = str(rng.choice(["TC-BREAK", "9999.9", "----"])) if rng.random() < 0.2 else ""
    extra = rng.random() < 0.25
    tnames, tcells, tunits, keys = _time_cells(rng, layout, t)
    head = [*tnames, *sensors] + (["speed [rpm]"] if extra else [])
    lines = [sep.join(head)]
    if rng.random() < 0.15:  # a units row under the header, as DAQ programs write it
        lines.append(sep.join(tunits + [unit] * len(sensors) + (["rpm"] if extra else [])))
    for ti, tc in zip(t, tcells, strict=True):
        cells = [c.replace(".", dec) if layout in ("min", "s", "excel", "unix") else c
                 for c in tc]
        for _ in sensors:
            r = rng.random()
            if r < 0.04:
                cells.append("")
            elif r < 0.07:
                cells.append("OVL")
            elif r < 0.1:
                cells.append(text_code.replace(".", dec) if text_code else "-999")
            else:
                v = t0 + 20.0 * (1 - math.exp(-ti / 600.0)) + rng.normal(0.0, 0.2)
                cells.append(f"{to_unit(v):.2f}".replace(".", dec))
        if extra:
            cells.append(f"{rng.uniform(0.0, 3000.0):.1f}".replace(".", dec))
        lines.append(sep.join(cells))
    # a logger on Windows (ANSI code page: °C is one byte) or Excel's "Unicode text"
    enc = str(rng.choice(["utf-8", "cp1252", "utf-16"], p=[0.8, 0.12, 0.08]))
    path.write_text("\n".join(lines) + "\n", encoding=enc)
    missing: list[Any] = [-999] + ([float(text_code)] if text_code == "9999.9" else
                                   [text_code] if text_code else [])
    # the unit as a header would spell it, now and then
    spelled = {"degC": ["°C", "celsius"], "K": ["kelvin"], "degF": ["°F", "fahrenheit"]}
    written = str(rng.choice(spelled[unit])) if rng.random() < 0.2 else unit
    return {"file": str(path), **keys, "unit": written, "columns": sensors,
            "missing_values": missing}


def _axial_load_steps(rng: np.random.Generator, steps: list[dict[str, Any]], c0: float,
                      rib_roller: bool) -> dict[str, Any]:
    """The first step's speed, radial load and duration as ``[schedule]`` defaults and an
    ``axial_load_steps`` sweep of 2 to 5 steps (up to ~20 % of the radial load on a
    both-ribbed roller bearing)."""
    first = steps[0]
    if rib_roller:
        top = float(first["radial_load"].split()[0]) * rng.uniform(0.0, 0.2)
        a0 = 0.0
    else:
        top = _log_uniform(rng, 0.01 * c0, 0.5 * c0)
        a0 = 0.0 if rng.random() < 0.5 else top * rng.uniform(0.0, 0.5)
    n = int(rng.integers(2, 6))
    da = max((top - a0) / (n - 1), 1e-3)
    if rng.random() < 0.04 and top > a0:
        da = (top - a0) * 1e-6  # a step typed in the wrong unit: a million steps, refused
    unit, f = ("kN", 1e-3) if rng.random() < 0.5 else ("N", 1.0)
    return {"speed": first["speed"], "radial_load": first["radial_load"],
            "step_duration": first["duration"],
            "axial_load_steps": {"start": _q(a0 * f, unit), "stop": _q((a0 + (n - 1) * da) * f,
                                                                      unit),
                                 "step": _q(da * f, unit)}}


def _pressure_law(rng: np.random.Generator) -> tuple[str, str]:
    """The ``[pressure_viscosity]`` table of a fuzz oil file and its tag: mostly Roelands
    with the ASME 1953 alpha fit (as the ISO VG presets), else a given alpha under Barus or
    Roelands (converted at a reference temperature, as OIL_4109) or a given Roelands z
    (alpha 1e-8 to 3.5e-8 1/Pa and z 0.4 to 0.9: the size of mineral oils and esters)."""
    r = rng.random()
    if r < 0.6:
        return 'law = "roelands"\nalpha_correlation = "asme1953_mineral_fit"', ""
    alpha = f'alpha = "{_log_uniform(rng, 1e-8, 3.5e-8):.3g} 1/Pa"'
    if r < 0.75:
        return f'law = "barus"\n{alpha}', "barus"
    if r < 0.9:
        ref = f'reference_temperature = "{rng.uniform(20.0, 100.0):.0f} degC"'
        return f'law = "roelands"\n{alpha}\n{ref}', "alpha"
    return f'law = "roelands"\nz = {rng.uniform(0.4, 0.9):.3f}', "z"


def _oil_file(rng: np.random.Generator, path: Path) -> tuple[dict[str, Any], str]:
    """A mineral-oil lubricant TOML of an ISO VG grade outside the presets (VG 2 to 1500),
    laid out as ``configs/lubricants/ISO_VG100.toml``: the scene's ``[lubricant] path``;
    its pressure law from :func:`_pressure_law` (tag after the grade: ``VG5z``)."""
    grade = int(rng.choice(sorted(EXTREME_GRADES)))
    law, tag = _pressure_law(rng)
    path.write_text(f'''name = "ISO_VG{grade}_fuzz"
source = "fuzz input: ISO VG {grade} mineral oil of about VI 95"
kind = "mineral"

[viscosity]
law = "astm_d341"
nu40 = "{grade} mm**2/s"
nu100 = "{EXTREME_GRADES[grade]} mm**2/s"

[pressure_viscosity]
{law}

[density]
value = "{rng.uniform(840.0, 910.0):.0f} kg/m**3"
reference_temperature = "15 degC"
temperature_law = "astm_d1250_lube"
pressure_law = "dowson_higginson"

[thermal]
model = "cragoe"
''', encoding="utf-8")
    return {"path": str(path)}, f"VG{grade}{tag}"


#: other spellings of the generator's units: (unit, factor, offset) with value' = value *
#: factor + offset
RESPELL = {
    "degC": [("K", 1.0, 273.15), ("degF", 1.8, 32.0)],
    "N": [("kN", 1e-3, 0.0), ("lbf", 1 / 4.4482216152605, 0.0)],
    "rpm": [("r/min", 1.0, 0.0), ("rad/s", math.pi / 30, 0.0), ("rev/s", 1 / 60, 0.0),
            ("krpm", 1e-3, 0.0)],
    "L/min": [("L/h", 60.0, 0.0), ("m**3/s", 1 / 60000, 0.0), ("mL/min", 1e3, 0.0)],
    "mm": [("m", 1e-3, 0.0), ("cm", 0.1, 0.0), ("inch", 1 / 25.4, 0.0)],
    "s": [("min", 1 / 60, 0.0), ("ms", 1e3, 0.0)],
    "mm**3/h": [("mm3/h", 1.0, 0.0), ("mL/h", 1e-3, 0.0)],
}
#: valid but unusual spellings of the same units (pint names, symbols, exponents written
#: with ^ or as a product with a negative power, another case of the prefix word): (unit,
#: factor, offset) as in RESPELL
ODD_SPELLINGS = {
    "degC": [("°C", 1.0, 0.0), ("celsius", 1.0, 0.0), ("degree_Celsius", 1.0, 0.0),
             ("kelvin", 1.0, 273.15), ("°F", 1.8, 32.0), ("fahrenheit", 1.8, 32.0)],
    "N": [("newton", 1.0, 0.0), ("kilonewton", 1e-3, 0.0), ("MN", 1e-6, 0.0),
          ("kgf", 1 / 9.80665, 0.0), ("daN", 0.1, 0.0)],
    "rpm": [("rev/min", 1.0, 0.0), ("revolution/minute", 1.0, 0.0), ("turn/min", 1.0, 0.0),
            ("rps", 1 / 60, 0.0), ("r/s", 1 / 60, 0.0), ("deg/s", 6.0, 0.0),
            ("rad/min", 2 * math.pi, 0.0)],
    "L/min": [("l/min", 1.0, 0.0), ("dm^3/min", 1.0, 0.0), ("liter/minute", 1.0, 0.0),
              ("L min^-1", 1.0, 0.0), ("cm**3/s", 1000 / 60, 0.0), ("litre/hour", 60.0, 0.0),
              ("m^3/h", 0.06, 0.0)],
    "mm": [("µm", 1e3, 0.0), ("μm", 1e3, 0.0), ("micrometer", 1e3, 0.0),
           ("millimeter", 1.0, 0.0), ("in", 1 / 25.4, 0.0), ("dm", 0.01, 0.0)],
    "s": [("sec", 1.0, 0.0), ("second", 1.0, 0.0), ("minutes", 1 / 60, 0.0),
          ("hr", 1 / 3600, 0.0), ("h", 1 / 3600, 0.0)],
    "mm**3/h": [("mm^3/h", 1.0, 0.0), ("mm³/h", 1.0, 0.0), ("µL/h", 1.0, 0.0),
                ("mm**3/min", 1 / 60, 0.0)],
    "W/(m**2*K)": [("W/m^2/K", 1.0, 0.0), ("W m^-2 K^-1", 1.0, 0.0),
                   ("W/(m²·K)", 1.0, 0.0), ("kW/(m**2*K)", 1e-3, 0.0)],
    "MPa": [("GPa", 1e-3, 0.0), ("N/mm**2", 1.0, 0.0), ("N/mm^2", 1.0, 0.0)],
}
_QTY = re.compile(r"^([-+]?[0-9.]+(?:e[-+]?\d+)?) (\S+)$")


def _number_text(rng: np.random.Generator, value: float) -> tuple[str, str]:
    """``value`` in one of the number forms a scene may write, and the separator to put
    before the unit: ``1500``, ``1.5e3`` / ``1.5E+03``, ``+1500``, ``.5`` (no leading
    zero), ``1500.`` (a trailing point), or no space before the unit (``1500rpm``)."""
    text = f"{value:.12g}"
    r = rng.random()
    if r < 0.15:
        text = f"{value:.9e}" if rng.random() < 0.5 else f"{value:.9E}"
    elif r < 0.25 and value > 0:
        text = "+" + text
    elif r < 0.35 and 0 < abs(value) < 1 and text.startswith(("0.", "-0.")):
        text = text.replace("0.", ".", 1)
    elif r < 0.42 and "." not in text and "e" not in text:
        text += "."
    return text, ("" if rng.random() < 0.15 else " ")


def respell(rng: np.random.Generator, doc: Any, share: float = 0.5, odd: float = 0.0) -> Any:
    """A copy of the scene document with about ``share`` of its quantities written in
    another unit (K / degF, kN / lbf, rad/s / rev/s / krpm, L/h, m, inch, min ...): the
    same scene, which must load to the same SI values. ``odd``: the share of those written
    in an unusual but valid spelling (ODD_SPELLINGS: ``°C``, ``kilonewton``, ``rev/min``,
    ``dm^3/min``, ``µm``, ``hr``, ``W m^-2 K^-1``...) and number form (``1.5E+03``,
    ``+1500``, ``.5``, ``1500.``, ``1500rpm``)."""
    if isinstance(doc, dict):
        return {k: respell(rng, v, share, odd) for k, v in doc.items()}
    if isinstance(doc, list):
        return [respell(rng, v, share, odd) for v in doc]
    if isinstance(doc, str):
        m = _QTY.match(doc)
        unit = m.group(2) if m else ""
        if m and (unit in RESPELL or unit in ODD_SPELLINGS) and rng.random() < share:
            if unit in ODD_SPELLINGS and rng.random() < odd:
                opts = ODD_SPELLINGS[unit]
                new, f, off = opts[int(rng.integers(0, len(opts)))]
                text, gap = _number_text(rng, float(m.group(1)) * f + off)
                return f"{text}{gap}{new}"
            if unit in RESPELL:
                opts = RESPELL[unit]
                new, f, off = opts[int(rng.integers(0, len(opts)))]
                return f"{float(m.group(1)) * f + off:.12g} {new}"
    return doc


def si_mismatch(plain: Any, spelled: Any) -> str | None:
    """Where two loaded scenes (the same quantities in other units) differ in SI values:
    the schedule's steps, supply, environment, output interval and solver chunk."""
    pairs: list[tuple[str, Any, Any]] = [
        ("supply.flow", plain.supply.flow, spelled.supply.flow),
        ("supply.inlet_temperature", plain.supply.inlet_temperature,
         spelled.supply.inlet_temperature),
        ("supply.level", plain.supply.level, spelled.supply.level),
        ("environment.ambient_temperature", plain.environment.ambient_temperature,
         spelled.environment.ambient_temperature),
        ("environment.initial_temperature", plain.environment.initial_temperature,
         spelled.environment.initial_temperature),
        ("outputs.interval", plain.outputs.interval, spelled.outputs.interval)]
    if len(plain.schedule.steps) != len(spelled.schedule.steps):
        return (f"schedule: {len(plain.schedule.steps)} steps, respelled "
                f"{len(spelled.schedule.steps)}")
    for i, (a, b) in enumerate(zip(plain.schedule.steps, spelled.schedule.steps,
                                   strict=True)):
        for key in ("duration", "speed", "radial_load", "axial_load"):
            pairs.append((f"schedule step {i} {key}", getattr(a, key), getattr(b, key)))
    for where, a, b in pairs:
        if (a is None) != (b is None) or (
                a is not None and not math.isclose(a, b, rel_tol=1e-7)):
            return f"{where}: {a!r} SI, respelled {b!r}"
    return None


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
    edge = _edge_step(rng, steps) if rng.random() < 0.05 else ""
    cold = rng.random() < 0.12
    hot = not cold and rng.random() < 0.07
    if cold:
        # a cold start: machine, oil and air below freezing, then the schedule's speeds
        amb = float(rng.uniform(*COLD_RANGE))
        supply["inlet_temperature"] = _q(amb + rng.uniform(0.0, 5.0), "degC", 4)
    elif hot:
        # a hot machine (a turbine or gearbox oil near its limit)
        amb = float(rng.uniform(*HOT_RANGE))
        supply["inlet_temperature"] = _q(float(rng.uniform(*HOT_RANGE)), "degC", 4)
    else:
        amb = float(rng.uniform(-20.0, 120.0))
    env: dict[str, Any] = {"ambient_temperature": _q(amb, "degC", 4)}
    if cold or hot or rng.random() < 0.6:
        env["initial_temperature"] = _q(
            amb if cold else rng.uniform(*HOT_RANGE) if hot else rng.uniform(-20.0, 120.0),
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
    form = rng.random()
    axial_ok = not roller or (rib is not None and kin == "race_control")
    if files is not None and form < 0.15:
        schedule = _schedule_file(rng, steps, files.with_name(files.name + "_protocol.csv"))
    elif form < 0.23 and len(steps) == 1:
        # the step as the [schedule] defaults (no steps array)
        st = steps[0]
        schedule = {"speed": st["speed"], "radial_load": st["radial_load"],
                    "axial_load": st["axial_load"], "step_duration": st["duration"]}
    elif form < 0.33 and axial_ok:
        schedule = _axial_load_steps(rng, steps, c0, roller)
    lubricant: dict[str, Any] = {"preset": str(rng.choice(lubricants))}
    oil = ""
    if files is not None and rng.random() < 0.12:
        lubricant, oil = _oil_file(rng, files.with_name(files.name + "_oil.toml"))
    doc: dict[str, Any] = {
        "title": "fuzz case",
        "bearings": bearings,
        "lubricant": lubricant,
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
                              ("rib", rib is not None), ("cold", cold), ("hot", hot),
                              ("file", "file" in schedule),
                              ("dflt", "step_duration" in schedule
                               and "axial_load_steps" not in schedule),
                              ("asteps", "axial_load_steps" in schedule),
                              ("meas", "measured" in doc)) if on]
    if edge:
        extras.append(edge)
    if oil:
        extras.append(oil)
    extras += _options(rng, doc, picks, kin)
    if rng.random() < 0.2:
        # the same scene in other units: must load to the same SI values (si_mismatch)
        from thermobearing.scene import dumps_toml

        desc["plain"] = dumps_toml(doc)
        odd = rng.random() < 0.5
        doc = respell(rng, doc, odd=0.7 if odd else 0.0)
        extras.append("oddunits" if odd else "units")
    if "file" in schedule:
        # the protocol's steps as written inline: the file must read to the same steps
        from thermobearing.scene import dumps_toml

        # (a column left to the [schedule] defaults takes the first step's value)
        kept = {("duration" if k == "step_duration" else k): v for k, v in schedule.items()
                if k != "file"}
        desc["inline"] = dumps_toml({**doc, "schedule": {"steps": [{**st, **kept}
                                                                   for st in steps]}})
    desc["extras"] = ",".join(extras)
    return doc, desc


def steps_mismatch(inline: Any, scene: Any, rel: float = 2e-5) -> str | None:
    """Where the scene's schedule steps (read from its protocol file) differ from those of
    ``inline`` (the same steps written in the TOML) beyond ``rel`` (the file's cells have
    six significant digits), or None."""
    a, b = inline.schedule.steps, scene.schedule.steps
    if len(a) != len(b):
        return f"schedule file: {len(b)} steps, written {len(a)}"
    for i, (x, y) in enumerate(zip(a, b, strict=True)):
        for key in ("duration", "speed", "radial_load", "axial_load"):
            u, v = getattr(x, key), getattr(y, key)
            if not math.isclose(u, v, rel_tol=rel, abs_tol=1e-9):
                return f"schedule file row {i + 1} {key}: read {v!r} SI, written {u!r}"
    return None


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
    if kin != "none" and rng.random() < 0.1:
        models["calibration"] = "none"
        drawn.append("nocal")
    if (kin != "none" and all(e.kind != "cylindrical" for e in picks)
            and rng.random() < 0.12):
        # the EHL rolling force in the ball balance (a plain name or with a reduction)
        red = str(rng.choice(["none", "thermal", "skf", "thermal_starvation"]))
        models["ball_rolling_resistance"] = ("harris" if rng.random() < 0.4
                                             else {"model": "harris", "reduction": red})
        drawn.append("rr")
    if "solver" in doc and rng.random() < 0.15:
        doc["solver"].update({"rtol": float(f"{_log_uniform(rng, 1e-8, 1e-3):.2g}"),
                              "atol": float(f"{_log_uniform(rng, 1e-7, 1e-2):.2g}"),
                              "kinematics_tolerance": round(float(rng.uniform(0.005, 0.3)),
                                                            3),
                              "max_step": _q(_log_uniform(rng, 1.0, 600.0), "s")})
        drawn.append("tol")
    if rng.random() < 0.1:
        checks = {"skid_limit": _q(rng.uniform(0.5, 20.0), "%", 3),
                  "contact_stress_limit": _q(rng.uniform(1500.0, 4500.0), "MPa", 4),
                  "min_film_parameter": round(float(rng.uniform(0.5, 3.0)), 2)}
        if rng.random() < 0.4:
            # a stress limit per bearing family (ISO 76: ball 4200, roller 4000 MPa)
            checks["contact_stress_limit"] = {
                fam: _q(rng.uniform(1500.0, 4500.0), "MPa", 4)
                for fam in ("ball", "roller") if rng.random() < 0.7} or {
                "ball": _q(4200.0, "MPa", 4)}
        if rng.random() < 0.4:  # only some of the thresholds
            for key in [str(k) for k in rng.permutation(list(checks))][:2]:
                checks.pop(key)
        doc["checks"] = checks
        drawn.append("checks")
    if kin != "none" and rng.random() < 0.12:
        # the bearings' own closed-form film named (the default written out), now and
        # then another one, which a scene refuses (models.film: race control and the film
        # table compute the kind's film whatever the scene names)
        balls = {e.kind != "cylindrical" for e in picks}
        own = {True: POINT_FILMS[0], False: LINE_FILMS[0]}
        if len(balls) == 1 and rng.random() < 0.75:
            models["film"] = own[balls.pop()]
        else:
            models["film"] = str(rng.choice(POINT_FILMS + LINE_FILMS))
        drawn.append("film")
    if kin != "none" and rng.random() < 0.12 and _source_option(
            rng, models, any(e.kind != "cylindrical" for e in picks)):
        drawn.append("srcopt")
    if "solver" in doc and rng.random() < 0.1:
        # the chunk repeat threshold, from eager (0.02) to hardly ever (3)
        doc["solver"]["chunk_viscosity_limit"] = float(f"{_log_uniform(rng, 0.02, 3.0):.2g}")
        drawn.append("cvl")
    return drawn


#: heat sources every bearing kind runs by default, whose documented numeric options
#: (registry ``limits``) :func:`_source_option` draws
OPTION_SOURCES = ("cage_guide", "churning_cage", "churning_elements", "churning_inner_ring",
                  "pocket_friction", "raceway_traction")


#: heat-source options the ball kinematics set to match their force models
#: (kinematic_models._ball_heat_options): a scene's own value for them is refused
BALL_SET_OPTIONS = {"raceway_traction": ("n_major", "n_minor"),
                    "churning_elements": ("drag_coefficient", "oil_fraction", "oil_swirl"),
                    "churning_cage": ("oil_fraction",), "churning_inner_ring": ("oil_fraction",),
                    "cage_guide": ("cage_share",), "pocket_friction": ("friction_coefficient",)}


def _source_option(rng: np.random.Generator, models: dict[str, Any], ball: bool = False
                   ) -> bool:
    """One documented numeric parameter of a default heat source in ``[models]
    heat_source_options``, drawn inside its registry interval (an end now and then), one in
    twelve outside it (for the refusal's message): a friction coefficient, a gap, an oil
    fraction, a share, the traction grid. With ball bearings (``ball``) mostly not one that
    the ball kinematics set themselves (BALL_SET_OPTIONS: refused, as a clash, by the run).
    False when no source fits (a listed heat_sources without any of them)."""
    from thermobearing.heat_sources import HEAT_SOURCES

    listed = models.get("heat_sources")
    names = [n for n in OPTION_SOURCES if listed is None or n in listed]
    if not names:
        return False
    src = str(rng.choice(names))
    entry = HEAT_SOURCES.entry(src)
    skip = BALL_SET_OPTIONS.get(src, ()) if ball and rng.random() < 0.9 else ()
    keys = sorted(k for k in entry.limits if entry.parameters.get(k) in ("-", "m", "N")
                  and k not in skip)
    if not keys:
        return False
    key = str(rng.choice(keys))
    lim, unit = entry.limits[key], entry.parameters[key]
    if rng.random() < 1 / 12:
        value = lim.low - 0.5 if math.isfinite(lim.low) and lim.low > 0 else (
            -0.1 if lim.low == 0 else lim.high + 1.0)
    elif math.isfinite(lim.high):
        r = rng.random()
        value = lim.low if r < 0.1 and lim.low_closed else (
            lim.high if r < 0.2 and lim.high_closed else float(rng.uniform(lim.low, lim.high)))
        if key.startswith("n_"):
            value = float(round(min(value, 64.0)))  # the traction grid: whole numbers
    else:
        value = _log_uniform(rng, 1e-7, 1e-3) if unit == "m" else _log_uniform(rng, 1e-2, 1e4)
    text: Any = (_q(value * 1e6, "um") if unit == "m" else _q(value, "N") if unit == "N"
                 else float(f"{value:.4g}"))
    opts = models.setdefault("heat_source_options", {})
    opts.setdefault(src, {})[key] = text
    return True


def _rpm_of(text: Any) -> float:
    """A step's speed [r/min] from its text (0 when it is none or not positive)."""
    from thermobearing.units import to_si

    try:
        return max(to_si(text, "angular_speed") * 30.0 / math.pi, 0.0)
    except Exception:  # noqa: BLE001 -- a malformed speed (an edge draw): no rpm
        return 0.0


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
    untouched = float(row.get("max load [N]", 1.0)) == 0.0
    if table == "film" and (at_rest or untouched) and column in (
            "central film [um]", "film parameter [-]", "closed-form central film [um]"):
        return True  # no film at rest, none on a raceway no element touches (0 N)
    return False


def _zero_pressure_under_load(df: Any, rollers: frozenset[str] = frozenset()) -> str | None:
    """A loaded, turning or resting bearing whose kinematics row gives 0 MPa (a number
    where the model computed no contact). A roller bearing (``rollers``: their names) under
    an axial load alone carries it on its ribs, not its raceways: 0 MPa there at rest is
    the raceways' true pressure."""
    need = ("max contact pressure [MPa]", "radial load [kN]", "axial load [kN]")
    if df is None or not all(c in df for c in need):
        return None
    axial_on_raceways = ~df["bearing"].isin(list(rollers)) if "bearing" in df \
        else True
    loaded = (df["radial load [kN]"] > 0) | ((df["axial load [kN]"] > 0) & axial_on_raceways)
    bad = df[loaded & (df["max contact pressure [MPa]"] == 0.0)]
    if bad.empty:
        return None
    r = bad.iloc[0]
    return (f"kinematics[max contact pressure [MPa]] = 0 under {r['radial load [kN]']:.4g} "
            f"kN radial, {r['axial load [kN]']:.4g} kN axial (bearing {r['bearing']})")


def check_results(results: Any, no_contacts_model: bool = False,
                  rollers: frozenset[str] = frozenset()) -> list[str]:
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
            if col in NONNEGATIVE_COLUMNS and np.any(arr < -1e-12):
                problems.append(f"{name}[{col}] negative: {np.nanmin(arr):.6g}")
            if col == "cage speed ratio [-]" and np.any(arr > 1.0 + 1e-9):
                # the cage runs between a still outer ring (0) and the shaft (1)
                problems.append(f"{name}[{col}] above 1: {np.nanmax(arr):.6g}")
    zero = _zero_pressure_under_load(results.tables.get("kinematics"), rollers)
    if zero:
        problems.append(zero)
    for w in results.warnings:
        why = garbled(str(w))
        if why:
            problems.append(f"garbled warning ({why}): {str(w)[:200]}")
    return problems


#: table columns of quantities that cannot be negative (films, film parameters, contact
#: pressures, the cage speed ratio: the cage turns with the shaft, never against it)
NONNEGATIVE_COLUMNS = frozenset({
    "min film parameter [-]", "max contact pressure [MPa]", "central film [um]",
    "film parameter [-]", "closed-form central film [um]", "cage speed ratio [-]",
    "theoretical cage speed ratio [-]", "minimum film [um]"})


@dataclass
class Case:
    index: int
    desc: dict[str, str]
    toml: str
    outcome: str = ""
    message: str = ""
    seconds: float = 0.0
    notes: list[str] = field(default_factory=list)
    plain: str = ""  # the scene before respell() (its SI values must be the same)
    inline: str = ""  # a protocol file's steps written inline (they must read the same)
    #: a user-made mutant (its measured file was written for the scene before the change)
    mutant: bool = False


#: the table each wanted output gives, by outputs.mode ("report" gives none)
WANTED_TABLES = {"film": ("film", "film"), "kinematics": ("kinematics", "kinematics"),
                 "losses": ("losses", "losses"),
                 "temperatures": ("temperatures", "steady_temperatures"),
                 "energy": ("energy", None)}


def missing_tables(scene: Any, results: Any) -> list[str]:
    """Wanted outputs whose table is missing without a warning that starts
    ``outputs.want`` and names it (a steady run's 'energy' says why it has none)."""
    out = []
    for want in scene.outputs.want:
        transient, steady = WANTED_TABLES.get(want, (None, None))
        table = transient if scene.outputs.mode == "transient" else steady
        if want not in WANTED_TABLES or table in results.tables:
            continue
        if not any(str(w).startswith("outputs.want") and want in str(w)
                   for w in results.warnings):
            out.append(f"outputs.want holds {want}: no {table or want} table and no word why")
    return out


def first_difference(a: Any, b: Any, where: str = "scene", rel: float = 1e-9) -> str | None:
    """The first place where two scenes differ (dataclass fields, mappings, sequences;
    floats beyond ``rel`` relative: a scene's TOML writes 12 significant digits), or None."""
    if dataclasses.is_dataclass(a) and type(a) is type(b):
        for f in dataclasses.fields(a):
            if f.compare:
                d = first_difference(getattr(a, f.name), getattr(b, f.name),
                                     f"{where}.{f.name}", rel)
                if d:
                    return d
        return None
    if isinstance(a, dict) and isinstance(b, dict):
        if set(a) != set(b):
            return f"{where}: keys {sorted(a)} != {sorted(b)}"
        for k in a:
            d = first_difference(a[k], b[k], f"{where}[{k!r}]", rel)
            if d:
                return d
        return None
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        if len(a) != len(b):
            return f"{where}: {len(a)} items != {len(b)}"
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            d = first_difference(x, y, f"{where}[{i}]", rel)
            if d:
                return d
        return None
    if (isinstance(a, float) and isinstance(b, float)
            and (math.isclose(a, b, rel_tol=rel) or (math.isnan(a) and math.isnan(b)))):
        return None
    return None if a == b else f"{where}: {a!r} != {b!r}"


def measured_mismatch(scene: Any) -> str | None:
    """The generator's measured file read back (``read_scene_measured``: its separators,
    decimal commas, time format, unit, dropouts) against the warm-up it was written from,
    t0 + 20 K (1 - exp(-t / 600 s)) with 0.2 K noise (t0 the initial temperature):
    where a reading is more than 1.5 K off, or a time runs backwards; None when it fits."""
    from thermobearing.measured import read_scene_measured

    df = read_scene_measured(scene)
    if df is None:
        return None
    t = df["time [s]"].to_numpy(dtype=float)
    if len(t) and (t[0] < -1.0 or np.any(np.diff(t) <= 0.0)):
        return f"measured times {t[:4].tolist()}... (from 0 s, increasing)"
    expect = scene.environment.initial_temperature - 273.15 + 20.0 * (1.0 - np.exp(-t / 600))
    for col in df.columns:
        if col == "time [s]":
            continue
        v = df[col].to_numpy(dtype=float)
        ok = np.isfinite(v)
        if ok.any() and np.max(np.abs(v[ok] - expect[ok])) > 1.5:
            i = int(np.flatnonzero(ok)[np.argmax(np.abs(v[ok] - expect[ok]))])
            return (f"measured column {col!r} reads {v[i]:.4g} at t = {t[i]:.4g} s, the file "
                    f"holds {expect[i]:.4g} degC ({scene.measured.unit})")
    return None


def check_scene(scene: Any, raises: bool = False) -> str | None:
    """What ``thermobearing check`` does with the scene (model names, preflight, the chain
    with citations, the estimates, the measured file), in this process: None when it
    passes, the refusal's text when it refuses (with ``raises``: the refusal itself, for
    the caller to classify; any other exception escapes as the case's defect)."""
    from thermobearing.commands._preflight import preflight
    from thermobearing.commands.check import describe_measured
    from thermobearing.errors import ConvergenceError, InputError
    from thermobearing.scene_checks import check_global_friction, check_model_names
    from thermobearing.simulation import Simulation

    try:
        check_model_names(scene)
        sim = Simulation(scene, progress=False)
        preflight(sim)
        check_global_friction(sim)
        text = sim.describe_chain(with_citations=True) + (sim.describe_estimates() or "")
        if scene.measured is not None:
            text += describe_measured(scene)
    except (InputError, ConvergenceError) as exc:
        if raises:
            raise
        return str(exc)
    why = garbled(text)
    if why:
        return f"garbled check text ({why}): {text[:300]}"
    return None


def _roller_names(scene: Any) -> frozenset[str]:
    """Names of the scene's roller bearings."""
    from thermobearing.geometry import load_bearing

    names = set()
    for spec in scene.bearings:
        b = load_bearing(spec.preset or str(scene.resolve_path(spec.path)),
                         overrides=spec.overrides or None)
        if not hasattr(b, "ball_diameter"):
            names.add(spec.name)
    return frozenset(names)


def _run_here(case: Case) -> None:
    """Load and run the case's scene in this process; fill its outcome."""
    from thermobearing.scene import loads_scene
    from thermobearing.simulation import Simulation

    t0 = time.process_time()
    refused: str | None = "not checked"
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            scene = loads_scene(case.toml, base_dir=ROOT)
            mismatch = (si_mismatch(loads_scene(case.plain, base_dir=ROOT), scene)
                        if case.plain else None)
            if mismatch:
                case.outcome, case.message = "DEFECT", f"units: {mismatch}"
                return
            misread = (steps_mismatch(loads_scene(case.inline, base_dir=ROOT), scene)
                       if case.inline else None)
            if misread:
                case.outcome, case.message = "DEFECT", misread
                return
            differs = first_difference(scene, loads_scene(scene.to_toml(), base_dir=ROOT))
            if differs:
                case.outcome, case.message = "DEFECT", (
                    f"round trip: loads_scene(scene.to_toml()) differs at {differs}")
                return
            refused = check_scene(scene)
            misread = (measured_mismatch(scene) if refused is None and not case.mutant
                       else None)
            if misread:
                case.outcome, case.message = "DEFECT", misread
                return
            results = Simulation(scene, progress=False).run()
        if refused is not None:
            case.outcome, case.message = "DEFECT", f"check refuses what runs: {refused}"
            return
        problems = check_results(results, scene.models.get("kinematics") == "none",
                                 _roller_names(scene))
        problems += missing_tables(scene, results)
        leaked = sorted({f"{w.category.__name__}: {w.message}" for w in caught
                         if not issubclass(w.category, DeprecationWarning)})
        case.notes.extend(leaked)
        if problems:
            case.outcome, case.message = "DEFECT", "; ".join(problems)
        else:
            case.outcome = "OK"
    except Exception as exc:  # noqa: BLE001 -- every failure is classified
        case.outcome, case.message = classify_error(exc)
        from thermobearing.errors import InputError

        if (case.outcome == "REFUSED" and isinstance(exc, InputError)
                and refused is None):
            # `thermobearing check` passed a scene whose run refuses its input: a check gap
            # when the input is known before any solve (a missing model option)
            case.notes.append(f"check passed, run refused: {case.message[:140]}")
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


def _cli(args: list[str], timeout: float) -> subprocess.CompletedProcess[str] | None:
    """``thermobearing ARGS`` in a subprocess (None: over the time limit)."""
    try:
        return subprocess.run([sys.executable, "-m", "thermobearing.cli", *args],
                              capture_output=True, text=True, timeout=timeout, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return None


def _cli_failure(proc: subprocess.CompletedProcess[str]) -> str | None:
    """A command's exit that is a defect: not 0 and not 1 with an ``error:`` line (a
    traceback, a crash); None otherwise."""
    err = proc.stderr.strip().splitlines()
    if proc.returncode == 0 or (proc.returncode == 1 and any("error:" in ln for ln in err)):
        return None
    return f"exit {proc.returncode}: {' | '.join(err[-3:])}"


def run_cli(case: Case, out_dir: Path, time_limit: float) -> None:
    """``thermobearing check SCENE``, ``thermobearing run SCENE --out DIR --quiet`` and
    ``thermobearing report DIR``: exit 0 (a run with a report), or 1 with an error line;
    anything else (a traceback, a missing report, a check that refuses what runs or a run
    that refuses what the API ran) is a defect."""
    scene_path = out_dir / f"case_{case.index:04d}.toml"
    # the scene as editors save it: UTF-8, now and then with a byte-order mark or UTF-16
    r = (case.index * 7919 % 100) / 100.0
    scene_path.write_text(("\ufeff" if 0.6 <= r < 0.8 else "") + case.toml,
                          encoding="utf-16" if r >= 0.95 else "utf-8")
    target = out_dir / f"case_{case.index:04d}_run"
    check = _cli(["check", str(scene_path)], time_limit)
    if check is not None and _cli_failure(check):
        case.outcome, case.message = "DEFECT", f"cli check {_cli_failure(check)}"
        return
    proc = _cli(["run", str(scene_path), "--out", str(target), "--quiet"], time_limit + 30)
    if proc is None:
        case.notes.append("cli: time limit")
        return
    err = proc.stderr.strip().splitlines()
    if proc.returncode == 0:
        if not (target / "report.html").is_file():
            case.outcome, case.message = "DEFECT", "cli: exit 0 without report.html"
            return
        if check is not None and check.returncode != 0:
            case.outcome, case.message = "DEFECT", (
                f"cli check refused what runs: {check.stderr.strip().splitlines()[-1]}")
            return
        (target / "report.html").unlink()
        rep = _cli(["report", str(target)], time_limit)
        if rep is not None and (rep.returncode != 0 or not (target / "report.html").is_file()):
            case.outcome, case.message = "DEFECT", (
                f"cli report of a finished run: {_cli_failure(rep) or rep.stderr[-300:]}")
    elif proc.returncode == 1 and any("error:" in line for line in err):
        if case.outcome == "OK":
            case.outcome, case.message = "DEFECT", f"cli refused what the API ran: {err[-1]}"
        elif (target / "metadata.json").is_file():
            # a stopped run's folder: its report must still be written (the CLI says so)
            rep = _cli(["report", str(target)], time_limit)
            if rep is not None and (rep.returncode != 0
                                    or not (target / "report.html").is_file()):
                case.outcome, case.message = "DEFECT", (
                    f"cli report of a stopped run: {_cli_failure(rep) or rep.stderr[-300:]}")
    else:
        case.outcome = "DEFECT"
        case.message = f"cli exit {proc.returncode}: {' | '.join(err[-3:])}"


def sweep_options(rng: np.random.Generator, doc: dict[str, Any]) -> list[str]:
    """The ``--set PATH=VALUES`` candidates for the scene, two values each: bare numbers
    in the scene's own unit of the field (now and then with ten significant digits, which
    the sweep must keep), a range ``start:stop:step``, values with their unit, or presets
    and lubricant files."""
    options: list[str] = []
    sup = doc.get("supply", {})

    def num(text: str) -> float:
        m = _NUM_UNIT.match(text)
        return float(m.group(1)) if m else float(text.split()[0])

    def fmt(x: float) -> str:
        return f"{x:.10g}" if rng.random() < 0.3 else f"{x:.6g}"

    if "flow" in sup and num(sup["flow"]) > 0:
        f = num(sup["flow"]) * float(rng.uniform(0.9, 1.1))
        options.append(f"supply.flow={fmt(f * 0.5)},{fmt(f * 2.0)}")
    if "inlet_temperature" in sup:
        t = num(sup["inlet_temperature"])
        options.append(f"supply.inlet_temperature={fmt(t)},{fmt(t + 10.0)}"
                       if rng.random() < 0.7 else
                       f"supply.inlet_temperature={fmt(t)}:{fmt(t + 10.0)}:10")
    if "level" in sup:
        options.append(f"supply.level={fmt(num(sup['level']) * 0.5)},{fmt(num(sup['level']))}")
    sched = doc.get("schedule", {})
    steps = sched.get("steps") or ([sched] if "speed" in sched else [])
    if steps and "speed" in steps[0]:
        v = num(steps[0]["speed"])
        options.append(f"schedule.speed={fmt(v)},{fmt(v * 1.5 + 1.0)}")
    if steps and "radial_load" in steps[0]:
        options.append(f"schedule.radial_load={fmt(num(steps[0]['radial_load']))},"
                       f"{fmt(num(steps[0]['radial_load']) * 1.3 + 1.0)}")
    amb = doc.get("environment", {}).get("ambient_temperature")
    if amb is not None:
        options.append(f"environment.ambient_temperature={fmt(num(amb))} degC,"
                       f"{fmt(num(amb) + 15.0)} degC" if "degC" in amb else
                       f"environment.ambient_temperature={fmt(num(amb))},{fmt(num(amb) + 15)}")
    two = [str(x) for x in rng.choice(lubricant_names(), 2, replace=False)]
    if "preset" in doc.get("lubricant", {}):
        options.append("lubricant.preset=" + ",".join(two))
    # lubricant files in place of the scene's preset or file (a preset's own TOML)
    options.append("lubricant.path=" + ",".join(
        str(ROOT / "configs" / "lubricants" / f"{n}.toml") for n in two))
    options.append(f"checks.skid_limit={rng.uniform(0.5, 5):.3g},{rng.uniform(5, 20):.3g}")
    if "network" in doc:
        options.append(f"network.parameters.h_oil={_log_uniform(rng, *H_OIL_RANGE):.4g},"
                       f"{_log_uniform(rng, *H_OIL_RANGE):.4g}")
        options.append(f"network.parameters.h_air={_log_uniform(rng, *H_AIR_RANGE):.4g},"
                       f"{_log_uniform(rng, *H_AIR_RANGE):.4g} W/(m**2*K)")
    return options


def sweep_sets(rng: np.random.Generator, doc: dict[str, Any]) -> list[str]:
    """One to three ``--set`` of different paths (a cartesian product of up to 8 cases;
    never both lubricant.preset and lubricant.path), or [] when none fits."""
    options = sweep_options(rng, doc)
    if not options:
        return []
    k = min(len(options), int(rng.choice([1, 2, 3], p=[0.6, 0.3, 0.1])))
    out: list[str] = []
    for i in rng.permutation(len(options)):
        path = options[int(i)].split("=", 1)[0]
        if any(o.split("=", 1)[0] == path or (o.startswith("lubricant.")
                                              and path.startswith("lubricant."))
               for o in out):
            continue
        out.append(options[int(i)])
        if len(out) == k:
            break
    return out


#: a quantity's number and unit, with or without a space between ("1500rpm", "+.5 kN")
_NUM_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def _written_unit(doc: dict[str, Any], path: str) -> str | None:
    """The unit the scene document writes the swept field in (the first step's for
    ``schedule.*``), or None (a preset, a threshold the scene does not set)."""
    node: Any = doc
    if path.startswith("schedule."):
        sched = doc.get("schedule", {})
        node = (sched.get("steps") or [sched])[0]
        path = path.split(".", 1)[1]
    for key in path.split("."):
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    m = _NUM_UNIT.match(node) if isinstance(node, str) else None
    return m.group(2) if m and m.group(2) else None


def swept_values_kept(setting: str, column: Any) -> str | None:
    """Where the sweep's summary column of ``setting`` (bare numbers, a comma list) holds
    a value other than the one given (rounded: ``1.234567891`` read as ``1.23457``), or
    None. Ranges and texts are not compared."""
    path, raw = setting.split("=", 1)
    numbers = raw.split()[0] if raw.split() else raw
    if ":" in raw or not re.fullmatch(r"[-+0-9.eE,]+", numbers):
        return None
    given = sorted(float(x) for x in numbers.split(","))
    got = sorted(float(_NUM_UNIT.match(str(v)).group(1)) for v in column)
    if len(given) == len(got) and not all(math.isclose(a, b, rel_tol=1e-9)
                                          for a, b in zip(given, got, strict=True)):
        return f"{path} swept as {given}, the cases ran {got}"
    return None


def _unchanged_by_sweep(summary: Any, path: str, stderr: str) -> str | None:
    """A swept setting whose cases gave the same numbers in every result column, and that
    the sweep did not call unused (``"<path> is swept but not used"``): a setting ignored
    without a word, or one with no effect on these outputs (a skid limit changes only the
    flags; a flow or an inlet at rest changes nothing). Listed for a look, not a defect."""
    if (f"{path} is swept but not used" in stderr or len(summary) < 2
            or path.startswith("checks.")):
        return None  # a threshold changes the flags only, which may well stay the same
    if "mean total loss [W]" in summary and (summary["mean total loss [W]"] == 0.0).all():
        return None  # nothing turns (steps at rest): no setting changes a loss
    if ("mean total loss [W]" not in summary and "max over-skidding [%]" in summary
            and summary["max over-skidding [%]"].isna().all()):
        return None  # kinematics at rest (no skidding to give): the lubricant cannot tell
    cols = [c for c in summary.columns if c != "case" and c != path
            and not c.startswith(path + " [") and is_numeric_dtype(summary[c])
            and not is_bool_dtype(summary[c])]
    if not cols or not all(np.allclose(summary[c], summary[c].iloc[0], rtol=1e-12,
                                       atol=0.0, equal_nan=True) for c in cols):
        return None
    return (f"identical: the {len(summary)} cases gave the same {len(cols)} result "
            "columns, no note")


def run_sweep_cli(case: Case, out_dir: Path, time_limit: float, settings: list[str]
                  ) -> None:
    """``thermobearing sweep SCENE --set ... [--set ...] -j 1 --quiet --out DIR`` and
    ``thermobearing report DIR``: a finished sweep has a summary.csv whose mean total loss
    is a finite number >= 0 in every row, each swept field in the scene's unit with the
    values given; a refusal is exit 1 with an error line."""
    import pandas as pd

    scene_path = out_dir / f"case_{case.index:04d}.toml"
    scene_path.write_text(case.toml, encoding="utf-8")
    target = out_dir / f"case_{case.index:04d}_sweep"
    shown = " ".join(settings)
    args = ["sweep", str(scene_path)]
    for setting in settings:
        args += ["--set", setting]
    proc = _cli([*args, "-j", "1", "--quiet", "--out", str(target)],
                len(settings) * 2 * time_limit + 60)
    if proc is None:
        case.notes.append(f"sweep {shown}: time limit")
        return
    if _cli_failure(proc):
        case.outcome, case.message = "DEFECT", f"cli sweep {shown}: {_cli_failure(proc)}"
        return
    if proc.returncode != 0:
        case.notes.append(f"sweep {shown}: {proc.stderr.strip().splitlines()[-1][:200]}")
        return
    summary = pd.read_csv(target / "summary.csv")
    doc = tomllib.loads(case.toml)
    for setting in settings:
        path = setting.split("=", 1)[0]
        written = _written_unit(doc, path)
        if written and path in summary:
            from thermobearing.units import quantity_unit

            got = {_NUM_UNIT.match(str(v)).group(2) for v in summary[path]}
            # the same unit in another spelling ("r/min" is rpm) is no defect
            if {quantity_unit(f"1 {u}") for u in got} != {quantity_unit(f"1 {written}")}:
                case.outcome, case.message = "DEFECT", (
                    f"cli sweep {shown}: bare numbers of {path} read in {sorted(got)}, the "
                    f"scene writes it in {written!r}")
                return
        lost = swept_values_kept(setting, summary[path]) if path in summary else None
        if lost:
            case.outcome, case.message = "DEFECT", f"cli sweep {shown}: {lost}"
            return
    col = next((c for c in ("mean total loss [W]", "total loss [W]") if c in summary), "")
    if col and not (np.isfinite(summary[col]).all() and (summary[col] >= 0).all()):
        case.outcome, case.message = "DEFECT", (
            f"cli sweep {shown}: summary.csv {col} = {summary[col].tolist()}")
        return
    same = (_unchanged_by_sweep(summary, settings[0].split("=", 1)[0], proc.stderr)
            if len(settings) == 1 else None)
    if same:
        case.notes.append(f"sweep {shown}: {same}")
    rep = _cli(["report", str(target)], time_limit)
    if rep is not None and (rep.returncode != 0 or not (target / "report.html").is_file()):
        case.outcome, case.message = "DEFECT", (
            f"cli report of sweep {shown}: {_cli_failure(rep) or rep.stderr[-300:]}")
    else:
        case.notes.append(f"sweep {len(settings)} set(s): ok")


#: sampling rates of the generated vibration records [Hz] (DAQ cards and sound cards)
RATES = (5120.0, 10240.0, 12800.0, 20000.0, 25600.0, 48000.0, 51200.0)
#: kinds of generated vibration record: (tag, weight); "clean" has a cage-modulated
#: ball-pass impulse train well above the noise, the others are what rigs also record
SIGNAL_KINDS = (("clean", 0.35), ("weak", 0.15), ("noise", 0.1), ("const", 0.04),
                ("clipped", 0.08), ("short", 0.06), ("gaps", 0.1), ("slow", 0.06),
                ("aliased", 0.06))


def vibration_record(rng: np.random.Generator, spec: dict[str, Any], rpm: float,
                     path_stem: Path) -> tuple[Path, list[str], dict[str, Any]]:
    """A synthetic acceleration record for ``thermobearing cage-speed`` (a fuzz input, not
    a rig's: an outer-race ball-pass impulse train at Z f_cage, each impulse ringing at a
    resonance, its amplitude modulated at the cage frequency, in Gaussian noise), with the
    cage turning at (1 - slip) of the pure-rolling ratio 0.5 (1 - D cos(alpha) / d_m)
    (Harris and Kotzalas, Rolling Bearing Analysis, 5th ed., Vol. 1, Eq. 7.12). Kinds
    (SIGNAL_KINDS): also pure noise, a constant, a clipped, short, slow or aliased record,
    NaN dropouts. Written as CSV (time column, comma / semicolon with decimal commas / tab
    with a units row, or samples only), .npy, .npz or .wav. Returns the file, the extra
    arguments (``--rpm`` in some spelling, ``--fs`` where the file has no rate, ``--band``,
    ``--search``, ``--fill-gaps``) and what was generated (kind, csr, rate)."""
    from thermobearing.geometry import load_bearing

    b = load_bearing(spec.get("preset") or spec["path"])
    d = float(getattr(b, "ball_diameter", getattr(b, "roller_diameter", 0.0)))
    cos_a = math.cos(float(getattr(b, "contact_angle", 0.0) or 0.0))
    csr_th = 0.5 * (1.0 - d * cos_a / float(b.pitch_diameter))
    kind = str(rng.choice([k for k, _ in SIGNAL_KINDS],
                          p=np.array([w for _, w in SIGNAL_KINDS])
                          / sum(w for _, w in SIGNAL_KINDS)))
    if kind == "slow":
        rpm = _log_uniform(rng, 1.0, 60.0)
    fs = float(rng.choice(RATES))
    slip = float(rng.uniform(0.0, 0.15))
    fr = rpm / 60.0
    f_cage = csr_th * (1.0 - slip) * fr
    bpfo = int(b.n_elements) * f_cage
    if kind == "aliased":
        fs = max(200.0, float(round(bpfo * rng.uniform(0.8, 2.5))))
    # long enough for 3.5 to 8 revolutions of a cage at 0.3 of the pure-rolling ratio (the
    # analyser's lowest search, which asks for 3), up to 4e5 samples; "short" and "slow"
    # records fall short of it
    seconds = (_log_uniform(rng, 0.005, 0.05) if kind == "short"
               else float(rng.uniform(0.5, 4.0)) if kind == "slow"
               else min(max(float(rng.uniform(0.5, 4.0)),
                            float(rng.uniform(3.5, 8.0)) / (0.3 * csr_th * fr)), 4.0e5 / fs))
    n = max(int(seconds * fs), 8)
    t = np.arange(n) / fs
    x = rng.normal(0.0, 1.0, n)
    if kind not in ("noise", "const"):
        amp = (8.0 if kind != "weak" else 0.8) * float(rng.uniform(0.5, 2.0))
        hits = np.zeros(n)
        times = np.arange(0.0, n / fs, 1.0 / bpfo) if bpfo > 0 else np.zeros(0)
        idx = np.minimum((times * fs).astype(int), n - 1)
        np.add.at(hits, idx, amp * (1.0 + 0.6 * np.cos(2 * math.pi * f_cage * times)))
        f_res = float(rng.uniform(0.12, 0.35)) * fs
        k = np.arange(min(400, n))
        ring = np.exp(-k / (fs / f_res * rng.uniform(3.0, 15.0))) * np.sin(
            2 * math.pi * f_res * k / fs)
        x += np.convolve(hits, ring)[:n]
        x += 0.5 * np.sin(2 * math.pi * fr * t)  # the shaft's own line (unbalance)
    if kind == "const":
        x = np.full(n, float(rng.uniform(-1.0, 1.0)))
    if kind == "clipped":
        x = np.clip(x, -0.3 * np.max(np.abs(x)), 0.3 * np.max(np.abs(x)))
    x += float(rng.uniform(-2.0, 2.0))  # a DC offset (an ICP channel's bias)
    args: list[str] = []
    if kind == "gaps":
        for _ in range(int(rng.integers(1, 4))):
            i0 = int(rng.integers(0, n))
            x[i0:i0 + int(rng.integers(1, 8))] = np.nan
        if rng.random() < 0.6:
            args.append("--fill-gaps")
    fmt = str(rng.choice(["csv", "csv_semicolon", "tsv_units", "csv_bare", "npy", "npz",
                          "wav"], p=[0.25, 0.15, 0.1, 0.1, 0.15, 0.1, 0.15]))
    if fmt == "wav" and kind == "gaps":
        fmt = "npy"
    if fmt.startswith(("csv", "tsv")):
        path = path_stem.with_name(path_stem.name + ("_vib.tsv" if fmt == "tsv_units"
                                                      else "_vib.csv"))
        sep, dec = {"csv": (",", "."), "csv_semicolon": (";", ","), "tsv_units": ("\t", "."),
                    "csv_bare": (",", ".")}[fmt]
        cells = ["" if not np.isfinite(v) else f"{v:.6g}".replace(".", dec) for v in x]
        if fmt == "csv_bare":
            lines = ["acc [g]"] + cells
            args += ["--fs", str(rng.choice([f"{fs:g}", f"{fs / 1000:g} kHz"]))]
        else:
            lines = [sep.join(["time [s]", "acc [g]"])]
            if fmt == "tsv_units":
                lines.append(sep.join(["s", "g"]))
            lines += [sep.join([f"{ti:.9f}".replace(".", dec), c]) for ti, c in
                      zip(t, cells, strict=True)]
        path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    elif fmt == "npy":
        path = path_stem.with_name(path_stem.name + "_vib.npy")
        np.save(path, x)
        args += ["--fs", f"{fs:g}"]
    elif fmt == "npz":
        path = path_stem.with_name(path_stem.name + "_vib.npz")
        # the rate under either name, as a scalar or a one-element array
        rate = np.float64(fs) if rng.random() < 0.7 else np.array([fs])
        np.savez(path, **{"data" if rng.random() < 0.7 else "acceleration": x,
                          "sampling_rate" if rng.random() < 0.6 else "fs": rate})
    else:
        from scipy.io import wavfile

        path = path_stem.with_name(path_stem.name + "_vib.wav")
        peak = float(np.max(np.abs(x))) or 1.0
        wavfile.write(path, int(fs), (x / peak * 30000).astype(np.int16))
    r = rng.random()
    args += ["--rpm", (f"{rpm:.6g}" if r < 0.4 else f"{rpm:.6g} rpm" if r < 0.6
                       else f"{rpm / 60:.6g} Hz" if r < 0.8 else f"{rpm * math.pi / 30:.6g} rad/s")]
    if rng.random() < 0.1:
        lo = float(rng.uniform(0.05, 0.3)) * fs
        args += ["--band", f"{lo:.0f}", f"{lo + float(rng.uniform(0.05, 0.2)) * fs:.0f}"]
    if rng.random() < 0.1:
        args += ["--search", f"{rng.uniform(0.5, 0.9):.2f}", f"{rng.uniform(1.0, 1.2):.2f}"]
    return path, args, {"kind": kind, "csr": csr_th * (1.0 - slip), "fs": fs, "rpm": rpm}


def _finite_numbers(rec: Any, where: str = "") -> str | None:
    """The first NaN / inf number in a JSON record (where), or None."""
    if isinstance(rec, dict):
        for k, v in rec.items():
            bad = _finite_numbers(v, f"{where}.{k}" if where else str(k))
            if bad:
                return bad
    elif isinstance(rec, list):
        for i, v in enumerate(rec):
            bad = _finite_numbers(v, f"{where}[{i}]")
            if bad:
                return bad
    elif isinstance(rec, float) and not math.isfinite(rec):
        return f"{where} = {rec}"
    return None


def run_cage_cli(case: Case, rng: np.random.Generator, spec: dict[str, Any], rpm: float,
                 out_dir: Path, time_limit: float) -> None:
    """``thermobearing cage-speed FILE --bearing B --rpm ... --json`` on a generated record
    (:func:`vibration_record`): exit 0 with a JSON record of finite numbers, 3 (not
    detected) or 1 with an error line; anything else, or a NaN in the record, is a
    defect. A clean record read more than 3 % off the generated ratio is noted."""
    import json

    stem = out_dir / f"case_{case.index:04d}"
    path, args, made = vibration_record(rng, spec, rpm, stem)
    bearing = spec.get("preset") or spec["path"]
    plot = ["--plot", str(stem.with_name(stem.name + "_vib.png"))] if rng.random() < 0.2 \
        else ["--no-plot"]
    cmd = ["cage-speed", str(path), "--bearing", bearing, *args, *plot, "--json"]
    shown = " ".join(repr(a) if " " in a else a for a in cmd)
    proc = _cli(cmd, time_limit)
    if proc is None:
        case.notes.append(f"cage-speed ({made['kind']}): time limit")
        return
    err = proc.stderr.strip().splitlines()
    if proc.returncode == 3 or (proc.returncode == 1 and any("error:" in ln for ln in err)):
        case.notes.append(f"cage-speed {made['kind']}: exit {proc.returncode}"
                          + (f" {err[-1][:120]}" if proc.returncode == 1 else ""))
        return
    if proc.returncode != 0:
        case.outcome, case.message = "DEFECT", (
            f"cli {shown}: exit {proc.returncode}: {' | '.join(err[-3:])}")
        return
    try:
        rec = json.loads(proc.stdout)
    except ValueError:
        case.outcome, case.message = "DEFECT", f"cli {shown}: no JSON record: {proc.stdout[:200]}"
        return
    bad = _finite_numbers(rec)
    if bad:
        case.outcome, case.message = "DEFECT", f"cli {shown}: {bad}"
        return
    csr = next((rec[k] for k in ("csr", "cage_speed_ratio") if k in rec), None)
    if (made["kind"] == "clean" and isinstance(csr, float)
            and abs(csr / made["csr"] - 1.0) > 0.03):
        case.notes.append(f"cage-speed clean: CSR {csr:.4g}, generated {made['csr']:.4g}")
    else:
        case.notes.append(f"cage-speed {made['kind']}: exit 0")


#: calibration fits drawn for a scene with a [measured] table: --fit paths, and --x0 /
#: --bounds now and then (bare numbers are in the parameter's unit)
CALIBRATE_FITS = (("network.parameters.h_oil", "50:3000", "200"),
                  ("network.parameters.h_air", "2:100", "'15 W/(m**2*K)'"),
                  ("supply.inlet_temperature", "0:150", "40"),
                  ("network.parameters.h_oil,network.parameters.h_air", "", ""))


def run_calibrate_cli(case: Case, rng: np.random.Generator, out_dir: Path,
                      time_limit: float) -> None:
    """``thermobearing calibrate SCENE --fit ... --max-runs 2 --quiet --out DIR`` on a scene
    with a (small, generated) measured file: exit 0 with a calibrated scene that loads and
    ``check`` passes, or 1 with an error line; anything else is a defect."""
    from thermobearing.scene import load_scene

    scene_path = out_dir / f"case_{case.index:04d}.toml"
    scene_path.write_text(case.toml, encoding="utf-8")
    target = out_dir / f"case_{case.index:04d}_calib"
    fit, bounds, x0 = CALIBRATE_FITS[int(rng.integers(0, len(CALIBRATE_FITS)))]
    args = ["calibrate", str(scene_path), "--fit", fit, "--max-runs", "2", "--quiet",
            "--out", str(target)]
    if bounds and rng.random() < 0.5:
        args += ["--bounds", f"{fit}={bounds}"]
    if x0 and rng.random() < 0.3:
        args += ["--x0", f"{fit}={x0.strip(chr(39))}"]
    proc = _cli(args, 8 * time_limit + 60)
    shown = " ".join(args[2:])
    if proc is None:
        case.notes.append(f"calibrate {shown}: time limit")
        return
    if _cli_failure(proc):
        case.outcome, case.message = "DEFECT", f"cli calibrate {shown}: {_cli_failure(proc)}"
        return
    if proc.returncode != 0:
        case.notes.append(f"calibrate: {proc.stderr.strip().splitlines()[-1][:160]}")
        return
    calibrated = target / f"{scene_path.stem}_calibrated.toml"
    if not calibrated.is_file():
        case.outcome, case.message = "DEFECT", f"cli calibrate {shown}: exit 0, no {calibrated}"
        return
    try:
        load_scene(str(calibrated))
    except Exception as exc:  # noqa: BLE001 -- any failure of the written scene
        case.outcome, case.message = "DEFECT", (
            f"cli calibrate {shown}: the calibrated scene does not load: {exc}")
        return
    check = _cli(["check", str(calibrated)], time_limit)
    if check is not None and check.returncode != 0:
        case.outcome, case.message = "DEFECT", (
            f"cli calibrate {shown}: check refuses the calibrated scene: "
            f"{check.stderr.strip()[-200:]}")
        return
    case.notes.append(f"calibrate {fit}: ok")


#: values a mutated scene puts in place of one of its values (another type, empty, a
#: sign, a size or a unit that does not fit)
MUTATIONS = (0, -1, 1.5, True, "", "abc", [], {}, [1, 2], {"a": 1}, "1e999 m", "-5 degC",
             "nan", 1e308, -1e308, "1 kg", "0", "  ")


def _leaves(doc: Any, path: tuple = ()) -> list[tuple]:
    if isinstance(doc, dict):
        return [p for k, v in doc.items() for p in _leaves(v, (*path, k))]
    if isinstance(doc, list):
        return [p for i, v in enumerate(doc) for p in _leaves(v, (*path, i))]
    return [path]


def mutate(rng: np.random.Generator, doc: dict[str, Any]) -> tuple[dict[str, Any], str]:
    """A copy of the scene document with one value (now and then its table) replaced by
    one of MUTATIONS or deleted, and where and what (``"supply/flow = -1"``)."""
    import copy

    out = copy.deepcopy(doc)
    leaves = _leaves(out)
    path = leaves[int(rng.integers(0, len(leaves)))]
    if len(path) > 1 and rng.random() < 0.15:
        path = path[:-1]
    parent: Any = out
    for key in path[:-1]:
        parent = parent[key]
    if rng.random() < 0.1:
        del parent[path[-1]]
        return out, "/".join(map(str, path)) + " deleted"
    value = MUTATIONS[int(rng.integers(0, len(MUTATIONS)))]
    parent[path[-1]] = value
    return out, f"{'/'.join(map(str, path))} = {value!r}"


#: unit typos a user writes for the generator's units, each meant as the unit it replaces:
#: accepted, the scene must read the value the unit meant; else a refusal naming its field
UNIT_TYPOS = {
    "degC": ("C", "\u00b0C", "\u00baC", "degc", "deg C", "Celsius", "DegC", "\u00b0 C", "deg_C",
             "degC."),
    "K": ("k", "\u00b0K", "Kelvin", "kelvins"),
    "degF": ("F", "\u00b0F", "degf", "deg F"),
    "rpm": ("RPM", "Rpm", "1/min", "min-1", "min^-1", "U/min", "rpm.", "r.p.m.", "rev/mn"),
    "r/min": ("R/min", "r/mn", "r / min"),
    "krpm": ("kRPM", "k rpm", "Krpm", "krev/min"),
    "rad/s": ("rad/sec", "1/s", "rad s^-1"),
    "rev/s": ("rps", "Hz", "rev/sec", "1/s"),
    "N": ("n", "Newton", "N."),
    "kN": ("KN", "kn", "Kn", "k N", "kN.", "kilo N"),
    "lbf": ("lb", "lbs", "LBF", "lb-f"),
    "L/min": ("l/min", "lpm", "LPM", "L/mn", "l/m", "L / min", "ltr/min", "Liter/min"),
    "L/h": ("l/h", "lph", "L/hr", "l/hour"),
    "mL/min": ("ml/min", "ccm", "cc/min"),
    "m**3/s": ("m3/s", "m^3/s", "cbm/s"),
    "mm": ("MM", "mm.", "mm2", "milimeter", "mm "),
    "cm": ("CM", "cm."),
    "m": ("M", "meter", "metre", "mtr"),
    "inch": ("\"", "in.", "inches", "Inch"),
    "s": ("sec", "secs", "S", "sek", "Sec"),
    "min": ("mins", "Min", "minute", "m", "mn", "MIN"),
    "ms": ("msec", "MS"),
    "mm**3/h": ("mm3/h", "mm^3/h", "mm\u00b3/hr"),
    "MPa": ("Mpa", "MPA", "N/mm2", "N/mm\u00b2"),
}
#: what goes between the number and its unit instead of one space
SEPARATOR_TYPOS = ("", "  ", "\u00a0", "\t", "_")


def _number_typos(num: str) -> list[str]:
    """The number ``num`` (as the scene wrote it) as a user might mistype it: a decimal
    comma, digit groups (comma, space, apostrophe, thin space), the minus sign U+2212, a
    doubled or trailing point, the letter O for a zero, an exponent with a space."""
    value = float(num)
    out = []
    if "." in num and "e" not in num.lower():
        out += [num.replace(".", ",", 1), num + ".", num.replace(".", "..", 1)]
    if abs(value) >= 1000 and value == int(value):
        digits = str(abs(int(value)))
        head, rest = digits[:len(digits) % 3 or 3], digits[len(digits) % 3 or 3:]
        groups = [rest[i:i + 3] for i in range(0, len(rest), 3)]
        for sep in (",", " ", "'", "\u2009"):
            out.append(("-" if value < 0 else "") + sep.join([head, *groups]))
    if value < 0:
        out.append("\u2212" + num.lstrip("-"))
    if "0" in num:
        out.append(num.replace("0", "O", 1))
    if "e" in num.lower():
        out.append(num.lower().replace("e", " e", 1))
    return out


def typo_mutate(rng: np.random.Generator, doc: dict[str, Any]
                ) -> tuple[dict[str, Any], str, tuple | None, str, str] | None:
    """A copy of the scene document with one quantity string (``"33 L/min"``) mistyped as
    a user would (:data:`UNIT_TYPOS`, :func:`_number_typos`, :data:`SEPARATOR_TYPOS`) but
    meant as written: the copy, what changed, the path, the original and the typo; None
    when the scene has no quantity in a known unit."""
    import copy

    leaves = []
    for path in _leaves(doc):
        value: Any = doc
        for key in path:
            value = value[key]
        m = _QTY.match(value) if isinstance(value, str) else None
        if m and m.group(2) in UNIT_TYPOS:
            leaves.append((path, value, m.group(1), m.group(2)))
    if not leaves:
        return None
    path, original, num, unit = leaves[int(rng.integers(0, len(leaves)))]
    r = rng.random()
    numbers = _number_typos(num)
    if r < 0.55:
        opts = UNIT_TYPOS[unit]
        typo = f"{num} {opts[int(rng.integers(0, len(opts)))]}"
    elif r < 0.85 and numbers:
        typo = f"{numbers[int(rng.integers(0, len(numbers)))]} {unit}"
    else:
        typo = f"{num}{SEPARATOR_TYPOS[int(rng.integers(0, len(SEPARATOR_TYPOS)))]}{unit}"
    out = copy.deepcopy(doc)
    parent: Any = out
    for key in path[:-1]:
        parent = parent[key]
    parent[path[-1]] = typo
    return out, f"{'/'.join(map(str, path))} = {typo!r} (meant {original!r})", path, \
        original, typo


#: user-made changes of a scene's structure (``structure_mutate``)
STRUCTURE_KINDS = ("duplicate", "empty", "swap", "reverse", "unicode", "scale", "extreme")
#: factors of the ``extreme`` kind: a number far outside physical sense in its own unit
#: (session-20 issue 6: 1e300 rpm stopped in an OverflowError, 1e150 L/min in a NaN)
EXTREME_FACTORS = (1e-300, 1e-150, 1e-30, 1e30, 1e150, 1e300)
UNICODE_NAMES = ("Lager-\u00dc 1", "\u8ef8\u53d7", "pr\u00fcfstand \u2713", "caf\u00e9 ",
                 "\u0394T-bearing", "A\u0301ngstr\u00f6m", "name with spaces")


def structure_mutate(rng: np.random.Generator, doc: dict[str, Any]
                     ) -> tuple[dict[str, Any], str] | None:
    """A copy of the scene document changed as a user might by mistake: a list element
    duplicated (a step, a heat source, a bearing), a table or list emptied, two quantities
    of one table swapped (start / stop, ambient / initial, two diameters), a list reversed,
    a name or title in other scripts, or one number scaled by 1e-6 .. 1e6 in its unit (mm
    written as m, kN as N), or (``extreme``) by 1e-300 .. 1e300 (:data:`EXTREME_FACTORS`:
    a value no bearing sees, which must be refused naming its field or run to finite
    numbers). None when the drawn kind finds nothing to change."""
    import copy

    out = copy.deepcopy(doc)
    kind = STRUCTURE_KINDS[int(rng.integers(0, len(STRUCTURE_KINDS)))]
    containers: list[tuple[tuple, Any]] = []

    def walk(node: Any, path: tuple) -> None:
        if isinstance(node, dict | list):
            containers.append((path, node))
            for k, v in (node.items() if isinstance(node, dict) else enumerate(node)):
                walk(v, (*path, k))

    walk(out, ())

    def pick(items: list) -> Any:
        return items[int(rng.integers(0, len(items)))] if items else None

    where = lambda path: "/".join(map(str, path)) or "scene"  # noqa: E731
    if kind == "duplicate":
        hit = pick([(p, c) for p, c in containers if isinstance(c, list) and c])
        if hit is None:
            return None
        path, lst = hit
        lst.append(copy.deepcopy(pick(lst)))
        return out, f"{where(path)}: an element duplicated"
    if kind == "empty":
        hit = pick([(p, c) for p, c in containers if p and c])
        if hit is None:
            return None
        path, node = hit
        node.clear()
        return out, f"{where(path)} emptied"
    if kind == "reverse":
        hit = pick([(p, c) for p, c in containers if isinstance(c, list) and len(c) > 1])
        if hit is None:
            return None
        hit[1].reverse()
        return out, f"{where(hit[0])} reversed"
    if kind == "swap":
        pairs = []
        for path, node in containers:
            if not isinstance(node, dict):
                continue
            qty = [(k, _QTY.match(v).group(2)) for k, v in node.items()
                   if isinstance(v, str) and _QTY.match(v)]
            pairs += [(path, a, b) for i, (a, ua) in enumerate(qty) for b, ub in qty[i + 1:]
                      if ua == ub and node[a] != node[b]]
        hit = pick(pairs)
        if hit is None:
            return None
        path, a, b = hit
        node = out
        for key in path:
            node = node[key]
        node[a], node[b] = node[b], node[a]
        return out, f"{where(path)}: {a} and {b} swapped"
    if kind == "unicode":
        spots = [(p, "name") for p, c in containers if isinstance(c, dict) and "name" in c]
        spots.append(((), "title"))
        path, key = pick(spots)
        node = out
        for k in path:
            node = node[k]
        node[key] = pick(list(UNICODE_NAMES))
        return out, f"{where((*path, key))} = {node[key]!r}"
    # scale
    hits = []
    for path, node in containers:
        for k, v in (node.items() if isinstance(node, dict) else enumerate(node)):
            if isinstance(v, str) and _QTY.match(v) and float(_QTY.match(v).group(1)) != 0:
                hits.append((path, k))
    hit = pick(hits)
    if hit is None:
        return None
    path, key = hit
    node = out
    for k in path:
        node = node[k]
    m = _QTY.match(node[key])
    factor = float(pick(list(EXTREME_FACTORS) if kind == "extreme"
                        else [1e-6, 1e-3, 1e3, 1e6]))
    node[key] = f"{float(m.group(1)) * factor:.6g} {m.group(2)}"
    return out, f"{where((*path, key))} = {node[key]!r} (x{factor:g})"


def _typo_misread(doc: dict[str, Any], mutated: Any, path: tuple, original: str,
                  typo: str) -> str | None:
    """For a typo the scene accepted: where it reads another value than the one meant --
    the scene's SI values against those of the original (:func:`si_mismatch`) and the typo
    in the original's unit against its number."""
    from thermobearing.errors import InputError
    from thermobearing.scene import dumps_toml, loads_scene
    from thermobearing.units import to_si

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        plain = loads_scene(dumps_toml(doc), base_dir=ROOT)
    mismatch = si_mismatch(plain, mutated)
    if mismatch:
        return f"accepted typo read as another value: {mismatch}"
    m = _QTY.match(original)
    try:
        read = to_si(typo, m.group(2))
    except InputError:
        return None  # a field that does not read through to_si (kept as text)
    if not math.isclose(read, float(m.group(1)), rel_tol=1e-9):
        return f"accepted typo {typo!r} read as {read:g} {m.group(2)}, meant {original!r}"
    return None


def run_mutations(rng: np.random.Generator, doc: dict[str, Any], n: int,
                  notes: list[str] | None = None,
                  accepted: list[tuple[str, str]] | None = None) -> list[str]:
    """Load and check (``thermobearing check``'s steps, no solve) ``n`` mutated copies of
    the scene (:func:`mutate`; user-made typos, :func:`typo_mutate`, and structural
    mistakes, :func:`structure_mutate`): a refusal must be an InputError naming its field,
    an accepted typo must read the value meant; anything else (a traceback, garbled check
    text) is returned as a defect line with its mutation. A refusal whose field is no key
    of a scene goes to ``notes``; a user-made mutant the check accepted (a typo, a
    structural mistake) to ``accepted`` as (what, TOML text), for a solve."""
    from thermobearing.errors import ConvergenceError, InputError
    from thermobearing.scene import dumps_toml, loads_scene

    defects = []
    for _ in range(n):
        typo = None
        r = rng.random()
        if r < 0.35:
            typo = typo_mutate(rng, doc)
        drawn = structure_mutate(rng, doc) if typo is None and r < 0.6 else None
        if typo is not None:
            mutated, what = typo[0], typo[1]
        elif drawn is not None:
            mutated, what = drawn
        else:
            mutated, what = mutate(rng, doc)
        try:
            text = dumps_toml(mutated)
        except Exception:  # noqa: BLE001 -- a value TOML cannot write: no scene to try
            continue
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                scene = loads_scene(text, base_dir=ROOT)
                garbled_text = check_scene(scene, raises=True)
            if garbled_text is not None:
                defects.append(f"mutation {what}: {garbled_text}")
            elif typo is not None:
                misread = _typo_misread(doc, scene, *typo[2:])
                if misread:
                    defects.append(f"mutation {what}: {misread}")
                elif accepted is not None:
                    accepted.append((what, text))
            elif drawn is not None and accepted is not None:
                accepted.append((what, text))
        except (InputError, ConvergenceError) as exc:
            outcome, msg = classify_error(exc)
            if outcome == "DEFECT":
                defects.append(f"mutation {what}: {msg}")
            elif msg.startswith("(not a scene field)") and notes is not None:
                notes.append(f"mutation {what}: {msg}")
        except Exception as exc:  # noqa: BLE001 -- every other failure is the defect
            defects.append(f"mutation {what}: {classify_error(exc)[1]}")
    return defects


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
    parser.add_argument("--sweep-every", type=int, default=5,
                        help="also sweep every N-th case (offset N/2) of those that ran OK "
                             "within a third of the time limit: `thermobearing sweep` "
                             "with one --set of two values, then `report` (0: never; "
                             "default 5)")
    parser.add_argument("--cage-every", type=int, default=4,
                        help="also run `thermobearing cage-speed` on a generated vibration "
                             "record of every N-th case's first bearing (0: never; default 4)")
    parser.add_argument("--calibrate", type=int, default=1,
                        help="also run `thermobearing calibrate --max-runs 2` on every case "
                             "with a measured file that ran OK within a quarter of the time "
                             "limit (0: never; default 1)")
    parser.add_argument("--mutations", type=int, default=3,
                        help="also load and check (no solve) N copies of each scene with one "
                             "value replaced by another type, size or unit, or deleted "
                             "(0: none; default 3)")
    parser.add_argument("--mutant-runs", type=int, default=1,
                        help="also solve up to N of each case's mutants that the check "
                             "accepted (user-made typos and structural mistakes: a value "
                             "scaled by 1e-6..1e6, two values swapped, a list element "
                             "duplicated, a table emptied), classified like a case "
                             "(0: none; default 1)")
    parser.add_argument("--only", type=str, default="",
                        help="comma list of case indices to run (reproduce a few)")
    args = parser.parse_args(argv)
    from thermobearing.scene import dumps_toml

    rng = np.random.default_rng(args.seed)
    catalogue, lubricants = bearing_catalogue(), lubricant_names()
    only = {int(x) for x in args.only.split(",") if x.strip()}
    out_dir = (args.out or Path(tempfile.mkdtemp(prefix="fuzz_scenes_"))).resolve()
    out_dir.mkdir(parents=True, exist_ok=True)
    cases = []
    import_package()
    runner = Runner()
    for i in range(args.n):
        doc, desc = make_scene(rng, catalogue, lubricants, out_dir / f"case_{i:04d}")
        settings = sweep_sets(rng, doc)  # drawn for every case: --only reruns the same
        if only and i not in only:
            continue
        case = Case(i, desc, dumps_toml(doc), plain=desc.get("plain", ""),
                    inline=desc.get("inline", ""))
        runner.run(case, args.time_limit)
        if args.cli_every and i % args.cli_every == 0 and case.outcome != "TIMEOUT":
            run_cli(case, out_dir, args.time_limit)
        if (args.sweep_every and i % args.sweep_every == args.sweep_every // 2
                and case.outcome == "OK" and case.seconds < args.time_limit / 3 and settings):
            run_sweep_cli(case, out_dir, args.time_limit, settings)
        extra_rng = np.random.default_rng([args.seed, i, 7])  # apart from the scene draws
        if args.cage_every and i % args.cage_every == 1 and case.outcome != "DEFECT":
            spec = doc["bearings"][0]
            step = (doc["schedule"].get("steps") or [doc["schedule"]])[0]
            rpm = _rpm_of(step.get("speed", "")) or _log_uniform(extra_rng, 300.0, 6000.0)
            run_cage_cli(case, extra_rng, spec, rpm, out_dir, args.time_limit)
        if (args.calibrate and "measured" in doc and case.outcome == "OK"
                and case.seconds < args.time_limit / 4):
            run_calibrate_cli(case, extra_rng, out_dir, args.time_limit)
        if args.mutations:
            mutants: list[tuple[str, str]] = []
            bad = run_mutations(extra_rng, doc, args.mutations, case.notes, mutants)
            if bad and case.outcome != "DEFECT":
                case.outcome, case.message = "DEFECT", "; ".join(bad)[:600]
            for k, (what, text) in enumerate(mutants[:args.mutant_runs]):
                run_mutant(runner, case, what, text, args.time_limit, out_dir, k)
        cases.append(case)
        print(f"{i:4d} {case.outcome:8s} {case.seconds:6.1f}s {desc['bearings']:>22s} "
              f"{desc['kinematics']:12s} {desc['outputs']:19s} {desc['supply']:11s} "
              f"{desc['speeds']:>20s} {desc['extras']:>16s}  {case.message[:90]}", flush=True)
    runner.close()
    print_summary(cases, out_dir)
    return 1 if any(c.outcome == "DEFECT" for c in cases) else 0


def run_mutant(runner: Runner, case: Case, what: str, text: str, time_limit: float,
               out_dir: Path | None = None, k: int = 0) -> None:
    """Solve one accepted mutant of ``case`` (``what`` changed; ``text`` its TOML) like a
    case: a defect makes the case's defect (its TOML replaced by the mutant's, the
    reproducer), a refusal or a timeout is a note, its TOML written to
    ``out_dir/case_<n>_mutant<k>.toml``."""
    mutant = Case(case.index, case.desc, text, mutant=True)
    runner.run(mutant, time_limit)
    if out_dir is not None and mutant.outcome != "OK":
        (out_dir / f"case_{case.index:04d}_mutant{k}.toml").write_text(
            f"# mutant of case {case.index}: {what}\n{text}", encoding="utf-8")
    case.notes.append(f"mutant solved: {mutant.outcome}")
    # a change that keeps the physics (the order of bearings, sources or outputs, a
    # bearing's name) must keep the outcome
    same_physics = ("reversed" in what and "steps" not in what) or "/name = " in what
    if same_physics and "TIMEOUT" not in (mutant.outcome, case.outcome) \
            and mutant.outcome != case.outcome:
        case.notes.append(f"mutant {what}: outcome {mutant.outcome}, the scene's "
                          f"{case.outcome} ({mutant.message[:150]})")
    if mutant.outcome == "DEFECT" and case.outcome != "DEFECT":
        case.outcome, case.message = "DEFECT", f"mutant {what}: {mutant.message}"[:600]
        case.toml = text
    elif mutant.outcome in ("REFUSED", "TIMEOUT"):
        case.notes.append(f"mutant {what}: {mutant.outcome} {mutant.message}"[:300])


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
