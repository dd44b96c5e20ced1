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
temperatures and expanded to second order in each node temperature a source reads, by
central differences (two evaluations per read node; the curvature is continued linearly
beyond 2 K): q(T) = q0 + J (T - T0) + 1/2 H (T - T0)^2 (``coupled._Linear``). The network
stepper (``solver.stepper``, exprb43 by default) integrates the chunk with that quadratic
heat and its Jacobian, so the temperature feedback on viscosity is implicit inside the step.
J and H are recomputed at each load step and after each kinematics re-solve, and reused
(with fresh heat, re-centred) for the other chunks. The kinematic state held over a chunk
is itself temperature dependent: the chunk model adds K (T - T_solve), K a Broyden secant of
each bearing's heat between its consecutive kinematics solves within a step, on the nodes
the kinematics read (:mod:`thermobearing.coupled_secant`); where a step's first chunk is
repeated shorter the first secant comes from one kinematics probe at +0.5 K (stat
``kinematic_probes``). The kinematics (skidding solver) are re-solved at a step change and
whenever the oil viscosity at the contact temperature has moved by more than
``solver.kinematics_tolerance`` (relative) since the last solve: the losses scale with a
power < 1 of the viscosity, so this bounds their change. The contact temperature (the one
the kinematics are solved at and the re-solve test reads) is the inlet oil temperature of
the raceway contacts, (T_inner_ring + T_outer_ring + 2 T_elements) / 4
(:func:`~thermobearing.kinematic_models.contact_temperature`): each contact's inlet oil lies
between the element and its ring, as the heat sources take it. Steady mode
(``mode = "steady"``): for each step the coupled fixed point of network and heat sources by
Newton (the same quadratic heat with its Jacobian), with the
kinematics re-solved until the temperatures stop moving.

