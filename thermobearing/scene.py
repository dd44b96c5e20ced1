"""Scenes: one configured study, read from TOML.

A scene names the bearing(s), the lubricant, the oil supply, the environment, the schedule of
speed and load steps, the models to use (one name per family), the thermal network, the
solver settings and the outputs wanted. Quantities are unit strings (``"1800 rpm"``,
``"33 L/min"``, ``"35 degC"``) converted once here to SI floats; bare numbers are SI. Unknown
keys are errors that name the key; :meth:`Scene.to_toml` writes a file that loads back to
an equal scene.

The tables are read by their own modules: :mod:`thermobearing.scene_sections` (bearings,
supply, environment, measured, solver, outputs, checks), :mod:`thermobearing.scene_schedule`
(the steps), :mod:`thermobearing.scene_values` (keys and units); the checks that run before a
solve are in :mod:`thermobearing.scene_checks`, the TOML writer in
:mod:`thermobearing.toml_writer`.

Layout (every table optional unless marked)::

    title = "..."                      # required
    source = "..."                     # where the study comes from

    [[bearings]]                       # required, one or more
    name = "drive_end"                 # unique; names the node group in the network
    preset = "QJ1044"                  # or path = "my_bearing.toml"
    overrides = { diametral_clearance = "0.1 mm" }
    load_share = { radial = 0.6, axial = 0 }   # its fractions of the schedule's loads
                                       # (default 1 each; axial = 0: a floating bearing)

    [lubricant]                        # required
    preset = "ISO_VG46"                # or path = "..."

    [supply]
    method = "jet"                     # jet | circulation | oil_bath | oil_air | grease
    flow = "33 L/min"                  # through each bearing (every bearing of the scene
                                       # gets this flow: its churning and its oil stream)
    inlet_temperature = "35 degC"
    level = "20 mm"                    # oil bath only (with a flow: a circulated bath)

    [environment]
    ambient_temperature = "35 degC"
    initial_temperature = "35 degC"    # default: ambient

    [schedule]                         # one of: steps | axial_load sweep | file
    speed = "1800 rpm"                 # defaults for every step
    radial_load = "1 kN"
    axial_load = "0 kN"
    step_duration = "3 min"
    axial_load_steps = { start = "0 kN", stop = "42 kN", step = "2 kN" }
    # steps = [{ duration = "3 min", speed = "1800 rpm", axial_load = "2 kN" }, ...]
    # file = "protocol.csv"   # columns duration [s], speed [rpm], radial_load [N], axial_load [N]

    [models]                           # one name per family (see `thermobearing models`)
    kinematics = "skidding"            # skidding | race_control | none (with global_friction)
    control = "outer_race"             # race control only: which race controls the spin
    film = "hamrock_dowson_1977_central"   # default; pan_hamrock_central for rollers
    heat_sources = ["raceway_traction", "churning_elements", "churning_cage",
                    "churning_inner_ring", "cage_guide", "pocket_friction"]
    heat_source_options = { pocket_friction = { ... } }   # per-source parameters
    film_options = { grid_points = 256 }   # numerical_tehl settings (scene_film.py)
    churning_heat_to = "oil"           # oil | paper002 (where the churning heat is booked)
    calibration = "preset"             # preset (<bearing>.calibration.toml if any) | none
    ball_rolling_resistance = "none"   # none | harris | { model = "harris", reduction =
                                       #   "thermal_starvation" } (EHL rolling force in the
                                       #   ball balance; adds ehl_rolling_resistance)

    [network]
    template = "four_node_paper002"
    parameters = { ... }               # template parameters, unit strings allowed
    shaft_link = { spacing = "500 mm" }  # bearings on one shaft (network/shaft.py)

    [solver]
    stepper = "exprb43"                # exprb43 | tr_bdf2 | backward_euler ...
    rtol = 1e-7                        # step error scale atol + rtol |T| (default 1e-5 K + 3e-5 K)
    atol = 1e-5                        # [K]; steps cost no heat-source call (chunk model)
    kinematics_tolerance = 0.03        # relative viscosity change that triggers a re-solve (BM-7)
    chunk = "90 s"                     # coupling interval: heat re-linearised, output row

    [outputs]
    mode = "transient"                 # transient | steady
    want = ["temperatures", "losses", "kinematics", "energy", "report"]

    [checks]                           # thresholds of the validity warnings (operating_checks)
    skid_limit = "2 %"                 # |CSR/CSR_ref - 1| [-]; default 5 % (operating_checks)
    contact_stress_limit = "3500 MPa"  # or { ball = ..., self_aligning_ball = ..., roller = ... }
    min_film_parameter = 1.5           # Lambda [-]; default 1 (boundary lubrication)

    [measured]                         # a rig's thermocouple file (measured.py: ; or tab,
    file = "rig.csv"                   # decimal commas, metadata and units rows, timestamps,
    time_column = "time [min]"         # hh:mm:ss, dropout flags such as OVL or ----)
    unit = "degC"
    columns = { "T_outer_DE" = "drive_end.housing" }
    # time_column = ["Datum", "Uhrzeit"] # a date and a time-of-day column, read together
    # time_zero = "2026-11-23 10:00:00"  # t = 0 in the time column's format, or "first"
"""

