"""Raceway sources: traction heat by hand, Blok partition, paper 000 eq. 35 rolling force."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError, ValidityWarning
from thermobearing.heat_sources import raceway
from thermobearing.state import ContactSet
from thermobearing.traction import make_traction_law

from .conftest import make_context, uniform_state

COULOMB = make_traction_law("linear_saturating", mu_max=0.05, slip_speed_max=1e-12)


def _sliding_state(z, load=1000.0, slide=0.5):
    contacts = tuple(
        ContactSet(race=race, normal_load=np.full(z, load), semi_major=2e-3, semi_minor=3e-4,
                   max_pressure=1e9, entrainment_speed=10.0, sliding_speed=slide)
        for race in ("inner", "outer"))
    return uniform_state(z, contacts=contacts)


def test_pure_sliding_heat_is_mu_q_v(qj1044, vg46, race_control_state):
    # hand calculation: 2 races x Z balls x mu Q |V| = 2 * Z * 0.05 * 1000 * 0.5
    op, _ = race_control_state
    z = qj1044.n_elements
    ctx = make_context(qj1044, vg46, op, _sliding_state(z), traction=COULOMB)
    r = raceway.raceway_traction(ctx)
    assert r.total == pytest.approx(2 * z * 0.05 * 1000 * 0.5, rel=1e-12)
    assert r.components["inner contact"] == pytest.approx(z * 25.0, rel=1e-12)
    # same material? no: steel balls and rings of QJ1044 -> shares from Blok's rule
    share = raceway.blok_partition(10.0, 0.5, 3e-4, qj1044.ball_material, qj1044.ring_material)
    assert r.power_by_role["elements"] == pytest.approx(float(share) * r.total, rel=1e-12)


def test_blok_partition_limits(qj1044):
    m = qj1044.ring_material
    assert float(raceway.blok_partition(5.0, 0.0, 3e-4, m, m)) == pytest.approx(0.5)
    # element surface 4x faster through the contact: share sqrt(4)/(sqrt(4)+1) = 2/3
    u, v = 2.5 * 1.0, 3.0  # u_e = u + v/2 = 4, u_r = u - v/2 = 1
    assert float(raceway.blok_partition(u, v, 3e-4, m, m)) == pytest.approx(2 / 3, rel=1e-9)


def test_traction_law_required(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    with pytest.raises(InputError, match="traction"):
        raceway.raceway_traction(make_context(qj1044, vg46, op, ks))


def test_film_law_uses_race_control_film(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    law = make_traction_law("eyring_limiting_shear", lubricant=vg46)
    r = raceway.raceway_traction(make_context(qj1044, vg46, op, ks, traction=law))
    assert r.total > 0 and math.isfinite(r.total)
    assert set(r.components) == {"inner contact", "outer contact"}


def test_film_law_without_film_errors(qj1044, vg46, race_control_state):
    op, _ = race_control_state
    law = make_traction_law("eyring_limiting_shear", lubricant=vg46)
    ctx = make_context(qj1044, vg46, op, _sliding_state(qj1044.n_elements), traction=law)
    with pytest.raises(InputError, match="film"):
        raceway.raceway_traction(ctx)


def test_rolling_force_paper000_by_hand():
    # eq. 35: Q_x = 18.4 G^-0.3 U^0.7 E' R l; E' = 2.28e11, R = 7e-3, l = 16 mm,
    # eta0 = 0.08, mean (entrainment) speed 5 m/s (surface speeds summing to 10 m/s),
    # alpha = 2e-8
    e, r, l, eta, u, a = 2.28e11, 7e-3, 0.016, 0.08, 5.0, 2e-8
    big_u = eta * u / (e * r)
    expected = 18.4 * (a * e) ** -0.3 * big_u ** 0.7 * e * r * l
    got = raceway.rolling_force_paper000(u, eta, a, e, r, l)
    assert float(got) == pytest.approx(expected, rel=1e-12)
    # by hand: U = 0.08 * 5 / (2.28e11 * 7e-3) = 2.506e-10, U^0.7 = 1.902e-7,
    # G^-0.3 = 4560^-0.3 = 0.07979, 18.4 * 0.07979 * 1.902e-7 = 2.793e-7;
    # E' R l = 2.554e7 N -> 7.13 N (11.6 N with the sum of the speeds in U: 2^0.7 = 1.62)
    assert float(got) == pytest.approx(7.13, rel=5e-3)  # N


def test_rolling_force_paper000_against_the_numerical_ehl_solution():
    """Hand check of the speed convention of eq. 35: the isothermal Newtonian EHL solution of
    the NU 214 inner contact (3000 r/min, 8 kN: most loaded roller 2412 N; ISO VG 46 at 320 K,
    Barus alpha) gives the rolling resultant Q_x = int p dh/dx dx = 3.85 N (1024 nodes). Eq.
    35 with the mean speed in U gives 3.46 N (-10 %); with the sum of the speeds (the
    printed eq. 14) it gave 5.62 N (+46 %). M = 7.8, L = 21."""
    from thermobearing.ehl import solve_line_contact

    e, r, l, eta, alpha, u, q = 2.28e11, 5.633e-3, 0.013, 0.02917, 2.183e-8, 7.521, 2412.2
    sol = solve_line_contact(q / l, r, e, u, eta, alpha=alpha, compressible=False, n=512)
    numerical = abs(float(np.trapezoid(sol.pressure * np.gradient(sol.film, sol.x), sol.x))) * l
    assert numerical == pytest.approx(3.87, rel=0.02)
    mean = float(raceway.rolling_force_paper000(u, eta, alpha, e, r, l))
    assert mean == pytest.approx(3.46, rel=0.01)
    assert mean == pytest.approx(numerical, rel=0.15)
    summed = float(raceway.rolling_force_paper000(2.0 * u, eta, alpha, e, r, l))
    assert summed > 1.4 * numerical


def test_rigid_isoviscous_rolling_force_by_hand():
    # Martin: h0 = 2.448 eta U R / w; Q_x = k_q eta U l sqrt(R/h0)
    from thermobearing.skidding.roller_fluid import martin_coefficients

    k_w, k_q, _, _ = martin_coefficients()
    assert k_w == pytest.approx(2.448, rel=1e-3)
    eta, u, r, l, q = 0.05, 20.0, 5e-3, 0.01, 10.0
    h0 = k_w * eta * u * r / (q / l)
    got = raceway.rolling_force_rigid_isoviscous(u, eta, q, r, l)
    assert float(got) == pytest.approx(k_q * eta * u * l * np.sqrt(r / h0), rel=1e-12)


def test_rolling_resistance_heat_is_qx_u(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    # the isothermal closed forms by hand (the default reduces them by Gupta's phi_T)
    ctx = make_context(qj1044, vg46, op, ks, options={
        "ehl_rolling_resistance": {"thermal_reduction": "none"}})
    with pytest.warns(ValidityWarning, match="line-contact"):
        r = raceway.ehl_rolling_resistance(ctx)
    cs = ks.contact("inner")
    qx = r.forces["inner_rolling_force"]
    # no sliding under race control: heat = Q_x u (module docstring)
    assert r.components["inner rolling resistance, load"] == pytest.approx(
        float(np.sum(qx * cs.entrainment_speed)), rel=1e-12)
    assert sum(p.power for p in r.force_pairs) == pytest.approx(r.total, rel=1e-12)
    # Dowson-Higginson (eq. 35) takes the mean speed in U, Martin's rigid film the sum (2u
    # under rolling)
    loaded = cs.normal_load > 0
    eta = float(vg46.dynamic_viscosity(cs.temperature[0]))
    alpha = float(vg46.pressure_viscosity_coefficient(cs.temperature[0]))
    length = np.pi * cs.semi_major / 2
    q_dh = raceway.rolling_force_paper000(cs.entrainment_speed, eta, alpha,
                                          qj1044.effective_modulus, cs.reduced_radius_x, length)
    q_ri = raceway.rolling_force_rigid_isoviscous(2 * cs.entrainment_speed, eta, cs.normal_load,
                                                  cs.reduced_radius_x, length)
    np.testing.assert_allclose(qx[loaded], np.minimum(q_dh, q_ri)[loaded], rtol=1e-12)


def test_rolling_resistance_thermal_reduction(qj1044, vg46, race_control_state):
    op, ks = race_control_state
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        iso = raceway.ehl_rolling_resistance(make_context(qj1044, vg46, op, ks, options={
            "ehl_rolling_resistance": {"thermal_reduction": "none"}})).total
        hot = raceway.ehl_rolling_resistance(make_context(qj1044, vg46, op, ks, options={
            "ehl_rolling_resistance": {"thermal_reduction": "gupta_1992"}})).total
    assert 0 < hot < iso
    from thermobearing.errors import UnknownNameError

    with pytest.raises(UnknownNameError):
        raceway.ehl_rolling_resistance(make_context(qj1044, vg46, op, ks, options={
            "ehl_rolling_resistance": {"thermal_reduction": "magic"}}))


def test_paper002_eq11_taken_literally_is_unbounded():
    # Paper 002 eq. 11 with a Newtonian film at the Hertz-pressure (Barus) viscosity:
    # Q = (dU^2 / h) * eta0 * int exp(alpha p) dA = (dU^2/h) eta0 2 pi a b [e^c (c-1) + 1]/c^2,
    # c = alpha p0 (closed form, see test_contact_traction). For a QJ1044-size contact
    # (Q = 2 kN, a = 2 mm, b = 0.3 mm, p0 = 1.6 GPa, alpha = 2e-8, eta0 = 0.03 Pa s,
    # h = 1 um, dU = 1 m/s) that is ~2e11 W, against ~1e2 W from a limiting-shear law.
    q, a, b, eta0, alpha, h, du = 2000.0, 2e-3, 3e-4, 0.03, 2e-8, 1e-6, 1.0
    p0 = 3 * q / (2 * math.pi * a * b)
    c = alpha * p0
    literal = du ** 2 / h * eta0 * 2 * math.pi * a * b * (math.exp(c) * (c - 1) + 1) / c ** 2
    bounded = 0.075 * q * du  # tau <= Lambda p everywhere -> heat <= Lambda Q dU
    assert literal > 1e7 * bounded


@pytest.mark.parametrize("t_outer, stacked", [(330.0, True), ("ramp", False)])
def test_stacked_integration_equals_set_by_set(qj1044, vg46, race_control_state, monkeypatch,
                                                t_outer, stacked):
    """The source integrates all contact sets of one kind at one temperature in one call;
    per contact the heat and the generalized forces equal integrate_contact_set set by
    set, bit for bit (film law, race-control films, sets that differ); sets at different
    temperatures are integrated set by set (a film law's viscosity source may differ)."""
    from thermobearing.contact_traction import integrate_contact_set

    op, ks = race_control_state
    law = make_traction_law("eyring_limiting_shear", lubricant=vg46)
    z = qj1044.n_elements
    inner, outer = ks.contacts
    t2 = np.linspace(320.0, 340.0, z) if t_outer == "ramp" else t_outer
    sets = (inner.with_(temperature=330.0),
            outer.with_(temperature=t2, sliding_speed=np.linspace(-0.3, 0.4, z)))
    ctx = make_context(qj1044, vg46, op, ks.with_(contacts=sets), traction=law)
    calls = []
    real = raceway.integrate
    monkeypatch.setattr(raceway, "integrate", lambda *a, **k: calls.append(1) or real(*a, **k))
    r = raceway.raceway_traction(ctx)
    assert len(calls) == (1 if stacked else 0)
    for cs in sets:
        ref = integrate_contact_set(law, cs, n_major=16, n_minor=8)
        assert r.components[f"{cs.race} contact"] == float(np.sum(ref.heat))
        np.testing.assert_array_equal(r.forces[f"{cs.race}_generalized_force"],
                                      ref.generalized_force)


def test_precomputed_tractions_are_used_only_when_they_match(qj1044, vg46, race_control_state):
    """A contact set carrying its producer's tractions (ContactSet.traction) is not
    integrated again when the law object and the quadrature match and the set has its
    temperature; a different law, quadrature or a field changed through with_() integrates
    anew (with_ drops the stale tractions)."""
    from thermobearing.contact_traction import ContactTraction, integrate_contact_set
    from thermobearing.state import PrecomputedTraction

    op, ks = race_control_state
    law = make_traction_law("eyring_limiting_shear", lubricant=vg46)
    sets = tuple(cs.with_(temperature=330.0) for cs in ks.contacts)
    exact = [integrate_contact_set(law, cs, n_major=16, n_minor=8) for cs in sets]
    # a marked copy (twice the true values) shows which path ran
    marked = [ContactTraction(*(2.0 * getattr(r, f) for f in (
        "transverse_force", "rolling_force", "moment_transverse", "moment_rolling",
        "moment_normal", "heat"))) for r in exact]

    def run(carried, law_used=law):
        state = ks.with_(contacts=carried)
        return raceway.raceway_traction(make_context(qj1044, vg46, op, state,
                                                     traction=law_used))

    with_pre = tuple(cs.with_(traction=PrecomputedTraction(law, 16, 8, m))
                     for cs, m in zip(sets, marked, strict=True))
    base = run(sets).total
    assert base == pytest.approx(sum(float(np.sum(r.heat)) for r in exact), rel=1e-14)
    assert run(with_pre).total == pytest.approx(2.0 * base, rel=1e-14)
    other = make_traction_law("eyring_limiting_shear", lubricant=vg46)
    assert run(with_pre, other).total == pytest.approx(base, rel=1e-14)
    coarse = tuple(cs.with_(traction=PrecomputedTraction(law, 8, 4, m))
                   for cs, m in zip(sets, marked, strict=True))
    assert run(coarse).total == pytest.approx(base, rel=1e-14)
    moved = tuple(cs.with_(sliding_speed=cs.sliding_speed) for cs in with_pre)
    assert all(cs.traction is None for cs in moved)
    assert run(moved).total == pytest.approx(base, rel=1e-14)
    with pytest.raises(InputError, match="traction"):
        sets[0].with_(traction=marked[0])


def test_rolling_resistance_with_a_surface_running_backwards(qj1044, vg46, race_control_state):
    """Gross sliding (u_e = 22.5 m/s, u_r = -2.5 m/s): the Poiseuille shear Q_x/2 acts on
    both surfaces against the entrainment, as the skidding solvers balance it, so its work
    is Q_x |u_e + u_r| / 2 = Q_x u_m and the force pairs' power is the booked heat. Booked
    surface by surface against each surface's own speed it was Q_x (|u_e| + |u_r|) / 2,
    Q_x/2 x 5 m/s more, a jump of Q_x where a surface speed crosses zero."""
    op, _ = race_control_state
    z = qj1044.n_elements
    ctx = make_context(qj1044, vg46, op, _sliding_state(z, slide=25.0))
    with pytest.warns(ValidityWarning, match="line-contact"):
        r = raceway.ehl_rolling_resistance(ctx)
    qx = r.forces["inner_rolling_force"]
    assert np.all(qx > 0)
    assert r.components["inner rolling resistance, load"] == pytest.approx(
        float(np.sum(qx * 10.0)), rel=1e-12)
    assert sum(p.power for p in r.force_pairs) == pytest.approx(r.total, rel=1e-12)
