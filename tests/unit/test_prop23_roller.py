"""Property tests, round 5: invariants of the roller skidding solve (``skidding.solve`` on a
cylindrical roller bearing; :mod:`thermobearing.skidding.roller`, not edited here).

- energy balance: the shaft power ``shaft_torque * omega`` equals the dissipation
  ``power_loss["total"]`` (raceway Couette C V and rolling Q_x |u_e|, pocket friction, the
  oil drag, a constant cage drag torque T_c omega_c) in a converged state: the roller moment
  balances (paper 000 eqs. 28/31), the orbital balances with drag (paper 002 eqs. 21/24) and
  the cage equation (paper 000 eq. 32) telescope to the inner-race torque (the result's
  docstring promises 1e-6 relative);
- rigid-roller kinematics: a roller has one surface speed omega_r D/2 at both raceways, the
  inner race moves at (omega - omega_c) r_i and the outer race at omega_c (d_m + D)/2 in the
  cage frame, so u_e -+ V/2 give them (paper 000 eqs. 5-8, V = u_race - u_roller);
- mirror symmetry of the load distribution about the load line: a radial load on a ring
  with a roller under it gives Q(psi) = Q(-psi) (Harris & Kotzalas 2006, ch. 7).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.errors import ConvergenceError, ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import solve
from thermobearing.state import OilSupply

ROLLER = {name: load_bearing(name) for name in ("NU214", "D1842926")}
OIL = {"NU214": load_lubricant("PAPER000_OIL"), "D1842926": load_lubricant("OIL_4109")}


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(ROLLER)),
       log_rpm=st.floats(math.log(100.0), math.log(15000.0)),
       log_fr=st.floats(math.log(100.0), math.log(20000.0)), t_c=st.floats(20.0, 120.0),
       cage_torque=st.one_of(st.just(0.0), st.floats(0.0, 0.3)),
       unloaded=st.sampled_from(["moment_balance", "outer_pure_rolling"]),
       oil_drag=st.booleans())
def test_roller_state_balances_energy_kinematics_and_symmetry(name, log_rpm, log_fr, t_c,
                                                               cage_torque, unloaded, oil_drag):
    """Shaft power = power_loss total to 1e-6; one roller surface speed at both raceways and
    the race speeds of the cage frame to 1e-9 of the surface speed; Q(psi) = Q(-psi)."""
    fr, omega = math.exp(log_fr), math.exp(log_rpm) * math.pi / 30.0
    supply = OilSupply("jet", 33 / 60000, t_c + 273.15) if oil_drag else None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        try:
            r = solve(ROLLER[name], OIL[name], omega, fr, 0.0, t_c + 273.15, supply=supply,
                      cage_drag_torque=cage_torque, unloaded_zone=unloaded)
        except ConvergenceError as err:   # allowed, but never silently NaN
            assert not math.isnan(err.residual)
            return
    assert r.converged
    shaft = r.shaft_torque * r.inner_speed
    loss = r.power_loss
    assert shaft > 0.0
    assert abs(loss["total"] - shaft) <= 1e-6 * shaft, (loss, shaft)
    if cage_torque > 0.0:
        assert math.isclose(loss["cage_drag"], cage_torque * r.cage_speed, rel_tol=1e-12)

    d, d_m = r.extras["roller_diameter"], r.extras["pitch_diameter"]
    r_i = r.extras["raceway_radius_inner"]
    scale = omega * r_i
    surface = r.roller_speed * d / 2.0
    for ue, v in ((r.inner_entrainment_speed, r.inner_sliding_speed),
                  (r.outer_entrainment_speed, r.outer_sliding_speed)):
        np.testing.assert_allclose(ue - v / 2.0, surface, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(r.inner_entrainment_speed + r.inner_sliding_speed / 2.0,
                               (r.inner_speed - r.cage_speed) * r_i, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(r.outer_entrainment_speed + r.outer_sliding_speed / 2.0,
                               r.cage_speed * (d_m + d) / 2.0, rtol=0, atol=1e-9 * scale)

    psi = np.mod(r.azimuth + math.pi, 2.0 * math.pi) - math.pi
    order = np.argsort(psi)
    mirrored = np.interp(-psi, psi[order], r.inner_load[order], period=2.0 * math.pi)
    np.testing.assert_allclose(mirrored, r.inner_load, rtol=0, atol=1e-9 * r.inner_load.max())
