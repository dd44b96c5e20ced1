"""The one orchestrator: ``Simulation(scene).run() -> Results``.

It wires, in a fixed order, only the models the scene's outputs need and holds no physics
of its own:

lubricant -> load distribution and contacts -> film -> kinematics (race control or the
skidding solver, warm-started) -> heat sources -> thermal network -> temperatures, which
feed back into the viscosity.

Model only what a scene needs (:func:`plan_chain`): ``film`` alone runs no kinematics and
no network; ``kinematics``/``losses`` run no network; ``temperatures``/``energy`` add the
network and the transient stepper (or the steady solve in ``mode = "steady"``).

Coupled transient (``mode = "transient"``)
------------------------------------------
Each schedule step is cut into ``chunks`` (solver.chunk, default 90 s: BM-7 found it the
cheapest setting within 1 K / 5 % on the default protocol). At the start of a
chunk the heat sources are evaluated on the current kinematic state at the current node
temperatures, and linearised in the node temperatures by finite differences (one extra
evaluation per node of the bearing's group): q(T) = q0 + J (T - T0). The network stepper
(TR-BDF2 by default) integrates the chunk with that affine heat and its constant Jacobian,
so the temperature feedback on viscosity is implicit inside the step. The Jacobian is
recomputed at each load step and after each kinematics re-solve, and reused (with fresh heat)
for the other chunks. The kinematics
(skidding solver) are re-solved at a step change and whenever the oil viscosity at the
contact temperature has moved by more than ``solver.kinematics_tolerance`` (relative)
since the last solve: the losses scale with a power < 1 of the viscosity, so this bounds
their change. Steady mode (``mode = "steady"``): for each step the coupled fixed point
of network and heat sources by Newton (affine heat with its Jacobian), with the kinematics
re-solved until the temperatures stop moving.
"""

from __future__ import annotations

import math
import sys
import time
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .citations import cite
from .errors import ConvergenceError, InputError, UnknownNameError, ValidityWarning
from .kinematic_models import KINEMATICS, KinematicsResult
from .operating_checks import (
    CheckLimits,
    CheckLog,
    check_film_rows,
    check_state,
    composite_roughness,
)
from .results import Results, ResultsWriter
from .scene import Scene, Step, loads_scene
from .state import OilSupply, OperatingPoint
from .units import from_si

#: validity warnings printed by :meth:`Simulation.summary_text` (the report lists all)
MAX_SHOWN_WARNINGS = 8
#: The keys a scene's ``[models]`` table accepts.
MODEL_KEYS = frozenset({"kinematics", "film", "heat_sources", "heat_source_options", "control",
                        "churning_heat_to", "calibration"})
BALL_SOURCES = ("raceway_traction", "churning_elements", "churning_cage", "churning_inner_ring",
                "cage_guide", "pocket_friction")
ROLLER_SOURCES = ("raceway_traction", "ehl_rolling_resistance", "churning_elements",
                  "churning_cage", "churning_inner_ring", "cage_guide", "pocket_friction",
                  "rib_friction")


@dataclass(frozen=True)
class ChainLink:
    """One model of the chain: family, registered name, citation keys, why it runs."""

    family: str
    name: str
    references: tuple[str, ...]
    purpose: str


def _needs(scene: Scene) -> dict[str, bool]:
    want = set(scene.outputs.want)
    thermal = bool(want & {"temperatures", "energy"})
    losses = thermal or "losses" in want or "report" in want
    kin = losses or "kinematics" in want
    return {"film": True, "kinematics": kin, "losses": losses, "network": thermal,
            "transient": thermal and scene.outputs.mode == "transient"}


def heat_source_names(scene: Scene, is_ball: bool) -> tuple[str, ...]:
    """Heat sources of the scene (``[models] heat_sources``) or the defaults per type."""
    names = scene.models.get("heat_sources")
    if names is None:
        if scene.models.get("kinematics") == "none":
            return ("global_friction",)
        return BALL_SOURCES if is_ball else ROLLER_SOURCES
    if isinstance(names, str):
        names = [names]
    return tuple(names)


def scene_heat_source_options(scene: Scene, sources: Sequence[str]) -> dict[str, dict]:
    """``[models] heat_source_options`` checked and converted to SI.

    A table per heat source, e.g. ``{ rib_friction = { model = "reduced", unbalance_mass =
    "0.11 g" } }``. Each source must be one of ``sources`` (the scene's heat sources) and
    each parameter one its registry entry documents; unit strings are converted to the
    documented SI unit, numbers are taken as SI, and strings of dimensionless (``"-"``)
    parameters are passed as names (the source checks them) unless the parameter has a
    documented interval (a number: ``"50 %"`` is 0.5). Numeric values are checked
    against the interval the entry documents (``limits``), so ``thermobearing check``
    refuses e.g. a negative gap or an oil fraction above 1 before anything is solved.
    """
    from .heat_sources import HEAT_SOURCES
    from .units import to_si

    raw = scene.models.get("heat_source_options", {})
    if not isinstance(raw, Mapping):
        raise InputError("models.heat_source_options", raw,
                         "a table of heat-source name -> table of parameters")
    out: dict[str, dict] = {}
    for src, params in raw.items():
        field_name = f"models.heat_source_options.{src}"
        if src not in sources:
            raise InputError(field_name, src, "one of the scene's heat sources: "
                             + ", ".join(sources))
        if not isinstance(params, Mapping):
            raise InputError(field_name, params, "a table of parameter = value")
        entry = HEAT_SOURCES.entry(src)
        documented = entry.parameters
        conv: dict[str, Any] = {}
        for key, value in params.items():
            if key not in documented:
                raise InputError(f"{field_name}.{key}", value,
                                 "a documented parameter of " + src + ": "
                                 + ", ".join(sorted(documented)))
            unit = documented[key]
            if isinstance(value, str) and unit == "-" and key not in entry.limits:
                conv[key] = value  # a name (form, model): the source checks it
                continue
            conv[key] = to_si(value, "" if unit == "-" else unit, field=f"{field_name}.{key}")
            try:  # the documented interval (registry limits), checked here: at `check`
                entry.check_parameter(key, conv[key], f"{field_name}.{key}")
            except InputError as exc:
                read = "" if conv[key] == value else f" (read as {conv[key]:g} {unit})"
                raise InputError(f"{field_name}.{key}", value, f"{exc.allowed}{read}") from None
        out[src] = conv
    return out


