"""Checks of a scene that run before anything is solved (``thermobearing check``, ``run``,
``sweep`` and ``Simulation.run`` call them): model names against their registries, the
measured CSV's data, the ``[network]`` table against its template, the scene's temperatures
against the lubricant's liquid range. Each error names the scene field, the value and what is
allowed. Re-exported by :mod:`thermobearing.scene`.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

from .errors import InputError, UnknownNameError

if TYPE_CHECKING:  # pragma: no cover
    from .lubricant import Lubricant
    from .scene import Scene


def check_temperatures(scene: Scene, lubricant: Lubricant) -> None:
    """The scene's ambient, initial and oil-inlet temperatures [K] against the lubricant's
    viscosity law: a temperature at which the law overflows, or (ASTM D341) gives more than
    the 1e6 cSt that ends its stated range (the oil below its pour point), or at which its
    density or thermal laws (c_p, k) leave their positive range, is an
    :class:`InputError` naming the scene field; the ambient temperature also against the air
    model's range (:data:`~thermobearing.lubricant_properties.AIR_T_RANGE`). A bare number in
    a scene is kelvin, so ``ambient_temperature = 35`` meant as degC lands here instead of
    failing later inside a solver (a residual of 1e24, a Roelands overflow at some contact
    pressure)."""
    from .lubricant import check_liquid_temperature

    fields = [("environment.ambient_temperature", scene.environment.ambient_temperature),
              ("environment.initial_temperature", scene.environment.initial_temperature)]
    # a bath has no inlet (OilSupply) unless a flow circulates it
    if scene.supply.method != "oil_bath" or scene.supply.flow > 0.0:
        fields.append(("supply.inlet_temperature", scene.supply.inlet_temperature))
    hint = "; a bare number in a scene is in K: write e.g. \"35 degC\""
    for field, kelvin in fields:
        check_liquid_temperature(lubricant, field, kelvin, hint=hint)
    # the air around the machine (convection to ambient): 1e4 degC stopped the run inside
    # the network build as "temperature = 5286.575", naming no scene field
    from .lubricant_properties import AIR_T_ALLOWED, AIR_T_RANGE

    kelvin = scene.environment.ambient_temperature
    if not AIR_T_RANGE[0] <= kelvin <= AIR_T_RANGE[1]:
        raise InputError("environment.ambient_temperature",
                         f"{kelvin:g} K ({kelvin - 273.15:g} degC)", AIR_T_ALLOWED + hint)


def check_model_names(scene: Scene) -> None:
    """Kinematics model, heat sources and stepper against their registries, so that the
    error names the scene field (``models.heat_sources[1]``) and lists the known names.

    ``thermobearing check`` / ``run`` / ``sweep`` call it before building the Simulation
    (which checks the same names, with the registry family as the field). Film models are
    checked, with the numerical ones, when the chain is planned.
    """
    from .heat_sources import HEAT_SOURCES
    from .kinematic_models import KINEMATICS
    from .network import STEPPERS

    models, stepper = scene.models, scene.solver.stepper
    kinematics = models.get("kinematics", "skidding")
    if kinematics not in KINEMATICS:
        raise UnknownNameError("models.kinematics", kinematics, KINEMATICS.names())
    sources = models.get("heat_sources", [])
    listed = [sources] if isinstance(sources, str) else list(sources)
    for i, name in enumerate(listed):
        where = "models.heat_sources" if isinstance(sources, str) else \
            f"models.heat_sources[{i}]"
        if name not in HEAT_SOURCES:
            raise UnknownNameError(where, name, HEAT_SOURCES.names())
        if name in listed[:i]:
            # each listed source ran once per listing: ["churning_cage", "churning_cage"]
            # booked the cage's churning twice (two loss rows, twice the heat)
            raise InputError(where, name, f"each heat source once ({name!r} is also "
                             f"models.heat_sources[{listed.index(name)}])")
    if stepper not in STEPPERS:
        raise UnknownNameError("solver.stepper", stepper, STEPPERS.names())
    if scene.outputs.mode == "transient" and not getattr(STEPPERS.get(stepper), "adaptive",
                                                          True):
        # the comparison steppers need a fixed step size, which a scene cannot give (the
        # transient stopped at its first chunk with "dt is missing", naming no scene field)
        usable = [n for n in STEPPERS.names() if getattr(STEPPERS.get(n), "adaptive", True)]
        raise InputError("solver.stepper", stepper,
                         "a stepper with error control (" + ", ".join(usable) + f"); "
                         f"{stepper!r} takes a fixed step size, for comparisons from Python "
                         "(thermobearing.network.integrate(..., dt=...))")
    if "control" in models:
        from .state import RACE_CONTROLS

        if kinematics != "race_control":
            raise InputError("models.control", models["control"],
                             "nothing unless kinematics = \"race_control\" (the option of "
                             f"race control; kinematics here is {kinematics!r})")
        if models["control"] not in RACE_CONTROLS:
            raise UnknownNameError("models.control", models["control"], RACE_CONTROLS)
    target = models.get("churning_heat_to", "oil")
    if target not in ("oil", "paper002"):
        raise UnknownNameError("models.churning_heat_to", target, ("oil", "paper002"))
    if "film" in models:
        check_closed_form_film(scene)
    from .simulation_chain import ball_rolling_resistance

    if (ball_rolling_resistance(scene)[0] != "none"
            and "ball" not in (_bearing_kinds(scene) or {"ball"})):
        # it acts on ball bearings only: on a roller-only scene it changed nothing, silently
        raise InputError("models.ball_rolling_resistance", models["ball_rolling_resistance"],
                         "'none' or no key in a scene without ball bearings (the option puts "
                         "the EHL rolling force into the ball skidding balance; roller "
                         "bearings book theirs with the ehl_rolling_resistance source by "
                         "default)")
    if ball_rolling_resistance(scene)[0] != "none" and "heat_sources" in models:
        named = [sources] if isinstance(sources, str) else list(sources)
        if "ehl_rolling_resistance" not in named:
            # the solver would balance a force whose heat no source books: the energy
            # audit would miss it
            raise InputError("models.heat_sources", named,
                             "a list with ehl_rolling_resistance when ball_rolling_resistance "
                             "is on (the source books the rolling force's heat)")


def _bearing_kinds(scene: Scene) -> set[str] | None:
    """``{"ball", "roller"}`` kinds of the scene's bearings, or None when one does not load
    (the Simulation reports it with its field)."""
    from .geometry import load_bearing

    kinds = set()
    for spec in scene.bearings:
        try:
            b = load_bearing(spec.preset or str(scene.resolve_path(spec.path)),
                             overrides=spec.overrides or None)
        except Exception:  # noqa: BLE001 - reported with its field when the run loads it
            return None
        kinds.add("ball" if hasattr(b, "ball_diameter") else "roller")
    return kinds


#: the closed-form raceway film of each contact kind: the one race control and the film
#: table compute (:func:`thermobearing.state.race_control_state`); ``[models] film`` may
#: name it, or a numerical line-contact model for roller bearings
KIND_FILMS = {"ball": "hamrock_dowson_1977_central", "roller": "pan_hamrock_central"}


def check_closed_form_film(scene: Scene) -> None:
    """``[models] film`` naming a closed-form model must be the one the scene's bearings
    use: race control and the film table take each contact kind's film
    (:data:`KIND_FILMS`), whatever the scene names, and the skidding solvers their own.
    Another name (``pan_hamrock_central`` on a ball bearing, ``hamrock_dowson_1977_minimum``,
    ``moes_line_central``) ran without a word with the kind's film while the model chain
    listed the name given (fuzz, session 17). Numerical models and unknown names are left
    to the chain plan; a bearing that does not load is left to the Simulation, which names
    its field."""
    from .film import FILM

    name = scene.models["film"]
    if not isinstance(name, str) or name not in FILM:
        return
    kinds = _bearing_kinds(scene)
    if kinds is None:
        return
    used = {KIND_FILMS[k] for k in kinds}
    if used == {name}:
        return
    if len(used) > 1:
        allowed = ("no film key in a scene with ball and roller bearings: ball bearings take "
                   f"{KIND_FILMS['ball']}, roller bearings {KIND_FILMS['roller']} (race "
                   "control and the film table compute those, whatever the scene names)")
    else:
        (kind,) = kinds
        allowed = (f"{KIND_FILMS[kind]} for the {kind} bearings of this scene (race control and "
                   "the film table compute it, whatever the scene names; the skidding "
                   "solvers keep their own film)"
                   + ("" if kind == "ball" else
                      ", or a numerical line-contact model: numerical_ehl, numerical_tehl")
                   + f"; {name} is for thermobearing.film from Python. Leave film out for "
                   "the default")
    raise InputError("models.film", name, allowed)


def check_measured_file(scene: Scene) -> None:
    """Validate the data of the scene's ``[measured]`` file before a run or a fit reads it.

    The file must exist and be readable by
    :func:`thermobearing.measured.read_measured_file` (the one reader; the formats are
    listed there): the time column and every mapped column in its header row, every
    non-empty cell of the mapped columns a number, a dropout flag (``OVL``, ``----``) or one of
    the section's ``missing_values`` (gaps, like empty cells; calibration leaves them out of
    its residuals), every time readable and the times never stepping back (repeated times
    are averaged). The error names the column, the row (1 = first data row)
    and the value.
    """
    from .measured import read_scene_measured

    read_scene_measured(scene)


def check_network(network: Mapping[str, Any], require: bool = True,
                  bearing_names: Sequence[str] | None = None) -> None:
    """Validate a scene's ``[network]`` table before anything runs.

    Keys ``template``, ``parameters`` and ``shaft_link`` only; the template must be
    registered; every parameter must be one the template documents, in a unit of the
    documented dimension; with ``require``, the parameters the template requires
    (keyword-only without a default) must be given (call it so before a run that builds
    the network). ``shaft_link`` (bearings on one shaft, :mod:`.network.shaft`): its keys,
    lengths > 0, material and bearing lists; with ``bearing_names`` (the scene's
    ``[[bearings]]`` names) also the names on each shaft (else the network build checks
    them). Ambient, oil inlet temperature and oil flow come from ``[environment]`` /
    ``[supply]``.
    """
    import inspect

    from .network.templates import TEMPLATES
    from .scene_values import _check_keys, _quantity, _table

    _check_keys("network", network, ("template", "parameters", "shaft_link"))
    if "shaft_link" in network:
        from .network.shaft import parse_shaft_links, resolve_shafts

        specs = parse_shaft_links(network["shaft_link"])
        if bearing_names is not None:
            resolve_shafts(specs, list(bearing_names))
    name = network.get("template", "four_node_paper002")
    if not isinstance(name, str):
        raise InputError("network.template", name, "a template name (a string)")
    if name not in TEMPLATES:
        raise UnknownNameError("network.template", name, TEMPLATES.names())
    entry = TEMPLATES.entry(name)
    params = _table("network.parameters", network.get("parameters", {}))
    from_scene = ("ambient_temperature", "oil_inlet_temperature", "oil_flow")
    for key, value in params.items():
        if key in from_scene:
            raise InputError(f"network.parameters.{key}", value,
                             "set in [environment] / [supply], not in the network")
        unit = entry.parameters.get(key)
        if unit is None:
            from .measured_layout import closest_name

            known = [k for k in sorted(entry.parameters) if k not in from_scene]
            raise InputError(f"network.parameters.{key}", value,
                             f"a parameter of template {name!r}: " + ", ".join(known)
                             + closest_name(str(key), known))
        if unit == "-" and isinstance(value, str):
            continue  # a dimensionless option given by name (a material, a model ...)
        _quantity(value, unit if unit != "-" else "dimensionless", f"network.parameters.{key}")
    required = [p.name for p in inspect.signature(entry.obj).parameters.values()
                if p.kind is inspect.Parameter.KEYWORD_ONLY and p.default is inspect.Parameter.empty
                and p.name not in from_scene and p.name not in params]
    if required and require:
        raise InputError("network.parameters", dict(params),
                         f"values for the parameters template {name!r} requires: "
                         + ", ".join(required))


def check_global_friction(sim: Any) -> None:
    """The ``global_friction`` heat source's inputs, at every distinct operating point of
    each bearing that runs it, before anything is solved: the source itself is evaluated
    (no kinematics: it needs only speeds, loads and the oil viscosity, at the run's
    unheated temperature), so a refusal is the one ``run`` gives at its first step, with
    the same text -- an SKF series the designation does not give (the D1842926 preset,
    the 7014C spindle bearing), the C0 the SKF model needs for a deep-groove bearing under
    axial load, an option of the wrong model. ``thermobearing check`` passed such scenes,
    which ``run`` then refused (session-20 issue 6). Only :class:`InputError` /
    :class:`UnknownNameError` are raised; the source's other failures are the run's."""
    from .heat_sources import HEAT_SOURCES, ROLES, HeatContext
    from .kinematic_models import no_kinematics
    from .state import OperatingPoint
    from .unheated import unheated_temperature

    users = [b for b in getattr(sim, "bearings", ()) if "global_friction" in b.sources]
    if not users:
        return
    source = HEAT_SOURCES.get("global_friction")
    temperature, _ = unheated_temperature(sim.scene)
    options = {"global_friction": dict(sim.source_options.get("global_friction", {}))}
    for b in users:
        seen = set()
        for step in sim.scene.schedule.steps:
            radial, axial = b.operating_loads(step)
            key = (step.speed, radial, axial)
            if key in seen:
                continue
            seen.add(key)
            op = OperatingPoint(inner_speed=step.speed, radial_load=radial, axial_load=axial)
            kin = no_kinematics(b.bearing, sim.lubricant, op, contact_temperature=temperature,
                                oil_temperature=temperature, supply=sim.supply)
            if kin.state.origin == "standstill":
                continue  # at rest the run books 0 W without calling any source
            ctx = HeatContext(bearing=b.bearing, lubricant=sim.lubricant, supply=sim.supply,
                              operating=op, temperatures=dict.fromkeys(ROLES, temperature),
                              kinematics=kin.state, options=options)
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")  # validity notes are the run's to give
                    source(ctx)
            except InputError:  # (UnknownNameError is one)
                raise
            except Exception:  # noqa: BLE001 - not an input error: the run reports it
                return
