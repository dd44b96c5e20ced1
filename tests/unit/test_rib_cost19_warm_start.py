"""Warm start of the coupled rib dynamics from a neighbouring temperature node (issue 9 cost):
roller_dynamics_heat ``warm_start_nodes`` and simulate_coupled ``start``."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from thermobearing.errors import ConvergenceError, InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_coupled as rc
from thermobearing.skidding import roller_dynamics_heat as rdh

RPM = math.pi / 30.0


@pytest.fixture(scope="module")
def crb():
    return load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699")


def _fake_runs(monkeypatch, fail_warm_at=()):
    """run_dynamics replaced by a recorder: (temperature, start temperature or None)."""
    calls = []

    def run(bearing, lubricant, speed, radial_load, temperature, unbalance_mass=0.0, *,
            start=None, **kw):
        calls.append((round(temperature, 6),
                      None if start is None else round(start.temperature, 6)))
        if start is not None and round(temperature, 6) in fail_warm_at:
            raise ConvergenceError("roller_dynamics.coupled", 0.3, "unstable coupled motion",
                                   {})
        out = rdh.RibDynamicsHeat(temperature / 1e4, temperature / 2e4, 1.0, 2.0, 0.5, 3.0,
                                  temperature, 0.25, 1, "coupled", 0, 2.0,
                                  int(start is not None))
        series = {"end_state": np.full(4, temperature),
                  "quasi_static_state": np.full(3, temperature)}
        return out, SimpleNamespace(series=series)

    monkeypatch.setattr(rdh, "run_dynamics", run)
    return calls


def test_a_node_starts_from_the_nearest_node_run_within_reach(monkeypatch):
    calls = _fake_runs(monkeypatch)
    rdh.clear_cache()
    try:
        heat = rdh.rib_dynamics_heat
        heat("bearing", "oil", 100.0, 3000.0, 350.0)
        first = heat("bearing", "oil", 100.0, 3000.0, 355.0)
        assert first.warm_starts == 1
        heat("bearing", "oil", 100.0, 3000.0, 370.0)      # 3 nodes from 355 K
        heat("bearing", "oil", 100.0, 3000.0, 395.0)      # 5 nodes from 370 K: cold
        heat("bearing", "oil", 100.0, 3000.0, 365.0)      # 370 K is nearer than 355 K
        heat("bearing", "oil", 100.0, 3000.0, 360.0)      # 355 and 365 K: the cooler one
        assert calls == [(350.0, None), (355.0, 350.0), (370.0, 355.0), (395.0, None),
                         (365.0, 370.0), (360.0, 355.0)]
        # a temperature between two nodes: the second node starts from the first
        calls.clear()
        out = heat("bearing", "oil", 100.0, 3000.0, 401.0)
        assert calls == [(400.0, 395.0), (405.0, 400.0)] and out.warm_starts == 2
        # another operating state (load) has no node to start from
        calls.clear()
        heat("bearing", "oil", 100.0, 2000.0, 355.0)
        assert calls == [(355.0, None)]
    finally:
        rdh.clear_cache()


def test_no_warm_start_with_an_unbalance_or_when_switched_off(monkeypatch):
    calls = _fake_runs(monkeypatch)
    rdh.clear_cache()
    try:
        for t in (350.0, 355.0):
            rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, t, 6e-5)
            rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, t, warm_start_nodes=0)
            rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, t, model="reduced")
        assert all(start is None for _, start in calls) and len(calls) == 6
        for bad in (-1, 1.5, True):
            with pytest.raises(InputError, match="warm_start_nodes"):
                rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0,
                                      warm_start_nodes=bad)
    finally:
        rdh.clear_cache()


def test_a_failed_warm_start_is_run_again_from_the_quasi_static_state(monkeypatch):
    calls = _fake_runs(monkeypatch, fail_warm_at=(355.0,))
    rdh.clear_cache()
    try:
        rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
        out = rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 355.0)
        assert calls == [(350.0, None), (355.0, 350.0), (355.0, None)]
        assert out.warm_starts == 0 and out.heat_left == pytest.approx(0.0355)
        assert out.runs == 1
    finally:
        rdh.clear_cache()


def test_start_state_is_checked_and_continues_the_motion(crb):
    b, lub = crb
    m = rd.build_model(b, lub, 20000 * RPM, 3000.0, 0.0, coupling="none")
    first = rc.simulate_coupled(m, b, lub, n_orbits=0.02, warmup_orbits=0.0)
    end = first.series["end_state"]
    z_n = len(m.azimuth)
    assert end.shape == (z_n * rc.N_ROLLER_STATES + 4,) and np.all(np.isfinite(end))
    # the run goes on from there: its first samples hold the end's cage speed and spins
    more = rc.simulate_coupled(m, b, lub, n_orbits=0.02, warmup_orbits=0.0, start=end)
    assert more.series["cage_speed"][0] == pytest.approx(end[z_n * rc.N_ROLLER_STATES + 1],
                                                         rel=1e-3)
    np.testing.assert_allclose(more.series["spin"][0], end[7:z_n * rc.N_ROLLER_STATES:8],
                               rtol=1e-3)
    with pytest.raises(InputError, match="start"):
        rc.simulate_coupled(m, b, lub, n_orbits=0.02, warmup_orbits=0.0, start=end[:-1])
    bad = end.copy()
    bad[3] = math.nan
    with pytest.raises(InputError, match="start"):
        rc.simulate_coupled(m, b, lub, n_orbits=0.02, warmup_orbits=0.0, start=bad)


def _start(resp, temperature):
    s = resp.series
    return rdh.CoupledStart(s["quasi_static_state"], s["end_state"], temperature)


def test_warm_start_keeps_the_settled_node_heat(crb, crb_rib_run):
    """20000 r/min, 3 kN, no unbalance: the 375 K node started from the 370 K node's end
    state books the cold start's rib heat (measured against a 30-orbit reference: cold
    -0.013 %, warm -0.028 %; benchmarks/bm_rib_friction.py nodes within 0.02 %); its
    quasi-static state (Newton from the 370 K one) is the cold solve's."""
    b, lub = crb
    w = 20000 * RPM
    _, prev = rdh.run_dynamics(b, lub, w, 3000.0, 370.0)
    cold, resp_cold = crb_rib_run(w, 375.0)  # rdh.run_dynamics(b, lub, w, 3000.0, 375.0)
    warm, resp_warm = rdh.run_dynamics(b, lub, w, 3000.0, 375.0, start=_start(prev, 370.0))
    assert cold.warm_starts == 0 and warm.warm_starts == 1
    np.testing.assert_allclose(resp_warm.series["quasi_static_state"],
                               resp_cold.series["quasi_static_state"], rtol=1e-6)
    assert warm.heat == pytest.approx(cold.heat, rel=1e-3)
    assert warm.rib_slide_speed == pytest.approx(cold.rib_slide_speed, rel=5e-4)
    assert warm.slip_speed == pytest.approx(cold.slip_speed, rel=3e-3)