def _rib_friction_unavailable(bearing: Any) -> str | None:
    """Why the ``rib_friction`` source cannot run on this bearing, or None."""
    from .rib import rib_geometry

    if getattr(bearing, "kind", None) != "cylindrical":
        return "not a cylindrical roller bearing"
    if getattr(bearing, "ribbed_ring", "inner") == "outer":
        return "ribs on the outer ring only (paper 003's inner-ring rib model)"
    try:
        rib_geometry(bearing)
    except InputError as exc:
        return str(exc)
    return None


def plan_chain(scene: Scene, lubricant: Any | None = None,
               is_ball: bool = True) -> list[ChainLink]:
    """The minimal model chain for the scene's outputs (see the module docstring)."""
    from .film import FILM
    from .lubricant import PRESSURE_VISCOSITY, VISCOSITY_TEMPERATURE

    for key in scene.models:
        if key not in MODEL_KEYS:
            raise InputError(f"models.{key}", scene.models[key],
                             "a known model family: " + ", ".join(sorted(MODEL_KEYS)))
    need = _needs(scene)
    links: list[ChainLink] = []

    def add(registry: Any, name: str, purpose: str) -> None:
        entry = registry.entry(name)
        links.append(ChainLink(registry.family, name, entry.references, purpose))

    if lubricant is not None:
        add(VISCOSITY_TEMPERATURE, lubricant.viscosity_law, "oil viscosity at node temperatures")
        add(PRESSURE_VISCOSITY, lubricant.pressure_law, "viscosity at contact pressure")
    film = scene.models.get("film", "hamrock_dowson_1977_central" if is_ball
                            else "pan_hamrock_central")
    if film not in FILM and film in _numerical_film_models():
        from .ehl import EHL_SOLVERS

        check_film_model(film, is_ball)
        add(EHL_SOLVERS, film, "film thickness and drag of the roller-race line contacts "
            "(numerical EHL, interpolation table over load, speed, sliding, temperature)")
    else:
        if film not in FILM:
            raise UnknownNameError("models.film", film,
                                   FILM.names() + _numerical_film_models())
        add(FILM, film, "film thickness of the raceway contacts")
    if need["kinematics"]:
        add(KINEMATICS, scene.models.get("kinematics", "skidding"),
            "cage and element speeds, sliding speeds")
    if need["losses"]:
        from .heat_sources import HEAT_SOURCES

        for name in heat_source_names(scene, is_ball):
            add(HEAT_SOURCES, name, "power loss")
    if need["network"]:
        from .network import STEPPERS
        from .network.templates import TEMPLATES

        add(TEMPLATES, scene.network.get("template", "four_node_paper002"),
            "thermal network")
        if need["transient"]:
            add(STEPPERS, scene.solver.stepper, "transient temperatures")
    return links


def _numerical_film_models() -> list[str]:
    """Names of the numerical line-contact film models (``thermobearing.ehl.EHL_SOLVERS``)."""
    from .ehl import EHL_SOLVERS

    return EHL_SOLVERS.names()


def check_film_model(film: str, is_ball: bool) -> None:
    """Numerical EHL film models are line-contact (roller) models: InputError for balls."""
    from .film import FILM

    if is_ball and film not in FILM and film in _numerical_film_models():
        raise InputError(
            "models.film", film,
            "a closed-form film model for ball bearings (" + ", ".join(FILM.names())
            + "); " + " and ".join(repr(n) for n in _numerical_film_models())
            + " solve line contacts and apply to roller bearings only")


def film_kinematics_options(film: str | None, bearing: Any, lubricant: Any,
                            is_ball: bool) -> dict[str, Any]:
    """Roller-solver options that put a numerical film model in the quasi-dynamics.

    ``numerical_tehl``: a :class:`thermobearing.ehl.coupling.TehlFilmModel` (one per bearing,
    its interpolation table lives as long as the Simulation) as ``film_model`` and the
    ``numerical_tehl`` drag model; ``numerical_ehl``: the isothermal numerical drag model.
    Closed-form names: no options (the roller solver keeps its own default film).
    """
    from .film import FILM

    if film is None or film in FILM or film not in _numerical_film_models():
        return {}
    check_film_model(film, is_ball)
    if film == "numerical_tehl":
        from .ehl.coupling import roller_film_model

        return {"film_model": roller_film_model(bearing, lubricant),
                "drag_model": "numerical_tehl"}
    return {"drag_model": film}


