"""The results store of a sweep folder: ``cases.jsonl``, ``summary.csv`` and ``scene.toml``.

Each finished case is appended to ``DIR/cases.jsonl`` the moment it completes
(:func:`finished_cases` reads them back, so that a rerun skips them); ``DIR/summary.csv``
is rewritten after each case; ``DIR/scene.toml`` records the base scene
(:func:`record_base_scene`); ``DIR/planned_cases.json`` the cases the sweep planned
(:func:`record_planned_cases`).

``summary.csv``: the case id, each swept value as set (``supply.flow``: ``"15 L/min"``)
and, for quantities, as a number with the unit in the column name
(``supply.flow [L/min]``), then the runner's results.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd

from .scene import Scene
from .sweep_cases import Case


def _store_path(out_dir: Path) -> Path:
    return out_dir / "cases.jsonl"


def counted(n: int, noun: str) -> str:
    """``n`` and the noun in the number it takes: ``"1 case"``, ``"0 cases"``,
    ``"6 cases"`` (the sweep's messages said ``"1 case(s)"``)."""
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


def kept_text(n: int, planned: int | None = None) -> str:
    """How many finished cases a sweep folder keeps, verb agreed:
    ``"1 finished case is kept"``, ``"2 finished cases of 9 planned are kept"``."""
    of = "" if planned is None else f" of {planned} planned"
    return f"{counted(n, 'finished case')}{of} {'is' if n == 1 else 'are'} kept"


def finished_cases(out_dir: Path | str) -> dict[str, dict[str, Any]]:
    """Cases already in the results store (id -> record); a torn last line is ignored.
    Result names written by earlier versions are read under their current names
    (:func:`thermobearing.simulation_summary.current_result_names`: ``total loss [W]`` ->
    ``mean total loss [W]``, ``rise <node> [K]`` -> ``rise over initial`` or, in a steady
    scene, ``rise over ambient``), so a resumed folder's summary has one column each."""
    from .simulation_summary import current_result_names

    path = _store_path(Path(out_dir))
    done: dict[str, dict[str, Any]] = {}
    if not path.is_file():
        return done
    base_mode = base_scene_mode(Path(out_dir))
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            rec = json.loads(line)
        except json.JSONDecodeError:
            continue
        mode = str(rec.get("params", {}).get("outputs.mode", base_mode))
        if isinstance(rec.get("result"), dict):
            rec["result"] = current_result_names(rec["result"], steady=mode == "steady")
        done[rec["case"]] = rec
    return done


def base_scene_mode(out_dir: Path) -> str:
    """``[outputs] mode`` of the folder's recorded base scene (``scene.toml``);
    ``"transient"`` (the scene default) when there is none or it does not parse."""
    import tomllib

    try:
        doc = tomllib.loads((out_dir / "scene.toml").read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError):
        return "transient"
    outputs = doc.get("outputs")
    mode = outputs.get("mode") if isinstance(outputs, dict) else None
    return mode if isinstance(mode, str) else "transient"


def _record(case: Case, result: Mapping[str, Any]) -> dict[str, Any]:
    return {"case": case.case_id, "params": dict(case.assignments), "result": dict(result)}


def _append(out_dir: Path, record: Mapping[str, Any]) -> None:
    """Append one case record as a line of the store. A store whose last line was cut
    (a sweep killed or the disk filled while it wrote) gets its line ended first: the
    record was written onto the cut line, which does not parse, so the first case finished
    after a resume was lost from the store and ran again at the next resume."""
    path = _store_path(out_dir)
    cut = False
    if path.is_file() and path.stat().st_size > 0:
        with path.open("rb") as fh:
            fh.seek(-1, 2)
            cut = fh.read(1) != b"\n"
    with path.open("a", encoding="utf-8") as fh:
        fh.write(("\n" if cut else "") + json.dumps(record) + "\n")
        fh.flush()


def summary_frame(records: Iterable[Mapping[str, Any]]) -> pd.DataFrame:
    """One row per case: the swept values then the runner's results.

    A swept quantity appears twice: as set (``supply.flow``: ``"15 L/min"``, the text the
    case's scene holds, in the folder's one unit of the field:
    :func:`thermobearing.sweep_params.in_store_units`) and as a number with its unit in the
    column name
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
    unit of the first (``["15 L/min", "0.5 L/s"]`` -> ``("L/min", [15.0, 30.0])``; units
    as data sheets write them, ``m3/s`` or ``r/min``, are read as the scene reads them); None
    for bare numbers (already numeric), text, or mixed dimensions."""
    from .units import quantity_unit, unit_registry

    if not values or not all(isinstance(v, str) for v in values):
        return None
    ureg = unit_registry()
    try:
        first = values[0].strip().split(maxsplit=1)
        if len(first) != 2:
            return None
        unit = first[1]
        # data-sheet spellings the scene reads (m3/s, mm3/h, r/min) in pint's spelling
        target = quantity_unit(values[0])
        numbers = []
        for v in values:
            num = v.strip().split(maxsplit=1)[0]
            numbers.append(float(ureg.Quantity(float(num), quantity_unit(v)).to(target)
                                 .magnitude))
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


#: the file of a sweep folder that records the cases its sweep planned
PLANNED_FILE = "planned_cases.json"


def record_planned_cases(out_dir: Path, cases: Sequence[Case]) -> None:
    """Write the cases a sweep plans to ``out_dir/planned_cases.json`` (their ids and swept
    values, in order): the report of an interrupted sweep then says how many of them
    finished ("1 of 9 planned cases finished"), and a folder whose sweep stopped before its
    first case is known as a sweep folder. A sweep of another plan in the same folder
    replaces the record, as it does ``summary.csv``."""
    doc = {"planned": len(cases),
           "cases": [{"case": c.case_id, "params": dict(c.assignments)} for c in cases]}
    (out_dir / PLANNED_FILE).write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")


def planned_cases(out_dir: Path) -> list[str] | None:
    """The case ids a sweep folder's sweep planned (:func:`record_planned_cases`); None
    for a folder without the record (written before it existed, or not a sweep's) or
    with one that does not read as such."""
    planned = planned_params(out_dir)
    return None if planned is None else [case for case, _ in planned]


def planned_params(out_dir: Path) -> list[tuple[str, dict[str, Any]]] | None:
    """The cases a sweep folder's sweep planned, each as (case id, swept values as set),
    in order (:func:`record_planned_cases`); None as for :func:`planned_cases`."""
    path = Path(out_dir) / PLANNED_FILE
    if not path.is_file():
        return None
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
        out = [(str(c["case"]), dict(c["params"])) for c in doc["cases"]]
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, KeyError, TypeError,
            ValueError):
        return None
    return out


def _write_summary(out_dir: Path, cases: Sequence[Case],
                   done: Mapping[str, Mapping[str, Any]] | None = None) -> pd.DataFrame:
    """Rewrite ``summary.csv`` with the finished ``cases`` in their order. ``done``: the
    records the caller keeps in memory (id -> record, as :func:`finished_cases` returns
    them); without it the store is read back (once per call: a sweep that passed nothing
    re-read ``cases.jsonl`` after every case, quadratic in the number of cases)."""
    if done is None:
        done = finished_cases(out_dir)
    order = {c.case_id: i for i, c in enumerate(cases)}
    recs = sorted((r for r in done.values() if r["case"] in order), key=lambda r: order[r["case"]])
    df = summary_frame(recs)
    df.to_csv(out_dir / "summary.csv", index=False)
    return df
