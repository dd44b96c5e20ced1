"""The sections of a scene other than the schedule, each a frozen dataclass read from its
TOML table (``from_dict``: strict keys, unit strings to SI) and written back (``to_dict``):
``[[bearings]]`` (:class:`BearingSpec`), ``[supply]``, ``[environment]``, ``[measured]``,
``[solver]``, ``[outputs]``, and the ``[checks]`` thresholds (:func:`checks_from_dict`,
:func:`checks_to_dict`). The layout of the whole file is in :mod:`thermobearing.scene`.
"""

from __future__ import annotations

import datetime
import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import Any

from .errors import InputError, UnknownNameError, check_positive
from .operating_checks import STRESS_FAMILIES, CheckLimits, check_limit_value
from .scene_values import _check_keys, _fmt, _quantity, _require, _table, _unit_of
from .units import to_si

SUPPLY_METHODS = ("jet", "circulation", "oil_bath", "oil_air", "grease")
OUTPUT_MODES = ("transient", "steady")
OUTPUT_KINDS = (
    "temperatures", "losses", "kinematics", "energy", "film", "report", "figures",
)
#: the keys of the optional ``[checks]`` table
CHECK_KEYS = ("skid_limit", "contact_stress_limit", "min_film_parameter")
#: what a run's summary names as the source of limits set in the scene
CHECKS_SOURCE = "scene [checks]"


#: largest magnitude of a ``load_share`` fraction
MAX_LOAD_SHARE = 100.0


def _checked_load_share(sec: str, share: Mapping[str, Any]) -> dict[str, float]:
    """A ``[[bearings]] load_share`` table checked (keys radial / axial, finite numbers,
    radial >= 0; ``sec`` names the bearing in errors) and converted to floats."""
    _check_keys(f"{sec}.load_share", share, ("radial", "axial"))
    out = {}
    for key, value in share.items():
        where = f"{sec}.load_share.{key}"
        if isinstance(value, bool) or not isinstance(value, int | float) \
                or not math.isfinite(value):
            raise InputError(where, value, "a number: the fraction of the schedule's "
                             f"{key} load this bearing carries (1 = all of it)")
        if key == "radial" and value < 0:
            raise InputError(where, value, "a fraction >= 0 of the radial load")
        if abs(value) > MAX_LOAD_SHARE:
            # 5e29 was refused as 'step.radial_load = 5e32', no key of the scene
            raise InputError(where, value, f"a share of magnitude up to {MAX_LOAD_SHARE:g} "
                             "(a lever-arm split gives an overhung load's bearing (a + L) / "
                             f"L, {MAX_LOAD_SHARE:g} only for an overhang 99 times the "
                             "bearing span)")
        out[key] = float(value)
    return out


