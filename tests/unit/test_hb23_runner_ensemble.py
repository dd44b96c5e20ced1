"""The paper003 runner's ensembles of the chaotic (unbalance) points (issue 9), on a cheap
stand-in of the roller dynamics: every unbalance point runs once per listed step count, the
points without unbalance once; the gated rows are functions of the ensemble means, with
their standard errors (hand-checked); a trajectory that runs away is left out and counted;
bad trajectory lists are refused naming the input."""

from __future__ import annotations

import math
import tomllib
import warnings
from types import SimpleNamespace

import pytest

from thermobearing.errors import ConvergenceError, InputError, ValidityWarning
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_coupled as rdc
from thermobearing.validation import cases_dir
from thermobearing.validation.runners_rib import paper003_pv_slip_trends

CASE = "paper003_pv_slip_trends"
#: stand-in point values by unbalance [mg]: (left PV, right PV [Pa m/s], slip [m/s])
VALUES = {0: (0.0, 0.0, 3.0), 60: (600e6, 606e6, 3.0), 110: (650e6, 663e6, 3.3)}
#: stand-in trajectory offset by step count: k = -1, 0, +1
OFFSET = {400: -1, 408: 0, 416: 1}


def _inputs() -> dict:
    text = (cases_dir() / CASE / "case.toml").read_text(encoding="utf-8")
    return dict(tomllib.loads(text)["inputs"])


def _response(mass: float, steps: int, fail: set) -> SimpleNamespace:
    mg = round(mass * 1e6)
    if (mg, steps) in fail:
        raise ConvergenceError("roller_dynamics.coupled", 0.3, "stand-in runaway")
    left, right, slip = VALUES[mg]
    k = OFFSET[steps] if mg else 0   # without unbalance: steady, no trajectory scatter
    return SimpleNamespace(pv_left=left * (1 + 0.01 * k), pv_right=right * (1 - 0.01 * k),
                           pv_contact_left=left, pv_contact_right=right, pv_peak_left=left,
                           pv_peak_right=right, slip_speed=slip + 0.1 * k, cost_s=1.0)


@pytest.fixture
def stand_in(monkeypatch):
    """Cheap stand-ins of the models the runner calls; records the coupled runs."""
    calls: list[tuple[int, int]] = []
    warmups: list[tuple[int, float]] = []
    fail: set = set()

    def build_model(bearing, lub, speed, load, mass, **kw):
        return SimpleNamespace(mass=mass, extras={"quasi_static": None})

    def simulate_coupled(m, bearing, lub, *, steps_per_period=400, warmup_orbits=None, **kw):
        calls.append((round(m.mass * 1e6), steps_per_period))
        warmups.append((round(m.mass * 1e6), warmup_orbits))
        return _response(m.mass, steps_per_period, fail)

    def pv_slip_map(bearing, lub, parameter, values, masses, *, model="reduced",
                    coupled_options=None, **kw):
        rows = []
        for value in values:
            for mass in masses:
                if model == "coupled":
                    steps = coupled_options["steps_per_period"]
                    calls.append((round(mass * 1e6), steps))
                    r = _response(mass, steps, fail)
                else:
                    r = _response(mass, 408, set())
                # a value-dependent PV so the sweeps' rows are defined
                rows.append({**vars(r), "pv_left": r.pv_left * (1 + value),
                             "parameter": parameter, "value": value})
        return rows

    one = SimpleNamespace(pv_left=1.0, pv_right=1.0, slip_speed=1.0, cost_s=0.1)
    monkeypatch.setattr(rd, "build_model", build_model)
    monkeypatch.setattr(rd, "pv_slip_map", pv_slip_map)
    monkeypatch.setattr(rd, "simulate_full", lambda m: one)
    monkeypatch.setattr(rd, "simulate_reduced", lambda m: one)
    monkeypatch.setattr(rdc, "simulate_coupled", simulate_coupled)
    return calls, fail, warmups


def _run(steps: list[int], sweep_steps: list[int]) -> dict:
    inputs = _inputs()
    inputs["coupled_trajectories"] = steps
    inputs["coupled_sweep_trajectories"] = sweep_steps
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return paper003_pv_slip_trends(inputs, cases_dir() / CASE)


