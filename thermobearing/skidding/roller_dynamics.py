"""Roller skew and axial motion with dynamic unbalance; PV and slip speed (paper 003).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], eqs. 18
(roller), 21-25 (PV of the end face, slip speed of the working surface), with the rib
contact of :mod:`thermobearing.rib` (eqs. 1-17).

What is modelled (and what is not)
----------------------------------
The paper integrates roller (6 DOF), cage (eq. 19) and inner ring (eq. 20) together with
GSTIFF [gear1971_dae]. Here the inner-ring motion and the raceway loads per azimuth are
*prescribed* by the quasi-static skidding solution of
:func:`thermobearing.skidding.roller.solve_roller` (paper 000's Z + 1 equations), and one
roller is followed with the degrees of freedom in which the unbalance acts (axial position
X, skew alpha, circumferential position z in its pocket, spin phase psi). The rib acts back
on the roller spins and the cage speed quasi-statically (:func:`couple_spins`, default):
the time-mean rib moment about each roller's axis, the mean circumferential rib force and
the extra cage-bar friction of the rattling roller are added to the Z + 1 moment and cage
balances, which are re-solved. What is not modelled: the inner-ring and cage whirl, the
roller tilt and radial motion (the radial part of the unbalance force only modulates the
raceway loads), the orbital centrifugal force of the unbalance mass (the roller mass of the
preset is taken to include it; its axial offset would only tilt the roller).

* ``coupled`` model (:func:`thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`):
  all Z rollers (these DOFs plus the spin) and the cage rotation integrated together; the
  spins then lag the load zone (J_p/k ~ 13 ms for an unloaded roller): base-case slip
  ~5.5 m/s against ~18 m/s with the quasi-static spins of the two models below. One jitted
  RK4 loop with paper 000's traction tabulated: ~1.4 s CPU per base-case point (2 + 3
  orbits); options: inner ring free axially (eq. 20 line 1), cage guide-land drag.
* ``full`` model (:func:`simulate_full`): X, alpha and psi of one roller travelling a whole
  orbit (azimuth phi = omega_c t) through the load zone; raceway loads and the (coupled)
  spin follow phi; option ``spin_dof`` adds omega_r. Stiff (the rib contact is a stiff
  Hertz spring): scipy's Radau IIA, variable step [hairer_wanner1996].
* ``reduced`` model (:func:`simulate_reduced`): the same equations at frozen azimuths (one
  per distinct load state of the orbit, weighted by the share of the orbit it
  represents), integrated with a numba-jitted fixed-step RK4 (h <= 1/omega of the rib
  contact's axial mode). Base case (0.11 g): PV -5.5 %, slip 0.0 % against the full model
  at 1/57 of its cost (8.0 s vs 0.14 s wall; 37 s vs 0.56 s on a loaded 2-core machine),
  both on the same coupled spins; the coupling itself costs ~1 s (validation case
  ``paper003_pv_slip_trends``).
* roller spins: ``spin="skidding"`` (default) starts from the quasi-static solver, whose
  unloaded rollers skid (about half the rolling speed at the base case), then couples;
  ``spin="rolling"`` puts every roller at its pure-rolling spin, uncoupled (a sensitivity
  switch, see the case's SOURCE.md); ``spin="lagged"`` takes the skidding (coupled) spins
  through the spin inertia along the orbit (:func:`lagged_spins`).
* spin stiffness k_omega (the full model's ``spin_dof``): -dT/d omega_r of the raceway and
  pocket moment T of the same quasi-static traction model (:func:`race_spin_stiffness`):
  ~6e-5 N m s for the loaded and ~5e-7 N m s for the unloaded rollers at the base case.

Rib contact: both end faces through the jitted kernel :func:`thermobearing.rib.face_contact`
(the same code as :func:`~thermobearing.rib.rib_forces`): the contact point moves
circumferentially with the skew (z_K = (R_s - L_r/2) sin alpha for the paper's spherical
end face), the friction acts along the full sliding velocity at that point (eq. 24 as a
vector), so its radial part brakes the roller spin (M_rib,x below) and its circumferential
part turns the roller about the skew axis.

Equations (cage frame, signs as in :mod:`thermobearing.rib`)::

    m X''      = Q_ez^X + N_i mu(s_i) + N_o mu(s_o)                       (eq. 18, line 1)
    J_t alpha'' = M_unb + M_rib + M_race + M_pocket                        (eq. 18, skew line)
    T_j(omega_r, omega_c) + <M_rib,x> = 0, cage balance + sum <F_rib,z> = 0   (couple_spins)

* unbalance (paper sec. 4; its refs [16,17] [cui2017_roller_unbalance] were not seen, so the
  force is derived from rigid-body kinematics): a mass m_u at axial position x_u and radius
  e_u rotating with the roller: F_cv = m_u e_u (omega_r - omega_c)^2 (absolute spin rate),
  circumferential component F_cv sin(psi), psi' = omega_r; skew moment
  M_unb = -x_u F_cv sin(psi). Its radial component (tilt, raceway load ripple) is not
  followed: the line contacts hold the tilt to ~1e-5 rad (H_contact changes < 0.2 um).
* raceway axial sliding of a skewed roller s_i = -u_i sin(alpha) - X', s_o = u_o sin(alpha)
  - X' (u_i = (omega_i - omega_c) d_i/2, u_o = omega_c d_o/2) with a regularised Coulomb
  traction mu(s) = mu_t tanh(s/s_0) (the shape of an EHL traction curve,
  [johnson_tevaarwerk1977_traction]; mu_t, s_0 estimated); the skew rate's sliding -alpha' x
  along the line gives M_race = -sum N mu_t tanh(alpha' l/s_0) l, l = L_e/(2 sqrt 3) (the
  rms arm of a uniform line load).
* pocket (paper 003 eq. 18 lines 2-3: N^c, F^c and the unbalance forces move the roller
  centre): a point mass at the chamfer is not only a couple -- its rotating force F_cv acts
  on the roller centre too. Circumferentially
  m z'' = F_d + F_cv sin(psi) + F_rib,z - c_z z' + F_bar(z, z', alpha),
  F_d the quasi-static pocket force (the raceways' net forward force), c_z = k_omega/(D/2)^2
  the raceway damping of the same traction model, F_bar the two cage bars as Winkler line
  springs with a squeeze film (:mod:`~thermobearing.skidding.roller_dynamics_pocket`), which
  also limit the skew. At the base case the free rattle amplitude F_cv/(m omega_r^2) is
  0.08 mm (0.06 g) to 0.14 mm (0.11 g) against a half clearance of 0.1 mm: the roller
  hits the bars every spin period. ``pocket_dof=False`` holds z = 0 (the bars then act on
  the skew only, as before 2026-11-22).

Outputs (paper 003 eqs. 21-25): PV per end face = time mean of P |v_i - v_r| over the
periodic state [Pa m/s] (also its peak and its mean over the time in contact); slip speed =
time mean of |V_roll|, V_roll = (omega_i - omega_c) d_i/2 - omega_r D_w/2. Eq. 25 as printed,
abs[(omega_ix d_i/2 - omega_rxj)(R_ro - omega_rsxj D_w/2)], multiplies a speed by a length
difference; with the parentheses moved, |(omega_ix - omega_rxj)(R_ro - D_w/2) -
omega_rsxj D_w/2| with omega_rxj the roller's orbital speed (= omega_c), R_ro - D_w/2 =
d_i/2 and omega_rsxj its spin, it is exactly |V_roll|, the rolling slip at the inner
raceway. The full sliding magnitude with the skew-induced parts,
sqrt(V_roll^2 + s_i^2 + (alpha' L_e)^2/12), is ``surface_slip_speed``. Units: SI.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numba import njit
from scipy.integrate import solve_ivp

from ..errors import ConvergenceError, InputError, check_positive, check_range
from ..rib import (
    _G_N,
    DEFAULT_RIB_FRICTION,
    F_FX,
    F_FZ,
    F_MSKEW,
    F_MSPIN,
    SIGN_REGULARISATION,
    RibGeometry,
    face_values,
    lubricant_drag,
    rib_forces,
    rib_geometry,
    unbalance_check,
)
from .roller_dynamics_pocket import (
    DEFAULT_SQUEEZE_FLOOR,
    bar_forces,
    extra_pocket_friction,
    pocket_force_z,
)

#: raceway traction limit mu_t [-] (estimated: typical EHL traction plateau 0.03-0.08)
DEFAULT_TRACTION_LIMIT = 0.05
#: slide speed s_0 of the traction curve's initial slope [m/s] (estimated)
DEFAULT_TRACTION_SPEED = 0.5
#: cage-bar contact stiffness [N/m] (estimated: brass bar, line contact over the roller length)
DEFAULT_POCKET_STIFFNESS = 2.0e7
#: oil volume fraction of the oil/air mixture at the rib (estimated, jet lubrication)
DEFAULT_OIL_FRACTION = 0.05


@dataclass(frozen=True)
class Unbalance:
    """Dynamic unbalance of a roller: mass [kg] at axial position x_u [m] (+ right end) and
    radius e_u [m] from the roller axis (paper 003 sec. 8: at the right chamfer)."""

    mass: float
    axial_position: float
    radius: float

    @property
    def moment_coefficient(self) -> float:
        """m_u e_u x_u [kg m^2] (a product of inertia)."""
        return self.mass * self.radius * self.axial_position


def chamfer_unbalance(bearing: Any, mass: float, side: int = +1,
                      chamfer: float = 0.5e-3) -> Unbalance:
    """Unbalance ``mass`` [kg] at the chamfer of the ``side`` end (+1 right, -1 left)."""
    unbalance_check(mass, bearing.roller_mass)
    if side not in (-1, 1):
        raise InputError("side", side, "+1 (right) or -1 (left)")
    check_range("chamfer", chamfer, 0.0, 0.5 * bearing.roller_diameter)
    return Unbalance(mass, side * (0.5 * bearing.roller_length - chamfer),
                     0.5 * bearing.roller_diameter - chamfer)


@dataclass(frozen=True)
class DynamicsModel:
    """Everything the roller integrators need (SI).

    Per-azimuth arrays come from the quasi-static skidding solution (``azimuth`` sorted,
    one orbit): ``inner_load``, ``outer_load`` [N], ``spin`` omega_qs [rad/s].
    """

    geom: RibGeometry
    inner_speed: float
    cage_speed: float
    azimuth: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    spin: np.ndarray
    roller_mass: float
    transverse_inertia: float
    polar_inertia: float
    effective_length: float
    outer_raceway_diameter: float
    pocket_clearance: float
    unbalance: Unbalance
    rib_friction: float = DEFAULT_RIB_FRICTION
    mixture_viscosity: float = 0.0
    traction_limit: float = DEFAULT_TRACTION_LIMIT
    traction_speed: float = DEFAULT_TRACTION_SPEED
    pocket_stiffness: float = DEFAULT_POCKET_STIFFNESS
    extras: dict[str, Any] = field(default_factory=dict)
    spin_k: np.ndarray | None = None
    spin_bias: np.ndarray | None = None
    pocket_force: np.ndarray | None = None
    pocket_viscosity: float = 0.0
    pocket_length: float = 0.0
    squeeze_floor: float = DEFAULT_SQUEEZE_FLOOR
    pocket_dof: bool = True
    pocket_friction: np.ndarray | None = None
    raceway_traction: str = "componentwise"

    def pocket_force_at(self, phi: float) -> float:
        """Quasi-static pocket force F_d [N] (positive: the roller pushes the cage
        forward) at azimuth ``phi``, interpolated like :meth:`at` (0 without data)."""
        return self._interp(self.pocket_force, phi)

    def _interp(self, arr: np.ndarray | None, phi: float) -> float:
        if arr is None:
            return 0.0
        p = phi % (2.0 * math.pi)
        az = np.append(self.azimuth, self.azimuth[0] + 2.0 * math.pi)
        v = np.append(arr, arr[0])
        return float(np.interp(p if p >= az[0] else p + 2.0 * math.pi, az, v))

    def circumferential_damping(self, k: float) -> float:
        """c_z = k_omega / (D/2)^2 [N s/m]: the raceway tractions' resistance to a
        circumferential slide of the roller centre, from the spin stiffness k_omega
        [N m s] of the same traction model (both contacts' dT/dV, module notes)."""
        r = 0.5 * self.geom.roller_diameter
        return k / (r * r)

    def at(self, phi: float) -> tuple[float, float, float]:
        """(N_i, N_o, omega_qs) at azimuth ``phi`` [rad] (periodic linear interpolation)."""
        p = phi % (2.0 * math.pi)
        az = self.azimuth
        n = len(az)
        j = int(np.searchsorted(az, p, side="right")) - 1
        j0 = j % n
        j1 = (j + 1) % n
        a0 = az[j0] if j >= 0 else az[-1] - 2.0 * math.pi
        a1 = az[j1] + (2.0 * math.pi if j1 <= j0 and j >= 0 else 0.0)
        w = (p - a0) / (a1 - a0) if a1 > a0 else 0.0
        return tuple(float(arr[j0] + w * (arr[j1] - arr[j0]))
                     for arr in (self.inner_load, self.outer_load, self.spin))

    def spin_stiffness(self, n_i: float, n_o: float) -> float:
        """k_omega = (D/2)^2 (N_i + N_o) mu_t / s_0 [N m s] (fallback when the model
        carries no ``spin_k`` of the quasi-static traction model)."""
        r = 0.5 * self.geom.roller_diameter
        return r * r * (n_i + n_o) * self.traction_limit / self.traction_speed

    def bias_at(self, phi: float) -> float:
        """Mean rib moment [N m] that the spins of a coupled model already balance
        (:func:`couple_spins`; 0 without coupling), interpolated at azimuth ``phi``."""
        if self.spin_bias is None:
            return 0.0
        p = phi % (2.0 * math.pi)
        az = np.append(self.azimuth, self.azimuth[0] + 2.0 * math.pi)
        b = np.append(self.spin_bias, self.spin_bias[0])
        return float(np.interp(p if p >= az[0] else p + 2.0 * math.pi, az, b))

    def stiffness_at(self, phi: float) -> float:
        """Spin stiffness k_omega [N m s] at azimuth ``phi``: ``spin_k`` interpolated like
        :meth:`at`, else :meth:`spin_stiffness`."""
        if self.spin_k is None:
            n_i, n_o, _ = self.at(phi)
            return self.spin_stiffness(n_i, n_o)
        p = phi % (2.0 * math.pi)
        az = np.append(self.azimuth, self.azimuth[0] + 2.0 * math.pi)
        k = np.append(self.spin_k, self.spin_k[0])
        return float(np.interp(p if p >= az[0] else p + 2.0 * math.pi, az, k))


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
                raceway_traction: str = "componentwise") -> DynamicsModel:
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
    if raceway_traction not in ("componentwise", "isotropic"):
        raise InputError("raceway_traction", raceway_traction, ("componentwise", "isotropic"))
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


