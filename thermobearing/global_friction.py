"""Global (whole-bearing) friction models: the SKF four-term model and Palmgren M0 + M1.

These are catalogue-level cross-checks for the local heat-source sum; they are registered
in :data:`GLOBAL_FRICTION` and are not the default loss model.

SI in, SI out: lengths [m], loads [N], speed [rad/s] (relative speed of the rings),
kinematic viscosity [m^2/s] at the operating temperature; torque [N m] and power [W].
Internally both models work in the catalogue units they were fitted in (N mm, mm, r/min,
mm^2/s), converted at the edges.

Sources
-------
- SKF four-term model: SKF General Catalogue 10000 EN (2012) / Rolling bearings 17000 EN
  (2018), section "The SKF model for calculating the frictional moment". The formulas
  below were checked against a public transcription of that catalogue (repository
  JRaposo-m/SKF-Bearing-Selection-Tool: frictional_moment.py, geometry_variables.py,
  friction_RS_constants.csv, digitised V_M curves) and the SKF web pages on inlet shear and
  drag losses; the per-series constants R1..R3, S1..S3 (catalogue Table 1a / 2) are as
  transcribed there and agree with the values the author of this module recalls for the
  62/63 deep-groove and four-point rows.
- Palmgren: M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 (nu n >= 2000), 160e-7 f0 d_m^3 below;
  M1 = f1 P1 d_m (Palmgren 1959; Harris & Kotzalas 2007 ch. 11 of vol. 1); f0, f1 and the P1
  rules of the Schaeffler catalogue as transcribed in the Thermca library
  (steffenschroe/Thermca: thermca/lib/bearing.py, after Jungnickel 2010 and Schaeffler 2013).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.interpolate import PchipInterpolator

from .errors import InputError, UnknownNameError, check_positive, check_range
from .registry import Registry

__all__ = [
    "GLOBAL_FRICTION", "KINDS", "LUBRICATION", "PALMGREN_FACTORS", "SKF_KL", "SKF_KZ", "SKF_RS",
    "BearingEnvelope", "GlobalFrictionResult", "envelope_of", "global_friction",
    "infer_skf_series", "palmgren", "palmgren_equivalent_load", "skf_drag_factor",
    "skf_four_term", "skf_geometry_variables",
]

GLOBAL_FRICTION: Registry[Callable[..., Any]] = Registry(
    "global_friction",
    "whole-bearing frictional moment models (catalogue cross-checks of the local heat sources)",
)

KINDS = ("deep_groove", "angular_contact", "four_point", "cylindrical")
LUBRICATION = ("oil_bath", "oil_jet", "circulating", "oil_air", "grease")
#: OilSupply.method spellings (thermobearing.state) -> the names used here
_LUBRICATION_ALIASES = {"jet": "oil_jet", "circulation": "circulating"}
_RPM_PER_RAD_S = 60.0 / (2.0 * math.pi)


# ---------------------------------------------------------------------------
# bearing envelope
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class BearingEnvelope:
    """What the catalogue models need to know about a bearing (SI).

    Attributes
    ----------
    kind : "deep_groove" | "angular_contact" | "four_point" | "cylindrical".
    bore, outer_diameter, width : d, D, B [m].
    element_diameter : ball or roller diameter [m] (oil-jet drag level).
    name : designation, used to infer the SKF series ("6304" -> "63", "NU214" -> "2").
    static_load_rating : C0 [N] (needed by SKF for a deep-groove bearing with axial load).
    rows : number of rows of rolling elements.
    """

    kind: str
    bore: float
    outer_diameter: float
    width: float
    element_diameter: float | None = None
    name: str = ""
    static_load_rating: float | None = None
    rows: int = 1

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise UnknownNameError("bearing.kind", self.kind, KINDS)
        check_positive("bearing.bore", self.bore)
        check_positive("bearing.outer_diameter", self.outer_diameter)
        check_positive("bearing.width", self.width)
        if self.outer_diameter <= self.bore:
            raise InputError("bearing.outer_diameter", self.outer_diameter,
                             f"a diameter larger than the bore {self.bore} m")
        if self.element_diameter is not None:
            check_positive("bearing.element_diameter", self.element_diameter)
        if self.static_load_rating is not None:
            check_positive("bearing.static_load_rating", self.static_load_rating)

    @property
    def mean_diameter(self) -> float:
        """Catalogue mean diameter d_m = (d + D)/2 [m]."""
        return 0.5 * (self.bore + self.outer_diameter)


def envelope_of(bearing: Any) -> BearingEnvelope:
    """A :class:`BearingEnvelope` from a BallBearing/RollerBearing (duck-typed) or itself."""
    if isinstance(bearing, BearingEnvelope):
        return bearing
    try:
        kind = bearing.kind
        d, D, B = bearing.bore, bearing.outer_diameter, bearing.width
    except AttributeError:
        raise InputError("bearing", type(bearing).__name__, "a BallBearing, RollerBearing or "
                         "BearingEnvelope (kind, bore, outer_diameter, width)") from None
    element = getattr(bearing, "ball_diameter", None) or getattr(bearing, "roller_diameter", None)
    return BearingEnvelope(kind=kind, bore=d, outer_diameter=D, width=B,
                           element_diameter=element, name=getattr(bearing, "name", ""),
                           static_load_rating=getattr(bearing, "static_load_rating", None))


# ---------------------------------------------------------------------------
# SKF constants (catalogue Table 1a / 2 and the drag table)
# ---------------------------------------------------------------------------
#: (kind, series) -> (R1, R2, R3, S1, S2, S3); None where the catalogue has no entry.
SKF_RS: dict[tuple[str, str], tuple[float, float | None, float | None, float, float | None,
                                    float | None]] = {}
for _s, _v in {
    ("2", "3"): (4.4e-7, 1.7, 2.00e-3, 100.0),
    ("42", "43"): (5.4e-7, 0.96, 3.00e-3, 40.0),
    ("60", "630"): (4.1e-7, 1.7, 3.73e-3, 14.6),
    ("62", "622"): (3.9e-7, 1.7, 3.23e-3, 36.5),
    ("63", "623"): (3.7e-7, 1.7, 2.84e-3, 92.8),
    ("64",): (3.6e-7, 1.7, 2.43e-3, 198.0),
    ("160", "161"): (4.3e-7, 1.7, 4.63e-3, 4.25),
    ("617", "618", "628", "637", "638"): (4.7e-7, 1.7, 6.50e-3, 0.78),
    ("619", "639"): (4.3e-7, 1.7, 4.75e-3, 3.6),
}.items():
    for _series in _s:
        SKF_RS[("deep_groove", _series)] = (_v[0], _v[1], None, _v[2], _v[3], None)
for _series, _v in {
    "72_BECBP": (4.33e-7, 2.02, 2.44e-12, 1.82e-2, 0.71, 2.44e-12),
    "73_BECBP": (4.54e-7, 2.02, 1.84e-12, 1.64e-2, 0.71, 1.84e-12),
    "72_ACCBM": (3.58e-7, 3.64, 3.55e-12, 1.14e-2, 1.55, 3.55e-12),
    "73_ACCBM": (3.48e-7, 3.64, 1.66e-12, 9.85e-3, 1.55, 1.66e-12),
    "32_A": (5.18e-7, 1.63, 4.18e-12, 1.08e-2, 1.47, 4.18e-12),
    "33_A": (5.31e-7, 1.63, 8.83e-13, 5.48e-3, 1.47, 8.83e-13),
}.items():
    SKF_RS[("angular_contact", _series)] = _v
SKF_RS[("four_point", "QJ")] = (4.78e-7, 2.42, 1.40e-12, 1.20e-2, 0.9, 1.40e-12)
for _s, _v in {
    ("2", "3"): (1.09e-6, 0.16),
    ("4",): (1.00e-6, 0.16),
    ("10",): (1.12e-6, 0.17),
    ("12", "20"): (1.23e-6, 0.16),
    ("22",): (1.40e-6, 0.16),
    ("23",): (1.48e-6, 0.16),
    ("full_complement",): (2.13e-6, 0.16),
}.items():
    for _series in _s:
        SKF_RS[("cylindrical", _series)] = (_v[0], None, None, _v[1], 0.0015, None)

#: drag constants K_Z (and K_L for rollers), SKF catalogue drag-loss table
SKF_KZ = {"deep_groove": 3.1, "angular_contact": 4.4, "four_point": 3.1, "cylindrical": 5.1}
SKF_KL = {"cylindrical": 0.65}

# V_M against H/d_m, SKF catalogue diagram, digitised (JRaposo-m/SKF-Bearing-Selection-Tool
# Graficos/.../Drag Loss Factor Vm/{ball,roller}_bearing.csv; the two lowest ball points
# from the zoomed diagram as quoted in shared/notes/losses-and-heat-transfer.md sec. 5.4).
_VM_BALL = np.array([
    (0.0, 0.0), (0.02, 0.061e-4), (0.056, 0.22e-4), (0.1087, 0.735e-4), (0.1478, 1.385e-4),
    (0.1935, 2.171e-4), (0.2522, 3.162e-4), (0.2826, 3.641e-4), (0.3239, 4.051e-4),
    (0.3652, 4.462e-4), (0.4348, 5.111e-4), (0.5, 5.658e-4), (0.5978, 6.376e-4),
    (0.6609, 6.752e-4), (0.7239, 7.197e-4), (0.8087, 7.846e-4), (0.8674, 8.359e-4),
    (0.9391, 9.009e-4), (1.0022, 9.487e-4), (1.0413, 9.795e-4), (1.0696, 10.068e-4),
    (1.1043, 10.513e-4), (1.1348, 10.889e-4), (1.1543, 11.299e-4), (1.1717, 11.778e-4),
    (1.1826, 12.222e-4), (1.2087, 12.462e-4), (1.4, 12.462e-4),
])
_VM_ROLLER = np.array([
    (0.0, 0.0), (0.0283, 0.222e-4), (0.0717, 0.632e-4), (0.1065, 1.214e-4), (0.1348, 1.726e-4),
    (0.1587, 2.239e-4), (0.1804, 2.615e-4), (0.2, 3.026e-4), (0.2196, 3.402e-4),
    (0.2435, 3.778e-4), (0.2739, 4.188e-4), (0.3152, 4.701e-4), (0.4109, 5.829e-4),
    (0.4891, 6.718e-4), (0.5522, 7.333e-4), (0.6609, 8.462e-4), (0.7587, 9.419e-4),
    (0.8239, 10.034e-4), (0.8891, 10.786e-4), (0.9587, 11.504e-4), (1.0435, 12.393e-4),
    (1.1087, 13.214e-4), (1.1978, 14.342e-4), (1.2696, 14.376e-4), (1.4, 14.376e-4),
])
_VM_INTERP = {
    "ball": PchipInterpolator(_VM_BALL[:, 0], _VM_BALL[:, 1]),
    "roller": PchipInterpolator(_VM_ROLLER[:, 0], _VM_ROLLER[:, 1]),
}


def skf_drag_factor(level_ratio: float, family: str) -> float:
    """SKF drag-loss factor V_M [-] at oil level H/d_m (monotone PCHIP of the catalogue curve).

    H/d_m above 1.2 is capped (the catalogue curve is flat there); family "ball"|"roller".
    """
    check_range("oil_level/d_m", level_ratio, 0.0, math.inf)
    return float(_VM_INTERP[family](min(level_ratio, 1.2)))


def _angle_code(suffix: str) -> str:
    """The contact-angle code that heads an angular-contact suffix: "AC" (25 deg), "A"
    (30 deg, the double-row 32 / 33 A) or "B" (40 deg: B, BE, BECBP, BEGAP ...); "" else."""
    for code in ("AC", "A", "B"):
        if suffix.startswith(code):
            return code
    return ""


def infer_skf_series(envelope: BearingEnvelope) -> str:
    """SKF series key from the designation ("6304" -> "63", "NU214" -> "2", "QJ1044" -> "QJ",
    "7210BE" -> "72_BECBP", "7310ACCBM" -> "73_ACCBM", "3210A" -> "32_A").

    The designation's first group of digits is the series followed by the two-digit bore
    code (letters before it, e.g. "NU" or "SKF", and a part after "-" such as "-2RS" are
    not read). An angular-contact series is keyed with its contact-angle suffix, the
    letters right after the digits: "AC" (25 deg), "A" (30 deg), "B"/"BE" (40 deg) pick
    the catalogue row of that angle (SKF catalogue friction Table 1a).
    """
    kind = envelope.kind
    if kind == "four_point":
        return "QJ"
    name = envelope.name or ""
    found = (re.search(r"(\d+)\s*([A-Za-z]*)", name)
             if name and "x" not in name.lower() else None)
    digits, suffix = (found.group(1), found.group(2).upper()) if found else ("", "")
    known = sorted({s for (k, s) in SKF_RS if k == kind}, key=len, reverse=True)
    if len(digits) > 2:
        for series in known:
            prefix, _, angle = series.partition("_")
            if digits[:-2] != prefix:
                continue
            if not angle or _angle_code(angle) == _angle_code(suffix) != "":
                return series
    read = ""
    if len(digits) > 2:
        angle = _angle_code(suffix) if kind == "angular_contact" else ""
        read = (f"; it reads as series {digits[:-2]!r}"
                + (f" with contact-angle code {angle!r}" if angle else
                   f" with the suffix {suffix!r}, not a contact-angle code AC, A or B"
                   if kind == "angular_contact" and suffix else
                   " with no contact-angle code (AC, A, B) after the digits"
                   if kind == "angular_contact" else "")
                + ", which has no constants here")
    shown = repr(envelope.name) if envelope.name else f"of this {kind} bearing (none given)"
    raise InputError(
        "models.heat_source_options.global_friction.series", None,
        f"the SKF four-term model needs the bearing's series, and the designation {shown} "
        f"names none the SKF constants cover for {kind} bearings "
        f"({', '.join(sorted(known))}){read}: give the series (scene: [models] "
        "heat_source_options = { global_friction = { series = \"...\" } }), name the "
        "bearing by its designation with the suffix (e.g. \"7210BE\") or use "
        "Palmgren (model = \"palmgren\")")


@dataclass(frozen=True)
class GlobalFrictionResult:
    """Result of a global friction model.

    torque [N m] (total frictional moment), power [W] = torque x relative speed,
    components : term -> torque [N m], details : intermediate factors (catalogue units).
    """

    model: str
    torque: float
    power: float
    components: Mapping[str, float]
    details: Mapping[str, float] = field(default_factory=dict)


def _lubrication(name: str) -> str:
    """Canonical lubrication name (accepts the OilSupply spellings "jet", "circulation")."""
    name = _LUBRICATION_ALIASES.get(name, name)
    if name not in LUBRICATION:
        raise UnknownNameError("lubrication", name, LUBRICATION)
    return name


def _catalogue_inputs(bearing: Any, speed: float, nu: float, radial: float, axial: float,
                      lubrication: str) -> tuple[BearingEnvelope, str, float, float]:
    """The inputs every registered catalogue model checks and converts first: the bearing's
    envelope (:func:`envelope_of`), the canonical lubrication name, and the speed and the
    kinematic viscosity in catalogue units, n = speed 60 / (2 pi) [r/min] and
    nu 10^6 [mm^2/s] (speed [rad/s] >= 0, nu [m^2/s] > 0, loads [N] >= 0, else InputError)."""
    env = envelope_of(bearing)
    lubrication = _lubrication(lubrication)
    check_range("speed", speed, 0.0, math.inf, unit="rad/s")
    check_positive("kinematic_viscosity", nu)
    check_range("radial_load", radial, 0.0, math.inf, unit="N")
    check_range("axial_load", axial, 0.0, math.inf, unit="N")
    return env, lubrication, speed * _RPM_PER_RAD_S, nu * 1e6


# ---------------------------------------------------------------------------
# SKF four-term model
# ---------------------------------------------------------------------------
def skf_geometry_variables(
    kind: str, series: str, dm: float, Fr: float, Fa: float, n: float,
    static_load_rating: float | None = None,
) -> tuple[float, float]:
    """SKF G_rr and G_sl in catalogue units (dm [mm], loads [N], n [r/min]).

    deep groove, Fa = 0:  G_rr = R1 dm^1.96 Fr^0.54,  G_sl = S1 dm^-0.26 Fr^(5/3)
    deep groove, Fa > 0:  alpha_F = 24.6 (Fa/C0)^0.24 deg,
        G_rr = R1 dm^1.96 (Fr + R2/sin(alpha_F) Fa)^0.54,
        G_sl = S1 dm^-0.145 (Fr^5 + S2 dm^1.5/sin(alpha_F) Fa^4)^(1/3)
    angular contact / four point: F_g = R3 dm^4 n^2 (rolling), S3 dm^4 n^2 (sliding),
        G_rr = R1 dm^1.97 (Fr + F_g + R2 Fa)^0.54, G_sl = S1 dm^0.26 ((Fr+F_g)^(4/3) + S2 Fa^(4/3))
    cylindrical roller: G_rr = R1 dm^2.41 Fr^0.31, G_sl = S1 dm^0.9 Fa + S2 dm Fr
    (SKF catalogue Table 1a.)
    """
    try:
        R1, R2, R3, S1, S2, S3 = SKF_RS[(kind, series)]
    except KeyError:
        known = sorted(s for (k, s) in SKF_RS if k == kind)
        raise UnknownNameError(f"SKF series for {kind}", series, known) from None
    if kind == "deep_groove":
        assert R2 is not None and S2 is not None
        if Fa <= 0.0:
            return R1 * dm**1.96 * Fr**0.54, S1 * dm**-0.26 * Fr ** (5.0 / 3.0)
        if static_load_rating is None:
            raise InputError("static_load_rating", None,
                             "C0 [N] for a deep-groove bearing with axial load (SKF alpha_F)")
        alpha_f = math.radians(24.6 * (Fa / static_load_rating) ** 0.24)
        s = math.sin(alpha_f)
        g_rr = R1 * dm**1.96 * (Fr + R2 / s * Fa) ** 0.54
        g_sl = S1 * dm**-0.145 * (Fr**5 + S2 * dm**1.5 / s * Fa**4) ** (1.0 / 3.0)
        return g_rr, g_sl
    if kind in ("angular_contact", "four_point"):
        assert R2 is not None and R3 is not None and S2 is not None and S3 is not None
        fg_rr = R3 * dm**4 * n**2
        fg_sl = S3 * dm**4 * n**2
        g_rr = R1 * dm**1.97 * (Fr + fg_rr + R2 * Fa) ** 0.54
        g_sl = S1 * dm**0.26 * ((Fr + fg_sl) ** (4.0 / 3.0) + S2 * Fa ** (4.0 / 3.0))
        return g_rr, g_sl
    assert S2 is not None
    return R1 * dm**2.41 * Fr**0.31, S1 * dm**0.9 * Fa + S2 * dm * Fr


@GLOBAL_FRICTION.register(
    "skf_four_term",
    references=["skf_catalogue_friction", "jraposo_skf_tool"],
    parameters={"speed": "rad/s", "kinematic_viscosity": "m**2/s", "radial_load": "N",
                "axial_load": "N", "oil_level": "m"},
    validity="SKF catalogue bearings (series constants known) at steady state, full-film "
    "to boundary lubrication; oil-jet drag rule recalled (see docstring)",
    summary="SKF four-term frictional moment M = M_rr + M_sl + M_seal + M_drag",
)
def skf_four_term(
    bearing: Any,
    kinematic_viscosity: float,
    speed: float,
    radial_load: float,
    axial_load: float = 0.0,
    *,
    lubrication: str = "oil_jet",
    oil_level: float | None = None,
    series: str | None = None,
    static_load_rating: float | None = None,
    lubricant_kind: str = "mineral",
    mu_bl: float = 0.15,
    mu_ehl: float | None = None,
    seal: Mapping[str, float] | None = None,
) -> GlobalFrictionResult:
    """Frictional moment by the SKF four-term model (SI in and out).

    .. math::
        M = \\phi_{ish}\\phi_{rs} G_{rr} (\\nu n)^{0.6} + G_{sl}\\mu_{sl} + M_{seal} + M_{drag}

    (catalogue units N mm, mm, r/min, mm^2/s) with

    - inlet shear: phi_ish = 1/(1 + 1.84e-9 (n d_m)^1.28 nu^0.64)
    - replenishment: phi_rs = 1/exp(K_rs nu n (d + D) sqrt(K_Z/(2 (D - d)))),
      K_rs = 3e-8 (oil bath, oil jet, circulating), 6e-8 (grease, oil-air)
    - sliding: mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL, phi_bl = 1/exp(2.6e-8 (n nu)^1.4 d_m);
      mu_bl = 0.15 (catalogue; 0.12 is also quoted for running bearings), mu_EHL = 0.05
      mineral / 0.04 synthetic / 0.1 transmission fluid, 0.02 for cylindrical roller bearings
    - seals: M_seal = K_S1 d_s^beta + K_S2 (``seal`` = {"d_s": [m], "K_S1", "K_S2", "beta"})
    - drag, ball: M_drag = 0.4 V_M K_ball d_m^5 n^2
      + 1.093e-7 n^2 d_m^3 (n d_m^2 f_t/nu)^-1.379 R_s,
      roller: 4 V_M K_roll C_w B d_m^4 n^2 + (same second term);
      K_ball = i_rw K_Z (d + D)/(D - d) 1e-12, K_roll = K_L K_Z (d + D)/(D - d) 1e-12,
      C_w = 2.789e-10 l_D^3 - 2.786e-4 l_D^2 + 0.0195 l_D + 0.6439, l_D = 5 B/d_m,
      t = 2 acos((0.6 d_m - H)/(0.6 d_m)), f_t = sin(t/2) (t <= pi) else 1,
      R_s = 0.36 d_m^2 (t - sin t) f_A, f_A = 0.05 K_Z (D + d)/(D - d).

    Oil level H (``oil_level``, from the lowest point of the outer raceway) is used for
    ``lubrication="oil_bath"``. For "oil_jet"/"circulating" the drag is the oil-bath value
    with H = half the rolling-element diameter, doubled -- SKF's rule for oil jets as
    recalled (not checked against the catalogue). "oil_air"/"grease": no drag.

    Parameters
    ----------
    bearing : BallBearing, RollerBearing or BearingEnvelope.
    kinematic_viscosity : nu at operating temperature [m^2/s].
    speed : relative speed of the rings [rad/s].
    radial_load, axial_load : [N].
    series : SKF series key (inferred from the bearing name if omitted).
    static_load_rating : C0 [N] for a deep-groove bearing under axial load.

    Returns
    -------
    GlobalFrictionResult with components rolling, sliding, seal, drag [N m].
    """
    env, lubrication, n, nu = _catalogue_inputs(bearing, speed, kinematic_viscosity, radial_load,
                                                axial_load, lubrication)
    check_range("mu_bl", mu_bl, 0.0, 1.0)
    series = series or infer_skf_series(env)
    d, D, B = env.bore * 1e3, env.outer_diameter * 1e3, env.width * 1e3
    dm = 0.5 * (d + D)
    kz = SKF_KZ[env.kind]
    c0 = static_load_rating if static_load_rating is not None else env.static_load_rating
    g_rr, g_sl = skf_geometry_variables(env.kind, series, dm, radial_load, axial_load, n, c0)

    from .rolling_resistance import skf_inlet_shear_factor, skf_replenishment_factor

    phi_ish = skf_inlet_shear_factor(speed, 0.5 * (env.bore + env.outer_diameter),
                                     kinematic_viscosity)
    phi_rs = skf_replenishment_factor(speed, kinematic_viscosity, env.bore,
                                      env.outer_diameter, kz, lubrication)
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6

    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    if mu_ehl is None:
        if env.kind == "cylindrical":
            mu_ehl = 0.02
        else:
            mu_ehl = {"mineral": 0.05, "synthetic": 0.04, "ester": 0.04, "pao": 0.04,
                      "transmission": 0.1}.get(lubricant_kind, 0.05)
    check_range("mu_ehl", mu_ehl, 0.0, 1.0)
    mu_sl = phi_bl * mu_bl + (1.0 - phi_bl) * mu_ehl
    m_sl = g_sl * mu_sl

    m_seal = 0.0
    if seal:
        unknown = set(seal) - {"d_s", "K_S1", "K_S2", "beta"}
        if unknown:
            raise UnknownNameError("seal key", sorted(unknown)[0], ["d_s", "K_S1", "K_S2", "beta"])
        m_seal = seal["K_S1"] * (seal["d_s"] * 1e3) ** seal["beta"] + seal["K_S2"]

    m_drag = 0.0
    level = None
    if lubrication == "oil_bath":
        if oil_level is None:
            raise InputError("oil_level", None, "an oil level [m] for oil-bath lubrication")
        check_range("oil_level", oil_level, 0.0, math.inf, unit="m")
        level = oil_level * 1e3
        m_drag = _skf_drag(env, d, D, B, dm, n, nu, level, kz)
    elif lubrication in ("oil_jet", "circulating"):
        if env.element_diameter is None:
            raise InputError("bearing.element_diameter", None,
                             "the rolling-element diameter (oil-jet drag level)")
        level = 0.5 * env.element_diameter * 1e3
        m_drag = 2.0 * _skf_drag(env, d, D, B, dm, n, nu, level, kz)

    comps = {"rolling": m_rr * 1e-3, "sliding": m_sl * 1e-3, "seal": m_seal * 1e-3,
             "drag": m_drag * 1e-3}
    total = sum(comps.values())
    details = {"series": series, "d_m_mm": dm, "n_rpm": n, "nu_mm2s": nu, "G_rr": g_rr,
               "G_sl": g_sl, "phi_ish": phi_ish, "phi_rs": phi_rs, "phi_bl": phi_bl,
               "mu_sl": mu_sl, "oil_level_mm": level if level is not None else float("nan")}
    return GlobalFrictionResult("skf_four_term", total, total * speed, comps, details)


def _skf_drag(env: BearingEnvelope, d: float, D: float, B: float, dm: float, n: float,
              nu: float, H: float, kz: float) -> float:
    """SKF drag moment [N mm] at oil level H [mm] (catalogue units; see skf_four_term)."""
    if n <= 0.0:
        return 0.0
    h = min(H, 1.2 * dm)
    t = 2.0 * math.acos(max(-1.0, min(1.0, (0.6 * dm - h) / (0.6 * dm))))
    f_t = math.sin(0.5 * t) if t <= math.pi else 1.0
    f_a = 0.05 * kz * (D + d) / (D - d)
    r_s = 0.36 * dm**2 * (t - math.sin(t)) * f_a
    second = 0.0
    if r_s > 0.0 and f_t > 0.0:
        second = 1.093e-7 * n**2 * dm**3 * ((n * dm**2 * f_t) / nu) ** -1.379 * r_s
    if env.kind == "cylindrical":
        k_roll = SKF_KL["cylindrical"] * kz * (d + D) / (D - d) * 1e-12
        l_d = 5.0 * B / dm
        c_w = 2.789e-10 * l_d**3 - 2.786e-4 * l_d**2 + 0.0195 * l_d + 0.6439
        first = 4.0 * skf_drag_factor(h / dm, "roller") * k_roll * c_w * B * dm**4 * n**2
    else:
        k_ball = env.rows * kz * (d + D) / (D - d) * 1e-12
        first = 0.4 * skf_drag_factor(h / dm, "ball") * k_ball * dm**5 * n**2
    return first + second


# ---------------------------------------------------------------------------
# Palmgren
# ---------------------------------------------------------------------------
#: kind -> (f0 grease, f0 oil bath, f1), Schaeffler values as transcribed in Thermca
PALMGREN_FACTORS = {
    "deep_groove": (1.0, 2.0, 0.00022),
    "angular_contact": (2.0, 3.3, 0.00046),
    "four_point": (6.0, 6.0, 0.00046),
    "cylindrical": (0.8, 3.0, 0.00030),
}


def palmgren_equivalent_load(kind: str, radial_load: float, axial_load: float) -> float:
    """P1 [N] of Palmgren's M1 (Schaeffler rules), never below F_r.

    deep groove 3.3 F_a - 0.1 F_r; single-row angular contact F_a - 0.1 F_r; four-point
    1.5 F_a + 3.6 F_r; cylindrical roller F_r. The Thermca transcription prints the
    four-point rule as 1.5 F_a - 3.6 F_r, which is negative under radial load; the "+"
    form is used here (more radial load cannot lower the load-dependent friction).
    """
    Fr, Fa = radial_load, axial_load
    p1 = {
        "deep_groove": 3.3 * Fa - 0.1 * Fr,
        "angular_contact": Fa - 0.1 * Fr,
        "four_point": 1.5 * Fa + 3.6 * Fr,
        "cylindrical": Fr,
    }[kind]
    return max(p1, Fr)


@GLOBAL_FRICTION.register(
    "palmgren",
    references=["palmgren1959", "harris_kotzalas2007", "thermca"],
    parameters={"speed": "rad/s", "kinematic_viscosity": "m**2/s", "radial_load": "N",
                "axial_load": "N"},
    validity="moderate speeds, full-film oil; f1 for ~10 % of the dynamic load rating",
    summary="Palmgren M = M0 + M1 (speed/viscosity term plus load term)",
)
def palmgren(
    bearing: Any,
    kinematic_viscosity: float,
    speed: float,
    radial_load: float,
    axial_load: float = 0.0,
    *,
    lubrication: str = "oil_jet",
    f0: float | None = None,
    f1: float | None = None,
) -> GlobalFrictionResult:
    """Frictional moment by Palmgren's M0 + M1 (SI in and out).

    .. math::
        M_0 = 10^{-7} f_0 (\\nu n)^{2/3} d_m^3 \\ (\\nu n \\ge 2000),\\quad
        M_0 = 160\\times10^{-7} f_0 d_m^3 \\ (\\nu n < 2000),\\quad M_1 = f_1 P_1 d_m

    in N mm with nu [mm^2/s], n [r/min], d_m [mm] (Palmgren 1959; Harris & Kotzalas 2007).
    f0 by lubrication: oil bath as tabulated, oil jet / circulating 2x the oil-bath value,
    oil-air 0.5x, grease the grease column (Schaeffler values via Thermca). Both branches
    of M0 carry f0 (Thermca's low-speed branch omits it; that slip is not copied).
    """
    env, lubrication, n, nu = _catalogue_inputs(bearing, speed, kinematic_viscosity, radial_load,
                                                axial_load, lubrication)
    f0_grease, f0_bath, f1_tab = PALMGREN_FACTORS[env.kind]
    if f0 is None:
        f0 = {"grease": f0_grease, "oil_bath": f0_bath, "oil_jet": 2.0 * f0_bath,
              "circulating": 2.0 * f0_bath, "oil_air": 0.5 * f0_bath}[lubrication]
    f1 = f1_tab if f1 is None else f1
    check_positive("f0", f0)
    check_positive("f1", f1)
    dm = 0.5 * (env.bore + env.outer_diameter) * 1e3
    if nu * n >= 2000.0:
        m0 = 1e-7 * f0 * (nu * n) ** (2.0 / 3.0) * dm**3
    else:
        m0 = 160e-7 * f0 * dm**3
    p1 = palmgren_equivalent_load(env.kind, radial_load, axial_load)
    m1 = f1 * p1 * dm
    comps = {"M0": m0 * 1e-3, "M1": m1 * 1e-3}
    total = comps["M0"] + comps["M1"]
    details = {"f0": f0, "f1": f1, "P1": p1, "d_m_mm": dm, "n_rpm": n, "nu_mm2s": nu}
    return GlobalFrictionResult("palmgren", total, total * speed, comps, details)


def global_friction(
    model: str,
    bearing: Any,
    lubricant: Any,
    temperature: float,
    speed: float,
    radial_load: float,
    axial_load: float = 0.0,
    *,
    lubrication: str = "oil_jet",
    supply: Any = None,
    **options: Any,
) -> GlobalFrictionResult:
    """Run the registered global model ``model`` with a :class:`~thermobearing.lubricant.Lubricant`.

    The viscosity is the lubricant's kinematic viscosity at ``temperature`` [K] (the
    catalogue models take the operating viscosity of the bearing); for the SKF model the
    lubricant's ``kind`` chooses mu_EHL (mineral 0.05, synthetic/ester 0.04) unless
    ``lubricant_kind`` or ``mu_ehl`` is given in ``options``. A ``supply``
    (:class:`thermobearing.state.OilSupply`) sets the lubrication method and, for the SKF
    model, the oil-bath level.
    """
    import inspect

    from .lubricant import Lubricant
    from .state import OilSupply

    func = GLOBAL_FRICTION.get(model)
    if not isinstance(lubricant, Lubricant):
        raise InputError("lubricant", type(lubricant).__name__,
                         "a Lubricant (thermobearing.lubricant.load_lubricant)")
    if supply is not None and not isinstance(supply, OilSupply):
        raise InputError("supply", supply, "an OilSupply (thermobearing.state.OilSupply) or None")
    known = [name for name, par in inspect.signature(func).parameters.items()
             if par.kind is inspect.Parameter.KEYWORD_ONLY and name != "lubrication"]
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise InputError(f"{model} options", unknown, "the options of "
                         f"{model}: {', '.join(known)}")
    if supply is not None:
        lubrication = supply.method
        if model == "skf_four_term" and getattr(supply, "level", None) is not None:
            options.setdefault("oil_level", supply.level)
    nu = float(lubricant.kinematic_viscosity(temperature))
    if model == "skf_four_term":
        options.setdefault("lubricant_kind", getattr(lubricant, "kind", "mineral"))
    return func(bearing, nu, speed, radial_load, axial_load, lubrication=lubrication, **options)
