"""Lubricant physics: viscosity vs temperature and pressure, density, thermal properties.

Every law is a registered, vectorised pure function (SI in, SI out); :class:`Lubricant`
ties a chosen set of laws to one oil and :func:`load_lubricant` builds one from
``configs/lubricants/<NAME>.toml``. The laws live in :mod:`thermobearing.viscosity_laws`
and :mod:`thermobearing.lubricant_properties` and are re-exported here.

Families (registries):

- ``viscosity_temperature``: ASTM D341 (Walther), Vogel, the exponential (Reynolds) law
  used for oil 4109 in paper 001, and the isothermal model of paper 000
  (``viscosity_laws``).
- ``pressure_viscosity``: Barus and Roelands (paper 000 eq. 9 form; ``viscosity_laws``).
- ``pressure_viscosity_coefficient``: correlations alpha(viscosity) for oils without a
  measured alpha.
- ``lubricant_thermal``: c_p and k from CoolProp (incompressible fluid library) or from
  the Cragoe correlations for petroleum oils, or constants from a paper's table.

Units: T [K], p [Pa], nu [m^2/s], eta [Pa s], rho [kg/m^3], c_p [J/(kg K)], k [W/(m K)].
"""

from __future__ import annotations

import math
import re
import tomllib
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .errors import (
    InputError,
    UnknownNameError,
    ValidityWarning,
    check_finite,
    check_positive,
    check_temperature,
)
from .lubricant_properties import (
    _D341_MAX_NU,
    _D341_MIN_NU,
    _D1250_DENSITY_RANGE,
    ALPHA_FIT_LOWEST_VISCOSITY,
    LUBRICANT_THERMAL,
    PRESSURE_VISCOSITY_COEFFICIENT,
    AirProperties,
    ArrayLike,
    _out,
    air_properties,
    alpha_gold_paraffinic,
    alpha_mineral_asme_fit,
    astm_d1250_lube_density,
    check_liquid_temperature,
    constant_properties,
    coolprop_properties,
    cragoe_properties,
    dowson_higginson_density,
    linear_expansion_density,
)
from .toml_files import read_toml
from .units import to_si
from .viscosity_laws import (  # the laws live there; re-exported here
    _VT_OUTPUT,
    PRESSURE_VISCOSITY,
    ROELANDS_ETA_INF,
    ROELANDS_P0,
    VISCOSITY_TEMPERATURE,
    alpha_from_roelands_index,
    barus_viscosity,
    d341_inverse_z,
    d341_z,
    exponential_viscosity,
    isothermal_viscosity,
    roelands_asymptotic_isoviscous_alpha,
    roelands_index_from_alpha,
    roelands_viscosity,
    vogel_viscosity,
    walther_constants,
    walther_kinematic_viscosity,
)

__all__ = [
    "LUBRICANT_THERMAL", "PRESSURE_VISCOSITY", "PRESSURE_VISCOSITY_COEFFICIENT",
    "VISCOSITY_TEMPERATURE", "AirProperties", "Lubricant", "air_properties",
    "alpha_from_roelands_index", "alpha_gold_paraffinic", "alpha_mineral_asme_fit",
    "astm_d1250_lube_density", "barus_viscosity", "check_liquid_temperature",
    "constant_properties",
    "coolprop_properties", "cragoe_properties", "d341_inverse_z", "d341_z",
    "dowson_higginson_density", "exponential_viscosity", "isothermal_viscosity",
    "linear_expansion_density", "load_lubricant", "lubricant_config_dir",
    "lubricant_from_dict", "preset_names", "roelands_asymptotic_isoviscous_alpha",
    "roelands_index_from_alpha", "roelands_viscosity", "vogel_viscosity",
    "walther_constants", "walther_kinematic_viscosity",
]

# ---------------------------------------------------------------------------
# the Lubricant
# ---------------------------------------------------------------------------


def _frozen(mapping: Mapping[str, Any]) -> tuple:
    return tuple(sorted((k, repr(v)) for k, v in mapping.items()))


_MEMO_SIZE = 4096


def _memo_scalar(method: Callable[..., Any]) -> Callable[..., Any]:
    """Memoise a property method for scalar arguments, per lubricant instance.

    The transient re-evaluates the same few oil properties at the same node temperatures
    many times per chunk (every heat source, every finite-difference column); for scalar
    (T, p) the result is a float and is kept in the instance's bounded memo. Array
    arguments, and calls that raise a warning (which must reach every caller), bypass it.
    """
    name = method.__name__

    def wrapper(self: Lubricant, *args: Any, **kwargs: Any) -> Any:
        if kwargs or not all(isinstance(a, (float, int)) and not isinstance(a, bool)
                             for a in args):
            return method(self, *args, **kwargs)
        key = (name, *args)
        memo = self._memo
        hit = memo.get(key)
        if hit is not None:
            return hit
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            value = method(self, *args)
        for w in caught:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
        if not caught and isinstance(value, float):
            if len(memo) >= _MEMO_SIZE:
                memo.clear()
            memo[key] = value
        return value

    wrapper.__name__ = name
    wrapper.__qualname__ = method.__qualname__
    wrapper.__doc__ = method.__doc__
    return wrapper


