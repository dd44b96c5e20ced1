"""User tour of ``thermobearing cage-speed`` (issue 8): the files a test rig's DAQ exports.

Before the tour, the reader took only comma-separated files with one header row: a
semicolon-separated export with decimal commas and a units row, a tab-separated file and a
file with an empty cell all failed with "numeric CSV rows (could not convert string to
float: ...)"; a time column in milliseconds gave a rate 1000x too small; a sample counter
as first column was read as a time at 1 Hz; a 2-D .npy could not be read at all; the
printout did not say which channel it analysed; a 60 s, 51.2 kHz CSV took 27 s CPU and
1.4 GB (pandas' C parser now).
"""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing import cli
from thermobearing import signal as S
from thermobearing.errors import InputError
from thermobearing.validation.runners_vibration import _synthetic_record

FS = 25600.0


def record(csr=0.4, duration=1.0, f_shaft=30.0, n_balls=9, seed=0):
    """Ball-pass impulses (Z f_c, 30 % modulated at f_c) ringing a 3 kHz resonance, plus
    white noise of equal power (0 dB): the cage speed ratio of this record is ``csr`` (the
    generator of the paper 002 analyser case)."""
    return _synthetic_record(csr * f_shaft, n_balls, FS, duration,
                             np.random.default_rng(seed))


def write(path, lines):
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def test_semicolon_decimal_comma_units_row(tmp_path):
    x = record(duration=0.5)
    y = -x
    t = np.arange(x.size) / FS
    rows = ["Time;Accel X;Accel Y", "s;m/s^2;m/s^2"] + [
        f"{a:.7f};{b:.6f};{c:.6f}".replace(".", ",") for a, b, c in zip(t, x, y, strict=True)]
    rec = S.load_acceleration(write(tmp_path / "daq.csv", rows))
    assert rec.sampling_rate == pytest.approx(FS, rel=1e-6)
    assert np.allclose(rec.data, x, atol=1e-6)
    assert rec.channel == "Accel X" and rec.n_channels == 2
    rec = S.load_acceleration(tmp_path / "daq.csv", column="Accel Y")
    assert np.allclose(rec.data, y, atol=1e-6) and rec.channel == "Accel Y"


@pytest.mark.parametrize("suffix", [".txt", ".csv", ".tsv"])
def test_tab_separated(tmp_path, suffix):
    x = record(duration=0.5)
    t = np.arange(x.size) / FS
    rows = ["Time\tacc"] + [f"{a:.7f}\t{b:.6f}" for a, b in zip(t, x, strict=True)]
    rec = S.load_acceleration(write(tmp_path / f"daq{suffix}", rows))
    assert rec.sampling_rate == pytest.approx(FS, rel=1e-6) and rec.data.size == x.size


def test_time_column_in_milliseconds(tmp_path):
    # before: the rate came out as 25.6 Hz (the time read as seconds)
    x = record(duration=0.5)
    t_ms = 1e3 * np.arange(x.size) / FS
    rows = ["Time [ms],acc [g]"] + [f"{a:.6f},{b:.6f}" for a, b in zip(t_ms, x, strict=True)]
    rec = S.load_acceleration(write(tmp_path / "ms.csv", rows))
    assert rec.sampling_rate == pytest.approx(FS, rel=1e-6)
    rows = ["t,acc", "ms,g"] + [f"{a:.6f},{b:.6f}" for a, b in zip(t_ms, x, strict=True)]
    rec = S.load_acceleration(write(tmp_path / "ms_units_row.csv", rows))
    assert rec.sampling_rate == pytest.approx(FS, rel=1e-6)


def test_sample_counter_is_no_time_column(tmp_path):
    # before: a counter 0, 1, 2, ... was a time column: "sampling rate 1 Hz"
    x = record(duration=0.5)
    rows = ["sample,acc"] + [f"{i},{b:.6f}" for i, b in enumerate(x)]
    path = write(tmp_path / "counter.csv", rows)
    with pytest.raises(InputError, match="counts samples"):
        S.load_acceleration(path)
    rec = S.load_acceleration(path, sampling_rate=FS)
    assert rec.sampling_rate == FS and np.allclose(rec.data, x, atol=1e-6)


def test_empty_cell_is_a_missing_sample_named_by_index(tmp_path):
    x = record(duration=0.5)
    t = np.arange(x.size) / FS
    rows = ["time,acc"] + [f"{a:.7f},{'' if i == 42 else f'{b:.6f}'}"
                           for i, (a, b) in enumerate(zip(t, x, strict=True))]
    with pytest.raises(InputError, match=r"1 NaN/inf samples \(first at index 42\)"):
        S.load_acceleration(write(tmp_path / "gap.csv", rows))


def test_text_in_a_data_row_names_row_and_column(tmp_path):
    x = record(duration=0.5)
    t = np.arange(x.size) / FS
    rows = ["time,acc"] + [f"{a:.7f},{'OVL' if i == 9 else f'{b:.6f}'}"
                           for i, (a, b) in enumerate(zip(t, x, strict=True))]
    with pytest.raises(InputError, match="data row 10, column 2: 'OVL'"):
        S.load_acceleration(write(tmp_path / "ovl.csv", rows))


def test_two_dimensional_npy_needs_a_column(tmp_path):
    x = record(duration=0.5)
    np.save(tmp_path / "two.npy", np.column_stack([x, -x]))
    with pytest.raises(InputError, match=r"column index in \[0, 1\]"):
        S.load_acceleration(tmp_path / "two.npy", sampling_rate=FS)
    rec = S.load_acceleration(tmp_path / "two.npy", sampling_rate=FS, column=1)
    assert np.array_equal(rec.data, -x) and rec.channel == "[:, 1]"


