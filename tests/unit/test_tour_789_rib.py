"""User tour of ``thermobearing rib-map`` and the rib contact (issue 9, paper 003).

Found on the tour (CRB_50x75x16, D_w = 6 mm, crown radius 300 mm):

* ``--param rib_angle --values "5 deg"`` printed PV 3552 MPa m/s without a word although the
  end-face point that touches the rib (R_s sin(theta_f) = 26 mm from the roller axis,
  paper 003 eq. 11) is far off a 6 mm roller; ``"9.9 deg"`` failed with
  ``rx = array(-0.19052027) is not allowed: a value > 0`` (a Hertz input the user never
  gave). Now: InputError naming the rib angle / crown radius beyond a roller diameter, a
  ValidityWarning between the roller radius and diameter (paper 003's own Figs. 11-12 go
  there: 0.6-0.9 deg, 600-800 mm).
* a bad value late in a sweep surfaced only when its point came up (after minutes of
  coupled solves), leaving a header-only CSV; now every point is checked first.
* nothing was printed while a map ran (the default six maps: ~130 points, minutes); now one
  progress line per point on stderr (``--quiet`` silences it).
"""

from __future__ import annotations

import math
import warnings

import pytest

from thermobearing.cli import main
from thermobearing.errors import InputError, ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.rib import rib_geometry


@pytest.fixture(scope="module")
def crb():
    return load_bearing("CRB_50x75x16")


@pytest.mark.parametrize(("override", "value"), [
    ("rib_angle", math.radians(5.0)), ("rib_angle", math.radians(9.9)),
    ("crown_radius", 5.0)])
def test_contact_point_off_the_roller_is_an_error_naming_the_fields(crb, override, value):
    with pytest.raises(InputError) as info:
        rib_geometry(crb, **{override: value})
    err = info.value
    assert err.field == "rib.rib_angle / rib.crown_radius"
    # D_w / R_s = 6 / 300 mm: rib angle < asin(0.02) = 1.15 deg at R_s = 300 mm
    assert "within a roller diameter D_w = 6 mm" in str(err)
    assert "1.15 deg" in str(err) or override == "crown_radius"


def test_contact_below_the_raceway_warns_and_cap_face_does_not(crb):
    with pytest.warns(ValidityWarning, match="off the roller's end face"):
        g = rib_geometry(crb, rib_angle=math.radians(0.8))  # 4.19 mm > D_w/2 = 3 mm
    assert g.contact_height() < 0  # eq. 11: 3 mm - 300 mm sin(0.8 deg) = -1.19 mm
    with warnings.catch_warnings():
        warnings.simplefilter("error", ValidityWarning)
        rib_geometry(crb, rib_angle=math.radians(0.5))  # 2.62 mm: on the face
        g = rib_geometry(crb, rib_angle=math.radians(5.0), end_face="cap")
    h, _, on_blend = g.contact_point(0.0)
    assert h > 0 and bool(on_blend)  # the cap face touches with its chamfer blend


def test_rib_map_checks_every_point_before_the_first_solve(tmp_path, capsys, monkeypatch):
    import thermobearing.skidding.roller_dynamics_map as rdm

    def no_solve(*args, **kwargs):
        raise AssertionError("a point was solved before the bad value was found")

    monkeypatch.setattr(rdm, "build_model", no_solve)
    out = tmp_path / "m"
    rc = main(["rib-map", "--param", "rib_angle", "--values", "0.3,0.5,1.2 deg",
               "--unbalance", "0.06 g", "--out", str(out)])
    err = capsys.readouterr().err
    assert rc == 1 and "rib.rib_angle / rib.crown_radius" in err and "'1.2 deg" in err
    assert not out.exists()
    rc = main(["rib-map", "--param", "speed", "--values", "30000 rpm", "--unbalance",
               "0.06,50 g", "--out", str(out)])
    err = capsys.readouterr().err
    assert rc == 1 and "unbalance_mass" in err and "roller mass 1.329 g" in err
    assert not out.exists()


def test_rib_map_prints_progress_per_point(tmp_path, capsys):
    rc = main(["rib-map", "--param", "axial_clearance", "--values", "0.03,0.05 mm",
               "--model", "reduced", "--unbalance", "0.11 g", "--out", str(tmp_path),
               "--no-plot"])
    err = capsys.readouterr().err
    assert rc == 0
    assert "rib-map: 2 points" in err
    assert "[1/2] axial_clearance 0.03 mm, m_u 0.11 g: PV L/R" in err and "[2/2]" in err
    rc = main(["rib-map", "--param", "axial_clearance", "--values", "0.03 mm", "--model",
               "reduced", "--unbalance", "0.11 g", "--out", str(tmp_path), "--no-plot",
               "--quiet"])
    assert rc == 0 and "[1/1]" not in capsys.readouterr().err


def test_values_without_a_unit_are_refused_and_spaces_separate(tmp_path, capsys):
    # before: "--values 0.01,0.03" mapped an axial clearance of 10 and 30 mm (SI metres)
    # without a word, and "0.01 0.03 mm" failed on the unit '0.010.03 mm'
    from thermobearing.commands.rib_map import _parse_list

    with pytest.raises(InputError, match=r"e\.g\. '0\.01,0\.03 mm' \(bare numbers would be in m"):
        _parse_list("0.01,0.03", "length", "--values", "mm")
    with pytest.raises(InputError, match="--unbalance"):
        _parse_list("0.06,0.11", "mass", "--unbalance", "g")
    assert _parse_list("0.01 0.03 mm", "length", "--values", "mm") == pytest.approx(
        [1e-5, 3e-5])
    assert _parse_list("0.3, 0.5 deg", "angle", "--values", "deg") == pytest.approx(
        [math.radians(0.3), math.radians(0.5)])
    assert _parse_list("2000 3000", "force", "--values", "N", bare_ok=True) == [2000.0, 3000.0]
    rc = main(["rib-map", "--param", "axial_clearance", "--values", "0.01,0.03", "--out",
               str(tmp_path / "x")])
    assert rc == 1 and "bare numbers" in capsys.readouterr().err