# parameter vector of the jitted right-hand side: the rib geometry vector
# (RibGeometry.params, _G_N entries) followed by these dynamics scalars (indices)
(_FG, _SREG, _MU, _UI, _UO, _LARM, _OM, _WC, _HL, _MUT, _S0, _CP, _KC, _MUE, _XU, _MASS,
 _JT, _ETA, _RAD, _FLOOR, _PDOF, _VEC, _NP) = range(_G_N, _G_N + 23)


def _params(m: DynamicsModel) -> np.ndarray:
    """Scalars of the rib contact, raceways, cage and unbalance, computed once per model."""
    g = m.geom
    f_g = 0.0
    if m.mixture_viscosity > 0.0 and g.axial_clearance > 0.0:
        f_g = abs(float(lubricant_drag(g, m.inner_speed, m.cage_speed,
                                       m.mixture_viscosity)[0]))
    wc = m.cage_speed
    p = np.zeros(_NP)
    p[:_G_N] = g.params()
    p[_FG] = f_g
    p[_SREG] = SIGN_REGULARISATION
    p[_MU] = m.rib_friction
    p[_UI] = (m.inner_speed - wc) * 0.5 * g.inner_raceway_diameter
    p[_UO] = wc * 0.5 * m.outer_raceway_diameter
    p[_LARM] = m.effective_length / (2.0 * math.sqrt(3.0))
    p[_OM] = m.inner_speed - wc
    p[_WC] = wc
    p[_HL] = 0.5 * g.roller_length
    p[_MUT] = m.traction_limit
    p[_S0] = m.traction_speed
    p[_CP] = m.pocket_clearance
    p[_KC] = m.pocket_stiffness
    p[_MUE] = m.unbalance.mass * m.unbalance.radius
    p[_XU] = m.unbalance.axial_position
    p[_MASS] = m.roller_mass
    p[_JT] = m.transverse_inertia
    p[_ETA] = m.pocket_viscosity
    p[_RAD] = 0.5 * g.roller_diameter
    p[_FLOOR] = m.squeeze_floor
    p[_PDOF] = 1.0 if m.pocket_dof else 0.0
    p[_VEC] = 1.0 if m.raceway_traction == "isotropic" else 0.0
    return p


