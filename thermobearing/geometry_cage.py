"""Cage geometry of a rolling bearing (:class:`CageGeometry`) and its mass estimate (SI)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import InputError, UnknownNameError, check_positive
from .materials import Material

CAGE_GUIDANCE = ("outer_ring", "inner_ring", "rolling_element")


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
