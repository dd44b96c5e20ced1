"""Raceway heat sources: traction (shear) heat and EHL rolling resistance of element contacts.

``raceway_traction``
    For every element-raceway contact of the kinematic state, the traction law is integrated
    over the Hertz ellipse (or the line contact) by :func:`thermobearing.contact_traction.
    integrate` -- the very function the skidding solver calls -- so the heat is the power of
    the traction forces and moments (force x relative sliding speed). This is the bounded
    form of paper 002 (seed 002_0add79adaca5495c.txt) eq. 11: eq. 11 writes the heat as
    (1/h) * integral of eta(T, p, gamma) dU^2 over the ellipse; with the viscosity taken
    literally at Hertzian pressure (Barus alpha = 2e-8 1/Pa at 1.5 GPa: e^30 ~ 1e13 times
    eta0) that integral is unbounded for any sliding, so here the shear stress comes from a
    traction law with a limiting shear stress (or a measured slip curve).
    States from the roller skidding solver carry the solver's own Couette forces (marked
    :class:`SolverContactForces`): paper 000 eq. 5's second term over the whole film (Hertz
    zone by the traction law AND the Newtonian inlet/outlet, eqs. 33-34); they are booked as
    they are (C V), since a Hertz-zone integral of the law leaves the inlet/outlet shear out
    (54.3 of 272.0 W at 5000 r/min, 200 N; 27.5 of 513.6 W at 3000 r/min, 8 kN: NU 214,
    ISO VG 46 at 320 K).
    Heat split between element and ring: Blok's partition for two surfaces moving through
    a flash-heated band at high Peclet number (Blok 1937/1963): each body takes a share
    proportional to e_k sqrt(|u_k|), e = sqrt(k rho c) the thermal effusivity and u_k the
    speed of surface k through the contact; the speed is floored at the Peclet-one speed
    2 kappa / b so a stationary surface still takes its conductive share.
``ehl_rolling_resistance``
    Hydrodynamic (Poiseuille) rolling force of the EHL inlet, the pressure term
    -integral (h/2) dp/dx dx of paper 000 (seed 000_3b5ca6eed61dd596.txt) eq. 5. Q_x, the
    rolling-direction pressure force on the element, is by parts
    Q_x = integral p dh/dx dx = -integral h dp/dx dx = 2 F_P, twice the Poiseuille shear force
    F_P that eq. 5 puts on EACH surface. Only the shear forces do work in the contact frame
    (the pressure acts along the normals of surfaces moving tangentially), so the heat is
    F_P (|u_element| + |u_race|) = Q_x u, rolling and sliding alike (u = entrainment speed).
    Q_x in closed form, the same three options as the roller skidding solver
    (``skidding/roller_fluid.py``, which builds U from the mean speed as here): skidding
    states carry the solver's own forces and are booked with them (the energy identity),
    race-control states and explicit options use these:

    - "dowson_higginson": paper 000 eq. 35, Q_x = 18.4 G^-0.3 U^0.7 E' R_x l with G = alpha E',
      U = eta0 u_m / (E' R_x), u_m = (|u_1| + |u_2|)/2 (the paper's eqs. 14 and 18 print U
      from the SUM of the surface speeds, 1.62 times the force; the mean is the
      Dowson-Higginson convention and agrees with the project's numerical EHL solution, see
      :func:`rolling_force_paper000`); the printed factor (1 - D/d_m) is the paper's
      normalisation by the roller radius (R_x,inner = (D/2)(1 - D/d_m)) and is carried by
      R_x here;
    - "rigid_isoviscous": Martin's rigid cylinder, Q_x = k_q eta0 U_sum l sqrt(R_x/h_0),
      h_0 = k_w eta0 U_sum R_x / w (coefficients from the Reynolds equation in
      ``roller_fluid.martin_coefficients``);
    - "regime_min" (default): the smaller of the two. The Dowson-Higginson fit is a
      heavy-load EHL result and exceeds the rigid-isoviscous force at light loads (e.g. the
      centrifugal-only outer contacts of unloaded rollers), where the contact is rigid.

    - "harris" (ball contacts only): the point-contact rolling force of
      :mod:`thermobearing.rolling_resistance` (Harris & Kotzalas' ball-race form) with its
      option ``reduction`` ("none", "thermal", "skf", "thermal_starvation") and the
      bearing-level factor ``supply_factor`` -- the function the ball skidding solver
      balances (``BallParameters.rolling_resistance``), so its heat closes the solver's
      energy identity. Without ``supply_factor`` the factor is the solver's (kinematic
      state extras ``rolling_resistance``) or else computed from the supply at the oil
      temperature.

    A roller skidding state carries the rolling forces its solver balanced (kinematic state
    extras ``raceway_rolling_force``, starved and clearance-film forms included); the source
    books those, F_P = Q_x/2 on each surface against the entrainment (the sign of the sum of
    the surface speeds), unless its options name a model.

    Eq. 35 is a line-contact formula; for ball contacts the length is the mean chord pi a / 2
    of the ellipse (an extrapolation, flagged by a ValidityWarning; "harris" avoids it).
    Both line forms are isothermal and fully flooded: at high speed inlet shear heating and
    starvation thin the film, and since the inlet force scales with the film (F_P ~ h_c /
    alpha) the rolling force too (SKF: the inlet's reverse flow "lowers the oil viscosity
    and reduces the film thickness and rolling friction", its phi_ish; Goksem & Hargreaves
    1978 computed the same fall of the rolling traction of a thermal EHL line contact --
    recalled, their numbers not re-read here). Option ``thermal_reduction`` (a
    ``film.THERMAL_FILM`` name: "none", the default ``DEFAULT_THERMAL_REDUCTION``,
    "gupta_1992", "wilson_sheu_1983") takes the film factor phi_T as an effective inlet
    viscosity: Dowson-Higginson's film and eq. 35's force both go as (eta0 u)^0.7, so
    h(eta_T) = phi_T h(eta0) gives eta_T = eta0 phi_T^(1/0.7); both closed forms are
    evaluated at eta_T, which multiplies eq. 35 by phi_T and Martin's rigid-isoviscous force
    (~ eta0^0.5) by phi_T^(5/7) (until 2026-11-24 both were multiplied by phi_T; the
    ball-contact module :mod:`thermobearing.rolling_resistance` reads phi_T the same way with
    Hamrock-Dowson's exponent 0.67). The inlet viscosity reading is this module's
    assumption: Gupta's fit is for the film of an EHL contact, and it is applied to the
    rigid (centrifugally seated) contacts through the same effective viscosity. phi_T of the
    no-load reference contact is taken at its own Hertz pressure. A skidding state's forces
    are booked as the solver carried them: the roller solver's default is this source's
    (``DEFAULT_THERMAL_REDUCTION``, the one name both read,
    :func:`thermobearing.skidding.roller_thermal.default_thermal_reduction`), and a scene
    that names ``[models.options.ehl_rolling_resistance] thermal_reduction`` has it passed
    to the solver by the simulation, so a skidding chain and a race-control chain apply the
    same reduction.

    Thermal reduction against the SKF model (measured 2026-11-24; NU 214, ISO VG 46 at
    50 degC, 10 kN, jet, race control, validation case crosscheck_global_friction): Gupta
    phi_T takes the rolling power from 49.7 / 167.9 / 591.6 / 1268.3 / 2206.0 / 3397.7 W to
    47.7 / 153.5 / 488.6 / 947.5 / 1496.7 / 2101.1 W at 1000 / 2000 / 4000 / 6000 / 8000 /
    10000 r/min, i.e. by 0.959 / 0.914 / 0.826 / 0.747 / 0.678 / 0.618, beside SKF's own
    inlet-shear factor phi_ish 0.962 / 0.913 / 0.811 / 0.719 / 0.639 / 0.571 (thermal loading
    L = beta eta0 u^2 / k_f of the inner contact 0.05-5.0, inside Gupta's range). What stays
    above SKF's rolling term (788 W at 8000 r/min) is mostly the no-load share, the
    centrifugally seated rollers' fully flooded rigid film (1141 -> 864 W at 8000 r/min),
    and SKF's replenishment factor phi_rs (0.74 there), which no local source models for a
    race-control roller state.

    Gap to the SKF model (measured, session 17; NU 214, ISO VG 46 at 50 degC, 8 kN, race
    control, per contact and per raceway: the inner race's loaded rollers, the outer race's
    loaded rollers and the 13 rollers outside the load zone pressed on the outer race by their
    centrifugal force): local rolling 43.2 / 321.1 / 1214.1 W at 1000 / 3000 / 6000 r/min
    against the SKF rolling term phi_ish phi_rs G_rr (nu n)^0.6 of 51.7 / 249.1 / 562.8 W
    (0.84 / 1.29 / 2.16; with eq. 35 on the sum of the speeds it was 67.3 / 477.3 / 1721.7 W,
    1.30 / 1.92 / 3.06). Against SKF's term without its inlet-shear and replenishment factors
    (55.8 / 323.9 / 981.7 W) the ratios are 0.77 / 0.99 / 1.24: the gap that remains at speed
    is what this source leaves out by default, inlet shear heating (``thermal_reduction``:
    Gupta phi_T brings 1214 to 908 W at 6000 r/min; 883 W when it multiplied both
    closed forms) and starvation, and the fully flooded
    rigid-isoviscous film of the centrifugally loaded rollers (4.6 / 70.9 / 401.3 W of the
    totals above), which SKF's G_rr ~ F_r^0.31 does not have. Nothing is tuned to SKF.
    At high speed the gap widens: CRB 50x75x16, 30000 r/min, 3 kN, MIL-PRF-23699 at
    80 degC, race control (session 20): 2831 W, of which 1980 W at the 24 outer contacts
    the centrifugal force alone seats (F_c = 83.7 N each), 1963 W with Gupta's phi_T
    (1484 W of it at those 24 contacts; 1835 W when phi_T multiplied both closed forms),
    against SKF's rolling term 651 W (1503 W without phi_ish phi_rs = 0.575 x 0.753).

    Loss class (load-dependent / load-independent, :mod:`thermobearing.losses`): Palmgren's
    split M = M0 + M1 takes M0 as the moment without external load and M1 as what the load
    adds. Per contact the EHL force of eq. 35 carries no load (W^0), but which contacts
    carry it does: the source was classed load-independent as a whole and grew 47 % from
    0.5 to 3 kN (CRB 50x75x16, 10000 r/min, jet, 80 degC, race control: 215.5 -> 317.0 W;
    the inner race, whose loaded zone widens, 52.9 -> 110.3 W). Each raceway is therefore
    split by :func:`no_load_contact_loads`: without external load only the centrifugal
    force seats the elements on the outer race, so "<race> rolling resistance, no load"
    (load-independent) is the force model at that load (same speeds, temperature, R_x, l;
    for an ellipse the chord scaled by (Q0/Q)^(1/3), for "harris" the pressure too; for a
    solver-carried force the regime_min line model), capped at the actual force, and
    "<race> rolling resistance, load" (load-dependent) the rest. Inner races have only the
    load share. Measured on that CRB: no-load 127.0 W at both loads (10000 r/min), 1979.5 W
    (30000 r/min); the load shares 88.5 -> 190.1 W and 382.5 -> 851.4 W
    (tests/unit/test_losses20_rolling_class.py). The sum, the forces and the force pairs
    are unchanged. Under a skidding state the no-load share still moves with the load
    through the orbital speed it reads (NU 214, 3000 r/min, roller solver: 10.9 W at
    2 kN, where the rollers slip, 26.1 W at 8 kN): the kinematics, not the contact load.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from ..contact_traction import ContactTraction, integrate, integrate_contact_set
from ..errors import InputError, UnknownNameError, ValidityWarning
from . import HEAT_SOURCES, ForcePair, HeatContext, HeatResult

_Q_NAMES = ("transverse_sliding_speed", "sliding_speed", "roll_speed", "tilt_speed",
            "spin_speed")


def _materials(bearing):
    elem = getattr(bearing, "ball_material", None) or getattr(bearing, "roller_material", None)
    ring = getattr(bearing, "ring_material", None)
    if elem is None or ring is None:
        raise InputError("bearing materials", (elem, ring),
                         "element and ring materials (density, specific heat, conductivity)")
    return elem, ring


def blok_partition(entrainment_speed, sliding_speed, semi_minor, element_material,
                   ring_material):
    """Share of contact heat that goes into the element (Blok's high-Peclet partition) [-].

    share_e = e_e sqrt(s_e) / (e_e sqrt(s_e) + e_r sqrt(s_r)), with e = sqrt(k rho c) and
    s_k = max(|u_k|, 2 kappa_k / b) the speed of surface k through the contact (u_element =
    u + V/2, u_race = u - V/2) floored at the Peclet-one speed. Equal materials and speeds
    give 1/2. Reference: Blok (1963), flash-temperature heat partition.

    Parameters
    ----------
    entrainment_speed, sliding_speed : u, V [m/s] (V = element minus race).
    semi_minor : b [m] (contact half-width in the rolling direction).
    element_material, ring_material : Materials with thermal_conductivity [W/mK],
        density [kg/m3], specific_heat [J/kgK].
    """
    u = np.asarray(entrainment_speed, float)
    v = np.asarray(sliding_speed, float)
    b = np.maximum(np.asarray(semi_minor, float), 1e-12)
    out = []
    for mat, speed in ((element_material, u + 0.5 * v), (ring_material, u - 0.5 * v)):
        k, rho, c = mat.thermal_conductivity, mat.density, mat.specific_heat
        kappa = k / (rho * c)
        s = np.maximum(np.abs(speed), 2.0 * kappa / b)
        out.append(math.sqrt(k * rho * c) * np.sqrt(s))
    return out[0] / (out[0] + out[1])


def _contact_temperature(ctx: HeatContext, cs) -> np.ndarray:
    if cs.temperature is not None:
        return cs.temperature
    # the two surfaces entering the contact: mean of the element and ring node temperatures
    t = 0.5 * (ctx.temperature("elements") + ctx.temperature(cs.ring_role))
    return np.full(cs.n_elements, t)


_SET_FIELDS = ("normal_load", "semi_major", "semi_minor", "sliding_speed",
               "transverse_sliding_speed", "spin_speed", "roll_speed", "tilt_speed",
               "deformed_radius")


@dataclass(frozen=True)
class SolverContactForces:
    """Marker ``law`` of a :class:`~thermobearing.state.PrecomputedTraction` that holds the
    contact forces a skidding solver balanced, computed by its own force model rather than
    by a quadrature of a traction law (its ``n_major``/``n_minor`` are 0 and mean nothing).

    The roller solver (:attr:`thermobearing.skidding.roller_result.RollerSkiddingResult.
    kinematic_state`, ``producer="roller_skidding"``) puts its Couette forces there: paper
    000 (seed 000_3b5ca6eed61dd596.txt) eq. 5's second term over the whole film, the Hertz
    zone by the traction law plus the Newtonian inlet and outlet (eqs. 33-34), which no
    Hertz-zone integral of the law reproduces. ``raceway_traction`` books such forces as they
    are (force x sliding speed), so its heat is the power of the forces that set the
    kinematics whatever its quadrature options.
    """

    producer: str


def _solver_forces(cs) -> bool:
    """Whether the contact set carries a solver's own contact forces
    (:class:`SolverContactForces`)."""
    return cs.traction is not None and isinstance(cs.traction.law, SolverContactForces)


def _integrate_sets(ctx: HeatContext, contacts, n_major: int, n_minor: int) -> list:
    """``integrate_contact_set`` of every contact set, at its own temperature (the
    solver's contact temperature where the set carries one, else the mean of the element
    and ring nodes). Sets of one contact kind and size, all with films (or all without) and
    at one temperature, are stacked into one ``contact_traction.integrate`` call: the
    integration is per contact, so the result is the same as set by set (bit for bit,
    tested), with one call's checks instead of one per raceway arc. Sets that carry the
    tractions their producer integrated with the same law and quadrature at a solver
    temperature (``ContactSet.traction``) are not integrated again; sets that carry a
    solver's own contact forces (:class:`SolverContactForces`) are taken as they are."""
    if contacts and any(_solver_forces(cs) for cs in contacts):
        others = [cs for cs in contacts if not _solver_forces(cs)]
        done = iter(_integrate_sets(ctx, others, n_major, n_minor) if others else ())
        return [cs.traction.result if _solver_forces(cs) else next(done) for cs in contacts]
    law = ctx.traction
    if contacts and all(cs.traction is not None and cs.temperature is not None
                        and cs.traction.matches(law, n_major, n_minor) for cs in contacts):
        # the producer of the state (the skidding solver) integrated this very law with
        # this quadrature at these contact fields and temperatures: its tractions are the
        # integral this source would compute
        return [cs.traction.result for cs in contacts]
    sets = [cs if cs.temperature is not None
            else cs.with_(temperature=_contact_temperature(ctx, cs)) for cs in contacts]
    z = sets[0].n_elements if sets else 0
    temps = [np.asarray(cs.temperature, dtype=float) for cs in sets]
    # one temperature for all: a film law then takes its viscosity from the same source
    # (e.g. the solver's isothermal table) in the stacked call as set by set
    one_temperature = all(t.size and np.all(t == temps[0].flat[0]) for t in temps)
    if len(sets) < 2 or not one_temperature \
            or len({(cs.kind, cs.film_thickness is None, cs.n_elements) for cs in sets}) > 1:
        return [integrate_contact_set(ctx.traction, cs, n_major=n_major, n_minor=n_minor)
                for cs in sets]

    def stack(name):
        vals = [getattr(cs, name) for cs in sets]
        if all(type(v) is np.ndarray and v.shape == (z,) for v in vals):
            return np.array(vals, dtype=float)
        return np.array([np.broadcast_to(np.asarray(v, dtype=float), (z,)) for v in vals])

    film = None if sets[0].film_thickness is None else stack("film_thickness")
    r = integrate(ctx.traction, **{f: stack(f) for f in _SET_FIELDS},
                  film_thickness=film, temperature=stack("temperature"), kind=sets[0].kind,
                  n_major=n_major, n_minor=n_minor)
    return [ContactTraction(**{f: getattr(r, f)[k] for f in _RESULT_FIELDS})
            for k in range(len(sets))]


_RESULT_FIELDS = ("transverse_force", "rolling_force", "moment_transverse",
                  "moment_rolling", "moment_normal", "heat")


@HEAT_SOURCES.register(
    "raceway_traction",
    references=["gao2022_overskidding", "johnson1985", "harris_kotzalas2007",
                "blok1963_flash_temperature"],
    parameters={"n_major": "-", "n_minor": "-"},
    limits={"n_major": "[2, 256]", "n_minor": "[1, 256]"},
    validity="any kinematic state with contact sets; traction law from the context",
)
def raceway_traction(ctx: HeatContext) -> HeatResult:
    """Shear heat of the element-raceway contacts from the traction law (bounded paper 002 eq. 11).

    Options (``ctx.options["raceway_traction"]``): ``n_major`` (16), ``n_minor`` (8)
    quadrature nodes. Needs ``ctx.traction``.
    """
    name = "raceway_traction"
    if ctx.traction is None:
        raise InputError(f"heat source {name!r} traction", None,
                         "a traction law in the heat context (traction.make_traction_law)")
    n_major = int(ctx.option(name, "n_major", 16))
    n_minor = int(ctx.option(name, "n_minor", 8))
    elem_mat, ring_mat = _materials(ctx.bearing)
    roles = {"elements": 0.0, "inner_ring": 0.0, "outer_ring": 0.0}
    components: dict[str, float] = {}
    split: dict[str, dict[str, float]] = {}
    pairs = []
    forces = {}
    contacts = ctx.kinematics.contacts
    for cs, r in zip(contacts, _integrate_sets(ctx, contacts, n_major, n_minor), strict=True):
        share = blok_partition(cs.entrainment_speed, cs.sliding_speed, cs.semi_minor,
                               elem_mat, ring_mat)
        heat = r.heat
        to_elem = float(np.sum(share * heat))
        to_ring = float(np.sum((1.0 - share) * heat))
        roles["elements"] += to_elem
        roles[cs.ring_role] += to_ring
        components[f"{cs.race} contact"] = float(np.sum(heat))
        split[f"{cs.race} contact"] = {"elements": to_elem, cs.ring_role: to_ring}
        q = np.stack([getattr(cs, n) for n in _Q_NAMES], axis=-1)
        gen = r.generalized_force
        pairs.append(ForcePair(f"{cs.race} contact traction", gen, q))
        forces[f"{cs.race}_generalized_force"] = gen
    return HeatResult(
        source=name, power_by_role=roles, components=components,
        loss_class=dict.fromkeys(components, "load_dependent"),
        forces=forces, force_pairs=tuple(pairs), component_roles=split)


def rolling_force_paper000(entrainment_speed, viscosity, pressure_viscosity,
                           effective_modulus, reduced_radius_x, length):
    """EHL rolling force Q_x [N], paper 000 eq. 35 (Dowson-Higginson form), dimensional.

    Q_x = 18.4 G^-0.3 U^0.7 E' R_x l,  G = alpha E',  U = eta0 u_m / (E' R_x),
    u_m = (|u_1| + |u_2|)/2 the mean (entrainment) speed of the two surfaces.

    Parameters
    ----------
    entrainment_speed : u_m = (|u_1| + |u_2|)/2 [m/s];
    viscosity : eta0 at the inlet [Pa s]; pressure_viscosity : alpha [1/Pa];
    effective_modulus : E' [Pa] (Hamrock convention); reduced_radius_x : R_x [m];
    length : effective contact length l [m] (the force is per contact: Q_x/l is the force
        per unit length of the correlation).

    Reference: seed 000_3b5ca6eed61dd596.txt eq. 35; the factor (1 - D/d_m) printed there is
    carried by R_x (module docstring). Validity: fully flooded, isothermal EHL line contacts.

    Speed: paper 000 builds its U-bar (eq. 18) from U_ij of eq. 14, which is printed as the
    SUM of the surface speeds, and this function took the sum until session 17. The
    Dowson-Higginson groups are defined with the mean speed u_m (U = eta0 u_m/(E' R), as in
    the film formulas of :mod:`thermobearing.film`); the sum makes Q_x 2^0.7 = 1.62 times
    larger. Hand check against the project's own numerical EHL solution of the same
    isothermal Newtonian line contact (:func:`thermobearing.ehl.solve_line_contact`,
    Q_x = int p dh/dx dx; Barus alpha, incompressible), E' = 2.28e11 Pa, R_x = 5.633 mm,
    l = 13 mm, alpha = 2.18e-8 1/Pa (the NU 214 inner contact, ISO VG 46 at 320 K):

    ============================  ======  ======  =========  ==========  =========
    Q [N], u_m [m/s], eta0 [Pa s]  M [-]   L [-]   numerical  mean (this)  sum (old)
    ============================  ======  ======  =========  ==========  =========
    2412, 7.52, 0.0292             7.85    21.3    3.85 N     3.46 N      5.62 N
    1000, 7.5, 0.029               3.25    21.3    4.26 N     3.46 N      5.62 N
    8000, 7.5, 0.029               26.0    21.3    4.51 N     3.46 N      5.62 N
    2412, 2.0, 0.029               15.2    15.3    1.49 N     1.37 N      2.23 N
    2412, 20, 0.029                4.81    27.2    9.69 N     6.87 N      11.16 N
    ============================  ======  ======  =========  ==========  =========

    (0.70-1.17 times the numerical force with the mean speed over M 0.65-26, L 15-27;
    1.14-1.91 times with the sum; with the Dowson-Higginson compressibility of paper 000
    eq. 10 the numerical force of the first row is 3.14 N.) In the rigid regime (M < 0.2)
    the numerical force agrees with :func:`rolling_force_rigid_isoviscous` built on the
    sum of the speeds to 5-9 %: Martin's k_w = 2.448 is written for the sum, so both
    closed forms now describe the same film. The original Dowson-Higginson / Harris (1966)
    text of the 18.4 correlation was not available here (searched): the speed convention
    rests on this hand check and on the mean-speed groups of every other Dowson-Higginson
    formula.
    """
    u = np.abs(np.asarray(entrainment_speed, float))
    e = float(effective_modulus)
    rx = np.asarray(reduced_radius_x, float)
    big_u = np.asarray(viscosity, float) * u / (e * rx)
    g = np.asarray(pressure_viscosity, float) * e
    return 18.4 * g ** -0.3 * big_u ** 0.7 * e * rx * np.asarray(length, float)


def rolling_force_rigid_isoviscous(sum_speed, viscosity, load, reduced_radius_x, length):
    """Rigid-isoviscous (Martin) rolling force Q_x [N] of a cylinder, fully flooded.

    h_0 = k_w eta0 U R / w,  Q_x = k_q eta0 U l sqrt(R / h_0), w = load / l, U = sum speed;
    k_w = 2.448 (Martin 1916) and k_q from the Reynolds equation with Reynolds outlet
    conditions (``skidding.roller_fluid.martin_coefficients``). Hamrock 2004.
    """
    from ..skidding.roller_fluid import martin_coefficients

    k_w, k_q, _, _ = martin_coefficients()
    u = np.abs(np.asarray(sum_speed, float))
    length = np.asarray(length, float)
    q = np.asarray(load, float)
    w = np.divide(q, length, out=np.zeros(np.broadcast(q, length).shape), where=length > 0)
    rx = np.asarray(reduced_radius_x, float)
    eta = np.asarray(viscosity, float)
    w_safe = np.where(w > 0, w, 1.0)
    u_safe = np.where(u > 0, u, 1.0)
    h0 = k_w * eta * u_safe * rx / w_safe
    return np.where((w > 0) & (u > 0), k_q * eta * u * length * np.sqrt(rx / h0), 0.0)


ROLLING_FORCE_MODELS = ("regime_min", "dowson_higginson", "rigid_isoviscous")
#: exponent of eta0 u in Dowson-Higginson's film and in eq. 35's force (h, Q_x ~ (eta0 u)^0.7):
#: a film factor phi_T is the inlet viscosity factor phi_T^(1/0.7) (module docstring)
DH_VISCOSITY_EXPONENT = 0.7
#: ``thermal_reduction`` of the line-contact models when the options name none, and of the
#: roller skidding solver's rolling force (``skidding.roller_thermal.default_thermal_reduction``)
DEFAULT_THERMAL_REDUCTION = "gupta_1992"


def _thermal_factor(model, ctx, cs, temp, eta, max_pressure):
    """Film thermal-reduction factor phi_T of ``film.THERMAL_FILM[model]`` per contact [-]
    at the Hertz pressure ``max_pressure`` [Pa] (the contact's, or its no-load contact's)."""
    from ..film import THERMAL_FILM

    lub = ctx.lubricant
    beta = -(np.log(np.asarray(lub.dynamic_viscosity(temp + 0.5), float))
             - np.log(np.asarray(lub.dynamic_viscosity(temp - 0.5), float)))
    k_oil = np.asarray(lub.thermal_conductivity(temp), float)
    phi = THERMAL_FILM.get(model)(
        entrainment_speed=cs.entrainment_speed, dynamic_viscosity=eta,
        temperature_viscosity_coefficient=beta, thermal_conductivity=k_oil,
        slide_to_roll=cs.slide_to_roll, max_pressure=max_pressure,
        effective_modulus=ctx.bearing.effective_modulus)
    return np.asarray(phi, float)


@HEAT_SOURCES.register(
    "ehl_rolling_resistance",
    references=["li2018_nu214_skidding", "blok1963_flash_temperature", "harris_kotzalas2007",
                "gupta1992", "skf_catalogue_friction"],
    parameters={"thermal_reduction": "-", "rolling_force": "-", "reduction": "-",
                "supply_factor": "-"},
    validity="fully flooded EHL; line contacts with Gupta's (1992) inlet-heating reduction "
             "by default (thermal_reduction = 'none': isothermal; a roller skidding state "
             "books its solver's force), ball contacts by the point-contact form "
             "(rolling_force = 'harris') or the mean-chord extension",
)
def ehl_rolling_resistance(ctx: HeatContext) -> HeatResult:
    """EHL rolling resistance (Poiseuille inlet force) of the raceway contacts, paper 000 eq. 5/35.

    Option ``rolling_force``: "regime_min" (default), "dowson_higginson", "rigid_isoviscous"
    (module docstring).

    The inlet viscosity and pressure-viscosity coefficient are taken at the contact
    temperature (contact set's, else the mean of element and ring nodes). Loaded contacts
    only (Q > 0). Needs ``reduced_radius_x`` in the contact sets, else it is computed from
    ``bearing.curvature(race, contact_angle)``. Option ``thermal_reduction``: a
    ``film.THERMAL_FILM`` name (default ``DEFAULT_THERMAL_REDUCTION`` for the line models,
    "none" for "harris", which reduces through its option ``reduction``), applied as the
    inlet viscosity eta0 phi_T^(1/0.7) (module docstring); the temperature-viscosity
    coefficient it needs is -d ln(eta)/dT of the lubricant by a central difference (+-0.5 K).

    Each raceway's power is split into its no-load part (load-independent, Palmgren's M0
    sense) and the rest (load-dependent, M1) by :func:`no_load_contact_loads` (module
    docstring): components "<race> rolling resistance, no load" and "<race> rolling
    resistance, load"; the sum is the raceway's rolling-resistance power.
    """
    name = "ehl_rolling_resistance"
    from ..film import THERMAL_FILM

    model = str(ctx.option(name, "rolling_force", "regime_min"))
    if model not in ROLLING_FORCE_MODELS + ("harris",):
        raise UnknownNameError(f"options[{name}].rolling_force", model,
                               ROLLING_FORCE_MODELS + ("harris",))
    # "harris" takes its reductions through the option ``reduction``
    thermal = str(ctx.option(name, "thermal_reduction",
                             "none" if model == "harris" else DEFAULT_THERMAL_REDUCTION))
    THERMAL_FILM.entry(thermal)  # unknown names raise, listing the known ones
    point = _point_contact_forces(ctx, name, model, thermal)
    carried = _carried_rolling_forces(ctx, name)
    bearing = ctx.bearing
    elem_mat, ring_mat = _materials(bearing)
    e_mod = bearing.effective_modulus
    roles = {"elements": 0.0, "inner_ring": 0.0, "outer_ring": 0.0}
    components: dict[str, float] = {}
    classes: dict[str, str] = {}
    split: dict[str, dict[str, float]] = {}
    pairs = []
    forces = {}
    no_load_q = no_load_contact_loads(bearing, ctx.kinematics)
    for cs, q0 in zip(ctx.kinematics.contacts, no_load_q, strict=True):
        loaded = cs.normal_load > 0
        temp = _contact_temperature(ctx, cs)
        if cs.reduced_radius_x is not None:
            rx = cs.reduced_radius_x
        else:
            race = cs.race.split("_")[0]
            rx = np.asarray(bearing.curvature(race, cs.contact_angle)[0], float) * np.ones(
                cs.n_elements)
        eta = np.asarray(ctx.lubricant.dynamic_viscosity(temp), float)
        alpha = np.asarray(ctx.lubricant.pressure_viscosity_coefficient(temp), float)
        u_e = cs.entrainment_speed + 0.5 * cs.sliding_speed
        u_r = cs.entrainment_speed - 0.5 * cs.sliding_speed
        usum = np.abs(u_e) + np.abs(u_r)
        q = np.asarray(cs.normal_load, float)
        own_force = carried is not None and cs.race in carried
        ratio = np.divide(q0, q, out=np.zeros_like(q), where=q > 0)
        eta_load = eta_no_load = eta
        if thermal != "none" and point is None and not own_force:
            # inlet shear heating as an effective inlet viscosity eta0 phi_T^(1/0.7) (module
            # docstring); the no-load contact's phi_T at its own Hertz pressure (line contact
            # p_h ~ Q^(1/2), ellipse Q^(1/3)), so the no-load share does not move with the load
            p_h = np.asarray(cs.max_pressure, float) * np.ones(cs.n_elements)
            p_h0 = p_h * (np.sqrt(ratio) if cs.kind == "line" else np.cbrt(ratio))
            inv = 1.0 / DH_VISCOSITY_EXPONENT
            eta_load = eta * _thermal_factor(thermal, ctx, cs, temp, eta, p_h) ** inv
            eta_no_load = eta * _thermal_factor(thermal, ctx, cs, temp, eta, p_h0) ** inv
        if point is not None:
            length = None
        elif cs.kind == "line":
            length = 2.0 * cs.semi_major
        else:
            if np.any(loaded):
                warnings.warn(
                    "ehl_rolling_resistance: paper 000 eq. 35 is a line-contact formula; "
                    "ball contacts use the ellipse's mean chord pi*a/2 as length",
                    ValidityWarning, stacklevel=2)
            length = 0.5 * math.pi * cs.semi_major

        def line_force(load, chord, _m=model, _u=usum, _eta=eta, _alpha=alpha, _rx=rx):
            # Dowson-Higginson with the mean speed, Martin with the sum (their conventions)
            q_dh = rolling_force_paper000(0.5 * _u, _eta, _alpha, e_mod, _rx, chord)
            if _m == "dowson_higginson":
                return q_dh
            q_ri = rolling_force_rigid_isoviscous(_u, _eta, load, _rx, chord)
            return q_ri if _m == "rigid_isoviscous" else np.minimum(q_dh, q_ri)

        if own_force:
            # the skidding solver's own rolling force of this raceway (paper 000 eq. 5
            # Poiseuille term), starved and clearance-film forms included
            fr = np.array(np.broadcast_to(np.asarray(carried[cs.race], float),
                                          (cs.n_elements,)))
            chord = 2.0 * cs.semi_major if cs.kind == "line" else 0.5 * math.pi * cs.semi_major
            fr0 = np.where(q0 > 0, line_force(q0, chord, _m="regime_min"), 0.0)
        elif point is not None:
            fr = np.where(loaded, point(cs, temp, rx), 0.0)
            fr0 = np.where(q0 > 0, point(cs.with_(
                normal_load=q0, max_pressure=np.asarray(cs.max_pressure, float)
                * np.cbrt(ratio)), temp, rx), 0.0)
        else:
            fr = np.where(loaded, line_force(q, length, _eta=eta_load), 0.0)
            # a line contact's length is the roller's; an ellipse's chord goes as Q^(1/3)
            chord0 = length if cs.kind == "line" else length * np.cbrt(ratio)
            fr0 = np.where(q0 > 0, line_force(q0, chord0, _eta=eta_no_load), 0.0)
        fr0 = np.minimum(fr0, fr)
        # Poiseuille shear F_P = Q_x/2 on each surface against the entrainment (the
        # direction of the inlet pressure gradient), as both skidding solvers balance it:
        # its work is F_P |u_e + u_r| (equal to F_P (|u_e| + |u_r|) unless a surface runs
        # backwards, where the per-surface reading jumped by Q_x)
        f_p = 0.5 * fr
        sign = np.where(cs.entrainment_speed >= 0.0, 1.0, -1.0)
        share = blok_partition(cs.entrainment_speed, cs.sliding_speed, cs.semi_minor,
                               elem_mat, ring_mat)
        speed = np.abs(u_e + u_r)
        total = f_p * speed
        base = 0.5 * fr0 * speed
        shares = (("no load", base, "load_independent"), ("load", total - base, "load_dependent"))
        # an inner race carries nothing without external load: no no-load component
        for label, part, cls in shares[0 if cs.race.split("_")[0] == "outer" else 1:]:
            comp = f"{cs.race} rolling resistance, {label}"
            to_elem = float(np.sum(share * part))
            to_ring = float(np.sum((1.0 - share) * part))
            roles["elements"] += to_elem
            roles[cs.ring_role] += to_ring
            components[comp] = float(np.sum(part))
            classes[comp] = cls
            split[comp] = {"elements": to_elem, cs.ring_role: to_ring}
        pairs.append(ForcePair(f"{cs.race} film on element", -f_p * sign, u_e))
        pairs.append(ForcePair(f"{cs.race} film on race", -f_p * sign, u_r))
        forces[f"{cs.race}_rolling_force"] = fr
    return HeatResult(
        source=name, power_by_role=roles, components=components, loss_class=classes,
        forces=forces, force_pairs=tuple(pairs), component_roles=split)


def no_load_contact_loads(bearing, kinematics) -> list[np.ndarray]:
    """Per contact set, the normal load [N] its contacts would carry without external
    load (the reference of the no-load share of the rolling resistance, module docstring).

    Without external load the rings still press nothing on the elements, but the
    centrifugal force F_c = m (d_m/2) omega_m^2 seats each element on the outer race
    (Harris & Kotzalas 2007, the unloaded elements of a radial bearing): an outer contact
    set takes F_c shared among the element's outer sets (two for a four-point ball), an
    inner one 0. Capped at the contact's actual load. m the ball or roller mass, omega_m
    each element's orbital speed [rad/s] from the kinematic state.
    """
    mass = getattr(bearing, "ball_mass", None) or getattr(bearing, "roller_mass", None)
    contacts = kinematics.contacts
    n_outer = sum(1 for cs in contacts if cs.race.split("_")[0] == "outer")
    out = []
    for cs in contacts:
        q = np.asarray(cs.normal_load, float) * np.ones(cs.n_elements)
        if cs.race.split("_")[0] != "outer" or not mass or n_outer == 0:
            out.append(np.zeros(cs.n_elements))
            continue
        omega = np.broadcast_to(np.asarray(kinematics.orbital_speed, float), (cs.n_elements,))
        f_c = float(mass) * 0.5 * bearing.pitch_diameter * omega ** 2 / n_outer
        out.append(np.minimum(np.where(q > 0, f_c, 0.0), q))
    return out


def _carried_rolling_forces(ctx: HeatContext, name: str):
    """The rolling forces Q_x [N] a skidding solver balanced (kinematic state extras
    ``raceway_rolling_force``: race name -> (Z,)), or None.

    Used unless the source's options name a model (``rolling_force``, ``thermal_reduction``,
    ``reduction``, ``supply_factor``): the roller solver's Q_x is paper 000 eq. 35 or its
    rigid-isoviscous form (the smaller, ``regime_min``), starved by the inlet oil layer when
    one is given, with the clearance film's rolling force at unloaded rollers; re-computing
    it here from the flooded formulas would book another force than the one the roller
    moment and cage balances (eqs. 28/31, 32) contain. An option asks for a different
    force on purpose: the heat then no longer adds up to the solver's shaft power."""
    carried = ctx.kinematics.extras.get("raceway_rolling_force")
    if carried is None:
        return None
    given = ctx.options.get(name) or {}
    named = [k for k in ("rolling_force", "thermal_reduction", "reduction", "supply_factor")
             if k in given]
    solver = ctx.kinematics.extras.get("raceway_rolling_thermal_reduction")
    if named == ["thermal_reduction"] and str(given["thermal_reduction"]) == solver:
        # the scene's reduction is the one the solver applied to the force it carries
        return carried
    return None if named else carried


def _point_contact_forces(ctx: HeatContext, name: str, model: str, thermal: str):
    """For ``rolling_force = "harris"``: a function (contact set, temperatures (Z,), R_x (Z,))
    -> F_R (Z,) [N] by :func:`thermobearing.rolling_resistance.rolling_force_array` (the
    ball solver's code path), its parameters built per distinct contact temperature by
    ``rolling_resistance.lubricant_kernel_parameters``; None for the line-contact models."""
    if model != "harris":
        return None
    from .. import rolling_resistance as rr

    if thermal != "none":
        raise InputError(f"options[{name}].thermal_reduction", thermal,
                         "'none' with rolling_force = 'harris' (its option 'reduction' "
                         f"takes one of {', '.join(rr.REDUCTIONS)})")
    reduction = str(ctx.option(name, "reduction", "none"))
    if reduction not in rr.REDUCTIONS:
        raise UnknownNameError(f"options[{name}].reduction", reduction, rr.REDUCTIONS)
    factor = ctx.option(name, "supply_factor", None)
    if factor is None:
        carried = ctx.kinematics.extras.get("rolling_resistance")
        if carried is not None:
            factor = float(carried[rr.K_FACTOR])
        else:
            t_oil = ctx.temperature("oil") if "oil" in ctx.temperatures else \
                ctx.temperature("elements")
            nu = float(ctx.lubricant.dynamic_viscosity(t_oil)) / float(
                ctx.lubricant.density(t_oil))
            factor = rr.supply_factor(reduction, ctx.bearing, abs(
                ctx.operating.inner_speed - ctx.operating.outer_speed), nu,
                ctx.supply.method)
    factor = float(factor)
    e_mod = ctx.bearing.effective_modulus
    params: dict[float, np.ndarray] = {}

    def forces(cs, temp, rx):
        if cs.kind == "line":
            raise InputError(f"options[{name}].rolling_force", model,
                             "a line-contact model (regime_min, dowson_higginson, "
                             "rigid_isoviscous) for the line contacts of a roller bearing")
        if cs.reduced_radius_y is not None:
            ry = np.asarray(cs.reduced_radius_y, float)
        else:
            race = cs.race.split("_")[0]
            ry = np.asarray(ctx.bearing.curvature(race, cs.contact_angle)[1], float)
        out = np.zeros(cs.n_elements)
        temp = np.broadcast_to(np.asarray(temp, float), (cs.n_elements,))
        for t in np.unique(temp):
            kp = params.get(float(t))
            if kp is None:
                kp = params[float(t)] = rr.lubricant_kernel_parameters(
                    model, reduction, ctx.lubricant, float(t), e_mod, factor)
            sel = temp == t
            out[sel] = rr.rolling_force_array(
                cs.entrainment_speed, cs.sliding_speed, cs.normal_load, cs.max_pressure,
                rx, ry * np.ones(cs.n_elements), kp)[sel]
        return out

    return forces
