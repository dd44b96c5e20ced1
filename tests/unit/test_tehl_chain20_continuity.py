"""The thermal-EHL film of the roller quasi-dynamics is continuous in the contact state while
:func:`~thermobearing.ehl.coupling.solve_roller_tehl` solves on a partly filled table (issue 7,
integrated chain).

Measured before the fix (D1842926, OIL_4109 at 30 degC, 13218 r/min, one film table shared
by 24 kN and then 8 kN, as the validation case paper001_tehl_film does): the 8 kN solve failed
(ConvergenceError, residual 3e-4 with the thermal solve, 3.3e-4 with the graded stand-in
below; both fallback states refused with energy gaps 0.025-0.028). The outer race's most
loaded cell had its SRR 0 and +0.05 nodes solved (from 24 kN) but not -0.05: a contact whose
cell had an unadmitted unsolved corner got the closed form times the table's mean reduction,
the others the table's film, and the film jumped by 22 % where the slide-to-roll ratio
crossed 0, at the root. Now the unsolved nodes take stand-in values in the same
interpolation. The thermal solve is replaced by closed-form stand-ins
(tests/unit/tehl_stand_in.py) whose reduction varies over the table as the thermal one does.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from tehl_stand_in import GradedTable

from thermobearing.ehl import coupling
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller_model import build_model

LUB = load_lubricant("OIL_4109")
T_IN = 303.15
OMEGA = 13218.0 * math.pi / 30.0


@pytest.fixture
def graded(monkeypatch):
    monkeypatch.setattr(coupling, "FilmTable", GradedTable)
    bearing = load_bearing("D1842926")
    return bearing, coupling.roller_film_model(bearing, LUB)


def test_film_is_continuous_where_a_half_solved_cell_meets_a_solved_one(graded):
    bearing, fm = graded
    radius, ep = bearing.curvature("outer")[0], bearing.effective_modulus
    w, u = np.array([2.07e5]), np.array([53.3])
    fm.films(w, u, np.array([1e-4]), T_IN, radius, ep)  # solves the SRR 0 and +0.05 nodes
    tab = fm.tables[(radius, ep)]
    assert all(tab.node_point(i)[2] >= 0.0 for i in tab.solved_nodes())
    table_film = fm.films(w, u, np.array([1e-9]), T_IN, radius, ep).central_film[0]
    solves = fm.solves
    fm.admitted = set()  # a driver pass that admits none of them
    try:
        side = [fm.films(w, u, np.array([s]), T_IN, radius, ep) for s in (-1e-9, 1e-9)]
    finally:
        fm.admitted = None
    assert fm.solves == solves  # the SRR -0.05 nodes were not solved
    # the solved side is the table's, the other side joins it (it jumped by about the ratio
    # of the cell's reduction to the table's mean reduction before)
    assert side[1].central_film[0] == table_film
    assert side[0].central_film[0] == pytest.approx(table_film, rel=1e-6)
    assert side[0].rolling_traction[0] == pytest.approx(side[1].rolling_traction[0], rel=1e-6)
    assert fm.provisional >= 1


def test_rolling_force_is_continuous_where_the_sliding_blend_starts(graded):
    # the table's rolling traction switched to the closed form's at |SRR| = max_slide_to_roll
    bearing, fm = graded
    model = build_model(bearing, LUB, T_IN, film_model=fm, drag_model="numerical_tehl")
    u_e, q = 53.3, np.array([2000.0, 2000.0])
    forces = []
    for srr in (0.05 - 1e-9, 0.05 + 1e-9):
        slide = srr * u_e
        f = model.contact_forces(q, model.length, model.radius_inner, model.effective_modulus,
                                 np.full(2, u_e + 0.5 * slide), np.full(2, u_e - 0.5 * slide),
                                 eta0=model.eta0, alpha=model.alpha, film=model.film_inner,
                                 traction_law=model.traction_law, temperature=T_IN)
        forces.append(f)
    assert forces[0].poiseuille[0] == pytest.approx(forces[1].poiseuille[0], rel=1e-6)
    assert forces[0].rolling_force[0] == pytest.approx(forces[1].rolling_force[0], rel=1e-6)
    assert forces[0].poiseuille[0] == pytest.approx(220.0 * model.length, rel=1e-3)


def test_table_shared_with_24kN_gives_the_8kN_state(graded):
    bearing, fm = graded
    heavy = coupling.solve_roller_tehl(bearing, LUB, OMEGA, 24e3, 0.0, T_IN, film_model=fm)
    res = coupling.solve_roller_tehl(bearing, LUB, OMEGA, 8e3, 0.0, T_IN, film_model=fm)
    assert heavy.converged and res.converged
    assert res.shaft_torque * OMEGA == pytest.approx(res.power_loss["total"], rel=1e-6)
    # every film of the returned state is the table's (no stand-in node, no new solve)
    solves, provisional = fm.solves, fm.provisional
    fm.admitted = set()
    try:
        for race in ("inner", "outer"):
            q = np.asarray(getattr(res, f"{race}_load"))
            ue = np.abs(getattr(res, f"{race}_entrainment_speed"))
            v = np.asarray(getattr(res, f"{race}_sliding_speed"))
            m = q > 0.0
            fm.films(q[m] / res.extras["contact_length"], ue[m], v[m] / ue[m], T_IN,
                     res.extras[f"radius_{race}"], bearing.effective_modulus)
    finally:
        fm.admitted = None
    assert (fm.solves, fm.provisional) == (solves, provisional)
    # (the state is not always the one a table of its own reaches: the roller at the edge of
    # the load zone has two balanced states here, SRR 0.03 on the thermal film and 0.14 on
    # the closed-form film beyond the sliding blend; the cage slip differs by 0.6 %)
