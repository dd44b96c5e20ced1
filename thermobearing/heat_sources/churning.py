"""Oil churning and drag of the cage, the rolling elements and the inner ring (paper 002).

Seed paper 002 (002_0add79adaca5495c.txt), eqs. 10 and 12-17, in consistent SI:

- viscous friction coefficient from the Reynolds and Taylor numbers
  N_Re = R omega c / nu,  N_Ta = N_Re sqrt(c / R)  (nu kinematic: the paper's "eta" must be
  the kinematic viscosity for N_Re to be dimensionless):
  laminar (N_Ta <= 41) mu_l = 16 / N_Re (eq. 12); Taylor-vortex (N_Ta > 41, N_Re <= 2500)
  1.3 mu_l (N_Ta/41)^0.539474 (eq. 13); Couette-turbulent (N_Re > 2500)
  3.0 mu_l (N_Re/2500)^0.85596 (eq. 14). The paper's regime conditions overlap
  ("N_Re < 2500 or N_Ta < 41" for laminar); we use the usual order laminar -> Taylor
  vortices -> turbulence. The printed formulas are discontinuous at the regime boundaries
  and so is mu_v (tests/unit/test_prop19_churning.py): x1.3 at N_Ta = 41 (eq. 13 starts at
  1.3 mu_l); at N_Re = 2500 by eq. 14 / eq. 13 = 3.0 / (1.3 (2500 sqrt(c/R) / 41)^0.539474),
  a function of the gap ratio only, > 1 below c/R = 0.00597 and < 1 above (0.34-0.87 for
  the default cage, ring and element gaps of configs/bearings, e.g. QJ1044 cage 0.87: the
  churning power then falls as the speed crosses N_Re = 2500); for c/R < (41/2500)^2 the
  laminar coefficient runs up to N_Ta = 41 above N_Re = 2500 and jumps to eq. 14 by
  3.0 (N_Re/2500)^0.85596 > 3.
- cage (eq. 15)    Q = pi rho mu_v omega_c^3 B_c D_c^4 / 64
- inner ring (eq. 17) Q = pi rho mu_v omega_i^3 (B_arc + 2 B_Li) D_Li^4 / 64
- balls (eq. 16)   printed as c_d pi rho mu_v omega_b^3 D_m^3 D_b N_b / (256 g). The g belongs
  to a weight-density form (rho [N/m^3] / g = mass density); with a mass density it goes.
  Even so the printed form is one length short of a power (kg m s^-3): the drag power of
  eq. 10 summed over the balls, N_b * (1/2) c_d rho (pi D_b^2/4) u^2 * u with u = omega_b
  D_m / 2, is c_d pi rho omega^3 D_m^3 D_b^2 N_b / 64, i.e. eq. 16 is this times mu_v / 4
  with D_b^2. We implement Q = c_d pi rho mu_v omega_b^3 D_m^3 D_b^2 N_b / 256 [W]
  (``form="paper002"``, default) or the plain eq. 10 drag (``form="harris"``); the
  dimensional check is a unit test.

Effective density: the bearing cavity holds an oil-air mixture, rho_e = X rho_oil (Harris;
primer losses 2.2), with the same rule for the dynamic viscosity so that nu_e = nu_oil.
X (volume fraction) from

- jets / circulation / oil-air: Parker's correlation (NASA TP-2275, 1984)
  X[%] = K Q^0.37 / (n d_m^1.7), Q in cm^3/min, n in r/min, d_m in mm, capped at 100 %.
  The exponents are as recalled in the primer; the constant K = 1.46e7 is tagged [R] there
  and could NOT be verified against TP-2275 in this build (searched the public corpora:
  not found). It is an option (``parker_constant``). Ratios between two flows at one speed
  depend only on the exponent 0.37.
- oil bath: geometric level model: an element (or cage/ring surface point) at radius r is
  immersed over the part of its revolution where it is below the static level H (measured
  from the lowest point of the outer raceway); time-averaged X = acos(clip((R_o - H)/r))/pi.
- grease: churning of channelled grease is not modelled: X = 0 with a ValidityWarning.
- ``options[...]["oil_fraction"]`` overrides X for any method.

Gaps and radii (the paper gives none): cage R = D_c/2 (cage mean diameter), c = mean radial
gap between the cage and its radial neighbours (the guide land of the guiding ring, the land
or raceway of the other, :func:`cage_neighbour_diameters`); balls R = D_m/2, c = radial
cavity height between the lands; inner ring R = D_Li/2, c = gap between inner land and cage
bore (:func:`inner_ring_churning_geometry`). Options override them. The skidding solvers'
drag models take the same geometry functions.

Each source returns the drag moment/force for the skidding solver (``forces``), the heat,
and the force pairs (moment x angular speed, force x orbital speed) whose power equals it.

High-speed roller bearing: why element churning dominates (checked 2026-11-24)
-------------------------------------------------------------------------------
The CRB_50x75x16 preset of seed paper 003 (inner rib only; the operating point of
configs/scenes/crb_rib_example.toml: jet 2 L/min, MIL-PRF-23699, 3 kN, race control; that
scene's ``ribbed_ring = "both"`` override, with the 65 mm cage that clears the outer ribs,
gives other ring and cage churning: inner ring 205.6 W, cage 59.0 W at 30000 r/min, 80 degC;
the 66 mm cage it had before sat across the ribs, its gap at the 0.1 mm floor, 38.0 W)
at 30000 r/min books about three quarters of its loss as element churning, and its total
lies 50-130 % above Palmgren's M0 + M1. Term by term (eq. 10 per roller,
tests/unit/test_losses20_churning.py):

- X = 1.46e7 * 2000^0.37 / (30000 * 62.5^1.7) % = 7.17 % (Parker; K unverified, above),
  rho_e = X rho_oil = 68.7 kg/m^3 at 80 degC;
- u = omega_m D_m / 2 = 1420 rad/s * 31.25 mm = 44.4 m/s, the oil at rest (``oil_swirl``
  0: eq. 10's relative speed is the orbital speed, an upper bound);
- A = D l = 6 mm x 6 mm (a cylinder broadside to its path: right); c_d = 1.0 (a
  cylinder's plateau at Re = u D / nu = 3.4e4; a free L/D = 1 cylinder is nearer 0.65,
  but the roller ends run against the ribs and the cage, which suppresses end flow, and
  the leading roller's wake lowers it: no in-bearing roller c_d was found to replace it);
- F = 0.5 c_d rho_e u^2 A = 2.43 N, P = 24 F u = 2592 W, as the source gives.

Against the catalogue models at the same point (global_friction, SKF series "10" given
by hand since "CRB_50x75x16" names no series; W):

====================  =====================  =================  ===============
r/min, oil [degC]      this (fluid / total*)  SKF drag / total   Palmgren M0+M1
====================  =====================  =================  ===============
30000, 80              2824 / 2972            2392 / 3061        1939
30000, 120             2717 / 2782            2385 / 2971        1215
10000, 80              322 / 338              90 / 296           341
====================  =====================  =================  ===============

(* fluid = elements + inner ring + cage churning; total adds the cage land, without EHL
rolling resistance, which that scene does not list.) So at 30000 r/min the fluid drag is
physics, not a slip: SKF's own drag term is 78 % of its total there and the element drag
is 1.05-1.08 x SKF's drag; the totals agree within 7 %. Palmgren's M0 = f0 (nu n)^(2/3)
d_m^3 has no inertial (n^2 moment) drag term and falls with the viscosity as the bearing
warms (1939 -> 1215 W from 80 to 120 degC), while drag does not depend on the viscosity
(eq. 10's c_d is a constant of the drag plateau, see :func:`churning_elements`):
hence the 50-130 % (more in hot transient steps). What does differ is the speed law:
with Parker's X ~ 1/n the element drag power goes as n^2 at a given flow, SKF's drag power
as n^3 (its moment ~ n^2, oil-jet rule recalled, not checked), so at 10000 r/min the
element drag is 3.2 x SKF's drag (288 against 90 W) though the totals are within 15 %.
Neither the Parker constant nor SKF's jet rule could be checked against its original, so
the difference is a model uncertainty, not a defect: ``parker_constant``,
``drag_coefficient`` and ``oil_swirl`` are the levers when measurements exist.

Fixed on that check: with an inner-ring-guided cage the inner-ring churning took the
guide clearance (0.1 mm) as its gap over the whole ring width, booking the guide film
that ``cage_guide`` books again (486 W of the 3264 W above; now 194 W, see
:func:`inner_ring_churning_geometry`).
"""