def test_warm_start_shortens_the_hot_oil_cage_creep(crb, crb_rib_run):
    """30000 r/min, 3 kN, 400 K, no unbalance: the cage mode is weakly damped in the hot oil
    (roller_dynamics_heat notes, "Warm start"), the cage creeps from its quasi-static
    1311 rad/s to ~1344 rad/s and the settling warm-up runs ~7 orbits; from the 395 K
    node's end state it settles within ~3-4 orbits to the same rib heat within the settling
    test's resolution (measured against a 35-orbit reference: cold +0.11 %, warm -0.085 %;
    roller_dynamics_coupled notes, "Settling test"). Those numbers are of the isothermal
    eq. 35 (quasi-static 1311, settled 1343.7 rad/s); with the default Gupta inlet heating
    of the rolling force (since 2026-11-24) the quasi-static cage is 1326.05 rad/s, the
    25 + 10-orbit reference 1351.94 rad/s and the cold window 1351.48 rad/s, rib heat
    +0.108 % (measured)."""
    b, lub = crb
    w = 30000 * RPM
    _, prev = rdh.run_dynamics(b, lub, w, 3000.0, 395.0)
    cold, resp_cold = crb_rib_run(w, 400.0)  # rdh.run_dynamics(b, lub, w, 3000.0, 400.0)
    warm, resp_warm = rdh.run_dynamics(b, lub, w, 3000.0, 400.0, start=_start(prev, 395.0))
    assert resp_cold.series["settled"][0] == 1 and resp_warm.series["settled"][0] == 1
    assert warm.orbits < cold.orbits - 2.0
    assert warm.heat == pytest.approx(cold.heat, rel=0.01)
    # both windows hold the settled cage (25 + 10-orbit mean 1351.94 rad/s) within 0.2 %
    for resp in (resp_cold, resp_warm):
        assert float(np.mean(resp.series["cage_speed"])) == pytest.approx(1351.94, rel=2e-3)


@pytest.mark.parametrize("bad", [1.5, -1, 11])
def test_heat_source_refuses_a_bad_warm_start_option(crb, bad):
    from thermobearing.heat_sources import HEAT_SOURCES, HeatContext
    from thermobearing.skidding.roller import solve_roller
    from thermobearing.state import OilSupply, OperatingPoint

    b, lub = crb
    w = 20000 * RPM
    kin = solve_roller(b, lub, w, 3000.0, 0.0, 362.0).kinematic_state
    ctx = HeatContext.isothermal(
        362.0, bearing=b, lubricant=lub,
        supply=OilSupply(method="jet", flow_rate=1e-5, inlet_temperature=353.15, level=None),
        operating=OperatingPoint(inner_speed=w, radial_load=3000.0, axial_load=0.0),
        kinematics=kin, options={"rib_friction": {"warm_start_nodes": bad}})
    with pytest.raises(InputError, match=r"options\[rib_friction\]\.warm_start_nodes"):
        HEAT_SOURCES.get("rib_friction")(ctx)
