"""Session-23 user tour D, ``thermobearing rib-map`` as the designer of a high-speed
cylindrical roller bearing (paper 003's use, issue 9).

Found: the map's base point was paper 003's (rib angle 0.3 deg, crown radius 300 mm,
C_a 0.03 mm, pocket 0.2 mm, 30000 r/min, 3000 N) whatever ``--bearing`` said, so an NJ 214
with a 0.5 deg rib and a 500 mm crown was refused for a rib it does not have; bad values
were refused under the model's SI fields (``rib.rib_height = 0.0015``, ``unbalance_mass =
0.005``, ``pocket_clearance = -0.0001``) without the value of the map that caused them; a
point whose solver failed stopped the map with a message naming no point; speeds were
printed ``2e+04 rpm``; the help gave no defaults; the figure's axis said ``rib_angle``.
"""

from __future__ import annotations

import math

import pytest

from thermobearing import cli
from thermobearing.commands import rib_map
from thermobearing.errors import ConvergenceError
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_map as rdm

#: an NJ-type NU 214: inner rib, a 0.5 deg rib face, a 500 mm end-face crown, 3 mm ribs
NJ214 = """name = "NJ214_tour"
kind = "cylindrical"
source = "NU214 preset envelope with an inner rib (session-23 tour)"
bore = "70 mm"
outer_diameter = "125 mm"
width = "24 mm"
roller_diameter = "13 mm"
roller_length = "13 mm"
roller_effective_length = "13 mm"
n_rollers = 18
pitch_diameter = "97.5 mm"
diametral_clearance = "0.025 mm"
ribbed_ring = "both"
end_face_crown_radius = "500 mm"
rib_angle = "0.5 deg"
rib_height = "3 mm"
axial_clearance = "0.05 mm"
roller_material = "PAPER000_STEEL"
ring_material = "PAPER000_STEEL"

[cage]
guidance = "rolling_element"
pocket_clearance = "0.3 mm"
width = "18 mm"
inner_diameter = "91 mm"
outer_diameter = "104 mm"
material = "BRASS"
"""


class _Captured(Exception):
    """Raised by the stand-in model builder with what it was given."""


@pytest.fixture()
def nj214(tmp_path):
    path = tmp_path / "nj214.toml"
    path.write_text(NJ214)
    return str(path)


@pytest.fixture()
def captured_build(monkeypatch):
    """build_model replaced: records its arguments, then stops the map."""
    seen = {}

    def build(bearing, lubricant, speed, radial_load, mass, **kw):
        seen.update(speed=speed, radial_load=radial_load, mass=mass, **kw)
        raise _Captured

    monkeypatch.setattr(rdm, "build_model", build)
    return seen


def test_the_map_varies_about_the_bearing_s_own_rib_geometry(nj214, tmp_path,
                                                             captured_build):
    """Before: 'rib.rib_height = 0.003 is not allowed: a rib higher than the end-face contact
    point H_contact = 3.882 mm' -- the contact height of paper 003's 0.3 deg and 300 mm,
    not of this bearing (0.5 deg, 500 mm: 2.137 mm, below its 3 mm rib)."""
    with pytest.raises(_Captured):
        cli.main(["rib-map", "--bearing", nj214, "--lubricant", "ISO_VG46", "--param",
                  "speed", "--values", "2000 rpm", "--speed", "4000 rpm", "--radial-load",
                  "8 kN", "--unbalance", "0 g", "--out", str(tmp_path / "m")])
    rib = captured_build["rib"]
    assert rib["rib_angle"] == pytest.approx(math.radians(0.5), rel=1e-12)
    assert rib["crown_radius"] == pytest.approx(0.5, rel=1e-12)
    assert rib["axial_clearance"] == pytest.approx(0.05e-3, rel=1e-12)
    assert captured_build["pocket_clearance"] == pytest.approx(0.3e-3, rel=1e-12)
    assert captured_build["radial_load"] == pytest.approx(8000.0, rel=1e-12)
    assert captured_build["speed"] == pytest.approx(2000 * math.pi / 30, rel=1e-12)


def test_the_default_bearing_keeps_paper_003_s_base_point(tmp_path, captured_build):
    with pytest.raises(_Captured):
        cli.main(["rib-map", "--param", "rib_angle", "--values", "0.45 deg",
                  "--unbalance", "0.06 g", "--out", str(tmp_path / "m")])
    base = rdm.PAPER003_BASE
    rib = captured_build["rib"]
    assert rib["rib_angle"] == pytest.approx(math.radians(0.45), rel=1e-12)
    assert rib["crown_radius"] == pytest.approx(base["crown_radius"], rel=1e-12)
    assert rib["axial_clearance"] == pytest.approx(base["axial_clearance"], rel=1e-12)
    assert captured_build["pocket_clearance"] == pytest.approx(base["pocket_clearance"],
                                                               rel=1e-12)
    # exactly paper 003's float: '30000 rpm' is one ulp from it, and the impacting motion
    # with an unbalance carries an ulp into the map's numbers
    assert captured_build["speed"] == base["speed"]
    assert captured_build["radial_load"] == pytest.approx(base["radial_load"], rel=1e-12)


