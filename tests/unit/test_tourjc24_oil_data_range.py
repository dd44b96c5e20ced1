"""Tour E (session 24): an oil inlet outside the temperatures the oil's property data cover.

A sweep of the default rig with an ISO VG 46 inlet at 200 degC ran without a word: past
146 degC the oil is thinner than the 2.4 mPa s where the data of its pressure-viscosity fit
end (the Roelands z is held there), and Cragoe's c_p and k are stated for 0-200 degC. The
sweep now says which values lie outside, before the runs; the runs still run.
"""

from __future__ import annotations

import html
import json
import math

import pytest

from thermobearing import load_lubricant
from thermobearing.lubricant_properties import ALPHA_FIT_VISCOSITY_RANGE
from thermobearing.lubricant_range import data_temperature_range, outside_data_note
from thermobearing.scene import load_scene, loads_scene
from thermobearing.sweep import parse_set, run_sweep


def _oil_runner(scene_toml: str) -> dict[str, float]:
    """The case's inlet temperature [degC] (the bookkeeping is under test, not physics)."""
    return {"inlet [degC]": loads_scene(scene_toml).supply.inlet_temperature - 273.15}


@pytest.mark.parametrize("name", ["ISO_VG32", "ISO_VG46", "ISO_VG68", "ISO_VG100"])
def test_mineral_oil_range_ends_where_the_alpha_data_and_cragoe_end(name):
    lub = load_lubricant(name)
    rng = data_temperature_range(lub)
    eta_lo, eta_hi = ALPHA_FIT_VISCOSITY_RANGE["asme1953_mineral_fit"]
    # the hot end: the viscosity of the fit's thinnest data point (before Cragoe's 200 degC)
    assert float(lub.dynamic_viscosity(rng.high)) == pytest.approx(eta_lo, rel=1e-6)
    assert rng.high < 473.15 and "asme1953_mineral_fit" in rng.high_reason
    # the cold end: Cragoe's 0 degC (these oils are thinner than 2000 mPa s there)
    assert float(lub.dynamic_viscosity(273.15)) < eta_hi
    assert rng.low == 273.15 and "cragoe" in rng.low_reason


def test_vg46_hot_end_is_the_one_its_preset_file_states():
    # configs/lubricants/ISO_VG46.toml: "held below the fit's lowest viscosity (2.4 mPa s:
    # above ... 146 ... degC for VG ... 46)"
    assert data_temperature_range(load_lubricant("ISO_VG46")).high - 273.15 == \
        pytest.approx(146.0, abs=0.5)


def test_oil_without_numeric_ranges_is_not_bounded():
    # OIL_4109: exponential viscosity law, given alpha, constant c_p and k: no stated
    # numeric range, nothing to compare with
    rng = data_temperature_range(load_lubricant("OIL_4109"))
    assert rng.low == -math.inf and rng.high == math.inf
    assert outside_data_note(load_lubricant("OIL_4109"), "supply.inlet_temperature",
                             473.15) is None


def test_note_names_field_values_oil_and_range():
    lub = load_lubricant("ISO_VG46")
    inside = [298.15, 308.15, 318.15, 333.15]   # the tour's 25-60 degC inlets
    assert outside_data_note(lub, "supply.inlet_temperature", inside) is None
    note = outside_data_note(lub, "supply.inlet_temperature", [*inside, 473.15, 423.15])
    assert note.startswith("supply.inlet_temperature = 150, 200 degC are outside")
    assert "ISO_VG46" in note and "0 to 146 degC" in note and "extrapolate" in note
    one = outside_data_note(lub, "environment.initial_temperature", 263.15)
    assert one.startswith("environment.initial_temperature = -10 degC is outside")


