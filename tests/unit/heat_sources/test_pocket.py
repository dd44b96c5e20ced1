"""Pocket source: paper 002 eq. 19 by hand, friction blend, bad coefficients."""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.heat_sources import pocket

from .conftest import make_context, uniform_state


def test_eq19_by_hand(qj1044, vg46, race_control_state):
    # Q_bp = sum omega_r D f_bp / 2 with f = mu F: 20 balls, F = 100 N, mu = 0.1,
    # omega_r = -500 rad/s: each 500 * D * 10 / 2
    op, _ = race_control_state
    z = qj1044.n_elements
    ks = uniform_state(z, spin=-500.0, pocket_force=100.0)
    ctx = make_context(qj1044, vg46, op, ks, options={"pocket_friction": {
        "friction_coefficient": 0.1}})
    r = pocket.pocket_friction(ctx)
    assert r.total == pytest.approx(z * 500 * qj1044.ball_diameter * 0.1 * 100 / 2, rel=1e-12)
    assert r.power_by_role["elements"] == pytest.approx(0.5 * r.total)
    assert r.components == {"ball pocket": pytest.approx(r.total)}
    assert r.force_pairs[0].power == pytest.approx(r.total, rel=1e-12)


def test_race_control_gives_no_pocket_heat(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    assert pocket.pocket_friction(make_context(qj1044, vg46, op, ks)).total == 0.0


def test_blend():
    np.testing.assert_allclose(pocket.pocket_friction_coefficient([0.5, 2.0, 5.0], 0.1, 0.01),
                               [0.1, 0.055, 0.01])


@pytest.mark.parametrize("mu", [-0.1, 1.01])
def test_friction_outside_unit_interval(qj1044, vg46, race_control_state, mu):
    op, _ = race_control_state
    ks = uniform_state(qj1044.n_elements, pocket_force=10.0)
    ctx = make_context(qj1044, vg46, op, ks, options={"pocket_friction": {
        "friction_coefficient": mu}})
    with pytest.raises(InputError, match="friction_coefficient"):
        pocket.pocket_friction(ctx)


def test_roller_pocket(vg46):
    # roller bearing NU214 (paper 000): same eq. 19 with the roller diameter
    from thermobearing.geometry import load_bearing
    from thermobearing.state import OperatingPoint

    nu214 = load_bearing("NU214")
    z = nu214.n_elements
    ks = uniform_state(z, spin=-1000.0, pocket_force=20.0)
    op = OperatingPoint(inner_speed=523.6, radial_load=150.0)
    ctx = make_context(nu214, vg46, op, ks, options={"pocket_friction": {
        "friction_coefficient": 0.05}})
    r = pocket.pocket_friction(ctx)
    assert r.components == {"roller pocket": pytest.approx(
        z * 0.05 * 20.0 * 1000.0 * nu214.roller_diameter / 2)}


def test_steady_ratio_pure_rolling():
    # pure rolling (outer ring fixed): omega_r = omega_i (D_m / 2D)(1 - gamma^2),
    # omega_c = omega_i (1 - gamma)/2, so k = mu omega_r D / (omega_c D_m) = mu (1 + gamma)
    d, dm, mu, wi = 0.034925, 0.28, 0.3, 188.5
    gamma = d / dm
    wr = wi * dm / (2 * d) * (1 - gamma**2)
    wc = wi * (1 - gamma) / 2
    assert pocket.steady_pocket_drag_ratio(mu, wr, d, wc, dm) == pytest.approx(
        mu * (1 + gamma), rel=1e-12)
    # QJ1044 at the over-skidding peak (validation case paper002_loss_ratios SOURCE.md):
    # mu 0.3, |omega_r| 911 rad/s, omega_c 92.7 rad/s -> 0.3 * 911 * 0.034925 / (92.7 * 0.28)
    assert pocket.steady_pocket_drag_ratio(0.3, -911.0, d, 92.7, dm) == pytest.approx(
        0.3 * 911 * 0.034925 / (92.7 * 0.28), rel=1e-12)
    with pytest.raises(InputError, match="cage_speed"):
        pocket.steady_pocket_drag_ratio(0.3, 911.0, d, 0.0, dm)


def test_steady_identity_with_eq19(qj1044, vg46, race_control_state):
    # all pockets push one way: the cage drag power they carry is sum F (D_m/2) omega_c and
    # eq. 19's heat is k times that (k from steady_pocket_drag_ratio)
    op, _ = race_control_state
    z = qj1044.n_elements
    ks = uniform_state(z, spin=-900.0, pocket_force=2.0)
    ctx = make_context(qj1044, vg46, op, ks, options={"pocket_friction": {
        "friction_coefficient": 0.3}})
    r = pocket.pocket_friction(ctx)
    wc = ks.cage_speed
    drag_power = z * 2.0 * 0.5 * qj1044.pitch_diameter * abs(wc)
    k = pocket.steady_pocket_drag_ratio(0.3, 900.0, qj1044.ball_diameter, wc,
                                        qj1044.pitch_diameter)
    assert r.total == pytest.approx(k * drag_power, rel=1e-12)
    assert r.details["normal_force_sum"] == pytest.approx(2.0 * z)
    assert r.details["sliding_over_cage_speed"] == pytest.approx(
        900.0 * 0.5 * qj1044.ball_diameter / (0.5 * qj1044.pitch_diameter * abs(wc)))


def test_circulation():
    assert pocket.pocket_circulation([-2.0, -2.0, -2.0]) == pytest.approx(1.0)
    # 8 kN point of the QJ1044 (SOURCE.md): some balls brake the cage, others push it
    assert pocket.pocket_circulation([3.0, -1.0, -1.0, -1.0, -1.0, -1.0]) == pytest.approx(4.0)
    assert pocket.pocket_circulation([1.0, -1.0]) == float("inf")
    assert pocket.pocket_circulation([0.0, 0.0]) == 1.0


def test_shear_damping_against_one_dimensional_integrals():
    # Omega along a: |v_t|^2 = Omega^2 (x^2 cos^2 phi + rho^2 sin^2 phi), integrated over phi:
    # C_aa = pi eta R_p R^2 int dx / h;  Omega along r (the pocket axis): |v_t| = Omega rho,
    # C_rr = 2 pi eta R_p int rho^2 / h dx  (h = R + c - sqrt(R^2 - x^2); derived by hand)
    import math

    from scipy.integrate import quad

    eta, d, c, lo, hi = 0.05, 0.034925, 0.3e-3, -8e-3, 10.2e-3
    r = d / 2

    def h(x):
        return r + c - math.sqrt(r * r - x * x)

    caa = math.pi * eta * (r + c) * r * r * quad(lambda x: 1 / h(x), lo, hi, points=[0.0])[0]
    crr = 2 * math.pi * eta * (r + c) * quad(lambda x: (r * r - x * x) / h(x), lo, hi,
                                             points=[0.0])[0]
    cm = pocket.pocket_shear_damping(eta, d, c, lo, hi)
    assert cm[0, 0] == pytest.approx(caa, rel=1e-8)
    assert cm[2, 2] == pytest.approx(caa, rel=1e-8)  # a and t equivalent about the bore axis
    assert cm[1, 1] == pytest.approx(crr, rel=1e-8)
    assert np.max(np.abs(cm - np.diag(np.diag(cm)))) < 1e-12 * cm[1, 1]
    # QJ1044 peak (SOURCE.md): Omega = (-905.7, 101.3, -15.6) rad/s, eta 0.0504 -> ~19 W
    om = np.array([-905.66, 101.34, -15.57])
    cq = pocket.pocket_shear_damping(0.0504, d, c, lo, hi)
    assert om @ cq @ om == pytest.approx(18.9, abs=0.05)
    with pytest.raises(InputError, match="section"):
        pocket.pocket_shear_damping(eta, d, c, 1e-3, -1e-3)
