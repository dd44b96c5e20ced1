"""Catalogue bearings (``estimate_missing = true``): what is filled, by which rule, and what is
refused. Hand-checked values: ISO 5753-1 Normal-group clearances from the tables reproduced in
``thermobearing/bearing_estimates.py`` (deep groove 24-30 mm bore: 5-20 um; cylindrical roller
24-30 mm: 20-45 um), d_m = (d + D)/2."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from thermobearing.bearing_config import bearing_from_dict
from thermobearing.bearing_estimates import (
    CYLINDRICAL_ROLLER_CN,
    DEEP_GROOVE_CN,
    complete_from_catalogue,
    normal_clearance,
)
from thermobearing.errors import InputError

B6206 = {"name": "6206", "kind": "deep_groove", "source": "catalogue", "estimate_missing": True,
         "bore": "30 mm", "outer_diameter": "62 mm", "width": "16 mm",
         "ball_diameter": "9.525 mm", "n_balls": 9}
NU206 = {"name": "NU206", "kind": "cylindrical", "source": "catalogue",
         "estimate_missing": True, "bore": "30 mm", "outer_diameter": "62 mm", "width": "16 mm",
         "roller_diameter": "7.5 mm", "roller_length": "7.5 mm", "n_rollers": 13}


def test_deep_groove_from_catalogue_data():
    b = bearing_from_dict(B6206)
    assert b.pitch_diameter == pytest.approx(0.046)               # (30 + 62)/2 mm
    assert b.diametral_clearance == pytest.approx(12.5e-6)        # CN 5-20 um, mid-range
    assert (b.inner_conformity, b.outer_conformity) == (0.52, 0.53)
    assert b.contact_angle == 0.0
    # free contact angle of the estimate: cos(alpha) = 1 - P_d / (2 A), A = 0.05 D
    A = 0.05 * 9.525e-3
    assert b.free_contact_angle == pytest.approx(math.acos(1 - 12.5e-6 / (2 * A)), rel=1e-9)
    assert b.ball_material.name == b.ring_material.name == "STEEL_52100"
    assert b.cage.guidance == "rolling_element" and b.cage.material.name == "STEEL_LOW_CARBON"
    assert b.cage.pocket_clearance == pytest.approx(0.03 * 9.525e-3)
    assert b.cage.width == pytest.approx(0.55 * 16e-3)
    assert b.cage.inner_diameter == pytest.approx(0.046 - 0.45 * 9.525e-3)
    assert b.cage.outer_diameter == pytest.approx(0.046 + 0.45 * 9.525e-3)
    filled = {"pitch_diameter", "inner_conformity", "outer_conformity", "contact_angle",
              "diametral_clearance", "ball_material", "ring_material", "raceway_roughness",
              "element_roughness", "cage.guidance", "cage.pocket_clearance", "cage.width",
              "cage.inner_diameter", "cage.outer_diameter", "cage.material"}
    assert set(b.estimated) == filled
    assert all(v.startswith("estimate_missing: ") for v in b.estimated.values())
    assert "5-20 um" in b.estimated["diametral_clearance"]


def test_given_values_are_kept_and_not_marked():
    data = {**B6206, "pitch_diameter": "46.5 mm", "inner_conformity": 0.515,
            "diametral_clearance": "0.023 mm",
            "estimated": {"pitch_diameter": "measured on a sample"}}
    b = bearing_from_dict(data)
    assert b.pitch_diameter == pytest.approx(0.0465)
    assert b.inner_conformity == 0.515 and b.diametral_clearance == pytest.approx(23e-6)
    assert b.estimated["pitch_diameter"] == "measured on a sample"
    assert "inner_conformity" not in b.estimated and "diametral_clearance" not in b.estimated
    # the cage follows the given pitch diameter
    assert b.cage.inner_diameter == pytest.approx(0.0465 - 0.45 * 9.525e-3)
    # estimate_missing = false: nothing is filled (the [cage] table is then required)
    with pytest.raises(InputError, match="cage"):
        bearing_from_dict({**B6206, "estimate_missing": False})


def test_cylindrical_roller_from_catalogue_data():
    b = bearing_from_dict(NU206)
    assert b.pitch_diameter == pytest.approx(0.046)
    assert b.diametral_clearance == pytest.approx(32.5e-6)        # Normal 20-45 um
    assert b.roller_material.name == "STEEL_52100" and b.cage.material.name == "BRASS"
    assert b.cage.width == pytest.approx(0.75 * 16e-3)
    assert b.cage.pocket_clearance == pytest.approx(0.02 * 7.5e-3)
    assert b.element_roughness == pytest.approx(0.08e-6)
    assert "20-45 um" in b.estimated["diametral_clearance"]


@pytest.mark.parametrize("kind, bore_mm, expected_um", [
    ("deep_groove", 10.0, (2, 13)),    # "incl" bound belongs to the lower row
    ("deep_groove", 10.001, (3, 18)),
    ("deep_groove", 100.0, (12, 36)),
    ("cylindrical", 30.0, (20, 45)),
    ("cylindrical", 30.5, (25, 50)),
    ("cylindrical", 500.0, (220, 330)),
])
def test_normal_clearance_rows(kind, bore_mm, expected_um):
    lo, hi = normal_clearance(kind, bore_mm * 1e-3)
    assert (lo * 1e6, hi * 1e6) == pytest.approx(expected_um)


def test_tables_are_contiguous_and_increasing():
    for table in (DEEP_GROOVE_CN, CYLINDRICAL_ROLLER_CN):
        for (_o1, i1, lo1, hi1), (o2, i2, lo2, hi2) in zip(table, table[1:], strict=False):
            assert i1 == o2 and i2 > o2
            assert lo2 >= lo1 and hi2 >= hi1 and hi1 > lo1


def test_what_cannot_be_estimated_is_refused_by_name():
    with pytest.raises(InputError, match=r"diametral_clearance.*100 mm"):
        bearing_from_dict({**B6206, "bore": "120 mm", "outer_diameter": "180 mm",
                           "width": "28 mm", "ball_diameter": "19.05 mm", "n_balls": 14})
    ok = bearing_from_dict({**B6206, "bore": "120 mm", "outer_diameter": "180 mm",
                            "width": "28 mm", "ball_diameter": "19.05 mm", "n_balls": 14,
                            "diametral_clearance": "0.03 mm"})
    assert ok.diametral_clearance == pytest.approx(3e-5)
    with pytest.raises(InputError, match=r"bearing\.n_balls"):
        bearing_from_dict({k: v for k, v in B6206.items() if k != "n_balls"})
    with pytest.raises(InputError, match=r"bearing\.contact_angle"):
        bearing_from_dict({**B6206, "kind": "angular_contact"})
    with pytest.raises(InputError, match=r"bearing\.diametral_clearance"):
        bearing_from_dict({**B6206, "kind": "four_point", "contact_angle": "35 deg"})
    with pytest.raises(InputError, match=r"bearing\.estimate_missing"):
        bearing_from_dict({**B6206, "estimate_missing": "yes"})
    with pytest.raises(InputError, match=r"bearing\.roller_length"):
        bearing_from_dict({k: v for k, v in NU206.items() if k != "roller_length"})


def test_angular_contact_takes_its_design_angle_as_free_angle():
    b = bearing_from_dict({**B6206, "kind": "angular_contact", "contact_angle": "40 deg"})
    assert b.diametral_clearance == 0.0
    assert b.free_contact_angle == pytest.approx(math.radians(40.0))
    assert b.cage.material.name == "BRASS"


def test_complete_from_catalogue_does_not_modify_its_input():
    data = dict(B6206)
    out = complete_from_catalogue(data)
    assert data == B6206 and "estimate_missing" not in out and "cage" in out


EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_catalogue_bearing_scene_runs_and_reports_its_estimates(tmp_path, capsys):
    """The example scene, whose bearing file gives only catalogue data, runs (steady losses
    here, to keep the test short); ``check`` lists the estimated fields, the report and
    metadata.json carry each with its reasoning, and ``thermobearing report DIR``
    re-renders them."""
    import dataclasses
    import json

    from thermobearing.cli import main
    from thermobearing.commands.report import run_report
    from thermobearing.scene import load_scene
    from thermobearing.simulation import Simulation

    path = EXAMPLES / "catalogue_bearing_rig.toml"
    assert main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    line = next(ln for ln in out.splitlines() if ln.startswith("  bearing test (6206)"))
    assert "15 values, 15 by estimate_missing" in line and "diametral_clearance" in line
    scene = load_scene(path)
    steady = dataclasses.replace(scene, outputs=dataclasses.replace(
        scene.outputs, mode="steady", want=("losses", "kinematics", "report")))
    sim = Simulation(steady, progress=False)
    res = sim.run(tmp_path / "out")
    losses = res.tables["losses"]
    assert (losses["power [W]"] >= 0).all() and losses["power [W]"].sum() > 1.0
    est = res.estimated["bearing test (6206)"]
    assert est["diametral_clearance"].startswith("estimate_missing: mid-range of the ISO")
    meta = json.loads((tmp_path / "out" / "metadata.json").read_text(encoding="utf-8"))
    assert meta["estimated"] == res.estimated
    for page in ((tmp_path / "out" / "report.html").read_text(encoding="utf-8"),
                 run_report(tmp_path / "out").read_text(encoding="utf-8")):
        assert "<h2 id='estimated-inputs'>Estimated inputs</h2>" in page
        assert "bearing test (6206)" in page and "ISO 5753-1 Normal (CN)" in page


def test_table_overrides_merge_into_the_preset_table():
    """``overrides = { cage = { guide_clearance = "0.4 mm" } }`` changes that key of the
    preset's [cage] and keeps the others (earlier versions replaced the table and the
    other cage keys were reported missing); a plain value still replaces."""
    from thermobearing.geometry import load_bearing

    base = load_bearing("QJ1044")
    b = load_bearing("QJ1044", {"cage": {"guide_clearance": "0.4 mm"},
                                "diametral_clearance": "0.12 mm"})
    assert b.cage.guide_clearance == pytest.approx(0.4e-3)
    assert b.cage.width == base.cage.width and b.cage.guidance == base.cage.guidance
    assert b.diametral_clearance == pytest.approx(0.12e-3)
    with pytest.raises(InputError, match="cage.colour"):
        load_bearing("QJ1044", {"cage": {"colour": "red"}})