# ---------------------------------------------------------------------------
@dataclass
class _Bearing:
    """One bearing of the scene with its models and warm-start memory."""

    name: str
    key: str
    bearing: Any
    is_ball: bool
    sources: tuple[str, ...]
    kinematics_name: str
    kin_options: dict[str, Any]
    last: KinematicsResult | None = None
    last_viscosity: float = math.nan
    last_step: int = -1
    solves: int = 0


@dataclass
class _Evaluation:
    """Heat of one bearing at one state: per role, per source/component, and diagnostics."""

    by_role: dict[str, float]
    rows: list[dict[str, Any]] = field(default_factory=list)
    #: temperature roles the sources read (the heat depends on no other node temperature)
    reads: frozenset[str] = frozenset(("inner_ring", "outer_ring", "elements", "cage", "oil"))


def _load_scene_bearing(src: str, overrides: Mapping[str, Any] | None, where: str) -> Any:
    """``load_bearing`` with the scene's overrides; an override the bearing refuses is named
    by its scene field (``bearings[0].overrides.contact_angle``) with the value as written
    (``'90 deg'``), the converted SI value beside the rule."""
    from .geometry import load_bearing

    try:
        return load_bearing(src, overrides=overrides or None)
    except InputError as exc:
        key = str(exc.field).rsplit(".", 1)[-1]
        if overrides and key in overrides and type(exc) is InputError:
            raise InputError(f"{where}.overrides.{key}", overrides[key],
                             f"{exc.allowed} (checked in SI: {exc.value!r})") from None
        raise


def _supply_notes(scene: Scene) -> list[str]:
    """What the scene sets that its oil supply does not use (said, not refused). An oil
    bath's inlet temperature defaults to the ambient one: only another value was set by the
    user and is worth a note (session 12: every oil-bath run said so, as a warning)."""
    sup = scene.supply
    if (sup.method == "oil_bath" and sup.flow == 0.0
            and sup.inlet_temperature != scene.environment.ambient_temperature):
        return [f"supply.inlet_temperature ({sup.inlet_temperature - 273.15:g} degC) is not "
                "used: an oil bath without flow has no inlet; the bath temperature is the "
                "network's oil node"]
    return []