@dataclass(frozen=True)
class Lubricant:
    """One lubricant: its laws and their parameters (all SI).

    Attributes
    ----------
    name, source : identification and where the numbers come from.
    viscosity_law : key of :data:`VISCOSITY_TEMPERATURE`; ``viscosity_parameters`` its
        arguments (astm_d341: A, B; vogel: a, b, c; exponential: eta0, beta, T0;
        isothermal: eta0).
    pressure_law : "barus" or "roelands"; ``pressure_parameters`` holds ``alpha`` [1/Pa]
        or ``z`` [-] (Roelands), optional ``p0`` [Pa] and ``reference_temperature`` [K]
        (temperature at which a given alpha holds, for converting it to z).
    alpha_correlation : key of :data:`PRESSURE_VISCOSITY_COEFFICIENT` used when neither
        alpha nor z is given: alpha(T) follows the viscosity.
    density_reference [kg/m^3] at density_reference_temperature [K];
        density_temperature_law "linear" (with thermal_expansion [1/K]) or
        "astm_d1250_lube" (reference temperature must be 15 degC);
        density_pressure_law "dowson_higginson" or "incompressible".
    thermal_model : key of :data:`LUBRICANT_THERMAL`; thermal_parameters its arguments.
    kind : "mineral", "ester", ... (informative).
    estimated : field -> reasoning, for values not taken from a source.
    """

    name: str
    source: str
    viscosity_law: str
    viscosity_parameters: Mapping[str, float]
    density_reference: float
    density_reference_temperature: float = 288.15
    thermal_expansion: float = 6.4e-4
    density_pressure_law: str = "dowson_higginson"
    density_temperature_law: str = "linear"
    pressure_law: str = "roelands"
    pressure_parameters: Mapping[str, float] = field(default_factory=dict)
    alpha_correlation: str | None = None
    thermal_model: str = "cragoe"
    thermal_parameters: Mapping[str, Any] = field(default_factory=dict)
    kind: str = "mineral"
    estimated: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_memo", {})
        law = VISCOSITY_TEMPERATURE.entry(self.viscosity_law)
        missing = set(law.parameters) - set(self.viscosity_parameters)
        extra = set(self.viscosity_parameters) - set(law.parameters)
        if missing or extra:
            raise InputError(
                f"{self.name}.viscosity_parameters",
                dict(self.viscosity_parameters),
                f"exactly the parameters {sorted(law.parameters)} of {self.viscosity_law}",
            )
        for key, val in self.viscosity_parameters.items():
            check_finite(f"{self.name}.viscosity.{key}", val)
        for key in ("eta0", "a", "T0"):
            if key in self.viscosity_parameters:
                check_positive(f"{self.name}.viscosity.{key}", self.viscosity_parameters[key])
        # the temperature slope of each law: ASTM D341's B, Vogel's b, the exponential law's
        # beta. A negative one (a sign slip: beta = -0.032 1/K) made the oil thicken as it
        # heats, 0.030 Pa s at 300 K and 0.148 Pa s at 350 K, and was accepted
        slope = {"astm_d341": "B", "vogel": "b", "exponential": "beta"}.get(self.viscosity_law)
        if slope is not None and not self.viscosity_parameters[slope] >= 0.0:
            raise InputError(f"{self.name}.viscosity.{slope}", self.viscosity_parameters[slope],
                             f"a value >= 0 for the {self.viscosity_law} law: the viscosity "
                             "falls as the oil heats (a negative value makes it rise)")
        check_positive(f"{self.name}.density", self.density_reference)
        check_temperature(f"{self.name}.density_reference_temperature",
                          self.density_reference_temperature)
        check_finite(f"{self.name}.thermal_expansion", self.thermal_expansion)
        if not 0.0 <= self.thermal_expansion < 5e-3:
            raise InputError(f"{self.name}.thermal_expansion", self.thermal_expansion,
                             "a value in [0, 5e-3) 1/K")
        if self.density_temperature_law not in ("linear", "astm_d1250_lube"):
            raise UnknownNameError(f"{self.name}.density_temperature_law",
                                   self.density_temperature_law, ["linear", "astm_d1250_lube"])
        if (self.density_temperature_law == "astm_d1250_lube"
                and abs(self.density_reference_temperature - 288.15) > 1e-9):
            raise InputError(f"{self.name}.density_reference_temperature",
                             self.density_reference_temperature,
                             "15 degC (288.15 K) with the astm_d1250_lube law")
        lo, hi = _D1250_DENSITY_RANGE
        if (self.density_temperature_law == "astm_d1250_lube"
                and not lo <= self.density_reference <= hi):
            # outside its tables the law's expansion coefficient 0.6278/rho15 runs away
            # (0.876 given as kg/m^3: a dynamic viscosity of 2e-124 Pa s at 40 degC)
            raise InputError(f"{self.name}.density", self.density_reference,
                             f"a 15 degC density in kg/m^3 within ASTM D1250 Table 54D's "
                             f"{lo:g}-{hi:g} kg/m^3 (0.876 g/cm^3 is 876 kg/m^3), or "
                             "density_temperature_law = 'linear'")
        if self.density_pressure_law not in ("dowson_higginson", "incompressible"):
            raise UnknownNameError(f"{self.name}.density_pressure_law",
                                   self.density_pressure_law,
                                   ["dowson_higginson", "incompressible"])
        PRESSURE_VISCOSITY.entry(self.pressure_law)
        pp = dict(self.pressure_parameters)
        allowed = {"alpha", "z", "p0", "reference_temperature"}
        for key in pp:
            if key not in allowed:
                raise UnknownNameError(f"{self.name}.pressure_viscosity", key, allowed)
        if self.alpha_correlation is not None:
            PRESSURE_VISCOSITY_COEFFICIENT.entry(self.alpha_correlation)
        n_given = ("alpha" in pp) + ("z" in pp) + (self.alpha_correlation is not None)
        if n_given != 1:
            raise InputError(f"{self.name}.pressure_viscosity", pp,
                             "exactly one of alpha, z or alpha_correlation")
        if "z" in pp and self.pressure_law != "roelands":
            raise InputError(f"{self.name}.pressure_viscosity.z", pp["z"],
                             "z only with the roelands law")
        for key in ("alpha", "z", "p0"):
            if key in pp:
                check_positive(f"{self.name}.pressure_viscosity.{key}", pp[key])
        for key, (high, allowed) in _PRESSURE_LIMITS.items():
            if key in pp and not pp[key] <= high:
                raise InputError(f"{self.name}.pressure_viscosity.{key}", pp[key], allowed)
        if "reference_temperature" in pp:
            check_temperature(f"{self.name}.pressure_viscosity.reference_temperature",
                              pp["reference_temperature"])
        LUBRICANT_THERMAL.entry(self.thermal_model)
        if "alpha" in pp and self.pressure_law == "roelands":
            self._check_derived_roelands_index(pp)

    def _check_derived_roelands_index(self, pp: Mapping[str, Any]) -> None:
        """A Roelands oil given by alpha takes z = alpha p0 / (ln eta0 + 9.67) at the
        reference temperature (:meth:`roelands_index`); a thin oil with a mineral oil's alpha
        (about 1 cSt, 2e-8 1/Pa) gets z above the 1.5 a given z may have, and its viscosity
        overflows at contact pressures: refused here, naming alpha and the z it implies."""
        tref = float(pp.get("reference_temperature", 313.15))
        eta = float(self._eta_atm(tref))
        high, _ = _PRESSURE_LIMITS["z"]
        if eta <= ROELANDS_ETA_INF:
            z = math.inf
        else:
            z = float(roelands_index_from_alpha(pp["alpha"], eta, self._p0))
        if not z <= high:
            raise InputError(
                f"{self.name}.pressure_viscosity.alpha", pp["alpha"],
                f"an alpha whose Roelands index at the reference temperature "
                f"({tref - 273.15:g} degC, eta0 = {eta:.3g} Pa s) is at most {high:g}: this one "
                f"gives z = {z:.3g}; give a smaller alpha, a z, or the barus law")

    def __hash__(self) -> int:  # mappings are not hashable; hash their sorted items
        return hash((
            self.name, self.viscosity_law, _frozen(self.viscosity_parameters),
            self.density_reference, self.density_reference_temperature, self.thermal_expansion,
            self.density_pressure_law, self.density_temperature_law, self.pressure_law,
            _frozen(self.pressure_parameters),
            self.alpha_correlation, self.thermal_model, _frozen(self.thermal_parameters),
        ))

    # -- viscosity ----------------------------------------------------------
    def _vt(self, T: ArrayLike) -> ArrayLike:
        law = VISCOSITY_TEMPERATURE.get(self.viscosity_law)
        try:
            if type(T) is float:       # the scalar laws use math: overflow raises
                v = law(T, **self.viscosity_parameters)
                if math.isfinite(v) and 0.0 < v <= _D341_MAX_NU:
                    return v
            else:
                with np.errstate(over="ignore", invalid="ignore"):
                    v = law(T, **self.viscosity_parameters)
        except OverflowError:
            v = np.inf
        if not (np.all(np.isfinite(v)) and np.all(np.asarray(v) > 0.0)):
            # far below the oil's pour point the law's double exponential overflows (ASTM
            # D341 at a few kelvin: OverflowError or inf, then NaN alpha), far above boiling
            # an exponential law underflows to 0; say so instead (property tests)
            in_celsius = (f"; temperatures are in K: {T:g} K is {T - 273.15:g} degC"
                          if isinstance(T, float) else "; temperatures are in K")
            raise InputError("temperature", T,
                             f"a temperature at which the {self.viscosity_law} viscosity law of "
                             f"{self.name} is finite and > 0 (it overflows or underflows here; "
                             "the law is meant for the liquid range, cloud to boiling point"
                             f"{in_celsius})")
        if self.viscosity_law == "astm_d341" and np.any(np.asarray(v) > _D341_MAX_NU):
            # the law's stated range ends at 1e6 cSt (its registry entry; below 0.21 cSt the
            # law itself warns): colder than that it extrapolates
            warnings.warn(f"{self.name}: ASTM D341 used above 1e6 cSt "
                          f"({float(np.max(v)) * 1e6:.3g} cSt): outside its range (the oil is "
                          "below its pour point)", ValidityWarning, stacklevel=3)
        return v

    @_memo_scalar
    def kinematic_viscosity(self, T: ArrayLike) -> ArrayLike:
        """Kinematic viscosity [m^2/s] at atmospheric pressure, T [K] (vectorised)."""
        v = self._vt(T)
        if _VT_OUTPUT[self.viscosity_law] == "kinematic":
            return v
        return _out(np.asarray(v) / np.asarray(self.density(T)))

    def _eta_atm(self, T: ArrayLike) -> ArrayLike:
        v = self._vt(T)
        if _VT_OUTPUT[self.viscosity_law] == "dynamic":
            return v
        return _out(np.asarray(v) * np.asarray(self.density(T)))

    @property
    def _p0(self) -> float:
        return float(self.pressure_parameters.get("p0", ROELANDS_P0))

    @_memo_scalar
    def roelands_index(self, T: ArrayLike) -> ArrayLike:
        """Roelands pressure-viscosity index z [-] at T [K].

        A given z is constant (Roelands' model); a given alpha is converted once at its
        ``reference_temperature`` (default 313.15 K) by z = alpha p0 / (ln eta0 + 9.67),
        Hamrock 2004 ch. 4; with an alpha correlation z follows alpha(T). For a Barus oil
        this is the Roelands index with the same initial slope.

        An eta-based correlation is followed down to the lowest viscosity of its data
        (``ALPHA_FIT_LOWEST_VISCOSITY``, the ASME 1953 fit: 2.4 mPa s); a thinner (hotter)
        oil keeps the z of that viscosity. The fit's alpha falls as eta0^0.16 while
        ln eta0 + 9.67 falls to 0, so its z rises without bound there, and with a z rising in
        temperature the Roelands viscosity at a fixed pressure rises with temperature
        (d ln eta / d ln eta0 = (1 + p/p0)^z [1 + ln(1 + p/p0) (ln eta0 + 9.67) dz/d ln eta0]):
        an ISO VG 2 oil at 1 GPa had 85 Pa s at 80 degC and 422 Pa s at 200 degC. With z held
        the viscosity falls with temperature at every pressure below the hold; above it the
        fit's z keeps it falling up to about 4 GPa (the ISO 76 static-rating stresses). The
        initial-slope alpha of the films stays the correlation's.
        """
        check_temperature("temperature", T)   # a constant z ignored T (0 K passed)
        pp = self.pressure_parameters
        if "z" in pp:
            return _out(np.full_like(np.asarray(T, dtype=float), pp["z"]))
        if "alpha" in pp:
            if self.pressure_law == "barus":
                return roelands_index_from_alpha(pp["alpha"], self._eta_atm(T), self._p0)
            tref = float(pp.get("reference_temperature", 313.15))
            z = float(roelands_index_from_alpha(pp["alpha"], self._eta_atm(tref), self._p0))
            return _out(np.full_like(np.asarray(T, dtype=float), z))
        lowest = ALPHA_FIT_LOWEST_VISCOSITY.get(str(self.alpha_correlation))
        if lowest is None:
            return roelands_index_from_alpha(self._alpha_correlated(T), self._eta_atm(T),
                                             self._p0)
        eta = np.maximum(np.asarray(self._eta_atm(T), dtype=float), lowest)
        entry = PRESSURE_VISCOSITY_COEFFICIENT.entry(str(self.alpha_correlation))
        return roelands_index_from_alpha(entry.obj(eta), _out(eta), self._p0)

    def _alpha_correlated(self, T: ArrayLike) -> ArrayLike:
        assert self.alpha_correlation is not None
        entry = PRESSURE_VISCOSITY_COEFFICIENT.entry(self.alpha_correlation)
        if "nu" in entry.parameters:
            return entry.obj(self.kinematic_viscosity(T))
        return entry.obj(self._eta_atm(T))

    @_memo_scalar
    def pressure_viscosity_coefficient(
        self, T: ArrayLike, definition: str = "initial_slope"
    ) -> ArrayLike:
        """Pressure-viscosity coefficient alpha [1/Pa] for film formulas, T [K].

        ``definition="initial_slope"`` (default): d(ln eta)/dp at p = 0; for a Roelands oil
        alpha = z (ln eta0 + 9.67)/p0 (Hamrock 2004 ch. 4), which reproduces paper 000's
        G = alpha E' = 5000. ``definition="asymptotic_isoviscous"``: Blok's alpha*
        (:func:`roelands_asymptotic_isoviscous_alpha`), smaller than the initial slope for a
        Roelands oil with z <= 1, larger for z > 1.
        """
        if definition not in ("initial_slope", "asymptotic_isoviscous"):
            raise UnknownNameError("definition", definition,
                                   ["initial_slope", "asymptotic_isoviscous"])
        pp = self.pressure_parameters
        t = np.asarray(T, dtype=float)
        check_temperature("temperature", t)
        if self.pressure_law == "barus":
            if "alpha" in pp:
                return _out(np.full_like(t, pp["alpha"]))
            return self._alpha_correlated(t)
        if definition == "initial_slope":
            if self.alpha_correlation is not None:
                return self._alpha_correlated(t)
            z = self.roelands_index(t)
            return alpha_from_roelands_index(z, self._eta_atm(t), self._p0)
        return roelands_asymptotic_isoviscous_alpha(
            self._eta_atm(t), self.roelands_index(t), self._p0
        )

    @_memo_scalar
    def dynamic_viscosity(self, T: ArrayLike, p: ArrayLike = 0.0) -> ArrayLike:
        """Dynamic viscosity [Pa s] at T [K] and gauge pressure p [Pa] (vectorised, broadcast)."""
        if type(p) is float and p == 0.0 and type(T) is float:  # the common scalar call
            return float(self._eta_atm(T))
        check_finite("pressure", p)
        eta0 = self._eta_atm(T)
        if np.all(np.asarray(p) == 0.0):
            return _out(np.broadcast_to(np.asarray(eta0), np.broadcast(eta0, p).shape).copy())
        if self.pressure_law == "barus":
            return barus_viscosity(eta0, self.pressure_viscosity_coefficient(T), p)
        return roelands_viscosity(eta0, p, self.roelands_index(T), self._p0)

    # -- density and thermal ------------------------------------------------
    @_memo_scalar
    def density(self, T: ArrayLike, p: ArrayLike = 0.0) -> ArrayLike:
        """Density [kg/m^3] at T [K], p [Pa]: temperature law, then Dowson-Higginson.

        The pressure factor is paper 000 eq. 10 (:func:`dowson_higginson_density`).
        """
        if self.density_temperature_law == "astm_d1250_lube":
            rho = astm_d1250_lube_density(T, self.density_reference)
            if not np.all(np.asarray(rho) > 0.0):
                # the exponential law underflows to 0 at absurd temperatures (1e12 K), and a
                # zero density divided the skidding models' drag by zero
                raise InputError("temperature", T, "temperatures at which the ASTM D1250 "
                                 "density law is > 0 (it underflows far above boiling)")
        else:
            rho = linear_expansion_density(T, self.density_reference,
                                           self.density_reference_temperature,
                                           self.thermal_expansion)
        if type(p) is float and p == 0.0 and np.ndim(rho) == 0:
            return float(rho)  # at gauge pressure 0 every pressure law gives rho(T)
        if self.density_pressure_law == "incompressible":
            check_finite("pressure", p)
            return _out(np.broadcast_to(np.asarray(rho), np.broadcast(rho, p).shape).copy())
        return dowson_higginson_density(rho, p)

    def _thermal(self, T: ArrayLike) -> tuple[ArrayLike, ArrayLike]:
        params = dict(self.thermal_parameters)
        if self.thermal_model == "cragoe":
            params.setdefault("density15", float(self.density(288.15)))
        cp, k = LUBRICANT_THERMAL.get(self.thermal_model)(T, **params)
        if not (np.all(np.asarray(cp) > 0.0) and np.all(np.asarray(k) > 0.0)):
            # a linear correlation extrapolated far beyond its range (Cragoe's k turns
            # negative above ~2100 K) must not return a negative conductivity
            entry = LUBRICANT_THERMAL.entry(self.thermal_model)
            raise InputError("temperature", T,
                             f"a temperature at which the {self.thermal_model} thermal "
                             f"properties of {self.name} are positive (validity: "
                             f"{entry.validity})")
        return cp, k

    @_memo_scalar
    def specific_heat(self, T: ArrayLike) -> ArrayLike:
        """Specific heat c_p [J/(kg K)] at T [K]."""
        return self._thermal(T)[0]

    @_memo_scalar
    def thermal_conductivity(self, T: ArrayLike) -> ArrayLike:
        """Thermal conductivity k [W/(m K)] at T [K]."""
        return self._thermal(T)[1]

    # -- construction ---------------------------------------------------------
    @classmethod
    def from_viscosities(
        cls,
        nu40: float,
        nu100: float,
        density15: float,
        *,
        name: str = "custom",
        source: str = "user input",
        T1: float = 313.15,
        T2: float = 373.15,
        thermal_expansion: float = 6.4e-4,
        density_temperature_law: str = "astm_d1250_lube",
        pressure_law: str = "roelands",
        alpha: float | None = None,
        z: float | None = None,
        alpha_correlation: str | None = None,
        thermal_model: str = "cragoe",
        thermal_parameters: Mapping[str, Any] | None = None,
        kind: str = "mineral",
        estimated: Mapping[str, str] | None = None,
    ) -> Lubricant:
        """A lubricant whose nu(T) is the ASTM D341 line through (T1, nu40) and (T2, nu100).

        nu40, nu100 [m^2/s] at T1 = 40 degC and T2 = 100 degC by default; density15
        [kg/m^3] at 15 degC; density vs temperature by ASTM D1250 for lubricating oils unless
        ``density_temperature_law="linear"``. Without alpha, z or alpha_correlation the mineral-oil
        correlation ``asme1953_mineral_fit`` is used. nu100 >= nu40 raises InputError, as
        does a viscosity outside ASTM D341's range, 0.21 cSt to 1e6 cSt (cSt given as m^2/s).
        """
        for key, t_ref in (("T1", T1), ("T2", T2)):
            # ASTM D341 describes liquid oils; the pour points of lubricants lie above about
            # -70 degC, so a reference temperature below 200 K is a degC value read as kelvin
            if isinstance(t_ref, int | float) and math.isfinite(t_ref) and t_ref < 200.0:
                raise InputError(f"{name}.{key}", t_ref,
                                 "a reference temperature in K of the liquid oil (>= 200 K; "
                                 f"{t_ref:g} K is {t_ref - 273.15:g} degC; 40 degC is 313.15 K)")
        for key, nu in (("nu40", nu40), ("nu100", nu100)):
            check_positive(f"{name}.{key}", nu)
            if not _D341_MIN_NU <= nu <= _D341_MAX_NU:
                raise InputError(f"{name}.{key}", nu, "a kinematic viscosity in m^2/s within "
                                 "ASTM D341's range, 2.1e-7 to 1 m^2/s (0.21 to 1e6 cSt; "
                                 "46 cSt = 46 mm^2/s is 4.6e-5 m^2/s)")
        A, B = walther_constants(nu40, T1, nu100, T2)
        pp: dict[str, float] = {}
        if alpha is not None:
            pp["alpha"] = alpha
        if z is not None:
            pp["z"] = z
        if alpha is None and z is None and alpha_correlation is None:
            alpha_correlation = "asme1953_mineral_fit"
        return cls(
            name=name,
            source=source,
            viscosity_law="astm_d341",
            viscosity_parameters={"A": A, "B": B},
            density_reference=density15,
            density_reference_temperature=288.15,
            thermal_expansion=thermal_expansion,
            density_temperature_law=density_temperature_law,
            pressure_law=pressure_law,
            pressure_parameters=pp,
            alpha_correlation=alpha_correlation,
            thermal_model=thermal_model,
            thermal_parameters=dict(thermal_parameters or {}),
            kind=kind,
            estimated=dict(estimated or {}),
        )


