"""The slide-variable roller solve with the Maxwell film (``fluid_shear_modulus``) and the
``film_pressure`` option (issue 5; skidding/roller_maxwell.py, roller_residual.py,
roller_slides.py; paper 000 Z + 1 equations, seed 000_3b5ca6eed61dd596.txt; Maxwell film:
Johnson & Tevaarwerk 1977).

Before: the Hertz-zone integral of these options took the difference of the surface speeds,
so the slide solve refused them and a stuck cold state was a ConvergenceError (CRB
50x75x16, 20 kN, ISO VG 46 at 20 degC, 5000 r/min, ``film_pressure="regime_min"``: the
round-off state refused with shaft power and dissipation 0.945 apart). Now they take the
exact slide and the state converges with shaft power = dissipation.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model, evaluate, solve_model
from thermobearing.skidding.roller_loads import _load_distribution
from thermobearing.skidding.roller_residual import exact_slides_supported
from thermobearing.skidding.roller_slides import evaluate_slides, slide_speeds

RPM = math.pi / 30.0
OPTIONS = [{"film_pressure": "regime_min"}, {"fluid_shear_modulus": 1e9},
           {"fluid_shear_modulus": 1e9, "film_pressure": "regime_min"}]
IDS = ["regime_min", "maxwell", "maxwell_regime_min"]


def _cold_crb_at_epicyclic(**opts):
    """CRB 50x75x16, ISO VG 46 at 20 degC, 5000 r/min, 20 kN, cage at the epicyclic speed:
    the model ``m``, omega [rad/s], the angles psi, the load distribution and the loaded
    rollers' mask."""
    m = build_model(load_bearing("CRB_50x75x16"), load_lubricant("ISO_VG46"), 293.15,
                    **opts)
    omega = 5000.0 * RPM
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    ld, fb = _load_distribution(m, omega, 20e3, m.theoretical_cage_speed_ratio * omega, None,
                                psi, (0.0, 0.0))
    return m, omega, psi, ld, fb, ld.inner_load > 0.0


@pytest.mark.parametrize("opts", OPTIONS, ids=IDS)
def test_slide_evaluation_is_the_speed_evaluation_away_from_pure_rolling(opts):
    """NU214, 2 kN, 40 degC, cage 5 % below epicyclic: the exact slides give the forces of
    the speeds' differences where those are large against the speeds' round-off."""
    m = build_model(load_bearing("NU214"), load_lubricant("PAPER000_OIL"), 313.15, **opts)
    assert exact_slides_supported(m)
    omega = 5000.0 * RPM
    z = m.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    delta = -0.05 * m.theoretical_cage_speed_ratio * omega
    ld, fb = _load_distribution(m, omega, 2000.0, m.theoretical_cage_speed_ratio * omega
                                + delta, None, psi, (0.0, 0.0))
    v_i = np.linspace(-0.3, 0.4, z)
    e_s, _x = evaluate_slides(m, omega, v_i, delta, ld.inner_load, fb, psi, (0.0, 0.0))
    wr, wc, _ = slide_speeds(m, omega, v_i, delta)
    e = evaluate(m, omega, wr, wc, ld.inner_load, fb, psi, (0.0, 0.0))
    np.testing.assert_allclose(e_s.inner.hertz_traction, e.inner.hertz_traction, rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose(e_s.roller_eq, e.roller_eq, rtol=1e-9, atol=1e-9)
    assert e_s.cage_eq == pytest.approx(e.cage_eq, rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("opts", OPTIONS, ids=IDS)
def test_hertz_traction_takes_a_slide_below_the_speeds_ulp(opts):
    """CRB 50x75x16, 20 kN, ISO VG 46 at 20 degC, 5000 r/min, at the epicyclic cage speed:
    loaded rollers given inner slides of +-1e-17 m/s (far below the 1e-15 m/s ulp of the
    surface speeds) carry opposite Hertz-zone tractions (the viscous cold film: hundreds of
    N, at its limiting stress there; the Maxwell film: elastic, ~1e-13 N); from the speeds,
    whose difference cannot hold such a slide, both signs gave the same force."""
    m, omega, psi, ld, fb, loaded = _cold_crb_at_epicyclic(**opts)
    z = m.n_rollers

    def hertz(v):
        return evaluate_slides(m, omega, np.full(z, v), 0.0, ld.inner_load, fb, psi,
                               (0.0, 0.0))[0].inner.hertz_traction

    up, down = hertz(1e-17), hertz(-1e-17)
    assert np.all(up[loaded] > 0.0)
    np.testing.assert_allclose(down[loaded], -up[loaded], rtol=1e-12)
    if "fluid_shear_modulus" not in opts:
        assert float(np.max(up)) > 1.0  # N


@pytest.mark.parametrize("pressure", ["hertz", "regime_min"])
def test_maxwell_traction_is_elastic_and_linear_at_tiny_slides(pressure):
    """Defect found with the slide solve: below 1e-12 m/s the Maxwell cell took the flow
    curve's slope for its secant; a cold film under load is at its limiting stress there
    (slope ~0), so the cell turned viscous and the Hertz-zone traction jumped to 276 N at
    1e-12 m/s against 2.9e-8 N at 2e-12 (CRB 50x75x16, 20 kN, ISO VG 46 at 20 degC,
    G = 1 GPa). In the elastic regime (Johnson & Tevaarwerk 1977) the traction is linear in
    the slide: the same slope from 1e-18 to 1e-6 m/s, rising with it."""
    m, omega, psi, ld, fb, loaded = _cold_crb_at_epicyclic(fluid_shear_modulus=1e9,
                                                           film_pressure=pressure)
    z = m.n_rollers
    slides = np.array([1e-18, 1e-17, 2e-17, 1e-15, 1e-12, 2e-12, 1e-9, 1e-6])
    slope = np.array([evaluate_slides(m, omega, np.full(z, v), 0.0, ld.inner_load, fb, psi,
                                      (0.0, 0.0))[0].inner.hertz_traction[loaded] / v
                      for v in slides])
    np.testing.assert_allclose(slope, np.broadcast_to(slope[-1], slope.shape), rtol=1e-3)
    assert np.all(slope > 0.0)


@pytest.mark.parametrize("rpm", [5000.0, 30000.0])
def test_regime_min_film_pressure_converges_with_the_energy_identity(rpm):
    """The reported point with ``film_pressure="regime_min"`` (was a ConvergenceError):
    rolls at the epicyclic cage speed to 1e-6, residual at round-off, shaft power =
    dissipation to 1e-6."""
    m = build_model(load_bearing("CRB_50x75x16"), load_lubricant("ISO_VG46"), 293.15,
                    film_pressure="regime_min")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = solve_model(m, rpm * RPM, 20e3)
    assert r.converged and r.residual_norm <= 1e-9
    assert r.cage_speed_ratio == pytest.approx(r.theoretical_cage_speed_ratio, rel=1e-6)
    shaft = r.shaft_torque * r.inner_speed
    assert r.power_loss["total"] == pytest.approx(shaft, rel=1e-6)
