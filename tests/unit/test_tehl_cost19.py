"""Cost of the thermal-EHL film in the roller quasi-dynamics (issue 7): table nodes solved.

The thermal solve (seconds per node) is replaced here by a closed-form stand-in (the Moes film
times 0.2) so that the tests count the nodes the table asks for; the stand-in changes the
physics, not which cells the solver visits. Pinned: the temperature origin of a table puts a
fixed inlet temperature on a node (half the corners of a cell), and
:func:`~thermobearing.ehl.coupling.solve_roller_tehl` solves only nodes around its converged
state, reaching the state the plain solve reaches with the same table.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from tehl_stand_in import CheapTable as _CheapTable
from tehl_stand_in import stand_in_film as _stand_in

from thermobearing.ehl import cache, coupling
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import solve

LUB = load_lubricant("OIL_4109")


def test_temperature_origin_puts_the_inlet_temperature_on_a_node():
    kw = {"lubricant": LUB, "load_step": 1.5, "speed_step": 1.25, "srr_step": 0.05}
    plain = _CheapTable("numerical_tehl", 6.0e-3, 2.3e11, **kw)
    anchored = _CheapTable("numerical_tehl", 6.0e-3, 2.3e11, temperature_origin=303.15, **kw)
    a = plain(2.0e5, 40.0, 0.0, 303.15)
    b = anchored(2.0e5, 40.0, 0.0, 303.15)
    # 2 loads x 2 speeds x 1 SRR (0 is a node) x 2 temperatures (300, 305 K) against 1
    assert plain.solves == 8 and anchored.solves == 4
    assert set(anchored.solved_nodes()) == set(anchored.corners(2.0e5, 40.0, 0.0, 303.15))
    assert all(anchored.node_point(i)[3] == pytest.approx(303.15) for i in
               anchored.solved_nodes())
    # both interpolate the same film (the anchored table without the temperature step)
    exact = _stand_in(2.0e5, 6.0e-3, 2.3e11, 40.0, 0.0, 303.15, lubricant=LUB)
    assert b.central_film == pytest.approx(exact.central_film, rel=0.01)
    assert a.central_film == pytest.approx(exact.central_film, rel=0.01)
    with pytest.raises(Exception, match="temperature_origin"):
        cache.FilmTable("numerical_tehl", 6.0e-3, 2.3e11, lubricant=LUB,
                        temperature_origin=math.nan)


def _d1842926(monkeypatch):
    monkeypatch.setattr(coupling, "FilmTable", _CheapTable)
    bearing = load_bearing("D1842926", overrides={"diametral_clearance": 40e-6})
    return bearing, 13218.0 * math.pi / 30.0, 303.15


def _driver_nodes_near_state(fm, res):
    """Every film of the returned state comes from solved nodes, and every solved node is
    within one table step (speed ratio 1.25) of the state's entrainment speeds."""
    assert coupling._result_cells(fm, res)
    fm.admitted = set()  # answer from solved nodes only, count the rest
    try:
        provisional, solves = fm.provisional, fm.solves
        for key in fm.tables:
            inner = math.isclose(key[0], res.extras["radius_inner"])
            q = np.asarray(res.inner_load if inner else res.outer_load)
            ue = np.abs(res.inner_entrainment_speed if inner else res.outer_entrainment_speed)
            v = np.asarray(res.inner_sliding_speed if inner else res.outer_sliding_speed)
            m = q > 0.0
            fm.films(q[m] / res.extras["contact_length"], ue[m], v[m] / ue[m],
                     res.temperature, key[0], key[1])
        assert (fm.provisional, fm.solves) == (provisional, solves)
    finally:
        fm.admitted = None
    for key, tab in fm.tables.items():
        is_inner = math.isclose(key[0], res.extras["radius_inner"])
        ue = np.abs(res.inner_entrainment_speed if is_inner else res.outer_entrainment_speed)
        for idx in tab.solved_nodes():
            u = tab.node_point(idx)[1]
            assert ue.min() / 1.25 <= u <= ue.max() * 1.25


def test_driver_solves_only_nodes_near_the_converged_state(monkeypatch):
    bearing, omega, T = _d1842926(monkeypatch)
    fm = coupling.roller_film_model(bearing, LUB)
    res = coupling.solve_roller_tehl(bearing, LUB, omega, 24e3, 0.0, T, film_model=fm)
    assert res.converged
    assert fm.admitted is None  # restored: later plain queries solve what they need
    assert fm.provisional > 0  # the first pass's iterates did not solve nodes
    _driver_nodes_near_state(fm, res)
    # a second call at the same point (warm, as a transient step): no new node
    solves = fm.solves
    again = coupling.solve_roller_tehl(bearing, LUB, omega, 24e3, 0.0, T, film_model=fm,
                                       guess=res)
    assert fm.solves == solves
    assert again.cage_speed_ratio == pytest.approx(res.cage_speed_ratio, rel=1e-9)


