"""Cylindrical roller bearings: :class:`RollerBearing` and its derived quantities (raceway and
land diameters, rib geometry of paper 003, reduced radii, kinematics). SI.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

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
    raceway_roughness, element_roughness : RMS roughness Rq of the raceways and of the
        elements [m] (optional, both or neither): the film parameter Lambda = h / (Rq_r^2 +
        Rq_e^2)^(1/2) of the run's validity checks (:mod:`thermobearing.operating_checks`).
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
    raceway_roughness: float | None = None
    element_roughness: float | None = None
    source: str = ""
    estimated: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.kind not in ROLLER_KINDS:
            raise UnknownNameError("bearing.kind", self.kind, BALL_KINDS + ROLLER_KINDS)
        _check_envelope("bearing", self.bore, self.outer_diameter, self.width,
                        self.roller_diameter, "roller_diameter", self.n_rollers,
                        self.pitch_diameter, "n_rollers")
        check_positive("bearing.roller_length", self.roller_length)
        _check_roughness(self)
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
        _check_cage_between_rings(self)

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
