"""The compiled (numba) ball skidding residual and Newton pieces against independent references.

- the Hertz / film fast paths compiled into the residual (hertz._hamrock_brewe_point_nb,
  hertz._ellipse_nb, film._hd1977_central_nb) against the public numpy functions;
- the fused residual (one compiled call) against the staged path (compiled geometry, film and
  viscosity in Python, compiled forces) and against a Python film callable;
- the compiled block-elimination step against a dense solve of the assembled Jacobian;
- warm starts with and without the Broyden updates converge to the same state;
- the numba cache guard flushes when a dependency's source changes.
"""

from __future__ import annotations

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from tests.unit.skidding.helpers import qj_like, simple_models
from thermobearing.contact_traction import refresh_stale_caches
from thermobearing.errors import ValidityWarning
from thermobearing.film import _hd1977_central_nb, hamrock_dowson_1977_central
from thermobearing.hertz import _ellipse_nb, _hamrock_brewe_point_nb, point_contact
from thermobearing.skidding.ball import ball_residual_system, race_control_guess, solve_ball
from thermobearing.skidding.ball_models import GuardedFilm
from thermobearing.skidding.ball_newton import _CAP_G, _CAP_X, _block_step, _factor_blocks

W1800 = 1800 * math.pi / 30


@pytest.fixture(scope="module")
def bearing():
    return qj_like()


@pytest.fixture(scope="module")
def default_models(bearing):
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.ball_models import default_ball_models
    from thermobearing.state import OilSupply

    return default_ball_models(bearing, load_lubricant("ISO_VG46"), temperature=330.0,
                               speed=W1800, supply=OilSupply("jet", 33 / 60000, 313.15))


def test_compiled_hertz_equals_public_hamrock_brewe():
    # hertz.point_contact(method="hamrock_brewe") is the validated public function
    E = 2.26e11
    for rx, ry, w in ((0.0125, 0.29, 800.0), (0.02, 0.02, 50.0), (0.3, 0.015, 9000.0)):
        r, k, big_e, K = _hamrock_brewe_point_nb(rx, ry, E)
        a, b, p = _ellipse_nb(w, r, k, big_e, E)
        pc = point_contact(w, rx, ry, E, method="hamrock_brewe")
        assert a == pytest.approx(float(pc.a), rel=1e-13)
        assert b == pytest.approx(float(pc.b), rel=1e-13)
        assert p == pytest.approx(float(pc.max_pressure), rel=1e-13)
        # Q = K delta^1.5 at the Hertz approach
        assert K * float(pc.approach) ** 1.5 == pytest.approx(w, rel=1e-9)
    assert _ellipse_nb(0.0, 0.01, 5.0, 1.1, E)[2] == 0.0


def test_compiled_film_equals_public_hamrock_dowson():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        for u, eta, alpha, q, rx, ry in ((3.0, 0.02, 2e-8, 800.0, 0.015, 0.3),
                                         (0.1, 0.3, 1.5e-8, 40.0, 0.02, 0.25)):
            ref = float(hamrock_dowson_1977_central(u, eta, alpha, q, rx, ry,
                                                    effective_modulus=2.26e11))
            assert _hd1977_central_nb(u, eta, alpha, q, rx, ry, 2.26e11) == pytest.approx(
                ref, rel=1e-13)
    assert _hd1977_central_nb(0.0, 0.02, 2e-8, 800.0, 0.015, 0.3, 2.26e11) == 0.0
    assert math.isinf(_hd1977_central_nb(1.0, 0.02, 2e-8, 0.0, 0.015, 0.3, 2.26e11))


def test_guarded_film_rejects_a_zero_floor():
    from thermobearing.errors import InputError

    with pytest.raises(InputError):
        GuardedFilm(0.02, 2e-8, 2.26e11, thickness_floor=0.0)


def _evaluate_both(system, X, G):
    """(fused, staged) residuals and details of one state."""
    assert system._fused
    R1, Gc1, G01, d1 = system.evaluate(X, G, details=True)
    system._fused = False
    system._last = None
    try:
        R2, Gc2, G02, d2 = system.evaluate(X, G, details=True)
    finally:
        system._fused = True
        system._last = None
    return (R1, Gc1, G01, d1), (R2, Gc2, G02, d2)


