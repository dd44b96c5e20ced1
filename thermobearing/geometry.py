"""Bearing geometry: ball and cylindrical-roller bearings, their cage, and derived quantities.

Everything is SI (m, kg, rad). Presets live in ``configs/bearings/<NAME>.toml`` and are read by
:func:`load_bearing`, which converts unit strings with :func:`thermobearing.units.to_si` and
rejects unknown keys.

Kinematic conventions (outer ring fixed unless an outer speed is given):

- gamma = D cos(alpha) / d_m (Harris & Kotzalas 2007, vol. 1 ch. 2; ``harris_kotzalas2007``).
- Epicyclic cage speed ratio with equal contact angles, CSR = (1 - gamma)/2; paper 000 eq. 40
  (``li2018_nu214_skidding``) for rollers, paper 004 section 2, omega_ct
  (``luo2022_cage_slip_vibration``) for balls. With unequal inner/outer angles the
  race-control forms of :mod:`thermobearing.kinematics` are used.
- Characteristic frequencies: BPFO = Z f_cage, BPFI = Z (f_shaft - f_cage); with cage slip
  s_c, f_cage = (1 - s_c) f_cage,th (paper 004, the f_bpo rule after its Fig. 11).

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
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from scipy.optimize import brentq

from .errors import (
    InputError,
    UnknownNameError,
    check_positive,
    check_range,
    check_temperature,
)
from .materials import Material, effective_modulus

BALL_KINDS = ("deep_groove", "angular_contact", "four_point")
ROLLER_KINDS = ("cylindrical",)
CAGE_GUIDANCE = ("outer_ring", "inner_ring", "rolling_element")
RACES = ("inner", "outer")


class CharacteristicFrequencies(NamedTuple):
    """Characteristic frequencies [Hz] (outer ring fixed unless stated).

    shaft: inner-ring rotation frequency; cage: cage (fundamental train) frequency;
    bpfo / bpfi: ball (roller) pass frequency over a point of the outer / inner ring;
    ball_spin: rotation frequency of an element about its own axis relative to the cage.
    """

    shaft: float
    cage: float
    bpfo: float
    bpfi: float
    ball_spin: float


# ---------------------------------------------------------------------------
# cage
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class CageGeometry:
    """Cage geometry.

    Attributes
    ----------
    guidance : "outer_ring" | "inner_ring" | "rolling_element"
    guide_land_diameter : diameter of the ring land the cage is centred on [m] (None for
        rolling-element guidance).
    guide_clearance : diametral clearance between the cage and the guiding land [m].
    land_width : axial width of the guiding land contact [m].
    pocket_clearance : pocket diameter (or circumferential length) minus element diameter [m].
    width : axial width of the cage [m].
    inner_diameter, outer_diameter : cage bore and outside diameter [m].
    mass : cage mass [kg]; if None, estimated from the material density and the annulus volume
        minus the pockets (see :attr:`effective_mass`).
    material : cage material (None: mass must be given).
    source : where the values come from.
    """

    guidance: str
    width: float
    inner_diameter: float
    outer_diameter: float
    pocket_clearance: float
    guide_land_diameter: float | None = None
    guide_clearance: float | None = None
    land_width: float | None = None
    mass: float | None = None
    material: Material | None = None
    source: str = ""

    def __post_init__(self) -> None:
        if self.guidance not in CAGE_GUIDANCE:
            raise UnknownNameError("cage.guidance", self.guidance, CAGE_GUIDANCE)
        for name in ("width", "inner_diameter", "outer_diameter"):
            check_positive(f"cage.{name}", getattr(self, name))
        check_positive("cage.pocket_clearance", self.pocket_clearance, allow_zero=True)
        if self.outer_diameter <= self.inner_diameter:
            raise InputError("cage.outer_diameter", self.outer_diameter,
                             f"a value > cage.inner_diameter = {self.inner_diameter}")
        if self.guidance != "rolling_element":
            for name in ("guide_land_diameter", "guide_clearance", "land_width"):
                value = getattr(self, name)
                if value is None:
                    raise InputError(f"cage.{name}", value,
                                     f"a value for a cage guided by the {self.guidance}")
                check_positive(f"cage.{name}", value)
        if self.mass is not None:
            check_positive("cage.mass", self.mass)
        elif self.material is None:
            raise InputError("cage.mass", None, "a mass, or a material to estimate it from")

    @property
    def guided_by_outer_ring(self) -> bool:
        return self.guidance == "outer_ring"

    def pocket_volume_removed(self, element_diameter: float, n_elements: int,
                              element_length: float | None = None) -> float:
        """Volume [m^3] removed by the pockets from the cage annulus (cylindrical bores)."""
        depth = 0.5 * (self.outer_diameter - self.inner_diameter)
        if element_length is None:  # round pocket of a ball cage
            area = math.pi * (element_diameter + self.pocket_clearance) ** 2 / 4.0
        else:  # rectangular pocket of a roller cage
            area = (element_diameter + self.pocket_clearance) * element_length
        return n_elements * area * depth

    def effective_mass(self, element_diameter: float, n_elements: int,
                       element_length: float | None = None) -> float:
        """Cage mass [kg]: the given mass, else rho * (annulus volume - pockets)."""
        if self.mass is not None:
            return self.mass
        assert self.material is not None
        annulus = math.pi / 4.0 * (self.outer_diameter**2 - self.inner_diameter**2) * self.width
        removed = self.pocket_volume_removed(element_diameter, n_elements, element_length)
        return self.material.density * max(annulus - removed, 0.2 * annulus)

    @property
    def mean_diameter(self) -> float:
        return 0.5 * (self.inner_diameter + self.outer_diameter)


# ---------------------------------------------------------------------------
# shared helpers
# ---------------------------------------------------------------------------
def _check_envelope(prefix: str, bore: float, outer: float, width: float, element: float,
                    element_name: str, n: int, pitch: float, count_name: str) -> None:
    for name, value in (("bore", bore), ("outer_diameter", outer), ("width", width),
                        (element_name, element), ("pitch_diameter", pitch)):
        check_positive(f"{prefix}.{name}", value)
    if outer <= bore:
        raise InputError(f"{prefix}.outer_diameter", outer, f"a value > bore = {bore}")
    section = 0.5 * (outer - bore)
    if element >= section:
        raise InputError(f"{prefix}.{element_name}", element,
                         f"a value smaller than the radial section (D - d)/2 = {section:.6g} m")
    if not bore < pitch < outer:
        raise InputError(f"{prefix}.pitch_diameter", pitch,
                         f"a value between bore {bore:.6g} m and outer diameter {outer:.6g} m")
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 3:
        raise InputError(f"{prefix}.{count_name}", n, "an integer >= 3")
    if n * element >= math.pi * pitch:
        raise InputError(f"{prefix}.{count_name}", n,
                         f"at most {int(math.pi * pitch / element)} elements of diameter "
                         f"{element:.6g} m on the pitch circle (they would overlap)")


def _check_rings(bearing: Any) -> None:
    """The raceways must lie inside the ring envelope (rings of positive thickness)."""
    if bearing.inner_raceway_diameter <= bearing.bore:
        raise InputError("bearing.pitch_diameter", bearing.pitch_diameter,
                         f"a value leaving an inner ring: raceway diameter "
                         f"{bearing.inner_raceway_diameter:.6g} m <= bore {bearing.bore:.6g} m")
    if bearing.outer_raceway_diameter >= bearing.outer_diameter:
        raise InputError("bearing.pitch_diameter", bearing.pitch_diameter,
                         f"a value leaving an outer ring: raceway diameter "
                         f"{bearing.outer_raceway_diameter:.6g} m >= outer diameter "
                         f"{bearing.outer_diameter:.6g} m")


def _cage_ratio(gamma: Any) -> Any:
    """Epicyclic cage/inner-ring speed ratio (1 - gamma)/2 (outer ring fixed)."""
    return 0.5 * (1.0 - gamma)


def _frequencies(shaft_hz: float, gamma: float, n: int, pitch: float, element: float,
                 cage_slip: float, outer_hz: float) -> CharacteristicFrequencies:
    """Frequencies of an epicyclic set with cage slip (paper 004, f_bpo with (1 - s_c)).

    f_cage = (1 - s_c) [f_i (1 - gamma) + f_o (1 + gamma)] / 2; BPFO = Z |f_cage - f_o|;
    BPFI = Z |f_i - f_cage|; element spin relative to the cage from rolling on the outer race
    (which the cage slip leaves intact in paper 004's picture): f_spin = |f_cage - f_o| d_m
    (1 + gamma) / D; with s_c = 0 this is Harris's (d_m / 2D) f_i (1 - gamma^2).
    """
    check_range("cage_slip", cage_slip, -1.0, 1.0, low_inclusive=False, high_inclusive=False)
    check_positive("shaft_speed_hz", shaft_hz, allow_zero=True)
    cage = (1.0 - cage_slip) * 0.5 * (shaft_hz * (1.0 - gamma) + outer_hz * (1.0 + gamma))
    bpfo = n * abs(cage - outer_hz)
    bpfi = n * abs(shaft_hz - cage)
    spin = abs(cage - outer_hz) * pitch * (1.0 + gamma) / element
    return CharacteristicFrequencies(shaft_hz, cage, bpfo, bpfi, spin)


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


#: Linear thermal expansion coefficient of through-hardened bearing steel [1/K] used when a
#: material carries none: about 11.9e-6 1/K for AISI 52100 between 20 and 100 degC (a typical
#: handbook value, recalled; bearing steels lie within 11-12.5e-6 1/K).
STEEL_EXPANSION = 11.9e-6


def _expansion(material: Any, given: float | None) -> float:
    if given is not None:
        check_positive("expansion_coefficient", given, allow_zero=True)
        return float(given)
    value = getattr(material, "thermal_expansion", None)
    return float(value) if value is not None else STEEL_EXPANSION


def _thermal_clearance(bearing: Any, inner_ring_temperature: float,
                       outer_ring_temperature: float, element_temperature: float,
                       reference_temperature: float, ring_expansion: float | None,
                       element_expansion: float | None, fit_reduction: float) -> float:
    """P_d(T) = P_d + G_r [d_o (T_o - T_0) - d_i (T_i - T_0)] - 2 G_e D (T_e - T_0) - fits.

    Free (unconstrained) thermal growth of the raceway diameters and of the elements
    (Harris & Kotzalas 2007 vol. 1, operating clearance): d -> d (1 + G dT). A negative
    result is a preload; the caller decides what to do with it.
    """
    for name, t in (("inner_ring_temperature", inner_ring_temperature),
                    ("outer_ring_temperature", outer_ring_temperature),
                    ("element_temperature", element_temperature),
                    ("reference_temperature", reference_temperature)):
        check_temperature(name, t)
    check_positive("fit_reduction", fit_reduction, allow_zero=True)
    g_r = _expansion(bearing.ring_material, ring_expansion)
    elem_mat = getattr(bearing, "ball_material", None) or bearing.roller_material
    g_e = _expansion(elem_mat, element_expansion)
    t0 = reference_temperature
    grow = g_r * (bearing.outer_raceway_diameter * (outer_ring_temperature - t0)
                  - bearing.inner_raceway_diameter * (inner_ring_temperature - t0))
    grow -= 2.0 * g_e * bearing.element_diameter * (element_temperature - t0)
    return float(bearing.diametral_clearance + grow - fit_reduction)


# ---------------------------------------------------------------------------
# ball bearings
# ---------------------------------------------------------------------------
class _ThermalClearance:
    """Operating clearance of a bearing from its component temperatures (shared by both
    bearing classes)."""

    def operating_clearance(self, inner_ring_temperature: float, outer_ring_temperature: float,
                            element_temperature: float, reference_temperature: float = 293.15,
                            *, ring_expansion: float | None = None,
                            element_expansion: float | None = None,
                            fit_reduction: float = 0.0) -> float:
        """Diametral clearance [m] at the given component temperatures [K].

        P_d + G_r [d_o (T_o - T_0) - d_i (T_i - T_0)] - 2 G_e D (T_e - T_0) - fit_reduction,
        free thermal growth (Harris & Kotzalas 2007); expansion coefficients [1/K] default to the
        materials' ``thermal_expansion`` if present, else :data:`STEEL_EXPANSION`. Negative =
        preload.
        """
        return _thermal_clearance(self, inner_ring_temperature, outer_ring_temperature,
                                  element_temperature, reference_temperature, ring_expansion,
                                  element_expansion, fit_reduction)


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
        check_positive("bearing.diametral_clearance", self.diametral_clearance, allow_zero=True)
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


# ---------------------------------------------------------------------------
# roller bearings
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class RollerBearing(_ThermalClearance):
    """A cylindrical roller bearing (frozen, SI).

    Attributes
    ----------
    name, kind : preset name; "cylindrical".
    bore, outer_diameter, width : envelope [m].
    roller_diameter, roller_length : D_w, L_r [m] (total length).
    roller_effective_length : straight (load-carrying) length l [m] (default: roller_length).
    n_rollers : Z. pitch_diameter : d_m [m]. diametral_clearance : P_d [m].
    crown_radius : axial crown radius of the roller generatrix [m] (None: straight roller).
    end_face_crown_radius : R_s, crown radius of the roller end face [m] (paper 003 eq. 2).
    rib_angle : theta_f, inclination of the rib face [rad] (paper 003 eq. 4).
    axial_clearance : C_a, roller-rib axial clearance [m] (paper 003 eq. 1).
    rib_height : h_f, rib height above the raceway [m] (paper 003 eq. 15).
    ribbed_ring : "inner" | "outer" | "both" -- which ring guides the rollers axially.
    roller_material, ring_material, cage, source, estimated : as for :class:`BallBearing`.
    """

    name: str
    kind: str
    bore: float
    outer_diameter: float
    width: float
    roller_diameter: float
    roller_length: float
    n_rollers: int
    pitch_diameter: float
    diametral_clearance: float
    roller_material: Material
    ring_material: Material
    cage: CageGeometry
    roller_effective_length: float | None = None
    crown_radius: float | None = None
    end_face_crown_radius: float | None = None
    rib_angle: float = 0.0
    axial_clearance: float = 0.0
    rib_height: float | None = None
    ribbed_ring: str = "outer"
    source: str = ""
    estimated: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in ROLLER_KINDS:
            raise UnknownNameError("bearing.kind", self.kind, BALL_KINDS + ROLLER_KINDS)
        _check_envelope("bearing", self.bore, self.outer_diameter, self.width,
                        self.roller_diameter, "roller_diameter", self.n_rollers,
                        self.pitch_diameter, "n_rollers")
        check_positive("bearing.roller_length", self.roller_length)
        if self.roller_length > self.width:
            raise InputError("bearing.roller_length", self.roller_length,
                             f"a value <= width = {self.width:.6g} m")
        if self.roller_effective_length is None:
            object.__setattr__(self, "roller_effective_length", self.roller_length)
        check_positive("bearing.roller_effective_length", self.roller_effective_length)
        if self.roller_effective_length > self.roller_length:
            raise InputError("bearing.roller_effective_length", self.roller_effective_length,
                             f"a value <= roller_length = {self.roller_length:.6g} m")
        check_positive("bearing.diametral_clearance", self.diametral_clearance, allow_zero=True)
        for name in ("crown_radius", "end_face_crown_radius", "rib_height"):
            if getattr(self, name) is not None:
                check_positive(f"bearing.{name}", getattr(self, name))
        check_range("bearing.rib_angle", self.rib_angle, 0.0, math.pi / 4, unit="rad")
        check_positive("bearing.axial_clearance", self.axial_clearance, allow_zero=True)
        if self.ribbed_ring not in ("inner", "outer", "both"):
            raise UnknownNameError("bearing.ribbed_ring", self.ribbed_ring,
                                   ("inner", "outer", "both"))
        _check_rings(self)

    contact_angle = 0.0

    @property
    def n_elements(self) -> int:
        return self.n_rollers

    @property
    def element_diameter(self) -> float:
        return self.roller_diameter

    @property
    def roller_mass(self) -> float:
        """m = rho pi D_w^2 L_r / 4 [kg] (chamfers neglected)."""
        return (self.roller_material.density * math.pi * self.roller_diameter**2
                * self.roller_length / 4.0)

    @property
    def roller_inertia(self) -> float:
        """Polar moment about the roller axis, J = m D_w^2 / 8 [kg m^2]."""
        return self.roller_mass * self.roller_diameter**2 / 8.0

    @property
    def roller_transverse_inertia(self) -> float:
        """Moment about a diameter through the centre, m (3 r^2 + L^2)/12 [kg m^2]."""
        r = 0.5 * self.roller_diameter
        return self.roller_mass * (3.0 * r**2 + self.roller_length**2) / 12.0

    element_mass = roller_mass
    element_inertia = roller_inertia

    @property
    def effective_modulus(self) -> float:
        """E' [Pa] of the roller-ring pair (Hamrock convention)."""
        return float(effective_modulus(self.roller_material, self.ring_material))

    @property
    def cage_mass(self) -> float:
        return self.cage.effective_mass(self.roller_diameter, self.n_rollers, self.roller_length)

    @property
    def inner_raceway_diameter(self) -> float:
        """d_i = d_m - D_w - P_d/2 [m] (Harris & Kotzalas 2007, vol. 1 ch. 2)."""
        return self.pitch_diameter - self.roller_diameter - 0.5 * self.diametral_clearance

    @property
    def outer_raceway_diameter(self) -> float:
        """d_o = d_m + D_w + P_d/2 [m]."""
        return self.pitch_diameter + self.roller_diameter + 0.5 * self.diametral_clearance

    @property
    def _rib_height_or_estimate(self) -> float:
        """Rib height [m]: given, or 0.2 D_w as an estimate (typical rib of a cylindrical
        roller bearing; used only for land diameters and the cavity volume)."""
        return self.rib_height if self.rib_height is not None else 0.2 * self.roller_diameter

    @property
    def inner_land_diameter(self) -> float:
        """Inner-ring land (rib or raceway) diameter [m]: d_i + 2 h_f on a ribbed inner ring,
        the raceway diameter otherwise."""
        ribbed = self.ribbed_ring in ("inner", "both")
        return self.inner_raceway_diameter + (2.0 * self._rib_height_or_estimate if ribbed
                                              else 0.0)

    @property
    def outer_land_diameter(self) -> float:
        """Outer-ring land (rib or raceway) diameter [m]: d_o - 2 h_f on a ribbed outer ring,
        the raceway diameter otherwise."""
        ribbed = self.ribbed_ring in ("outer", "both")
        return self.outer_raceway_diameter - (2.0 * self._rib_height_or_estimate if ribbed
                                              else 0.0)

    @property
    def roller_centre_height(self) -> float:
        """H_rollercm: distance from the roller centre to the inner raceway [m] (paper 003)."""
        return 0.5 * self.roller_diameter

    @property
    def rib_axial_clearance(self) -> float:
        """C_af = (H_rollercm - D_w/2) tan(theta_f) [m] (paper 003 eq. 4).

        With the roller centre on the pitch circle H_rollercm = D_w/2 and C_af = 0; the paper's
        H_rollercm includes the roller's radial displacement, so pass a displaced height to
        :meth:`rib_axial_clearance_at`.
        """
        return self.rib_axial_clearance_at(self.roller_centre_height)

    def rib_axial_clearance_at(self, centre_height: Any) -> Any:
        """C_af for a roller centre ``centre_height`` [m] above the raceway (paper 003 eq. 4)."""
        return (np.asarray(centre_height) - 0.5 * self.roller_diameter) * math.tan(
            self.rib_angle)

    def contact_diameter(self, race: str, contact_angle: Any = None) -> float:
        """Raceway diameter at the contact [m]: d_m -+ D_w."""
        if race not in RACES:
            raise UnknownNameError("race", race, RACES)
        return self.inner_raceway_diameter if race == "inner" else self.outer_raceway_diameter

    def gamma(self, contact_angle: Any = None) -> float:
        """gamma = D_w / d_m."""
        return self.roller_diameter / self.pitch_diameter

    def curvature(self, race: str, contact_angle: Any = None) -> tuple[float, float]:
        """(R_x, R_y) [m]: R_x = D_w (d_m -+ D_w)/(2 d_m); R_y = crown radius (inf if straight)."""
        if race not in RACES:
            raise UnknownNameError("race", race, RACES)
        g = self.gamma()
        rx = 0.5 * self.roller_diameter * (1.0 - g if race == "inner" else 1.0 + g)
        return rx, (math.inf if self.crown_radius is None else self.crown_radius)

    def curvature_sum(self, race: str, contact_angle: Any = None) -> float:
        rx, ry = self.curvature(race)
        return 1.0 / rx + 1.0 / ry

    def theoretical_cage_speed_ratio(self, contact_angle: Any = None,
                                     outer_contact_angle: Any = None,
                                     control: str = "outer_race") -> float:
        """(1 - D_w/d_m)/2, paper 000 eq. 40 (n_m = n_i (1 - D_b/d_m)/2)."""
        return _cage_ratio(self.gamma())

    def summary(self) -> dict[str, tuple[float, str]]:
        """Derived quantities for tables and reports: name -> (SI value, unit)."""
        rx_i, ry_i = self.curvature("inner")
        rx_o, _ = self.curvature("outer")
        return {
            "pitch_diameter": (self.pitch_diameter, "m"),
            "roller_diameter": (self.roller_diameter, "m"),
            "roller_effective_length": (float(self.roller_effective_length or 0.0), "m"),
            "n_rollers": (float(self.n_rollers), "-"),
            "gamma": (self.gamma(), "-"),
            "theoretical_cage_speed_ratio": (self.theoretical_cage_speed_ratio(), "-"),
            "inner_raceway_diameter": (self.inner_raceway_diameter, "m"),
            "outer_raceway_diameter": (self.outer_raceway_diameter, "m"),
            "rx_inner": (rx_i, "m"), "rx_outer": (rx_o, "m"), "ry": (ry_i, "m"),
            "roller_mass": (self.roller_mass, "kg"), "roller_inertia": (self.roller_inertia,
                                                                       "kg*m**2"),
            "cage_mass": (self.cage_mass, "kg"),
            "effective_modulus": (self.effective_modulus, "Pa"),
        }

    def characteristic_frequencies(self, shaft_speed_hz: float, contact_angle: Any = None,
                                   cage_slip: float = 0.0,
                                   outer_speed_hz: float = 0.0) -> CharacteristicFrequencies:
        """Cage, BPFO, BPFI and roller-spin frequencies [Hz] with optional cage slip."""
        return _frequencies(shaft_speed_hz, self.gamma(), self.n_rollers, self.pitch_diameter,
                            self.roller_diameter, cage_slip, outer_speed_hz)


Bearing = BallBearing | RollerBearing


# ---------------------------------------------------------------------------
# loading presets (implementation in :mod:`thermobearing.bearing_config`)
# ---------------------------------------------------------------------------
def configs_dir() -> Path:
    """The repository's ``configs`` folder."""
    from .bearing_config import configs_dir as _f

    return _f()


def preset_names() -> list[str]:
    """Names of the bearing presets in ``configs/bearings``."""
    from .bearing_config import preset_names as _f

    return _f()


def bearing_from_dict(data: Mapping[str, Any], *, origin: str = "bearing") -> Bearing:
    """Build a bearing from a config mapping (unit strings allowed); unknown keys are errors."""
    from .bearing_config import bearing_from_dict as _f

    return _f(data, origin=origin)


def load_bearing(name_or_path: str | Path,
                 overrides: Mapping[str, Any] | None = None) -> Bearing:
    """Load a bearing from a preset name (``"QJ1044"``) or a TOML path.

    ``overrides`` replaces top-level keys (unit strings allowed, e.g.
    ``{"diametral_clearance": "0.1 mm"}``) before the bearing is built. For a four-point preset
    with a gothic-arch offset, overriding only the clearance keeps the offset and lets the
    contact angle follow (as :meth:`BallBearing.with_clearance`). Unknown keys, unknown presets
    and bad values raise :class:`~thermobearing.errors.InputError`.
    """
    from .bearing_config import load_bearing as _f

    return _f(name_or_path, overrides)
