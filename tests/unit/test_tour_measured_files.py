"""A rig's thermocouple file in a scene's ``[measured]`` table (thermobearing.measured).

Every file written here carries the SAME temperatures as the shipped comma/minutes example
``examples/synthetic_rig_temperatures.csv`` (SYNTHETIC data: model output + 0.1 K noise,
see its scene ``configs/scenes/qj1044_synthetic_measured.toml``), laid out the way data
loggers write them (semicolon + decimal comma + metadata + units row, tab, timestamps,
hh:mm:ss, dropout flags, BOM/CRLF). The reader must give the identical table, and the
report's measured-vs-predicted RMSE must be the same as with the original file (one run of
the example scene, ~2 s, shared by the module).
"""

from __future__ import annotations

from datetime import datetime, timedelta
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from thermobearing.calibrate_model import measured_table
from thermobearing.errors import InputError
from thermobearing.measured import read_measured_file
from thermobearing.report import read_measured, temperature_errors, write_report
from thermobearing.scene import Scene, check_measured_file, load_scene, loads_scene

EXAMPLE = "qj1044_synthetic_measured"
DE, NDE = "TC_DE_synthetic", "TC_NDE_synthetic"
START = datetime(2026, 11, 23, 10, 15, 30)


@pytest.fixture(scope="module")
def original() -> pd.DataFrame:
    """The example CSV as written (time [min], two sensors, a text column)."""
    scene = load_scene(EXAMPLE)
    return pd.read_csv(scene.resolve_path(scene.measured.file), comment="#")


@pytest.fixture(scope="module")
def reference(original) -> pd.DataFrame:
    """What read_measured gives for the shipped scene and file."""
    ref = read_measured(load_scene(EXAMPLE))
    assert list(ref.columns) == ["time [s]", DE, NDE] and len(ref) == 61
    np.testing.assert_array_equal(ref["time [s]"], original["time [min]"] * 60.0)
    np.testing.assert_array_equal(ref[DE], original[DE])
    return ref


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """One run of the example scene (race control, 60 min, ~2 s): its results."""
    from thermobearing.simulation import Simulation

    return Simulation(load_scene(EXAMPLE), progress=False).run(
        out_dir=tmp_path_factory.mktemp("run"))


def scene_with(path: Path, **measured) -> Scene:
    d = load_scene(EXAMPLE).to_dict()
    d["measured"] = {"file": path.name, "unit": "degC",
                     "columns": {DE: "drive_end.housing", NDE: "non_drive_end.housing"},
                     **measured}
    return Scene.from_dict(d, path.parent)


def write(path: Path, lines: list[str], *, bom: bool = False, crlf: bool = False) -> Path:
    text = ("\r\n" if crlf else "\n").join(lines) + ("\r\n" if crlf else "\n")
    path.write_bytes(("\ufeff" if bom else "").encode() + text.encode("utf-8"))
    return path


def rows(df: pd.DataFrame) -> list[tuple[float, float, float]]:
    """(time [min], DE, NDE) per row of the original file."""
    return list(zip(df["time [min]"], df[DE], df[NDE], strict=True))


def comma(x: float) -> str:
    return repr(float(x)).replace(".", ",")


def same_table(got: pd.DataFrame, ref: pd.DataFrame) -> None:
    assert list(got.columns) == list(ref.columns)
    for col in ref.columns:
        np.testing.assert_allclose(got[col], ref[col], rtol=0, atol=1e-9, err_msg=col)


# --------------------------------------------------------------------------- formats
def test_semicolon_decimal_comma_metadata_units_row_bom_crlf(tmp_path, original, reference,
                                                            run):
    """A European logger: BOM, CRLF, three metadata lines, header, units row ``s;°C;°C``,
    decimal commas, time in seconds (the unit from the units row: the header has none)."""
    lines = ["Logger;TC-08 rig 2;serial 4711", "Date;23.11.2026", "Channels;2", "",
             f"Zeit;{DE};{NDE}", "s;°C;°C"]
    lines += [f"{comma(t * 60)};{comma(a)};{comma(b)}"
              for t, a, b in rows(original)]
    path = write(tmp_path / "logger.csv", lines, bom=True, crlf=True)
    scene = scene_with(path, time_column="Zeit")
    got = read_measured(scene)
    same_table(got, reference)
    # the report's measured-vs-predicted table is the same as with the original file
    temps = run.tables["temperatures"]
    cols = scene.measured.columns
    pd.testing.assert_frame_equal(temperature_errors(temps, got, cols),
                                  temperature_errors(temps, reference, cols))
    html_new = write_report(run, scene, tmp_path / "new.html").read_text()
    html_ref = write_report(run, load_scene(EXAMPLE), tmp_path / "ref.html").read_text()
    table = html_ref.index("<h3>measured vs predicted</h3>")
    assert html_ref[table:html_ref.index("</table>", table)] in html_new


