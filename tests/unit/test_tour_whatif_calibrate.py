"""What a user meets calibrating a scene from the command line (issue 6 item 7, a user
tour): each test is a defect found by running ``thermobearing calibrate`` on the shipped
synthetic example, written before its fix. The "measured" data are SYNTHETIC (model output,
``synthetic_measurements``), so the right answer is known.
"""

from __future__ import annotations

import numpy as np
import pytest

from tests.unit.test_calibrate import SENSORS, _short_scene
from thermobearing import cli
from thermobearing.calibrate import calibrate, no_influence, synthetic_measurements
from thermobearing.errors import InputError
from thermobearing.scene import load_scene


# --- a bad --fit name: the option is named, and the right path suggested ----------------
@pytest.mark.parametrize(("fit", "hint"), [
    ("h_oil", "did you mean network.parameters.h_oil?"),
    ("supply.flw", "did you mean supply.flow?"),
    ("inlet_temperature", "did you mean supply.inlet_temperature?"),
])
def test_bad_fit_name_names_fit_and_suggests(tmp_path, capsys, fit, hint):
    # before: "--set = 'h_oil' is not allowed" (the sweep's option) and no suggestion
    out = tmp_path / "cal"
    code = cli.main(["calibrate", "qj1044_synthetic_measured", "--fit", fit, "--quiet",
                     "--out", str(out)])
    err = capsys.readouterr().err
    assert code == 1
    assert not out.exists()  # before: an empty results folder was left behind
    assert f"fit = '{fit}'" in err and "--set" not in err
    assert hint in err and "network.parameters.<name>" in err


def test_bad_synthetic_value_path_names_values():
    with pytest.raises(InputError, match="values = 'h_air'"):
        synthetic_measurements(load_scene("qj1044_synthetic_measured"), SENSORS,
                               values={"h_air": 15.0})


# --- a parameter with no influence is named and does not spoil the others ---------------
def test_no_influence_columns():
    J = np.array([[1.0, 0.0, 2e-3], [2.0, 0.0, -1e-3], [0.5, 1e-14, 0.0]])
    assert no_influence(J).tolist() == [False, True, False]
    assert no_influence(np.zeros((3, 2))).tolist() == [True, True]


def test_parameter_without_influence_is_reported_and_left_out(tmp_path):
    """h_oil (true 400 W/(m^2 K)) with the oil-bath level of a JET-lubricated scene, which
    no model reads. Before: J^T J singular, so h_oil's interval came out as 0 .. inf too
    ("the data do not separate the fitted parameters"), after 45 model runs instead of ~18
    (full example); and the calibrated scene gained supply.level = 20 mm."""
    truth = {"network.parameters.h_oil": "400 W/(m**2*K)"}
    scene0 = _short_scene(tmp_path, measured=False)
    data = synthetic_measurements(scene0, SENSORS, values=truth, noise_sd=0.0, every=300.0,
                                  decimals=6)
    scene = _short_scene(tmp_path, data)
    res = calibrate(scene, ["network.parameters.h_oil", "supply.level"],
                    x0={"supply.level": "20 mm"})
    h_oil, level = res.parameters
    assert level.no_influence and not h_oil.no_influence
    assert level.value == pytest.approx(20.0) and level.ci_high == np.inf
    assert h_oil.value == pytest.approx(400.0, rel=3e-3)
    assert np.isfinite(h_oil.ci_low) and np.isfinite(h_oil.ci_high)
    assert not res.identifiable
    assert any("supply.level has no influence" in n for n in res.notes)
    assert not any("do not separate" in n for n in res.notes)
    assert res.dof == res.points - 1
    assert res.scene.supply.level is None  # not written into the calibrated scene
    # the dead parameter costs one run at the start only: start + its column + the fit
    assert res.runs <= 14


def test_only_parameters_without_influence_is_an_error(tmp_path):
    data = synthetic_measurements(_short_scene(tmp_path, measured=False), SENSORS,
                                  noise_sd=0.0, every=900.0, decimals=6)
    scene = _short_scene(tmp_path, data)
    with pytest.raises(InputError, match="changes the predicted temperatures"):
        calibrate(scene, ["supply.level"], x0={"supply.level": "20 mm"})


# --- bounds that exclude the start: say where the start comes from, in the user's unit ---
def test_bounds_excluding_the_start_name_the_start_and_x0(tmp_path, capsys):
    # before: "x0[supply.inlet_temperature] = 308.15 is not allowed: a start inside the
    # bounds [313.15, 323.15]" (kelvin, and the user never gave an x0)
    code = cli.main(["calibrate", "qj1044_synthetic_measured", "--fit",
                     "supply.inlet_temperature", "--bounds",
                     "supply.inlet_temperature=40 degC:50 degC", "--quiet",
                     "--out", str(tmp_path / "cal")])
    err = capsys.readouterr().err
    assert code == 1
    assert "'35 degC'" in err and "40 degC .. 50 degC" in err
    assert "the scene's value" in err and "--x0" in err


