"""The ``--set`` parameter language of a sweep: dotted scene paths and their values.

``--set supply.flow=15,20,25,33`` or ``--set schedule.speed=600:1800:300`` names a field of
the scene by its dotted path and gives its values (:func:`parse_set`); :func:`check_path`
says whether a sweep (or a calibration fit) may set that path, :func:`get_path` and
:func:`assign_path` read and write it in a scene dict.

Values: a comma list (``15,20,25,33``) or a range ``start:stop:step`` (stop included).
A bare number takes the unit the scene uses for that field (``schedule.speed=600:1800:300``
with a scene written in rpm means rpm; a field the scene leaves out takes
:data:`DISPLAY_UNITS` / :data:`PATH_UNITS`: L/min, degC, % for ``checks.skid_limit``, MPa
for the contact-stress limits); a unit may be given after the list
(``supply.flow=15,33 L/min``) or with each value. Text values are presets
(``lubricant.preset=ISO_VG32,ISO_VG68``); ``lubricant.path=my_oil.toml`` replaces the
scene's preset, and a relative file is read from the current folder when it is there (else
from the scene's folder). A repeated value (the same quantity) is dropped
and reported in :attr:`SweepParameter.dropped`. ``schedule.<field>`` sets that field in
every step; ``checks.<threshold>`` sets a validity-check threshold (no physics changes).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .errors import InputError

DISPLAY_UNITS = {  # display unit used when the scene's own value carries none
    "speed": "rpm", "radial_load": "kN", "axial_load": "kN", "duration": "min",
    "flow": "L/min", "inlet_temperature": "degC", "ambient_temperature": "degC",
    "initial_temperature": "degC", "level": "mm",
}
#: display units of whole paths (checked before DISPLAY_UNITS): the [checks] thresholds of
#: operating_checks, so that a bare 2 means 2 % and a bare 3500 means 3500 MPa
PATH_UNITS = {
    "checks.skid_limit": "%", "checks.contact_stress_limit": "MPa",
    "checks.contact_stress_limit.ball": "MPa",
    "checks.contact_stress_limit.self_aligning_ball": "MPa",
    "checks.contact_stress_limit.roller": "MPa",
}


#: most cases one sweep builds: each is a whole scene run (seconds to minutes), so that
#: many are days of computing; a range of more values (``1:1e9:1``) is refused before its
#: values are made, and so is a cartesian product of more cases (sweep_cases.expand)
MAX_SWEEP_CASES = 10_000


@dataclass(frozen=True)
class SweepParameter:
    """One swept field: dotted path and its values (TOML-ready strings or numbers).

    ``dropped``: values of the ``--set`` text left out because they repeat an earlier one
    (the same quantity, e.g. ``15`` after ``15 L/min``), as ``"'15' (= '15 L/min')"``.
    ``notes``: what the sweep says before its runs about values it reads in a way the
    user may not have meant (:func:`_temperature_notes`: a bare 313 read as 313 degC).
    """

    path: str
    values: tuple[Any, ...]
    dropped: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()


#: a quantity as a scene writes it: a number, then its unit with or without a space
_QUANTITY = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*(.*?)\s*$")
#: significant digits of a swept number written back into the scene (a double's 15, less
#: the float noise of a range's start + i * step)
_DIGITS = 12


def _split_unit(text: str) -> tuple[str, str]:
    """``"15,33 L/min"`` -> ``("15,33", "L/min")``: the numbers (ending in a digit or a dot),
    then the unit (whatever follows, starting with a letter or ``%``). Text that does not
    start with numbers comes back whole with no unit."""
    m = re.match(r"^\s*([-+0-9.eE:,\s]*[0-9.])\s*([A-Za-z%].*?)?\s*$", text)
    if not m:
        return text, ""
    return m.group(1), (m.group(2) or "").strip()


def _range_value(a: float, b: float, d: float, i: int) -> float:
    """Value ``i`` of the range ``a:b:d``, rounded to :data:`_DIGITS` significant digits of
    the range's scale max(|a|, |b|, d) rather than of the value itself: a value that cancels
    to zero kept the noise of the cancellation ("-0.3:0.3:0.1" wrote 5.55111512313e-17 degC
    for 0 degC, "-4903.50:5464.23:80.37" -0.929999999999 for -0.93)."""
    v = a + i * d
    scale = max(abs(a), abs(b), d)
    if scale > 0.0 and math.isfinite(scale):
        v = round(v, _DIGITS - 1 - math.floor(math.log10(scale)))
    return v + 0.0 if v != 0.0 else 0.0  # no "-0"


def _number(text: str, field: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise InputError(field, text, "a number (several values are separated by commas: "
                         "15,20,33 or 15,20,33 L/min)") from None


def _existing_unit(scene_dict: Mapping[str, Any], path: str) -> str:
    """Unit of the field's current value in the scene (for bare sweep numbers); for a
    bearing override the scene does not set, the unit of the bearing preset's value
    (``bearings.0.overrides.diametral_clearance=0.1,0.2`` means mm for QJ1044, whose
    preset writes "0.10 mm")."""
    try:
        value = get_path(scene_dict, path)
    except (KeyError, IndexError, ValueError, TypeError):
        value = None
    parts = path.split(".")
    if value is None and len(parts) >= 4 and parts[0] == "bearings" and parts[2] == "overrides":
        value = bearing_file_value(scene_dict, parts[1], parts[3:])
    if isinstance(value, str):
        # the unit as the scene writes it, with or without a space ("95 degF", "95degF");
        # a power in pint's spelling as data sheets write it: the scene read "30 mm3/h"
        # and writes it back as "mm**3/h", which the sweep's values, summary column and
        # figure titles showed ("10 mm**3/h"); "mm3/h" is read the same
        m = _QUANTITY.match(value)
        if m and m.group(1):
            return re.sub(r"\*\*(\d+)", r"\1", m.group(1))
    return PATH_UNITS.get(path) or DISPLAY_UNITS.get(path.rsplit(".", 1)[-1], "")


def bearing_file_value(scene_dict: Mapping[str, Any], index: str, keys: Sequence[str]) -> Any:
    """The raw value of ``keys`` in the bearing TOML (preset or absolute path) of the
    scene's bearing ``index``; None when it cannot be read."""
    import tomllib

    from .scene import configs_dir

    try:
        bearing = scene_dict["bearings"][int(index)]
        if "preset" in bearing:
            file = configs_dir() / "bearings" / f"{bearing['preset']}.toml"
        else:
            file = Path(bearing["path"])
        cur: Any = tomllib.loads(file.read_text(encoding="utf-8"))
        for key in keys:
            cur = cur[key]
        return cur
    except (KeyError, IndexError, ValueError, TypeError, OSError, tomllib.TOMLDecodeError):
        return None


