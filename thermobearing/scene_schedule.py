"""The ``[schedule]`` table of a scene: the operating steps (duration, speed, loads) from
defaults, an axial-load sweep, an array of steps or a CSV protocol file.
"""

from __future__ import annotations

import csv
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import InputError, check_finite, check_positive
from .scene_values import _check_keys, _fmt, _quantity, _require, _table, _unit_of
from .text_files import text_encoding


@dataclass(frozen=True)
class Step:
    """One schedule step: duration [s], inner-ring speed [rad/s], loads [N]."""

    duration: float
    speed: float
    radial_load: float
    axial_load: float

    def __post_init__(self) -> None:
        # the rules of a scene's steps also for a Step built or replaced in code
        # (dataclasses.replace(step, radial_load=-10.0) was reported as "0 kN" by a later
        # check, a negative duration ran)
        for key in _STEP_KEYS:
            check_finite(f"step.{key}", getattr(self, key))
            object.__setattr__(self, key, float(getattr(self, key)))
        check_positive("step.duration", self.duration)
        check_positive("step.speed", self.speed, allow_zero=True)
        check_positive("step.radial_load", self.radial_load, allow_zero=True)
        _check_bounds({k: getattr(self, k) for k in _STEP_KEYS}, {}, "step")
        # axial: any sign here (a bearing's own steps carry a negative load_share's reversed
        # load, simulation_bearings); a scene's steps are >= 0 (_make_step)


_STEP_KEYS = ("duration", "speed", "radial_load", "axial_load")
#: most steps an ``axial_load_steps`` table makes: each step is a solve of its own (a
#: second to minutes), so more are days of computing; a typo in the step (1 mN for 1 kN)
#: is refused before a billion steps are built
MAX_LOAD_STEPS = 10_000
_STEP_KINDS = {"duration": "time", "speed": "angular_speed", "radial_load": "force",
               "axial_load": "force"}
_STEP_UNITS = {"duration": "min", "speed": "rpm", "radial_load": "kN", "axial_load": "kN"}
#: highest step speed [rad/s]: 1e6 r/min, twice the ~5e5 r/min of dental-turbine bearings,
#: the fastest rolling bearings in service (spindles and turbochargers run at n d_m up to
#: ~4e6 mm r/min, far below it for any bearing of a few mm bore). 1e300 r/min stopped the
#: skidding solver with a bare OverflowError (the balls' centrifugal force)
MAX_SPEED = 1e6 * 2.0 * math.pi / 60.0
#: highest step load [N]: 1 GN, ten times the static load rating of the largest rolling
#: bearings built (slewing and tunnel-boring-machine main bearings of several metres, C0
#: of order 1e8 N). 1e300 N stopped the load distribution with "residual nan"
MAX_LOAD = 1e9


def _make_step(values: Mapping[str, Any], defaults: Mapping[str, float], where: str,
               written: Mapping[str, Any] | None = None) -> Step:
    """One step from its own ``values`` and the ``[schedule]`` ``defaults`` [SI];
    ``written``: the defaults as the scene wrote them (``"-3 krpm"``), shown in an error
    instead of the SI number (``-314.159``)."""
    _check_keys(where, values, _STEP_KEYS)
    out = dict(defaults)
    values = {**(written or {}), **values} if written else values
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
    _check_bounds(out, values, where)
    return Step(**{k: float(out[k]) for k in _STEP_KEYS})


def _check_defaults(defaults: Mapping[str, float], written: Mapping[str, Any],
                    dur_key: str) -> None:
    """The ``[schedule]`` defaults [SI] checked as a step's values are, the refusal naming
    the key the scene wrote (``schedule.step_duration = '-3 min'``; it named the first
    step that took it, ``schedule.axial_load_steps[0].duration``, a field not in the
    file)."""
    names = {"duration": dur_key}
    for key, value in defaults.items():
        field = f"schedule.{names.get(key, key)}"
        shown = written.get(key, value)
        if key == "duration" and not value > 0:
            raise InputError(field, shown, "a duration > 0")
        if key in ("radial_load", "axial_load") and value < 0:
            raise InputError(field, shown, "a load >= 0")
        if key == "speed" and value < 0:
            raise InputError(field, shown, "a speed >= 0")
    _check_bounds({k: defaults.get(k, 0.0) for k in ("speed", "radial_load", "axial_load")},
                  {k: v for k, v in written.items() if k != "duration"}, "schedule")