The parts it wires live beside it: :mod:`thermobearing.simulation_chain` (the chain plan,
heat-source names and options, film-model options), :mod:`thermobearing.simulation_bearings`
(one scene bearing's record and set-up), :mod:`thermobearing.simulation_tables` (table rows),
:mod:`thermobearing.simulation_summary` (the sweep runner :func:`summarize_scene`); their
public names are importable from here.
"""

from __future__ import annotations

import dataclasses
import math
import sys
import time
import warnings
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .citations import cite
from .errors import (
    ConvergenceError,
    InputError,
    ThermobearingError,
    UnknownNameError,
    ValidityWarning,
)
from .kinematic_models import KINEMATICS, KinematicsResult, contact_temperature
from .operating_checks import (
    CheckLimits,
    CheckLog,
    check_film_rows,
    check_state,
    composite_roughness,
)
from .results import Results, ResultsWriter
from .scene import Scene, Step
from .simulation_bearings import (
    _apply_calibration,
    _Bearing,
    _Evaluation,
    _load_scene_bearing,
    _supply_notes,
    axial_direction,
    axial_load_path,
    level_notes,
    radial_load_contact,
)
from .simulation_chain import (
    BALL_SOURCES,
    MODEL_KEYS,
    ROLLER_SOURCES,
    ChainLink,
    _needs,
    _rib_friction_unavailable,
    ball_rolling_resistance,
    check_film_model,
    film_kinematics_options,
    heat_source_names,
    plan_chain,
    scene_film_options,
    scene_heat_source_options,
)
from .simulation_summary import summarize_scene
from .simulation_tables import (
    DETAIL_TABLES,
    film_table,
    kinematics_columns,
    over_skidding_range,
    step_columns,
)
from .state import OilSupply, OperatingPoint
from .warning_groups import WarningGroups, merge_twin_bearings

__all__ = [
    "BALL_SOURCES", "MAX_SHOWN_WARNINGS", "MODEL_KEYS", "ROLLER_SOURCES", "ChainLink",
    "Simulation", "check_film_model", "check_known", "film_kinematics_options", "film_table",
    "heat_source_names", "kinematics_columns", "plan_chain", "scene_heat_source_options",
    "step_columns", "summarize_scene",
]

#: validity warnings printed by :meth:`Simulation.summary_text` (the report lists all)
MAX_SHOWN_WARNINGS = 8


class Simulation:
    """Run a scene.

    Parameters
    ----------
    scene : the configured study (:func:`thermobearing.scene.load_scene`).
    progress : show a progress bar (default: when stderr is a terminal).

    ``step_log``: a callable given one line per finished schedule step (step i of n, the
    simulated time, the wall time; :meth:`log_step`), or None (the default). ``thermobearing
    run`` sets it to print to stderr when stderr is no terminal (no progress bar: a run
    into a log file said nothing until its end, 30-75 s for the CRB rib example).
    """

    step_log: Callable[[str], None] | None = None
    #: schedule steps finished so far (:meth:`log_step`; None before :meth:`run` starts):
    #: ``thermobearing run`` says how many a Ctrl-C or an error left in the folder
    steps_done: int | None = None

    def __init__(self, scene: Scene, *, progress: bool | None = None) -> None:
        from . import load_lubricant
        from .scene import Scene
        from .scene_checks import check_model_names, check_temperatures

        if not isinstance(scene, Scene):  # Simulation("qj1044_rig"): was an AttributeError
            raise InputError("scene", type(scene).__name__, "a Scene: thermobearing.load_scene"
                             "(preset name or TOML path) or loads_scene(TOML text)")
        check_model_names(scene)  # the error names the scene field and the known names
        self.scene = scene
        self.progress = sys.stderr.isatty() if progress is None else bool(progress)
        lub_spec = scene.lubricant
        self.lubricant = load_lubricant(lub_spec.get("preset") or
                                        str(scene.resolve_path(lub_spec["path"])))
        self.supply = OilSupply.from_scene(scene.supply)
        check_temperatures(scene, self.lubricant)  # a bare 35 in a scene is 35 K
        self.notes: list[str] = [*scene.schedule.unitless, *_supply_notes(scene),
                                 *_data_range_notes(scene, self.lubricant)]
        kin_name = scene.models.get("kinematics", "skidding")
        KINEMATICS.entry(kin_name)
        kin_options: dict[str, Any] = {}
        if "control" in scene.models:
            kin_options["control"] = scene.models["control"]
        self.bearings: list[_Bearing] = []
        dropped: list[str] = []
        for i_spec, spec in enumerate(scene.bearings):
            b = _scene_bearing(scene, spec, i_spec)
            is_ball = hasattr(b, "ball_diameter")
            self.notes.extend(n for n in level_notes(scene, spec.name, b)
                              if n not in self.notes)
            opts = dict(kin_options)
            opts.update(film_kinematics_options(scene.models.get("film"), b, self.lubricant,
                                                is_ball, scene_film_options(scene)))
            if is_ball:
                params, b, note = _apply_calibration(b, spec, scene)
                rr_model, rr_reduction = ball_rolling_resistance(scene)
                if rr_model != "none":
                    params = dataclasses.replace(params, rolling_resistance=rr_model,
                                                 rolling_resistance_reduction=rr_reduction)
                opts["params"] = params
                if note and note not in self.notes:
                    self.notes.append(note)
            key = repr((spec.preset, spec.path, sorted(spec.overrides.items()),
                        spec.radial_share, spec.axial_share))
            sources = heat_source_names(scene, is_ball)
            why = "rib_friction" in sources and _rib_friction_unavailable(b)
            if why and "heat_sources" in scene.models:  # named: refused before the run
                _refuse_rib_geometry(b, spec, i_spec)
                raise InputError(
                    "models.heat_sources", "rib_friction",
                    f"sources every bearing can host; {spec.name!r} ({b.name}) cannot run "
                    f"rib_friction ({why}). Without heat_sources, roller bearings with rib "
                    "geometry run rib_friction by default and the others leave it out")
            if why:  # a default source the bearing's geometry cannot host: left out, said
                geometry_why = _rib_geometry_text(b)
                why = geometry_why or why
                sources = tuple(n for n in sources if n != "rib_friction")
                # the hint only where the bearing's data can fix it (earlier versions also
                # printed it for outer-ring ribs, which no key of the bearing changes); a
                # bearing with a crown radius and a rib height the contact refuses was told
                # to add them
                hint = ("" if why.startswith(("ribs on the outer ring", "not a cylindrical"))
                        else "; the end face must reach the rib: change the bearing's "
                             "rib_height, rib_angle or end_face_crown_radius" if geometry_why
                        else "; name it in [models] heat_sources once the bearing has "
                             "end_face_crown_radius and rib_height")
                dropped.append(f"{spec.name}: default heat source rib_friction left out "
                               f"({why}){hint}")
            record = _Bearing(spec.name, key, b, is_ball, sources, kin_name, opts,
                              radial_share=spec.radial_share, axial_share=spec.axial_share)
            axial_direction(f"bearings[{i_spec}].load_share.axial", b, spec.axial_share,
                            scene.schedule.steps)
            own_steps = record.steps(scene.schedule.steps)
            if _needs(scene)["kinematics"]:  # a film-only scene runs no kinematics
                radial_load_contact(spec.name, b, own_steps, kin_name)
            no_path = axial_load_path(spec.name, b, own_steps, kin_name, sources)
            if no_path:
                dropped.append(no_path)
            self.bearings.append(record)
            if spec.load_share:
                self.notes.append(
                    f"{spec.name} carries {spec.radial_share:g} of the schedule's radial load "
                    f"and {spec.axial_share:g} of its axial load ([[bearings]] load_share)")
        if _needs(scene)["losses"]:
            for b in self.bearings:
                note = _unbooked_rolling_note(scene, b)
                if note and note not in self.notes:
                    self.notes.append(note)
        from .heat_sources import HEAT_SOURCES

        HEAT_SOURCE_FAMILY = HEAT_SOURCES.family
        running = {n for b in self.bearings for n in b.sources}
        self.chain = [link for link in plan_chain(scene, self.lubricant,
                                                      [b.is_ball for b in self.bearings])
                      if link.family != HEAT_SOURCE_FAMILY or link.name in running]
        self.needs = _needs(scene)
        self.network = None
        # a source left out matters only to a run that books losses (a film-only or
        # kinematics-only scene runs no heat source: nothing to say)
        self.warnings: list[str] = list(self.notes) + (
            dropped if _needs(scene)["losses"] else [])
        #: default sources left out and thrust without a loss path (``check`` prints them
        #: under the chain: they were only in the run's warnings)
        self.left_out: list[str] = list(dropped) if _needs(scene)["losses"] else []
        self._warning_groups = WarningGroups(self.warnings)
        #: while not None, the validity warnings raised go here, not into the run's list
        #: (:meth:`held_warnings`: the iterates of a steady run's fixed point)
        self._held: list[tuple[str, str, int | None]] | None = None
        self.source_options = scene_heat_source_options(
            scene, tuple(dict.fromkeys(n for b in self.bearings for n in b.sources)))
        self._check_option_clashes()
        self._check_unbalance_option()
        if self.needs["losses"]:
            for note in _unbooked_drag_notes(self.bearings, self.supply):
                if note not in self.warnings:
                    self.warnings.append(note)
                    self.notes.append(note)
        drag_params = _roller_drag_params(self.source_options)
        thermal = self.source_options.get("ehl_rolling_resistance", {}).get("thermal_reduction")
        for b in self.bearings:
            if drag_params and not b.is_ball and b.kinematics_name == "skidding":
                # the roller solver balances the drag the churning sources book: the same
                # c_d and Parker constant (skidding.roller_drag)
                b.kin_options["params"] = dict(drag_params)
            if thermal is not None and not b.is_ball and b.kinematics_name == "skidding":
                # the rolling force the roller solver carries takes the inlet-heating
                # reduction the scene names for the rolling-resistance source (one force)
                b.kin_options["thermal_reduction"] = str(thermal)
        # identical bearings (same preset and overrides) at the same state share results
        # (bearing key, step) -> (viscosity, result, its validity warnings, bearing solved);
        # an identical bearing in the same state takes the result and the warnings
        self._kin_shared: dict[tuple[str, int],
                               tuple[float, KinematicsResult, tuple[str, ...], str, float]] = {}
        self._kin_replayed: set[tuple[int, str]] = set()
        self._heat_memo: dict[tuple[str, str], list[tuple[Any, ...]]] = {}
        # warnings of each batch of heat evaluations: batch -> (bearing evaluated, messages);
        # (batch, bearing) pairs already replayed for an identical bearing
        self._heat_batches: dict[int, tuple[str, tuple[str, ...]]] = {}
        self._heat_replayed: set[tuple[int, str]] = set()
        self._heat_batch_count = 0
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
        lines.extend(f"  note: {n}" for n in self.left_out if n not in self.notes)
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
    def _operating(self, step: Step, b: _Bearing | None = None) -> OperatingPoint:
        """The operating point of a step, with bearing ``b``'s share of the loads."""
        radial, axial = ((step.radial_load, step.axial_load) if b is None
                         else b.operating_loads(step))
        return OperatingPoint(inner_speed=step.speed, radial_load=radial, axial_load=axial)

    def solve_kinematics(self, b: _Bearing, step_index: int, step: Step,
                    temps: Mapping[str, float]) -> KinematicsResult:
        """Solve (or reuse) the kinematics of one bearing at the current temperatures.

        They are solved at the contacts' inlet oil temperature
        (:func:`kinematic_models.contact_temperature`: (T_inner_ring + T_outer_ring +
        2 T_elements) / 4 [K], the heat sources' convention), and re-solved when the
        viscosity at that same temperature has moved by more than
        ``solver.kinematics_tolerance`` (relative) since the last solve. The skidding
        solvers also balance the oil drag at the oil node's temperature (the roller solver's
        churning and guide moments are what the sources then book): for them the oil's
        viscosity moving by more than the tolerance re-solves as well."""
        t_contact = contact_temperature(temps)
        visc = float(self.lubricant.dynamic_viscosity(t_contact))
        visc_oil = (float(self.lubricant.dynamic_viscosity(temps["oil"]))
                    if b.kinematics_name == "skidding" else math.nan)
        tol = self.scene.solver.kinematics_tolerance

        def near(v: float, ref: float) -> bool:
            return math.isnan(v) or abs(v / ref - 1.0) <= tol

        if (b.last is not None and b.last_step == step_index
                and near(visc, b.last_viscosity) and near(visc_oil, b.last_oil_viscosity)):
            return b.last
        shared = self._kin_shared.get((b.key, step_index))
        if shared is not None and near(visc, shared[0]) and near(visc_oil, shared[4]):
            b.last, b.last_viscosity, b.last_step = shared[1], shared[0], step_index
            b.last_oil_viscosity = shared[4]
            b.last_warnings = shared[2]
            if shared[3] != b.name and (id(shared[1]), b.name) not in self._kin_replayed:
                self._kin_replayed.add((id(shared[1]), b.name))
                for message in shared[2]:  # the twin's film ranges hold for this one too
                    self._warn(message, b.name, step_index)
            self.checks[b.name].record(step_index, check_state(b.bearing, shared[1],
                                                               self.check_limits))
            return shared[1]
        op = self._operating(step, b)
        fn = KINEMATICS.get(b.kinematics_name)
        guess = b.last if b.last is not None else None
        nearby: list[str] = []  # the note of a solve at a shifted temperature
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", ValidityWarning)
            try:
                try:
                    res = fn(b.bearing, self.lubricant, op, contact_temperature=t_contact,
                             oil_temperature=temps["oil"], supply=self.supply, guess=guess,
                             options=b.kin_options)
                except ConvergenceError as first:
                    try:
                        if guess is None:
                            raise
                        res = fn(b.bearing, self.lubricant, op, contact_temperature=t_contact,
                                 oil_temperature=temps["oil"], supply=self.supply, guess=None,
                                 options=b.kin_options)
                    except ConvergenceError:
                        res, visc = self._solve_nearby(b, fn, op, t_contact, temps, guess,
                                                       first, nearby)
            except ConvergenceError as exc:
                # the solver's own error names neither the bearing nor the step
                raise ConvergenceError(
                    f"kinematics ({b.kinematics_name}) of {b.name}", exc.residual,
                    f"at step {step_index} ({step.speed * 30.0 / np.pi:.6g} r/min, radial "
                    f"{op.radial_load:.6g} N, axial {op.axial_load:.6g} N, contacts at "
                    f"{t_contact - 273.15:.1f} degC): {exc}", {"step": step_index}) from exc
        for note in nearby:
            self._warn(note, b.name, step_index)
        self._note(caught, b.name, step_index)
        if not res.converged:
            raise ConvergenceError(f"kinematics ({b.kinematics_name}) of {b.name}",
                                   res.residual_norm, "at step", {"step": step_index})
        b.last, b.last_viscosity, b.last_step = res, visc, step_index
        b.last_oil_viscosity = visc_oil
        b.last_warnings = tuple(str(w.message) for w in caught
                                if issubclass(w.category, ValidityWarning))
        self._kin_shared[(b.key, step_index)] = (
            visc, res, b.last_warnings, b.name, visc_oil)
        b.last_warnings += tuple(nearby)  # this bearing's solve, not a twin's
        b.solves += 1
        self.checks[b.name].record(step_index, check_state(b.bearing, res, self.check_limits))
        return res

    def _solve_nearby(self, b: _Bearing, fn: Any, op: OperatingPoint, t_contact: float,
                      temps: Mapping[str, float], guess: KinematicsResult | None,
                      exc: ConvergenceError, notes: list[str]
                      ) -> tuple[KinematicsResult, float]:
        """The kinematics at contact and oil temperatures a little off the current ones,
        where the solver stalled (-> (result, contact viscosity there)).

        The coupled run already accepts kinematics solved at a viscosity up to
        ``solver.kinematics_tolerance`` (relative) away from the current one; a shift of
        an eighth of that (a few tenths of a kelvin at most) stays well inside it. Measured
        case: the QJ1044 rig at 40 L/min and 40 degC inlet, 4 kN, stalled at residual
        6.7e-4 in a window narrower than 0.02 K of oil temperature (the drag's viscosity)
        and converged 0.01 K on either side of it. Both temperatures are moved by the same
        delta, tried at +delta, then -delta, warm-started from the last state and then
        cold; the error of the exact temperature is raised if both fail. The shift, with
        the stalled residual, is appended to ``notes`` (the caller puts it into the run's
        warnings).
        """
        tol = self.scene.solver.kinematics_tolerance
        lub = self.lubricant
        beta = float(np.log(lub.dynamic_viscosity(t_contact - 0.5))
                     - np.log(lub.dynamic_viscosity(t_contact + 0.5)))
        if not (beta > 0.0 and tol > 0.0):
            raise exc
        delta = min(0.125 * tol / beta, 1.0)
        for shift in (delta, -delta):
            t_try = t_contact + shift
            for start in ((guess, None) if guess is not None else (None,)):
                try:
                    res = fn(b.bearing, lub, op, contact_temperature=t_try,
                             oil_temperature=temps["oil"] + shift, supply=self.supply,
                             guess=start, options=b.kin_options)
                except ConvergenceError:
                    continue
                if res.converged:
                    visc = float(lub.dynamic_viscosity(t_try))
                    notes.append(
                        f"kinematics solved at contact and oil temperatures {shift:+.3g} K off "
                        f"(contacts {t_contact - 273.15:.2f} degC; viscosity "
                        f"{visc / float(lub.dynamic_viscosity(t_contact)) - 1.0:+.2%}, inside "
                        f"solver.kinematics_tolerance = {tol:g}): the solver stalled at "
                        f"residual {exc.residual:.3g} at the exact temperature")
                    return res, visc
        raise exc

    def _note(self, caught: Sequence[warnings.WarningMessage], bearing: str,
              step: int | None = None) -> None:
        """The caught warnings into the run's warnings, repeats merged into one line per
        bearing and message shape (:class:`~thermobearing.warning_groups.WarningGroups`)."""
        for w in caught:
            self._warn(str(w.message), bearing, step)

    def _warn(self, message: str, bearing: str, step: int | None = None) -> None:
        """One validity warning of ``bearing`` (at schedule ``step`` if known) into the
        run's warnings, or into the held list while :meth:`held_warnings` is open."""
        if self._held is not None:
            self._held.append((message, bearing, step))
        else:
            self._warning_groups.add(message, bearing, step)

    @contextmanager
    def held_warnings(self) -> Iterator[list[tuple[str, str, int | None]]]:
        """Inside, the validity warnings of the kinematics and heat evaluations go to the
        yielded list of (message, bearing, step), not into the run's warnings: a steady
        run's fixed-point iterates are no states the bearing runs in (a QJ1044 pair from
        -10 degC: the film formula's G range warned at the cold iterates only). The
        converged state's warnings are then recorded by :meth:`record_state_warnings`. An
        error inside records the held warnings as they came (a run stopped there)."""
        outer, held = self._held, []
        self._held = held
        try:
            yield held
        except BaseException:
            # a run stopped inside: the iterates' warnings are all it has of that step
            self._held = outer
            for message, bearing, step in held:
                self._warn(message, bearing, step)
            raise
        finally:
            self._held = outer

    def record_state_warnings(self, b: _Bearing, step_index: int, step: Step,
                              temps: Mapping[str, float]) -> None:
        """The validity warnings of bearing ``b``'s state at schedule step ``step_index``
        into the run's warnings: those of the kinematic solve that gave its state
        (``b.last``) and those of its heat sources evaluated afresh at the role
        temperatures ``temps`` [K] (the memo bypassed: a memoised evaluation warns no
        more). A steady run calls it once per step at its steady state."""
        for message in b.last_warnings:
            self._warn(message, b.name, step_index)
        if b.last is not None and b.sources:
            self.evaluate_heat(b, step, b.last, temps, fresh=True, step_index=step_index)

    def evaluate_heat(self, b: _Bearing, step: Step, kin: KinematicsResult,
                      temps: Mapping[str, float], with_rows: bool = False,
                      fresh: bool = False, step_index: int | None = None) -> _Evaluation:
        """Heat of the bearing's sources at the given role temperatures.

        Memoised per source: a source's result is reused while the kinematic state is the
        same and every temperature role it read (``heat_sources.RoleTemperatures``) is
        unchanged -- e.g. the raceway shear of a skidding state, computed at the solver's
        contact temperature, is evaluated once per kinematics solve, not once per
        finite-difference column. Two identical bearings in the same state share results.
        ``reads`` of the evaluation is the union of the roles the sources read.
        ``with_rows``: also the loss-table rows, one per source, component and role (the
        component where the heat goes, :meth:`heat_sources.HeatResult.split`) with its
        power [W]; a component's rows add up to its power. ``fresh``: every source is
        evaluated, none taken from the memo (its validity warnings are raised again), and
        its warnings are the schedule step ``step_index``'s.
        """
        from .heat_sources import HeatContext, evaluate_recorded

        temps = {r: float(v) for r, v in temps.items()}
        memo = self._heat_memo
        if len(memo) > 512:
            memo.clear()
            self._heat_batches.clear()
            self._heat_replayed.clear()
        found: dict[str, tuple[Any, frozenset[str]]] = {}
        for name in () if fresh else b.sources:
            for entry_kin, entry_step, reads, values, result, batch in memo.get((b.key, name),
                                                                                 ()):
                if (entry_kin is kin and (entry_step is step or entry_step == step)
                        and all(temps.get(r) == values[r] for r in reads)):
                    found[name] = (result, reads)
                    self._replay_heat_warnings(batch, b.name)
                    break
        missing = [name for name in b.sources if name not in found]
        if missing:
            ctx = HeatContext(bearing=b.bearing, lubricant=self.lubricant, supply=self.supply,
                              operating=self._operating(step, b), temperatures=temps,
                              kinematics=kin.state, traction=kin.traction,
                              options=self._heat_options(kin))
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", ValidityWarning)
                computed = evaluate_recorded(missing, ctx)
            self._note(caught, b.name, step_index)
            batch = self._heat_batch_count = self._heat_batch_count + 1
            self._heat_batches[batch] = (b.name, tuple(
                str(w.message) for w in caught if issubclass(w.category, ValidityWarning)))
            for name, (result, reads) in zip(missing, computed, strict=True):
                found[name] = (result, reads)
                entries = memo.setdefault((b.key, name), [])
                entries.insert(0, (kin, step, reads, {r: temps.get(r) for r in reads}, result,
                                   batch))
                del entries[8:]
        by_role = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 0.0)
        rows = []
        tables: dict[str, list[dict[str, Any]]] = {}
        reads_all: set[str] = set()
        for name in b.sources:
            r, reads = found[name]
            reads_all |= reads
            for role, p in r.power_by_role.items():
                by_role[role] += p
            if with_rows:
                # one row per component and the role its heat goes to (HeatResult.split:
                # the source's own split, else in proportion to its heat by role)
                rows.extend({"source": r.source, "component": comp, "role": role,
                             "power [W]": p,
                             "load dependence": r.loss_class.get(comp, "")}
                            for comp, role, p in r.split())
                if r.source in DETAIL_TABLES:
                    # the source's own numbers of this very result (the rib table)
                    table, columns = DETAIL_TABLES[r.source]
                    tables.setdefault(table, []).append(columns(b.bearing, r.details))
        return _Evaluation(by_role, rows, reads=frozenset(reads_all), tables=tables)

    def _replay_heat_warnings(self, batch: int, bearing: str) -> None:
        """The validity warnings of a memoised heat evaluation of an identical bearing, once
        under ``bearing``'s name (its own repeats were recorded when they were computed)."""
        owner, messages = self._heat_batches[batch]
        if owner == bearing or not messages or (batch, bearing) in self._heat_replayed:
            return
        self._heat_replayed.add((batch, bearing))
        for message in messages:
            self._warn(message, bearing)

    def _check_option_clashes(self) -> None:
        """Refuse, before anything is solved, a ``[models] heat_source_options`` parameter
        that a ball bearing's kinematics sets to match its own force models (the same rule
        as :meth:`_heat_options`, which met it only at the first heat evaluation, after
        ``thermobearing check`` had passed). Which parameters the ball kinematics set does
        not depend on the speed (``skidding.ball_models.heat_context_options``). A roller
        bearing's skidding solver balances the oil drag the churning and cage-guide sources
        book (``skidding.roller_drag``): their options other than where the heat goes are
        refused unless the solver takes them too (:func:`_roller_drag_clash`)."""
        from .kinematic_models import _ball_heat_options

        if not self.source_options:
            return
        mu_c = self.source_options.get("cage_guide", {}).get("friction_coefficient")
        if mu_c is not None:  # it stopped the run at the first heat evaluation
            raise InputError(
                "models.heat_source_options.cage_guide.friction_coefficient", mu_c,
                "no value in a scene: the cage_guide source's drag is the Petroff torque of "
                "the land film (form 'short_bearing'); the coefficient mu_c belongs to paper "
                "002's eq. 18 bookkeeping only (thermobearing.losses.paper002_bookkeeping)")
        for b in self.bearings:
            if not b.is_ball and b.kinematics_name == "skidding":
                _roller_drag_clash(b.name, self.source_options)
                continue
            if not b.is_ball or b.kinematics_name not in ("race_control", "skidding"):
                continue
            speed = next((s.speed for s in self.scene.schedule.steps if s.speed > 0), 0.0)
            if speed == 0.0:  # every step at rest: no heat evaluation takes the options
                continue
            owned = _ball_heat_options(b.bearing, self.supply, speed,
                                       b.kin_options.get("params"))
            for src, params in self.source_options.items():
                mine = set(owned.get(src, {}))
                if "oil_fraction" in mine:  # a Parker constant would go unused
                    mine.add("parker_constant")
                clash = sorted(set(params) & mine)
                if clash:
                    raise InputError(
                        f"models.heat_source_options.{src}.{clash[0]}", params[clash[0]],
                        f"a parameter the {b.kinematics_name} kinematics of bearing "
                        f"'{b.name}' does not set: it sets "
                        f"{', '.join(sorted(owned[src]))} to match its own force models "
                        "(change those through the bearing's calibration instead)")

    def _check_unbalance_option(self) -> None:
        """``heat_source_options.rib_friction.unbalance_mass`` below the roller mass of every
        bearing that runs the rib source, refused before anything is solved: ``check``
        passed "5 g" on CRB_50x75x16 (1.33 g rollers) and the run stopped at its first
        solve with ``unbalance_mass = 0.005 is not allowed`` (no scene field, kg beside g)."""
        from .heat_sources.rib import check_unbalance_option

        mass = self.source_options.get("rib_friction", {}).get("unbalance_mass")
        if mass is None:
            return
        for b in self.bearings:
            if "rib_friction" in b.sources:
                check_unbalance_option(
                    float(mass), b.bearing,
                    "models.heat_source_options.rib_friction.unbalance_mass")

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

        self.steps_done = 0
        # what loading cannot know wrong fails here, before any model is solved (the CLI
        # runs the same checks earlier): the network template's required parameters and
        # the measured CSV (columns, numbers, increasing times)
        check_network(self.scene.network, require=bool(self.needs.get("network")))
        check_measured_file(self.scene)
        writer = ResultsWriter(out_dir) if out_dir is not None else None
        if out_dir is not None:
            _clear_earlier_outputs(Path(out_dir))
        t_wall = time.perf_counter()
        self._t_wall = t_wall
        # absolute file paths: the results folder's scene.toml still finds its files
        scene_toml = with_absolute_paths(self.scene).to_toml()
        if writer is not None:
            (Path(out_dir) / "scene.toml").write_text(scene_toml, encoding="utf-8")
        if self.needs["network"] and "film" in self.scene.outputs.want:
            note = ("outputs.want: no film table in a run with temperatures (the films "
                    "change with them); the kinematics table gives each solved state's "
                    "min film parameter")
            if note not in self.warnings:
                self.warnings.append(note)
        try:
            if self.needs["network"]:
                from .coupled import run_coupled

                tables, stats = run_coupled(self, writer)
            else:
                tables, stats = self._run_operating_points(writer)
        except (ThermobearingError, KeyboardInterrupt) as exc:
            if out_dir is not None:  # the folder's report still has the chain, the checks
                self._write_stopped(Path(out_dir), scene_toml, exc,  # and why it stopped
                                    time.perf_counter() - t_wall)
            raise
        stats["wall_time_s"] = time.perf_counter() - t_wall
        stats["kinematics_solves"] = sum(b.solves for b in self.bearings)
        for b in self.bearings:
            # the numerical film's table work (numerical_tehl): how often it answered from
            # the table and how much CPU its thermal solves cost (a run could sit minutes in
            # them without a sign)
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
                          estimated=self.estimated_inputs(), flagged=self.flagged_steps())
        if out_dir is not None:
            from .report import attach_figures, write_report

            try:
                attach_figures(results, self.scene)
                results.write(out_dir)
                write_report(results, self.scene, Path(out_dir) / "report.html")
            except KeyboardInterrupt:
                # Ctrl-C after the last step, while the figures or the report were drawn
                # (seconds): the folder had the step tables but no metadata.json, and
                # `thermobearing report DIR` read as a run without a chain or warnings
                # (every step was computed: not a 'stopped' run, whose report says so)
                results.stats["output_interrupted"] = (
                    "Ctrl-C while the figures and report were written; every step was "
                    "computed: `thermobearing report DIR` writes them")
                results.write(out_dir)
                raise
        return results

    def log_step(self, i: int, t: float | None = None) -> None:
        """Give :attr:`step_log` the line of finished step ``i``: ``step 3/6 done (t = 1800
        of 4200 s simulated), 12.3 s wall`` (``t``: the simulated time at its end [s], None
        for a run of operating points without time)."""
        self.steps_done = max(self.steps_done or 0, i + 1)
        if self.step_log is None:
            return
        n = len(self.scene.schedule.steps)
        when = ("" if t is None else
                f" (t = {t:.0f} of {self.scene.schedule.duration:.0f} s simulated)")
        wall = time.perf_counter() - getattr(self, "_t_wall", time.perf_counter())
        self.step_log(f"step {i + 1}/{n} done{when}, {wall:.1f} s wall")

    def _write_stopped(self, out: Path, scene_toml: str, exc: BaseException,
                       wall: float) -> None:
        """``metadata.json`` of a run stopped by an error or Ctrl-C: the tables written so
        far are on disk (``ResultsWriter``); this adds the model chain, the estimated
        inputs, the validity checks of the steps solved and, first among the warnings, why
        the run stopped, so that ``thermobearing report DIR`` says so instead of reading as
        a finished run with no warnings."""
        why = ("interrupted (Ctrl-C)" if isinstance(exc, KeyboardInterrupt)
               else f"stopped by an error: {exc}")
        note = (f"run {why}; the tables hold only the steps computed before it, the report "
                "covers those")
        checked = [line for log in self.checks.values() for line in log.summary()]
        limits = self.check_limits.as_dict() if any(
            log.steps for log in self.checks.values()) else {}
        Results(scene_toml=scene_toml, chain=[(link.family, link.name) for link in self.chain],
                citations=self.citations(), warnings=[note, *self.warnings, *checked],
                stats={"stopped": why, "wall_time_s": wall}, check_limits=limits,
                estimated=self.estimated_inputs(), flagged=self.flagged_steps()).write(out)

    def flagged_steps(self) -> dict[str, dict[str, list[int]]]:
        """The steps each operating check flags, per bearing with any flagged
        (:meth:`.CheckLog.flagged_step_indices`): the report marks those rows."""
        out = {}
        for name, log in self.checks.items():
            flags = log.flagged_step_indices()
            if any(flags.values()):
                out[str(name)] = flags
        return out

    def _run_operating_points(self, writer: ResultsWriter | None
                              ) -> tuple[dict[str, pd.DataFrame], dict[str, Any]]:
        """Kinematics and/or losses per schedule step at the temperature of a run without a
        network (:func:`thermobearing.unheated.unheated_temperature`)."""
        from tqdm.auto import tqdm

        from .unheated import unheated_temperature

        t0, _ = unheated_temperature(self.scene)
        temps = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), t0)
        kin_rows: list[dict[str, Any]] = []
        loss_rows: list[dict[str, Any]] = []
        film_rows: list[dict[str, Any]] = []
        detail_rows: dict[str, list[dict[str, Any]]] = {}
        steps = self.scene.schedule.steps
        want_film = "film" in self.scene.outputs.want
        for i, step in enumerate(tqdm(steps, disable=not self.progress, desc="steps")):
            for b in self.bearings:
                base = step_columns(i, None, b.name, step, b)
                if self.needs["kinematics"]:
                    kin = self.solve_kinematics(b, i, step, temps)
                    row = {**base, **kinematics_columns(kin, b.bearing)}
                    kin_rows.append(row)
                    if writer:
                        writer.append("kinematics", [row])
                    if want_film:
                        # the film table asked beside kinematics / losses: the closed-form
                        # films at the same (initial) temperatures; the checks are the
                        # kinematic state's
                        with warnings.catch_warnings(record=True) as caught:
                            warnings.simplefilter("always", ValidityWarning)
                            rows, _ = film_table(b, self.lubricant, step, temps)
                        self._note(caught, b.name, i)
                        film_rows.extend({**base, **r} for r in rows)
                    if self.needs["losses"]:
                        ev = self.evaluate_heat(b, step, kin, temps, with_rows=True)
                        rows = [{**base, **r} for r in ev.rows]
                        loss_rows.extend(rows)
                        if writer:
                            writer.append("losses", rows)
                        for name, extra in ev.tables.items():
                            extra = [{**base, **r} for r in extra]
                            detail_rows.setdefault(name, []).extend(extra)
                            if writer:
                                writer.append(name, extra)
                else:
                    rows, csr = film_table(b, self.lubricant, step, temps)
                    film_rows.extend({**base, **r} for r in rows)
                    # the stress and Lambda checks apply to the film rows too
                    self.checks[b.name].record(i, check_film_rows(b.bearing, rows, csr,
                                                                  self.check_limits))
            self.log_step(i)
        tables = {}
        if kin_rows:
            tables["kinematics"] = pd.DataFrame(kin_rows)
        if loss_rows:
            tables["losses"] = pd.DataFrame(loss_rows)
        if film_rows:
            tables["film"] = pd.DataFrame(film_rows)
        tables.update({name: pd.DataFrame(r) for name, r in detail_rows.items()})
        return tables, {"steps": len(steps)}

    def summary_text(self, results: Results) -> str:
        """A few lines for the terminal: only what the run computed (a chain with
        ``kinematics = "none"`` solves no kinematics: its table holds the theoretical cage
        speed ratio and no over-skidding, which are not printed as results, nor its count
        of pure-rolling states as kinematics solves; a film-only chain has no kinematics)."""
        lines = []
        solved = any(tuple(x)[0] == "kinematics" and tuple(x)[1] != "none"
                     for x in results.chain)
        kin = results.tables.get("kinematics")
        if kin is not None and not kin.empty and solved:
            lines.extend(_first_csr_lines(kin, self.checks,
                                          ("kinematics", "race_control") in
                                          [tuple(x)[:2] for x in results.chain],
                                          steady="steady_temperatures" in results.tables))
        losses = results.tables.get("losses")
        if losses is not None and not losses.empty:
            lines.append(_loss_range_line(losses))
        rib = results.tables.get("rib")
        if rib is not None and not rib.empty:
            from .simulation_summary import rib_summary_lines

            lines.extend(rib_summary_lines(rib))
        temps = results.tables.get("temperatures")
        steady = results.tables.get("steady_temperatures")
        if temps is not None and not temps.empty:
            cols = [c for c in temps.columns if c.endswith("[degC]")]
            lines.append("final temperatures: " + ", ".join(
                f"{c.replace(' [degC]', '')} {temps[c].iloc[-1]:.1f} degC" for c in cols))
        elif steady is not None and not steady.empty:
            # a steady run printed no temperature at all; its hottest step and its last
            cols = [c for c in steady.columns if c.endswith("[degC]")]
            hot = int(steady[cols].max(axis=1).to_numpy(dtype=float).argmax())
            for what, k in (("hottest steady state", hot), ("last steady state", -1)):
                row = steady.iloc[k]
                lines.append(f"{what} (step {int(row['step'])}): " + ", ".join(
                    f"{c.replace(' [degC]', '')} {row[c]:.1f} degC" for c in cols))
                if hot == len(steady) - 1:
                    break
        energy = results.tables.get("energy")
        if energy is not None and not energy.empty:
            last = energy.iloc[-1]
            gen = last["generated [J]"]
            lines.append(f"energy audit: generated {gen / 1e6:.3f} MJ, imbalance "
                         f"{abs(last['imbalance [J]']) / max(abs(gen), 1e-300):.2e} (relative)")
        lines.append(f"wall time {results.stats.get('wall_time_s', float('nan')):.2f} s"
                     + (f", {results.stats.get('kinematics_solves', 0)} kinematics solves"
                        if solved else ""))
        for key, value in results.stats.items():
            if key.endswith(": film table") and isinstance(value, dict):
                lines.append(f"{key} (numerical film): {value['solves']} thermal EHL solves "
                             f"({value['solve_cpu_s']:.1f} s CPU), {value['queries']} queries")
        if results.warnings:
            # identical bearings' identical lines once (the default rig listed each twice)
            merged = merge_twin_bearings(list(results.warnings),
                                         [b.name for b in self.bearings])
            shown = merged[:MAX_SHOWN_WARNINGS]
            lines.append(f"validity warnings ({len(merged)}; all in the report):")
            lines.extend(f"  - {w}" for w in shown)
            if len(merged) > len(shown):
                lines.append(f"  ... {len(merged) - len(shown)} more")
        return "\n".join(lines)