# ---------------------------------------------------------------------------
# loading presets
# ---------------------------------------------------------------------------
def lubricant_config_dir() -> Path:
    """``configs/lubricants`` at the repository root."""
    import thermobearing

    return Path(thermobearing.__file__).resolve().parents[1] / "configs" / "lubricants"


def preset_names() -> list[str]:
    """Names of the lubricant presets, their digit runs compared as numbers (ISO_VG32,
    ISO_VG46, ISO_VG68, ISO_VG100: a text sort listed ISO_VG100 first)."""
    folder = lubricant_config_dir()
    if not folder.is_dir():
        return []

    def natural(name: str) -> list[tuple[int, int | str]]:
        return [(0, int(p)) if p.isdigit() else (1, p) for p in re.split(r"(\d+)", name) if p]

    return sorted((p.stem for p in folder.glob("*.toml")), key=natural)


_TOP_KEYS = {"name", "source", "kind", "viscosity", "pressure_viscosity", "density",
             "thermal", "estimated"}
_SECTION_UNITS: dict[str, dict[str, str]] = {
    # Vogel's b is a temperature difference (eta = a exp(b / (T - c))): "1000 degC" is
    # 1000 K, not 1273.15 K (read as a temperature it made the oil 5.3x as viscous at
    # 40 degC with a = 5e-5 Pa s, c = 150 K)
    "viscosity": {"law": "", "nu40": "m**2/s", "nu100": "m**2/s", "T1": "K", "T2": "K",
                  "eta0": "Pa*s", "beta": "1/K", "T0": "K", "a": "Pa*s",
                  "b": "temperature_difference", "c": "K", "A": "", "B": "", "source": ""},
    "pressure_viscosity": {"law": "", "alpha": "1/Pa", "z": "", "p0": "Pa",
                           "reference_temperature": "K", "alpha_correlation": "",
                           "source": ""},
    "density": {"value": "kg/m**3", "reference_temperature": "K", "expansion": "1/K",
                "pressure_law": "", "temperature_law": "", "source": ""},
    "thermal": {"model": "", "fluid": "", "specific_heat": "J/(kg*K)",
                "thermal_conductivity": "W/(m*K)", "source": ""},
}


