"""``[schedule] axial_load_steps`` whose step is far too small, found while fuzzing the
scene front end (session 18): 0 N to 1 MN by 1 mN built a billion steps and hung
``thermobearing check``; a step of 1e-308 N stopped with an OverflowError traceback. Both
are refused, naming the table and the number of steps."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene_schedule import MAX_LOAD_STEPS, Schedule


def _sched(start: str, stop: str, step: str) -> Schedule:
    return Schedule.from_dict({"speed": "1500 rpm", "radial_load": "1 kN",
                               "step_duration": "1 s",
                               "axial_load_steps": {"start": start, "stop": stop,
                                                    "step": step}})


@pytest.mark.parametrize(("stop", "step", "count"), [("1 MN", "1 mN", r"1e\+09"),
                                                     ("1e308 N", "1e-308 N", "inf")])
def test_too_many_axial_load_steps_are_refused(stop, step, count):
    with pytest.raises(InputError, match=rf"schedule.axial_load_steps = .*at most "
                                         rf"{MAX_LOAD_STEPS} steps \(these give {count}"):
        _sched("0 N", stop, step)


def test_the_limit_itself_is_allowed():
    steps = _sched("0 N", f"{MAX_LOAD_STEPS - 1} N", "1 N").steps
    assert len(steps) == MAX_LOAD_STEPS
    assert steps[-1].axial_load == pytest.approx(MAX_LOAD_STEPS - 1.0)
