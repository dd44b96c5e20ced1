"""``thermobearing check SCENE``: validate a scene and print the model chain it will run."""

from __future__ import annotations

import argparse

from ..scene import load_scene
from ..scene_checks import check_model_names

NAME = "check"
HELP = "validate a scene and print the model chain that will run, with citations"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", nargs="?", help="scene TOML path or preset name")


def run(args: argparse.Namespace) -> int:
    from ..simulation import Simulation
    from ._preflight import preflight

    scene = load_scene(args.scene)
    check_model_names(scene)
    sim = Simulation(scene, progress=False)
    preflight(sim)
    print(f"scene: {scene.title}")
    print(f"schedule: {len(scene.schedule.steps)} steps, {scene.schedule.duration / 60:g} min")
    print(sim.describe_chain(with_citations=True))
    estimates = sim.describe_estimates()
    if estimates:
        print(estimates)
    return 0
