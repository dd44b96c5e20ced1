"""A catalogue-level heat source: the whole bearing loss from a global friction model.

The ``global_friction`` source is the cheapest rung of the fidelity ladder (L0 of BM-7):
the SKF four-term model or Palmgren's M0 + M1 (:mod:`thermobearing.global_friction`) gives
the frictional torque of the whole bearing at the oil viscosity of the node temperature,
and the power M * omega is booked on one node role (the oil by default). It needs no
kinematic detail: use it with ``[models] kinematics = "none"`` and
``heat_sources = ["global_friction"]``.
"""

from __future__ import annotations

from ..global_friction import global_friction
from . import HEAT_SOURCES, ROLES, HeatContext, HeatResult

_MODELS = ("skf_four_term", "palmgren")
#: terms of the global models that do not depend on the load (FVA convention)
_LOAD_INDEPENDENT = frozenset({"drag", "seal", "M0"})


@HEAT_SOURCES.register(
    "global_friction",
    references=["harris_kotzalas2007"],
    parameters={"model": "-", "temperature_role": "-", "role": "-", "series": "-",
                "static_load_rating": "N"},
    limits={"static_load_rating": "(0, inf)"},
    validity="as the chosen catalogue model (see `thermobearing models global_friction`)",
    summary="Whole-bearing loss from the SKF four-term or Palmgren model (no kinematics).",
)
def global_friction_source(ctx: HeatContext) -> HeatResult:
    """Power loss M * |omega_i - omega_o| [W] of the global model ``model`` (option,
    default ``skf_four_term``), with the kinematic viscosity at the temperature of
    ``temperature_role`` (default ``oil``), booked on ``role`` (default ``oil``); one
    component per term of the model (SKF rolling / sliding / seal / drag, Palmgren M0 / M1)
    with its load class. ``series``: the SKF series key (``72_ACCBM``, ...; default read
    from the bearing's designation), for the SKF model only. ``static_load_rating``: the
    bearing's catalogue C0 [N], which the SKF model needs for a deep-groove bearing under
    axial load (alpha_F = 24.6 (F_a/C0)^0.24 deg; SKF model only); without it such a
    step is refused naming this option."""
    from ..errors import InputError, UnknownNameError

    name = "global_friction"
    model = ctx.option(name, "model", "skf_four_term")
    if model not in _MODELS:
        raise UnknownNameError(f"heat source {name!r} option model", model, _MODELS)
    t_role = ctx.option(name, "temperature_role", "oil")
    role = ctx.option(name, "role", "oil")
    if role not in ROLES:
        raise UnknownNameError(f"heat source {name!r} option role", role, ROLES)
    op = ctx.operating
    speed = abs(op.inner_speed - op.outer_speed)
    series = ctx.option(name, "series", None)
    extra = {}
    if series is not None:
        if model != "skf_four_term":
            raise InputError(f"heat source {name!r} option series", series,
                             "no series with model = \"palmgren\" (SKF four-term only)")
        extra["series"] = str(series)
    c0 = ctx.option(name, "static_load_rating", None)
    if c0 is not None:
        if model != "skf_four_term":
            raise InputError(f"heat source {name!r} option static_load_rating", c0,
                             "no static_load_rating with model = \"palmgren\" (SKF four-term "
                             "only)")
        extra["static_load_rating"] = float(c0)
    try:
        res = global_friction(model, ctx.bearing, ctx.lubricant, ctx.temperature(t_role),
                              speed, op.radial_load, op.axial_load, supply=ctx.supply,
                              **extra)
    except InputError as exc:
        if exc.field != "static_load_rating":
            raise
        # the bearing files carry no C0: name the scene field that gives it
        raise InputError(
            f"models.heat_source_options.{name}.static_load_rating", None,
            f"the static load rating C0 of {ctx.bearing.name} from its catalogue, a force "
            "with its unit: the SKF four-term model needs it for a deep-groove bearing under "
            f"axial load ({op.axial_load:g} N here; alpha_F = 24.6 (F_a/C0)^0.24 deg), or "
            "model = \"palmgren\"") from None
    power = float(res.power)
    if not power >= 0.0:
        raise InputError(f"heat source {name!r} power", power, "a finite loss >= 0 W")
    # one component per term of the model, each with its load class (the FVA split the
    # loss tables use): SKF rolling and sliding and Palmgren's M1 depend on the load, SKF
    # drag and seal and Palmgren's M0 do not
    comps = {f"{model} {term}": float(m) * speed for term, m in res.components.items()
             if float(m) != 0.0}   # (no seal: no seal row)
    total = sum(comps.values())
    if comps and total > 0.0:
        comps = {k: v * power / total for k, v in comps.items()}  # the same total
    else:
        comps = {f"{model} total": power}
    classes = {k: ("load_independent" if k.split(" ")[-1] in _LOAD_INDEPENDENT
                   else "load_dependent") for k in comps}
    return HeatResult(source=name, power_by_role={role: power}, components=comps,
                      loss_class=classes, details={"torque [N m]": float(res.torque)})