class Simulation:
    """Run a scene.

    Parameters
    ----------
    scene : the configured study (:func:`thermobearing.scene.load_scene`).
    progress : show a progress bar (default: when stderr is a terminal).
    """

    def __init__(self, scene: Scene, *, progress: bool | None = None) -> None:
        from . import load_lubricant
        from .scene_checks import check_model_names

        check_model_names(scene)  # the error names the scene field and the known names
        self.scene = scene
        self.progress = sys.stderr.isatty() if progress is None else bool(progress)
        lub_spec = scene.lubricant
        self.lubricant = load_lubricant(lub_spec.get("preset") or
                                        str(scene.resolve_path(lub_spec["path"])))
        self.supply = OilSupply.from_scene(scene.supply)
        self.notes: list[str] = _supply_notes(scene)
        kin_name = scene.models.get("kinematics", "skidding")
        KINEMATICS.entry(kin_name)
        kin_options: dict[str, Any] = {}
        if "control" in scene.models:
            kin_options["control"] = scene.models["control"]
        self.bearings: list[_Bearing] = []
        dropped: list[str] = []
        for i_spec, spec in enumerate(scene.bearings):
            src = spec.preset or str(scene.resolve_path(spec.path))
            b = _load_scene_bearing(src, spec.overrides, f"bearings[{i_spec}]")
            is_ball = hasattr(b, "ball_diameter")
            opts = dict(kin_options)
            opts.update(film_kinematics_options(scene.models.get("film"), b, self.lubricant,
                                                is_ball))
            if is_ball:
                params, b, note = _apply_calibration(b, spec, scene)
                opts["params"] = params
                if note and note not in self.notes:
                    self.notes.append(note)
            key = repr((spec.preset, spec.path, sorted(spec.overrides.items())))
            sources = heat_source_names(scene, is_ball)
            why = ("rib_friction" in sources and "heat_sources" not in scene.models
                   and _rib_friction_unavailable(b))
            if why:  # a default source the bearing's geometry cannot host: left out, said
                sources = tuple(n for n in sources if n != "rib_friction")
                # the hint only where the bearing's data can fix it (session 12: it was
                # also printed for outer-ring ribs, which no key of the bearing changes)
                hint = ("" if why.startswith(("ribs on the outer ring", "not a cylindrical"))
                        else "; name it in [models] heat_sources once the bearing has "
                             "end_face_crown_radius and rib_height")
                dropped.append(f"{spec.name}: default heat source rib_friction left out "
                               f"({why}){hint}")
            self.bearings.append(_Bearing(spec.name, key, b, is_ball, sources, kin_name, opts))
        from .heat_sources import HEAT_SOURCES

        HEAT_SOURCE_FAMILY = HEAT_SOURCES.family
        running = {n for b in self.bearings for n in b.sources}
        self.chain = [link for link in plan_chain(scene, self.lubricant, self.bearings[0].is_ball)
                      if link.family != HEAT_SOURCE_FAMILY or link.name in running]
        self.needs = _needs(scene)
        self.network = None
        # a source left out matters only to a run that books losses (a film-only or
        # kinematics-only scene runs no heat source: nothing to say; session 12)
        self.warnings: list[str] = list(self.notes) + (
            dropped if _needs(scene)["losses"] else [])
        self.source_options = scene_heat_source_options(
            scene, tuple(dict.fromkeys(n for b in self.bearings for n in b.sources)))
        # identical bearings (same preset and overrides) at the same state share results
        self._kin_shared: dict[tuple[str, int], tuple[float, KinematicsResult]] = {}
        self._heat_memo: dict[tuple[str, str], list[tuple[Any, ...]]] = {}
        #: thresholds of the validity checks: the scene's [checks], else the defaults
        self.check_limits = scene.checks if scene.checks is not None else CheckLimits()
        #: validity checks of every solved kinematic state, per bearing (report warnings)
        self.checks = {b.name: CheckLog(b.name, composite_roughness(b.bearing),
                                        limits=self.check_limits)
                       for b in self.bearings}

    # ------------------------------------------------------------------ chain
    def describe_chain(self, with_citations: bool = False) -> str:
        """The model chain as text (``thermobearing check``)."""
        lines = ["model chain:"]
        for i, link in enumerate(self.chain, 1):
            lines.append(f"  {i}. {link.family}: {link.name}  ({link.purpose})")
            if with_citations:
                lines.extend(f"       {c}" for c in cite(link.references))
        lines.extend(f"  note: {n}" for n in self.notes)
        return "\n".join(lines)

    def citations(self) -> list[str]:
        return cite(k for link in self.chain for k in link.references)

    def estimated_inputs(self) -> dict[str, dict[str, str]]:
        """The input values no source gives, with the reasoning of each: per scene bearing
        (its config's ``estimated`` table, including what ``estimate_missing`` filled) and
        ``"lubricant"``; empty entries are left out."""
        out = {f"bearing {b.name} ({b.bearing.name})": dict(b.bearing.estimated)
               for b in self.bearings if b.bearing.estimated}
        lub = dict(getattr(self.lubricant, "estimated", {}) or {})
        if lub:
            out[f"lubricant ({self.lubricant.name})"] = lub
        return out

    def describe_estimates(self) -> str:
        """One line per bearing / lubricant with the estimated fields (``thermobearing
        check``); the reasoning of each is in the report."""
        lines = ["estimated inputs (no source gives them; reasoning in the report):"]
        for what, fields_ in self.estimated_inputs().items():
            filled = sum(v.startswith("estimate_missing:") for v in fields_.values())
            how = f", {filled} by estimate_missing" if filled else ""
            lines.append(f"  {what}: {len(fields_)} values{how}: " + ", ".join(fields_))
        return "\n".join(lines) if len(lines) > 1 else ""

    # ------------------------------------------------------------ evaluation
    def _operating(self, step: Step) -> OperatingPoint:
        return OperatingPoint(inner_speed=step.speed, radial_load=step.radial_load,
                              axial_load=step.axial_load)

    def solve_kinematics(self, b: _Bearing, step_index: int, step: Step,
                    temps: Mapping[str, float]) -> KinematicsResult:
        """Solve (or reuse) the kinematics of one bearing at the current temperatures."""
        t_contact = 0.5 * (temps["inner_ring"] + temps["outer_ring"])
        visc = float(self.lubricant.dynamic_viscosity(t_contact))
        tol = self.scene.solver.kinematics_tolerance
        if (b.last is not None and b.last_step == step_index
                and abs(visc / b.last_viscosity - 1.0) <= tol):
            return b.last
        shared = self._kin_shared.get((b.key, step_index))
        if shared is not None and abs(visc / shared[0] - 1.0) <= tol:
            b.last, b.last_viscosity, b.last_step = shared[1], shared[0], step_index
            self.checks[b.name].record(step_index, check_state(b.bearing, shared[1],
                                                               self.check_limits))
            return shared[1]
        op = self._operating(step)
        fn = KINEMATICS.get(b.kinematics_name)
        guess = b.last if b.last is not None else None
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", ValidityWarning)
            try:
                res = fn(b.bearing, self.lubricant, op, contact_temperature=t_contact,
                         oil_temperature=temps["oil"], supply=self.supply, guess=guess,
                         options=b.kin_options)
            except ConvergenceError:
                if guess is None:
                    raise
                res = fn(b.bearing, self.lubricant, op, contact_temperature=t_contact,
                         oil_temperature=temps["oil"], supply=self.supply, guess=None,
                         options=b.kin_options)
        self._note(caught, f"{b.name}, step {step_index}")
        if not res.converged:
            raise ConvergenceError(f"kinematics ({b.kinematics_name}) of {b.name}",
                                   res.residual_norm, "at step", {"step": step_index})
        b.last, b.last_viscosity, b.last_step = res, visc, step_index
        self._kin_shared[(b.key, step_index)] = (visc, res)
        b.solves += 1
        self.checks[b.name].record(step_index, check_state(b.bearing, res, self.check_limits))
        return res

    def _note(self, caught: Sequence[warnings.WarningMessage], where: str) -> None:
        for w in caught:
            text = f"{where}: {w.message}"
            if text not in self.warnings and len(self.warnings) < 200:
                self.warnings.append(text)

    def evaluate_heat(self, b: _Bearing, step: Step, kin: KinematicsResult,
                      temps: Mapping[str, float], with_rows: bool = False) -> _Evaluation:
        """Heat of the bearing's sources at the given role temperatures.

        Memoised per source: a source's result is reused while the kinematic state is the
        same and every temperature role it read (``heat_sources.RoleTemperatures``) is
        unchanged -- e.g. the raceway shear of a skidding state, computed at the solver's
        contact temperature, is evaluated once per kinematics solve, not once per
        finite-difference column. Two identical bearings in the same state share results.
        ``reads`` of the evaluation is the union of the roles the sources read.
        """
        from .heat_sources import HeatContext, evaluate_recorded

        temps = {r: float(v) for r, v in temps.items()}
        memo = self._heat_memo
        if len(memo) > 512:
            memo.clear()
        found: dict[str, tuple[Any, frozenset[str]]] = {}
        for name in b.sources:
            for entry_kin, entry_step, reads, values, result in memo.get((b.key, name), ()):
                if (entry_kin is kin and (entry_step is step or entry_step == step)
                        and all(temps.get(r) == values[r] for r in reads)):
                    found[name] = (result, reads)
                    break
        missing = [name for name in b.sources if name not in found]
        if missing:
            ctx = HeatContext(bearing=b.bearing, lubricant=self.lubricant, supply=self.supply,
                              operating=self._operating(step), temperatures=temps,
                              kinematics=kin.state, traction=kin.traction,
                              options=self._heat_options(kin))
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", ValidityWarning)
                computed = evaluate_recorded(missing, ctx)
            self._note(caught, b.name)
            for name, (result, reads) in zip(missing, computed, strict=True):
                found[name] = (result, reads)
                entries = memo.setdefault((b.key, name), [])
                entries.insert(0, (kin, step, reads, {r: temps.get(r) for r in reads}, result))
                del entries[8:]
        by_role = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 0.0)
        rows = []
        reads_all: set[str] = set()
        for name in b.sources:
            r, reads = found[name]
            reads_all |= reads
            for role, p in r.power_by_role.items():
                by_role[role] += p
            if with_rows:
                for comp, p in r.components.items():
                    rows.append({"source": r.source, "component": comp,
                                 "power [W]": p,
                                 "load dependence": r.loss_class.get(comp, "")})
        return _Evaluation(by_role, rows, frozenset(reads_all))

    def _heat_options(self, kin: KinematicsResult) -> dict[str, Any]:
        """Heat-source options: those matching the kinematics' force models, plus where
        churning heat is booked (``[models] churning_heat_to``).

        ``"oil"`` (default): the viscous dissipation of churning and drag happens in the oil
        and the oil stream carries it away, so all churning heat goes to the oil node.
        ``"paper002"``: as paper 002 eqs. 22-25 book it (ball churning on the balls, inner
        ring churning on the shaft, cage churning on the oil+cage node).
        """
        opts = {k: dict(v) for k, v in kin.heat_options.items()}
        for src, params in self.source_options.items():
            mine = opts.setdefault(src, {})
            clash = sorted(set(params) & set(mine))
            if clash:
                raise InputError(
                    f"models.heat_source_options.{src}.{clash[0]}", params[clash[0]],
                    "a parameter the kinematics model does not set: it sets "
                    f"{', '.join(sorted(mine))} to match its own force models (change those "
                    "through the bearing's calibration instead)")
            mine.update(params)
        target = self.scene.models.get("churning_heat_to", "oil")
        if target not in ("oil", "paper002"):
            raise InputError("models.churning_heat_to", target, "'oil' or 'paper002'")
        if target == "oil":
            for src in ("churning_elements", "churning_inner_ring", "churning_cage"):
                opts.setdefault(src, {})["role"] = "oil"
        return opts

    # ------------------------------------------------------------------- run
    def run(self, out_dir: Path | str | None = None) -> Results:
        """Run the scene; write results to ``out_dir`` as they are computed (if given)."""
        from .scene import with_absolute_paths
        from .scene_checks import check_measured_file, check_network

        # what loading cannot know wrong fails here, before any model is solved (the CLI
        # runs the same checks earlier): the network template's required parameters and
        # the measured CSV (columns, numbers, increasing times)
        check_network(self.scene.network, require=bool(self.needs.get("network")))
        check_measured_file(self.scene)
        writer = ResultsWriter(out_dir) if out_dir is not None else None
        t_wall = time.perf_counter()
        # absolute file paths: the results folder's scene.toml still finds its files
        scene_toml = with_absolute_paths(self.scene).to_toml()
        if writer is not None:
            (Path(out_dir) / "scene.toml").write_text(scene_toml, encoding="utf-8")
        if self.needs["network"]:
            from .coupled import run_coupled

            tables, stats = run_coupled(self, writer)
        else:
            tables, stats = self._run_operating_points(writer)
        stats["wall_time_s"] = time.perf_counter() - t_wall
        stats["kinematics_solves"] = sum(b.solves for b in self.bearings)
        for b in self.bearings:
            # the numerical film's table work (numerical_tehl): how often it answered from
            # the table and how much CPU its thermal solves cost (session 12: a run sat
            # minutes in them without a sign)
            fm = b.kin_options.get("film_model")
            if fm is not None and hasattr(fm, "solve_time"):
                stats[f"{b.name}: film table"] = {"solves": int(fm.solves),
                                                  "queries": int(fm.queries),
                                                  "solve_cpu_s": float(fm.solve_time)}
        checked = [line for log in self.checks.values() for line in log.summary()]
        # the thresholds are recorded when some state was checked
        limits = self.check_limits.as_dict() if any(
            log.steps for log in self.checks.values()) else {}
        results = Results(tables=tables, scene_toml=scene_toml,
                          chain=[(link.family, link.name) for link in self.chain],
                          citations=self.citations(), warnings=list(self.warnings) + checked,
                          stats=stats, check_limits=limits,
                          estimated=self.estimated_inputs())
        if out_dir is not None:
            from .report import attach_figures, write_report

            attach_figures(results, self.scene)
            results.write(out_dir)
            write_report(results, self.scene, Path(out_dir) / "report.html")
        return results

    def _run_operating_points(self, writer: ResultsWriter | None
                              ) -> tuple[dict[str, pd.DataFrame], dict[str, Any]]:
        """Kinematics and/or losses per schedule step at the initial temperature."""
        from tqdm.auto import tqdm

        t0 = self.scene.environment.initial_temperature
        temps = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), t0)
        kin_rows: list[dict[str, Any]] = []
        loss_rows: list[dict[str, Any]] = []
        film_rows: list[dict[str, Any]] = []
        steps = self.scene.schedule.steps
        for i, step in enumerate(tqdm(steps, disable=not self.progress, desc="steps")):
            for b in self.bearings:
                base = step_columns(i, 0.0, b.name, step)
                if self.needs["kinematics"]:
                    kin = self.solve_kinematics(b, i, step, temps)
                    row = {**base, **kinematics_columns(kin, b.bearing)}
                    kin_rows.append(row)
                    if writer:
                        writer.append("kinematics", [row])
                    if self.needs["losses"]:
                        ev = self.evaluate_heat(b, step, kin, temps, with_rows=True)
                        rows = [{**base, **r} for r in ev.rows]
                        loss_rows.extend(rows)
                        if writer:
                            writer.append("losses", rows)
                else:
                    rows, csr = film_table(b, self.lubricant, step, temps)
                    film_rows.extend({**base, **r} for r in rows)
                    # the stress and Lambda checks apply to the film rows too
                    self.checks[b.name].record(i, check_film_rows(b.bearing, rows, csr,
                                                                  self.check_limits))
        tables = {}
        if kin_rows:
            tables["kinematics"] = pd.DataFrame(kin_rows)
        if loss_rows:
            tables["losses"] = pd.DataFrame(loss_rows)
        if film_rows:
            tables["film"] = pd.DataFrame(film_rows)
        return tables, {"steps": len(steps)}

    def summary_text(self, results: Results) -> str:
        """A few lines for the terminal."""
        lines = []
        kin = results.tables.get("kinematics")
        if kin is not None and not kin.empty:
            first = kin.iloc[0]
            lines.append(f"CSR at first step: {first['cage speed ratio [-]']:.4f} "
                         f"(theoretical {first['theoretical cage speed ratio [-]']:.4f})")
            k = kin["over-skidding [%]"].to_numpy()
            lines.append(f"over-skidding: max {np.nanmax(k):+.2f} %, min {np.nanmin(k):+.2f} %")
        losses = results.tables.get("losses")
        if losses is not None and not losses.empty:
            per_step = losses.groupby(["step", "bearing"])["power [W]"].sum()
            lines.append(f"total loss per bearing: {per_step.min():.0f} - {per_step.max():.0f} W")
        temps = results.tables.get("temperatures")
        if temps is not None and not temps.empty:
            cols = [c for c in temps.columns if c.endswith("[degC]")]
            lines.append("final temperatures: " + ", ".join(
                f"{c.replace(' [degC]', '')} {temps[c].iloc[-1]:.1f} degC" for c in cols))
        energy = results.tables.get("energy")
        if energy is not None and not energy.empty:
            last = energy.iloc[-1]
            gen = last["generated [J]"]
            lines.append(f"energy audit: generated {gen / 1e6:.3f} MJ, imbalance "
                         f"{abs(last['imbalance [J]']) / max(abs(gen), 1e-300):.2e} (relative)")
        lines.append(f"wall time {results.stats.get('wall_time_s', float('nan')):.2f} s, "
                     f"{results.stats.get('kinematics_solves', 0)} kinematics solves")
        for key, value in results.stats.items():
            if key.endswith(": film table") and isinstance(value, dict):
                lines.append(f"{key} (numerical film): {value['solves']} thermal EHL solves "
                             f"({value['solve_cpu_s']:.1f} s CPU), {value['queries']} queries")
        if results.warnings:
            shown = results.warnings[:MAX_SHOWN_WARNINGS]
            lines.append(f"validity warnings ({len(results.warnings)}; all in the report):")
            lines.extend(f"  - {w}" for w in shown)
            if len(results.warnings) > len(shown):
                lines.append(f"  ... {len(results.warnings) - len(shown)} more")
        return "\n".join(lines)


