"""``thermobearing check SCENE``: validate a scene and print the model chain it will run."""

from __future__ import annotations

import argparse

from ..scene_checks import check_model_names
from ._preflight import load_scene_argument

NAME = "check"
HELP = "validate a scene and print the model chain that will run, with citations"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?",
                        help="scene TOML path or preset name (default: the embedded QJ1044 "
                             "rig of seed paper 002, as for `run`)")


def run(args: argparse.Namespace) -> int:
    from ..simulation import Simulation
    from ._preflight import preflight

    scene = load_scene_argument(args.scene)
    check_model_names(scene)
    sim = Simulation(scene, progress=False)
    preflight(sim)  # with what run refuses at its first step, before any solve
    print(f"scene: {scene.title}")
    n = len(scene.schedule.steps)
    print(f"schedule: {n} step{'' if n == 1 else 's'}, {scene.schedule.duration / 60:g} min")
    print(sim.describe_chain(with_citations=True))
    estimates = sim.describe_estimates()
    if estimates:
        print(estimates)
    if scene.measured is not None:
        print(describe_measured(scene))
    return 0


def describe_measured(scene) -> str:
    """The ``[measured]`` file as the run will read it: sensors, samples, time span, the
    file's columns no node is mapped to, the reader's notes (gaps per sensor and cause,
    averaged rows, units) and how the file covers the schedule."""
    from ..measured import (
        coverage_notes,
        interval_note,
        measured_notes,
        minutes_span,
        read_scene_measured,
    )

    df = read_scene_measured(scene)
    t = df["time [s]"]
    sensors = [c for c in df.columns if c != "time [s]"]
    plural = "s" if len(sensors) != 1 else ""
    lines = [f"measured: {scene.measured.file}: {len(sensors)} sensor{plural}, "
             f"{len(df)} samples"
             + (f", {minutes_span(t.iloc[0], t.iloc[-1])}" if len(df) else "")]
    read_as = df.attrs.get("time_read_as")
    if read_as:
        names = scene.measured.time_column
        name = names if isinstance(names, str) else " + ".join(names)
        lines.append(f"  time column {name!r} read as {read_as}")
    unmapped = df.attrs.get("unmapped", [])
    if unmapped:  # an extra channel, or a thermocouple left out of the column map
        lines.append("  not compared (no node in [measured] columns): "
                     + ", ".join(repr(c) for c in unmapped))
    notes = measured_notes(df) + coverage_notes(df, 0.0, scene.schedule.duration)
    if scene.outputs.mode == "transient" and "temperatures" in scene.outputs.want:
        notes += interval_note(df, scene.solver.chunk, scene.outputs.interval)
    lines += [f"  - {n}" for n in notes]
    return "\n".join(lines)