@njit(cache=True)
def _axial_share(s: float, v: float, s0: float) -> float:
    """tanh(|u|/s0) s/|u| [-] for the slide vector u = (v, s) [m/s] (v rolling, s axial;
    s0 [m/s]): the axial share of a traction law mu_t tanh(|u|/s0) directed along u, the
    shear stress of a film being collinear with its sliding velocity
    [johnson_tevaarwerk1977_traction] (``raceway_traction="isotropic"`` of
    :func:`build_model`); s/s0 at |u| -> 0."""
    r = math.sqrt(s * s + v * v)
    if r < 1e-9 * s0:
        return s / s0
    return math.tanh(r / s0) * s / r


@njit(cache=True)
def _rhs(p: np.ndarray, x: float, xd: float, a: float, ad: float, z: float, zd: float,
         n_i: float, n_o: float, spin: float, psi: float, f_d: float, c_z: float
         ) -> tuple[float, float, float, float, float, float, float]:
    """(X', X'', alpha', alpha'', z', z'', rib spin moment) with the inner ring fixed:
    :func:`_rhs_ring` at zero ring speed."""
    r = _rhs_ring(p, x, xd, a, ad, z, zd, n_i, n_o, spin, psi, f_d, c_z, 0.0)
    return r[0], r[1], r[2], r[3], r[4], r[5], r[6]