def test_tab_separated_with_units_row_in_minutes_and_comment_column(tmp_path, original,
                                                                   reference):
    """A LabVIEW-style tab file: metadata, header ``Time`` (no unit), units row ``min``,
    an unmapped free-text column with separators inside quotes."""
    lines = ["LabVIEW Measurement\tWriter_Version\t2", "Operator\tM", f"Time\t{DE}\t{NDE}\tnote",
             "min\tdegC\tdegC\t-"]
    lines += [f"{t}\t{a}\t{b}\t\"ok, dry; run\""
              for t, a, b in rows(original)]
    got = read_measured_file(write(tmp_path / "rig.txt", lines), "Time", [DE, NDE])
    same_table(got, reference)


@pytest.mark.parametrize("fmt, sep, dec", [
    ("%Y-%m-%dT%H:%M:%S", ",", "."),       # ISO 8601 with T
    ("%Y-%m-%d %H:%M:%S", ",", "."),       # ISO with a space
    ("%d.%m.%Y %H:%M:%S", ";", ","),       # German logger, decimal comma
    ("%d/%m/%Y %H:%M:%S", ";", "."),       # day first (23 > 12 tells it)
])
def test_timestamps_count_from_the_first_row(tmp_path, original, reference, fmt, sep, dec):
    lines = ["# exported by RigPLC v3", f"Timestamp{sep}{DE}{sep}{NDE}"]
    for t, a, b in rows(original):
        stamp = (START + timedelta(minutes=float(t))).strftime(fmt)
        va, vb = (comma(a), comma(b)) if dec == "," else (repr(a), repr(b))
        lines.append(f"{stamp}{sep}{va}{sep}{vb}")
    got = read_measured_file(write(tmp_path / "stamps.csv", lines), "Timestamp", [DE, NDE])
    same_table(got, reference)


def test_time_zero_shifts_timestamps(tmp_path, original, reference, run):
    """The logger started 2 min before the protocol: ``time_zero`` in the scene puts t = 0
    at the protocol start; the two early rows fall before the run and do not count."""
    lines = [f"Timestamp,{DE},{NDE}",
             f"{START - timedelta(minutes=2):%Y-%m-%d %H:%M:%S},22.0,22.0",
             f"{START - timedelta(minutes=1):%Y-%m-%d %H:%M:%S},OVL,22.1"]
    lines += [f"{START + timedelta(minutes=float(t)):%Y-%m-%d %H:%M:%S},{a},{b}"
              for t, a, b in rows(original)]
    path = write(tmp_path / "early.csv", lines)
    scene = scene_with(path, time_column="Timestamp", time_zero=f"{START:%Y-%m-%d %H:%M:%S}")
    got = read_measured(scene)
    assert got["time [s]"].iloc[:2].tolist() == [-120.0, -60.0]
    same_table(got.iloc[2:].reset_index(drop=True), reference)
    temps = run.tables["temperatures"]
    pd.testing.assert_frame_equal(temperature_errors(temps, got, scene.measured.columns),
                                  temperature_errors(temps, reference, scene.measured.columns))
    # without time_zero the first row is t = 0: everything 2 min later
    plain = read_measured_file(path, "Timestamp", [DE, NDE])
    np.testing.assert_allclose(plain["time [s]"].iloc[2:], reference["time [s]"] + 120.0)
    # the scene key round-trips through to_toml, and "first" is accepted
    back = loads_scene(scene.to_toml(), base_dir=path.parent)
    assert back.measured == scene.measured
    first = read_measured(scene_with(path, time_column="Timestamp", time_zero="first"))
    np.testing.assert_allclose(first["time [s]"], plain["time [s]"])


