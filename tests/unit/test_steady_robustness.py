"""Steady mode keeps its trial states inside the models' range (coupled._run_steady,
coupled._steady_pass): a cold start whose chunk model has no usable Newton path, a model
refusing an update, and the invariants of the converged state."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scene_parts import (
    PAPER002_AMBIENT,
    PAPER002_NETWORK,
    PAPER002_OIL,
    QJ1044_DE,
    RACE_CONTROL,
    scene_title,
)

from thermobearing.coupled import Coupler, coldest_boundary
from thermobearing.errors import ConvergenceError, InputError
from thermobearing.network import solve_steady
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

RIG = (Path(__file__).resolve().parents[2] / "configs" / "scenes" / "qj1044_rig.toml")


def _cold_oil_air_rig(speed: str) -> str:
    """The default QJ1044 rig (two bearings on one shaft, four-node networks) at 151 kN
    axial on oil-air at 33 L/min, ambient, inlet and start at -16 degC, one steady point."""
    doc = RIG.read_text(encoding="utf-8")
    start = doc.index("[supply]")
    network = doc.index("[models]")
    head = doc[:start]
    tail = doc[network:doc.index("[outputs]")]
    return head + f"""[supply]
method = "oil_air"
flow = "33 L/min"
inlet_temperature = "-16 degC"

[environment]
ambient_temperature = "-16 degC"
initial_temperature = "-16 degC"

[schedule]
speed = "{speed}"
radial_load = "1 kN"
axial_load = "151 kN"
duration = "3 min"

""" + tail + """[outputs]
mode = "steady"
want = ["temperatures", "losses"]
"""


def _state(res, sim) -> np.ndarray:
    row = res.tables["steady_temperatures"].iloc[-1]
    return np.array([row[f"{n} [degC]"] for n in sim.network.state_nodes]) + 273.15


def _check_fixed_point(sim, res, tol_K: float = 1e-2) -> None:
    """The steady temperatures are the network's steady state under the exact heat there
    (kinematics re-solved at them), that heat is the losses table's, and it leaves through
    the boundaries and the oil streams."""
    T = _state(res, sim)
    net = sim.network
    coupler = Coupler(sim, net)
    step = sim.scene.schedule.steps[-1]
    coupler.kinematics(len(sim.scene.schedule.steps) - 1, step, T)
    q = coupler.heat(step, T)
    check = solve_steady(net, q, T_guess=T)
    assert np.max(np.abs(check.temperatures_vector - T)) < tol_K
    assert check.generated == pytest.approx(check.to_boundaries + check.to_streams, rel=1e-9)
    losses = res.tables["losses"]
    last = losses[losses["step"] == losses["step"].max()]
    assert float(last["power [W]"].sum()) == pytest.approx(float(q.sum()), rel=1e-6)
    # a loss never cools a node below the coldest boundary (ambient, oil inlet)
    assert float(T.min()) >= coldest_boundary(net) - 1e-6
    assert res.stats["relative_energy_imbalance"] < 1e-9


def test_cold_oil_air_rig_at_4500_rpm_converges_to_a_balanced_steady_state():
    """Before: the first pass's Newton step of the chunk model (82 kW of outer-ring heat
    per housing at -16 degC, falling by 9.3 kW per kelvin of oil) put the housings at
    -570 degC, the held model's Newton stopped at -330 degC and the run stopped with 'line
    search failed ... temperature = 35.27 is not allowed: 100 K to 2000 K for air'. The
    pass now relaxes the held model's transient to its steady state."""
    sim = Simulation(loads_scene(_cold_oil_air_rig("4500 rpm")), progress=False)
    res = sim.run()
    T = _state(res, sim) - 273.15
    assert np.all(np.isfinite(T))
    # both bearings identical and identically loaded: identical temperatures
    half = len(T) // 2
    assert np.allclose(T[:half], T[half:], atol=1e-6)
    _check_fixed_point(sim, res)


def test_cold_oil_air_rig_that_cannot_be_cooled_stops_naming_the_runaway():
    """At 6000 r/min the same rig's heat outgrows what the network removes: a clear
    ConvergenceError naming the node and the limit (was: a line-search failure on a
    temperature far below absolute zero)."""
    with pytest.raises(ConvergenceError, match="no steady state below the runaway limit") \
            as info:
        Simulation(loads_scene(_cold_oil_air_rig("6000 rpm")), progress=False).run()
    assert "balls" in str(info.value) and "below absolute zero" not in str(info.value)


BASE = (scene_title("steady") + QJ1044_DE + PAPER002_OIL + PAPER002_AMBIENT + RACE_CONTROL
        + PAPER002_NETWORK + """[schedule]
speed = "1200 rpm"
radial_load = "1 kN"
axial_load = "10 kN"
duration = "1 min"
[outputs]
mode = "steady"
want = ["temperatures", "losses"]
""")


def _refusing(monkeypatch, above_K: float, times: int | None) -> list[float]:
    """Make the kinematics refuse (InputError) states whose oil node is more than
    ``above_K`` above the start, ``times`` times (None: always); returns the refused oil
    temperatures [K]."""
    real = Simulation.solve_kinematics
    refused: list[float] = []
    start = loads_scene(BASE).environment.initial_temperature

    def solve(self, b, step_index, step, temps):
        if temps["oil"] > start + above_K and (times is None or len(refused) < times):
            refused.append(temps["oil"])
            raise InputError("temperature", temps["oil"], "a state this test accepts")
        return real(self, b, step_index, step, temps)

    monkeypatch.setattr(Simulation, "solve_kinematics", solve)
    return refused


def test_a_refused_update_is_backtracked_and_the_run_converges(monkeypatch):
    plain_sim = Simulation(loads_scene(BASE), progress=False)
    plain = _state(plain_sim.run(), plain_sim)
    refused = _refusing(monkeypatch, 0.3, times=1)
    sim = Simulation(loads_scene(BASE), progress=False)
    res = sim.run()
    assert len(refused) == 1
    assert res.stats["backtracks"] == 1
    assert any("a model refused an update" in w for w in sim.warnings)
    # the same fixed point as without the refusal
    assert np.max(np.abs(_state(res, sim) - plain)) < 1e-2
    monkeypatch.undo()
    _check_fixed_point(sim, res)


def test_models_refusing_every_update_stop_with_the_residual_and_the_state(monkeypatch):
    _refusing(monkeypatch, 0.3, times=None)
    with pytest.raises(ConvergenceError) as info:
        Simulation(loads_scene(BASE), progress=False).run()
    err = info.value
    assert err.solver == "coupled steady state"
    assert np.isfinite(err.residual) and err.residual > 0.0
    text = str(err)
    assert "de.oil" in text and "step" in text


def test_a_refused_start_is_the_model_own_error(monkeypatch):
    """The operating point's first state is the scene's: its refusal is not backtracked
    but raised as the model raised it (naming its field)."""
    _refusing(monkeypatch, -1.0, times=None)
    with pytest.raises(InputError, match="a state this test accepts"):
        Simulation(loads_scene(BASE), progress=False).run()
