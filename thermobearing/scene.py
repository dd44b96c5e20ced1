"""Scenes: one configured study, read from TOML.

A scene names the bearing(s), the lubricant, the oil supply, the environment, the schedule of
speed and load steps, the models to use (one name per family), the thermal network, the
solver settings and the outputs wanted. Quantities are unit strings (``"1800 rpm"``,
``"33 L/min"``, ``"35 degC"``) converted once here to SI floats; bare numbers are SI. Unknown
keys are errors that name the key; :meth:`Scene.to_toml` writes a file that loads back to
an equal scene.

Layout (every table optional unless marked)::

    title = "..."                      # required
    source = "..."                     # where the study comes from

    [[bearings]]                       # required, one or more
    name = "drive_end"                 # unique; names the node group in the network
    preset = "QJ1044"                  # or path = "my_bearing.toml"
    overrides = { diametral_clearance = "0.1 mm" }

    [lubricant]                        # required
    preset = "ISO_VG46"                # or path = "..."

    [supply]
    method = "jet"                     # jet | circulation | oil_bath | oil_air | grease
    flow = "33 L/min"
    inlet_temperature = "35 degC"
    level = "20 mm"                    # oil bath only

    [environment]
    ambient_temperature = "35 degC"
    initial_temperature = "35 degC"    # default: ambient

    [schedule]                         # one of: steps | axial_load sweep | file
    speed = "1800 rpm"                 # defaults for every step
    radial_load = "1 kN"
    axial_load = "0 kN"
    step_duration = "3 min"
    axial_load_steps = { start = "0 kN", stop = "42 kN", step = "2 kN" }
    # steps = [{ duration = "3 min", speed = "1800 rpm", axial_load = "2 kN" }, ...]
    # file = "protocol.csv"   # columns duration [s], speed [rpm], radial_load [N], axial_load [N]

    [models]                           # one name per family (see `thermobearing models`)
    kinematics = "skidding"            # skidding | race_control | none (with global_friction)
    control = "outer_race"             # race control only: which race controls the spin
    film = "hamrock_dowson_1977_central"   # default; pan_hamrock_central for rollers
    heat_sources = ["raceway_traction", "churning_elements", "churning_cage",
                    "churning_inner_ring", "cage_guide", "pocket_friction"]
    heat_source_options = { pocket_friction = { ... } }   # per-source parameters
    churning_heat_to = "oil"           # oil | paper002 (where the churning heat is booked)
    calibration = "preset"             # preset (<bearing>.calibration.toml if any) | none

    [network]
    template = "four_node_paper002"
    parameters = { ... }               # template parameters, unit strings allowed

    [solver]
    stepper = "exprb43"                # exprb43 | tr_bdf2 | backward_euler ...
    rtol = 1e-7                        # step error scale atol + rtol |T| (default 1e-5 K + 3e-5 K)
    atol = 1e-5                        # [K]; steps cost no heat-source call (chunk model)
    kinematics_tolerance = 0.03        # relative viscosity change that triggers a re-solve (BM-7)
    chunk = "90 s"                     # coupling interval: heat re-linearised, output row

    [outputs]
    mode = "transient"                 # transient | steady
    want = ["temperatures", "losses", "kinematics", "energy", "report"]

    [checks]                           # thresholds of the validity warnings (operating_checks)
    skid_limit = "2 %"                 # |CSR/CSR_th - 1| [-]; default 5 %
    contact_stress_limit = "3500 MPa"  # or { ball = ..., self_aligning_ball = ..., roller = ... }
    min_film_parameter = 1.5           # Lambda [-]; default 1 (boundary lubrication)

    [measured]                         # a rig's thermocouple file (measured.py: ; or tab,
    file = "rig.csv"                   # decimal commas, metadata and units rows, timestamps,
    time_column = "time [min]"         # hh:mm:ss, dropout flags such as OVL or ----)
    unit = "degC"
    columns = { "T_outer_DE" = "drive_end.housing" }
    # time_column = ["Datum", "Uhrzeit"] # a date and a time-of-day column, read together
    # time_zero = "2026-11-23 10:00:00"  # t = 0 in the time column's format, or "first"
"""

from __future__ import annotations

import copy
import csv
import datetime
import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from .errors import InputError, UnknownNameError
from .operating_checks import STRESS_FAMILIES, CheckLimits, check_limit_value
from .units import format_quantity, to_si