def parse_set(spec: str, scene_dict: Mapping[str, Any]) -> SweepParameter:
    """Parse one ``--set path=values`` argument against the scene it applies to."""
    if "=" not in spec:
        raise InputError("--set", spec, "'path=value1,value2,...' or 'path=start:stop:step'")
    path, raw = (s.strip() for s in spec.split("=", 1))
    if not path:
        raise InputError("--set", spec, "'path=value1,value2,...' or 'path=start:stop:step'")
    if not raw:
        # "supply.flow=" (an empty list): the error named no field and no reason
        raise InputError(f"--set {path}", raw, "at least one value: a comma list "
                         "(15,20,33) or a range start:stop:step")
    check_path(scene_dict, path)
    param = _checked_temperatures(_parse_values(path, raw, scene_dict), raw)
    note = _flattened_steps_note(scene_dict, path)
    return param if note is None else SweepParameter(param.path, param.values,
                                                     param.dropped, (*param.notes, note))


def _flattened_steps_note(scene_dict: Mapping[str, Any], path: str) -> str | None:
    """What ``schedule.<field>`` does to a protocol whose steps differ in that field: every
    step takes the case's value (:func:`assign_path`), so the steps' own values are gone.
    (Tour 22: ``--set schedule.speed=2000,4000`` on an NU 214 run-up of 3000 and 6000 r/min
    ran both steps at 2000, then at 4000 r/min, without a word; on the default rig
    ``schedule.axial_load`` replaces the 0-42 kN load steps by one load.)"""
    parts = path.split(".")
    if parts[0] != "schedule" or len(parts) != 2:
        return None
    steps = scene_dict.get("schedule", {}).get("steps")
    if not isinstance(steps, list) or len(steps) < 2:
        return None
    written = [step.get(parts[1]) for step in steps if isinstance(step, Mapping)]
    distinct = list(dict.fromkeys(str(v) for v in written))
    if len(distinct) < 2:
        return None
    shown = ", ".join(distinct[:4]) + (f", ... ({len(distinct)} values)"
                                       if len(distinct) > 4 else "")
    words = parts[1].replace("_", " ")
    return (f"sweep: {path} sets the {words} of every step: the scene's {len(steps)} "
            f"steps ({shown}) each run at the case's {words} instead of their own")


