"""Inlet shear heating in the roller rolling resistance (``ehl_rolling_resistance``).

The film factor phi_T enters as an effective inlet viscosity eta0 phi_T^(1/0.7): eq. 35
(Dowson-Higginson, ~ (eta0 u)^0.7) falls by phi_T, Martin's rigid-isoviscous force
(~ eta0^0.5) by phi_T^(5/7); the no-load reference contact takes phi_T at its own Hertz
pressure; forces a skidding state carries are booked as they are.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.film import gupta_1992
from thermobearing.geometry import load_bearing
from thermobearing.global_friction import global_friction
from thermobearing.heat_sources import HeatContext, evaluate, raceway
from thermobearing.lubricant import load_lubricant
from thermobearing.state import KinematicState, OilSupply, OperatingPoint

RPM = math.pi / 30.0
GUPTA = {"ehl_rolling_resistance": {"thermal_reduction": "gupta_1992"}}
ISO = {"ehl_rolling_resistance": {"thermal_reduction": "none"}}


def _state(name, oil, temperature, radial_load, rpm):
    bearing = load_bearing(name)
    lub = load_lubricant(oil)
    op = OperatingPoint(inner_speed=rpm * RPM, radial_load=radial_load, axial_load=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(bearing, op, lubricant=lub,
                                              temperature=temperature)
    return bearing, lub, op, ks


def _rolling(bearing, lub, op, ks, temperature, options):
    ctx = HeatContext.isothermal(
        temperature, bearing=bearing, lubricant=lub,
        supply=OilSupply("jet", 2e-3 / 60.0, temperature, None), operating=op,
        kinematics=ks, options=options)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return evaluate(["ehl_rolling_resistance"], ctx)[0]


def _nu214(rpm, radial_load=10e3):
    t = 323.15
    bearing, lub, op, ks = _state("NU214", "ISO_VG46", t, radial_load, rpm)
    return bearing, lub, op, ks, t


def test_thermal_reduction_is_an_effective_inlet_viscosity_by_hand():
    bearing, lub, op, ks, t = _nu214(8000.0)
    r = _rolling(bearing, lub, op, ks, t, GUPTA)
    eta = float(lub.dynamic_viscosity(t))
    alpha = float(lub.pressure_viscosity_coefficient(t))
    beta = -(math.log(float(lub.dynamic_viscosity(t + 0.5)))
             - math.log(float(lub.dynamic_viscosity(t - 0.5))))
    k_f = float(lub.thermal_conductivity(t))
    e = bearing.effective_modulus
    branches = set()
    for cs in ks.contacts:
        q = np.asarray(cs.normal_load, float)
        loaded = q > 0
        u = np.abs(np.asarray(cs.entrainment_speed, float))
        length = 2.0 * cs.semi_major
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            phi = gupta_1992(u, eta, beta, k_f, cs.slide_to_roll, cs.max_pressure, e)
        q_dh = raceway.rolling_force_paper000(u, eta, alpha, e, cs.reduced_radius_x, length)
        q_ri = raceway.rolling_force_rigid_isoviscous(2.0 * u, eta, q, cs.reduced_radius_x,
                                                      length)
        expected = np.minimum(phi * q_dh, phi ** (5.0 / 7.0) * q_ri)
        got = r.forces[f"{cs.race}_rolling_force"]
        np.testing.assert_allclose(got[loaded], expected[loaded], rtol=1e-9)
        assert np.all(phi[loaded] < 1.0)
        branches |= {"dh" if a <= b else "ri" for a, b in zip(
            (phi * q_dh)[loaded], (phi ** (5.0 / 7.0) * q_ri)[loaded], strict=True)}
    # both closed forms are exercised here: loaded rollers (eq. 35) and the rollers the
    # centrifugal force alone seats on the outer race (rigid film)
    assert branches == {"dh", "ri"}


def test_no_load_share_with_thermal_reduction_does_not_move_with_the_load():
    t = 353.15
    shares = []
    for load in (500.0, 3000.0):
        bearing, lub, op, ks = _state("CRB_50x75x16", "MIL_PRF_23699", t, load, 10000.0)
        iso = _rolling(bearing, lub, op, ks, t, ISO)
        hot = _rolling(bearing, lub, op, ks, t, GUPTA)
        comp = "outer rolling resistance, no load"
        shares.append(hot.components[comp])
        assert 0.0 < hot.components[comp] < iso.components[comp]
        assert 0.0 < hot.total < iso.total
        assert sum(p.power for p in hot.force_pairs) == pytest.approx(hot.total, rel=1e-12)
    assert shares[0] == pytest.approx(shares[1], rel=1e-9)


@pytest.mark.parametrize("rpm", [2000.0, 6000.0, 10000.0])
def test_gupta_reduction_beside_skf_inlet_shear_factor(rpm):
    # two independent corrections for the same inlet heating: Gupta's film factor on the
    # local forces (through the inlet viscosity) and SKF's bearing-level phi_ish; measured
    # 0.914 / 0.747 / 0.618 against phi_ish 0.913 / 0.719 / 0.571 (NU 214, VG 46, 50 degC)
    bearing, lub, op, ks, t = _nu214(rpm)
    iso = _rolling(bearing, lub, op, ks, t, ISO).total
    hot = _rolling(bearing, lub, op, ks, t, GUPTA).total
    skf = global_friction("skf_four_term", bearing, lub, t, op.inner_speed, 10e3, 0.0,
                          lubrication="oil_jet")
    assert abs(hot / iso - skf.details["phi_ish"]) < 0.06
    # the isothermal local rolling term lies above SKF's rolling term, the reduced one nearer
    skf_rolling = skf.components["rolling"] * op.inner_speed
    assert abs(math.log(hot / skf_rolling)) < abs(math.log(iso / skf_rolling))


def test_default_reduction_applies_to_line_models_only(monkeypatch):
    bearing, lub, op, ks, t = _nu214(6000.0)
    monkeypatch.setattr(raceway, "DEFAULT_THERMAL_REDUCTION", "gupta_1992")
    default = _rolling(bearing, lub, op, ks, t, {})
    explicit = _rolling(bearing, lub, op, ks, t, GUPTA)
    assert default.total == pytest.approx(explicit.total, rel=1e-12)
    # "harris" (ball contacts) reduces through its own option 'reduction': the line
    # models' default does not reach it and does not make it refuse
    qj = load_bearing("QJ1044")
    lub46 = load_lubricant("ISO_VG46")
    opq = OperatingPoint(inner_speed=1800.0 * RPM, radial_load=1e3, axial_load=20e3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ksq = KinematicState.from_race_control(qj, opq, lubricant=lub46, temperature=318.15)
    harris = {"ehl_rolling_resistance": {"rolling_force": "harris"}}
    hot = _rolling(qj, lub46, opq, ksq, 318.15, harris)
    monkeypatch.setattr(raceway, "DEFAULT_THERMAL_REDUCTION", "none")
    cold = _rolling(qj, lub46, opq, ksq, 318.15, harris)
    assert hot.total == pytest.approx(cold.total, rel=1e-12)
    assert hot.total > 0.0


def test_default_reduction_leaves_a_skidding_states_own_forces(monkeypatch):
    bearing, lub, op, ks, t = _nu214(6000.0)
    iso = _rolling(bearing, lub, op, ks, t, ISO)
    carried = {cs.race: iso.forces[f"{cs.race}_rolling_force"] for cs in ks.contacts}
    own = dataclasses.replace(ks, extras={**dict(ks.extras),
                                          "raceway_rolling_force": carried})
    monkeypatch.setattr(raceway, "DEFAULT_THERMAL_REDUCTION", "gupta_1992")
    booked = _rolling(bearing, lub, op, own, t, {})
    for race, force in carried.items():
        np.testing.assert_array_equal(booked.forces[f"{race}_rolling_force"], force)
    assert booked.total == pytest.approx(iso.total, rel=1e-12)