@pytest.mark.slow
def test_driver_reaches_the_plain_solves_state_with_fewer_nodes(monkeypatch):
    bearing, omega, T = _d1842926(monkeypatch)
    plain_fm = coupling.roller_film_model(bearing, LUB)
    plain = solve(bearing, LUB, omega, 24e3, 0.0, T, drag_model="numerical_tehl",
                  film_model=plain_fm)
    fm = coupling.roller_film_model(bearing, LUB)
    res = coupling.solve_roller_tehl(bearing, LUB, omega, 24e3, 0.0, T, film_model=fm)
    assert res.cage_speed_ratio == pytest.approx(plain.cage_speed_ratio, rel=1e-9)
    np.testing.assert_allclose(res.roller_speed, plain.roller_speed, rtol=1e-7)
    # the plain solve filled the table along its cold starts (outer-race entrainment down to
    # ~12 m/s, 171 nodes with the stand-in); the driver around its state only (48)
    assert fm.solves < 0.5 * plain_fm.solves
    _driver_nodes_near_state(fm, res)


def test_driver_rejects_bad_pass_count(monkeypatch):
    bearing, omega, T = _d1842926(monkeypatch)
    with pytest.raises(Exception, match="max_passes"):
        coupling.solve_roller_tehl(bearing, LUB, omega, 24e3, 0.0, T, max_passes=1)


def test_thermal_solve_keeps_its_newton_preconditioner_across_outer_iterations(monkeypatch):
    # the full preconditioner setup once per outer iteration was 64 % of a thermal solve
    # (n = 1024); kept, it is rebuilt only when GMRES slows, and the solution is the same
    from thermobearing.ehl import precond, solver, thermal

    bearing = load_bearing("D1842926")
    rx = bearing.curvature("inner")[0]
    setups = []
    real = precond.TwoLevelPreconditioner.__init__

    def counting(self, *args, **kwargs):
        setups.append(1)
        real(self, *args, **kwargs)

    monkeypatch.setattr(precond.TwoLevelPreconditioner, "__init__", counting)
    args = (4.3e5, rx, bearing.effective_modulus, 44.4, 0.0, LUB, 303.15)
    solid = coupling.roller_film_model(bearing, LUB).solids[0]
    kept = thermal.solve_thermal_line_contact(*args, solid1=solid, eyring_stress=5e6)
    n_kept = len(setups)
    setups.clear()
    newton = solver.newton_solve
    monkeypatch.setattr(thermal, "newton_solve",
                        lambda *a, preconditioner_memo=None, **k: newton(*a, **k))
    fresh = thermal.solve_thermal_line_contact(*args, solid1=solid, eyring_stress=5e6)
    assert len(setups) >= fresh.outer_iterations  # one (or more) per outer iteration
    assert n_kept <= 0.6 * len(setups)  # 14 against 38 here; 3 against 50 at n = 1024
    assert kept.central_film == pytest.approx(fresh.central_film, rel=1e-6)
    assert kept.minimum_film == pytest.approx(fresh.minimum_film, rel=1e-6)
    assert kept.rolling_force == pytest.approx(fresh.rolling_force, rel=1e-5)
    assert kept.max_temperature == pytest.approx(fresh.max_temperature, abs=1e-3)


def test_failed_corner_with_small_weight_does_not_discard_the_solved_ones():
    # the SRR = 0.05 node of D1842926's heaviest inner contacts at 55 m/s does not converge
    # (the film runs away); a rolling contact (SRR 5e-6) put weight 1e-4 on it and fell
    # back to the isothermal closed-form film
    def sliding_fails(w, rx, ep, u, s, T, *, lubricant, **kw):
        if s > 0.04:
            raise coupling.ConvergenceError("ehl.thermal", 200.0, "film temperature ran away")
        return _stand_in(w, rx, ep, u, s, T, lubricant=lubricant, **kw)

    table = _CheapTable("numerical_tehl", 6.0e-3, 2.3e11, lubricant=LUB, srr_step=0.05,
                        temperature_origin=303.15)
    table.solver = sliding_fails
    rolling = table(2.0e5, 40.0, 0.0, 303.15)
    near = table(2.0e5, 40.0, 5.0e-6, 303.15)
    assert table.partial_answers == 1
    assert near.central_film == pytest.approx(rolling.central_film, rel=1e-12)
    with pytest.raises(coupling.ConvergenceError):
        table(2.0e5, 40.0, 0.03, 303.15)  # weight 0.6 on the failed corners
    with pytest.raises(Exception, match="max_failed_weight"):
        cache.FilmTable("numerical_tehl", 6.0e-3, 2.3e11, lubricant=LUB, max_failed_weight=1.0)