def test_unbalance_rows_are_ratios_of_ensemble_means_with_their_standard_errors(stand_in):
    calls, _, warmups = stand_in
    out = _run([400, 408, 416], [400, 408])
    base = calls[:7]
    # the base point without unbalance runs once (deterministic), each unbalance point
    # once per listed step count
    assert base == [(0, 400), (60, 400), (60, 408), (60, 416), (110, 400), (110, 408),
                    (110, 416)]
    # the base points with unbalance take their own warm-up, the others the sweeps'
    inputs = _inputs()
    warm = [w for _, w in warmups[:7]]
    assert warm == [inputs["coupled_warmup_orbits"]] + [inputs["coupled_base_warmup_orbits"]] * 6
    # slip 3.2 / 3.3 / 3.4 at 0.11 g and 2.9 / 3.0 / 3.1 at 0.06 g: means 3.3 / 3.0, each
    # SE^2 = 0.1^2 / 3 (independent points): SE(R) = R sqrt(SE^2 (1/3.3^2 + 1/3.0^2))
    var = 0.1**2 / 3.0
    assert out["slip_ratio_unbalance_high_vs_low"] == pytest.approx(1.1, rel=1e-12)
    assert out["slip_ratio_unbalance_high_vs_low_stderr"] == pytest.approx(
        1.1 * math.sqrt(var / 3.3**2 + var / 3.0**2), rel=1e-6)
    # against the deterministic point without unbalance (3.0, one run): SE(3.3) / 3.0
    assert out["slip_ratio_unbalance_high_vs_none"] == pytest.approx(1.1, rel=1e-12)
    assert out["slip_ratio_unbalance_high_vs_none_stderr"] == pytest.approx(
        math.sqrt(var) / 3.0, rel=1e-6)
    # right / left at 0.11 g, paired and anticorrelated (+-1 % of 663 / 650 MPa m/s):
    # R = 1.02, SE^2 = R^2 (1e-4 + 1e-4 + 2e-4) / 3
    assert out["pv_right_over_left_high_unbalance"] == pytest.approx(1.02, rel=1e-12)
    assert out["pv_right_over_left_high_unbalance_stderr"] == pytest.approx(
        1.02 * math.sqrt(4e-4 / 3.0), rel=1e-6)
    assert out["base_slip_speed_high_unbalance"] == pytest.approx(3.3, rel=1e-12)
    assert out["coupled_trajectories_per_point"] == 3.0
    assert out["coupled_sweep_trajectories_per_point"] == 2.0
    assert out["coupled_trajectories_failed"] == 0.0
    # the sweeps: unbalance points twice, the load sweep's points (no unbalance) once
    sweep = calls[7:]
    assert sweep.count((0, 400)) == len(_inputs()["radial_loads"])
    assert (0, 408) not in sweep
    assert sweep.count((110, 400)) == sweep.count((110, 408)) > 0


def test_one_trajectory_gives_the_value_without_a_standard_error(stand_in):
    out = _run([408], [408])
    assert out["slip_ratio_unbalance_high_vs_low"] == pytest.approx(1.1, rel=1e-12)
    assert math.isnan(out["slip_ratio_unbalance_high_vs_low_stderr"])
    assert math.isnan(out["pv_ratio_speed_high_vs_low_stderr"])


def test_a_runaway_trajectory_is_left_out_and_counted(stand_in):
    _, fail, _ = stand_in
    fail.add((110, 416))
    with pytest.warns(ValidityWarning, match="416 steps per spin period"):
        inputs = _inputs()
        inputs["coupled_trajectories"] = [400, 408, 416]
        inputs["coupled_sweep_trajectories"] = [400, 408]
        out = paper003_pv_slip_trends(inputs, cases_dir() / CASE)
    # 0.11 g from 3.2 and 3.3 (mean 3.25, SE 0.05), 0.06 g from all three
    assert out["slip_ratio_unbalance_high_vs_low"] == pytest.approx(3.25 / 3.0, rel=1e-12)
    assert out["slip_ratio_unbalance_high_vs_low_stderr"] == pytest.approx(
        3.25 / 3.0 * math.sqrt(0.05**2 / 3.25**2 + 0.01 / 3.0 / 3.0**2), rel=1e-6)
    assert out["coupled_trajectories_failed"] == 1.0
    assert out["coupled_points_failed"] == 0.0


@pytest.mark.parametrize("bad", [-1.0, 51, True, "6"])
def test_a_bad_base_warmup_is_refused_naming_it(bad):
    inputs = _inputs()
    inputs["coupled_base_warmup_orbits"] = bad
    with pytest.raises(InputError, match=r"inputs\.coupled_base_warmup_orbits"):
        paper003_pv_slip_trends(inputs, cases_dir() / CASE)


@pytest.mark.parametrize("bad", [[], [399, 408], [400, 400], [400.0], [True], "400", 400,
                                 list(range(400, 433))])
def test_a_bad_trajectory_list_is_refused_naming_it(bad):
    for key in ("coupled_trajectories", "coupled_sweep_trajectories"):
        inputs = _inputs()
        inputs[key] = bad
        with pytest.raises(InputError, match=rf"inputs\.{key}"):
            paper003_pv_slip_trends(inputs, cases_dir() / CASE)