SUPPLY_METHODS = ("jet", "circulation", "oil_bath", "oil_air", "grease")
OUTPUT_MODES = ("transient", "steady")
OUTPUT_KINDS = (
    "temperatures", "losses", "kinematics", "energy", "film", "report", "figures",
)
#: the keys of the optional ``[checks]`` table
CHECK_KEYS = ("skid_limit", "contact_stress_limit", "min_film_parameter")
#: what a run's summary names as the source of limits set in the scene
CHECKS_SOURCE = "scene [checks]"


def _check_keys(section: str, data: Mapping[str, Any], allowed: Sequence[str]) -> None:
    for key in data:
        if key not in allowed:
            raise InputError(f"{section}.{key}", data[key], "a known key: " + ", ".join(allowed))


def _table(field_name: str, value: Any) -> Mapping[str, Any]:
    """``value`` if it is a TOML table, else InputError naming the field."""
    if not isinstance(value, Mapping):
        raise InputError(field_name, value, "a table (key = value pairs)")
    return value


def _quantity(raw: Any, kind: str, field: str) -> float:
    """``to_si`` that also refuses NaN / inf (a bare ``nan`` is a float TOML allows)."""
    value = to_si(raw, kind, field=field)
    if not math.isfinite(value):
        raise InputError(field, raw, "a finite number with a unit")
    return value


def _require(section: str, data: Mapping[str, Any], key: str) -> Any:
    if key not in data:
        raise InputError(f"{section}.{key}", None, "a value (this key is required)")
    return data[key]


def _fmt(value: float, unit: str) -> str | float:
    """SI float -> unit string for TOML output, exact enough to round-trip."""
    if unit in ("", "-"):
        return value
    return format_quantity(value, unit, digits=12)


# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class BearingSpec:
    """One bearing of the scene: a preset or a TOML path, with overrides."""

    name: str
    preset: str | None = None
    path: str | None = None
    overrides: Mapping[str, Any] = field(default_factory=dict)

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], index: int) -> BearingSpec:
        sec = f"bearings[{index}]"
        _check_keys(sec, data, ("name", "preset", "path", "overrides"))
        preset, path = data.get("preset"), data.get("path")
        if (preset is None) == (path is None):
            raise InputError(f"{sec}.preset", preset, "exactly one of 'preset' or 'path'")
        return cls(
            name=str(data.get("name", f"bearing{index + 1}")),
            preset=preset,
            path=path,
            overrides=dict(_table(f"{sec}.overrides", data.get("overrides", {}))),
        )

    def to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"name": self.name}
        if self.preset:
            out["preset"] = self.preset
        if self.path:
            out["path"] = self.path
        if self.overrides:
            out["overrides"] = dict(self.overrides)
        return out


@dataclass(frozen=True)
class Supply:
    """Oil supply: method, volume flow [m^3/s], inlet temperature [K], bath level [m]."""

    method: str = "jet"
    flow: float = 0.0
    inlet_temperature: float = 308.15
    level: float | None = None

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], ambient: float) -> Supply:
        _check_keys("supply", data, ("method", "flow", "inlet_temperature", "level"))
        method = data.get("method", "jet")
        if method not in SUPPLY_METHODS:
            raise UnknownNameError("supply.method", method, SUPPLY_METHODS)
        flow = _quantity(data.get("flow", 0.0), "volume_flow", "supply.flow")
        if flow < 0 or (flow == 0 and method not in ("oil_bath", "grease")):
            raise InputError(
                "supply.flow", data.get("flow"),
                "a flow > 0 (zero only for an oil bath or grease)",
            )
        t_in = _quantity(data.get("inlet_temperature", ambient), "temperature",
                     field="supply.inlet_temperature")
        if t_in <= 0:
            raise InputError("supply.inlet_temperature", data.get("inlet_temperature"),
                             "a temperature above absolute zero")
        level = data.get("level")
        level_si = None if level is None else _quantity(level, "length", "supply.level")
        if level_si is not None and level_si < 0:
            raise InputError("supply.level", level, "an oil level >= 0")
        if method == "oil_bath" and level_si is None:
            raise InputError("supply.level", None, "an oil level for an oil bath")
        return cls(method=method, flow=flow, inlet_temperature=t_in, level=level_si)

    def to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {
            "method": self.method,
            "flow": _fmt(self.flow, "L/min"),
            "inlet_temperature": _fmt(self.inlet_temperature, "degC"),
        }
        if self.level is not None:
            out["level"] = _fmt(self.level, "mm")
        return out