def _check_bounds(out: Mapping[str, float], values: Mapping[str, Any], where: str) -> None:
    """A step's speed and loads [SI] within :data:`MAX_SPEED` / :data:`MAX_LOAD`, the
    refusal naming the field and the value as written."""
    if out["speed"] > MAX_SPEED:
        raise InputError(f"{where}.speed", values.get("speed", out["speed"]),
                         "a speed from 0 to 1e6 rpm (1.047e5 rad/s): faster than any rolling "
                         "bearing runs (dental-turbine bearings, the fastest in service, run "
                         "at about 5e5 rpm)")
    for key in ("radial_load", "axial_load"):
        if abs(out[key]) > MAX_LOAD:
            raise InputError(f"{where}.{key}", values.get(key, out[key]),
                             "a load from 0 to 1e9 N (1 GN, ten times the static load rating "
                             "of the largest rolling bearings built)")


def _note_units(units: dict[str, str], values: Mapping[str, Any]) -> None:
    """Record the unit of each step quantity the scene writes with one (the first wins)."""
    for key, raw in values.items():
        if key in _STEP_KINDS and key not in units and isinstance(raw, str):
            unit = _unit_of(raw, _STEP_KINDS[key], "")
            if unit:
                units[key] = unit


@dataclass(frozen=True)
class Schedule:
    """The protocol: a tuple of steps run one after the other.

    ``units``: the unit the scene wrote each step quantity in (``{"axial_load": "N"}``);
    :meth:`to_dict` writes the steps in them (else min, rpm, kN), so a sweep's bare numbers
    are in the scene's own unit (``--set schedule.axial_load=300,800`` after ``"500 N"``
    means newtons).
    """

    steps: tuple[Step, ...]
    units: Mapping[str, str] = field(default_factory=dict, compare=False, repr=False)
    #: notes on step speeds and durations the scene wrote as bare numbers (read in SI:
    #: rad/s and s), :func:`unitless_notes`; a run and ``check`` print them
    unitless: tuple[str, ...] = field(default=(), compare=False, repr=False)

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
        written = {k: data[k] for k in ("speed", "radial_load", "axial_load") if k in data}
        if dur_key in data:
            written["duration"] = data[dur_key]
        units: dict[str, str] = {}
        _note_units(units, {k: data[k] for k in ("speed", "radial_load", "axial_load")
                            if k in data})
        if dur_key in data:
            _note_units(units, {"duration": data[dur_key]})
        _check_defaults(defaults, written, dur_key)
        forms = [k for k in ("axial_load_steps", "steps", "file") if k in data]
        if len(forms) > 1:
            raise InputError("schedule", forms, "only one of axial_load_steps, steps or file")
        steps: list[Step] = []
        file_notes: list[str] = []  # columns of a schedule file without a unit
        if not forms:
            if "duration" not in defaults:
                defaults["duration"] = 3600.0
            steps.append(_make_step({}, defaults, "schedule", written))
        elif forms[0] == "axial_load_steps":
            sweep = _table("schedule.axial_load_steps", data["axial_load_steps"])
            _check_keys("schedule.axial_load_steps", sweep, ("start", "stop", "step"))
            a0 = _quantity(_require("schedule.axial_load_steps", sweep, "start"), "force",
                       field="schedule.axial_load_steps.start")
            _note_units(units, {"axial_load": sweep["start"]})
            a1 = _quantity(_require("schedule.axial_load_steps", sweep, "stop"), "force",
                       field="schedule.axial_load_steps.stop")
            da = _quantity(_require("schedule.axial_load_steps", sweep, "step"), "force",
                       field="schedule.axial_load_steps.step")
            if da <= 0 or a1 < a0:
                raise InputError("schedule.axial_load_steps", dict(sweep),
                                 "start <= stop and step > 0")
            count = (a1 - a0) / da + 1.0
            if not count <= MAX_LOAD_STEPS:  # (0 N to 1 MN by 1 mN: 1e9 steps, hung)
                raise InputError("schedule.axial_load_steps", dict(sweep),
                                 f"at most {MAX_LOAD_STEPS} steps (these give {count:.3g}: "
                                 "a larger step?)")
            n = int(math.floor((a1 - a0) / da + 1e-9)) + 1
            for i in range(n):
                steps.append(_make_step({}, {**defaults, "axial_load": a0 + i * da},
                                        f"schedule.axial_load_steps[{i}]",
                                        {k: v for k, v in written.items()
                                         if k != "axial_load"}))
        elif forms[0] == "steps":
            items = data["steps"]
            if not isinstance(items, list):
                raise InputError("schedule.steps", items,
                                 "an array of tables, e.g. [{ duration = \"3 min\" }, ...]")
            for i, item in enumerate(items):
                where = f"schedule.steps[{i}]"
                steps.append(_make_step(_table(where, item), defaults, where, written))
                _note_units(units, item)
        else:
            steps.extend(_read_schedule_file(data["file"], defaults, base_dir, units,
                                             file_notes))
        if not steps:
            raise InputError("schedule", dict(data), "at least one step")
        bare = [(f"schedule.{k}", k, data[k]) for k in ("speed", dur_key) if k in data]
        if forms and forms[0] == "steps":
            bare += [(f"schedule.steps[{i}].{k}", k, item[k])
                     for i, item in enumerate(data["steps"]) for k in ("speed", "duration")
                     if k in item]
        return cls(steps=tuple(steps), units=units,
                   unitless=unitless_notes(bare) + tuple(file_notes))

    def to_dict(self) -> dict[str, Any]:
        units = {**_STEP_UNITS, **self.units}
        return {
            "steps": [
                {k: _fmt(getattr(s, k), units[k]) for k in _STEP_KEYS} for s in self.steps
            ]
        }


