"""Roller / cage-bar contact of the roller dynamics (paper 003 eq. 18, cage terms N^c, F^c).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear]: eq. 18
lines 2-3 move the roller circumferentially under the pocket normal force N^c, its friction
F^c and the unbalance forces F_cv, F_cw; line 4 brakes the spin with F^c D_w/2; sec. 10.2
explains the pocket-clearance trend by the roller swinging between the front and rear bars
("limited by the unilateral beam" above 0.35 mm). The paper gives no contact law. Here:

* **bar contact** (:func:`bar_contact`): each bar a flat face at +-c_p/2 from the roller
  axis in the circumferential direction (c_p the pocket circumferential clearance), a linear
  Winkler line spring of total stiffness k_c over the roller length L_r (k_c estimated,
  ``DEFAULT_POCKET_STIFFNESS`` of :mod:`~thermobearing.skidding.roller_dynamics`). A roller
  displaced by z and skewed by alpha has its line at z - alpha x (x along the axis), so the
  penetration into the front bar is d_f(x) = z - alpha x - c_p/2 and into the rear bar
  d_b(x) = -(z - alpha x) - c_p/2; force and skew moment are the exact integrals of the
  positive parts (piecewise linear).
* **squeeze film** (:func:`squeeze_coefficient`): a rigid cylinder of radius R = D_w/2
  approaching a flat bar through a Newtonian film of viscosity eta at gap h carries
  w' = -3 sqrt(2) pi eta (R/h)^(3/2) dh/dt per unit length (long-cylinder Reynolds
  equation; derivation: h = h_0 + x^2/(2R), h^3 p' = 12 eta h_0' x,
  w' = -int x p' dx = -12 eta h_0' (2R)^(3/2) h_0^(-3/2) pi/8; the cylinder-plane squeeze
  film of Hamrock, Schmid & Jacobson 2004 [hamrock2004]). Applied at the mid-length gap
  h = c_p/2 -+ z while that gap closes only (on separation the film cavitates and the
  suction is neglected, the half-Sommerfeld idealisation), floored at
  ``DEFAULT_SQUEEZE_FLOOR`` (the film cannot thin below the roughness; estimated,
  sensitivity in the validation case's SOURCE.md).
  This is what dissipates the impacts (the raceway tractions of an unloaded roller damp
  its circumferential motion only weakly, c ~ 0.05 N s/m).
* **bar friction**: the pocket film friction of paper 000 eqs. 37-38
  (:func:`thermobearing.skidding.roller_fluid.pocket_forces`, the same function the
  quasi-static skidding model uses) at the instantaneous bar force; its time mean minus the
  friction the quasi-static model already counts at its steady pocket force is the extra
  spin-braking friction of the rattling roller (:func:`extra_pocket_friction`).
Units: SI.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit

#: smallest bar gap of the squeeze film [m] (estimated: a few composite roughnesses of a
#: ground roller on a machined brass bar, Ra ~ 0.2-0.4 um)
DEFAULT_SQUEEZE_FLOOR = 1.0e-6

#: 3 sqrt(2) pi: coefficient of the cylinder-plane squeeze film (module notes)
SQUEEZE_COEFFICIENT = 3.0 * math.sqrt(2.0) * math.pi


@njit(cache=True)
def _positive_part_integrals(p: float, q: float, h: float) -> tuple[float, float]:
    """(int g+ dx, int x g+ dx) over [-h, h] for g = p + q x."""
    if abs(q) < 1e-300:
        if p <= 0.0:
            return 0.0, 0.0
        return 2.0 * h * p, 0.0
    x0 = -p / q
    if q > 0.0:
        lo = max(-h, x0)
        hi = h
    else:
        lo = -h
        hi = min(h, x0)
    if hi <= lo:
        return 0.0, 0.0
    i0 = p * (hi - lo) + 0.5 * q * (hi * hi - lo * lo)
    i1 = 0.5 * p * (hi * hi - lo * lo) + q * (hi**3 - lo**3) / 3.0
    return i0, i1


@njit(cache=True)
def bar_contact(z: float, a: float, half_length: float, clearance: float,
                stiffness: float) -> tuple[float, float, float, float]:
    """Elastic cage-bar forces on a roller (module notes), jitted scalar kernel.

    z : circumferential displacement of the roller axis from the pocket centre [m]
    (positive towards the front bar, the sense of rotation). a : skew alpha [rad].
    half_length : L_r/2 [m]. clearance : c_p, total circumferential pocket clearance [m].
    stiffness : k_c, total stiffness of one bar over the roller length [N/m].

    Returns (F_z [N] on the roller, skew moment M_y [N m] on the roller (about the radial
    axis, the sign convention of :mod:`thermobearing.rib`), front-bar force [N] >= 0,
    rear-bar force [N] >= 0).
    """
    k_l = stiffness / (2.0 * half_length)
    f0, f1 = _positive_part_integrals(z - 0.5 * clearance, -a, half_length)
    b0, b1 = _positive_part_integrals(-z - 0.5 * clearance, a, half_length)
    f_front = k_l * f0
    f_back = k_l * b0
    # front force density -k_l d_f(x) along z at x: M_y = -x f_z, integrated
    return f_back - f_front, k_l * (f1 - b1), f_front, f_back


@njit(cache=True)
def squeeze_coefficient(gap: float, viscosity: float, radius: float, length: float,
                        floor: float) -> float:
    """Damping c [N s/m] of the cylinder-plane squeeze film at ``gap`` [m] (module notes):
    c = 3 sqrt(2) pi eta L (R / max(h, floor))^(3/2)."""
    h = max(gap, floor)
    return SQUEEZE_COEFFICIENT * viscosity * length * (radius / h) ** 1.5


@njit(cache=True)
def pocket_force_z(z: float, zd: float, a: float, half_length: float, clearance: float,
                   stiffness: float, viscosity: float, radius: float,
                   floor: float) -> tuple[float, float, float, float]:
    """Bar contact plus squeeze films of both bars: (F_z [N], M_y [N m], front-bar force
    [N], rear-bar force [N]), the bar forces including their squeeze-film parts (closing
    gap only; module notes). viscosity [Pa s] (0: no squeeze film), radius R = D_w/2 [m],
    floor [m]."""
    fz, my, ff, fb = bar_contact(z, a, half_length, clearance, stiffness)
    length = 2.0 * half_length
    if viscosity > 0.0:
        c_f = squeeze_coefficient(0.5 * clearance - z, viscosity, radius, length, floor)
        c_b = squeeze_coefficient(0.5 * clearance + z, viscosity, radius, length, floor)
        # front gap closes at zd > 0 (force -c_f zd on the roller), rear gap at zd < 0
        if zd > 0.0:
            ff += c_f * zd
            fz -= c_f * zd
        else:
            fb -= c_b * zd
            fz -= c_b * zd
    return fz, my, ff, fb


@njit(cache=True)
def _bar_series(z: np.ndarray, zd: np.ndarray, a: np.ndarray, half_length: float,
                clearance: float, stiffness: float, viscosity: float, radius: float,
                floor: float) -> np.ndarray:
    out = np.zeros((4, z.shape[0]))
    for i in range(z.shape[0]):
        r = pocket_force_z(z[i], zd[i], a[i], half_length, clearance, stiffness, viscosity,
                           radius, floor)
        for j in range(4):
            out[j, i] = r[j]
    return out


def bar_forces(z: Any, zd: Any, a: Any, half_length: float, clearance: float,
               stiffness: float, viscosity: float, radius: float,
               floor: float = DEFAULT_SQUEEZE_FLOOR) -> tuple[Any, ...]:
    """:func:`pocket_force_z` over arrays: (F_z, M_y, front, rear) [N, N m, N, N]."""
    zz, vv, aa = np.broadcast_arrays(*(np.asarray(v, float) for v in (z, zd, a)))
    shape = zz.shape
    out = _bar_series(np.ascontiguousarray(zz.ravel()), np.ascontiguousarray(vv.ravel()),
                      np.ascontiguousarray(aa.ravel()), float(half_length), float(clearance),
                      float(stiffness), float(viscosity), float(radius), float(floor))
    return tuple(out[j].reshape(shape)[()] for j in range(4))


def extra_pocket_friction(net_bar_force: np.ndarray, t: np.ndarray, spin: Any,
                          steady_force: Any, roller_diameter: float, length: float,
                          viscosity: float, clearance: float) -> float:
    """Time-mean pocket film friction [N] of the bar force history ``net_bar_force`` (front
    minus rear, [N]) at ``spin`` [rad/s] over ``t`` [s], minus the friction at the steady
    pocket force ``steady_force`` [N] (scalar or per sample) that the quasi-static model
    already counts (paper 000 eqs. 37-38 via
    :func:`thermobearing.skidding.roller_fluid.pocket_forces`, used for both)."""
    from .roller_fluid import pocket_forces

    w = np.broadcast_to(np.asarray(spin, float), t.shape)
    f = pocket_forces(net_bar_force, w, roller_diameter, length, viscosity,
                      clearance).friction
    f0 = pocket_forces(np.broadcast_to(np.asarray(steady_force, float), t.shape), w,
                       roller_diameter, length, viscosity, clearance).friction
    span = t[-1] - t[0]
    if span <= 0:
        return float(np.mean(f - f0))
    return float(np.trapezoid(f - f0, t) / span)
