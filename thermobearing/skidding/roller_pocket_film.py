"""Roller-cage pocket film of the roller skidding solver (paper 000 eqs. 37-38).

A rigid roller turning at ``omega_r`` against a flat pocket face, isoviscous, Reynolds outlet
condition: the printed form is read as the Martin load ``w = 2.448 eta U R / h0`` (U =
omega_r D/2, R = D/2) and a friction force ``~ eta U sqrt(R/h0)``
(:mod:`thermobearing.skidding.roller_fluid` module docstring). Two laws: one face with the
film capped by the clearance (:func:`pocket_forces`) and both faces wetted
(:func:`pocket_forces_two_faces`). Vectorised over rollers; SI units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .roller_fluid_coefficients import martin_coefficients


@dataclass(frozen=True)
class PocketForces:
    """Roller-cage pocket film (paper 000 eqs. 37-38, consistent form).

    Attributes
    ----------
    friction : f_d, friction force on the roller surface against its rotation [N] (>= 0).
    film_thickness : pocket film h0 [m].
    """

    friction: np.ndarray
    film_thickness: np.ndarray


def pocket_forces(
    normal_force: Any,
    roller_speed: Any,
    roller_diameter: float,
    length: float,
    eta0: float,
    pocket_clearance: float,
    smoothing: float = 1e-4,
) -> PocketForces:
    """Friction of the roller-pocket film for a given pocket normal force.

    ``h0`` from the Martin load ``|F_d| = k_w eta0 U R l / h0`` with U = |omega_r| D/2 and
    R = D/2, capped smoothly by the pocket clearance, ``1/h0 = |F_d|/(k_w eta0 U R l) +
    1/c_p``; then ``f_d = (k_c + k_q/2) eta0 U l sqrt(R/h0)`` (Couette + Poiseuille on the
    roller surface, both against its motion).

    Parameters
    ----------
    normal_force : (Z,) F_d [N] (either sign; the face it acts on does not matter here).
    roller_speed : (Z,) roller angular speed omega_r [rad/s].
    roller_diameter : D [m].  length : pocket contact length [m].
    eta0 : ambient viscosity [Pa s].  pocket_clearance : c_p [m] (> 0).
    smoothing : |F_d| is replaced by sqrt(F_d^2 + smoothing^2) [N] (differentiable at 0).

    Reference: paper 000 eqs. 37-38; Martin 1916 and Hamrock et al. 2004 (rigid cylinder).
    """
    k_w, k_q, k_c, _ = martin_coefficients()
    fn = np.sqrt(np.asarray(normal_force, dtype=float) ** 2 + smoothing**2)
    r = 0.5 * roller_diameter
    u = np.abs(np.asarray(roller_speed, dtype=float)) * r
    u_safe = np.maximum(u, 1e-9)
    inv_h = fn / (k_w * eta0 * u_safe * r * length) + 1.0 / pocket_clearance
    h0 = 1.0 / inv_h
    fric = (k_c + 0.5 * k_q) * eta0 * u * length * np.sqrt(r * inv_h)
    return PocketForces(friction=fric, film_thickness=h0)


#: pocket film models of the roller skidding solver (``build_model(pocket_film=...)``)
POCKET_FILM_MODELS = ("one_face", "two_faces")


def pocket_forces_two_faces(
    normal_force: Any,
    roller_speed: Any,
    roller_diameter: float,
    length: float,
    eta0: float,
    pocket_clearance: float,
) -> PocketForces:
    """Friction of a roller between the two flooded faces of its cage pocket.

    The roller sits in a pocket whose two faces (ahead of and behind it) are both wetted;
    each face is a rigid cylinder against a plane with the Martin film of
    :func:`pocket_forces` (paper 000 eqs. 37-38 read as Martin, load coefficient
    k_w = 2.448). With the roller displaced by ``s`` from the pocket centre the films are
    ``h_1 = c_p/2 - s`` (the face it is pressed on) and ``h_2 = c_p/2 + s`` and the net normal
    force is

        F_d = A (1/h_1 - 1/h_2),   A = k_w eta0 U R l,  U = |omega_r| D/2,  R = D/2   [N]

    which gives, with g = F_d (c_p/2) / A [-],

        s = (c_p/2) g / (1 + sqrt(1 + g^2))                                          [m]

    (root of F s^2 + 2 A s - F (c_p/2)^2 = 0 in (-c_p/2, c_p/2)). Both films shear the roller
    against its rotation, f_d = (k_c + k_q/2) eta0 U l sqrt(R) (h_1^-1/2 + h_2^-1/2) [N]
    (Couette + Poiseuille of each face, the coefficients of :func:`pocket_forces`).

    Compared with the one-face law of :func:`pocket_forces` (``1/h0 = |F_d|/A + 1/c_p``, a
    single film capped by the whole clearance), f_d is a smooth, even function of F_d: at
    F_d = 0 the roller is centred with two films of c_p/2 (friction 2 sqrt(2) times the
    one-face value at F_d = 0) instead of a kink where the roller changes faces, and for
    |F_d| >> A/c_p the loaded face tends to the one-face film A/|F_d| while the other face
    adds its film of about c_p. The two-face form matters where the pocket forces are small
    against their changes, e.g. a whirling bearing whose rollers nearly balance (paper 000,
    film-supported ring: |F_d| ~ 0.1-0.2 N against a whirl inertia of 0.22 N).

    Parameters
    ----------
    normal_force : (Z,) net pocket normal force F_d [N] (either sign).
    roller_speed : (Z,) roller angular speed omega_r [rad/s].
    roller_diameter : D [m].  length : pocket contact length l [m].
    eta0 : ambient viscosity [Pa s].  pocket_clearance : c_p, pocket width minus D [m] (> 0).

    Returns
    -------
    PocketForces (friction f_d [N] >= 0, film_thickness = the thinner film h_1 [m]).

    Reference: paper 000 eqs. 37-38 [li2018_nu214_skidding]; Martin 1916
    [martin1916_gear_lubrication] and Hamrock et al. 2004 [hamrock2004] (rigid cylinder).
    Validity: rigid-isoviscous films (pocket loads far below the Hertz regime), flooded
    pocket, roller parallel to the faces.
    """
    k_w, k_q, k_c, _ = martin_coefficients()
    f = np.asarray(normal_force, dtype=float)
    r = 0.5 * roller_diameter
    u = np.abs(np.asarray(roller_speed, dtype=float)) * r
    a = k_w * eta0 * np.maximum(u, 1e-9) * r * length
    half = 0.5 * pocket_clearance
    ag = np.abs(f) * half / a
    q = np.sqrt(1.0 + ag * ag)
    # h_1 = c/2 - |s| and h_2 = c/2 + |s| written without cancellation at large |g|
    h1 = half * (1.0 + 1.0 / (q + ag)) / (1.0 + q)
    h2 = half * (1.0 + q + ag) / (1.0 + q)
    fric = (k_c + 0.5 * k_q) * eta0 * u * length * math.sqrt(r) * (h1**-0.5 + h2**-0.5)
    return PocketForces(friction=fric, film_thickness=h1)