from __future__ import annotations

import math
import warnings
from typing import Any, NamedTuple

import numpy as np

from ..errors import InputError, ValidityWarning, check_positive
from . import HEAT_SOURCES, ForcePair, HeatContext, HeatResult

TAYLOR_CRITICAL = 41.0
REYNOLDS_CRITICAL = 2500.0


class ChurningRegime(NamedTuple):
    """Viscous friction coefficient and the flow regime (0 laminar, 1 vortex, 2 turbulent)."""

    mu_v: np.ndarray
    regime: np.ndarray
    reynolds: np.ndarray
    taylor: np.ndarray


def reynolds_taylor(radius: Any, omega: Any, gap: Any, kinematic_viscosity: Any):
    """N_Re = R |omega| c / nu and N_Ta = N_Re sqrt(c / R) (paper 002 below eq. 14).

    radius R [m], omega [rad/s], gap c [m], kinematic viscosity nu [m^2/s].
    """
    r = np.asarray(radius, float)
    c = np.asarray(gap, float)
    re = r * np.abs(np.asarray(omega, float)) * c / np.asarray(kinematic_viscosity, float)
    return re, re * np.sqrt(c / r)


def _mu_v_regime(re: float, ta: float) -> tuple[float, int]:
    """(mu_v, regime) of paper 002 eqs. 12-14 at one (N_Re, N_Ta): laminar 16/N_Re for
    N_Ta <= 41; Taylor vortices 1.3 mu_l (N_Ta/41)^0.539474 for N_Re <= 2500; turbulent
    3.0 mu_l (N_Re/2500)^0.85596 above. N_Re = 0 (no rotation) gives mu_v = 0."""
    mu_l = 16.0 / re if re > 0.0 else 0.0
    if ta <= TAYLOR_CRITICAL:
        return mu_l, 0
    if re <= REYNOLDS_CRITICAL:
        return 1.3 * mu_l * (ta / TAYLOR_CRITICAL) ** 0.539474, 1
    return 3.0 * mu_l * (re / REYNOLDS_CRITICAL) ** 0.85596, 2


