"""Normal damping of the 6-DOF roller's raceway line contacts (paper 003 eq. 18, y_r and tilt).

Paper 003 (Zhang et al. 2021, seed ``003_743e023ae6e45686.txt``) moves the roller radially
(eq. 18 lines 2-3) under the raceway normal forces N^i, N^o without saying how they are
damped. The coupled model's raceway slices
(:func:`~thermobearing.skidding.roller_dynamics_tilt.raceway_slices`) are elastic
(Palmgren); their normal damping is the Reynolds squeeze film of the lubricated line
contact:

* **law** (:func:`line_squeeze_coefficient`): a rigid cylinder of reduced radius R_x
  approaching a plane through an isoviscous Newtonian film of viscosity eta at gap h
  carries, per unit length, w' = 3 sqrt(2) pi eta (R_x/h)^(3/2) (-dh/dt): the long-cylinder
  Reynolds equation h^3 dp/dx = 12 eta (dh/dt) x with h = h_0 + x^2/(2 R_x), integrated
  twice (the cylinder-plane squeeze film of Hamrock, Schmid & Jacobson, *Fundamentals of
  Fluid Film Lubrication*, 2nd ed., 2004, ch. "Squeeze film bearings", parallel cylinder
  against a plane [hamrock2004]; derivation in
  :mod:`~thermobearing.skidding.roller_dynamics_pocket`). Units: eta [Pa s], R_x, h [m];
  the coefficient c' [N s/m^2] times the closing speed [m/s] is a force per length [N/m].
  A separating gap cavitates (half-Sommerfeld), so the film acts on closing slices only.
* **gap** (:func:`raceway_film_thickness`): the slice's geometric gap, but not below the
  central film thickness h_c of the rolling contact. While the roller rolls, the inlet's
  entrainment keeps the surfaces h_c apart (the same film model as the quasi-static roller
  solver, :func:`thermobearing.skidding.roller_model.build_model` ``film_model``, default
  Moes' line-contact central film, :func:`thermobearing.film.moes_line_central`), so the
  squeeze acts on the inlet of gap h = max(gap, h_c). h_c of each race is taken at the
  unloaded zone's outer contact load (the roller's centrifugal force, the load on which an
  unloaded roller rattles in the radial play) and each race's entrainment speed there
  (quasi-static solution). Paper 003's base case (CRB_50x75x16, 30000 r/min, 3000 N,
  MIL-PRF-23699 at 80 degC): 79.2 N on L_e = 5.4 mm, h_c = 0.710 um (outer), 0.659 um
  (inner); the loaded rollers' own films (quasi-static solution) are 0.655-0.684 um (outer)
  and 0.623-0.705 um (inner): their damping is within -11 % / +11 % of the law's.

Validity and what the law leaves out: the Reynolds squeeze above is exact for a rigid,
isoviscous film (Moes M -> 0, alpha p << 1). The base case's contacts are at M = 0.71
(unloaded zone, p_H = 398 MPa, alpha p_H = 4.0) to 6.9 (most loaded, alpha p_H = 13.9) and
L = 12.0-13.4: the piezoviscous-rigid to EHL transition, whose Hertz zone is not
rigid-isoviscous. There the film inside the Hertz zone is convected at
the entrainment speed rather than squeezed (its viscosity exp(alpha p) high), and the
approach is taken by the elastic slices; the law is the inlet's squeeze at the film the
inlet forms. Not modelled: the inlet's dependence on the instantaneous load (h_c ~ w'^-1 in
the rigid regime: 1.6 um at 20 N, 6.3 um at 5 N on the outer race at the base case) and the
EHL film's own transient stiffness (validation case SOURCE.md, raceway normal damping).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InputError, check_positive
from .roller_dynamics_pocket import SQUEEZE_COEFFICIENT

#: normal damping models of the raceway slices (build_model ``raceway_damping``): "film"
#: (default: the squeeze film at h = max(gap, h_c), h_c the rolling contact's central film),
#: "floor" (the cage bars' film floor ``squeeze_floor`` instead of h_c, the estimate before
#: 2026-11-24 session 24) and "none" (elastic slices, undamped)
RACEWAY_DAMPING = ("film", "floor", "none")


def line_squeeze_coefficient(viscosity: float, reduced_radius: float, gap: float) -> float:
    """Squeeze-film damping per unit length c' [N s/m^2] of a rigid cylinder against a plane.

    c' = 3 sqrt(2) pi eta (R_x/h)^(3/2) (long-cylinder Reynolds equation, isoviscous,
    [hamrock2004], module notes): the film's force per unit length is c' (-dh/dt) while the
    gap closes. ``viscosity`` eta [Pa s], ``reduced_radius`` R_x [m], ``gap`` h [m].
    """
    check_positive("viscosity", viscosity)
    check_positive("reduced_radius", reduced_radius)
    check_positive("gap", gap)
    return SQUEEZE_COEFFICIENT * viscosity * (reduced_radius / gap) ** 1.5


def raceway_film_thickness(bearing: Any, lubricant: Any, temperature: float,
                           quasi_static: Any) -> tuple[float, float]:
    """(outer, inner) central film thickness h_c [m] of the raceway line contacts at the
    unloaded zone's outer load (module notes): the quasi-static solution's smallest outer
    load (the roller's centrifugal force) per unit effective length, each race's entrainment
    speed at that azimuth, the roller solver's film model at ``temperature`` [K]."""
    from .roller import build_model as race_model

    q_o = np.asarray(quasi_static.outer_load, float)
    j = int(np.argmin(q_o))
    load = float(q_o[j])
    if not (math.isfinite(load) and load > 0.0):
        raise InputError("quasi_static.outer_load", load,
                         "a positive outer load in the unloaded zone (the roller's "
                         "centrifugal force)")
    rm = race_model(bearing, lubricant, temperature)
    w = np.array([load / float(bearing.roller_effective_length)])
    h_o = float(rm.film_outer(np.array([float(quasi_static.outer_entrainment_speed[j])]), w)[0])
    h_i = float(rm.film_inner(np.array([float(quasi_static.inner_entrainment_speed[j])]), w)[0])
    for name, h in (("outer", h_o), ("inner", h_i)):
        if not (math.isfinite(h) and h > 0.0):
            raise InputError(f"raceway film thickness ({name})", h, "a positive film [m]")
    return h_o, h_i
