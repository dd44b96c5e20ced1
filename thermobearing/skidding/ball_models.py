"""Force models of the ball skidding solver, built from the heat-source physics (owner F).

The solver must balance exactly the forces whose power the heat sources report, so every
drag model here is a thin adapter around the functions of :mod:`thermobearing.heat_sources`
(one code path):

- raceway traction: :func:`thermobearing.contact_traction.integrate` with a traction law of
  :mod:`thermobearing.traction` (default ``eyring_limiting_shear`` with a smooth cap, film
  thickness from :func:`thermobearing.film.hamrock_dowson_1977_central`);
- ball churning drag: paper 002 eq. 10 (``heat_sources.churning.drag_force``, the
  ``churning_elements`` source with ``form="harris"``) in the oil-air mixture of volume
  fraction X (Parker's correlation of ``heat_sources.churning.parker_oil_fraction`` with a
  calibratable constant, or a fixed fraction);
- cage: churning (paper 002 eq. 15, ``churning_cage``) plus the cage-guide land torque
  (paper 002 eq. 5, ``heat_sources.cage_guide.land_drag_torque``, centred cage);
- inner ring churning (paper 002 eq. 17, ``churning_inner_ring``) for the shaft torque;
- ball-pocket friction coefficient mu_p (paper 002 eq. 19, ``heat_sources.pocket``).

:func:`heat_context_options` returns the matching ``HeatContext.options`` so that running the
registered heat sources on the solver's :class:`~thermobearing.state.KinematicState` gives,
to round-off, the solver's own heat (the energy test of issue 5).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..contact_traction import _table_viscosity_array
from ..errors import InputError, UnknownNameError
from .ball import BallModels
from .ball_residual import guarded_film_array

__all__ = ["BallParameters", "GuardedFilm", "default_ball_models", "heat_context_options"]


@dataclass(frozen=True)
class BallParameters:
    """Parameters of the ball force models that paper 002 does not give (SI).

    Attributes
    ----------
    limiting_shear_coefficient : Lambda of the Eyring/limiting-shear traction law [-].
    eyring_stress : tau0 [Pa].
    pocket_friction : ball-pocket friction coefficient [-].
    drag_coefficient : c_d of the ball drag, paper 002 eq. 10 [-] (0.45: sphere plateau).
    parker_constant : K of Parker's oil-fraction correlation [-] (1.46e7 recalled).
    oil_fraction : fixed oil volume fraction X [-] (overrides Parker when not None).
    n_major, n_minor : quadrature nodes of the contact integration.
    source : where the values come from ("default", "calibrated: ...").
    rolling_resistance : EHL rolling resistance of the raceway contacts in the balance and
        the heat, ``rolling_resistance.MODELS``: "none" (default) or "harris" (point-contact
        hydrodynamic rolling force, :mod:`thermobearing.rolling_resistance`).
    rolling_resistance_reduction : its reduction, ``rolling_resistance.REDUCTIONS``: "none"
        (isothermal, fully flooded; default), "thermal" (Gupta 1992 inlet heating per
        contact), "skf" (SKF phi_ish phi_rs), "thermal_starvation" (Gupta x SKF phi_rs).
    """

    limiting_shear_coefficient: float = 0.07
    eyring_stress: float = 5.0e6
    pocket_friction: float = 0.1
    drag_coefficient: float = 0.45
    parker_constant: float = 1.46e7
    oil_fraction: float | None = None
    n_major: int = 8
    n_minor: int = 4
    source: str = "default"
    extra: dict = field(default_factory=dict)
    rolling_resistance: str = "none"
    rolling_resistance_reduction: str = "none"

    def __post_init__(self) -> None:
        from ..rolling_resistance import MODELS, REDUCTIONS

        if self.rolling_resistance not in MODELS:
            raise UnknownNameError("BallParameters.rolling_resistance",
                                   self.rolling_resistance, MODELS)
        if self.rolling_resistance_reduction not in REDUCTIONS:
            raise UnknownNameError("BallParameters.rolling_resistance_reduction",
                                   self.rolling_resistance_reduction, REDUCTIONS)

    def with_(self, **changes: Any) -> BallParameters:
        return replace(self, **changes)


def _oil_fraction(bearing, supply, speed: float, params: BallParameters) -> float:
    from ..heat_sources.churning import oil_bath_fraction, parker_oil_fraction

    if params.oil_fraction is not None:
        return float(params.oil_fraction)
    if supply is None:
        raise InputError("supply", None, "an OilSupply (or BallParameters.oil_fraction)")
    if supply.method == "oil_bath":
        return float(oil_bath_fraction(supply.level, 0.5 * bearing.outer_raceway_diameter,
                                       0.5 * bearing.pitch_diameter))
    if supply.method == "grease":
        return 0.0
    return parker_oil_fraction(supply.flow_rate, speed, bearing.pitch_diameter,
                               params.parker_constant)


def rolling_supply_factor(bearing, supply, speed: float, params: BallParameters,
                          lubricant, oil_temperature: float) -> float:
    """The bearing-level factor of the rolling-resistance reduction (SKF phi_ish phi_rs or
    phi_rs, :func:`thermobearing.rolling_resistance.supply_factor`) at the oil temperature's
    kinematic viscosity [-]; 1 without a bearing-level factor."""
    from ..rolling_resistance import supply_factor

    red = params.rolling_resistance_reduction
    if params.rolling_resistance == "none" or red in ("none", "thermal"):
        return 1.0
    if supply is None:
        raise InputError("supply", None, "an OilSupply (the rolling-resistance reduction "
                         f"{red!r} depends on the lubrication method)")
    t = float(oil_temperature)
    nu = float(lubricant.dynamic_viscosity(t)) / float(lubricant.density(t))
    return supply_factor(red, bearing, speed, nu, supply.method)


def heat_context_options(bearing, supply, speed: float, params: BallParameters,
                         rolling_factor: float | None = None) -> dict:
    """``HeatContext.options`` matching the solver's force models (see module docstring).

    With ``params.rolling_resistance`` other than "none", an ``ehl_rolling_resistance``
    entry; that source must be among the scene's heat sources for the heat to close.
    ``rolling_factor`` None (default): no model named, the source books the rolling forces
    the solver balanced (the kinematic state's ``raceway_rolling_force``) against the
    entrainment, F_R |u_e| per contact, the solver's power. Given (the bearing-level factor
    the solver used, ``rolling_supply_factor``): the source re-evaluates the force from the
    state's contact fields with the model, the reduction and that factor, and books it per
    surface, f_p (|u_b| + |u_r|) -- the same heat unless a surface's speed has the other
    sign than the entrainment (nearly stopped unloaded balls)."""
    x = _oil_fraction(bearing, supply, speed, params)
    out = {
        "raceway_traction": {"n_major": params.n_major, "n_minor": params.n_minor},
        "churning_elements": {"form": "harris", "drag_coefficient": params.drag_coefficient,
                              "oil_fraction": x, "oil_swirl": 0.0},
        "churning_cage": {"oil_fraction": x},
        "churning_inner_ring": {"oil_fraction": x},
        "cage_guide": {"form": "short_bearing", "cage_share": 0.0},
        "pocket_friction": {"friction_coefficient": params.pocket_friction},
    }
    if params.rolling_resistance != "none":
        # no model named: the source books the forces the solver balanced (kinematic state
        # extras ``raceway_rolling_force``), against the entrainment as the solver applies
        # them; naming the model here made it re-evaluate them and book f_p (|u_b| + |u_r|),
        # more than the solver's F_R |u_e| where a nearly stopped ball's surface speed has
        # the other sign (unloaded balls at low speed)
        out["ehl_rolling_resistance"] = {}
        if rolling_factor is not None:
            out["ehl_rolling_resistance"] = {
                "rolling_force": params.rolling_resistance,
                "reduction": params.rolling_resistance_reduction,
                "supply_factor": float(rolling_factor)}
    return out


def finite_pressure_limit(lubricant, temperature: float, p_max: float) -> float:
    """``p_max`` [Pa] if the lubricant's eta(T, p) is finite up to it, else the largest
    pressure below it where it is (bisection to 1e-9 of ``p_max``, on the finite side).
    The pressure-viscosity laws refuse an overflowing pressure with an
    :class:`~thermobearing.errors.InputError` naming it (Roelands at eta0 of a few hundred
    Pa s: ``exp`` of more than 709); that pressure is not an operating state, only the end
    of the range a table may cover. Units: Pa, K."""
    def finite(p: float) -> bool:
        try:
            with np.errstate(over="ignore"):
                v = float(lubricant.dynamic_viscosity(temperature, p))
        except InputError:
            return False
        return math.isfinite(v)

    if finite(p_max):
        return float(p_max)
    lo, hi = 0.0, float(p_max)
    if not finite(lo):
        raise InputError("temperature", f"{temperature:g} K",
                         "a temperature at which the lubricant's viscosity is finite at "
                         "atmospheric pressure")
    while hi - lo > 1e-9 * p_max:
        mid = 0.5 * (lo + hi)
        if finite(mid):
            lo = mid
        else:
            hi = mid
    return lo


#: upper end of the tabulated pressure range [Pa] (docstring of IsothermalViscosity; the
#: SKF6304's most loaded ball reaches p_0 = 6.6 GPa at 30 kN radial, 1.8 C)
EXTENDED_PRESSURE = 8.0e9


class IsothermalViscosity:
    """The lubricant's eta(T, p) at one temperature, tabulated in p for speed.

    ``ln eta(T0, p)`` of the lubricant's own pressure-viscosity law (owner A) is tabulated on
    a uniform grid of step 1.25 MPa (4001 points over 0-5 GPa, continued with the same step
    to :data:`EXTENDED_PRESSURE`) and interpolated linearly (relative error measured 6e-6 for
    the Roelands law of ISO VG46 at 330 K, tests/unit/skidding/test_ball_fast_path.py; exact
    for Barus); other temperatures or pressures beyond the grid fall back to the lubricant.
    The grid ended at 5 GPa before: contacts above it (SKF6304 beyond about 1.1 C radial,
    p_0 = 5.7 GPa at 20 kN) fell back to the lubricant, without the analytic Jacobian and its
    round-off acceptance, and 20 and 22 kN at 50-300 r/min in 20 degC ISO VG46 failed after
    up to 80 s of fallbacks while 18, 21 and 24 kN converged (tests/unit/
    test_prop19_ball_energy.py); they converge at the first Newton solve now. The traction
    law evaluates eta at every quadrature node of every contact in every Newton residual,
    which otherwise dominates the solver's run time.

    In cold oil the law overflows below 5 GPa (ISO VG100 at -37 degC, still liquid by
    :func:`~thermobearing.lubricant_properties.check_liquid_temperature`: Roelands eta is
    1e49 Pa s at 1 GPa and infinite from 4.46 GPa); the grid then ends at the largest
    pressure where eta is finite (:func:`finite_pressure_limit`), so an operating point whose
    contacts stay below it is solved, and a contact beyond it falls back to the lubricant,
    which refuses naming the pressure.
    """

    def __init__(self, lubricant, temperature: float, p_max: float = 5.0e9, n: int = 4001,
                 extend_to: float = EXTENDED_PRESSURE):
        self.lubricant = lubricant
        self.temperature = float(temperature)
        if not (math.isfinite(float(p_max)) and p_max >= 0.0):
            raise InputError("IsothermalViscosity.p_max", p_max,
                             "a finite pressure >= 0 Pa (the top of the table)")
        if int(n) != n or n < 2:
            raise InputError("IsothermalViscosity.n", n, "an integer >= 2 (grid points)")
        p_max = finite_pressure_limit(lubricant, self.temperature, p_max)
        if p_max < extend_to and p_max == 5.0e9 and n == 4001:
            # the same 1.25 MPa step on to extend_to (or the law's finite limit): the grid
            # points and so every table value below 5 GPa are those of the 0-5 GPa table
            step = 5.0e9 / 4000
            top = finite_pressure_limit(lubricant, self.temperature, extend_to)
            n = int(math.floor(top / step + 1e-9)) + 1
            p_max = (n - 1) * step
        if p_max <= 0.0:
            # an empty range (p_max = 0 asked for, or a law finite only at p = 0, below
            # 1e-9 of the asked top): the table is the one point p = 0; any p > 0 is beyond
            # it and goes to the lubricant (which refuses an overflowing pressure naming it).
            # 1/step is 0 there: the compiled interpolation then reads ln eta(T, 0) at p = 0
            p_max, n = 0.0, 1
        self._p = np.linspace(0.0, p_max, n)
        self._ln = np.log(np.asarray(lubricant.dynamic_viscosity(self.temperature, self._p),
                                     float))
        self._slope = np.append(np.diff(self._ln), 0.0)   # per grid step
        self._inv_dp = (n - 1) / p_max if p_max > 0.0 else 0.0
        self.p_max = p_max

    def viscosity_table(self, T, p_max: float):
        """(ln eta grid, slope per step, 1/step) for the compiled contact integration
        (:func:`thermobearing.contact_traction.viscosity_source`) when ``T`` is this
        table's temperature and the pressures stay within the grid, else None."""
        if float(T) == self.temperature and 0.0 <= p_max <= self.p_max:
            return self._ln, self._slope, self._inv_dp
        return None

    def dynamic_viscosity(self, T, p=0.0):
        T = np.asarray(T, float)
        p = np.asarray(p, float)
        if np.all(T == self.temperature) and np.all(p <= self.p_max) and np.all(p >= 0.0):
            # linear interpolation on the uniform grid: the compiled interpolation the
            # contact integration uses (contact_traction._table_viscosity)
            shape = np.broadcast_shapes(T.shape, p.shape)
            flat = np.ascontiguousarray(np.broadcast_to(p, shape)).ravel()
            return _table_viscosity_array(flat, self._ln, self._slope,
                                          self._inv_dp).reshape(shape)
        return self.lubricant.dynamic_viscosity(T, p)

    def __getattr__(self, name):
        return getattr(self.lubricant, name)