_MU_V_REGIME = np.frompyfunc(_mu_v_regime, 2, 2)


def viscous_friction_coefficient(radius: Any, omega: Any, gap: Any,
                                 kinematic_viscosity: Any) -> ChurningRegime:
    """Viscous friction coefficient mu_v [-], paper 002 eqs. 12-14 (see module docstring).

    Scalar inputs give scalar fields (the skidding solver's cage and inner-ring torques call
    this once per cage speed: plain float arithmetic, ~1 us); arrays broadcast.
    Validity: N_Re > 0 (zero speed gives mu_v = 0 with zero power anyway).
    """
    args = (radius, omega, gap, kinematic_viscosity)
    if all(isinstance(a, float | int) for a in args):
        re = radius * abs(omega) * gap / kinematic_viscosity
        ta = re * math.sqrt(gap / radius)
        mu, regime = _mu_v_regime(re, ta)
        return ChurningRegime(np.float64(mu), np.int64(regime), np.float64(re), np.float64(ta))
    re, ta = reynolds_taylor(*args)
    mu, regime = _MU_V_REGIME(re, ta)
    return ChurningRegime(np.asarray(mu, dtype=float), np.asarray(regime, dtype=np.int64),
                          re, ta)


def cage_churning_power(density, mu_v, omega, width, diameter):
    """Paper 002 eq. 15: Q = pi rho mu_v |omega|^3 B_c D_c^4 / 64 [W].

    density [kg/m^3], mu_v [-], omega cage speed [rad/s], width B_c [m], diameter D_c [m].
    """
    return math.pi * density * mu_v * np.abs(omega) ** 3 * width * diameter ** 4 / 64.0


def inner_ring_churning_power(density, mu_v, omega, arc_length, shoulder_length,
                              shoulder_diameter):
    """Paper 002 eq. 17: Q = pi rho mu_v |omega_i|^3 (B_arc + 2 B_Li) D_Li^4 / 64 [W]."""
    return (math.pi * density * mu_v * np.abs(omega) ** 3
            * (arc_length + 2.0 * shoulder_length) * shoulder_diameter ** 4 / 64.0)


def ball_churning_power_paper002(drag_coefficient, density, mu_v, omega, pitch_diameter,
                                 ball_diameter, n_balls=1):
    """Paper 002 eq. 16 in consistent SI: c_d pi rho mu_v |omega|^3 D_m^3 D_b^2 N_b / 256 [W].

    The printed eq. 16 divides by g (weight-density form) and has D_b to the first power;
    both are fixed here (module docstring). omega is the orbital (revolution) speed.
    """
    return (drag_coefficient * math.pi * density * mu_v * np.abs(omega) ** 3
            * pitch_diameter ** 3 * ball_diameter ** 2 * n_balls / 256.0)


def drag_force(drag_coefficient, density, frontal_area, speed):
    """Paper 002 eq. 10: F = (1/2) c_d rho u^2 A [N] (magnitude; opposes the motion)."""
    return 0.5 * drag_coefficient * density * np.asarray(speed, float) ** 2 * frontal_area


def parker_oil_fraction(flow_rate: float, shaft_speed: float, pitch_diameter: float,
                        constant: float = 1.46e7) -> float:
    """Oil volume fraction X [-] in the cavity of a jet-lubricated bearing (Parker 1984).

    X[%] = K Q^0.37 / (n d_m^1.7), Q [cm^3/min], n [r/min], d_m [mm]; returned as a fraction,
    capped at 1. Inputs in SI: flow_rate [m^3/s], shaft_speed [rad/s], pitch_diameter [m].
    K = 1.46e7 is recalled (primer [R]), not verified in this build.
    """
    check_positive("supply.flow_rate", flow_rate, allow_zero=True)
    check_positive("parker.shaft_speed", abs(shaft_speed), allow_zero=True)
    if flow_rate == 0.0:
        return 0.0
    n = abs(shaft_speed) * 60.0 / (2.0 * math.pi)
    if n == 0.0:
        return 1.0
    q = flow_rate * 6.0e7  # m^3/s -> cm^3/min
    x = constant * q ** 0.37 / (n * (pitch_diameter * 1e3) ** 1.7) / 100.0
    return float(min(x, 1.0))


def oil_bath_fraction(level: float, outer_raceway_radius: float, radius: Any) -> np.ndarray:
    """Time-averaged immersed fraction of a point orbiting at ``radius`` in an oil bath [-].

    acos(clip((R_o - H) / r, -1, 1)) / pi, H = static level above the lowest point of the
    outer raceway (radius R_o). Geometric model (derived here), no splash or swirl.
    """
    r = np.asarray(radius, float)
    return np.arccos(np.clip((outer_raceway_radius - level) / r, -1.0, 1.0)) / math.pi


