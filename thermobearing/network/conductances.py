"""Edge conductance models of the thermal network (registry ``conductance``).

Each model is a small frozen dataclass with ``conductance(Ta, Tb) -> G [W/K]`` (``Ta``, ``Tb``
the temperatures [K] of the edge's first and second node) and ``to_dict()`` for the scene
TOML. Models whose ``temperature_dependent`` flag is set are re-evaluated by the steppers at
the start of every step for their linear part and at every stage value for the drift
within the step (``Assembler.drift``; see :mod:`.steppers`), so they are not lagged.

Paper 002 (Gao et al. 2022, ``seeds/002_*.txt``) eq. 27 writes a convective resistance as
``R = L / (h A)``; that is dimensionally wrong (K m / W). A convective resistance is
``R = 1 / (h A)`` [K/W], which is what :class:`Convection` implements.
"""

from __future__ import annotations

import abc
import dataclasses
import functools
import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
from scipy.special import ellipk

from ..errors import InputError, ValidityWarning
from ..registry import Registry

CONDUCTANCE: Registry[type] = Registry(
    "conductance", "thermal conductance of a network edge (conduction, convection, contact)"
)

#: standard gravity [m/s^2]
G_STANDARD = 9.80665


class ConductanceModel(abc.ABC):
    """Base class: subclasses are frozen dataclasses registered in :data:`CONDUCTANCE`."""

    model_name: ClassVar[str] = ""
    temperature_dependent: ClassVar[bool] = False

    @abc.abstractmethod
    def conductance(self, Ta: float, Tb: float) -> float:
        """Conductance [W/K] between the edge's nodes at temperatures Ta, Tb [K]."""

    def to_dict(self) -> dict[str, Any]:
        """``{"model": name, **parameters}`` (floats, strings)."""
        d: dict[str, Any] = {"model": self.model_name}
        for f in dataclasses.fields(self):  # type: ignore[arg-type]
            d[f.name] = getattr(self, f.name)
        return d


def _register(name: str, **kw: Any):
    def deco(cls: type) -> type:
        cls.model_name = name
        return CONDUCTANCE.register(name, **kw)(cls)

    return deco


#: largest convection coefficient a Convection takes [W/(m^2 K)]: ten times the top of the
#: range Incropera et al. (2007) Table 1.1 give for any convection (boiling and
#: condensation, 2500-1e5; forced convection of liquids 100-20000)
H_CONVECTION_MAX = 1e6


def _pos(field: str, v: float, allow_zero: bool = False) -> None:
    if not math.isfinite(float(v)) or float(v) < 0 or (float(v) == 0 and not allow_zero):
        raise InputError(field, v, "a finite value " + (">= 0" if allow_zero else "> 0"))


# --------------------------------------------------------------------- simple models
@_register("fixed", references=["incropera2007"], parameters={"value": "W/K"},
           validity="any value >= 0")
@dataclass(frozen=True)
class Fixed(ConductanceModel):
    """A given conductance G [W/K] (Incropera et al. 2007, sec. 3.1.3, thermal resistance)."""

    value: float

    def __post_init__(self) -> None:
        _pos("conductance.value", self.value, allow_zero=True)

    def conductance(self, Ta: float, Tb: float) -> float:
        return float(self.value)


@_register("plane_wall", references=["incropera2007"],
           parameters={"thermal_conductivity": "W/(m*K)", "area": "m**2", "thickness": "m"},
           validity="1-D conduction, constant k")
@dataclass(frozen=True)
class PlaneWall(ConductanceModel):
    """Conduction through a plane wall, G = k A / L (Incropera et al. 2007, eq. 3.6).

    Parameters: thermal_conductivity k [W/(m K)], area A [m^2], thickness L [m].
    """

    thermal_conductivity: float
    area: float
    thickness: float

    def __post_init__(self) -> None:
        for f in ("thermal_conductivity", "area", "thickness"):
            _pos(f"plane_wall.{f}", getattr(self, f))

    def conductance(self, Ta: float, Tb: float) -> float:
        return self.thermal_conductivity * self.area / self.thickness


@_register("cylindrical_shell", references=["incropera2007"],
           parameters={"thermal_conductivity": "W/(m*K)", "inner_radius": "m",
                       "outer_radius": "m", "length": "m"},
           validity="radial 1-D conduction, constant k, outer_radius > inner_radius")
