"""Validation runners of the loss sources (paper002_churning_flow_ratio, crosscheck)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from thermobearing.validation import RUNNERS, cases_dir


def _run(case):
    d = Path(cases_dir()) / case
    inputs = tomllib.loads((d / "case.toml").read_text())["inputs"]
    import thermobearing.validation.runners_losses  # noqa: F401 - registers the runners

    return RUNNERS.get(case)(inputs, d)


def test_churning_flow_ratio_case():
    out = _run("paper002_churning_flow_ratio")
    # churning is linear in rho_e = X rho_oil and Parker's X ~ Q^0.37 (same temperature)
    assert out["churning_ratio_low_over_high"] == pytest.approx((15 / 33) ** 0.37, rel=1e-9)
    assert 0.5 <= out["churning_ratio_low_over_high"] <= 0.85
    assert out["churning_share_low_flow"] < out["churning_share_high_flow"]


def test_crosscheck_case_prints_all_three_models():
    out = _run("crosscheck_global_friction")
    for key in ("skf6304", "qj1044"):
        rows = [k for k in out if k.startswith("local_over_skf_" + key)]
        assert len(rows) == 3
        for k in rows:
            assert out[k] > 0
    assert out["local_qj1044_1800rpm"] > out["local_qj1044_600rpm"]