@pytest.mark.parametrize("argv, words", [
    # the swept value that puts the contact above the rib, in the unit it was given
    (["--param", "rib_angle", "--values", "0.1,0.3 deg"],
     ["--values = '0.1 deg'", "at 0.1 deg", "rib_height = 1.5 mm", "H_contact = 2.476 mm"]),
    (["--param", "axial_clearance", "--values=-0.01,0.03 mm"],
     ["--values = '-0.01 mm'", "axial clearance values >= 0"]),
    (["--param", "pocket_clearance", "--values=-0.1,0.2 mm"],
     ["--values = '-0.1 mm'", "pocket clearance values >= 0"]),
    (["--param", "speed", "--values", "20000 rpm", "--unbalance", "5 g"],
     ["--unbalance = '5 g'", "roller mass 1.329 g"]),
    (["--param", "crown_radius", "--values", "2,300 mm"],
     ["--values = '2 mm'", "end_face_crown_radius = 2 mm"]),
    (["--bearing", "NU214"], ["--bearing = 'NU214'", "end_face_crown_radius and rib_height"]),
    (["--speed", "0 rpm"], ["--speed = '0 rpm'", "a speed > 0"]),
])
def test_bad_input_names_the_option_and_the_value_as_given(argv, words, tmp_path, capsys,
                                                            captured_build):
    rc = cli.main(["rib-map", *argv, "--model", "reduced", "--out", str(tmp_path / "m")])
    err = capsys.readouterr().err
    assert rc == 1 and "Traceback" not in err
    for word in words:
        assert word in err, (word, err)
    assert not captured_build  # refused before the first solve


def test_default_values_the_bearing_cannot_take_say_to_give_values(nj214, tmp_path, capsys,
                                                                   captured_build):
    """Paper 003's rib angles 0.3-0.8 deg on the NJ 214's 500 mm crown: 0.3 deg puts the
    contact 3.88 mm up, above its 3 mm rib."""
    rc = cli.main(["rib-map", "--bearing", nj214, "--param", "rib_angle", "--out",
                   str(tmp_path / "m")])
    err = capsys.readouterr().err
    assert rc == 1
    assert "--param rib_angle (its default values) = '0.3 deg'" in err
    assert "H_contact = 3.882 mm" in err and "give --values for NJ214_tour" in err


def _fake_map(fail_masses):
    """pv_slip_map stand-in: a row per point, a ConvergenceError for the masses given."""
    def fake(bearing, lubricant, parameter, values, masses, *, on_row=None, **kw):
        rows = []
        for v in values:
            for m in masses:
                if m in fail_masses:
                    raise ConvergenceError("roller_dynamics.coupled", 0.2,
                                           "unstable coupled motion", state={"t": 0.01})
                row = {k: 1.0 for k in (
                    "pv_left", "pv_right", "pv_peak_left", "pv_peak_right",
                    "pv_contact_left", "pv_contact_right", "contact_slide_speed",
                    "slip_speed", "surface_slip_speed", "max_skew", "rib_contact_fraction",
                    "rib_heat", "bar_contact_fraction", "pocket_friction_extra",
                    "cage_speed", "cost_s")}
                row.update(parameter=parameter, value=float(v), unbalance_mass=float(m))
                rows.append(row)
                on_row(row)
        return rows
    return fake


def test_a_failed_point_is_named_and_keep_going_maps_the_others(tmp_path, capsys,
                                                                monkeypatch):
    """Before: the coupled runaway at 20000 r/min and 0.11 g stopped the map with
    'roller_dynamics.coupled did not converge ... [t=0.0101, ...]', no point named."""
    monkeypatch.setattr(rd, "pv_slip_map", _fake_map({0.11e-3}))
    out = tmp_path / "m"
    argv = ["rib-map", "--param", "speed", "--values", "20000,25000 rpm", "--unbalance",
            "0.06,0.11 g", "--no-plot", "--out", str(out)]
    rc = cli.main(argv)
    err = capsys.readouterr().err
    assert rc == 1
    assert "the point speed 20000 rpm, m_u 0.11 g (coupled model) failed" in err
    assert "--keep-going" in err and "--model reduced" in err
    assert len((out / "rib_map_speed.csv").read_text().splitlines()) == 2  # header + 1
    rc = cli.main([*argv, "--keep-going"])
    err = capsys.readouterr().err
    assert rc == 1
    lines = (out / "rib_map_speed.csv").read_text().splitlines()
    assert [ln.split(",")[:2] for ln in lines[1:]] == [["20000", "0.06"], ["25000", "0.06"]]
    assert "2 of 4 points failed (no row)" in err
    assert "[2/4] speed 20000 rpm, m_u 0.11 g: FAILED" in err


