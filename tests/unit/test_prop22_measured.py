"""Round-trip property of the measured-temperature reader (thermobearing.measured,
session 22): a random rig file is written, read with read_measured_file and compared with
what was written.

The file: comma, semicolon or tab separated (a decimal comma with the last two), metadata
and comment lines above the header, the sensor columns in a random order among unmapped
columns, the temperature unit (degC, K, degF) and the time unit (s, min, h) stated in the
header's brackets, in a units row, or left to the scene (``unit``), gaps as empty cells,
dropout flags and overload codes.

- every mapped column holds the written readings in degC, whatever its place in the file,
  NaN exactly at the gaps, and the gaps are counted by cause;
- the time column is the written times in seconds (numbers in s, min, h; timestamps of
  four layouts counted from the first row; elapsed hh:mm:ss clock times past midnight);
- the columns come back in the order the scene maps them, and the mapping order does not
  change any value.

Defect found (signal_input.guess_decimal_mark, fixed): one overload code ``+9.9E+37``
(written with a point by the instrument in any locale) among decimal-comma readings made
the whole file read with a decimal point, and the reader stopped at the first time cell
(semicolon file, times ``0,0000``, ``0,5000``: InputError "row 1: '0,0000' ... is not
allowed"; with whole-number times it stopped at the first reading ``21,5``).
"""

from __future__ import annotations

import math
import tempfile
from datetime import datetime, timedelta
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.measured import read_measured_file

SENSORS = ("TC1 outer ring", "TC2", "Housing_T", "oil out")
OTHERS = ("Speed", "Torque", "Load cell")
TIME_FACTOR = {"s": 1.0, "min": 60.0, "h": 3600.0}
FROM_C = {"degC": lambda c: c, "K": lambda c: c + 273.15, "degF": lambda c: c * 1.8 + 32.0}
GAPS = {"": "empty cells", "OVL": "dropout flags", "----": "dropout flags",
        "+9.9E+37": "overload codes"}


@st.composite
def rig_files(draw):
    sep = draw(st.sampled_from([",", ";", "\t"]))
    decimal = "," if sep != "," and draw(st.booleans()) else "."
    n_sensors = draw(st.integers(1, len(SENSORS)))
    sensors = list(draw(st.permutations(SENSORS)))[:n_sensors]
    others = draw(st.lists(st.sampled_from(OTHERS), unique=True, max_size=2))
    order = draw(st.permutations(sensors + others))
    unit = draw(st.sampled_from(list(FROM_C)))
    tunit = draw(st.sampled_from(list(TIME_FACTOR)))
    stated = draw(st.sampled_from(["brackets", "units row", "scene"]))
    n = draw(st.integers(2, 30))
    dt = draw(st.sampled_from([0.5, 1.0, 2.5, 10.0]))
    t0 = draw(st.sampled_from([0.0, 3.0, 120.0]))
    readings = {s: [draw(st.floats(-40.0, 400.0)) for _ in range(n)] for s in sensors}
    gaps = {s: [draw(st.sampled_from([None, None, None, None, *GAPS])) for _ in range(n)]
            for s in sensors}
    comments = draw(st.booleans())
    return sep, decimal, sensors, order, unit, tunit, stated, n, dt, t0, readings, gaps, \
        comments


def _num(x: float, decimal: str) -> str:
    text = f"{x:.4f}"
    return text.replace(".", ",") if decimal == "," else text


