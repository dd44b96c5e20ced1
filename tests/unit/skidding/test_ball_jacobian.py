"""The analytic Jacobian of the ball skidding residual (skidding/ball_jacobian.py).

References: central finite differences of the compiled residual itself (the same scaled
residual and unknowns; with h = 1e-6 scaled the analytic blocks agree to 2e-7 - 4e-6 of the
largest entry; smaller steps disagree more, 1e-4 at h = 1e-8, where round-off of the radial
force balance -- contact loads of kN against their small sum -- takes over), the traction
law's own fast path
(traction._eyring_smooth_node) and the contact integration's (contact_traction.
_integrate_contacts). Solver-level: Newton with the analytic Jacobian converges to the state
of Newton with the finite-difference one (the same equations), warm starts to cold starts.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.unit.skidding.helpers import qj_like, simple_models
from thermobearing.contact_traction import _integrate_contacts, _rule
from thermobearing.skidding import ball as ball_mod
from thermobearing.skidding import ball_newton
from thermobearing.skidding.ball import solve_ball
from thermobearing.skidding.ball_jacobian import (
    _contact_traction_jac,
    _eyring_smooth_grad,
    analytic_blocks,
    supports_analytic,
)
from thermobearing.skidding.ball_residual import (
    A_RY,
    G_A,
    G_B,
    G_CURV,
    G_OMX,
    G_OMY,
    G_OMZ,
    G_Q,
    G_RX,
    G_UE,
    G_VX,
    G_VY,
    N_BALL,
    N_GEO,
    N_GLOBAL,
    _ball_geometry,
    guarded_film_array,
)
from thermobearing.traction import EYRING, _eyring_smooth_node

W1800 = 1800 * math.pi / 30


@pytest.fixture(scope="module")
def bearing():
    return qj_like()


def _models(bearing, temperature, speed):
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.ball_models import default_ball_models
    from thermobearing.state import OilSupply

    return default_ball_models(bearing, load_lubricant("ISO_VG46"), temperature=temperature,
                               speed=speed, supply=OilSupply("jet", 33 / 60000, 313.15))


def _central_blocks(system, X, G, h=1e-6):
    """Central differences of the scaled residual in the scaled unknowns, block layout of
    ball_newton._fd_blocks (every ball's column c perturbed at once: the balls are coupled
    only through the globals)."""
    xs, gs = system.scales()
    Z = system.Z
    nb = N_BALL + N_GLOBAL
    out = {}
    for sign in (1.0, -1.0):
        Xb = np.empty((nb, Z, N_BALL))
        Xb[:] = X
        Gb = np.empty((nb, N_GLOBAL))
        Gb[:] = G
        for c in range(N_BALL):
            Xb[c, :, c] += sign * h * xs[c]
        for g in range(N_GLOBAL):
            Gb[N_BALL + g, g] += sign * h * gs[g]
        out[sign] = system.evaluate(Xb, Gb)[:3]
    (Rp, Gcp, Gkp), (Rm, Gcm, Gkm) = out[1.0], out[-1.0]
    A = np.transpose((Rp[:N_BALL] - Rm[:N_BALL]) / (2 * h), (1, 2, 0))
    B = np.transpose((Rp[N_BALL:] - Rm[N_BALL:]) / (2 * h), (1, 2, 0))
    C = np.transpose((Gcp[:N_BALL] - Gcm[:N_BALL]) / (2 * h), (1, 2, 0))
    tot_p = Gcp[N_BALL:].sum(axis=1) + Gkp[N_BALL:]
    tot_m = Gcm[N_BALL:].sum(axis=1) + Gkm[N_BALL:]
    Dg = ((tot_p - tot_m) / (2 * h)).T
    return A, B, C, Dg


@pytest.mark.parametrize("temperature, rpm, fa", [(303.15, 1800.0, 10e3), (353.15, 600.0, 2e3),
                                                  (330.0, 3000.0, 0.0)])
def test_analytic_blocks_equal_central_differences(bearing, temperature, rpm, fa):
    w = rpm * math.pi / 30
    models = _models(bearing, temperature, w)
    r = solve_ball(bearing, models, w, 1000.0, fa, theoretical_reference=0.45)
    system = r.extra["system"]
    X, G = r.unknowns
    assert supports_analytic(system)
    J = analytic_blocks(system, X, G)
    ref = _central_blocks(system, X, G)
    for name, fd in zip(("A", "B", "C", "Dg"), ref, strict=True):
        an = getattr(J, name)
        scale = np.abs(fd).max()
        # 2e-5 of the block's largest entry: the finite-difference truncation and round-off
        # (the cage torque models and the R_x dependence of the Hertz constants enter by
        # forward differences in the analytic path too)
        assert np.abs(an - fd).max() <= 2e-5 * scale, name


def test_eyring_gradient_equals_the_law_and_its_differences():
    lam, tau0 = 0.07, 5e6
    for s, p, rate in ((0.3, 1.2e9, 3e9), (1e-5, 8e8, 1e12), (2.0, 2e9, 1e6), (0.0, 1e9, 1e9)):
        tau, ts, tp, tr = _eyring_smooth_grad(lam, tau0, 1.0 / tau0, s, p, rate)
        assert tau == pytest.approx(_eyring_smooth_node(lam, tau0, 1.0 / tau0, s, p, rate, 1.0),
                                    rel=1e-13, abs=1e-300)
        base = (s, p, rate)
        for i in range(3):
            x = base[i]
            hh = 1e-6 * max(abs(x), 1e-3)
            lo = max(x - hh, 0.0)
            args_up = tuple(x + hh if j == i else base[j] for j in range(3))
            args_dn = tuple(lo if j == i else base[j] for j in range(3))
            up = _eyring_smooth_grad(lam, tau0, 1.0 / tau0, *args_up)[0]
            dn = _eyring_smooth_grad(lam, tau0, 1.0 / tau0, *args_dn)[0]
            fd = (up - dn) / (x + hh - lo)
            assert (ts, tp, tr)[i] == pytest.approx(fd, rel=1e-5, abs=1e-12 * abs(tau) + 1e-30)


def test_contact_tractions_of_the_jacobian_pass_equal_the_integration(bearing):
    models = _models(bearing, 330.0, W1800)
    r = solve_ball(bearing, models, W1800, 1000.0, 8e3, theoretical_reference=0.45)
    s = r.extra["system"]
    X, G = r.unknowns
    nk = s._arc.shape[1]
    n = s.Z * nk
    geo = np.empty((N_GEO, n))
    _ball_geometry(X.reshape(1, s.Z, N_BALL).copy(), G.reshape(1, 3).copy(), s._cpsi, s._arc,
                   s._c, geo)
    ry = np.tile(s._arc[A_RY], s.Z)
    film = guarded_film_array(geo[G_UE].copy(), geo[G_Q].copy(), geo[G_RX].copy(), ry,
                              s._film_params)
    ln_tab, slope_tab, inv_dp, _ = s._tab
    rule = _rule("point", 8, 4)
    args = (geo[G_Q], geo[G_A], geo[G_B], geo[G_VY], geo[G_VX], geo[G_OMZ], geo[G_OMX],
            geo[G_OMY], geo[G_CURV], film)
    ref = np.empty((n, 6))
    _integrate_contacts(EYRING, s._law_params, 1, ln_tab, slope_tab, inv_dp, np.empty((0, 0)),
                        *args, *rule, True, False, ref, np.empty((0, 5, 5)), np.empty((0, 5)))
    tr = np.empty((n, 5))
    jac = np.empty((n, 5, 9))
    _contact_traction_jac(s._law_params, ln_tab, slope_tab, inv_dp, *args, *rule, tr, jac)
    np.testing.assert_allclose(tr, ref[:, :5], rtol=1e-11, atol=1e-12 * np.abs(ref).max())
    assert np.all(jac[geo[G_Q] == 0.0] == 0.0)          # unloaded contacts: no traction


def test_models_without_the_compiled_path_fall_back_to_differences(bearing):
    models = simple_models(bearing)            # a Python film callable: no analytic path
    r = solve_ball(bearing, models, W1800, 1000.0, 6e3, theoretical_reference=0.45)
    assert not supports_analytic(r.extra["system"])
    assert analytic_blocks(r.extra["system"], *r.unknowns) is None
    assert r.extra["n_jacobian"] == 0 and r.converged


def test_newton_with_the_analytic_jacobian_reaches_the_same_state(bearing):
    models = _models(bearing, 303.15, W1800)
    out = {}
    for flag in (True, False):
        original = ball_newton.newton_block

        def patched(*a, _flag=flag, _orig=original, **k):
            return _orig(*a, **{**k, "analytic": _flag})

        ball_mod.newton_block = patched
        try:
            out[flag] = solve_ball(bearing, models, W1800, 1000.0, 3e3,
                                   theoretical_reference=0.45)
        finally:
            ball_mod.newton_block = original
    a, b = out[True], out[False]
    assert a.cage_speed_ratio == pytest.approx(b.cage_speed_ratio, rel=1e-9)
    assert a.shaft_torque == pytest.approx(b.shaft_torque, rel=1e-7)
    assert a.shaft_torque * W1800 == pytest.approx(a.heat["total"], rel=1e-8)
    assert a.extra["n_jacobian"] > 0 and b.extra["n_jacobian"] == 0
    # each analytic Jacobian replaces a batch of nine perturbed residuals
    assert a.extra["n_eval"] < b.extra["n_eval"]


@pytest.mark.parametrize("temperature", [303.15, 353.15])
def test_warm_step_with_refresh_converges_to_the_cold_start(bearing, temperature):
    models = _models(bearing, temperature, W1800)
    r0 = solve_ball(bearing, models, W1800, 1000.0, 10e3, theoretical_reference=0.45)
    fa = 1.02 * 10e3 + 20.0                     # the BM-5 transient-like step
    warm = solve_ball(bearing, models, W1800, 1000.0, fa, guess=r0,
                      theoretical_reference=0.45)
    cold = solve_ball(bearing, models, W1800, 1000.0, fa, theoretical_reference=0.45)
    refreshed = solve_ball(bearing, models, W1800, 1000.0, fa, guess=r0,
                           theoretical_reference=0.45, warm_refresh=2.0)
    assert refreshed.extra["n_jacobian"] >= 1
    for other in (cold, refreshed):
        assert warm.cage_speed_ratio == pytest.approx(other.cage_speed_ratio, rel=1e-9)
        assert warm.shaft_torque == pytest.approx(other.shaft_torque, rel=1e-7)
        assert warm.heat["total"] == pytest.approx(other.heat["total"], rel=1e-7)
    assert warm.shaft_torque * W1800 == pytest.approx(warm.heat["total"], rel=1e-8)
    assert warm.residual_norm <= 1e-9


@pytest.mark.parametrize("fa", [10e3, 1e3])
def test_compiled_chord_phase_takes_the_python_loops_steps(bearing, fa):
    # ball_newton._chord_phase runs the warm start's chord / Broyden steps in one compiled
    # loop with the cage torques as a quadratic in the cage speed, then puts the exact torques
    # back: the same iterations and evaluations as the Python loop, the same state to the
    # solver tolerance, the exact residual at the end
    models = _models(bearing, 303.15, W1800)
    r0 = solve_ball(bearing, models, W1800, 1000.0, fa, theoretical_reference=0.45)
    out = {}
    for flag in (True, False):
        original = ball_newton.newton_block

        def patched(*a, _flag=flag, _orig=original, **k):
            return _orig(*a, **{**k, "compiled_chord": _flag})

        ball_mod.newton_block = patched
        try:
            out[flag] = solve_ball(bearing, models, W1800, 1000.0, 1.02 * fa + 20.0, guess=r0,
                                   theoretical_reference=0.45)
        finally:
            ball_mod.newton_block = original
    a, b = out[True], out[False]
    assert (a.iterations, a.extra["n_eval"], a.extra["n_jacobian"]) == (
        b.iterations, b.extra["n_eval"], b.extra["n_jacobian"])
    assert a.cage_speed_ratio == pytest.approx(b.cage_speed_ratio, rel=1e-10)
    assert a.shaft_torque * W1800 == pytest.approx(a.heat["total"], rel=1e-8)
    # the returned residual is that of a fresh evaluation with the exact torque models
    system = a.extra["system"].reloaded(1000.0, 1.02 * fa + 20.0)
    system._last = None
    R, Gc, G0, _ = system.evaluate(*a.unknowns)
    assert math.sqrt(np.sum(R ** 2) + np.sum((Gc.sum(0) + G0) ** 2)) == pytest.approx(
        a.residual_norm, rel=1e-6, abs=1e-13)


def test_first_warm_step_is_the_tangent_predictor(bearing):
    # at the previous solution x0 the residual under the new loads is exactly the load change
    # in the two ring-force rows (dR/dp dp), so the first step of a warm start with the
    # Jacobian at x0, x1 = x0 - J^-1 dR/dp dp, is the Euler (tangent) predictor: the residual
    # falls from O(dp) to O(dp^2). Measured here for +0.5 / +1 / +2 % axial-load steps.
    from thermobearing.skidding.ball_newton import (
        _CAP_G,
        _CAP_X,
        _NO_HIST,
        _factor_blocks,
        _inverse_small,
        _propose,
        _residual_norm,
    )

    models = _models(bearing, 353.15, W1800)
    r0 = solve_ball(bearing, models, W1800, 1000.0, 10e3, theoretical_reference=0.45)
    s0 = r0.extra["system"]
    X, G = r0.unknowns
    J0 = analytic_blocks(s0, X, G)
    out = {}
    for frac in (0.005, 0.01, 0.02):
        s = s0.reloaded(1000.0, 10e3 * (1.0 + frac))
        J = J0.rescaled(s)
        R, Gc, Gk, _ = s.evaluate(X, G)
        n0 = _residual_norm(R, Gc, Gk)
        Ainv, AiB, S, ok = _factor_blocks(J.A, J.B, np.ascontiguousarray(J.C), J.Dg)
        Sinv, ok2 = _inverse_small(S)
        assert ok and ok2
        xs, gs = s.scales()
        *_, Xn, Gn, _ = _propose(Ainv, AiB, np.ascontiguousarray(J.C), Sinv, R, Gc, Gk, _CAP_X,
                                 _CAP_G, _NO_HIST, 0, xs, gs, X, G)
        Rn, Gcn, Gkn, _ = s.evaluate(Xn, Gn)
        out[frac] = (n0, _residual_norm(Rn, Gcn, Gkn))
    (a0, a1), (b0, b1), (c0, c1) = out[0.005], out[0.01], out[0.02]
    # the start residual is first order in the step (the load term, exactly linear)...
    assert b0 / a0 == pytest.approx(2.0, rel=0.02) and c0 / b0 == pytest.approx(2.0, rel=0.02)
    # ... the predicted one second order (doubling the step: x 4, here within 3-5)
    assert 3.0 < b1 / a1 < 5.0 and 3.0 < c1 / b1 < 5.0
    assert c1 < 0.02 * c0


def test_torque_model_of_the_chord_phase_reproduces_the_models(bearing):
    # ball_newton._torque_model: churning torque as a power of the cage speed (paper 002
    # eqs. 12-15: mu_v a power of N_Re per flow regime), the Petroff guide torque linear
    # (eq. 5), the ball drag term as a power (eq. 10: ~ omega^2), fitted to two exact values;
    # exact to round-off within a regime, checked against the Python models +-5 %
    from thermobearing.skidding.ball_newton import _torque_model

    models = _models(bearing, 303.15, W1800)
    r = solve_ball(bearing, models, W1800, 1000.0, 10e3, theoretical_reference=0.45)
    s = r.extra["system"]
    wc0 = r.cage_speed
    h = 1e-3 * wc0
    t0, t1 = s._cage_torques(wc0), s._cage_torques(wc0 + h)
    lr = math.log1p(h / wc0)
    tq = np.array([wc0, 0.1 * wc0, t0[0], math.log(t1[0] / t0[0]) / lr, t0[1],
                   (t1[1] - t0[1]) / h, t0[3], math.log(t1[3] / t0[3]) / lr, s.T_s, 1.0, 1.0])
    assert tq[7] == pytest.approx(2.0, rel=1e-9)          # drag ~ omega^2
    for f in (0.95, 0.99, 1.0004, 1.03, 1.05):
        wc = wc0 * f
        g0, fd = _torque_model(tq, wc)
        t = s._cage_torques(wc)
        assert g0 == pytest.approx(-(t[0] + t[1]) / s.T_s, rel=1e-12)
        assert fd == pytest.approx(t[3], rel=1e-12)
