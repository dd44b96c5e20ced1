"""Paper 001 cage sliding trends: the gated directions hold and every row is computed."""

from __future__ import annotations

import math

from thermobearing.validation import run_case


def test_paper001_cage_sliding_trends_case():
    records = run_case("paper001_cage_sliding_trends")
    assert records and all(math.isfinite(r.computed) for r in records)
    gated = [r for r in records if r.gated]
    assert {r.quantity for r in gated} == {"falls_with_load", "rises_with_speed"}
    assert all(r.passed for r in gated)
