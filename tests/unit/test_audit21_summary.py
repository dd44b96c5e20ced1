"""The run summary counts a schedule step flagged by an operating check once, however many
bearings it flags (summary.csv's ``steps over ... limit [-]``; earlier versions summed the
counts over the bearings, so two identical bearings doubled every count)."""

from __future__ import annotations

from thermobearing.operating_checks import CheckLog, StateCheck
from thermobearing.simulation_summary import flagged_step_counts


def _state(slip: float, pressure: float, film: float | None = None) -> StateCheck:
    return StateCheck(slip=slip, csr=0.45 * (1.0 + slip), csr_th=0.45, max_pressure=pressure,
                      stress_limit=4e9, film_parameter=film)


def _log(name: str, states: dict[int, list[StateCheck]]) -> CheckLog:
    log = CheckLog(bearing=name, roughness=1e-7)
    for step, cs in states.items():
        for c in cs:
            log.record(step, c)
    return log


def test_a_step_flagged_at_two_bearings_counts_once():
    # step 1 skids (-30 %, default limit 5 %) at both bearings, step 2 at "nde" only;
    # step 0 is over its 4 GPa limit at both; the film is thin (Lambda 0.5, limit 1) at
    # step 2 of "de" only
    de = _log("de", {0: [_state(0.0, 4.5e9)], 1: [_state(0.0, 1e9), _state(-0.3, 1e9)],
                     2: [_state(0.0, 1e9, film=0.5)]})
    nde = _log("nde", {0: [_state(0.0, 4.2e9)], 1: [_state(-0.3, 1e9)],
                       2: [_state(-0.3, 1e9, film=3.0)]})
    assert de.flagged_step_indices() == {"skid": [1], "stress": [0], "film": [2]}
    assert nde.flagged_step_indices() == {"skid": [1, 2], "stress": [0], "film": []}
    # summed over the bearings these were skid 3, stress 2, film 1
    assert flagged_step_counts([de, nde]) == {"skid": 2, "stress": 1, "film": 1}
    # one bearing: its own counts (CheckLog.flagged_steps)
    assert flagged_step_counts([nde]) == nde.flagged_steps()
    assert flagged_step_counts([]) == {"skid": 0, "stress": 0, "film": 0}


def test_identical_bearings_count_as_one():
    states = {i: [_state(-0.3, 4.5e9, film=0.5)] for i in range(3)}
    one = flagged_step_counts([_log("de", states)])
    assert one == {"skid": 3, "stress": 3, "film": 3}
    assert flagged_step_counts([_log("de", states), _log("nde", states)]) == one