# ---------------------------------------------------------------------------
def _apply_calibration(bearing: Any, spec: Any, scene: Scene) -> tuple[Any, Any, str]:
    """Ball force-model parameters and bearing for the skidding solver.

    With ``[models] calibration = "preset"`` (default) and a file
    ``configs/bearings/<preset>.calibration.toml`` (written by the skidding calibration,
    fitted on one stated condition), its parameters are used and its diametral clearance
    replaces the preset's estimate unless the scene overrides the clearance. Returns
    (parameters, bearing, note); ``calibration = "none"`` keeps the defaults.
    """
    from .geometry import configs_dir
    from .skidding.ball_models import BallParameters

    mode = scene.models.get("calibration", "preset")
    if mode not in ("preset", "none"):
        raise InputError("models.calibration", mode, "'preset' or 'none'")
    path = Path(configs_dir()) / "bearings" / f"{bearing.name}.calibration.toml"
    if mode == "none" or not path.is_file():
        return BallParameters(), bearing, ""
    from .skidding.qj1044 import load_calibration, with_clearance

    cal = load_calibration(path)
    if "diametral_clearance" not in (spec.overrides or {}):
        bearing = with_clearance(bearing, cal["diametral_clearance"])
    cond = cal["condition"]
    note = (f"calibrated ball force-model parameters from {path.name} "
            f"(fitted at {cond.get('speed')}, {cond.get('flow')}; other conditions are "
            f"predictions)")
    return cal["params"], bearing, note


