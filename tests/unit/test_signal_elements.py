"""Cage-speed analyser: the bearing's element count Z checked against the spectrum.

The comb pairs the ball-pass line with Z f_c, Z from --bearing; a wrong bearing was
accepted silently: the QJ1044 model record (Z = 20) analysed as a 21- or 24-ball bearing
gave CSR 0.4400 with nothing said, as a 19-ball bearing CSR 0.4632 (f_c = BPFO / 19), an
impulse train of a 9-ball bearing analysed with Z = 7..12 read BPFO / Z at confidence 1.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.unit.test_signal import impulse_train
from tests.unit.test_signal_family import F_I, FS, qj_record
from thermobearing import signal as S
from thermobearing.geometry import load_bearing
from thermobearing.signal_checks import ball_count_check


@pytest.fixture(scope="module")
def qj044():
    b = load_bearing("QJ1044")
    return qj_record(b, 0.44), float(b.theoretical_cage_speed_ratio(b.contact_angle))


def test_the_right_count_is_consistent(qj044):
    x, csr_th = qj044
    est = S.estimate_cage_speed(x, FS, F_I, 20, csr_th)
    assert est.ball_count.status == "consistent" and est.ball_count.spectrum_count == 20
    assert not [n for n in est.notes if n.startswith("BEARING")]


@pytest.mark.parametrize("z", [18, 21, 22, 24])
def test_a_wrong_count_with_cage_lines_is_contradicted(qj044, z):
    """The cage frequency is read from its own lines (independent of Z); the strongest
    line at a multiple of it is 20 f_c, not Z f_c."""
    x, csr_th = qj044
    est = S.estimate_cage_speed(x, FS, F_I, z, csr_th)
    assert est.detected
    assert est.ball_count.status == "contradicted"
    assert est.ball_count.spectrum_count in (20, 40)  # 40 x f_c / 2 when read at half
    note = [n for n in est.notes if n.startswith("BEARING")]
    assert len(note) == 1 and "check --bearing" in note[0]


def test_a_multiple_of_the_count_is_doubtful(qj044):
    """Z = 10: the line at 20 f_c may be a strong second ball-pass harmonic or the ball pass
    of a 20-element bearing."""
    x, csr_th = qj044
    est = S.estimate_cage_speed(x, FS, F_I, 10, csr_th)
    assert est.ball_count.status == "doubtful" and est.ball_count.spectrum_count == 20


@pytest.mark.parametrize("z", [7, 8, 10, 11, 12])
def test_a_cage_reading_on_the_ball_pass_alone_names_the_other_count(z):
    """A 9-ball impulse train (cage line and cage sidebands of the ball pass) analysed with
    the wrong Z: the comb puts f_c at BPFO / Z with no cage line; the record's own cage
    family at BPFO / 9 makes Z doubtful."""
    x = impulse_train(0.38, snr_db=0.0, seed=12)
    est = S.estimate_cage_speed(x, FS, 30.0, z, 0.45)
    assert est.detected
    assert est.ball_count.status == "doubtful" and est.ball_count.spectrum_count == 9
    right = S.estimate_cage_speed(x, FS, 30.0, 9, 0.45)
    assert right.ball_count.status == "consistent"
    assert right.csr == pytest.approx(0.38, rel=0.005)


def test_without_a_cage_line_the_count_is_not_checked():
    # ball pass only (a perfect bearing): f_c = BPFO / Z whatever Z is
    x = impulse_train(0.38, snr_db=0.0, seed=13, cage_modulation=0.0)
    est = S.estimate_cage_speed(x, FS, 30.0, 9, 0.45)
    assert est.detected and est.ball_count.status == "not checked"
    assert [n for n in est.notes if "could not be checked" in n]


def test_check_function_rules():
    lines = {10.0: 1e3, 90.0: 1e4, 180.0: 5e3}  # cage, BPFO of Z = 9, its 2nd harmonic

    def power(f):
        return max((p for g, p in lines.items() if abs(g - f) < 0.25), default=0.5)

    kw = dict(shaft_frequency=23.0, resolution=0.5, threshold=12.0, f_end=400.0,
              search_band=(4.0, 16.0))
    ok = ball_count_check(power, power, 10.0, 9, independent=True, **kw)
    assert ok.status == "consistent"
    bad = ball_count_check(power, power, 10.0, 7, independent=True, **kw)
    assert bad.status == "contradicted" and bad.spectrum_count == 9
    none = ball_count_check(lambda f: 0.5, lambda f: 0.5, 10.0, 9, independent=True, **kw)
    assert none.status == "not checked"


def test_cli_prints_the_element_check(tmp_path, capsys):
    from thermobearing.cli import main

    np.save(tmp_path / "r.npy", impulse_train(0.38, f_shaft=30.2, duration=2.0, seed=12))
    assert main(["cage-speed", str(tmp_path / "r.npy"), "--fs", "25600", "--rpm", "1812",
                 "--bearing", "QJ1044", "--no-plot"]) == 0  # a 9-ball record, Z = 20
    out = capsys.readouterr().out
    assert "elements    Z = 20: DOUBTFUL by the spectrum" in out
    assert "note        BEARING:" in out
