"""One scene bearing inside a :class:`~thermobearing.simulation.Simulation`: its record (models,
heat sources, warm-start memory), the heat of one evaluation, and its set-up from the scene
(preset with overrides, the ball force-model calibration, notes on the oil supply).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from .errors import InputError
from .kinematic_models import KinematicsResult
from .scene import Scene
from .unheated import fed_stream


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
    #: the oil node's viscosity at the last skidding solve (its drag's) [Pa s]
    last_oil_viscosity: float = math.nan
    last_step: int = -1
    #: the validity warnings of the solve that gave ``last`` (a steady run reports its
    #: steady state's kinematic warnings only, :meth:`Simulation.record_state_warnings`)
    last_warnings: tuple[str, ...] = ()
    solves: int = 0
    #: fractions of the schedule's radial / axial loads this bearing carries
    #: (``[[bearings]] load_share``)
    radial_share: float = 1.0
    axial_share: float = 1.0

    def loads(self, step: Any) -> tuple[float, float]:
        """(radial, axial) load [N] of this bearing at a schedule step (the axial load
        negative under a negative ``load_share.axial``: the tables show the direction)."""
        return step.radial_load * self.radial_share, step.axial_load * self.axial_share

    def operating_loads(self, step: Any) -> tuple[float, float]:
        """(radial, axial) load magnitudes [N] the models take at a schedule step. A
        reversed thrust (negative axial share) loads a deep-groove or four-point bearing, and
        a roller bearing with ribs on both rings, as the same thrust the other way: their
        models are symmetric about the bearing's mid-plane, so only its magnitude enters
        (an angular-contact bearing, which carries thrust one way only, refuses it before
        the run: :func:`axial_direction`)."""
        radial, axial = self.loads(step)
        return radial, abs(axial)

    def steps(self, steps: Any) -> list[Any]:
        """The schedule's steps with this bearing's loads (for the pre-run checks)."""
        import dataclasses

        if self.radial_share == 1.0 and self.axial_share == 1.0:
            return list(steps)
        return [dataclasses.replace(s, radial_load=s.radial_load * self.radial_share,
                                    axial_load=s.axial_load * self.axial_share)
                for s in steps]


@dataclass
class _Evaluation:
    """Heat of one bearing at one state: per role, per source/component, and diagnostics."""

    by_role: dict[str, float]
    rows: list[dict[str, Any]] = field(default_factory=list)
    #: with the loss rows, the rows of the sources' detail tables (table -> rows,
    #: :data:`thermobearing.simulation_tables.DETAIL_TABLES`: ``rib``), from the same results
    tables: dict[str, list[dict[str, Any]]] = field(default_factory=dict)
    #: temperature roles the sources read (the heat depends on no other node temperature)
    reads: frozenset[str] = frozenset(("inner_ring", "outer_ring", "elements", "cage", "oil"))


def _load_scene_bearing(src: str, overrides: Mapping[str, Any] | None, where: str) -> Any:
    """``load_bearing`` with the scene's overrides; an override the bearing refuses is named
    by its scene field (``bearings[0].overrides.contact_angle``) with the value as written
    (``'90 deg'``), the converted SI value beside the rule."""
    from .geometry import load_bearing

    try:
        bearing = load_bearing(src, overrides=overrides or None)
    except InputError as exc:
        key = str(exc.field).rsplit(".", 1)[-1]
        if overrides and key in overrides and type(exc) is InputError:
            raise InputError(f"{where}.overrides.{key}", overrides[key],
                             f"{exc.allowed} (checked in SI: {exc.value!r})") from None
        raise
    return _without_overridden_estimates(bearing, overrides)


def _overridden_keys(overrides: Mapping[str, Any] | None, prefix: str = "") -> set[str]:
    """Dotted keys a scene's overrides set (``ribbed_ring``, ``cage.inner_diameter``)."""
    keys: set[str] = set()
    for key, value in (overrides or {}).items():
        keys.add(f"{prefix}{key}")
        if isinstance(value, Mapping):
            keys |= _overridden_keys(value, f"{prefix}{key}.")
    return keys