@dataclass(frozen=True)
class Environment:
    """Ambient and initial temperatures [K]."""

    ambient_temperature: float = 308.15
    initial_temperature: float = 308.15

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Environment:
        _check_keys("environment", data, ("ambient_temperature", "initial_temperature"))
        amb = _quantity(data.get("ambient_temperature", "35 degC"), "temperature",
                    field="environment.ambient_temperature")
        ini = _quantity(data.get("initial_temperature", amb), "temperature",
                    field="environment.initial_temperature")
        for name, v in (("ambient_temperature", amb), ("initial_temperature", ini)):
            if v <= 0:
                raise InputError(f"environment.{name}", data.get(name, v),
                                 "a temperature above absolute zero (0 K = -273.15 degC)")
        return cls(ambient_temperature=amb, initial_temperature=ini)

    def to_dict(self) -> dict[str, Any]:
        return {
            "ambient_temperature": _fmt(self.ambient_temperature, "degC"),
            "initial_temperature": _fmt(self.initial_temperature, "degC"),
        }


@dataclass(frozen=True)
class Step:
    """One schedule step: duration [s], inner-ring speed [rad/s], loads [N]."""

    duration: float
    speed: float
    radial_load: float
    axial_load: float


_STEP_KEYS = ("duration", "speed", "radial_load", "axial_load")
_STEP_KINDS = {"duration": "time", "speed": "angular_speed", "radial_load": "force",
               "axial_load": "force"}
_STEP_UNITS = {"duration": "min", "speed": "rpm", "radial_load": "kN", "axial_load": "kN"}


def _make_step(values: Mapping[str, Any], defaults: Mapping[str, float], where: str) -> Step:
    _check_keys(where, values, _STEP_KEYS)
    out = dict(defaults)
    for key, raw in values.items():
        out[key] = _quantity(raw, _STEP_KINDS[key], f"{where}.{key}")
    for key in _STEP_KEYS:
        if key not in out:
            raise InputError(f"{where}.{key}", None, "a value (no default given in [schedule])")
    if not out["duration"] > 0:
        raise InputError(f"{where}.duration", values.get("duration", out["duration"]),
                         "a duration > 0")
    for key in ("radial_load", "axial_load"):
        if out[key] < 0:
            raise InputError(f"{where}.{key}", values.get(key, out[key]), "a load >= 0")
    if out["speed"] < 0:
        raise InputError(f"{where}.speed", values.get("speed", out["speed"]), "a speed >= 0")
    return Step(**{k: float(out[k]) for k in _STEP_KEYS})


@dataclass(frozen=True)
class Schedule:
    """The protocol: a tuple of steps run one after the other."""

    steps: tuple[Step, ...]

    @property
    def breakpoints(self) -> list[float]:
        """Times [s] at which one step ends and the next begins (discontinuities)."""
        t, out = 0.0, []
        for s in self.steps[:-1]:
            t += s.duration
            out.append(t)
        return out

    @property
    def duration(self) -> float:
        return float(sum(s.duration for s in self.steps))

    def step_at(self, t: float) -> int:
        """Index of the step active at time ``t`` (right-continuous)."""
        acc = 0.0
        for i, s in enumerate(self.steps):
            acc += s.duration
            if t < acc:
                return i
        return len(self.steps) - 1

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], base_dir: Path | None = None) -> Schedule:
        allowed = ("speed", "radial_load", "axial_load", "step_duration", "duration",
                   "axial_load_steps", "steps", "file")
        _check_keys("schedule", data, allowed)
        defaults: dict[str, float] = {}
        for key, kind_key in (("speed", "speed"), ("radial_load", "radial_load"),
                              ("axial_load", "axial_load")):
            if key in data:
                defaults[key] = _quantity(data[key], _STEP_KINDS[kind_key], f"schedule.{key}")
        dur_key = "step_duration" if "step_duration" in data else "duration"
        if dur_key in data:
            defaults["duration"] = _quantity(data[dur_key], "time", f"schedule.{dur_key}")
        forms = [k for k in ("axial_load_steps", "steps", "file") if k in data]
        if len(forms) > 1:
            raise InputError("schedule", forms, "only one of axial_load_steps, steps or file")
        steps: list[Step] = []
        if not forms:
            if "duration" not in defaults:
                defaults["duration"] = 3600.0
            steps.append(_make_step({}, defaults, "schedule"))
        elif forms[0] == "axial_load_steps":
            sweep = _table("schedule.axial_load_steps", data["axial_load_steps"])
            _check_keys("schedule.axial_load_steps", sweep, ("start", "stop", "step"))
            a0 = _quantity(_require("schedule.axial_load_steps", sweep, "start"), "force",
                       field="schedule.axial_load_steps.start")
            a1 = _quantity(_require("schedule.axial_load_steps", sweep, "stop"), "force",
                       field="schedule.axial_load_steps.stop")
            da = _quantity(_require("schedule.axial_load_steps", sweep, "step"), "force",
                       field="schedule.axial_load_steps.step")
            if da <= 0 or a1 < a0:
                raise InputError("schedule.axial_load_steps", dict(sweep),
                                 "start <= stop and step > 0")
            n = int(math.floor((a1 - a0) / da + 1e-9)) + 1
            for i in range(n):
                steps.append(_make_step({}, {**defaults, "axial_load": a0 + i * da},
                                        f"schedule.axial_load_steps[{i}]"))
        elif forms[0] == "steps":
            items = data["steps"]
            if not isinstance(items, list):
                raise InputError("schedule.steps", items,
                                 "an array of tables, e.g. [{ duration = \"3 min\" }, ...]")
            for i, item in enumerate(items):
                where = f"schedule.steps[{i}]"
                steps.append(_make_step(_table(where, item), defaults, where))
        else:
            steps.extend(_read_schedule_file(data["file"], defaults, base_dir))
        if not steps:
            raise InputError("schedule", dict(data), "at least one step")
        return cls(steps=tuple(steps))

    def to_dict(self) -> dict[str, Any]:
        return {
            "steps": [
                {k: _fmt(getattr(s, k), _STEP_UNITS[k]) for k in _STEP_KEYS} for s in self.steps
            ]
        }