from __future__ import annotations

import copy
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from .errors import InputError, UnknownNameError
from .operating_checks import CheckLimits
from .scene_schedule import MAX_LOAD, Schedule, Step
from .scene_sections import (
    CHECK_KEYS,
    CHECKS_SOURCE,
    OUTPUT_KINDS,
    OUTPUT_MODES,
    SUPPLY_METHODS,
    BearingSpec,
    Environment,
    Measured,
    Outputs,
    Solver,
    Supply,
    checks_from_dict,
    checks_to_dict,
)
from .scene_values import _check_keys, _require, _table
from .toml_writer import dumps_toml

__all__ = [
    "CHECK_KEYS", "CHECKS_SOURCE", "DEFAULT_SCENE", "OUTPUT_KINDS", "OUTPUT_MODES",
    "SUPPLY_METHODS", "BearingSpec", "Environment", "Measured", "Outputs", "Scene",
    "Schedule", "Solver", "Step", "Supply", "check_measured_file", "check_model_names",
    "check_network", "checks_from_dict", "checks_to_dict", "configs_dir", "dumps_toml",
    "load_scene", "loads_scene", "scene_presets", "with_absolute_paths",
]


#: most temperature rows ``[outputs] interval`` may ask of a transient (each is a dense-output
#: evaluation and a table row; a week at 1 s is 6e5), and most coupling chunks
#: (``[solver] chunk``, each a row too and a re-linearised heat model, 10-20 ms), and the
#: fewest network steps ``[solver] max_step`` may force (schedule / max_step)
MAX_OUTPUT_ROWS = 1_000_000


