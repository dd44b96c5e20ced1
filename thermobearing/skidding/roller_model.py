"""The fixed model of one cylindrical-roller skidding solve (paper 000).

One job: collect geometry, contact stiffness, fluid properties, film and traction laws and
the model options into a :class:`RollerModel` (:func:`build_model`) for the residual of
:mod:`thermobearing.skidding.roller_residual`. Li, Chen, Zhang, Wang (2018), seed
``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding], after Harris (1966)
[harris1966_roller_skidding; harris_kotzalas2007].

Options. An unloaded roller has no inner contact (paper sec. 1: it rolls on the outer race,
pressed by its centrifugal force). By default its spin follows from its moment balance
(eq. 31 with the eq. 5 shear: outer-race Couette against Poiseuille and pocket friction),
which lets it slide on the outer race; with ``unloaded_zone="outer_pure_rolling"`` it rolls
purely on the outer race as paper 000 sec. 1 states (omega_r = (d_m + D)/D omega_c, the outer
shear = f_d as a constraint force). The second is not consistent with eq. 5 (a Newtonian
film carries no Couette shear at zero sliding), hence not the default. With
``ring_support="films"`` the ring rests on the films of every roller instead of a dry load
zone (films as thick as the clearance; see
:func:`thermobearing.loads_roller.roller_film_load_distribution` and
:mod:`thermobearing.skidding.roller_loads`); every roller then has an inner contact, and a
bearing without radial load has a defined cage speed.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import InputError, check_positive, check_temperature
from .roller_fluid import POCKET_FILM_MODELS, ROLLER_DRAG, LineContactForces

#: default pocket clearance when the cage geometry gives none [m] (estimated: 1-2 % of D)
DEFAULT_POCKET_CLEARANCE_FRACTION = 0.015

#: models of the rollers outside the load zone (see :func:`build_model`)
UNLOADED_ZONE_MODELS = ("moment_balance", "outer_pure_rolling")

#: models of the inner-ring support (see :func:`build_model`)
RING_SUPPORT_MODELS = ("contacts", "films")


@dataclass(frozen=True)
class RollerModel:
    """Everything the residual needs, fixed during one solve (built by :func:`build_model`).

    Geometry: pitch_diameter d_m, roller_diameter D, length l, n_rollers Z, roller_mass,
    radii R_i, R_o [m], effective_modulus E' [Pa], diametral_clearance [m],
    pocket_clearance [m], contact stiffnesses k_inner, k_outer [N/m^(10/9)].
    Fluid: eta0 [Pa s], alpha [1/Pa], temperature [K], film(u_e, w, race) -> h_c [m],
    traction_law, contact_forces (drag model callable), cage_drag_torque [N m].
    Oil drag: ``drag`` (:class:`~thermobearing.skidding.roller_drag.RollerDrag`, or None:
    none, paper 000).
    Inlet heating: ``thermal_reduction`` (a ``film.THERMAL_FILM`` name) and its factor
    ``inlet_heating`` (u_e, S, p_H) -> phi_T, None for "none"
    (:mod:`~thermobearing.skidding.roller_thermal`).
    """

    pitch_diameter: float
    roller_diameter: float
    length: float
    n_rollers: int
    roller_mass: float
    radius_inner: float
    radius_outer: float
    effective_modulus: float
    diametral_clearance: float
    pocket_clearance: float
    k_inner: float
    k_outer: float
    eta0: float
    alpha: float
    temperature: float
    film_inner: Callable[[np.ndarray, np.ndarray], np.ndarray]
    film_outer: Callable[[np.ndarray, np.ndarray], np.ndarray]
    traction_law: Any
    contact_forces: Callable[..., LineContactForces]
    cage_drag_torque: float = 0.0
    rolling_force: str = "regime_min"
    oil_layer: float | None = None
    clearance_film: bool = False
    clearance_film_floor: float = 1e-6
    inner_gap: np.ndarray | None = None
    unloaded_zone: str = "moment_balance"
    ring_support: str = "contacts"
    fluid_shear_modulus: float | None = None
    film_pressure: str = "hertz"
    traction_curve: Any = None
    pocket_film: str = "one_face"
    drag: Any = None
    thermal_reduction: str = "none"
    inlet_heating: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray] | None = None

    @property
    def theoretical_cage_speed_ratio(self) -> float:
        """(1 - D/d_m)/2, paper 000 eq. 40."""
        return 0.5 * (1.0 - self.roller_diameter / self.pitch_diameter)


def _film_for(lubricant: Any, temperature: float, eta0: float, alpha: float, radius: float,
              e_prime: float, film_model: str | Callable[..., Any]
              ) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    """``film(u_e, w) -> h_c`` from a film model of :mod:`thermobearing.film` or a callable.

    A callable is used as ``film_model(u_e [m/s], w [N/m], radius [m], eta0 [Pa s],
    alpha [1/Pa], e_prime [Pa]) -> h_c [m]``.
    """
    if callable(film_model):
        return lambda ue, w: np.asarray(film_model(ue, w, radius, eta0, alpha, e_prime))
    from ..film import FILM

    func = FILM.get(film_model)

    def h(ue: np.ndarray, w: np.ndarray) -> np.ndarray:
        # line-contact film formulas take (u, eta0, alpha, load, length, R_x, E'): pass the
        # load per unit length with a unit length
        return np.asarray(func(ue, eta0, alpha, w, 1.0, radius, effective_modulus=e_prime))

    return h


def default_traction_law(lubricant: Any, eyring_stress: float | None = None,
                         limiting_shear_coefficient: float = 0.075, cap: str = "min") -> Any:
    """Eyring/Newtonian film with a limiting shear stress (traction law of the force model).

    ``eyring_stress=None`` gives the Newtonian film of paper 000 eq. 5, capped by Lambda p
    (``cap="min"``, the literal cap; ``"smooth"`` is differentiable but lowers the traction
    near the cap, by 29 % where the Newtonian stress equals Lambda p).
    """
    from ..traction import make_traction_law

    return make_traction_law("eyring_limiting_shear", lubricant=lubricant,
                             limiting_shear_coefficient=limiting_shear_coefficient,
                             eyring_stress=eyring_stress, cap=cap)


def build_model(
    bearing: Any,
    lubricant: Any,
    temperature: float,
    *,
    viscosity: float | None = None,
    traction_law: Any = None,
    eyring_stress: float | None = None,
    limiting_shear_coefficient: float = 0.075,
    film_model: str | Callable[..., Any] = "moes_line_central",
    drag_model: str = "closed_form",
    pocket_clearance: float | None = None,
    cage_drag_torque: float = 0.0,
    rolling_force: str = "regime_min",
    oil_layer: float | None = None,
    clearance_film: bool = False,
    clearance_film_floor: float = 1e-6,
    unloaded_zone: str = "moment_balance",
    ring_support: str = "contacts",
    fluid_shear_modulus: float | None = None,
    film_pressure: str = "hertz",
    traction_curve: Any = None,
    pocket_film: str = "one_face",
    drag: Any = None,
    thermal_reduction: str | None = None,
) -> RollerModel:
    """Collect geometry, stiffness, fluid properties and models for the residual.

    Parameters
    ----------
    bearing : :class:`thermobearing.geometry.RollerBearing`.
    lubricant : :class:`thermobearing.lubricant.Lubricant`.
    temperature : oil/contact temperature [K].
    viscosity : ambient viscosity override eta0 [Pa s] (None: lubricant at temperature).
        When given, the lubricant's viscosity law is replaced by an isothermal eta0 for the
        traction law too.
    traction_law : traction law object (default :func:`default_traction_law`).
    eyring_stress, limiting_shear_coefficient : parameters of the default traction law.
    film_model : line-contact central-film model in :data:`thermobearing.film.FILM` (default
        Moes 1992, which spans the rigid-isoviscous regime of the centrifugally loaded rollers
        and the EHL regime of the loaded ones) or a callable (see ``_film_for``).
    drag_model : name in :data:`~thermobearing.skidding.roller_fluid.ROLLER_DRAG`.
    pocket_clearance : c_p [m] (default: the cage's pocket clearance, else 1.5 % of D).
    cage_drag_torque : resisting torque on the cage [N m] (paper 000: 0).
    rolling_force : rolling (pressure) force model of the raceway contacts, see
        :func:`~thermobearing.skidding.roller_fluid.closed_form_contact_forces`.
    oil_layer : available inlet oil layer [m] (None: fully flooded contacts), see
        :func:`~thermobearing.skidding.roller_fluid.closed_form_contact_forces`. With
        ``ring_support="films"`` the load distribution uses the same starved film
        (:func:`~thermobearing.skidding.roller_fluid.starved_film`): a roller whose films
        cannot fill its gap has no inner film load.
    clearance_film : add the flooded hydrodynamic film across the radial gap of every roller
        without a Hertz inner contact (drive from the inner ring, rolling force, film load
        onto the outer race; :func:`~thermobearing.skidding.roller_fluid.clearance_film_forces`).
        Default False: paper 000's unloaded rollers have no inner-ring force. The film load is
        not fed back into the ring equilibrium.
    clearance_film_floor : smallest gap used by the clearance film [m].
    unloaded_zone : how a roller without an inner contact spins (one of
        :data:`UNLOADED_ZONE_MODELS`). ``"moment_balance"`` (default): its spin follows from
        its moment balance (outer-race shear against pocket friction, eq. 31 with the traction
        law). ``"outer_pure_rolling"``: paper 000 sec. 1, "the roller purely rolls along the
        outer ring raceway for the unloaded zone": omega_r = (d_m + D)/D omega_c, the outer
        contact supplies whatever tangential force eq. 31 needs (rigid rolling constraint, no
        sliding work) and eq. 30 gives the pocket force.
    ring_support : ``"contacts"`` (default): dry load distribution with clearance and
        centrifugal force (:func:`~thermobearing.loads_roller.roller_load_distribution`,
        Harris; rollers outside the load zone have no inner contact). ``"films"``: every
        roller fills its radial gap with its inner and outer films (the film formula
        ``film_model`` at the current entrainment speeds) and the ring rests on all of them
        (:func:`~thermobearing.loads_roller.roller_film_load_distribution`); coupled to the
        speeds by a fixed point. For films as thick as the clearance (paper 000: 4-30 um
        against P_d/2 = 12.5 um), where the dry distribution is not consistent with the films
        the traction uses.
    fluid_shear_modulus : elastic shear modulus G of the oil in the Hertz zone [Pa]. None
        (default): the Hertz-zone shear follows the traction law point by point (viscous
        film). Given: the film is a Maxwell element (Johnson & Tevaarwerk 1977), the stress
        builds up along the contact and the traction at small slip is elastic, linear in the
        roller load instead of growing like exp(alpha p_H)
        (:mod:`thermobearing.skidding.roller_maxwell`).
    film_pressure : pressure under which the Hertz-zone oil is sheared. ``"hertz"``
        (default): the semi-elliptic Hertz pressure. ``"regime_min"``: at every point the
        smaller of the Hertz and the rigid-isoviscous (Martin) pressure, so that a contact in
        the rigid regime (Moes M < ~1, paper 000's light loads) is not sheared at the
        viscosity of a Hertz pressure it does not have
        (:mod:`thermobearing.skidding.roller_pressure`).
    traction_curve : None (default): the Hertz-zone shear follows the traction law (a film
        rheology at the local pressure). Given (a name in
        :data:`thermobearing.traction_curve.TRACTION_CURVES`, optionally written
        ``"curve:<name>"``, or a curve object with ``traction(s, Q, u_e, R, E', T)``): the
        Hertz-zone traction of every raceway contact is mu(s) Q, a traction-coefficient curve
        of the slide-to-roll ratio times the contact load (the law of quasi-dynamic codes of
        paper 001's school; :func:`~thermobearing.skidding.roller_fluid.curve_contact_forces`);
        the inlet/outlet Couette, Poiseuille and rolling forces stay those of the drag model.
        The traction law then serves only the inlet/outlet (Newtonian) shear. Closed-form drag
        only, not with ``fluid_shear_modulus`` or ``film_pressure``.
    pocket_film : roller-pocket film of paper 000 eqs. 37-38 (one of
        :data:`~thermobearing.skidding.roller_fluid.POCKET_FILM_MODELS`). ``"one_face"``
        (default): the roller's film on the face it is pressed on, capped by the pocket
        clearance (:func:`~thermobearing.skidding.roller_fluid.pocket_forces`; a kink at
        F_d = 0 where the roller changes faces). ``"two_faces"``: both faces of a flooded
        pocket carry a Martin film, the roller's offset in the pocket balances the net
        normal force (:func:`~thermobearing.skidding.roller_fluid.pocket_forces_two_faces`;
        smooth and even in F_d). The difference matters where the pocket forces are as small
        as their changes (film-supported ring under whirl, paper 000).
    drag : None (default, paper 000: no oil drag) or a
        :class:`~thermobearing.skidding.roller_drag.RollerDrag`
        (:func:`~thermobearing.skidding.roller_drag.build_drag`, what ``skidding.solve``
        builds from the oil supply): the roller drag enters each roller's orbital balance
        (pocket force), the cage churning and guide-land moments the cage equation, the
        inner-ring churning the shaft torque.
    thermal_reduction : inlet shear heating of the raceway rolling force Q_x (paper 000
        eq. 35 and its rigid-isoviscous form), a ``film.THERMAL_FILM`` name, e.g.
        "gupta_1992", the line-contact rolling-resistance heat source's default
        (``heat_sources.raceway.DEFAULT_THERMAL_REDUCTION``). None (default) is that
        default (``roller_thermal.default_thermal_reduction``, one name for the solver and
        the heat source; "none" is the isothermal eq. 35 of paper 000) for the
        closed-form drag and "none" for a drag model that integrates its own film pressure
        (a name other than "none" is refused there). The factor phi_T of each contact, at
        its entrainment speed, slide-to-roll ratio and Hertz pressure, is the heat source's
        (the lubricant's beta and k_f at ``temperature``), applied as the inlet viscosity
        eta0 phi_T^(1/0.7) of the rolling force only
        (:mod:`~thermobearing.skidding.roller_thermal`). With ``viscosity`` given the oil is
        isothermal (beta = 0) and phi_T = 1. The clearance film of ``clearance_film``
        stays isothermal.
    """
    if drag is not None:
        from .roller_drag import RollerDrag

        if not isinstance(drag, RollerDrag):
            raise InputError("drag", type(drag).__name__,
                             "None or a RollerDrag (skidding.roller_drag.build_drag)")
    if pocket_film not in POCKET_FILM_MODELS:
        raise InputError("pocket_film", pocket_film, POCKET_FILM_MODELS)
    if unloaded_zone not in UNLOADED_ZONE_MODELS:
        raise InputError("unloaded_zone", unloaded_zone, UNLOADED_ZONE_MODELS)
    if ring_support not in RING_SUPPORT_MODELS:
        raise InputError("ring_support", ring_support, RING_SUPPORT_MODELS)
    if ring_support == "films" and clearance_film:
        raise InputError("ring_support", ring_support,
                         "'contacts' with clearance_film (the film-supported distribution "
                         "already fills every roller's gap with its films)")
    if oil_layer is not None:
        check_positive("oil_layer", oil_layer)
    check_positive("clearance_film_floor", clearance_film_floor)
    if fluid_shear_modulus is not None:
        check_positive("fluid_shear_modulus", fluid_shear_modulus)
    from ..hertz import line_contact_stiffness

    check_temperature("temperature", temperature)
    if getattr(bearing, "kind", None) != "cylindrical":
        raise InputError("bearing.kind", getattr(bearing, "kind", None),
                         "a cylindrical roller bearing (RollerBearing)")
    if viscosity is not None:
        check_positive("viscosity", viscosity)
        lubricant = dataclasses.replace(lubricant, viscosity_law="isothermal",
                                        viscosity_parameters={"eta0": float(viscosity)})
    eta0 = float(np.asarray(lubricant.dynamic_viscosity(temperature)))
    alpha = float(np.asarray(lubricant.pressure_viscosity_coefficient(temperature)))
    d_m = bearing.pitch_diameter
    d = bearing.roller_diameter
    length = bearing.roller_effective_length
    e_prime = bearing.effective_modulus
    r_i, _ = bearing.curvature("inner")
    r_o, _ = bearing.curvature("outer")
    k = float(line_contact_stiffness(length, e_prime))
    if pocket_clearance is None:
        cage = getattr(bearing, "cage", None)
        pc = getattr(cage, "pocket_clearance", None) if cage is not None else None
        pocket_clearance = pc if pc else DEFAULT_POCKET_CLEARANCE_FRACTION * d
    check_positive("pocket_clearance", pocket_clearance)
    law = traction_law if traction_law is not None else default_traction_law(
        lubricant, eyring_stress, limiting_shear_coefficient)
    forces = ROLLER_DRAG.get(drag_model)()
    if film_pressure not in ("hertz", "regime_min"):
        raise InputError("film_pressure", film_pressure, ("hertz", "regime_min"))
    if drag_model != "closed_form" and (fluid_shear_modulus is not None
                                        or film_pressure != "hertz"):
        # the options replace the Hertz-zone shear of the drag model by a closed-form
        # integral; a numerical drag integrates its own pressure and film
        raise InputError("film_pressure / fluid_shear_modulus",
                         (film_pressure, fluid_shear_modulus),
                         f"'hertz' and None with drag_model={drag_model!r} (the Hertz-zone "
                         "options apply to the closed-form drag only)")
    if traction_curve is not None:
        from ..traction_curve import get_traction_curve
        from .roller_fluid import curve_contact_forces

        if drag_model != "closed_form" or fluid_shear_modulus is not None \
                or film_pressure != "hertz":
            raise InputError("traction_curve", traction_curve,
                             "None with drag_model other than 'closed_form', "
                             "fluid_shear_modulus or film_pressure != 'hertz' (the curve "
                             "replaces the Hertz-zone shear those options model)")
        traction_curve = get_traction_curve(traction_curve)
        forces = curve_contact_forces(forces, traction_curve)
    if fluid_shear_modulus is not None or film_pressure != "hertz":
        from .roller_maxwell import maxwell_contact_forces

        forces = maxwell_contact_forces(
            forces, None if fluid_shear_modulus is None else float(fluid_shear_modulus),
            film_pressure)
    from .roller_thermal import inlet_heating_factor, resolve_thermal_reduction

    thermal_reduction = resolve_thermal_reduction(
        thermal_reduction, bool(getattr(forces, "thermal_rolling", False)), drag_model)
    return RollerModel(
        pitch_diameter=d_m, roller_diameter=d, length=length, n_rollers=bearing.n_rollers,
        roller_mass=bearing.roller_mass, radius_inner=r_i, radius_outer=r_o,
        effective_modulus=e_prime, diametral_clearance=bearing.diametral_clearance,
        pocket_clearance=float(pocket_clearance), k_inner=k, k_outer=k, eta0=eta0, alpha=alpha,
        temperature=float(temperature),
        film_inner=_film_for(lubricant, temperature, eta0, alpha, r_i, e_prime, film_model),
        film_outer=_film_for(lubricant, temperature, eta0, alpha, r_o, e_prime, film_model),
        traction_law=law, contact_forces=forces,
        cage_drag_torque=float(cage_drag_torque), rolling_force=rolling_force,
        oil_layer=None if oil_layer is None else float(oil_layer),
        clearance_film=bool(clearance_film), clearance_film_floor=float(clearance_film_floor),
        unloaded_zone=unloaded_zone, ring_support=ring_support,
        fluid_shear_modulus=None if fluid_shear_modulus is None else float(fluid_shear_modulus),
        film_pressure=film_pressure, traction_curve=traction_curve, pocket_film=pocket_film,
        drag=drag, thermal_reduction=thermal_reduction,
        inlet_heating=inlet_heating_factor(thermal_reduction, lubricant, temperature, eta0,
                                           e_prime),
    )