def _parse_values(path: str, raw: str, scene_dict: Mapping[str, Any]) -> SweepParameter:
    """The values of ``--set path=raw`` (``raw`` not empty, ``path`` checked)."""
    if ":" in raw:
        numbers, unit = _split_unit(raw)
        # "5 L/min:60 L/min:5 L/min" was refused as "a range start:stop:step", which it
        # looked like: say where the unit goes
        unit_here = _existing_unit(scene_dict, path)
        form = ("a range start:stop:step of numbers with one unit after it, e.g. 10:30:10"
                + (f" {unit_here}" if unit_here else ""))
        if not re.fullmatch(r"[-+0-9.eE:, ]+", numbers):
            raise InputError(f"--set {path}", raw, form)
        parts = numbers.split(":")
        if len(parts) != 3:
            raise InputError(f"--set {path}", raw, form)
        a, b, d = (_number(p, f"--set {path}") for p in parts)
        if d <= 0 or b < a:
            raise InputError(f"--set {path}", raw, "start <= stop and step > 0")
        count = (b - a) / d + 1.0
        if not count <= MAX_SWEEP_CASES:  # (1:1e9:1 built a billion values, then hung)
            raise InputError(f"--set {path}", raw, f"a range of at most {MAX_SWEEP_CASES} "
                             f"values (this one gives {count:.3g}: a larger step?)")
        n = int(math.floor((b - a) / d + 1e-9)) + 1
        unit = unit or _existing_unit(scene_dict, path)
        points = [_range_value(a, b, d, i) for i in range(n)]
        notes: tuple[str, ...] = ()
        if not math.isclose(points[-1], b, rel_tol=1e-9, abs_tol=1e-12 * max(abs(b), d)):
            # "1500:3000:1000" ran 1500 and 2500 r/min and never the 3000 written as its
            # stop, without a word
            unit_text = f" {unit}" if unit else ""
            notes = (f"sweep: {path} = {raw} runs {', '.join(f'{v:.{_DIGITS}g}' for v in points)}"
                     f"{unit_text}: the stop {b:g} is not the start plus a whole number of "
                     f"steps of {d:g}, so it is not run (a range runs start, start + step, "
                     "... up to the stop); add it to a comma list to run it",)
        return SweepParameter(path, tuple(f"{v:.{_DIGITS}g} {unit}" if unit else v
                                          for v in points), (), notes)
    pieces = [v.strip() for v in raw.split(",")]
    if pieces and not pieces[-1]:
        pieces = pieces[:-1]  # a trailing comma ("15,33,") adds nothing
    if "" in pieces[:-1] or (pieces and not pieces[-1]):
        # "15,,33": a value left out between commas (a typo of 15,25,33?) was dropped
        # without a word
        k = pieces.index("")
        raise InputError(f"--set {path}", raw, f"a value between every two commas (value "
                         f"{k + 1} is empty)")
    items = [v for v in pieces if v]
    if not items:
        raise InputError(f"--set {path}", raw, "at least one value")
    split = [_split_unit(v) for v in items]
    numeric = [bool(re.fullmatch(r"[-+0-9.eE ]+", num)) for num, _ in split]
    if not any(numeric):  # strings: lubricant presets, files etc.
        return _unique(path, _files_from_here(path, items), items)
    # each value may carry its own unit ("30 degC,50 degC"); a bare number takes the unit
    # written after the list ("15,33 L/min"), else the unit of the scene's current value.
    # A text among numbers ("15,abc") is passed on as written, so that the scene's check
    # names that value.
    last = max(i for i, ok in enumerate(numeric) if ok)
    trailing = split[last][1] or _existing_unit(scene_dict, path)
    own = [i for i, ok in enumerate(numeric) if ok and split[i][1] and i != last]
    bare = [i for i, ok in enumerate(numeric) if ok and not split[i][1]]
    if split[last][1] and own and bare:
        # "313.15 K,50,104 degF": a unit on other values too, so the last one's unit is
        # that value's own, not one written after the list; the bare 50 took it (50 degF)
        # where the scene's unit (degC) was as likely meant
        raise InputError(f"--set {path}", raw, f"a unit after the list for every value "
                         f"(15,33 L/min) or one with each value; here "
                         f"{items[bare[0]]!r} has none while other values carry their "
                         f"own: write its unit")
    values: list[Any] = []
    for item, (num, unit), ok in zip(items, split, numeric, strict=True):
        if not ok:
            values.append(item)
            continue
        x = _number(num.strip(), f"--set {path}")
        unit = unit or trailing
        if unit:
            values.append(f"{x:.{_DIGITS}g} {unit}")
        else:  # a count written as a whole number stays an integer (n_balls=18,20)
            values.append(int(num) if re.fullmatch(r"\s*[-+]?\d+\s*", num) else x)
    return _unique(path, values, items)


