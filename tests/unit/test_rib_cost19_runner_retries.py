"""The paper003 validation runner's table retries (issue 9): the same setting as the rib
heat source, refused when it is not a whole count."""

from __future__ import annotations

import tomllib

import pytest

from thermobearing.errors import InputError
from thermobearing.skidding.roller_dynamics_heat import DEFAULT_TABLE_RETRIES
from thermobearing.validation import cases_dir
from thermobearing.validation.runners_rib import paper003_pv_slip_trends

CASE = "paper003_pv_slip_trends"


def _inputs() -> dict:
    text = (cases_dir() / CASE / "case.toml").read_text(encoding="utf-8")
    return dict(tomllib.loads(text)["inputs"])


def test_the_case_uses_the_heat_sources_table_retries():
    # SOURCE.md "Table retries in the runner": 0 -> 3 moved no gated row; one runaway point
    # (20000 r/min, 0.11 g) finishes on a table retry instead of failing on both paths
    assert _inputs()["coupled_table_retries"] == DEFAULT_TABLE_RETRIES


@pytest.mark.parametrize("bad", [2.5, -1, 11, True, "3"])
def test_a_bad_table_retries_input_is_refused_naming_it(bad):
    inputs = _inputs()
    inputs["coupled_table_retries"] = bad
    with pytest.raises(InputError, match=r"inputs\.coupled_table_retries"):
        paper003_pv_slip_trends(inputs, cases_dir() / CASE)
