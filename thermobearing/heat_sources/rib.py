"""Roller end-face / inner-ring rib friction heat (paper 003 eqs. 12-17, 24).

Heat of one end-face contact = friction force (eq. 12) times the relative speed of eq. 24 at
the contact point, from :mod:`thermobearing.rib`. Option ``model`` (default
:data:`DEFAULT_MODEL`):

* ``"coupled"`` (default): every end face's time-mean friction power from the coupled
  all-roller + cage integration of paper 003 eqs. 18-19
  (:mod:`thermobearing.skidding.roller_dynamics_coupled`) at the operating state (relative
  ring speed, radial load, the "elements" temperature, option ``unbalance_mass`` [kg] at
  the right chamfer, default 0): skew contacts *and* the lubricant drag F_G of eq. 14 on
  both faces, at the integrated spins; Z x the roller mean. The run is cached per
  operating state on a temperature grid (option ``temperature_step`` [K], default 5 K,
  linear interpolation between the two nodes, measured error < 1 %:
  :mod:`thermobearing.skidding.roller_dynamics_heat`), so a transient re-runs it only when
  the temperature enters a new 5 K cell (~1.1-1.7 s CPU per node at paper 003's base case).
  Option ``convergence`` (default 0.005): the integration stops when the running means
  of the rib heat and the rib slide speed have converged to it (settled motion without
  unbalance: 1.5-2 orbits instead of the fixed 5 at 5000-20000 r/min, ~2.2-2.8x cheaper,
  rib heat within 0.2 %; a slowly creeping cage, e.g. at 30000 r/min, runs all 5;
  :mod:`thermobearing.skidding.roller_dynamics_heat`, "Where the integration stops");
  0 runs the fixed 2 + 3 orbit window. Option ``table_retries`` (default 3): a run that
  enters the cage runaway first tries that many other trajectories on the table path,
  then the evaluate path (0: the evaluate path at once, as before; with 0.06 g x 3.6
  cheaper in bm_rib_friction, re-run nodes within the chaotic node scatter).
  Option ``settle`` (default :data:`~thermobearing.skidding.roller_dynamics_convergence.
  DEFAULT_SETTLE`): without unbalance the warm-up runs whole orbits until the orbit-mean
  cage speed has settled to this (orbit-to-orbit change, no turning point, the creep's
  extrapolated remainder; cap 16 orbits; a creeping cage at 1000 N left the fixed window's
  slip 8 % high); 0 keeps the fixed warm-up. Option
  ``warm_start_nodes`` (default 4): without unbalance a temperature node starts from the
  end state of the nearest node of its operating state already run, at most that many
  grid steps away (0: every node from the quasi-static state): 2 orbits instead of 3 at
  5000-20000 r/min (heat within 0.02 %), 4 instead of 8 at 30000 r/min in hot oil (400 K,
  where the weakly damped cage creeps; cold and warm both within the settling test's
  residue of a long run's heat, 0.1-0.3 % at 400-440 K, on opposite sides)
  (:mod:`thermobearing.skidding.roller_dynamics_heat`, "Warm start").
  Scatter: with an unbalance the node values scatter by about +-4 % (the chaotic impacting
  motion; validation case ``paper003_pv_slip_trends``, section "Rib heat source on the
  coupled model").
  Where the coupled motion stops at a temperature node and its neighbours, or would
  integrate more than :data:`MAX_COUPLED_TIME` of motion (slow cages: the cost grows as
  1/speed), the reduced model below books the heat and a ValidityWarning says so. A mineral
  oil's stiff roller spin (ISO VG46: h |lambda| ~ 60 for explicit steps) stopped the
  coupled motion until 2026-11-23; it is integrated by ETDRK4 since
  (:mod:`~thermobearing.skidding.roller_dynamics_coupled`, "Stiff spin") and runs coupled.
* ``"reduced"``: the drag F_G of both faces at the kinematic state's (quasi-static) spins;
  with ``unbalance_mass`` > 0 the one-roller reduced dynamics
  (:func:`thermobearing.skidding.roller_dynamics.simulate_reduced`, on the quasi-static
  coupled spins) instead, whose heat holds the drag. Its time-mean PV is ~29 % and its rib
  heat ~50 % below the coupled model's at paper 003's base case (0.11 g): issue 9 allows a
  reduced model only within 10 % of the full one (validation case
  ``paper003_pv_slip_trends``, reason 10).

**Thrust** (both models): an axial load F_a of the operating point is carried by the rib
contacts, each roller's end face taking Q = F_a / (Z cos theta_f) (uniform share), at the
rib slide speed of the model's spins (coupled: the time- and roller-mean |v_i - v_r| of
the integration; reduced: the kinematic state's spins). The thrust share is superposed on
the dynamics (it does not act back on the skew). A bearing with ribs on one ring only
(paper 003's: inner ring, ``ribbed_ring = "inner"``) has no path for an axial load: a
ValidityWarning says so and the share is booked as if an opposite rib carried it. In a
``"both"``-ribbed bearing (NJ / NUP) the opposite rib is on the outer ring and each roller
presses it with the same Q: its own loss component ``"roller end face / outer rib"``,
mu Q |v_o| per roller at the kinematic state's spins and cage speed, the contact of paper
003 eqs. 10-11, 24 mirrored onto the outer rib (:mod:`thermobearing.rib_outer`: same rib
angle and crown radius, concave rib cone), its heat split between the rollers and the
"outer_ring" by Blok's partition. Until 2026-11-24 it was not booked: about half of the
thrust heat of such a bearing was missing (the two contacts slide at similar speeds,
D_w/2 - rho from the raceways). The lubricant drag of eq. 14 and the skew contacts stay
the inner ribs' (paper 003's model); the outer rib's drag is not modelled.

Energy: the dynamics' heat is the work rate of the rib forces the integrator applies
(force x sliding speed, :mod:`~thermobearing.skidding.roller_dynamics_heat`; per face
|friction force| x |v_i - v_r| + |F_G v_g|, tests/unit/test_rib21_cone_normal.py); the
thrust share is mu Q |v|. Since 2026-11-24 the contact's normal force acts along the rib
cone's normal at the contact point (:mod:`thermobearing.rib`, "Contact normal"), so it does
no work on the rib's rotation: the power the rib forces take from the roller and the inner
ring equals that heat plus the elastic rate Q d delta/dt (which averages out) to round-off
(tests/unit/test_prop20_rib.py; with eq. 1's planar normal 0.5 % of a face's heat at
0.01 rad skew was unbooked). The sum is split between the roller ("elements") and the inner ring
("inner_ring") by Blok's high-Peclet partition [blok1963_flash_temperature]
(:func:`thermobearing.heat_sources.raceway.blok_partition`) with the speeds of the two
surfaces through the contact (rib: (omega_i - omega_c)(d_i/2 + H_contact), end face: rib
speed minus the model's mean slide) and the contact half-width sqrt(a b); option
``element_share`` overrides it. Units: SI.

Details (``HeatResult.details``, the numbers the heat was computed from; a run writes them
to its ``rib`` table, :func:`thermobearing.simulation_tables.rib_columns`): ``model``
(the model that booked the heat: ``"reduced"`` where the coupled one handed over, above),
``dynamics`` (``"coupled"``, ``"reduced"`` or ``"none"``: no roller dynamics ran, the heat
is the thrust share and the drag at the kinematic state's spins), ``friction_coefficient``,
``thrust_normal_force`` Q [N] per roller, ``thrust_slide_speed`` (the roller-mean |v| the
thrust share slides at) [m/s], ``thrust_heat`` = mu Q Z x that [W], ``drag_heat`` (without
dynamics: 2 F_G sum |v| [W]; with them the drag is in the face heats), with dynamics
``heat_left`` / ``heat_right`` (all rollers [W]), ``pv_left`` / ``pv_right`` (time- and
roller-mean P |v| [Pa m/s]; right = the unbalance's side), ``slip_speed`` (eq. 25 [m/s]; the
dynamics' time mean, without them the kinematic state's, :func:`inner_slip_speed`),
``rib_slide_speed``, ``dynamics_orbits``; ``total_heat`` [W] = ``thrust_heat`` +
``drag_heat`` + ``heat_left`` + ``heat_right`` (those present), the component's power;
``temperature`` [K] (the "elements" temperature the models ran at), ``n_rollers``,
``element_share``; with an outer rib (``"both"``, thrust > 0) ``outer_thrust_heat`` [W]
(all rollers), ``outer_thrust_slide_speed`` [m/s] (roller-mean |v_o|) and
``outer_element_share``, and ``total_heat`` holds it. The thrust share's pressure and
contact area are Hertz's at Q (:func:`thrust_contact`, computed when the table is written,
not in the heat evaluation).
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

from ..errors import ConvergenceError, InputError, ValidityWarning, check_positive, check_range
from ..hertz import point_contact
from ..rib import DEFAULT_RIB_FRICTION, lubricant_drag, rib_geometry, rib_sliding_speed
from ..rib_outer import outer_contact_radius, outer_rib_sliding_speed, outer_thrust_contact
from ..skidding.roller_dynamics_heat import (
    DEFAULT_CONVERGENCE,
    DEFAULT_ORBITS,
    DEFAULT_SETTLE,
    DEFAULT_TABLE_RETRIES,
    DEFAULT_TEMPERATURE_STEP,
    DEFAULT_WARM_START_NODES,
    DEFAULT_WARMUP_ORBITS,
    MODELS,
    rib_dynamics_heat,
)
from . import HEAT_SOURCES, ForcePair, HeatContext, HeatResult
from .raceway import blok_partition

#: default model of the rib dynamics (module notes: fidelity vs cost, measured)
DEFAULT_MODEL = "coupled"
#: longest motion [s] the coupled model integrates per temperature node (its fixed cage
#: orbits at this cage speed); beyond it the reduced model books the heat (~20-30 s CPU at
#: the ~1.5 us steps the rib contact sets; paper 003's base case needs 0.027 s). The ETDRK4
#: integrator (2026-11-23) lifts the spin's stability limit, not this step: at slow cages the
#: step is 1/omega_rib (~1.5 us) either way (ISO VG46, 40 degC, 5000 r/min: 0.106 s of
#: motion in 2.6 s CPU, ~25 s CPU per simulated second), so the limit is unchanged
MAX_COUPLED_TIME = 0.5


#: display unit (scale from SI, name) of the rib geometry's fields in user messages
RIB_FIELD_UNITS = {"rib_height": (1e3, "mm"), "axial_clearance": (1e3, "mm"),
                   "crown_radius": (1e3, "mm"), "roller_diameter": (1e3, "mm"),
                   "roller_length": (1e3, "mm"), "chamfer": (1e3, "mm"),
                   "rib_angle": (180.0 / math.pi, "deg")}
#: the bearing key of each :class:`thermobearing.rib.RibGeometry` field a user sets
RIB_BEARING_KEYS = {"crown_radius": "end_face_crown_radius", "rib_angle": "rib_angle",
                    "rib_height": "rib_height", "axial_clearance": "axial_clearance"}


def rib_input_text(exc: InputError) -> str:
    """The message of an :class:`InputError` of the rib geometry
    (:class:`thermobearing.rib.RibGeometry`, fields ``rib.<name>``) with its value in the
    unit a bearing file writes it in and the field named by its bearing key:
    ``rib_height = 3 mm is not allowed: a rib higher than ...`` instead of
    ``rib.rib_height = 0.003 is not allowed: ...`` (a value in metres beside a limit in mm).
    Other errors: their message unchanged."""
    field = str(getattr(exc, "field", ""))
    name = field[4:] if field.startswith("rib.") else None
    if name not in RIB_FIELD_UNITS or not isinstance(exc.value, (int, float)):
        return str(exc)
    scale, unit = RIB_FIELD_UNITS[name]
    return (f"{RIB_BEARING_KEYS.get(name, name)} = {float(exc.value) * scale:.4g} {unit} is "
            f"not allowed: {exc.allowed}")


def check_unbalance_option(unbalance: float, bearing: object, field: str) -> None:
    """InputError naming ``field`` unless 0 <= ``unbalance`` [kg] < the roller mass of
    ``bearing`` (paper 003's unbalance mass sits on one roller's chamfer; one as heavy as
    the roller is no roller). Values in g, as the option is written."""
    mass = getattr(bearing, "roller_mass", None)
    if not unbalance >= 0.0:  # negative or NaN, shown in g as written (was kg)
        raise InputError(field, f"{unbalance * 1e3:.4g} g", "an unbalance_mass >= 0 g")
    if mass is not None and unbalance >= float(mass):
        raise InputError(field, f"{unbalance * 1e3:.4g} g",
                         f"an unbalance_mass from 0 g up to below the roller mass "
                         f"{float(mass) * 1e3:.4g} g of {getattr(bearing, 'name', 'the bearing')}")


def inner_slip_speed(geom: object, inner_speed: float, cage_speed: float,
                     roller_spin: object) -> float:
    """Roller-mean slip speed at the inner raceway, paper 003 eq. 25 (as read in
    :mod:`thermobearing.skidding.roller_dynamics_response`):
    mean |(omega_i - omega_c) d_i/2 - omega_r D_w/2| [m/s] over the rollers.

    geom : :class:`thermobearing.rib.RibGeometry` (``inner_raceway_diameter`` d_i,
    ``roller_diameter`` D_w [m]).  inner_speed, cage_speed : omega_i, omega_c [rad/s].
    roller_spin : omega_r per roller [rad/s] (array or scalar)."""
    u_i = (float(inner_speed) - float(cage_speed)) * 0.5 * float(geom.inner_raceway_diameter)
    spin = np.asarray(roller_spin, float)
    return float(np.mean(np.abs(u_i - spin * 0.5 * float(geom.roller_diameter))))


def thrust_contact(geom: object, normal_force: float) -> tuple[float, float]:
    """Hertz contact of one roller's thrust share on the rib: (maximum pressure P [Pa],
    contact area pi a b [m^2]) of the normal force Q [N] at the unskewed contact point's
    radii (:meth:`thermobearing.rib.RibGeometry.curvature`), Brewe-Hamrock ellipse as the
    dynamics' PV (paper 003 eqs. 22-23). Q = (2/3) P pi a b, so the thrust share's heat
    mu Q |v| equals mu (2/3) (pi a b) P |v| (the table's PV times 2/3 of the area).
    Q = 0 gives (0, 0)."""
    q = float(normal_force)
    check_positive("normal_force", q, allow_zero=True)
    if q == 0.0:
        return 0.0, 0.0
    rx, ry = geom.curvature()
    pc = point_contact(q, rx, ry, geom.effective_modulus, method="brewe_hamrock_1977")
    return float(pc.max_pressure), math.pi * float(pc.a) * float(pc.b)


@HEAT_SOURCES.register(
    "rib_friction",
    references=["zhang2021_abnormal_wear", "blok1963_flash_temperature",
                "harris_kotzalas2007"],
    parameters={"friction_coefficient": "-", "oil_fraction": "-", "unbalance_mass": "kg",
                "element_share": "-", "temperature_step": "delta_degC", "model": "-",
                "convergence": "-", "table_retries": "-", "settle": "-",
                "warm_start_nodes": "-"},
    limits={"friction_coefficient": "[0, 1]", "oil_fraction": "[0, 1]",
            "unbalance_mass": "[0, inf)", "element_share": "[0, 1]",
            "temperature_step": "(0, inf)", "convergence": "[0, 0.1]",
            "table_retries": "[0, 10]", "settle": "[0, 0.1]", "warm_start_nodes": "[0, 10]"},
    validity="cylindrical roller bearings with ribs (end_face_crown_radius, rib_height set)",
)
def rib_friction(ctx: HeatContext) -> HeatResult:
    """Roller end-face / rib friction heat (paper 003 eqs. 12-17, 24)."""
    name = "rib_friction"
    b = ctx.bearing
    if getattr(b, "kind", None) != "cylindrical":
        raise InputError("bearing", getattr(b, "name", b),
                         "a cylindrical roller bearing (the rib_friction source)")
    if getattr(b, "ribbed_ring", "inner") == "outer":
        raise InputError("bearing.ribbed_ring", b.ribbed_ring,
                         "'inner' or 'both' (the rib_friction source models paper 003's "
                         "inner-ring rib; an outer-ring rib is not modelled)")
    geom = rib_geometry(b)
    mu = float(ctx.option(name, "friction_coefficient", DEFAULT_RIB_FRICTION))
    check_range(f"options[{name}].friction_coefficient", mu, 0.0, 1.0)
    oil_fraction = float(ctx.option(name, "oil_fraction", 0.05))
    check_range(f"options[{name}].oil_fraction", oil_fraction, 0.0, 1.0)
    unbalance = float(ctx.option(name, "unbalance_mass", 0.0))
    check_unbalance_option(unbalance, b, f"options[{name}].unbalance_mass")
    model = ctx.option(name, "model", DEFAULT_MODEL)
    if model not in MODELS:
        raise InputError(f"options[{name}].model", model, MODELS)
    t_step = float(ctx.option(name, "temperature_step", DEFAULT_TEMPERATURE_STEP))
    check_positive(f"options[{name}].temperature_step", t_step)
    conv = float(ctx.option(name, "convergence", DEFAULT_CONVERGENCE))
    check_range(f"options[{name}].convergence", conv, 0.0, 0.1)
    convergence = conv if conv > 0.0 else None     # 0: the fixed window
    retries_opt = ctx.option(name, "table_retries", DEFAULT_TABLE_RETRIES)
    check_range(f"options[{name}].table_retries", float(retries_opt), 0.0, 10.0)
    if float(retries_opt) != int(float(retries_opt)):
        raise InputError(f"options[{name}].table_retries", retries_opt,
                         "a whole number of retries in [0, 10]")
    retries = int(float(retries_opt))
    settle_opt = float(ctx.option(name, "settle",
                                  0.0 if DEFAULT_SETTLE is None else DEFAULT_SETTLE))
    check_range(f"options[{name}].settle", settle_opt, 0.0, 0.1)
    settle = settle_opt if settle_opt > 0.0 else None   # 0: the fixed warm-up
    warm_opt = ctx.option(name, "warm_start_nodes", DEFAULT_WARM_START_NODES)
    check_range(f"options[{name}].warm_start_nodes", float(warm_opt), 0.0, 10.0)
    if float(warm_opt) != int(float(warm_opt)):
        raise InputError(f"options[{name}].warm_start_nodes", warm_opt,
                         "a whole number of temperature nodes in [0, 10]")
    warm_nodes = int(float(warm_opt))
    kin = ctx.kinematics
    op = ctx.operating
    temperature = ctx.temperature("elements")
    wi, wc, wo = float(kin.inner_speed), float(kin.cage_speed), float(kin.outer_speed)
    # the rib heat is the same in the mirror image (rotation reversed): a state turning the
    # other way (inner ring faster backwards than the outer, e.g. the outer ring driven
    # forward over a fixed inner ring) is mirrored into the forward sense, in which the
    # roller spin magnitude |element_spin| has the sign of the models below (paper 003
    # eqs. 13, 24: omega_r > 0 when omega_i > omega_c). The spin was taken positive in either
    # sense: backwards the roller's and the rib's surface speeds added instead of
    # cancelling (reduced model: 3.0x the heat, CRB_50x75x16 at 524 rad/s, 3 kN), and the
    # coupled model was called with a negative speed (InputError 'speed')
    sense = -1.0 if wi - wo < 0.0 else 1.0
    wi, wc, wo = sense * wi, sense * wc, sense * wo
    spin = np.abs(np.asarray(kin.element_spin, float)) * np.ones(b.n_rollers)
    z = b.n_rollers
    h = float(geom.contact_height())
    rho = 0.5 * geom.roller_diameter - h

    # thrust share (one rib per roller carries the axial load)
    fa = abs(float(op.axial_load))
    q = fa / (z * math.cos(geom.rib_angle)) if fa > 0 else 0.0
    both_ribbed = getattr(b, "ribbed_ring", "both") == "both"
    if fa > 0 and not both_ribbed:
        warnings.warn(ValidityWarning(
            f"rib_friction: {getattr(b, 'name', 'the bearing')} has ribs on the "
            f"{b.ribbed_ring} ring only, so an axial load has no path through it (paper 003 "
            "sec. 3.2); its thrust share is booked as if an opposite rib carried it"),
            stacklevel=2)
    dyn = None
    if float(op.radial_load) <= 0.0 and (model == "coupled" or unbalance > 0.0):
        # no roller touches the inner ring: the roller dynamics (paper 003) have no loaded
        # zone, and their quasi-static start, the roller skidding solver, stops there
        # ("no roller touches the inner ring ... residual inf"); the thrust share and the
        # lubricant drag at the kinematics' spins are what the reduced path books
        warnings.warn(ValidityWarning(
            f"rib_friction: no radial load on {getattr(b, 'name', 'the bearing')}, so no "
            f"roller touches the inner ring and the {model} roller dynamics (paper 003) "
            "have no loaded zone to run on: the rib heat is the thrust share and the "
            "lubricant drag at the kinematics' roller spins"
            + (" (the unbalance is not modelled there)" if unbalance > 0.0 else "")),
            stacklevel=2)
        model, unbalance = "reduced", 0.0
    if model == "coupled":
        # the coupled integration's step is set by the rib contact (~1.5 us) and it runs a
        # fixed number of cage orbits, so its cost grows as 1/speed (45 r/min: 265 s CPU
        # per temperature node); beyond MAX_COUPLED_TIME of simulated motion the reduced
        # model books the heat, said in a warning
        orbit = 2.0 * math.pi / max(abs(wc), 1e-12)
        simulated = (DEFAULT_WARMUP_ORBITS + DEFAULT_ORBITS) * orbit
        if simulated > MAX_COUPLED_TIME:
            warnings.warn(ValidityWarning(
                f"rib_friction: the coupled roller dynamics would integrate "
                f"{simulated:.3g} s of motion at this cage speed ({abs(wc):.3g} rad/s; "
                f"limit {MAX_COUPLED_TIME:g} s, ~1.5 us steps): the reduced model (one "
                "roller, quasi-static spins) books the rib heat here"), stacklevel=2)
            model = "reduced"
    if model == "coupled" or unbalance > 0.0:
        speed = wi - wo
        try:
            dyn = rib_dynamics_heat(b, ctx.lubricant, speed, float(op.radial_load),
                                    temperature, unbalance, model=model,
                                    friction_coefficient=mu, oil_fraction=oil_fraction,
                                    temperature_step=t_step, convergence=convergence,
                                    table_retries=retries, settle=settle,
                                    warm_start_nodes=warm_nodes)
        except ConvergenceError as exc:
            if model != "coupled":
                raise
            # the coupled motion is unstable at this state and at the neighbouring
            # temperature nodes: the reduced model books the rib heat, said in a warning
            warnings.warn(ValidityWarning(
                f"rib_friction: the coupled roller dynamics stopped ({exc}); the reduced "
                "model (one roller, quasi-static spins) books the rib heat here"),
                stacklevel=2)
            model = "reduced"
            dyn = (rib_dynamics_heat(b, ctx.lubricant, speed, float(op.radial_load),
                                     temperature, unbalance, model=model,
                                     friction_coefficient=mu, oil_fraction=oil_fraction,
                                     temperature_step=t_step, convergence=convergence,
                                     table_retries=retries, settle=settle,
                                     warm_start_nodes=warm_nodes)
                   if unbalance > 0.0 else None)
    details: dict = {"thrust_normal_force": q, "friction_coefficient": mu, "model": model}
    if model == "coupled":
        # every face from the coupled integration (contacts and drag); the thrust share
        # slides at the coupled model's mean rib slide speed
        slide = np.full(z, dyn.rib_slide_speed)
        friction = np.full(z, mu * q)
        heat_thrust = friction * slide
        dynamic = z * dyn.heat
        v_end_mean = (wi - wc) * (0.5 * geom.inner_raceway_diameter + h) - dyn.rib_slide_speed
        pairs = (ForcePair("rib on roller end face (thrust share, coupled spins)",
                           friction, -slide),)
        details.update(thrust_heat=float(np.sum(heat_thrust)),
                       thrust_slide_speed=float(dyn.rib_slide_speed))
    else:
        from ..lubricant_properties import air_properties

        v = rib_sliding_speed(geom, wi, wc, spin)        # (Z,) rib minus end face [m/s]
        eta = (oil_fraction * float(ctx.lubricant.dynamic_viscosity(temperature))
               + (1.0 - oil_fraction) * air_properties(temperature).dynamic_viscosity)
        f_g = (abs(float(lubricant_drag(geom, wi, wc, eta)[0]))
               if geom.axial_clearance > 0 else 0.0)
        details["drag_force"] = f_g
        # the reduced dynamics' heat holds the drag of both faces: not counted twice
        friction = mu * q + (2.0 * f_g if dyn is None else 0.0)
        friction = friction * np.ones(z)
        heat_thrust = np.abs(friction * v)
        dynamic = z * dyn.heat if dyn is not None else 0.0
        v_end_mean = float(np.mean(spin)) * rho
        # the thrust and drag parts of heat_thrust (both mu Q |v| and 2 F_G |v| >= 0)
        slide_sum = float(np.sum(np.abs(v)))
        details.update(thrust_heat=mu * q * slide_sum,
                       thrust_slide_speed=slide_sum / z)
        if dyn is None:
            details.update(drag_heat=2.0 * f_g * slide_sum,
                           slip_speed=inner_slip_speed(geom, wi, wc, spin))
        # force on the end face and the face's speed relative to the rib, in the real sense
        pairs = (ForcePair("rib on roller end face (thrust + drag)",
                           sense * friction * np.sign(v), -sense * v),)
    if dyn is not None:
        details.update(pv_left=dyn.pv_left, pv_right=dyn.pv_right, slip_speed=dyn.slip_speed,
                       dynamic_heat=dynamic, heat_left=z * dyn.heat_left,
                       heat_right=z * dyn.heat_right, rib_slide_speed=dyn.rib_slide_speed,
                       dynamics_cost_s=dyn.cost_s, dynamics_runs=dyn.runs,
                       dynamics_orbits=dyn.orbits,
                       dynamics_traction_fallbacks=dyn.fallbacks,
                       dynamics_warm_starts=dyn.warm_starts)
    total = float(np.sum(heat_thrust)) + dynamic
    details.update(dynamics="none" if dyn is None else model, total_heat=total,
                   n_rollers=z, temperature=temperature)
    share = ctx.option(name, "element_share", None)
    if share is None:
        qq = max(q, 1e-3)
        rx, ry = geom.curvature()
        pc = point_contact(qq, rx, ry, geom.effective_modulus)
        v_rib = (wi - wc) * (0.5 * geom.inner_raceway_diameter + h)
        share = float(blok_partition(0.5 * (v_rib + v_end_mean), v_end_mean - v_rib,
                                     math.sqrt(float(pc.a) * float(pc.b)),
                                     b.roller_material, b.ring_material))
    check_range(f"options[{name}].element_share", share, 0.0, 1.0)
    comp = "roller end face / rib"
    outer = _outer_rib_thrust(geom, b, mu, q, wo, wc, spin) if both_ribbed else None
    if outer is not None:
        pairs += (outer.pair,)
        details.update(outer_thrust_heat=outer.heat, outer_thrust_slide_speed=outer.slide,
                       outer_element_share=outer.share, total_heat=total + outer.heat)
    if dynamic > 0:
        # time-mean power of the dynamics' rib forces, as F [W/(1 m/s)] x 1 m/s
        pairs += (ForcePair(f"rib contacts and drag ({model} dynamics, time mean)",
                            np.array(dynamic), np.array(-1.0)),)
    roles = {comp: {"elements": share * total, "inner_ring": (1.0 - share) * total}}
    if outer is not None:
        roles[OUTER_COMPONENT] = {"elements": outer.share * outer.heat,
                                  "outer_ring": (1.0 - outer.share) * outer.heat}
    by_role: dict[str, float] = {}
    for split in roles.values():
        for role, power in split.items():
            by_role[role] = by_role.get(role, 0.0) + power
    return HeatResult(
        source=name,
        power_by_role=by_role,
        components={c: sum(split.values()) for c, split in roles.items()},
        loss_class=dict.fromkeys(roles, "load_dependent"),
        forces={"rib_friction_force": friction},
        force_pairs=pairs,
        details={**details, "element_share": share},
        component_roles=roles)


#: loss component of the thrust share's contact on the outer-ring rib (``ribbed_ring =
#: "both"``), beside the inner rib's "roller end face / rib"
OUTER_COMPONENT = "roller end face / outer rib"


class OuterRibThrust(NamedTuple):
    """The thrust share's contact on the outer-ring rib of a both-ribbed bearing:
    ``heat`` [W] (all rollers), ``slide`` [m/s] (roller-mean |v_o|), ``share`` [-] (Blok's
    partition to the rollers), ``pair`` (the friction force and the slide it acts across)."""

    heat: float
    slide: float
    share: float
    pair: ForcePair


def _outer_rib_thrust(geom: object, bearing: object, mu: float, q: float, outer_speed: float,
                      cage_speed: float, spin: np.ndarray) -> OuterRibThrust | None:
    """The outer rib's share of an axial load (:mod:`thermobearing.rib_outer`): each roller
    presses the opposite outer rib with the same Q [N] as the inner rib, at the kinematic
    state's spins and cage speed (the roller dynamics are integrated against the inner ribs
    only). Heat mu Q |v_o| per roller; Blok's partition between the end face (speed
    -omega_r rho) and the rib ((omega_o - omega_c) r_o) at the contact's sqrt(a b). None
    without thrust."""
    if q <= 0.0:
        return None
    v = np.asarray(outer_rib_sliding_speed(geom, outer_speed, cage_speed, spin), float)
    friction = np.full(v.shape, mu * q)
    heat = float(np.sum(friction * np.abs(v)))
    _, _, half_width = outer_thrust_contact(geom, q)
    v_rib = (outer_speed - cage_speed) * outer_contact_radius(geom)
    v_end = -float(np.mean(spin)) * float(geom.contact_arm)
    share = float(blok_partition(0.5 * (v_rib + v_end), v_end - v_rib, half_width,
                                 bearing.roller_material, bearing.ring_material))
    pair = ForcePair("outer rib on roller end face (thrust share, kinematic spins)",
                     friction * np.sign(v), -v)
    return OuterRibThrust(heat, float(np.mean(np.abs(v))), share, pair)