@dataclass(frozen=True)
class BearingSpec:
    """One bearing of the scene: a preset or a TOML path, with overrides.

    ``load_share``: the fractions of the schedule's loads this bearing carries, ``{ radial =
    0.6, axial = 0 }`` (default 1 each: every bearing carries the step's loads). On a shaft
    with two bearings the radial load splits by the lever arms (statics of the shaft, not
    computed here) and a locating / floating arrangement puts the axial load on the locating
    bearing only (``axial = 0`` for the floating one, e.g. an NU cylindrical roller bearing,
    which carries none); a negative axial share reverses the load's direction on that
    bearing. Radial share >= 0.
    """

    name: str
    preset: str | None = None
    path: str | None = None
    overrides: Mapping[str, Any] = field(default_factory=dict)
    load_share: Mapping[str, float] = field(default_factory=dict)

    def __post_init__(self) -> None:
        # the rules of a [[bearings]] table also for a BearingSpec built or replaced in code
        # (a load_share of -0.5 or "0.5" reached the solvers)
        sec = f"bearings[{self.name}]"
        if (self.preset is None) == (self.path is None):
            raise InputError(f"{sec}.preset", self.preset, "exactly one of 'preset' or 'path'")
        _checked_load_share(sec, self.load_share)

    @property
    def radial_share(self) -> float:
        return float(self.load_share.get("radial", 1.0))

    @property
    def axial_share(self) -> float:
        return float(self.load_share.get("axial", 1.0))

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], index: int) -> BearingSpec:
        sec = f"bearings[{index}]"
        _check_keys(sec, data, ("name", "preset", "path", "overrides", "load_share"))
        preset, path = data.get("preset"), data.get("path")
        if (preset is None) == (path is None):
            raise InputError(f"{sec}.preset", preset, "exactly one of 'preset' or 'path'")
        for key, value in (("preset", preset), ("path", path)):
            if value is not None and (not isinstance(value, str) or not value.strip()):
                raise InputError(f"{sec}.{key}", value, "a bearing preset name" if key ==
                                 "preset" else "a bearing TOML file path")
        share = _checked_load_share(sec, _table(f"{sec}.load_share",
                                                 data.get("load_share", {})))
        name = data.get("name", f"bearing{index + 1}")
        if isinstance(name, bool) or not isinstance(name, str | int) or not str(name).strip():
            # name = "" or {} loaded: the bearing's nodes were ".oil", "{}.oil" and its
            # table rows named by an empty or garbled string
            raise InputError(f"{sec}.name", name, "a name (text with a visible character: "
                             "it names the bearing's network nodes and table rows)")
        return cls(
            name=str(name),
            preset=preset,
            path=path,
            overrides=dict(_table(f"{sec}.overrides", data.get("overrides", {}))),
            load_share=share,
        )

    def to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"name": self.name}
        if self.preset:
            out["preset"] = self.preset
        if self.path:
            out["path"] = self.path
        if self.overrides:
            out["overrides"] = dict(self.overrides)
        if self.load_share:
            out["load_share"] = dict(self.load_share)
        return out


#: largest oil flow of a scene's supply [m^3/s]: 1e4 L/min. Jet and circulating supplies give
#: a bearing of order 0.1-100 L/min (the largest bearings a few hundred), so 1e4 L/min is
#: beyond any bearing; the oil's heat capacity rate is then ~2.8e5 W/K (ISO VG 68 at 40 degC),
#: which holds the oil node at its inlet temperature as well as any larger flow would (an
#: SKF 6304 at 3000 r/min: the same final temperatures at 100 and 1e8 L/min). 1e150 L/min
#: stopped the transient in the network stepper with "temperature = nan"
MAX_FLOW = 1e4 / 60_000.0
MAX_FLOW_ALLOWED = ("a flow from 0 to 1e4 L/min (0.167 m^3/s): jet and circulating supplies "
                    "give a bearing of order 0.1-100 L/min; above 1e4 L/min the oil node "
                    "sits at its inlet temperature whatever the flow")

#: what a grease supply allows as its flow
GREASE_FLOW = ("0 or no flow for a grease fill: grease stays in the bearing, no stream carries "
               "heat away (a circulating or sprayed oil is method = \"circulation\" / "
               "\"jet\" / \"oil_air\")")


def check_below_runaway(name: str, raw: Any, kelvin: float) -> None:
    """Refuse a scene temperature at or above the runaway limit
    (:data:`thermobearing.coupled.RUNAWAY_TEMPERATURE`, 300 degC): a node heads for the
    inlet, ambient or initial temperature and the run stops there as a thermal runaway
    (a sweep refuses such a value with the same words,
    :func:`thermobearing.sweep_params.parse_set`).

    ``name``: the scene field; ``raw``: the value as written; ``kelvin``: it read in K.
    A bare number is read in kelvin: the refusal gives that reading in degC too
    (``inlet_temperature = 600`` is 600 K = 326.85 degC)."""
    from .coupled import RUNAWAY_TEMPERATURE

    if kelvin < RUNAWAY_TEMPERATURE:
        return
    bare = isinstance(raw, int | float) and not isinstance(raw, bool)
    how = (f"; a bare number is read in kelvin ({raw:g} K = {kelvin - 273.15:.6g} degC)"
           if bare else "")
    raise InputError(name, raw, f"a temperature below the {RUNAWAY_TEMPERATURE - 273.15:g} "
                     "degC runaway limit (a run stops as a thermal runaway there)" + how)


