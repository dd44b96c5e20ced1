"""Parameter sweeps over a scene: cartesian products, run locally or on dask, resumable.

``thermobearing sweep SCENE --set supply.flow=15,20,25,33 --set schedule.speed=600:1800:300``
expands every combination of the ``--set`` values into one case, checks every case as a
scene that can run (:func:`check_cases`: preset and model names, network values, the
measured file) before the first one runs, runs each case with a runner (by default
:func:`thermobearing.simulation.summarize_scene`), and appends each finished case to
``DIR/cases.jsonl`` the moment it completes; ``DIR/summary.csv`` is rewritten after each
case; ``DIR/scene.toml`` records the base scene (:func:`record_base_scene`). Rerunning the
same command (in any order of its ``--set`` options) skips the cases already in
``cases.jsonl``, so an interrupted sweep resumes where it stopped.

Values: a comma list (``15,20,25,33``) or a range ``start:stop:step`` (stop included).
A bare number takes the unit the scene uses for that field (``schedule.speed=600:1800:300``
with a scene written in rpm means rpm; a field the scene leaves out takes
:data:`DISPLAY_UNITS` / :data:`PATH_UNITS`: L/min, degC, % for ``checks.skid_limit``, MPa
for the contact-stress limits); a unit may be given after the list
(``supply.flow=15,33 L/min``) or with each value. Text values are presets
(``lubricant.preset=ISO_VG32,ISO_VG68``). A repeated value (the same quantity) is dropped
and reported in :attr:`SweepParameter.dropped`. ``schedule.<field>`` sets that field in
every step; ``checks.<threshold>`` sets a validity-check threshold (no physics changes).

``summary.csv``: the case id, each swept value as set (``supply.flow``: ``"15 L/min"``)
and, for quantities, as a number with the unit in the column name
(``supply.flow [L/min]``), then the runner's results.

Executors: a local process pool (default), serial (``workers=1``), or an existing
dask.distributed scheduler (``scheduler="tcp://host:8786"``). A malformed address is an
InputError; an unreachable scheduler (or a server that does not answer as one within
three times ``connect_timeout``) is :class:`SchedulerUnreachable` unless
``fallback_local=True``.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import re
import sys
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd

from .errors import InputError, ThermobearingError
from .scene import Scene, loads_scene

Runner = Callable[[str], Mapping[str, float]]

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


@dataclass(frozen=True)
class SweepParameter:
    """One swept field: dotted path and its values (TOML-ready strings or numbers).

    ``dropped``: values of the ``--set`` text left out because they repeat an earlier one
    (the same quantity, e.g. ``15`` after ``15 L/min``), as ``"'15' (= '15 L/min')"``.
    """

    path: str
    values: tuple[Any, ...]
    dropped: tuple[str, ...] = ()


class SchedulerUnreachable(ThermobearingError):
    """The dask scheduler given for a sweep cannot be reached."""


# ---------------------------------------------------------------------------
def _split_unit(text: str) -> tuple[str, str]:
    """``"15,33 L/min"`` -> ``("15,33", "L/min")``: the numbers (ending in a digit or a dot),
    then the unit (whatever follows, starting with a letter or ``%``). Text that does not
    start with numbers comes back whole with no unit."""
    m = re.match(r"^\s*([-+0-9.eE:,\s]*[0-9.])\s*([A-Za-z%].*?)?\s*$", text)
    if not m:
        return text, ""
    return m.group(1), (m.group(2) or "").strip()


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
        words = value.split(maxsplit=1)
        if len(words) == 2:
            return words[1]
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
    if not path or not raw:
        raise InputError("--set", spec, "'path=value1,value2,...' or 'path=start:stop:step'")
    check_path(scene_dict, path)
    if ":" in raw:
        numbers, unit = _split_unit(raw)
        if not re.fullmatch(r"[-+0-9.eE:, ]+", numbers):
            raise InputError(f"--set {path}", raw, "a range start:stop:step with one unit")
        parts = numbers.split(":")
        if len(parts) != 3:
            raise InputError(f"--set {path}", raw, "a range start:stop:step")
        a, b, d = (_number(p, f"--set {path}") for p in parts)
        if d <= 0 or b < a:
            raise InputError(f"--set {path}", raw, "start <= stop and step > 0")
        n = int(math.floor((b - a) / d + 1e-9)) + 1
        unit = unit or _existing_unit(scene_dict, path)
        return SweepParameter(path, tuple(f"{a + i * d:g} {unit}" if unit else a + i * d
                                          for i in range(n)))
    items = [v.strip() for v in raw.split(",") if v.strip()]
    if not items:
        raise InputError(f"--set {path}", raw, "at least one value")
    split = [_split_unit(v) for v in items]
    numeric = [bool(re.fullmatch(r"[-+0-9.eE ]+", num)) for num, _ in split]
    if not any(numeric):
        return _unique(path, items, items)  # strings: lubricant presets etc.
    # each value may carry its own unit ("30 degC,50 degC"); a bare number takes the unit
    # written after the list ("15,33 L/min"), else the unit of the scene's current value.
    # A text among numbers ("15,abc") is passed on as written, so that the scene's check
    # names that value.
    last = max(i for i, ok in enumerate(numeric) if ok)
    trailing = split[last][1] or _existing_unit(scene_dict, path)
    values: list[Any] = []
    for item, (num, unit), ok in zip(items, split, numeric, strict=True):
        if not ok:
            values.append(item)
            continue
        x = _number(num.strip(), f"--set {path}")
        unit = unit or trailing
        if unit:
            values.append(f"{x:g} {unit}")
        else:  # a count written as a whole number stays an integer (n_balls=18,20)
            values.append(int(num) if re.fullmatch(r"\s*[-+]?\d+\s*", num) else x)
    return _unique(path, values, items)


def _same_quantity_key(value: Any) -> Any:
    """Key under which two sweep values are the same quantity ("15 L/min" and "0.25 L/s");
    the text itself when it is not a quantity."""
    if isinstance(value, int | float) and not isinstance(value, bool):
        return ("", float(f"{float(value):.12g}"))
    try:
        from .units import unit_registry

        q = unit_registry().Quantity(value).to_base_units()
        return (f"{q.units:~}", float(f"{float(q.magnitude):.12g}"))
    except Exception:  # noqa: BLE001 - not a quantity (a preset name ...): compare the text
        return ("text", str(value).strip())


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
                "checks.skid_limit, bearings.0.overrides.<field>, network.parameters.<name>")


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


def assign_path(d: dict[str, Any], path: str, value: Any) -> None:
    """Set a dotted path of a scene dict (``schedule.<field>``: in every step)."""
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


def _absolute_paths(d: dict[str, Any], base_dir: Path | None) -> None:
    """Make the scene's relative file paths (bearing and lubricant TOMLs, measured CSV)
    absolute against the scene's folder, so that a case's TOML text runs anywhere."""
    if base_dir is None:
        return

    def fix(table: Any, key: str) -> None:
        if isinstance(table, dict) and isinstance(table.get(key), str):
            path = Path(table[key])
            if not path.is_absolute():
                table[key] = str(base_dir / path)

    for bearing in d.get("bearings", []):
        fix(bearing, "path")
    fix(d.get("lubricant"), "path")
    fix(d.get("measured"), "file")


@dataclass(frozen=True)
class Case:
    """One combination of sweep values."""

    case_id: str
    assignments: tuple[tuple[str, Any], ...]
    scene_toml: str


def expand(scene: Scene, params: Sequence[SweepParameter]) -> list[Case]:
    """Cartesian product of the sweep values, each validated as a scene (a path swept
    twice is an error; a repeated combination is one case)."""
    paths = [p.path for p in params]
    for path in paths:
        if paths.count(path) > 1:
            raise InputError("--set", path, "each path once (give all its values in one "
                             "--set, e.g. supply.flow=15,20,33)")
    base = scene.to_dict()
    base_text = scene.to_toml()
    cases: list[Case] = []
    seen: set[str] = set()
    base_dir = Path(scene.base_dir) if scene.base_dir else None
    for combo in itertools.product(*(p.values for p in params)):
        assignments = tuple((p.path, v) for p, v in zip(params, combo, strict=True))
        d = json.loads(json.dumps(base))
        for path, value in assignments:
            assign_path(d, path, value)
        _absolute_paths(d, base_dir)  # the runner gets only the TOML text, not the folder
        sc = Scene.from_dict(d, base_dir)  # raises InputError naming the bad field
        # the id does not depend on the order of the --set options (distinct paths commute)
        key = json.dumps([base_text, sorted([list(a) for a in assignments], key=str)],
                         sort_keys=True)
        cid = hashlib.sha1(key.encode()).hexdigest()[:12]
        if cid in seen:
            continue
        seen.add(cid)
        cases.append(Case(cid, assignments, sc.to_toml()))
    return cases


# ---------------------------------------------------------------------------
def _store_path(out_dir: Path) -> Path:
    return out_dir / "cases.jsonl"


def finished_cases(out_dir: Path | str) -> dict[str, dict[str, Any]]:
    """Cases already in the results store (id -> record); a torn last line is ignored."""
    path = _store_path(Path(out_dir))
    done: dict[str, dict[str, Any]] = {}
    if not path.is_file():
        return done
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            rec = json.loads(line)
        except json.JSONDecodeError:
            continue
        done[rec["case"]] = rec
    return done


def _record(case: Case, result: Mapping[str, Any]) -> dict[str, Any]:
    return {"case": case.case_id, "params": dict(case.assignments), "result": dict(result)}


def _append(out_dir: Path, record: Mapping[str, Any]) -> None:
    with _store_path(out_dir).open("a", encoding="utf-8") as fh:
        fh.write(json.dumps(record) + "\n")
        fh.flush()


def summary_frame(records: Iterable[Mapping[str, Any]]) -> pd.DataFrame:
    """One row per case: the swept values then the runner's results.

    A swept quantity appears twice: as set (``supply.flow``: ``"15 L/min"``, the text the
    case's scene holds) and as a number with its unit in the column name
    (``supply.flow [L/min]``: 15.0, in the unit of the first case's value), so that the
    table plots and filters without parsing text. Text values (lubricant presets) appear
    once.
    """
    recs = list(records)
    rows = []
    for rec in recs:
        row = {"case": rec["case"]}
        row.update(rec["params"])
        row.update(rec["result"])
        rows.append(row)
    df = pd.DataFrame(rows)
    params = list(dict.fromkeys(k for rec in recs for k in rec["params"]))
    for path in params:
        numeric = _numeric_column(df[path].tolist())
        if numeric is not None:
            unit, values = numeric
            df.insert(df.columns.get_loc(path) + 1, f"{path} [{unit}]", values)
    return df


def _numeric_column(values: Sequence[Any]) -> tuple[str, list[float]] | None:
    """(unit, numbers) of swept values that are all quantities of one dimension, in the
    unit of the first (``["15 L/min", "0.5 L/s"]`` -> ``("L/min", [15.0, 30.0])``); None
    for bare numbers (already numeric), text, or mixed dimensions."""
    from .units import unit_registry

    if not values or not all(isinstance(v, str) for v in values):
        return None
    ureg = unit_registry()
    try:
        first = values[0].strip().split(maxsplit=1)
        if len(first) != 2:
            return None
        unit = first[1]
        numbers = []
        for v in values:
            num, _, u = v.strip().partition(" ")
            numbers.append(float(ureg.Quantity(float(num), u.strip()).to(unit).magnitude))
    except Exception:  # noqa: BLE001 - text (a preset name) or mixed dimensions: no column
        return None
    return unit, numbers


def record_base_scene(out_dir: Path, scene: Scene) -> None:
    """Write the base scene, its file paths absolute, to ``out_dir/scene.toml``: the sweep
    report names the bearing and the conditions not swept from it.

    A folder resumed with another base scene gets it replaced, as ``summary.csv`` is
    rewritten with the cases of this sweep alone (the case ids include the base scene, so
    none of the earlier cases counts as finished; their records stay in ``cases.jsonl``);
    stderr says so."""
    from .scene import with_absolute_paths

    text = with_absolute_paths(scene).to_toml()
    path = out_dir / "scene.toml"
    if path.is_file():
        try:
            old = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            old = None
        if old == text:
            return
        print(f"sweep: {path} held another base scene; replaced by this sweep's (its "
              "cases run anew; summary.csv lists this sweep's cases, cases.jsonl keeps "
              "the earlier ones)", file=sys.stderr)
    path.write_text(text, encoding="utf-8")


def _write_summary(out_dir: Path, cases: Sequence[Case]) -> pd.DataFrame:
    done = finished_cases(out_dir)
    order = {c.case_id: i for i, c in enumerate(cases)}
    recs = sorted((r for r in done.values() if r["case"] in order), key=lambda r: order[r["case"]])
    df = summary_frame(recs)
    df.to_csv(out_dir / "summary.csv", index=False)
    return df


def check_scheduler_address(scheduler: str) -> None:
    """InputError unless ``scheduler`` reads as a dask.distributed scheduler address
    (``tcp://host:8786``, ``host:8786``, ``tls://...``, ``inproc://...``): a typo is named
    at once instead of failing inside dask with a traceback."""
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import backends

    allowed = ("a dask scheduler address such as tcp://host:8786 or host:8786 (schemes: "
               + ", ".join(sorted(backends)) + ")")
    if not isinstance(scheduler, str) or not scheduler.strip():
        raise InputError("--scheduler", scheduler, allowed)
    try:
        scheme, loc = parse_address(scheduler.strip())
    except (ValueError, TypeError):
        raise InputError("--scheduler", scheduler, allowed) from None
    if scheme not in backends:
        raise InputError("--scheduler", scheduler, allowed)
    if scheme in ("tcp", "tls", "ws", "wss", "ucx"):
        try:
            host, port = parse_host_port(loc)
        except (ValueError, TypeError):
            raise InputError("--scheduler", scheduler, allowed) from None
        if not host or not 0 < int(port) < 65536:
            raise InputError("--scheduler", scheduler, allowed)


def _dask_client(scheduler: str, timeout: float = 5.0):
    """A dask Client connected to ``scheduler``, or SchedulerUnreachable.

    dask's own ``timeout`` bounds the TCP connection only; a server that accepts the
    connection but never answers the handshake (another service on that port, e.g. the
    scheduler's web dashboard) would block forever, and one that answers with something
    else fails with an arbitrary exception. The connection is therefore made in a helper
    thread with an overall deadline of three times ``timeout``, and every failure is
    reported as unreachable.
    """
    import threading

    from distributed import Client

    check_scheduler_address(scheduler)
    box: dict[str, Any] = {}

    def connect() -> None:
        try:
            box["client"] = Client(scheduler, timeout=f"{timeout}s", set_as_default=False)
        except Exception as exc:  # noqa: BLE001 - any failure: reported as unreachable
            box["error"] = f"{type(exc).__name__}: {exc}" if not isinstance(
                exc, OSError | TimeoutError) else str(exc)

    worker = threading.Thread(target=connect, name="thermobearing-dask-connect", daemon=True)
    worker.start()
    worker.join(3.0 * timeout)
    advice = ("; start it (dask scheduler) or give its right address, or ask for a local "
              "run instead (--fallback-local, fallback_local=True)")
    if worker.is_alive():
        raise SchedulerUnreachable(
            f"cannot reach the dask scheduler at {scheduler!r}: something accepted the "
            f"connection but did not answer as a dask scheduler within {3.0 * timeout:g} s "
            "(is that the scheduler's port, usually 8786, and not its dashboard's, 8787?)"
            + advice)
    if "error" in box:
        raise SchedulerUnreachable(
            f"cannot reach the dask scheduler at {scheduler!r}: {box['error']}" + advice)
    return box["client"]


def _require_workers(client: Any, scheduler: str, timeout: float) -> None:
    """SchedulerUnreachable (the client closed) unless the scheduler has a worker within
    ``timeout`` seconds: a scheduler started without workers accepts the cases and never
    runs them, and the sweep would wait forever."""
    try:
        client.wait_for_workers(1, timeout=timeout)
    except (TimeoutError, OSError):
        client.close()
        raise SchedulerUnreachable(
            f"the dask scheduler at {scheduler!r} has no workers (none joined within "
            f"{timeout:g} s): start some (dask worker {scheduler}), or ask for a local run "
            "instead (--fallback-local, fallback_local=True)") from None


@contextmanager
def _naming_case(case: Case, out: Path | None) -> Iterator[None]:
    """A package error raised by one case names the case's values and where the finished
    cases are (the type and fields of the error are kept); ``out`` None: the error comes
    from the check of the cases before any ran."""
    try:
        yield
    except ThermobearingError as exc:
        values = ", ".join(f"{k}={v}" for k, v in case.assignments)
        if out is None:
            where = "no case was run (every case is checked before the first one runs)"
        else:
            n = len(finished_cases(out))
            where = (f"{n} finished case(s) are kept in {_store_path(out)} (rerun the same "
                     "command to resume)")
        exc.args = (f"sweep case {case.case_id} ({values}): {exc}; {where}", *exc.args[1:])
        raise
    except Exception as exc:
        # not an input or solver error the package names (a bug, a dask worker without
        # thermobearing, ...): the traceback stays, with a note on the case and the store
        values = ", ".join(f"{k}={v}" for k, v in case.assignments)
        kept = "" if out is None else (f"; {len(finished_cases(out))} finished case(s) are "
                                       f"kept in {_store_path(out)}")
        exc.add_note(f"in sweep case {case.case_id} ({values}){kept}")
        raise


def check_cases(cases: Sequence[Case]) -> None:
    """Check every case as a scene that can run, before the first one runs: what
    ``thermobearing check`` checks without solving (model, bearing and lubricant preset
    names, the network template's parameters and values, the measured CSV). A bad value
    (``lubricant.preset=ISO_VG99``) then fails in a second, naming the case, instead of
    after the good cases have run. Costs a few milliseconds per case."""
    from .commands._preflight import preflight
    from .scene_checks import check_model_names
    from .simulation import Simulation

    for case in cases:
        with _naming_case(case, None):
            scene = loads_scene(case.scene_toml)
            check_model_names(scene)
            preflight(Simulation(scene, progress=False), build=True)


def run_sweep(
    scene: Scene,
    params: Sequence[SweepParameter],
    out_dir: Path | str,
    *,
    runner: Runner | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    fallback_local: bool = False,
    progress: bool | None = None,
    connect_timeout: float = 5.0,
    check: bool = True,
) -> pd.DataFrame:
    """Run every case not yet in ``out_dir``; returns the summary table of all cases.

    Parameters
    ----------
    scene : the base scene.
    params : swept fields (from :func:`parse_set`).
    out_dir : results folder (``cases.jsonl`` store and ``summary.csv``).
    runner : picklable ``runner(scene_toml) -> {name: float}``; default
        :func:`thermobearing.simulation.summarize_scene`.
    workers : local processes (1 = serial in this process; default: CPU count).
    scheduler : address of a dask.distributed scheduler to run the cases on.
    fallback_local : if the scheduler cannot be reached, run locally instead of failing.
    progress : show a progress bar (default: when stderr is a terminal).
    connect_timeout : seconds to wait for the scheduler before it counts as unreachable
        (a server that accepts the connection but does not answer as a scheduler: three
        times as long).
    check : check every case not yet run with :func:`check_cases` before the first runs.
    """
    from tqdm.auto import tqdm

    if not (isinstance(connect_timeout, (int, float)) and not isinstance(connect_timeout, bool)
            and math.isfinite(connect_timeout) and connect_timeout > 0):
        raise InputError("connect_timeout", connect_timeout, "a positive number of seconds")

    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or workers < 1):
        raise InputError("workers", workers, "a whole number of local processes >= 1 "
                         "(1 = serial in this process; default: one per CPU)")
    if scheduler:
        check_scheduler_address(scheduler)
    if runner is None:
        from .simulation import summarize_scene as runner
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError("--out", str(out), "a results folder (new or of this sweep); this "
                         "is a file")
    cases = expand(scene, params)
    done = finished_cases(out)
    todo = [c for c in cases if c.case_id not in done]
    if check:
        check_cases(todo)
    out.mkdir(parents=True, exist_ok=True)
    record_base_scene(out, scene)
    show = sys.stderr.isatty() if progress is None else progress
    bar = tqdm(total=len(cases), initial=len(cases) - len(todo), disable=not show,
               desc="sweep", unit="case")
    try:
        if todo:
            client = None
            if scheduler:
                try:
                    client = _dask_client(scheduler, connect_timeout)
                    _require_workers(client, scheduler, connect_timeout)
                except SchedulerUnreachable as exc:
                    if not fallback_local:
                        raise
                    client = None
                    why = "has no workers" if "no workers" in str(exc) else "unreachable"
                    print(f"sweep: scheduler {scheduler} {why}, running locally",
                          file=sys.stderr)
            if client is not None:
                from distributed import as_completed as dask_completed

                try:
                    with client.as_current():
                        futures = {client.submit(runner, c.scene_toml, pure=False): c
                                   for c in todo}
                        for fut in dask_completed(list(futures)):
                            with _naming_case(futures[fut], out):
                                result = fut.result()
                            _append(out, _record(futures[fut], result))
                            _write_summary(out, cases)
                            bar.update(1)
                finally:
                    client.close()
            elif workers == 1 or len(todo) == 1:
                for c in todo:
                    with _naming_case(c, out):
                        result = runner(c.scene_toml)
                    _append(out, _record(c, result))
                    _write_summary(out, cases)
                    bar.update(1)
            else:
                with ProcessPoolExecutor(max_workers=workers) as pool:
                    futs = {pool.submit(runner, c.scene_toml): c for c in todo}
                    try:
                        for fut in as_completed(futs):
                            with _naming_case(futs[fut], out):
                                result = fut.result()
                            _append(out, _record(futs[fut], result))
                            _write_summary(out, cases)
                            bar.update(1)
                    except KeyboardInterrupt:
                        # leaving the with-block would wait for every queued case: drop them
                        pool.shutdown(wait=False, cancel_futures=True)
                        raise
    finally:
        bar.close()
    return _write_summary(out, cases)


def scene_from_case(case: Case) -> Scene:
    """The scene of one case."""
    return loads_scene(case.scene_toml)