@dataclass(frozen=True)
class CylindricalShell(ConductanceModel):
    """Radial conduction through a cylindrical shell, G = 2 pi k L / ln(r_o/r_i).

    Incropera et al. (2007) eq. 3.33. thermal_conductivity k [W/(m K)], inner_radius r_i [m],
    outer_radius r_o [m], length L [m]. Between the mid-radii of two rings, give the radii of
    the two node centres.
    """

    thermal_conductivity: float
    inner_radius: float
    outer_radius: float
    length: float

    def __post_init__(self) -> None:
        for f in ("thermal_conductivity", "inner_radius", "outer_radius", "length"):
            _pos(f"cylindrical_shell.{f}", getattr(self, f))
        if self.outer_radius <= self.inner_radius:
            raise InputError("cylindrical_shell.outer_radius", self.outer_radius,
                             f"a value > inner_radius = {self.inner_radius}")

    def conductance(self, Ta: float, Tb: float) -> float:
        return (2.0 * math.pi * self.thermal_conductivity * self.length
                / math.log(self.outer_radius / self.inner_radius))


@_register("convection", references=["incropera2007", "gao2022_overskidding"],
           parameters={"h": "W/(m**2*K)", "area": "m**2"},
           validity="h given (paper 002: oil 50-1500 W/(m^2 K))")
@dataclass(frozen=True)
class Convection(ConductanceModel):
    """Convection with a given coefficient, G = h A, i.e. R = 1/(h A) [K/W].

    Paper 002 (``seeds/002_*.txt``) eq. 27 writes R = L/(h A), which has units K m/W, not
    K/W: the characteristic length L does not belong there (Incropera et al. 2007, eq. 3.9,
    R_conv = 1/(h A)). The paper's areas are its eq. 28-29; its oil h ranges from 50 to
    1500 W/(m^2 K). h [W/(m^2 K)], area A [m^2].
    """

    h: float
    area: float

    def __post_init__(self) -> None:
        _pos("convection.h", self.h, allow_zero=True)
        if self.h > H_CONVECTION_MAX:
            # (a calibration started at h = 1e300 stopped on a singular stepper matrix,
            # "residual inf"; no convection comes near it)
            raise InputError("convection.h", self.h, f"a coefficient <= {H_CONVECTION_MAX:g} "
                             "W/(m^2 K) (boiling and condensation reach 1e5; Incropera et "
                             "al. 2007, Table 1.1)")
        _pos("convection.area", self.area)

    def conductance(self, Ta: float, Tb: float) -> float:
        return self.h * self.area


@_register("contact_fit", references=["incropera2007"],
           parameters={"contact_conductance": "W/(m**2*K)", "area": "m**2"},
           validity="contact conductance h_c measured or taken from tables for the pair")
@dataclass(frozen=True)
class ContactFit(ConductanceModel):
    """Thermal contact conductance of a fit (ring in housing, ring on shaft), G = h_c A.

    Incropera et al. (2007) sec. 3.1.4 (R''_tc = 1/h_c; Table 3.1-3.2 give h_c of metal pairs,
    1e3-1e5 W/(m^2 K) by pressure and interstitial fluid). contact_conductance h_c
    [W/(m^2 K)], area A [m^2] (the fit's cylindrical surface, pi D B).
    """

    contact_conductance: float
    area: float

    def __post_init__(self) -> None:
        _pos("contact_fit.contact_conductance", self.contact_conductance)
        _pos("contact_fit.area", self.area)

    def conductance(self, Ta: float, Tb: float) -> float:
        return self.contact_conductance * self.area


# ------------------------------------------------------------------ Hertz contacts
def elliptic_constriction_resistance(a: Any, b: Any, k: Any) -> np.ndarray:
    """Constriction resistance [K/W] of an isothermal elliptical contact on a half-space.

    R = K(e) / (2 pi k a), e^2 = 1 - (b/a)^2, K the complete elliptic integral of the first
    kind (parameter m = e^2). Derived here (the primer tags it [R]): the flux density
    q = Q / (2 pi a b sqrt(1 - x^2/a^2 - y^2/b^2)) makes the ellipse isothermal (the same
    potential problem as the flat elliptical punch, Johnson 1985, sec. 3.3), and the
    half-space Green's function 1/(2 pi k r) gives the centre temperature
    Q K(e)/(2 pi k a); the test integrates it numerically. For a circle (b = a) it gives the
    classical 1/(4 k a) (Carslaw & Jaeger 1959; Yovanovich 1976). a, b [m] semi-axes
    (a >= b or not: the larger is taken as a), k [W/(m K)].
    """
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    big = np.maximum(a, b)
    small = np.minimum(a, b)
    if np.any(small <= 0):
        raise InputError("contact semi-axes", (a, b), "values > 0")
    m = 1.0 - (small / big) ** 2
    return ellipk(m) / (2.0 * math.pi * np.asarray(k, dtype=float) * big)


