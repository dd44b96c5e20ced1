"""Inlet shear heating of the roller skidding solver's rolling force (``thermal_reduction``).

The solver evaluates paper 000 eq. 35 (and its rigid-isoviscous form) at the inlet viscosity
eta0 phi_T^(1/0.7), phi_T the heat source's factor (``film.THERMAL_FILM``, default
``heat_sources.raceway.DEFAULT_THERMAL_REDUCTION``), so that a race-control chain and a
skidding chain of the same roller bearing book the same rolling physics; the energy identity
(shaft power = booked heat) holds with it.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing import skidding
from thermobearing.errors import InputError, UnknownNameError, ValidityWarning
from thermobearing.film import gupta_1992
from thermobearing.heat_sources import HeatContext, evaluate, raceway
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model, default_traction_law, solve_roller
from thermobearing.skidding.roller_fluid import closed_form_contact_forces
from thermobearing.skidding.roller_thermal import inlet_heating_factor
from thermobearing.state import OilSupply, OperatingPoint

RPM = math.pi / 30.0
T = 323.15
SUPPLY = OilSupply("jet", 2e-3 / 60.0, T)


@pytest.fixture(scope="module")
def vg46():
    return load_lubricant("ISO_VG46")


def _solve(bearing, lub, rpm, load=10e3, **options):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return skidding.solve(bearing, lub, rpm * RPM, load, 0.0, T, supply=SUPPLY, **options)


@pytest.fixture(scope="module")
def states(nu214, vg46):
    """NU 214, 10 kN, ISO VG 46 at 50 degC, jet: default and isothermal solves."""
    return {rpm: (_solve(nu214, vg46, rpm, thermal_reduction="gupta_1992"),
                  _solve(nu214, vg46, rpm, thermal_reduction="none"))
            for rpm in (2000.0, 8000.0)}


def test_default_and_the_heat_sources_name(nu214, vg46):
    """The solver's default is the heat source's default name (one name, read from
    ``raceway.DEFAULT_THERMAL_REDUCTION`` at each build), which the option also takes."""
    model = build_model(nu214, vg46, T)
    assert raceway.DEFAULT_THERMAL_REDUCTION == "gupta_1992"
    assert model.thermal_reduction == raceway.DEFAULT_THERMAL_REDUCTION
    assert model.inlet_heating is not None
    hot = build_model(nu214, vg46, T, thermal_reduction=raceway.DEFAULT_THERMAL_REDUCTION)
    assert hot.thermal_reduction == "gupta_1992" and hot.inlet_heating is not None
    assert build_model(nu214, vg46, T, thermal_reduction="none").inlet_heating is None


def test_default_follows_the_heat_sources_constant(nu214, vg46, monkeypatch):
    """One constant: changing the heat source's default changes the solver's."""
    monkeypatch.setattr(raceway, "DEFAULT_THERMAL_REDUCTION", "wilson_sheu_1983")
    assert build_model(nu214, vg46, T).thermal_reduction == "wilson_sheu_1983"
    monkeypatch.setattr(raceway, "DEFAULT_THERMAL_REDUCTION", "none")
    assert build_model(nu214, vg46, T).inlet_heating is None


def test_factor_is_gupta_with_the_sources_beta(nu214, vg46):
    """phi_T of the solver = film.gupta_1992 at beta = -d ln eta/dT by +-0.5 K and k_f."""
    phi = inlet_heating_factor("gupta_1992", vg46, T, float(vg46.dynamic_viscosity(T)),
                               nu214.effective_modulus)
    u = np.array([2.0, 8.0, 30.0])
    s = np.array([0.0, 0.01, 0.3])
    p = np.array([0.3e9, 0.8e9, 1.2e9])
    beta = -(math.log(float(vg46.dynamic_viscosity(T + 0.5)))
             - math.log(float(vg46.dynamic_viscosity(T - 0.5))))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ref = gupta_1992(u, float(vg46.dynamic_viscosity(T)), beta,
                         float(vg46.thermal_conductivity(T)), s, p, nu214.effective_modulus)
    np.testing.assert_allclose(phi(u, s, p), ref, rtol=1e-14)
    assert np.all(np.diff(phi(u, np.zeros(3), np.full(3, 0.8e9))) < 0.0)  # falls with speed


@pytest.mark.parametrize("rolling_force", ["dowson_higginson", "rigid_isoviscous",
                                           "regime_min"])
def test_rolling_force_at_the_effective_inlet_viscosity(nu214, vg46, rolling_force):
    """Q_x with the factor = the isothermal closed forms at eta0 phi^(1/0.7): eq. 35 x phi,
    Martin x phi^(5/7); Couette shear and film unchanged."""
    model = build_model(nu214, vg46, T, thermal_reduction="gupta_1992")
    q = np.array([2000.0, 50.0, 0.0])
    u_race = np.array([20.0, 30.0, 25.0])
    u_roll = np.array([19.9, 29.0, 25.0])
    kw = dict(eta0=model.eta0, alpha=model.alpha, film=model.film_inner,
              traction_law=model.traction_law, temperature=T, rolling_force=rolling_force)
    iso = closed_form_contact_forces(q, model.length, model.radius_inner,
                                     model.effective_modulus, u_race, u_roll, **kw)
    hot = closed_form_contact_forces(q, model.length, model.radius_inner,
                                     model.effective_modulus, u_race, u_roll,
                                     inlet_heating=model.inlet_heating, **kw)
    ue = 0.5 * (u_race + u_roll)
    phi = model.inlet_heating(ue, np.abs(u_race - u_roll) / ue, iso.max_pressure)
    assert np.all(phi[:2] < 0.95) and np.all(phi > 0.05)
    eta_t = model.eta0 * phi ** (1.0 / 0.7)
    dh = raceway.rolling_force_paper000(ue, eta_t, model.alpha, model.effective_modulus,
                                        model.radius_inner, model.length)
    ri = raceway.rolling_force_rigid_isoviscous(2.0 * ue, eta_t, q, model.radius_inner,
                                                model.length)
    want = {"dowson_higginson": dh, "rigid_isoviscous": ri,
            "regime_min": np.minimum(dh, ri)}[rolling_force]
    np.testing.assert_allclose(hot.rolling_force[:2], want[:2], rtol=1e-12)
    assert hot.rolling_force[2] == 0.0 == iso.rolling_force[2]
    np.testing.assert_array_equal(hot.traction, iso.traction)
    np.testing.assert_array_equal(hot.film_thickness, iso.film_thickness)
    ratio = hot.rolling_force[:2] / iso.rolling_force[:2]
    if rolling_force == "dowson_higginson":
        np.testing.assert_allclose(ratio, phi[:2], rtol=1e-12)
    if rolling_force == "rigid_isoviscous":
        np.testing.assert_allclose(ratio, phi[:2] ** (5.0 / 7.0), rtol=1e-12)


def test_starved_film_rolling_force_falls_too(nu214, vg46):
    model = build_model(nu214, vg46, T, thermal_reduction="gupta_1992")
    kw = dict(eta0=model.eta0, alpha=model.alpha, film=model.film_inner,
              traction_law=model.traction_law, temperature=T, oil_layer=2e-6)
    args = (np.array([500.0]), model.length, model.radius_inner, model.effective_modulus,
            np.array([20.0]), np.array([20.0]))
    iso = closed_form_contact_forces(*args, **kw)
    hot = closed_form_contact_forces(*args, inlet_heating=model.inlet_heating, **kw)
    assert 0.0 < hot.rolling_force[0] < iso.rolling_force[0]
    assert hot.film_thickness[0] == iso.film_thickness[0]


def test_skidding_books_the_heat_sources_rolling_force(states, nu214, vg46):
    """The solver's Q_x of every loaded contact equals the heat source's own line force with
    its default thermal reduction on the same state (race-control formulas, rel 1e-10)."""
    for rpm, (res, _) in states.items():
        ks = res.kinematic_state
        op = OperatingPoint(inner_speed=rpm * RPM, radial_load=10e3, axial_load=0.0)
        ctx = HeatContext.isothermal(
            T, bearing=nu214, lubricant=vg46, supply=SUPPLY, operating=op, kinematics=ks,
            options={"ehl_rolling_resistance": {"rolling_force": "regime_min"}})
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            own = evaluate(["ehl_rolling_resistance"], ctx)[0]
        for race, f in (("inner", res.inner), ("outer", res.outer)):
            loaded = np.asarray(f.rolling_force) > 0.0
            assert np.count_nonzero(loaded) >= 4
            np.testing.assert_allclose(
                own.forces[f"{race}_rolling_force"][loaded], f.rolling_force[loaded],
                rtol=1e-10, err_msg=f"{rpm} r/min {race}")


def test_rolling_loss_falls_and_energy_identity_holds(states):
    for hot, iso in states.values():
        assert hot.converged and iso.converged
        for res in (hot, iso):
            shaft = res.shaft_torque * res.inner_speed
            assert res.power_loss["total"] == pytest.approx(shaft, rel=1e-7)
        roll = {k: r.power_loss["inner_rolling"] + r.power_loss["outer_rolling"]
                for k, r in (("hot", hot), ("iso", iso))}
        assert roll["hot"] < roll["iso"]
        assert hot.extras["thermal_reduction"] == "gupta_1992"
        assert iso.extras["thermal_reduction"] == "none"
        assert hot.kinematic_state.extras["raceway_rolling_thermal_reduction"] == "gupta_1992"
    # stronger reduction at speed (inlet heating grows with u^2)
    r2 = (states[2000.0][0].power_loss["inner_rolling"]
          / states[2000.0][1].power_loss["inner_rolling"])
    r8 = (states[8000.0][0].power_loss["inner_rolling"]
          / states[8000.0][1].power_loss["inner_rolling"])
    assert r8 < r2 < 1.0


SOURCES = ["raceway_traction", "ehl_rolling_resistance", "churning_elements",
           "churning_cage", "churning_inner_ring", "cage_guide", "pocket_friction"]


def test_heat_sources_book_the_reduced_forces_and_the_shaft_power(states, nu214, vg46):
    """The state carries the reduced Q_x; the sources (no options) book exactly the solver's
    dissipation, whose total is the shaft power (energy identity, rel 1e-8)."""
    for rpm, (res, _) in states.items():
        op = OperatingPoint(inner_speed=rpm * RPM, radial_load=10e3, axial_load=0.0)
        ctx = HeatContext.isothermal(T, bearing=nu214, lubricant=vg46, supply=SUPPLY,
                                     operating=op, kinematics=res.kinematic_state,
                                     traction=default_traction_law(vg46))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            got = {r.source: r.total for r in evaluate(SOURCES, ctx)}
        booked = res.booked_power()
        for name in SOURCES:
            assert got[name] == pytest.approx(booked[name], rel=1e-10, abs=1e-9), name
        assert sum(got.values()) == pytest.approx(res.shaft_torque * res.inner_speed,
                                                  rel=1e-8)


def test_bad_and_unsupported_names(nu214, vg46):
    with pytest.raises(UnknownNameError, match="thermal"):
        build_model(nu214, vg46, T, thermal_reduction="gupta")
    with pytest.raises(InputError, match="thermal_reduction"):
        build_model(nu214, vg46, T, thermal_reduction=1.0)


def test_numerical_drag_defaults_to_none_and_refuses_a_reduction(nu214, vg46):
    pytest.importorskip("thermobearing.ehl")
    model = build_model(nu214, vg46, T, drag_model="numerical_ehl")
    assert model.thermal_reduction == "none" and model.inlet_heating is None
    with pytest.raises(InputError, match="drag_model='numerical_ehl'"):
        build_model(nu214, vg46, T, drag_model="numerical_ehl", thermal_reduction="gupta_1992")


def test_isothermal_oil_gives_phi_one(nu214):
    """PAPER000_OIL (isothermal, beta = 0): the reduction changes no force (paper 000 cases,
    which pin thermal_reduction = "none" for the paper's isothermal eq. 35)."""
    oil = load_lubricant("PAPER000_OIL")
    a = solve_roller(nu214, oil, 5000 * RPM, 1000.0, 0.0, 313.15, thermal_reduction="gupta_1992")
    b = solve_roller(nu214, oil, 5000 * RPM, 1000.0, 0.0, 313.15, thermal_reduction="none")
    np.testing.assert_array_equal(a.outer.rolling_force, b.outer.rolling_force)
    assert a.cage_speed == b.cage_speed