#: swept fields that are temperatures (a bare number is in the scene's unit, degC by default)
_TEMPERATURE_FIELDS = ("inlet_temperature", "ambient_temperature", "initial_temperature")
#: a bare temperature read at or above this [K] (150 degC) whose number read in kelvin is a
#: usual oil or room temperature (:data:`_KELVIN_LIKE`) is said: 313 typed for 313 K
_HOT_BARE = 423.15
#: numbers that read in kelvin as -50 to 150 degC
_KELVIN_LIKE = (223.15, 423.15)


def _checked_temperatures(param: SweepParameter, raw: str) -> SweepParameter:
    """``param`` with its temperatures checked: a value at or above the runaway limit
    (:data:`thermobearing.coupled.RUNAWAY_TEMPERATURE`, 300 degC) is refused (no run can
    pass it: a node heads for the inlet or ambient temperature, and the run stops as a
    thermal runaway), and a bare number that reads as a hot temperature in the scene's
    unit but as a usual one in kelvin is noted (:attr:`SweepParameter.notes`).

    (Tour 22: ``--set supply.inlet_temperature=313`` on an NU 214 scene written in degC,
    meant as 313 K, ran a 313 degC jet without a word: the oil node reached 285.6 degC and
    the rollers 236 degC, and the summary's only flag was the film limit.)"""
    if param.path.rsplit(".", 1)[-1] not in _TEMPERATURE_FIELDS:
        return param
    from .coupled import RUNAWAY_TEMPERATURE
    from .units import to_si

    bare = _split_unit(raw)[1] == ""  # no unit after the list (values may carry their own)
    notes = list(param.notes)
    for value in param.values:
        if not isinstance(value, str):
            continue
        number, _, unit = value.partition(" ")
        try:
            x = float(number)
            kelvin = to_si(value, "K", field=param.path)
        except (ValueError, InputError):
            continue  # not a quantity: the scene's check names it
        typed = bare and not _split_unit(_typed_item(raw, number))[1]
        hint = ""
        if typed and _KELVIN_LIKE[0] <= x <= _KELVIN_LIKE[1] and unit != "K":
            hint = (f"; a bare number is in {unit} here (the unit of this field in the "
                    "scene): "
                    f"for kelvin write '{x:g} K' ({x - 273.15:g} degC)")
        if not kelvin < RUNAWAY_TEMPERATURE:
            raise InputError(f"--set {param.path}", value, "a temperature below the "
                             f"{RUNAWAY_TEMPERATURE - 273.15:g} degC runaway limit (a run "
                             "stops as a thermal runaway there)" + hint)
        if hint and kelvin >= _HOT_BARE:
            celsius = "" if unit == "degC" else f" ({kelvin - 273.15:.4g} degC)"
            notes.append(f"sweep: {param.path} = {x:g} is read as {value}{celsius}{hint}")
    return SweepParameter(param.path, param.values, param.dropped, tuple(notes))