def _section(data: dict, name: str, where: str) -> dict[str, Any]:
    raw = data.get(name, {})
    if not isinstance(raw, dict):
        raise InputError(f"{where}.{name}", raw, "a TOML table")
    units = _SECTION_UNITS[name]
    out: dict[str, Any] = {}
    for key, val in raw.items():
        if key not in units:
            raise UnknownNameError(f"{where}.{name} key", key, units)
        unit = units[key]
        if unit and key != "source":
            out[key] = to_si(val, unit, field=f"{where}.{name}.{key}")
        elif key in ("A", "B", "z"):
            out[key] = to_si(val, "dimensionless", field=f"{where}.{name}.{key}")
        else:
            out[key] = val
    return out


#: upper bounds of a given pressure-viscosity parameter, with what is allowed. Measured
#: oils have alpha of about 1-4e-8 1/Pa (mineral, synthetic, traction fluids) and Roelands
#: z of about 0.4-1.1; far above, the viscosity overflows double precision inside the
#: contacts (Barus exp(alpha p) at alpha p > 709: 2e-5 1/Pa at 35 MPa; Roelands z = 1.8 of an
#: ISO VG 68 oil at 2.5 GPa, z = 1.5 at 4.2 GPa) and the ball solver's pressure table
#: stopped with a ZeroDivisionError (alpha = 2e22 1/Pa, z = 6e29)
_PRESSURE_LIMITS = {
    "alpha": (1e-7, "a pressure-viscosity coefficient up to 1e-7 1/Pa (measured oils: about "
                    "1-4e-8 1/Pa, i.e. 10-40 1/GPa; a bare number is in 1/Pa)"),
    "z": (1.5, "a Roelands index z up to 1.5 (oils: about 0.4-1.1; above, the viscosity "
               "overflows below the 2-4 GPa of loaded rolling contacts)"),
}


