"""Materials of rings, rolling elements and cages, and the effective elastic modulus.

All values SI: Young's modulus [Pa], density [kg/m^3], specific heat [J/(kg K)], thermal
conductivity [W/(m K)]. Every preset names its source; values not taken from a source are
listed in its ``estimated`` mapping with the reasoning.

Convention (contract): E' = 2 / ((1 - v1^2)/E1 + (1 - v2^2)/E2) (Hamrock 2004, ch. 3;
twice Johnson's E*).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

import numpy as np

from .errors import InputError, UnknownNameError, check_positive, check_range


class ReadOnlyTable(dict):
    """A dict that refuses changes (TypeError) but copies and pickles as one: the
    ``estimated`` table of a shared material preset."""

    def _read_only(self, *args, **kwargs):
        raise TypeError("a material's estimated table is read-only (the presets are shared); "
                        "build a new Material with dataclasses.replace(..., estimated={...})")

    __setitem__ = __delitem__ = __ior__ = _read_only
    clear = pop = popitem = setdefault = update = _read_only

    def __reduce__(self):
        return (type(self), (dict(self),))


@dataclass(frozen=True)
class Material:
    """An isotropic solid.

    Attributes
    ----------
    name : preset name.
    youngs_modulus : E [Pa].
    poisson_ratio : nu [-], in (-1, 0.5).
    density : rho [kg/m^3].
    specific_heat : c [J/(kg K)].
    thermal_conductivity : k [W/(m K)].
    source : where the numbers come from.
    estimated : field -> reasoning, for values not taken from ``source``.
    """

    name: str
    youngs_modulus: float
    poisson_ratio: float
    density: float
    specific_heat: float
    thermal_conductivity: float
    source: str
    estimated: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        # a read-only copy: the presets are module-level objects shared by every bearing
        # that names them, so a mutable mapping would let one caller's edit leak into the
        # next load (no global mutable state)
        object.__setattr__(self, "estimated", ReadOnlyTable(self.estimated))
        check_positive(f"{self.name}.youngs_modulus", self.youngs_modulus)
        check_range(f"{self.name}.poisson_ratio", self.poisson_ratio, -1.0, 0.5,
                    low_inclusive=False, high_inclusive=False)
        check_positive(f"{self.name}.density", self.density)
        check_positive(f"{self.name}.specific_heat", self.specific_heat)
        check_positive(f"{self.name}.thermal_conductivity", self.thermal_conductivity)

    def __hash__(self) -> int:  # ``estimated`` is a mapping; hash the numbers and the name
        return hash((self.name, self.youngs_modulus, self.poisson_ratio, self.density,
                     self.specific_heat, self.thermal_conductivity, self.source))

    @property
    def thermal_diffusivity(self) -> float:
        """k / (rho c) [m^2/s]."""
        return self.thermal_conductivity / (self.density * self.specific_heat)

    @property
    def plane_strain_modulus(self) -> float:
        """E / (1 - nu^2) [Pa]; E' of two identical bodies."""
        return self.youngs_modulus / (1.0 - self.poisson_ratio**2)


def effective_modulus_from(E1: float, nu1: float, E2: float, nu2: float) -> float:
    """Hamrock's effective modulus E' [Pa] from two (E [Pa], nu [-]) pairs.

    .. math:: E' = \\frac{2}{(1-\\nu_1^2)/E_1 + (1-\\nu_2^2)/E_2}

    Hamrock, Schmid & Jacobson 2004, ch. 3 ("effective elastic modulus"); equals
    2 E* of Johnson 1985 eq. 4.22. Vectorised over numpy arrays.
    """
    for f, v in (("E1", E1), ("E2", E2)):
        check_positive(f, v)
    for f, v in (("nu1", nu1), ("nu2", nu2)):
        check_range(f, v, -1.0, 0.5, low_inclusive=False, high_inclusive=False)
    out = 2.0 / ((1.0 - np.asarray(nu1) ** 2) / E1 + (1.0 - np.asarray(nu2) ** 2) / E2)
    return float(out) if np.ndim(out) == 0 else out


def effective_modulus(m1: Material, m2: Material) -> float:
    """E' [Pa] of a contact between materials ``m1`` and ``m2`` (Hamrock convention).

    Example: 52100 on 52100 (E = 203.4 GPa, nu = 0.3): E' = E/(1 - nu^2) = 223.5 GPa.
    """
    if not isinstance(m1, Material) or not isinstance(m2, Material):
        raise InputError("material", (m1, m2), "two Material objects (see get_material)")
    return effective_modulus_from(m1.youngs_modulus, m1.poisson_ratio,
                                  m2.youngs_modulus, m2.poisson_ratio)