def _loss_range_line(losses: pd.DataFrame) -> str:
    """``total loss per bearing: lo - hi W`` over the steps that turn; steps at rest (both
    rings stopped: every source books 0 W) are named after it, not taken as the lowest
    loss (a rig protocol ending with a stop read "0 - 400 W")."""
    keys = ["step", "bearing"]
    per_step = losses.groupby(keys, sort=False)["power [W]"].sum()
    rest: list[int] = []
    if "speed [rpm]" in losses:
        speed = losses.groupby(keys, sort=False)["speed [rpm]"].first()
        at_rest = speed.to_numpy(float) == 0.0
        if at_rest.any() and not at_rest.all():
            rest = sorted({int(k[0]) for k in per_step.index[at_rest]})
            per_step = per_step[~at_rest]
    lo, hi = _watts(per_step.min()), _watts(per_step.max())
    # a small bearing's watts keep their digits (the 6206 map read "1 - 23 W" for
    # 0.962 - 22.9 W); one operating point gives one number
    line = f"total loss per bearing: {lo} W" if lo == hi else \
        f"total loss per bearing: {lo} - {hi} W"
    if rest:
        line += (f" (turning steps; 0 W at rest: step{'s' if len(rest) > 1 else ''} "
                 + ", ".join(str(i) for i in rest) + ")")
    return line