@pytest.mark.parametrize("time_column, cells, zero, expect", [
    ("t [min]", ["3", "4", "5,5"], "3", [0.0, 60.0, 150.0]),        # a number in minutes
    ("t [min]", ["3", "4", "5,5"], "first", [0.0, 60.0, 150.0]),
    ("t", ["10:00:00", "10:01:00", "10:02:30"], "09:59:00", [60.0, 120.0, 210.0]),  # clock
    ("t", ["10:00:00", "10:01:00", "10:02:30"], "first", [0.0, 60.0, 150.0]),
    ("t", ["10:00:00", "10:01:00", "10:02:30"], None, [36000.0, 36060.0, 36150.0]),
])
def test_time_zero_for_numbers_and_clock_times(tmp_path, time_column, cells, zero, expect):
    lines = [f"{time_column};TC1"] + [f"{c};35,{k}" for k, c in enumerate(cells)]
    got = read_measured_file(write(tmp_path / "z.csv", lines), time_column, ["TC1"],
                             time_zero=zero)
    np.testing.assert_allclose(got["time [s]"], expect)
    np.testing.assert_allclose(got["TC1"], [35.0, 35.1, 35.2])


def test_separate_date_and_time_columns_across_midnight(tmp_path, original, reference):
    """``Datum;Uhrzeit;...`` (ALMEMO / Testo style): ``time_column = ["Datum", "Uhrzeit"]``
    in the scene; the log runs across midnight, which a time-of-day column alone cannot."""
    start = datetime(2026, 11, 23, 23, 30, 0)
    lines = [f"Datum;Uhrzeit;{DE};{NDE}", "dd.mm.yyyy;hh:mm:ss;°C;°C"]
    for t, a, b in rows(original):
        stamp = start + timedelta(minutes=float(t))
        lines.append(f"{stamp:%d.%m.%Y};{stamp:%H:%M:%S};{comma(a)};{comma(b)}")
    path = write(tmp_path / "almemo.csv", lines)
    scene = scene_with(path, time_column=["Datum", "Uhrzeit"])
    assert scene.measured.time_column == ("Datum", "Uhrzeit")
    assert loads_scene(scene.to_toml(), base_dir=tmp_path).measured == scene.measured
    same_table(read_measured(scene), reference)
    with pytest.raises(InputError, match=r"measured.time_column.*date column"):
        scene_with(path, time_column=["Datum"])
    with pytest.raises(InputError, match=r"measured.time_column.*'Zeit'.*Datum, Uhrzeit"):
        read_measured_file(path, ["Datum", "Zeit"], [DE])


@pytest.mark.parametrize("style", ["hh:mm:ss", "mm:ss"])
def test_elapsed_clock_format(tmp_path, original, reference, style):
    lines = [f"elapsed;{DE};{NDE}", f"{style};°C;°C"]
    for t, a, b in rows(original):
        m = int(t)
        stamp = f"{m // 60:02d}:{m % 60:02d}:00" if style == "hh:mm:ss" else f"{m:02d}:00"
        lines.append(f"{stamp};{comma(a)};{comma(b)}")
    got = read_measured_file(write(tmp_path / "elapsed.csv", lines, crlf=True), "elapsed",
                             [DE, NDE])
    same_table(got, reference)


def test_dropout_flags_and_empty_cells_are_gaps(tmp_path, original, reference, run):
    """``OVL``, ``----``, ``Err`` and an empty cell read as NaN; the RMSE is that of the
    original table without those samples (their count in ``points``)."""
    flags = {3: "OVL", 17: "----", 40: "", 41: "Err"}
    lines = [f"time [min];{DE};{NDE}"]
    for k, (t, a, b) in enumerate(rows(original)):
        lines.append(f"{comma(t)};{flags.get(k, comma(a))};{comma(b)}")
    path = write(tmp_path / "broken.csv", lines)
    scene = scene_with(path, time_column="time [min]")
    check_measured_file(scene)  # gaps are allowed before a run
    got = read_measured(scene)
    assert np.isnan(got[DE].iloc[list(flags)]).all()
    keep = [k for k in range(len(reference)) if k not in flags]
    np.testing.assert_array_equal(got[DE].iloc[keep], reference[DE].iloc[keep])
    same_table(got[["time [s]", NDE]], reference[["time [s]", NDE]])
    temps = run.tables["temperatures"]
    cols = scene.measured.columns
    err = temperature_errors(temps, got, cols).set_index("sensor")
    expect = temperature_errors(temps, reference.iloc[keep], cols).set_index("sensor")
    assert err.loc[DE, "points"] == 61 - len(flags)
    assert err.loc[DE, "RMSE [K]"] == pytest.approx(expect.loc[DE, "RMSE [K]"], rel=1e-14)
    assert np.isfinite(err["RMSE [K]"]).all()
    # calibration leaves each sensor's gaps out of its residuals (before: a
    # named error): the table keeps them as NaN
    nodes = ["drive_end.housing", "non_drive_end.housing"]
    table = measured_table(scene, nodes)
    assert int(np.isnan(table[DE]).sum()) == len(flags)


