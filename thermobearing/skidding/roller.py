"""Skidding of a cylindrical roller bearing: the Z + 1 equations of paper 000.

Li, Chen, Zhang, Wang (2018), seed ``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding],
after Harris (1966) [harris1966_roller_skidding; harris_kotzalas2007]. Unknowns: the spin
speed ``omega_r,j`` of every roller and the cage speed ``omega_c``. Equations (paper eqs.
12-15, 20-32):

* kinematics (eqs. 12-15), in the cage frame, along each contact's race velocity:
  inner  u_race = (d_m - D)/2 (omega - omega_c),  outer  u_race = (d_m + D)/2 omega_c,
  roller surface speed u_roller = D/2 omega_r (both contacts), sliding V = u_race - u_roller;
* roller moment about its axis (eqs. 22/25, 28/31):  S_i + S_o - f_d = 0, where S is the
  shear force (Couette + Poiseuille, eq. 5/33-34) of a contact on the roller surface and
  f_d the pocket-film friction (eq. 38);
* roller force along the orbit (eqs. 21/24): the pocket normal force
  F_d = (S_i + (1 - D/d_m) Q_xi) - (S_o + (1 + D/d_m) Q_xo) - m_r a_t,j  (Q_x the rolling
  resultant of the film pressure, eq. 35, of which the roller takes the share R_x/(D/2);
  a_t the tangential whirl acceleration, eqs. 3-4);
* cage (eq. 32): sum_j F_d,j = (D/d_m) sum_j f_d,j + T_c / (d_m/2). Paper 000 writes
  sum F_d = 0; the radial pocket friction f_d acts D/2 beside the roller centre and retards
  the cage on either pocket face, and without it the energy balance (shaft power = the
  dissipation, :attr:`RollerSkiddingResult.power_loss`) does not close. ``cage_drag_torque``
  T_c [N m] is an optional extra drag (default 0, as the paper).

Radial equilibrium (eqs. 20/23) with the centrifugal force and the whirl inertia gives the
contact loads (:mod:`thermobearing.loads_roller`); an unloaded roller has no inner contact
(paper sec. 1: it rolls on the outer race, pressed by its centrifugal force). By default its
spin follows from its moment balance (eq. 31 with the eq. 5 shear: outer-race Couette against
Poiseuille and pocket friction), which lets it slide on the outer race; with
``unloaded_zone="outer_pure_rolling"`` it rolls purely on the outer race as paper 000 sec. 1
states (omega_r = (d_m + D)/D omega_c, the outer shear = f_d as a constraint force). The
second is not consistent with eq. 5 (a Newtonian film carries no Couette shear at zero
sliding), hence not the default. With ``ring_support="films"`` the ring rests on the films of
every roller instead of a dry load zone (films as thick as the clearance; see
:func:`thermobearing.loads_roller.roller_film_load_distribution`); every roller then has an
inner contact, and a bearing without radial load has a defined cage speed.

Numerics: Newton-Raphson on the Z + 1 equations with a structured finite-difference
Jacobian (roller blocks are scalar and coupled only through the cage: an "arrow" matrix,
two extra residual evaluations per iteration, eliminated in O(Z)), backtracking line
search, warm starts, and an outer fixed point for the centrifugal loads. When Newton stalls
(heavy loads: the tractions saturate within a tiny slip and the cage equation jumps across
pure rolling) a bracketed fallback solves each roller's moment balance by bisection inside a
Brent solve of the cage equation. Failure raises :class:`~thermobearing.errors.ConvergenceError`
with the residual and the state; so does a state without any inner-ring contact (no drive).

Slip (paper eqs. 39-40): s_f = 1 - n / n_m, n_m = n_i (1 - D/d_m)/2.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import (
    ConvergenceError,
    InputError,
    check_finite,
    check_positive,
    check_temperature,
)
from ..loads_roller import (
    LINE_CONTACT_EXPONENT,
    roller_body_force,
    roller_film_load_distribution,
    roller_load_distribution,
)
from .roller_fluid import (
    ROLLER_DRAG,
    LineContactForces,
    clearance_film_forces,
    pocket_forces,
)

#: default pocket clearance when the cage geometry gives none [m] (estimated: 1-2 % of D)
DEFAULT_POCKET_CLEARANCE_FRACTION = 0.015

#: models of the rollers outside the load zone (see :func:`build_model`)
UNLOADED_ZONE_MODELS = ("moment_balance", "outer_pure_rolling")

#: models of the inner-ring support (see :func:`build_model`)
RING_SUPPORT_MODELS = ("contacts", "films")


@dataclass(frozen=True)
class RollerSkiddingResult:
    """Quasi-static skidding state of a cylindrical roller bearing (SI).

    Attributes
    ----------
    inner_speed : omega [rad/s].  cage_speed : omega_c [rad/s].
    cage_speed_ratio : omega_c / omega [-].
    theoretical_cage_speed_ratio : (1 - D/d_m)/2 (paper 000 eq. 40) [-].
    slip : cage slip fraction s_f = 1 - CSR / CSR_th (paper 000 eq. 39) [-].
    roller_speed : (Z,) roller spin omega_r about its own axis [rad/s] (positive = rolling
        sense, the sense that pure rolling on the inner race gives).
    azimuth : (Z,) roller azimuths [rad].
    inner_load, outer_load : (Z,) [N].
    inner_sliding_speed, outer_sliding_speed : (Z,) V = u_race - u_roller [m/s].
    inner_entrainment_speed, outer_entrainment_speed : (Z,) (u_race + u_roller)/2 [m/s].
    inner, outer : LineContactForces of the two contacts.
    pocket_normal_force : (Z,) F_d [N] (positive: the roller pushes the cage forward).
    pocket_friction : (Z,) f_d [N].
    converged : bool.  residual_norm : scaled residual norm [-].  iterations : Newton steps.
    residual : (Z+1,) force residuals [N] at the solution.
    temperature [K], eta0 [Pa s] used.
    """

    inner_speed: float
    cage_speed: float
    cage_speed_ratio: float
    theoretical_cage_speed_ratio: float
    slip: float
    roller_speed: np.ndarray
    azimuth: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    inner_sliding_speed: np.ndarray
    outer_sliding_speed: np.ndarray
    inner_entrainment_speed: np.ndarray
    outer_entrainment_speed: np.ndarray
    inner: LineContactForces
    outer: LineContactForces
    pocket_normal_force: np.ndarray
    pocket_friction: np.ndarray
    converged: bool
    residual_norm: float
    iterations: int
    residual: np.ndarray
    temperature: float
    eta0: float
    extras: dict[str, Any] = field(default_factory=dict)

    @property
    def cage_speed_rpm(self) -> float:
        """Cage speed [r/min] (for reports)."""
        return self.cage_speed * 30.0 / math.pi

    @property
    def element_speeds(self) -> np.ndarray:
        """Alias of ``roller_speed`` (the common skidding-result name)."""
        return self.roller_speed

    @property
    def shaft_torque(self) -> float:
        """Torque the shaft delivers to the inner ring [N m].

        T = (d_m - D)/2 * sum_j (S_ij + Q_xij): minus the tangential fluid force on the inner
        raceway (shear plus pressure), at the raceway radius of paper 000 eq. 12.
        """
        r_i = float(self.extras["raceway_radius_inner"])
        return r_i * float(np.sum(self.inner.race_shear_force))

    @property
    def power_loss(self) -> dict[str, float]:
        """Power dissipated by mechanism [W] (frame independent, from relative speeds).

        At a raceway contact the film takes ``C V + Q_x u_e`` (Couette force times the sliding
        V = u_race - u_roller, plus the rolling resistance Q_x times the entrainment speed
        u_e = (u_race + u_roller)/2, which is the Poiseuille shear Q_x/2 on each surface);
        in the pocket film ``f_d omega_r D/2``. Keys:
        ``inner_shear``, ``inner_rolling``, ``outer_shear``, ``outer_rolling``, ``pocket``,
        ``total``. In a converged state ``total`` equals ``shaft_torque * inner_speed``
        (energy balance; it follows from the roller moment and cage equations).
        """
        d = float(self.extras["roller_diameter"])
        out = {}
        for race, f, v, ue in (
                ("inner", self.inner, self.inner_sliding_speed, self.inner_entrainment_speed),
                ("outer", self.outer, self.outer_sliding_speed, self.outer_entrainment_speed)):
            out[f"{race}_shear"] = float(np.sum(f.traction * v))
            out[f"{race}_rolling"] = float(np.sum(f.rolling_force * np.abs(ue)))
        out["pocket"] = float(np.sum(self.pocket_friction * np.abs(self.roller_speed) * 0.5 * d))
        out["total"] = sum(out.values())
        return out

    @property
    def kinematic_state(self) -> Any:
        """The :class:`thermobearing.state.KinematicState` the heat sources consume.

        Line contacts (``semi_major`` = l/2, ``semi_minor`` = Hertz b); sliding speeds in the
        state's convention (element minus race = -V here); pocket force as a magnitude;
        film thickness 0 where a contact carries no load; origin "skidding".
        """
        from ..state import ContactSet, KinematicState

        length = float(self.extras["contact_length"])
        sets = []
        for race, f, v, ue, q, rx in (
                ("inner", self.inner, self.inner_sliding_speed, self.inner_entrainment_speed,
                 self.inner_load, self.extras["radius_inner"]),
                ("outer", self.outer, self.outer_sliding_speed, self.outer_entrainment_speed,
                 self.outer_load, self.extras["radius_outer"])):
            loaded = q > 0
            sets.append(ContactSet(
                race=race, kind="line", normal_load=q,
                semi_major=np.where(loaded, 0.5 * length, 0.0), semi_minor=f.half_width,
                max_pressure=f.max_pressure, entrainment_speed=ue, sliding_speed=-v,
                film_thickness=np.where(loaded, f.film_thickness, 0.0),
                temperature=np.full(q.shape, self.temperature), reduced_radius_x=rx))
        return KinematicState(
            inner_speed=self.inner_speed, outer_speed=0.0, cage_speed=self.cage_speed,
            orbital_speed=np.full(self.roller_speed.shape, self.cage_speed),
            element_spin=self.roller_speed, contacts=tuple(sets), attitude_angle=0.0,
            azimuth=self.azimuth, pocket_normal_force=np.abs(self.pocket_normal_force),
            origin="skidding",
            extras={"pocket_friction": self.pocket_friction, "slip": self.slip})


@dataclass(frozen=True)
class RollerModel:
    """Everything the residual needs, fixed during one solve (built by :func:`build_model`).

    Geometry: pitch_diameter d_m, roller_diameter D, length l, n_rollers Z, roller_mass,
    radii R_i, R_o [m], effective_modulus E' [Pa], diametral_clearance [m],
    pocket_clearance [m], contact stiffnesses k_inner, k_outer [N/m^(10/9)].
    Fluid: eta0 [Pa s], alpha [1/Pa], temperature [K], film(u_e, w, race) -> h_c [m],
    traction_law, contact_forces (drag model callable), cage_drag_torque [N m].
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
        :func:`~thermobearing.skidding.roller_fluid.closed_form_contact_forces`.
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
    """
    if unloaded_zone not in UNLOADED_ZONE_MODELS:
        raise InputError("unloaded_zone", unloaded_zone, UNLOADED_ZONE_MODELS)
    if ring_support not in RING_SUPPORT_MODELS:
        raise InputError("ring_support", ring_support, RING_SUPPORT_MODELS)
    if ring_support == "films" and (clearance_film or oil_layer is not None):
        raise InputError("ring_support", ring_support,
                         "'contacts' with clearance_film or oil_layer (the film-supported "
                         "distribution assumes flooded Hertz-zone films at every roller)")
    if oil_layer is not None:
        check_positive("oil_layer", oil_layer)
    check_positive("clearance_film_floor", clearance_film_floor)
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
    return RollerModel(
        pitch_diameter=d_m, roller_diameter=d, length=length, n_rollers=bearing.n_rollers,
        roller_mass=bearing.roller_mass, radius_inner=r_i, radius_outer=r_o,
        effective_modulus=e_prime, diametral_clearance=bearing.diametral_clearance,
        pocket_clearance=float(pocket_clearance), k_inner=k, k_outer=k, eta0=eta0, alpha=alpha,
        temperature=float(temperature),
        film_inner=_film_for(lubricant, temperature, eta0, alpha, r_i, e_prime, film_model),
        film_outer=_film_for(lubricant, temperature, eta0, alpha, r_o, e_prime, film_model),
        traction_law=law, contact_forces=ROLLER_DRAG.get(drag_model)(),
        cage_drag_torque=float(cage_drag_torque), rolling_force=rolling_force,
        oil_layer=None if oil_layer is None else float(oil_layer),
        clearance_film=bool(clearance_film), clearance_film_floor=float(clearance_film_floor),
        unloaded_zone=unloaded_zone, ring_support=ring_support,
    )


def _gapped(model: RollerModel, ld: Any) -> RollerModel:
    """The model with the inner gaps -delta_j of a load distribution (clearance film)."""
    if not model.clearance_film:
        return model
    return dataclasses.replace(model, inner_gap=-np.asarray(ld.interference, dtype=float))


@dataclass(frozen=True)
class _Eval:
    roller_eq: np.ndarray  # (Z,) moment balances / (D/2) [N]
    pocket: np.ndarray  # (Z,) F_d [N]
    cage_eq: float  # sum F_d - T_c/(d_m/2) [N]
    inner: LineContactForces
    outer: LineContactForces
    friction: np.ndarray
    v_i: np.ndarray
    v_o: np.ndarray
    ue_i: np.ndarray
    ue_o: np.ndarray
    q_o: np.ndarray
    cage_terms: np.ndarray  # (Z,) per-roller parts of the cage equation [N]


def evaluate(model: RollerModel, omega: float, omega_r: np.ndarray, omega_c: float,
             inner_load: np.ndarray, body_force_const: np.ndarray, azimuth: np.ndarray,
             whirl_acceleration: tuple[float, float]) -> _Eval:
    """Residuals of the Z + 1 equations (module docstring) at (omega_r, omega_c).

    ``body_force_const`` is the outward body force without the centrifugal term (whirl
    inertia) [N]; the centrifugal force m (d_m/2) omega_c^2 is added here so that the outer
    loads follow omega_c exactly.
    """
    d_m, d = model.pitch_diameter, model.roller_diameter
    half_d = 0.5 * d
    q_o = inner_load + body_force_const + model.roller_mass * 0.5 * d_m * omega_c**2
    q_o = np.maximum(q_o, 0.0)
    u_ri = 0.5 * (d_m - d) * (omega - omega_c) * np.ones_like(omega_r)
    u_ro = 0.5 * (d_m + d) * omega_c * np.ones_like(omega_r)
    free = None
    if model.unloaded_zone == "outer_pure_rolling" and not model.clearance_film:
        # paper 000 sec. 1: outside the load zone the roller rolls purely on the outer race
        free = inner_load <= 0.0
        spin_in = omega_r
        omega_r = np.where(free, (d_m + d) / d * omega_c, omega_r)
    u_roll = half_d * omega_r
    common = dict(eta0=model.eta0, alpha=model.alpha, traction_law=model.traction_law,
                  temperature=model.temperature, rolling_force=model.rolling_force,
                  oil_layer=model.oil_layer)
    fi = model.contact_forces(inner_load, model.length, model.radius_inner,
                              model.effective_modulus, u_ri, u_roll, film=model.film_inner,
                              **common)
    if model.clearance_film and model.inner_gap is not None:
        cf, w_h = clearance_film_forces(
            np.where(inner_load > 0.0, np.inf, model.inner_gap), model.length,
            model.radius_inner, u_ri, u_roll, model.eta0, model.clearance_film_floor)
        fi = fi.combined(cf)
        q_o = q_o + w_h
    fo = model.contact_forces(q_o, model.length, model.radius_outer, model.effective_modulus,
                              u_ro, u_roll, film=model.film_outer, **common)
    ax, ay = whirl_acceleration
    a_t = -ax * np.sin(azimuth) + ay * np.cos(azimuth)
    share_i, share_o = model.radius_inner / half_d, model.radius_outer / half_d
    if free is not None and np.any(free):
        # eqs. 30-31 with a rigid rolling constraint at the outer race: the outer shear on
        # the roller S_o equals the pocket friction f_d (eq. 31), the pocket force follows
        # from eq. 30, F_d = -(S_o + share_o Q_xo) - m a_t, and f_d depends on F_d
        # (eqs. 37-38): a contraction (df_d/dF_d ~ 0.1), solved by fixed point
        base = (-share_o * fo.rolling_force * fo.entrainment_sign
                - model.roller_mass * a_t)
        s_o = np.zeros_like(base)
        for _ in range(8):
            s_o = pocket_forces(base - s_o, omega_r, d, model.length, model.eta0,
                                model.pocket_clearance).friction
        fo = dataclasses.replace(fo, traction=np.where(
            free, s_o + fo.poiseuille * fo.entrainment_sign, fo.traction))
    pocket = fi.orbital_force(share_i) - fo.orbital_force(share_o) - model.roller_mass * a_t
    fric = pocket_forces(pocket, omega_r, d, model.length, model.eta0,
                         model.pocket_clearance).friction
    roller_eq = fi.shear_force + fo.shear_force - fric * np.sign(omega_r + 1e-300)
    if free is not None:
        # the constraint replaces the moment balance of a free roller (N per rad/s scale)
        roller_eq = np.where(free, (omega_r - spin_in) * model.roller_mass * omega * half_d,
                             roller_eq)
    # cage: pocket normal forces at d_m/2; the (radial) pocket friction acts at D/2 beside
    # the roller centre and retards the cage on either pocket face
    cage_terms = pocket - (d / d_m) * fric
    cage_eq = float(np.sum(cage_terms)) - model.cage_drag_torque / (0.5 * d_m)
    return _Eval(roller_eq, pocket, cage_eq, fi, fo, fric, u_ri - u_roll, u_ro - u_roll,
                 0.5 * (u_ri + u_roll), 0.5 * (u_ro + u_roll), q_o, cage_terms)


def _newton(model: RollerModel, omega: float, x0: np.ndarray, inner_load: np.ndarray,
            fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float], *, tol: float,
            max_iter: int) -> tuple[np.ndarray, _Eval, float, int, bool]:
    """Newton with the arrow-structured FD Jacobian and backtracking. x = (omega_r, omega_c)."""
    z = model.n_rollers
    force_scale = max(float(np.max(inner_load, initial=0.0)),
                      model.roller_mass * 0.5 * model.pitch_diameter * omega**2 * 0.05, 1e-3)

    def ev(x: np.ndarray) -> tuple[_Eval, np.ndarray, np.ndarray]:
        e = evaluate(model, omega, x[:z], x[z], inner_load, fb, psi, acc)
        r = np.append(e.roller_eq, e.cage_eq) / force_scale
        return e, r, e.cage_terms

    x = np.array(x0, dtype=float)
    e, r, pk = ev(x)
    norm = float(np.linalg.norm(r))
    it = 0
    while norm > tol and it < max_iter:
        it += 1
        h = 1e-7 * omega
        xp = x.copy()
        xp[:z] += h
        _, rp, pkp = ev(xp)
        diag = (rp[:z] - r[:z]) / h
        c_row = (pkp - pk) / (h * force_scale)
        xq = x.copy()
        xq[z] += h
        _, rq, _ = ev(xq)
        b_col = (rq[:z] - r[:z]) / h
        d_cc = (rq[z] - r[z]) / h
        diag = np.where(np.abs(diag) > 1e-300, diag, 1e-300)
        denom = d_cc - np.sum(c_row * b_col / diag)
        if not np.isfinite(denom) or denom == 0.0:
            break
        dwc = (-r[z] + np.sum(c_row * r[:z] / diag)) / denom
        dwr = (-r[:z] - b_col * dwc) / diag
        step = np.append(dwr, dwc)
        # keep the cage inside (0, omega) and the rollers turning forward
        lam = 1.0
        limit = 0.5 * omega
        big = np.max(np.abs(step) / limit)
        if big > 1.0:
            lam = 1.0 / big
        accepted = False
        for _ in range(30):
            xn = x + lam * step
            if 0.0 < xn[z] < omega and np.all(xn[:z] > 0.0):
                en, rn, pkn = ev(xn)
                nn = float(np.linalg.norm(rn))
                if np.isfinite(nn) and nn < (1.0 - 1e-4 * lam) * norm:
                    accepted = True
                    break
            lam *= 0.5
        if not accepted:
            break
        x, e, r, pk, norm = xn, en, rn, pkn, nn
    return x, e, norm, it, norm <= tol


def initial_guess(model: RollerModel, omega: float, cage_ratio: float | None = None) -> np.ndarray:
    """Cage at ``cage_ratio`` (default 0.8 of the theoretical CSR), rollers rolling on the
    outer race (paper 000's unloaded-zone assumption)."""
    csr = model.theoretical_cage_speed_ratio * (0.8 if cage_ratio is None else cage_ratio)
    wc = csr * omega
    wr = (model.pitch_diameter + model.roller_diameter) / model.roller_diameter * wc
    return np.append(np.full(model.n_rollers, wr), wc)


def _roller_speeds(model: RollerModel, omega: float, wc: float, inner_load: np.ndarray,
                   fb: np.ndarray, psi: np.ndarray, acc: tuple[float, float]) -> np.ndarray:
    """Roller spins solving each roller's moment balance at a given cage speed (bisection).

    The moment balance falls monotonically with the roller's own spin (the tractions fall,
    the pocket friction rises), and the rollers couple only through the cage speed, so all
    rollers are bracketed at once.
    """
    d_m, d = model.pitch_diameter, model.roller_diameter
    top = 2.0 * max((d_m - d) / d * (omega - wc), (d_m + d) / d * wc) + 1e-9 * omega
    lo = np.full(model.n_rollers, 1e-12 * omega)
    hi = np.full(model.n_rollers, top)
    for _ in range(44):  # bracket width 2^-44 ~ 6e-14 of the top speed
        mid = 0.5 * (lo + hi)
        r = evaluate(model, omega, mid, wc, inner_load, fb, psi, acc).roller_eq
        lo = np.where(r > 0.0, mid, lo)
        hi = np.where(r > 0.0, hi, mid)
    return 0.5 * (lo + hi)


def _nested(model: RollerModel, omega: float, loads: Callable[..., Any], psi: np.ndarray,
            acc: tuple[float, float], tol: float, max_iter: int, ld0: Any,
            wc0: float | None = None) -> tuple[np.ndarray, _Eval, float, int, bool, Any]:
    """Bracketed fallback: Brent on the cage equation with bisected roller spins."""
    from scipy.optimize import brentq

    z = model.n_rollers
    ld, fb = ld0, None
    wc = None
    first = wc0
    csr_th = model.theoretical_cage_speed_ratio
    lo_c, hi_c = 1e-6 * csr_th * omega, min(0.999, 1.5 * csr_th) * omega
    for _outer in range(4):
        wc_guess = (first if first is not None and 0 < first < omega else lo_c) \
            if wc is None else wc
        ld, fb = loads(wc_guess, tuple(ld.ring_displacement))
        mg = _gapped(model, ld)

        def cage(w: float, ld: Any = ld, fb: np.ndarray = fb, mg: RollerModel = mg) -> float:
            wr = _roller_speeds(mg, omega, w, ld.inner_load, fb, psi, acc)
            return evaluate(mg, omega, wr, w, ld.inner_load, fb, psi, acc).cage_eq

        f_lo, f_hi = cage(lo_c), cage(hi_c)
        if not (f_lo > 0.0 > f_hi):
            break
        wc_new, info = brentq(cage, lo_c, hi_c, xtol=1e-10 * omega, rtol=1e-14, maxiter=200,
                              full_output=True, disp=False)
        if not info.converged:
            wc = None
            break
        done = wc is not None and abs(wc_new - wc) <= 1e-8 * omega
        wc = wc_new
        if done:
            break
    if wc is None:
        x = np.append(np.zeros(z), 0.0)
        return x, None, math.inf, 0, False, ld
    model = _gapped(model, ld)
    wr = _roller_speeds(model, omega, wc, ld.inner_load, fb, psi, acc)
    x = np.append(wr, wc)
    xp, e, norm, it, ok = _newton(model, omega, x, ld.inner_load, fb, psi, acc, tol=tol,
                                  max_iter=max_iter)
    if ok:
        return xp, e, norm, it, ok, ld
    e = evaluate(model, omega, wr, wc, ld.inner_load, fb, psi, acc)
    force_scale = max(float(np.max(ld.inner_load, initial=0.0)), 1e-3)
    norm = float(np.linalg.norm(np.append(e.roller_eq, e.cage_eq))) / force_scale
    # bracketed to round-off (Brent converged, rollers bisected to machine precision): the
    # residual left is what the stiffness of saturated tractions makes of round-off changes
    # of the speeds (heavy loads: the cage equation jumps across pure rolling). Accepted;
    # the residual norm is reported as it is.
    return x, e, norm, it, True, ld


def _load_distribution(model: RollerModel, omega: float, radial_load: float, wc: float,
                       wr: np.ndarray | None, psi: np.ndarray, acc: tuple[float, float],
                       ring: Any = None, q0: np.ndarray | None = None
                       ) -> tuple[Any, np.ndarray]:
    """Load distribution at cage speed ``wc`` (and roller spins ``wr`` for film support) and
    the body force without the centrifugal term (see :func:`evaluate`)."""
    z = model.n_rollers
    fb_total = roller_body_force(model.roller_mass, model.pitch_diameter, wc, psi, acc)
    if model.ring_support == "films":
        d_m, d = model.pitch_diameter, model.roller_diameter
        spin = np.full(z, (d_m + d) / d * wc) if wr is None else np.asarray(wr, dtype=float)
        u_roll = 0.5 * d * spin
        # entrainment speeds as closed_form_contact_forces forms them (same film, same h)
        ue_i = np.maximum(0.5 * np.abs(0.5 * (d_m - d) * (omega - wc) + u_roll), 1e-6)
        ue_o = np.maximum(0.5 * np.abs(0.5 * (d_m + d) * wc + u_roll), 1e-6)
        length = model.length
        ld = roller_film_load_distribution(
            z, model.diametral_clearance, radial_load,
            lambda q: model.film_inner(ue_i, q / length),
            lambda q: model.film_outer(ue_o, q / length), model.k_inner, model.k_outer,
            body_force=fb_total, azimuth=psi, exponent=LINE_CONTACT_EXPONENT, x0=ring, q0=q0)
    else:
        ld = roller_load_distribution(z, model.diametral_clearance, radial_load, model.k_inner,
                                      model.k_outer, body_force=fb_total, azimuth=psi,
                                      exponent=LINE_CONTACT_EXPONENT, x0=ring)
    return ld, fb_total - model.roller_mass * 0.5 * model.pitch_diameter * wc**2


def solve_model(
    model: RollerModel,
    omega: float,
    radial_load: float,
    *,
    azimuth: np.ndarray | None = None,
    whirl_acceleration: tuple[float, float] = (0.0, 0.0),
    x0: np.ndarray | None = None,
    tol: float = 1e-9,
    max_iter: int = 60,
    load_x0: tuple[float, float] | None = None,
    fallback: bool = True,
) -> RollerSkiddingResult:
    """Solve the Z + 1 equations for a prepared :class:`RollerModel` (see :func:`solve_roller`).

    ``fallback=False`` skips the (slow, robust) bracketed solve when Newton fails and raises
    the ConvergenceError at once.
    """
    z = model.n_rollers
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None else np.asarray(azimuth, float)

    last_q: list[np.ndarray | None] = [None]

    def loads(wc: float, ring: Any, wr: np.ndarray | None = None) -> tuple[Any, np.ndarray]:
        ld, fbw = _load_distribution(model, omega, radial_load, wc, wr, psi,
                                     whirl_acceleration, ring, last_q[0])
        last_q[0] = ld.inner_load
        return ld, fbw

    starts = [x0] if x0 is not None else []
    starts += [initial_guess(model, omega, c) for c in (0.8, 0.4)]
    best = None
    method = "newton"
    for start in starts:
        x = np.array(start, dtype=float)
        ring = load_x0
        films = model.ring_support == "films"
        for _outer in range(60 if films else 8):
            ld, fb_whirl = loads(x[z], ring, x[:z])
            if ld.n_loaded == 0:
                raise ConvergenceError(
                    "roller_skidding", math.inf,
                    "no roller touches the inner ring (radial load "
                    f"{radial_load:g} N with clearance): the model has no traction to drive the "
                    "cage (paper 000 neglects the hydrodynamic drive across the clearance), so "
                    "the cage speed is undetermined",
                    {"radial_load": radial_load, "inner_speed": omega})
            ring = tuple(ld.ring_displacement)
            x_old = x.copy()
            x, e, norm, it, ok = _newton(_gapped(model, ld), omega, x, ld.inner_load, fb_whirl,
                                         psi,
                                         whirl_acceleration, tol=tol, max_iter=max_iter)
            if not ok or float(np.max(np.abs(x - x_old))) <= 1e-8 * omega:
                break
        if best is None or norm < best[2]:
            best = (x, e, norm, it, ok, ld)
        if ok:
            break
    if not best[4] and fallback:
        # robust fallback: roller equations by vectorised bisection inside a bracketed
        # (Brent) solve of the cage equation, then a Newton polish
        x, e, norm, it, ok, ld = _nested(model, omega, loads, psi, whirl_acceleration, tol,
                                         max_iter, best[5], float(best[0][z]))
        if ok:
            best = (x, e, norm, it, ok, ld)
            method = "bracketed"
    x, e, norm, it, ok, ld = best
    if not ok:
        raise ConvergenceError(
            "roller_skidding", norm, "Newton with line search stalled and the bracketed "
            "fallback failed",
            {"cage_speed": x[z], "cage_speed_ratio": x[z] / omega, "radial_load": radial_load,
             "inner_speed": omega, "roller_speed_mean": float(np.mean(x[:z])),
             "iterations": it})
    csr = x[z] / omega
    csr_th = model.theoretical_cage_speed_ratio
    return RollerSkiddingResult(
        inner_speed=omega, cage_speed=float(x[z]), cage_speed_ratio=float(csr),
        theoretical_cage_speed_ratio=csr_th, slip=float(1.0 - csr / csr_th),
        roller_speed=x[:z].copy(), azimuth=psi, inner_load=ld.inner_load, outer_load=e.q_o,
        inner_sliding_speed=e.v_i, outer_sliding_speed=e.v_o,
        inner_entrainment_speed=e.ue_i, outer_entrainment_speed=e.ue_o,
        inner=e.inner, outer=e.outer, pocket_normal_force=e.pocket, pocket_friction=e.friction,
        converged=True, residual_norm=norm, iterations=it,
        residual=np.append(e.roller_eq, e.cage_eq), temperature=model.temperature,
        eta0=model.eta0, extras={"ring_displacement": ld.ring_displacement, "method": method,
                                 "n_loaded": ld.n_loaded, "contact_length": model.length,
                                 "radius_inner": model.radius_inner,
                                 "radius_outer": model.radius_outer,
                                 "roller_diameter": model.roller_diameter,
                                 "raceway_radius_inner": 0.5 * (model.pitch_diameter
                                                                - model.roller_diameter)},
    )


@dataclass(frozen=True)
class CageForceBalance:
    """Pocket forces at a prescribed cage speed (see :func:`cage_force_balance`) [N].

    Attributes
    ----------
    cage_speed : the prescribed omega_c [rad/s].
    drive : sum of the cage-equation terms of the rollers with an inner contact [N].
    drag : minus the sum over the rollers without one [N] (positive: they hold the cage back).
    residual : the cage equation, drive - drag - T_c/(d_m/2) [N] (> 0: the cage would speed up).
    n_loaded : rollers with an inner contact.  roller_speed : (Z,) [rad/s].
    """

    cage_speed: float
    drive: float
    drag: float
    residual: float
    n_loaded: int
    roller_speed: np.ndarray


def cage_force_balance(model: RollerModel, omega: float, radial_load: float, cage_speed: float,
                       *, azimuth: np.ndarray | None = None,
                       whirl_acceleration: tuple[float, float] = (0.0, 0.0)
                       ) -> CageForceBalance:
    """Drive of the loaded rollers and drag of the others at a prescribed cage speed.

    Diagnostic of the Z + 1 equations of paper 000: at ``cage_speed`` [rad/s] every roller is
    put in moment balance (eqs. 28/31, bisection), the loads follow from the load
    distribution with the centrifugal force at that cage speed (eqs. 20/23), and the cage
    equation (eq. 32, energy-consistent form, module docstring) is split into the part of
    the rollers with an inner contact (``drive``) and of those without (``drag``). At the
    solved cage speed ``residual`` is 0; at a published cage speed it is the force the model
    lacks (< 0) or has in excess (> 0) to run there. omega [rad/s], radial_load [N].
    """
    check_positive("speed", omega)
    check_positive("cage_speed", cage_speed)
    z = model.n_rollers
    psi = (2.0 * math.pi * np.arange(z) / z) if azimuth is None else np.asarray(azimuth, float)
    wr = None
    for _ in range(60 if model.ring_support == "films" else 1):
        # film support: loads and spins by fixed point (contraction ~0.2 per step)
        ld, fbw = _load_distribution(model, omega, radial_load, cage_speed, wr, psi,
                                     whirl_acceleration)
        mg = _gapped(model, ld)
        wr_new = _roller_speeds(mg, omega, cage_speed, ld.inner_load, fbw, psi,
                                whirl_acceleration)
        done = wr is not None and float(np.max(np.abs(wr_new - wr))) <= 1e-9 * omega
        wr = wr_new
        if done:
            break
    e = evaluate(mg, omega, wr, cage_speed, ld.inner_load, fbw, psi, whirl_acceleration)
    loaded = ld.inner_load > 0.0
    drive = float(np.sum(e.cage_terms[loaded]))
    drag = -float(np.sum(e.cage_terms[~loaded]))
    return CageForceBalance(cage_speed=float(cage_speed), drive=drive, drag=drag,
                            residual=float(e.cage_eq), n_loaded=int(np.count_nonzero(loaded)),
                            roller_speed=wr)


def as_warm_start(guess: Any) -> np.ndarray | None:
    """(omega_r, omega_c) array from an array, a RollerSkiddingResult or a WhirlResult."""
    if guess is None:
        return None
    states = getattr(guess, "states", None)
    if states:
        guess = states[-1]
    if hasattr(guess, "roller_speed") and hasattr(guess, "cage_speed"):
        return np.append(np.asarray(guess.roller_speed, dtype=float), float(guess.cage_speed))
    arr = np.asarray(guess, dtype=float)
    if arr.ndim != 1 or arr.size < 4:
        raise InputError("x0", guess, "an array (omega_r..., omega_c) or a previous result")
    return arr


def solve_roller(
    bearing: Any,
    lubricant: Any,
    speed: float,
    radial_load: float,
    axial_load: float = 0.0,
    temperature: float = 313.15,
    *,
    whirl: Any = None,
    x0: np.ndarray | None = None,
    azimuth: np.ndarray | None = None,
    tol: float = 1e-9,
    max_iter: int = 60,
    **model_options: Any,
) -> Any:
    """Cage and roller speeds of a cylindrical roller bearing (paper 000 Z + 1 equations).

    Parameters
    ----------
    bearing : :class:`thermobearing.geometry.RollerBearing`.
    lubricant : :class:`thermobearing.lubricant.Lubricant`.
    speed : inner-ring speed omega [rad/s] (> 0; outer ring fixed).
    radial_load : F_r [N] (>= 0).
    axial_load : must be 0 (a cylindrical roller bearing carries no axial load here) [N].
    temperature : oil/contact temperature [K].
    whirl : None, or a :class:`thermobearing.skidding.whirl.Whirl` (paper 000 eqs. 1-4):
        the result is then a :class:`~thermobearing.skidding.whirl.WhirlResult` time series.
    x0 : warm start: an array (omega_r (Z,), omega_c) [rad/s], or a previous
        RollerSkiddingResult / WhirlResult (its last sample) of the same bearing.
    azimuth : (Z,) roller azimuths [rad] (default: a roller under the load).
    tol : tolerance on the residual norm scaled by the largest inner load [-].
    **model_options : passed to :func:`build_model` (viscosity, eyring_stress,
        limiting_shear_coefficient, traction_law, film_model, drag_model, pocket_clearance,
        cage_drag_torque).

    Returns
    -------
    RollerSkiddingResult (or WhirlResult when ``whirl`` is given).
    """
    check_positive("speed", speed)
    check_positive("radial_load", radial_load, allow_zero=True)
    check_finite("axial_load", axial_load)
    if axial_load != 0.0:
        raise InputError("axial_load", axial_load,
                         "0 for a cylindrical roller bearing (roller-rib thrust is not modelled "
                         "in the skidding solver; see thermobearing.rib)")
    x0 = as_warm_start(x0)
    model = build_model(bearing, lubricant, temperature, **model_options)
    if whirl is not None:
        from .whirl import solve_whirl

        return solve_whirl(model, speed, radial_load, whirl, x0=x0, tol=tol, max_iter=max_iter)
    return solve_model(model, speed, radial_load, azimuth=azimuth, x0=x0, tol=tol,
                       max_iter=max_iter)
