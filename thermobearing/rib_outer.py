"""Thrust contact of a roller end face on the *outer*-ring rib (NJ / NUP bearings).

In a bearing with ribs on both rings (``ribbed_ring = "both"``) an axial load F_a passes
from the inner-ring rib through each roller into the opposite outer-ring rib: every roller
carries the same normal force Q = F_a / (Z cos theta_f) on both contacts (axial equilibrium
of the roller; friction moments neglected as in the inner rib's thrust share of
:mod:`thermobearing.heat_sources.rib`). Paper 003 [zhang2021_abnormal_wear] models the inner
rib only (its bearing has no outer rib); this module carries its geometry over to the outer
rib by mirror symmetry about the roller axis. One rib geometry per bearing: the outer rib has
the bearing's ``rib_angle`` theta_f and the end face its crown radius R_s.

Geometry (frame of :mod:`thermobearing.rib`: ``z`` circumferential, positive in the sense the
inner ring moves relative to the cage; roller spin omega_r positive in the rolling sense, so
a point of the roller ``y`` below its axis moves at +omega_r y along z and one above at
-omega_r y):

* contact point: the point of the crowned end face whose normal is the outer rib's,
  rho = R_s sin(theta_f) *above* the roller axis (paper 003 eq. 11 mirrored), at the radius
  r_o = d_i/2 + D_w/2 + rho from the bearing axis (d_i/2 + D_w/2 = d_m/2, the roller axis);
* curvature: R_y = R_s; the rib is a cone of revolution whose surface normal (into the
  roller) points towards the bearing axis, so its circumferential curvature is *concave*:
  1/R_x = 1/R_s - tan(theta_f)/r_o (paper 003 eq. 10 with the sign of the cone's curvature
  turned; Meusnier's theorem: normal curvature of a surface of revolution n_r / r);
* sliding speed, rib minus end face, in the cage frame (paper 003 eq. 24 at the outer rib):
  v_o = (omega_o - omega_c) r_o + omega_r rho. In pure rolling on the outer raceway,
  (omega_o - omega_c) d_o/2 = -omega_r D_w/2, so v_o = -(omega_o - omega_c + omega_r) *
  (D_w/2 - rho): the end face slides over the outer rib at the height D_w/2 - rho below the
  outer raceway, as it does over the inner rib at H_contact above the inner one.

Units: SI (m, rad/s, N, Pa).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .errors import InputError, check_positive
from .hertz import point_contact


def outer_contact_radius(geom: Any) -> float:
    """r_o [m]: distance of the outer-rib contact point from the bearing axis,
    d_i/2 + D_w/2 + R_s sin(theta_f) (paper 003 eq. 11 mirrored about the roller axis).

    geom : :class:`thermobearing.rib.RibGeometry`."""
    return (0.5 * float(geom.inner_raceway_diameter) + 0.5 * float(geom.roller_diameter)
            + float(geom.contact_arm))


def outer_curvature(geom: Any) -> tuple[float, float]:
    """(R_x, R_y) [m] of the end-face / outer-rib contact: R_y = R_s,
    1/R_x = 1/R_s - tan(theta_f)/r_o (paper 003 eq. 10 with the concave cone of the outer
    rib). A cone more curved than the end face (no convex contact) -> InputError naming the
    rib angle."""
    r_o = outer_contact_radius(geom)
    inv = 1.0 / float(geom.crown_radius) - math.tan(float(geom.rib_angle)) / r_o
    if not inv > 0.0:
        raise InputError(
            "bearing.rib_angle", f"{math.degrees(float(geom.rib_angle)):.4g} deg",
            f"an outer-rib cone less curved than the end face (tan(theta_f) < r_o / R_s = "
            f"{r_o / float(geom.crown_radius):.4g} at r_o = {r_o * 1e3:.4g} mm, R_s = "
            f"{float(geom.crown_radius) * 1e3:.4g} mm)")
    return 1.0 / inv, float(geom.crown_radius)


def outer_rib_sliding_speed(geom: Any, outer_speed: Any, cage_speed: Any,
                            roller_spin: Any) -> Any:
    """v_o [m/s] = (omega_o - omega_c) r_o + omega_r rho, the outer rib's speed minus the end
    face's at their contact point (module notes; paper 003 eq. 24 at the outer rib).

    outer_speed, cage_speed : omega_o, omega_c [rad/s]; roller_spin : omega_r [rad/s] (array
    per roller or scalar, positive in the rolling sense)."""
    rho = float(geom.contact_arm)
    return ((np.asarray(outer_speed, float) - np.asarray(cage_speed, float))
            * outer_contact_radius(geom) + np.asarray(roller_spin, float) * rho)


def outer_thrust_contact(geom: Any, normal_force: float) -> tuple[float, float, float]:
    """Hertz contact of one roller's thrust share Q [N] on the outer rib: (maximum pressure
    [Pa], contact area pi a b [m^2], mean half-width sqrt(a b) [m]) at
    :func:`outer_curvature`'s radii, Brewe-Hamrock ellipse as the inner rib's (paper 003
    eqs. 22-23). Q = 0 gives zeros."""
    q = float(normal_force)
    check_positive("normal_force", q, allow_zero=True)
    if q == 0.0:
        return 0.0, 0.0, 0.0
    rx, ry = outer_curvature(geom)
    pc = point_contact(q, rx, ry, float(geom.effective_modulus), method="brewe_hamrock_1977")
    return (float(pc.max_pressure), math.pi * float(pc.a) * float(pc.b),
            math.sqrt(float(pc.a) * float(pc.b)))
