"""Traction laws: shear stress in a lubricated rolling contact as a function of sliding speed.

Every law is a small frozen dataclass registered in :data:`TRACTION` with one method::

    law.shear_stress(slide_speed, pressure, film_thickness=None, temperature=None)
        -> ShearStress(stress [Pa], dstress_dspeed [Pa s/m])

evaluated point by point (numpy broadcasting) at the quadrature nodes of a contact by
:func:`thermobearing.contact_traction.integrate`. ``slide_speed`` is the *magnitude* of the
local sliding velocity [m/s] (>= 0); the stress acts against the sliding direction. The
derivative is returned so that the skidding solver gets an analytic Jacobian.

Laws
----
``linear_saturating``
    paper 004 (Luo et al. 2022, Fig. 3): mu rises linearly with the sliding speed up to mu_m
    at dv_m and stays at mu_m beyond; tau = mu p.
``eyring_limiting_shear``
    Newtonian or Eyring film, tau = tau0 asinh(eta(T, p) (dv/h) / tau0), with the viscosity
    at the local Hertzian pressure from the lubricant's pressure-viscosity law, capped by the
    limiting shear stress tau_L = Lambda p (Bair & Winer 1979). Needs film thickness and
    temperature.
``four_parameter``
    ADORE-type slip curve mu(u) = (A + B u) exp(-C u) + D (Gupta 1984), fitted to mu at zero
    slip, the maximum mu at the slip speed u_m, and mu at infinite slip; tau = mu p.

Use :func:`make_traction_law` to build a law by name from a scene's parameters.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any, NamedTuple, Protocol

import numba
import numpy as np
from llvmlite import ir
from numba import types
from numba.extending import intrinsic
from scipy.optimize import brentq

from .errors import InputError, check_positive, check_range
from .registry import Registry


class ShearStress(NamedTuple):
    """Local shear stress and its derivative with respect to the sliding speed."""

    stress: np.ndarray  #: shear stress [Pa], >= 0
    dstress_dspeed: np.ndarray  #: d(stress)/d(slide speed) [Pa s/m]


class TractionLaw(Protocol):
    """What :func:`thermobearing.contact_traction.integrate` needs from a law."""

    requires_film: bool

    def shear_stress(self, slide_speed: Any, pressure: Any, film_thickness: Any = None,
                     temperature: Any = None) -> ShearStress: ...


TRACTION: Registry[type] = Registry(
    "traction", "shear stress of a lubricated rolling contact versus sliding speed")


def _check_coefficient(field: str, value: float) -> None:
    check_range(field, value, 0.0, 1.0)


def _as_speed(slide_speed: Any) -> np.ndarray:
    s = np.asarray(slide_speed, dtype=float)
    if np.any(s < 0) or not np.all(np.isfinite(s)):
        raise InputError("traction.slide_speed", "negative or non-finite values",
                         "sliding-speed magnitudes >= 0 [m/s]")
    return s


def _as_pressure(pressure: Any) -> np.ndarray:
    """Pressure array [Pa]; NaN or inf raise InputError (a NaN pressure gave a NaN stress
    silently in the pressure-proportional laws)."""
    p = np.asarray(pressure, dtype=float)
    if not np.all(np.isfinite(p)):
        raise InputError("traction.pressure", "non-finite values", "finite pressures [Pa]")
    return p


# ---------------------------------------------------------------------------
# Compiled kernels: the ONE implementation of every law's stress. ``shear_stress`` (below)
# and the contact integration (contact_traction._integrate_contacts, also inside the ball
# skidding residual) call these same functions. A law is handed to compiled code as
# (law id, params): params is the law's float64[4] (see each law's ``kernel``).
LINEAR_SATURATING, EYRING, FOUR_PARAMETER = 0, 1, 2


@numba.njit(cache=True, inline="always")
def _law_stress(law_id: int, params: np.ndarray, s: float, p: float, rate: float,
                need_d: bool) -> tuple[float, float]:
    """(tau [Pa], d tau / d s [Pa s/m]) of law ``law_id`` at the slide speed s >= 0 [m/s] and
    pressure p [Pa]; ``rate`` = eta(T, p) / h [Pa s/m] (viscosity over film thickness, used by
    the film law only). ``need_d`` False returns 0 for the derivative (skips its work). The
    formulas are documented on the law classes below."""
    if law_id == LINEAR_SATURATING:
        # paper 004 Fig. 3: mu = mu_m min(s / dv_m, 1), tau = mu p
        mu_m, dv_m = params[0], params[1]
        if s < dv_m:
            return mu_m * (s / dv_m) * p, (mu_m / dv_m) * p
        return mu_m * p, 0.0 * p
    if law_id == EYRING:
        # params: (Lambda, tau0 (0: Newtonian), 1.0 smooth cap / 0.0 min cap, 1/tau0)
        lam, tau0, smooth = params[0], params[1], params[2]
        if p < 0.0:
            p = 0.0
        tau_n = rate * s                     # Newtonian stress eta dv / h
        dtau_e = 0.0
        if tau0 > 0.0:
            x = tau_n * params[3]
            tau_e = tau0 * math.asinh(x)
            if need_d:
                dtau_e = rate / math.sqrt(1.0 + x * x)
        else:
            tau_e, dtau_e = tau_n, rate
        tau_l = lam * p
        if smooth == 0.0:
            if tau_e >= tau_l:
                return tau_l, 0.0
            return tau_e, dtau_e
        if tau_l > 0.0:
            # tau_E / sqrt(1 + (tau_E / tau_L)^2), written with the smaller stress over the
            # larger: tau_E^2 overflowed above 1.3e154 Pa (a Newtonian film, eta dv / h
            # unbounded) and the stress fell to 0 instead of tau_L
            if tau_e <= tau_l:
                r = tau_e / tau_l
                factor = 1.0 / math.sqrt(1.0 + r * r)
                tau = tau_e * factor
            else:
                r = tau_l / tau_e
                root = math.sqrt(1.0 + r * r)
                factor = r / root
                tau = tau_l / root
        else:
            factor = 1e-150                  # tau_E / tau_L -> inf, capped at 1e150
            tau = tau_e * factor
        if need_d:
            return tau, dtau_e * (factor * factor * factor)
        return tau, 0.0
    # FOUR_PARAMETER: mu = (A + B u) exp(-C u) + D, tau = mu p
    a, b, c, d = params[0], params[1], params[2], params[3]
    e = math.exp(-c * s)
    return ((a + b * s) * e + d) * p, ((b - c * (a + b * s)) * e) * p


@numba.njit(cache=True, inline="always")
def _eyring_smooth_node(lam: float, tau0: float, inv_tau0: float, s: float, p: float,
                        rate: float, weight: float) -> float:
    """Fast path of the ``eyring`` law with the smooth cap and tau0 > 0 (the ball solver's
    default) for the contact integration: tau(s, p) * weight [N] for slide speed s >= 0
    [m/s], pressure p >= 0 [Pa], rate = eta / h [Pa s/m] and the node's area ``weight``
    [m^2]. The same formula as :func:`_law_stress` (tau_E = tau0 asinh(eta s / (h tau0)),
    tau = tau_E tau_L / sqrt(tau_L^2 + tau_E^2), tau_L = Lambda p; tau_E 1e-150 when
    tau_L = 0), without its branches on the law, the cap and the derivative; equal to it
    to round-off (a few ulp; test). Reference: :class:`EyringTraction`."""
    tau_e = tau0 * math.asinh(rate * s * inv_tau0)
    tau_l = lam * p
    if tau_l > 0.0:
        return tau_e * tau_l * weight / math.sqrt(tau_l * tau_l + tau_e * tau_e)
    return tau_e * 1e-150 * weight



# ---------------------------------------------------------------------------
# Vectorisable elementary functions of the Eyring fast path. numba compiles
# math.log / math.asinh to calls of the C library, which stop LLVM from vectorising the
# contact integration's node loop; these are the same algorithms in straight-line code
# (bit manipulation and polynomials only), so that the node loop of
# ``contact_traction._integrate_eyring_fast`` runs in SIMD registers (2.2-2.5x faster,
# measured in-process on the 48 loaded contacts of a Z = 16 QJ1044 state).
@intrinsic
def _bits_of(typingctx, x):
    """The IEEE-754 bit pattern of a float64 as an int64 (an LLVM bitcast, no conversion)."""
    sig = types.int64(types.float64)

    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], ir.IntType(64))

    return sig, codegen


@intrinsic
def _float_of(typingctx, i):
    """The float64 whose IEEE-754 bit pattern is the int64 ``i`` (an LLVM bitcast)."""
    sig = types.float64(types.int64)

    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], ir.DoubleType())

    return sig, codegen


# fdlibm e_log.c (Sun Microsystems 1993, as in FreeBSD and musl): log(1+f) = f - f^2/2 +
# s (f^2/2 + R(s^2)), s = f / (2 + f), R a minimax polynomial (error < 2^-58.45)
_LG1, _LG2 = 6.666666666666735130e-01, 3.999999999940941908e-01
_LG3, _LG4 = 2.857142874366239149e-01, 2.222219843214978396e-01
_LG5, _LG6 = 1.818357216161805012e-01, 1.531383769920937332e-01
_LG7 = 1.479819860511658591e-01
_LN2_HI, _LN2_LO = 6.93147180369123816490e-01, 1.90821492927058770002e-10
_ASINH_BIG = 268435456.0           # 2^28: asinh(x) = ln(2x) to double precision above
_LN2 = 6.93147180559945286227e-01


@numba.njit(cache=True, inline="always", error_model="numpy")
def _log_pos(x: float) -> float:
    """Natural logarithm of a finite normal x > 0 without branches (vectorisable).

    fdlibm's ``e_log.c`` (Sun Microsystems 1993; the algorithm of FreeBSD's and musl's
    ``log``): x = 2^k (1 + f) with 1 + f in [sqrt(2)/2, sqrt(2)) taken from the bit pattern,
    log x = k ln2_hi + (f - f^2/2 + s (f^2/2 + R(s^2)) + k ln2_lo), s = f / (2 + f). Within
    1 ulp of the C library's log (test: 2e5 values over 1e-300..1e300); not for x <= 0,
    subnormal x, inf or nan (the callers pass x >= 1)."""
    ix = _bits_of(x)
    hx = (ix >> 32) + (0x3FF00000 - 0x3FE6A09E)
    k = (hx >> 20) - 0x3FF
    hx = (hx & 0x000FFFFF) + 0x3FE6A09E
    f = _float_of((hx << 32) | (ix & 0xFFFFFFFF)) - 1.0
    hfsq = 0.5 * f * f
    s = f / (2.0 + f)
    z = s * s
    w = z * z
    t1 = w * (_LG2 + w * (_LG4 + w * _LG6))
    t2 = z * (_LG1 + w * (_LG3 + w * (_LG5 + w * _LG7)))
    dk = float(k)
    return s * (hfsq + t1 + t2) + dk * _LN2_LO - hfsq + f + dk * _LN2_HI


@numba.njit(cache=True, inline="always", error_model="numpy")
def _asinh_abs(x: float) -> float:
    """asinh(x) = ln(x + sqrt(1 + x^2)) for x >= 0 without branches (vectorisable) [-], with
    the log of :func:`_log_pos`; above 2^28 ln(x) + ln(2) (the neglected 1/(4x^2) is below
    2^-58).

    Accurate in absolute terms: measured (2e5 values over 4e-18..2e17 and edge cases, test)
    within 2 ulp of the C library's asinh where asinh >= 0.5 and within 2.8e-16 absolute
    below, where the relative error grows like 1e-16 / x (no log1p: for the Eyring stress
    tau0 asinh(x) of a quadrature node that is an absolute error below tau0 2.8e-16, under
    the round-off of the contact's node sums, and it saves two divisions per node against
    the log1p form). nan and inf give nan."""
    u = x + math.sqrt(1.0 + x * x)
    c = 0.0 * x                                      # 0, or nan for nan / inf input
    if x > _ASINH_BIG:
        u = x
        c += _LN2
    return _log_pos(u) + c


# fdlibm e_exp.c (Sun Microsystems 1993): exp(r) = 1 + r + r c / (2 - c) with
# c = r - r^2 (P1 + r^2 (P2 + ... P5)) on |r| <= ln2 / 2 (error < 2^-59)
_P1, _P2 = 1.66666666666666019037e-01, -2.77777777770155933842e-03
_P3, _P4 = 6.61375632143793436117e-05, -1.65339022054652515390e-06
_P5 = 4.13813679705723846039e-08
_INV_LN2 = 1.44269504088896338700e+00


@numba.njit(cache=True, inline="always", error_model="numpy")
def _exp_fin(x: float) -> float:
    """exp(x) for -708 <= x <= 709 without branches (vectorisable) [-].

    fdlibm's ``e_exp.c`` (Sun Microsystems 1993): x = k ln2 + r, k = round(x / ln2), ln2
    split in a high and a low part, exp(r) = 1 - ((lo - r c / (2 - c)) - hi) with the minimax
    polynomial c, times 2^k from the bit pattern. Within 1 ulp of the C library's exp
    (test); outside the range (overflow, subnormal results) not valid -- the callers take
    logarithms of positive normal numbers."""
    k = math.floor(_INV_LN2 * x + 0.5)
    hi = x - k * _LN2_HI
    lo = k * _LN2_LO
    r = hi - lo
    t = r * r
    c = r - t * (_P1 + t * (_P2 + t * (_P3 + t * (_P4 + t * _P5))))
    y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi)
    return y * _float_of((int(k) + 1023) << 52)


@numba.njit(cache=True)
def _stress_array(law_id: int, params: np.ndarray, s: np.ndarray, p: np.ndarray,
                  eta: np.ndarray, h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_law_stress` over flat float64 arrays of one length (eta and h may have
    length 1: the same value for every point)."""
    n = s.size
    tau = np.empty(n)
    dtau = np.empty(n)
    one_e = eta.size == 1
    one_h = h.size == 1
    for i in range(n):
        tau[i], dtau[i] = _law_stress(law_id, params, s[i], p[i],
                                      eta[0 if one_e else i] / h[0 if one_h else i], True)
    return tau, dtau