def _typed_item(raw: str, number: str) -> str:
    """The item of the ``--set`` text whose number is ``number`` (its own unit, if any)."""
    for item in raw.split(","):
        num, _ = _split_unit(item)
        try:
            if float(num) == float(number):
                return item
        except ValueError:
            continue
    return number


def _same_quantity_key(value: Any) -> Any:
    """Key under which two sweep values are the same quantity ("15 L/min" and "0.25 L/s");
    the text itself when it is not a quantity."""
    if isinstance(value, int | float) and not isinstance(value, bool):
        return ("", float(f"{float(value):.12g}"))
    try:
        from .units import quantity_unit, unit_registry

        # data-sheet spellings (r/min, m3/s) as the scene reads them
        q = unit_registry().Quantity(float(str(value).split()[0]),
                                     quantity_unit(value)).to_base_units()
        return (f"{q.units:~}", float(f"{float(q.magnitude):.12g}"))
    except Exception:  # noqa: BLE001 - not a quantity (a preset name ...): compare the text
        return ("text", str(value).strip())


def _in_unit(value: Any, unit: str) -> Any:
    """``value`` (a quantity string) written in ``unit`` as the store wrote it
    (``"500 N"`` in ``"kN"`` -> ``"0.5 kN"``, to :data:`_DIGITS` significant digits);
    the value unchanged when it is not a quantity of the unit's dimension (a bare number,
    a preset name) or is written in that unit already."""
    from .units import quantity_unit, unit_registry

    if not isinstance(value, str) or value.strip().split(maxsplit=1)[1:] == [unit]:
        return value
    try:
        ureg = unit_registry()
        q = ureg.Quantity(float(value.split()[0]), quantity_unit(value))
        number = float(q.to(quantity_unit(f"1 {unit}")).magnitude)
    except Exception:  # noqa: BLE001 - not a quantity of that dimension: as written
        return value
    return f"{number:.{_DIGITS}g} {unit}"


def in_store_units(params: Sequence[SweepParameter],
                   records: Mapping[str, Mapping[str, Any]] | Sequence[Mapping[str, Any]]
                   ) -> list[SweepParameter]:
    """The swept values written in one unit per field throughout a sweep folder: the unit
    of the field's first value in the folder's finished cases (``records``, id -> record
    or a list of records, as :func:`thermobearing.sweep_store.finished_cases` reads them),
    else of the field's first value here. A sweep of ``schedule.radial_load=0.5 kN``
    resumed with ``=500 N,700 N`` then runs and records ``0.7 kN`` (its ``summary.csv``
    listed both ``0.5 kN`` and ``500 N`` in the text column); values of another dimension
    or without a unit are kept as written."""
    recs = list(records.values()) if isinstance(records, Mapping) else list(records)
    out = []
    for p in params:
        written = [rec["params"][p.path] for rec in recs
                   if isinstance(rec.get("params"), Mapping) and p.path in rec["params"]]
        first = next((v for v in [*written, *p.values] if isinstance(v, str)
                      and len(v.strip().split(maxsplit=1)) == 2), None)
        if first is None:
            out.append(p)
            continue
        unit = first.strip().split(maxsplit=1)[1]
        out.append(SweepParameter(p.path, tuple(_in_unit(v, unit) for v in p.values),
                                  p.dropped, p.notes))
    return out