def test_speeds_are_printed_without_an_exponent(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(rd, "pv_slip_map", _fake_map(set()))
    rc = cli.main(["rib-map", "--param", "speed", "--values", "20000,35000 rpm",
                   "--unbalance", "0.06 g", "--no-plot", "--out", str(tmp_path / "m")])
    captured = capsys.readouterr()
    assert rc == 0
    text = captured.out + captured.err
    assert "e+04" not in text
    assert "speed 20000 rpm, m_u 0.06 g" in captured.err
    assert "base point radial load 3000 N, speed 30000 rpm, axial clearance 0.03 mm" in (
        captured.err)


def test_the_figure_names_the_parameter_in_words_and_the_base_point(tmp_path, monkeypatch):
    import matplotlib.figure

    figures = []
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig",
                        lambda self, *a, **k: figures.append(self))
    rows = [{"unbalance_mass": 0.06e-3, "value": math.radians(v), "pv_left": 4e8,
             "pv_right": 5e8, "slip_speed": 14.0} for v in (0.3, 0.45)]
    rib_map._plot(rows, "rib_angle", "deg", math.radians(1.0), tmp_path / "f.png",
                  "CRB_50x75x16; base point speed 30000 rpm")
    (fig,) = figures
    a, b = fig.axes
    assert a.get_xlabel() == "rib angle [deg]" == b.get_xlabel()
    assert a.get_ylabel() == "time-mean PV of the roller end face [MPa m/s]"
    assert "base point speed 30000 rpm" in fig._suptitle.get_text()


