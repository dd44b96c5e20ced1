"""Ball bearings (deep-groove, angular-contact, four-point): :class:`BallBearing` and its
derived quantities (raceway diameters, free contact angle, reduced radii, kinematics). SI.

Reduced radii of a ball-raceway contact (Hamrock, Schmid & Jacobson 2004, ch. 17;
``hamrock2004``):

    R_x,i = D (d_m - D cos a) / (2 d_m),   R_x,o = D (d_m + D cos a) / (2 d_m)
    R_y,k = f_k D / (2 f_k - 1)

Four-point (gothic-arch) rings: each ring has two arcs of radius f D whose curvature centres are
offset axially by +-s/2; a centred ball touches both arcs at the shim angle theta_s with
sin(theta_s) = s / ((2 f - 1) D) (``../shared/notes/over-skidding.md`` section 4, checked here
by the geometry of :meth:`BallBearing.free_contact_angle`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from scipy.optimize import brentq

from .errors import InputError, UnknownNameError, check_positive, check_range
from .geometry_cage import CageGeometry
from .geometry_common import (
    BALL_KINDS,
    RACES,
    ROLLER_KINDS,
    CharacteristicFrequencies,
    _cage_ratio,
    _check_cage_between_rings,
    _check_envelope,
    _check_rings,
    _check_roughness,
    _frequencies,
)
from .geometry_thermal import _ThermalClearance
from .materials import Material, effective_modulus


def _diagonal_free_angle(d: float, fi: float, fo: float, offset: float, clearance: float,
                         field: str = "diametral_clearance") -> float:
    """Free contact angle [rad] of a diagonal arc pair (or a single-arc groove, offset 0).

    cos(alpha_f) = [(f_i - 1/2) D cos(theta_i) + (f_o - 1/2) D cos(theta_o) - P_d/2] / A with
    sin(theta_k) = s / ((2 f_k - 1) D) and A = (f_i + f_o - 1) D (see
    :meth:`BallBearing.free_contact_angle_for`).
    """
    big_a = (fi + fo - 1.0) * d
    radial = -0.5 * clearance
    for f in (fi, fo):
        half = (f - 0.5) * d
        sin_t = offset / (2.0 * half)
        if not 0.0 <= sin_t < 1.0:
            raise InputError("bearing.gothic_arch_offset", offset,
                             f"a value < (2 f - 1) D = {2 * half:.6g} m")
        radial += half * math.sqrt(1.0 - sin_t * sin_t)
    c = radial / big_a
    if c <= 0.0:
        raise InputError(field, clearance,
                         "a clearance small enough that the balls stay in the grooves")
    return math.acos(min(c, 1.0))


@dataclass(frozen=True)
class BallBearing(_ThermalClearance):
    """A deep-groove, angular-contact or four-point-contact ball bearing (frozen, SI).

    Attributes
    ----------
    name, kind : preset name; "deep_groove" | "angular_contact" | "four_point".
    bore, outer_diameter, width : envelope [m].
    ball_diameter : D [m]. n_balls : Z. pitch_diameter : d_m [m].
    inner_conformity, outer_conformity : f_i = r_i/D, f_o = r_o/D (> 0.5).
    contact_angle : nominal contact angle [rad] (deep groove: 0, the free angle then follows
        from the clearance; angular contact: the free design angle; four-point: the free
        contact angle of a diagonal pair of arcs with the given clearance).
    diametral_clearance : P_d [m]; for a four-point bearing the additional diametral play of the
        groove arcs beyond the gothic-arch geometry.
    gothic_arch_offset : s [m], axial offset between the two arc centres of a four-point ring;
        when not given it is derived so that the free diagonal contact angle equals
        ``contact_angle``: cos(theta_s) = cos(alpha_0) + P_d/(2A), s = (2 f_i - 1) D sin(theta_s);
        when given it must reproduce ``contact_angle`` within 0.5 deg.
    ball_material, ring_material : :class:`~thermobearing.materials.Material`.
    cage : :class:`CageGeometry`.
    inner_shoulder_diameter, outer_shoulder_diameter : land diameters [m]; default
        d_m -+ 0.6 D (shoulder height about 0.1 D above the groove edge, an estimate).
    raceway_roughness, element_roughness : RMS roughness Rq of the raceways and of the
        elements [m] (optional, both or neither): the film parameter Lambda = h / (Rq_r^2 +
        Rq_e^2)^(1/2) of the run's validity checks (:mod:`thermobearing.operating_checks`).
    source : where the data come from. estimated : field -> reasoning for estimated values.
    """

    name: str
    kind: str
    bore: float
    outer_diameter: float
    width: float
    ball_diameter: float
    n_balls: int
    pitch_diameter: float
    inner_conformity: float
    outer_conformity: float
    contact_angle: float
    diametral_clearance: float
    ball_material: Material
    ring_material: Material
    cage: CageGeometry
    gothic_arch_offset: float | None = None
    inner_shoulder_diameter: float | None = None
    outer_shoulder_diameter: float | None = None
    raceway_roughness: float | None = None
    element_roughness: float | None = None
    source: str = ""
    estimated: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in BALL_KINDS:
            raise UnknownNameError("bearing.kind", self.kind, BALL_KINDS + ROLLER_KINDS)
        _check_envelope("bearing", self.bore, self.outer_diameter, self.width,
                        self.ball_diameter, "ball_diameter", self.n_balls, self.pitch_diameter,
                        "n_balls")
        for name in ("inner_conformity", "outer_conformity"):
            check_range(f"bearing.{name}", getattr(self, name), 0.5, 1.0,
                        low_inclusive=False)
        check_range("bearing.contact_angle", self.contact_angle, 0.0, math.pi / 2,
                    high_inclusive=False, unit="rad")
        if self.diametral_clearance < 0.0:  # the usual way to write a preload, not modelled
            raise InputError("bearing.diametral_clearance", self.diametral_clearance,
                             "a value >= 0 [m]: a negative clearance (preload by "
                             "interference) is not modelled; give the preload as the "
                             "schedule's axial load (the load each bearing of a preloaded "
                             "pair carries)")
        check_positive("bearing.diametral_clearance", self.diametral_clearance, allow_zero=True)
        _check_roughness(self)
        if self.kind == "four_point":
            if self.contact_angle <= 0.0:
                raise InputError("bearing.contact_angle", self.contact_angle,
                                 "a nominal contact angle > 0 for a four-point bearing")
            if self.gothic_arch_offset is None:
                object.__setattr__(self, "gothic_arch_offset", self._derive_offset())
            else:
                check_positive("bearing.gothic_arch_offset", self.gothic_arch_offset)
                limit = (2 * min(self.inner_conformity, self.outer_conformity) - 1) * (
                    self.ball_diameter)
                if self.gothic_arch_offset >= limit:
                    raise InputError("bearing.gothic_arch_offset", self.gothic_arch_offset,
                                     f"a value < (2 f - 1) D = {limit:.6g} m")
                free = self.free_contact_angle
                if abs(free - self.contact_angle) > math.radians(0.5):
                    raise InputError(
                        "bearing.gothic_arch_offset", self.gothic_arch_offset,
                        f"an offset consistent with contact_angle = "
                        f"{math.degrees(self.contact_angle):.3f} deg and the clearance (it gives "
                        f"a free contact angle of {math.degrees(free):.3f} deg); omit it to "
                        "derive it")
        elif self.gothic_arch_offset not in (None, 0.0):
            raise InputError("bearing.gothic_arch_offset", self.gothic_arch_offset,
                             "only for kind = 'four_point'")
        if self.kind == "deep_groove" and self.contact_angle != 0.0:
            raise InputError("bearing.contact_angle", self.contact_angle,
                             "0 for a deep-groove bearing (the free angle follows from the "
                             "clearance)")
        _check_rings(self)
        _check_cage_between_rings(self)

    def _derive_offset(self) -> float:
        """Arc-centre offset s [m] giving the nominal free diagonal contact angle.

        Solves (f_i - 1/2) D cos(theta_i) + (f_o - 1/2) D cos(theta_o) - P_d/2 = A cos(alpha_0)
        with sin(theta_k) = s / ((2 f_k - 1) D); for f_i = f_o this is
        cos(theta_s) = cos(alpha_0) + P_d/(2A).
        """
        d = self.ball_diameter
        big_a = self.total_curvature_distance
        target = big_a * math.cos(self.contact_angle)
        s_max = (2 * min(self.inner_conformity, self.outer_conformity) - 1) * d

        def radial(s: float) -> float:
            out = -0.5 * self.diametral_clearance - target
            for f in (self.inner_conformity, self.outer_conformity):
                half = (f - 0.5) * d
                out += half * math.sqrt(max(1.0 - (s / (2 * half)) ** 2, 0.0))
            return out

        if radial(0.0) <= 0.0:
            raise InputError("bearing.diametral_clearance", self.diametral_clearance,
                             "a clearance small enough for the nominal contact angle "
                             f"(< {2 * big_a * (1 - math.cos(self.contact_angle)):.4g} m)")
        if radial(s_max) > 0.0:
            raise InputError("bearing.contact_angle", self.contact_angle,
                             "a nominal angle reachable with these conformities and clearance")
        return float(brentq(radial, 0.0, s_max, xtol=1e-15, rtol=1e-14))

    # -- basic derived quantities ------------------------------------------------------
    @property
    def n_elements(self) -> int:
        return self.n_balls

    @property
    def element_diameter(self) -> float:
        return self.ball_diameter

    @property
    def ball_mass(self) -> float:
        """m = rho pi D^3 / 6 [kg]."""
        return self.ball_material.density * math.pi * self.ball_diameter**3 / 6.0

    @property
    def ball_inertia(self) -> float:
        """J = m D^2 / 10 [kg m^2] (solid sphere)."""
        return self.ball_mass * self.ball_diameter**2 / 10.0

    element_mass = ball_mass
    element_inertia = ball_inertia

    @property
    def effective_modulus(self) -> float:
        """E' [Pa] of the ball-ring pair (Hamrock convention)."""
        return float(effective_modulus(self.ball_material, self.ring_material))

    @property
    def cage_mass(self) -> float:
        return self.cage.effective_mass(self.ball_diameter, self.n_balls)

    def shim_angle(self, race: str = "inner") -> float:
        """theta_s [rad] of a ring: sin(theta_s) = s/((2f - 1) D); 0 for non-four-point kinds."""
        if self.kind != "four_point":
            return 0.0
        f = self._conformity(race)
        assert self.gothic_arch_offset is not None
        return math.asin(self.gothic_arch_offset / ((2 * f - 1) * self.ball_diameter))

    def _conformity(self, race: str) -> float:
        if race == "inner":
            return self.inner_conformity
        if race == "outer":
            return self.outer_conformity
        raise UnknownNameError("race", race, RACES)

    @property
    def total_curvature_distance(self) -> float:
        """A = (f_i + f_o - 1) D [m], distance between the groove curvature centres."""
        return (self.inner_conformity + self.outer_conformity - 1.0) * self.ball_diameter

    def _arc_centre_radius(self, race: str) -> float:
        """Radius [m] of a groove arc's curvature centre from the bearing axis."""
        f = self._conformity(race)
        theta = self.shim_angle(race) if self.kind == "four_point" else (
            self.contact_angle if self.kind == "angular_contact" else 0.0)
        off = (f - 0.5) * self.ball_diameter * math.cos(theta)
        if race == "inner":
            return 0.5 * self.pitch_diameter + off - 0.25 * self.diametral_clearance
        return 0.5 * self.pitch_diameter - off + 0.25 * self.diametral_clearance

    def _half_offset(self) -> float:
        return 0.5 * (self.gothic_arch_offset or 0.0)

    @property
    def inner_raceway_diameter(self) -> float:
        """Groove-bottom diameter of the inner ring [m] (d_m - D - P_d/2 for a deep groove)."""
        r = self.inner_conformity * self.ball_diameter
        return 2.0 * (self._arc_centre_radius("inner") - math.sqrt(r**2 - self._half_offset()**2))

    @property
    def outer_raceway_diameter(self) -> float:
        """Groove-bottom diameter of the outer ring [m] (d_m + D + P_d/2 for a deep groove)."""
        r = self.outer_conformity * self.ball_diameter
        return 2.0 * (self._arc_centre_radius("outer") + math.sqrt(r**2 - self._half_offset()**2))

    @property
    def inner_land_diameter(self) -> float:
        """Inner-ring shoulder diameter [m] (given, or d_m - 0.6 D as an estimate)."""
        if self.inner_shoulder_diameter is not None:
            return self.inner_shoulder_diameter
        return self.pitch_diameter - 0.6 * self.ball_diameter

    @property
    def outer_land_diameter(self) -> float:
        """Outer-ring shoulder diameter [m] (given, or d_m + 0.6 D as an estimate)."""
        if self.outer_shoulder_diameter is not None:
            return self.outer_shoulder_diameter
        return self.pitch_diameter + 0.6 * self.ball_diameter

    def contact_diameter(self, race: str, contact_angle: Any = None) -> Any:
        """Raceway diameter at the contact point [m]: d_m -+ D cos(alpha) (default nominal)."""
        a = self.contact_angle if contact_angle is None else contact_angle
        sign = -1.0 if race == "inner" else 1.0
        self._conformity(race)
        return self.pitch_diameter + sign * self.ball_diameter * np.cos(a)

    # -- contact angles ------------------------------------------------------------------
    def free_contact_angle_for(self, diametral_clearance: float) -> float:
        """Unloaded contact angle [rad] for a given diametral clearance.

        Deep groove: cos(alpha_f) = 1 - P_d/(2A) (Harris & Kotzalas 2007, vol. 1 ch. 2).
        Four-point (diagonal pair of arcs, one inner and the opposite outer arc): at zero
        clearance the centres are A apart along the shim-angle line; a clearance P_d moves them
        radially by P_d/2 and the rings shift axially until the centres are A apart again:
        cos(alpha_f) = [(f_i - 1/2) D cos(theta_i) + (f_o - 1/2) D cos(theta_o) - P_d/2] / A,
        i.e. cos(theta_s) - P_d/(2A) for equal conformities; theta = 0 gives Harris's form.
        Angular contact: the design angle (the clearance is built into it).
        """
        check_positive("diametral_clearance", diametral_clearance, allow_zero=True)
        if self.kind == "angular_contact":
            return self.contact_angle
        offset = float(self.gothic_arch_offset or 0.0) if self.kind == "four_point" else 0.0
        return _diagonal_free_angle(self.ball_diameter, self.inner_conformity,
                                    self.outer_conformity, offset, diametral_clearance)

    def with_clearance(self, diametral_clearance: float) -> BallBearing:
        """The same bearing with another diametral clearance (e.g. after fits or heating).

        Four-point: the gothic-arch offset (the ground geometry) is kept and the nominal
        contact angle becomes the new free diagonal angle. Deep groove / angular contact: only
        the clearance changes.
        """
        check_positive("diametral_clearance", diametral_clearance, allow_zero=True)
        if self.kind != "four_point":
            return replace(self, diametral_clearance=float(diametral_clearance))
        angle = self.free_contact_angle_for(diametral_clearance)
        return replace(self, diametral_clearance=float(diametral_clearance), contact_angle=angle)

    @property
    def free_contact_angle(self) -> float:
        """Unloaded contact angle [rad] with the bearing's own diametral clearance."""
        return self.free_contact_angle_for(self.diametral_clearance)

    def mounted_contact_angle(self, clearance_reduction: float) -> float:
        """Contact angle [rad] after fits/thermal growth reduce P_d by ``clearance_reduction``.

        A reduction larger than the clearance (preload) is an error here: the unloaded angle is
        undefined; use a load-distribution solve instead.
        """
        remaining = self.diametral_clearance - clearance_reduction
        if remaining < 0.0:
            raise InputError("clearance_reduction", clearance_reduction,
                             f"a value <= diametral_clearance = {self.diametral_clearance:.4g} m")
        return self.free_contact_angle_for(remaining)

    # -- curvature ------------------------------------------------------------------------
    def gamma(self, contact_angle: Any = None) -> Any:
        """gamma = D cos(alpha) / d_m (alpha default: the nominal ``contact_angle``)."""
        a = self.contact_angle if contact_angle is None else contact_angle
        return self.ball_diameter * np.cos(a) / self.pitch_diameter

    def curvature(self, race: str, contact_angle: Any = None) -> tuple[Any, Any]:
        """Reduced radii (R_x, R_y) [m] of the ball-``race`` contact at ``contact_angle`` [rad].

        R_x (rolling direction) = D (d_m -+ D cos a)/(2 d_m); R_y = f D/(2f - 1) (hamrock2004).
        Vectorised over contact_angle.
        """
        f = self._conformity(race)
        g = self.gamma(contact_angle)
        d = self.ball_diameter
        rx = 0.5 * d * (1.0 - g) if race == "inner" else 0.5 * d * (1.0 + g)
        ry = f * d / (2.0 * f - 1.0)
        return rx, np.broadcast_to(ry, np.shape(rx))[()] if np.ndim(rx) else ry

    def curvature_sum(self, race: str, contact_angle: Any = None) -> Any:
        """Sum of principal curvatures [1/m] = 1/R_x + 1/R_y."""
        rx, ry = self.curvature(race, contact_angle)
        return 1.0 / rx + 1.0 / ry

    def curvature_difference(self, race: str, contact_angle: Any = None) -> Any:
        """Harris's F(rho) = (1/R_x - 1/R_y)/(1/R_x + 1/R_y) (dimensionless)."""
        rx, ry = self.curvature(race, contact_angle)
        return (1.0 / rx - 1.0 / ry) / (1.0 / rx + 1.0 / ry)

    # -- kinematics -------------------------------------------------------------------------
    def theoretical_cage_speed_ratio(self, contact_angle: Any = None,
                                     outer_contact_angle: Any = None,
                                     control: str = "outer_race") -> Any:
        """Cage/inner-ring speed ratio of pure rolling, outer ring fixed.

        With one angle (or equal inner and outer angles): (1 - gamma)/2, gamma = D cos a / d_m
        (paper 004 section 2, omega_ct; paper 002's CSR_th). With unequal angles the ball-spin
        axis matters; the race-control limit ``control`` ("outer_race" | "inner_race") of
        :mod:`thermobearing.kinematics` is used (Jones 1960; Harris & Kotzalas 2007).
        """
        ai = self.contact_angle if contact_angle is None else contact_angle
        if outer_contact_angle is None:
            return _cage_ratio(self.gamma(ai))
        from .kinematics import race_control_cage_ratio

        return race_control_cage_ratio(self.ball_diameter / self.pitch_diameter, ai,
                                       outer_contact_angle, control)

    def summary(self) -> dict[str, tuple[float, str]]:
        """Derived quantities for tables and reports: name -> (SI value, unit)."""
        rx_i, ry_i = self.curvature("inner")
        rx_o, ry_o = self.curvature("outer")
        out = {
            "pitch_diameter": (self.pitch_diameter, "m"),
            "ball_diameter": (self.ball_diameter, "m"),
            "n_balls": (float(self.n_balls), "-"),
            "nominal_contact_angle": (self.contact_angle, "rad"),
            "free_contact_angle": (self.free_contact_angle, "rad"),
            "gamma": (float(self.gamma()), "-"),
            "theoretical_cage_speed_ratio": (float(self.theoretical_cage_speed_ratio()), "-"),
            "inner_raceway_diameter": (self.inner_raceway_diameter, "m"),
            "outer_raceway_diameter": (self.outer_raceway_diameter, "m"),
            "rx_inner": (float(rx_i), "m"), "ry_inner": (float(ry_i), "m"),
            "rx_outer": (float(rx_o), "m"), "ry_outer": (float(ry_o), "m"),
            "ball_mass": (self.ball_mass, "kg"), "ball_inertia": (self.ball_inertia, "kg*m**2"),
            "cage_mass": (self.cage_mass, "kg"),
            "effective_modulus": (self.effective_modulus, "Pa"),
        }
        if self.kind == "four_point":
            out["gothic_arch_offset"] = (float(self.gothic_arch_offset or 0.0), "m")
            out["shim_angle_inner"] = (self.shim_angle("inner"), "rad")
            out["shim_angle_outer"] = (self.shim_angle("outer"), "rad")
        return out

    def characteristic_frequencies(self, shaft_speed_hz: float, contact_angle: Any = None,
                                   cage_slip: float = 0.0,
                                   outer_speed_hz: float = 0.0) -> CharacteristicFrequencies:
        """Cage, BPFO, BPFI and ball-spin frequencies [Hz] (paper 004 f_bpo with (1 - s_c)).

        ``contact_angle`` defaults to the nominal angle (0 for a radially loaded deep-groove
        bearing, as paper 004 uses); pass ``free_contact_angle`` or an operating angle otherwise.
        """
        a = self.contact_angle if contact_angle is None else contact_angle
        return _frequencies(shaft_speed_hz, float(self.gamma(a)), self.n_balls,
                            self.pitch_diameter, self.ball_diameter, cage_slip, outer_speed_hz)