def test_windows_1252_file_with_umlauts_and_degree_sign(tmp_path, original, reference):
    """A Windows logger writes the ANSI code page: ``°C`` and ``Gehäuse`` are not UTF-8."""
    de, nde = "Gehäuse AS", "Gehäuse BS"
    lines = ["Messgerät;ALMEMO 2890", f"Zeit;{de};{nde}", "min;°C;°C"]
    lines += [f"{comma(t)};{comma(a)};{comma(b)}" for t, a, b in rows(original)]
    path = tmp_path / "ansi.csv"
    path.write_bytes("\r\n".join(lines).encode("cp1252"))
    got = read_measured_file(path, "Zeit", [de, nde])
    same_table(got.rename(columns={de: DE, nde: NDE}), reference)


def test_kelvin_file_with_units_row(tmp_path, original, reference):
    lines = [f"time [min],{DE},{NDE}", ",K,K"]
    lines += [f"{t},{a + 273.15!r},{b + 273.15!r}"
              for t, a, b in rows(original)]
    path = write(tmp_path / "kelvin.csv", lines)
    same_table(read_measured_file(path, "time [min]", [DE, NDE], "K"), reference)
    with pytest.raises(InputError, match=r"measured.unit.*'K'.*units row.*TC_DE_synthetic"):
        read_measured_file(path, "time [min]", [DE, NDE], "degC")


def test_us_daq_export_12_hour_clock_overload_codes_and_flags(tmp_path, original, reference):
    """A US DAQ export (BenchLink / Graphtec style): metadata, ``Scan`` counter, 12-hour
    timestamps crossing noon, units in the column names ``(C)``, an overload code
    ``+9.90000000E+37`` and the flags ``+OVER``, ``Burnout``, ``+++++`` as gaps."""
    de, nde = f"{DE} (C)", f"{NDE} (C)"
    gaps = {5: "+9.90000000E+37", 6: "+OVER", 30: "Burnout", 59: "+++++"}
    lines = ['"Acquisition Date:","11/23/2026 11:45:30 AM"', '"Instrument:","34972A"', "",
             f'"Scan","Time","{de}","{nde}"']
    start = datetime(2026, 11, 23, 11, 45, 30)
    for k, (t, a, b) in enumerate(rows(original)):
        stamp = (start + timedelta(minutes=float(t))).strftime("%m/%d/%Y %I:%M:%S %p")
        lines.append(f"{k + 1},{stamp},{gaps.get(k, f'{a:+.8E}')},{b:+.8E}")
    got = read_measured_file(write(tmp_path / "daq.csv", lines), "Time", [de, nde])
    assert lines[-1].split(",")[1] == "11/23/2026 12:45:30 PM"  # crossed noon
    keep = [k for k in range(len(reference)) if k not in gaps]
    assert np.isnan(got[de].iloc[list(gaps)]).all()
    np.testing.assert_allclose(got[de].iloc[keep], reference[DE].iloc[keep], rtol=1e-12)
    np.testing.assert_allclose(got[nde], reference[NDE], rtol=1e-12)
    np.testing.assert_array_equal(got["time [s]"], reference["time [s]"])


