"""Network templates built from a bearing, a lubricant and a few housing/shaft dimensions.

Registry ``network_template`` (the scene names one):

- ``four_node_paper002`` -- paper 002 (Gao et al. 2022, ``seeds/002_*.txt``) sec. 2.3,
  eqs. 21-29: nodes balls, housing (+ outer ring), shaft (+ inner ring), oil (+ cage), with
  the ambient and the oil inlet as fixed temperatures and the oil flow as an enthalpy
  stream from the inlet through the oil node.
- ``seven_node`` -- a finer network: outer ring, housing, inner ring, shaft, balls, cage,
  oil (same boundaries and stream).

Both return an editable :class:`~.graph.ThermalNetwork` (nodes carry ``roles`` and the
bearing's ``group``; pass ``group=`` to put two bearings in one network with
:func:`merge`). Every geometric estimate a template makes (volumes of rings and housing,
oil in the cavity) is written in the docstring; change it after construction with
``set_capacity``/``set_edge_conductance`` if you know better.

Every template has a ``shaft`` node (:data:`SHAFT_NODE`) holding the inner ring's shaft
piece (:func:`shaft_segment`); ``[network] shaft_link`` joins those of bearings on one shaft
(:mod:`.shaft`).

Role map of the four-node template (contract): outer_ring -> housing, inner_ring -> shaft,
elements -> balls, cage -> oil, oil -> oil. In a roller bearing the element node is named
``rollers`` (same role, same equations with the rollers' mass and surface).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import InputError
from ..registry import Registry
from .conductances import (
    Convection,
    HertzConstriction,
    HertzContactPaper002,
    NaturalConvectionCylinder,
)
from .graph import ThermalNetwork

TEMPLATES: Registry[Any] = Registry("network_template", "thermal network built from a bearing")

#: default convection coefficient of the oil on wetted surfaces [W/(m^2 K)]: paper 002 gives
#: 50-1500 W/(m^2 K) for its jet-lubricated bearing (sec. 2.3); the geometric mean is used.
H_OIL_DEFAULT = 270.0
#: default h of air on a rotating shaft end / ring faces [W/(m^2 K)] (estimate: natural
#: convection plus linearised radiation ~ 10 W/(m^2 K), primer sec. 4.2 worked example).
H_AIR_DEFAULT = 10.0
#: default material of housing and shaft (the templates' ``housing_material``)
HOUSING_MATERIAL_DEFAULT = "STEEL_52100"
#: name of the node (after the bearing's prefix) that holds the inner ring's shaft piece in
#: every template: ``[network] shaft_link`` joins these nodes (:mod:`.shaft`)
SHAFT_NODE = "shaft"


#: units of the parameters both templates take (seat, oil supply, boundaries, contacts), in the
#: order the registry lists them; the seven-node template adds ``fit_conductance`` after them
_SEAT_PARAMETERS = {
    "housing_outer_diameter": "m", "housing_length": "m", "shaft_diameter": "m",
    "shaft_length": "m", "oil_flow": "m**3/s", "oil_inlet_temperature": "K",
    "ambient_temperature": "K", "ball_load": "N", "h_oil": "W/(m**2*K)", "h_air": "W/(m**2*K)",
}
#: units of the cavity-fill, contact-model and material parameters of both templates
_FILL_PARAMETERS = {"oil_fill": "-", "contact_model": "-", "housing_material": "-"}


def _material(m, field: str = "housing_material"):
    """The material preset ``m`` (or a Material); errors name the template's ``field``
    (they named ``material``, which the scene's [network] table does not have)."""
    from ..errors import UnknownNameError
    from ..materials import get_material

    try:
        return get_material(m)
    except UnknownNameError as exc:
        raise UnknownNameError(field, m, exc.known) from None
    except InputError as exc:
        if type(exc) is not InputError:
            raise
        raise InputError(field, m, exc.allowed) from None


def _fraction(field: str, value: Any) -> float:
    """A fraction in [0, 1] given as a number or a dimensionless quantity (``"30 %"``:
    a string reached the comparison as a TypeError)."""
    from ..units import to_si

    f = to_si(value, "dimensionless", field=field)
    if not 0.0 <= f <= 1.0:
        raise InputError(field, value, "a fraction in [0, 1]")
    return f


def _check_coefficients(**coefficients: float | None) -> None:
    """Heat transfer coefficients [W/(m^2 K)] against the limits of their conductance
    (:class:`Convection`; ``fit_conductance``: :class:`ContactFit`), named as the template's
    parameter: ``fit_conductance = 0`` was refused as ``contact_fit.contact_conductance``."""
    from .conductances import ContactFit

    for name, h in coefficients.items():
        if h is None:
            continue
        try:
            (ContactFit if name == "fit_conductance" else Convection)(h, 1.0)
        except InputError as exc:
            if type(exc) is not InputError:
                raise
            raise InputError(name, h, exc.allowed) from None


def _contact_axes(bearing, ball_load: float) -> dict[str, tuple[float, float]]:
    """Semi-axes (a, b) [m] of the inner and outer contacts at element load Q [N] (Hertz):
    the contact ellipse of a ball, or for a roller half its effective length and the
    half-width of the line contact."""
    from ..hertz import line_contact, point_contact

    out = {}
    for race in ("inner", "outer"):
        rx, ry = bearing.curvature(race)
        if _is_ball(bearing):
            pc = point_contact(ball_load, rx, ry, bearing.effective_modulus)
            out[race] = (float(pc.a), float(pc.b))
        else:
            length = bearing.roller_effective_length or bearing.roller_length
            lc = line_contact(ball_load, length, rx, bearing.effective_modulus)
            out[race] = (0.5 * float(length), float(lc.half_width))
    return out


def _is_ball(bearing) -> bool:
    return hasattr(bearing, "ball_diameter")


def _element(bearing) -> dict[str, Any]:
    """Rolling elements of a ball or roller bearing: material, count Z, diameter, mass of one
    element [kg], volume of one [m^3] and wetted surface of one [m^2] (ball pi D^2; roller
    pi D L + 2 pi D^2 / 4)."""
    if _is_ball(bearing):
        D = bearing.ball_diameter
        return {"material": bearing.ball_material, "Z": bearing.n_balls, "D": D,
                "mass": bearing.ball_mass, "volume": math.pi * D**3 / 6.0,
                "area": math.pi * D**2}
    D, L = bearing.roller_diameter, bearing.roller_length
    return {"material": bearing.roller_material, "Z": bearing.n_rollers, "D": D,
            "mass": bearing.roller_mass, "volume": math.pi * D**2 * L / 4.0,
            "area": math.pi * D * L + 0.5 * math.pi * D**2}


def _element_node(bearing) -> str:
    """Name of the rolling-element node: ``balls`` or ``rollers``."""
    return "balls" if _is_ball(bearing) else "rollers"


def _oil_properties(lubricant, T: float) -> tuple[float, float]:
    return float(lubricant.density(T)), float(lubricant.specific_heat(T))


@dataclass(frozen=True)
class ShaftSegment:
    """The solid shaft piece a template's ``shaft`` node holds besides the inner ring.

    diameter d_s [m] (``shaft_diameter``, default the bore d), length L_s [m]
    (``shaft_length``, default the housing length L_h; the piece is taken centred on the
    bearing), material (``housing_material``). Capacity rho c pi d_s^2 / 4 L_s [J/K].
    """

    diameter: float
    length: float
    material: Any

    @property
    def capacity_per_length(self) -> float:
        """rho c pi d_s^2 / 4 [J/(K m)]."""
        return (self.material.density * self.material.specific_heat
                * math.pi / 4.0 * self.diameter**2)


def shaft_segment(bearing, *, housing_length: float, shaft_diameter: float | None = None,
                  shaft_length: float | None = None,
                  housing_material: str = HOUSING_MATERIAL_DEFAULT, **_: Any) -> ShaftSegment:
    """The shaft piece of the templates' ``shaft`` node for the template parameters (SI),
    as :func:`four_node_paper002` and :func:`seven_node` count it (other parameters are
    ignored, so a template's whole parameter set can be passed)."""
    return ShaftSegment(shaft_diameter or bearing.bore, shaft_length or housing_length,
                        _material(housing_material))


def _check_dims(**dims: float) -> None:
    for k, v in dims.items():
        if v is None:
            continue
        if not math.isfinite(float(v)) or float(v) <= 0:
            raise InputError(k, v, "a finite value > 0 (SI)")
        if not math.isfinite(float(v) * float(v) * float(v) * 1e12):
            # a length whose volume overflows (housing_outer_diameter = 1e308 m stopped
            # with OverflowError in the housing volume)
            raise InputError(k, v, "a value whose cube (a volume) is a finite number (SI)")


def _check_seat(bearing, housing_length: float, shaft_diameter: float | None) -> None:
    """Refuse a seat that cannot hold the bearing: a shaft wider than the bore d (the inner
    ring sits on it) or a housing shorter than the ring width B (it holds the outer ring).
    Equal within a relative 1e-9 passes (the same length read twice from unit strings)."""
    d, B = bearing.bore, bearing.width
    if shaft_diameter is not None and shaft_diameter > d * (1.0 + 1e-9):
        raise InputError("shaft_diameter", shaft_diameter,
                         f"a diameter <= the bearing bore {d:g} m ({1e3 * d:g} mm): the inner "
                         "ring sits on the shaft (omit it to take the bore)")
    if housing_length < B * (1.0 - 1e-9):
        raise InputError("housing_length", housing_length,
                         f"a length >= the bearing width {B:g} m ({1e3 * B:g} mm): the housing "
                         "holds the outer ring over its width")


def _cavity(bearing) -> dict[str, float]:
    """Geometry of the bearing cavity [m, m^2, m^3] between the ring lands."""
    B = bearing.width
    d_li = bearing.inner_land_diameter
    d_lo = bearing.outer_land_diameter
    el = _element(bearing)
    v_balls = el["Z"] * el["volume"]
    cage = bearing.cage
    v_cage = 0.0
    if cage.material is not None:
        v_cage = bearing.cage_mass / cage.material.density
    v_free = max(math.pi / 4.0 * (d_lo**2 - d_li**2) * B - v_balls - v_cage, 0.0)
    return {"B": B, "d_li": d_li, "d_lo": d_lo, "v_free": v_free, "v_cage": v_cage}


def _ring_capacities(bearing, cav: dict[str, float]) -> tuple[float, float]:
    """Heat capacities rho c V [J/K] of the (outer, inner) ring: the annulus between the outer
    diameter D and the outer land diameter D_Lo, and between the bore d and the inner land
    diameter D_Li, over the width B (``cav`` from :func:`_cavity`; an estimate of the ring
    volumes, as :func:`four_node_paper002` states)."""
    ring = bearing.ring_material
    rho_c = ring.density * ring.specific_heat
    B, d_li, d_lo = cav["B"], cav["d_li"], cav["d_lo"]
    v_outer = math.pi / 4.0 * (bearing.outer_diameter**2 - d_lo**2) * B
    v_inner = math.pi / 4.0 * (d_li**2 - bearing.bore**2) * B
    return rho_c * v_outer, rho_c * v_inner


@TEMPLATES.register(
    "four_node_paper002",
    references=["gao2022_overskidding", "incropera2007", "churchill_chu1975"],
    parameters={**_SEAT_PARAMETERS, **_FILL_PARAMETERS},
    validity="lumped bodies (no gradient inside a component); paper 002's rig",
)
def four_node_paper002(
    bearing,
    lubricant,
    *,
    housing_outer_diameter: float,
    housing_length: float,
    shaft_diameter: float | None = None,
    shaft_length: float | None = None,
    oil_flow: float = 0.0,
    oil_inlet_temperature: float = 308.15,
    ambient_temperature: float = 308.15,
    ball_load: float = 1000.0,
    h_oil: float = H_OIL_DEFAULT,
    h_air: float | None = None,
    oil_fill: float = 0.3,
    contact_model: str = "hertz_constriction",
    housing_material: str = HOUSING_MATERIAL_DEFAULT,
    group: str = "bearing",
    prefix: str = "",
    network: ThermalNetwork | None = None,
) -> ThermalNetwork:
    """Four-node network of paper 002 (eqs. 21-29) for one ball bearing.

    Nodes [J/K] (C = rho c V, eq. 21):

    - ``balls`` (``rollers`` in a roller bearing): Z m_ball c_ball;
    - ``housing``: housing annulus pi/4 (D_h^2 - D^2) L_h plus the outer ring, estimated
      as the annulus between the outer diameter D and the outer land diameter D_Lo over
      the width B;
    - ``shaft``: inner ring (annulus between the bore d and the inner land diameter D_Li
      over B) plus a solid shaft of ``shaft_diameter`` (default d) and ``shaft_length``
      (default L_h) of ``housing_material`` (:func:`shaft_segment`), the piece taken centred
      on the bearing; bearings on one shaft are joined node to node by
      :mod:`.shaft` (``[network] shaft_link``), which shares pieces that overlap;
    - ``oil``: oil filling ``oil_fill`` of the free cavity volume (between the lands, minus
      balls and cage) times rho c_p, plus the cage mass times its c.

    Edges (eqs. 22-25): balls-housing and balls-shaft through the Hertz contacts at ball
    load ``ball_load`` [N] (``contact_model`` ``hertz_constriction``, the elliptic
    constriction, or ``hertz_contact_paper002``, eq. 26 in consistent form; see
    :mod:`.conductances`), x Z contacts; balls-, housing- and shaft-oil by convection with
    ``h_oil`` over eq. 28's areas A_boil = Z pi D_b^2, A_hoil = pi D_Lo L_h,
    A_soil = pi D_Li L_h; housing-ambient by natural convection from a horizontal cylinder
    (Churchill-Chu with CoolProp air) over eq. 29's A_hatm = pi (D_h^2 - D_Lo^2)/2 +
    pi D_h L_h, or with ``h_air`` if given; shaft-ambient over A_satm with
    h = ``h_air`` (default 10 W/(m^2 K)); oil-ambient over A_oilatm = A_boil + A_hoil + A_soil
    (eq. 29) with the same air h. Eq. 29 prints A_satm = pi (D_s^2 - D_Li^2)/2 with D_s "the
    diameter of the inner ring"; read literally with D_s the bore it is negative, so the
    two side faces of the inner-ring annulus pi (D_Li^2 - d^2)/2 are used. Eq. 27's
    R = L/(h A) is taken as R = 1/(h A) (dimensionally consistent).

    Oil stream: oil_inlet -> oil with m_dot c_p = rho(T_in) c_p(T_in) ``oil_flow``
    [m^3/s]; change it later with ``network.set_stream_flow(prefix + "oil", W)``.

    Parameters are SI: lengths [m], temperatures [K], oil_flow [m^3/s], h [W/(m^2 K)].
    ``network``/``prefix``/``group`` add the nodes into an existing network (two bearings
    on one rig: call twice with different prefixes and groups; the boundaries are shared).
    """
    _check_dims(housing_outer_diameter=housing_outer_diameter, housing_length=housing_length,
                shaft_diameter=shaft_diameter, shaft_length=shaft_length, ball_load=ball_load)
    if oil_flow < 0 or not math.isfinite(oil_flow):
        raise InputError("oil_flow", oil_flow, "a flow >= 0 m^3/s")
    oil_fill = _fraction("oil_fill", oil_fill)
    if housing_outer_diameter <= bearing.outer_diameter:
        raise InputError("housing_outer_diameter", housing_outer_diameter,
                         f"a diameter > the bearing outer diameter {bearing.outer_diameter} m")
    _check_seat(bearing, housing_length, shaft_diameter)
    net = network if network is not None else ThermalNetwork(f"{bearing.name} four-node")
    p = prefix
    _boundaries(net, ambient_temperature, oil_inlet_temperature)
    cav = _cavity(bearing)
    d_li, d_lo = cav["d_li"], cav["d_lo"]
    D_h, L_h = housing_outer_diameter, housing_length
    d = bearing.bore
    D = bearing.outer_diameter
    shaft = shaft_segment(bearing, housing_length=L_h, shaft_diameter=shaft_diameter,
                          shaft_length=shaft_length, housing_material=housing_material)
    ring = bearing.ring_material
    hous = _material(housing_material)
    el = _element(bearing)
    ball = el["material"]
    Z = el["Z"]

    c_balls = Z * el["mass"] * ball.specific_heat
    c_outer, c_inner = _ring_capacities(bearing, cav)
    v_house = math.pi / 4.0 * (D_h**2 - D**2) * L_h
    c_house = hous.density * hous.specific_heat * v_house + c_outer
    v_shaft = math.pi / 4.0 * shaft.diameter**2 * shaft.length
    c_shaft = c_inner + shaft.material.density * shaft.material.specific_heat * v_shaft
    rho_o, cp_o = _oil_properties(lubricant, oil_inlet_temperature)
    c_oil = oil_fill * cav["v_free"] * rho_o * cp_o
    if bearing.cage.material is not None:
        c_oil += bearing.cage_mass * bearing.cage.material.specific_heat

    e = _element_node(bearing)
    net.add_node(p + e, c_balls, group=group, role="elements")
    net.add_node(p + "housing", c_house, group=group, role="outer_ring")
    net.add_node(p + SHAFT_NODE, c_shaft, group=group, role="inner_ring")
    net.add_node(p + "oil", c_oil, group=group, role=("oil", "cage"))

    axes = _contact_axes(bearing, ball_load)
    for race, node in (("outer", "housing"), ("inner", "shaft")):
        a, b = axes[race]
        net.add_edge(p + e, p + node, _contact(contact_model, a, b, ball, ring, Z),
                     name=f"{p}{e}--{node} (Hertz, eq. 26)")
    A_boil = Z * el["area"]
    A_hoil = math.pi * d_lo * L_h
    A_soil = math.pi * d_li * L_h
    net.add_edge(p + e, p + "oil", Convection(h_oil, A_boil), name=f"{p}{e}--oil")
    net.add_edge(p + "housing", p + "oil", Convection(h_oil, A_hoil), name=f"{p}housing--oil")
    net.add_edge(p + "shaft", p + "oil", Convection(h_oil, A_soil), name=f"{p}shaft--oil")
    A_hatm = math.pi * (D_h**2 - d_lo**2) / 2.0 + math.pi * D_h * L_h
    A_satm = math.pi * (d_li**2 - d**2) / 2.0
    h_a = H_AIR_DEFAULT if h_air is None else h_air
    house_air = (NaturalConvectionCylinder(D_h, A_hatm) if h_air is None
                 else Convection(h_air, A_hatm))
    net.add_edge(p + "housing", "ambient", house_air, name=f"{p}housing--ambient")
    net.add_edge(p + "shaft", "ambient", Convection(h_a, A_satm), name=f"{p}shaft--ambient")
    net.add_edge(p + "oil", "ambient", Convection(h_a, A_boil + A_hoil + A_soil),
                 name=f"{p}oil--ambient")
    net.add_stream(["oil_inlet", p + "oil"], rho_o * cp_o * oil_flow, name=p + "oil")
    return net


def _boundaries(net: ThermalNetwork, T_amb: float, T_in: float) -> None:
    if "ambient" not in net.graph:
        net.add_boundary("ambient", T_amb)
    if "oil_inlet" not in net.graph:
        net.add_boundary("oil_inlet", T_in)


def _contact(model: str, a: float, b: float, ball, ring, Z: int):
    if model == "hertz_constriction":
        return HertzConstriction(a, b, ball.thermal_conductivity, ring.thermal_conductivity, Z)
    if model == "hertz_contact_paper002":
        k = 2.0 / (1.0 / ball.thermal_conductivity + 1.0 / ring.thermal_conductivity)
        return HertzContactPaper002(a, b, k, Z)
    raise InputError("contact_model", model, "'hertz_constriction' or 'hertz_contact_paper002'")


@TEMPLATES.register(
    "seven_node",
    references=["gao2022_overskidding", "incropera2007", "churchill_chu1975"],
    parameters={**_SEAT_PARAMETERS, "fit_conductance": "W/(m**2*K)", **_FILL_PARAMETERS},
    validity="lumped bodies; fits by a contact conductance; cage exchanges heat with oil only",
)
def seven_node(
    bearing,
    lubricant,
    *,
    housing_outer_diameter: float,
    housing_length: float,
    shaft_diameter: float | None = None,
    shaft_length: float | None = None,
    oil_flow: float = 0.0,
    oil_inlet_temperature: float = 308.15,
    ambient_temperature: float = 308.15,
    ball_load: float = 1000.0,
    h_oil: float = H_OIL_DEFAULT,
    h_air: float | None = None,
    fit_conductance: float = 5000.0,
    oil_fill: float = 0.3,
    contact_model: str = "hertz_constriction",
    housing_material: str = HOUSING_MATERIAL_DEFAULT,
    group: str = "bearing",
    prefix: str = "",
    network: ThermalNetwork | None = None,
) -> ThermalNetwork:
    """Seven-node network: outer ring, housing, inner ring, shaft, balls, cage, oil.

    As :func:`four_node_paper002`, with the rings split from housing and shaft: ring-housing
    and ring-shaft fits by a contact conductance ``fit_conductance`` [W/(m^2 K)] over
    pi D B and pi d B (:class:`~.conductances.ContactFit`; 5000 W/(m^2 K) is an estimate
    inside the 1e3-1e5 range of Incropera et al. 2007 Table 3.1 for metal pairs); the
    Hertz contacts go ball-ring; oil convection (``h_oil``) on the balls (Z pi D^2), the
    outer-ring land (pi D_Lo B), the inner-ring land (pi D_Li B), the housing bore faces
    (pi D_Lo L_h as in paper 002) and both cage cylinders (pi (d_c,in + d_c,out) w_c); cage
    heat capacity from its mass. Roles: outer_ring, inner_ring, elements, cage, oil.
    """
    _check_coefficients(fit_conductance=fit_conductance)
    if h_oil == 0.0:
        # the cage node's one edge is its oil convection: without it the cage has no path
        # to a fixed temperature (the network check named node 'a.cage', no parameter)
        raise InputError("h_oil", h_oil, "a coefficient > 0 in the seven-node template: "
                         "the cage exchanges heat only with the oil, by this convection")
    net = network if network is not None else ThermalNetwork(f"{bearing.name} seven-node")
    base = four_node_paper002(
        bearing, lubricant, housing_outer_diameter=housing_outer_diameter,
        housing_length=housing_length, shaft_diameter=shaft_diameter,
        shaft_length=shaft_length, oil_flow=oil_flow,
        oil_inlet_temperature=oil_inlet_temperature, ambient_temperature=ambient_temperature,
        ball_load=ball_load, h_oil=h_oil, h_air=h_air, oil_fill=oil_fill,
        contact_model=contact_model, housing_material=housing_material, group=group,
        prefix="__tmp__",
    )
    from .conductances import ContactFit

    p = prefix
    _boundaries(net, ambient_temperature, oil_inlet_temperature)
    cav = _cavity(bearing)
    B, d_li, d_lo = cav["B"], cav["d_li"], cav["d_lo"]
    d, D = bearing.bore, bearing.outer_diameter
    c_outer, c_inner = _ring_capacities(bearing, cav)
    c_house = base.capacity("__tmp__housing") - c_outer
    c_shaft = base.capacity("__tmp__shaft") - c_inner
    cage = bearing.cage
    c_cage = bearing.cage_mass * cage.material.specific_heat if cage.material else 0.0
    c_oil = base.capacity("__tmp__oil") - c_cage
    rho_o, cp_o = _oil_properties(lubricant, oil_inlet_temperature)
    # reuse the four-node template's evaluated models where the physics is the same
    edge = {name: m for _, _, _, m, name in _named_edges(base)}

    net.add_node(p + "outer_ring", c_outer, group=group, role="outer_ring")
    net.add_node(p + "housing", c_house, group=group)
    net.add_node(p + "inner_ring", c_inner, group=group, role="inner_ring")
    net.add_node(p + SHAFT_NODE, c_shaft, group=group)
    e = _element_node(bearing)
    net.add_node(p + e, base.capacity(f"__tmp__{e}"), group=group, role="elements")
    net.add_node(p + "cage", max(c_cage, 0.0), group=group, role="cage")
    net.add_node(p + "oil", c_oil, group=group, role="oil")

    net.add_edge(p + "outer_ring", p + "housing", ContactFit(fit_conductance, math.pi * D * B))
    net.add_edge(p + "inner_ring", p + "shaft", ContactFit(fit_conductance, math.pi * d * B))
    net.add_edge(p + e, p + "outer_ring", edge[f"__tmp__{e}--housing (Hertz, eq. 26)"])
    net.add_edge(p + e, p + "inner_ring", edge[f"__tmp__{e}--shaft (Hertz, eq. 26)"])
    net.add_edge(p + e, p + "oil", edge[f"__tmp__{e}--oil"])
    net.add_edge(p + "outer_ring", p + "oil", Convection(h_oil, math.pi * d_lo * B))
    net.add_edge(p + "inner_ring", p + "oil", Convection(h_oil, math.pi * d_li * B))
    net.add_edge(p + "housing", p + "oil", edge["__tmp__housing--oil"])
    a_cage = math.pi * (cage.inner_diameter + cage.outer_diameter) * cage.width
    net.add_edge(p + "cage", p + "oil", Convection(h_oil, a_cage))
    net.add_edge(p + "housing", "ambient", edge["__tmp__housing--ambient"])
    net.add_edge(p + "shaft", "ambient", edge["__tmp__shaft--ambient"])
    net.add_edge(p + "oil", "ambient", edge["__tmp__oil--ambient"])
    net.add_stream(["oil_inlet", p + "oil"], rho_o * cp_o * oil_flow, name=p + "oil")
    return net


def _named_edges(net: ThermalNetwork):
    for _, _, k, d in net.graph.edges(keys=True, data=True):
        yield d["a"], d["b"], k, d["model"], d["name"]


def oil_capacity_rate(lubricant, oil_flow: float, inlet_temperature: float) -> float:
    """m_dot c_p [W/K] = rho(T_in) c_p(T_in) Q for an oil flow Q [m^3/s] at T_in [K]."""
    rho, cp = _oil_properties(lubricant, inlet_temperature)
    return rho * cp * oil_flow