def test_fused_equals_staged_path(bearing, default_models):
    system = ball_residual_system(bearing, default_models, W1800, 1000.0, 4e3)
    X, G, _ = race_control_guess(bearing, W1800, 1000.0, 4e3)
    (R1, Gc1, G01, d1), (R2, Gc2, G02, d2) = _evaluate_both(system, X, G)
    np.testing.assert_array_equal(R1, R2)
    np.testing.assert_array_equal(Gc1, Gc2)
    np.testing.assert_array_equal(G01, G02)
    np.testing.assert_array_equal(d1["film"], d2["film"])
    assert d1["shaft_torque"] == d2["shaft_torque"]
    assert np.any(d1["cf"].load > 0)


def test_python_film_callable_equals_compiled_film(bearing):
    # the test models' film is a Python closure around the public Hamrock-Dowson function,
    # and their law takes eta(T, p) from the lubricant per node (staged path); the same
    # physics with the compiled GuardedFilm must give the same residual
    models = simple_models(bearing)
    lub = models.traction_law.lubricant
    T = models.temperature
    compiled = GuardedFilm(float(lub.dynamic_viscosity(T)),
                           float(lub.pressure_viscosity_coefficient(T)),
                           bearing.effective_modulus)
    from dataclasses import replace

    models_c = replace(models, film_thickness=compiled)
    X, G, _ = race_control_guess(bearing, W1800, 1000.0, 4e3)
    s_py = ball_residual_system(bearing, models, W1800, 1000.0, 4e3)
    s_c = ball_residual_system(bearing, models_c, W1800, 1000.0, 4e3)
    assert not s_py._fused and not s_c._fused     # per-node viscosity: staged
    Rp, Gcp, _, dp = s_py.evaluate(X, G, details=True)
    Rc, Gcc, _, dc = s_c.evaluate(X, G, details=True)
    np.testing.assert_allclose(dc["film"], dp["film"], rtol=1e-13)
    np.testing.assert_allclose(Rc, Rp, rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(Gcc, Gcp, rtol=1e-11, atol=1e-12)


def test_block_step_equals_dense_solve():
    rng = np.random.default_rng(7)
    Z, nb, ng = 5, 6, 3
    A = rng.normal(size=(Z, nb, nb)) + 4 * np.eye(nb)
    B = rng.normal(size=(Z, nb, ng))
    C = rng.normal(size=(Z, ng, nb))
    Dg = rng.normal(size=(ng, ng)) + 6 * np.eye(ng)
    R = rng.normal(size=(Z, nb))
    g = rng.normal(size=ng)
    # dense Jacobian of (ball residuals, global residuals) in (ball unknowns, globals)
    n = Z * nb + ng
    J = np.zeros((n, n))
    for z in range(Z):
        J[z * nb:(z + 1) * nb, z * nb:(z + 1) * nb] = A[z]
        J[z * nb:(z + 1) * nb, Z * nb:] = B[z]
        J[Z * nb:, z * nb:(z + 1) * nb] = C[z]
    J[Z * nb:, Z * nb:] = Dg
    ref = np.linalg.solve(J, -np.concatenate([R.ravel(), g]))
    Ainv = np.linalg.inv(A)
    Ainv_B = Ainv @ B
    S = Dg - np.einsum("zgi,zij->gj", C, Ainv_B)
    dX, dG, big = _block_step(Ainv, Ainv_B, C, np.linalg.inv(S), R, g, _CAP_X, _CAP_G)
    np.testing.assert_allclose(np.concatenate([dX.ravel(), dG]), ref, rtol=1e-10, atol=1e-12)
    assert big == pytest.approx(max(np.max(np.abs(dX) / _CAP_X), np.max(np.abs(dG) / _CAP_G)))


def test_warm_start_broyden_converges_to_the_same_state(bearing, default_models):
    from thermobearing.skidding import ball_newton

    r0 = solve_ball(bearing, default_models, W1800, 1000.0, 6e3, theoretical_reference=0.45)
    out = {}
    for flag in (True, False):
        original = ball_newton.newton_block

        # the finite-difference Jacobian (analytic=False): the setting the Broyden updates were
        # introduced for; with the analytic one a refresh is cheap (test_ball_jacobian.py)
        def patched(*a, _flag=flag, _orig=original, **k):
            return _orig(*a, broyden_warm=_flag, **{**k, "analytic": False})

        from thermobearing.skidding import ball as ball_mod

        ball_mod.newton_block = patched
        try:
            out[flag] = solve_ball(bearing, default_models, W1800, 1000.0, 6.14e3, guess=r0,
                                   theoretical_reference=0.45)
        finally:
            ball_mod.newton_block = original
    a, b = out[True], out[False]
    assert a.converged and b.converged
    assert a.cage_speed_ratio == pytest.approx(b.cage_speed_ratio, rel=1e-9)
    assert a.shaft_torque == pytest.approx(b.shaft_torque, rel=1e-7)
    # energy identity of the Broyden solution: shaft power = total heat
    assert a.shaft_torque * W1800 == pytest.approx(a.heat["total"], rel=1e-8)
    assert a.extra["n_eval"] <= b.extra["n_eval"]


def test_reloaded_system_equals_a_new_one(bearing, default_models):
    s1 = ball_residual_system(bearing, default_models, W1800, 1000.0, 4e3)
    s2 = s1.reloaded(500.0, 12e3)
    s3 = ball_residual_system(bearing, default_models, W1800, 500.0, 12e3)
    X, G, _ = race_control_guess(bearing, W1800, 500.0, 12e3)
    for a, b in zip(s2.evaluate(X, G)[:3], s3.evaluate(X, G)[:3], strict=True):
        np.testing.assert_array_equal(a, b)
    assert s1.Fa == 4e3 and s1.F_s != s2.F_s      # the original is untouched


def test_cache_guard_flushes_on_a_dependency_change(tmp_path):
    flushed = []
    cache = SimpleNamespace(cache_path=str(tmp_path), flush=lambda: flushed.append(1))
    disp = SimpleNamespace(_cache=cache)
    dep_file = tmp_path / "dep.py"
    dep_file.write_text("x = 1\n")
    dep = SimpleNamespace(__file__=str(dep_file))
    assert refresh_stale_caches("t", (disp,), (dep,)) is True      # no stamp yet
    assert refresh_stale_caches("t", (disp,), (dep,)) is False     # unchanged
    dep_file.write_text("x = 2\n")
    assert refresh_stale_caches("t", (disp,), (dep,)) is True      # dependency edited
    assert len(flushed) == 2
    # caching disabled (no cache object): nothing to do
    assert refresh_stale_caches("t", (SimpleNamespace(_cache=None),), (dep,)) is False


def test_jacobian_batch_reuses_the_pocket_force_column_exactly(bearing, default_models):
    # the Q_p-perturbed state of the Jacobian batch has the contacts of the current state:
    # its tractions are copied from that evaluation; the residuals must be bit-identical
    X, G, _ = race_control_guess(bearing, W1800, 1000.0, 4e3)
    Xb = np.repeat(X[None], 3, axis=0)
    Xb[1, :, 5] += 1e-3                    # pocket-force column
    Xb[2, :, 2] += 1e-3                    # a spin column (contacts change)
    Gb = np.repeat(G[None], 3, axis=0)
    s1 = ball_residual_system(bearing, default_models, W1800, 1000.0, 4e3)
    s1.evaluate(X, G)
    assert list(s1._reuse_flags(Xb, Gb)[0]) == [1, 1, 0]
    s2 = ball_residual_system(bearing, default_models, W1800, 1000.0, 4e3)   # nothing to reuse
    for a, b in zip(s1.evaluate(Xb, Gb)[:3], s2.evaluate(Xb, Gb)[:3], strict=True):
        np.testing.assert_array_equal(a, b)


def test_cache_guard_survives_an_unwritable_cache(tmp_path):
    def flush():
        raise PermissionError("read-only")

    disp = SimpleNamespace(_cache=SimpleNamespace(cache_path=str(tmp_path / "ro"), flush=flush))
    dep_file = tmp_path / "dep.py"
    dep_file.write_text("x = 1\n")
    assert refresh_stale_caches("t", (disp,), (SimpleNamespace(__file__=str(dep_file)),)) is False


def test_compiled_block_factors_equal_numpy_inverse_and_schur():
    # _factor_blocks (Gauss-Jordan with partial pivoting) against numpy's LAPACK inverse and
    # the Schur complement S = D - sum_z C_z A_z^-1 B_z written with einsum
    rng = np.random.default_rng(7)
    Z = 5
    A = rng.normal(size=(Z, 6, 6)) + 4.0 * np.eye(6)
    A[2, [0, 3]] = A[2, [3, 0]]             # a block that needs row pivoting
    A[2, 0, 0] = 0.0
    B = rng.normal(size=(Z, 6, 3))
    C = rng.normal(size=(Z, 3, 6))
    Dg = rng.normal(size=(3, 3))
    Ainv, AiB, S, ok = _factor_blocks(A, B, C, Dg)
    assert ok
    np.testing.assert_allclose(Ainv, np.linalg.inv(A), rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(AiB, np.linalg.inv(A) @ B, rtol=1e-12, atol=1e-13)
    S_ref = Dg - np.einsum("zgi,zij->gj", C, np.linalg.inv(A) @ B)
    np.testing.assert_allclose(S, S_ref, rtol=1e-12, atol=1e-13)
    A[3, :, 4] = 0.0                        # singular ball block: reported, not inverted
    assert not _factor_blocks(A, B, C, Dg)[3]


def test_compiled_propose_equals_block_step_and_broyden_step():
    # _propose (one compiled call per Newton iteration) against its pieces: the global sum,
    # _block_step, _broyden_step and the full-step state
    from thermobearing.skidding.ball_newton import _broyden_step, _propose

    rng = np.random.default_rng(3)
    Z = 4
    Ainv = rng.normal(size=(Z, 6, 6))
    AiB = rng.normal(size=(Z, 6, 3))
    C = rng.normal(size=(Z, 3, 6))
    Sinv = rng.normal(size=(3, 3))
    R, Gc, Gk = rng.normal(size=(Z, 6)), rng.normal(size=(Z, 3)), rng.normal(size=3)
    X, G = rng.normal(size=(Z, 6)), rng.normal(size=3)
    xs, gs = np.abs(rng.normal(size=6)), np.abs(rng.normal(size=3))
    hist = rng.normal(size=(3, Z * 6 + 3))
    dX0, dG0, big0 = _block_step(Ainv, AiB, C, Sinv, R, Gc.sum(0) + Gk, _CAP_X, _CAP_G)
    for m in (0, 2):
        dX, dG, big, Xn, Gn, degenerate = _propose(Ainv, AiB, C, Sinv, R, Gc, Gk, _CAP_X,
                                                   _CAP_G, hist, m, xs, gs, X, G)
        ref = (dX0, dG0, big0) if m == 0 else _broyden_step(hist, m, dX0, dG0, _CAP_X, _CAP_G)
        assert not degenerate and ref[2] >= 0
        np.testing.assert_allclose(dX, ref[0], rtol=1e-13, atol=1e-14)
        np.testing.assert_allclose(dG, ref[1], rtol=1e-13, atol=1e-14)
        assert big == pytest.approx(ref[2], rel=1e-13)
        np.testing.assert_allclose(Xn, X + ref[0] * xs, rtol=1e-14, atol=1e-15)
        np.testing.assert_allclose(Gn, G + ref[1] * gs, rtol=1e-14, atol=1e-15)


def test_compiled_fd_blocks_equal_the_numpy_formulas():
    # _fd_blocks against the numpy expressions it replaced (moveaxis of the differences)
    from thermobearing.skidding.ball_newton import _fd_blocks

    rng = np.random.default_rng(5)
    Z, h = 4, 1e-6
    R, Gc, Gk = rng.normal(size=(Z, 6)), rng.normal(size=(Z, 3)), rng.normal(size=3)
    Rb = R + h * rng.normal(size=(9, Z, 6))
    Gcb = Gc + h * rng.normal(size=(9, Z, 3))
    Gkb = Gk + h * rng.normal(size=(9, 3))
    A, B, C, Dg = _fd_blocks(Rb, Gcb, Gkb, R, Gc, Gk, h)
    dR = (Rb - R) / h
    np.testing.assert_allclose(A, np.moveaxis(dR[:6], 0, -1), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(B, np.moveaxis(dR[6:], 0, -1), rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(C, np.moveaxis((Gcb[:6] - Gc) / h, 0, -1), rtol=1e-12,
                               atol=1e-9)
    Dg_ref = (((Gcb[6:].sum(1) + Gkb[6:]) - (Gc.sum(0) + Gk)) / h).T
    np.testing.assert_allclose(Dg, Dg_ref, rtol=1e-8, atol=1e-8)


def test_vectorised_hertz_and_film_equal_the_scalar_kernels():
    # the residual's Hertz constants, ellipse and film run in vectorised loops
    # with branch-free log / exp (ball_residual._hb_point, _ellipse_vec, _hd1977_central_vec);
    # they must equal the scalar kernels of hertz / film (libm powers and cube roots) to
    # round-off: measured <= 1.1e-15 relative (Hertz) and 6.7e-15 (film) over these ranges
    # (R_x 2-20 mm, R_y 0.05-1 m,
    # loads 1e-3 N - 50 kN, entrainment 1e-3 - 50 m/s)
    import numba

    from thermobearing.skidding.ball_residual import (
        _ellipse_vec,
        _hb_point,
        _hd1977_central_vec,
    )

    @numba.njit(error_model="numpy")
    def vec(rx, ry, q, u, out):
        for i in range(rx.size):
            r, k, e, K = _hb_point(rx[i], ry[i], 2.26e11)
            a, b, p = _ellipse_vec(q[i], r, k, e, 2.26e11)
            out[i, 0], out[i, 1], out[i, 2], out[i, 3] = K, a, b, p
            out[i, 4] = _hd1977_central_vec(u[i], 0.02, 2e-8, q[i], rx[i], ry[i], 2.26e11)

    @numba.njit
    def ref(rx, ry, q, u, out):
        for i in range(rx.size):
            r, k, e, K = _hamrock_brewe_point_nb(rx[i], ry[i], 2.26e11)
            a, b, p = _ellipse_nb(q[i], r, k, e, 2.26e11)
            out[i, 0], out[i, 1], out[i, 2], out[i, 3] = K, a, b, p
            out[i, 4] = _hd1977_central_nb(u[i], 0.02, 2e-8, q[i], rx[i], ry[i], 2.26e11)

    rng = np.random.default_rng(8)
    n = 20000
    rx = rng.uniform(2e-3, 20e-3, n)
    ry = rng.uniform(0.05, 1.0, n)
    q = np.exp(rng.uniform(np.log(1e-3), np.log(5e4), n))
    u = np.exp(rng.uniform(np.log(1e-3), np.log(50.0), n))
    q[:3] = 0.0
    got, want = np.empty((n, 5)), np.empty((n, 5))
    vec(rx, ry, q, u, got)
    ref(rx, ry, q, u, want)
    np.testing.assert_array_equal(got[:3, 1:4], 0.0)        # zero load: no ellipse
    assert np.all(np.isinf(got[:3, 4]))                      # W = 0: infinite film, as libm
    np.testing.assert_allclose(got[3:], want[3:], rtol=1e-14, atol=0.0)
    # u = 0 gives no film, as the scalar kernel
    out = np.empty((1, 5))
    vec(rx[:1], ry[:1], q[3:4], np.zeros(1), out)
    assert out[0, 4] == 0.0
