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
  represents), integrated with a numba-jitted fixed-step ETDRK4: the pocket slide's
  raceway damping exact, RK4 on the rest (h <= 1/omega of the rib contact's axial mode
  and of the raceway traction's damping rates; the NJ 214 rig point at 2000 r/min, 8 kN
  in ISO VG46 diverged under plain RK4: module notes of
  :mod:`~thermobearing.skidding.roller_dynamics_integrate`). Base case (0.11 g): PV -5.5 %,
  slip 0.0 % against the full model at 1/57 of its cost (8.0 s vs 0.14 s wall; 37 s vs
  0.56 s on a loaded 2-core machine), both on the same coupled spins; the coupling
  itself costs ~1 s (validation case ``paper003_pv_slip_trends``).
* roller spins: ``spin="skidding"`` (default) starts from the quasi-static solver, whose
  unloaded rollers skid (about half the rolling speed at the base case), then couples;
  ``spin="rolling"`` puts every roller at its pure-rolling spin, uncoupled (a sensitivity
  switch, see the case's SOURCE.md); ``spin="lagged"`` takes the skidding (coupled) spins
  through the spin inertia along the orbit (:func:`lagged_spins`).
* spin stiffness k_omega (the full model's ``spin_dof``): -dT/d omega_r of the raceway and
  pocket moment T of the same quasi-static traction model (:func:`race_spin_stiffness`):
  ~6e-5 N m s for the loaded and ~5e-7 N m s for the unloaded rollers at the base case.

Modules (one job each; their names are re-exported here):
:mod:`~thermobearing.skidding.roller_dynamics_model` (the model record, unbalance, load
states), :mod:`~thermobearing.skidding.roller_dynamics_setup` (:func:`build_model`),
:mod:`~thermobearing.skidding.roller_dynamics_rhs` (equations of motion, compiled),
:mod:`~thermobearing.skidding.roller_dynamics_integrate` (the full and reduced integrators),
:mod:`~thermobearing.skidding.roller_dynamics_response` (PV, slip, heat: eqs. 21-25),
:mod:`~thermobearing.skidding.roller_dynamics_coupling` (spin-cage coupling),
:mod:`~thermobearing.skidding.roller_dynamics_map` (PV/slip maps); beside them
:mod:`~thermobearing.skidding.roller_dynamics_pocket` (cage bars) and
:mod:`~thermobearing.skidding.roller_dynamics_coupled` (all rollers and the cage together).
"""

from __future__ import annotations

# re-exports: every name importable from here before the split stays importable
from ..rib import DEFAULT_RIB_FRICTION, SIGN_REGULARISATION  # noqa: F401
from .roller_dynamics_coupling import (
    _race_eval,
    couple_spins,
    lagged_spins,
    race_spin_stiffness,
)
from .roller_dynamics_integrate import (  # noqa: F401
    _etd_frozen,
    _state_post,
    simulate,
    simulate_full,
    simulate_reduced,
)
from .roller_dynamics_map import MAP_PARAMETERS, PAPER003_BASE, pv_slip_map
from .roller_dynamics_model import (  # noqa: F401
    DEFAULT_OIL_FRACTION,
    DEFAULT_POCKET_STIFFNESS,
    DEFAULT_TRACTION_LIMIT,
    DEFAULT_TRACTION_SPEED,
    DynamicsModel,
    Unbalance,
    chamfer_unbalance,
    load_states,
)
from .roller_dynamics_pocket import DEFAULT_SQUEEZE_FLOOR  # noqa: F401
from .roller_dynamics_response import RollerResponse, _mean, _post, _response  # noqa: F401
from .roller_dynamics_rhs import (  # noqa: F401
    _CP,
    _ETA,
    _FG,
    _FLOOR,
    _HL,
    _JT,
    _KC,
    _LARM,
    _MASS,
    _MU,
    _MUE,
    _MUT,
    _NP,
    _OM,
    _PDOF,
    _RAD,
    _S0,
    _SREG,
    _UI,
    _UO,
    _VEC,
    _WC,
    _XU,
    _axial_share,
    _consts,
    _params,
    _rhs,
    _rhs_ring,
    _roller_rhs,
)
from .roller_dynamics_setup import build_model

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
