"""Race-control kinematics of ball and roller bearings (used until/alongside the skidding solver).

Frame and symbols (``../shared/notes/over-skidding.md`` section 1-2, re-derived here):
cage frame x' axial, y' tangential, z' radially outward at the element centre; outer ring fixed
unless ``outer_speed`` is given (then everything is solved in the outer ring's frame and the
outer speed is added back); gamma' = D/d_m; alpha_i, alpha_o operating contact angles; beta the
attitude (pitch) angle of the ball spin axis from x' in the x'z' plane (yaw beta' = 0);
omega_R the ball spin relative to the cage (negative in this sign convention, as in Harris).

Rolling without slip at both contact centres (K1, K2):

    omega_m / omega = (1 - g cos a_i) cos(a_o - b) /
                      [cos(a_i - b) + cos(a_o - b) + g sin b sin(a_i - a_o)]
    omega_R / omega = -1 / { g cos b [ (cos a_o + tan b sin a_o)/(1 + g cos a_o)
                                      + (cos a_i + tan b sin a_i)/(1 - g cos a_i) ] }

Race control (Jones 1960, ``jones1960``; Harris & Kotzalas 2007): zero spin at the controlling
contact fixes beta:

- outer-race control: tan b = sin a_o / (cos a_o + g), CSR = (1 - g cos a_i)/(1 + cos(a_i - a_o))
- inner-race control: tan b = sin a_i / (cos a_i - g),
  CSR = (cos(a_i - a_o) - g cos a_o)/(1 + cos(a_i - a_o))

Spins and spin-to-roll ratios (relative angular velocity of the ball to the race projected on
the contact normal, and on the in-plane axis normal to the rolling direction):

    w_s,o = w_R sin(a_o - b) + w_m sin a_o ;   w_s,i = w_R sin(a_i - b) - (w - w_m) sin a_i
    (w_s / w_roll)_o = tan(a_o - b) - g sin b / cos(a_o - b)
    (w_s / w_roll)_i = tan(a_i - b) + g sin b / cos(a_i - b)

All of these (the primer's [R] items) were re-derived symbolically from the rigid-body
velocities of the contact points; ``tests/unit/test_kinematics.py`` checks them numerically
against a direct vector computation. With a_i = a_o the CSR is (1 - g cos a)/2 for every beta.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .errors import InputError, UnknownNameError, check_finite, check_range

CONTROLS = ("outer_race", "inner_race")


@dataclass(frozen=True)
class ElementKinematics:
    """Kinematics of the rolling elements (arrays broadcast over the contact angles).

    Attributes
    ----------
    control : "pure_rolling" | "outer_race" | "inner_race" | "given_attitude".
    inner_speed, outer_speed : ring speeds [rad/s].
    orbital_speed : element orbital (= cage, no pocket slip) speed omega_m [rad/s].
    cage_speed_ratio : (omega_m - omega_o)/(omega_i - omega_o) [-] (CSR for a fixed outer ring).
    element_spin : omega_R, spin of the element about its own axis relative to the cage [rad/s].
    attitude_angle : beta [rad].
    spin_inner, spin_outer : spin (normal) components of the element's angular velocity
        relative to each race [rad/s].
    roll_inner, roll_outer : rolling components of the same [rad/s].
    spin_to_roll_inner, spin_to_roll_outer : their ratios [-].
    entrainment_inner, entrainment_outer : entrainment (mean rolling) speeds [m/s].
    contact_angle_inner, contact_angle_outer : angles used [rad].
    """

    control: str
    inner_speed: float
    outer_speed: float
    orbital_speed: Any
    cage_speed_ratio: Any
    element_spin: Any
    attitude_angle: Any
    spin_inner: Any
    spin_outer: Any
    roll_inner: Any
    roll_outer: Any
    spin_to_roll_inner: Any
    spin_to_roll_outer: Any
    entrainment_inner: Any
    entrainment_outer: Any
    contact_angle_inner: Any
    contact_angle_outer: Any


def attitude_angle(gamma_prime: float, contact_angle_i: Any, contact_angle_o: Any,
                   control: str) -> Any:
    """Race-control attitude angle beta [rad] (Jones 1960; zero spin at the controlling race)."""
    ai = np.asarray(contact_angle_i, dtype=float)
    ao = np.asarray(contact_angle_o, dtype=float)
    if control == "outer_race":
        return np.arctan2(np.sin(ao), np.cos(ao) + gamma_prime)[()]
    if control == "inner_race":
        return np.arctan2(np.sin(ai), np.cos(ai) - gamma_prime)[()]
    raise UnknownNameError("control", control, CONTROLS)


def race_control_cage_ratio(gamma_prime: float, contact_angle_i: Any, contact_angle_o: Any,
                            control: str = "outer_race") -> Any:
    """Cage/inner speed ratio under outer- or inner-race control (outer ring fixed) [-].

    ORC: (1 - g cos a_i)/(1 + cos(a_i - a_o)); IRC: (cos(a_i - a_o) - g cos a_o)/(1 + cos(...)),
    g = D/d_m (Harris & Kotzalas 2007; ``jones1960``). Equal angles give (1 - g cos a)/2.
    """
    ai = np.asarray(contact_angle_i, dtype=float)
    ao = np.asarray(contact_angle_o, dtype=float)
    c = np.cos(ai - ao)
    if control == "outer_race":
        return ((1.0 - gamma_prime * np.cos(ai)) / (1.0 + c))[()]
    if control == "inner_race":
        return ((c - gamma_prime * np.cos(ao)) / (1.0 + c))[()]
    raise UnknownNameError("control", control, CONTROLS)


def rolling_speeds(gamma_prime: float, contact_angle_i: Any, contact_angle_o: Any,
                   beta: Any) -> tuple[Any, Any]:
    """(omega_m/omega, omega_R/omega) for rolling at both contact centres, attitude beta (K1, K2).

    Outer ring fixed, inner ring at omega; yaw 0.
    """
    ai = np.asarray(contact_angle_i, dtype=float)
    ao = np.asarray(contact_angle_o, dtype=float)
    b = np.asarray(beta, dtype=float)
    g = gamma_prime
    csr = (1.0 - g * np.cos(ai)) * np.cos(ao - b) / (
        np.cos(ai - b) + np.cos(ao - b) + g * np.sin(b) * np.sin(ai - ao))
    t = np.tan(b)
    bracket = ((np.cos(ao) + t * np.sin(ao)) / (1.0 + g * np.cos(ao))
               + (np.cos(ai) + t * np.sin(ai)) / (1.0 - g * np.cos(ai)))
    spin = -1.0 / (g * np.cos(b) * bracket)
    return csr[()], spin[()]


def _require_bearing(bearing: Any) -> None:
    """An :class:`InputError` unless ``bearing`` is a BallBearing or RollerBearing (a
    lubricant passed in its place was an AttributeError)."""
    from .geometry import BallBearing, RollerBearing

    if not isinstance(bearing, BallBearing | RollerBearing):
        raise InputError("bearing", type(bearing).__name__,
                         "a BallBearing or RollerBearing (thermobearing.load_bearing)")


def _geometry(bearing: Any) -> tuple[float, float, float]:
    _require_bearing(bearing)
    d = float(bearing.element_diameter)
    dm = float(bearing.pitch_diameter)
    return d, dm, d / dm


def _angles(bearing: Any, contact_angle_i: Any, contact_angle_o: Any) -> tuple[Any, Any]:
    if getattr(bearing, "kind", "") == "cylindrical":
        zero = np.zeros(np.shape(contact_angle_i)) if contact_angle_i is not None else 0.0
        return zero, zero
    ai = bearing.contact_angle if contact_angle_i is None else contact_angle_i
    ao = ai if contact_angle_o is None else contact_angle_o
    check_range("contact_angle_i", ai, 0.0, math.pi / 2, high_inclusive=False, unit="rad")
    check_range("contact_angle_o", ao, 0.0, math.pi / 2, high_inclusive=False, unit="rad")
    return np.asarray(ai, dtype=float), np.asarray(ao, dtype=float)


def element_kinematics(bearing: Any, inner_speed: float, contact_angle_i: Any = None,
                       contact_angle_o: Any = None, *, attitude: Any = None,
                       control: str = "given_attitude", outer_speed: float = 0.0
                       ) -> ElementKinematics:
    """Rolling-element kinematics with rolling at both contact centres and a given attitude.

    Parameters
    ----------
    bearing : a :class:`~thermobearing.geometry.BallBearing` or ``RollerBearing``.
    inner_speed, outer_speed : ring speeds [rad/s].
    contact_angle_i, contact_angle_o : operating contact angles [rad] (default: the nominal
        angle, the outer defaults to the inner). Arrays give per-element results.
    attitude : beta [rad]; default the inner contact angle (for equal angles this is the
        textbook pure-rolling ball spin, omega_R = -(1 - g^2 cos^2 a)/(2 g) omega).
    control : label stored in the result.
    """
    for name, v in (("inner_speed", inner_speed), ("outer_speed", outer_speed)):
        if not np.isfinite(v):
            raise InputError(name, v, "a finite speed in rad/s")
    d, dm, g = _geometry(bearing)
    ai, ao = _angles(bearing, contact_angle_i, contact_angle_o)
    if attitude is not None:
        check_finite("attitude", attitude)  # NaN / inf gave NaN kinematics silently
    beta = np.asarray(ai if attitude is None else attitude, dtype=float)
    w_rel = inner_speed - outer_speed
    csr, spin_ratio = rolling_speeds(g, ai, ao, beta)
    wm_rel = csr * w_rel  # orbital speed relative to the outer ring
    w_r = spin_ratio * w_rel
    s_o = w_r * np.sin(ao - beta) + wm_rel * np.sin(ao)
    s_i = w_r * np.sin(ai - beta) - (w_rel - wm_rel) * np.sin(ai)
    r_o = w_r * np.cos(ao - beta) + wm_rel * np.cos(ao)
    r_i = w_r * np.cos(ai - beta) - (w_rel - wm_rel) * np.cos(ai)
    with np.errstate(divide="ignore", invalid="ignore"):
        sr_o = np.where(r_o != 0, s_o / np.where(r_o != 0, r_o, 1.0), 0.0)
        sr_i = np.where(r_i != 0, s_i / np.where(r_i != 0, r_i, 1.0), 0.0)
    u_i = 0.5 * np.abs(w_rel - wm_rel) * (dm - d * np.cos(ai))
    u_o = 0.5 * np.abs(wm_rel) * (dm + d * np.cos(ao))
    return ElementKinematics(
        control=control, inner_speed=float(inner_speed), outer_speed=float(outer_speed),
        orbital_speed=(outer_speed + wm_rel)[()] if np.ndim(wm_rel) else float(
            outer_speed + wm_rel),
        cage_speed_ratio=np.asarray(csr)[()], element_spin=np.asarray(w_r)[()],
        attitude_angle=np.broadcast_to(beta, np.shape(csr))[()] if np.ndim(csr) else float(beta),
        spin_inner=np.asarray(s_i)[()], spin_outer=np.asarray(s_o)[()],
        roll_inner=np.asarray(r_i)[()], roll_outer=np.asarray(r_o)[()],
        spin_to_roll_inner=np.asarray(sr_i)[()], spin_to_roll_outer=np.asarray(sr_o)[()],
        entrainment_inner=np.asarray(u_i)[()], entrainment_outer=np.asarray(u_o)[()],
        contact_angle_inner=np.asarray(ai)[()], contact_angle_outer=np.asarray(ao)[()],
    )


def pure_rolling(bearing: Any, inner_speed: float, contact_angle_i: Any = None,
                 contact_angle_o: Any = None, *, outer_speed: float = 0.0,
                 attitude: Any = None) -> ElementKinematics:
    """Epicyclic pure rolling: rolling at both contact centres, attitude = contact angle.

    With equal inner and outer angles the CSR is (1 - g cos a)/2 whatever the attitude; the
    attitude beta = a gives the textbook ball spin frequency. With unequal angles the attitude
    defaults to the mean of the two angles (an assumption; use the race-control functions for
    the Jones limits).
    """
    d, dm, g = _geometry(bearing)
    ai, ao = _angles(bearing, contact_angle_i, contact_angle_o)
    beta = 0.5 * (ai + ao) if attitude is None else attitude
    return element_kinematics(bearing, inner_speed, ai, ao, attitude=beta,
                              control="pure_rolling", outer_speed=outer_speed)


def outer_race_control(bearing: Any, inner_speed: float, contact_angle_i: Any = None,
                       contact_angle_o: Any = None, *, outer_speed: float = 0.0
                       ) -> ElementKinematics:
    """Outer-race control (no spin at the outer contact; Jones 1960)."""
    d, dm, g = _geometry(bearing)
    ai, ao = _angles(bearing, contact_angle_i, contact_angle_o)
    beta = attitude_angle(g, ai, ao, "outer_race")
    return element_kinematics(bearing, inner_speed, ai, ao, attitude=beta,
                              control="outer_race", outer_speed=outer_speed)


def inner_race_control(bearing: Any, inner_speed: float, contact_angle_i: Any = None,
                       contact_angle_o: Any = None, *, outer_speed: float = 0.0
                       ) -> ElementKinematics:
    """Inner-race control (no spin at the inner contact; Jones 1960)."""
    d, dm, g = _geometry(bearing)
    ai, ao = _angles(bearing, contact_angle_i, contact_angle_o)
    beta = attitude_angle(g, ai, ao, "inner_race")
    return element_kinematics(bearing, inner_speed, ai, ao, attitude=beta,
                              control="inner_race", outer_speed=outer_speed)


def select_race_control(load_i: Any, load_o: Any, a_i: Any, a_o: Any, second_kind_i: Any,
                        second_kind_o: Any, contact_angle_i: Any, contact_angle_o: Any) -> Any:
    """Jones's criterion: outer-race control where Q_o a_o E_o cos(a_i - a_o) > Q_i a_i E_i.

    Q normal loads [N], a semi-major axes [m], E complete elliptic integrals of the second kind
    [-] of each contact (from :func:`thermobearing.hertz.point_contact`). Returns an array of
    "outer_race"/"inner_race" per element (the primer notes OpenJones applies one median ball's
    verdict to all balls; here it is per element). Harris & Kotzalas 2007; ``jones1960``.
    """
    lhs = (np.asarray(load_o) * np.asarray(a_o) * np.asarray(second_kind_o)
           * np.cos(np.asarray(contact_angle_i) - np.asarray(contact_angle_o)))
    rhs = np.asarray(load_i) * np.asarray(a_i) * np.asarray(second_kind_i)
    return np.where(lhs > rhs, "outer_race", "inner_race")[()]


def race_control_for_loads(bearing: Any, load_i: Any, load_o: Any, contact_angle_i: Any,
                           contact_angle_o: Any) -> Any:
    """Jones's race-control verdict per element from the contact loads [N] and angles [rad].

    Computes the Hertz semi-major axes and E(e) of both contacts of a ball bearing
    (:func:`thermobearing.hertz.point_contact`, exact) and applies
    :func:`select_race_control`. Unloaded contacts count as zero.
    """
    from .hertz import point_contact

    _require_bearing(bearing)
    e_prime = bearing.effective_modulus
    rx_i, ry_i = bearing.curvature("inner", contact_angle_i)
    rx_o, ry_o = bearing.curvature("outer", contact_angle_o)
    pc_i = point_contact(load_i, rx_i, ry_i, e_prime)
    pc_o = point_contact(load_o, rx_o, ry_o, e_prime)
    return select_race_control(load_i, load_o, pc_i.a, pc_o.a, pc_i.second_kind,
                               pc_o.second_kind, contact_angle_i, contact_angle_o)
