"""Checks run by ``thermobearing check`` and ``run`` before any model is solved.

Everything that can be known wrong without solving a model fails here, in seconds, with the
field named, instead of after the first operating points of a long run: the network
template's required parameters and (``check``) their values, the ``[measured]`` CSV
(columns, numbers, increasing times), the ``global_friction`` source's inputs at every
distinct operating point (an SKF series the designation does not give, a missing C0: ``run``
computed the steps before the first refused one) and, when the scene builds a network, the
column -> node map of ``[measured]``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..errors import InputError
from ..measured_layout import closest_name
from ..scene_checks import check_global_friction, check_measured_file, check_network

#: the first line of the numerical kernels' compilation, printed before a first run's first
#: step: the default scene's first run compiles 112 signatures of 77 kernels in 45-57 s of
#: CPU (README set-up), and a user saw nothing between "writing results" and its first
#: step line for 96 s of wall time (session-24 tour F, fresh clone)
COMPILE_NOTE = ("first run of this install: the numerical kernels (numba) compile before the "
                "first step, about a minute; they are cached for the next runs")


def compile_note(root: Path | None = None) -> str | None:
    """:data:`COMPILE_NOTE` when no numba cache index (``*.nbi``) lies under ``root`` (the
    package folder, or numba's ``NUMBA_CACHE_DIR`` when set), else None: a cache written by
    an earlier run loads in under a second."""
    if root is None:
        import numba

        cache_dir = getattr(numba.config, "CACHE_DIR", "")
        root = Path(cache_dir) if cache_dir else Path(__file__).resolve().parents[1]
    if not root.is_dir():
        return COMPILE_NOTE
    return None if next(root.rglob("*.nbi"), None) is not None else COMPILE_NOTE


def load_scene_argument(name: str | None) -> Any:
    """The scene of a command's SCENE argument (:func:`thermobearing.scene.load_scene`, which
    refuses a path to a file that is not there naming the file where it was looked for)."""
    from ..scene import load_scene

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
    check_global_friction(sim)
    if not (build and thermal):
        return
    from ..coupled import build_network

    nodes = build_network(sim).state_nodes  # the template checks its parameter values
    for column, node in (scene.measured.columns if scene.measured is not None else {}).items():
        if node not in nodes:
            raise InputError(f"measured.columns[{column!r}]", node,
                             "a node of the network: " + ", ".join(nodes)
                             + closest_name(str(node), list(nodes)))


def check_inputs_not_replaced(out: Path, scene: Any, scene_arg: str | None,
                              names: set[str], prefix: str = "loss_maps_",
                              marker: str = "metadata.json") -> None:
    """Refuse a results folder in which a run or sweep would overwrite one of its inputs
    (``names``: the files it writes there; ``prefix``: of its further figure files):
    ``thermobearing run scene.toml --out .`` replaced the user's scene (its comments
    lost) with the run's copy, and a rig file named ``temperatures.csv`` in that folder
    would have been replaced by the predicted temperatures. The ``scene.toml`` of a folder
    the tool wrote (``marker`` there: a run's ``metadata.json``, a sweep's
    ``cases.jsonl``) may be given as the scene of a rerun into that folder: it is the
    tool's own copy."""
    inputs = []
    own = (out / marker).is_file()
    if scene_arg and Path(scene_arg).is_file() and not own:
        inputs.append(("the scene", Path(scene_arg)))
    for i, spec in enumerate(scene.bearings):
        if spec.path:
            inputs.append((f"bearings[{i}].path", scene.resolve_path(spec.path)))
    if scene.lubricant.get("path"):
        inputs.append(("lubricant.path", scene.resolve_path(scene.lubricant["path"])))
    if scene.measured is not None:
        inputs.append(("measured.file", scene.resolve_path(scene.measured.file)))
    for what, path in inputs:
        name = path.name
        if (name in names or (name.startswith(prefix) and name.endswith(".png"))) \
                and path.resolve().parent == out.resolve():
            raise InputError("--out", str(out),
                             f"a folder where the run does not replace its inputs: {what} "
                             f"({path}) has the name of a file written there; give "
                             "another --out folder (or rename the file)")
