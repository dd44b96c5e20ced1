"""Traction-coefficient curves mu(s) of the slide-to-roll ratio (disk-machine fits).

One job: the traction coefficient of a lubricated rolling-sliding contact as a fitted curve
of the slide-to-roll ratio, ``mu = F / Q``, the form quasi-dynamic bearing codes use in place
of a film rheology (the traction of a contact is then mu(s) times its normal load). Pure,
vectorised functions, SI inside.

Form (four coefficients; Wang's traction model as written by Yan et al. 2025, eq. 15
[yan2025_crb_flexible_rollers], and in the public MATLAB transcription ``oil_coe_model.m``
[harris_model_matlab])::

    mu(s) = sign(s) [ (A + B |s|) exp(-C |s|) + D ]          s = (u1 - u2) / u_e   (1)

with u_e = (u1 + u2)/2 (the package's convention). mu(0+) = A + D; a curve with A = -D
starts at zero traction and rises with slope B + C D, passes a maximum where
d/ds [(A + B s) e^{-Cs}] = 0, s* = 1/C - A/B, and tends to D at large slip.

Named curves (:data:`TRACTION_CURVES`):

``oil4109_wang``: aviation lubricating oil 4109 (the oil of seed paper 001), the regression
of Wang Y.'s disk-machine measurements (PhD thesis, Harbin Institute of Technology, 2006
[wang2006_aviation_oil_rheology]; its form is published by Yan et al. 2025, eqs. 16-19,
who use it for a cylindrical roller bearing) on the dimensionless load, speed and thermal
numbers of the contact::

    W = Q / (E' R^2),   U = eta0 u_e / (E' R),   T = theta sqrt(k eta0 beta) / (E' R)   (2)
    W_c = 7.956015e12 T^2 + 5553.09 T + 1.758455e-6                                  (3)
    X = X0 W^(X1 |W_c/W - 1|) U^X2 T^X3     for X = A, B, C                          (4)
    D = -A                                                                            (5)

with (X0, X1, X2, X3) = A: (-4.793526e-8, 0.0068361, -0.4047492, -0.1833848),
B: (8.37449e-15, 0.01409715, -0.5868325, -0.8173636), C: (1.180823e-4, 0.006321, -0.20617,
-0.3631740), and the oil constants of the fit eta0 = 0.033 Pa s, beta = 0.0215 1/K,
k = 0.0966 W/(m K). W_c is the "critical load" at which the traction changes behaviour
(the abstract of "Traction behavior of 4106 aviation lubricating oil", Tribology (China)
24(2):156-159, 2004, reports such a critical load for the sister oil 4106).

Provenance, honestly. The numbers of (3)-(5) are taken from the public MATLAB file
``oil_coe_model.m`` of github.com/Shane1911/Harris_model (commit e79b410), titled there
"lubricating oil 4109, traction coefficient vs slide-to-roll ratio (P = 20 N, V = 30 m/s,
R = 10 mm)" and plotted for theta = 25, 75, 125 degC and s = 0-0.2. Yan et al. 2025 print the
form (4) (their exponent of |W_c/W - 1| is lost in the text we could read) and attribute it
to Wang's thesis; the thesis itself and a table of its coefficients could not be retrieved,
so the coefficient values are NOT checked against the thesis: they are a transcription.
The oil constants of the transcription are its own: eta0 = 0.033 Pa s and k = 0.0966
W/(m K) are paper 001's Table 2 values for 4109, but its beta = 0.0215 1/K differs from
paper 001's 0.032; the defaults here are the transcription's (the fit was made with them).

Units, honestly. theta enters (2) as the numeric value of the oil inlet temperature in degC
(the transcription sweeps theta = 25/75/125 "degC"), so T is not a true dimensionless
group (it is not invariant under a change of temperature scale). A regression defines its
own variables: converting theta to kelvin would change T by a factor 12 at 25 degC and,
through T^X3, the coefficients completely. It is implemented as fitted (degC), which limits
it to theta > 0 degC (T -> 0 makes B diverge); it is not "made consistent" because no
consistent form reproduces the fitted numbers.

Validity. The disk-machine ranges of Wang's measurements are not stated in the
transcription. It exercises Q = 20-29 N on R = 10 mm (W ~ 1e-6, a ball-disc point
contact), u_e = 30 m/s, theta = 25-125 degC, |s| <= 0.2. Applied to a roller-raceway line
contact (W ~ 5e-4) the load is extrapolated; because the load exponents are small
(X1 |W_c/W - 1| <= 0.014) a factor 100 in W changes A by 3-6 %, so the curve depends on the
load mainly through the factor Q in F = mu Q: the traction of a contact is proportional to
its load, the property that distinguishes this law from a film rheology at the Hertz pressure
(whose traction at a fixed sliding speed grows like exp(alpha p_H)). Errors: non-positive
load, speed, radius or modulus, theta <= 0 degC. Warnings (ValidityWarning): theta outside
25-125 degC, |s| > 0.2 (in :func:`traction_coefficient` only).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from .errors import InputError, ValidityWarning, check_finite, check_positive
from .registry import Registry

#: named slide-to-roll traction curves
TRACTION_CURVES: Registry[Any] = Registry(
    "traction_curve", "traction coefficient mu(s) of the slide-to-roll ratio (fitted curves)")

#: 0 degC [K] (the Wang 4109 fit takes the inlet temperature in degC)
_ZERO_CELSIUS = 273.15


class FourCoefficients(NamedTuple):
    """Coefficients of mu(s) = (A + B s) exp(-C s) + D, s >= 0 (eq. 1) [-]."""

    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    d: np.ndarray


def four_coefficient_traction(slide_roll_ratio: Any, a: Any, b: Any, c: Any, d: Any
                              ) -> tuple[np.ndarray, np.ndarray]:
    """Traction coefficient of the four-coefficient curve and its slope (eq. 1).

    ``mu(s) = sign(s) [(A + B |s|) exp(-C |s|) + D]`` (odd in s: the traction opposes the
    sliding of the surface it acts on, whichever way it slides).

    Parameters
    ----------
    slide_roll_ratio : s = (u1 - u2)/u_e [-] (any sign).
    a, b, c, d : curve coefficients A, B, C, D [-] (C >= 0 for a curve that levels off).

    Returns
    -------
    mu : traction coefficient [-], sign of s (0 at s = 0).
    dmu_ds : d mu / d s [-] (even in s; at s = 0 the right-hand slope B - C A).

    Reference: Yan et al. 2025 eq. 15 (with exp(C s), C < 0); oil_coe_model.m (exp(-C s)).
    """
    s = np.asarray(slide_roll_ratio, dtype=float)
    s, a, b, c, d = np.broadcast_arrays(s, *(np.asarray(v, dtype=float) for v in (a, b, c, d)))
    x = np.abs(s)
    e = np.exp(-c * x)
    mu = np.sign(s) * ((a + b * x) * e + d)
    dmu = (b - c * (a + b * x)) * e
    if not (np.all(np.isfinite(mu)) and np.all(np.isfinite(dmu))):
        raise InputError("slide_roll_ratio / coefficients", "non-finite traction",
                         "finite s and coefficients (C >= 0)")
    return mu, dmu


def _group(name: str, value: Any) -> np.ndarray:
    v = np.asarray(value, dtype=float)
    if np.any(~np.isfinite(v)) or np.any(v <= 0.0):
        raise InputError(name, value, "> 0 and finite")
    return v


@TRACTION_CURVES.register(
    "oil4109_wang",
    references=["wang2006_aviation_oil_rheology", "yan2025_crb_flexible_rollers",
                "harris_model_matlab"],
    parameters={"load": "N", "entrainment_speed": "m/s", "reduced_radius": "m",
                "effective_modulus": "Pa", "temperature": "K", "eta0": "Pa*s",
                "beta": "1/K", "conductivity": "W/(m*K)"},
    validity="theta > 0 degC (errors); exercised by the source: theta 25-125 degC, "
             "|s| <= 0.2, u_e = 30 m/s, W ~ 1e-6 (ball-disc); fit ranges not published",
)
@dataclass(frozen=True)
class Oil4109Wang:
    """Aviation oil 4109: Wang's regression of A, B, C, D on W, U, T (eqs. 2-5).

    Attributes: the oil constants of the fit, eta0 [Pa s], beta [1/K] (viscosity-temperature
    coefficient), conductivity k [W/(m K)] (defaults: those of the transcription, see the
    module docstring).
    """

    eta0: float = 0.033
    beta: float = 0.0215
    conductivity: float = 0.0966
    name: str = "oil4109_wang"
    #: largest |s| exercised by the source (warnings beyond it) [-]
    s_max: float = 0.2

    def __post_init__(self) -> None:
        check_positive("eta0", self.eta0)
        check_positive("beta", self.beta)
        check_positive("conductivity", self.conductivity)

    def groups(self, load: Any, entrainment_speed: Any, reduced_radius: Any,
               effective_modulus: Any, temperature: Any
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """W, U, T of eq. 2 [-] (T with the inlet temperature in degC, module docstring).

        load Q [N], entrainment_speed u_e [m/s], reduced_radius R [m] (rolling direction),
        effective_modulus E' [Pa] (Hamrock's), temperature: oil inlet temperature [K].
        """
        q = _group("load", load)
        ue = _group("entrainment_speed", entrainment_speed)
        r = _group("reduced_radius", reduced_radius)
        e = _group("effective_modulus", effective_modulus)
        t = np.asarray(temperature, dtype=float)
        check_finite("temperature", t)
        theta = t - _ZERO_CELSIUS
        if np.any(theta <= 0.0):
            raise InputError("temperature", temperature,
                             "> 273.15 K: the 4109 fit uses the inlet temperature in degC "
                             "as a power-law variable")
        if np.any((theta < 25.0) | (theta > 125.0)):
            warnings.warn(f"oil4109_wang: inlet temperature {np.min(theta):.1f}-"
                          f"{np.max(theta):.1f} degC outside 25-125 degC exercised by the "
                          "source", ValidityWarning, stacklevel=3)
        er = e * r
        w = q / (er * r)
        u = self.eta0 * ue / er
        tt = theta * np.sqrt(self.conductivity * self.eta0 * self.beta) / er
        return w, u, tt

    def coefficients(self, load: Any, entrainment_speed: Any, reduced_radius: Any,
                     effective_modulus: Any, temperature: Any) -> FourCoefficients:
        """A, B, C, D of eq. 1 for the contact (eqs. 3-5); arguments as :meth:`groups`."""
        w, u, t = self.groups(load, entrainment_speed, reduced_radius, effective_modulus,
                              temperature)
        wc = 7.956015e12 * t**2 + 5553.09 * t + 1.758455e-6
        k = np.abs(wc / w - 1.0)
        a = -4.793526e-8 * w ** (0.0068361 * k) * u**-0.4047492 * t**-0.1833848
        b = 8.37449e-15 * w ** (0.01409715 * k) * u**-0.5868325 * t**-0.8173636
        c = 1.180823e-4 * w ** (0.006321 * k) * u**-0.20617 * t**-0.3631740
        return FourCoefficients(a, b, c, -a)

    def traction(self, slide_roll_ratio: Any, load: Any, entrainment_speed: Any,
                 reduced_radius: Any, effective_modulus: Any, temperature: Any
                 ) -> tuple[np.ndarray, np.ndarray]:
        """(mu, d mu/d s) at the slide-to-roll ratio s [-] for the contact (eq. 1)."""
        co = self.coefficients(load, entrainment_speed, reduced_radius, effective_modulus,
                               temperature)
        return four_coefficient_traction(slide_roll_ratio, *co)


@dataclass(frozen=True)
class FixedFourCoefficientCurve:
    """A four-coefficient curve with fixed A, B, C, D (eq. 1), e.g. a user's own disk fit.

    Attributes: a, b, c, d [-]; source (where the coefficients come from: required, so that
    a result can say what it used); s_max: largest |s| of the fit (warning beyond) [-].
    """

    a: float
    b: float
    c: float
    d: float
    source: str
    s_max: float = np.inf
    name: str = "fixed"

    def __post_init__(self) -> None:
        for f in ("a", "b", "c", "d"):
            check_finite(f, getattr(self, f))
        check_positive("c", self.c, allow_zero=True)
        if not self.s_max > 0.0:
            raise InputError("s_max", self.s_max, "> 0 (inf: no limit)")
        if not self.source.strip():
            raise InputError("source", self.source, "where the coefficients come from")

    def traction(self, slide_roll_ratio: Any, load: Any, entrainment_speed: Any,
                 reduced_radius: Any, effective_modulus: Any, temperature: Any
                 ) -> tuple[np.ndarray, np.ndarray]:
        """(mu, d mu/d s) at s [-]; the contact arguments are accepted and not used."""
        return four_coefficient_traction(slide_roll_ratio, self.a, self.b, self.c, self.d)


def get_traction_curve(curve: Any) -> Any:
    """A curve object from a name in :data:`TRACTION_CURVES` (or ``"curve:<name>"``), or the
    object itself if it already has ``traction(s, load, u_e, R, E', T)``."""
    if isinstance(curve, str):
        name = curve.removeprefix("curve:")
        return TRACTION_CURVES.get(name)()
    if not callable(getattr(curve, "traction", None)):
        raise InputError("traction_curve", curve,
                         f"a name in {sorted(TRACTION_CURVES.names())} or an object with "
                         "traction(s, load, u_e, R, E', T)")
    return curve


def traction_coefficient(curve: Any, slide_roll_ratio: Any, load: Any, entrainment_speed: Any,
                         reduced_radius: Any, effective_modulus: Any, temperature: Any
                         ) -> np.ndarray:
    """Traction coefficient mu [-] of a named curve (or curve object) at s [-] for a contact
    with normal load [N], entrainment speed [m/s], reduced radius [m], E' [Pa] and oil
    inlet temperature [K]; warns (ValidityWarning) where |s| exceeds the curve's ``s_max``
    (0.2 for ``oil4109_wang``, the largest slip its source exercises)."""
    c = get_traction_curve(curve)
    s = np.asarray(slide_roll_ratio, dtype=float)
    s_max = getattr(c, "s_max", np.inf)
    if np.any(np.abs(s) > s_max):
        warnings.warn(f"{getattr(c, 'name', 'curve')}: |s| up to {np.max(np.abs(s)):.3g} "
                      f"beyond {s_max:g} exercised by its source", ValidityWarning,
                      stacklevel=2)
    mu, _ = c.traction(s, load, entrainment_speed, reduced_radius, effective_modulus,
                       temperature)
    return mu
