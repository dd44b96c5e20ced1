"""Tests of thermobearing.signal: envelope analysis and cage speed from vibration."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing import signal as S
from thermobearing.errors import InputError

FS = 25600.0


def impulse_train(csr, *, fs=FS, duration=1.0, f_shaft=30.0, n_balls=9, snr_db=0.0,
                  cage_modulation=0.3, f_res=3000.0, zeta=0.03, seed=0):
    """Ball-pass impulses (rate Z f_c, amplitude modulated at f_c) ringing a resonance,
    plus white noise at ``snr_db`` (noise power relative to signal power)."""
    rng = np.random.default_rng(seed)
    n = int(fs * duration)
    fc = csr * f_shaft
    imp = np.zeros(n)
    for tk in np.arange(0.0, duration, 1.0 / (n_balls * fc)):
        i = int(round(tk * fs))
        if i < n:
            imp[i] += 1.0 + cage_modulation * math.cos(2 * math.pi * fc * tk)
    th = np.arange(int(0.01 * fs)) / fs
    w = 2 * math.pi * f_res
    h = np.exp(-zeta * w * th) * np.sin(w * math.sqrt(1 - zeta**2) * th)
    x = np.convolve(imp, h)[:n]
    noise = rng.normal(scale=math.sqrt(np.mean(x**2) / 10 ** (snr_db / 10)), size=n)
    return x + noise


# -- paper 002 section 4.2 arithmetic: f_i = 30.2 Hz ---------------------------------
@pytest.mark.parametrize(("cage_hz", "csr"), [(6.93, 0.229), (15.13, 0.501), (13.67, 0.4527)])
def test_paper002_csr_arithmetic(cage_hz, csr):
    # Gao et al. 2022 (seed 002) sec. 4.2: CSR = CRF / f_i with f_i = 30.2 Hz, as printed
    # to 3-4 digits. Within one unit of the last printed digit: 13.67 / 30.2 = 0.452649,
    # which the brief quotes as 0.4527 (rounded half-up from 0.45265).
    last_digit = 10.0 ** -len(str(csr).split(".")[1])
    assert abs(S.cage_speed_ratio(cage_hz, 30.2) - csr) <= last_digit


def test_cage_slip_sign_convention():
    # paper 004 eq. 2: s_c = 1 - w_ca / w_ct; over-skidding (CSR > CSR_th) is negative
    assert S.cage_slip(0.40, 0.452) == pytest.approx(1 - 0.40 / 0.452)
    assert S.cage_slip(0.501, 0.452) < 0
    with pytest.raises(InputError):
        S.cage_slip(0.4, 0.0)
    with pytest.raises(InputError):
        S.cage_speed_ratio(10.0, -1.0)


# -- round trip on a synthetic impulse train at 0 dB SNR -------------------------------
@pytest.mark.parametrize("slip", [-0.12, 0.0, 0.2, 0.4, 0.6])
def test_synthetic_round_trip_0db(slip):
    csr_th = 0.45
    csr = (1 - slip) * csr_th
    x = impulse_train(csr, snr_db=0.0, seed=int(100 * slip) + 20)
    est = S.estimate_cage_speed(x, FS, 30.0, 9, csr_th)
    assert est.detected
    assert abs(est.csr / csr - 1) < 0.005
    assert est.slip == pytest.approx(slip, abs=0.005 * (1 - slip) + 1e-12)
    assert est.ball_pass_frequency == pytest.approx(9 * est.cage_frequency)
    assert 0.9 <= est.confidence <= 1.0


def test_ball_pass_only_signal_gives_cage_speed():
    # a perfect bearing (paper 004): no cage line, only Z f_c; CSR from the ball pass
    csr = 0.45 * 0.7
    x = impulse_train(csr, cage_modulation=0.0, snr_db=0.0, seed=3)
    est = S.estimate_cage_speed(x, FS, 30.0, 9, 0.45)
    assert est.detected
    assert abs(est.csr / csr - 1) < 0.005


def test_noise_only_is_not_detected():
    x = np.random.default_rng(11).normal(size=int(FS))
    est = S.estimate_cage_speed(x, FS, 30.0, 9, 0.45)
    assert not est.detected
    assert est.cage_frequency is None and est.csr is None and est.slip is None
    assert "no significant" in est.reason
    assert est.false_alarm_probability > 1e-3


def test_envelope_spectrum_of_am_tone():
    # carrier 4 kHz amplitude modulated at 37.25 Hz: squared envelope line at 37.25 Hz
    t = np.arange(int(FS)) / FS
    x = (1 + 0.5 * np.cos(2 * np.pi * 37.25 * t)) * np.sin(2 * np.pi * 4000 * t)
    es = S.envelope_spectrum(x, FS, (3000.0, 5000.0))
    f, snr = S.refine_peak(es, 37.0, 1.0)
    assert f == pytest.approx(37.25, abs=0.01)  # sub-bin (bin = 1 Hz)
    assert snr > 100


def test_kurtogram_finds_resonance_band():
    x = impulse_train(0.4, snr_db=0.0, f_res=6000.0)
    kg = S.kurtogram_band(x, FS, min_frequency=500.0)
    assert kg.band[0] < 6000.0 < kg.band[1]
    assert kg.kurtosis > 1.0


# -- bad input ---------------------------------------------------------------------------
def test_bad_inputs():
    x = impulse_train(0.4)
    bad = x.copy()
    bad[100] = np.nan
    with pytest.raises(InputError, match="NaN"):
        S.estimate_cage_speed(bad, FS, 30.0, 9, 0.45)
    with pytest.raises(InputError, match="constant"):
        S.estimate_cage_speed(np.full(30000, 2.0), FS, 30.0, 9, 0.45)
    with pytest.raises(InputError, match="Nyquist"):
        S.estimate_cage_speed(x, FS, 30.0, 9, 0.45, band=(10000.0, 14000.0))
    with pytest.raises(InputError, match="sampling_rate"):
        S.estimate_cage_speed(x[::40], FS / 40, 30.0, 9, 0.45)
    with pytest.raises(InputError, match="duration"):
        S.estimate_cage_speed(x[:2000], FS, 30.0, 9, 0.45)
    with pytest.raises(InputError):
        S.estimate_cage_speed(x, FS, 30.0, 9, 0.45, search=(1.2, 0.5))


def test_load_csv_and_npy(tmp_path):
    x = impulse_train(0.4, duration=0.5)
    np.save(tmp_path / "a.npy", x)
    rec = S.load_acceleration(tmp_path / "a.npy", sampling_rate=FS)
    assert rec.sampling_rate == FS and np.array_equal(rec.data, x)
    with pytest.raises(InputError, match="sampling_rate"):
        S.load_acceleration(tmp_path / "a.npy")
    t = np.arange(x.size) / FS
    np.savetxt(tmp_path / "b.csv", np.column_stack([t, x]), delimiter=",",
               header="time_s,accel_m_s2", comments="")
    rec = S.load_acceleration(tmp_path / "b.csv")
    assert rec.sampling_rate == pytest.approx(FS, rel=1e-9)
    assert np.allclose(rec.data, x)
    with pytest.raises(InputError, match="rate of the file"):
        S.load_acceleration(tmp_path / "b.csv", sampling_rate=10000.0)
    gap = np.column_stack([np.delete(t, np.s_[100:110]), np.delete(x, np.s_[100:110])])
    np.savetxt(tmp_path / "gap.csv", gap, delimiter=",")
    with pytest.raises(InputError, match="non-uniform"):
        S.load_acceleration(tmp_path / "gap.csv")
    np.savetxt(tmp_path / "c.csv", np.full(1000, 1.0))
    with pytest.raises(InputError, match="constant"):
        S.load_acceleration(tmp_path / "c.csv", sampling_rate=FS)
    with pytest.raises(InputError):
        S.load_acceleration(tmp_path / "missing.csv", sampling_rate=FS)


def test_cage_speed_command(tmp_path, capsys):
    # thermobearing cage-speed FILE --rpm --bearing: QJ1044 preset (Z from the preset), a
    # synthetic record with the cage at 15.13 Hz at f_i = 30.2 Hz (paper 002 point 2)
    from thermobearing.cli import main
    from thermobearing.geometry import load_bearing

    z = load_bearing("QJ1044").n_balls
    x = impulse_train(15.13 / 30.2, f_shaft=30.2, n_balls=z, duration=4.0, seed=5)
    np.save(tmp_path / "rec.npy", x)
    plot = tmp_path / "out.png"
    rc = main(["cage-speed", str(tmp_path / "rec.npy"), "--fs", "25.6 kHz", "--rpm", "1812",
               "--bearing", "QJ1044", "--plot", str(plot)])
    out = capsys.readouterr().out
    assert rc == 0
    assert "CSR         0.5010" in out and "over-skidding" in out
    assert plot.is_file() and plot.stat().st_size > 10_000
    np.save(tmp_path / "noise.npy", np.random.default_rng(3).normal(size=int(4 * FS)))
    rc = main(["cage-speed", str(tmp_path / "noise.npy"), "--fs", "25600", "--rpm", "1812",
               "--bearing", "QJ1044", "--no-plot"])
    assert rc == 3
    assert "NOT DETECTED" in capsys.readouterr().out
    assert main(["cage-speed", str(tmp_path / "noise.npy"), "--rpm", "1812",
                 "--bearing", "QJ1044"]) == 1  # no sampling rate: clear error


def test_shaft_modulation_alone_is_not_a_cage_line():
    # impulses once per shaft revolution (runout/unbalance) give envelope lines at m f_s
    # only; f_s / 7 would put the ball pass of a 7-ball bearing on them: not a cage speed
    x = impulse_train(1.0 / 7.0, n_balls=7, cage_modulation=0.0, snr_db=0.0, seed=9)
    est = S.estimate_cage_speed(x, FS, 30.0, 7, 0.37, search=(0.3, 1.3))
    assert not est.detected


def test_cage_harmonic_beside_the_shaft_is_not_reported_as_the_shaft_line():
    """At CSR 0.488 (QJ1044 over-skidding 8 %) the second cage harmonic, 29.5 Hz, falls in
    the +-2 % window around the 30.2 Hz shaft frequency; a signal without any shaft
    component must not report it as a measured shaft line (it once did)."""
    csr = 0.452 * 1.08
    x = impulse_train(csr, f_shaft=30.2, n_balls=20, duration=2.0, snr_db=0.0,
                      cage_modulation=0.5, seed=4)
    est = S.estimate_cage_speed(x, FS, 30.2, 20, 0.452)
    assert est.detected and abs(est.csr / csr - 1) < 0.005
    assert est.measured_shaft_frequency is None
    shaft = [ln for ln in est.lines if ln.kind == "shaft"]
    assert len(shaft) == 1 and not shaft[0].detected


def test_a_real_shaft_line_is_still_measured():
    """Amplitude modulation at the shaft frequency (runout) next to the cage comb: the shaft
    line is measured at its frequency."""
    t = np.arange(int(2 * FS)) / FS
    x = impulse_train(0.45 * 0.9, f_shaft=30.0, duration=2.0, snr_db=10.0, seed=5)
    x = x * (1.0 + 0.5 * np.cos(2 * math.pi * 30.0 * t))
    est = S.estimate_cage_speed(x, FS, 30.0, 9, 0.45)
    assert est.detected
    assert est.measured_shaft_frequency == pytest.approx(30.0, abs=0.05)