@dataclass(frozen=True)
class Scene:
    """One configured study (see the module docstring for the TOML layout)."""

    title: str
    bearings: tuple[BearingSpec, ...]
    lubricant: Mapping[str, Any]
    supply: Supply
    environment: Environment
    schedule: Schedule
    models: Mapping[str, Any] = field(default_factory=dict)
    network: Mapping[str, Any] = field(default_factory=dict)
    solver: Solver = field(default_factory=Solver)
    outputs: Outputs = field(default_factory=Outputs)
    measured: Measured | None = None
    source: str = ""
    base_dir: str | None = None
    #: thresholds of the run's validity checks (``[checks]``; None: the defaults)
    checks: CheckLimits | None = None

    _TOP = ("title", "source", "bearings", "lubricant", "supply", "environment", "schedule",
            "models", "network", "solver", "outputs", "measured", "checks")

    def __post_init__(self) -> None:
        # a scene changed in code (with_changes) keeps its bearings' names unique: they
        # name the node groups of the network and the rows of every table
        names = [b.name for b in self.bearings]
        if len(set(names)) != len(names):
            raise InputError("bearings[].name", names, "unique names")
        for i, spec in enumerate(self.bearings):
            # a bearing's share of the loads within the step bounds, named as the share
            # (else a later Step refused 'step.radial_load', no key of the scene)
            for key, share in spec.load_share.items():
                top = max(abs(getattr(s, f"{key}_load")) for s in self.schedule.steps)
                if top * abs(share) > MAX_LOAD:
                    raise InputError(f"bearings[{i}].load_share.{key}", share,
                                     f"a share that keeps this bearing's {key} load within "
                                     f"{MAX_LOAD:g} N (the schedule's largest is {top:g} N)")
        total = sum(step.duration for step in self.schedule.steps)
        if self.outputs.mode == "transient" and total / self.solver.chunk > MAX_OUTPUT_ROWS:
            # each chunk ends in a row and re-linearises the heat (10-20 ms): chunk = "1 us"
            # over two 1-min steps was 1.2e8 chunks, weeks of computing
            raise InputError("solver.chunk", f"{self.solver.chunk:g} s",
                             f"at most {MAX_OUTPUT_ROWS:.0e} coupling chunks over the "
                             f"schedule's {total:g} s: a chunk >= "
                             f"{total / MAX_OUTPUT_ROWS:.3g} s")
        if self.outputs.mode == "transient" and total / self.solver.max_step > MAX_OUTPUT_ROWS:
            # the stepper takes at least one step per max_step (0.5-1 ms each on the four-node
            # network: max_step = "1 ms" over 2 min was 95 s of wall time, "1e-9 s" would
            # have been 1.2e11 steps, years)
            raise InputError("solver.max_step", f"{self.solver.max_step:g} s",
                             f"at most {MAX_OUTPUT_ROWS:.0e} network steps over the schedule's "
                             f"{total:g} s: a max_step >= {total / MAX_OUTPUT_ROWS:.3g} s (the "
                             "stepper's error control chooses smaller steps where it needs "
                             "them; max_step only caps them)")
        interval = self.outputs.interval
        if interval is not None and self.outputs.mode == "transient":
            if total / interval > MAX_OUTPUT_ROWS:
                # interval = "1 us" over two 1-min steps asked for 1.2e8 rows: the first
                # chunk built a 9e7-element time array and the run never came back
                raise InputError("outputs.interval", f"{interval:g} s",
                                 f"at most {MAX_OUTPUT_ROWS:.0e} temperature rows over the "
                                 f"schedule's {total:g} s: an interval >= "
                                 f"{total / MAX_OUTPUT_ROWS:.3g} s")

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], base_dir: Path | None = None) -> Scene:
        """Validate and convert a parsed TOML document."""
        _check_keys("scene", data, cls._TOP)
        title = str(_require("scene", data, "title"))
        raw_bearings = _require("scene", data, "bearings")
        if isinstance(raw_bearings, Mapping):
            raw_bearings = [raw_bearings]
        if not isinstance(raw_bearings, list) or not raw_bearings:
            raise InputError("bearings", raw_bearings,
                             "one or more [[bearings]] tables (name, preset or path)")
        bearings = tuple(BearingSpec.from_dict(_table(f"bearings[{i}]", b), i)
                         for i, b in enumerate(raw_bearings))
        names = [b.name for b in bearings]
        if len(set(names)) != len(names):
            raise InputError("bearings[].name", names, "unique names")
        lub = dict(_table("lubricant", _require("scene", data, "lubricant")))
        _check_keys("lubricant", lub, ("preset", "path"))
        if ("preset" in lub) == ("path" in lub):
            raise InputError("lubricant", lub, "exactly one of 'preset' or 'path'")
        for key in ("preset", "path"):
            if key in lub and (not isinstance(lub[key], str) or not lub[key].strip()):
                # (preset = 0 stopped with a KeyError, preset = -1 with a TypeError)
                raise InputError(f"lubricant.{key}", lub[key],
                                 "a preset name, e.g. ISO_VG32 (the files of configs/lubricants)"
                                 if key == "preset" else "a lubricant TOML file path")
        for name in ("supply", "environment", "schedule", "models", "network", "solver",
                     "outputs", "measured", "checks"):
            if name in data:
                _table(name, data[name])
        if "path" in lub:
            lub_path = Path(str(lub["path"]))
            if not lub_path.is_absolute() and base_dir is not None:
                lub_path = Path(base_dir) / lub_path
            if not lub_path.is_file():
                raise InputError("lubricant.path", lub["path"],
                                 f"an existing lubricant TOML file (looked at {lub_path})")
        env = Environment.from_dict(data.get("environment", {}))
        _check_model_types(_table("models", data.get("models", {})))
        network = dict(data.get("network", {}))
        solver = Solver.from_dict(data.get("solver", {}))
        scene = cls(
            title=title,
            source=str(data.get("source", "")),
            bearings=bearings,
            lubricant=lub,
            supply=Supply.from_dict(data.get("supply", {}), env.ambient_temperature),
            environment=env,
            schedule=Schedule.from_dict(_require("scene", data, "schedule"), base_dir),
            models=dict(data.get("models", {})),
            network=network,
            solver=solver,
            outputs=Outputs.from_dict(data.get("outputs", {})),
            measured=Measured.from_dict(data["measured"]) if "measured" in data else None,
            base_dir=str(base_dir) if base_dir is not None else None,
            checks=checks_from_dict(data["checks"]) if "checks" in data else None,
        )
        # names, keys and units of [network] now; the template's required parameters only
        # when the scene is run (check_network(..., require=True) in `run` / `check`), so
        # a scene that never builds its network still loads
        check_network(network, require=False, bearing_names=names)
        return scene

    def to_dict(self) -> dict[str, Any]:
        """The resolved scene as a TOML-ready dict (SI floats back to unit strings); a deep
        copy, so editing it never changes the scene."""
        return copy.deepcopy(self._to_dict())

    def _to_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"title": self.title}
        if self.source:
            out["source"] = self.source
        out["bearings"] = [b.to_dict() for b in self.bearings]
        out["lubricant"] = dict(self.lubricant)
        out["supply"] = self.supply.to_dict()
        out["environment"] = self.environment.to_dict()
        out["schedule"] = self.schedule.to_dict()
        if self.models:
            out["models"] = dict(self.models)
        if self.network:
            out["network"] = dict(self.network)
        out["solver"] = self.solver.to_dict()
        out["outputs"] = self.outputs.to_dict()
        if self.checks is not None:
            out["checks"] = checks_to_dict(self.checks)
        if self.measured is not None:
            out["measured"] = self.measured.to_dict()
        return out

    def to_toml(self) -> str:
        """TOML text that :func:`loads_scene` reads back to an equal scene."""
        return dumps_toml(self.to_dict())

    def with_changes(self, **changes: Any) -> Scene:
        """A copy with some top-level fields replaced, e.g.
        ``scene.with_changes(supply=dataclasses.replace(scene.supply, flow=2.5e-4))``; the
        sections check their values as their TOML tables are checked."""
        known = [f.name for f in fields(self)]
        for name in changes:
            if name not in known:  # was a TypeError from dataclasses.replace
                raise UnknownNameError("Scene field", name, known)
        return replace(self, **changes)

    def resolve_path(self, name: str) -> Path:
        """A path given in the scene, relative to the scene file's folder."""
        p = Path(name)
        if not p.is_absolute() and self.base_dir:
            p = Path(self.base_dir) / p
        return p


