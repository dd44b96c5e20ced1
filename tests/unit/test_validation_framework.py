"""The validation driver: parallel runs equal serial ones, progress lines, bad input."""

from __future__ import annotations

import pytest

from thermobearing import validation
from thermobearing.errors import InputError, UnknownNameError

FAST = ["paper004_bpfo", "paper002_csr_theoretical", "paper000_cage_speed_theoretical"]


def test_progress_line_per_case_in_order() -> None:
    lines: list[str] = []
    records = validation.run_cases(FAST, progress=lines.append)
    assert [ln.split("]")[0] + "]" for ln in lines] == [f"[{c}]" for c in FAST]
    assert all(" ok (" in ln for ln in lines)
    assert [r.case for r in records][0] == FAST[0] and records[-1].case == FAST[-1]


@pytest.mark.slow  # two spawned workers import the package (~15-30 s on 2 cores)
def test_parallel_equals_serial_in_the_given_order() -> None:
    serial = validation.run_cases(FAST)
    parallel = validation.run_cases(FAST, jobs=2)
    assert [r.case for r in serial] == [r.case for r in parallel]
    assert [(r.quantity, r.computed, r.passed) for r in serial] == \
        [(r.quantity, r.computed, r.passed) for r in parallel]


def test_bad_jobs_and_unknown_case() -> None:
    with pytest.raises(InputError, match="jobs"):
        validation.run_cases(FAST[:1], jobs=0)
    with pytest.raises(UnknownNameError, match="no_such_case"):
        validation.run_cases(["paper004_bpfo", "no_such_case"])
