"""Tests of thermobearing.global_friction against hand calculations (catalogue units).

Every expected number below is computed step by step in the test from the SKF catalogue
formulas (SKF 10000 EN / 17000 EN, "The SKF model for calculating the frictional moment")
or Palmgren's M0 + M1, in N mm, mm, r/min and mm^2/s, then converted to SI.
"""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.global_friction import (
    GLOBAL_FRICTION,
    BearingEnvelope,
    infer_skf_series,
    palmgren,
    palmgren_equivalent_load,
    skf_drag_factor,
    skf_four_term,
    skf_geometry_variables,
)

RPM = 2 * math.pi / 60

# SKF 6304 of paper 004 Table 1 (d = 20, D = 52, B = 15 mm, ball 9.525 mm)
B6304 = BearingEnvelope("deep_groove", 0.020, 0.052, 0.015, 9.525e-3, "SKF6304")
QJ1044 = BearingEnvelope("four_point", 0.220, 0.340, 0.056, 0.0325, "QJ1044")
NU214 = BearingEnvelope("cylindrical", 0.070, 0.125, 0.024, 0.013, "NU214")


def test_series_inference():
    assert infer_skf_series(B6304) == "63"
    assert infer_skf_series(QJ1044) == "QJ"
    assert infer_skf_series(NU214) == "2"
    assert infer_skf_series(BearingEnvelope("deep_groove", .02, .047, .014, None, "61804")) \
        == "618"
    with pytest.raises(InputError, match="series"):
        infer_skf_series(BearingEnvelope("cylindrical", .05, .075, .016, .006, "CRB_50x75x16"))


