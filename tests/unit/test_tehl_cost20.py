"""Cost of the thermal EHL solve (issue 7): the column scan and the outer fixed point.

The column scan of the film energy equation (:func:`thermobearing.ehl.thermal._column_scan`)
sweeps alternately downstream and upstream with the column factors computed once per call; the
outer (pressure-temperature) iteration limits its first temperature update to
``MAX_FIRST_TEMPERATURE_STEP`` and solves each scan only to a fraction of the last outer change
(``INNER_TOLERANCE_FRACTION``). Pinned: the scan solves the stated discrete equations (against a
sparse direct solve), the reverse flow of an inlet is carried upstream within one sweep, and the
thermal solve reaches the fixed point of the downstream-only scan to 1e-4 K without the step
limit (the solve before the change).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.sparse import lil_matrix
from scipy.sparse.linalg import spsolve

from thermobearing.ehl import coupling, thermal
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant

LUB = load_lubricant("OIL_4109")
T_IN = 303.15


def _scan_problem(n=60, nc=9, reverse=True, seed=3):
    """Random coefficients of the column scan; a reverse-flow band in the middle of the film
    over the first half of the columns (the inlet) when ``reverse``."""
    rng = np.random.default_rng(seed)
    u = rng.uniform(0.5, 3.0, (n, nc))
    if reverse:
        u[: n // 2, 3: nc - 3] = -rng.uniform(0.5, 3.0, (n // 2, nc - 6))
    adv = rng.uniform(1.0, 2.0, (n, nc))
    g = rng.uniform(0.5, 2.0, (n, nc - 1))
    src = rng.uniform(0.0, 5.0, (n, nc))
    lin = -rng.uniform(0.0, 0.2, (n, nc))
    return u, adv, g, src, lin, 0.7


def _direct(u, adv, g, src, lin, dx, t_in):
    """The discrete energy equations of the scan's docstring, solved directly: per interior
    node ``(g- + g+ + c - lin) T - g- T[k-1] - g+ T[k+1] - c T[upwind] = src`` with
    ``c = adv |u| / dx`` (no inflow through the outlet), Dirichlet column 0 and deep nodes."""
    n, nc = u.shape
    idx = np.arange(n * nc).reshape(n, nc)
    A = lil_matrix((n * nc, n * nc))
    rhs = np.zeros(n * nc)
    for i in range(n):
        for k in range(nc):
            r = idx[i, k]
            if i == 0 or k in (0, nc - 1):
                A[r, r] = 1.0
                rhs[r] = t_in
                continue
            c = adv[i, k] * abs(u[i, k]) / dx
            up = i - 1 if u[i, k] >= 0 else i + 1
            if up >= n:
                c = 0.0
            A[r, r] = g[i, k - 1] + g[i, k] + c - lin[i, k]
            A[r, idx[i, k - 1]] = -g[i, k - 1]
            A[r, idx[i, k + 1]] = -g[i, k]
            if c:
                A[r, idx[up, k]] = -c
            rhs[r] = src[i, k]
    return spsolve(A.tocsr(), rhs).reshape(n, nc)


@pytest.mark.parametrize("reverse", [False, True])
def test_column_scan_solves_the_discrete_energy_equations(reverse):
    u, adv, g, src, lin, dx = _scan_problem(reverse=reverse)
    T = np.full(u.shape, T_IN)
    change = thermal._column_scan(T, u, adv, g, src, lin, dx, T_IN, 500, 1e-12)
    assert change < 1e-12
    np.testing.assert_allclose(T, _direct(u, adv, g, src, lin, dx, T_IN), rtol=0, atol=1e-9)


def test_reverse_flow_is_carried_upstream_within_one_sweep():
    # all interior nodes flow backwards (u < 0): the upstream sweep is an exact march, so a
    # downstream and an upstream sweep solve it (a downstream-only sweep moved the outlet's
    # information one column per sweep: ~n sweeps)
    u, adv, g, src, lin, dx = _scan_problem(n=200, reverse=False)
    u = -u
    T = np.full(u.shape, T_IN)
    thermal._column_scan(T, u, adv, g, src, lin, dx, T_IN, 2, 0.0)
    exact = _direct(u, adv, g, src, lin, dx, T_IN)
    np.testing.assert_allclose(T, exact, rtol=0, atol=1e-9)
    # the first column next to the outlet differs from the inlet temperature: the test is
    # not trivially satisfied by the start values
    assert np.max(np.abs(exact[1] - T_IN)) > 1.0


def _downstream_only(real):
    """The scan before the change: downstream sweeps only (each call of one sweep starts
    downstream), each outer iteration's scan to 1e-4 K."""
    def scan(T, u, adv, g, src, lin, dx, t_in, sweeps, tol):
        change = math.inf
        for _ in range(sweeps):
            change = real(T, u, adv, g, src, lin, dx, t_in, 1, 1e-4)
            if change < 1e-4:
                break
        return change
    return scan


@pytest.fixture(scope="module")
def inner_contact():
    bearing = load_bearing("D1842926")
    solids = coupling.roller_film_model(bearing, LUB).solids
    rx = bearing.curvature("inner")[0]
    # the most loaded inner contact of D1842926 at 24 kN, 13218 r/min, sliding at the edge of
    # the quasi-dynamic table (SRR 0.05), on a small grid
    args = (4.3e5, rx, bearing.effective_modulus, 44.4, 0.05, LUB, T_IN)
    kw = {"solid1": solids[0], "solid2": solids[1], "n": 128, "eyring_stress": 5e6}
    return args, kw


def _plain(monkeypatch, args, kw, **more):
    with monkeypatch.context() as m:
        m.setattr(thermal, "_column_scan", _downstream_only(thermal._column_scan))
        m.setattr(thermal, "MAX_FIRST_TEMPERATURE_STEP", math.inf)
        return thermal.solve_thermal_line_contact(*args, **kw, **more)


def _agree(a, b, rel, kelvin):
    for name in ("central_film", "minimum_film", "max_pressure", "shear_force",
                 "rolling_force"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), rel=rel), name
    assert a.max_temperature == pytest.approx(b.max_temperature, abs=kelvin)
    np.testing.assert_allclose(a.temperature, b.temperature, rtol=0, atol=10 * kelvin)


def test_thermal_solve_reaches_the_fixed_point_of_the_plain_iteration(monkeypatch,
                                                                      inner_contact):
    args, kw = inner_contact
    plain = _plain(monkeypatch, args, kw, tol_temperature=1e-3)
    tight = thermal.solve_thermal_line_contact(*args, **kw, tol_temperature=1e-3)
    # the same fixed point: both solved to 1e-3 K
    _agree(tight, plain, rel=5e-5, kelvin=0.01)
    # the default tolerance (0.03 K): within the stated ~1e-3 of the fixed point
    default = thermal.solve_thermal_line_contact(*args, **kw)
    assert default.temperature_change < 0.03
    _agree(default, plain, rel=2e-3, kelvin=0.1)


def test_temperature_step_limit_keeps_the_fixed_point(monkeypatch, inner_contact):
    args, kw = inner_contact
    ref = thermal.solve_thermal_line_contact(*args, **kw, tol_temperature=1e-3)
    monkeypatch.setattr(thermal, "MAX_FIRST_TEMPERATURE_STEP", 20.0)
    small = thermal.solve_thermal_line_contact(*args, **kw, tol_temperature=1e-3)
    _agree(small, ref, rel=2e-4, kelvin=0.02)