@dataclass(frozen=True)
class Supply:
    """Oil supply: method, volume flow [m^3/s], inlet temperature [K], bath level [m].

    ``inlet_given``: whether the scene gave the inlet temperature; one it did not give is
    the ambient temperature and is left out of :meth:`to_dict`, so a scene changed at
    ``environment.ambient_temperature`` (a sweep, a calibration) moves it along.
    """

    method: str = "jet"
    flow: float = 0.0
    inlet_temperature: float = 308.15
    level: float | None = None
    inlet_given: bool = field(default=True, compare=False, repr=False)
    #: the unit the scene wrote the flow in (``"mm**3/h"`` for oil-air), used to write it
    #: back, by a sweep's bare numbers and by the report
    flow_unit: str = field(default="L/min", compare=False, repr=False)
    #: the units the scene wrote the inlet temperature (``"K"``, ``"degF"``) and the bath
    #: level (``"cm"``) in, kept for the same reasons: a scene written in kelvin swept with
    #: ``--set supply.inlet_temperature=300,350`` means kelvin, not 300 degC
    temperature_unit: str = field(default="degC", compare=False, repr=False)
    level_unit: str = field(default="mm", compare=False, repr=False)

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
        if flow > MAX_FLOW * (1.0 + 1e-12):  # the limit as written: 1e4 L/min converts to
            # 0.1666666666666667 m^3/s, an ulp above 1e4 / 60000, and was refused
            # 1e150 L/min stopped the transient inside the stepper as "temperature = nan"
            raw = data.get("flow")
            # flow = 2 meant as 2 L/min is 2 m^3/s: the refusal said only the range
            bare = (f"; a bare number in a scene is in m^3/s ({raw:g} m^3/s = "
                    f"{flow * 60_000.0:.6g} L/min): write the unit, e.g. \"{raw:g} L/min\""
                    if isinstance(raw, int | float) and not isinstance(raw, bool) else "")
            raise InputError("supply.flow", raw, MAX_FLOW_ALLOWED + bare)
        if method == "grease" and flow > 0:
            # the network took it as an oil stream through the bearing: a 5 L/min "grease"
            # cooled an SKF 6304 from 42 to 21 degC
            raise InputError("supply.flow", data.get("flow"), GREASE_FLOW)
        t_in = _quantity(data.get("inlet_temperature", ambient), "temperature",
                     field="supply.inlet_temperature")
        if t_in <= 0:
            raise InputError("supply.inlet_temperature", data.get("inlet_temperature"),
                             "a temperature above absolute zero")
        if "inlet_temperature" in data:  # one taken from the ambient is checked there
            check_below_runaway("supply.inlet_temperature", data["inlet_temperature"], t_in)
        level = data.get("level")
        level_si = None if level is None else _quantity(level, "length", "supply.level")
        if level_si is not None and level_si < 0:
            raise InputError("supply.level", level, "an oil level >= 0")
        if method == "oil_bath" and level_si is None:
            raise InputError("supply.level", None, "an oil level for an oil bath")
        return cls(method=method, flow=flow, inlet_temperature=t_in, level=level_si,
                   inlet_given="inlet_temperature" in data,
                   flow_unit=_unit_of(data.get("flow"), "volume_flow", "L/min"),
                   temperature_unit=_unit_of(data.get("inlet_temperature"), "temperature",
                                             "degC"),
                   level_unit=_unit_of(level, "length", "mm"))

    def to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"method": self.method, "flow": _fmt(self.flow, self.flow_unit)}
        if self.inlet_given:
            out["inlet_temperature"] = _fmt(self.inlet_temperature, self.temperature_unit)
        if self.level is not None:
            out["level"] = _fmt(self.level, self.level_unit)
        return out


@dataclass(frozen=True)
class Environment:
    """Ambient and initial temperatures [K].

    ``initial_given``: whether the scene gave the initial temperature; one it did not give
    is the ambient temperature and is left out of :meth:`to_dict`, so a scene changed at
    ``ambient_temperature`` (a sweep, a calibration) starts at the new ambient.
    """

    ambient_temperature: float = 308.15
    initial_temperature: float = 308.15
    initial_given: bool = field(default=True, compare=False, repr=False)
    #: the units the scene wrote the two temperatures in (``"K"``, ``"degF"``), used to
    #: write them back and by a sweep's bare numbers
    ambient_unit: str = field(default="degC", compare=False, repr=False)
    initial_unit: str = field(default="degC", compare=False, repr=False)

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
            if name in data or name == "ambient_temperature":
                check_below_runaway(f"environment.{name}", data.get(name, "35 degC"), v)
        return cls(ambient_temperature=amb, initial_temperature=ini,
                   initial_given="initial_temperature" in data,
                   ambient_unit=_unit_of(data.get("ambient_temperature"), "temperature",
                                         "degC"),
                   initial_unit=_unit_of(data.get("initial_temperature"), "temperature",
                                         "degC"))

    def to_dict(self) -> dict[str, Any]:
        out = {"ambient_temperature": _fmt(self.ambient_temperature, self.ambient_unit)}
        if self.initial_given:
            out["initial_temperature"] = _fmt(self.initial_temperature, self.initial_unit)
        return out