@_register("hertz_constriction", references=["johnson1985", "yovanovich1976"],
           parameters={"semi_major": "m", "semi_minor": "m", "k_element": "W/(m*K)",
                       "k_ring": "W/(m*K)", "n_contacts": "-"},
           validity="dry, stationary isothermal ellipse; ignores the EHL film and rolling "
                    "(Peclet) effects, which lower/raise it")
@dataclass(frozen=True)
class HertzConstriction(ConductanceModel):
    """Conduction through Z Hertz contacts by elliptic constriction (element + ring halves).

    G = Z / [K(e)/(2 pi a) (1/k_element + 1/k_ring)] (see
    :func:`elliptic_constriction_resistance`); for one material R = K(e)/(pi k a) per
    contact. semi_major a, semi_minor b [m]; k_element, k_ring [W/(m K)]; n_contacts Z [-].
    """

    semi_major: float
    semi_minor: float
    k_element: float
    k_ring: float
    n_contacts: float

    def __post_init__(self) -> None:
        for f in ("semi_major", "semi_minor", "k_element", "k_ring", "n_contacts"):
            _pos(f"hertz_constriction.{f}", getattr(self, f))

    def conductance(self, Ta: float, Tb: float) -> float:
        r_unit = float(elliptic_constriction_resistance(self.semi_major, self.semi_minor, 1.0))
        r = r_unit * (1.0 / self.k_element + 1.0 / self.k_ring)
        return self.n_contacts / r


@_register("hertz_contact_paper002", references=["gao2022_overskidding"],
           parameters={"semi_major": "m", "semi_minor": "m", "thermal_conductivity": "W/(m*K)",
                       "n_contacts": "-"},
           validity="as paper 002; a conduction-slab estimate, not a constriction solution")
@dataclass(frozen=True)
class HertzContactPaper002(ConductanceModel):
    """Ball-ring conduction of paper 002 eq. 26 in its dimensionally consistent form.

    Paper 002 (``seeds/002_*.txt``) eq. 26: R_bh = 2 N_b L_a / (K pi L_a L_b), a slab of
    length 2 L_a and area pi L_a L_b (the contact ellipse, L_a, L_b its semi-axes). As
    written, N_b multiplies the resistance, so more balls would conduct *less*; the Z
    contacts are in parallel, so here R = 2 L_a / (K pi L_a L_b Z), i.e.
    G = Z K pi L_b / 2. semi_major L_a, semi_minor L_b [m], thermal_conductivity K
    [W/(m K)], n_contacts Z [-]. For one material, :class:`HertzConstriction` (a true
    constriction solution) is larger by the factor 2 L_a / (L_b K(e)) (about 3.9 for
    L_b/L_a = 0.15): the slab estimate under-predicts the contact conductance.
    """

    semi_major: float
    semi_minor: float
    thermal_conductivity: float
    n_contacts: float

    def __post_init__(self) -> None:
        for f in ("semi_major", "semi_minor", "thermal_conductivity", "n_contacts"):
            _pos(f"hertz_contact_paper002.{f}", getattr(self, f))

    def conductance(self, Ta: float, Tb: float) -> float:
        area = math.pi * self.semi_major * self.semi_minor
        length = 2.0 * self.semi_major
        return self.n_contacts * self.thermal_conductivity * area / length


# --------------------------------------------------------------- correlations
def _air(T: float):
    """Air properties (rho, mu, k, c_p) at T [K] and 1 atm
    (:func:`thermobearing.lubricant_properties.air_properties`: its 1-atm table, linear in T,
    so the conductances are continuous in T), memoised on T."""
    return _air_at(float(T))


