"""Isothermal line-contact EHL: convergence, formulas, errors, traction."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.ehl.line import (
    moes_dimensionless,
    solve_dimensionless,
    solve_line_contact,
)
from thermobearing.errors import ConvergenceError, InputError


def _hc(M, L, n):
    return solve_dimensionless(M, L, n=n, max_grid_error=1.0).central_film_moes


def test_grid_convergence_second_order_and_n512_within_1_percent():
    # M = 10, L = 5: central film on n = 256, 512, 1024 nodes; the discretisation is second
    # order (conservative central Poiseuille term, second-order upwind wedge). Measured:
    # 3.79504, 3.81233, 3.81662 (order 2.01; with n = 2048 as well the next pair gives 2.01).
    hs = [_hc(10.0, 5.0, n) for n in (256, 512, 1024)]
    d1, d2 = hs[1] - hs[0], hs[2] - hs[1]
    order = math.log2(abs(d1 / d2))
    extrap = hs[2] + d2 / 3.0
    err512 = abs(hs[1] - extrap) / extrap
    print(f"\nM=10 L=5 h_c: {hs}, observed order {order:.2f}, N=512 error {err512:.3%}")
    assert 1.6 < order < 2.6
    assert err512 < 0.01


@pytest.mark.slow
def test_grid_convergence_heavier_loads_reported():
    # Honest record: at M = 100 the inlet zone is thin and the error constant large; the
    # N = 512 central film is about 2 % (M=100, L=10, domain [-2.5, 1.5]) from the
    # extrapolated value, i.e. the 1 % target is met there only from N = 1024 on.
    rows = []
    for M, L in ((10.0, 10.0), (100.0, 5.0), (100.0, 10.0)):
        hs = [_hc(M, L, n) for n in (512, 1024, 2048)]
        d1, d2 = hs[1] - hs[0], hs[2] - hs[1]
        extrap = hs[2] + d2 / 3.0
        rows.append((M, L, math.log2(abs(d1 / d2)), abs(hs[0] - extrap) / extrap,
                     abs(hs[1] - extrap) / extrap))
    print("\n  M     L   order  err(N=512)  err(N=1024)")
    for r in rows:
        print(f"{r[0]:5g} {r[1]:5g} {r[2]:6.2f} {r[3]:10.3%} {r[4]:10.3%}")
    for r in rows:
        assert 1.5 < r[2] < 2.7
        assert r[4] < 0.01


def test_central_film_close_to_moes_formula_m10():
    # Moes (1992) line-contact formula (B's film.moes_line_central): measured +4 % at M=10, L=5
    h = solve_dimensionless(10.0, 5.0, n=1024).central_film_extrapolated * 8 * 10 / math.pi
    assert h == pytest.approx(moes_dimensionless(10.0, 5.0), rel=0.10)


def test_out_of_range_and_coarse_grid_errors_name_m_l_and_pointer():
    with pytest.raises(InputError, match="thermobearing.film"):
        solve_dimensionless(1e5, 10.0)
    with pytest.raises(InputError):
        solve_dimensionless(10.0, 5.0, n=32)
    with pytest.raises(ConvergenceError, match=r"grid too coarse.*M=10.*thermobearing\.film"):
        solve_dimensionless(10.0, 2.0, n=256, max_grid_error=1e-6)


def test_dimensional_front_end_and_traction_split():
    # steel roller pair, 1e5 N/m, R = 10 mm, 5 m/s, eta0 = 0.05 Pa s, alpha = 2e-8 1/Pa
    sol = solve_line_contact(1e5, 0.01, 2.2e11, 5.0, 0.05, alpha=2e-8, n=512)
    assert 1 < sol.M < 3000
    assert sol.minimum_film < sol.central_film
    assert sol.max_pressure > 0.9 * sol.hertz_pressure
    # load balance: integral of the pressure = load per length
    assert np.trapezoid(sol.pressure, sol.x) == pytest.approx(1e5, rel=2e-3)
    t0 = sol.traction(0.0)
    t1 = sol.traction(0.01)
    t2 = sol.traction(0.02)
    assert t0.couette == 0.0
    assert t1.couette < 0.0 < t1.total - t1.couette + abs(t1.couette) * 10  # sign: u2 - u1 < 0
    assert t2.couette == pytest.approx(2 * t1.couette, rel=1e-12)  # Newtonian: linear in SRR
    assert t1.poiseuille == t2.poiseuille
    capped = sol.traction(0.02, limiting_shear_coefficient=0.05)
    assert abs(capped.couette) < abs(t2.couette)


@pytest.mark.slow
def test_light_load_reproduces_martin_rigid_isoviscous_film():
    # Martin (1916) rigid cylinder, isoviscous, Reynolds outlet condition:
    # w' = 4.8966 eta0 u_m R / h0 (Hamrock et al. 2004 ch. 8), i.e. H = 2.448/M in Moes' scaling
    M = 0.1
    sol = solve_dimensionless(M, 0.0, n=2048)
    assert sol.central_film_moes * M == pytest.approx(2.448, rel=0.005)


@pytest.mark.slow
def test_numerical_roller_drag_forces():
    from thermobearing.ehl.drag import NumericalRollerDrag

    class Newtonian:  # ambient-viscosity Newtonian shear: tau = eta0 |V| / h
        def shear_stress(self, s, p, h, T):
            return 0.05 * s / h, 0.05 / h

    drag = NumericalRollerDrag(n=512)
    load = np.array([0.0, 2000.0, 2000.0])
    u_race = np.array([5.0, 5.1, 4.9])
    u_roll = np.array([5.0, 4.9, 5.1])
    f = drag(load, 0.01, 0.01, 2.2e11, u_race, u_roll, eta0=0.05, alpha=2e-8,
             traction_law=Newtonian(), temperature=313.15)
    assert f.traction[0] == 0.0 and f.film_thickness[0] == np.inf
    assert f.traction[1] > 0.0 and f.traction[2] == pytest.approx(-f.traction[1], rel=1e-12)
    assert np.all(f.poiseuille[1:] > 0.0) and np.all(f.rolling_force[1:] > 0.0)
    assert 1e-8 < f.film_thickness[1] < 1e-5
    # linear in V for a Newtonian law; derivative consistent
    assert f.dtraction_dslide[1] == pytest.approx(f.traction[1] / 0.2, rel=1e-9)


def test_numerical_roller_drag_rigid_rescaling_matches_martin():
    # a contact below the solver's M range is rescaled from Martin's self-similar solution:
    # its central film must follow h_c = 4.8966 eta0 u R / w' (Hamrock et al. 2004 ch. 8)
    from thermobearing.ehl.drag import NumericalRollerDrag

    class Newtonian:
        def shear_stress(self, s, p, h, T):
            return 0.08 * s / h, 0.08 / h

    drag = NumericalRollerDrag(n=512)
    q = np.array([1e-6, 1e-3])  # N over 10 mm: far below M = 0.002
    f = drag(q, 0.01, 0.01, 2.2e11, np.array([10.0, 10.0]), np.array([10.0, 10.0]),
             eta0=0.08, alpha=2e-8, traction_law=Newtonian(), temperature=313.15)
    martin = 4.8966 * 0.08 * 10.0 * 0.01 / (q / 0.01)
    assert np.allclose(f.film_thickness, martin, rtol=0.01)
    assert np.all(f.poiseuille > 0)


def test_default_start_retried_when_a_later_level_fails():
    """M = 39, L = 1.3 (a loaded roller of paper 000 with the numerical drag): the 64-node
    default start converges but the 256-node level cannot follow its spike; the solver starts
    again on 128 nodes and gives the film of an explicit 128-node start."""
    from thermobearing.ehl.line import nodes_for, start_grid

    M, L = 39.0126, 1.29731
    n = nodes_for(M, 512, L)
    assert start_grid(M) == 64
    with pytest.raises(ConvergenceError):
        solve_dimensionless(M, L, n=n, coarse_n=64)
    default = solve_dimensionless(M, L, n=n)
    explicit = solve_dimensionless(M, L, n=n, coarse_n=128)
    assert default.central_film == pytest.approx(explicit.central_film, rel=1e-9)
    assert default.minimum_film == pytest.approx(explicit.minimum_film, rel=1e-9)


def test_numerical_drag_refines_the_grid_when_the_error_estimate_is_too_large(monkeypatch):
    """The drag model doubles the nodes while the line solver reports its central-film error
    estimate above 5 % (GridResolutionError), up to MAX_NODES, then lets the error through."""
    import thermobearing.ehl.line as line
    from thermobearing.ehl import drag
    from thermobearing.ehl.line import GridResolutionError

    seen = []

    def fake(w, radius, e_prime, u, eta0, *, alpha, n):
        seen.append(n)
        if n < 2048:
            raise GridResolutionError("ehl.line", 0.053, "grid too coarse")
        return ("solution", n)

    monkeypatch.setattr(line, "solve_line_contact", fake)
    assert drag._solve_refined(1e5, 0.01, 2.3e11, 10.0, 0.08, 2e-8, 512) == ("solution", 2048)
    assert seen == [512, 1024, 2048]
    seen.clear()
    monkeypatch.setattr(drag, "MAX_NODES", 1024)
    with pytest.raises(GridResolutionError):
        drag._solve_refined(1e5, 0.01, 2.3e11, 10.0, 0.08, 2e-8, 512)
    assert seen == [512, 1024]
    assert issubclass(GridResolutionError, ConvergenceError)


def test_spike_smoothing_same_solution_fewer_newton_iterations(monkeypatch):
    # BM-6's slow case (M = 10, L = 20): the start interpolated from the coarser grid is far
    # off only at the exit spike; a few local Newton steps there (solver.smooth_spike) save
    # global iterations and change nothing in the converged solution (measured at n = 1024:
    # 39 -> 27 global iterations, films equal to 1e-7)
    from thermobearing.ehl import line

    with_smoothing = solve_dimensionless(10.0, 20.0, n=1024, max_grid_error=math.inf)
    monkeypatch.setattr(line, "SMOOTH_SPIKE", False)
    without = solve_dimensionless(10.0, 20.0, n=1024, max_grid_error=math.inf)
    assert with_smoothing.report.local_iterations > 0
    assert without.report.local_iterations == 0
    assert with_smoothing.report.iterations < without.report.iterations
    assert with_smoothing.central_film == pytest.approx(without.central_film, rel=1e-6)
    assert with_smoothing.minimum_film == pytest.approx(without.minimum_film, rel=1e-6)
    assert with_smoothing.max_pressure == pytest.approx(without.max_pressure, rel=1e-5)