def _call_kernel(law_id: int, params: np.ndarray, s: Any, p: Any, eta: Any = None,
                 h: Any = None) -> ShearStress:
    """Broadcast the inputs, run :func:`_stress_array`, give the broadcast shape back."""
    arrays = [np.asarray(s, dtype=float), np.asarray(p, dtype=float)]
    if eta is not None:
        arrays += [np.asarray(eta, dtype=float), np.asarray(h, dtype=float)]
    arrays = np.broadcast_arrays(*arrays)
    shape = arrays[0].shape
    flat = [np.ascontiguousarray(a).ravel() for a in arrays]
    one = np.ones(1)
    e_, h_ = (flat[2], flat[3]) if eta is not None else (one, one)
    tau, dtau = _stress_array(law_id, params, flat[0], flat[1], e_, h_)
    return ShearStress(tau.reshape(shape), dtau.reshape(shape))


# ---------------------------------------------------------------------------
@TRACTION.register(
    "linear_saturating",
    references=["luo2022_cage_slip_vibration"],
    parameters={"mu_max": "-", "slip_speed_max": "m/s"},
    validity="0 <= mu_max <= 1; slip_speed_max > 0; independent of pressure, temperature, film",
)
@dataclass(frozen=True)
class LinearSaturatingTraction:
    """Linear-then-constant friction-slip law of paper 004 (Luo et al. 2022, Fig. 3).

    mu(dv) = mu_m * dv / dv_m for dv < dv_m, and mu_m for dv >= dv_m; tau = mu * p.

    Parameters
    ----------
    mu_max : mu_m, friction coefficient reached at and beyond ``slip_speed_max`` [-].
        Paper 004 uses 0.01 ... 0.05.
    slip_speed_max : dv_m, sliding speed at which mu saturates [m/s].

    Notes
    -----
    Source: seed paper 004_0105d7aba121b014.txt, Section 2 and Fig. 3 (the paper gives the
    shape, not dv_m). The paper states the law is independent of speed, pressure and
    temperature (a "solid lubricant" idealisation after Gupta); film thickness is ignored.
    """

    mu_max: float
    slip_speed_max: float
    requires_film = False

    def __post_init__(self) -> None:
        _check_coefficient("traction.mu_max", self.mu_max)
        check_positive("traction.slip_speed_max", self.slip_speed_max)

    def coefficient(self, slide_speed: Any) -> np.ndarray:
        """Friction coefficient mu(dv) [-]."""
        s = _as_speed(slide_speed)
        return self.mu_max * np.minimum(s / self.slip_speed_max, 1.0)

    def shear_stress(self, slide_speed: Any, pressure: Any, film_thickness: Any = None,
                     temperature: Any = None) -> ShearStress:
        """Shear stress tau = mu(dv) p [Pa] and d tau / d dv [Pa s/m]."""
        return self._stress(_as_speed(slide_speed), _as_pressure(pressure))

    @functools.cached_property
    def kernel(self) -> tuple[int, np.ndarray]:
        """(law id, params) for the compiled kernels: (mu_max, slip_speed_max, 0, 0)."""
        return LINEAR_SATURATING, np.array([self.mu_max, self.slip_speed_max, 0.0, 0.0])

    def _stress(self, s: np.ndarray, p: np.ndarray, film_thickness: Any = None,
                temperature: Any = None, derivative: bool = True) -> ShearStress:
        """Unchecked core of :meth:`shear_stress` (float arrays, s >= 0 finite): the
        compiled :func:`_law_stress`."""
        return _call_kernel(*self.kernel, s, p)