def step_columns(index: int, time_s: float, bearing: str, step: Step) -> dict[str, Any]:
    """The columns that identify one operating step in the tables."""
    return {"step": index, "time [s]": time_s, "bearing": bearing,
            "speed [rpm]": from_si(step.speed, "rpm"),
            "radial load [kN]": step.radial_load / 1e3,
            "axial load [kN]": step.axial_load / 1e3}


def kinematics_columns(kin: KinematicsResult, bearing: Any) -> dict[str, Any]:
    """Kinematics table columns of one result, with the largest Hertz pressure and the
    smallest film parameter of its loaded contacts (:mod:`.operating_checks`; NaN when
    the bearing gives no roughness)."""
    check = check_state(bearing, kin)
    return {"cage speed ratio [-]": kin.cage_speed_ratio,
            "theoretical cage speed ratio [-]": kin.theoretical_cage_speed_ratio,
            "over-skidding [%]": 100.0 * kin.over_skid,
            "max contact pressure [MPa]": check.max_pressure / 1e6,
            "min film parameter [-]": (math.nan if check.film_parameter is None
                                       else check.film_parameter),
            "converged": kin.converged, "residual": kin.residual_norm,
            "iterations": kin.iterations}


def film_table(b: _Bearing, lubricant: Any, step: Step,
               temps: Mapping[str, float]) -> tuple[list[dict[str, Any]], float]:
    """Contact and film of the most loaded element per raceway (film-only scenes): race
    control. Returns the rows and the state's cage speed ratio [-]."""
    from .state import race_control_state

    op = OperatingPoint(inner_speed=step.speed, radial_load=step.radial_load,
                        axial_load=step.axial_load)
    t_c = 0.5 * (temps["inner_ring"] + temps["outer_ring"])
    state = race_control_state(b.bearing, op, lubricant=lubricant, temperature=t_c)
    rows = []
    numerical = _numerical_film_of(b, lubricant)
    for cs in state.contacts:
        q = np.asarray(cs.normal_load)
        j = int(np.argmax(q))
        extra: dict[str, Any] = {}
        if numerical is not None:
            extra = numerical(cs.race, float(q[j]),
                              float(np.asarray(cs.entrainment_speed)[j]), t_c)
        rows.append({"race": cs.race, "max load [N]": float(q[j]),
                     "max pressure [GPa]": float(np.asarray(cs.max_pressure)[j]) / 1e9,
                     "semi-major a [mm]": float(np.asarray(cs.semi_major)[j]) * 1e3,
                     "semi-minor b [mm]": float(np.asarray(cs.semi_minor)[j]) * 1e3,
                     "contact angle [deg]": math.degrees(float(np.asarray(cs.contact_angle)[j])),
                     "entrainment speed [m/s]": float(np.asarray(cs.entrainment_speed)[j]),
                     "central film [um]": (float(np.asarray(cs.film_thickness)[j]) * 1e6
                                           if cs.film_thickness is not None else math.nan)})
        if extra:
            row = rows[-1]
            row["closed-form central film [um]"] = row["central film [um]"]
            row["central film [um]"] = extra["numerical central film [um]"]
            row["minimum film [um]"] = extra["numerical minimum film [um]"]
            row["film model"] = extra["film model"]
        sigma = composite_roughness(b.bearing)
        if sigma is not None:  # Lambda of the film the row reports (operating_checks)
            row = rows[-1]
            h = row.get("minimum film [um]", row["central film [um]"])
            row["film parameter [-]"] = h * 1e-6 / sigma
    csr = state.cage_speed / state.inner_speed if state.inner_speed else math.nan
    return rows, float(csr)