# --- Ctrl-C before the first model run finished ------------------------------------------
def test_ctrl_c_before_any_run_says_nothing_was_written(tmp_path, capsys, monkeypatch):
    import thermobearing.calibrate as calibrate_module

    def interrupted(scene, fit, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(calibrate_module, "calibrate", interrupted)
    out = tmp_path / "cal"
    code = cli.main(["calibrate", "qj1044_synthetic_measured", "--fit",
                     "network.parameters.h_oil", "--out", str(out), "--quiet"])
    err = capsys.readouterr().err
    # before: "every finished model run is in .../calibration_runs.csv; no model run had
    # finished" -- a file that did not exist
    assert code == 130
    assert "before the first model run finished" in err and "nothing was written" in err
    assert not (out / "calibration_runs.csv").exists()


def test_scene_without_measured_fails_before_the_header(tmp_path, capsys):
    # before: "fitting network.parameters.h_oil to ? (one scene run per evaluation)", then
    # the error
    code = cli.main(["calibrate", "qj1044_rig", "--fit", "network.parameters.h_oil",
                     "--out", str(tmp_path / "cal")])
    captured = capsys.readouterr()
    assert code == 1
    assert "to ?" not in captured.out and "fitting" not in captured.out
    assert "[measured]" in captured.err and "examples/README.md" in captured.err


# --- bare numbers in --bounds / --x0 are in the parameter's unit, as in sweep --set --------
def test_bare_bounds_and_start_are_in_the_parameters_unit(capsys, tmp_path):
    from thermobearing.calibrate import _make_parameter

    scene = load_scene("qj1044_synthetic_measured")
    d = scene.to_dict()
    # before: "30:45" meant 30 K .. 45 K, so the 35 degC start was "outside the bounds"
    t_in = _make_parameter(scene, d, "supply.inlet_temperature", {},
                           {"supply.inlet_temperature": ("30", "45")}, {})
    assert (t_in.lower, t_in.upper) == (pytest.approx(303.15), pytest.approx(318.15))
    flow = _make_parameter(scene, d, "supply.flow", {"supply.flow": "20"},
                           {"supply.flow": ("10", "40")}, {})
    assert flow.initial == pytest.approx(20e-3 / 60) and flow.upper == pytest.approx(40e-3 / 60)
    # Python numbers stay SI (the library's documented convention)
    h = _make_parameter(scene, d, "network.parameters.h_oil", {},
                        {"network.parameters.h_oil": (50.0, 5000.0)}, {})
    assert (h.lower, h.upper) == (50.0, 5000.0)
    code = cli.main(["calibrate", "qj1044_synthetic_measured", "--fit",
                     "supply.inlet_temperature", "--bounds", "supply.inlet_temperature=40:50",
                     "--quiet", "--out", str(tmp_path / "cal")])
    assert code == 1
    assert "40 degC .. 50 degC" in capsys.readouterr().err


# --- strongly correlated estimates are said in words, not only in the matrix --------------
def test_strong_correlation_is_a_note():
    from thermobearing.calibrate import correlation_notes

    # the three-parameter fit of the shipped example (h_oil, h_air, inlet temperature):
    # correlations -0.9996, -0.9976, 0.9991 -- printed only as a matrix before
    corr = np.array([[1.0, -0.9996, -0.9976], [-0.9996, 1.0, 0.9991],
                     [-0.9976, 0.9991, 1.0]])
    notes = correlation_notes(["h_oil", "h_air", "t_in"], corr)
    assert len(notes) == 3 and "h_oil and h_air are strongly correlated (r = -0.9996)" in \
        notes[0]
    assert correlation_notes(["a", "b"], np.array([[1.0, 0.5], [0.5, 1.0]])) == []
    assert correlation_notes(["a", "b"], np.full((2, 2), np.nan)) == []


def test_ctrl_c_says_how_to_go_on_from_the_best_run(tmp_path, capsys, monkeypatch):
    import thermobearing.calibrate as calibrate_module

    def interrupted(scene, fit, *, callback=None, **kwargs):
        callback(1, {"network.parameters.h_oil": 270.0}, 0.70)
        callback(2, {"network.parameters.h_oil": 375.0626}, 0.108)
        raise KeyboardInterrupt

    monkeypatch.setattr(calibrate_module, "calibrate", interrupted)
    code = cli.main(["calibrate", "qj1044_synthetic_measured", "--fit",
                     "network.parameters.h_oil", "--out", str(tmp_path / "cal"), "--quiet"])
    err = capsys.readouterr().err
    # before: the best run was named, but not how to start a new fit there (bare --x0
    # numbers are in the parameter's unit, the unit of the progress lines)
    assert code == 130
    assert "rerun with --x0 network.parameters.h_oil=375.063" in err


def test_bearing_override_starts_from_the_preset_value():
    # before: "x0[...] is missing: a starting value: the scene does not set this field and
    # its default is a correlation" -- the default is the preset's "0.10 mm"
    from thermobearing.calibrate import _make_parameter

    scene = load_scene("qj1044_synthetic_measured")
    p = _make_parameter(scene, scene.to_dict(), "bearings.0.overrides.diametral_clearance",
                        {}, {}, {})
    assert p.initial == pytest.approx(0.10e-3) and p.display_unit == "mm"
    assert p.transform == "log"
