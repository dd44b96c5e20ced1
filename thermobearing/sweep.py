"""Parameter sweeps over a scene: cartesian products, run locally or on dask, resumable.

``thermobearing sweep SCENE --set supply.flow=15,20,25,33 --set schedule.speed=600:1800:300``
expands every combination of the ``--set`` values into one case, runs each case with a
runner (by default :func:`thermobearing.simulation.summarize_scene`), and appends each
finished case to ``DIR/cases.jsonl`` the moment it completes; ``DIR/summary.csv`` is
rewritten after each case. Rerunning the same command skips the cases already in
``cases.jsonl``, so an interrupted sweep resumes where it stopped.

Values: a comma list (``15,20,25,33``) or a range ``start:stop:step`` (stop included).
A bare number takes the unit the scene uses for that field (``schedule.speed=600:1800:300``
with a scene written in rpm means rpm); a unit may be given after the list
(``supply.flow=15,33 L/min``). ``schedule.<field>`` sets that field in every step.

Executors: a local process pool (default), serial (``workers=1``), or an existing
dask.distributed scheduler (``scheduler="tcp://host:8786"``). An unreachable scheduler is
an error unless ``fallback_local=True``.
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


@dataclass(frozen=True)
class SweepParameter:
    """One swept field: dotted path and its values (TOML-ready strings or numbers)."""

    path: str
    values: tuple[Any, ...]


class SchedulerUnreachable(ThermobearingError):
    """The dask scheduler given for a sweep cannot be reached."""


# ---------------------------------------------------------------------------
def _split_unit(text: str) -> tuple[str, str]:
    """``"15,33 L/min"`` -> ``("15,33", "L/min")``: the numbers (ending in a digit or a dot),
    then the unit (whatever follows, starting with a letter). Text that does not start with
    numbers comes back whole with no unit."""
    m = re.match(r"^\s*([-+0-9.eE:,\s]*[0-9.])\s*([A-Za-z].*?)?\s*$", text)
    if not m:
        return text, ""
    return m.group(1), (m.group(2) or "").strip()


def _number(text: str, field: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise InputError(field, text, "a number") from None


def _existing_unit(scene_dict: Mapping[str, Any], path: str) -> str:
    """Unit of the field's current value in the scene (for bare sweep numbers)."""
    try:
        value = get_path(scene_dict, path)
    except KeyError:
        value = None
    if isinstance(value, str):
        parts = value.split(maxsplit=1)
        if len(parts) == 2:
            return parts[1]
    return DISPLAY_UNITS.get(path.rsplit(".", 1)[-1], "")


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
    if not all(re.fullmatch(r"[-+0-9.eE ]+", num) for num, _ in split):
        return SweepParameter(path, tuple(items))  # strings: lubricant presets etc.
    # each value may carry its own unit ("30 degC,50 degC"); a bare number takes the unit
    # written after the list ("15,33 L/min"), else the unit of the scene's current value
    trailing = split[-1][1] or _existing_unit(scene_dict, path)
    values = []
    for num, unit in split:
        x = _number(num.strip(), f"--set {path}")
        unit = unit or trailing
        values.append(f"{x:g} {unit}" if unit else x)
    return SweepParameter(path, tuple(values))


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
}