def unitless_notes(values: list[tuple[str, str, Any]]) -> tuple[str, ...]:
    """Notes on step speeds and durations written as bare numbers, ``values`` being
    ``(field, key, raw)`` as the scene wrote them (``key``: ``speed``, ``duration`` or
    ``step_duration``). A bare number in a scene is SI, so ``speed = 3000`` is 3000 rad/s
    (28648 r/min, not 3000 r/min) and ``duration = 10`` is 10 s: both run without
    complaint (within the bounds), which a rig protocol meant in r/min and minutes did with
    speeds 9.5 times too high or steps 60 times too short. One note per quantity, naming
    its first field, how many more there are, and the reading; zero (a stop) is the same
    in every unit and not noted."""
    notes = []
    for key, unit, per, other, spellings in (
            ("speed", "rad/s", 30.0 / math.pi, "r/min", ("rpm", "rad/s")),
            ("duration", "s", 1.0 / 60.0, "min", ("min", "s"))):
        hits = [(f, float(raw)) for f, k, raw in values
                if k.removeprefix("step_") == key and isinstance(raw, int | float)
                and not isinstance(raw, bool) and raw != 0]
        if not hits:
            continue
        where, raw = hits[0]
        more = (f" (and {len(hits) - 1} more {key} value{'s' if len(hits) > 2 else ''} "
                "without a unit)") if len(hits) > 1 else ""
        notes.append(f"{where} = {raw:g}{more} has no unit: a bare number in a scene is SI, "
                     f"read as {raw:g} {unit} = {raw * per:.6g} {other}; write the unit, "
                     f"\"{raw:g} {spellings[0]}\" or \"{raw:g} {spellings[1]}\"")
    return tuple(notes)


