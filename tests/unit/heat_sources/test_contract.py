"""Heat-source plug-in contract: registry, roles, evaluate(), entry points, bad input."""

from __future__ import annotations

import importlib.metadata

import pytest

import thermobearing.heat_sources as hs
from thermobearing.errors import InputError, UnknownNameError

from .conftest import make_context


def test_builtin_sources_registered():
    expected = {"raceway_traction", "ehl_rolling_resistance", "churning_cage",
                "churning_elements", "churning_inner_ring", "cage_guide", "pocket_friction"}
    assert expected <= set(hs.HEAT_SOURCES)


def test_result_rejects_unknown_role():
    with pytest.raises(UnknownNameError, match="housing"):
        hs.HeatResult(source="x", power_by_role={"housing": 1.0}, components={"c": 1.0})
    with pytest.raises(InputError, match="same total"):
        hs.HeatResult(source="x", power_by_role={"oil": 1.0}, components={"c": 2.0})
    with pytest.raises(InputError):
        hs.HeatResult(source="x", power_by_role={"oil": float("nan")}, components={"c": 1.0})
    with pytest.raises(UnknownNameError):
        hs.HeatResult(source="x", power_by_role={"oil": 1.0}, components={"c": 1.0},
                      loss_class={"c": "sometimes"})


def test_evaluate_checks_network_roles(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    ctx = make_context(qj1044, vg46, op, ks)
    out = hs.evaluate(["churning_inner_ring"], ctx, node_roles=hs.ROLES)
    assert out[0].total > 0
    with pytest.raises(InputError, match="churning_inner_ring"):
        hs.evaluate(["churning_inner_ring"], ctx, node_roles=["outer_ring", "oil"])
    with pytest.raises(UnknownNameError):
        hs.evaluate(["churning_inner_ring"], ctx, node_roles=["shaft"])
    with pytest.raises(UnknownNameError):
        hs.evaluate(["no_such_source"], ctx)


def test_context_temperatures(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    ctx = make_context(qj1044, vg46, op, ks)
    assert ctx.temperature("cage") == pytest.approx(318.15)
    with pytest.raises(UnknownNameError):
        hs.HeatContext(bearing=qj1044, lubricant=vg46, supply=ctx.supply, operating=op,
                       temperatures={"shaft": 300.0}, kinematics=ks)
    partial = hs.HeatContext(bearing=qj1044, lubricant=vg46, supply=ctx.supply, operating=op,
                             temperatures={"oil": 300.0}, kinematics=ks)
    with pytest.raises(InputError, match="inner_ring"):
        partial.temperature("inner_ring")


def _plugin(ctx):
    return hs.HeatResult(source="test_plugin_seal", power_by_role={"outer_ring": 1.5},
                         components={"seal": 1.5}, loss_class={"seal": "load_independent"})


_plugin.references = ["harris_kotzalas2007"]
_plugin.summary = "test plug-in: a constant 1.5 W seal"


class _EP:
    name = "test_plugin_seal"

    def load(self):
        return _plugin


def test_entry_point_plugin(monkeypatch, qj1044, vg46, race_control_state):
    def fake(group):
        assert group == hs.ENTRY_POINT_GROUP
        return [_EP()]

    monkeypatch.setattr(importlib.metadata, "entry_points", fake)
    added = hs.load_entry_points()
    try:
        assert added == ["test_plugin_seal"]
        op, ks = race_control_state
        res = hs.evaluate(["test_plugin_seal"], make_context(qj1044, vg46, op, ks))
        assert res[0].total == 1.5
        assert hs.HEAT_SOURCES.entry("test_plugin_seal").references == ("harris_kotzalas2007",)
    finally:
        hs.HEAT_SOURCES._entries.pop("test_plugin_seal", None)  # keep the registry clean