# ---------------------------------------------------------------------------
@TRACTION.register(
    "eyring_limiting_shear",
    references=["johnson_tevaarwerk1977_traction", "bair_winer1979_limiting_shear",
                "gao2022_overskidding"],
    parameters={"limiting_shear_coefficient": "-", "eyring_stress": "Pa"},
    validity="full-film EHL (film thickness > 0); Lambda 0.03-0.12; tau0 ~ 1-20 MPa; "
             "isothermal film at the contact inlet temperature",
)
@dataclass(frozen=True)
class EyringLimitingShearTraction:
    """Newtonian/Eyring film with a limiting shear stress tau_L = Lambda p.

    tau_E = tau0 * asinh(eta(T, p) * gamma / tau0),  gamma = dv / h   (Eyring; Newtonian
    eta * gamma when ``eyring_stress`` is None), then capped by the limiting shear stress

        cap = "min":     tau = min(tau_E, Lambda p)
        cap = "smooth":  tau = tau_E / sqrt(1 + (tau_E / (Lambda p))**2)

    Parameters
    ----------
    lubricant : :class:`thermobearing.lubricant.Lubricant`; its ``dynamic_viscosity(T, p)``
        [Pa s] (the lubricant's pressure-viscosity law, Barus or Roelands) is evaluated at the
        local Hertzian pressure of every quadrature node.
    limiting_shear_coefficient : Lambda [-]; Bair & Winer report 0.05-0.1 for mineral oils
        and esters, traction fluids at the top of the range.
    eyring_stress : tau0 [Pa] (None: Newtonian). Order 2-10 MPa for mineral oils at EHL
        pressures (Johnson & Tevaarwerk 1977).
    cap : "min" (default, the literal cap) or "smooth" (differentiable everywhere).

    Notes
    -----
    This is the bounded form of paper 002 (seed 002_0add79adaca5495c.txt) eq. 11, which
    writes the shear heat as eta(T, p, gamma) dU^2 / h. Taken literally with the viscosity
    at Hertzian pressure (e.g. Barus, alpha = 2e-8 1/Pa, p = 1.5 GPa: eta/eta0 = e^30 ~ 1e13)
    eq. 11 is unbounded, so the shear stress must come from a traction law with a limit:
    this one. The film is isothermal at ``temperature`` (no flash-temperature rise), so the
    law over-predicts traction at large slip unless Lambda is taken at the contact temperature.
    """

    lubricant: Any
    limiting_shear_coefficient: float = 0.075
    eyring_stress: float | None = 5.0e6
    cap: str = "min"
    requires_film = True

    def __post_init__(self) -> None:
        check_range("traction.limiting_shear_coefficient", self.limiting_shear_coefficient,
                    0.0, 1.0, low_inclusive=False)
        if self.eyring_stress is not None:
            check_positive("traction.eyring_stress", self.eyring_stress)
        if self.cap not in ("min", "smooth"):
            raise InputError("traction.cap", self.cap, "'min' or 'smooth'")
        if not hasattr(self.lubricant, "dynamic_viscosity"):
            raise InputError("traction.lubricant", self.lubricant,
                             "a Lubricant with dynamic_viscosity(T, p)")

    def shear_stress(self, slide_speed: Any, pressure: Any, film_thickness: Any = None,
                     temperature: Any = None) -> ShearStress:
        """Shear stress [Pa] and its derivative [Pa s/m] at sliding speed, pressure, h, T."""
        if film_thickness is None:
            raise InputError("traction[eyring_limiting_shear].film_thickness", None,
                             "a film thickness [m] > 0 (this law shears a fluid film)")
        if temperature is None:
            raise InputError("traction[eyring_limiting_shear].temperature", None,
                             "a contact temperature [K]")
        h = np.asarray(film_thickness, dtype=float)
        check_positive("traction[eyring_limiting_shear].film_thickness", h)
        return self._stress(_as_speed(slide_speed), np.asarray(pressure, dtype=float), h,
                            temperature)

    @functools.cached_property
    def kernel(self) -> tuple[int, np.ndarray]:
        """(law id, params) for the compiled kernels: (Lambda, tau0 or 0 for Newtonian,
        1 for the smooth cap or 0 for the min cap, 1/tau0 or 0)."""
        tau0 = 0.0 if self.eyring_stress is None else float(self.eyring_stress)
        return EYRING, np.array([self.limiting_shear_coefficient, tau0,
                                 1.0 if self.cap == "smooth" else 0.0,
                                 1.0 / tau0 if tau0 > 0 else 0.0])

    def _stress(self, s: np.ndarray, p: np.ndarray, h: np.ndarray,
                temperature: Any, derivative: bool = True) -> ShearStress:
        """Unchecked core of :meth:`shear_stress` (float arrays; s >= 0 finite, h > 0).

        The viscosity eta(T, max(p, 0)) comes from the lubricant, the stress from the
        compiled :func:`_law_stress`. ``derivative`` is accepted for the callers'
        convenience; the derivative is always returned (it costs nothing in the kernel)."""
        p = np.asarray(p, dtype=float)
        eta = np.asarray(self.lubricant.dynamic_viscosity(temperature, np.maximum(p, 0.0)),
                         dtype=float)
        return _call_kernel(*self.kernel, s, p, eta, h)

    def coefficient(self, slide_speed: Any, pressure: Any, film_thickness: Any,
                    temperature: Any) -> np.ndarray:
        """Local traction coefficient tau / p [-]."""
        tau = self.shear_stress(slide_speed, pressure, film_thickness, temperature).stress
        return tau / np.asarray(pressure, dtype=float)