def _read_schedule_file(name: str, defaults: Mapping[str, float],
                        base_dir: Path | None, seen_units: dict[str, str],
                        notes: list[str] | None = None) -> list[Step]:
    """The steps of a CSV protocol file: a header of ``duration [s], speed [rpm],
    radial_load [N], axial_load [N]`` (any of them may be left to the ``[schedule]``
    defaults; the units in brackets, these by default), comma separated, or semicolon / tab
    separated with decimal commas as spreadsheets export them; a UTF-8 BOM is skipped, rows
    with every cell empty (a spreadsheet's trailing ``,,,``) are skipped, and so are empty
    cells past the header's last column. Headers are read case-insensitively; a column whose
    header gives no unit may carry one in each cell (``10 s``); in a file with decimal
    commas a point groups thousands (``1.000``). A duplicated column or a row with more
    filled cells than the header has columns is an error naming it. ``notes`` gets a line
    per column without a unit whose cells are bare numbers (read in the default unit: a
    ``duration`` of 10 is 10 s)."""
    if not isinstance(name, str) or not name.strip():  # ({a = 1} stopped in pathlib)
        raise InputError("schedule.file", name, "a CSV file path (a text)")
    path = Path(name)
    if not path.is_absolute() and base_dir is not None:
        path = base_dir / path
    if not path.is_file():
        raise InputError("schedule.file", name, "an existing CSV file")
    units = {"duration": "s", "speed": "rpm", "radial_load": "N", "axial_load": "N"}
    steps = []
    # UTF-8 (a BOM skipped), UTF-16 after its mark (Excel's "Unicode text"), else the
    # Windows ANSI code page; undecodable bytes replaced (the header check then names them)
    with path.open(newline="", encoding=text_encoding(path), errors="replace") as fh:
        first = fh.readline()
        fh.seek(0)
        delim = "," if "," in first else next((d for d in (";", "\t") if d in first), ",")
        reader = csv.DictReader(fh, delimiter=delim)
        colmap: dict[str, str] = {}
        unit_given: dict[str, bool] = {}
        for col in reader.fieldnames or []:
            key, _, unit = col.partition("[")
            key = key.strip().lower()  # "Duration [s]" as spreadsheets capitalise it
            if key not in _STEP_KEYS:
                raise InputError(f"schedule.file column {col!r}", col,
                                 "columns named " + ", ".join(_STEP_KEYS) + " with [unit], "
                                 "separated by commas (or semicolons / tabs)")
            if key in colmap.values():
                raise InputError(f"schedule.file column {col!r}", col,
                                 f"one column per quantity ({key} is given twice)")
            colmap[col] = key
            unit_given[key] = bool(unit)
            if unit:
                units[key] = unit.rstrip("] ")
        rows = list(reader)
        comma_decimals = delim != "," and any(
            _comma_decimal((v or "").strip()) for row in rows
            for c, v in row.items() if c is not None)
        for i, row in enumerate(rows):
            if any((v or "").strip() for v in row.get(None, ())):
                raise InputError(f"schedule.file row {i + 1}", delim.join(row[None]),
                                 f"at most {len(colmap)} cells, one per header column "
                                 "(extra cells)")
            row.pop(None, None)
            if not any((v or "").strip() for v in row.values()):
                continue
            values = {colmap[c]: _cell(v, colmap[c], units[colmap[c]], unit_given[colmap[c]],
                                       comma_decimals, f"schedule.file row {i + 1}")
                      for c, v in row.items() if v and v.strip()}
            steps.append(_make_step(values, defaults, f"schedule.file row {i + 1}"))
            _note_units(seen_units, values)
    if notes is not None:
        for col, key in colmap.items():
            bare = [v.strip() for row in rows if (v := row.get(col)) and _bare_cell(v)]
            if not unit_given[key] and bare:
                notes.append(f"schedule.file {path.name}: column {col!r} has no [unit]: its "
                             f"numbers are read in {units[key]} ({bare[0]} = {bare[0]} "
                             f"{units[key]}); write the unit in the header, e.g. "
                             f"'{key} [{_OTHER_UNIT[key]}]'")
    return steps


#: a unit to suggest for a schedule file's column header
_OTHER_UNIT = {"duration": "min", "speed": "rpm", "radial_load": "kN", "axial_load": "kN"}


def _bare_cell(cell: str) -> bool:
    """A cell holding a plain number (no unit), decimal comma or point."""
    try:
        float(cell.strip().replace(",", "."))
    except ValueError:
        return False
    return True


#: a number with a decimal comma ("2,5", "-0,25")
_DECIMAL_COMMA = re.compile(r"^[-+]?\d*,\d+")
#: a number grouped in thousands with points, as decimal-comma locales write it ("1.000",
#: "12.500,5")
_THOUSANDS_POINTS = re.compile(r"^[-+]?\d{1,3}(\.\d{3})+(,\d*)?$")


def _comma_decimal(cell: str) -> bool:
    """Whether a cell writes a decimal comma: ``2,5``, or grouped thousands with one
    (``1.031,5``, ``1.031,5 r/min``). A file whose only decimal-comma cells were grouped
    read its commas as part of the unit (``'1.031,5 r/min'``: 'a known unit')."""
    number = cell.partition(" ")[0]
    return bool(_DECIMAL_COMMA.match(number)) or (
        "," in number and bool(_THOUSANDS_POINTS.match(number)))


def _cell(cell: str, key: str, unit: str, unit_given: bool, comma_decimals: bool,
          where: str) -> str:
    """A protocol cell as a quantity string: its number in the column's unit (the header's
    ``[unit]``, else the default), or the cell as written when the header gives no unit and
    the cell carries one (``10 s``). In a file with decimal commas (separated by semicolons
    or tabs) a point groups thousands (``1.000`` = 1000); a point elsewhere there is an
    error, as is a unit in the cell of a column whose header gives one."""
    text = cell.strip()
    number, _, rest = text.partition(" ")
    rest = rest.strip()
    if rest and unit_given:
        raise InputError(f"{where}.{key}", text, f"a bare number: the column header gives "
                         f"the unit [{unit}]")
    if comma_decimals:
        if "." in number:
            if not _THOUSANDS_POINTS.match(number):
                raise InputError(f"{where}.{key}", text, "a number with a decimal comma, as "
                                 "the other cells of this file write them (points group "
                                 "thousands: 1.000,5)")
            number = number.replace(".", "")
        number = number.replace(",", ".")
    return f"{number} {rest or unit}"