def _watts(p: float) -> str:
    """A loss for the run summary: three significant digits below 100 W, whole watts
    above (``0.962``, ``22.9``, ``1318``)."""
    return f"{p:.3g}" if abs(p) < 100.0 else f"{p:.0f}"


def _first_csr_lines(kin: pd.DataFrame, checks: Mapping[str, Any] | None = None,
                     race_control: bool = False, steady: bool = False) -> list[str]:
    """The cage speed ratio at each bearing's first turning step and the over-skidding
    range: a step at rest has no ratio (NaN), so it is skipped, not printed as ``nan``.
    The range is over every solved state (``checks``, the run's operating-check logs:
    :func:`.simulation_tables.over_skidding_range`), so that it agrees with the skid
    warnings; it gave the kinematics table's range, each step's first state (NU 214 at
    8000 r/min: min -37.8 % beside a warning of -44.7 % at the same step). Race control
    rolls by construction, which the line says. A steady run's rows are its steady states
    (``steady``), each step's one state."""
    csr, theo = "cage speed ratio [-]", "theoretical cage speed ratio [-]"
    parts, later = [], False
    for name, rows in kin.groupby("bearing", sort=False):
        turning = rows[np.isfinite(rows[csr].to_numpy(dtype=float))]
        if turning.empty:
            continue
        first = turning.iloc[0]
        label = f"{name} " if kin["bearing"].nunique() > 1 else ""
        later = later or first["step"] != 0
        parts.append(f"{label}{first[csr]:.4f} (theoretical {first[theo]:.4f}"
                     + (f", step {int(first['step'])})" if first["step"] != 0 else ")"))
    if not parts:
        return ["cage speed ratio: every step at rest (undefined)"]
    span = over_skidding_range(kin, checks or {})
    if span is None:
        skid = "over-skidding: none computed"
    elif checks is None:  # the table alone
        skid = f"over-skidding: max {span[0]:+.2f} %, min {span[1]:+.2f} %"
    elif race_control:
        skid = (f"over-skidding: max {span[0]:+.2f} %, min {span[1]:+.2f} % (race control: "
                "the cage rolls by construction)")
    elif steady:
        skid = (f"over-skidding at the steady states: max {span[0]:+.2f} %, min "
                f"{span[1]:+.2f} %")
    else:
        skid = (f"over-skidding over every solved state: max {span[0]:+.2f} %, min "
                f"{span[1]:+.2f} % (kinematics.csv: each step's first state)")
    return [("CSR at first step: " if len(parts) == 1 and not later
             else "CSR at first turning step: ")
            + ", ".join(parts), skid]