@dataclass(frozen=True)
class GuardedFilm:
    """Central film thickness of the ball contacts [m]: Hamrock & Dowson 1977 (film.py,
    :func:`thermobearing.film.hamrock_dowson_1977_central`, unchecked compiled core) at the
    entrainment speed max(|u|, u_min) and load max(Q, Q_min), floored at h_min (a film
    must stay positive where the traction law divides by it).

    Called as ``film(u [m/s], Q [N], rx [m], ry [m])``; ``kernel_params`` lets the ball
    residual evaluate it inside its compiled kernel
    (:func:`thermobearing.skidding.ball_residual.guarded_film`, the same code).
    """

    dynamic_viscosity: float          #: eta0 at the contact inlet temperature [Pa s]
    pressure_viscosity_coefficient: float   #: alpha [1/Pa]
    effective_modulus: float          #: E' [Pa]
    speed_floor: float = 1e-3         #: u_min [m/s]
    load_floor: float = 1e-3          #: Q_min [N]
    thickness_floor: float = 1e-9     #: h_min [m] (> 0)

    def __post_init__(self) -> None:
        from ..errors import check_positive

        check_positive("film.dynamic_viscosity", self.dynamic_viscosity)
        check_positive("film.pressure_viscosity_coefficient",
                       self.pressure_viscosity_coefficient, allow_zero=True)
        check_positive("film.effective_modulus", self.effective_modulus)
        for name in ("speed_floor", "load_floor", "thickness_floor"):
            check_positive(f"film.{name}", getattr(self, name))

    @property
    def kernel_params(self) -> np.ndarray:
        return np.array([self.dynamic_viscosity, self.pressure_viscosity_coefficient,
                         self.effective_modulus, self.speed_floor, self.load_floor,
                         self.thickness_floor])

    def __call__(self, u, Q, rx, ry):
        arrays = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (u, Q, rx, ry)))
        flat = [np.ascontiguousarray(a).ravel() for a in arrays]
        return guarded_film_array(*flat, self.kernel_params).reshape(arrays[0].shape)


