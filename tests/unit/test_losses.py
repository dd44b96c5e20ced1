"""Loss breakdown (thermobearing.losses): tidy rows, role split per component, FVA totals."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.heat_sources import HeatResult
from thermobearing.losses import COLUMNS, by_source, loss_breakdown, loss_totals

FOUR_NODE = {"outer_ring": "housing", "inner_ring": "shaft", "elements": "balls",
             "cage": "oil", "oil": "oil"}


def _results():
    race = HeatResult(
        source="raceway_traction", power_by_role={"elements": 6.0, "inner_ring": 3.0,
                                                  "outer_ring": 1.0},
        components={"inner contact": 7.0, "outer contact": 3.0},
        loss_class={"inner contact": "load_dependent", "outer contact": "load_dependent"},
        component_roles={"inner contact": {"elements": 4.0, "inner_ring": 3.0},
                         "outer contact": {"elements": 2.0, "outer_ring": 1.0}})
    churn = HeatResult(source="churning_cage", power_by_role={"oil": 20.0},
                       components={"cage churning": 20.0},
                       loss_class={"cage churning": "load_independent"})
    return [race, churn]


def test_tidy_rows_and_totals():
    df = loss_breakdown(_results(), point="Fa=20kN", role_to_node=FOUR_NODE)
    assert tuple(df.columns) == COLUMNS
    assert df["power [W]"].sum() == pytest.approx(30.0)
    inner = df[(df.component == "inner contact")]
    assert set(inner.role) == {"elements", "inner_ring"}  # per-component split, not proportional
    assert set(df[df.role == "outer_ring"].node) == {"housing"}
    tot = loss_totals(df)
    assert tot.loc["Fa=20kN", "load_dependent [W]"] == pytest.approx(10.0)
    assert tot.loc["Fa=20kN", "load_independent [W]"] == pytest.approx(20.0)
    assert tot.loc["Fa=20kN", "total [W]"] == pytest.approx(30.0)
    shares = by_source(df)
    assert shares["share [-]"].sum() == pytest.approx(1.0)


def test_role_missing_from_network_is_an_error():
    with pytest.raises(InputError, match="raceway_traction"):
        loss_breakdown(_results(), role_to_node={"oil": "oil", "elements": "balls"})


def test_component_roles_must_add_up():
    with pytest.raises(InputError, match="component_roles"):
        HeatResult(source="s", power_by_role={"oil": 2.0}, components={"c": 2.0},
                   component_roles={"c": {"oil": 1.0}})


def test_role_map_from_a_network():
    from thermobearing.losses import role_map
    from thermobearing.network import ThermalNetwork

    net = ThermalNetwork()
    net.add_node("housing", capacity=1.0, role="outer_ring")
    net.add_node("shaft", capacity=1.0, role="inner_ring")
    net.add_node("balls", capacity=1.0, role="elements")
    net.add_node("oil", capacity=1.0, role=["cage", "oil"])
    m = role_map(net)
    assert m == FOUR_NODE
    df = loss_breakdown(_results(), role_to_node=m)
    assert set(df.node) == {"housing", "shaft", "balls", "oil"}