def _clear_earlier_outputs(out: Path) -> None:
    """Remove the report and the figures an earlier run left in the results folder ``out``
    (its tables the results writer removes): rerun into the same folder, a steady scene
    after a transient one left the transient's ``temperatures.png`` and loss maps beside
    its own, and a run stopped by an error left the earlier run's ``report.html``, which
    read as this one. Only the files a run writes under these names go; others stay."""
    from .report import FIGURE_CAPTIONS

    names = {f"{n}.png" for n in FIGURE_CAPTIONS} | {"report.html", "loss_maps.png"}
    for path in out.glob("*"):
        if path.is_file() and (path.name in names or (path.name.startswith("loss_maps_")
                                                      and path.suffix == ".png")):
            path.unlink()


def check_known(name: str, known: Sequence[str], field_name: str) -> None:
    """UnknownNameError naming ``field_name`` when ``name`` is not one of ``known``."""
    if name not in known:
        raise UnknownNameError(field_name, name, known)


#: options of the churning / cage-guide sources that only say where their heat goes
_ROLLER_BOOKING = {"churning_elements": ("role",), "churning_cage": ("role",),
                   "churning_inner_ring": ("role",), "cage_guide": ("cage_share",)}


def _roller_drag_params(source_options: Mapping[str, Mapping[str, Any]]) -> dict[str, float]:
    """The drag parameters of ``[models] heat_source_options`` that the roller skidding
    solver takes (``skidding.solve(..., params=...)``, :mod:`thermobearing.skidding.
    roller_drag`): ``churning_elements.drag_coefficient`` and the Parker constant of the
    churning sources (one value: :func:`_roller_drag_clash` refuses different ones)."""
    from .heat_sources.churning import SOLVER_DRAG_OPTIONS

    out: dict[str, float] = {}
    for src, keys in SOLVER_DRAG_OPTIONS.items():
        for key in keys:
            if key in source_options.get(src, {}):
                out[key] = float(source_options[src][key])
    return out