def supply_oil_fraction(supply: Any, bearing: Any, radius: Any, shaft_speed: float,
                        parker_constant: float = 1.46e7) -> np.ndarray:
    """Oil volume fraction X [-] at ``radius`` [m] by the supply method (module docstring):
    the bath level model for ``oil_bath``, 0 for ``grease`` (not modelled), else Parker's
    correlation at the relative ring speed ``shaft_speed`` [rad/s]. The rule of
    :func:`oil_fraction` without its options and warning; the roller skidding solver's drag
    (:mod:`thermobearing.skidding.roller_drag`) takes the same numbers."""
    if supply.method == "oil_bath":
        return oil_bath_fraction(supply.level, 0.5 * bearing.outer_raceway_diameter, radius)
    if supply.method == "grease":
        return np.zeros(np.shape(radius))
    x = parker_oil_fraction(supply.flow_rate, shaft_speed, bearing.pitch_diameter,
                            float(parker_constant))
    return np.full(np.shape(radius), x)


def oil_fraction(ctx: HeatContext, radius: Any, source: str) -> np.ndarray:
    """Oil volume fraction X for ``source`` at ``radius`` by the supply method (see module)."""
    override = ctx.option(source, "oil_fraction", None)
    if override is not None:
        check_positive(f"options[{source}].oil_fraction", override, allow_zero=True)
        if override > 1:
            raise InputError(f"options[{source}].oil_fraction", override, "a fraction in [0, 1]")
        return np.full(np.shape(radius), float(override))
    if ctx.supply.method == "grease":
        _warn_grease(source)
    speed = ctx.operating.inner_speed - ctx.operating.outer_speed
    k = float(ctx.option(source, "parker_constant", 1.46e7))
    return supply_oil_fraction(ctx.supply, ctx.bearing, radius, speed, k)


def _warn_grease(source: str) -> None:
    warnings.warn(f"{source}: churning of grease is not modelled (oil fraction 0)",
                  ValidityWarning, stacklevel=4)


def cage_neighbour_diameters(bearing: Any) -> tuple[float, float]:
    """(D_in, D_out) [m]: the ring surfaces radially next to the cage body, the bore of the
    cage facing D_in and its outside diameter facing D_out.

    The guiding ring's neighbour is its guide land (``cage.guide_land_diameter``), on which
    the cage is centred; the other ring's is its land (rib or shoulder) or, where the cage
    reaches past that land, the raceway beyond it (the cavity between the ribs): of the
    ring's land and raceway diameters the nearest one not inside the cage body. A side
    with no ring surface outside the cage body (a cage drawn through the raceway) takes
    the cage's own diameter there (no gap on that side)."""
    cage = bearing.cage
    c_in, c_out = float(cage.inner_diameter), float(cage.outer_diameter)
    land_in, land_out = _land_diameters(bearing)
    race_in = float(bearing.inner_raceway_diameter)
    race_out = float(bearing.outer_raceway_diameter)
    guidance = getattr(cage, "guidance", None)
    guide = getattr(cage, "guide_land_diameter", None)
    if guidance == "inner_ring" and guide is not None:
        d_in = float(guide)
    else:
        d_in = max((d for d in (land_in, race_in) if d <= c_in), default=c_in)
    if guidance == "outer_ring" and guide is not None:
        d_out = float(guide)
    else:
        d_out = min((d for d in (land_out, race_out) if d >= c_out), default=c_out)
    return d_in, d_out


def cage_churning_geometry(bearing: Any) -> tuple[float, float]:
    """(D_c, c) [m] of the cage churning (paper 002 eq. 15): the cage mean diameter and the
    default gap, the mean radial gap between the cage body and its neighbours
    (:func:`cage_neighbour_diameters`), c = ((D_out - D_o,c) + (D_i,c - D_in)) / 4, at
    least 0.1 mm (module docstring). The roller skidding solver's drag
    (:mod:`thermobearing.skidding.roller_drag`) and the ball solver's
    (:mod:`thermobearing.skidding.ball_models`) take the same numbers.

    The neighbours, not the two lands: the body of a cage may face other surfaces than
    its guide lands (D1842926: cage 150/161.83 mm guided on the 162.23 mm bore of the
    outer ribs; gaps 0.2 mm (guide) and 3.515 mm (bore to inner raceway, 142.97 mm), mean
    1.8575 mm)."""
    cage = bearing.cage
    d_c = 0.5 * (cage.inner_diameter + cage.outer_diameter)
    d_in, d_out = cage_neighbour_diameters(bearing)
    gap = 0.25 * ((d_out - d_in) - (cage.outer_diameter - cage.inner_diameter))
    return d_c, max(gap, 1e-4)