def lubricant_from_dict(data: Mapping[str, Any], where: str = "lubricant") -> Lubricant:
    """Build a :class:`Lubricant` from a parsed TOML mapping (unknown keys are errors)."""
    for key in data:
        if key not in _TOP_KEYS:
            raise UnknownNameError(f"{where} key", key, _TOP_KEYS)
    for req in ("name", "source", "viscosity", "density"):
        if req not in data:
            raise InputError(f"{where}.{req}", None, "a required entry")
    vis = _section(dict(data), "viscosity", where)
    pv = _section(dict(data), "pressure_viscosity", where)
    den = _section(dict(data), "density", where)
    th = _section(dict(data), "thermal", where)
    est = dict(data.get("estimated", {}))
    law = vis.pop("law", "astm_d341")
    vis.pop("source", None)
    if "value" not in den:
        raise InputError(f"{where}.density.value", None, "a density, e.g. \"870 kg/m^3\"")
    common = {
        "name": str(data["name"]),
        "source": str(data["source"]),
        "kind": str(data.get("kind", "mineral")),
        "estimated": est,
        "density_reference": den["value"],
        "density_reference_temperature": den.get("reference_temperature", 288.15),
        "thermal_expansion": den.get("expansion", 6.4e-4),
        "density_pressure_law": den.get("pressure_law", "dowson_higginson"),
        "density_temperature_law": den.get("temperature_law", "linear"),
        "pressure_law": pv.pop("law", "roelands"),
        "alpha_correlation": pv.pop("alpha_correlation", None),
        "thermal_model": th.pop("model", "cragoe"),
    }
    pv.pop("source", None)
    th.pop("source", None)
    common["pressure_parameters"] = pv
    common["thermal_parameters"] = th
    if law == "astm_d341" and ("nu40" in vis or "nu100" in vis):
        if not {"nu40", "nu100"} <= set(vis):
            raise InputError(f"{where}.viscosity", vis, "both nu40 and nu100")
        T1, T2 = vis.get("T1", 313.15), vis.get("T2", 373.15)
        try:
            A, B = walther_constants(vis["nu40"], T1, vis["nu100"], T2)
        except InputError as exc:
            raise _file_error(exc, where, data, {
                "nu1": "viscosity.nu40", "nu2": "viscosity.nu100", "T1": "viscosity.T1",
                "T2": "viscosity.T2",
                # "viscosity at 373.15 K": the one at the higher temperature
                "viscosity at": "viscosity.nu100" if T2 > T1 else "viscosity.nu40"}) from None
        params: dict[str, float] = {"A": A, "B": B}
    elif law == "astm_d341" and not {"A", "B"} <= set(vis):
        # an empty [viscosity] table was refused as "exactly the parameters ['A', 'B']"
        raise InputError(f"{where}.viscosity", data.get("viscosity"),
                         "nu40 and nu100 (or the chart constants A and B) for the default law "
                         "astm_d341, e.g. { nu40 = \"46 mm**2/s\", nu100 = \"6.8 mm**2/s\" }")
    else:
        params = {k: float(v) for k, v in vis.items()}
    name = common["name"]
    try:
        return Lubricant(viscosity_law=law, viscosity_parameters=params, **common)
    except InputError as exc:
        # the dataclass names its attributes ("ISO_VG46.density_reference_temperature");
        # the file's keys are what the user can change
        fields = {f"{name}.{attr}": key for attr, key in _ATTRIBUTE_KEYS.items()}
        fields.update({f"{name}.viscosity.": "viscosity.",
                       f"{name}.pressure_viscosity.": "pressure_viscosity.",
                       "lubricant_thermal model": "thermal.model"})
        raise _file_error(exc, where, data, fields) from None