def _read_schedule_file(name: str, defaults: Mapping[str, float],
                        base_dir: Path | None) -> list[Step]:
    path = Path(name)
    if not path.is_absolute() and base_dir is not None:
        path = base_dir / path
    if not path.is_file():
        raise InputError("schedule.file", name, "an existing CSV file")
    units = {"duration": "s", "speed": "rpm", "radial_load": "N", "axial_load": "N"}
    steps = []
    with path.open(newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        colmap: dict[str, str] = {}
        for col in reader.fieldnames or []:
            key, _, unit = col.partition("[")
            key = key.strip()
            if key not in _STEP_KEYS:
                raise InputError(f"schedule.file column {col!r}", col,
                                 "columns named " + ", ".join(_STEP_KEYS) + " with [unit]")
            colmap[col] = key
            if unit:
                units[key] = unit.rstrip("] ")
        for i, row in enumerate(reader):
            values = {colmap[c]: f"{v} {units[colmap[c]]}" for c, v in row.items() if v}
            steps.append(_make_step(values, defaults, f"schedule.file row {i + 1}"))
    return steps


@dataclass(frozen=True)
class Measured:
    """Measured temperatures: a rig's thermocouple file with a time column and a
    column -> node map (formats: :func:`thermobearing.measured.read_measured_file`).

    ``time_column``: a column name, or ``[date column, time-of-day column]``.
    ``time_zero``: the instant of the scene's t = 0 in the time column's own format (a
    timestamp, ``hh:mm:ss`` or a number in the column's unit) or ``"first"`` (the first
    row); None: the first row for timestamps, the values as they are otherwise.
    """

    file: str
    columns: Mapping[str, str]
    time_column: str | tuple[str, str] = "time [min]"
    unit: str = "degC"
    time_zero: str | None = None

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Measured:
        _check_keys("measured", data, ("file", "columns", "time_column", "unit", "time_zero"))
        unit = data.get("unit", "degC")
        if unit not in ("degC", "K", "degF"):
            raise InputError("measured.unit", unit, "degC, K or degF")
        cols = data.get("columns")
        if not isinstance(cols, Mapping) or not cols:
            raise InputError("measured.columns", cols, "a table of CSV column -> node name")
        zero = data.get("time_zero")
        if isinstance(zero, datetime.datetime | datetime.time):  # an unquoted TOML time
            zero = zero.isoformat(sep=" ") if isinstance(zero, datetime.datetime) \
                else zero.isoformat()
        if zero is not None and (not isinstance(zero, str | int | float)
                                 or isinstance(zero, bool) or not str(zero).strip()):
            raise InputError("measured.time_zero", zero, "\"first\" or a time in the format "
                             "of the file's time column (\"2026-11-23 10:00:00\", "
                             "\"00:05:00\", 5)")
        tcol = data.get("time_column", "time [min]")
        if isinstance(tcol, list | tuple):
            if len(tcol) != 2 or not all(isinstance(c, str) and c for c in tcol):
                raise InputError("measured.time_column", tcol, "a column name, or the names "
                                 "of a date column and a time-of-day column [\"date\", "
                                 "\"time\"]")
            tcol = (tcol[0], tcol[1])
        else:
            tcol = str(tcol)
        return cls(file=str(_require("measured", data, "file")), columns=dict(cols),
                   time_column=tcol, unit=unit,
                   time_zero=None if zero is None else str(zero).strip())

    def to_dict(self) -> dict[str, Any]:
        tcol = self.time_column
        out = {"file": self.file, "columns": dict(self.columns),
               "time_column": tcol if isinstance(tcol, str) else list(tcol),
               "unit": self.unit}
        if self.time_zero is not None:
            out["time_zero"] = self.time_zero
        return out


@dataclass(frozen=True)
class Solver:
    """Solver settings.

    ``rtol``, ``atol`` [K]: the stepper's error scale atol + rtol |T| per step. Inside a
    coupling chunk the heat is the chunk's quadratic model (:mod:`thermobearing.coupled`),
    so a step costs no heat-source evaluation and the tight defaults are nearly free
    (default scene: 95 instead of 44 steps, 4e-6 instead of 5.6e-5 K from a tight LSODA
    reference of the same chain, the same CPU time; BM-E2E). TR-BDF2, second order, pays
    more for them: 756 instead of 145 steps on the default scene, +37 % CPU; on a large
    network where its steps dominate, rtol 1e-4 / atol 1e-3 K keep the old cost.
    """

    stepper: str = "exprb43"
    rtol: float = 1e-7
    atol: float = 1e-5
    kinematics_tolerance: float = 0.03
    max_step: float = 600.0
    chunk: float = 90.0

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Solver:
        names = [f.name for f in fields(cls)]
        _check_keys("solver", data, names)
        kw: dict[str, Any] = {}
        if "stepper" in data:
            if not isinstance(data["stepper"], str):
                raise InputError("solver.stepper", data["stepper"], "a stepper name (a string)")
            kw["stepper"] = data["stepper"]
        limits = {"rtol": ("a relative tolerance in (0, 1)", 1.0),
                  "atol": ("an absolute tolerance > 0 (K)", math.inf),
                  "kinematics_tolerance": ("a relative viscosity change in (0, 1)", 1.0)}
        for key, (allowed, high) in limits.items():
            if key in data:
                raw = data[key]
                if isinstance(raw, bool) or not isinstance(raw, int | float):
                    raise InputError(f"solver.{key}", raw, "a number: " + allowed)
                v = float(raw)
                if not (math.isfinite(v) and 0.0 < v < high):
                    raise InputError(f"solver.{key}", raw, allowed)
                kw[key] = v
        for key in ("max_step", "chunk"):
            if key in data:
                kw[key] = _quantity(data[key], "time", f"solver.{key}")
                if kw[key] <= 0:
                    raise InputError(f"solver.{key}", data[key], "a time > 0")
        return cls(**kw)

    def to_dict(self) -> dict[str, Any]:
        return {"stepper": self.stepper, "rtol": self.rtol, "atol": self.atol,
                "kinematics_tolerance": self.kinematics_tolerance,
                "max_step": _fmt(self.max_step, "s"), "chunk": _fmt(self.chunk, "s")}


@dataclass(frozen=True)
class Outputs:
    """What the scene must produce; decides which models run.

    ``interval`` [s] (optional, transient runs): temperature rows also at every multiple of
    it, from the stepper's own dense output between the coupling chunk ends (default: the
    chunk ends only). A measured CSV is compared with these rows, so a thermocouple log
    sampled faster than the chunk is met by the model's curve, not by straight lines
    between chunk ends.
    """

    mode: str = "transient"
    want: tuple[str, ...] = ("temperatures", "losses", "kinematics", "energy", "report")
    interval: float | None = None

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Outputs:
        _check_keys("outputs", data, ("mode", "want", "interval"))
        interval = None
        if "interval" in data:
            interval = _quantity(data["interval"], "time", "outputs.interval")
            if not interval > 0:
                raise InputError("outputs.interval", data["interval"], "a time > 0")
        mode = data.get("mode", "transient")
        if mode not in OUTPUT_MODES:
            raise UnknownNameError("outputs.mode", mode, OUTPUT_MODES)
        raw_want = data.get("want", cls.want)
        if isinstance(raw_want, str) or not isinstance(raw_want, list | tuple):
            raise InputError("outputs.want", raw_want,
                             "an array of output names, e.g. [\"temperatures\", \"losses\"]")
        want = tuple(raw_want)
        for w in want:
            if w not in OUTPUT_KINDS:
                raise UnknownNameError("outputs.want", w, OUTPUT_KINDS)
        return cls(mode=mode, want=want, interval=interval)

    def to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"mode": self.mode, "want": list(self.want)}
        if self.interval is not None:
            out["interval"] = _fmt(self.interval, "s")
        return out


