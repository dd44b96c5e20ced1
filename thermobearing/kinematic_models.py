"""How element and cage speeds are found: race control or the skidding solver.

Registry ``kinematics`` (scenes choose with ``[models] kinematics = "..."``):

``race_control``
    quasi-static load distribution (``loads.py``) and race-control kinematics (Jones; no
    slip at the contact centres, ``state.race_control_state``): cheap, no cage dynamics.
``skidding``
    the skidding / over-skidding solver (``skidding.solve``): cage and element speeds
    from the traction / drag balance, warm-started from the previous operating point.

The contact temperature the kinematics are solved at (:func:`contact_temperature`) is the
inlet oil temperature of the raceway contacts: the mean of the two contacts' inlet
temperatures, each the mean of the element node and that contact's ring node, the same
convention as the heat sources (``heat_sources.raceway``). The solvers take one temperature
for both raceways (the roller model builds one viscosity and one pressure-viscosity
coefficient per solve, the ball solver one traction law).

A schedule step with both rings at rest (a stop in a rig protocol, when the bearing cools)
needs no solver: every registered model returns :func:`standstill` there.

Both return a :class:`KinematicsResult` whose ``state`` is the
:class:`~thermobearing.state.KinematicState` the heat sources read and whose
``heat_options`` are the :class:`~thermobearing.heat_sources.HeatContext` options that
match the force models the kinematics used (so heat = force x sliding speed).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .errors import InputError, ValidityWarning
from .registry import Registry
from .state import KinematicState, OilSupply, OperatingPoint


@dataclass(frozen=True)
class KinematicsResult:
    """Kinematic state of one bearing at one operating point.

    Attributes
    ----------
    state : the KinematicState for the heat sources.
    cage_speed_ratio : CSR = omega_cage / omega_inner [-].
    theoretical_cage_speed_ratio : epicyclic CSR at the quasi-static contact angles [-].
    converged, residual_norm, iterations : solver diagnostics (race control: exact).
    heat_options : HeatContext options matching the force models used.
    traction : the raceway traction law the kinematics used (the heat sources use it too).
    raw : the solver's own result object (warm start of the next solve).
    """

    state: KinematicState
    cage_speed_ratio: float
    theoretical_cage_speed_ratio: float
    converged: bool = True
    residual_norm: float = 0.0
    iterations: int = 0
    heat_options: Mapping[str, Mapping[str, Any]] = field(default_factory=dict)
    traction: Any = None
    raw: Any = None

    @property
    def over_skid(self) -> float:
        """CSR / CSR_th - 1 [-] (positive: over-skidding, negative: skidding)."""
        return self.cage_speed_ratio / self.theoretical_cage_speed_ratio - 1.0


def contact_temperature(temperatures: Mapping[str, float]) -> float:
    """Temperature [K] of the oil entering the raceway contacts, at which the kinematics are
    solved and their re-solve test reads the viscosity.

    T_c = (T_inner_ring + T_outer_ring + 2 T_elements) / 4, the mean of the two contacts'
    inlet temperatures (T_elements + T_ring) / 2: the oil entering a contact lies between
    the two surfaces that drag it in, the element and its ring, so it takes the mean of
    their node temperatures -- the convention of the heat sources
    (``heat_sources.raceway._contact_temperature``), so that kinematics and heat see the
    same oil. The rings alone would leave a hot element out: on a fast run-up the rollers
    heat within seconds while the rings lag, and the contact oil would stay as viscous as
    the rings' while the element node runs away.

    ``temperatures``: node temperatures [K] by role (``"inner_ring"``, ``"outer_ring"``,
    ``"elements"``, others ignored).
    """
    missing = [r for r in ("inner_ring", "outer_ring", "elements") if r not in temperatures]
    if missing:
        raise InputError("temperatures", sorted(temperatures),
                         "a temperature for every contact role (inner_ring, outer_ring, "
                         f"elements); missing: {', '.join(missing)}")
    return 0.25 * (float(temperatures["inner_ring"]) + float(temperatures["outer_ring"])
                   + 2.0 * float(temperatures["elements"]))


def default_traction(bearing: Any, lubricant: Any, temperature: float, params: Any = None
                     ) -> Any:
    """The raceway traction law of the skidding solvers, at the contact temperature [K]:
    Eyring with a limiting shear stress for balls (``skidding.ball_models.make_traction``),
    the roller solver's law for rollers (``skidding.roller.default_traction_law``)."""
    if hasattr(bearing, "ball_diameter"):
        from .skidding.ball_models import BallParameters, make_traction

        return make_traction(lubricant, params or BallParameters(), temperature)
    from .skidding.roller import default_traction_law

    return default_traction_law(lubricant)