def _numerical_film_of(b: _Bearing, lubricant: Any) -> Any:
    """For film-only scenes with a numerical film model: ``f(race, load, u_e, T) -> columns``
    (central and minimum film of the numerical model at pure rolling, the closed-form
    central film beside it), else None."""
    model = b.kin_options.get("film_model")
    drag = b.kin_options.get("drag_model")
    if model is None and drag != "numerical_ehl":
        return None
    bearing = b.bearing
    length = bearing.roller_effective_length
    e_prime = bearing.effective_modulus

    def columns(race: str, load: float, ue: float, temperature: float) -> dict[str, Any]:
        rx, _ = bearing.curvature(race)
        w = load / length
        if model is not None:
            res = model.films(w, ue, 0.0, temperature, rx, e_prime)
            hc, hm = float(res.central_film[0]), float(res.minimum_film[0])
            name = "numerical_tehl"
        else:
            from .ehl import EHL_SOLVERS

            p = EHL_SOLVERS.get("numerical_ehl")(w, rx, e_prime, ue, 0.0, temperature,
                                                 lubricant=lubricant)
            hc, hm, name = p.central_film, p.minimum_film, "numerical_ehl"
        return {"film model": name, "numerical central film [um]": hc * 1e6,
                "numerical minimum film [um]": hm * 1e6}

    return columns


