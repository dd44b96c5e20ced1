"""Rib heat of the roller dynamics: a temperature node whose run stops borrows the nearest
node's value (thermobearing.skidding.roller_dynamics_heat)."""

from __future__ import annotations

import pytest

from thermobearing.errors import ConvergenceError, ValidityWarning
from thermobearing.skidding import roller_dynamics_heat as rdh


def _value(temperature: float) -> rdh.RibDynamicsHeat:
    return rdh.RibDynamicsHeat(temperature / 10, temperature / 20, 1.0, 2.0, 0.5, 3.0,
                               temperature, 0.25, 1, "coupled", 0)


@pytest.fixture
def fake_runs(monkeypatch):
    """run_dynamics replaced: the node at 350 K (and, if asked, 345 K) is unstable."""
    calls = []
    unstable = {350.0}

    def run(bearing, lubricant, speed, radial_load, temperature, unbalance_mass=0.0, **kw):
        calls.append(temperature)
        if round(temperature, 6) in unstable:
            raise ConvergenceError("roller_dynamics.coupled", 0.2,
                                   "unstable coupled motion: the cage speed ran out", {})
        return _value(temperature), None

    monkeypatch.setattr(rdh, "run_dynamics", run)
    rdh.clear_cache()
    yield calls, unstable
    rdh.clear_cache()


def test_a_failed_node_takes_the_cooler_neighbour_with_a_warning(fake_runs):
    calls, _ = fake_runs
    with pytest.warns(ValidityWarning, match=r"at 350.00 K stopped .* grid node at 345.00 K"):
        out = rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
    assert out.heat_left == pytest.approx(34.5) and out.heat_right == pytest.approx(17.25)
    assert calls == [350.0, 345.0]
    # cached: the node is not run again (no new warning, no new run)
    again = rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
    assert again.heat_left == out.heat_left and calls == [350.0, 345.0]
    # between 350 and 355 K the failed node's borrowed value enters the interpolation
    mid = rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 352.5)
    assert mid.heat_left == pytest.approx(0.5 * 34.5 + 0.5 * 35.5)


def test_the_warmer_neighbour_then_two_steps_and_then_the_error(fake_runs):
    calls, unstable = fake_runs
    unstable.add(345.0)
    with pytest.warns(ValidityWarning, match="grid node at 355.00 K"):
        rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
    rdh.clear_cache()
    unstable.update({355.0, 340.0, 360.0})
    with pytest.raises(ConvergenceError, match="unstable coupled motion"):
        rdh.rib_dynamics_heat("bearing", "oil", 100.0, 3000.0, 350.0)
