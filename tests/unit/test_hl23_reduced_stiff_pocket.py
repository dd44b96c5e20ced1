"""Session 23 (HL): the reduced roller dynamics (paper 003, one roller at frozen load states)
stopped with "RK4 diverged" on the NU 214 made NJ-type of the user tour (ISO VG46, 60 degC,
2000 r/min, 8 kN, any unbalance mass). Cause: the raceways' damping of the roller's slide in
its pocket, c_z = k_omega/(D/2)^2, is stiff on the loaded rollers there (k_omega = 9.3 N m s,
c_z/m = 1.65e7 1/s against the rib contact's step of 4.2 us: h c_z/m = 70, RK4 is stable to
2.8 and its refinements reached 5.2). The integrator is now ETDRK4 with that linear term
exact (roller_dynamics_integrate, module notes)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing import load_lubricant, load_scene
from thermobearing.geometry import load_bearing
from thermobearing.simulation import Simulation
from thermobearing.skidding.roller_dynamics import build_model, simulate_reduced
from thermobearing.skidding.roller_dynamics_integrate import (
    _etd_frozen,
    _state_post,
    explicit_rate,
    pocket_rate,
)
from thermobearing.skidding.roller_dynamics_model import load_states
from thermobearing.skidding.roller_dynamics_rhs import _params, _rhs

#: the bearing and oil of the user tour's rig (tests/unit/test_toure23_rig.py)
SCENE = """title = "NJ 214 rig"
[[bearings]]
name = "test"
preset = "NU214"
[bearings.overrides]
ribbed_ring = "both"
end_face_crown_radius = "500 mm"
rib_angle = "0.5 deg"
rib_height = "3 mm"
axial_clearance = "0.05 mm"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "25 degC"
[schedule]
radial_load = "8 kN"
axial_load = "0.5 kN"
step_duration = "5 min"
steps = [{ speed = "2000 rpm" }]
[models]
kinematics = "race_control"
heat_sources = ["raceway_traction", "rib_friction"]
[network]
template = "four_node_paper002"
parameters = { housing_outer_diameter = "180 mm", housing_length = "50 mm" }
"""
NJ214_SPEED = 2000.0 * math.pi / 30.0
NJ214_LOAD = 8000.0
NJ214_TEMPERATURE = 333.15


def _rk4_reference(p, n_i, n_o, spin, f_d, c_z, z0, h, n_steps):
    """Classical RK4 of the same equations with the pocket damping inside the right-hand
    side (the integrator before the fix), in Python: the state after ``n_steps``."""
    y = np.zeros(6)
    y[4] = z0
    t = 0.0

    def f(tt, yy):
        return np.array(_rhs(p, *yy, n_i, n_o, spin, spin * tt, f_d, c_z)[:6])

    for _ in range(n_steps):
        k1 = f(t, y)
        k2 = f(t + 0.5 * h, y + 0.5 * h * k1)
        k3 = f(t + 0.5 * h, y + 0.5 * h * k2)
        k4 = f(t + h, y + h * k3)
        y = y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        t += h
    return y


@pytest.fixture(scope="module")
def crb():
    """Paper 003's bearing without unbalance, spins uncoupled (a cheap model for the
    kernel tests): its parameter vector and most loaded state."""
    m = build_model(load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699"),
                    20000.0 * math.pi / 30.0, 3000.0, 0.0, temperature=353.15)
    n_i, n_o, w, _, k, f_d = max(load_states(m), key=lambda s: s[0])
    return m, _params(m), n_i, n_o, w, k, f_d


@pytest.fixture(scope="module")
def nj214():
    """The user tour's NJ 214 (tests/unit/test_toure23_rig.py) at 2000 r/min, 8 kN, 60 degC
    with 0.11 g of unbalance: the bearing and its roller dynamics model (the rib coupling
    of the spins runs the reduced integration too, and diverged there before)."""
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "rig.toml"
        path.write_text(SCENE)
        sim = Simulation(load_scene(path), progress=False)
    bearing = sim.bearings[0]
    bearing = getattr(bearing, "bearing", bearing)
    m = build_model(bearing, sim.lubricant, NJ214_SPEED, NJ214_LOAD, 0.11e-3,
                    temperature=NJ214_TEMPERATURE)
    return bearing, sim.lubricant, m


def test_without_a_linear_rate_the_kernel_is_classical_rk4(crb):
    m, p, n_i, n_o, w, _, f_d = crb
    z0 = 0.5 * m.pocket_clearance
    h = 1e-6
    rows = _etd_frozen(p, n_i, n_o, w, f_d, 0.0, z0, h, 299, 1, 1)   # after step 300
    ref = _rk4_reference(p, n_i, n_o, w, f_d, 0.0, z0, h, 300)
    assert rows.shape == (1, 7) and rows[0, 0] == pytest.approx(300 * h, rel=1e-12)
    np.testing.assert_allclose(rows[0, 1:], ref, rtol=1e-10, atol=1e-14)


def test_the_exact_damping_agrees_with_rk4_at_a_step_rk4_resolves(crb):
    """c_z/m = 2e5 1/s at h = 0.1 us (h c_z/m = 0.02): ETDRK4 with the damping exact and
    RK4 with it in the right-hand side agree to their truncation error."""
    m, p, n_i, n_o, w, _, f_d = crb
    lam = -2.0e5
    z0 = 0.5 * m.pocket_clearance
    h = 1e-7
    rows = _etd_frozen(p, n_i, n_o, w, f_d, lam, z0, h, 399, 1, 1)   # after step 400
    ref = _rk4_reference(p, n_i, n_o, w, f_d, -lam * m.roller_mass, z0, h, 400)
    scale = np.array([1e-6, 1e-3, 1e-4, 1.0, 1e-6, 1e-3])   # m, m/s, rad, rad/s
    assert np.max(np.abs(rows[0, 1:] - ref) / scale) < 1e-6
    assert abs(ref[5]) > 1e-6    # the pocket slide moved: the comparison is not of zeros


def test_a_damping_rk4_cannot_take_at_the_step_stays_bounded_and_relaxes(crb):
    """h c_z/m = 70 (the NJ 214 point's most loaded roller): RK4 with the damping in the
    right-hand side blows up; the exact treatment relaxes the slide speed to the quasi-static
    F/c_z, below the free-rattle speed."""
    m, p, n_i, n_o, w, _, f_d = crb
    h = 4.2e-6
    lam = -70.0 / h
    z0 = 0.5 * m.pocket_clearance
    with np.errstate(all="ignore"):
        ref = _rk4_reference(p, n_i, n_o, w, f_d, -lam * m.roller_mass, z0, h, 60)
    assert not np.all(np.isfinite(ref)) or np.max(np.abs(ref)) > 1e6
    rows = _etd_frozen(p, n_i, n_o, w, f_d, lam, z0, h, 0, 2000, 100)
    assert np.all(np.isfinite(rows))
    f_scale = abs(f_d) + m.unbalance.mass * m.unbalance.radius * w * w + 1.0
    assert np.max(np.abs(rows[:, 6])) < 10.0 * f_scale / (-lam * m.roller_mass)


def test_pocket_rate_and_explicit_rate(crb):
    m, _, n_i, n_o, _, k, _ = crb
    assert pocket_rate(m, k) == pytest.approx(-m.circumferential_damping(k) / m.roller_mass)
    from dataclasses import replace

    assert pocket_rate(replace(m, pocket_dof=False), k) == 0.0
    omega_c = math.sqrt(1.5 * m.geom.stiffness * math.sqrt(20e-6) / m.roller_mass)
    assert explicit_rate(m, n_i, n_o) == pytest.approx(omega_c)   # the rib contact rules
    heavy = 1e3 * (n_i + n_o)                                       # the traction rules
    assert explicit_rate(m, heavy, 0.0) == pytest.approx(
        heavy * m.traction_limit / (m.traction_speed * m.roller_mass))


def test_nj214_point_stiff_state_is_what_diverged(nj214):
    """The most loaded state's pocket damping against the step the explicit part takes."""
    _, _, m = nj214
    n_i, n_o, _, _, k, _ = max(load_states(m), key=lambda s: s[0])
    h = 1.0 / explicit_rate(m, n_i, n_o)
    assert -pocket_rate(m, k) * h > 10.0    # far beyond RK4's 2.8


def test_nj214_point_runs_and_is_step_converged(nj214):
    _, _, m = nj214
    r = simulate_reduced(m)
    fine = simulate_reduced(m, steps_per_period=16000)
    assert np.isfinite([r.pv_left, r.pv_right, r.slip_speed, r.rib_heat_left,
                        r.rib_heat_right]).all()
    assert r.slip_speed > 0.0 and r.rib_heat_left > 0.0 and r.rib_heat_right > 0.0
    for name in ("slip_speed", "rib_heat_left", "rib_heat_right", "pv_left", "pv_right"):
        assert getattr(r, name) == pytest.approx(getattr(fine, name), rel=1e-6, abs=1.0), name


def test_nj214_point_every_state_runs_at_the_given_step(nj214):
    """No state needs the divergence refinements any more."""
    _, _, m = nj214
    c = _params(m)
    for n_i, n_o, w, _, k, f_d in load_states(m):
        post, _ = _state_post(m, c, n_i, n_o, w, 5.0, 1.0, 400, 100, k, f_d)
        assert np.all(np.isfinite(post["t"]))


def test_nj214_rib_heat_of_the_reduced_source_path(nj214):
    """The rib_friction source's reduced path (rib_dynamics_heat, two temperature nodes)."""
    from thermobearing.skidding.roller_dynamics_heat import rib_dynamics_heat

    bearing, lub, _ = nj214
    out = rib_dynamics_heat(bearing, lub, NJ214_SPEED, NJ214_LOAD, NJ214_TEMPERATURE,
                            0.11e-3, model="reduced")
    assert math.isfinite(out.heat_left) and out.heat_left > 0.0
    assert math.isfinite(out.slip_speed) and out.slip_speed > 0.0
