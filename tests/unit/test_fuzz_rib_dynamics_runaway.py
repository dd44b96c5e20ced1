"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1 cases 32, 89, 135; seed 2 case 81): the
default rib_friction source (coupled roller + cage dynamics of paper 003) on the
CRB 50x75x16 with a viscous oil (ISO VG46 at 40 degC) diverges, and on the table path the
runaway spins were tabulated on the fixed 50 rad/s spin step: at 5000 r/min the table
asked for 3.9e6 spin nodes (10.9 GiB) and the run died of memory. A spin beyond
SPIN_RUNAWAY x the inner raceway's drive now stops the table path first. The cause, the stiff
spin under a mineral oil's raceway shear, is integrated by ETDRK4 since (these states run:
test_roller_dynamics_etd); the safety nets are tested here on the explicit RK4 scheme
(integrator="rk4"), which still runs away."""

from __future__ import annotations

import math

import pytest

from thermobearing import load_lubricant
from thermobearing.errors import ConvergenceError
from thermobearing.geometry import load_bearing
from thermobearing.skidding.roller_dynamics import build_model
from thermobearing.skidding.roller_dynamics_coupled import SPIN_RUNAWAY, simulate_coupled


def test_runaway_spin_stops_the_table_path():
    bearing = load_bearing("CRB_50x75x16")
    oil = load_lubricant("ISO_VG46")
    m = build_model(bearing, oil, 5000.0 * math.pi / 30.0, 2865.92, 0.0,
                    temperature=313.15, coupling="none")
    with pytest.raises(ConvergenceError) as err:
        simulate_coupled(m, bearing, oil, fallback=False, integrator="rk4")
    assert "a roller spin ran to" in str(err.value)
    assert f"beyond {SPIN_RUNAWAY:g} x the" in str(err.value)


def test_nan_state_on_the_reference_path_is_a_convergence_error(monkeypatch):
    """ISO VG46 at 80 degC, 3 kN, 20000 r/min, 1600 steps per spin period: the reference
    (evaluate) path's state turned NaN between the integrator's finiteness checks and the
    next traction refresh stopped on it with "load = array([nan, nan, ...]) is not
    allowed: a finite number". Since the raceway traction feels the pocket speed (session
    17, roller dynamics commits d31d9d0 / 935bf3b) this state runs on RK4 too, so the state
    going non-finite inside a block is made here: the first integrator block returns with
    its status unchanged and one state value NaN, as the kernel did between its checks."""
    import thermobearing.skidding.roller_dynamics_coupled as coupled

    real = coupled._integrate
    calls = {"n": 0}

    def nan_after_first_block(*args):
        out = real(*args)
        calls["n"] += 1
        if calls["n"] == 1:
            args[1][0] = math.nan  # y: the state vector the kernel integrates in place
        return out

    monkeypatch.setattr(coupled, "_integrate", nan_after_first_block)
    bearing = load_bearing("CRB_50x75x16")
    oil = load_lubricant("ISO_VG46")
    m = build_model(bearing, oil, 20000.0 * math.pi / 30.0, 3000.0, 0.0,
                    temperature=353.15, coupling="none")
    with pytest.raises(ConvergenceError, match="roller_dynamics.coupled did not converge"
                       ) as err:
        simulate_coupled(m, bearing, oil, steps_per_period=1600, integrator="rk4",
                         traction="evaluate")
    assert "state not finite" in str(err.value) and "array(" not in str(err.value)
    assert calls["n"] == 1
