"""The skidding kinematics hands a table-backed film's solve to the driver the film
registers in :data:`thermobearing.kinematic_models.TABLE_FILM_DRIVERS` (no name of a film
in kinematic_models): ``numerical_tehl`` registers :func:`solve_roller_tehl`, and a second
table-backed film registered the same way is driven without any edit there."""

from __future__ import annotations

import math

import pytest

from thermobearing import kinematic_models as km
from thermobearing.ehl import coupling
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.registry import Registry
from thermobearing.skidding import solve
from thermobearing.state import OilSupply, OperatingPoint

LUB = load_lubricant("OIL_4109")
OP = OperatingPoint(inner_speed=5000.0 * math.pi / 30.0, radial_load=2e3)
SUPPLY = OilSupply("jet", 1e-3 / 60.0, 313.15)


def test_numerical_tehl_registers_its_driver():
    driver = km.table_film_driver("numerical_tehl")
    assert driver is km.TABLE_FILM_DRIVERS.get("numerical_tehl")
    entry = km.TABLE_FILM_DRIVERS.entry("numerical_tehl")
    assert "shi2015_tehl_roller" in entry.references
    # the plain solve's drag models and no drag model have no driver
    assert km.table_film_driver("closed_form") is None
    assert km.table_film_driver(None) is None


def test_the_tehl_driver_is_solve_roller_tehl_looked_up_when_called(monkeypatch):
    seen = []
    monkeypatch.setattr(coupling, "solve_roller_tehl",
                        lambda *a, **k: seen.append((a, k)) or "result")
    out = km.table_film_driver("numerical_tehl")("b", "oil", 1.0, 2.0, 3.0, 300.0,
                                                 film_model="fm", guess=None)
    assert out == "result"
    assert seen == [(("b", "oil", 1.0, 2.0, 3.0, 300.0), {"film_model": "fm", "guess": None})]


def test_a_second_table_backed_film_is_driven_through_the_registry(monkeypatch):
    """A stand-in 'second_table' film registered in a fresh driver registry: the
    kinematics call its driver with the solve's arguments (drag_model taken out, the other
    options passed on) and build the result from what it returns. The driver here runs
    the plain closed-form solve, so the state must equal the plain kinematics'."""
    drivers: Registry = Registry("table_film_driver", "test")
    calls = []

    @drivers.register("second_table", references=["li2018_nu214_skidding"],
                      summary="test driver")
    def driver(bearing, lubricant, speed, radial_load, axial_load, temperature, **opts):
        calls.append(dict(opts))
        opts.pop("film_model")
        return solve(bearing, lubricant, speed, radial_load, axial_load, temperature, **opts)

    monkeypatch.setattr(km, "TABLE_FILM_DRIVERS", drivers)
    # the name is known to the roller drag family (no provider import is attempted)
    from thermobearing.skidding.roller_fluid import ROLLER_DRAG

    monkeypatch.setitem(ROLLER_DRAG._entries, "second_table",
                        ROLLER_DRAG.entry("closed_form"))
    bearing = load_bearing("NU214")
    options = {"drag_model": "second_table", "film_model": "table"}
    res = km.skidding(bearing, LUB, OP, contact_temperature=313.15, oil_temperature=313.15,
                      supply=SUPPLY, options=options)
    assert len(calls) == 1
    assert "drag_model" not in calls[0] and calls[0]["film_model"] == "table"
    assert calls[0]["supply"] is SUPPLY and calls[0]["oil_temperature"] == 313.15
    assert options == {"drag_model": "second_table", "film_model": "table"}  # not consumed
    plain = km.skidding(bearing, LUB, OP, contact_temperature=313.15,
                        oil_temperature=313.15, supply=SUPPLY, options={})
    assert res.raw.converged and plain.raw.converged
    assert res.cage_speed_ratio == pytest.approx(plain.cage_speed_ratio, rel=1e-9)
    assert res.state.cage_speed == pytest.approx(plain.state.cage_speed, rel=1e-9)