# ---------------------------------------------------------------------------
# presets
# ---------------------------------------------------------------------------
STEEL_52100 = Material(
    name="STEEL_52100",
    youngs_modulus=29.5e6 * 6894.757,  # 29.5e6 psi = 203.4 GPa
    poisson_ratio=0.30,
    density=0.283 * 27679.9,  # 0.283 lb/in^3 = 7833 kg/m^3
    specific_heat=470.0,
    thermal_conductivity=47.0,
    source="AISI 52100 (GCr15, 100Cr6) through-hardened bearing steel: E = 29.5e6 psi and "
    "density 0.283 lb/in^3 from a ball manufacturer's 52100 data sheet; nu = 0.3 as in "
    "paper 004 Table 1 and paper 001 Table 1; c = 470 J/(kg K) and k = 47 W/(m K) from the "
    "MakeItFrom SAE-AISI 52100 data sheet",
    estimated={
        "thermal_conductivity": "the data-sheet value is not specific to the hardened "
        "condition; hardened 52100 is also quoted near 40 W/(m K)",
    },
)

GCR15 = replace(
    STEEL_52100,
    name="GCR15",
    source="GB/T 18254 GCr15 is the Chinese designation of AISI 52100 (1C-1.5Cr); same "
    "values as STEEL_52100",
)

M50 = Material(
    name="M50",
    youngs_modulus=190e9,
    poisson_ratio=0.29,
    density=7900.0,
    specific_heat=470.0,
    thermal_conductivity=35.0,
    source="AMS 6491 / SAE-AISI M50 (80MoCrV42-16, Cr4Mo4V) aero-engine bearing steel: "
    "E, nu, density, c and k from the MakeItFrom data sheet 'Annealed M50 Tool Steel'",
    estimated={
        "condition": "the data sheet is for the annealed condition; through-hardened bearing "
        "M50 has a somewhat lower k (the hardened M52 sheet of the same source gives 31 "
        "W/(m K)) and E is usually quoted near 200 GPa in bearing work",
    },
)

SILICON_NITRIDE = Material(
    name="SILICON_NITRIDE",
    youngs_modulus=310e9,
    poisson_ratio=0.27,
    density=3200.0,
    specific_heat=750.0,
    thermal_conductivity=29.0,
    source="hot-isostatically-pressed bearing-grade Si3N4 (ASTM F2094 class): E about 310 GPa "
    "and density about 3.2 g/cm^3 as quoted for hybrid-bearing balls (Harris & Kotzalas "
    "2007, vol. 1, materials chapter); c = 750 J/(kg K) for hot-pressed Si3N4 from "
    "Callister, Materials Science and Engineering, Table B.8",
    estimated={
        "poisson_ratio": "0.26-0.28 in manufacturer data; 0.27 taken",
        "thermal_conductivity": "25-35 W/(m K) in manufacturer data; 29 taken",
    },
)

BRASS = Material(
    name="BRASS",
    youngs_modulus=100e9,
    poisson_ratio=0.34,
    density=0.306 * 27679.9,  # 0.306 lb/in^3 = 8470 kg/m^3
    specific_heat=0.096 * 4186.8,  # 0.096 Btu/(lb F) = 402 J/(kg K)
    thermal_conductivity=69.33 * 1.730735,  # 69.33 Btu/(h ft F) = 120 W/(m K)
    source="machined-cage brass: yellow-brass density, specific heat and conductivity "
    "from the Engineers Edge table 'Thermal properties of metals' (0.306 lb/in^3, "
    "0.096 Btu/(lb F), 69.33 Btu/(h ft F))",
    estimated={
        "youngs_modulus": "97-105 GPa for alpha-beta brasses in handbooks; 100 taken",
        "poisson_ratio": "typical of brasses (0.33-0.35)",
    },
)

STEEL_LOW_CARBON = Material(
    name="STEEL_LOW_CARBON",
    youngs_modulus=200e9,
    poisson_ratio=0.29,
    density=7832.0,
    specific_heat=434.0,
    thermal_conductivity=63.9,
    source="low-carbon sheet steel of pressed cages (AISI 1010 class): density, c_p and k "
    "at 300 K from Incropera et al., Fundamentals of Heat and Mass Transfer, Table A.1 "
    "(AISI 1010)",
    estimated={
        "youngs_modulus": "200 GPa: typical of plain carbon steels (not in Incropera's table)",
        "poisson_ratio": "0.29: typical of plain carbon steels",
    },
)