def _check_model_types(models: Mapping[str, Any]) -> None:
    """The value types of ``[models]`` (the names themselves are checked against the
    registries when the model chain is planned): one name per family, a list of names
    for ``heat_sources``, a table for ``heat_source_options``."""
    for key, value in models.items():
        if key == "heat_sources":
            if isinstance(value, str):
                continue
            if not (isinstance(value, list) and all(isinstance(v, str) for v in value)):
                raise InputError("models.heat_sources", value,
                                 "a heat-source name or an array of names")
        elif key == "heat_source_options":
            _table("models.heat_source_options", value)
        elif key == "film_options":  # keys, units and ranges: scene_film (chain planning)
            _table("models.film_options", value)
        elif key == "ball_rolling_resistance" and isinstance(value, Mapping):
            continue  # { model = ..., reduction = ... }: checked with the model names
        elif not isinstance(value, str):
            raise InputError(f"models.{key}", value, "a model name (a string)")


def with_absolute_paths(scene: Scene) -> Scene:
    """The scene with its relative file paths (bearing / lubricant TOMLs, measured CSV) made
    absolute against its folder, so that its TOML text (a results folder's ``scene.toml``,
    a sweep case) still finds them when read from elsewhere."""
    if not scene.base_dir:
        return scene
    base = Path(scene.base_dir)
    d = scene.to_dict()
    changed = False
    tables = [*d.get("bearings", []), d.get("lubricant"), d.get("measured")]
    for table, key in zip(tables, ["path"] * (len(tables) - 1) + ["file"], strict=True):
        if isinstance(table, dict) and isinstance(table.get(key), str) \
                and not Path(table[key]).is_absolute():
            table[key] = str((base / table[key]).resolve())
            changed = True
    if not changed:
        return scene
    # the schedule as loaded: the same steps, with its notes on bare numbers (the TOML
    # round trip writes every step with its unit)
    return replace(Scene.from_dict(d, base), schedule=scene.schedule)