def test_skf_6304_radial_hand_calculation():
    n, nu, Fr = 2000.0, 20.0, 2000.0
    dm = 36.0
    # series 63: R1 = 3.7e-7, S1 = 2.84e-3 (catalogue Table 1a)
    g_rr = 3.7e-7 * dm**1.96 * Fr**0.54
    g_sl = 2.84e-3 * dm**-0.26 * Fr ** (5 / 3)
    phi_ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    phi_rs = 1 / math.exp(3e-8 * nu * n * (20 + 52) * math.sqrt(3.1 / (2 * (52 - 20))))
    m_rr = phi_ish * phi_rs * g_rr * (nu * n) ** 0.6
    phi_bl = 1 / math.exp(2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * 0.15 + (1 - phi_bl) * 0.05
    m_sl = g_sl * mu_sl
    # oil jet: oil bath with H = 9.525/2 mm, doubled
    H = 9.525 / 2
    t = 2 * math.acos((0.6 * dm - H) / (0.6 * dm))
    f_t = math.sin(t / 2)
    f_a = 0.05 * 3.1 * (52 + 20) / (52 - 20)
    r_s = 0.36 * dm**2 * (t - math.sin(t)) * f_a
    k_ball = 3.1 * (20 + 52) / (52 - 20) * 1e-12
    v_m = skf_drag_factor(H / dm, "ball")
    drag = 2 * (0.4 * v_m * k_ball * dm**5 * n**2
                + 1.093e-7 * n**2 * dm**3 * (n * dm**2 * f_t / nu) ** -1.379 * r_s)
    total = (m_rr + m_sl + drag) * 1e-3
    res = skf_four_term(B6304, nu * 1e-6, n * RPM, Fr, 0.0, lubrication="oil_jet")
    assert res.components["rolling"] == pytest.approx(m_rr * 1e-3, rel=1e-12)
    assert res.components["sliding"] == pytest.approx(m_sl * 1e-3, rel=1e-12)
    assert res.components["drag"] == pytest.approx(drag * 1e-3, rel=1e-12)
    assert res.torque == pytest.approx(total, rel=1e-12)
    assert res.power == pytest.approx(total * n * RPM, rel=1e-12)
    # magnitude check: about 35 N mm -> 7.3 W for this small bearing at 2000 r/min
    assert 0.02 < res.torque < 0.06


def test_skf_deep_groove_axial_needs_c0_and_uses_alpha_f():
    with pytest.raises(InputError, match="static_load_rating"):
        skf_four_term(B6304, 20e-6, 2000 * RPM, 1000.0, 500.0)
    dm, Fr, Fa, C0 = 36.0, 1000.0, 500.0, 7800.0
    s = math.sin(math.radians(24.6 * (Fa / C0) ** 0.24))
    g_rr, g_sl = skf_geometry_variables("deep_groove", "63", dm, Fr, Fa, 2000.0, C0)
    assert g_rr == pytest.approx(3.7e-7 * dm**1.96 * (Fr + 1.7 / s * Fa) ** 0.54, rel=1e-12)
    assert g_sl == pytest.approx(
        2.84e-3 * dm**-0.145 * (Fr**5 + 92.8 * dm**1.5 / s * Fa**4) ** (1 / 3), rel=1e-12)


def test_skf_four_point_centrifugal_term_hand():
    dm, n, Fr, Fa = 280.0, 1800.0, 1000.0, 10000.0
    fg = 1.40e-12 * dm**4 * n**2  # R3 = S3 = 1.40e-12 for four-point bearings
    g_rr, g_sl = skf_geometry_variables("four_point", "QJ", dm, Fr, Fa, n)
    assert g_rr == pytest.approx(4.78e-7 * dm**1.97 * (Fr + fg + 2.42 * Fa) ** 0.54)
    assert g_sl == pytest.approx(1.20e-2 * dm**0.26 * ((Fr + fg) ** (4 / 3) + 0.9 * Fa ** (4 / 3)))


def test_skf_oil_bath_level_and_drag_monotonic():
    low = skf_four_term(QJ1044, 20e-6, 1800 * RPM, 1000.0, 10000.0, lubrication="oil_bath",
                        oil_level=0.02)
    high = skf_four_term(QJ1044, 20e-6, 1800 * RPM, 1000.0, 10000.0, lubrication="oil_bath",
                         oil_level=0.10)
    assert high.components["drag"] > low.components["drag"] > 0
    air = skf_four_term(QJ1044, 20e-6, 1800 * RPM, 1000.0, 10000.0, lubrication="oil_air")
    assert air.components["drag"] == 0.0
    with pytest.raises(InputError, match="oil_level"):
        skf_four_term(QJ1044, 20e-6, 1800 * RPM, 1000.0, 0.0, lubrication="oil_bath")


def test_skf_drag_primer_example():
    # 6208 (d_m = 60 mm), n = 3000 r/min, H/d_m = 0.5: first drag term ~14.8 N mm
    # (shared/notes/losses-and-heat-transfer.md sec. 5.4): 0.4 V_M K_ball d_m^5 n^2
    k_ball = 3.1 * (40 + 80) / (80 - 40) * 1e-12
    first = 0.4 * skf_drag_factor(0.5, "ball") * k_ball * 60.0**5 * 3000.0**2
    assert first == pytest.approx(14.8, rel=0.01)


def test_drag_factor_monotone_and_capped():
    prev = -1.0
    for h in [0.0, 0.05, 0.1, 0.3, 0.6, 1.0, 1.2]:
        v = skf_drag_factor(h, "roller")
        assert v >= prev
        prev = v
    assert skf_drag_factor(2.0, "ball") == skf_drag_factor(1.2, "ball")


def test_skf_seal_term():
    seal = {"d_s": 0.030, "K_S1": 0.023, "K_S2": 2.0, "beta": 2.25}
    res = skf_four_term(B6304, 20e-6, 2000 * RPM, 2000.0, seal=seal)
    assert res.components["seal"] == pytest.approx((0.023 * 30.0**2.25 + 2.0) * 1e-3)
    with pytest.raises(UnknownNameError):
        skf_four_term(B6304, 20e-6, 2000 * RPM, 2000.0, seal={"ds": 0.03})


def test_skf_cylindrical_roller_hand():
    # NU214, series 2: R1 = 1.09e-6, S1 = 0.16, S2 = 0.0015; radial only
    dm, Fr, n, nu = 97.5, 5000.0, 3000.0, 15.0
    g_rr, g_sl = skf_geometry_variables("cylindrical", "2", dm, Fr, 0.0, n)
    assert g_rr == pytest.approx(1.09e-6 * dm**2.41 * Fr**0.31)
    assert g_sl == pytest.approx(0.0015 * dm * Fr)
    res = skf_four_term(NU214, nu * 1e-6, n * RPM, Fr, lubrication="oil_air")
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    assert res.details["mu_sl"] == pytest.approx(phi_bl * 0.15 + (1 - phi_bl) * 0.02)


def test_palmgren_hand_calculation():
    # 6304, oil jet: f0 = 2 x 2 = 4, f1 = 0.00022, P1 = max(3.3*0 - 0.1*2000, 2000) = 2000
    n, nu, dm = 2000.0, 20.0, 36.0
    m0 = 1e-7 * 4 * (nu * n) ** (2 / 3) * dm**3
    m1 = 0.00022 * 2000.0 * dm
    res = palmgren(B6304, nu * 1e-6, n * RPM, 2000.0)
    assert res.components["M0"] == pytest.approx(m0 * 1e-3, rel=1e-12)
    assert res.components["M1"] == pytest.approx(m1 * 1e-3, rel=1e-12)
    assert res.power == pytest.approx((m0 + m1) * 1e-3 * n * RPM, rel=1e-12)
    # low-speed branch nu n < 2000: M0 = 160e-7 f0 d_m^3 (with f0, unlike Thermca)
    slow = palmgren(B6304, 10e-6, 100 * RPM, 2000.0, lubrication="oil_bath")
    assert slow.components["M0"] == pytest.approx(160e-7 * 2 * dm**3 * 1e-3)


def test_palmgren_p1_rules():
    assert palmgren_equivalent_load("deep_groove", 1000, 1000) == pytest.approx(3200)
    assert palmgren_equivalent_load("deep_groove", 1000, 100) == 1000
    assert palmgren_equivalent_load("four_point", 1000, 10000) == pytest.approx(18600)
    assert palmgren_equivalent_load("angular_contact", 1000, 5000) == pytest.approx(4900)


def test_registry_and_bad_input():
    assert set(GLOBAL_FRICTION.names()) == {"skf_four_term", "palmgren"}
    model = GLOBAL_FRICTION.get("palmgren")
    with pytest.raises(InputError, match="speed"):
        model(B6304, 20e-6, -1.0, 1000.0)
    with pytest.raises(InputError, match="kinematic_viscosity"):
        model(B6304, 0.0, 100.0, 1000.0)
    with pytest.raises(UnknownNameError, match="oil_jet"):
        model(B6304, 20e-6, 100.0, 1000.0, lubrication="splash")
    with pytest.raises(InputError, match="mu_bl"):
        skf_four_term(B6304, 20e-6, 100.0, 1000.0, mu_bl=1.5)
    with pytest.raises(UnknownNameError, match="kind"):
        BearingEnvelope("needle", 0.02, 0.03, 0.01)
    with pytest.raises(InputError, match="outer_diameter"):
        BearingEnvelope("deep_groove", 0.05, 0.03, 0.01)
    with pytest.raises(InputError):
        skf_four_term(object(), 20e-6, 100.0, 1000.0)


def test_geometry_objects_are_accepted():
    from thermobearing.geometry import load_bearing

    brg = load_bearing("SKF6304")
    res = skf_four_term(brg, 20e-6, 2000 * RPM, 2000.0, series="63")
    ref = skf_four_term(B6304, 20e-6, 2000 * RPM, 2000.0, series="63")
    assert res.torque == pytest.approx(ref.torque, rel=0.05)


def test_global_friction_with_lubricant():
    from thermobearing.global_friction import global_friction
    from thermobearing.lubricant import load_lubricant

    oil = load_lubricant("ISO_VG46")
    T = 333.15
    nu = oil.kinematic_viscosity(T)
    for name in ("skf_four_term", "palmgren"):
        got = global_friction(name, QJ1044, oil, T, 1800 * RPM, 1000.0, 10000.0)
        ref = GLOBAL_FRICTION.get(name)(QJ1044, nu, 1800 * RPM, 1000.0, 10000.0)
        assert got.torque == pytest.approx(ref.torque, rel=1e-12)
    ester = load_lubricant("MIL_PRF_23699")
    res = global_friction("skf_four_term", QJ1044, ester, T, 1800 * RPM, 1000.0, 10000.0)
    # at high n*nu phi_bl -> 0, so mu_sl -> mu_EHL = 0.04 for a synthetic oil
    assert res.details["mu_sl"] == pytest.approx(0.04, abs=1e-3)


def test_oil_supply_spellings_and_object():
    from thermobearing.global_friction import global_friction
    from thermobearing.lubricant import load_lubricant

    a = palmgren(B6304, 20e-6, 2000 * RPM, 2000.0, lubrication="jet")
    b = palmgren(B6304, 20e-6, 2000 * RPM, 2000.0, lubrication="oil_jet")
    assert a.torque == b.torque
    state = pytest.importorskip("thermobearing.state")
    supply = state.OilSupply(method="oil_bath", flow_rate=0.0, inlet_temperature=313.15,
                             level=0.01)
    oil = load_lubricant("ISO_VG68")
    res = global_friction("skf_four_term", QJ1044, oil, 330.0, 1800 * RPM, 1000.0, 5000.0,
                          supply=supply)
    assert res.details["oil_level_mm"] == pytest.approx(10.0)
