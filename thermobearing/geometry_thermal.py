"""Operating diametral clearance of a bearing from its component temperatures (free thermal
growth of the raceways and the rolling elements; Harris & Kotzalas 2007 vol. 1,
``harris_kotzalas2007``). SI: m, K, 1/K.
"""

from __future__ import annotations

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