def check_path(scene_dict: Mapping[str, Any], path: str) -> None:
    """Raise InputError unless ``path`` names a field a sweep or a fit may set."""
    parts = path.split(".")
    try:
        get_path(scene_dict, path)
        return
    except (KeyError, IndexError, ValueError, TypeError):
        pass
    if len(parts) == 2 and parts[1] in _SETTABLE_NEW.get(parts[0], ()):
        return
    if len(parts) >= 2 and parts[0] in ("models", "network"):
        return  # free-form tables: the model/template validates its own keys
    if len(parts) >= 3 and parts[0] == "bearings" and parts[2] == "overrides":
        return
    raise InputError("--set", path, "an existing scene field (e.g. supply.flow, "
                     "schedule.speed, environment.ambient_temperature, lubricant.preset, "
                     "bearings.0.overrides.<field>, network.parameters.<name>)")


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
    """Cartesian product of the sweep values, each validated as a scene."""
    base = scene.to_dict()
    base_text = scene.to_toml()
    cases = []
    base_dir = Path(scene.base_dir) if scene.base_dir else None
    for combo in itertools.product(*(p.values for p in params)):
        assignments = tuple((p.path, v) for p, v in zip(params, combo, strict=True))
        d = json.loads(json.dumps(base))
        for path, value in assignments:
            assign_path(d, path, value)
        _absolute_paths(d, base_dir)  # the runner gets only the TOML text, not the folder
        sc = Scene.from_dict(d, base_dir)  # raises InputError naming the bad field
        key = json.dumps([base_text, [list(a) for a in assignments]], sort_keys=True)
        cid = hashlib.sha1(key.encode()).hexdigest()[:12]
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
    """One row per case: the swept values then the runner's results."""
    rows = []
    for rec in records:
        row = {"case": rec["case"]}
        row.update(rec["params"])
        row.update(rec["result"])
        rows.append(row)
    return pd.DataFrame(rows)


def _write_summary(out_dir: Path, cases: Sequence[Case]) -> pd.DataFrame:
    done = finished_cases(out_dir)
    order = {c.case_id: i for i, c in enumerate(cases)}
    recs = sorted((r for r in done.values() if r["case"] in order), key=lambda r: order[r["case"]])
    df = summary_frame(recs)
    df.to_csv(out_dir / "summary.csv", index=False)
    return df


def _dask_client(scheduler: str, timeout: float = 5.0):
    from distributed import Client

    try:
        return Client(scheduler, timeout=f"{timeout}s", set_as_default=False)
    except (OSError, TimeoutError) as exc:
        raise SchedulerUnreachable(
            f"cannot reach the dask scheduler at {scheduler!r}: {exc}; start it (dask "
            "scheduler) or give its right address, or ask for a local run instead "
            "(--fallback-local, fallback_local=True)"
        ) from None


@contextmanager
def _naming_case(case: Case, out: Path) -> Iterator[None]:
    """A package error raised by one case names the case's values and where the finished
    cases are (the type and fields of the error are kept)."""
    try:
        yield
    except ThermobearingError as exc:
        values = ", ".join(f"{k}={v}" for k, v in case.assignments)
        exc.args = (f"sweep case {case.case_id} ({values}): {exc}; the finished cases are "
                    f"kept in {_store_path(out)} (rerun the same command to resume)",
                    *exc.args[1:])
        raise


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
    connect_timeout : seconds to wait for the scheduler before it counts as unreachable.
    """
    from tqdm.auto import tqdm

    if not (isinstance(connect_timeout, (int, float)) and not isinstance(connect_timeout, bool)
            and math.isfinite(connect_timeout) and connect_timeout > 0):
        raise InputError("connect_timeout", connect_timeout, "a positive number of seconds")

    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or workers < 1):
        raise InputError("workers", workers, "a whole number of local processes >= 1 "
                         "(1 = serial in this process; default: one per CPU)")
    if runner is None:
        from .simulation import summarize_scene as runner
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    cases = expand(scene, params)
    done = finished_cases(out)
    todo = [c for c in cases if c.case_id not in done]
    show = sys.stderr.isatty() if progress is None else progress
    bar = tqdm(total=len(cases), initial=len(cases) - len(todo), disable=not show,
               desc="sweep", unit="case")
    try:
        if todo:
            client = None
            if scheduler:
                try:
                    client = _dask_client(scheduler, connect_timeout)
                except SchedulerUnreachable:
                    if not fallback_local:
                        raise
                    print(f"sweep: scheduler {scheduler} unreachable, running locally",
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
