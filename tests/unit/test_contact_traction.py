"""Contact integration (thermobearing.contact_traction): closed forms, power identity, Jacobian."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.contact_traction import integrate, integrate_contact_set, spin_moment_harris
from thermobearing.errors import InputError
from thermobearing.state import ContactSet
from thermobearing.traction import EyringLimitingShearTraction, make_traction_law

COULOMB = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=1e-12)


class BarusOil:
    """Test double: eta = eta0 exp(alpha p) (see test_traction.py)."""

    def __init__(self, eta0=0.05, alpha=2.0e-8):
        self.eta0, self.alpha = eta0, alpha

    def dynamic_viscosity(self, T, p=0.0):
        return self.eta0 * np.exp(self.alpha * np.asarray(p, dtype=float)) + 0.0 * np.asarray(T)


def test_pure_sliding_gives_mu_q():
    # saturated law, rigid sliding: F = -mu Q along the slip, heat = mu Q |V|
    r = integrate(COULOMB, normal_load=[1000.0, 0.0], semi_major=2e-3, semi_minor=0.4e-3,
                  sliding_speed=[2.0, 2.0], transverse_sliding_speed=[-1.0, -1.0])
    v = math.hypot(2.0, 1.0)
    np.testing.assert_allclose(r.rolling_force, [-0.05 * 1000 * 2 / v, 0.0], rtol=1e-12)
    np.testing.assert_allclose(r.transverse_force, [0.05 * 1000 / v, 0.0], rtol=1e-12)
    np.testing.assert_allclose(r.heat, [0.05 * 1000 * v, 0.0], rtol=1e-12)
    np.testing.assert_allclose(r.moment_normal, [0.0, 0.0], atol=1e-12)


def test_line_contact_sliding():
    r = integrate(COULOMB, normal_load=500.0, semi_major=5e-3, semi_minor=0.1e-3,
                  sliding_speed=-0.5, kind="line")
    assert float(r.rolling_force) == pytest.approx(0.05 * 500, rel=1e-12)
    assert float(r.heat) == pytest.approx(0.05 * 500 * 0.5, rel=1e-12)


@pytest.mark.parametrize("ratio", [1.0, 0.5, 0.15])
def test_pure_spin_matches_harris(ratio):
    # Harris & Kotzalas: M_s = 3 mu Q a E(k) / 8 for tau = mu p, k^2 = 1 - (b/a)^2
    a = 2e-3
    r = integrate(COULOMB, normal_load=800.0, semi_major=a, semi_minor=ratio * a,
                  spin_speed=150.0, n_major=32, n_minor=16)
    expected = spin_moment_harris(0.05, 800.0, a, ratio * a)
    assert -float(r.moment_normal) == pytest.approx(float(expected), rel=5e-4)
    assert float(r.heat) == pytest.approx(-float(r.moment_normal) * 150.0, rel=1e-12)


def test_heathcote_linear_law_hand_calculation():
    # Linear law tau = k p s (unsaturated). Pure rolling Omega_x with no centre slip:
    # dv_y = -Omega_x x^2/(2 R_d); F_y = k Omega_x/(2 R_d) * int p x^2 dA = k Omega_x Q a^2/(10 R_d)
    # (int p x^2 dA = Q a^2 / 5 for a Hertz ellipse). Shifting the centre slip by
    # V_y = Omega_x a^2 / (10 R_d) puts the two Heathcote zero-slip lines where F_y = 0.
    k = 0.05 / 10.0
    law = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=10.0)
    q, a, b, rd, wx = 2000.0, 3e-3, 0.4e-3, 18e-3, 500.0
    r = integrate(law, normal_load=q, semi_major=a, semi_minor=b, roll_speed=wx,
                  deformed_radius=rd)
    assert float(r.rolling_force) == pytest.approx(k * wx * q * a * a / (10 * rd), rel=1e-10)
    r0 = integrate(law, normal_load=q, semi_major=a, semi_minor=b, roll_speed=wx,
                   deformed_radius=rd, sliding_speed=wx * a * a / (10 * rd))
    assert abs(float(r0.rolling_force)) < 1e-9 * float(r.rolling_force)
    assert float(r0.heat) > 0


def test_newtonian_barus_closed_form():
    # Newtonian film (no Eyring, no cap reached), Barus viscosity at the Hertz pressure:
    # F_y = -(V eta0 / h) * int exp(alpha p) dA = -(V eta0/h) 2 pi a b [e^c (c-1) + 1] / c^2,
    # c = alpha p0 (polar substitution u = sqrt(1 - r^2)).
    oil = BarusOil(eta0=0.05, alpha=2e-8)
    law = EyringLimitingShearTraction(oil, limiting_shear_coefficient=0.9, eyring_stress=None)
    q, a, b, h, v = 300.0, 1.5e-3, 0.3e-3, 5e-7, 1e-5
    p0 = 3 * q / (2 * math.pi * a * b)
    c = oil.alpha * p0
    expected = v * oil.eta0 / h * 2 * math.pi * a * b * (math.exp(c) * (c - 1) + 1) / c ** 2
    r = integrate(law, normal_load=q, semi_major=a, semi_minor=b, sliding_speed=v,
                  film_thickness=h, temperature=330.0, n_major=48, n_minor=24)
    assert -float(r.rolling_force) == pytest.approx(expected, rel=2e-3)


def test_film_law_without_film_is_an_error():
    law = EyringLimitingShearTraction(BarusOil())
    with pytest.raises(InputError, match="film"):
        integrate(law, normal_load=100.0, semi_major=1e-3, semi_minor=1e-4, sliding_speed=1.0)


def test_bad_geometry_is_an_error():
    with pytest.raises(InputError, match="normal_load"):
        integrate(COULOMB, normal_load=-1.0, semi_major=1e-3, semi_minor=1e-4)
    with pytest.raises(InputError, match="kind"):
        integrate(COULOMB, normal_load=1.0, semi_major=1e-3, semi_minor=1e-4, kind="area")


def test_vectorised_shapes_and_zero_load():
    z = 7
    load = np.zeros((2, z))
    load[0, :3] = [100.0, 200.0, 300.0]
    r = integrate(COULOMB, normal_load=load, semi_major=1e-3, semi_minor=2e-4,
                  sliding_speed=np.linspace(-1, 1, z), spin_speed=10.0, jacobian=True)
    assert r.heat.shape == (2, z) and r.jacobian.shape == (2, z, 5, 5)
    assert np.all(np.isfinite(r.jacobian)) and np.all(r.heat[1] == 0)


def _random_q(rng):
    return dict(sliding_speed=rng.normal(0, 0.5), transverse_sliding_speed=rng.normal(0, 0.2),
                spin_speed=rng.normal(0, 50), roll_speed=rng.normal(0, 500),
                tilt_speed=rng.normal(0, 50))


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), law_index=st.integers(0, 2))
def test_power_identity(seed, law_index):
    # heat == -(F.V + M.Omega) for any motion: one code path for forces and heat
    rng = np.random.default_rng(seed)
    law = [COULOMB,
           make_traction_law("four_parameter", mu_zero=0.01, mu_max=0.06,
                             slip_speed_at_max=0.4, mu_infinity=0.03),
           EyringLimitingShearTraction(BarusOil(), 0.07, 4e6)][law_index]
    n = 5
    kw = {k: np.array([_random_q(rng)[k] for _ in range(n)]) for k in _random_q(rng)}
    load = rng.uniform(0, 3000, n)
    a = rng.uniform(1.5e-4, 3e-4, n) * np.cbrt(load)  # Hertz-like scaling: p0 <= ~3 GPa
    r = integrate(law, normal_load=load, semi_major=a, semi_minor=rng.uniform(0.1, 1.0, n) * a,
                  deformed_radius=rng.uniform(5e-3, 5e-2, n),
                  film_thickness=rng.uniform(5e-8, 1e-6, n), temperature=340.0, **kw)
    q = np.stack([kw["transverse_sliding_speed"], kw["sliding_speed"], kw["roll_speed"],
                  kw["tilt_speed"], kw["spin_speed"]], axis=-1)
    power = -(r.generalized_force * q).sum(-1)
    np.testing.assert_allclose(r.heat, power, rtol=1e-9, atol=1e-12 * max(1.0, r.heat.max()))
    assert np.all(r.heat >= 0)


def test_jacobian_matches_finite_differences():
    rng = np.random.default_rng(3)
    law = make_traction_law("four_parameter", mu_zero=0.0, mu_max=0.06,
                            slip_speed_at_max=0.4, mu_infinity=0.03)
    base = dict(normal_load=1500.0, semi_major=2.5e-3, semi_minor=0.35e-3, deformed_radius=2e-2)
    q0 = np.array([0.3, -0.8, 300.0, 20.0, 40.0])  # large centre slip: no zero-slip point
    names = ["transverse_sliding_speed", "sliding_speed", "roll_speed", "tilt_speed",
             "spin_speed"]

    def run(q, jac=False):
        return integrate(law, **base, **dict(zip(names, q, strict=True)), jacobian=jac)

    r = run(q0, True)
    fd = np.zeros((5, 5))
    gfd = np.zeros(5)
    for j in range(5):
        dq = np.zeros(5)
        dq[j] = 1e-6 * max(1.0, abs(q0[j]))
        rp, rm = run(q0 + dq), run(q0 - dq)
        fd[:, j] = (rp.generalized_force - rm.generalized_force) / (2 * dq[j])
        gfd[j] = (rp.heat - rm.heat) / (2 * dq[j])
    np.testing.assert_allclose(r.jacobian, fd, rtol=1e-5, atol=1e-8 * np.abs(fd).max())
    np.testing.assert_allclose(r.heat_gradient, gfd, rtol=1e-5, atol=1e-8 * np.abs(gfd).max())
    assert rng is not None


def test_contact_set_wrapper():
    cs = ContactSet(race="inner", normal_load=[100.0, 200.0], semi_major=1e-3, semi_minor=1e-4,
                    max_pressure=1e9, sliding_speed=[0.5, -0.5])
    r = integrate_contact_set(COULOMB, cs)
    np.testing.assert_allclose(r.rolling_force, [-5.0, 10.0])
    assert cs.ring_role == "inner_ring"


@pytest.mark.parametrize("law", [
    make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=0.05),
    make_traction_law("four_parameter", mu_zero=0.01, mu_max=0.06, slip_speed_at_max=0.5,
                      mu_infinity=0.03)])
def test_default_quadrature_accuracy(law):
    # spinning ball contact with Heathcote slip (zero-slip curves inside the ellipse):
    # the default 16 x 8 nodes give heat and spin moment within 1 % of a 128 x 48 rule
    kw = dict(normal_load=2000.0, semi_major=3e-3, semi_minor=4e-4, sliding_speed=0.05,
              spin_speed=80.0, roll_speed=700.0, deformed_radius=0.018)
    ref = integrate(law, **kw, n_major=128, n_minor=48)
    r = integrate(law, **kw)
    assert float(r.heat) == pytest.approx(float(ref.heat), rel=1e-2)
    assert float(r.moment_normal) == pytest.approx(float(ref.moment_normal), rel=1e-2)


def test_eyring_fast_path_equals_generic_loop():
    # the node loop's fast path (Eyring, smooth cap, tau0 > 0, tabulated viscosity, no
    # Jacobian; traction._eyring_smooth_node) against the generic loop of the same kernel
    # (taken with jacobian=True): forces, moments and heat agree to round-off. Contacts:
    # random loads / ellipses / slip and spin (seeded), one unloaded; Barus viscosity
    # tabulated on a uniform pressure grid (ln eta linear in p, exact for Barus).
    from thermobearing.contact_traction import _integrate_contacts, _rule
    from thermobearing.traction import EYRING

    rng = np.random.default_rng(11)
    n = 40
    q = rng.uniform(50.0, 3000.0, n)
    q[3] = 0.0
    a = rng.uniform(1e-3, 3e-3, n)
    b = rng.uniform(0.2e-3, 0.5e-3, n)
    vy, vx = rng.normal(0.0, 0.5, n), rng.normal(0.0, 0.05, n)
    wz, wx, wy = rng.normal(0.0, 200.0, n), rng.normal(0.0, 500.0, n), rng.normal(0.0, 50.0, n)
    curv = np.full(n, 1.0 / 0.02)
    h = rng.uniform(0.1e-6, 1e-6, n)
    p_max, m = 4e9, 401
    inv_dp = (m - 1) / p_max
    ln_tab = np.log(0.05) + 2e-8 * np.linspace(0.0, p_max, m)
    slope_tab = np.full(m, 2e-8 / inv_dp)
    tau0 = 5e6
    params = np.array([0.08, tau0, 1.0, 1.0 / tau0])
    rule = _rule("point", 8, 4)
    outs = []
    for jac in (False, True):
        out = np.empty((n, 6))
        _integrate_contacts(EYRING, params, 1, ln_tab, slope_tab, inv_dp, np.zeros((0, 0)), q,
                            a, b, vy, vx, wz, wx, wy, curv, h, *rule, True, jac, out,
                            np.empty((n, 5, 5)), np.empty((n, 5)))
        outs.append(out)
    fast, generic = outs
    assert np.all(fast[3] == 0.0)
    scale = np.abs(generic).max(axis=0)
    np.testing.assert_allclose(fast, generic, rtol=1e-13, atol=1e-13 * scale.max())
    np.testing.assert_allclose(fast[:, 5], generic[:, 5], rtol=1e-13)
    assert np.all(fast[:, 5] >= 0.0) and np.abs(fast[:, :2]).max() > 0.0