def _ball_heat_options(bearing: Any, supply: OilSupply, speed: float, params: Any
                       ) -> dict[str, Any]:
    from .skidding.ball_models import BallParameters, heat_context_options

    opts = heat_context_options(bearing, supply, speed, params or BallParameters())
    if "ball_pocket" in opts and "pocket_friction" not in opts:
        opts["pocket_friction"] = opts.pop("ball_pocket")
    return opts


def at_rest(operating: OperatingPoint) -> bool:
    """Both rings stopped (inner and outer speed exactly 0)."""
    return operating.inner_speed == 0.0 and operating.outer_speed == 0.0


def standstill(bearing: Any, operating: OperatingPoint) -> KinematicsResult:
    """The bearing at rest under its loads: nothing rolls or slides, so no heat source
    dissipates anything (:func:`thermobearing.heat_sources.evaluate_recorded` books 0 W
    for every source of a ``"standstill"`` state) while the network keeps cooling.

    The contacts are those of the quasi-static load distribution at zero speed
    (``state.race_control_state`` without a lubricant: Hertz loads and pressures for the
    stress check, no film, all speeds 0); with no load at all there are none. The cage
    speed ratio is undefined at rest: NaN (the kinematics table leaves it empty, the
    operating checks flag nothing); the theoretical ratio is the bearing's nominal one."""
    from .state import race_control_state

    theo = float(bearing.theoretical_cage_speed_ratio())
    z = bearing.n_elements
    if operating.radial_load == 0.0 and operating.axial_load == 0.0:
        import numpy as np

        state = KinematicState(inner_speed=0.0, outer_speed=0.0, cage_speed=0.0,
                               orbital_speed=np.zeros(z), element_spin=np.zeros(z),
                               contacts=(), origin="standstill")
    else:
        state = dataclasses.replace(race_control_state(bearing, operating), origin="standstill")
    return KinematicsResult(state=state, cage_speed_ratio=math.nan,
                            theoretical_cage_speed_ratio=theo)


KINEMATICS: Registry[Any] = Registry(
    "kinematics", "element and cage speeds: race control or the skidding solver")

#: Drag models whose film is an interpolation table filled as the solve asks for nodes
#: (``"numerical_tehl"``, registered by :mod:`thermobearing.ehl.coupling`): each registers
#: here, under its ``ROLLER_DRAG`` name, the driver that runs the skidding solve with it.
#: A driver has the signature of :func:`thermobearing.skidding.solve` without
#: ``drag_model`` (it sets its own); the ``skidding`` kinematics hands the solve to it
#: whenever the options name its drag model, so that a new table-backed film needs no
#: edit here.
TABLE_FILM_DRIVERS: Registry[Callable[..., Any]] = Registry(
    "table_film_driver", "skidding solves of the drag models on a tabulated numerical film")


#: packages whose import registers numerical drag models (and their table-film drivers):
#: imported when a drag model is named that no imported module has registered yet
DRAG_MODEL_PROVIDERS = ("thermobearing.ehl",)


def table_film_driver(drag_model: Any) -> Callable[..., Any] | None:
    """The driver registered in :data:`TABLE_FILM_DRIVERS` for ``drag_model``, or None
    (no drag model named, or one that the plain :func:`thermobearing.skidding.solve`
    runs). A name no roller drag model has registered yet imports
    :data:`DRAG_MODEL_PROVIDERS` first (a scene imports them when it names its film; a
    direct call may not have)."""
    if not isinstance(drag_model, str):
        return None
    from .skidding.roller_fluid import ROLLER_DRAG

    if drag_model not in ROLLER_DRAG:
        import importlib

        for module in DRAG_MODEL_PROVIDERS:
            importlib.import_module(module)
    if drag_model in TABLE_FILM_DRIVERS:
        return TABLE_FILM_DRIVERS.get(drag_model)
    return None


