"""``thermobearing run [SCENE] [--out DIR] [--quiet]``: run a scene and write its results.

With no SCENE the embedded default scene runs: the QJ1044 test rig of seed paper 002
(1800 r/min, 33 L/min, axial load 0-42 kN in 2 kN steps of 3 min, 1 kN radial load,
two test bearings on one shaft, 35 degC ambient). Results are written as they are
computed; Ctrl-C keeps what was written and says where.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from ..errors import InputError, ThermobearingError
from ..scene import with_absolute_paths
from ..scene_checks import check_model_names
from ._preflight import (
    check_inputs_not_replaced,
    compile_note,
    load_scene_argument,
    preflight,
)

NAME = "run"
HELP = "run a scene (default: the embedded QJ1044 rig of seed paper 002) and write results"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?",
                        help="scene TOML path or preset name (default: the embedded QJ1044 "
                             "rig of seed paper 002, preset qj1044_rig; copy "
                             "configs/scenes/qj1044_rig.toml to edit it)")
    parser.add_argument("--out", default=None,
                        help="results folder (default: results/<scene file name>)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar, less output")


def run(args: argparse.Namespace) -> int:
    from ..simulation import Simulation

    # before the scene's Simulation is built: building it already writes numba cache
    # files (51 of a fresh clone's), so a later look found them and said nothing
    note = compile_note()
    # absolute file paths: the results folder's scene.toml (read by `report`) must find them
    scene = with_absolute_paths(load_scene_argument(args.scene))
    check_model_names(scene)
    name = Path(args.scene).stem if args.scene else "qj1044_rig"
    out = Path(args.out) if args.out else Path("results") / name
    if out.is_file():  # refused before the scene and its chain are printed as if to run
        raise InputError("--out", str(out), "a results folder (new or existing); this is "
                         "a file")
    check_inputs_not_replaced(out, scene, args.scene, output_names())
    progress = None if not args.quiet else False
    sim = Simulation(scene, progress=progress)
    if not args.quiet and not sys.stderr.isatty():
        # no progress bar into a file or pipe: one line per finished step instead
        sim.step_log = _print_step
    preflight(sim, build=False)  # run_coupled checks the node map when it builds the network
    if not args.quiet:
        print(f"scene: {scene.title}")
        print(sim.describe_chain())
        print(f"writing results to {out}/ as they are computed", flush=True)
        if note:
            print(note, flush=True)
    try:
        results = sim.run(out_dir=out)
    except KeyboardInterrupt:
        print("\n" + stopped_text(out, sim.steps_done, len(scene.schedule.steps), True),
              file=sys.stderr)
        return 130
    except ThermobearingError as exc:
        # the error as the command line prints it, then where the steps before it are
        print(f"thermobearing run: error: {exc}", file=sys.stderr)
        if (out / "metadata.json").is_file():  # written by Simulation.run when it stops
            print(stopped_text(out, sim.steps_done, len(scene.schedule.steps), False),
                  file=sys.stderr)
        return 1
    if not args.quiet:
        print(sim.summary_text(results))
        _print_measured(scene, results)
    print(f"results written to {out}/ (report: {out / 'report.html'})")
    if (out / "loss_breakdown.csv").is_file():
        print(f"loss breakdown, one column per source [W]: {out / 'loss_breakdown.csv'}")
    from ..report_measured import COMPARISON_CSV

    if (out / COMPARISON_CSV).is_file() and _has_rows(out / COMPARISON_CSV):
        # (a file with its header only, no reading inside the run, is not announced as
        # "every compared reading": the measured notes above say why none was compared)
        print(f"measured vs predicted, every compared reading: {out / COMPARISON_CSV}")
    return 0


def output_names() -> set[str]:
    """The file names a run writes (or removes as an earlier run's) in its folder."""
    from ..report import FIGURE_CAPTIONS
    from ..report_measured import COMPARISON_CSV
    from ..results import TABLES

    return ({f"{t}.csv" for t in TABLES} | {f"{n}.png" for n in FIGURE_CAPTIONS}
            | {"loss_breakdown.csv", COMPARISON_CSV, "metadata.json", "scene.toml",
               "report.html", "loss_maps.png"})


def stopped_text(out: Path, done: int | None, steps: int, interrupted: bool) -> str:
    """What a run stopped by Ctrl-C (``interrupted``) or an error left in ``out`` after
    ``done`` of ``steps`` schedule steps (None: not known, the run's step loop never
    started). Stopped before its first step finished, a run said "everything computed so
    far is in DIR/" of a folder that was empty or held only the scene and metadata, and
    sent the user to a report whose loss section then read as a scene asking for no
    losses."""
    why = "interrupted" if interrupted else "stopped by the error"
    held = (out / "metadata.json").is_file()
    if done == 0:
        first = "the first step" if steps == 1 else f"the first of {steps} steps"
        return (f"{why} before {first} finished: no step was computed, "
                f"nothing to report" + (f" ({out}/ holds the scene and the model chain "
                                        "only)" if held else ""))
    count = "" if done is None else (
        ("its one step" if steps == 1 else f"all {steps} steps")
        + "; stopped while the figures and report were written"
        if done >= steps else f"{done} of {steps} steps")
    hint = f"`thermobearing report {out}` writes their report" if held else ""
    extra = "; ".join(x for x in (count, hint) if x)
    extra = f" ({extra})" if extra else ""
    if interrupted:
        return f"interrupted: everything computed so far is in {out}/{extra}"
    return f"the steps computed before the error are in {out}/{extra}"


def _has_rows(path: Path) -> bool:
    """Whether a CSV file has a line below its header."""
    with path.open(encoding="utf-8") as fh:
        return sum(1 for line, _ in zip(fh, range(2), strict=False) if line.strip()) > 1


def _print_step(line: str) -> None:
    print(line, file=sys.stderr, flush=True)


def _print_measured(scene: Any, results: Any) -> None:
    """Each sensor's error and the measured file's notes (gaps, averaged rows, coverage of
    the run), shortened; the report lists them all."""
    temps = results.tables.get("temperatures")
    if scene.measured is None or temps is None or temps.empty:
        return
    from ..measured import read_scene_measured
    from ..report_measured import terminal_lines

    measured = read_scene_measured(scene)
    for line in terminal_lines(measured, temps, scene.measured.columns):
        print(line)
    if scene.outputs.mode == "transient" and "time [s]" in temps:
        from ..measured import interval_note

        for note in interval_note(measured, scene.solver.chunk, scene.outputs.interval):
            print(f"note: {note}")