@dataclass(frozen=True)
class Measured:
    """Measured temperatures: a rig's thermocouple file with a time column and a
    column -> node map (formats: :func:`thermobearing.measured.read_measured_file`).

    ``time_column``: a column name, or ``[date column, time-of-day column]``.
    ``time_zero``: the instant of the scene's t = 0 in the time column's own format (a
    timestamp, ``hh:mm:ss`` or a number in the column's unit) or ``"first"`` (the first
    row); None: the first row for timestamps, the values as they are otherwise.
    ``time_format``: how to read the time column when the file cannot say it: ``"excel"``,
    ``"excel_1904"`` (day numbers), ``"unix"`` (seconds since 1970) or a strptime pattern
    (``"%d/%m/%Y %H:%M:%S"``); None: detected (:mod:`thermobearing.measured_time`).
    ``missing_values``: the logger's dropout codes, numbers in the file's unit (``-999``,
    ``9999.9``) or texts (``"OPEN"``); their readings are gaps, counted per sensor.
    """

    file: str
    columns: Mapping[str, str]
    time_column: str | tuple[str, str] = "time [min]"
    unit: str = "degC"
    time_zero: str | None = None
    time_format: str | None = None
    missing_values: tuple[float | str, ...] | None = None

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Measured:
        from .measured_time import check_time_format

        _check_keys("measured", data, ("file", "columns", "time_column", "unit", "time_zero",
                                       "time_format", "missing_values"))
        time_format = data.get("time_format")
        if time_format is not None and not isinstance(time_format, str):
            raise InputError("measured.time_format", time_format,
                             "a text: excel, excel_1904, unix or a strptime pattern")
        check_time_format(time_format, "measured")
        missing = data.get("missing_values")
        if missing is not None:
            if isinstance(missing, str | int | float) and not isinstance(missing, bool):
                missing = [missing]
            if (not isinstance(missing, list | tuple) or not missing
                    or any(isinstance(v, bool) or not isinstance(v, str | int | float)
                           or (isinstance(v, str) and not v.strip()) for v in missing)):
                raise InputError("measured.missing_values", missing,
                                 "a list of the logger's dropout codes: numbers in the "
                                 "file's unit or texts, e.g. [-999, 9999.9, \"OPEN\"]")
            missing = tuple(missing)
        from .measured_layout import TEMPERATURE_UNITS

        unit = data.get("unit", "degC")
        # the spellings a logger's header may use ("°C", "celsius", "℉"), not a bare C / F
        # (coulomb, farad to the unit reader)
        spelled = (TEMPERATURE_UNITS.get(unit.strip().lower())
                   if isinstance(unit, str) and unit.strip().lower() not in ("c", "f")
                   else None)
        if unit not in ("degC", "K", "degF") and spelled is None:
            raise InputError("measured.unit", unit, "degC, K or degF (or °C, °F, kelvin, "
                             "celsius, fahrenheit)")
        unit = spelled or unit
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
        elif not isinstance(tcol, str) or not tcol.strip():
            # (a number was looked for as a header cell and found in a data row: "a
            # column of the file: 5, 30")
            raise InputError("measured.time_column", tcol, "a column name (a text such as "
                             "\"time [min]\"), or the names of a date column and a "
                             "time-of-day column [\"date\", \"time\"]")
        file = _require("measured", data, "file")
        if not isinstance(file, str) or not file.strip():
            raise InputError("measured.file", file, "a data file path (a text)")
        return cls(file=file, columns=dict(cols),
                   time_column=tcol, unit=unit,
                   time_zero=None if zero is None else str(zero).strip(),
                   time_format=time_format, missing_values=missing)

    def to_dict(self) -> dict[str, Any]:
        tcol = self.time_column
        out = {"file": self.file, "columns": dict(self.columns),
               "time_column": tcol if isinstance(tcol, str) else list(tcol),
               "unit": self.unit}
        if self.time_zero is not None:
            out["time_zero"] = self.time_zero
        if self.time_format is not None:
            out["time_format"] = self.time_format
        if self.missing_values is not None:
            out["missing_values"] = list(self.missing_values)
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

    ``chunk`` [s]: the coupling interval (kinematic state and heat model held);
    ``kinematics_tolerance``: relative change of the contact viscosity that re-solves the
    kinematics at a chunk start; ``chunk_viscosity_limit``: the largest relative change of
    that viscosity within one chunk -- a chunk that exceeds it is repeated at half the length
    (down to ``MIN_CHUNK`` = 0.1 s), so a cold start straight to a high speed, where the
    elements heat by tens of kelvin per second, does not run on a kinematic state the
    temperatures left long ago (:func:`thermobearing.coupled._run_transient`).
    """

    stepper: str = "exprb43"
    rtol: float = 1e-7
    atol: float = 1e-5
    kinematics_tolerance: float = 0.03
    max_step: float = 600.0
    chunk: float = 90.0
    chunk_viscosity_limit: float = 0.25

    #: field -> (what is allowed, exclusive upper bound); the lower bound is 0, exclusive
    _LIMITS = {"rtol": ("a relative tolerance in (0, 1)", 1.0),
               "atol": ("an absolute tolerance > 0 (K)", math.inf),
               "kinematics_tolerance": ("a relative viscosity change in (0, 1)", 1.0),
               "chunk_viscosity_limit": ("a relative viscosity change > 0", math.inf),
               "max_step": ("a time > 0 [s]", math.inf), "chunk": ("a time > 0 [s]", math.inf)}

    def __post_init__(self) -> None:
        # the limits of from_dict also for a Solver built or replaced in code
        if not isinstance(self.stepper, str):
            raise InputError("solver.stepper", self.stepper, "a stepper name (a string)")
        for key, (allowed, high) in self._LIMITS.items():
            v = getattr(self, key)
            if isinstance(v, bool) or not isinstance(v, int | float) or not (
                    math.isfinite(v) and 0.0 < v < high):
                raise InputError(f"solver.{key}", v, allowed)
            object.__setattr__(self, key, float(v))

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Solver:
        names = [f.name for f in fields(cls)]
        _check_keys("solver", data, names)
        kw: dict[str, Any] = {}
        if "stepper" in data:
            if not isinstance(data["stepper"], str):
                raise InputError("solver.stepper", data["stepper"], "a stepper name (a string)")
            kw["stepper"] = data["stepper"]
        limits = {k: v for k, v in cls._LIMITS.items() if k not in ("max_step", "chunk")}
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
                "chunk_viscosity_limit": self.chunk_viscosity_limit,
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

    def __post_init__(self) -> None:
        # here, not in from_dict only: an Outputs built or replaced in code
        # (dataclasses.replace(scene.outputs, want=("lossess",))) ran a film-only scene
        if self.mode not in OUTPUT_MODES:
            raise UnknownNameError("outputs.mode", self.mode, OUTPUT_MODES)
        if isinstance(self.want, str) or not isinstance(self.want, list | tuple):
            raise InputError("outputs.want", self.want,
                             "an array of output names, e.g. [\"temperatures\", \"losses\"]")
        for w in self.want:
            if w not in OUTPUT_KINDS:
                raise UnknownNameError("outputs.want", w, OUTPUT_KINDS)
        object.__setattr__(self, "want", tuple(self.want))
        if self.interval is not None:
            check_positive("outputs.interval", self.interval)

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Outputs:
        _check_keys("outputs", data, ("mode", "want", "interval"))
        interval = None
        if "interval" in data:
            interval = _quantity(data["interval"], "time", "outputs.interval")
            if not interval > 0:
                raise InputError("outputs.interval", data["interval"], "a time > 0")
        return cls(mode=data.get("mode", "transient"), want=data.get("want", cls.want),
                   interval=interval)

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
