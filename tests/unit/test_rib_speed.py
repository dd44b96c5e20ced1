"""Running-mean stop of the coupled rib dynamics (roller_dynamics_convergence): the test
itself, the heat it books against the fixed window, and the fixed window's result kept
exactly where the motion does not converge."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import roller_dynamics_heat as rdh
from thermobearing.skidding.roller_dynamics_convergence import window_converged

RPM = math.pi / 30.0


@pytest.fixture(scope="module")
def crb():
    return load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699")


def test_window_test_drift_scatter_and_zero():
    flat = np.full(6, 0.0323)
    assert window_converged(flat, 0.005)
    # a start transient left: the halves differ by 1 % of the mean
    assert not window_converged(np.array([1.0, 1.0, 1.0, 1.01, 1.01, 1.01]), 0.005)
    # chaotic block scatter of 5 % (paper 003 base case, 0.11 g): 2 se = 4 % > 0.5 %
    rng = np.random.default_rng(1)
    assert not window_converged(73.0 * (1.0 + 0.05 * rng.standard_normal(12)), 0.005)
    # a heat of exactly 0 (no contact, no drag) is converged; a tiny scatter about 0 only
    # through the floor
    assert window_converged(np.zeros(4), 0.005)
    tiny = np.array([0.0, 1e-12, 0.0, 1e-12])
    assert not window_converged(tiny, 0.005)
    assert window_converged(tiny, 0.005, floor=1e-9)
    assert not window_converged(np.array([1.0]), 0.5)          # one block: no statistics
    assert not window_converged(np.array([1.0, math.nan]), 0.5)


def test_converged_heat_within_half_a_percent_of_the_fixed_window(crb, crb_rib_run):
    """No unbalance (a scene's default), 20000 r/min, 3 kN, 375 K: the motion settles, the
    running-mean stop ends before the fixed 5 orbits and its rib heat and rib slide speed
    (which sets the thrust share's heat) agree with the fixed window's (2 warm-up + 3
    statistics orbits) within the stated 1 % (measured 0.02-0.2 %, benchmarks/
    bm_rib_friction.py). The default settling warm-up (roller_dynamics_coupled "Cage
    settling") comes first: 3 orbits here, the stop after ~3 instead of ~2."""
    b, lub = crb
    fixed, _ = rdh.run_dynamics(b, lub, 20000 * RPM, 3000.0, 375.0, 0.0, convergence=None,
                                settle=None)
    # rdh.run_dynamics(b, lub, 20000 * RPM, 3000.0, 375.0, 0.0, convergence=DEFAULT_CONVERGENCE)
    assert rdh.DEFAULT_CONVERGENCE is not None
    conv, resp = crb_rib_run(20000 * RPM, 375.0)
    assert resp.series["converged"][0] == 1
    assert fixed.orbits == pytest.approx(5.0, rel=1e-3)
    assert conv.orbits < 5.0
    assert conv.heat == pytest.approx(fixed.heat, rel=0.01)
    assert conv.rib_slide_speed == pytest.approx(fixed.rib_slide_speed, rel=0.005)
    assert conv.slip_speed == pytest.approx(fixed.slip_speed, rel=0.03)
    t0, t1 = resp.series["window"]
    assert 0.0 < t0 < t1
    assert resp.series["t"][0] >= t0 - 1e-12


def test_unconverged_run_is_the_fixed_window_exactly(crb):
    """With the unbalance (chaotic impacting motion) a tolerance no window meets: the run
    integrates the whole fixed window and returns its samples and numbers."""
    from thermobearing.skidding.roller_dynamics import build_model
    from thermobearing.skidding.roller_dynamics_coupled import simulate_coupled

    b, lub = crb
    m = build_model(b, lub, 30000 * RPM, 3000.0, 1.1e-4, temperature=353.15,
                    coupling="none")
    kw = dict(n_orbits=0.75, warmup_orbits=0.75)
    ref = simulate_coupled(m, b, lub, **kw)
    run = simulate_coupled(m, b, lub, converge=1e-9, **kw)
    assert run.series["converged"][0] == 0
    assert len(run.series["t"]) == len(ref.series["t"])
    np.testing.assert_allclose(run.series["t"], ref.series["t"], rtol=0, atol=0)
    for name in ("rib_heat_left", "rib_heat_right", "pv_left", "pv_right", "slip_speed"):
        assert getattr(run, name) == pytest.approx(getattr(ref, name), rel=1e-12), name


def test_cache_keys_the_convergence_and_the_option_is_checked(crb):
    b, lub = crb
    rdh.clear_cache()
    with pytest.raises(InputError, match="converge"):
        rdh.run_dynamics(b, lub, 20000 * RPM, 3000.0, 375.0, 0.0, convergence=2.0)
    from thermobearing.skidding.roller_dynamics import build_model
    from thermobearing.skidding.roller_dynamics_coupled import simulate_coupled

    m = build_model(b, lub, 20000 * RPM, 3000.0, 0.0, coupling="none")
    with pytest.raises(InputError, match="converge"):
        simulate_coupled(m, b, lub, converge=0.0)


def test_heat_source_books_within_one_percent_of_the_fixed_window(crb):
    """rib_friction (coupled, no unbalance, 20000 r/min, 3 kN, 480 N axial, 362 K: the
    nodes 360 and 365 K): the default running-mean stop against ``convergence = 0`` (the
    fixed window), the booked total (drag of the dynamics + thrust share mu Q |v| at the
    coupled rib slide) within the stated 1 %; an option outside [0, 0.1] is refused. Both
    warm up until the cage settles first (default ``settle``): the fixed window then spans
    its settled warm-up + 3 orbits (>= 5)."""
    from thermobearing.errors import ValidityWarning
    from thermobearing.heat_sources import HEAT_SOURCES, HeatContext
    from thermobearing.skidding.roller import solve_roller
    from thermobearing.state import OilSupply, OperatingPoint

    b, lub = crb
    w = 20000 * RPM
    kin = solve_roller(b, lub, w, 3000.0, 0.0, 362.0).kinematic_state

    def ctx(options):
        return HeatContext.isothermal(
            362.0, bearing=b, lubricant=lub,
            supply=OilSupply(method="jet", flow_rate=1e-5, inlet_temperature=353.15,
                             level=None),
            operating=OperatingPoint(inner_speed=w, radial_load=3000.0, axial_load=480.0),
            kinematics=kin, options={"rib_friction": options})

    src = HEAT_SOURCES.get("rib_friction")
    rdh.clear_cache()
    with pytest.warns(ValidityWarning, match="no path"):
        fixed = src(ctx({"convergence": 0.0}))
        conv = src(ctx({}))
    assert fixed.details["model"] == conv.details["model"] == "coupled"
    assert fixed.details["dynamics_orbits"] >= 5.0 - 1e-3
    assert conv.details["dynamics_orbits"] < fixed.details["dynamics_orbits"] - 1.0
    assert conv.total == pytest.approx(fixed.total, rel=0.01)
    assert conv.details["thrust_heat"] > 0.5 * conv.total      # the thrust share books most
    assert conv.details["dynamic_heat"] == pytest.approx(fixed.details["dynamic_heat"],
                                                         rel=0.01)
    with pytest.raises(InputError, match="convergence"):
        src(ctx({"convergence": 0.5}))
    # the settling warm-up: an option outside [0, 0.1] is refused; 0 keeps the fixed
    # warm-up (2 orbits before the fixed 3: exactly 5)
    with pytest.raises(InputError, match=r"options\[rib_friction\]\.settle"):
        src(ctx({"settle": 0.5}))
    with pytest.warns(ValidityWarning, match="no path"):
        unsettled = src(ctx({"convergence": 0.0, "settle": 0.0}))
    assert unsettled.details["dynamics_orbits"] == pytest.approx(5.0, abs=1e-3)
    assert unsettled.total == pytest.approx(fixed.total, rel=0.01)


def test_runaway_retries_other_table_trajectories_before_the_evaluate_path(crb, monkeypatch):
    """A table-path run that enters the cage runaway is re-run on other trajectories of the
    table path (the start's cage speed perturbed by k x 1e-9) before the evaluate path:
    the result is that trajectory's, flagged; if every retry runs away too, the evaluate
    path finishes as before."""
    from thermobearing.skidding import roller_dynamics_coupled as rc
    from thermobearing.skidding.roller_dynamics import build_model

    b, lub = crb
    m = build_model(b, lub, 20000 * RPM, 3000.0, 0.6e-4, temperature=420.0, coupling="none")
    kw = dict(n_orbits=0.03, warmup_orbits=0.0)
    real = rc._simulate_coupled_path
    calls = []

    def stop_first(*args, traction, trajectory=0, **kwargs):
        calls.append((traction, trajectory))
        if traction == "table" and trajectory < 2:
            raise rc._TableCannotFollow("test", {"t": 1e-3, "cage_speed": 1234.0})
        return real(*args, traction=traction, trajectory=trajectory, **kwargs)

    monkeypatch.setattr(rc, "_simulate_coupled_path", stop_first)
    got = rc.simulate_coupled(m, b, lub, table_retries=3, **kw)
    assert calls == [("table", 0), ("table", 1), ("table", 2)]
    assert got.series["traction_fallback"][0] == 1 and got.series["table_retries"][0] == 2
    assert got.series["fallback_traction"][0] == "table"
    ref = real(m, b, lub, traction="table", trajectory=2, refresh=20e-6,
               steps_per_period=400, samples_per_period=100, phase_spread=True,
               table_options=None, ring_axial=False, cage_land=False,
               cage_band=rc.DEFAULT_CAGE_BAND, integrator="etd", **kw)
    assert got.pv_left == ref.pv_left and got.rib_heat == ref.rib_heat
    # the perturbed start is another trajectory, not the same one
    assert ref.series["cage_speed"][0] != real(
        m, b, lub, traction="table", trajectory=0, refresh=20e-6, steps_per_period=400,
        samples_per_period=100, phase_spread=True, table_options=None, ring_axial=False,
        cage_land=False, cage_band=rc.DEFAULT_CAGE_BAND, integrator="etd",
        **kw).series["cage_speed"][0]
    calls.clear()
    got = rc.simulate_coupled(m, b, lub, table_retries=1, **kw)
    assert calls == [("table", 0), ("table", 1), ("evaluate", 0)]
    assert got.series["fallback_traction"][0] == "evaluate"
    assert got.series["table_retries"][0] == 1
    with pytest.raises(InputError, match="table_retries"):
        rc.simulate_coupled(m, b, lub, table_retries=-1, **kw)


def test_a_failed_node_takes_a_cached_neighbour_without_running_it(monkeypatch):
    """The neighbour a failed node borrows from is taken from the cache when it is there
    (it was run again before), and a neighbour run is cached under its own node."""
    from thermobearing.errors import ConvergenceError, ValidityWarning

    calls = []

    def run(bearing, lubricant, speed, radial_load, temperature, unbalance_mass=0.0, **kw):
        calls.append(temperature)
        if round(temperature, 6) == 350.0:
            raise ConvergenceError("roller_dynamics.coupled", 0.2, "unstable coupled motion",
                                   {})
        return rdh.RibDynamicsHeat(temperature / 10, temperature / 20, 1.0, 2.0, 0.5, 3.0,
                                   temperature, 0.25, 1, "coupled", 0), None

    monkeypatch.setattr(rdh, "run_dynamics", run)
    rdh.clear_cache()
    try:
        rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 345.0)     # node 345 cached
        assert calls == [345.0]
        with pytest.warns(ValidityWarning, match="grid node at 345.00 K"):
            out = rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
        assert calls == [345.0, 350.0]            # the failed node only: 345 K from the cache
        assert out.heat_left == pytest.approx(34.5) and out.runs == 1
        rdh.clear_cache()
        calls.clear()
        with pytest.warns(ValidityWarning):
            rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
        rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 345.0)     # cached by then
        assert calls == [350.0, 345.0]
    finally:
        rdh.clear_cache()