@functools.lru_cache(maxsize=4096)
def _air_at(T: float):
    from ..lubricant_properties import air_properties

    p = air_properties(T)
    return (float(p.density), float(p.dynamic_viscosity), float(p.thermal_conductivity),
            float(p.specific_heat))


@_register("natural_convection_horizontal_cylinder",
           references=["churchill_chu1975", "incropera2007"],
           parameters={"diameter": "m", "area": "m**2"},
           validity="Ra_D <= 1e12; surface node first, ambient air node second")
@dataclass(frozen=True)
class NaturalConvectionCylinder(ConductanceModel):
    """Free convection from a horizontal cylinder (housing) to still air, G = h A.

    Nu_D = {0.60 + 0.387 Ra^(1/6) / [1 + (0.559/Pr)^(9/16)]^(8/27)}^2 (Churchill & Chu 1975;
    Incropera et al. 2007 eq. 9.34), evaluated by
    ``ht.conv_free_immersed.Nu_horizontal_cylinder_Churchill_Chu`` with air properties at the
    film temperature (CoolProp), beta = 1/T_film, Gr = g beta |Ta - Tb| D^3 / nu^2,
    h = Nu k / D. diameter D [m], area A [m^2] (the whole convecting surface). Radiation is
    not included (add a ``convection`` edge with a linearised radiative h if wanted).
    ``Ta`` is the surface, ``Tb`` the air.
    """

    temperature_dependent: ClassVar[bool] = True
    diameter: float
    area: float

    def __post_init__(self) -> None:
        _pos("natural_convection_horizontal_cylinder.diameter", self.diameter)
        _pos("natural_convection_horizontal_cylinder.area", self.area)

    def heat_transfer_coefficient(self, Ta: float, Tb: float) -> float:
        """h [W/(m^2 K)] at surface Ta and air Tb [K]."""
        from ht.conv_free_immersed import Nu_horizontal_cylinder_Churchill_Chu

        Tf = 0.5 * (Ta + Tb)
        rho, mu, k, cp = _air(Tf)
        nu = mu / rho
        dT = max(abs(Ta - Tb), 1e-3)  # Nu -> 0.36 at Gr -> 0: conduction limit, never 0
        gr = G_STANDARD * dT * self.diameter**3 / (Tf * nu**2)
        pr = mu * cp / k
        if gr * pr > 1e12:
            import warnings

            warnings.warn(f"Ra = {gr * pr:.3g} > 1e12 outside Churchill-Chu range",
                          ValidityWarning, stacklevel=2)
        return Nu_horizontal_cylinder_Churchill_Chu(pr, gr) * k / self.diameter

    def conductance(self, Ta: float, Tb: float) -> float:
        return self.heat_transfer_coefficient(Ta, Tb) * self.area


def whitaker_sphere_nusselt(re: Any, pr: Any, viscosity_ratio: Any = 1.0) -> np.ndarray:
    """Forced convection from a sphere: Whitaker (1972), Incropera et al. (2007) eq. 7.56.

    Nu_D = 2 + (0.4 Re^(1/2) + 0.06 Re^(2/3)) Pr^0.4 (mu/mu_s)^(1/4), valid for
    3.5 < Re < 7.6e4, 0.71 < Pr < 380, 1 < mu/mu_s < 3.2 (warns outside). re, pr [-],
    viscosity_ratio mu(T_fluid)/mu(T_surface) [-].
    """
    re = np.asarray(re, dtype=float)
    pr = np.asarray(pr, dtype=float)
    if np.any((re < 3.5) | (re > 7.6e4)) or np.any((pr < 0.71) | (pr > 380)):
        import warnings

        warnings.warn(f"Whitaker sphere correlation outside 3.5<Re<7.6e4, 0.71<Pr<380 "
                      f"(Re={re}, Pr={pr})", ValidityWarning, stacklevel=2)
    return 2.0 + (0.4 * np.sqrt(re) + 0.06 * re ** (2.0 / 3.0)) * pr**0.4 * np.asarray(
        viscosity_ratio, dtype=float) ** 0.25


def _lubricant(name: str):
    from ..lubricant import load_lubricant

    return load_lubricant(name)


@_register("oil_forced_convection_sphere", references=["whitaker1972", "incropera2007"],
           parameters={"lubricant": "-", "diameter": "m", "velocity": "m/s",
                       "n_elements": "-"},
           validity="3.5 < Re < 7.6e4, 0.71 < Pr < 380; oil node second")