def checks_from_dict(data: Mapping[str, Any]) -> CheckLimits:
    """The thresholds of the optional ``[checks]`` table (:class:`CheckLimits`, SI).

    ``skid_limit`` and ``min_film_parameter`` are dimensionless (``0.02``, ``"2 %"``, ``1.5``);
    ``contact_stress_limit`` is a stress (``"3500 MPa"``) for every bearing family, or a
    table ``{ ball = ..., self_aligning_ball = ..., roller = ... }`` setting some of them
    (the others keep the ISO 76 stress). Keys left out keep their defaults.
    """
    _check_keys("checks", data, CHECK_KEYS)
    kw: dict[str, float] = {}

    def limit(name: str, raw: Any, kind: str, where: str) -> None:
        value = to_si(raw, kind, field=where)
        check_limit_value(name, value, where, raw)
        kw[name] = value

    for name in ("skid_limit", "min_film_parameter"):
        if name in data:
            limit(name, data[name], "dimensionless", f"checks.{name}")
    if "contact_stress_limit" in data:
        raw = data["contact_stress_limit"]
        if isinstance(raw, Mapping):
            _check_keys("checks.contact_stress_limit", raw, STRESS_FAMILIES)
            if not raw:
                raise InputError("checks.contact_stress_limit", dict(raw),
                                 "a stress, or a table naming one or more of "
                                 + ", ".join(STRESS_FAMILIES))
            for family, value in raw.items():
                limit(f"{family}_stress_limit", value, "stress",
                      f"checks.contact_stress_limit.{family}")
        else:
            for family in STRESS_FAMILIES:
                limit(f"{family}_stress_limit", raw, "stress", "checks.contact_stress_limit")
    return CheckLimits(**kw, source=CHECKS_SOURCE)


