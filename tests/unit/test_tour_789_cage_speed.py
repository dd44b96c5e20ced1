"""User tour of ``thermobearing cage-speed`` (issue 8): messages and the spectrum plot.

Found on the tour: a record sampled too slowly for the kurtogram got
``band = 'min_frequency 301 Hz, min_bandwidth 332 Hz' is not allowed`` although the user
gave no band (the rate was the problem, and the rate check before it had passed); a noise
record's "not detected" reason said "all strong lines on shaft harmonics" when there were
no lines at all; the envelope panel of the plot was linear (the cage lines, 1e2-1e4 times
the noise floor, invisible beside a 1e5 ball-pass line) and the raw spectrum of a 60 s
record drew 1.5 M points.
"""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing import cli
from thermobearing import signal as S
from thermobearing.commands.cage_speed import _peak_hold
from thermobearing.errors import InputError

# SKF 6304 (Z = 7, pure-rolling CSR 0.3677 at 0 deg) at 1800 r/min: the comb reaches
# 3 Z f_c at CSR 1.3 x 0.3677, i.e. 301 Hz
Z, CSR_TH, F_SHAFT = 7, 0.3677083333333333, 30.0


def test_rate_too_low_for_the_kurtogram_names_the_rate_and_the_rate_needed():
    fs = 1280.0  # passes the comb check (> 4 x 301 Hz) but leaves no band 332 Hz wide
    x = np.random.default_rng(1).normal(size=int(4 * fs))
    with pytest.raises(InputError) as info:
        S.estimate_cage_speed(x, fs, F_SHAFT, Z, CSR_TH)
    err = info.value
    assert err.field == "sampling_rate" and err.value == fs
    assert "at least 1332 Hz" in str(err) and "--band" in str(err)
    # at the rate it names, the kurtogram finds a band (noise: analysed, not detected)
    fs2 = 1332.0
    est = S.estimate_cage_speed(np.random.default_rng(2).normal(size=int(4 * fs2)), fs2,
                                F_SHAFT, Z, CSR_TH)
    assert not est.detected


def test_not_detected_reason_does_not_invent_shaft_lines():
    x = np.random.default_rng(3).normal(size=4 * 25600)
    est = S.estimate_cage_speed(x, 25600.0, F_SHAFT, Z, CSR_TH)
    assert not est.detected and est.cage_frequency is None
    assert "no significant cage comb" in est.reason
    strong = [ln for ln in est.lines if ln.kind != "shaft" and ln.snr > 20.0]
    assert not strong  # noise: no line stands out ...
    assert "shaft harmonics" not in est.reason  # ... so none "on shaft harmonics" either


def test_peak_hold_keeps_a_one_bin_line_and_thins_the_rest():
    f = np.arange(1_500_001) * 0.0167
    a = np.full(f.size, 1e-3)
    a[1_234_567] = 5.0
    fp, ap = _peak_hold(f, a)
    assert ap.size <= 6000 and ap.max() == 5.0
    assert fp[int(np.argmax(ap))] == pytest.approx(f[1_234_567], abs=300 * 0.0167)
    f2, a2 = _peak_hold(f[:100], a[:100])
    assert f2.size == 100


def test_plot_of_a_long_record_is_written(tmp_path, capsys):
    fs = 25600.0
    x = np.random.default_rng(4).normal(size=int(20 * fs))
    np.save(tmp_path / "long.npy", x)
    rc = cli.main(["cage-speed", str(tmp_path / "long.npy"), "--fs", "25.6 kHz", "--rpm",
                   "1800", "--bearing", "SKF6304", "--plot", str(tmp_path / "p.png")])
    out = capsys.readouterr().out
    assert rc == 3 and "NOT DETECTED" in out
    assert (tmp_path / "p.png").stat().st_size > 10_000


@pytest.mark.parametrize(("angle", "message"), [
    ("40", "an angle with a unit, e.g. '40 deg'"), ("100 deg", r"in \[0, 90\) deg"),
    ("-5 deg", r"in \[0, 90\) deg")])
def test_contact_angle_needs_a_unit_and_a_range(tmp_path, capsys, angle, message):
    # before: "--contact-angle 40" was 40 rad (QJ1044 CSR_th 0.5416 instead of 0.4522) and
    # "100 deg" gave CSR_th 0.5108, both without a word
    import re

    np.save(tmp_path / "x.npy", np.random.default_rng(5).normal(size=25600))
    rc = cli.main(["cage-speed", str(tmp_path / "x.npy"), "--fs", "25600", "--rpm", "1800",
                   "--bearing", "QJ1044", "--no-plot", f"--contact-angle={angle}"])
    err = capsys.readouterr().err
    assert rc == 1 and "--contact-angle" in err and re.search(message, err)


def test_contact_angle_with_unit_sets_the_pure_rolling_ratio(tmp_path, capsys):
    np.save(tmp_path / "x.npy", np.random.default_rng(6).normal(size=4 * 25600))
    cli.main(["cage-speed", str(tmp_path / "x.npy"), "--fs", "25600", "--rpm", "1800",
              "--bearing", "QJ1044", "--no-plot", "--contact-angle", "40 deg"])
    assert "CSR_th = 0.4522" in capsys.readouterr().out  # (1 - D cos 40 deg / d_m) / 2