# ---------------------------------------------------------------------------
def fit_four_parameter(mu_zero: float, mu_max: float, slip_speed_at_max: float,
                       mu_infinity: float) -> tuple[float, float, float, float]:
    """Coefficients (A, B, C, D) of mu(u) = (A + B u) exp(-C u) + D.

    Conditions: mu(0) = mu_zero, mu(inf) = mu_infinity, d mu/du = 0 at u_m with mu(u_m) =
    mu_max. Then D = mu_inf, A = mu_0 - mu_inf, B = C A / (1 - s) with s = C u_m, and s solves
    A exp(-s) / (1 - s) = mu_max - mu_inf (s in (0, 1) for A > 0, s > 1 for A < 0, s = 1 and
    B = e (mu_max - mu_inf) / u_m for A = 0). Derivation: primer losses-and-heat-transfer 6
    (checked here by substitution, see tests).

    Returns
    -------
    A [-], B [s/m], C [s/m], D [-]
    """
    for name, v in (("mu_zero", mu_zero), ("mu_max", mu_max), ("mu_infinity", mu_infinity)):
        _check_coefficient(f"traction.{name}", v)
    check_positive("traction.slip_speed_at_max", slip_speed_at_max)
    if mu_max <= max(mu_zero, mu_infinity):
        raise InputError("traction.mu_max", mu_max,
                         f"a peak above mu_zero = {mu_zero} and mu_infinity = {mu_infinity}")
    a = mu_zero - mu_infinity
    d = mu_infinity
    target = mu_max - mu_infinity
    um = slip_speed_at_max
    if abs(a) <= 1e-200 * target:
        # A = 0 (or so small against the peak that 1 - s underflows): s = 1, B = e target / u_m;
        # A is kept, so mu(0) = mu_zero exactly and mu(u_m) = mu_max to A / e
        return a, math.e * target / um, 1.0 / um, d
    # solved for y = ln t, t = |1 - s| (not for s): near s = 1 (|A| << mu_max - mu_inf)
    # B = C A / (1 - s) needs 1 - s to full relative precision; an absolute tolerance on s
    # lost it (A = 1e-14 put the peak 2.4 % off mu_max), and bisection in t itself does not
    # reach t ~ 1e-38 in brentq's 100 iterations
    ln_ratio = math.log(abs(a)) - math.log(target)
    if a > 0:
        # s = 1 - t in (0, 1): a e^-s/(1-s) = target  <=>  y - e^y = ln(a/target) - 1,
        # rising on y < 0 from -inf to -1; ln(a/target) < 0, so the root has y < 0
        def g(y: float) -> float:
            return y - math.exp(y) - ln_ratio + 1.0
        y = brentq(g, ln_ratio - 2.0, 0.0, xtol=1e-15, rtol=1e-15)
    else:
        # s = 1 + t, t > 0: |a| e^-s/(s-1) = target  <=>  y + e^y = ln(|a|/target) - 1,
        # rising from -inf to +inf
        def g(y: float) -> float:
            return y + math.exp(y) - ln_ratio + 1.0
        lo = min(ln_ratio - 2.0, -1.0)
        y = brentq(g, lo, max(ln_ratio, lo + 1.0), xtol=1e-15, rtol=1e-15)
    t = math.exp(y)
    s = 1.0 - t if a > 0 else 1.0 + t
    c = s / um
    b = c * a / t if a > 0 else -c * a / t
    return a, b, c, d


