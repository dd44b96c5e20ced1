"""Cage-speed analyser: what confirms the shaft frequency given (CSR = f_cage / f_shaft).

A line in the envelope within 0.5 % of the given shaft frequency confirmed it; with an
off-size ball the envelope holds every cage harmonic k f_c, and one of them could sit
there: a 30 Hz shaft given as 48.1 Hz (the 4th cage harmonic at CSR 0.4 is 48.0 Hz, 0.2 %
away) gave CSR 0.2495 instead of 0.4000 with no note.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing import signal as S

FS = 25600.0


def big_ball_train(csr, *, f_shaft=30.0, n_balls=9, seconds=2.0, big=1.0, runout=0.0,
                   seed=0, snr_db=0.0):
    """Ball-pass impulses, ball 0 ``1 + big`` times as strong (all cage harmonics in the
    envelope), optionally modulated by a runout at the shaft frequency; white noise."""
    rng = np.random.default_rng(seed)
    n = int(FS * seconds)
    fc = csr * f_shaft
    imp = np.zeros(n)
    for j, tk in enumerate(np.arange(0.0, seconds, 1.0 / (n_balls * fc))):
        i = int(round(tk * FS))
        if i < n:
            imp[i] += (1.0 + (big if j % n_balls == 0 else 0.0)) * (
                1.0 + runout * math.cos(2 * math.pi * f_shaft * tk))
    th = np.arange(int(0.01 * FS)) / FS
    w = 2 * math.pi * 3000.0
    x = np.convolve(imp, np.exp(-0.03 * w * th) * np.sin(w * th))[:n]
    return x + rng.normal(scale=math.sqrt(np.mean(x**2) / 10 ** (snr_db / 10)), size=n)


@pytest.mark.parametrize(("given", "k"), [(48.1, 4), (47.9, 4), (60.2, 5)])
def test_a_cage_harmonic_beside_a_wrong_shaft_frequency_confirms_nothing(given, k):
    x = big_ball_train(0.4)
    est = S.estimate_cage_speed(x, FS, given, 9, 0.45)
    assert est.detected  # the comb is real; the CSR scales with the wrong speed
    assert est.cage_frequency == pytest.approx(12.0, abs=0.01)
    assert est.measured_shaft_frequency is None
    note = [n for n in est.notes if "does not confirm the shaft frequency" in n]
    assert len(note) == 1 and f"cage harmonic {k} x" in note[0]
    assert not est.shaft_confirmed


def test_a_real_shaft_line_still_confirms_and_a_wrong_speed_still_does_not():
    x = big_ball_train(0.4, runout=0.3, seed=3)
    est = S.estimate_cage_speed(x, FS, 30.0, 9, 0.45)
    assert est.detected and est.csr == pytest.approx(0.4, abs=1e-3)
    assert est.measured_shaft_frequency == pytest.approx(30.0, abs=0.05)
    assert not [n for n in est.notes if "shaft" in n] and est.shaft_confirmed
    wrong = S.estimate_cage_speed(x, FS, 48.1, 9, 0.45)
    assert [n for n in wrong.notes if "does not confirm the shaft frequency 48.1" in n]


def test_the_shaft_line_does_not_carry_the_snr_of_a_cage_harmonic_in_its_window():
    # 48.1 Hz given: the 4th cage harmonic at 48.0 Hz is the peak of the shaft's +-2 %
    # window; the shaft entry printed 'measured -' beside that harmonic's SNR
    x = big_ball_train(0.4)
    est = S.estimate_cage_speed(x, FS, 48.1, 9, 0.45)
    shaft = [ln for ln in est.lines if ln.kind == "shaft"]
    assert len(shaft) == 1 and math.isnan(shaft[0].measured)
    assert math.isnan(shaft[0].snr) and not shaft[0].detected
    real = S.estimate_cage_speed(big_ball_train(0.4, runout=0.3, seed=3), FS, 30.0, 9, 0.45)
    own = [ln for ln in real.lines if ln.kind == "shaft"][0]
    assert own.detected and own.snr > 10.0
