"""Roller end-face / inner-ring rib contact of a cylindrical roller bearing (paper 003).

Zhang, Deng, Zhang, Wang, Zheng (2021), seed ``003_743e023ae6e45686.txt``
[zhang2021_abnormal_wear], eqs. 1-17 (geometry, Hertz force, friction with the lubricant
drag, forces and moments on the roller) and eqs. 21-24 (PV value of the end face). The
geometry follows Kleckner et al. 1980 [kleckner1980_cybean] as the paper cites it.

Frame (one roller, in the cage frame): ``x`` along the roller axis (positive towards the
*right* rib), ``y`` radial (outwards), ``z`` circumferential, positive in the sense the
inner ring (and its rib) moves relative to the cage. Skew ``alpha`` is a rotation about
``y``; a skew rate moves the end at ``x`` by ``-alpha_dot * x`` along ``z``. Roller spin
``omega_r`` [rad/s] is counted positive in the rolling sense (the roller surface at the
inner raceway moves along +z), as in :mod:`thermobearing.skidding.roller`.

Readings of the paper (it is garbled or under-specified in places; each is a choice):

* eq. 1: ``R_p - L_p/2`` with eqs. 2-3 reduces identically to ``R_s - L_r/2``; we use the
  reduced form. The approach of side K is
  ``delta_K = [(1 - cos alpha)(R_s - L_r/2) - (C_a/2 + C_af) + X_K] cos(theta_f)``,
  ``X_L = -X``, ``X_R = +X`` (eq. 5).
* eq. 11: ``H_contact = H_rollercm - R_s sin(theta_f) +- L_r/2 sin(alpha_e)`` is the height
  of the contact point above the inner raceway; its distance from the roller axis is
  ``rho = D_w/2 - H_contact`` (the arm of eq. 16's ``M_e_theta_x``). A contact point above
  the rib (``H_contact > h_f``) cannot exist: :class:`InputError`. A contact point below
  the raceway level (``H_contact < 0``, large rib angle x crown radius) is kept as the
  paper's own sweeps (rib angle to 0.7 deg and more, crown radius 600 mm and more at
  R_s sin(theta_f) > D_w/2) require it; it means an undercut rib root.
* eq. 6 is the Hertz point-contact law Q = K delta^1.5; we evaluate it with
  :func:`thermobearing.hertz.point_contact_stiffness` (``method="brewe_hamrock_1977"`` are
  the paper's eqs. 7-9 fits; the default "exact" differs by < 3 %).
* eq. 15 as printed has ``sqrt((D_w/2)^2 - (D_w/2)^2) = 0``; the consistent form is the
  area of the end-face segment covered by a rib of height h_f,
  ``int R/C_a dA = (4/3)(R_0/C_a) h_f sqrt((D_w/2)^2 - (D_w/2 - h_f)^2)`` (segment area
  ~ 4/3 x height x half chord). ``nu rho_e`` is the dynamic viscosity of the oil/air
  mixture in the gap; eq. 14 then has units Pa s x 1/s x m^2 = N.
* eq. 24: the rib speed at the contact point is ``(omega_i - omega_c) (d_i/2 + H_contact)``
  and the roller end-face speed ``omega_r rho - alpha_dot x_K`` (our kinematics, the
  paper gives no formula); the skew-rate term is the "roller swing speed" the paper's
  discussion of Figs. 11-12 invokes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, NamedTuple

import numpy as np

from .errors import InputError, check_positive, check_range
from .hertz import point_contact, point_contact_stiffness

#: default roller chamfer [m] (paper 003 sec. 11: 0.5 +- 0.1 mm before, 0.5 +- 0.05 after)
DEFAULT_CHAMFER = 0.5e-3
#: default end-face/rib friction coefficient [-] (estimated: boundary/mixed lubrication of a
#: lightly loaded, poorly entrained sliding contact; paper 003 gives no value)
DEFAULT_RIB_FRICTION = 0.05
#: velocity scale of the smoothed sign of eq. 13 in the dynamics [m/s]
SIGN_REGULARISATION = 0.05


@dataclass(frozen=True)
class RibGeometry:
    """Geometry of the roller end face / inner-ring rib pair (SI, paper 003 notation).

    Attributes
    ----------
    roller_diameter : D_w [m].  roller_length : L_r [m].
    crown_radius : R_s, end-face crown radius [m] (eq. 2).
    rib_angle : theta_f [rad] (eq. 4).  axial_clearance : C_a [m] (eq. 1, total).
    rib_height : h_f [m] (eq. 15).  inner_raceway_diameter : d_i [m].
    effective_modulus : E' [Pa] (Hamrock convention).
    pitch_diameter : d_m [m].  chamfer : roller chamfer [m].
    """

    roller_diameter: float
    roller_length: float
    crown_radius: float
    rib_angle: float
    axial_clearance: float
    rib_height: float
    inner_raceway_diameter: float
    effective_modulus: float
    pitch_diameter: float
    chamfer: float = DEFAULT_CHAMFER

    def __post_init__(self) -> None:
        for name in ("roller_diameter", "roller_length", "crown_radius", "rib_height",
                     "inner_raceway_diameter", "effective_modulus", "pitch_diameter"):
            check_positive(f"rib.{name}", getattr(self, name))
        check_positive("rib.axial_clearance", self.axial_clearance, allow_zero=True)
        check_range("rib.rib_angle", self.rib_angle, 0.0, math.radians(10.0), unit="rad")
        check_range("rib.chamfer", self.chamfer, 0.0, 0.5 * self.roller_diameter, unit="m")
        if self.crown_radius <= 0.5 * self.roller_length:
            raise InputError("rib.crown_radius", self.crown_radius,
                             f"a value > L_r/2 = {0.5 * self.roller_length:.4g} m")
        if self.rib_height >= self.roller_diameter:
            raise InputError("rib.rib_height", self.rib_height,
                             f"a value < D_w = {self.roller_diameter:.4g} m")
        h = self.contact_height()
        if h > self.rib_height:
            raise InputError(
                "rib.rib_height", self.rib_height,
                f"a rib higher than the end-face contact point H_contact = {h * 1e3:.4g} mm "
                "(paper 003 eq. 11): the roller cannot touch the rib")

    def contact_height(self, tilt: Any = 0.0, side: int = 1) -> Any:
        """H_contact [m], height of the contact point above the inner raceway (eq. 11).

        ``tilt`` alpha_e [rad]; ``side`` +1 (right) / -1 (left): the tilt raises one end and
        lowers the other (the paper prints one sign).
        """
        return (0.5 * self.roller_diameter - self.crown_radius * math.sin(self.rib_angle)
                + side * 0.5 * self.roller_length * np.sin(tilt))

    @property
    def contact_arm(self) -> float:
        """rho = R_s sin(theta_f) [m]: distance of the contact point from the roller axis."""
        return self.crown_radius * math.sin(self.rib_angle)

    def curvature(self, contact_height: Any = None) -> tuple[Any, Any]:
        """(R_x, R_y) [m] of the end-face/rib contact, paper 003 eq. 10.

        R_y = R_s; 1/R_x = 1/R_s + tan(theta_f)/(d_i/2 + H_contact) (the rib cone's
        circumferential curvature; a flat rib at theta_f = 0 gives R_x = R_s).
        """
        h = self.contact_height() if contact_height is None else contact_height
        r_c = 0.5 * self.inner_raceway_diameter + np.asarray(h, float)
        rx = 1.0 / (1.0 / self.crown_radius + math.tan(self.rib_angle) / r_c)
        return rx, np.full(np.shape(rx), self.crown_radius)[()]

    def unilateral_clearance(self, centre_height: Any = None) -> Any:
        """C_af = (H_rollercm - D_w/2) tan(theta_f) [m], eq. 4 (0 for a centred roller)."""
        hc = 0.5 * self.roller_diameter if centre_height is None else centre_height
        return (np.asarray(hc, float) - 0.5 * self.roller_diameter) * math.tan(self.rib_angle)

    def approach(self, skew: Any, axial_shift: Any, centre_height: Any = None
                 ) -> tuple[Any, Any]:
        """(delta_L, delta_R) [m] end-face/rib approach, eqs. 1-5 (negative = gap).

        skew alpha_r [rad]; axial_shift X_r [m] of the roller relative to the inner ring
        (positive towards the right rib).
        """
        a = np.asarray(skew, float)
        x = np.asarray(axial_shift, float)
        base = ((1.0 - np.cos(a)) * (self.crown_radius - 0.5 * self.roller_length)
                - (0.5 * self.axial_clearance + self.unilateral_clearance(centre_height)))
        c = math.cos(self.rib_angle)
        return (base - x) * c, (base + x) * c

    @property
    def stiffness(self) -> float:
        """K [N/m^1.5] with Q = K delta^1.5 (eq. 6 via hertz.point_contact_stiffness)."""
        rx, ry = self.curvature()
        return float(point_contact_stiffness(rx, ry, self.effective_modulus))


def rib_geometry(bearing: Any, **overrides: Any) -> RibGeometry:
    """:class:`RibGeometry` of a :class:`~thermobearing.geometry.RollerBearing`.

    ``overrides``: any RibGeometry field (SI), e.g. ``rib_angle=math.radians(0.5)``.
    Missing crown radius / rib height on the bearing -> InputError naming the field.
    """
    if getattr(bearing, "kind", None) != "cylindrical":
        raise InputError("bearing", getattr(bearing, "name", bearing),
                         "a cylindrical RollerBearing")
    fields = {
        "roller_diameter": bearing.roller_diameter,
        "roller_length": bearing.roller_length,
        "crown_radius": bearing.end_face_crown_radius,
        "rib_angle": bearing.rib_angle,
        "axial_clearance": bearing.axial_clearance,
        "rib_height": bearing.rib_height,
        "inner_raceway_diameter": bearing.inner_raceway_diameter,
        "effective_modulus": bearing.effective_modulus,
        "pitch_diameter": bearing.pitch_diameter,
    }
    fields.update(overrides)
    for key in ("crown_radius", "rib_height"):
        if fields[key] is None:
            name = "end_face_crown_radius" if key == "crown_radius" else key
            raise InputError(f"bearing.{name}", None, "a value (needed by the rib contact)")
    return RibGeometry(**{k: float(v) for k, v in fields.items()})


def with_changes(geom: RibGeometry, **changes: Any) -> RibGeometry:
    """A copy of ``geom`` with fields changed (re-validated)."""
    return replace(geom, **changes)


def rib_normal_force(geom: RibGeometry, approach: Any) -> Any:
    """Q_ez [N] = K max(delta, 0)^1.5, the Hertz point-contact force (paper 003 eq. 6)."""
    d = np.maximum(np.asarray(approach, float), 0.0)
    return geom.stiffness * d**1.5


def lubricant_drag(geom: RibGeometry, inner_speed: Any, cage_speed: Any,
                   mixture_viscosity: Any) -> tuple[Any, Any]:
    """(F_G [N], M_G [N m]) lubricant drag on one end face, paper 003 eqs. 14, 15, 17.

    F_G = (omega_i - omega_c) eta_e (4/3)(R_0/C_a) h_f sqrt((D/2)^2 - (D/2 - h_f)^2),
    eta_e = nu rho_e [Pa s] the oil/air mixture viscosity, R_0 = d_i/2 + H_contact the
    radius of the contact point; M_G = F_G (D_w/2 - h_f/2) (eq. 17). Eq. 15 repaired (see
    module notes). Zero axial clearance -> InputError (the drag diverges).
    """
    check_positive("rib.axial_clearance", geom.axial_clearance)
    r = 0.5 * geom.roller_diameter
    r0 = 0.5 * geom.inner_raceway_diameter + geom.contact_height()
    integral = (4.0 / 3.0) * (r0 / geom.axial_clearance) * geom.rib_height * math.sqrt(
        r**2 - (r - geom.rib_height) ** 2)
    f = (np.asarray(inner_speed, float) - np.asarray(cage_speed, float)) * np.asarray(
        mixture_viscosity, float) * integral
    return f, f * (r - 0.5 * geom.rib_height)


def rib_sliding_speed(geom: RibGeometry, inner_speed: Any, cage_speed: Any, roller_spin: Any,
                      skew_rate: Any = 0.0, side: int = 1, contact_height: Any = None) -> Any:
    """v_i - v_r [m/s] at the end-face/rib contact of side ``side`` (+1 right, -1 left).

    v_i = (omega_i - omega_c)(d_i/2 + H_contact), v_r = omega_r rho - alpha_dot x_K with
    rho = D_w/2 - H_contact and x_K = side L_r/2 (paper 003 eqs. 13, 24; kinematics ours).
    """
    h = geom.contact_height() if contact_height is None else np.asarray(contact_height, float)
    rho = 0.5 * geom.roller_diameter - h
    vi = (np.asarray(inner_speed, float) - np.asarray(cage_speed, float)) * (
        0.5 * geom.inner_raceway_diameter + h)
    vr = np.asarray(roller_spin, float) * rho - np.asarray(skew_rate, float) * (
        side * 0.5 * geom.roller_length)
    return vi - vr


class RibForces(NamedTuple):
    """Forces and moments of both ribs on one roller (paper 003 eq. 16), SI.

    normal_left/right : Q_ez^K [N].  friction_left/right : Q_e_theta^K [N] along +z.
    sliding_left/right : v_i - v_r [m/s].  pressure_left/right : P = 3Q/(2 pi a b) [Pa].
    pv_left/right : P |v| [Pa m/s] (eqs. 21-24).  heat_left/right : |Q_e_theta v| [W].
    axial_force : Q_ez^X on the roller along +x [N].  radial_force : Q_ez^Y [N].
    skew_moment : moment about y (skew axis) [N m].  spin_moment : about the roller axis,
    positive in the rolling sense [N m].  tangential_force : sum of Q_e_theta [N].
    """

    normal_left: Any
    normal_right: Any
    friction_left: Any
    friction_right: Any
    sliding_left: Any
    sliding_right: Any
    pressure_left: Any
    pressure_right: Any
    pv_left: Any
    pv_right: Any
    heat_left: Any
    heat_right: Any
    axial_force: Any
    radial_force: Any
    skew_moment: Any
    spin_moment: Any
    tangential_force: Any


def rib_forces(geom: RibGeometry, skew: Any, axial_shift: Any, *, inner_speed: float,
               cage_speed: float, roller_spin: Any, skew_rate: Any = 0.0,
               friction_coefficient: float = DEFAULT_RIB_FRICTION,
               mixture_viscosity: float = 0.0, smooth_sign: float | None = None,
               with_pressure: bool = True) -> RibForces:
    """Both end-face/rib contacts of a roller, paper 003 eqs. 1-17 and 21-24.

    Parameters
    ----------
    geom : :class:`RibGeometry`.
    skew : alpha_r [rad].  axial_shift : X_r [m] (towards the right rib).
    inner_speed, cage_speed : omega_i, omega_c [rad/s].
    roller_spin : omega_r [rad/s] (rolling sense, cage frame).
    skew_rate : alpha_dot [rad/s].
    friction_coefficient : mu of eq. 12 [-].
    mixture_viscosity : nu rho_e of eq. 14 [Pa s] (0: no drag term).
    smooth_sign : None -> the exact sign of eq. 13; a speed v_s [m/s] -> tanh(v / v_s) (for
        the integrator).
    with_pressure : compute P and PV (Hertz a, b; eq. 22-23) -- skip inside the dynamics.

    Returns
    -------
    :class:`RibForces`. Sign conventions in the module docstring. Friction is along the
    rib's velocity relative to the roller (eq. 13: C = +1 for v_i >= v_r).
    """
    check_range("friction_coefficient", friction_coefficient, 0.0, 1.0)
    check_positive("mixture_viscosity", mixture_viscosity, allow_zero=True)
    d_l, d_r = geom.approach(skew, axial_shift)
    q_l, q_r = rib_normal_force(geom, d_l), rib_normal_force(geom, d_r)
    h = geom.contact_height()
    rho = 0.5 * geom.roller_diameter - h
    v_l = rib_sliding_speed(geom, inner_speed, cage_speed, roller_spin, skew_rate, -1, h)
    v_r = rib_sliding_speed(geom, inner_speed, cage_speed, roller_spin, skew_rate, +1, h)
    if mixture_viscosity > 0.0:
        f_g, _ = lubricant_drag(geom, inner_speed, cage_speed, mixture_viscosity)
        f_g = abs(float(f_g))
    else:
        f_g = 0.0
    if smooth_sign is None:
        c_l, c_r = np.where(v_l >= 0, 1.0, -1.0), np.where(v_r >= 0, 1.0, -1.0)
    else:
        c_l, c_r = np.tanh(v_l / smooth_sign), np.tanh(v_r / smooth_sign)
    fr_l = c_l * (f_g + friction_coefficient * q_l)
    fr_r = c_r * (f_g + friction_coefficient * q_r)
    ct, st = math.cos(geom.rib_angle), math.sin(geom.rib_angle)
    arm = geom.crown_radius - 0.5 * geom.roller_length
    half = 0.5 * geom.roller_length + 0.5 * geom.axial_clearance
    sa = np.sin(np.asarray(skew, float))
    skew_moment = (-(q_l + q_r) * ct * arm * sa        # M_er, restoring (eq. 16)
                   + (fr_l - fr_r) * half)            # M_e_theta (eq. 16)
    # spin moment: eq. 16 M_e_theta_x with the friction at arm rho and the drag at the
    # mid-rib arm of eq. 17, both along the friction direction
    r_g = 0.5 * geom.roller_diameter - 0.5 * geom.rib_height
    spin_moment = (c_l * friction_coefficient * q_l + c_r * friction_coefficient * q_r) * rho \
        + (c_l + c_r) * f_g * r_g
    if with_pressure:
        rx, ry = geom.curvature(h)
        p_l = point_contact(q_l, rx, ry, geom.effective_modulus).max_pressure
        p_r = point_contact(q_r, rx, ry, geom.effective_modulus).max_pressure
    else:
        p_l = p_r = np.zeros(np.shape(q_l))
    return RibForces(
        normal_left=q_l, normal_right=q_r, friction_left=fr_l, friction_right=fr_r,
        sliding_left=v_l, sliding_right=v_r, pressure_left=p_l, pressure_right=p_r,
        pv_left=p_l * np.abs(v_l), pv_right=p_r * np.abs(v_r),
        heat_left=np.abs(fr_l * v_l), heat_right=np.abs(fr_r * v_r),
        axial_force=(q_l - q_r) * ct, radial_force=(q_l + q_r) * st,
        skew_moment=skew_moment, spin_moment=spin_moment, tangential_force=fr_l + fr_r)


def unbalance_check(unbalance_mass: float, roller_mass: float) -> None:
    """InputError unless 0 <= unbalance_mass < roller_mass [kg] (issue 9 bad input)."""
    check_positive("unbalance_mass", unbalance_mass, allow_zero=True)
    if unbalance_mass >= roller_mass:
        raise InputError("unbalance_mass", unbalance_mass,
                         f"a mass < the roller mass {roller_mass * 1e3:.4g} g")
