"""Identical bearings share a kinematics solve and its validity warnings."""

from __future__ import annotations

from thermobearing.scene import load_scene, loads_scene
from thermobearing.simulation import Simulation
from thermobearing.toml_writer import dumps_toml


def test_the_twin_bearing_gets_the_film_range_warnings_of_the_shared_solve():
    # before: the default rig's non-drive-end bearing took the drive end's kinematics
    # (same bearing, same state) without its warnings: only drive_end listed the film
    # formula outside its fitted range, as if the other bearing were inside it
    d = load_scene().to_dict()
    d["schedule"] = {"steps": [{"duration": "1 min", "speed": "1800 rpm",
                                "radial_load": "1 kN", "axial_load": "4 kN"}]}
    sim = Simulation(loads_scene(dumps_toml(d)), progress=False)
    res = sim.run()
    solves = {b.name: b.solves for b in sim.bearings}
    assert solves["drive_end"] >= 1 and solves["non_drive_end"] == 0  # the solve was shared
    film = [w for w in res.warnings if "hamrock_dowson_1977_central:" in w]
    assert [w.split(",")[0] for w in film] == ["drive_end", "non_drive_end"]
    assert film[0].split(",", 1)[1] == film[1].split(",", 1)[1]  # same ranges, steps, count


def test_the_twin_bearing_gets_the_heat_source_warnings_of_the_shared_evaluation(monkeypatch):
    # heat evaluations are shared the same way (memo keyed by the bearing's content); a
    # source's warning raised for drive_end only was missing for non_drive_end
    import warnings

    import thermobearing.heat_sources as hs
    from thermobearing.errors import ValidityWarning

    real = hs.evaluate_recorded

    def warning_source(names, ctx):
        warnings.warn("cage_guide: Reynolds number 4.1e4 beyond laminar", ValidityWarning,
                      stacklevel=2)
        return real(names, ctx)

    monkeypatch.setattr(hs, "evaluate_recorded", warning_source)
    d = load_scene().to_dict()
    d["schedule"] = {"steps": [{"duration": "1 min", "speed": "1800 rpm",
                                "radial_load": "1 kN", "axial_load": "4 kN"}]}
    res = Simulation(loads_scene(dumps_toml(d)), progress=False).run()
    lines = [w for w in res.warnings if "Reynolds number" in w]
    assert [w.split(":")[0] for w in lines] == ["drive_end", "non_drive_end"]