def _roller_drag_clash(name: str, source_options: Mapping[str, Mapping[str, Any]]) -> None:
    """Refuse a churning / cage-guide option the roller skidding solver of bearing ``name``
    cannot balance (the source would book another drag than the shaft torque holds), and
    Parker constants that differ between the churning sources (the solver has one)."""
    from .heat_sources.churning import SOLVER_DRAG_OPTIONS

    parker = {src: float(opts["parker_constant"]) for src, opts in source_options.items()
              if src in SOLVER_DRAG_OPTIONS and "parker_constant" in opts}
    if len(set(parker.values())) > 1:
        src = sorted(parker)[1]
        raise InputError(
            f"models.heat_source_options.{src}.parker_constant", parker[src],
            f"one Parker constant for every churning source of bearing '{name}' (the roller "
            f"skidding solver balances their drag with one oil fraction): "
            + ", ".join(f"{k} = {v:g}" for k, v in sorted(parker.items())))
    for src, booking in _ROLLER_BOOKING.items():
        given = source_options.get(src, {})
        taken = (*booking, *SOLVER_DRAG_OPTIONS.get(src, ()))
        other = sorted(k for k in given if k not in taken)
        if other:
            raise InputError(
                f"models.heat_source_options.{src}.{other[0]}", given[other[0]],
                f"an option the roller skidding solver of bearing '{name}' balances as well "
                f"({', '.join(taken)}): it balances the oil drag this source books, so a "
                "source's own drag model would book heat the shaft torque does not hold; "
                "use kinematics = \"race_control\" to evaluate the source's own model")