def test_sweep_says_the_inlets_outside_the_oil_data_before_the_runs(tmp_path, capsys):
    scene = load_scene()
    params = [parse_set("supply.inlet_temperature=35,200 degC", scene.to_dict()),
              parse_set("lubricant.preset=ISO_VG46,ISO_VG100", scene.to_dict())]
    df = run_sweep(scene, params, tmp_path, runner=_oil_runner, workers=1, progress=False)
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if "property data cover" in ln]
    assert len(lines) == 2   # one per oil, each naming only its value outside
    assert any("= 200 degC is outside" in ln and "ISO_VG46's" in ln for ln in lines)
    assert any("= 200 degC is outside" in ln and "ISO_VG100's" in ln for ln in lines)
    assert df.attrs["outside_data"] == lines
    assert len(df) == 4   # the cases ran


def test_sweep_inside_the_oil_data_says_nothing(tmp_path, capsys):
    scene = load_scene()
    params = [parse_set("supply.inlet_temperature=25,60 degC", scene.to_dict())]
    df = run_sweep(scene, params, tmp_path, runner=_oil_runner, workers=1, progress=False)
    assert "property data cover" not in capsys.readouterr().err
    assert df.attrs["outside_data"] == []


def test_sweep_report_repeats_the_note(tmp_path):
    # the report of the folder says it too (the sweep's terminal lines are gone by then)
    from thermobearing.commands.report import outside_data_notes, sweep_report

    scene = load_scene()
    params = [parse_set("supply.inlet_temperature=35,150,200 degC", scene.to_dict())]
    run_sweep(scene, params, tmp_path, runner=_oil_runner, workers=1, progress=False)
    records = [json.loads(line) for line in
               (tmp_path / "cases.jsonl").read_text(encoding="utf-8").splitlines()]
    notes = outside_data_notes(tmp_path, records)
    assert len(notes) == 1 and notes[0].startswith(
        "supply.inlet_temperature = 150, 200 degC are outside the temperatures ISO_VG46's")
    assert html.escape(notes[0]) in sweep_report(tmp_path).read_text(encoding="utf-8")
    inside = tmp_path / "inside"
    run_sweep(scene, [parse_set("supply.inlet_temperature=25,60 degC", scene.to_dict())],
              inside, runner=_oil_runner, workers=1, progress=False)
    assert "property data cover" not in sweep_report(inside).read_text(encoding="utf-8")


def test_inlet_sweep_report_says_every_case_starts_at_the_initial_temperature(tmp_path):
    # the default rig's 0 kN skid stood at -31 % for 35-60 degC inlets: every case's first
    # state, at the fixed 35 degC start; the report now says where the cases start
    from thermobearing.commands.report import fixed_start_note

    scene = load_scene()
    d = scene.to_dict()
    run_sweep(scene, [parse_set("supply.inlet_temperature=25,60", d)], tmp_path,
              runner=_oil_runner, workers=1, progress=False)
    note = fixed_start_note(tmp_path, ["supply.inlet_temperature"])
    assert note.startswith("every case starts at the base scene's initial temperature, "
                           "35 degC, whatever its inlet temperature")
    assert fixed_start_note(tmp_path, ["supply.inlet_temperature",
                                       "environment.initial_temperature"]) is None
    assert fixed_start_note(tmp_path, ["supply.flow"]) is None


def test_sweep_command_says_it_too(tmp_path, capsys, monkeypatch):
    import thermobearing.simulation as simulation
    from thermobearing import cli

    monkeypatch.setattr(simulation, "summarize_scene", _oil_runner)
    code = cli.main(["sweep", "--set", "supply.inlet_temperature=25,60", "--out",
                     str(tmp_path / "s"), "--workers", "1", "--quiet"])
    assert code == 0
    err = capsys.readouterr().err
    assert "note: every case starts at the base scene's initial temperature, 35 degC" in err
    code = cli.main(["sweep", "--set", "supply.flow=20,33", "--out", str(tmp_path / "f"),
                     "--workers", "1", "--quiet"])
    assert code == 0 and "every case starts" not in capsys.readouterr().err
