"""The cases of a sweep: the cartesian product of the swept values, each one a scene.

:func:`expand` turns the swept fields (:class:`~thermobearing.sweep_params.SweepParameter`)
into one :class:`Case` per combination: its id (independent of the order of the ``--set``
options), the values it sets and the TOML text of its scene, whose file paths are made
absolute so that the text runs anywhere (a worker process, a dask worker).
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from .errors import InputError, ThermobearingError
from .scene import Scene, loads_scene
from .sweep_params import MAX_SWEEP_CASES, SweepParameter, _same_quantity_key, assign_path


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
    twice, no swept field or a field without values is an error; a repeated combination
    is one case)."""
    if not params:
        # a sweep of nothing ran the base scene as one case and called it a sweep
        raise InputError("params", "[]", "at least one swept field (a SweepParameter from "
                         "parse_set('supply.flow=15,33', scene.to_dict()); on the command "
                         "line --set PATH=VALUES)")
    for p in params:
        if not p.values:
            # an empty value list gave a sweep of 0 cases: an empty summary without a word
            raise InputError(f"--set {p.path}", "", "at least one value: a comma list "
                             "(15,20,33) or a range start:stop:step")
    paths = [p.path for p in params]
    for path in paths:
        if paths.count(path) > 1:
            raise InputError("--set", path, "each path once (give all its values in one "
                             "--set, e.g. supply.flow=15,20,33)")
    total = math.prod(len(p.values) for p in params)
    if total > MAX_SWEEP_CASES:
        raise InputError("--set", " x ".join(f"{p.path} ({len(p.values)})" for p in params),
                         f"at most {MAX_SWEEP_CASES} cases in one sweep (these give {total}: "
                         "fewer values, or several sweeps)")
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
        cid = _case_id(base_text, assignments)
        try:
            sc = Scene.from_dict(d, base_dir)  # raises InputError naming the bad field
        except ThermobearingError as exc:
            # the case's values with the field's error: 'supply.method=jet,oil_bath' x
            # 'supply.flow=...' said only "supply.level is missing: an oil level for an oil
            # bath", naming neither the combination nor that nothing ran
            values = ", ".join(f"{k}={v}" for k, v in assignments)
            exc.args = (f"sweep case {cid} ({values}): {exc}; no case was run (every case "
                        "is checked before the first one runs)", *exc.args[1:])
            raise
        if cid in seen:
            continue
        seen.add(cid)
        cases.append(Case(cid, assignments, sc.to_toml()))
    return cases


def _case_id(base_text: str, assignments: Sequence[Sequence[Any]],
             same_quantity: bool = False) -> str:
    """The id of a case: a hash of the base scene and the values set, independent of the
    order of the --set options (distinct paths commute). ``same_quantity``: of the values
    as quantities (``15 L/min`` and ``900 L/h`` alike) instead of as written."""
    pairs = [[path, _same_quantity_key(v) if same_quantity else v]
             for path, v in assignments]
    key = json.dumps([base_text, sorted(pairs, key=str)], sort_keys=True)
    return hashlib.sha1(key.encode()).hexdigest()[:12]


def match_finished(scene: Scene, cases: Sequence[Case],
                   done: dict[str, dict[str, Any]]) -> list[Case]:
    """``cases`` with the id of a finished case of the store (``done``, id -> record)
    that set the same quantities in other units (``--set supply.flow=900,1980 L/h`` after
    ``supply.flow=15,33``): that case is not run again. A record counts only when its id
    is the id of its values on this base scene (a record of another base scene in the
    same folder does not)."""
    base_text = scene.to_toml()
    by_quantity: dict[str, str] = {}
    for rec in done.values():
        try:
            assignments = list(rec["params"].items())
        except (KeyError, AttributeError):
            continue
        if _case_id(base_text, assignments) == rec.get("case"):
            by_quantity.setdefault(_case_id(base_text, assignments, True), rec["case"])
    out = []
    for case in cases:
        if case.case_id not in done:
            alias = by_quantity.get(_case_id(base_text, case.assignments, True))
            if alias is not None:
                case = Case(alias, case.assignments, case.scene_toml)
        out.append(case)
    return out


def scene_from_case(case: Case) -> Scene:
    """The scene of one case."""
    return loads_scene(case.scene_toml)