def test_time_unit_in_parentheses_and_unit_in_column_name(tmp_path, original, reference):
    lines = [f"Time (s),{DE},{NDE}"] + [f"{t * 60},{a},{b}" for t, a, b in rows(original)]
    same_table(read_measured_file(write(tmp_path / "s.csv", lines), "Time (s)", [DE, NDE]),
               reference)
    path = write(tmp_path / "k.csv", ["t,TC1 [K],TC2", "0,308.15,35", "1,309.15,36"])
    with pytest.raises(InputError, match=r"measured.unit.*'K'.*column name.*'TC1 \[K\]'"):
        read_measured_file(path, "t", ["TC1 [K]", "TC2"])
    got = read_measured_file(path, "t", ["TC1 [K]"], "K")
    np.testing.assert_allclose(got["TC1 [K]"], [35.0, 36.0])
    # a bare (F) in a name may be a label ("front"): no unit check on it
    path = write(tmp_path / "f.csv", ["t,TC (F)", "0,35", "1,36"])
    np.testing.assert_allclose(read_measured_file(path, "t", ["TC (F)"])["TC (F)"], [35, 36])


# --------------------------------------------------------------------------- bad files
def bad(tmp_path, lines, time_column="t", match="", **kw):
    path = write(tmp_path / "bad.csv", lines)
    with pytest.raises(InputError, match=match):
        read_measured_file(path, time_column, ["TC1"], **kw)


def test_timestamps_going_backwards_name_the_row(tmp_path):
    bad(tmp_path, ["t;TC1", "23.11.2026 10:00:00;35,0", "23.11.2026 10:05:00;35,5",
                   "23.11.2026 10:04:00;36,0"],
        match=r"measured column 't'.*row 3: 23.11.2026 10:04:00 after 23.11.2026 10:05:00.*"
              r"strictly increasing")


def test_text_cell_that_is_no_flag(tmp_path):
    bad(tmp_path, ["t,TC1", "0,35", "1,hot", "2,36"],
        match=r"measured column 'TC1'.*row 2: 'hot'.*numbers.*dropout flag")


def test_unknown_and_mixed_time_formats(tmp_path):
    bad(tmp_path, ["t,TC1", "yesterday,35", "today,36"],
        match=r"measured column 't'.*row 1: 'yesterday'.*hh:mm:ss.*yyyy-mm-dd")
    bad(tmp_path, ["t,TC1", "00:00:00,35", "00:01:00,36", "2026-11-23 10:00:00,37"],
        match=r"row 3: '2026-11-23 10:00:00'.*format of row 1 \(elapsed hh:mm:ss")
    bad(tmp_path, ["t,TC1", "0,35", "", "1,36", "2,37", ",38"],
        match=r"row 4: ''.*a time in every row")


def test_ambiguous_day_month_order(tmp_path):
    bad(tmp_path, ["t;TC1", "01/02/2026 10:00:00;35", "01/02/2026 10:01:00;36"],
        match=r"row 1.*unambiguous date")
    # a day > 12 further down decides it: day first
    path = write(tmp_path / "dm.csv", ["t;TC1", "12/11/2026 23:59:00;35",
                                       "13/11/2026 00:00:00;36"])
    assert read_measured_file(path, "t", ["TC1"])["time [s]"].tolist() == [0.0, 60.0]


def test_bad_time_zero(tmp_path):
    bad(tmp_path, ["t,TC1", "2026-11-23 10:00:00,35", "2026-11-23 10:01:00,36"],
        time_zero="10 min", match=r"measured.time_zero.*'10 min'.*ISO 8601")


def test_missing_columns_list_the_header(tmp_path):
    lines = ["Logger;X", "t;TC1;TC2", "0;35;36"]
    bad(tmp_path, lines, time_column="time", match=r"measured.time_column.*'time'.*t, TC1, TC2")
    path = write(tmp_path / "cols.csv", lines)
    with pytest.raises(InputError, match=r"measured.columns\['TC9'\].*t, TC1, TC2"):
        read_measured_file(path, "t", ["TC9"])


def test_scene_time_zero_key(tmp_path):
    path = write(tmp_path / "rig.csv", [f"t,{DE},{NDE}", "0,35,35"])
    with pytest.raises(InputError, match=r"measured.time_zero"):
        scene_with(path, time_column="t", time_zero=True)
    with pytest.raises(InputError, match=r"time_zer"):
        scene_with(path, time_column="t", time_zer="first")
    # an unquoted TOML datetime is accepted and written back as a string
    text = scene_with(path, time_column="t").to_toml().replace(
        'unit = "degC"', 'unit = "degC"\ntime_zero = 2026-11-23T10:00:00', 1)
    assert loads_scene(text, base_dir=tmp_path).measured.time_zero == "2026-11-23 10:00:00"