def checks_to_dict(limits: CheckLimits) -> dict[str, Any]:
    """The ``[checks]`` table of ``limits``: only the thresholds that differ from the
    defaults; one stress when every family has the same set value."""
    out: dict[str, Any] = {}
    if not limits.is_default("skid_limit"):
        percent = f"{100.0 * limits.skid_limit:.12g} %"  # as users write it, when exact
        out["skid_limit"] = percent if to_si(percent, "dimensionless") == limits.skid_limit \
            else limits.skid_limit
    stress = {f: limits.stress_limit(f) for f in STRESS_FAMILIES
              if not limits.is_default(f"{f}_stress_limit")}
    if len(stress) == len(STRESS_FAMILIES) and len(set(stress.values())) == 1:
        out["contact_stress_limit"] = _fmt(next(iter(stress.values())), "MPa")
    elif stress:
        out["contact_stress_limit"] = {f: _fmt(v, "MPa") for f, v in stress.items()}
    if not limits.is_default("min_film_parameter"):
        out["min_film_parameter"] = limits.min_film_parameter
    return out


@dataclass(frozen=True)
class Scene:
    """One configured study (see the module docstring for the TOML layout)."""

    title: str
    bearings: tuple[BearingSpec, ...]
    lubricant: Mapping[str, Any]
    supply: Supply
    environment: Environment
    schedule: Schedule
    models: Mapping[str, Any] = field(default_factory=dict)
    network: Mapping[str, Any] = field(default_factory=dict)
    solver: Solver = field(default_factory=Solver)
    outputs: Outputs = field(default_factory=Outputs)
    measured: Measured | None = None
    source: str = ""
    base_dir: str | None = None
    #: thresholds of the run's validity checks (``[checks]``; None: the defaults)
    checks: CheckLimits | None = None

    _TOP = ("title", "source", "bearings", "lubricant", "supply", "environment", "schedule",
            "models", "network", "solver", "outputs", "measured", "checks")

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], base_dir: Path | None = None) -> Scene:
        """Validate and convert a parsed TOML document."""
        _check_keys("scene", data, cls._TOP)
        title = str(_require("scene", data, "title"))
        raw_bearings = _require("scene", data, "bearings")
        if isinstance(raw_bearings, Mapping):
            raw_bearings = [raw_bearings]
        if not isinstance(raw_bearings, list) or not raw_bearings:
            raise InputError("bearings", raw_bearings,
                             "one or more [[bearings]] tables (name, preset or path)")
        bearings = tuple(BearingSpec.from_dict(_table(f"bearings[{i}]", b), i)
                         for i, b in enumerate(raw_bearings))
        names = [b.name for b in bearings]
        if len(set(names)) != len(names):
            raise InputError("bearings[].name", names, "unique names")
        lub = dict(_table("lubricant", _require("scene", data, "lubricant")))
        _check_keys("lubricant", lub, ("preset", "path"))
        if ("preset" in lub) == ("path" in lub):
            raise InputError("lubricant", lub, "exactly one of 'preset' or 'path'")
        for name in ("supply", "environment", "schedule", "models", "network", "solver",
                     "outputs", "measured", "checks"):
            if name in data:
                _table(name, data[name])
        if "path" in lub:
            lub_path = Path(str(lub["path"]))
            if not lub_path.is_absolute() and base_dir is not None:
                lub_path = Path(base_dir) / lub_path
            if not lub_path.is_file():
                raise InputError("lubricant.path", lub["path"],
                                 f"an existing lubricant TOML file (looked at {lub_path})")
        env = Environment.from_dict(data.get("environment", {}))
        _check_model_types(_table("models", data.get("models", {})))
        network = dict(data.get("network", {}))
        solver = Solver.from_dict(data.get("solver", {}))
        scene = cls(
            title=title,
            source=str(data.get("source", "")),
            bearings=bearings,
            lubricant=lub,
            supply=Supply.from_dict(data.get("supply", {}), env.ambient_temperature),
            environment=env,
            schedule=Schedule.from_dict(_require("scene", data, "schedule"), base_dir),
            models=dict(data.get("models", {})),
            network=network,
            solver=solver,
            outputs=Outputs.from_dict(data.get("outputs", {})),
            measured=Measured.from_dict(data["measured"]) if "measured" in data else None,
            base_dir=str(base_dir) if base_dir is not None else None,
            checks=checks_from_dict(data["checks"]) if "checks" in data else None,
        )
        # names, keys and units of [network] now; the template's required parameters only
        # when the scene is run (check_network(..., require=True) in `run` / `check`), so
        # a scene that never builds its network still loads
        check_network(network, require=False)
        return scene

    def to_dict(self) -> dict[str, Any]:
        """The resolved scene as a TOML-ready dict (SI floats back to unit strings); a deep
        copy, so editing it never changes the scene."""
        return copy.deepcopy(self._to_dict())

    def _to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"title": self.title}
        if self.source:
            out["source"] = self.source
        out["bearings"] = [b.to_dict() for b in self.bearings]
        out["lubricant"] = dict(self.lubricant)
        out["supply"] = self.supply.to_dict()
        out["environment"] = self.environment.to_dict()
        out["schedule"] = self.schedule.to_dict()
        if self.models:
            out["models"] = dict(self.models)
        if self.network:
            out["network"] = dict(self.network)
        out["solver"] = self.solver.to_dict()
        out["outputs"] = self.outputs.to_dict()
        if self.checks is not None:
            out["checks"] = checks_to_dict(self.checks)
        if self.measured is not None:
            out["measured"] = self.measured.to_dict()
        return out

    def to_toml(self) -> str:
        """TOML text that :func:`loads_scene` reads back to an equal scene."""
        return dumps_toml(self.to_dict())

    def with_changes(self, **changes: Any) -> Scene:
        """A copy with some top-level fields replaced."""
        return replace(self, **changes)

    def resolve_path(self, name: str) -> Path:
        """A path given in the scene, relative to the scene file's folder."""
        p = Path(name)
        if not p.is_absolute() and self.base_dir:
            p = Path(self.base_dir) / p
        return p