@TRACTION.register(
    "four_parameter",
    references=["gupta1984_adore", "harris_kotzalas2007"],
    parameters={"mu_zero": "-", "mu_max": "-", "slip_speed_at_max": "m/s", "mu_infinity": "-"},
    validity="coefficients in [0, 1], mu_max above mu_zero and mu_infinity; slip speed in m/s",
)
@dataclass(frozen=True)
class FourParameterTraction:
    """ADORE-type slip curve mu(u) = (A + B u) exp(-C u) + D, tau = mu p.

    Parameters
    ----------
    mu_zero : mu at zero slip [-].
    mu_max : maximum mu [-], reached at ``slip_speed_at_max``.
    slip_speed_at_max : u_m [m/s].
    mu_infinity : mu as the slip speed goes to infinity [-].

    Notes
    -----
    The functional form is the one of Gupta's ADORE (Gupta 1984, Advanced Dynamics of
    Rolling Elements) as used in public ADORE-style codes (primer over-skidding 3.6); the
    coefficients are fitted by :func:`fit_four_parameter`. With mu_zero > 0 the stress does
    not vanish at zero slip, so the traction direction jumps across a zero-slip line; the
    contact integral then converges only as O(1/n) in the node count.
    """

    mu_zero: float
    mu_max: float
    slip_speed_at_max: float
    mu_infinity: float
    requires_film = False

    def __post_init__(self) -> None:
        fit_four_parameter(self.mu_zero, self.mu_max, self.slip_speed_at_max, self.mu_infinity)

    @property
    def coefficients(self) -> tuple[float, float, float, float]:
        """(A, B, C, D)."""
        return self._coefficients

    @functools.cached_property
    def _coefficients(self) -> tuple[float, float, float, float]:
        # fitted once per law (a brentq root solve; the law is frozen)
        return fit_four_parameter(self.mu_zero, self.mu_max, self.slip_speed_at_max,
                                  self.mu_infinity)

    def coefficient(self, slide_speed: Any) -> np.ndarray:
        """Friction coefficient mu(u) [-]."""
        a, b, c, d = self.coefficients
        u = _as_speed(slide_speed)
        return (a + b * u) * np.exp(-c * u) + d

    def shear_stress(self, slide_speed: Any, pressure: Any, film_thickness: Any = None,
                     temperature: Any = None) -> ShearStress:
        """Shear stress mu(u) p [Pa] and its derivative [Pa s/m]."""
        return self._stress(_as_speed(slide_speed), _as_pressure(pressure))

    @functools.cached_property
    def kernel(self) -> tuple[int, np.ndarray]:
        """(law id, params) for the compiled kernels: (A, B, C, D)."""
        return FOUR_PARAMETER, np.array(self._coefficients, dtype=float)

    def _stress(self, u: np.ndarray, p: np.ndarray, film_thickness: Any = None,
                temperature: Any = None, derivative: bool = True) -> ShearStress:
        """Unchecked core of :meth:`shear_stress` (float arrays, u >= 0 finite): the
        compiled :func:`_law_stress`."""
        return _call_kernel(*self.kernel, u, p)


def make_traction_law(name: str, **parameters: Any) -> TractionLaw:
    """Build the traction law registered as ``name`` with keyword ``parameters``.

    Example: ``make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.1)``.
    Unknown names raise :class:`~thermobearing.errors.UnknownNameError` listing the known ones;
    unknown or missing parameters raise :class:`~thermobearing.errors.InputError`.
    """
    cls = TRACTION.get(name)
    try:
        return cls(**parameters)
    except TypeError as exc:
        import dataclasses
        import inspect

        if dataclasses.is_dataclass(cls):
            known = [f.name for f in dataclasses.fields(cls) if f.init]
        else:
            known = [p for p in inspect.signature(cls).parameters if p != "self"]
        raise InputError(f"traction[{name}] parameters", sorted(parameters),
                         f"the parameters of {name!r}: {', '.join(known)} ({exc})") from None