@KINEMATICS.register(
    "race_control",
    references=["harris_kotzalas2007", "johnson1985"],
    summary="Quasi-static load distribution with race-control kinematics (no cage slip).",
)
def race_control(bearing: Any, lubricant: Any, operating: OperatingPoint, *,
                 contact_temperature: float, oil_temperature: float, supply: OilSupply,
                 guess: KinematicsResult | None = None, options: Mapping[str, Any] | None = None
                 ) -> KinematicsResult:
    """Race-control kinematics (``state.race_control_state``, outer-race control by default)."""
    if at_rest(operating):
        return standstill(bearing, operating)
    from .state import race_control_state

    opts = dict(options or {})
    params = opts.get("params")
    state = race_control_state(bearing, operating, control=opts.get("control", "outer_race"),
                               lubricant=lubricant, temperature=contact_temperature)
    csr = state.cage_speed_ratio
    theo = bearing.theoretical_cage_speed_ratio()
    heat_options = (_ball_heat_options(bearing, supply, operating.inner_speed, params)
                    if hasattr(bearing, "ball_diameter") else {})
    return KinematicsResult(state=state, cage_speed_ratio=csr,
                            theoretical_cage_speed_ratio=float(theo), raw=state,
                            heat_options=heat_options,
                            traction=default_traction(bearing, lubricant, contact_temperature,
                                                      params))


@KINEMATICS.register(
    "skidding",
    references=["gao2022_overskidding", "li2018_nu214_skidding", "harris_kotzalas2007"],
    summary="Skidding / over-skidding solver: cage and element speeds from the force balance.",
)
def skidding(bearing: Any, lubricant: Any, operating: OperatingPoint, *,
             contact_temperature: float, oil_temperature: float, supply: OilSupply,
             guess: KinematicsResult | None = None, options: Mapping[str, Any] | None = None
             ) -> KinematicsResult:
    """The skidding solver (``skidding.solve``), warm-started from ``guess``; with a
    table-backed drag model in ``options`` (:data:`TABLE_FILM_DRIVERS`) that model's
    driver runs the solve instead."""
    if at_rest(operating):
        return standstill(bearing, operating)
    if operating.outer_speed != 0.0:
        raise InputError("operating.outer_speed", operating.outer_speed,
                         "0 rad/s under the skidding solvers: they turn the inner ring with the "
                         "outer ring fixed (kinematics = \"race_control\" takes a driven outer "
                         "ring)")
    from .skidding import solve

    opts = dict(options or {})
    params = opts.pop("params", None)
    raw_guess = guess.raw if guess is not None else None
    run = solve
    driver = table_film_driver(opts.get("drag_model"))
    if driver is not None:  # a table-backed film: its driver solves (it sets the drag model)
        opts.pop("drag_model")
        run = driver
    res = run(bearing, lubricant, operating.inner_speed, operating.radial_load,
              operating.axial_load, contact_temperature, supply=supply, params=params,
              guess=raw_guess, oil_temperature=oil_temperature, **opts)
    heat_options = (_ball_heat_options(bearing, supply, operating.inner_speed, params)
                    if hasattr(bearing, "ball_diameter") else {})
    if hasattr(bearing, "ball_diameter") and res.converged:
        _ball_film_range(bearing, lubricant, res.kinematic_state, contact_temperature)
        if res.extra.get("fallback") == "round_off":
            heat = float(res.heat["total"])
            gap = abs(res.shaft_torque * res.inner_speed - heat) / max(abs(heat), 1e-300)
            from .skidding.ball_round_off import FLOOR_FACTOR

            # what ball_round_off measured: the residual against the change of the scaled
            # residual that one-ulp changes of the unknowns cause through the analytic
            # Jacobian; that change is large because the traction rises with the slip
            # almost as a step (viscous oil), not because of the ulp itself (measured on
            # SKF6304 at 10012 r/min, 573 N, contacts at -13.8 degC in ISO VG46: floor 6.7e-5,
            # from the ball moment rows, through the radial-position (86 %) and axial-spin
            # (14 %) columns)
            warnings.warn(ValidityWarning(
                f"skidding.ball: state accepted at the round-off floor of its residual, "
                f"above the 1e-9 tolerance: scaled residual {res.residual_norm:.2g} against "
                f"{res.extra['round_off_floor']:.2g}, the residual change that the smallest "
                "representable changes of the unknowns cause (from the Jacobian; accepted "
                f"within {FLOOR_FACTOR:g} x it). The traction of the contacts at "
                f"{contact_temperature - 273.15:.1f} degC rises with the slip almost as a "
                "step (steep traction curve of the viscous oil), so the balls' moment rows "
                "change by that much across one representable step of a ball's position "
                "or spin and no Newton step lowers them; the ring and cage equations, which "
                "set the cage speed, are met (to the tolerance or to their own, smaller, "
                f"floor); the energy identity holds to {gap:.1g} (relative)"),
                stacklevel=2)
    return KinematicsResult(
        state=res.kinematic_state,
        cage_speed_ratio=float(res.cage_speed_ratio),
        theoretical_cage_speed_ratio=float(res.theoretical_cage_speed_ratio),
        converged=bool(res.converged),
        residual_norm=float(res.residual_norm),
        iterations=int(getattr(res, "iterations", 0)),
        heat_options=heat_options,
        traction=_solver_traction(res, bearing, lubricant, contact_temperature, params),
        raw=res,
    )