@njit(cache=True)
def _rhs_ring(p: np.ndarray, x: float, xd: float, a: float, ad: float, z: float, zd: float,
              n_i: float, n_o: float, spin: float, psi: float, f_d: float, c_z: float,
              xd_ring: float) -> tuple[float, float, float, float, float, float, float, float]:
    """(X', X'', alpha', alpha'', z', z'', rib spin moment, axial force on the inner ring):
    both faces of
    :func:`thermobearing.rib.face_values` (the kernel of :func:`~thermobearing.rib.rib_forces`)
    plus raceway, cage-bar (:func:`~thermobearing.skidding.roller_dynamics_pocket.pocket_force_z`)
    and unbalance terms (module notes). z: circumferential position in the pocket [m];
    f_d: quasi-static pocket force [N] (the raceways' net forward force on the roller);
    c_z: raceway damping of z [N s/m]. With the pocket DOF off, z stays 0.
    x, xd: axial position and speed of the roller *relative to the inner ring* [m, m/s]
    (rib contact, inner raceway slide); xd_ring: the inner ring's axial speed [m/s] (outer
    raceway slide: the outer ring is fixed); X'' is the roller's absolute axial
    acceleration (paper 003 eq. 18 line 1); the last entry is minus the rib and inner-
    raceway axial forces on the roller, i.e. their reaction on the inner ring (eq. 20
    line 1) [N]."""
    gp = p[:_G_N]
    fl = face_values(gp, -1, a, x, ad, spin, p[_OM], xd, p[_MU], p[_FG], p[_SREG])
    fr = face_values(gp, 1, a, x, ad, spin, p[_OM], xd, p[_MU], p[_FG], p[_SREG])
    m_rib = fl[F_MSKEW] + fr[F_MSKEW]
    m_spin = fl[F_MSPIN] + fr[F_MSPIN]
    mu_t = p[_MUT]
    s0 = p[_S0]
    sa = math.sin(a)
    s_i = -p[_UI] * sa - xd
    s_o = p[_UO] * sa - xd - xd_ring
    arm = p[_LARM]
    if p[_VEC] > 0.5:
        # isotropic film: the tanh law on the resultant slide, its axial share s/|s|
        v_i = p[_UI] - spin * p[_RAD]
        v_o = p[_UO] - spin * p[_RAD]
        f_inner = mu_t * n_i * _axial_share(s_i, v_i, s0)
        f_race = f_inner + mu_t * n_o * _axial_share(s_o, v_o, s0)
        m_race = -mu_t * (n_i * _axial_share(ad * arm, v_i, s0)
                          + n_o * _axial_share(ad * arm, v_o, s0)) * arm
    else:
        f_inner = mu_t * n_i * math.tanh(s_i / s0)
        f_race = f_inner + mu_t * n_o * math.tanh(s_o / s0)
        m_race = -(n_i + n_o) * mu_t * math.tanh(ad * arm / s0) * arm
    fz_bar, m_pocket, _, _ = pocket_force_z(z, zd, a, p[_HL], p[_CP], p[_KC], p[_ETA],
                                            p[_RAD], p[_FLOOR])
    f_cv = p[_MUE] * (spin - p[_WC]) ** 2
    sp = math.sin(psi)
    m_unb = -p[_XU] * f_cv * sp
    xdd = (fl[F_FX] + fr[F_FX] + f_race) / p[_MASS]
    add = (m_rib + m_race + m_pocket + m_unb) / p[_JT]
    zdd = 0.0
    if p[_PDOF] > 0.5:
        zdd = (f_d + f_cv * sp + fl[F_FZ] + fr[F_FZ] - c_z * zd + fz_bar) / p[_MASS]
    return xd, xdd, ad, add, zd, zdd, m_spin, -(fl[F_FX] + fr[F_FX] + f_inner)