def test_cli_names_the_channel_and_finds_the_cage(tmp_path, capsys):
    # paper 002 point 2 again (CSR 15.13/30.2 = 0.501 at f_i = 30.2 Hz), QJ1044 (Z from the
    # preset), exported by a DAQ with semicolons, decimal commas and a units row
    from thermobearing.geometry import load_bearing

    z = load_bearing("QJ1044").n_balls
    x = record(15.13 / 30.2, duration=4.0, f_shaft=30.2, n_balls=z, seed=5)
    t = np.arange(x.size) / FS
    rows = ["Zeit;Beschl. DE;Beschl. NDE", "s;m/s2;m/s2"] + [
        f"{a:.7f};{b:.6f};{b:.6f}".replace(".", ",") for a, b in zip(t, x, strict=True)]
    path = write(tmp_path / "export.csv", rows)
    rc = cli.main(["cage-speed", str(path), "--rpm", "1812", "--bearing", "QJ1044",
                   "--no-plot"])
    out = capsys.readouterr().out
    assert rc == 0
    assert "[Beschl. DE]" in out and "of 2 (--column picks another)" in out
    assert "CSR         0.5010" in out


def test_metadata_block_bom_crlf_header_and_units_row(tmp_path):
    # a DAQ export with a BOM, CRLF line ends, metadata lines (one with as many cells as
    # the data: it was taken for the header, channel '2026-11-23'), channel names with
    # units and a units row below them
    x = record(duration=0.5)
    t = np.arange(x.size) / FS
    lines = ["Export from DAQ v2.1", "Sample rate: 25600 Hz", "Date;2026-11-23;10:00", "",
             "Time [s];Acc DE [m/s²];Acc NDE [m/s²]", "s;m/s²;m/s²"]
    lines += [f"{a:.7f};{b:.6f};{-b:.6f}".replace(".", ",") for a, b in zip(t, x, strict=True)]
    path = tmp_path / "export.csv"
    path.write_text("\r\n".join(lines) + "\r\n", encoding="utf-8-sig", newline="")
    rec = S.load_acceleration(path)
    assert rec.channel == "Acc DE [m/s²]" and rec.sampling_rate == pytest.approx(FS, rel=1e-6)
    rec = S.load_acceleration(path, column="Acc NDE [m/s²]")
    assert np.allclose(rec.data, -x, atol=1e-6)
    # one text row only is the header, even when its words parse as units ('t', 'acc')
    rows = ["t acc"] + [f"{a:.7f}   {b:.6f}" for a, b in zip(t, x, strict=True)]
    rec = S.load_acceleration(write(tmp_path / "spaces.txt", rows))
    assert rec.channel == "acc" and rec.sampling_rate == pytest.approx(FS, rel=1e-6)


def test_example_synthetic_vibration_file_round_trip(tmp_path, capsys):
    # examples/make_synthetic_vibration.py: model record (anti-aliased) + 0 dB noise written
    # as a DAQ export with semicolons and decimal commas; cage-speed gets the true CSR back
    import importlib.util
    from pathlib import Path

    path = Path(__file__).parents[2] / "examples" / "make_synthetic_vibration.py"
    spec = importlib.util.spec_from_file_location("make_synthetic_vibration", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    out = tmp_path / "syn.csv"
    assert mod.main(["--slip", "-0.12", "--duration", "1.5", "--sep", ";", "--out",
                     str(out)]) == 0
    capsys.readouterr()
    rc = cli.main(["cage-speed", str(out), "--rpm", "1800", "--bearing", "SKF6304",
                   "--no-plot"])
    text = capsys.readouterr().out
    assert rc == 0
    # true CSR (1 + 0.12) x 0.3677083 = 0.411833
    assert "CSR         0.4118" in text and "slip        -12.0" in text


def test_wav_file_carries_its_rate_and_channels(tmp_path):
    from scipy.io import wavfile

    x = record(duration=0.5)
    pcm = np.round(x / np.abs(x).max() * 32000).astype(np.int16)
    wavfile.write(tmp_path / "rec.wav", int(FS), np.column_stack([pcm, -pcm]))
    with pytest.raises(InputError, match=r"column index in \[0, 1\]"):
        S.load_acceleration(tmp_path / "rec.wav")
    rec = S.load_acceleration(tmp_path / "rec.wav", column=0)
    assert rec.sampling_rate == FS and np.array_equal(rec.data, pcm.astype(float))
    with pytest.raises(InputError, match="rate of the file"):
        S.load_acceleration(tmp_path / "rec.wav", sampling_rate=FS / 2, column=0)


def test_fill_gaps_interpolates_short_dropouts_only(tmp_path):
    x = record(duration=0.5)
    y = x.copy()
    y[[100, 5000, 5001]] = np.nan  # three dropouts, the longest 2 samples
    np.save(tmp_path / "drop.npy", y)
    with pytest.raises(InputError, match="--fill-gaps"):
        S.load_acceleration(tmp_path / "drop.npy", sampling_rate=FS)
    rec = S.load_acceleration(tmp_path / "drop.npy", sampling_rate=FS, fill_gaps=True)
    assert rec.gaps_filled == 3 and np.all(np.isfinite(rec.data))
    assert rec.data[100] == pytest.approx(0.5 * (x[99] + x[101]))
    assert np.array_equal(rec.data[:100], x[:100])
    y[2000:2010] = np.nan  # a 10-sample dropout: not filled, named
    np.save(tmp_path / "long_drop.npy", y)
    with pytest.raises(InputError, match="the longest run 10 at index 2000"):
        S.load_acceleration(tmp_path / "long_drop.npy", sampling_rate=FS, fill_gaps=True)
