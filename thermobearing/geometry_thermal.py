"""Operating diametral clearance of a bearing from its component temperatures (free thermal
growth of the raceways and the rolling elements; Harris & Kotzalas 2007 vol. 1,
``harris_kotzalas2007``). SI: m, K, 1/K.
"""

from __future__ import annotations

import math
from typing import Any

from .errors import check_positive, check_temperature

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


def _ball_groove_play(bearing: Any, inner: float, outer: float, element: float) -> float:
    """Diametral clearance P_d [m] of a ball bearing from its groove and ball dimensions, the
    inner ring's scaled by ``inner``, the outer ring's by ``outer`` and the ball's by
    ``element`` (all 1: the bearing's own P_d, to round-off).

    The inverse of the groove geometry of :class:`~thermobearing.geometry_ball.BallBearing`
    (arc-centre radii and groove-bottom diameters):

        P_d = d_o - d_i - 2 [(r_o^2 - h_o^2)^(1/2) + (r_i^2 - h_i^2)^(1/2)] + 2 (e_i + e_o)

    with d the groove-bottom diameters, r = f D the groove radii and h = s/2 the half
    gothic-arch offset of each ring (0 unless four-point), and e the radial offset of a
    groove's arc centre from the ball centre, ((r - D/2)^2 - h^2)^(1/2) (four-point, deep
    groove), (r - D/2) cos(alpha) for an angular-contact ring. For single-arc grooves
    (h = 0, no angle) it reduces to d_o - d_i - 2 D.
    """
    d_ball = bearing.ball_diameter * element
    half = 0.5 * float(bearing.gothic_arch_offset or 0.0)
    play = 0.0
    for race, scale, sign in (("inner", inner, -1.0), ("outer", outer, 1.0)):
        conformity = (bearing.inner_conformity if race == "inner"
                      else bearing.outer_conformity)
        r = conformity * bearing.ball_diameter * scale
        h = half * scale
        diameter = (bearing.inner_raceway_diameter if race == "inner"
                    else bearing.outer_raceway_diameter) * scale
        if bearing.kind == "angular_contact":
            centre = (r - 0.5 * d_ball) * math.cos(bearing.contact_angle)
        else:
            centre = math.sqrt((r - 0.5 * d_ball) ** 2 - h * h)
        play += sign * diameter - 2.0 * math.sqrt(r * r - h * h) + 2.0 * centre
    return play


def _thermal_clearance(bearing: Any, inner_ring_temperature: float,
                       outer_ring_temperature: float, element_temperature: float,
                       reference_temperature: float, ring_expansion: float | None,
                       element_expansion: float | None, fit_reduction: float) -> float:
    """P_d(T) = P_d + G_r [d_o (T_o - T_0) - d_i (T_i - T_0)] - 2 G_e D (T_e - T_0) - fits
    for cylindrical raceways and single-arc ball grooves.

    Free (unconstrained) thermal growth of the rings and of the elements (Harris &
    Kotzalas 2007 vol. 1, operating clearance): every length of a part -> length (1 + G dT).
    Gothic-arch (four-point) and angular-contact grooves: P_d of the grown groove and ball
    dimensions (:func:`_ball_groove_play`); d_o - d_i - 2 D is not their clearance (0.94 mm
    against P_d = 0.1 mm for the QJ1044), and the formula above made uniform heating of the
    QJ1044 by 60 K grow its clearance by 0.67 um instead of the similar geometry's
    G P_d dT = 0.071 um. A negative result is a preload; the caller decides what to do with
    it.
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
    if getattr(bearing, "kind", None) in ("four_point", "angular_contact"):
        grown = [1.0 + g * (t - t0) for g, t in ((g_r, inner_ring_temperature),
                                                 (g_r, outer_ring_temperature),
                                                 (g_e, element_temperature))]
        grow = _ball_groove_play(bearing, *grown) - _ball_groove_play(bearing, 1.0, 1.0, 1.0)
        return float(bearing.diametral_clearance + grow - fit_reduction)
    grow = g_r * (bearing.outer_raceway_diameter * (outer_ring_temperature - t0)
                  - bearing.inner_raceway_diameter * (inner_ring_temperature - t0))
    grow -= 2.0 * g_e * bearing.element_diameter * (element_temperature - t0)
    return float(bearing.diametral_clearance + grow - fit_reduction)


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