def _without_overridden_estimates(bearing: Any, overrides: Mapping[str, Any] | None) -> Any:
    """``bearing`` without the ``estimated`` marks of the values the scene overrides: they
    are the user's now. ``check`` listed an NU 214 overridden to ``ribbed_ring = "both"``
    with ``ribbed_ring`` among its estimates and the report gave the preset's reasoning
    ("NU type: two ribs on the outer ring, none on the inner ring") beside the NJ-type
    bearing that ran. A whole table overridden (``cage = {...}``) keeps the marks of the
    keys it leaves."""
    estimated = dict(getattr(bearing, "estimated", {}) or {})
    given = _overridden_keys(overrides)
    kept = {k: v for k, v in estimated.items() if k not in given}
    if len(kept) == len(estimated):
        return bearing
    return replace(bearing, estimated=kept)


def _supply_notes(scene: Scene) -> list[str]:
    """What the scene sets that its oil supply does not use (said, not refused), and what an
    oil-air supply (its carrier air) and a grease supply (the grease's churning) leave out.
    An oil bath's inlet temperature defaults to the ambient one: only another value was set
    by the user and is worth a note (not every oil-bath run, as a warning). A level set for
    another method (a jet switched from an oil bath) is not used either."""
    sup = scene.supply
    notes = []
    if (sup.method == "oil_bath" and sup.flow == 0.0
            and sup.inlet_temperature != scene.environment.ambient_temperature):
        notes.append(f"supply.inlet_temperature ({sup.inlet_temperature - 273.15:g} degC) is "
                     "not used: an oil bath without flow has no inlet; the bath temperature "
                     "is the network's oil node")
    if sup.method == "grease" and sup.inlet_given and (
            sup.inlet_temperature != scene.environment.ambient_temperature):
        notes.append(f"supply.inlet_temperature ({sup.inlet_temperature - 273.15:g} degC) is "
                     "not used: a grease fill has no inlet (no stream enters the bearing)")
    heat = bool(set(scene.outputs.want) & {"losses", "temperatures", "energy"})
    if sup.method == "oil_bath" and sup.flow > 0.0 and heat:
        notes.append(f"oil bath with supply.flow ({sup.flow * 6e4:g} L/min): the flow runs "
                     "through each bearing's bath (a circulated bath): the network's oil "
                     f"stream takes it in at {sup.inlet_temperature - 273.15:g} degC "
                     "(supply.inlet_temperature, default the ambient); the churning follows "
                     "supply.level, not the flow")
    if sup.method == "grease" and heat:
        notes.append("supply grease: the churning of grease is not modelled (oil fraction "
                     "0: the churning sources book 0 W); the lubricant is read as the "
                     "grease's base oil for the films and the traction")
    if sup.method == "oil_air" and heat:
        notes.append("supply oil_air: the churning sources take the oil fraction of Parker's "
                     "jet correlation at the oil flow alone; the carrier air's flow, its "
                     "cooling and its drag are not modelled (the network's oil stream carries "
                     "the oil's heat only)")
    thermal = bool(set(scene.outputs.want) & {"temperatures", "energy"})
    t_ini = scene.environment.initial_temperature
    if (not thermal and fed_stream(sup) and sup.inlet_given
            and sup.inlet_temperature != t_ini and scene.environment.initial_given):
        # no network: the operating points are taken with every part and the oil at one
        # temperature (thermobearing.unheated): the initial one when the scene gives it,
        # which then wins over the inlet; a swept inlet changes nothing, which the user is
        # told rather than left to find in identical rows
        notes.append(f"supply.inlet_temperature ({sup.inlet_temperature - 273.15:g} degC) is "
                     "not used: without 'temperatures' or 'energy' in [outputs] want no "
                     "thermal network runs, and the films, kinematics and losses are taken "
                     "with the rings, the elements and the oil at the scene's "
                     f"environment.initial_temperature ({t_ini - 273.15:g} degC); leave that "
                     "out to take them at the inlet temperature")
    if sup.method != "oil_bath" and sup.level is not None:
        notes.append(f"supply.level ({sup.level * 1e3:g} mm) is not used by the "
                     f"{sup.method} supply: only an oil bath (supply.method = \"oil_bath\") "
                     "has a level")
    return notes + _thermal_setting_notes(scene, thermal)


