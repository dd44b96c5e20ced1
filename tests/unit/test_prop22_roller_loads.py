"""Property tests of the roller load distribution (thermobearing.loads_roller, session 22),
beside the ring balance, mirror symmetry, Stribeck sum, load zone and film tests of
test_property_loads.py, test_prop19_loads.py and test_prop20_hertz_loads.py.

- similarity: Q = K delta^n, so scaling the clearance and the approaches by lambda and the
  stiffnesses by lambda^-n leaves every load unchanged and scales the ring displacement by
  lambda;
- without clearance and body force the problem is homogeneous: the loads are proportional
  to F_r and the ring displacement to F_r^(1/n);
- the rollers are a set: a permutation of the azimuths (and their body forces) permutes the
  loads; the solution does not depend on the warm start;
- the most loaded roller carries more with more clearance (fewer rollers share the load,
  Harris & Kotzalas 2007 vol. 1);
- the rigid limit: with stiff contacts one roller under the load carries it all and the
  ring moves by P_d/2 plus that roller's approach.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.hertz import line_contact_stiffness
from thermobearing.loads_roller import LINE_CONTACT_EXPONENT, roller_load_distribution

N = LINE_CONTACT_EXPONENT
K_LINE = float(line_contact_stiffness(0.013))


@settings(max_examples=50, deadline=None)
@given(z=st.integers(6, 36), pd=st.one_of(st.just(0.0), st.floats(1e-7, 2e-4)),
       load=st.floats(10.0, 3e5), body=st.one_of(st.just(0.0), st.floats(0.1, 2000.0)),
       ratio=st.floats(0.5, 2.0), log_lam=st.floats(-2.0, 2.0))
def test_similarity_in_clearance_and_stiffness(z, pd, load, body, ratio, log_lam):
    lam = 10.0**log_lam
    a = roller_load_distribution(z, pd, load, K_LINE, K_LINE * ratio, body_force=body)
    b = roller_load_distribution(z, pd * lam, load, K_LINE * lam**-N, K_LINE * ratio * lam**-N,
                                 body_force=body)
    scale = max(load, float(np.max(a.outer_load)))
    np.testing.assert_allclose(b.inner_load, a.inner_load, rtol=0, atol=1e-8 * scale)
    np.testing.assert_allclose(b.outer_load, a.outer_load, rtol=0, atol=1e-8 * scale)
    np.testing.assert_allclose(b.ring_displacement, lam * a.ring_displacement, rtol=1e-7,
                               atol=1e-9 * lam * abs(float(a.ring_displacement[0])))


@settings(max_examples=50, deadline=None)
@given(z=st.integers(6, 40), load=st.floats(1.0, 3e5), more=st.floats(1.01, 100.0),
       ratio=st.floats(0.5, 2.0))
def test_loads_proportional_to_the_load_without_clearance(z, load, more, ratio):
    a = roller_load_distribution(z, 0.0, load, K_LINE, K_LINE * ratio)
    b = roller_load_distribution(z, 0.0, load * more, K_LINE, K_LINE * ratio)
    np.testing.assert_allclose(b.inner_load, more * a.inner_load, rtol=0,
                               atol=1e-9 * more * load)
    assert math.isclose(float(b.ring_displacement[0]),
                        more ** (1.0 / N) * float(a.ring_displacement[0]), rel_tol=1e-8)


@settings(max_examples=50, deadline=None)
@given(z=st.integers(6, 30), pd=st.one_of(st.just(0.0), st.floats(1e-7, 1e-4)),
       load=st.floats(10.0, 2e5), seed=st.integers(0, 2**31 - 1),
       body=st.floats(0.0, 1000.0))
def test_a_permutation_of_the_rollers_permutes_the_loads(z, pd, load, seed, body):
    # irregular azimuths, each within 0.4 of its pitch of the regular one: the gaps stay
    # below pi, so the rollers span every direction and the load can be carried
    rng = np.random.default_rng(seed)
    psi = 2.0 * math.pi * (np.arange(z) + rng.uniform(-0.4, 0.4, z)) / z
    fb = body * rng.uniform(0.5, 1.5, z)
    perm = rng.permutation(z)
    a = roller_load_distribution(z, pd, load, K_LINE, K_LINE, body_force=fb, azimuth=psi)
    b = roller_load_distribution(z, pd, load, K_LINE, K_LINE, body_force=fb[perm],
                                 azimuth=psi[perm])
    scale = max(load, float(np.max(a.outer_load)))
    np.testing.assert_allclose(b.inner_load, a.inner_load[perm], rtol=0, atol=1e-8 * scale)
    np.testing.assert_allclose(b.outer_load, a.outer_load[perm], rtol=0, atol=1e-8 * scale)


@settings(max_examples=50, deadline=None)
@given(z=st.integers(6, 30), pd=st.one_of(st.just(0.0), st.floats(1e-7, 1e-4)),
       load=st.floats(10.0, 2e5), body=st.floats(0.0, 1000.0),
       x0=st.tuples(st.floats(-2e-4, 4e-4), st.floats(-2e-4, 2e-4)))
def test_the_solution_does_not_depend_on_the_warm_start(z, pd, load, body, x0):
    a = roller_load_distribution(z, pd, load, K_LINE, K_LINE, body_force=body)
    b = roller_load_distribution(z, pd, load, K_LINE, K_LINE, body_force=body, x0=x0)
    scale = max(load, float(np.max(a.outer_load)))
    np.testing.assert_allclose(b.inner_load, a.inner_load, rtol=0, atol=1e-8 * scale)


@settings(max_examples=50, deadline=None)
@given(z=st.integers(6, 40), load=st.floats(10.0, 3e5), c1=st.floats(0.0, 1e-4),
       c2=st.floats(1e-7, 1e-4), body=st.one_of(st.just(0.0), st.floats(0.1, 1000.0)))
def test_the_most_loaded_roller_carries_more_with_more_clearance(z, load, c1, c2, body):
    a = roller_load_distribution(z, c1, load, K_LINE, K_LINE, body_force=body)
    b = roller_load_distribution(z, c1 + c2, load, K_LINE, K_LINE, body_force=body)
    assert float(np.max(b.inner_load)) >= float(np.max(a.inner_load)) * (1.0 - 1e-9)


@settings(max_examples=30, deadline=None)
@given(z=st.integers(3, 20), load=st.floats(100.0, 3e5), pd=st.floats(1e-6, 1e-4))
def test_the_rigid_limit_is_one_roller(z, load, pd):
    """With contacts 1e8 times stiffer the approaches are ~1e-7 of the clearance: an odd Z
    with roller 0 under the load puts it all on roller 0 (its neighbours stay clear by
    P_d/2 (1 - cos(2 pi / Z)), far above the approach), the ring moves by P_d/2 plus the
    series approach of the two contacts under F_r; the load on roller 0 is F_r to the ring
    residual returned (whose tolerance is rtol max(F_r, 1e-6 K (P_d/2)^n), the second term
    large with such stiff contacts)."""
    z = 2 * (z // 2) + 1
    stiff = K_LINE * 1e8
    ld = roller_load_distribution(z, pd, load, stiff, stiff)
    assert ld.n_loaded == 1
    assert abs(float(ld.inner_load[0]) - load) <= ld.residual * (1.0 + 1e-6) + 1e-12 * load
    approach = 2.0 * (float(ld.inner_load[0]) / stiff) ** (1.0 / N)
    assert math.isclose(float(ld.ring_displacement[0]), 0.5 * pd + approach, rel_tol=1e-9)
    assert abs(float(ld.ring_displacement[1])) <= 1e-9 * pd


def _films(h0_i: float, h0_o: float, expo: float):
    """Flooded central films falling with the load as EHL films do, h = h0 (Q / 1 N)^-e."""
    def inner(q):
        return h0_i * np.maximum(np.asarray(q, float), 1e-300) ** -expo

    def outer(q):
        return h0_o * np.maximum(np.asarray(q, float), 1e-300) ** -expo

    return inner, outer


film_case = dict(z=st.integers(6, 30), pd=st.floats(0.0, 6e-5), load=st.floats(10.0, 5e4),
                 h0=st.floats(1e-7, 3e-6), ratio=st.floats(0.5, 2.0),
                 expo=st.floats(0.05, 0.2), body=st.floats(0.0, 200.0))


@settings(max_examples=30, deadline=None)
@given(**film_case, x0=st.tuples(st.floats(-5e-5, 8e-5), st.floats(-3e-5, 3e-5)),
       seed=st.integers(0, 2**31 - 1))
def test_film_distribution_balances_the_ring_and_forgets_its_start(z, pd, load, h0, ratio,
                                                                    expo, body, x0, seed):
    """roller_film_load_distribution with flooded films: the ring is in balance, each
    loaded roller's gap equation (3) holds, a roller left unloaded is one whose films
    cannot fill its gap even at the solver's smallest film load (1e-9 N: these films grow
    without bound as the load falls, but a wide gap needs less than that), and neither the
    warm start of the ring nor that of the roller loads nor the order of the rollers
    changes the loads."""
    from thermobearing.loads_roller import roller_film_load_distribution

    inner, outer = _films(h0, h0 * ratio, expo)
    ld = roller_film_load_distribution(z, pd, load, inner, outer, K_LINE, K_LINE,
                                       body_force=body)
    psi = ld.azimuth
    assert abs(float(np.sum(ld.inner_load * np.cos(psi))) - load) <= 1e-8 * load + 1e-9
    assert abs(float(np.sum(ld.inner_load * np.sin(psi)))) <= 1e-8 * load + 1e-9
    q, qo = ld.inner_load, ld.outer_load
    gap = 0.5 * pd - (ld.ring_displacement[0] * np.cos(psi)
                      + ld.ring_displacement[1] * np.sin(psi))
    on = ld.loaded
    lhs = inner(q) + outer(qo) - (q / K_LINE) ** (1 / N) - (qo / K_LINE) ** (1 / N)
    np.testing.assert_allclose(lhs[on], gap[on], rtol=0, atol=1e-12 + 1e-9 * h0)
    q_min = 1e-9 + body * (1 + 1e-12)
    floor = inner(1e-9) + outer(q_min) - (1e-9 / K_LINE) ** (1 / N) - (q_min / K_LINE) ** (1 / N)
    assert np.all(floor <= gap[~on] * (1 + 1e-9) + 1e-15)
    scale = max(load, float(np.max(qo)))
    warm = roller_film_load_distribution(z, pd, load, inner, outer, K_LINE, K_LINE,
                                         body_force=body, x0=x0,
                                         q0=q * np.random.default_rng(seed).uniform(0.3, 3, z))
    np.testing.assert_allclose(warm.inner_load, q, rtol=0, atol=1e-7 * scale)
    perm = np.random.default_rng(seed).permutation(z)
    shuffled = roller_film_load_distribution(z, pd, load, inner, outer, K_LINE, K_LINE,
                                             body_force=body, azimuth=psi[perm])
    np.testing.assert_allclose(shuffled.inner_load, q[perm], rtol=0, atol=1e-7 * scale)