def make_traction(lubricant, params: BallParameters, temperature: float | None = None):
    """The solver's default traction law (Eyring with limiting shear, smooth cap)."""
    from ..traction import make_traction_law

    if temperature is not None:
        lubricant = IsothermalViscosity(lubricant, temperature)
    return make_traction_law("eyring_limiting_shear", lubricant=lubricant,
                             limiting_shear_coefficient=params.limiting_shear_coefficient,
                             eyring_stress=params.eyring_stress, cap="smooth")


def default_ball_models(bearing, lubricant, *, temperature: float, speed: float, supply=None,
                        params: BallParameters | None = None,
                        oil_temperature: float | None = None) -> BallModels:
    """Build :class:`BallModels` for ``bearing`` from the heat-source physics.

    Parameters
    ----------
    bearing : BallBearing.  lubricant : Lubricant.
    temperature : contact (inlet) temperature for the traction law and the film [K].
    speed : inner-ring speed [rad/s] (Parker's oil fraction depends on it).
    supply : OilSupply (flow, method) for the oil fraction.
    params : BallParameters (default values when None).
    oil_temperature : oil temperature for churning [K] (default ``temperature``).
    """
    from ..errors import check_positive
    from ..heat_sources import churning as ch

    p = params or BallParameters()
    t_oil = float(oil_temperature if oil_temperature is not None else temperature)
    rho = float(lubricant.density(t_oil))
    eta_oil = float(lubricant.dynamic_viscosity(t_oil))
    nu = eta_oil / rho
    eta_c = float(lubricant.dynamic_viscosity(temperature))
    alpha_c = float(lubricant.pressure_viscosity_coefficient(temperature))
    E = bearing.effective_modulus
    x = _oil_fraction(bearing, supply, speed, p)
    rho_e = x * rho
    law = make_traction(lubricant, p, temperature)

    check_positive("lubricant dynamic_viscosity", eta_c)
    check_positive("lubricant pressure_viscosity_coefficient", alpha_c, allow_zero=True)
    check_positive("bearing effective_modulus", E)

    # film.hamrock_dowson_1977_central without its per-call checks and range warnings
    # (inputs validated above and by the solver; the range is not checked in the loop)
    film = GuardedFilm(eta_c, alpha_c, E)

    D = bearing.ball_diameter
    area = 0.25 * math.pi * D * D
    dm = bearing.pitch_diameter

    def ball_drag(u):
        return ch.drag_force(p.drag_coefficient, rho_e, area, u)

    cage = bearing.cage
    # the heat sources' geometry (paper 002 eqs. 15 and 17): one code path, so the drag the
    # solver balances is the churning the heat sources book (an inner-ring-guided cage's
    # guide film is cage_guide's, not the inner ring churning's)
    d_c, gap_c = ch.cage_churning_geometry(bearing)
    d_in, arc, shoulder, gap_i = ch.inner_ring_churning_geometry(bearing)
    guide = None
    if cage.guidance in ("outer_ring", "inner_ring"):
        from ..heat_sources.cage_guide import land_drag_torque

        land = cage.land_width if cage.land_width is not None else cage.width
        c_r = 0.5 * cage.guide_clearance

        def guide(wc, wg):
            # centred cage (eccentricity 0): Petroff drag of paper 002 eq. 5 (F's form)
            return -land_drag_torque(eta_oil, cage.guide_land_diameter, wg, wc, land, c_r, 0.0)

    r_c = 0.5 * d_c
    gap_root = math.sqrt(gap_c / r_c)

    def cage_torque(wc):
        # paper 002 eqs. 12-15: ch.viscous_friction_coefficient's scalar branch (N_Re =
        # R |omega| c / nu, N_Ta = N_Re sqrt(c / R), the same operations, so the same bits)
        # and its regime core ch._mu_v_regime without the ChurningRegime wrapping (
        # the solver calls this once per new cage speed; 16 -> ~4 us per call)
        re = r_c * abs(wc) * gap_c / nu
        mu_v = ch._mu_v_regime(re, re * gap_root)[0]
        q = float(ch.cage_churning_power(rho_e, mu_v, wc, cage.width, d_c))
        return q / wc if wc != 0 else 0.0

    def inner_torque(wi):
        reg = ch.viscous_friction_coefficient(0.5 * d_in, wi, gap_i, nu)
        q = float(ch.inner_ring_churning_power(rho_e, reg.mu_v, wi, arc, shoulder, d_in))
        return q / wi if wi != 0 else 0.0

    rolling = None
    if p.rolling_resistance != "none":
        from ..rolling_resistance import lubricant_kernel_parameters

        factor = rolling_supply_factor(bearing, supply, speed, p, lubricant, t_oil)
        rolling = lubricant_kernel_parameters(p.rolling_resistance,
                                              p.rolling_resistance_reduction, lubricant,
                                              float(temperature), E, factor)
    return BallModels(traction_law=law, pocket_friction=p.pocket_friction,
                      ball_drag=ball_drag, cage_torque=cage_torque, cage_guide_torque=guide,
                      guide_on_inner_ring=cage.guidance == "inner_ring",
                      inner_ring_torque=inner_torque, film_thickness=film,
                      temperature=float(temperature), n_major=p.n_major, n_minor=p.n_minor,
                      drag_radius=0.5 * dm,
                      parameters={"oil_fraction": x, "params": p,
                                  "cage_guide_model": guide is not None},
                      rolling_resistance=rolling)