@njit(cache=True)
def _rk4_frozen(p: np.ndarray, n_i: float, n_o: float, spin: float, f_d: float, c_z: float,
                z0: float, h: float, n_warm: int, n_keep: int, every: int) -> np.ndarray:
    """Classical RK4 at a frozen load state; returns (n_keep // every, 7) rows
    (t, X, X', alpha, alpha', z, z') after ``n_warm`` discarded steps (start at z0)."""
    y = np.zeros(6)
    y[4] = z0
    k = np.zeros((4, 6))
    out = np.zeros((n_keep // every, 7))
    t = 0.0
    j = 0
    for step in range(n_warm + n_keep):
        for stage in range(4):
            c = 0.0 if stage == 0 else (0.5 if stage < 3 else 1.0)
            yy = y + c * h * k[stage - 1] if stage > 0 else y.copy()
            tt = t + c * h
            r = _rhs(p, yy[0], yy[1], yy[2], yy[3], yy[4], yy[5], n_i, n_o, spin, spin * tt,
                     f_d, c_z)
            for q in range(6):
                k[stage, q] = r[q]
        y = y + h / 6.0 * (k[0] + 2.0 * k[1] + 2.0 * k[2] + k[3])
        t += h
        if step >= n_warm and (step - n_warm) % every == 0 and j < out.shape[0]:
            out[j, 0] = t
            out[j, 1:] = y
            j += 1
    return out


def _roller_rhs(m: DynamicsModel, c: np.ndarray, y: Any, n_i: float, n_o: float,
                spin: float, psi: float, f_d: float = 0.0, c_z: float = 0.0
                ) -> tuple[float, float, float, float, float, float, float]:
    """Python entry to the jitted right-hand side (``c`` = :func:`_params` of ``m``);
    ``y`` = (X, X', alpha, alpha'[, z, z'])."""
    z, zd = (float(y[4]), float(y[5])) if len(y) > 4 else (0.0, 0.0)
    return _rhs(c, float(y[0]), float(y[1]), float(y[2]), float(y[3]), z, zd, float(n_i),
                float(n_o), float(spin), float(psi), float(f_d), float(c_z))


_consts = _params


@dataclass(frozen=True)
class RollerResponse:
    """PV and slip of one roller over the periodic state (paper 003 eqs. 21-25), SI.

    pv_left, pv_right : time-mean P |v| per end face [Pa m/s]; pv_peak_* the maxima.
    slip_speed : time mean of the slip speed of eq. 25, |V_roll| at the inner contact [m/s].
    rolling_slip_speed : the same (kept for existing callers) [m/s].
    surface_slip_speed : time mean of the full sliding-speed magnitude of the inner contact,
        sqrt(V_roll^2 + s_i^2 + (alpha' L_e)^2/12), skew-induced parts included [m/s].
    rib_heat_left, rib_heat_right : time-mean friction power per face [W]: the work rate
        of the rib forces the dynamics apply (Coulomb part mu Q v^2 / sqrt(v^2 + v_s^2)
        with the regularising speed v_s = ``SIGN_REGULARISATION`` of the integrator, i.e.
        mu Q |v| within 0.1 % for |v| > 1 m/s, plus the drag F_G tanh(v_g/v_s) v_g).
    max_skew : max |alpha| [rad].  rib_contact_fraction : share of time with a rib force.
    mean_spin_moment : time-mean rib moment about the roller axis [N m].
    model : "full" | "reduced".  cost_s : CPU time of this process [s] (shared machine).
    n_rhs : right-hand-side calls.
    pv_contact_left, pv_contact_right : mean P |v| over the time the face is in contact
        [Pa m/s] (= pv_* / that face's contact fraction).
    contact_slide_speed : mean |v_i - v_r| (eq. 24) of the faces while in contact [m/s].
    pocket_friction_extra : time-mean cage-bar film friction of the rattling roller beyond
        what the quasi-static model counts at its steady pocket force [N] (orbit mean).
    bar_contact_fraction : share of time a cage bar touches the roller (elastic contact).
    bar_force_mean : time mean of the front + rear bar forces [N].
    """

    pv_left: float
    pv_right: float
    pv_peak_left: float
    pv_peak_right: float
    slip_speed: float
    rolling_slip_speed: float
    rib_heat_left: float
    rib_heat_right: float
    max_skew: float
    rib_contact_fraction: float
    mean_spin_moment: float
    model: str
    cost_s: float
    n_rhs: int
    series: dict[str, np.ndarray] = field(default_factory=dict, repr=False)
    surface_slip_speed: float = 0.0
    pv_contact_left: float = 0.0
    pv_contact_right: float = 0.0
    contact_slide_speed: float = 0.0
    pocket_friction_extra: float = 0.0
    bar_contact_fraction: float = 0.0
    bar_force_mean: float = 0.0

    @property
    def pv(self) -> float:
        """Larger of the two end faces' mean PV [Pa m/s]."""
        return max(self.pv_left, self.pv_right)

    @property
    def rib_heat(self) -> float:
        """Mean rib friction heat of one roller, both faces [W]."""
        return self.rib_heat_left + self.rib_heat_right


def _post(m: DynamicsModel, t: np.ndarray, x: np.ndarray, xd: np.ndarray, a: np.ndarray,
          ad: np.ndarray, spin: np.ndarray, z: np.ndarray | None = None,
          zd: np.ndarray | None = None, steady_pocket: Any = 0.0) -> dict[str, np.ndarray]:
    """PV, heat, slip and cage-bar forces along a sampled trajectory (exact sign of eq. 13).
    ``steady_pocket``: the quasi-static pocket force F_d [N] of the trajectory (scalar or
    per sample) for the extra pocket friction."""
    g = m.geom
    z = np.zeros_like(t) if z is None else z
    zd = np.zeros_like(t) if zd is None else zd
    _, _, front, rear = bar_forces(z, zd, a, 0.5 * g.roller_length, m.pocket_clearance,
                                   m.pocket_stiffness, m.pocket_viscosity,
                                   0.5 * g.roller_diameter, m.squeeze_floor)
    elastic = bar_forces(z, 0.0, a, 0.5 * g.roller_length, m.pocket_clearance,
                         m.pocket_stiffness, 0.0, 0.5 * g.roller_diameter, m.squeeze_floor)
    f_extra = 0.0
    # without the pocket DOF the roller is held centred: its bar force is not the cage's
    # reaction to F_d, so no extra friction is derived from it
    if m.pocket_dof and m.pocket_viscosity > 0.0 and m.pocket_length > 0.0:
        fd_ss = np.broadcast_to(np.asarray(steady_pocket, float), t.shape)
        f_extra = extra_pocket_friction(front - rear, t, spin, fd_ss, g.roller_diameter,
                                        m.pocket_length, m.pocket_viscosity,
                                        m.pocket_clearance)
    rf = rib_forces(g, a, x, inner_speed=m.inner_speed, cage_speed=m.cage_speed,
                    roller_spin=spin, skew_rate=ad, axial_speed=xd,
                    friction_coefficient=m.rib_friction,
                    mixture_viscosity=m.mixture_viscosity, smooth_sign=SIGN_REGULARISATION)
    wc = m.cage_speed
    u_i = (m.inner_speed - wc) * 0.5 * g.inner_raceway_diameter
    v_roll = u_i - spin * 0.5 * g.roller_diameter
    s_ax = -u_i * np.sin(a) - xd
    slip = np.sqrt(v_roll**2 + s_ax**2 + (ad * m.effective_length) ** 2 / 12.0)
    return {"pv_left": rf.pv_left, "pv_right": rf.pv_right, "heat_left": rf.heat_left,
            "heat_right": rf.heat_right, "slip": slip, "v_roll": np.abs(v_roll),
            "contact": (rf.normal_left + rf.normal_right) > 0, "skew": a,
            "contact_left": (rf.normal_left > 0).astype(float),
            "contact_right": (rf.normal_right > 0).astype(float),
            "slide_in_contact": (np.where(rf.normal_left > 0, rf.slide_speed_left, 0.0)
                                 + np.where(rf.normal_right > 0, rf.slide_speed_right, 0.0)),
            "spin_moment": rf.spin_moment, "tangential_force": rf.tangential_force, "t": t,
            "bar_force": front + rear,
            "bar_contact": ((elastic[2] + elastic[3]) > 0).astype(float),
            "pocket_extra": np.full(t.shape, f_extra)}


def _mean(v: np.ndarray, t: np.ndarray) -> float:
    span = t[-1] - t[0]
    return float(np.trapezoid(v, t) / span) if span > 0 else float(np.mean(v))


def simulate_full(m: DynamicsModel, *, n_orbits: float = 2.0, warmup_periods: float = 3.0,
                  rtol: float = 1e-6, samples_per_period: int = 64,
                  start_azimuth: float = 0.0, spin_dof: bool = False) -> RollerResponse:
    """Integrate X, alpha, z (pocket) and psi of one roller over ``n_orbits`` orbits
    (Radau), the load state (raceway loads, spin, quasi-static pocket force) following the
    azimuth.

    ``spin_dof=False`` (default): the spin follows the orbit's spins of the model (for a
    coupled model, :func:`couple_spins`, the quasi-static balance of the raceway, pocket
    and mean rib moments). ``spin_dof=True`` adds omega_r as a degree of freedom,
    J_p omega_r' = -k (omega_r - omega(phi)) - M_bias(phi) + M_rib,x(t), with k the spin
    stiffness of the quasi-static traction model: for unloaded rollers J_p/k is ~13 ms,
    three orbits at the base case, so that option needs many more orbits to settle.
    The first ``warmup_periods`` spin periods are integrated and discarded; statistics
    are taken over the following ``n_orbits`` orbits. ConvergenceError if the integrator
    fails.
    """
    t0 = time.process_time()
    n_calls = [0]
    g = m.geom
    c = _params(m)

    # state: X, X', alpha, alpha', z, z', psi (, omega_r with spin_dof)
    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        n_calls[0] += 1
        phi = start_azimuth + m.cage_speed * t
        n_i, n_o, w_qs = m.at(phi)
        w = y[7] if spin_dof else w_qs
        k = m.stiffness_at(phi)
        d = _roller_rhs(m, c, y, n_i, n_o, w, y[6], m.pocket_force_at(phi),
                        m.circumferential_damping(k))
        if not spin_dof:
            return np.array([d[0], d[1], d[2], d[3], d[4], d[5], w])
        wdot = (-k * (y[7] - w_qs) - m.bias_at(phi) + d[6]) / m.polar_inertia
        return np.array([d[0], d[1], d[2], d[3], d[4], d[5], w, wdot])

    _, _, w0 = m.at(start_azimuth)
    f0 = m.pocket_force_at(start_azimuth)
    z0 = math.copysign(0.5 * m.pocket_clearance, f0) if m.pocket_dof else 0.0
    period = 2.0 * math.pi / max(abs(w0), 1.0)
    t_warm = warmup_periods * period
    t_end = t_warm + n_orbits * 2.0 * math.pi / m.cage_speed
    n_out = int(samples_per_period * (t_end - t_warm) / period) + 2
    t_eval = np.linspace(t_warm, t_end, n_out)
    n_y = 8 if spin_dof else 7
    atol = np.array([1e-9, 1e-6, 1e-7, 1e-3, 1e-9, 1e-6, 1e-6, 1e-2])[:n_y]
    y0 = np.array([0.0, 0.0, 0.0, 0.0, z0, 0.0, 0.0, w0])[:n_y]
    sol = solve_ivp(rhs, (0.0, t_end), y0,
                    method="Radau", rtol=rtol, atol=atol, t_eval=t_eval,
                    max_step=period / 8.0)
    if not sol.success:
        raise ConvergenceError("roller_dynamics.full", float("nan"), sol.message,
                               {"t": sol.t[-1] if sol.t.size else 0.0})
    y = sol.y
    phis = start_azimuth + m.cage_speed * sol.t
    spin = (y[7] if spin_dof else np.array([m.at(p)[2] for p in phis]))
    post = _post(m, sol.t, y[0], y[1], y[2], y[3], spin, y[4], y[5],
                 np.array([m.pocket_force_at(p) for p in phis]))
    return _response(post, "full", time.process_time() - t0, n_calls[0], g)


def _response(post: dict[str, np.ndarray], model: str, cost: float, n_rhs: int,
              g: RibGeometry, weights: list[tuple[float, dict]] | None = None
              ) -> RollerResponse:
    if weights is None:
        weights = [(1.0, post)]
    keys = ("pv_left", "pv_right", "heat_left", "heat_right", "slip", "v_roll",
            "spin_moment", "contact_left", "contact_right", "slide_in_contact",
            "pocket_extra", "bar_contact", "bar_force")
    mean = {k: sum(w * _mean(p[k], p["t"]) for w, p in weights) for k in keys}
    contact = sum(w * _mean(p["contact"].astype(float), p["t"]) for w, p in weights)
    f_l, f_r = mean["contact_left"], mean["contact_right"]
    return RollerResponse(
        pv_contact_left=mean["pv_left"] / f_l if f_l > 0 else 0.0,
        pv_contact_right=mean["pv_right"] / f_r if f_r > 0 else 0.0,
        contact_slide_speed=(mean["slide_in_contact"] / (f_l + f_r)
                             if f_l + f_r > 0 else 0.0),
        pv_left=mean["pv_left"], pv_right=mean["pv_right"],
        pocket_friction_extra=mean["pocket_extra"], bar_contact_fraction=mean["bar_contact"],
        bar_force_mean=mean["bar_force"],
        pv_peak_left=max(float(np.max(p["pv_left"])) for _, p in weights),
        pv_peak_right=max(float(np.max(p["pv_right"])) for _, p in weights),
        slip_speed=mean["v_roll"], rolling_slip_speed=mean["v_roll"],
        surface_slip_speed=mean["slip"],
        rib_heat_left=mean["heat_left"], rib_heat_right=mean["heat_right"],
        max_skew=max(float(np.max(np.abs(p["skew"]))) for _, p in weights),
        rib_contact_fraction=contact, mean_spin_moment=mean["spin_moment"],
        model=model, cost_s=cost, n_rhs=n_rhs,
        series={k: v for k, v in weights[0][1].items()} if model == "full" else {})


def load_states(m: DynamicsModel, decimals: int = 6
                ) -> list[tuple[float, float, float, float, float, float]]:
    """Distinct (N_i, N_o, omega, weight, k_omega, F_d) states of the orbit (weights sum
    to 1; k_omega the spin stiffness [N m s] and F_d the quasi-static pocket force [N] of the
    state's first roller)."""
    states: dict[tuple[float, float, float], list[int]] = {}
    for j, (n_i, n_o, w) in enumerate(zip(m.inner_load, m.outer_load, m.spin, strict=True)):
        key = (round(float(n_i), 3), round(float(n_o), 3), round(float(w), 3))
        states.setdefault(key, []).append(j)
    n = len(m.azimuth)
    out = []
    for idx in states.values():
        j = idx[0]
        k = (float(m.spin_k[j]) if m.spin_k is not None
             else m.spin_stiffness(float(m.inner_load[j]), float(m.outer_load[j])))
        f_d = float(m.pocket_force[j]) if m.pocket_force is not None else 0.0
        out.append((float(m.inner_load[j]), float(m.outer_load[j]), float(m.spin[j]),
                    len(idx) / n, k, f_d))
    return out


def simulate_reduced(m: DynamicsModel, *, periods: float = 20.0, warmup_periods: float = 3.0,
                     steps_per_period: int = 400, samples_per_period: int = 100
                     ) -> RollerResponse:
    """Skew and axial motion at the orbit's distinct frozen load states (see module notes).

    Each state is integrated with classical RK4 at a fixed step of 1/``steps_per_period``
    spin period, and at most 1/omega_c with omega_c the rib contact's axial frequency at a
    20 um approach (~6e5 rad/s: h <= 1.6 us; RK4 is stable to h omega < 2.8) for
    ``warmup_periods`` + ``periods`` spin periods; statistics over the last ``periods``,
    averaged with the states' orbit shares. The mean rib spin moment changes the spin
    quasi-statically by M / k_omega before the slip is evaluated.
    """
    t0 = time.process_time()
    n_calls = 0
    weights = []
    c = _params(m)
    for n_i, n_o, w_qs, share, k, f_d in load_states(m):
        post, calls = _state_post(m, c, n_i, n_o, w_qs, periods, warmup_periods,
                                  steps_per_period, samples_per_period, k, f_d)
        n_calls += calls
        weights.append((share, post))
    return _response(weights[0][1], "reduced", time.process_time() - t0, n_calls, m.geom,
                     weights)


def simulate(m: DynamicsModel, model: str = "reduced", **options: Any) -> RollerResponse:
    """Dispatch to :func:`simulate_full` or :func:`simulate_reduced`."""
    if model == "full":
        return simulate_full(m, **options)
    if model == "reduced":
        return simulate_reduced(m, **options)
    raise InputError("model", model, ("full", "reduced"))


def _state_post(m: DynamicsModel, c: np.ndarray, n_i: float, n_o: float, w: float,
                periods: float, warmup_periods: float, steps_per_period: int,
                samples_per_period: int, k: float = 0.0, f_d: float = 0.0
                ) -> tuple[dict[str, np.ndarray], int]:
    """RK4 run of the skew/axial/pocket motion at one frozen load state and spin ``w``
    [rad/s] with spin stiffness ``k`` [N m s] (raceway damping of the pocket motion) and
    quasi-static pocket force ``f_d`` [N]: (post-processed samples, right-hand-side calls).
    ConvergenceError if it diverges."""
    omega_c = math.sqrt(1.5 * m.geom.stiffness * math.sqrt(20e-6) / m.roller_mass)
    h_max = 1.0 / omega_c
    period = 2.0 * math.pi / max(abs(w), 1.0)
    n_per = max(steps_per_period, int(math.ceil(period / h_max)))
    h = period / n_per
    n_warm = int(round(warmup_periods * n_per))
    n_keep = int(round(periods * n_per))
    every = max(1, n_per // samples_per_period)
    z0 = math.copysign(0.5 * m.pocket_clearance, f_d) if m.pocket_dof else 0.0
    rows = _rk4_frozen(c, float(n_i), float(n_o), float(w), float(f_d),
                       m.circumferential_damping(k), z0, h, n_warm, n_keep, every)
    if not np.all(np.isfinite(rows)):
        raise ConvergenceError("roller_dynamics.reduced", float("inf"),
                               "RK4 diverged (reduce the step: steps_per_period)",
                               {"state": (n_i, n_o, w)})
    spin = np.full(rows.shape[0], w)
    post = _post(m, rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3], rows[:, 4], spin,
                 rows[:, 5], rows[:, 6], f_d)
    return post, 4 * (n_warm + n_keep)


# re-exports (split modules; names kept importable from here)
from .roller_dynamics_coupling import (  # noqa: E402
    _race_eval,
    couple_spins,
    lagged_spins,
    race_spin_stiffness,
)
from .roller_dynamics_map import MAP_PARAMETERS, PAPER003_BASE, pv_slip_map  # noqa: E402

__all__ = [
    "MAP_PARAMETERS",
    "PAPER003_BASE",
    "DynamicsModel",
    "RollerResponse",
    "Unbalance",
    "build_model",
    "chamfer_unbalance",
    "couple_spins",
    "lagged_spins",
    "load_states",
    "pv_slip_map",
    "race_spin_stiffness",
    "simulate",
    "simulate_full",
    "simulate_reduced",
    "_race_eval",
]
