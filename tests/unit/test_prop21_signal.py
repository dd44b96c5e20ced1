"""Property tests of the spectral line estimators at any sampling rate and record length
(session 21), beside test_prop19_signal.py (one rate, powers of two) and
test_prop20_signal.py (the cage-speed estimator's invariances).

:func:`spectral_peak` (Hann window, zero padding, log-parabolic interpolation) and the
squared-envelope line of an amplitude-modulated carrier (:func:`envelope_spectrum` then
:func:`refine_peak`) are frequency-scale free: the estimate in bins depends on the record
only through the tone's position in bins, so it must hold for any sampling rate (1 kHz to
300 kHz), any record length (odd and non-power-of-two lengths included), any phase and any
carrier below a quarter of the sampling rate. Measured on 300 seeded draws: worst 1.1e-4 bin
for the envelope line (10-60 bins, band 3-8 f_m either side of the carrier) and 3.2e-5 bin
for the raw tone (10 bins to n/4); asserted to 1e-3 bin.

The envelope spectrum is computed on the record minus its mean and scaled back from unit
peak, so a gain a (any unit: g, m/s^2 ... between 1e-30 and 1e30) and a DC offset c leave
the line's frequency and its normalised power unchanged to round-off.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.signal_envelope import envelope_spectrum, refine_peak, spectral_peak

LENGTHS = [1000, 2047, 4096, 5000, 8192, 12345]


def _am_record(fs, n, fm_bins, fc_frac, depth, phase, carrier_phase):
    df = fs / n
    fm = fm_bins * df
    fc = fc_frac * fs
    t = np.arange(n) / fs
    x = (1 + depth * np.cos(2 * math.pi * fm * t + phase)) * np.sin(
        2 * math.pi * fc * t + carrier_phase)
    return x, fm, fc, df


@settings(max_examples=40, deadline=None)
@given(log_fs=st.floats(3.0, 5.5), n=st.sampled_from(LENGTHS), fm_bins=st.floats(10.0, 60.0),
       fc_frac=st.floats(0.1, 0.24), width=st.floats(3.0, 8.0), depth=st.floats(0.1, 1.0),
       phase=st.floats(0.0, 2 * math.pi), carrier_phase=st.floats(0.0, 2 * math.pi))
def test_envelope_line_at_any_rate_and_length(log_fs, n, fm_bins, fc_frac, width, depth, phase,
                                              carrier_phase):
    fs = 10.0**log_fs
    x, fm, fc, df = _am_record(fs, n, fm_bins, fc_frac, depth, phase, carrier_phase)
    bw = width * fm
    band = (max(fc - bw, 0.0), min(fc + bw, 0.5 * fs))
    es = envelope_spectrum(x, fs, band)
    f, power = refine_peak(es, fm, 5 * df)
    assert abs(f - fm) < 1e-3 * df
    assert power > 100.0


@settings(max_examples=30, deadline=None)
@given(log_fs=st.floats(3.0, 5.5), n=st.sampled_from(LENGTHS), fm_bins=st.floats(10.0, 60.0),
       phase=st.floats(0.0, 2 * math.pi), log_gain=st.floats(-30.0, 30.0),
       offset=st.floats(-10.0, 10.0), negate=st.booleans())
def test_envelope_line_is_gain_polarity_and_offset_free(log_fs, n, fm_bins, phase, log_gain,
                                                       offset, negate):
    fs = 10.0**log_fs
    x, fm, fc, df = _am_record(fs, n, fm_bins, 0.2, 0.5, phase, 0.3)
    band = (fc - 3 * fm, fc + 3 * fm)  # inside (0, fs / 2): f_m <= 0.06 fs, f_c = 0.2 fs
    gain = (-1.0 if negate else 1.0) * 10.0**log_gain
    f1, p1 = refine_peak(envelope_spectrum(x, fs, band), fm, 5 * df)
    f2, p2 = refine_peak(envelope_spectrum(gain * (x + offset), fs, band), fm, 5 * df)
    assert abs(f2 - f1) < 1e-9 * df
    assert abs(p2 / p1 - 1.0) < 1e-9


@settings(max_examples=40, deadline=None)
@given(log_fs=st.floats(2.0, 6.0), n=st.sampled_from(LENGTHS), frac=st.floats(0.0, 1.0),
       phase=st.floats(0.0, 2 * math.pi), log_amp=st.floats(-20.0, 20.0),
       offset=st.floats(-10.0, 10.0))
def test_spectral_peak_at_any_rate_and_length(log_fs, n, frac, phase, log_amp, offset):
    """A tone 10 bins above DC up to a quarter of the rate, on a DC level of up to 10 times
    its amplitude: within 1e-3 bin, amplitude within 0.5 %."""
    fs = 10.0**log_fs
    df = fs / n
    f0 = (10.0 + frac * (n / 4 - 10.0)) * df
    amp = 10.0**log_amp
    x = amp * (offset + np.sin(2 * math.pi * f0 * np.arange(n) / fs + phase))
    f, a = spectral_peak(x, fs, max(0.0, f0 - 20 * df), min(fs / 2, f0 + 20 * df))
    assert abs(f - f0) < 1e-3 * df
    assert abs(a / amp - 1.0) < 5e-3