def _write(case, folder: Path):
    sep, decimal, sensors, order, unit, tunit, stated, n, dt, t0, readings, gaps, \
        comments = case
    tname = "Time" + (f" [{tunit}]" if stated == "brackets" else "")
    header = [tname] + [c + (f" [{unit}]" if stated == "brackets" and c in sensors else "")
                        for c in order]
    lines = ["Rig log export", "operator: test"]
    if comments:
        lines.append("# channels follow")
    lines.append(sep.join(header))
    if stated == "units row":
        lines.append(sep.join([tunit] + [unit if c in sensors else "rpm" for c in order]))
    expected = {s: [] for s in sensors}
    for k in range(n):
        t = t0 + k * dt
        row = [_num(t, decimal)]
        for c in order:
            if c not in sensors:
                row.append(_num(1000.0 + k, decimal))
                continue
            g = gaps[c][k]
            if g is not None:
                row.append(g)
                expected[c].append(math.nan)
                continue
            text = _num(FROM_C[unit](readings[c][k]), decimal)
            row.append(text)
            written = float(text.replace(",", "."))
            back = {"degC": written, "K": written - 273.15,
                    "degF": (written - 32.0) * 5.0 / 9.0}[unit]
            expected[c].append(back)
        lines.append(sep.join(row))
        if comments and k == 0:
            lines.append("# a comment between the rows")
    path = folder / "rig.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    times = np.array([(t0 + k * dt) * TIME_FACTOR[tunit] for k in range(n)])
    columns = {(c + (f" [{unit}]" if stated == "brackets" else "")): c for c in sensors}
    return path, tname, columns, expected, times


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rig_files())
def test_a_written_rig_file_reads_back(case):
    sep, decimal, sensors, order, unit, tunit, stated, n, dt, t0, readings, gaps, _ = case
    if stated == "scene" and tunit != "s":
        stated = "brackets"  # a bare 'Time' is seconds: the unit goes in the name
        case = (*case[:6], stated, *case[7:])
    with tempfile.TemporaryDirectory() as d:
        path, tname, columns, expected, times = _write(case, Path(d))
        out = read_measured_file(path, tname, columns, unit=unit)
        keys = list(columns)
        again = read_measured_file(path, tname, dict(reversed(list(columns.items()))),
                                   unit=unit)
    assert list(out.columns) == ["time [s]", *keys]
    np.testing.assert_allclose(out["time [s]"].to_numpy(), times, rtol=1e-12, atol=1e-9)
    for key, sensor in columns.items():
        got = out[key].to_numpy(float)
        want = np.array(expected[sensor])
        assert np.array_equal(np.isnan(got), np.isnan(want)), key
        ok = ~np.isnan(want)
        np.testing.assert_allclose(got[ok], want[ok], rtol=1e-12, atol=1e-9)
        np.testing.assert_array_equal(again[key].to_numpy(float), got)
        counts = out.attrs["gaps"][key]
        for cause in set(GAPS.values()):
            assert counts[cause] == sum(GAPS[g] == cause for g in gaps[sensor]
                                        if g is not None), (key, cause)
        assert out.attrs["units"][key] == unit


def test_an_overload_code_among_decimal_comma_readings(tmp_path):
    from thermobearing.signal_input import guess_decimal_mark

    path = tmp_path / "rig.csv"
    path.write_text("Time [s];TC1;TC2\n0,0;21,5;+9.9E+37\n0,5;21,75;22,0\n", encoding="utf-8")
    out = read_measured_file(path, "Time [s]", ["TC1", "TC2"])
    np.testing.assert_allclose(out["time [s]"], [0.0, 0.5])
    np.testing.assert_allclose(out["TC1"], [21.5, 21.75])
    assert math.isnan(out["TC2"][0]) and out["TC2"][1] == 22.0
    assert out.attrs["gaps"]["TC2"]["overload codes"] == 1
    assert guess_decimal_mark(["21,5", "+9.9E+37", "-9.90000000E+37"], ";") == ","
    assert guess_decimal_mark(["21,5", "21.5"], ";") == "."  # a reading with a point: "."
    assert guess_decimal_mark(["21,5", "9.9E+29"], ";") == "."  # a number, not a code


STAMPS = ("%Y-%m-%d %H:%M:%S", "%Y-%m-%dT%H:%M:%S", "%d.%m.%Y %H:%M:%S", "%Y/%m/%d %H:%M:%S",
          "elapsed")


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(fmt=st.sampled_from(STAMPS),
       start=st.datetimes(min_value=datetime(2000, 1, 1), max_value=datetime(2035, 12, 31)),
    steps=st.lists(st.integers(1, 4000), min_size=1, max_size=25),
    sep=st.sampled_from([",", ";", "\t"]))
def test_time_stamps_read_back_as_seconds(fmt, start, steps, sep):
    """Timestamps count from the first row; elapsed hh:mm:ss clock times are taken as they
    are, +24 h from each midnight they pass (a row at most 4000 s after the one before)."""
    start = start.replace(microsecond=0)
    stamps = [start]
    for s in steps:
        stamps.append(stamps[-1] + timedelta(seconds=s))
    if fmt == "elapsed":
        cells = [f"{t.hour}:{t.minute:02d}:{t.second:02d}" for t in stamps]
        clock0 = start.hour * 3600 + start.minute * 60 + start.second
        want = [clock0 + (t - start).total_seconds() for t in stamps]
    else:
        cells = [t.strftime(fmt) for t in stamps]
        want = [(t - start).total_seconds() for t in stamps]
    text = "\n".join([f"Time{sep}TC1"] + [f"{c}{sep}{20 + k}.5" for k, c in enumerate(cells)])
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "rig.csv"
        path.write_text(text + "\n", encoding="utf-8")
        out = read_measured_file(path, "Time", ["TC1"])
    np.testing.assert_allclose(out["time [s]"].to_numpy(), want, rtol=0, atol=1e-6)
    np.testing.assert_allclose(out["TC1"].to_numpy(), 20.5 + np.arange(len(cells)))