#: the :class:`Lubricant` attribute each lubricant-file key sets
_ATTRIBUTE_KEYS = {
    "viscosity_parameters": "viscosity", "viscosity_law": "viscosity.law",
    "density_reference_temperature": "density.reference_temperature",
    "density_temperature_law": "density.temperature_law",
    "density_pressure_law": "density.pressure_law", "thermal_expansion": "density.expansion",
    "density": "density.value", "pressure_viscosity": "pressure_viscosity",
    "pressure_law": "pressure_viscosity.law", "thermal_model": "thermal.model",
    "thermal_parameters": "thermal",
}


def _file_error(exc: InputError, where: str, data: Mapping[str, Any],
                fields: Mapping[str, str]) -> InputError:
    """``exc`` renamed to the lubricant file's key (``where`` + ``.`` + the key ``fields``
    maps the error's field, or its longest matching prefix, to), with the value as the file
    wrote it; ``exc`` itself when no entry matches. A bare number the file gave for a
    quantity out of range gets a note that bare numbers are SI (``nu40 = 46`` is 46 m^2/s)."""
    field = str(exc.field)
    match = max((k for k in fields if field == k or (k.endswith((".", " at"))
                                                      and field.startswith(k))),
                key=len, default=None)
    if match is None:
        return exc
    key = fields[match] + (field[len(match):] if match.endswith(".") else "")
    raw: Any = data
    for part in key.split("."):
        raw = raw.get(part) if isinstance(raw, Mapping) else None
    value = exc.value if raw is None else raw
    allowed = exc.allowed
    if isinstance(raw, int | float) and not isinstance(raw, bool):
        allowed += ("; a bare number in a lubricant file is SI: write the unit, e.g. "
                    "nu40 = \"46 mm**2/s\", value = \"876 kg/m**3\"")
    if isinstance(exc, UnknownNameError):
        return UnknownNameError(f"{where}.{key}", value, exc.known)
    return InputError(f"{where}.{key}", value, allowed)


def load_lubricant(name_or_path: str | Path) -> Lubricant:
    """Load a lubricant preset (``"ISO_VG46"``) or a TOML file path.

    An unknown preset name raises :class:`UnknownNameError` listing the presets.
    """
    path = Path(name_or_path)
    if path.suffix != ".toml" or not path.is_file():
        candidate = lubricant_config_dir() / f"{name_or_path}.toml"
        if not candidate.is_file():
            raise UnknownNameError("lubricant preset", str(name_or_path), preset_names())
        path = candidate
    try:
        data = read_toml(path)
    except tomllib.TOMLDecodeError as exc:
        raise InputError("lubricant file", str(path), f"valid TOML ({exc})") from None
    return lubricant_from_dict(data, where=f"lubricant[{path.stem}]")
