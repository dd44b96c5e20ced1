"""Race-control kinematics checked against a direct rigid-body computation."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing import kinematics as kin
from thermobearing.geometry import load_bearing


def _direct(gp: float, ai: float, ao: float, beta: float, omega: float = 1.0):
    """Solve rolling at both contact centres numerically from the contact-point velocities.

    Cage frame: x' axial, z' radial (ball centre at R_c = d_m/2 = D/(2 g') with D = 1),
    ball angular velocity relative to the cage w_R (cos b, 0, -sin b), inner ring at
    (omega - w_m) e_x, outer at -w_m e_x. Unknowns (w_m, w_R) from the two tangential (y')
    no-slip conditions; returns also the spins and rolls about the normal/in-plane axes.
    """
    d = 1.0
    rc = np.array([0.0, 0.0, d / (2 * gp)])
    n_o = np.array([math.sin(ao), 0.0, math.cos(ao)])
    n_i = np.array([math.sin(ai), 0.0, math.cos(ai)])
    r_o, r_i = 0.5 * d * n_o, -0.5 * d * n_i
    axis = np.array([math.cos(beta), 0.0, -math.sin(beta)])
    ex = np.array([1.0, 0.0, 0.0])
    # velocity slip (ball - race) in y' is linear in (w_m, w_R): build the 2x2 system
    def slip(wm: float, wr: float) -> np.ndarray:
        om = wr * axis
        v_o = np.cross(om, r_o)[1] - np.cross(-wm * ex, rc + r_o)[1]
        v_i = np.cross(om, r_i)[1] - np.cross((omega - wm) * ex, rc + r_i)[1]
        return np.array([v_o, v_i])

    b0 = slip(0.0, 0.0)
    a = np.column_stack([slip(1.0, 0.0) - b0, slip(0.0, 1.0) - b0])
    wm, wr = np.linalg.solve(a, -b0)
    om = wr * axis
    t_o = np.array([math.cos(ao), 0.0, -math.sin(ao)])
    t_i = np.array([math.cos(ai), 0.0, -math.sin(ai)])
    s_o = (om + wm * ex) @ n_o
    s_i = (om - (omega - wm) * ex) @ n_i
    ro = (om + wm * ex) @ t_o
    ri = (om - (omega - wm) * ex) @ t_i
    return wm, wr, s_o, s_i, s_o / ro, s_i / ri


CASES = [(0.125, 0.70, 0.70, 0.3), (0.125, 0.9, 0.5, 0.6), (0.26, 0.2, 0.05, 0.1),
         (0.1, 1.0, 0.16, 0.9)]


@pytest.mark.parametrize(("gp", "ai", "ao", "beta"), CASES)
def test_closed_forms_match_direct_computation(gp, ai, ao, beta) -> None:
    csr, spin = kin.rolling_speeds(gp, ai, ao, beta)
    wm, wr, *_ = _direct(gp, ai, ao, beta)
    assert csr == pytest.approx(wm, rel=1e-12)
    assert spin == pytest.approx(wr, rel=1e-12)


def test_equal_angles_csr_independent_of_attitude() -> None:
    # primer section 2.2 identity: a_i = a_o = a -> CSR = (1 - g cos a)/2 for every beta
    gp, a = 0.1247, math.radians(40)
    for beta in np.linspace(-0.5, 1.4, 9):
        csr, _ = kin.rolling_speeds(gp, a, a, beta)
        assert csr == pytest.approx((1 - gp * math.cos(a)) / 2, rel=1e-13)


@pytest.mark.parametrize(("gp", "ai", "ao", "beta"), CASES)
def test_race_control_zero_spin(gp, ai, ao, beta) -> None:
    b_orc = kin.attitude_angle(gp, ai, ao, "outer_race")
    _, _, s_o, _, _, _ = _direct(gp, ai, ao, b_orc)
    assert abs(s_o) < 1e-12
    assert kin.rolling_speeds(gp, ai, ao, b_orc)[0] == pytest.approx(
        kin.race_control_cage_ratio(gp, ai, ao, "outer_race"), rel=1e-12)
    b_irc = kin.attitude_angle(gp, ai, ao, "inner_race")
    _, _, _, s_i, _, _ = _direct(gp, ai, ao, b_irc)
    assert abs(s_i) < 1e-12
    assert kin.rolling_speeds(gp, ai, ao, b_irc)[0] == pytest.approx(
        kin.race_control_cage_ratio(gp, ai, ao, "inner_race"), rel=1e-12)


def test_element_kinematics_spins_match_direct() -> None:
    b = load_bearing("QJ1044")
    w = 1800 * 2 * math.pi / 60
    ai, ao = math.radians(52.0), math.radians(25.0)
    for fn in (kin.outer_race_control, kin.inner_race_control, kin.pure_rolling):
        k = fn(b, w, ai, ao)
        gp = b.ball_diameter / b.pitch_diameter
        wm, wr, s_o, s_i, sr_o, sr_i = _direct(gp, ai, ao, float(k.attitude_angle), w)
        assert k.orbital_speed == pytest.approx(wm, rel=1e-12)
        assert k.element_spin == pytest.approx(wr, rel=1e-12)
        assert k.spin_outer == pytest.approx(s_o, abs=1e-9 * w)
        assert k.spin_inner == pytest.approx(s_i, abs=1e-9 * w)
        assert k.spin_to_roll_outer == pytest.approx(sr_o, abs=1e-12)
        assert k.spin_to_roll_inner == pytest.approx(sr_i, abs=1e-12)
        # primer section 2.4 closed forms of the spin-to-roll ratios
        beta = float(k.attitude_angle)
        assert k.spin_to_roll_outer == pytest.approx(
            math.tan(ao - beta) - gp * math.sin(beta) / math.cos(ao - beta), abs=1e-12)
        assert k.spin_to_roll_inner == pytest.approx(
            math.tan(ai - beta) + gp * math.sin(beta) / math.cos(ai - beta), abs=1e-12)


def test_over_skidding_mechanism_signs() -> None:
    # primer section 5: with a_i > a_o the ORC CSR exceeds the epicyclic value, and a smaller
    # attitude angle raises the CSR further
    gp, ai, ao = 0.125, math.radians(51.8), math.radians(24.6)
    epicyclic = (1 - gp * math.cos(math.radians(40))) / 2
    orc = kin.race_control_cage_ratio(gp, ai, ao, "outer_race")
    assert orc > epicyclic
    assert kin.rolling_speeds(gp, ai, ao, 0.0)[0] > orc


def test_pure_rolling_textbook_ball_spin_and_entrainment() -> None:
    b = load_bearing("SKF6304")
    w = 2000 * 2 * math.pi / 60
    k = kin.pure_rolling(b, w)  # nominal angle 0
    g = 9.525 / 36
    assert k.cage_speed_ratio == pytest.approx((1 - g) / 2, rel=1e-12)
    assert abs(k.element_spin) == pytest.approx((1 - g**2) / (2 * g) * w, rel=1e-12)
    # entrainment (Hamrock): u = (d_m^2 - D^2) |w_i - w_o| / (4 d_m) at both contacts
    u = (0.036**2 - 0.009525**2) * w / (4 * 0.036)
    assert k.entrainment_inner == pytest.approx(u, rel=1e-12)
    assert k.entrainment_outer == pytest.approx(u, rel=1e-12)
    assert k.spin_inner == pytest.approx(0.0, abs=1e-9) and k.spin_outer == pytest.approx(
        0.0, abs=1e-9)


def test_rotating_outer_ring() -> None:
    b = load_bearing("NU214")
    k = kin.pure_rolling(b, 500.0, outer_speed=100.0)
    assert k.orbital_speed == pytest.approx(100.0 + 400.0 * (1 - 13 / 97.5) / 2, rel=1e-12)


def test_vectorised_over_elements_and_selection() -> None:
    b = load_bearing("QJ1044")
    ai = np.radians([45.0, 50.0, 55.0])
    ao = np.radians([35.0, 30.0, 20.0])
    k = kin.outer_race_control(b, 100.0, ai, ao)
    assert np.shape(k.orbital_speed) == (3,)
    assert np.allclose(k.spin_outer, 0.0, atol=1e-10)
    verdict = kin.select_race_control([100.0, 100.0], [300.0, 50.0], [1e-3, 1e-3], [1e-3, 1e-3],
                                      [1.1, 1.1], [1.1, 1.1], ai[:2], ao[:2])
    assert list(verdict) == ["outer_race", "inner_race"]


# primer ../shared/notes/over-skidding.md section 5 table (D = 35.1 mm, d_m = 280 mm):
# (alpha_i, alpha_o) [deg] -> CSR_ORC, CSR(beta = 0), rounded to 3 decimals in the primer
PRIMER_TABLE = [((44.6, 35.1), 0.459, 0.487), ((41.1, 40.8), 0.453, 0.454),
                ((53.8, 20.1), 0.505, 0.568), ((57.2, 9.3), 0.558, 0.602),
                ((51.8, 24.6), 0.488, 0.549), ((44.6, 35.9), 0.458, 0.485),
                ((42.2, 39.7), 0.454, 0.462)]


@pytest.mark.parametrize(("angles", "csr_orc", "csr_beta0"), PRIMER_TABLE)
def test_primer_table_columns(angles, csr_orc, csr_beta0) -> None:
    gp = 35.1 / 280.0
    ai, ao = (math.radians(a) for a in angles)
    assert kin.race_control_cage_ratio(gp, ai, ao, "outer_race") == pytest.approx(
        csr_orc, abs=6e-4)
    assert kin.rolling_speeds(gp, ai, ao, 0.0)[0] == pytest.approx(csr_beta0, abs=6e-4)


def test_race_control_for_loads() -> None:
    b = load_bearing("QJ1044")
    ai = np.radians([45.0, 45.0])
    ao = np.radians([35.0, 35.0])
    # a heavily loaded outer contact (centrifugal force) -> outer-race control; a tiny one ->
    # inner-race control
    verdict = kin.race_control_for_loads(b, np.array([500.0, 500.0]), np.array([2000.0, 1.0]),
                                         ai, ao)
    assert list(verdict) == ["outer_race", "inner_race"]
