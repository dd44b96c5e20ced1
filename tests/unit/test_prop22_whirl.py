"""Property tests of the quasi-static whirl model (thermobearing.skidding.whirl, session 22;
paper 000 eqs. 1-4, 20-25).

- no whirl, no change: a zero radius gives the static solution at every sample (either
  reading of the radial inertia; with the cage rotating, the static solution at the
  azimuths the rollers have reached);
- periodicity: with frozen azimuths the states repeat from one whirl period to the next;
- quasi-static similarity: each sample depends on the whirl only through the acceleration
  e omega_w^2 at its phase, so (e, omega_w) and (e / k^2, k omega_w) give the same cage
  speed series (sampled at the same phases), the times scaled by 1 / k;
- the statistics are those of the series (min <= mean <= max, fluctuation = max - min).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing import load_bearing, load_lubricant
from thermobearing.skidding.roller import build_model, solve_model
from thermobearing.skidding.whirl import Whirl, solve_whirl

OMEGA = 5000.0 * math.pi / 30.0  # paper 000: n_i = 5000 r/min


@pytest.fixture(scope="module")
def model():
    return build_model(load_bearing("NU214"), load_lubricant("PAPER000_OIL"), 313.15)


def _close(a, b, rel=1e-7):
    np.testing.assert_allclose(a, b, rtol=rel, atol=0)


@settings(max_examples=4, deadline=None)
@given(load=st.floats(100.0, 5000.0), reading=st.sampled_from(["projected", "in_phase"]),
       phase=st.floats(0.0, 2.0 * math.pi))
def test_zero_radius_is_the_static_solution(model, load, reading, phase):
    static = solve_model(model, OMEGA, load,
                         azimuth=phase + 2.0 * math.pi * np.arange(model.n_rollers)
                         / model.n_rollers)
    w = solve_whirl(model, OMEGA, load, Whirl(0.0, n_samples=4, radial_inertia=reading,
                                              cage_phase=phase))
    assert w.converged
    _close(w.cage_speed, np.full(4, static.cage_speed))
    for s in w.states:
        np.testing.assert_allclose(s.inner_load, static.inner_load, rtol=1e-7,
                                   atol=1e-9 * load)
    assert w.cage_speed_stats.fluctuation <= 1e-7 * static.cage_speed


def test_zero_radius_with_the_cage_rotating_follows_the_rollers(model):
    load = 400.0
    w = solve_whirl(model, OMEGA, load, Whirl(0.0, n_samples=5, cage_rotation=True))
    dt = 2.0 * math.pi / OMEGA / 5
    z = model.n_rollers
    phase = 0.0
    for s in w.states:
        static = solve_model(model, OMEGA, load,
                             azimuth=phase + 2.0 * math.pi * np.arange(z) / z)
        assert s.cage_speed == pytest.approx(static.cage_speed, rel=1e-7)
        phase = (phase + s.cage_speed * dt) % (2.0 * math.pi)


@settings(max_examples=3, deadline=None)
@given(load=st.floats(100.0, 3000.0), radius=st.floats(1e-5, 1e-4),
       reading=st.sampled_from(["projected", "in_phase"]))
def test_frozen_azimuths_repeat_every_whirl_period(model, load, radius, reading):
    w = solve_whirl(model, OMEGA, load, Whirl(radius, n_samples=8, periods=2.0,
                                              radial_inertia=reading))
    assert w.converged and w.cage_speed.size == 16
    # sample 0 is solved cold, sample 8 warm: they agree to the solver tolerance
    _close(w.cage_speed[8:], w.cage_speed[:8], rel=1e-6)
    _close(w.times[8:] - w.times[:8], np.full(8, 2.0 * math.pi / OMEGA), rel=1e-12)


@settings(max_examples=3, deadline=None)
@given(load=st.floats(100.0, 3000.0), radius=st.floats(1e-5, 1e-4), k=st.floats(0.5, 2.0))
def test_only_the_whirl_acceleration_matters(model, load, radius, k):
    a = solve_whirl(model, OMEGA, load, Whirl(radius, frequency=OMEGA, n_samples=8))
    b = solve_whirl(model, OMEGA, load, Whirl(radius / k**2, frequency=k * OMEGA,
                                              n_samples=8))
    _close(b.cage_speed, a.cage_speed, rel=1e-6)
    _close(b.times[1:], a.times[1:] / k, rel=1e-12)
    for stats in (a.cage_speed_stats, a.slip_stats):
        assert stats.minimum <= stats.mean <= stats.maximum
        assert stats.fluctuation == pytest.approx(stats.maximum - stats.minimum, abs=0)
    assert a.cage_speed_stats.minimum == pytest.approx(float(np.min(a.cage_speed)), abs=0)
    assert a.cage_speed_stats.maximum == pytest.approx(float(np.max(a.cage_speed)), abs=0)


def test_a_whirl_of_no_sample_names_its_periods(model):
    from thermobearing.errors import InputError

    with pytest.raises(InputError, match="periods"):
        solve_whirl(model, OMEGA, 200.0, Whirl(6e-5, periods=0.001))
