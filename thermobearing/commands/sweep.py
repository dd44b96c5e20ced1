"""``thermobearing sweep SCENE --set path=values ... --out DIR``: a resumable parameter sweep.

Example: ``thermobearing sweep qj1044_rig --set supply.flow=15,20,25,33
--set schedule.speed=600:1800:300 --out sweep_flow`` (SCENE may be left out: the default
scene, as for ``run``). Every case is checked before the first one runs; every finished
case is appended to ``DIR/cases.jsonl`` at once; rerunning the same command skips
finished cases. ``DIR/scene.toml`` records the base scene (file paths absolute) for
``thermobearing report DIR``. ``--scheduler ADDRESS`` runs the cases on an existing dask.distributed
cluster. The terminal shows the main results; ``DIR/summary.csv`` has every column.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import pandas as pd

from ..errors import InputError
from ..scene_checks import check_measured_file, check_model_names, check_network
from ..sweep import finished_cases, parse_set, run_sweep
from ..sweep_store import counted, kept_text
from ._preflight import check_inputs_not_replaced, load_scene_argument

NAME = "sweep"
HELP = "sweep scene parameters (cartesian product), locally or on dask, resumable"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?",
                        help="scene TOML path or preset name (default: the embedded QJ1044 "
                             "rig of seed paper 002, as for `run`)")
    parser.add_argument("--set", action="append", required=True, dest="sets",
                        metavar="PATH=VALUES",
                        help="one swept field (repeat for a cartesian product): comma "
                             "list or start:stop:step, a bare number in the scene's unit, "
                             "e.g. supply.flow=15,20,33, supply.inlet_temperature=30,45 degC, "
                             "schedule.speed=600:1800:300, lubricant.preset=ISO_VG32,"
                             "ISO_VG68, checks.skid_limit=2,5 (%%), "
                             "network.parameters.h_oil=200,400")
    parser.add_argument("--out", required=True, help="results folder")
    parser.add_argument("--workers", "--jobs", "-j", type=int, default=None, dest="workers",
                        help="local processes (default: one per CPU; 1 = serial; -j N as "
                             "for `validate`)")
    parser.add_argument("--scheduler", default=None, help="dask scheduler address")
    parser.add_argument("--fallback-local", action="store_true",
                        help="run locally if the scheduler cannot be reached")
    parser.add_argument("--keep-going", action="store_true",
                        help="run the other cases when one fails (a solver that does not "
                             "converge); the failed ones are listed and a rerun tries them "
                             "again")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


#: the files a sweep and its report write in the sweep folder (and ``sweep_*.png``)
SWEEP_OUTPUTS = {"scene.toml", "summary.csv", "cases.jsonl", "report.html",
                 "planned_cases.json"}


def run(args: argparse.Namespace) -> int:
    scene = load_scene_argument(args.scene)
    check_model_names(scene)
    # what `run` checks before solving anything, once for the base scene (a case only
    # changes values, which expand() validates)
    check_network(scene.network,
                  require=bool(set(scene.outputs.want) & {"temperatures", "energy"}))
    check_measured_file(scene)
    d = scene.to_dict()
    params = [parse_set(s, d) for s in args.sets]
    for p in params:
        if p.dropped:
            word = "value" if len(p.dropped) == 1 else "values"
            print(f"sweep: {p.path}: repeated {word} left out: {', '.join(p.dropped)}",
                  file=sys.stderr)
    out = Path(args.out)
    check_inputs_not_replaced(out, scene, args.scene, SWEEP_OUTPUTS, prefix="sweep_",
                              marker="cases.jsonl" if (out / "cases.jsonl").is_file()
                              else "planned_cases.json")
    # what summarize_scene reduces to columns: losses (also behind "report"), kinematics,
    # temperatures (also behind "energy") and a film-only scene's smallest films
    tabulated = {"losses", "kinematics", "temperatures", "energy", "report", "film"}
    empty_note = ("a sweep reduces each run to its losses, kinematics, temperatures and "
                  "films (thermobearing.simulation.summarize_scene), and this scene's outputs "
                  f"are {', '.join(scene.outputs.want) or 'none'}")
    warned = not set(scene.outputs.want) & tabulated
    if warned:  # say it before the runs, not after
        print(f"note: the cases will give no results to tabulate: {empty_note}",
              file=sys.stderr)
    try:
        df = run_sweep(scene, params, out, workers=args.workers, scheduler=args.scheduler,
                       fallback_local=args.fallback_local,
                       progress=False if args.quiet else None,
                       keep_going=args.keep_going)
    except KeyboardInterrupt:
        planned = record_plan(out, scene, params)
        print("\n" + interrupt_message(out, len(finished_cases(out)), planned),
              file=sys.stderr)
        return 130
    except BaseException:
        record_plan(out, scene, params)
        raise
    record_plan(out, scene, params)
    shown, hidden = terminal_columns(df, [p.path for p in params])
    print(df[shown].to_string(index=False, float_format=lambda v: f"{v:.4g}"))
    more = f" ({hidden} more result columns there)" if hidden else ""
    print(f"summary written to {out / 'summary.csv'}{more}")
    for line in flagged_notes(df, [p.path for p in params]):
        print(line, file=sys.stderr)
    from .report import fixed_start_note

    start = fixed_start_note(out, [p.path for p in params])
    if start and not df.empty:
        print(f"note: {start}", file=sys.stderr)
    for line in df.attrs.get("identical", []):
        print(line, file=sys.stderr)
    failures = df.attrs.get("failed", [])
    if failures:
        them = "it" if len(failures) == 1 else "them"
        print(f"{counted(len(failures), 'case')} failed (not in {out / 'summary.csv'}; a rerun "
              f"tries {them} again):", file=sys.stderr)
        for line in failures:
            print(f"  {line}", file=sys.stderr)
    swept = {p.path for p in params}
    if not warned and all(c == "case" or c in swept
                          or any(c.startswith(p + " [") for p in swept) for c in df.columns):
        print(f"note: the cases gave no results to tabulate: {empty_note}", file=sys.stderr)
    return 1 if failures else 0


def record_plan(out: Path, scene, params) -> int | None:
    """Record the cases this sweep planned in ``out`` (:func:`thermobearing.sweep_store.
    record_planned_cases`) once the sweep has started there, i.e. the folder's
    ``scene.toml`` is this sweep's base scene (a sweep refused before its start leaves the
    folder as it was); returns how many cases it planned, None when it did not start.

    Written when the sweep ends, finished, failed or interrupted, with the case ids of the
    store (a case finished earlier in other units keeps its id)."""
    from ..scene import with_absolute_paths
    from ..sweep_cases import expand, match_finished
    from ..sweep_params import in_store_units
    from ..sweep_store import record_planned_cases

    path = out / "scene.toml"
    try:
        if not path.is_file() or path.read_text(encoding="utf-8") != \
                with_absolute_paths(scene).to_toml():
            return None
        done = finished_cases(out)
        cases = match_finished(scene, expand(scene, in_store_units(params, done)), done)
        record_planned_cases(out, cases)
    except (OSError, UnicodeDecodeError, InputError):
        return None  # not this sweep's folder any more, or values it refused
    return len(cases)


def interrupt_message(out: Path, done: int, planned: int | None) -> str:
    """What an interrupted sweep prints: how many cases finished (of how many planned)
    and what the folder keeps."""
    if done:
        return (f"interrupted: {kept_text(done, planned)} in "
                f"{out / 'cases.jsonl'} (table: {out / 'summary.csv'}); rerun the same "
                "command to resume with the cases not yet run")
    if planned is not None:
        return (f"interrupted before the first case finished: 0 of "
                f"{counted(planned, 'planned case')} finished; {out} keeps the base scene "
                "(scene.toml) and the planned cases (planned_cases.json), no result; rerun the "
                "same command to start again")
    return ("interrupted before the first case finished: nothing was kept; rerun the same "
            "command to start again")


#: the run checks' counts of the summary and what each flags
_FLAG_COLUMNS = {
    "steps over skid limit [-]": "cage skidding beyond the skid limit",
    "steps over stress limit [-]": "contact pressure above the stress limit (ISO 76 "
                                   "static-rating stress unless [checks] sets another)",
    "steps under film limit [-]": "film parameter Lambda below its limit",
}


def flagged_notes(df, swept: list[str]) -> list[str]:
    """One note per validity check that flags steps in some case (the summary's ``steps
    over ... limit`` counts, which the terminal table does not show): how many cases, and
    the swept values of the first one (a load typed in the wrong unit shows here)."""
    lines = []
    for col, what in _FLAG_COLUMNS.items():
        if col not in df.columns:
            continue
        counts = pd.to_numeric(df[col], errors="coerce").fillna(0.0)
        bad = df[counts > 0]
        if bad.empty:
            continue
        first = bad.iloc[0]
        values = ", ".join(f"{p} = {first[p]}" for p in swept if p in df.columns)
        lines.append(f"note: {len(bad)} of {len(df)} cases have steps with {what} "
                     f"(summary.csv column {col!r}; first: case {first['case']}"
                     + (f", {values}" if values else "") + ")")
    return lines


#: results shown on the terminal when the runner gives them (summary.csv has all)
_MAIN_RESULTS = ("mean total loss [W]",)
#: the summary's extremes of the cage's slip against rolling (over-skidding > 0: the cage
#: faster than rolling; < 0: skidding, slower)
_OVER_SKID = ("max over-skidding [%]", "min over-skidding [%]")


def slip_columns(df, results: list[str]) -> list[str]:
    """The over-skidding extremes the terminal shows: both, unless one is negligible
    (below 1 % of the other's largest magnitude over the cases). A cylindrical roller
    bearing that skids has min over-skidding -20 to -41 % and max -0.005 to -0.02 % (NU 214,
    5000 r/min, 0.5-8 kN, 0.5-8 L/min): the max alone, shown before, said nothing of its
    cage slip; the QJ1044 rig skids at 0 kN (min -31 to -68 %) and over-skids at 2-8 kN
    (max +5 to +12 %): both. None when both are 0 in every case (race control)."""
    present = [c for c in _OVER_SKID if c in results]

    def size(col: str) -> float:
        values = pd.to_numeric(df[col], errors="coerce").abs()
        return float(values.max()) if values.notna().any() else 0.0

    largest = max((size(c) for c in present), default=0.0)
    if largest == 0.0:
        # 0 % in every case: race control rolls the cage by construction (the CRB rib
        # example's flow sweep showed two columns of zeros); the report draws no panel
        return []
    return [c for c in present if size(c) >= 0.01 * largest]


def terminal_columns(df, swept: list[str], max_results: int = 4) -> tuple[list[str], int]:
    """Columns printed on the terminal: the case, the swept values as set, and a few main
    results (mean total loss, the over-skidding extremes (:func:`slip_columns`), the first
    housing temperature and, with one slip column, its rise, when present; else the
    largest loss columns, then the others); and how many result columns are left out."""
    params = [c for c in df.columns if c in swept
              or any(c.startswith(p + " [") for p in swept)]
    results = [c for c in df.columns if c != "case" and c not in params]
    chosen = [c for c in _MAIN_RESULTS if c in results] + slip_columns(df, results)
    housing = [c for c in results if "housing" in c and c.startswith(("final", "rise"))][:2]
    # the first housing's final temperature, and its rise while there is room (two slip
    # columns leave it out: final minus the initial temperature, both in summary.csv)
    chosen += housing[:1]
    if len(chosen) < max_results:
        chosen += housing[1:]

    def weight(c: str) -> tuple[int, float]:
        # fill with the largest loss columns first (a source that books 0 W in every case,
        # e.g. the cage guide of a roller-guided cage, says nothing), then the others
        values = pd.to_numeric(df[c], errors="coerce").abs()
        size = float(values.mean()) if values.notna().any() else 0.0
        return (0 if c.endswith("[W]") and size > 0.0 else 1, -size)

    for c in sorted((c for c in results if c not in chosen), key=weight):
        if len(chosen) >= max_results:
            break
        chosen.append(c)
    chosen = [c for c in results if c in chosen]  # keep the table's order
    shown = ["case", *[c for c in df.columns if c in swept], *chosen]
    return [c for c in shown if c in df.columns], len(results) - len(chosen)