def _unique(path: str, values: Sequence[Any], written: Sequence[str]) -> SweepParameter:
    """The parameter with repeated values dropped (a repeated value would run the same case
    twice); what was dropped is kept in ``dropped`` for the command to say."""
    kept: list[Any] = []
    seen: dict[Any, Any] = {}
    dropped: list[str] = []
    for value, text in zip(values, written, strict=True):
        key = _same_quantity_key(value)
        if key in seen:
            dropped.append(f"{text!r} (= {seen[key]!r})")
            continue
        seen[key] = value
        kept.append(value)
    return SweepParameter(path, tuple(kept), tuple(dropped))


def get_path(d: Mapping[str, Any], path: str) -> Any:
    """Value at a dotted path of a scene dict (``schedule.<field>``: the first step's)."""
    cur: Any = d
    parts = path.split(".")
    if parts[0] == "schedule" and len(parts) == 2 and "steps" in d.get("schedule", {}):
        return d["schedule"]["steps"][0][parts[1]]
    for p in parts:
        if isinstance(cur, list):
            cur = cur[int(p)]
        else:
            cur = cur[p]
    return cur


_SETTABLE_NEW = {  # optional fields a sweep may set although the scene leaves them out
    "supply": ("method", "flow", "inlet_temperature", "level"),
    "environment": ("ambient_temperature", "initial_temperature"),
    "solver": ("stepper", "rtol", "atol", "kinematics_tolerance", "max_step"),
    "schedule": ("speed", "radial_load", "axial_load", "duration"),
    "lubricant": ("preset", "path"),
    # the validity-check thresholds (optional [checks] table; they change no physics)
    "checks": ("skid_limit", "contact_stress_limit", "min_film_parameter"),
}

#: what an unknown path error offers as examples
_KNOWN_PATHS = ("supply.flow, supply.inlet_temperature, schedule.speed, "
                "schedule.axial_load, environment.ambient_temperature, lubricant.preset, "
                "checks.skid_limit, bearings.0.overrides.<field>, bearings.0.preset, "
                "bearings.0.path, network.parameters.<name>")


def check_path(scene_dict: Mapping[str, Any], path: str, option: str = "--set") -> None:
    """Raise InputError unless ``path`` names a field a sweep or a fit may set.

    ``option``: the option or argument named in the error (``--set`` for a sweep,
    ``fit`` for a calibration).
    """
    from .operating_checks import STRESS_FAMILIES

    parts = path.split(".")
    try:
        get_path(scene_dict, path)
        return
    except (KeyError, IndexError, ValueError, TypeError):
        pass
    if len(parts) == 2 and parts[1] in _SETTABLE_NEW.get(parts[0], ()):
        return
    if len(parts) == 3 and parts[:2] == ["checks", "contact_stress_limit"]:
        current = scene_dict.get("checks", {}).get("contact_stress_limit")
        if parts[2] not in STRESS_FAMILIES:
            raise InputError(option, path, "checks.contact_stress_limit.<family>, a family "
                             "of " + ", ".join(STRESS_FAMILIES))
        if current is not None and not isinstance(current, Mapping):
            raise InputError(option, path, "checks.contact_stress_limit (the scene gives one "
                             f"stress for every family, {current!r}, not a table)")
        return
    if len(parts) >= 2 and parts[0] in ("models", "network"):
        return  # free-form tables: the model/template validates its own keys
    if parts[0] == "bearings" and len(parts) >= 2:
        names = [b.get("name", "?") for b in scene_dict.get("bearings", [])]
        if not (parts[1].isdigit() and int(parts[1]) < len(names)):
            listed = ", ".join(f"{i} = {n}" for i, n in enumerate(names))
            raise InputError(option, path, f"bearings.<index>.<field> with an index of the "
                             f"scene's bearings ({listed}), e.g. "
                             "bearings.0.overrides.diametral_clearance")
    if len(parts) >= 4 and parts[0] == "bearings" and parts[2] == "overrides":
        return
    if len(parts) == 4 and parts[0] == "bearings" and parts[2] == "load_share" \
            and parts[3] in ("radial", "axial"):
        return  # a share the scene leaves at its default 1 (the lever-arm split)
    if len(parts) == 3 and parts[0] == "bearings" and parts[2] in _EITHER:
        return  # a bearing's preset or file replaces the other (assign_path)
    if path == "schedule.step_duration":
        # the [schedule] key of the steps' default duration: refused as "not an existing
        # scene field" beside a scene that has it, with only 'did you mean' to go on
        raise InputError(option, path, "schedule.duration, the duration of every step (the "
                         "scene's [schedule] step_duration is the steps' default; a sweep "
                         "sets the steps' own, as for schedule.speed)")
    raise InputError(option, path, f"an existing scene field, e.g. {_KNOWN_PATHS}"
                     + _did_you_mean(scene_dict, path))


