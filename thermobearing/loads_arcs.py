"""Raceway arcs of a ball bearing and the contact-field type of the load distribution.

One job: the geometry the quasi-static load distribution (:mod:`thermobearing.loads`) and the
ball skidding residual (:mod:`thermobearing.skidding.ball_residual`) share -- where the
curvature centres of the raceway arcs lie (:func:`ball_arcs`, :class:`ArcSet`) and the
per-(ball, arc) contact state (:class:`ContactField`). No solver, no compiled code.

Sources: Jones 1959 in the form of Harris & Kotzalas 2007, vol. 2, ch. 1-3 (every arc an
independent contact, ../shared/notes/over-skidding.md section 4 for the gothic arch);
Harris & Kotzalas 2007, vol. 1, eq. 2.29 (free contact angle). Split out of ``loads.py``
(names re-exported there). Units: SI (m, N).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import InputError

__all__ = ["INNER", "OUTER", "ArcSet", "ContactField", "ball_arcs"]

INNER = 0
OUTER = 1


@dataclass(frozen=True)
class ArcSet:
    """Raceway arcs of a ball bearing in the axial plane of one ball, inner ring centred.

    Attributes
    ----------
    ring : (k,) int, 0 = inner ring arc, 1 = outer ring arc.
    centre_x : (k,) axial coordinate of the arc's curvature centre [m].
    centre_r : (k,) radial coordinate (from the bearing axis) of the curvature centre [m].
    free_distance : (k,) ``(f_k - 1/2) D``: centre distance at which contact starts [m].
    conformity : (k,) ``f_k = r_k / D`` [-].
    ball_diameter, pitch_radius : D and d_m / 2 [m].
    effective_modulus : E' of the ball-ring pair [Pa] (cached from the bearing).
    """

    ring: np.ndarray
    centre_x: np.ndarray
    centre_r: np.ndarray
    free_distance: np.ndarray
    conformity: np.ndarray
    ball_diameter: float
    pitch_radius: float
    effective_modulus: float = 0.0

    @property
    def n_arcs(self) -> int:
        return int(self.ring.size)


def ball_arcs(bearing) -> ArcSet:
    """Build the raceway arcs of a :class:`thermobearing.geometry.BallBearing`.

    Geometry
    --------
    - ``four_point``: two arcs per ring whose curvature centres are offset axially by
      ``+-s/2`` (``s = bearing.gothic_arch_offset``); each arc passes through the groove bottom
      (diameters ``inner_raceway_diameter``, ``outer_raceway_diameter`` of the geometry
      module), so the radial play of the centred ball is half the diametral clearance and the
      centred ball touches both arcs of a ring at the shim angle
      ``sin(theta_s) = (s/2) / ((f - 1/2) D)`` when the clearance is zero (primer section 4,
      checked in ``tests/unit/test_loads.py``).
    - ``deep_groove`` / ``angular_contact``: one arc per ring; the curvature centres are placed
      so that, with the inner ring shifted axially until contact, the line of centres makes
      the free contact angle ``bearing.free_contact_angle`` (Harris & Kotzalas 2007, vol. 1,
      eq. 2.29: ``cos(alpha_f) = 1 - P_d / (2 A)``, ``A = (f_i + f_o - 1) D``); the inner
      ring's zero axial displacement is that touching position.
    """
    D = float(bearing.ball_diameter)
    Rm = 0.5 * float(bearing.pitch_diameter)
    fi = float(bearing.inner_conformity)
    fo = float(bearing.outer_conformity)
    kind = bearing.kind
    if kind == "four_point":
        s = float(bearing.gothic_arch_offset)
        ri, ro = fi * D, fo * D
        if not (0.0 <= 0.5 * s < min((fi - 0.5), (fo - 0.5)) * D):
            raise InputError("bearing.gothic_arch_offset", s,
                             "0 <= s/2 < (f - 1/2) D for both rings")
        di = float(bearing.inner_raceway_diameter)
        do = float(bearing.outer_raceway_diameter)
        # arc through the groove bottom (x = 0): |(0, d/2) - (+-s/2, r_c)| = f D
        rci = 0.5 * di + np.sqrt(ri * ri - 0.25 * s * s)
        rco = 0.5 * do - np.sqrt(ro * ro - 0.25 * s * s)
        ring = np.array([INNER, INNER, OUTER, OUTER])
        cx = np.array([0.5 * s, -0.5 * s, -0.5 * s, 0.5 * s])
        cr = np.array([rci, rci, rco, rco])
        conf = np.array([fi, fi, fo, fo])
    elif kind in ("deep_groove", "angular_contact"):
        alpha_f = float(bearing.free_contact_angle)
        li, lo = (fi - 0.5) * D, (fo - 0.5) * D
        ring = np.array([INNER, OUTER])
        cx = np.array([li * np.sin(alpha_f), -lo * np.sin(alpha_f)])
        cr = np.array([Rm + li * np.cos(alpha_f), Rm - lo * np.cos(alpha_f)])
        conf = np.array([fi, fo])
    else:
        raise InputError("bearing.kind", kind, "deep_groove, angular_contact or four_point")
    return ArcSet(ring=ring, centre_x=cx, centre_r=cr, free_distance=(conf - 0.5) * D,
                  conformity=conf, ball_diameter=D, pitch_radius=Rm,
                  effective_modulus=float(bearing.effective_modulus))


@dataclass(frozen=True)
class ContactField:
    """Contact state of every (ball, arc) pair; arrays of shape (Z, k).

    Attributes
    ----------
    approach : elastic approach delta_k [m] (negative = open gap).
    load : normal load Q_k [N].
    normal_x, normal_r : unit vector from the arc centre to the ball centre; the contact
        point lies at ``b + (D/2) n`` and the force on the ball is ``-Q n``.
    distance : |b - c_k| [m].
    contact_angle : signed contact angle atan2(n_x, |n_r|) [rad].
    stiffness : K_k with Q = K delta^1.5 [N/m^1.5].
    """

    approach: np.ndarray
    load: np.ndarray
    normal_x: np.ndarray
    normal_r: np.ndarray
    distance: np.ndarray
    contact_angle: np.ndarray
    stiffness: np.ndarray
