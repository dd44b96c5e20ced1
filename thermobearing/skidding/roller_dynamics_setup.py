"""Set-up of the paper 003 roller dynamics: :func:`build_model` makes a
:class:`~thermobearing.skidding.roller_dynamics_model.DynamicsModel` of a bearing from the
quasi-static skidding solution (:func:`thermobearing.skidding.roller.solve_roller`, paper 000's
Z + 1 equations), the rib geometry (:func:`thermobearing.rib.rib_geometry`, paper 003 eqs.
1-17) and the spin coupling (:mod:`~thermobearing.skidding.roller_dynamics_coupling`).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear]; model notes
in :mod:`thermobearing.skidding.roller_dynamics`. Units: SI.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from ..errors import InputError, check_positive, check_range
from ..rib import DEFAULT_RIB_FRICTION, rib_geometry
from .roller_dynamics_coupling import couple_spins, lagged_spins, race_spin_stiffness
from .roller_dynamics_model import (
    DEFAULT_OIL_FRACTION,
    DEFAULT_POCKET_STIFFNESS,
    DEFAULT_TRACTION_LIMIT,
    DEFAULT_TRACTION_SPEED,
    DynamicsModel,
    chamfer_unbalance,
)
from .roller_dynamics_pocket import DEFAULT_SQUEEZE_FLOOR
from .roller_dynamics_raceway_film import RACEWAY_DAMPING, raceway_film_thickness


def build_model(bearing: Any, lubricant: Any, speed: float, radial_load: float,
                unbalance_mass: float, *, temperature: float = 353.15, side: int = +1,
                rib: dict[str, float] | None = None, pocket_clearance: float | None = None,
                rib_friction: float = DEFAULT_RIB_FRICTION,
                oil_fraction: float = DEFAULT_OIL_FRACTION,
                traction_limit: float = DEFAULT_TRACTION_LIMIT,
                traction_speed: float = DEFAULT_TRACTION_SPEED,
                pocket_stiffness: float = DEFAULT_POCKET_STIFFNESS,
                quasi_static: Any = None, spin: str = "skidding",
                coupling: str = "rib", pocket_dof: bool = True,
                squeeze_floor: float = DEFAULT_SQUEEZE_FLOOR,
                raceway_traction: str = "componentwise",
                rib_squeeze: bool = False, tilt: bool | None = None,
                raceway_damping: str = "film") -> DynamicsModel:
    """Set up the roller dynamics of ``bearing`` at ``speed`` [rad/s], ``radial_load`` [N].

    ``rib``: RibGeometry overrides (``rib_angle`` [rad], ``crown_radius`` [m],
    ``axial_clearance`` [m], ...). ``pocket_clearance`` [m] (default: the cage's).
    ``spin``: "skidding" (the quasi-static solver's roller spins: unloaded rollers skid) or
    "rolling" (every roller at the pure-rolling spin (omega_i - omega_c) d_i / D_w on the
    solver's cage speed) -- a sensitivity switch: the rib sliding speed of eq. 24 depends
    on it strongly (see the validation case's SOURCE.md) -- or "lagged" (the skidding
    spins, coupled, then carried through the spin inertia along the orbit,
    :func:`lagged_spins`).
    ``quasi_static``: a previous :class:`~thermobearing.skidding.roller.RollerSkiddingResult`
    of the same speed/load/temperature (skips the solve; maps reuse it).
    ``coupling``: "rib" (default with ``spin="skidding"``: the mean rib moments and forces
    are fed back into the quasi-static spin and cage equations, :func:`couple_spins`) or
    "none" (spins and cage speed as the quasi-static solver gives them). The spin
    stiffness of the dynamics is always that of the quasi-static traction model
    (:func:`race_spin_stiffness`).
    ``pocket_dof``: True (default) moves the roller circumferentially in its pocket under
    the unbalance's rotating force, the quasi-static pocket force, the raceway damping and
    the cage bars (:mod:`~thermobearing.skidding.roller_dynamics_pocket`); False holds it
    centred (the bars then act on the skew only, the model before 2026-11-22 noon).
    ``squeeze_floor``: smallest bar gap of the squeeze film [m] (estimated).
    ``raceway_traction``: the skew's axial raceway traction and skew damping with the tanh
    law on the axial slide alone ("componentwise", default) or on the resultant of the
    axial and rolling slides, directed along it ("isotropic": a film's shear stress is
    collinear with its sliding velocity [johnson_tevaarwerk1977_traction], so a skidding
    roller's axial traction is ~mu_t s/|V|; a sensitivity, see the validation case).
    ``rib_squeeze``: False (default): the end face meets its rib through paper 003's
    elastic Hertz contact (eq. 6) and Coulomb friction (eq. 12) alone, nothing damps the
    approach; True: the squeeze film of the oil/air mixture in the rib gap opposes an end
    face approaching its rib (:func:`thermobearing.rib.face_squeeze`, eq. 14's mixture
    viscosity, ``squeeze_floor``). A sensitivity, not the paper's model: at paper 003's
    base case it keeps the rollers off the ribs (PV ~0 instead of ~650 MPa m/s) and it
    removes the friction-driven axial/skew rattle behind the 10000 r/min runaway
    (validation case SOURCE.md, 2026-11-23 evening).
    ``tilt``: True adds each roller's radial position and tilt with their speeds (paper 003
    eq. 18's remaining DOFs, the 6-DOF roller: raceway slices in the radial play, the
    unbalance's and the roller's centrifugal forces and tilt moments, the rib's axial force
    on the tilt, gyroscopic coupling; :mod:`~thermobearing.skidding.roller_dynamics_tilt`);
    False: the rollers move axially, skew, slide in their pockets and spin (5 DOF). None
    (default): True where the roller carries an unbalance mass, False without one. Measured
    (validation case SOURCE.md, "Tilt and radial play", 2026-11-24): without unbalance the
    two models agree within 0.2 % (the load rows), at 1.2x the cost for 6 DOF; with 0.11 g
    the 5-DOF model is 22 % high on PV and 18 % low on slip against the 6-DOF one, which
    also keeps the 10000 r/min point in its cage band (6 of 6 trajectories; 0 of 6 on 5
    DOF).
    ``raceway_damping`` (6 DOF only): the normal damping of the raceway slices
    (:mod:`~thermobearing.skidding.roller_dynamics_raceway_film`): "film" (default) the
    line contact's Reynolds squeeze film at h = max(gap, h_c), h_c the rolling contact's
    central film thickness (film module, the quasi-static solver's film model); "floor" the
    same law floored at ``squeeze_floor`` (the estimate before 2026-11-24, session 24);
    "none" undamped elastic slices (a sensitivity).
    Used by :func:`~thermobearing.skidding.roller_dynamics_coupled.simulate_coupled` only.
    Bad input (negative clearance, unbalance >= roller mass, rib below the contact point)
    raises InputError naming the field.
    """
    from ..lubricant_properties import air_properties
    from .roller import solve_roller

    check_positive("speed", speed)
    check_positive("radial_load", radial_load, allow_zero=True)
    geom = rib_geometry(bearing, **(rib or {}))
    cp = bearing.cage.pocket_clearance if pocket_clearance is None else pocket_clearance
    check_positive("pocket_clearance", cp, allow_zero=True)
    check_range("oil_fraction", oil_fraction, 0.0, 1.0)
    check_range("rib_friction", rib_friction, 0.0, 1.0)  # else refused only after the run
    check_positive("traction_limit", traction_limit)
    check_positive("traction_speed", traction_speed)
    check_positive("pocket_stiffness", pocket_stiffness)
    check_positive("squeeze_floor", squeeze_floor)
    unb = chamfer_unbalance(bearing, unbalance_mass, side, geom.chamfer)
    qs = quasi_static if quasi_static is not None else solve_roller(
        bearing, lubricant, speed, radial_load, 0.0, temperature)
    order = np.argsort(np.mod(qs.azimuth, 2.0 * math.pi))
    spins = np.asarray(qs.roller_speed, float)[order]
    if spin == "rolling":
        spins = np.full(spins.shape, (speed - float(qs.cage_speed))
                        * geom.inner_raceway_diameter / geom.roller_diameter)
    elif spin not in ("skidding", "lagged"):
        raise InputError("spin", spin, ("skidding", "rolling", "lagged"))
    if coupling not in ("rib", "none"):
        raise InputError("coupling", coupling, ("rib", "none"))
    if raceway_damping not in RACEWAY_DAMPING:
        raise InputError("raceway_damping", raceway_damping, RACEWAY_DAMPING)
    if raceway_traction not in ("componentwise", "isotropic"):
        raise InputError("raceway_traction", raceway_traction, ("componentwise", "isotropic"))
    with_tilt = bool(unbalance_mass > 0.0) if tilt is None else bool(tilt)
    raceway_film = (raceway_film_thickness(bearing, lubricant, temperature, qs)
                    if with_tilt and raceway_damping == "film" else None)
    eta = (oil_fraction * float(lubricant.dynamic_viscosity(temperature))
           + (1.0 - oil_fraction) * air_properties(temperature).dynamic_viscosity)
    model = DynamicsModel(
        geom=geom, inner_speed=float(speed), cage_speed=float(qs.cage_speed),
        azimuth=np.mod(qs.azimuth, 2.0 * math.pi)[order],
        inner_load=np.asarray(qs.inner_load, float)[order],
        outer_load=np.asarray(qs.outer_load, float)[order],
        spin=spins,
        roller_mass=bearing.roller_mass, transverse_inertia=bearing.roller_transverse_inertia,
        polar_inertia=bearing.roller_inertia,
        effective_length=float(bearing.roller_effective_length),
        outer_raceway_diameter=bearing.outer_raceway_diameter, pocket_clearance=float(cp),
        unbalance=unb, rib_friction=rib_friction, mixture_viscosity=float(eta),
        traction_limit=traction_limit, traction_speed=traction_speed,
        pocket_stiffness=pocket_stiffness,
        pocket_force=np.asarray(qs.pocket_normal_force, float)[order],
        pocket_friction=np.asarray(qs.pocket_friction, float)[order],
        pocket_viscosity=float(lubricant.dynamic_viscosity(temperature)),
        pocket_length=float(bearing.roller_effective_length), squeeze_floor=squeeze_floor,
        pocket_dof=bool(pocket_dof), raceway_traction=raceway_traction,
        rib_squeeze=bool(rib_squeeze),
        tilt=with_tilt, raceway_film=raceway_film,
        raceway_squeeze=raceway_damping != "none",
        extras={"quasi_static": qs, "temperature": temperature, "radial_load": radial_load,
                "spin": spin, "coupling": None})
    if coupling == "rib" and spin != "rolling" and unbalance_mass > 0.0:
        model = couple_spins(model, bearing, lubricant)
    else:
        from .roller import build_model as race_model

        k = race_spin_stiffness(race_model(bearing, lubricant, temperature), model)
        model = dataclasses.replace(model, spin_k=k)
    if spin == "lagged":
        model = dataclasses.replace(model, spin=lagged_spins(model))
    return model
