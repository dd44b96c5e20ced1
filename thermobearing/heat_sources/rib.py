"""Roller end-face / inner-ring rib friction heat (paper 003 eqs. 12-17, 24).

Heat of one end-face contact = |Q_e_theta| |v_i - v_r| (friction force of eq. 12 times the
relative speed of eq. 24 at the contact point), from :mod:`thermobearing.rib`. Two load
cases, added:

* **thrust**: an axial load F_a of the operating point is carried by the rib contacts; each
  roller's end face takes Q = F_a / (Z cos theta_f) (uniform share, the rollers' spin from
  the kinematic state);
* **skew with dynamic unbalance** (option ``unbalance_mass`` [kg] > 0): the mean rib heat of
  a roller from :func:`thermobearing.skidding.roller_dynamics.simulate_reduced` at the
  operating point (radial load, speed; paper 003's mechanism), times Z. This costs a few
  seconds (quasi-static skidding solve + integration), so it is off by default. Caveat
  (validation case ``paper003_pv_slip_trends``, reason 10): the reduced model runs on the
  quasi-static spins, which skid ~3x more than the spins of the coupled all-roller + cage
  integration (:mod:`thermobearing.skidding.roller_dynamics_coupled`); its time-mean rib PV
  is ~30 % below the coupled model's at the paper's base case.

The lubricant drag F_G of eq. 14 acts on every face even without contact; it is included
(oil/air mixture viscosity: option ``oil_fraction``, default 0.05) with the face's sliding
speed.

Heat split between the roller ("elements") and the inner ring ("inner_ring"): Blok's
high-Peclet partition [blok1963_flash_temperature] via
:func:`thermobearing.heat_sources.raceway.blok_partition` with the speeds of the two
surfaces through the contact (rib: (omega_i - omega_c)(d_i/2 + H_contact), end face:
omega_r rho) and the contact half-width sqrt(a b); option ``element_share`` overrides it.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError, check_positive, check_range
from ..hertz import point_contact
from ..rib import DEFAULT_RIB_FRICTION, lubricant_drag, rib_geometry, rib_sliding_speed
from . import HEAT_SOURCES, ForcePair, HeatContext, HeatResult
from .raceway import blok_partition


@HEAT_SOURCES.register(
    "rib_friction",
    references=["zhang2021_abnormal_wear", "blok1963_flash_temperature",
                "harris_kotzalas2007"],
    parameters={"friction_coefficient": "-", "oil_fraction": "-", "unbalance_mass": "kg",
                "element_share": "-"},
    validity="cylindrical roller bearings with ribs (end_face_crown_radius, rib_height set)",
)
def rib_friction(ctx: HeatContext) -> HeatResult:
    """Roller end-face / rib friction heat (paper 003 eqs. 12-17, 24)."""
    name = "rib_friction"
    b = ctx.bearing
    if getattr(b, "kind", None) != "cylindrical":
        raise InputError("bearing", getattr(b, "name", b),
                         "a cylindrical roller bearing (the rib_friction source)")
    geom = rib_geometry(b)
    mu = float(ctx.option(name, "friction_coefficient", DEFAULT_RIB_FRICTION))
    check_range(f"options[{name}].friction_coefficient", mu, 0.0, 1.0)
    oil_fraction = float(ctx.option(name, "oil_fraction", 0.05))
    check_range(f"options[{name}].oil_fraction", oil_fraction, 0.0, 1.0)
    unbalance = float(ctx.option(name, "unbalance_mass", 0.0))
    check_positive(f"options[{name}].unbalance_mass", unbalance, allow_zero=True)
    kin = ctx.kinematics
    op = ctx.operating
    temperature = ctx.temperature("elements")
    wi, wc = float(kin.inner_speed), float(kin.cage_speed)
    spin = np.abs(np.asarray(kin.element_spin, float)) * np.ones(b.n_rollers)
    z = b.n_rollers
    h = float(geom.contact_height())
    rho = 0.5 * geom.roller_diameter - h
    v = rib_sliding_speed(geom, wi, wc, spin)        # (Z,) rib minus end face [m/s]

    # thrust share (one rib per roller carries the axial load)
    fa = abs(float(op.axial_load))
    q = fa / (z * math.cos(geom.rib_angle)) if fa > 0 else 0.0
    from ..lubricant_properties import air_properties
    eta = (oil_fraction * float(ctx.lubricant.dynamic_viscosity(temperature))
           + (1.0 - oil_fraction) * air_properties(temperature).dynamic_viscosity)
    f_g = abs(float(lubricant_drag(geom, wi, wc, eta)[0])) if geom.axial_clearance > 0 else 0.0
    friction = mu * q + 2.0 * f_g                     # per roller: thrust face + drag on both
    heat_thrust = np.abs(friction * v)
    dynamic = 0.0
    details = {"thrust_normal_force": q, "drag_force": f_g, "friction_coefficient": mu}
    if unbalance > 0.0:
        from ..skidding.roller_dynamics import build_model, simulate_reduced

        model = build_model(b, ctx.lubricant, wi - float(kin.outer_speed), float(op.radial_load),
                            unbalance, temperature=temperature, rib_friction=mu,
                            oil_fraction=oil_fraction)
        resp = simulate_reduced(model)
        dynamic = z * resp.rib_heat
        details.update(pv_left=resp.pv_left, pv_right=resp.pv_right,
                       slip_speed=resp.slip_speed, dynamic_heat=dynamic)
    total = float(np.sum(heat_thrust)) + dynamic
    share = ctx.option(name, "element_share", None)
    if share is None:
        qq = max(q, 1e-3)
        rx, ry = geom.curvature()
        pc = point_contact(qq, rx, ry, geom.effective_modulus)
        v_rib = (wi - wc) * (0.5 * geom.inner_raceway_diameter + h)
        v_end = float(np.mean(spin)) * rho
        share = float(blok_partition(0.5 * (v_rib + v_end), v_end - v_rib,
                                     math.sqrt(float(pc.a) * float(pc.b)),
                                     b.roller_material, b.ring_material))
    check_range(f"options[{name}].element_share", share, 0.0, 1.0)
    comp = "roller end face / rib"
    pairs = (ForcePair("rib on roller end face (thrust + drag)", friction * np.sign(v), -v),)
    if dynamic > 0:
        # time-mean power of |Q_e_theta v| of the skew contacts, as F [W/(1 m/s)] x 1 m/s
        pairs += (ForcePair("rib skew contacts (time mean)", np.array(dynamic),
                            np.array(-1.0)),)
    return HeatResult(
        source=name,
        power_by_role={"elements": share * total, "inner_ring": (1.0 - share) * total},
        components={comp: total},
        loss_class={comp: "load_dependent"},
        forces={"rib_friction_force": friction},
        force_pairs=pairs,
        details={**details, "element_share": share})