def inner_ring_churning_geometry(bearing: Any) -> tuple[float, float, float, float]:
    """(D_Li, B_arc, B_Li, c) [m] of the inner-ring churning (paper 002 eq. 17) by default:
    the inner land diameter (raceway diameter for roller bearings), the wetted raceway arc
    D (element diameter), the shoulder length (width - D)/2 and the gap between the inner
    land and the cage bore, at least 0.1 mm.

    A cage guided on the inner ring runs on the inner land: the gap between that land and
    the cage bore is the guide film, whose shear the ``cage_guide`` source books (paper 002
    eq. 5 over the land width, full oil). Eq. 17 there would book the same film a second
    time (in its laminar branch eq. 17 is twice Petroff's torque of that annulus), over the
    whole ring width. So for an inner-ring-guided cage the shoulder length leaves out the
    land width (half on each side) and the gap is the radial height of the cavity between
    the inner and outer lands, (D_outer land - D_Li)/2, the space the rest of the ring
    surface churns (an estimate; paper 002's bearing is outer-ring guided)."""
    d_in, d_out = _land_diameters(bearing)
    d_elem = bearing.element_diameter
    shoulder = max(0.5 * (bearing.width - d_elem), 0.0)
    cage = bearing.cage
    if getattr(cage, "guidance", None) == "inner_ring":
        land = cage.land_width if cage.land_width is not None else cage.width
        shoulder = max(shoulder - 0.5 * land, 0.0)
        return d_in, float(d_elem), shoulder, max(0.5 * (d_out - d_in), 1e-4)
    gap = max(0.5 * (cage.inner_diameter - d_in), 1e-4)
    return d_in, float(d_elem), shoulder, gap


def element_frontal_area(bearing: Any) -> float:
    """Frontal area A of one rolling element in its orbital motion [m^2] (paper 002 eq. 10):
    pi D^2 / 4 for a ball, D l for a roller (l the roller length)."""
    d_elem = bearing.element_diameter
    if hasattr(bearing, "ball_diameter"):
        return 0.25 * math.pi * d_elem ** 2
    return d_elem * bearing.roller_length


#: the options of each churning source that only say where its heat goes; any other option
#: asks the source to evaluate its own model instead of the drag a skidding solver balanced
BOOKING_OPTIONS = ("role",)

#: source -> the options of its drag model that the roller skidding solver takes as well
#: (a scene's ``[models] heat_source_options`` hands them to it,
#: :meth:`thermobearing.simulation.Simulation`): the solver balances the same drag
SOLVER_DRAG_OPTIONS: dict[str, tuple[str, ...]] = {
    "churning_elements": ("drag_coefficient", "parker_constant"),
    "churning_cage": ("parker_constant",),
    "churning_inner_ring": ("parker_constant",),
}


def solver_drag(ctx: HeatContext, source: str, key: str,
                booking: tuple[str, ...] = BOOKING_OPTIONS, churning: bool = True) -> Any:
    """The drag the roller skidding solver balanced for ``source`` (kinematic state extras
    ``solver_drag[key]``, :mod:`thermobearing.skidding.roller_drag`), or None: a state
    without it (race control, balls, the solver without an oil supply), or options of the
    source that ask for its own model on purpose (any but ``booking``, default
    :data:`BOOKING_OPTIONS`; the heat then departs from the solver's force balance, which a
    ValidityWarning says).
    ``churning``: warn, as :func:`oil_fraction` does, that a grease fill churns nothing."""
    drag = ctx.kinematics.extras.get("solver_drag")
    if not drag or key not in drag:
        return None
    given = ctx.options.get(source) or {}
    # the drag parameters a scene hands the solver too (Simulation: models.
    # heat_source_options routed to the roller solver): the same model, not an own one
    shared = {k for k in SOLVER_DRAG_OPTIONS.get(source, ())
              if k in given and k in drag and float(given[k]) == float(drag[k])}
    own = sorted(k for k in given if k not in booking and k not in shared)
    if own:
        warnings.warn(
            f"{source}: options {', '.join(own)} ask for the source's own model: its heat is "
            "not the drag the roller skidding solver balanced, so the booked heat and the "
            "solver's shaft power differ by the difference", ValidityWarning, stacklevel=3)
        return None
    if churning and ctx.supply.method == "grease":
        _warn_grease(source)
    return drag


def _carried_moment(source: str, role: str, component: str, force: str, pair: str,
                    moment: float, omega: float, fraction: float) -> HeatResult:
    """The heat of a churning moment M [N m] the roller skidding solver balanced on a body
    turning at omega [rad/s] (extras ``solver_drag``): |M omega| [W] to ``role``."""
    q = abs(moment * omega)
    return HeatResult(
        source=source, power_by_role={role: q}, components={component: q},
        loss_class={component: "load_independent"}, forces={force: moment},
        force_pairs=(ForcePair(pair, moment, omega),),
        details={"oil_fraction": fraction, "regime": "solver drag (roller skidding balance)"})


def _oil(ctx: HeatContext):
    t = ctx.temperature("oil")
    rho = float(ctx.lubricant.density(t))
    nu = float(ctx.lubricant.dynamic_viscosity(t)) / rho
    return rho, nu


def _land_diameters(b):
    inner = getattr(b, "inner_land_diameter", None)
    outer = getattr(b, "outer_land_diameter", None)
    if inner is None:  # bearings without lands: raceway diameters bound the cavity
        inner = b.inner_raceway_diameter
    if outer is None:
        outer = b.outer_raceway_diameter
    return float(inner), float(outer)


def _role(ctx: HeatContext, source: str, default: str) -> str:
    return str(ctx.option(source, "role", default))