# ---------------------------------------------------------------------------
def configs_dir() -> Path:
    """The repository's ``configs`` folder (bearings, lubricants, scenes)."""
    return Path(__file__).resolve().parents[1] / "configs"


DEFAULT_SCENE = "qj1044_rig"


def scene_presets() -> list[str]:
    """Names of the scene presets in ``configs/scenes`` (for :func:`load_scene`)."""
    folder = configs_dir() / "scenes"
    return sorted(p.stem for p in folder.glob("*.toml"))


def loads_scene(text: str, base_dir: Path | None = None, source: str | None = None) -> Scene:
    """Parse TOML text into a :class:`Scene` (``source``: the file name for messages)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("scene", source or "<toml>", f"valid TOML ({exc})") from None
    if not data:  # an empty file said only "scene.title is missing"
        raise InputError("scene", source or "<toml>",
                         "a scene: this TOML has no key at all (an empty or unsaved file?); "
                         "copy configs/scenes/qj1044_rig.toml to start one")
    return Scene.from_dict(data, base_dir)


def load_scene(name_or_path: str | Path | None = None) -> Scene:
    """Load a scene from a TOML path or a preset name in ``configs/scenes`` (default scene
    when ``None``). A ``.toml`` name or a path with a folder in it that is not a file is
    refused naming where it was looked for (not as a misspelt preset)."""
    if name_or_path is None:
        name_or_path = DEFAULT_SCENE
    path = Path(name_or_path)
    if not path.is_file():
        looks_like_file = (path.suffix.lower() == ".toml" or len(path.parts) > 1
                           or path.is_dir())
        if looks_like_file:  # a path, not a misspelt preset name: say where it was looked for
            where = "a folder" if path.is_dir() else "no such file"
            raise InputError("scene", str(name_or_path),
                             f"a scene TOML file ({where}: {path.absolute()}) or a preset "
                             "name: " + ", ".join(scene_presets()))
        preset = configs_dir() / "scenes" / f"{name_or_path}.toml"
        if not preset.is_file():
            raise UnknownNameError("scene", str(name_or_path), scene_presets())
        path = preset
    from .text_files import toml_text

    try:
        text = toml_text(path)  # a byte-order mark skipped; not UTF-8: said where
    except tomllib.TOMLDecodeError as exc:
        raise InputError("scene", str(path), f"valid TOML ({exc})") from None
    return loads_scene(text, base_dir=path.parent, source=str(path))


# the pre-run checks live in scene_checks (one job per module); re-exported here, where
# callers have always found them
from .scene_checks import (  # noqa: E402, F401
    check_measured_file,
    check_model_names,
    check_network,
)
