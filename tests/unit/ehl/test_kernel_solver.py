"""Unit tests of the EHL deformation kernel and the discrete Newton problem (engineer D)."""

from __future__ import annotations

import math

import numpy as np

from thermobearing.ehl.kernel import LogKernel
from thermobearing.ehl.solver import LineProblem, Rheology


def test_hertz_pressure_gives_flat_deformed_gap():
    # Line-contact Hertz theory (Johnson 1985 ch. 5): the Hertz pressure sqrt(1 - X^2) makes
    # X^2/2 + deformation constant over the contact; the discrete kernel must reproduce it to
    # O(dx^1.5) (square-root edge). Measured: 8.3e-5 at n = 513, 1.1e-5 at n = 2049.
    for n, bound in ((513, 1.5e-4), (2049, 2e-5)):
        x = np.linspace(-4.5, 1.5, n)
        k = LogKernel(n, x[1] - x[0])
        p = np.sqrt(np.maximum(1 - x**2, 0.0))
        h = 0.5 * x**2 + k.apply(p)
        inside = np.abs(x) < 0.9
        assert np.ptp(h[inside]) < bound


def test_fft_product_equals_dense_matrix_product():
    n = 300
    k = LogKernel(n, 0.02)
    v = np.random.default_rng(1).random(n)
    assert np.allclose(k.apply(v), k.dense() @ v, rtol=0, atol=1e-12)


def test_residual_jacobian_matches_finite_differences():
    # analytic Jacobian (dense assembly) against central differences of the residual
    rh = Rheology(law="roelands", roelands_a=math.log(0.04) + 9.67, roelands_z=0.6,
                  hertz_pressure=1e9, compressible=True)
    n = 41
    prob = LineProblem(n, -3.0, 1.5, 1e-2, rh, f_e=np.linspace(1, 2, n),
                       f_r=np.linspace(1, 1.5, n))
    x = prob.x
    p = np.sqrt(np.maximum(1 - x**2, 0.0)) + 0.05 * np.random.default_rng(0).random(n)
    p[0] = p[-1] = 0.0
    h0 = 0.3
    st = prob.evaluate(p, h0)
    jac = prob.dense_jacobian_r(st)
    fd = np.zeros_like(jac)
    eps = 1e-7
    for j in range(1, n - 1):
        pp, pm = p.copy(), p.copy()
        pp[j] += eps
        pm[j] -= eps
        fd[:, j - 1] = (prob.evaluate(pp, h0, False)["R"] - prob.evaluate(pm, h0, False)["R"]) / (
            2 * eps)
    assert np.max(np.abs(jac - fd)) / np.max(np.abs(fd)) < 1e-7
    dh = (prob.evaluate(p, h0 + eps, False)["R"] - prob.evaluate(p, h0 - eps, False)["R"]) / (
        2 * eps)
    assert np.max(np.abs(dh - st["b_sum"])) / np.max(np.abs(dh)) < 1e-7
    # the banded preconditioner matrix with a band covering everything is the full Jacobian
    ab, kl, ku = prob.banded_jacobian_r(st, n, np.ones(n - 2), np.zeros(n - 2))
    full = np.zeros((n - 2, n - 2))
    for i in range(n - 2):
        for j in range(n - 2):
            if -kl <= j - i <= ku:
                full[i, j] = ab[kl + ku + i - j, j]
    assert np.allclose(full, jac, rtol=1e-12, atol=1e-12 * np.max(np.abs(jac)))


def test_rheology_laws_match_paper000_eqs_9_10():
    rh = Rheology(law="roelands", roelands_a=math.log(0.08) + 9.67, roelands_z=0.68,
                  hertz_pressure=1e9, compressible=True)
    P = np.array([0.0, 0.5, 1.0])
    eta, _ = rh.viscosity(P)
    p = P * 1e9
    # paper 000 eq. 9 prints 5.1e-9 1/Pa, i.e. 1/p0 = 1/1.96e8 rounded; the exponent is z
    expected = np.exp((math.log(0.08) + 9.67) * ((1 + p / 1.96e8) ** 0.68 - 1))
    assert np.allclose(eta, expected, rtol=1e-12)
    rho, _ = rh.density(P)
    assert np.allclose(rho, 1 + 0.6e-9 * p / (1 + 1.7e-9 * p))