#: Smallest radial gap [m] the churning options ``gap`` take (:func:`_gap`). Eqs. 12-14
#: describe the oil annulus between two smooth cylinders (Couette flow, Taylor vortices);
#: at 1 um the gap is of the order of the roughness of turned or ground cage and land
#: surfaces (Ra 0.2-1.6 um, recalled) and of an EHL film, where the surfaces touch through
#: a film and the annulus model no longer applies; below it the laminar mu_v = 16 / N_Re
#: makes the power grow as 1 / c without bound (1e-300 mm gave an infinite cage power,
#: 1e-30 mm a transient the stepper could not converge, residual 1.2e15).
MIN_GAP = 1.0e-6


def _gap(ctx: HeatContext, source: str, default: float) -> float:
    """The radial gap c [m] of ``source``: option ``gap`` (>= :data:`MIN_GAP`, else an
    InputError naming it and why) or ``default``."""
    gap = float(ctx.option(source, "gap", default))
    if gap < MIN_GAP:
        raise InputError(f"options[{source}].gap", f"{gap:g} m",
                         f"a gap >= {MIN_GAP * 1e6:g} um: a thinner gap is of the order of the "
                         "roughness of turned or ground surfaces and of a lubricant film, not "
                         "the oil annulus of paper 002 eqs. 12-14, whose power grows as 1/gap")
    return gap


def _check_length(source: str, key: str, value: float, bound: float, why: str) -> float:
    """``value`` [m] of option ``key`` of ``source`` within [0, ``bound``] [m], else an
    InputError naming the option, the bound and ``why`` (the bearing dimension it comes
    from)."""
    if not 0.0 <= value <= bound:
        raise InputError(f"options[{source}].{key}", f"{value:g} m",
                         f"a length in [0, {bound * 1e3:.6g} mm]: {why}")
    return value


def _finite_power(ctx: HeatContext, source: str, power: float) -> float:
    """``power`` [W] if finite; else an InputError naming the options of ``source`` the
    scene gave (a power that overflows comes from them; without options the heat result
    refuses it naming the source)."""
    given = dict(ctx.options.get(source) or {})
    if not math.isfinite(power) and given:
        shown = ", ".join(f"{k} = {v!r}" for k, v in sorted(given.items()))
        raise InputError(f"options[{source}]", shown,
                         f"options that give a finite churning power (they give {power} W)")
    return power


@HEAT_SOURCES.register(
    "churning_cage",
    references=["gao2022_overskidding", "parker1984_tp2275", "harris_kotzalas2007"],
    parameters={"oil_fraction": "-", "gap": "m", "parker_constant": "-"},
    limits={"oil_fraction": "[0, 1]", "gap": "[1e-06, inf)", "parker_constant": "(0, inf)"},
    validity="paper 002 regimes; oil fraction from Parker (jets) or the bath level",
)
def churning_cage(ctx: HeatContext) -> HeatResult:
    """Cage churning in the oil-air mixture, paper 002 eq. 15 (heat to the oil node).

    A roller skidding state carries the churning moment its cage equation balanced
    (extras ``solver_drag``): the source books its power |M omega_c| (same eq. 15, oil
    fraction and viscosity as the solver) unless options other than ``role`` are given."""
    name = "churning_cage"
    omega = ctx.kinematics.cage_speed
    role = _role(ctx, name, "oil")
    carried = solver_drag(ctx, name, "cage_churning_moment")
    if carried is not None:
        return _carried_moment(name, role, "cage churning", "cage_drag_moment", "oil on cage",
                               float(carried["cage_churning_moment"]), omega,
                               float(carried["cage_oil_fraction"]))
    b = ctx.bearing
    cage = b.cage
    rho, nu = _oil(ctx)
    d_c, default_gap = cage_churning_geometry(b)
    gap = _gap(ctx, name, default_gap)
    x = float(oil_fraction(ctx, 0.5 * d_c, name))
    reg = viscous_friction_coefficient(0.5 * d_c, omega, gap, nu)
    q = _finite_power(ctx, name, float(cage_churning_power(x * rho, reg.mu_v, omega,
                                                          cage.width, d_c)))
    moment = -q / omega if omega != 0 else 0.0  # on the cage, about the bearing axis
    return HeatResult(
        source=name, power_by_role={role: q}, components={"cage churning": q},
        loss_class={"cage churning": "load_independent"},
        forces={"cage_drag_moment": moment},
        force_pairs=(ForcePair("oil on cage", moment, omega),),
        details={"oil_fraction": x, "reynolds": float(reg.reynolds),
                 "taylor": float(reg.taylor), "regime": int(reg.regime),
                 "mu_v": float(reg.mu_v)})