def _thermal_setting_notes(scene: Scene, thermal: bool) -> list[str]:
    """Settings of the thermal run that the scene's outputs leave unused, said in one note:
    without 'temperatures' or 'energy' no network runs, so ``[network]``, ``[solver]``
    settings, ``[measured]``, ``outputs.interval`` and ``models.churning_heat_to`` change
    nothing (a scene keeps them for other outputs: it loads and runs, but the user who set
    them is told); ``outputs.interval`` of a steady run neither (one row per step), nor
    ``[measured]`` (a steady run is compared with no reading)."""
    from .scene_sections import Solver

    if not thermal:
        unused = [name for name, given in (
            ("[network]", bool(scene.network)),
            ("[solver]", scene.solver != Solver()),
            ("[measured]", scene.measured is not None),
            ("outputs.interval", scene.outputs.interval is not None),
            ("models.churning_heat_to", "churning_heat_to" in scene.models)) if given]
        if not unused:
            return []
        return [f"{', '.join(unused)} {'is' if len(unused) == 1 else 'are'} not used: "
                f"the outputs ({', '.join(scene.outputs.want) or 'none'}) run no thermal "
                "network (add 'temperatures' to [outputs] want for it)"]
    notes = []
    if scene.outputs.mode == "steady" and scene.outputs.interval is not None:
        notes.append(f"outputs.interval ({scene.outputs.interval:g} s) is not used: a steady "
                     "run (outputs.mode = \"steady\") gives one row per step; the interval "
                     "adds rows between the chunk ends of a transient run")
    if scene.outputs.mode == "steady" and scene.measured is not None:
        # a rig engineer's steady scene with its thermocouple file ran, checked the file
        # and compared nothing, without a word (session-24 tour F)
        notes.append("[measured] is not used: a steady run (outputs.mode = \"steady\") has no "
                     "time axis to compare the file's readings with; run the protocol as a "
                     "transient (outputs.mode = \"transient\") for the measured-vs-predicted "
                     "comparison")
    if scene.outputs.mode == "steady" and "energy" in scene.outputs.want:
        notes.append("outputs.want 'energy' gives no table in a steady run: the energy table "
                     "books the heat generated, stored and carried away over the time of a "
                     "transient (outputs.mode = \"transient\"); a steady state stores none")
    return notes


def level_notes(scene: Scene, name: str, bearing: Any) -> list[str]:
    """An oil-bath level above the top of a bearing's outer raceway (measured from its
    lowest point, :func:`thermobearing.heat_sources.churning.oil_bath_fraction`): the
    bearing runs fully immersed, which a level written without a unit (read in metres,
    ``level = 5``) gives by mistake; said, not refused (a flooded housing is a real case)."""
    sup = scene.supply
    top = getattr(bearing, "outer_raceway_diameter", None)
    if sup.method != "oil_bath" or sup.level is None or top is None or sup.level <= top:
        return []
    return [f"supply.level ({sup.level * 1e3:g} mm) is above the top of the outer raceway "
            f"of bearing {name} ({top * 1e3:g} mm above its lowest point): it runs fully "
            "immersed (a level without a unit is read in metres: \"5 mm\", not 5)"]


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
    if scene.models.get("kinematics", "skidding") == "none":
        # a global friction model runs no ball force model: only the clearance is used
        used = ("" if "diametral_clearance" in (spec.overrides or {}) else
                f"calibrated diametral clearance from {path.name}; ")
        note = (f"{used}its ball force-model parameters are not used with kinematics = "
                "\"none\"") if used else ""
        return cal["params"], bearing, note
    note = (f"calibrated ball force-model parameters from {path.name} "
            f"(fitted at {cond.get('speed')}, {cond.get('flow')}; other conditions are "
            f"predictions)")
    return cal["params"], bearing, note


def axial_load_path(name: str, bearing: Any, steps: Any, kinematics: str,
                    sources: tuple[str, ...]) -> str | None:
    """Check the schedule's axial loads against a cylindrical roller bearing's ribs before
    anything is solved (``thermobearing check`` and ``Simulation``); None for other bearings
    or a schedule without axial load.

    An axial load on a cylindrical roller bearing has a path only through roller end faces
    on ribs of both rings (NJ / NUP / NF types, ``ribbed_ring = "both"``; paper 003 sec.
    3.2): on an NU-type bearing (``ribbed_ring = "outer"``, no inner-ring rib) it has none,
    and the roller skidding solver carries no rib thrust (``skidding.roller``), so both are
    errors naming the first loaded step and what to change. Under race control the thrust's
    heat is booked by the ``rib_friction`` source only: without it the run would book no
    loss for the axial load, so the returned note says so (a run warning); the whole-bearing
    ``global_friction`` source takes the axial load in its own formula.
    """
    if getattr(bearing, "kind", None) != "cylindrical":
        return None
    loaded = [i for i, s in enumerate(steps) if s.axial_load != 0.0]
    if not loaded:
        return None
    i = loaded[0]
    value = f"{steps[i].axial_load / 1000.0:g} kN"
    where = f"schedule step {i} axial_load (bearing {name!r}, {bearing.name})"
    ribs = getattr(bearing, "ribbed_ring", "both")
    if ribs == "outer":
        raise InputError(
            where, value,
            "0 kN: ribbed_ring = 'outer' is an NU-type bearing (no rib on the inner ring), "
            "which carries no axial load; an NJ / NUP-type bearing carries it through its "
            "ribs (override ribbed_ring = 'both' with end_face_crown_radius and rib_height, "
            "kinematics = 'race_control' and the rib_friction heat source)")
    if kinematics == "skidding":
        raise InputError(
            where, value,
            "0 kN with kinematics = 'skidding' (the roller skidding solver carries no rib "
            "thrust); set [models] kinematics = 'race_control', where the rib_friction heat "
            "source books the roller end-face / rib heat of the axial load")
    if "rib_friction" not in sources and "global_friction" not in sources:
        steps_text = ", ".join(str(j) for j in loaded)
        return (f"{name}: the axial load of steps {steps_text} books no loss (the rib_friction "
                "heat source, which carries it on the ribs, is not running)")
    return None


