"""Session-20 issue 6: a steady run's validity warnings are those of its steady states, not
of the fixed-point iterates on the way (the QJ1044 pair from -10 degC: the film formula's G
range and U up to 4.47e-9 at cold iterates; the steady states, about 43 degC, have
neither). A transient run's states are all real: its warnings stay every state's."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.toml_writer import dumps_toml

RIG = Path(__file__).resolve().parents[2] / "configs" / "scenes" / "qj1044_rig.toml"
#: one variable's interval in a range warning line: "U in [lo, hi] outside [a, b]"
_VAR = re.compile(r"(\S+) in \[([^,\]]+), ([^\]]+)\] outside")


def _rig(mode: str, start: str, **schedule: object) -> Simulation:
    """The default QJ1044 rig scene, 0 and 2 kN axial, from ``start``, in ``mode``."""
    data = tomllib.loads(RIG.read_text(encoding="utf-8"))
    data["outputs"] = {"mode": mode, "want": ["temperatures", "losses", "kinematics"]}
    data["environment"]["initial_temperature"] = start
    data["schedule"]["axial_load_steps"] = {"start": "0 kN", "stop": "2 kN", "step": "2 kN"}
    data["schedule"].update(schedule)
    return Simulation(loads_scene(dumps_toml(data), base_dir=RIG.parent), progress=False)


def _film_ranges(warnings: list[str], bearing: str) -> dict[str, tuple[float, float]]:
    """Variable -> (lo, hi) of the bearing's film-formula range line (empty: no line)."""
    lines = [w for w in warnings if w.startswith(bearing + ",")
             and "hamrock_dowson_1977_central:" in w]
    assert len(lines) <= 1, lines
    if not lines:
        return {}
    return {m.group(1): (float(m.group(2)), float(m.group(3)))
            for m in _VAR.finditer(lines[0])}


@pytest.fixture(scope="module")
def steady_cold():
    return _rig("steady", "-10 degC").run()


@pytest.fixture(scope="module")
def steady_warm():
    return _rig("steady", "80 degC").run()


def test_iterate_only_warning_is_gone(steady_cold):
    """From -10 degC the iterates passed through G = alpha E' = 8990 (the fit's G ends at
    8000) and U up to 4.47e-9; the steady states (about 43 degC) have G inside and U
    below 1.4e-10."""
    ranges = _film_ranges(steady_cold.warnings, "drive_end")
    assert "G" not in ranges
    assert ranges["U"][1] < 2e-10
    temps = steady_cold.tables["steady_temperatures"]
    assert float(temps["drive_end.oil [degC]"].min()) > 30.0  # the steady states are warm


def test_converged_state_warning_remains_and_does_not_depend_on_the_start(
        steady_cold, steady_warm):
    """The steady states' own film warning (U above the fit's 1e-10) stays, for each bearing,
    with the same envelope whether the fixed point started cold or hot (before: -10 degC
    gave U up to 4.47e-9 and a G line, 80 degC U up to 1.4e-10 and W up to 1.01e-5)."""
    for bearing in ("drive_end", "non_drive_end"):
        cold = _film_ranges(steady_cold.warnings, bearing)
        warm = _film_ranges(steady_warm.warnings, bearing)
        assert set(cold) == set(warm) == {"U", "W"}
        assert cold["U"][0] > 1e-10  # the steady state itself is outside the fit
        for var in cold:
            assert cold[var] == pytest.approx(warm[var], rel=1e-2)
    # the steady states' checks (skidding) are reported as before
    assert any("cage skidding" in w for w in steady_cold.warnings)


def test_transient_keeps_the_warnings_of_every_state():
    """A transient run from -10 degC runs through the cold states: their G warning is
    reported (the held warnings are the steady run's only)."""
    res = _rig("transient", "-10 degC", step_duration="20 s").run()
    ranges = _film_ranges(res.warnings, "drive_end")
    assert "G" in ranges
    assert ranges["U"][1] > 1e-9


def test_held_warnings_are_recorded_when_the_run_stops_inside():
    """An error inside :meth:`Simulation.held_warnings` records what it held (a stopped
    steady run keeps the warnings of the step it stopped in); without error nothing held
    reaches the run's warnings."""
    sim = _rig("steady", "35 degC")
    before = list(sim.warnings)
    with sim.held_warnings() as held:
        sim._warn("m: X in [2, 3] outside [0, 1]", "drive_end", 0)
    assert held and sim.warnings == before
    with pytest.raises(RuntimeError), sim.held_warnings():
        sim._warn("m: X in [2, 3] outside [0, 1]", "drive_end", 0)
        raise RuntimeError("stop")
    assert sim.warnings[len(before):] == ["drive_end, step 0: m: X in [2, 3] outside [0, 1]"]


def test_record_state_warnings_gives_the_state_kinematics_and_fresh_heat():
    """record_state_warnings re-raises the warnings of the solve that gave the bearing's
    state and evaluates its heat sources afresh (a memoised evaluation warns no more)."""
    sim = _rig("steady", "35 degC")
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    cold = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 263.15)
    with sim.held_warnings() as held:
        sim.solve_kinematics(b, 0, step, cold)
        sim.evaluate_heat(b, step, b.last, cold)
    assert held and b.last_warnings
    n = len(sim.warnings)
    sim.record_state_warnings(b, 0, step, cold)
    ranges = _film_ranges(sim.warnings, b.name)
    assert "G" in ranges  # the cold state's own warnings
    assert all(w.startswith(b.name + ", step 0:") for w in sim.warnings[n:])


def test_report_says_the_steady_warnings_are_the_steady_states(steady_cold, tmp_path):
    """The report's validity section of a steady run says whose warnings they are; a
    transient's does not."""
    from thermobearing.report import STEADY_WARNINGS_NOTE, write_report

    sim = _rig("steady", "-10 degC")
    html = write_report(steady_cold, sim.scene, tmp_path / "steady.html").read_text(
        encoding="utf-8")
    section = html.split("id='validity-warnings'", 1)[1].split("id='model-chain'", 1)[0]
    assert STEADY_WARNINGS_NOTE in section
    assert "hamrock_dowson_1977_central" in section
    transient = _rig("transient", "-10 degC", step_duration="20 s")
    res = transient.run()
    html = write_report(res, transient.scene, tmp_path / "transient.html").read_text(
        encoding="utf-8")
    assert STEADY_WARNINGS_NOTE not in html