def _check_model_types(models: Mapping[str, Any]) -> None:
    """The value types of ``[models]`` (the names themselves are checked against the
    registries when the model chain is planned): one name per family, a list of names
    for ``heat_sources``, a table for ``heat_source_options``."""
    for key, value in models.items():
        if key == "heat_sources":
            if isinstance(value, str):
                continue
            if not (isinstance(value, list) and all(isinstance(v, str) for v in value)):
                raise InputError("models.heat_sources", value,
                                 "a heat-source name or an array of names")
        elif key == "heat_source_options":
            _table("models.heat_source_options", value)
        elif not isinstance(value, str):
            raise InputError(f"models.{key}", value, "a model name (a string)")


def with_absolute_paths(scene: Scene) -> Scene:
    """The scene with its relative file paths (bearing / lubricant TOMLs, measured CSV) made
    absolute against its folder, so that its TOML text (a results folder's ``scene.toml``,
    a sweep case) still finds them when read from elsewhere."""
    if not scene.base_dir:
        return scene
    base = Path(scene.base_dir)
    d = scene.to_dict()
    changed = False
    tables = [*d.get("bearings", []), d.get("lubricant"), d.get("measured")]
    for table, key in zip(tables, ["path"] * (len(tables) - 1) + ["file"], strict=True):
        if isinstance(table, dict) and isinstance(table.get(key), str) \
                and not Path(table[key]).is_absolute():
            table[key] = str((base / table[key]).resolve())
            changed = True
    return Scene.from_dict(d, base) if changed else scene