@dataclass(frozen=True)
class OilForcedConvectionSphere(ConductanceModel):
    """Oil convection on Z balls, G = Z h pi D^2 with h from Whitaker's sphere correlation.

    See :func:`whitaker_sphere_nusselt`. Properties of ``lubricant`` (a preset name or
    path, :func:`thermobearing.lubricant.load_lubricant`) at the oil temperature ``Tb``;
    mu_s at the ball temperature ``Ta``. velocity [m/s] is the ball speed relative to the
    oil (e.g. its orbital speed for a still oil cloud), diameter D [m], n_elements Z [-].
    In an oil-air mixture the effective properties are those of the mixture (primer sec.
    2.2); this uses neat oil and so overestimates h for a lean mist.
    """

    temperature_dependent: ClassVar[bool] = True
    lubricant: str
    diameter: float
    velocity: float
    n_elements: float

    def __post_init__(self) -> None:
        _pos("oil_forced_convection_sphere.diameter", self.diameter)
        _pos("oil_forced_convection_sphere.velocity", self.velocity)
        _pos("oil_forced_convection_sphere.n_elements", self.n_elements)

    def heat_transfer_coefficient(self, Ta: float, Tb: float) -> float:
        """h [W/(m^2 K)] with the ball at Ta and the oil at Tb [K]."""
        lub = _lubricant(self.lubricant)
        rho = float(lub.density(Tb))
        mu = float(lub.dynamic_viscosity(Tb))
        mu_s = float(lub.dynamic_viscosity(Ta))
        k = float(lub.thermal_conductivity(Tb))
        cp = float(lub.specific_heat(Tb))
        re = rho * self.velocity * self.diameter / mu
        nu_ = whitaker_sphere_nusselt(re, mu * cp / k, mu / mu_s)
        return float(nu_) * k / self.diameter

    def conductance(self, Ta: float, Tb: float) -> float:
        return (self.n_elements * math.pi * self.diameter**2
                * self.heat_transfer_coefficient(Ta, Tb))


@_register("oil_forced_convection_plate", references=["incropera2007"],
           parameters={"lubricant": "-", "length": "m", "velocity": "m/s", "area": "m**2"},
           validity="flat-plate boundary layer; laminar Re_L < 5e5 (ht Baehr), "
                    "turbulent above; ring surfaces as plates of length L in the flow")
@dataclass(frozen=True)
class OilForcedConvectionPlate(ConductanceModel):
    """Oil convection on a ring surface treated as a flat plate, G = h A.

    Average Nu_L over a plate of length L from ``ht.conv_external.Nu_external_horizontal_plate``
    (laminar, Baehr: Nu = 0.678 Re^(1/2) Pr^(1/3) for Pr > 10, as for oils; 0.664 for
    0.6 < Pr < 10, Incropera et al. 2007 eq. 7.30; turbulent above Re = 5e5), with the
    properties of ``lubricant`` at the
    film temperature. length L [m] along the flow, velocity [m/s] of the surface relative to
    the oil, area A [m^2]. ``Ta`` the surface, ``Tb`` the oil.
    """

    temperature_dependent: ClassVar[bool] = True
    lubricant: str
    length: float
    velocity: float
    area: float

    def __post_init__(self) -> None:
        for f in ("length", "velocity", "area"):
            _pos(f"oil_forced_convection_plate.{f}", getattr(self, f))

    def heat_transfer_coefficient(self, Ta: float, Tb: float) -> float:
        """h [W/(m^2 K)] with the surface at Ta and the oil at Tb [K]."""
        from ht.conv_external import Nu_external_horizontal_plate

        lub = _lubricant(self.lubricant)
        Tf = 0.5 * (Ta + Tb)
        rho = float(lub.density(Tf))
        mu = float(lub.dynamic_viscosity(Tf))
        k = float(lub.thermal_conductivity(Tf))
        cp = float(lub.specific_heat(Tf))
        re = rho * self.velocity * self.length / mu
        return float(Nu_external_horizontal_plate(re, mu * cp / k, self.length)) * k / self.length

    def conductance(self, Ta: float, Tb: float) -> float:
        return self.heat_transfer_coefficient(Ta, Tb) * self.area