def summarize_scene(scene_toml: str) -> dict[str, float]:
    """Sweep runner: run a scene and reduce it to a few numbers.

    Returns, with the unit in each name:

    * ``total loss [W]``: the scene's power loss (all bearings) averaged over the protocol,
      each step weighted by its duration; ``max total loss [W]`` the largest step; one
      ``<source> [W]`` per heat source (all bearings, the same average); with more than one
      bearing also ``total loss <bearing> [W]`` each. (Until session 12 these were plain
      means over the steps of the first bearing only, which their names did not say.)
    * ``max / min over-skidding [%]``, ``max contact pressure [MPa]`` and ``min film
      parameter [-]`` of the solved states (:mod:`.operating_checks`; Lambda when the bearing
      gives its roughness), and ``steps over skid limit [-]``, ``steps over stress limit
      [-]``, ``steps under film limit [-]`` (the scene's ``[checks]`` thresholds; summed over
      bearings), so that a sweep of the thresholds shows what they flag;
    * film-only scenes: ``min central film [um]``, ``min minimum film [um]`` and ``min film
      parameter [-]`` of the film table;
    * with a network: ``final <node> [degC]`` and ``rise <node> [K]`` (final minus the
      node's temperature at the start, the scene's initial temperature; a scene whose inlet
      oil is warmer than that counts the difference in the rise too).
    """
    scene = loads_scene(scene_toml)
    sim = Simulation(scene, progress=False)
    res = sim.run()
    out: dict[str, float] = {}
    durations = {i: float(st.duration) for i, st in enumerate(scene.schedule.steps)}
    losses = res.tables.get("losses")
    if losses is not None and not losses.empty:
        def averaged(frame: pd.DataFrame) -> tuple[pd.DataFrame, pd.Series]:
            per = frame.groupby(["step", "source"])["power [W]"].sum().unstack(fill_value=0.0)
            w = np.array([durations.get(int(i), 0.0) for i in per.index])
            w = w / w.sum() if w.sum() > 0 else np.full(len(per), 1.0 / len(per))
            return per, pd.Series(w, index=per.index)

        per, w = averaged(losses)
        total = per.sum(axis=1)
        out["total loss [W]"] = float((total * w).sum())
        out["max total loss [W]"] = float(total.max())
        for src in per.columns:
            out[f"{src} [W]"] = float((per[src] * w).sum())
        names = list(dict.fromkeys(losses["bearing"]))
        if len(names) > 1:
            for name in names:
                per_b, w_b = averaged(losses[losses["bearing"] == name])
                out[f"total loss {name} [W]"] = float((per_b.sum(axis=1) * w_b).sum())
    kin = res.tables.get("kinematics")
    if kin is not None and not kin.empty:
        out["max over-skidding [%]"] = float(kin["over-skidding [%]"].max())
        out["min over-skidding [%]"] = float(kin["over-skidding [%]"].min())
    states = [c for log in sim.checks.values() for cs in log.steps.values() for c in cs]
    if states:
        out["max contact pressure [MPa]"] = max(c.max_pressure for c in states) / 1e6
        films = [c.film_parameter for c in states if c.film_parameter is not None]
        if films:
            out["min film parameter [-]"] = min(films)
        counts = [log.flagged_steps() for log in sim.checks.values()]
        out["steps over skid limit [-]"] = float(sum(c["skid"] for c in counts))
        out["steps over stress limit [-]"] = float(sum(c["stress"] for c in counts))
        out["steps under film limit [-]"] = float(sum(c["film"] for c in counts))
    film = res.tables.get("film")
    if film is not None and not film.empty and kin is None:
        for col, key in (("central film [um]", "min central film [um]"),
                         ("minimum film [um]", "min minimum film [um]"),
                         ("film parameter [-]", "min film parameter [-]")):
            if col in film:
                out[key] = float(film[col].min())
    temps = res.tables.get("temperatures")
    if temps is not None and not temps.empty:
        for c in temps.columns:
            if c.endswith("[degC]"):
                out[f"final {c}"] = float(temps[c].iloc[-1])
                out[f"rise {c.replace('[degC]', '[K]')}"] = float(temps[c].iloc[-1]
                                                                  - temps[c].iloc[0])
    return out


def check_known(name: str, known: Sequence[str], field_name: str) -> None:
    if name not in known:
        raise UnknownNameError(field_name, name, known)
