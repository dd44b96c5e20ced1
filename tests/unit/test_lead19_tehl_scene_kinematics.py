"""The scene's skidding kinematics with ``film = "numerical_tehl"`` goes through
:func:`thermobearing.ehl.coupling.solve_roller_tehl` (table nodes only around the converged
state), not the plain solve that fills the table along every Newton iterate. The thermal
solve is replaced by the closed-form stand-in of ``test_tehl_cost19`` (node counting)."""

from __future__ import annotations

import math

from tehl_stand_in import CheapTable as _CheapTable

from thermobearing.ehl import coupling
from thermobearing.geometry import load_bearing
from thermobearing.kinematic_models import skidding
from thermobearing.lubricant import load_lubricant
from thermobearing.simulation_chain import film_kinematics_options
from thermobearing.state import OilSupply, OperatingPoint

LUB = load_lubricant("OIL_4109")


def test_scene_kinematics_uses_the_tehl_driver(monkeypatch):
    monkeypatch.setattr(coupling, "FilmTable", _CheapTable)
    calls = []
    real = coupling.solve_roller_tehl

    def spy(*args, **kwargs):
        calls.append(kwargs)
        return real(*args, **kwargs)

    monkeypatch.setattr(coupling, "solve_roller_tehl", spy)
    bearing = load_bearing("D1842926", overrides={"diametral_clearance": 40e-6})
    opts = film_kinematics_options("numerical_tehl", bearing, LUB, False)
    fm = opts["film_model"]
    op = OperatingPoint(inner_speed=13218.0 * math.pi / 30.0, radial_load=24e3)
    supply = OilSupply("jet", 2e-3 / 60.0, 303.15)
    res = skidding(bearing, LUB, op, contact_temperature=303.15, oil_temperature=303.15,
                   supply=supply, options=opts)
    assert len(calls) == 1 and calls[0]["film_model"] is fm
    assert "drag_model" not in calls[0]
    assert opts["drag_model"] == "numerical_tehl"  # the scene's options are not consumed
    # the driver's first pass ran on provisional films, later passes solved table nodes
    assert fm.provisional > 0 and fm.solves > 0
    assert fm.admitted is None  # restored after the driver
    assert res.raw.converged and res.state.cage_speed > 0.0
    # a warm step at the same point solves no new node
    solves = fm.solves
    skidding(bearing, LUB, op, contact_temperature=303.15, oil_temperature=303.15,
             supply=supply, options=opts, guess=res)
    assert fm.solves == solves
    assert len(calls) == 2


def test_scene_kinematics_without_tehl_keeps_the_plain_solve(monkeypatch):
    called = []
    monkeypatch.setattr(coupling, "solve_roller_tehl",
                        lambda *a, **k: called.append(1))  # must not be reached
    bearing = load_bearing("NU214")
    op = OperatingPoint(inner_speed=5000.0 * math.pi / 30.0, radial_load=2e3)
    supply = OilSupply("jet", 1e-3 / 60.0, 313.15)
    res = skidding(bearing, LUB, op, contact_temperature=313.15, oil_temperature=313.15,
                   supply=supply, options={})
    assert not called and res.state.cage_speed > 0.0
    assert res.raw.converged
