"""Checks run by ``thermobearing check`` and ``run`` before any model is solved.

Everything that can be known wrong without solving a model fails here, in seconds, with the
field named, instead of after the first operating points of a long run: the network
template's required parameters and (``check``) their values, the ``[measured]`` CSV
(columns, numbers, increasing times) and, when the scene builds a network, the column ->
node map of ``[measured]``.
"""

from __future__ import annotations

from typing import Any

from ..errors import InputError
from ..scene_checks import check_measured_file, check_network


def load_scene_argument(name: str | None) -> Any:
    """The scene of a command's SCENE argument (:func:`thermobearing.scene.load_scene`); a
    path to a file that is not there (a ``.toml`` name or one with a folder in it) is
    refused naming the file where it was looked for (``thermobearing run nosuch.toml``
    said "scene = 'nosuch.toml' is not allowed: known names are: crb_rib_example, ...", as
    if a preset had been misspelt)."""
    from pathlib import Path

    from ..scene import load_scene, scene_presets

    if name is not None:
        path = Path(name)
        looks_like_file = (path.suffix.lower() == ".toml" or len(path.parts) > 1
                           or path.is_dir())
        if looks_like_file and not path.is_file():
            where = "a folder" if path.is_dir() else "no such file"
            raise InputError("scene", name, f"a scene TOML file ({where}: {path.absolute()}) "
                             "or a preset name: " + ", ".join(scene_presets()))
    return load_scene(name)


def preflight(sim: Any, build: bool = True) -> None:
    """Validate ``sim.scene`` beyond what loading it checks (see the module docstring).

    ``build``: also build the thermal network (cheap), so that its template checks the
    parameter values (a negative housing length ...) and the measured-column map is checked
    against its node names.
    """
    scene = sim.scene
    thermal = bool(sim.needs.get("network"))
    check_network(scene.network, require=thermal)
    check_measured_file(scene)
    if not (build and thermal):
        return
    from ..coupled import build_network

    nodes = build_network(sim).state_nodes  # the template checks its parameter values
    for column, node in (scene.measured.columns if scene.measured is not None else {}).items():
        if node not in nodes:
            raise InputError(f"measured.columns[{column!r}]", node,
                             "a node of the network: " + ", ".join(nodes))
