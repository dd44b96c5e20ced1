"""BM-7's roller-bearing ladder (benchmarks/bm7_fidelity_ladder.py, roller problem): the
L0/L1 plumbing on the first load step of configs/scenes/paper001_ladder.toml, without the
numerical-EHL level (L2, minutes of CPU; the slow test runs it on one step)."""

from __future__ import annotations

import math

import pytest

FIELDS = {"benchmark", "case", "method", "level", "setting", "sweep", "reference", "time_s",
          "cpu_s", "max_error_K", "error", "worst", "kinematics_solves", "film_table_solves",
          "film_table_cpu_s", "ratio_vs_anchor"}


@pytest.fixture(scope="module")
def no_l2(bm7):
    return bm7.roller_ladder(steps=1, l2=False, sweeps=False, warm_up=False)


def test_records_have_the_fields_and_the_reference_is_exact(no_l2):
    records, notes = no_l2
    assert records
    for r in records:
        assert FIELDS <= set(r), FIELDS - set(r)
        assert r["case"] == notes["case"] == "paper001_ladder_1step"
        assert r["reference"] == notes["reference"]
        assert math.isfinite(r["max_error_K"]) and math.isfinite(r["error"])
        assert r["cpu_s"] > 0.0
    refs = [r for r in records if r["sweep"] == "reference"]
    assert len(refs) == 1  # without L2 the reference is L1 at the tight settings
    assert refs[0]["max_error_K"] == 0.0 and refs[0]["error"] == 0.0
    assert refs[0]["worst"] == ""
    for r in records:
        if r["max_error_K"] > 0.0:  # where the largest difference is: a node, a step
            assert r["worst"].split(",")[0] in notes["nodes"] and "step 1" in r["worst"]
    assert notes["l2_error"] == ""
    assert not any(r["level"] == "L2" for r in records)
    assert all(r["film_table_solves"] == 0 for r in records)  # no numerical film ran


def test_levels_differ_and_only_l1_solves_kinematics(no_l2):
    records, notes = no_l2
    by_level = {}
    for r in records:
        by_level.setdefault(r["level"], []).append(r)
    assert len(by_level["L0"]) == 2  # SKF four-term and Palmgren
    assert all(r["kinematics_solves"] == 0 for r in by_level["L0"])
    assert all(r["kinematics_solves"] >= 1 for r in by_level["L1"])
    l1 = next(r for r in by_level["L1"] if r["sweep"] == "ladder")
    assert l1["max_error_K"] < 1.0  # the scene's L1 is near its own tight-setting run
    for r in by_level["L0"]:
        # a global model with all the heat on the oil node is another answer, not L1's
        assert r["max_error_K"] > 10.0 * max(l1["max_error_K"], 1e-3)
        assert r["error"] > 0.05
    # the reference warms the bearing: every node above the 30 degC start at the step end
    assert (notes["temperatures"] > 303.15 + 1.0).all()
    assert (notes["losses"] > 0.0).all()


def test_roller_scene_steps_are_checked(bm7):
    from _protocol import roller_scene

    from thermobearing.errors import InputError

    assert len(roller_scene(2).schedule.steps) == 2
    with pytest.raises(InputError, match="steps"):
        roller_scene(0)


@pytest.mark.slow
def test_l2_is_the_reference_and_fills_its_film_table(bm7):
    records, notes = bm7.roller_ladder(steps=1, l2=True, sweeps=False)
    assert notes["l2_error"] == ""
    l2 = [r for r in records if r["level"] == "L2"]
    assert len(l2) == 1
    assert l2[0]["max_error_K"] == 0.0 and l2[0]["error"] == 0.0
    assert l2[0]["film_table_solves"] > 0 and l2[0]["film_table_cpu_s"] > 0.0
    assert all(r["reference"] == notes["reference"] == "L2 skidding + numerical_tehl"
               for r in records)
    l1 = next(r for r in records if r["level"] == "L1")
    assert l1["film_table_solves"] == 0
    assert l1["max_error_K"] > 0.0 or l1["error"] > 0.0  # the numerical film changes the run