def test_help_gives_the_defaults_and_the_base_point(capsys):
    with pytest.raises(SystemExit):
        cli.main(["rib-map", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for word in ("default: CRB_50x75x16", "default: MIL_PRF_23699", "default: 80 degC",
                 "default: 30000 rpm", "default: 3000 N", "default: 0.06,0.08,0.11 g",
                 "base point", "--keep-going",
                 "rib_angle 0.3,0.4,0.45,0.5,0.55,0.6,0.7,0.8 deg"):
        assert word in text, word


def test_the_settings_file_records_the_base_point_and_model(nj214, tmp_path, monkeypatch):
    """The CSV files give the swept column only; the base point was nowhere in the folder.
    One file per map: a folder holding maps of several runs keeps each map's settings."""
    import json

    monkeypatch.setattr(rd, "pv_slip_map", _fake_map(set()))
    out = tmp_path / "m"
    assert cli.main(["rib-map", "--bearing", nj214, "--param", "speed", "--values",
                     "2000 rpm", "--speed", "4000 rpm", "--radial-load", "8000",
                     "--unbalance", "0,0.5 g", "--model", "reduced", "--no-plot",
                     "--out", str(out)]) == 0
    settings = json.loads((out / "rib_map_speed_settings.json").read_text())
    assert settings["bearing"] == "NJ214_tour" and settings["model"] == "reduced"
    assert settings["parameter"] == "speed"
    assert settings["unbalance_mass [g]"] == pytest.approx([0.0, 0.5])
    assert settings["base_point"] == pytest.approx({
        "radial_load [N]": 8000.0, "speed [rpm]": 4000.0, "axial_clearance [mm]": 0.05,
        "pocket_clearance [mm]": 0.3, "rib_angle [deg]": 0.5, "crown_radius [mm]": 500.0})


def test_warnings_are_printed_once_each_without_python_s_source_line(tmp_path, capsys,
                                                                      monkeypatch):
    """rib angles of 0.6 deg put the contact beyond the 3 mm roller radius (a
    ValidityWarning): it came as '.../rib.py:346: ValidityWarning: ...' plus the source
    line 'return RibGeometry(...)', once per check of the point."""
    monkeypatch.setattr(rd, "pv_slip_map", _fake_map(set()))
    assert cli.main(["rib-map", "--param", "rib_angle", "--values", "0.5,0.6 deg",
                     "--unbalance", "0.06 g", "--no-plot", "--out", str(tmp_path / "m")]) == 0
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if "beyond the roller radius" in ln]
    assert len(lines) == 1 and lines[0].startswith("rib-map: warning: rib: the end-face point")
    assert "RibGeometry" not in err and "rib.py:" not in err


def test_cost_prints_the_map_s_estimate_and_maps_nothing(tmp_path, capsys, monkeypatch):
    """``--cost`` went on to map all six parameters (123 coupled points, minutes of CPU)."""
    from types import SimpleNamespace

    import thermobearing.skidding.roller_dynamics_coupled as rdc

    def result(model, cost):
        return SimpleNamespace(model=model, cost_s=cost, n_rhs=10, pv_left=1e8,
                               pv_right=1e8, slip_speed=1.0)

    monkeypatch.setattr(rd, "build_model", lambda *a, **k: SimpleNamespace(
        extras={"quasi_static": None}))
    monkeypatch.setattr(rd, "simulate_full", lambda m: result("full", 5.0))
    monkeypatch.setattr(rd, "simulate_reduced", lambda m: result("reduced", 0.1))
    monkeypatch.setattr(rdc, "simulate_coupled", lambda *a, **k: result("coupled", 2.0))
    monkeypatch.setattr(rd, "pv_slip_map", _fake_map(set()))
    out = tmp_path / "m"
    assert cli.main(["rib-map", "--cost", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "123 points x 2 s = about 4.1 min of CPU with the coupled model" in text
    assert not out.exists()


@pytest.mark.parametrize("argv, words", [
    (["--temperature", "80"], ["--temperature = '80'", "e.g. '80 degC'"]),  # was '80 K'
    (["--temperature", "500 degC"], ["--temperature = '500 degC'", "below 300 degC"]),
    (["--orbits", "0,0"], ["--orbits = '0,0'", "statistics orbits > 0"]),
    (["--unbalance", "-0.01 g"], ["--unbalance = '-0.01 g'", ">= 0 g"]),  # was -1e-05
    (["--lubricant", "VG46"], ["--lubricant = 'VG46'", "did you mean 'ISO_VG46'"]),
    (["--bearing", "NU_214"], ["--bearing = 'NU_214'", "did you mean 'NU214'"]),
    (["--radial-load", "-5 kN"], ["--radial-load = '-5000 N'", ">= 0 N"]),
    (["--bearing", "my_crb.toml"], ["--bearing = 'my_crb.toml'", "looked at /"]),
])
def test_more_bad_options_are_refused_before_any_solve(argv, words, tmp_path, capsys,
                                                       captured_build):
    """'--temperature 500 degC' and '--orbits 0,0' mapped every point."""
    rc = cli.main(["rib-map", *argv, "--model", "reduced", "--out", str(tmp_path / "m")])
    err = capsys.readouterr().err
    assert rc == 1 and "Traceback" not in err
    for word in words:
        assert word in err, (word, err)
    assert not captured_build


def test_ctrl_c_keeps_the_rows_finished_and_says_where(tmp_path, capsys, monkeypatch):
    """The point loop of --keep-going still stops at Ctrl-C with the rows written."""
    done = _fake_map(set())
    calls = []

    def interrupted(*args, **kwargs):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return done(*args, **kwargs)

    monkeypatch.setattr(rd, "pv_slip_map", interrupted)
    out = tmp_path / "m"
    rc = cli.main(["rib-map", "--param", "speed", "--values", "20000,25000 rpm",
                   "--unbalance", "0.06 g", "--keep-going", "--out", str(out)])
    err = capsys.readouterr().err
    assert rc == 130
    assert "interrupted while mapping speed" in err and "rerun with --param" in err
    assert len((out / "rib_map_speed.csv").read_text().splitlines()) == 2
    assert not (out / "rib_map_speed.png").exists()


@pytest.mark.parametrize("text, kind, expected", [
    ("0.3 deg, 0.5 deg", "angle", [math.radians(0.3), math.radians(0.5)]),
    ("20000rpm,25000rpm", "angular_speed", [20000 * math.pi / 30, 25000 * math.pi / 30]),
    ("1 kN, 2000 N", "force", [1000.0, 2000.0]),
    ("0.3,0.5 deg", "angle", [math.radians(0.3), math.radians(0.5)]),   # one unit, as before
    ("0.03 0.05 mm", "length", [3e-5, 5e-5]),
])
def test_values_may_carry_their_own_units(text, kind, expected):
    """'0.3 deg, 0.5 deg' (as sweep --set reads lists) was refused: 'numbers ... then one
    unit'."""
    assert rib_map._parse_list(text, kind, "--values", "deg") == pytest.approx(expected,
                                                                               rel=1e-12)


def test_a_list_mixing_bare_and_unit_values_says_both_spellings():
    from thermobearing.errors import InputError

    with pytest.raises(InputError) as info:
        rib_map._parse_list("0.3 deg, 0.5", "angle", "--values", "deg")
    assert "then one unit, e.g. '1,2 deg', or each value with its unit" in str(info.value)
    assert "'0.3,deg,0.5 deg'" not in str(info.value)  # the example it made of the tokens