@HEAT_SOURCES.register(
    "churning_inner_ring",
    references=["gao2022_overskidding", "parker1984_tp2275"],
    parameters={"oil_fraction": "-", "gap": "m", "raceway_arc_length": "m",
                "shoulder_length": "m", "parker_constant": "-"},
    limits={"oil_fraction": "[0, 1]", "gap": "[1e-06, inf)", "raceway_arc_length": "[0, inf)",
            "shoulder_length": "[0, inf)", "parker_constant": "(0, inf)"},
    validity="paper 002 regimes; oil fraction from Parker (jets) or the bath level",
)
def churning_inner_ring(ctx: HeatContext) -> HeatResult:
    """Inner-ring churning, paper 002 eq. 17; heat to the oil (scene default) or the inner ring.

    Where the heat is booked: option ``role``, default the inner ring (paper 002 eq. 24),
    as a scene with ``[models] churning_heat_to = "paper002"`` books it; a scene's default
    ``churning_heat_to = "oil"`` sets ``role = "oil"`` (the oil stream carries the viscous
    dissipation away; :meth:`thermobearing.simulation.Simulation._heat_options`).

    B_arc defaults to the groove arc wetted across the ball, D (raceway arc length over the
    ball diameter, an estimate), B_Li to the shoulder length (width - D)/2 on each side.
    A roller skidding state carries the moment the solver's shaft torque contains (extras
    ``solver_drag``): booked as |M omega_i| unless options other than ``role`` are given.
    """
    name = "churning_inner_ring"
    omega = ctx.operating.inner_speed
    role = _role(ctx, name, "inner_ring")
    carried = solver_drag(ctx, name, "inner_ring_moment")
    if carried is not None:  # the roller skidding solver's shaft torque contains it
        return _carried_moment(name, role, "inner ring churning", "inner_ring_drag_moment",
                               "oil on inner ring", float(carried["inner_ring_moment"]),
                               omega, float(carried["inner_ring_oil_fraction"]))
    b = ctx.bearing
    rho, nu = _oil(ctx)
    d_in, arc0, shoulder0, gap0 = inner_ring_churning_geometry(b)
    # B_arc: a groove arc whose chord is at most the ring width w and which is no deeper
    # than a semicircle is at most pi w / 2 long; the two shoulders lie beside it within w
    arc = _check_length(name, "raceway_arc_length",
                        float(ctx.option(name, "raceway_arc_length", arc0)),
                        0.5 * math.pi * b.width,
                        f"at most pi w / 2, the semicircle on the ring width w = "
                        f"{b.width * 1e3:.6g} mm (a groove arc spans at most the width)")
    shoulder = _check_length(name, "shoulder_length",
                             float(ctx.option(name, "shoulder_length", shoulder0)),
                             0.5 * b.width,
                             f"at most w / 2 of the ring width w = {b.width * 1e3:.6g} mm "
                             "(one of the two shoulders beside the raceway)")
    gap = _gap(ctx, name, gap0)
    x = float(oil_fraction(ctx, 0.5 * d_in, name))
    reg = viscous_friction_coefficient(0.5 * d_in, omega, gap, nu)
    q = _finite_power(ctx, name, float(inner_ring_churning_power(x * rho, reg.mu_v, omega,
                                                                 arc, shoulder, d_in)))
    moment = -q / omega if omega != 0 else 0.0
    return HeatResult(
        source=name, power_by_role={role: q}, components={"inner ring churning": q},
        loss_class={"inner ring churning": "load_independent"},
        forces={"inner_ring_drag_moment": moment},
        force_pairs=(ForcePair("oil on inner ring", moment, omega),),
        details={"oil_fraction": x, "reynolds": float(reg.reynolds),
                 "taylor": float(reg.taylor), "regime": int(reg.regime),
                 "mu_v": float(reg.mu_v)})


