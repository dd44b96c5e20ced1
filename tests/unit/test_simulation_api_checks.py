"""The Python API (``Simulation(scene).run()``) checks what the CLI's preflight checks, so
that a script gets the same named errors, before any model is solved."""

from __future__ import annotations

import pytest

from tests.unit.test_bad_input_cli import GOOD_CSV, measured_scene, write_scene
from tests.unit.test_bad_input_scene import BASE, edited
from thermobearing.errors import InputError, UnknownNameError
from thermobearing.scene import load_scene
from thermobearing.simulation import Simulation


def _no_solve(monkeypatch):
    """Make any kinematics solve fail loudly: the checks must come first."""
    import thermobearing.simulation as simulation

    def boom(*args, **kwargs):
        raise AssertionError("a model was solved before the input check")

    monkeypatch.setattr(simulation.Simulation, "solve_kinematics", boom)


def test_missing_network_parameters_named_before_any_solve(tmp_path, monkeypatch):
    scene = load_scene(write_scene(tmp_path, edited("network.parameters", {})))
    _no_solve(monkeypatch)
    with pytest.raises(InputError) as info:
        Simulation(scene, progress=False).run()
    assert "network.parameters" in info.value.field
    assert "housing_outer_diameter" in str(info.value)


def test_measured_text_cell_named_before_any_solve(tmp_path, monkeypatch):
    scene = load_scene(measured_scene(tmp_path, "time [min],TC1\n0,35\n5,abc\n10,37\n"))
    _no_solve(monkeypatch)
    with pytest.raises(InputError) as info:
        Simulation(scene, progress=False).run()
    assert "TC1" in info.value.field and "'abc'" in str(info.value.value)


def test_control_with_skidding_kinematics_named_at_construction(tmp_path):
    data = edited("models.control", "outer_race")
    data["models"]["kinematics"] = "skidding"
    scene = load_scene(write_scene(tmp_path, data))
    with pytest.raises((InputError, UnknownNameError)) as info:
        Simulation(scene, progress=False)
    assert "models.control" in str(info.value)


def test_results_scene_toml_has_absolute_paths(tmp_path, monkeypatch):
    import thermobearing.coupled as coupled

    def stop(sim, writer):  # the scene.toml is written before the run starts
        raise KeyboardInterrupt

    monkeypatch.setattr(coupled, "run_coupled", stop)
    scene = load_scene(measured_scene(tmp_path, GOOD_CSV))
    out = tmp_path / "elsewhere"
    with pytest.raises(KeyboardInterrupt):
        Simulation(scene, progress=False).run(out)
    kept = load_scene(out / "scene.toml")
    assert kept.measured.file == str((tmp_path / "rig.csv").resolve())


def test_bearing_override_refused_is_named_by_its_scene_field(tmp_path):
    data = edited("bearings.0.overrides", {"contact_angle": "90 deg"})
    scene = load_scene(write_scene(tmp_path, data))
    with pytest.raises(InputError) as info:
        Simulation(scene, progress=False)
    assert info.value.field == "bearings[0].overrides.contact_angle"
    assert info.value.value == "90 deg" and "SI" in info.value.allowed


def test_network_parameter_refused_by_the_template_is_named_by_its_scene_field(tmp_path):
    from thermobearing.coupled import build_network

    params = dict(BASE["network"]["parameters"])
    params["housing_length"] = "-140 mm"
    scene = load_scene(write_scene(tmp_path, edited("network.parameters", params)))
    sim = Simulation(scene, progress=False)
    with pytest.raises(InputError) as info:
        build_network(sim)
    assert info.value.field == "network.parameters.housing_length"
    assert info.value.value == "-140 mm"
    params["housing_length"] = "140 mm"
    params["h_oil"] = "-5 W/(m**2*K)"
    scene = load_scene(write_scene(tmp_path, edited("network.parameters", params)))
    with pytest.raises(InputError) as info:
        build_network(Simulation(scene, progress=False))
    assert info.value.field.startswith("network (template") and "h_oil" in str(info.value)


def test_scene_sets_the_template_housing_material_and_contact_model(tmp_path):
    from thermobearing.coupled import build_network
    from thermobearing.scene import check_network

    params = dict(BASE["network"]["parameters"])
    params.update(housing_material="STEEL_LOW_CARBON", contact_model="hertz_contact_paper002")
    data = edited("network.parameters", params)
    check_network(data["network"], require=True)
    net = build_network(Simulation(load_scene(write_scene(tmp_path, data)), progress=False))
    steel = build_network(Simulation(load_scene(write_scene(tmp_path, BASE)), progress=False))
    assert net.state_nodes == steel.state_nodes
    # the contact model changes the ball-ring conductances
    assert {e[3].__class__.__name__ for e in net.edges()} != {
        e[3].__class__.__name__ for e in steel.edges()}
    params["housing_material"] = "UNOBTAINIUM"
    with pytest.raises(InputError):
        build_network(Simulation(load_scene(write_scene(
            tmp_path, edited("network.parameters", params))), progress=False))