def _did_you_mean(scene_dict: Mapping[str, Any], path: str) -> str:
    """``"; did you mean network.parameters.h_oil?"`` for a bare, misplaced or misspelt
    name: the known paths with the same last name, else the closest spellings."""
    import difflib

    known = [f"{section}.{key}" for section, keys in _SETTABLE_NEW.items() for key in keys]
    for section in ("supply", "environment", "solver", "checks", "outputs"):
        table = scene_dict.get(section)
        if isinstance(table, Mapping):
            known += [f"{section}.{k}" for k in table if f"{section}.{k}" not in known]
    network = scene_dict.get("network", {})
    params = network.get("parameters", {}) if isinstance(network, Mapping) else {}
    names = set(params) if isinstance(params, Mapping) else set()
    template = network.get("template") if isinstance(network, Mapping) else None
    if template:
        try:
            from .network.templates import TEMPLATES

            names |= set(TEMPLATES.entry(template).parameters)
        except Exception:  # noqa: BLE001 - an unknown template is reported elsewhere
            pass
    known += [f"network.parameters.{n}" for n in sorted(names)]
    last = path.rsplit(".", 1)[-1]
    hits = [k for k in known if k.rsplit(".", 1)[-1] == last and k != path]
    if not hits:
        hits = difflib.get_close_matches(path, known, n=3, cutoff=0.8)
    return f"; did you mean {' or '.join(hits)}?" if hits else ""


#: keys of which a table (the lubricant, a bearing) takes exactly one: setting one drops
#: the other
_EITHER = {"preset": "path", "path": "preset"}


def assign_path(d: dict[str, Any], path: str, value: Any) -> None:
    """Set a dotted path of a scene dict (``schedule.<field>``: in every step).

    ``lubricant.path`` replaces the scene's ``lubricant.preset`` (and the other way
    round; a bearing's ``preset`` / ``path`` likewise): a table takes one of the two."""
    parts = path.split(".")
    if parts[0] == "schedule" and len(parts) == 2:
        for step in d["schedule"]["steps"]:
            step[parts[1]] = value
        return
    cur: Any = d
    for p in parts[:-1]:
        if isinstance(cur, list):
            cur = cur[int(p)]
        else:
            cur = cur.setdefault(p, {})
    if isinstance(cur, list):
        cur[int(parts[-1])] = value
    else:
        cur[parts[-1]] = value
        if (parts[-1] in _EITHER and (parts[0] == "lubricant" and len(parts) == 2
                                      or parts[0] == "bearings" and len(parts) == 3)):
            cur.pop(_EITHER[parts[-1]], None)


#: swept values that are file paths: a relative one is read from the current folder
#: when a file is there (typed on the command line), else from the scene's folder
_FILE_PATHS = re.compile(r"^(lubricant\.path|bearings\.\d+\.path|measured\.file)$")


def _files_from_here(path: str, values: Sequence[Any]) -> tuple[Any, ...]:
    """Relative file values of ``path`` made absolute against the current folder (the
    README: "a relative file from the current folder"), also a file that is not there, so
    that the case check names where it was looked for: a missing ``my_oil.toml`` was left
    relative and looked for in the scene's folder ("looked at .../configs/scenes/
    my_oil.toml" for the default scene)."""
    if not _FILE_PATHS.match(path):
        return tuple(values)
    out = []
    for v in values:
        if isinstance(v, str) and v.strip() and not Path(v).is_absolute():
            v = str(Path(v).resolve())
        out.append(v)
    return tuple(out)