def _ball_film_range(bearing: Any, lubricant: Any, state: Any, temperature: float) -> None:
    """The fitted-range check of the ball solver's film (Hamrock-Dowson 1977 central film,
    evaluated by the solver's compiled core without checks), on the loaded, rolling contacts
    of the converged state: the dimensionless groups U = eta u / (E' R_x), W = Q / (E' R_x^2),
    G = alpha E' and the ellipticity k against :data:`thermobearing.film.HD1977_RANGE`, with
    the same ValidityWarning as :func:`thermobearing.film.hamrock_dowson_1977_central` (race
    control's check); a scene run merges the repeats. The groups only, not the checked film
    function: this runs at every kinematics solve of a transient."""
    from .film import HD1977_RANGE, _warn_range, hamrock_dowson_ellipticity

    eta = float(lubricant.dynamic_viscosity(temperature))
    e_mod = float(bearing.effective_modulus)
    big_g = float(lubricant.pressure_viscosity_coefficient(temperature)) * e_mod
    for cs in state.contacts:
        if cs.film_thickness is None or cs.reduced_radius_x is None:
            continue
        q = np.asarray(cs.normal_load, float)
        u = np.abs(np.asarray(cs.entrainment_speed, float))
        use = (q > 0) & (u > 0)
        if not np.any(use):
            continue
        rx = np.broadcast_to(np.asarray(cs.reduced_radius_x, float), q.shape)[use]
        groups = {}
        if cs.reduced_radius_y is not None:
            ry = np.broadcast_to(np.asarray(cs.reduced_radius_y, float), q.shape)[use]
            groups["k"] = (hamrock_dowson_ellipticity(rx, ry), HD1977_RANGE["k"])
        groups["U"] = (eta * u[use] / (e_mod * rx), HD1977_RANGE["U"])
        groups["W"] = (q[use] / (e_mod * rx**2), HD1977_RANGE["W"])
        groups["G"] = (big_g, HD1977_RANGE["G"])
        _warn_range("hamrock_dowson_1977_central", **groups)


def _solver_traction(res: Any, bearing: Any, lubricant: Any, temperature: float,
                     params: Any) -> Any:
    """The traction law the solver balanced its forces with (the raceway heat source must
    integrate the same law for the shaft power to equal the heat); built anew only when
    the result does not carry it (roller results)."""
    extra = getattr(res, "extra", None)
    law = extra.get("traction_law") if isinstance(extra, dict) else None
    return law if law is not None else default_traction(bearing, lubricant, temperature,
                                                        params)


@KINEMATICS.register(
    "none",
    references=["harris_kotzalas2007"],
    summary="No kinematics: epicyclic cage speed only, for whole-bearing (global) loss models.",
)
def no_kinematics(bearing: Any, lubricant: Any, operating: OperatingPoint, *,
                  contact_temperature: float, oil_temperature: float, supply: OilSupply,
                  guess: KinematicsResult | None = None,
                  options: Mapping[str, Any] | None = None) -> KinematicsResult:
    """The epicyclic (pure-rolling) cage speed at the nominal contact angle and no contact
    detail: the cheapest rung, for heat sources that need only speeds and loads (the
    ``global_friction`` source). Sources that integrate contacts cannot run on it."""
    if at_rest(operating):
        return standstill(bearing, operating)
    import numpy as np

    csr = float(bearing.theoretical_cage_speed_ratio())
    w_c = operating.outer_speed + csr * (operating.inner_speed - operating.outer_speed)
    z = bearing.n_elements
    state = KinematicState(inner_speed=operating.inner_speed, outer_speed=operating.outer_speed,
                           cage_speed=w_c, orbital_speed=np.full(z, w_c),
                           element_spin=np.zeros(z), contacts=(), origin="given")
    return KinematicsResult(state=state, cage_speed_ratio=csr,
                            theoretical_cage_speed_ratio=csr)
