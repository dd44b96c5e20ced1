"""The rig state at paper 002's over-skidding peak, solved directly
(:mod:`thermobearing.validation.paper002_peak`): the energy-consistent booking equals the
solver's shaft power; paper 002's booking (its eqs. 16 and 18) leaves part of it unbooked and
gives its section 4.3 shares (measured 2026-11-24 at 4 kN: pocket share 0.089 -> 0.246,
cage guide / pocket 1.86 -> 0.18 with mu_c = 0.1)."""

from __future__ import annotations

import math

import pytest

from thermobearing.heat_sources import evaluate
from thermobearing.losses import paper002_bookkeeping
from thermobearing.simulation import BALL_SOURCES
from thermobearing.validation.paper002_peak import loss_shares, solve_rig


@pytest.fixture(scope="module")
def peak():
    return solve_rig(4000.0, 1800.0 * math.pi / 30.0, 33.0 / 6e4)


def test_energy_consistent_booking_is_the_shaft_power(peak):
    heat = {r.source: r.total for r in evaluate(BALL_SOURCES, peak.context)}
    shaft = peak.result.shaft_torque * peak.result.inner_speed
    assert sum(heat.values()) == pytest.approx(shaft, rel=1e-8)
    shares = loss_shares(heat)
    assert shares["total"] == pytest.approx(shaft, rel=1e-8)
    assert shares["pocket_share"] == pytest.approx(
        heat["pocket_friction"] / shaft, rel=1e-12)


def test_paper_booking_changes_only_ball_churning_and_cage_guide(peak):
    heat = {r.source: r.total for r in evaluate(BALL_SOURCES, peak.context)}
    paper = paper002_bookkeeping(peak.context, guide_friction=0.1)
    for name in ("raceway_traction", "churning_cage", "churning_inner_ring",
                 "pocket_friction"):
        assert paper[name] == pytest.approx(heat[name], rel=1e-12)
    assert paper["churning_elements"] < 0.05 * heat["churning_elements"]
    assert paper["cage_guide"] < heat["cage_guide"]
    shares = loss_shares(paper)
    assert shares["total"] < sum(heat.values())
    assert 0.2 < shares["pocket_share"] < 0.3
    assert 0.1 < shares["cage_guide_over_pocket"] < 0.4