#: the heat sources that book the oil drag the skidding solvers balance (ball: paper 002
#: eqs. 9-10 and the cage torque; roller: ``skidding.roller_drag``)
_DRAG_SOURCES = ("churning_elements", "churning_cage", "churning_inner_ring", "cage_guide")


def _unbooked_rolling_note(scene: Scene, bearing: Any) -> str | None:
    """A roller bearing under race control whose ``[models] heat_sources`` list leaves out
    ``ehl_rolling_resistance``: race control rolls without slide, so ``raceway_traction``
    books 0 W and nothing books the raceway contacts' rolling resistance, the load's main
    loss (an NJ 214 at 8 kN, 2000-4000 r/min: ``raceway_traction`` 0.0 W on every step,
    said nowhere). The roller defaults have the source; the example scene
    ``crb_rib_example.toml``, copied as a start, lists its sources without it."""
    if (bearing.is_ball or bearing.kinematics_name != "race_control"
            or "heat_sources" not in scene.models
            or "ehl_rolling_resistance" in bearing.sources):
        return None
    return (f"{bearing.name}: the raceway contacts book no rolling resistance: "
            "[models] heat_sources leaves out ehl_rolling_resistance (in the roller "
            "bearings' default sources), and under race control the rollers roll without "
            "slide, so raceway_traction books 0 W")