@HEAT_SOURCES.register(
    "churning_elements",
    references=["gao2022_overskidding", "parker1984_tp2275", "harris_kotzalas2007"],
    parameters={"drag_coefficient": "-", "oil_fraction": "-", "gap": "m", "oil_swirl": "-",
                "parker_constant": "-"},
    limits={"drag_coefficient": "(0, 10)", "oil_fraction": "[0, 1]", "gap": "[1e-06, inf)",
            "oil_swirl": "[0, 1]", "parker_constant": "(0, inf)"},
    validity="sphere/cylinder drag plateau (1e3 < Re < 2e5 for c_d = 0.45)",
)
def churning_elements(ctx: HeatContext) -> HeatResult:
    """Element drag/churning, paper 002 eqs. 10, 16; heat to the oil (scene default) or elements.

    Options: ``form`` "paper002" (eq. 16 SI, default for balls) or "harris" (eq. 10 per
    element, default for rollers: eq. 16 is a ball formula);
    ``drag_coefficient`` c_d (0.45: sphere drag plateau, Harris & Kotzalas; rollers 1.0,
    cylinder plateau); ``oil_swirl`` s: the mixture orbits at s * cage speed (default 0).
    Per-element drag force F_j (for the solver) with heat sum F_j |u_j|, u_j = (omega_m,j -
    s omega_c) D_m / 2. Heat to option ``role``, default the elements (paper 002 eq. 22, a
    scene's ``churning_heat_to = "paper002"``); a scene's default ``churning_heat_to =
    "oil"`` books it on the oil.

    A roller skidding state carries the drag force its roller and cage equations balanced
    (extras ``solver_drag``, eq. 10 with the solver's c_d, oil fraction and density, no
    swirl): booked as sum F_j |u_j| unless options other than ``role`` are given.

    Why c_d is a constant (eq. 10, ``form="harris"``: every roller bearing): paper 002 gives
    eq. 10 with "the experimentally determined drag coefficient c_d", one number per body,
    and no Reynolds-number law for it; Harris & Kotzalas (as the primer recalls them) read
    c_d off the drag curve of an isolated body against Re = u D / nu, which is flat over its
    plateau (spheres c_d = 0.4-0.5 for 1e3 < Re < 2e5; a cylinder broadside near 1.0; the
    losses primer ../shared/notes, section 2.1). So the cited model's drag does not change
    with the oil grade or the temperature inside the plateau: only the mixture density X
    rho(T) does, by the oil's thermal expansion (NU 214, 5 kN, 1 L/min jet: 396.6 W at 6000
    r/min with ISO VG 32 at 40 degC, 383.7 W at 80 degC, 402.8 W with ISO VG 100 at 40 degC;
    its elements' Re is 1.7e3-2.0e4 there). Outside the plateau (thick oil at low speed: the
    same bearing with ISO VG 100 at 40 degC and 1000 r/min has Re = 290) a free body's c_d
    rises as Re falls; no Re-dependent c_d of a roller inside a bearing is cited (the
    primer's sphere fit of a public code is for balls, its in-bearing correlations are
    recalled, not retrieved), so none is applied: ``drag_coefficient`` is the lever there.
    The ball form (eq. 16) does depend on the viscosity, through the annulus friction
    coefficient mu_v(N_Re, N_Ta) of eqs. 12-14, as the paper writes it.
    """
    name = "churning_elements"
    b = ctx.bearing
    kin = ctx.kinematics
    carried = solver_drag(ctx, name, "element_force")
    if carried is not None:
        return _solver_element_drag(ctx, name, carried)
    rho, nu = _oil(ctx)
    is_ball = hasattr(b, "ball_diameter")
    form = str(ctx.option(name, "form", "paper002" if is_ball else "harris"))
    if form not in ("paper002", "harris"):
        raise InputError(f"options[{name}].form", form, "'paper002' or 'harris'")
    cd = float(ctx.option(name, "drag_coefficient", 0.45 if is_ball else 1.0))
    if not 0 < cd < 10:
        raise InputError(f"options[{name}].drag_coefficient", cd, "a value in (0, 10)")
    d_elem = b.element_diameter
    d_m = b.pitch_diameter
    d_in, d_out = _land_diameters(b)
    gap = _gap(ctx, name, max(0.5 * (d_out - d_in), 1e-4))
    swirl = float(ctx.option(name, "oil_swirl", 0.0))
    rel_omega = kin.orbital_speed - swirl * kin.cage_speed
    u = 0.5 * d_m * rel_omega
    x = oil_fraction(ctx, 0.5 * d_m, name)
    rho_e = x * rho
    area = element_frontal_area(b)
    reg = viscous_friction_coefficient(0.5 * d_m, rel_omega, gap, nu)
    if form == "harris":
        force = drag_force(cd, rho_e, area, u)
    else:
        if not is_ball:
            raise InputError(f"options[{name}].form", form,
                             "'harris' for roller bearings (eq. 16 is a ball formula)")
        # per-ball share of eq. 16 divided by the ball speed: c_d pi rho mu_v w^2 Dm^2 Db^2/128
        force = cd * math.pi * rho_e * reg.mu_v * rel_omega ** 2 * d_m ** 2 * d_elem ** 2 / 128.0
    return _element_result(ctx, name, -force * np.sign(u), u,
                           {"oil_fraction": float(np.mean(x)), "form": form,
                            "mu_v": float(np.mean(reg.mu_v)),
                            "reynolds": float(np.mean(reg.reynolds)),
                            # the element's own Re = |u| D / nu, which sets c_d (the drag
                            # plateau of the validity range); "reynolds" is eq. 16's annulus
                            "element_reynolds": float(np.mean(np.abs(u))) * d_elem / nu})


def _element_result(ctx: HeatContext, name: str, signed: np.ndarray, u: np.ndarray,
                    details: dict) -> HeatResult:
    """Element churning heat of the drag forces F_j [N] (negative: against the orbit) at
    the orbital speeds u_j [m/s]: Q = sum_j |F_j u_j| [W] to the "elements" role."""
    q = _finite_power(ctx, name, float(np.sum(np.abs(signed * u))))
    return HeatResult(
        source=name, power_by_role={_role(ctx, name, "elements"): q},
        components={"element churning": q},
        loss_class={"element churning": "load_independent"},
        forces={"element_drag_force": signed},
        force_pairs=(ForcePair("oil on elements", signed, u),), details=details)


def _solver_element_drag(ctx: HeatContext, name: str, carried: Any) -> HeatResult:
    """Element churning heat of the drag a roller skidding state carries: the force F_j
    along each roller's orbit (negative: against it; paper 002 eq. 10,
    :mod:`thermobearing.skidding.roller_drag`) at the orbital speed u_j = omega_m,j D_m/2,
    Q = sum_j |F_j u_j| [W], the power the solver's roller and cage equations balance."""
    kin = ctx.kinematics
    u = 0.5 * ctx.bearing.pitch_diameter * np.asarray(kin.orbital_speed, float)
    signed = np.broadcast_to(np.asarray(carried["element_force"], float), u.shape).copy()
    return _element_result(ctx, name, signed, u,
                           {"oil_fraction": float(carried["element_oil_fraction"]),
                            "form": "harris",
                            "drag_coefficient": float(carried["drag_coefficient"]),
                            "regime": "solver drag (roller skidding balance)"})
