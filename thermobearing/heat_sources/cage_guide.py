"""Cage-guide (land) friction: paper 002 eqs. 1-5 and 18, inner- or outer-ring guided cages.

Seed paper 002 (002_0add79adaca5495c.txt), section 2.1. The cage land runs on the guiding
ring's land with radial clearance c (half the diametral ``guide_clearance`` c_cg) and
eccentricity e = eps c. Two regimes, by the minimum gap c - e against the critical film
thickness h_c:

Hydrodynamic (c - e > h_c): short journal bearing (Ocvirk), eq. 4,
    F_t = pi eta D_g (omega_g + omega_c) B_c^3 eps / (8 c^2 (1 - eps^2)^1.5)
    F_r = eta |D_g (omega_g + omega_c)| B_c^3 eps^2 / (2 c^2 (1 - eps^2)^2)
and the drag torque of relative sliding, eq. 5 in the consistent Petroff form
    M = pi eta D_g^3 (omega_g - omega_c) B_c / (4 c sqrt(1 - eps^2))
(2 pi eta omega R^3 L / (c sqrt(1 - eps^2)) with R = D_g/2; primer losses 3.2). The paper
prints the denominator 2 c_g: that equals ours when its c_g is the *diametral* clearance,
while its eq. 4 matches Ocvirk only with the *radial* clearance; we use the radial one in
both. Heat = |M (omega_g - omega_c)|: the power of the drag torque (the force pair).
Paper eq. 18 instead writes Q = mu_c |F| D_m (omega_g - omega_c) / 2 with an unstated
hydrodynamic friction coefficient mu_c; it is available as ``form="paper002_eq18"``
(option ``friction_coefficient``), with the matching drag torque mu_c |F| D_m / 2.

Metallic contact (c - e <= h_c): eqs. 1-3, Palmgren-type line contact of the land,
    F_cg = E B_c^(8/9) / 4 (delta / 0.39)^(10/9),  delta = h_c - (c - e)
(the paper prints delta = h_c - (e - c/2 ...) with the sign of the gap reversed: the
penetration must grow as the gap closes), friction f = mu_cg F_cg (eq. 2) and the friction
torque M = f D_g / 2 (eq. 3 prints F_cg where the friction force is meant).
Heat = f (D_g/2) |omega_g - omega_c|.
The two regimes do not meet (as printed): at c - e = h_c the film torque of eq. 5 is finite
and the contact force of eq. 1 zero, so the heat falls there from the Petroff value to zero
(QJ1044, 1800 r/min, h_c = 1 um: from 1.8 kW; tests/unit/test_prop19_cage_pocket.py).

The eccentricity comes from the kinematic state (``cage_eccentricity``, skidding solver);
if that is 0 and ``cage_guide_force`` is given (or ``options["cage_guide"]["load"]``,
e.g. the cage weight), eps is solved from |F(eps)| = load (Ocvirk), switching to the
contact regime when the film cannot carry it. Heat goes to the guiding ring (paper 002
eq. 23 puts Q_cg into the housing/outer-ring node); ``cage_share`` moves part to the cage.
Rolling-element-guided cages have no land: the source returns zero.

A roller skidding state carries the land moment its cage equation balanced (extras
``solver_drag``: eq. 5 for a centred cage at the oil temperature); the source books its
power |M (omega_g - omega_c)| unless options other than ``cage_share`` are given.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from scipy.optimize import brentq

from ..errors import InputError, check_range
from . import HEAT_SOURCES, ForcePair, HeatContext, HeatResult


class LandForces(NamedTuple):
    """Short-journal-bearing forces of the cage land (paper 002 eq. 4) [N]."""

    tangential: float
    radial: float

    @property
    def magnitude(self) -> float:
        """Resultant [N]."""
        return math.hypot(self.tangential, self.radial)


def short_bearing_forces(viscosity, guide_diameter, omega_guide, omega_cage, width,
                         radial_clearance, eccentricity_ratio) -> LandForces:
    """Paper 002 eq. 4 (Ocvirk short bearing) with the radial clearance c [m].

    viscosity [Pa s], guide_diameter D_g [m], speeds [rad/s], width B_c [m],
    eccentricity_ratio eps in [0, 1).
    """
    eps = float(eccentricity_ratio)
    check_range("cage_guide.eccentricity_ratio", eps, 0.0, 1.0, high_inclusive=False)
    s = guide_diameter * (omega_guide + omega_cage)
    ft = math.pi * viscosity * s * width ** 3 * eps / (
        8.0 * radial_clearance ** 2 * (1.0 - eps * eps) ** 1.5)
    fr = viscosity * abs(s) * width ** 3 * eps ** 2 / (
        2.0 * radial_clearance ** 2 * (1.0 - eps * eps) ** 2)
    return LandForces(ft, fr)


def land_drag_torque(viscosity, guide_diameter, omega_guide, omega_cage, width,
                     radial_clearance, eccentricity_ratio) -> float:
    """Viscous drag torque on the cage from the guide land [N m] (paper 002 eq. 5, Petroff).

    M = pi eta D_g^3 (omega_g - omega_c) B_c / (4 c sqrt(1 - eps^2)); positive M drives
    the cage forward when the guide ring runs faster than the cage.
    """
    eps = float(eccentricity_ratio)
    return math.pi * viscosity * guide_diameter ** 3 * (omega_guide - omega_cage) * width / (
        4.0 * radial_clearance * math.sqrt(1.0 - eps * eps))


def contact_force(youngs_modulus, width, penetration) -> float:
    """Paper 002 eq. 1: F_cg = E B_c^(8/9)/4 (delta/0.39)^(10/9) [N] (delta [m] > 0)."""
    if penetration <= 0:
        return 0.0
    return youngs_modulus * width ** (8.0 / 9.0) / 4.0 * (penetration / 0.39) ** (10.0 / 9.0)


def _penetration_for_force(youngs_modulus, width, force) -> float:
    return 0.39 * (4.0 * force / (youngs_modulus * width ** (8.0 / 9.0))) ** 0.9


@HEAT_SOURCES.register(
    "cage_guide",
    references=["gao2022_overskidding", "hamrock2004", "harris_kotzalas2007"],
    parameters={"critical_film": "m", "friction_coefficient": "-", "boundary_friction": "-",
                "load": "N", "cage_share": "-"},
    limits={"critical_film": "(0, inf)", "friction_coefficient": "[0, 1]",
            "boundary_friction": "[0, 1]", "load": "[0, inf)", "cage_share": "[0, 1]"},
    validity="ring-guided cages; short-bearing theory B_c/D_g < ~0.5; eps < 1",
)
def cage_guide(ctx: HeatContext) -> HeatResult:
    """Cage-land friction heat, paper 002 eqs. 1-5 and 18 (see module docstring).

    Options: ``critical_film`` h_c [m] (default 1e-6), ``boundary_friction`` mu_cg
    (default 0.1, boundary friction of steel/brass under oil), ``form`` "short_bearing"
    (default) or "paper002_eq18" with ``friction_coefficient`` mu_c, ``load`` [N] (land
    load when the kinematic state gives none), ``cage_share`` (default 0).
    """
    name = "cage_guide"
    b = ctx.bearing
    cage = b.cage
    guidance = cage.guidance
    kin = ctx.kinematics
    if guidance not in ("outer_ring", "inner_ring"):
        return HeatResult(source=name, power_by_role={}, components={"cage guide": 0.0},
                          loss_class={"cage guide": "load_independent"},
                          details={"guidance": guidance})
    if cage.guide_clearance is None or cage.guide_land_diameter is None:
        raise InputError("bearing.cage.guide_clearance/guide_land_diameter",
                         (cage.guide_clearance, cage.guide_land_diameter),
                         "both given for a ring-guided cage")
    ring_role = "outer_ring" if guidance == "outer_ring" else "inner_ring"
    omega_g = kin.outer_speed if guidance == "outer_ring" else kin.inner_speed
    omega_c = kin.cage_speed
    d_g = cage.guide_land_diameter
    width = cage.land_width if cage.land_width is not None else cage.width
    c = 0.5 * cage.guide_clearance
    h_c = float(ctx.option(name, "critical_film", 1.0e-6))
    mu_b = float(ctx.option(name, "boundary_friction", 0.1))
    check_range(f"options[{name}].boundary_friction", mu_b, 0.0, 1.0)
    share = float(ctx.option(name, "cage_share", 0.0))
    check_range(f"options[{name}].cage_share", share, 0.0, 1.0)
    form = str(ctx.option(name, "form", "short_bearing"))
    if form not in ("short_bearing", "paper002_eq18"):
        raise InputError(f"options[{name}].form", form, "'short_bearing' or 'paper002_eq18'")
    mu_given = ctx.option(name, "friction_coefficient", None)
    if mu_given is not None:
        check_range(f"options[{name}].friction_coefficient", mu_given, 0.0, 1.0)
        if form != "paper002_eq18":
            raise InputError(f"options[{name}].friction_coefficient", mu_given,
                             "no value with form = 'short_bearing' (the default: its drag is "
                             "the Petroff torque of the land film); the coefficient mu_c is "
                             "used only with form = 'paper002_eq18'")
    carried = _solver_guide_moment(ctx, name)
    if carried is not None:
        # the moment the roller skidding solver's cage equation balanced (centred cage)
        heat = abs(carried * (omega_g - omega_c))
        return HeatResult(
            source=name, power_by_role={ring_role: (1.0 - share) * heat, "cage": share * heat},
            components={"cage guide": heat}, loss_class={"cage guide": "load_independent"},
            forces={"cage_guide_moment": carried},
            force_pairs=(ForcePair("guide land on cage", carried, omega_c - omega_g),),
            details={"eccentricity_ratio": 0.0, "regime": "solver drag (roller skidding "
                     "balance, centred cage)", "guidance": guidance})
    eta = float(ctx.lubricant.dynamic_viscosity(ctx.temperature("oil")))
    material = getattr(cage, "material", None)
    e_mod = getattr(material, "youngs_modulus", None) or b.ring_material.youngs_modulus
    dw = omega_g - omega_c

    eps = kin.cage_eccentricity
    load = kin.cage_guide_force if kin.cage_guide_force is not None else ctx.option(
        name, "load", None)
    eps_max = 1.0 - h_c / c if h_c < c else 0.0
    contact = False
    f_contact = 0.0
    if eps == 0.0 and load:
        load = float(load)

        def residual(e):
            return short_bearing_forces(eta, d_g, omega_g, omega_c, width, c, e).magnitude - load

        if eps_max > 0 and residual(eps_max) >= 0:
            eps = brentq(residual, 0.0, eps_max, xtol=1e-14)
        else:
            contact, f_contact = True, load
    elif eps > eps_max:
        contact = True
        f_contact = contact_force(e_mod, width, h_c - c * (1.0 - eps))

    details = {"eccentricity_ratio": eps, "regime": "contact" if contact else "hydrodynamic",
               "guidance": guidance}
    if contact:
        friction = mu_b * f_contact
        moment = math.copysign(friction * 0.5 * d_g, dw) if dw != 0 else 0.0
        details["contact_force"] = f_contact
        details["penetration"] = _penetration_for_force(e_mod, width, f_contact) if f_contact else 0
    else:
        forces = short_bearing_forces(eta, d_g, omega_g, omega_c, width, c, eps)
        details["film_force"] = forces.magnitude
        if form == "short_bearing":
            moment = land_drag_torque(eta, d_g, omega_g, omega_c, width, c, eps)
        else:
            mu_c = float(ctx.option(name, "friction_coefficient", float("nan")))
            check_range(f"options[{name}].friction_coefficient", mu_c, 0.0, 1.0)
            moment = math.copysign(mu_c * forces.magnitude * 0.5 * b.pitch_diameter, dw)
    # moment acts on the cage; the cage turns at omega_c relative to the ring's omega_g
    heat = abs(moment * dw)
    roles = {ring_role: (1.0 - share) * heat, "cage": share * heat}
    return HeatResult(
        source=name, power_by_role=roles, components={"cage guide": heat},
        loss_class={"cage guide": "load_independent"},
        forces={"cage_guide_moment": moment},
        force_pairs=(ForcePair("guide land on cage", moment, omega_c - omega_g),),
        details=details)


def _solver_guide_moment(ctx: HeatContext, name: str) -> float | None:
    """The land moment on the cage [N m] the roller skidding solver balanced (kinematic
    state extras ``solver_drag["cage_guide_moment"]``: paper 002 eq. 5 for a centred cage at
    the oil temperature, :mod:`thermobearing.skidding.roller_drag`), or None: a state
    without it, or options other than ``cage_share`` (they ask for the source's own model:
    an eccentric or touching cage, eq. 18)."""
    from .churning import solver_drag

    drag = solver_drag(ctx, name, "cage_guide_moment", booking=("cage_share",),
                       churning=False)
    return None if drag is None else float(drag["cage_guide_moment"])
