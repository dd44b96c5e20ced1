"""Files in other encodings, found while fuzzing the scene front end (session 18): a scene
TOML with a UTF-8 byte-order mark was refused as invalid TOML at line 1, column 1; one in
UTF-16 or Windows-1252 stopped with a UnicodeDecodeError traceback, as did a schedule CSV
saved as Excel's "Unicode text" (UTF-16, tabs); a vibration CSV in Windows-1252 (``m/s²``
in its units row) was refused. Now: UTF-8 with or without the mark and UTF-16 with its
mark are read everywhere, CSV files also in Windows-1252, and a TOML file in any other
encoding is an error naming the file, the line and the column of the first foreign byte."""

from __future__ import annotations

import numpy as np
import pytest
from scene_parts import SKF6304_A, VG32_JET_1LPM

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.measured import read_measured_file
from thermobearing.scene import configs_dir, load_scene, loads_scene
from thermobearing.signal_input import load_acceleration

SCENE = 'title = "encodings"\n' + SKF6304_A + VG32_JET_1LPM + """inlet_temperature = "35 °C"
[schedule]
{schedule}
[outputs]
mode = "steady"
want = ["film"]
"""
INLINE = 'speed = "1500 rpm"\nradial_load = "1 kN"\naxial_load = "0 N"'


@pytest.mark.parametrize("encoded", [b"\xef\xbb\xbf" + SCENE.format(schedule=INLINE).encode(),
                                     SCENE.format(schedule=INLINE).encode("utf-16")])
def test_scene_with_a_byte_order_mark_loads(tmp_path, encoded):
    path = tmp_path / "scene.toml"
    path.write_bytes(encoded)
    scene = load_scene(path)
    assert scene.supply.inlet_temperature == pytest.approx(308.15)


def test_scene_in_windows_1252_names_the_byte(tmp_path):
    path = tmp_path / "scene.toml"
    path.write_bytes(SCENE.format(schedule=INLINE).encode("cp1252"))
    with pytest.raises(InputError, match=r"scene = .*scene.toml.*not UTF-8 text: byte 0xB0 "
                                         r"at line 10, column 25"):
        load_scene(path)


def test_bearing_file_in_windows_1252_is_an_input_error(tmp_path):
    text = (configs_dir() / "bearings" / "SKF6304.toml").read_text(encoding="utf-8")
    path = tmp_path / "mine.toml"
    path.write_bytes(("# Käfig: Messing\n" + text).encode("cp1252"))
    with pytest.raises(InputError, match=r"bearing file .*not UTF-8 text: byte 0xE4 at line 1"):
        load_bearing(str(path))


def test_schedule_as_excel_unicode_text(tmp_path):
    csv = tmp_path / "protocol.txt"
    csv.write_bytes("duration [s]\tspeed [rpm]\tradial_load [N]\taxial_load [N]\r\n"
                    "10\t100\t1000\t0\r\n20\t200\t500\t0\r\n".encode("utf-16"))
    scene = loads_scene(SCENE.format(schedule=f'file = "{csv}"'))
    assert [s.duration for s in scene.schedule.steps] == [10.0, 20.0]
    assert scene.schedule.steps[1].radial_load == pytest.approx(500.0)


def test_schedule_file_of_bytes_is_refused_by_its_header(tmp_path):
    csv = tmp_path / "protocol.csv"
    csv.write_bytes(b"\x00\x81\x02\xff\xfe\n\x9d\x00")
    with pytest.raises(InputError, match=r"schedule.file column"):
        loads_scene(SCENE.format(schedule=f'file = "{csv}"'))


def test_vibration_csv_in_windows_1252(tmp_path):
    t = np.arange(2048) / 2048.0
    x = np.random.default_rng(0).normal(size=t.size)
    lines = ["Zeit [s];Beschl. [m/s²]", "s;m/s²"] + [
        f"{a:.6f};{b:.5f}".replace(".", ",") for a, b in zip(t, x, strict=True)]
    path = tmp_path / "vib.csv"
    path.write_bytes("\n".join(lines).encode("cp1252"))
    rec = load_acceleration(path)
    assert rec.sampling_rate == pytest.approx(2048.0, rel=1e-6)
    assert rec.data == pytest.approx(x, abs=1e-5)


def test_measured_file_in_utf16(tmp_path):
    path = tmp_path / "rig.txt"
    path.write_bytes("time [min]\tTC1 [°C]\n0\t25\n1\t26,5\n".replace(",", ".")
                     .encode("utf-16"))
    df = read_measured_file(path, "time [min]", {"TC1 [°C]": "a.housing"})
    assert df["time [s]"].tolist() == [0.0, 60.0]
    assert df.iloc[:, 1].tolist() == pytest.approx([25.0, 26.5])
