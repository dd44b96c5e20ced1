"""Invariances of the cage-speed estimator (:func:`thermobearing.signal.estimate_cage_speed`,
session 20), beside the tone recovery of test_prop19_signal.py.

The estimate depends on the record only through power ratios, so it must not change when the
record is multiplied by any factor (a change of unit: g, m/s^2, mm/s^2 ... or a gain),
negated (sensor polarity) or offset (a DC level: the demodulation band lies above it); it
changes only within its own uncertainty when the record starts a few samples later (a time
shift), and the cage line of the same synthetic bearing sampled at another rate is found at
the same frequency within a small fraction of a bin.

The record is the impulse train of test_signal.py (ball passes at Z f_c, amplitude
modulated at f_c, ringing a 3 kHz resonance, 0 dB white noise): Z = 9, f_shaft = 30 Hz,
CSR 0.42, 2 s.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.unit.test_signal import FS, impulse_train
from thermobearing import signal as sig
from thermobearing.signal_kurtogram import kurtogram_bands

CSR, F_SHAFT, Z, CSR_TH = 0.42, 30.0, 9, 0.45


@functools.lru_cache(maxsize=8)
def _record(fs: float = FS, seed: int = 3) -> np.ndarray:
    x = impulse_train(CSR, fs=fs, f_shaft=F_SHAFT, n_balls=Z, snr_db=0.0, seed=seed,
                      duration=2.0)
    x.setflags(write=False)
    return x


@functools.lru_cache(maxsize=8)
def _base(seed: int = 3):
    return sig.estimate_cage_speed(_record(FS, seed), FS, F_SHAFT, Z, CSR_TH)


def _estimate(x, fs=FS):
    return sig.estimate_cage_speed(x, fs, F_SHAFT, Z, CSR_TH)


@settings(max_examples=25, deadline=None)
@given(exponent=st.floats(-150.0, 150.0), negate=st.booleans(), seed=st.integers(0, 3))
def test_estimate_is_scale_and_polarity_free(exponent, negate, seed):
    """Defect found by this test: a record whose peak was beyond about 1e+-75 was reported
    'no significant cage comb' (the squared envelope's spectrum and the kurtogram's fourth
    moments hold x^4: over/underflow; the same train at 1e80 or 1e-80 m/s^2 was not
    detected, at 1e-75 its CSR moved by 2e-6). The record is now analysed at unit peak:
    the same CSR to round-off at any scale."""
    base = _base(seed)
    assert base.detected
    c = (-1.0 if negate else 1.0) * 10.0**exponent
    est = _estimate(c * _record(FS, seed))
    assert est.detected
    assert math.isclose(est.csr, base.csr, rel_tol=1e-12)
    assert [(ln.kind, ln.detected) for ln in est.lines] == [
        (ln.kind, ln.detected) for ln in base.lines]
    kb = kurtogram_bands(c * _record(FS, seed), FS, 3)
    k0 = kurtogram_bands(_record(FS, seed), FS, 3)
    assert [k.band for k in kb] == [k.band for k in k0]


@settings(max_examples=10, deadline=None)
@given(offset=st.floats(-1e4, 1e4))
def test_estimate_ignores_a_dc_offset(offset):
    x = _record()
    est = _estimate(x + offset * float(np.std(x)))
    assert est.detected
    assert math.isclose(est.csr, _base().csr, rel_tol=1e-9)


@settings(max_examples=10, deadline=None)
@given(shift=st.integers(1, int(FS / (CSR * F_SHAFT))))
def test_time_shift_moves_the_estimate_within_its_uncertainty(shift):
    """Dropping the first samples (up to one cage revolution): the CSR moves by less than
    three times the sum of the two standard uncertainties (measured: 5e-7 relative against
    uncertainties of 1.4e-5)."""
    base = _base()
    est = _estimate(_record()[shift:])
    assert est.detected
    assert abs(est.csr - base.csr) <= 3.0 * (est.csr_uncertainty + base.csr_uncertainty)


@settings(max_examples=6, deadline=None)
@given(factor=st.sampled_from([0.75, 1.25, 1.5, 2.0, 3.0]))
def test_sampling_rate_leaves_the_cage_line_in_place(factor):
    """The same bearing sampled at 19.2-76.8 kHz: CSR within 1e-4 of the true 0.42, i.e.
    0.0025 bin of the 0.5 Hz resolution at f_c = 12.6 Hz (measured 2e-6 .. 2.5e-5)."""
    fs = FS * factor
    est = _estimate(_record(fs), fs)
    assert est.detected
    assert abs(est.csr / CSR - 1.0) < 1e-4


@settings(max_examples=4, deadline=None)
@given(seed=st.integers(0, 3))
def test_time_reversal_keeps_the_cage_line(seed):
    """A record played backwards has the same power spectrum, the same kurtogram cells and
    an envelope with the same spectral magnitudes: the same bands, and a CSR within its
    uncertainty (measured 3e-8 relative, the sub-bin interpolation of the padded spectrum
    seeing another phase; uncertainty 1.4e-5)."""
    base = _base(seed)
    est = _estimate(np.ascontiguousarray(_record(FS, seed)[::-1]))
    assert est.detected
    assert est.spectrum.bands == base.spectrum.bands
    assert abs(est.csr - base.csr) <= 0.1 * (est.csr_uncertainty + base.csr_uncertainty)


@settings(max_examples=15, deadline=None)
@given(exponent=st.floats(-70.0, 70.0))
def test_envelope_spectrum_scales_with_the_fourth_power(exponent):
    """envelope_spectrum's power is in unit^4: c x gives c^4 times the power and the same
    normalised spectrum; a record whose fourth power is not representable (beyond about
    1e+-75) is an InputError (its normalised spectrum was NaN without a word)."""
    from thermobearing.errors import InputError
    from thermobearing.signal_envelope import envelope_spectrum

    x = _record()
    c = 10.0**exponent
    a = envelope_spectrum(x, FS, (1500.0, 4500.0), max_frequency=500.0)
    b = envelope_spectrum(c * x, FS, (1500.0, 4500.0), max_frequency=500.0)
    np.testing.assert_allclose(b.normalised, a.normalised, rtol=1e-9)
    np.testing.assert_allclose(b.power, a.power * c**4, rtol=1e-9)
    for huge in (1e80, 1e-80):
        with pytest.raises(InputError, match="signal"):
            envelope_spectrum(huge * x, FS, (1500.0, 4500.0))
