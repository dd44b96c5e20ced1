"""Property tests, round 5: vibration records (:mod:`thermobearing.vibration_results`,
:mod:`thermobearing.vibration_sunnersjo`).

- statistics of any record: Pearson's inequality kurtosis >= 1 + skewness^2 >= 1 (Pearson
  1916); Popoviciu's inequality var <= (max - min)^2 / 4, so PTP >= 2 std; RMS about zero
  >= std; PTP and RMS scale with |c| and kurtosis is invariant under a -> c a + b (c != 0);
  a sine over whole periods has kurtosis 3/2 and RMS = amplitude / sqrt 2;
- Sunnersjo's varying-compliance model (Sunnersjo 1978): the ring is forced with the period
  of the ball passage, 1 / (Z f_cage); a damped stable system's steady response is periodic
  with that period, so a(t + T_vc) = a(t) after the transients (checked with T_vc a whole
  number of samples), and the mean acceleration over whole periods is zero (the ring stays
  in place: a(t) = x''(t) of a periodic x);
- the amplitude spectrum (Hann, amplitude-corrected) of a tone on a frequency bin peaks at
  that bin with the tone's amplitude to O(1/N) (np.hanning is the symmetric window: its sum
  is (N - 1)/2, the coherent gain of the periodic one N/2).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.vibration_params import paper004_parameters
from thermobearing.vibration_results import amplitude_spectrum, statistics
from thermobearing.vibration_sunnersjo import simulate_sunnersjo

_records = st.lists(st.floats(-1e3, 1e3), min_size=4, max_size=200).filter(
    lambda v: np.ptp(np.asarray(v)) > 1e-3)


@settings(max_examples=150, deadline=None)
@given(_records, st.floats(1e-3, 1e3).flatmap(lambda m: st.sampled_from([m, -m])),
       st.floats(-1e3, 1e3))
def test_statistics_obey_pearson_popoviciu_and_affine_invariance(values, c, b):
    """kurtosis >= 1 + skew^2; PTP >= 2 std; RMS >= std; PTP, RMS (of c a) scale with |c|;
    kurtosis(c a + b) = kurtosis(a)."""
    a = np.asarray(values)
    s = statistics(a)
    d = a - a.mean()
    std = math.sqrt(float(np.mean(d * d)))
    skew = float(np.mean(d**3)) / std**3
    assert s.kurtosis >= (1.0 + skew * skew) * (1.0 - 1e-9)
    assert s.ptp >= 2.0 * std * (1.0 - 1e-12)
    assert s.rms >= std * (1.0 - 1e-12)
    scaled = statistics(c * a)
    assert math.isclose(scaled.ptp, abs(c) * s.ptp, rel_tol=1e-12)
    assert math.isclose(scaled.rms, abs(c) * s.rms, rel_tol=1e-12)
    shifted = statistics(c * a + b)
    assert math.isclose(shifted.kurtosis, s.kurtosis, rel_tol=1e-6)


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 20), st.integers(32, 400), st.floats(0.01, 100.0),
       st.floats(0.0, 2.0 * math.pi))
def test_sine_over_whole_periods(periods, per_period, amp, phase):
    """kurtosis 3/2, RMS A/sqrt 2, PTP <= 2 A (the sampled extremes), of whole periods."""
    t = np.arange(periods * per_period) / per_period
    s = statistics(amp * np.sin(2.0 * math.pi * t + phase))
    assert math.isclose(s.kurtosis, 1.5, rel_tol=1e-9)
    assert math.isclose(s.rms, amp / math.sqrt(2.0), rel_tol=1e-9)
    assert s.ptp <= 2.0 * amp * (1.0 + 1e-12)


@settings(max_examples=40, deadline=None)
@given(st.integers(256, 4096), st.floats(0.05, 0.45), st.floats(0.01, 100.0),
       st.floats(0.0, 2.0 * math.pi), st.floats(-10.0, 10.0))
def test_amplitude_spectrum_of_an_on_bin_tone(n, frac, amp, phase, offset):
    """Peak at the tone's bin, height A (1 +- 3/N); the offset is removed."""
    fs = 1000.0
    k = max(4, int(frac * n))
    t = np.arange(n) / fs
    f, spec = amplitude_spectrum(offset + amp * np.cos(2.0 * math.pi * k * fs / n * t + phase),
                                 fs)
    assert int(np.argmax(spec)) == k
    assert math.isclose(f[k], k * fs / n, rel_tol=1e-12)
    assert abs(spec[k] - amp) <= 3.0 * amp / n


@settings(max_examples=6, deadline=None)
@given(st.sampled_from([250, 400, 1000, 2000]), st.floats(200.0, 10000.0))
def test_sunnersjo_response_is_periodic_at_the_ball_pass_frequency(samples_per_period, load):
    """a(t + 1/(Z f_c)) = a(t) to 1e-3 of the peak after 0.1 s settling (measured 2.5e-11 to
    3.3e-10 after 0.2 s, up to 1.6e-5 after 0.05 s), mean over whole periods ~ 0."""
    p = paper004_parameters()
    fs = 100_000.0
    f_vc = fs / samples_per_period
    shaft = 2.0 * math.pi * f_vc / (p.n_balls * p.theoretical_cage_speed_ratio)
    a = simulate_sunnersjo(p, shaft, load, duration=0.04, settle_time=0.1, sampling_rate=fs)
    peak = float(np.max(np.abs(a)))
    assert peak > 0.0
    np.testing.assert_allclose(a[samples_per_period:], a[:-samples_per_period], rtol=0,
                               atol=1e-3 * peak)
    whole = (a.size // samples_per_period) * samples_per_period
    assert abs(float(np.mean(a[:whole]))) <= 1e-3 * peak
