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


def test_paper002_bookkeeping_by_hand():
    # a QJ1044 state with the cage at 80 rad/s (outer-ring land fixed), 2 N per pocket:
    # eq. 18 books mu_c |F| D_m omega_c / 2 with |F| = the cage weight the land film carries,
    # eq. 16 books mu_v / 4 of the eq. 10 drag power (churning.py module docstring)
    import math

    import numpy as np

    from thermobearing.geometry import load_bearing
    from thermobearing.heat_sources import HeatContext, evaluate
    from thermobearing.losses import STANDARD_GRAVITY, paper002_bookkeeping
    from thermobearing.lubricant import load_lubricant
    from thermobearing.state import KinematicState, OilSupply, OperatingPoint

    b = load_bearing("QJ1044")
    z = b.n_elements
    ks = KinematicState(inner_speed=188.5, outer_speed=0.0, cage_speed=80.0,
                        orbital_speed=np.full(z, 80.0), element_spin=-900.0, contacts=(),
                        pocket_normal_force=2.0)
    opts = {"churning_elements": {"form": "harris", "oil_fraction": 0.1},
            "churning_cage": {"oil_fraction": 0.1}, "churning_inner_ring": {"oil_fraction": 0.1},
            "pocket_friction": {"friction_coefficient": 0.3}}
    ctx = HeatContext.isothermal(
        318.15, bearing=b, lubricant=load_lubricant("ISO_VG46"),
        supply=OilSupply("jet", 33.0 / 6e4, 308.15),
        operating=OperatingPoint(inner_speed=188.5, radial_load=1000.0, axial_load=4000.0),
        kinematics=ks, options=opts)
    names = ("churning_elements", "churning_cage", "churning_inner_ring", "cage_guide",
             "pocket_friction")
    own = {r.source: r for r in evaluate(names, ctx)}
    booked = paper002_bookkeeping(ctx, guide_friction=0.1, sources=names)
    weight = STANDARD_GRAVITY * b.cage.effective_mass(b.ball_diameter, z)
    assert booked["cage_guide"] == pytest.approx(0.1 * weight * b.pitch_diameter * 80.0 / 2,
                                                 rel=1e-6)
    # the energy-consistent land loss is the Petroff drag power, an order of magnitude more
    assert own["cage_guide"].total > 5 * booked["cage_guide"]
    paper_elem = evaluate(["churning_elements"], HeatContext.isothermal(
        318.15, bearing=b, lubricant=ctx.lubricant, supply=ctx.supply, operating=ctx.operating,
        kinematics=ks, options={**opts, "churning_elements": {"form": "paper002",
                                                               "oil_fraction": 0.1}}))[0]
    mu_v = paper_elem.details["mu_v"]
    assert booked["churning_elements"] == pytest.approx(
        own["churning_elements"].total * mu_v / 4, rel=1e-9)
    for name in ("churning_cage", "churning_inner_ring", "pocket_friction"):
        assert booked[name] == pytest.approx(own[name].total, rel=1e-12)
    assert math.isfinite(sum(booked.values()))
    with pytest.raises(InputError, match="guide_friction"):
        paper002_bookkeeping(ctx, guide_friction=1.5, sources=names)