# ---------------------------------------------------------------------------
def configs_dir() -> Path:
    """The repository's ``configs`` folder (bearings, lubricants, scenes)."""
    return Path(__file__).resolve().parents[1] / "configs"


DEFAULT_SCENE = "qj1044_rig"


def scene_presets() -> list[str]:
    folder = configs_dir() / "scenes"
    return sorted(p.stem for p in folder.glob("*.toml"))


def loads_scene(text: str, base_dir: Path | None = None, source: str | None = None) -> Scene:
    """Parse TOML text into a :class:`Scene` (``source``: the file name for messages)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("scene", source or "<toml>", f"valid TOML ({exc})") from None
    return Scene.from_dict(data, base_dir)


def load_scene(name_or_path: str | Path | None = None) -> Scene:
    """Load a scene from a TOML path or a preset name in ``configs/scenes`` (default scene
    when ``None``)."""
    if name_or_path is None:
        name_or_path = DEFAULT_SCENE
    path = Path(name_or_path)
    if not path.is_file():
        preset = configs_dir() / "scenes" / f"{name_or_path}.toml"
        if not preset.is_file():
            raise UnknownNameError("scene", str(name_or_path), scene_presets())
        path = preset
    return loads_scene(path.read_text(encoding="utf-8"), base_dir=path.parent,
                       source=str(path))


# ---------------------------------------------------------------------------
def _toml_value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v) if math.isfinite(v) else ("nan" if math.isnan(v) else
                                                 ("inf" if v > 0 else "-inf"))
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_toml_key(k)} = {_toml_value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, list | tuple):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _toml_key(k: str) -> str:
    return k if k.replace("_", "").replace("-", "").isalnum() else _toml_value(k)


def dumps_toml(data: Mapping[str, Any]) -> str:
    """Small TOML writer for scene documents (tables, arrays of tables, inline values)."""
    lines: list[str] = []
    scalars = {k: v for k, v in data.items() if not _is_table(v) and not _is_table_array(v)}
    for k, v in scalars.items():
        lines.append(f"{_toml_key(k)} = {_toml_value(v)}")
    for k, v in data.items():
        if _is_table_array(v):
            for item in v:
                lines.append("")
                lines.append(f"[[{_toml_key(k)}]]")
                for kk, vv in item.items():
                    lines.append(f"{_toml_key(kk)} = {_toml_value(vv)}")
        elif _is_table(v):
            lines.append("")
            lines.append(f"[{_toml_key(k)}]")
            for kk, vv in v.items():
                if kk == "steps" and isinstance(vv, list):
                    lines.append(f"{kk} = [")
                    lines.extend(f"  {_toml_value(x)}," for x in vv)
                    lines.append("]")
                else:
                    lines.append(f"{_toml_key(kk)} = {_toml_value(vv)}")
    return "\n".join(lines) + "\n"


def _is_table(v: Any) -> bool:
    return isinstance(v, Mapping)


def _is_table_array(v: Any) -> bool:
    """An array of named tables (``[[bearings]]``) is written in the long form."""
    return (isinstance(v, list) and bool(v)
            and all(isinstance(x, Mapping) and "name" in x for x in v))


# the pre-run checks live in scene_checks (one job per module); re-exported here, where
# callers have always found them
from .scene_checks import (  # noqa: E402, F401
    check_measured_file,
    check_model_names,
    check_network,
)