PEEK = Material(
    name="PEEK",
    youngs_modulus=3.6e9,
    poisson_ratio=0.40,
    density=1300.0,
    specific_heat=1340.0,
    thermal_conductivity=0.25,
    source="unfilled PEEK (polyether ether ketone) cage material: typical datasheet values",
    estimated={
        "all": "typical unfilled-PEEK datasheet values (E 3.5-4 GPa, rho 1.30 g/cm^3, "
        "k 0.25 W/(m K)); glass- or carbon-filled cage grades differ",
    },
)

PAPER001_STEEL = Material(
    name="PAPER001_STEEL",
    youngs_modulus=218e9,
    poisson_ratio=0.3,
    density=7870.0,
    specific_heat=460.0,
    thermal_conductivity=15.0,
    source="Shi & Wang 2015 (seed paper 001) Table 1, roller and race of D1842926: "
    "E = 218 GPa, nu = 0.3, rho = 7870 kg/m^3, c = 460 J/(kg degC), k = 15 W/(m degC)",
)

PAPER001_CAGE = replace(
    PAPER001_STEEL,
    name="PAPER001_CAGE",
    youngs_modulus=209e9,
    source="Shi & Wang 2015 (seed paper 001) Table 1, cage of D1842926: E = 209 GPa, "
    "nu = 0.3, rho = 7870 kg/m^3",
    estimated={
        "specific_heat": "not given for the cage in paper 001; the table's single value "
        "(460 J/(kg degC)) taken",
        "thermal_conductivity": "not given for the cage in paper 001; the table's single "
        "value (15 W/(m degC)) taken",
    },
)

PAPER000_STEEL = Material(
    name="PAPER000_STEEL",
    youngs_modulus=2.28e11 * (1.0 - 0.3**2),
    poisson_ratio=0.3,
    density=7800.0,
    specific_heat=STEEL_52100.specific_heat,
    thermal_conductivity=STEEL_52100.thermal_conductivity,
    source="Li et al. 2018 (seed paper 000) Table 1: E' = 2.28e11 Pa and roller density "
    "7800 kg/m^3; E = E'(1 - nu^2) so that two such bodies give E' = 2.28e11 Pa",
    estimated={
        "poisson_ratio": "paper 000 gives only E'; nu = 0.3 assumed (bearing steel)",
        "specific_heat": "not in paper 000; 52100 value",
        "thermal_conductivity": "not in paper 000; 52100 value",
    },
)

PAPER004_STEEL = replace(
    STEEL_52100,
    name="PAPER004_STEEL",
    youngs_modulus=2.07e11,
    poisson_ratio=0.3,
    source="Luo et al. 2022 (seed paper 004) Table 1: bearing steel E = 2.07e11 Pa, nu = 0.3",
    estimated={
        "density": "not in paper 004; 52100 value",
        "specific_heat": "not in paper 004; 52100 value",
        "thermal_conductivity": "not in paper 004; 52100 value",
    },
)

MATERIALS: dict[str, Material] = {
    m.name: m
    for m in (STEEL_52100, GCR15, M50, SILICON_NITRIDE, BRASS, STEEL_LOW_CARBON, PEEK,
              PAPER000_STEEL,
              PAPER001_STEEL, PAPER001_CAGE, PAPER004_STEEL)
}

_ALIASES = {
    "AISI52100": "STEEL_52100",
    "52100": "STEEL_52100",
    "100CR6": "STEEL_52100",
    "AISI_52100": "STEEL_52100",
    "SI3N4": "SILICON_NITRIDE",
    "M50_STEEL": "M50",
}


def material_names() -> list[str]:
    """Names of the material presets."""
    return sorted(MATERIALS)


def get_material(name: str | Material) -> Material:
    """The preset ``name`` (case-insensitive; aliases GCr15, 52100, 100Cr6, Si3N4).

    A :class:`Material` is returned unchanged. Unknown names raise
    :class:`UnknownNameError` listing the presets.
    """
    if isinstance(name, Material):
        return name
    if not isinstance(name, str):
        raise InputError("material", name, "a preset name or a Material")
    key = name.strip().upper().replace("-", "_").replace(" ", "_")
    key = _ALIASES.get(key, key)
    try:
        return MATERIALS[key]
    except KeyError:
        raise UnknownNameError("material", name, MATERIALS) from None