def test_clipped_record_is_said_and_still_measured(tmp_path, capsys):
    # a DAQ input range too small: 10 % of the samples at the rails. Before: not a word.
    from thermobearing.commands.cage_speed import clipped_fraction

    rng = np.random.default_rng(7)
    fs, f_shaft, csr = 25600.0, 30.0, 0.34
    t = np.arange(int(4 * fs)) / fs
    fc = csr * f_shaft
    # ball-pass bursts (Z = 7) modulated at the cage frequency, ringing at 3 kHz, + noise
    env = (1 + 0.3 * np.cos(2 * np.pi * fc * t)) * (np.mod(t * Z * fc, 1.0) < 0.05)
    x = env * np.sin(2 * np.pi * 3000 * t) + 0.3 * rng.normal(size=t.size)
    rail = np.quantile(np.abs(x), 0.9)
    xc = np.clip(x, -rail, rail)
    assert clipped_fraction(x) < 1e-3 < 0.05 < clipped_fraction(xc)
    np.save(tmp_path / "clip.npy", xc)
    rc = cli.main(["cage-speed", str(tmp_path / "clip.npy"), "--fs", "25600", "--rpm", "1800",
                   "--bearing", "SKF6304", "--no-plot"])
    out = capsys.readouterr().out
    assert rc == 0 and "looks clipped" in out
    assert "CSR         0.3400" in out


def test_kurtogram_moments_in_chunks_equal_the_whole_stft(monkeypatch):
    # a 60 s, 51.2 kHz record held 0.55 GB of STFT at once in the kurtogram (0.33 GB peak
    # for the whole analysis now); the chunked moments must be those of scipy's STFT
    from scipy import signal as sps

    import thermobearing.signal_kurtogram as K

    x = np.random.default_rng(8).standard_t(3, size=50_001)  # impulsive: SK > 0
    monkeypatch.setattr(K, "_CHUNK_VALUES", 1000)  # many chunks
    for nw in (8, 64, 512):
        f, _, z = sps.stft(x, fs=1000.0, window="hann", nperseg=nw, noverlap=3 * nw // 4,
                           boundary=None, padded=False, detrend=False)
        p2 = np.abs(z) ** 2
        sk = (p2**2).mean(axis=1) / p2.mean(axis=1) ** 2
        f2, m2, m4 = K._stft_moments(x, 1000.0, nw)
        assert np.array_equal(f, f2)
        assert np.allclose(m4 / m2**2, sk, rtol=1e-10, atol=0)


def _train(csr, f_shaft, n, fs=25600.0, duration=2.0, f_res=9000.0, seed=0):
    """Impulses at n csr f_shaft, 30 % modulated at csr f_shaft, ringing at f_res, + 0 dB
    white noise (the generator of the paper 002 analyser case)."""
    from thermobearing.validation.runners_vibration import _synthetic_record

    return _synthetic_record(csr * f_shaft, n, fs, duration, np.random.default_rng(seed),
                             resonance=f_res)


def test_fast_bearing_at_25k6_uses_fewer_ball_pass_harmonics(tmp_path, capsys):
    # D1842926 (Z = 30) at 13218 r/min: 3 Z f_c reaches 11.9 kHz, a 47.6 kHz rate; a
    # 25.6 kHz rig record was refused outright before. The fundamentals (f_c ~ 97 Hz,
    # BPFO ~ 2.9 kHz) fit: the comb drops to one ball-pass harmonic and says so.
    from thermobearing.geometry import load_bearing

    b = load_bearing("D1842926")
    f_shaft = 13218 / 60
    np.save(tmp_path / "hs.npy", _train(0.44, f_shaft, b.n_elements))
    rc = cli.main(["cage-speed", str(tmp_path / "hs.npy"), "--fs", "25600", "--rpm", "13218",
                   "--bearing", "D1842926", "--no-plot"])
    out = capsys.readouterr().out
    assert rc == 0 and "CSR         0.4400" in out
    assert "comb reduced to 1 ball-pass harmonic(s)" in out
    assert "(roller pass " in out and "= BPFO)" in out  # not "ball pass" for rollers
    rc = cli.main(["cage-speed", str(tmp_path / "hs.npy"), "--fs", "25600", "--rpm", "13218",
                   "--bearing", "D1842926", "--no-plot", "--ball-pass-harmonics", "3"])
    err = capsys.readouterr().err
    assert rc == 1 and "fewer ball-pass harmonics than 3" in err
    # noise with the reduced comb: still not detected
    np.save(tmp_path / "n.npy", np.random.default_rng(9).normal(size=2 * 25600))
    rc = cli.main(["cage-speed", str(tmp_path / "n.npy"), "--fs", "25600", "--rpm", "13218",
                   "--bearing", "D1842926", "--no-plot"])
    assert rc == 3 and "NOT DETECTED" in capsys.readouterr().out