def _data_range_notes(scene: Any, lubricant: Any) -> list[str]:
    """Notes naming a supplied inlet or a given initial temperature outside the
    temperatures the oil's property laws cover
    (:func:`thermobearing.lubricant_range.outside_data_note`; a sweep names them before its
    runs, a single run or check said nothing: ISO VG 46 at a 200 degC inlet ran silently)."""
    from .lubricant_range import data_temperature_range, outside_data_note
    from .unheated import fed_stream

    fields = []
    sup = scene.supply
    if sup.inlet_given and fed_stream(sup):
        fields.append(("supply.inlet_temperature", sup.inlet_temperature))
    if scene.environment.initial_given:
        fields.append(("environment.initial_temperature",
                       scene.environment.initial_temperature))
    if not fields:
        return []
    rng = data_temperature_range(lubricant)
    notes = (outside_data_note(lubricant, f, t, rng) for f, t in fields)
    return [n for n in notes if n is not None]


def _rib_geometry_text(bearing: Any) -> str | None:
    """The rib geometry's refusal of ``bearing`` in a bearing file's units
    (``rib_height = 3 mm is not allowed: ...``; :func:`heat_sources.rib.rib_input_text`),
    or None when its rib geometry is valid or missing (no crown radius / rib height)."""
    from .heat_sources.rib import rib_input_text
    from .rib import rib_geometry

    if getattr(bearing, "kind", None) != "cylindrical" or getattr(
            bearing, "ribbed_ring", "inner") == "outer":
        return None
    if bearing.end_face_crown_radius is None or bearing.rib_height is None:
        return None
    try:
        rib_geometry(bearing)
    except InputError as exc:
        return rib_input_text(exc)
    return None


def _refuse_rib_geometry(bearing: Any, spec: Any, index: int) -> None:
    """A scene that names ``rib_friction`` for a roller bearing whose rib geometry the rib
    contact refuses (a rib lower than the end face's contact point, a crown radius below
    half the roller length, ...): InputError naming the bearing's key in the scene
    (``bearings[0].overrides.rib_height`` when the scene overrides it, else the preset's or
    file's key), its value in mm / deg and what is allowed. It was refused under
    ``models.heat_sources = 'rib_friction'`` with ``rib.rib_height = 0.003`` (metres) in
    the middle of the message."""
    from .heat_sources.rib import RIB_BEARING_KEYS, RIB_FIELD_UNITS
    from .rib import rib_geometry

    if _rib_geometry_text(bearing) is None:
        return
    try:
        rib_geometry(bearing)
    except InputError as exc:
        # one field (rib.rib_height) or two (rib.rib_angle / rib.crown_radius), each named
        # by its bearing key
        names = [f[4:] if f.startswith("rib.") else f for f in exc.field.split(" / ")]
        keys = [RIB_BEARING_KEYS.get(n, n) for n in names]
        given = any(k in spec.overrides for k in keys)
        where = (f"bearings[{index}].overrides." if given
                 else f"bearings[{index}] ({spec.preset or spec.path}) ") + " / ".join(keys)
        name = names[0]
        scale, unit = RIB_FIELD_UNITS.get(name, (1.0, ""))
        value = (f"{float(exc.value) * scale:.4g} {unit}".strip()
                 if isinstance(exc.value, (int, float)) else exc.value)
        raise InputError(where, value, f"{exc.allowed} (the rib geometry of bearing "
                         f"'{spec.name}', needed by the rib_friction source that "
                         "[models] heat_sources names)") from None


def _scene_bearing(scene: Scene, spec: Any, index: int) -> Any:
    """The bearing of ``scene.bearings[index]`` (``spec``) with its overrides; a bearing
    file that is not there or a preset name that is not known is named by its scene field
    (``bearings[0].path``, with the file looked at; ``bearings[0].preset``), not as
    ``bearing path`` / ``bearing preset`` without the place it was looked for."""
    where = f"bearings[{index}]"
    if not spec.preset:
        path = scene.resolve_path(spec.path)
        if not path.is_file():
            raise InputError(f"{where}.path", spec.path,
                             f"an existing bearing TOML file (looked at {path})")
        return _load_scene_bearing(str(path), spec.overrides, where)
    try:
        return _load_scene_bearing(spec.preset, spec.overrides, where)
    except UnknownNameError as exc:
        if exc.field != "bearing preset":
            raise
        raise UnknownNameError(f"{where}.preset", spec.preset, exc.known) from None


def _unbooked_drag_notes(bearings: Sequence[Any], supply: Any) -> list[str]:
    """A note per skidding bearing whose scene leaves out a source of the oil drag its
    solver balances anyway (the drag is physics of the kinematics, not a choice of what to
    book): the heat booked is then below the shaft power by that drag's work."""
    if supply.method == "grease":  # no churning drag is balanced
        return []
    notes = []
    for b in bearings:
        if b.kinematics_name != "skidding":
            continue
        cage = getattr(b.bearing, "cage", None)
        guided = str(getattr(cage, "guidance", "")) in ("inner_ring", "outer_ring")
        left = [n for n in _DRAG_SOURCES if n not in b.sources
                and (n != "cage_guide" or guided)]
        if left:
            notes.append(
                f"{b.name}: the skidding solver balances the oil drag of "
                f"{', '.join(left)}, which [models] heat_sources leaves out: the heat "
                "booked is below the shaft power by that drag's work")
    return notes