def axial_direction(where: str, bearing: Any, share: float, steps: Any) -> None:
    """Refuse a negative axial share (a reversed thrust) on an angular-contact bearing for a
    schedule with an axial load: its balls take thrust in the direction of the contact angle
    only, the other way the rings lift off the balls (a pair mounted back-to-back or
    face-to-face gives each direction to one bearing). ``where`` names the scene field
    (``bearings[1].load_share.axial``). The run stopped at the first solve with
    ``operating.axial_load = -2302.95 is not allowed``, naming no scene field."""
    if share >= 0.0 or getattr(bearing, "kind", None) != "angular_contact":
        return
    if not any(s.axial_load != 0.0 for s in steps):
        return
    raise InputError(
        where, share,
        f"a share >= 0 for the angular-contact bearing {bearing.name}: it carries thrust in "
        "the direction of its contact angle only; give the reversed thrust to the bearing "
        "mounted the other way (share 0 here, 1 there)")


def radial_load_contact(name: str, bearing: Any, steps: Any, kinematics: str) -> None:
    """Refuse, before anything is solved, a turning step without radial load on a cylindrical
    roller bearing with clearance under the roller skidding solver: no roller touches the
    inner ring, so the solver has no traction to drive the cage and stops at that step
    ("the cage speed is undetermined", ``skidding.roller``). The error names the step and
    what to change (a radial load, as a rig's loading unit or the shaft weight applies, or
    race control).

    Likewise a turning step with neither radial nor axial load on a ball bearing under the
    ball skidding solver: the centrifugal force holds the balls on the outer ring, none
    touches the inner ring, and the solver stopped at that step with "no external load ...
    (residual inf)", naming neither the step nor the bearing."""
    if kinematics == "skidding" and hasattr(bearing, "ball_diameter"):
        for i, s in enumerate(steps):
            if s.speed != 0.0 and s.radial_load <= 0.0 and s.axial_load == 0.0:
                raise InputError(
                    f"schedule step {i} radial_load and axial_load (bearing {name!r}, "
                    f"{bearing.name})", "0 kN and 0 kN",
                    "a radial or axial load with kinematics = 'skidding': without load the "
                    "centrifugal force holds the balls on the outer ring, none touches the "
                    "inner ring, and the ball skidding solver has no traction to drive the "
                    "cage (paper 002); give the load the rig or the mounting applies (a "
                    "preload, at least the shaft's weight share) or set [models] kinematics "
                    "= 'race_control'")
        return
    if kinematics != "skidding" or getattr(bearing, "kind", None) != "cylindrical":
        return
    if not getattr(bearing, "diametral_clearance", 0.0) > 0.0:
        return
    for i, s in enumerate(steps):
        if s.speed != 0.0 and s.radial_load <= 0.0:
            raise InputError(
                f"schedule step {i} radial_load (bearing {name!r}, {bearing.name})",
                f"{s.radial_load / 1000.0:g} kN",
                "> 0 kN with kinematics = 'skidding': with its diametral clearance "
                f"({bearing.diametral_clearance * 1e3:g} mm) no roller touches the inner ring "
                "without a radial load, so the roller skidding solver has no traction to "
                "drive the cage (paper 000); give the radial load the rig applies (at least "
                "the shaft's weight share) or set [models] kinematics = 'race_control'")
