"""User tour of the vibration model (issue 8, paper 004) from Python.

Found on the tour:

* ``simulate(..., sampling_rate=25600)`` point-samples the model, which rings at the ball's
  radial frequency between its contacts (46.8 kHz for the SKF 6304 at 2000 N): the record
  holds alias lines, and the envelope analyser, fed the record of a bearing with one
  off-size ball (2 um), reported CSR 0.1226 (true 0.3677) and 0.1691 (true 0.3383) with
  confidence 1.000, even with noise at 30 dB. Now a ValidityWarning says so, and
  ``anti_alias=True`` records as a DAQ with an anti-aliasing filter would.
* a ``max_step`` above RK4's stability bound with a steep traction law gave a bounded but
  wrong record without a word: RMS 68 m/s^2 instead of 0.50 (split scheme and RK4 at
  2.5e-7 s agree on 0.50). Now a ValidityWarning names the step, the bound and the cure.
"""

from __future__ import annotations

import math
import warnings

import pytest

from thermobearing import signal as S
from thermobearing import vibration as V
from thermobearing.errors import ConvergenceError, ValidityWarning
from thermobearing.traction import make_traction_law

WS = 1800 * math.pi / 30  # 1800 r/min
LOAD = 2000.0
MILD = make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)  # paper 004
STEEP = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.01)


@pytest.fixture(scope="module")
def off_size():
    # one ball 2 um oversize: it carries the cage frequency into the signal
    return V.paper004_parameters(ball_diameter_deviation=(2e-6, 0, 0, 0, 0, 0, 0))


def test_point_sampling_below_the_ball_frequency_warns(off_size):
    f_ball = V.stability_report(off_size, LOAD, MILD).ball_radial / (2 * math.pi)
    assert 40e3 < f_ball < 55e3
    with pytest.warns(ValidityWarning, match="point-sampled at 25600 Hz.*anti_alias=True"):
        V.simulate(off_size, WS, LOAD, traction=MILD, duration=0.02, settle_time=0.01,
                   sampling_rate=25600.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ValidityWarning)
        # above twice the ball frequency (paper 004's statistics are at 100 kHz): no warning
        V.simulate(off_size, WS, LOAD, traction=MILD, duration=0.02, settle_time=0.01,
                   sampling_rate=100e3)
        V.simulate(off_size, WS, LOAD, traction=MILD, duration=0.02, settle_time=0.01,
                   sampling_rate=25600.0, anti_alias=True)


@pytest.mark.parametrize("slip", [0.0, 0.08])
def test_anti_aliased_record_gives_the_true_cage_speed(off_size, slip):
    r = V.simulate(off_size, WS, LOAD, traction=MILD, cage_slip=slip, duration=1.5,
                   sampling_rate=25600.0, anti_alias=True)
    assert r.sampling_rate == 25600.0 and r.acceleration_x.size == 38400
    assert r.time[1] - r.time[0] == pytest.approx(1 / 25600.0)
    est = S.estimate_cage_speed(r.acceleration_x, r.sampling_rate, WS / (2 * math.pi),
                                off_size.n_balls, off_size.theoretical_cage_speed_ratio)
    csr = r.cage_speed / WS  # the cage speed the simulation was given
    assert est.detected and est.csr == pytest.approx(csr, rel=1e-3)


def test_rk4_step_above_its_stability_bound_warns_and_names_the_bound():
    p = V.paper004_parameters()
    rep = V.stability_report(p, LOAD, STEEP)
    assert rep.rk4_max_step < 1e-6  # the spin equations are stiff with this law
    with pytest.warns(ValidityWarning, match=r"above the rk4 stability bound.*method='split'"):
        V.simulate(p, WS, LOAD, traction=STEEP, duration=0.005, settle_time=0.005,
                   method="rk4", max_step=4e-6)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ValidityWarning)
        V.simulate(p, WS, LOAD, traction=STEEP, duration=0.005, settle_time=0.005,
                   sampling_rate=100e3, method="split")  # its own stable step


def test_divergence_names_the_stability_bound():
    p = V.paper004_parameters()
    with pytest.warns(ValidityWarning), pytest.raises(ConvergenceError,
                                                      match="stability bound of this case"):
        V.simulate(p, WS, LOAD, traction=MILD, duration=0.02, settle_time=0.02,
                   method="rk4", max_step=1e-5, sampling_rate=100e3)


def test_roller_bearing_is_refused_by_name():
    # before: InputError "radius_ratio = inf ... (R_big/R_small)" from the Hertz stiffness
    from thermobearing.errors import InputError
    from thermobearing.geometry import load_bearing

    with pytest.raises(InputError) as info:
        V.VibrationParameters.from_bearing(load_bearing("NU214"), inner_ring_mass=0.4,
                                           support_damping=350.0)
    assert info.value.field == "bearing" and info.value.value == "NU214"
    assert "a ball bearing" in str(info.value)
