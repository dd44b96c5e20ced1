"""The model chain of a scene: which models run, in which order and why.

Model only what a scene needs (:func:`plan_chain`): ``film`` alone runs no kinematics and
no network; ``kinematics``/``losses`` run no network; ``temperatures``/``energy`` add the
network and the transient stepper (or the steady solve in ``mode = "steady"``). Also the
scene's heat sources (defaults per bearing type) and their options in SI, and the roller
solver's options that put a numerical film model into the quasi-dynamics.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from .errors import InputError, UnknownNameError
from .kinematic_models import KINEMATICS
from .scene import Scene
from .scene_film import describe_film_options, film_options_from_models

#: The keys a scene's ``[models]`` table accepts.
MODEL_KEYS = frozenset({"kinematics", "film", "film_options", "heat_sources",
                        "heat_source_options", "control", "churning_heat_to", "calibration",
                        "ball_rolling_resistance"})
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
    """Which parts of the chain a scene runs. ``film``: something computes the contacts'
    films -- the film table (``want`` has "film"), or kinematics that solve contacts
    (every model but ``"none"``, whose global friction source computes no contact and no
    film)."""
    want = set(scene.outputs.want)
    thermal = bool(want & {"temperatures", "energy"})
    losses = thermal or "losses" in want or "report" in want
    kin = losses or "kinematics" in want
    contacts = kin and scene.models.get("kinematics", "skidding") != "none"
    return {"film": "film" in want or contacts or not kin, "kinematics": kin,
            "losses": losses, "network": thermal,
            "transient": thermal and scene.outputs.mode == "transient"}


def ball_rolling_resistance(scene: Scene) -> tuple[str, str]:
    """``[models] ball_rolling_resistance`` as (model, reduction), checked.

    A name of :data:`thermobearing.rolling_resistance.MODELS` (reduction "none") or a table
    ``{ model = "harris", reduction = "thermal_starvation" }`` (reductions
    :data:`thermobearing.rolling_resistance.REDUCTIONS`). Default ("none", "none"): ball
    bearings run without EHL rolling resistance (the paper 002 force models). Errors name
    the field, the value and the allowed names.
    """
    from .rolling_resistance import MODELS, REDUCTIONS

    field = "models.ball_rolling_resistance"
    raw = scene.models.get("ball_rolling_resistance", "none")
    if isinstance(raw, str):
        model, reduction = raw, "none"
    elif isinstance(raw, Mapping):
        unknown = sorted(set(raw) - {"model", "reduction"})
        if unknown:
            raise InputError(f"{field}.{unknown[0]}", raw[unknown[0]],
                             "the keys 'model' and 'reduction'")
        model = raw.get("model", "harris")
        reduction = raw.get("reduction", "none")
    else:
        raise InputError(field, raw, "a model name (" + ", ".join(MODELS) + ") or a table "
                         "{ model = ..., reduction = ... }")
    if model not in MODELS:
        raise UnknownNameError(f"{field}.model" if isinstance(raw, Mapping) else field,
                               model, MODELS)
    if reduction not in REDUCTIONS:
        raise UnknownNameError(f"{field}.reduction", reduction, REDUCTIONS)
    if model != "none" and scene.models.get("kinematics", "skidding") == "none":
        raise InputError(field, model, "'none' with kinematics = \"none\" (the global "
                         "friction model has no contacts to put a rolling force on)")
    return str(model), str(reduction)


def heat_source_names(scene: Scene, is_ball: bool) -> tuple[str, ...]:
    """Heat sources of the scene (``[models] heat_sources``) or the defaults per type
    (ball bearings add ``ehl_rolling_resistance`` when ``ball_rolling_resistance`` is on)."""
    names = scene.models.get("heat_sources")
    if names is None:
        if scene.models.get("kinematics") == "none":
            return ("global_friction",)
        if is_ball and ball_rolling_resistance(scene)[0] != "none":
            return (*BALL_SOURCES, "ehl_rolling_resistance")
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

    ``global_friction`` may be given without being a heat source, with the catalogue
    inputs only (:data:`CROSSCHECK_OPTIONS`: ``series``, ``static_load_rating``): they
    then configure the report's catalogue cross-check (:func:`crosscheck_options`) and no
    loss is booked; they are checked and converted as any other option.
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
        crosscheck_only = src == "global_friction" and src not in sources
        if src not in sources and not crosscheck_only:
            raise InputError(field_name, src, "one of the scene's heat sources: "
                             + ", ".join(sources) + " (or global_friction with "
                             + ", ".join(CROSSCHECK_OPTIONS) + " only: the catalogue "
                             "cross-check's inputs, no loss booked)")
        if not isinstance(params, Mapping):
            raise InputError(field_name, params, "a table of parameter = value")
        if crosscheck_only:
            extra = sorted(set(params) - set(CROSSCHECK_OPTIONS))
            if extra:
                raise InputError(
                    f"{field_name}.{extra[0]}", params[extra[0]],
                    "no value while global_friction is not one of the scene's heat sources ("
                    + ", ".join(sources) + "): only " + ", ".join(CROSSCHECK_OPTIONS)
                    + ", the catalogue cross-check's inputs (nothing is booked)")
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


#: the ``global_friction`` options a scene may give without running that source: the
#: inputs of the report's catalogue cross-check (SKF series, catalogue C0 [N])
CROSSCHECK_OPTIONS = ("series", "static_load_rating")


def crosscheck_options(scene: Scene) -> dict[str, Any]:
    """The SKF model's inputs for the report's catalogue cross-check, from ``[models]
    heat_source_options.global_friction`` (checked and in SI: ``series`` a name,
    ``static_load_rating`` [N]); empty when the scene gives none. The same table also sets
    the ``global_friction`` heat source when the scene runs it; without the source these
    options book no loss (:func:`scene_heat_source_options`)."""
    raw = scene.models.get("heat_source_options", {})
    if not isinstance(raw, Mapping) or "global_friction" not in raw:
        return {}
    checked = scene_heat_source_options(scene, tuple(raw))
    return {k: v for k, v in checked.get("global_friction", {}).items()
            if k in CROSSCHECK_OPTIONS}


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
               is_ball: bool | Sequence[bool] = True) -> list[ChainLink]:
    """The minimal model chain for the scene's outputs (see the module docstring).

    ``is_ball``: the kind of the scene's bearings, one flag or one per bearing; a shaft with
    ball and roller bearings lists the default film model and the heat sources of each
    kind once (a ball bearing beside a roller bearing runs the point-contact film).
    """
    from .film import FILM
    from .lubricant import PRESSURE_VISCOSITY, VISCOSITY_TEMPERATURE

    for key in scene.models:
        if key not in MODEL_KEYS:
            raise InputError(f"models.{key}", scene.models[key],
                             "a known model family: " + ", ".join(sorted(MODEL_KEYS)))
    film_options_from_models(scene.models)  # refused here (check) before anything runs
    need = _needs(scene)
    links: list[ChainLink] = []

    def add(registry: Any, name: str, purpose: str) -> None:
        entry = registry.entry(name)
        links.append(ChainLink(registry.family, name, entry.references, purpose))

    if lubricant is not None:
        add(VISCOSITY_TEMPERATURE, lubricant.viscosity_law, "oil viscosity at node temperatures")
        if need["film"]:  # the contacts' films and tractions use it, nothing else
            add(PRESSURE_VISCOSITY, lubricant.pressure_law, "viscosity at contact pressure")
    kinds = tuple(dict.fromkeys([is_ball] if isinstance(is_ball, bool) else is_ball))
    films = {scene.models.get("film", "hamrock_dowson_1977_central" if ball
                              else "pan_hamrock_central"): ball for ball in kinds}
    for film, ball in films.items():
        which = ("" if len(films) == 1
                 else " (ball bearings)" if ball else " (roller bearings)")
        if film not in FILM and film in _numerical_film_models():
            from .ehl import EHL_SOLVERS

            for ball in kinds:
                check_film_model(film, ball)
            if need["film"]:
                add(EHL_SOLVERS, film, "film thickness and drag of the roller-race line "
                    "contacts (numerical EHL, interpolation table over load, speed, sliding, "
                    "temperature)" + describe_film_options(scene.models))
        else:
            if film not in FILM:
                raise UnknownNameError("models.film", film,
                                       FILM.names() + _numerical_film_models())
            if need["film"]:
                add(FILM, film, "film thickness of the raceway contacts" + which)
    if need["kinematics"]:
        kin = scene.models.get("kinematics", "skidding")
        add(KINEMATICS, kin, "epicyclic cage speed: pure rolling, no contacts"
            if kin == "none" else "cage and element speeds, sliding speeds")
    if need["losses"]:
        from .heat_sources import HEAT_SOURCES

        for name in dict.fromkeys(n for ball in kinds for n in heat_source_names(scene, ball)):
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
                            is_ball: bool, film_options: Mapping[str, Any] | None = None
                            ) -> dict[str, Any]:
    """Roller-solver options that put a numerical film model in the quasi-dynamics.

    ``numerical_tehl``: a :class:`thermobearing.ehl.coupling.TehlFilmModel` (one per bearing,
    its interpolation table lives as long as the Simulation) as ``film_model`` and the
    ``numerical_tehl`` drag model; ``numerical_ehl``: the isothermal numerical drag model.
    Closed-form names: no options (the roller solver keeps its own default film).

    ``film_options``: the film model's keywords, as :func:`scene_film_options` returns them
    (``{"n": 256, "temperature_step": 5.0}``); given for any other film, InputError.
    """
    from .film import FILM

    if film_options and film != "numerical_tehl":
        raise InputError("models.film_options", dict(film_options),
                         f"film_options only with [models] film = \"numerical_tehl\" (the "
                         f"film here is {film!r})")
    if film is None or film in FILM or film not in _numerical_film_models():
        return {}
    check_film_model(film, is_ball)
    if film == "numerical_tehl":
        from .ehl.coupling import roller_film_model

        return {"film_model": roller_film_model(bearing, lubricant, **(film_options or {})),
                "drag_model": "numerical_tehl"}
    return {"drag_model": film}


def scene_film_options(scene: Scene) -> dict[str, Any]:
    """``[models] film_options`` of the scene, checked, as film-model keywords in SI
    (:func:`thermobearing.scene_film.film_options_from_models`); {} without the key."""
    return film_options_from_models(scene.models)
