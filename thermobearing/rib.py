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

* eq. 1: ``R_p - L_p/2`` with eqs. 2-3 reduces identically to ``R_s - L_r/2``. Eq. 1 is the
  change, with skew ``alpha`` and axial shift ``X``, of the *support function* of the
  crowned end face (a sphere of radius R_s centred on the roller axis at ``x = +-(L_r/2 -
  R_s)``) in the direction of the rib normal ``n_K = (+-cos theta_f, -sin theta_f, 0)``,
  ``delta_K = h_K(alpha) - h_K(0) + (X_K - C_a/2 - C_af) cos(theta_f)``; for the sphere
  ``h_K(alpha) - h_K(0) = (R_s - L_r/2)(1 - cos alpha) cos(theta_f)``, the paper's term.
  It also gives *where* the contact is: the point of the sphere whose normal is ``n_K``,
  i.e. ``c_K + R_s m`` with ``m = R(alpha)^T n_K`` in roller axes. Its height above the
  inner raceway is eq. 11, but it moves **circumferentially** by about
  ``z_K = (R_s - L_r/2) sin(alpha)`` -- about 3 mm at the 0.6 deg skew at which a centred
  roller of the base case reaches the rib: a contact point that far from the roller axis
  slides radially at about ``omega_r R_s sin(alpha)`` over the rib (eq. 24 below). Larger
  axial clearance -> contact at larger skew -> larger offset and sliding speed (paper 003
  Fig. 9). With the paper's sphere the point may lie beyond the roller's chamfer
  (3.4 mm from the axis at the base case, flat face 2.5 mm): the paper's model, kept.
  ``end_face="cap"`` (an option, not the paper's model) bounds the sphere by the chamfer:
  a toroidal blend of radius = chamfer between the sphere and the roller's cylinder;
  beyond its edge the contact moves onto the blend (smaller curvature radius, point
  closer to the roller axis height).
* Contact normal (ours, 2026-11-24; improves eq. 1): the rib is a cone of revolution about
  the bearing axis (eq. 10 takes its circumferential curvature tan(theta_f)/(d_i/2 +
  H_contact)), so off the roller's radial plane its normal is ``n_K`` turned about the
  bearing axis by the point's angle phi = atan(z / (d_i/2 + D_w/2 + y)):
  ``n = (+-cos theta_f, -sin theta_f cos phi, -sin theta_f sin phi)``. Eq. 1's planar
  ``n_K`` at the offset point is not normal to the rib there: the rib's velocity has a
  part ``(omega_i - omega_c) sin(theta_f) z_K`` along it, so the normal force would work
  on the rib's rotation -- 0.5 % of the face's heat at 0.01 rad skew went unbooked and the
  contact's energy balance did not close. The model takes the approach as the depth of
  the face's deepest point past the cone (:func:`_support`): where the face's normal is the
  cone's normal. For the sphere that point lies in the meridional plane of the sphere's
  centre (phi = atan(z_c / (d_i/2 + D_w/2)), z_c = (R_s - L_r/2) sin alpha), at
  ``z_K = z_c - R_s sin(theta_f) sin(phi)`` and ``H_contact = D_w/2 - R_s sin(theta_f)
  cos(phi)``, and eq. 1 loses the cone's rise there,
  ``delta_K = eq. 1 - sin(theta_f)(sqrt((d_i/2 + D_w/2)^2 + z_c^2) - (d_i/2 + D_w/2))``
  (1.06 um of eq. 1's 6.4 um at 0.012 rad, base case: contact 2.6 % later in skew). The rib's
  rotation and the roller's spin (bodies of revolution about their own axes) then slide
  the surfaces within themselves: the normal force works only on the approach,
  Q d delta/dt, and power in = heat closes to round-off (tests/unit/test_prop20_rib.py).
* eq. 6 is the Hertz point-contact law Q = K delta^1.5 with the Brewe-Hamrock 1977 fits of
  eqs. 7-9. As printed, eq. 6 has the two elliptic integrals swapped: with the paper's own
  eq. 9 (Gamma = 1.0003 + 0.5968 R_x/R_y is the *second* kind E, Pi = 1.5277 + 0.6023
  ln(R_y/R_x) the *first* kind K) the consistent law is
  ``Q = (pi k E'/3) [2 R_eff Gamma (delta/Pi)^3]^(1/2)`` (Hamrock & Dowson; it inverts the
  approach delta = K [(9/(2 E R))(Q/(pi k E'))^2]^(1/3)); eq. 23 uses Gamma correctly.
* eq. 15 as printed has ``sqrt((D_w/2)^2 - (D_w/2)^2) = 0``; the consistent form is the
  area of the end-face segment covered by a rib of height h_f,
  ``int R/C_a dA = (4/3)(R_0/C_a) h_f sqrt((D_w/2)^2 - (D_w/2 - h_f)^2)`` (segment area
  ~ 4/3 x height x half chord). ``nu rho_e`` is the dynamic viscosity of the oil/air
  mixture in the gap; eq. 14 then has units Pa s x 1/s x m^2 = N.
* eq. 24 ``V' = |v_i - v_r|`` is taken as the magnitude of the *vector* difference of the
  rib and end-face velocities at the contact point, tangential to the rib (the paper gives
  no formula). In the cage frame the rib turns at ``omega_i - omega_c`` about the bearing
  axis; the roller spins at ``omega_r`` about its skewed axis and skews at ``alpha_dot``.
  At the contact point of eq. 11 (``rho = R_s sin(theta_f)`` below the roller axis; cos phi
  times that with the cone's normal) and offset ``z_K`` this gives a circumferential part
  ``(omega_i - omega_c)(d_i/2 + H_contact) - omega_r rho + alpha_dot x_K`` (the only part
  for ``alpha = 0``) and a radial part
  ``-(omega_i - omega_c) z_K - omega_r R_s cos(theta_f) sin(alpha)`` (at phi = 0), less
  the slide's part along the contact normal (the approach rate). The
  friction of eq. 12 acts along this sliding direction, so its radial part brakes the
  roller spin with the arm ``z_K`` (M_e_theta_x of eq. 16 generalised) -- the "drag of the
  rib on the roller end face" that the paper's discussion of Figs. 9, 11, 12 invokes.
* ``slide="radial_plane"`` (option): the paper's own equations place the friction and the
  sliding speed in the roller's radial plane -- eq. 16's arms are those of a
  circumferential force at (x = +-(L_p/2 + C_a/2), y = -(H_rollercm - H_contact), z = 0)
  (M_e_theta_x arm H_rollercm - H_contact, M_e_theta arm L_p/2 + C_a/2) and eq. 13's sign
  C of the scalar v_i - v_r only makes sense for collinear, circumferential speeds -- while
  the normal force keeps the offset z_K (eq. 16's M_er = Q cos(theta_f)(R_p - L_p/2)
  sin(alpha_r) is its moment with that arm). With this option the radial slide of the
  offset point is dropped: v_i - v_r = (omega_i - omega_c)(d_i/2 + H_contact) - omega_r rho
  + alpha_dot x_K, circumferential. Both PV minima of paper 003 (0.55 deg at R_s = 300 mm,
  550 mm at 0.3 deg) lie at the same R_s sin(theta_f) = 2.88 mm, i.e. at the same contact
  height, which is what this circumferential-only speed depends on.
* eq. 12-13: the drag F_G of eq. 14 acts on each face (with or without contact) along the
  circumferential sliding at the rib mid-height, arm D_w/2 - h_f/2 (eq. 17); the
  Coulomb part mu Q_ez along the sliding direction at the contact point.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, fields, replace
from typing import Any, NamedTuple

import numpy as np
from numba import njit

from .errors import (
    InputError,
    UnknownNameError,
    ValidityWarning,
    check_finite,
    check_positive,
    check_range,
)
from .hertz import point_contact, point_contact_stiffness

#: end-face shapes: the paper's sphere (eqs. 1, 11) or the sphere cap with a chamfer blend
END_FACES = ("sphere", "cap")
#: where the end-face sliding of eq. 24 is evaluated (module notes)
SLIDES = ("offset", "radial_plane")

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
    pitch_diameter : d_m [m].  chamfer : roller chamfer [m] (blend radius of ``"cap"``).
    end_face : "sphere" (paper eqs. 1, 11: the crowned face as a whole sphere) or "cap"
        (sphere cap bounded by a toroidal chamfer blend; see module notes).
    slide : "offset" (the sliding speed of eq. 24 and the friction at the skew-offset
        contact point, along the full tangential slide) or "radial_plane" (the paper's
        eqs. 11-13, 16: at the point's projection on the roller's radial plane,
        circumferential only); the normal force acts at the contact point in both
        (module notes).
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
    end_face: str = "sphere"
    slide: str = "offset"

    def __post_init__(self) -> None:
        for name in ("roller_diameter", "roller_length", "crown_radius", "rib_height",
                     "inner_raceway_diameter", "effective_modulus", "pitch_diameter"):
            check_positive(f"rib.{name}", getattr(self, name))
        check_positive("rib.axial_clearance", self.axial_clearance, allow_zero=True)
        check_range("rib.rib_angle", self.rib_angle, 0.0, math.radians(10.0), unit="rad")
        check_range("rib.chamfer", self.chamfer, 0.0, 0.5 * self.roller_diameter, unit="m")
        if self.end_face not in END_FACES:
            raise InputError("rib.end_face", self.end_face, END_FACES)
        if self.slide not in SLIDES:
            raise InputError("rib.slide", self.slide, SLIDES)
        if self.crown_radius <= 0.5 * self.roller_length:
            raise InputError("rib.crown_radius", self.crown_radius,
                             f"a value > L_r/2 = {0.5 * self.roller_length:.4g} m")
        if self.rib_height >= self.roller_diameter:
            raise InputError("rib.rib_height", self.rib_height,
                             f"a value < D_w = {self.roller_diameter:.4g} m")
        if self.end_face == "sphere":
            self._check_contact_on_roller()
        h = self.contact_height()
        if h > self.rib_height:
            raise InputError(
                "rib.rib_height", self.rib_height,
                f"a rib higher than the end-face contact point H_contact = {h * 1e3:.4g} mm "
                "(paper 003 eq. 11): the roller cannot touch the rib")

    def _check_contact_on_roller(self) -> None:
        """The end-face point that touches the rib (whole sphere, eq. 11) lies
        rho = R_s sin(theta_f) from the roller axis. Beyond the roller radius (H_contact < 0)
        it is below the inner raceway, off the roller's end face: paper 003's own maps go
        there (0.6-0.9 deg at 300 mm, 600-800 mm at 0.3 deg with D_w = 6 mm), so that is a
        ValidityWarning; beyond a roller diameter the geometry has nothing to do with a roller
        (and eq. 10's rib-cone radius d_i/2 + H_contact soon turns negative): InputError."""
        rho = self.contact_arm
        r = 0.5 * self.roller_diameter
        if rho <= r:
            return
        angle_max = math.degrees(math.asin(min(1.0, self.roller_diameter
                                                / self.crown_radius)))
        crown_max = self.roller_diameter / max(math.sin(self.rib_angle), 1e-300)
        where = (f"the end-face point that touches the rib, R_s sin(theta_f) = "
                 f"{rho * 1e3:.3g} mm from the roller axis (paper 003 eq. 11, crown radius "
                 f"{self.crown_radius * 1e3:.4g} mm, rib angle "
                 f"{math.degrees(self.rib_angle):.3g} deg)")
        if rho >= self.roller_diameter:
            raise InputError(
                "rib.rib_angle / rib.crown_radius",
                f"{math.degrees(self.rib_angle):.4g} deg / {self.crown_radius * 1e3:.4g} mm",
                f"{where} within a roller diameter D_w = {self.roller_diameter * 1e3:.4g} mm "
                f"of it: a rib angle < {angle_max:.3g} deg at this crown radius or a crown "
                f"radius < {crown_max * 1e3:.4g} mm at this rib angle (end_face='cap' keeps "
                "the contact on the face)")
        warnings.warn(ValidityWarning(
            f"rib: {where} is beyond the roller radius {r * 1e3:.3g} mm, i.e. "
            f"{(rho - r) * 1e3:.3g} mm below the inner raceway: off the roller's end face. "
            "Paper 003's whole-sphere model is extrapolated there (its Figs. 11-12 go there); "
            "end_face='cap' bounds the face by its chamfer blend"), stacklevel=4)

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
        (positive towards the right rib). Evaluated as the change of the end face's support
        function along the rib normal (module notes; identical to eq. 1 for the sphere).
        """
        a = np.asarray(skew, float)
        x = np.asarray(axial_shift, float)
        gp = self.params()
        gp[_G_CA2] = 0.5 * self.axial_clearance + float(
            np.max(self.unilateral_clearance(centre_height)))
        out = []
        for side in (-1, 1):
            sup = np.vectorize(lambda aa, s=side: _support(gp, s, aa)[0])(a)
            out.append((sup - gp[_G_S0] + (side * x - gp[_G_CA2]) * gp[_G_CT])[()])
        return out[0], out[1]

    def contact_point(self, skew: Any, side: int = 1) -> tuple[Any, Any, Any]:
        """(H_contact [m], z_K [m], on_blend) of side ``side`` at skew ``skew`` [rad].

        H_contact: height of the contact point above the inner raceway (eq. 11 for the
        sphere); z_K: its circumferential offset from the roller's radial plane
        ((R_s - L_r/2) sin alpha for the sphere); on_blend: True where a ``"cap"`` face
        touches with its chamfer blend.
        """
        gp = self.params()

        def one(aa: float) -> tuple[float, float, float]:
            _, px, py, pz, blend, _, _, _, _ = _support(gp, side, aa)
            c, s = math.cos(aa), math.sin(aa)
            return 0.5 * self.roller_diameter + py, -px * s + pz * c, blend

        h, z, b = np.vectorize(one)(np.asarray(skew, float))
        return h[()], z[()], (b > 0.5)[()]

    def params(self) -> np.ndarray:
        """Float vector of the geometry for the jitted contact (:func:`face_contact`)."""
        gp = np.zeros(_G_N)
        gp[_G_RS] = self.crown_radius
        gp[_G_HL] = 0.5 * self.roller_length
        gp[_G_R] = 0.5 * self.roller_diameter
        gp[_G_CT] = math.cos(self.rib_angle)
        gp[_G_ST] = math.sin(self.rib_angle)
        gp[_G_CA2] = 0.5 * self.axial_clearance + float(self.unilateral_clearance())
        gp[_G_RC0] = 0.5 * self.inner_raceway_diameter + 0.5 * self.roller_diameter
        gp[_G_DI2] = 0.5 * self.inner_raceway_diameter
        gp[_G_E] = self.effective_modulus
        gp[_G_RG] = 0.5 * self.roller_diameter - 0.5 * self.rib_height
        if self.end_face == "cap" and self.chamfer > 0.0:
            rc = self.chamfer
            rt = 0.5 * self.roller_diameter - rc
            gp[_G_CAP] = 1.0
            gp[_G_RCH] = rc
            gp[_G_RT] = rt
            gp[_G_XT] = math.sqrt((self.crown_radius - rc) ** 2 - rt**2)
        gp[_G_S0] = _support(gp, 1, 0.0)[0]
        gp[_G_PLANE] = 1.0 if self.slide == "radial_plane" else 0.0
        return gp

    @property
    def stiffness(self) -> float:
        """K [N/m^1.5] with Q = K delta^1.5 at zero skew (eqs. 6-10, Brewe-Hamrock fits)."""
        rx, ry = self.curvature()
        return float(point_contact_stiffness(rx, ry, self.effective_modulus,
                                             method="brewe_hamrock_1977"))


def rib_geometry(bearing: Any, **overrides: Any) -> RibGeometry:
    """:class:`RibGeometry` of a :class:`~thermobearing.geometry.RollerBearing`.

    ``overrides``: any RibGeometry field (SI), e.g. ``rib_angle=math.radians(0.5)``.
    Missing crown radius / rib height on the bearing -> InputError naming the field.
    """
    if getattr(bearing, "kind", None) != "cylindrical":
        raise InputError("bearing", getattr(bearing, "name", bearing),
                         "a cylindrical RollerBearing")
    _check_override_names("rib", overrides)
    values = {
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
    values.update(overrides)
    for key in ("crown_radius", "rib_height"):
        if values[key] is None:
            name = "end_face_crown_radius" if key == "crown_radius" else key
            raise InputError(f"bearing.{name}", None, "a value (needed by the rib contact)")
    return RibGeometry(**{k: (v if k in ("end_face", "slide") else float(v))
                          for k, v in values.items()})


def _check_override_names(field: str, overrides: dict[str, Any]) -> None:
    """UnknownNameError (listing the RibGeometry fields) for an override that is not one."""
    known = [f.name for f in fields(RibGeometry)]
    for key in overrides:
        if key not in known:
            raise UnknownNameError(f"{field}.{key}", key, known)


def with_changes(geom: RibGeometry, **changes: Any) -> RibGeometry:
    """A copy of ``geom`` with fields changed (re-validated)."""
    _check_override_names("rib", changes)
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


# indices of the geometry vector RibGeometry.params() (jitted contact)
(_G_RS, _G_HL, _G_R, _G_CT, _G_ST, _G_CA2, _G_RC0, _G_DI2, _G_E, _G_RG, _G_CAP, _G_RCH,
 _G_RT, _G_XT, _G_S0, _G_PLANE, _G_N) = range(17)
#: columns of :func:`face_contact`'s result
(F_Q, F_FX, F_FY, F_FZ, F_MSKEW, F_MSPIN, F_VT, F_VZ, F_RX, F_RY, F_H, F_Z, F_HEAT,
 F_FRZ, F_N) = range(15)


@njit(cache=True)
def _support(gp: np.ndarray, side: int, a: float
             ) -> tuple[float, float, float, float, float, float, float, float, float]:
    """(h, p_x, p_y, p_z, on_blend, sin phi, cos phi, |m_yz|, r_P) of end face ``side`` at
    skew ``a`` [rad]: the depth h [m] of its deepest point in the rib cone, that point in
    roller axes [m] (x times ``side``), the rib normal there and the point's distance r_P [m]
    from the bearing axis.

    The rib is a cone of revolution about the bearing axis (paper 003 eq. 10 takes its
    circumferential curvature tan(theta_f)/(d_i/2 + H_contact)); in a meridional half-plane
    its generator has the unit normal (side cos theta_f, -sin theta_f) in (x, r), r the
    distance from the bearing axis (rc0 = d_i/2 + D_w/2 below the roller axis). The signed
    distance of a point P (cage axes, from the roller centre) past the cone is
    ``g(P) = side cos(theta_f) P_x - sin(theta_f) (r(P) - rc0)`` plus a constant; the face's
    approach is the largest g over the face, reached where the face's outward normal is the
    cone's normal at that point, ``n = (side ct, -st cos phi, -st sin phi)``,
    phi = atan2(P_z, rc0 + P_y) the meridional angle of P. Paper 003 eq. 1 takes n in the
    roller's radial plane (phi = 0); at a skew the contact point lies z_K off that plane,
    where the rib's velocity has a part om st z_K along the planar normal, so the normal
    force would do work on the rib's rotation. With the cone's own normal the rib's rotation
    (and the roller's spin, the face being a body of revolution about its axis) slide the
    surfaces within themselves: the normal force works only on the approach,
    Q d delta/dt (module notes, "Contact normal"). For the sphere the normal passes through
    its centre, so P lies in the centre's meridional plane (phi in closed form); on the
    chamfer blend phi is iterated (contraction ~ rho/rc0 per pass, to 1e-15 rad).
    ``h - h(0)`` reduces to paper 003 eq. 1's (R_s - L_r/2)(1 - cos alpha) cos(theta_f)
    minus st (sqrt(rc0^2 + z_c^2) - rc0), z_c = (R_s - L_r/2) sin(alpha) the sphere
    centre's offset."""
    ct = gp[_G_CT]
    st = gp[_G_ST]
    rc0 = gp[_G_RC0]
    rs = gp[_G_RS]
    hl = gp[_G_HL]
    c = math.cos(a)
    s = math.sin(a)
    # sphere centre's offset: its meridional plane is the contact's on the sphere
    # (sin, cos of phi from the point's coordinates: no trigonometric calls)
    zc = -(hl - rs) * side * s
    rr = math.sqrt(zc * zc + rc0 * rc0)
    sf = zc / rr
    cf = rc0 / rr
    # rib normal in roller axes (x times side)
    mx = ct * c + side * st * sf * s
    my = -st * cf
    mz = side * ct * s - st * sf * c
    myz = math.sqrt(my * my + mz * mz)
    blend = 0.0
    if gp[_G_CAP] > 0.5 and myz * gp[_G_XT] > mx * gp[_G_RT]:
        blend = 1.0
    # the sphere: its centre's plane is exact
    px = side * (hl - rs + rs * mx)
    py = rs * my
    pz = rs * mz
    if blend < 0.5:
        # closed form: r_P = r_C - R_s st (n's radial part is -st in the centre's plane),
        # h = ct (L_r/2 - R_s) cos(a) + R_s - st (r_C - rc0)
        return (ct * (hl - rs) * c + rs - st * zc * zc / (rr + rc0), px, py, pz, 0.0, sf, cf,
                myz, rr - rs * st)
    rt = gp[_G_RT]
    rc = gp[_G_RCH]
    xt = hl - rs + gp[_G_XT]
    for _ in range(60):
        if gp[_G_CAP] > 0.5 and myz * gp[_G_XT] > mx * rt:
            px = side * (xt + rc * mx)
            py = rt * my / myz + rc * my
            pz = rt * mz / myz + rc * mz
            blend = 1.0
        else:
            px = side * (hl - rs + rs * mx)
            py = rs * my
            pz = rs * mz
            blend = 0.0
        # the point's own meridional angle
        qz = -px * s + pz * c
        qy = rc0 + py
        rr = math.sqrt(qz * qz + qy * qy)
        done = abs(qz / rr - sf) <= 1e-15
        sf = qz / rr
        cf = qy / rr
        if done:
            break
        mx = ct * c + side * st * sf * s
        my = -st * cf
        mz = side * ct * s - st * sf * c
        myz = math.sqrt(my * my + mz * mz)
    r_x = px * c + pz * s
    r_z = -px * s + pz * c
    # r(P) - rc0 without cancellation
    rp = math.sqrt((rc0 + py) ** 2 + r_z * r_z)
    dr = (py * (2.0 * rc0 + py) + r_z * r_z) / (rp + rc0)
    h = side * ct * r_x - st * dr
    return h, px, py, pz, blend, sf, cf, myz, rp


@njit(cache=True)
def _stiffness_bh(rx: float, ry: float, ep: float) -> float:
    """K [N/m^1.5] of Q = K delta^1.5, Brewe-Hamrock fits (paper 003 eqs. 6-9, consistent
    form: module notes)."""
    ratio = max(rx, ry) / min(rx, ry)
    r = 1.0 / (1.0 / rx + 1.0 / ry)
    k = max(1.0339 * ratio**0.636, 1.0)
    big_e = 1.0003 + 0.5968 / ratio
    big_k = 1.5277 + 0.6023 * math.log(ratio)
    return math.pi * k * ep * math.sqrt(2.0 * big_e * r / (9.0 * big_k**3))


@njit(cache=True)
def face_contact(gp: np.ndarray, side: int, a: float, x: float, ad: float, wr: float,
                 om: float, xd: float, mu: float, f_g: float, sreg: float) -> np.ndarray:
    """:func:`face_values` as a vector indexed by the ``F_*`` constants (jitted)."""
    out = np.empty(F_N)
    v = face_values(gp, side, a, x, ad, wr, om, xd, mu, f_g, sreg)
    for i in range(F_N):
        out[i] = v[i]
    return out


@njit(cache=True)
def _contact_radii(gp: np.ndarray, rp: float, py: float, pz: float, blend: float,
                   myz: float) -> tuple[float, float]:
    """Principal radii (R_x, R_y) [m] of the end-face / rib contact at the point
    (., py, pz) [m, roller axes] of :func:`_support`, r_P [m] from the bearing axis
    (paper 003 eqs. 1-13): on the chamfer
    blend (``blend`` > 0.5) the chamfer's radius and the blend's second principal radius
    rho/|m_yz| (the normal's run to the roller axis); on the crowned end face the sphere's
    radius combined with the rib cone's circumferential curvature, eq. 10, at the contact
    point's own distance r_P from the bearing axis (d_i/2 + H_contact in the radial plane,
    sqrt((rc0 + p_y)^2 + z_K^2) off it)."""
    if blend > 0.5:
        return gp[_G_RCH], math.sqrt(py * py + pz * pz) / myz
    rs = gp[_G_RS]
    return 1.0 / (1.0 / rs + (gp[_G_ST] / gp[_G_CT]) / rp), rs


@njit(cache=True)
def face_values(gp: np.ndarray, side: int, a: float, x: float, ad: float, wr: float,
                om: float, xd: float, mu: float, f_g: float, sreg: float, dca: float = 0.0
                ) -> tuple[float, float, float, float, float, float, float, float, float,
                           float, float, float, float, float]:
    """One end face / rib contact (paper 003 eqs. 1-17, 24), jitted scalar kernel.

    gp : :meth:`RibGeometry.params`.  side : -1 left, +1 right.  a : skew alpha [rad].
    x : axial shift X [m].  ad : skew rate [rad/s].  wr : roller spin omega_r [rad/s]
    (rolling sense).  om : omega_i - omega_c [rad/s].  xd : axial speed X' [m/s].
    mu : Coulomb coefficient [-].  f_g : lubricant drag force of eq. 14 [N] (>= 0).
    sreg : regularising speed [m/s] of the friction direction (0: exact).
    dca : approach added to both faces over cos(theta_f) [m] (the roller's tilt,
    :mod:`~thermobearing.skidding.roller_dynamics_tilt`; 0 without).

    Returns a tuple in the order of the ``F_*`` constants (no allocation: the dynamics call
    it four times per roller and RK4 step): Q_ez [N]; force on the roller
    (x axial, y radial, z circumferential) [N]; skew moment (about y) and spin moment
    (about the roller axis, rolling sense positive) [N m]; tangential sliding speed
    |v_i - v_r| (eq. 24) [m/s]; its circumferential part [m/s]; contact radii R_x, R_y [m];
    H_contact [m]; circumferential offset z_K [m]; friction heat mu Q |v| + F_G |v_g| [W];
    circumferential friction (Coulomb + drag) on the roller [N].
    """
    h, px, py, pz, blend, sf, cf, myz, rp = _support(gp, side, a)
    ct = gp[_G_CT]
    st = gp[_G_ST]
    delta = h - gp[_G_S0] + (side * x - gp[_G_CA2] + dca) * ct
    rx, ry = _contact_radii(gp, rp, py, pz, blend, myz)
    q = 0.0
    if delta > 0.0:
        q = _stiffness_bh(rx, ry, gp[_G_E]) * delta * math.sqrt(delta)
    c = math.cos(a)
    s = math.sin(a)
    # contact point from the roller centre, cage axes
    r_x = px * c + pz * s
    r_y = py
    r_z = -px * s + pz * c
    # where the sliding is evaluated and the friction acts: the contact point, or (slide =
    # "radial_plane", paper 003 eqs. 11-13, 16, 24) its projection on the roller's radial
    # plane, the friction then circumferential only
    plane = gp[_G_PLANE] > 0.5
    v_z = 0.0 if plane else r_z
    # roller angular velocity: spin about the skewed axis (rolling sense = -axis) + skew rate
    wx = -wr * c
    wy = ad
    wz = wr * s
    vrx = wy * v_z - wz * r_y + xd
    vry = wz * r_x - wx * v_z
    vrz = wx * r_y - wy * r_x
    # rib: turns at om about the bearing axis, which lies rc0 below the roller axis
    sx = -vrx
    sy = -om * v_z - vry
    sz = om * (r_y + gp[_G_RC0]) - vrz
    # the rib cone's normal at the contact point (:func:`_support`)
    nx = side * ct
    ny = -st * cf
    nz = -st * sf
    if plane:
        tx = 0.0
        ty = 0.0
        tz = sz
    else:
        sn = sx * nx + sy * ny + sz * nz
        tx = sx - sn * nx
        ty = sy - sn * ny
        tz = sz - sn * nz
    vt = math.sqrt(tx * tx + ty * ty + tz * tz)
    if sreg > 0.0:
        ff = mu * q / math.sqrt(vt * vt + sreg * sreg)
    else:
        ff = mu * q / vt if vt > 0.0 else 0.0
    # normal force -Q n at the contact point, friction at (r_x, r_y, v_z)
    qx = -q * nx
    qy = -q * ny
    fx = qx + ff * tx
    fy = qy + ff * ty
    fz = ff * tz - q * nz
    mxm = r_y * fz - v_z * ff * ty - r_z * qy
    mym = v_z * ff * tx + r_z * qx - r_x * fz
    mzm = r_x * fy - r_y * fx
    # lubricant drag (eqs. 14, 17): circumferential, at the rib mid-height of the face
    gx = side * gp[_G_HL] * c
    gy = -gp[_G_RG]
    vg = om * (gy + gp[_G_RC0]) - (wx * gy - wy * gx)
    fd = 0.0
    if f_g > 0.0:
        if sreg > 0.0:
            fd = f_g * math.tanh(vg / sreg)
        else:
            fd = f_g if vg >= 0.0 else -f_g
    mxm += gy * fd
    mym -= gx * fd
    fz += fd
    return (q, fx, fy, fz, mym, -mxm * c + mzm * s, vt, tz, rx, ry, gp[_G_R] + r_y, r_z,
            ff * vt * vt + abs(fd * vg), ff * tz + fd)


#: face sides as int64 (not Literal[int]) for the kernels that are not specialised per face
SIDE_LEFT = np.int64(-1)
SIDE_RIGHT = np.int64(1)


@njit(cache=True)
def face_squeeze(gp: np.ndarray, side: int, a: float, x: float, ad: float, xd: float,
                 eta: float, floor: float, dca: float = 0.0
                 ) -> tuple[float, float, float, float]:
    """Squeeze film of the lubricant between end face ``side`` and its rib (ours; paper 003
    has the gap's lubricant only as the drag of eq. 14): (normal force F_s [N] on the roller,
    its axial part [N], its skew moment [N m], dissipated power F_s v_n [W]).

    The end face approaches the rib along the rib cone's normal at the contact point,
    n = (side cos theta_f, -sin theta_f cos phi, -sin theta_f sin phi) (:func:`_support`),
    at v_n = d delta/dt = side cos(theta_f) X' + (n_x P_z - n_z P_x) alpha' (the rate of the
    depth of :func:`_support`, envelope theorem; the roller's spin and the rib's rotation
    move both surfaces within themselves -- bodies of revolution about their own axes --
    so they do not squeeze).
    A closing gap (v_n > 0) is opposed by the rigid-isoviscous
    Reynolds squeeze force of a sphere on a plane, F_s = 6 pi eta R_x R_y v_n / h
    (Hamrock, Schmid & Jacobson, Fundamentals of Fluid Film Lubrication, ch. 9: 6 pi eta R^2
    v / h for R_x = R_y = R; the geometric mean for the nearly circular contact of paper
    003's 300 mm crown on the conical rib, R_x/R_y = 0.95 at the base case), at the gap
    h = max(-delta, floor) (in Hertz contact the film is at its floor); an opening gap
    cavitates (no force), the rule of the cage-bar squeeze film
    (:mod:`~thermobearing.skidding.roller_dynamics_pocket`), whose film floor the dynamics
    passes here too (``dca`` [m]: the tilt's share of the approach, as in
    :func:`face_values`). eta: viscosity of the rib gap
    (eq. 14's oil/air mixture in the dynamics) [Pa s]; floor [m]. F_s acts along the Hertz
    force's line (-n at the contact point; n meets the roller axis, the face being a body of
    revolution: no spin moment); its circumferential part F_s sin(theta_f) sin(phi) (~5e-4
    F_s at 0.6 deg skew) enters the skew moment, not the pocket motion z (whose speed the rib
    kinematics leave out).
    """
    if eta <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    ct = gp[_G_CT]
    h, px, py, pz, blend, sf, _, myz, rp = _support(gp, side, a)
    c = math.cos(a)
    s = math.sin(a)
    r_x = px * c + pz * s
    r_z = -px * s + pz * c
    v_n = side * ct * xd + (side * ct * r_z + gp[_G_ST] * sf * r_x) * ad
    if v_n <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    delta = h - gp[_G_S0] + (side * x - gp[_G_CA2] + dca) * ct
    rx, ry = _contact_radii(gp, rp, py, pz, blend, myz)
    gap = max(-delta, floor)
    f_s = 6.0 * math.pi * eta * rx * ry * v_n / gap
    # along -n at the contact point: n_z = -st sin(phi) gives a circumferential part
    fx = -f_s * side * ct
    fz = f_s * gp[_G_ST] * sf
    return f_s, fx, r_z * fx - r_x * fz, f_s * v_n


@njit(cache=True)
def _squeeze_series(gp: np.ndarray, a: np.ndarray, x: np.ndarray, ad: np.ndarray,
                    xd: np.ndarray, eta: float, floor: float) -> np.ndarray:
    """:func:`face_squeeze` of both faces over 1-D arrays -> (n, 2, 4)."""
    n = a.shape[0]
    out = np.zeros((n, 2, 4))
    for i in range(n):
        fl = face_squeeze(gp, SIDE_LEFT, a[i], x[i], ad[i], xd[i], eta, floor)
        fr = face_squeeze(gp, SIDE_RIGHT, a[i], x[i], ad[i], xd[i], eta, floor)
        for q in range(4):
            out[i, 0, q] = fl[q]
            out[i, 1, q] = fr[q]
    return out


def squeeze_forces(geom: RibGeometry, skew: Any, axial_shift: Any, skew_rate: Any,
                   axial_speed: Any, viscosity: float, floor: float
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(F_s left, F_s right [N], dissipated power left, right [W]) of the rib-gap squeeze
    film of both faces (:func:`face_squeeze`) over arrays of skew [rad], X [m], skew rate
    [rad/s] and X' [m/s]; viscosity [Pa s], film floor [m]."""
    check_positive("viscosity", viscosity, allow_zero=True)
    check_positive("floor", floor)
    arrs = np.broadcast_arrays(*(np.asarray(v, float) for v in (
        skew, axial_shift, skew_rate, axial_speed)))
    shape = arrs[0].shape
    flat = [np.ascontiguousarray(v.ravel()) for v in arrs]
    res = _squeeze_series(geom.params(), flat[0], flat[1], flat[2], flat[3],
                          float(viscosity), float(floor))
    return (res[:, 0, 0].reshape(shape), res[:, 1, 0].reshape(shape),
            res[:, 0, 3].reshape(shape), res[:, 1, 3].reshape(shape))


@njit(cache=True)
def _faces(gp: np.ndarray, a: np.ndarray, x: np.ndarray, ad: np.ndarray, wr: np.ndarray,
           om: float, xd: np.ndarray, mu: float, f_g: float, sreg: float) -> np.ndarray:
    """:func:`face_contact` of both faces over 1-D arrays -> (n, 2, F_N)."""
    n = a.shape[0]
    out = np.zeros((n, 2, F_N))
    for i in range(n):
        # literal sides: face_values compiles once per face (as in the roller dynamics'
        # right-hand side), 2-4 % faster than with the side as a run-time int64 (measured)
        fl = face_contact(gp, -1, a[i], x[i], ad[i], wr[i], om, xd[i], mu, f_g, sreg)
        fr = face_contact(gp, 1, a[i], x[i], ad[i], wr[i], om, xd[i], mu, f_g, sreg)
        for q in range(F_N):    # element loop: a row assignment from an array compiles
            out[i, 0, q] = fl[q]  # numba's shape-mismatch message code (seconds)
            out[i, 1, q] = fr[q]
    return out


class RibForces(NamedTuple):
    """Forces and moments of both ribs on one roller (paper 003 eq. 16), SI.

    normal_left/right : Q_ez^K [N].  friction_left/right : circumferential friction on the
    roller, Coulomb + drag (Q_e_theta^K of eq. 12) [N].  sliding_left/right : circumferential
    part of v_i - v_r at the contact point [m/s] (eq. 13's sign).  pressure_left/right :
    P = 3Q/(2 pi a b) [Pa].  pv_left/right : P |v_i - v_r| with the full tangential sliding
    speed (eqs. 21-24) [Pa m/s].  heat_left/right : friction power [W].  axial_force : on
    the roller along +x [N].  radial_force [N].  skew_moment : about y [N m].  spin_moment :
    about the roller axis, rolling sense positive [N m].  tangential_force : sum of the
    circumferential forces [N].  slide_speed_left/right : |v_i - v_r| (eq. 24) [m/s].
    contact_height_left/right : H_contact [m].  contact_offset_left/right : z_K [m].
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
    slide_speed_left: Any = 0.0
    slide_speed_right: Any = 0.0
    contact_height_left: Any = 0.0
    contact_height_right: Any = 0.0
    contact_offset_left: Any = 0.0
    contact_offset_right: Any = 0.0


def rib_forces(geom: RibGeometry, skew: Any, axial_shift: Any, *, inner_speed: float,
               cage_speed: float, roller_spin: Any, skew_rate: Any = 0.0,
               axial_speed: Any = 0.0, friction_coefficient: float = DEFAULT_RIB_FRICTION,
               mixture_viscosity: float = 0.0, smooth_sign: float | None = None,
               with_pressure: bool = True) -> RibForces:
    """Both end-face/rib contacts of a roller, paper 003 eqs. 1-17 and 21-24.

    Parameters
    ----------
    geom : :class:`RibGeometry`.
    skew : alpha_r [rad].  axial_shift : X_r [m] (towards the right rib).
    inner_speed, cage_speed : omega_i, omega_c [rad/s].
    roller_spin : omega_r [rad/s] (rolling sense, cage frame).
    skew_rate : alpha_dot [rad/s].  axial_speed : X' [m/s].
    friction_coefficient : mu of eq. 12 [-].
    mixture_viscosity : nu rho_e of eq. 14 [Pa s] (0: no drag term).
    smooth_sign : None -> the exact direction of eq. 13; a speed v_s [m/s] -> the
        regularised direction v / sqrt(v^2 + v_s^2) (for the integrator).
    with_pressure : compute P and PV (Hertz a, b; eqs. 22-23) -- skip inside the dynamics.

    Returns
    -------
    :class:`RibForces` (arrays broadcast over the inputs). Sign conventions in the module
    docstring. Kernel: :func:`face_contact`.
    """
    check_range("friction_coefficient", friction_coefficient, 0.0, 1.0)
    check_positive("mixture_viscosity", mixture_viscosity, allow_zero=True)
    arrs = np.broadcast_arrays(*(np.asarray(v, float) for v in (
        skew, axial_shift, skew_rate, roller_spin, axial_speed)))
    shape = arrs[0].shape
    flat = [np.ascontiguousarray(v.ravel()) for v in arrs]
    names = ("skew", "axial_shift", "skew_rate", "roller_spin", "axial_speed")
    for name, v in zip(names, flat, strict=True):  # a NaN read as "no contact" before
        if not np.all(np.isfinite(v)):
            raise InputError(name, v if v.size > 1 else float(v[0]), "finite numbers")
    check_finite("inner_speed", inner_speed)
    check_finite("cage_speed", cage_speed)
    f_g = 0.0
    if mixture_viscosity > 0.0:
        f_g = abs(float(lubricant_drag(geom, inner_speed, cage_speed, mixture_viscosity)[0]))
    sreg = 0.0 if smooth_sign is None else float(smooth_sign)
    res = _faces(geom.params(), flat[0], flat[1], flat[2], flat[3],
                 float(inner_speed) - float(cage_speed), flat[4], friction_coefficient, f_g,
                 sreg)

    def col(side: int, j: int) -> Any:
        return res[:, side, j].reshape(shape)[()]

    q_l, q_r = col(0, F_Q), col(1, F_Q)
    if with_pressure:
        p_l = point_contact(q_l, col(0, F_RX), col(0, F_RY), geom.effective_modulus,
                            method="brewe_hamrock_1977").max_pressure
        p_r = point_contact(q_r, col(1, F_RX), col(1, F_RY), geom.effective_modulus,
                            method="brewe_hamrock_1977").max_pressure
    else:
        p_l = p_r = np.zeros(shape)[()]
    v_l, v_r = col(0, F_VT), col(1, F_VT)
    return RibForces(
        normal_left=q_l, normal_right=q_r, friction_left=col(0, F_FRZ),
        friction_right=col(1, F_FRZ), sliding_left=col(0, F_VZ), sliding_right=col(1, F_VZ),
        pressure_left=p_l, pressure_right=p_r, pv_left=p_l * v_l, pv_right=p_r * v_r,
        heat_left=col(0, F_HEAT), heat_right=col(1, F_HEAT),
        axial_force=col(0, F_FX) + col(1, F_FX), radial_force=col(0, F_FY) + col(1, F_FY),
        skew_moment=col(0, F_MSKEW) + col(1, F_MSKEW),
        spin_moment=col(0, F_MSPIN) + col(1, F_MSPIN),
        tangential_force=col(0, F_FZ) + col(1, F_FZ),
        slide_speed_left=v_l, slide_speed_right=v_r,
        contact_height_left=col(0, F_H), contact_height_right=col(1, F_H),
        contact_offset_left=col(0, F_Z), contact_offset_right=col(1, F_Z))


def unbalance_check(unbalance_mass: float, roller_mass: float) -> None:
    """InputError unless 0 <= unbalance_mass < roller_mass [kg] (issue 9 bad input)."""
    check_positive("unbalance_mass", unbalance_mass, allow_zero=True)
    if unbalance_mass >= roller_mass:
        raise InputError("unbalance_mass", unbalance_mass,
                         f"a mass < the roller mass {roller_mass * 1e3:.4g} g")
