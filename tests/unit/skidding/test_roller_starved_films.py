"""Tests of the film-supported roller load distribution with a finite inlet oil layer
(loads_roller.roller_film_load_distribution with films that cannot fill every gap,
roller_fluid.starved_film, build_model(ring_support="films", oil_layer=...))."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.hertz import line_contact_stiffness
from thermobearing.loads_roller import roller_film_load_distribution
from thermobearing.skidding.roller import build_model, solve_model
from thermobearing.skidding.roller_fluid import (
    closed_form_contact_forces,
    rigid_starved_film,
    starved_film,
)

OMEGA = 5000.0 * math.pi / 30.0  # paper 000: n_i = 5000 r/min
T = 313.15
L = 0.013  # NU214 roller length (paper 000 Table 1) [m]


def test_starved_film_is_the_film_of_the_contact_forces(nu214, oil):
    # the load distribution and the drag must see one film: starved_film(u_e, w) equals the
    # h_c closed_form_contact_forces reports with the same oil layer
    m = build_model(nu214, oil, T, viscosity=0.08, limiting_shear_coefficient=1.0)
    q = np.array([0.5, 5.0, 50.0, 500.0])
    u_race = np.full(4, 12.0)
    u_roll = np.full(4, 3.0)
    for layer in (None, 1e-5, 3e-6):
        f = closed_form_contact_forces(q, L, m.radius_inner, m.effective_modulus, u_race,
                                       u_roll, film=m.film_inner, eta0=m.eta0, alpha=m.alpha,
                                       traction_law=m.traction_law, temperature=T,
                                       oil_layer=layer)
        h = starved_film(m.film_inner, m.radius_inner, m.eta0, layer)(
            np.full(4, 0.5 * (12.0 + 3.0)), q / L)
        np.testing.assert_allclose(h, f.film_thickness, rtol=1e-12)
    # starved: never thicker than the flooded film; as w -> 0 the starved rigid film tends
    # to the oil layer and h_c to 1.2257 times it (the closed form scales Moes's central film,
    # whose rigid-isoviscous asymptote is 1.2257 x Martin's k_w film, by the starved ratio;
    # measured here, a known approximation of the closed form)
    hs = starved_film(m.film_inner, m.radius_inner, m.eta0, 1e-5)
    assert np.all(hs(np.full(4, 7.5), q / L) <= m.film_inner(np.full(4, 7.5), q / L))
    assert float(hs(np.array([7.5]), np.array([1e-9]))[0]) == pytest.approx(1.2257e-5,
                                                                             rel=1e-3)
    h_r = rigid_starved_film(np.array([1e-3]), np.array([15.0]), m.radius_inner, m.eta0,
                             1e-5)[0]
    assert h_r[0] < 1e-5


def _films(limit: float):
    """Rigid-isoviscous-like films h = min(c / Q, limit) [m] (thinner with load, at most
    ``limit``: a starved inlet); c = 2e-4 N m gives 4 um at 50 N."""
    return lambda q: np.minimum(2e-4 / np.maximum(q, 1e-300), limit)


def test_films_that_cannot_fill_wide_gaps_leave_rollers_unloaded():
    # P_d = 25 um (NU214), films of at most 5 um per contact: the rollers opposite the load
    # see a gap wider than their two films and carry no inner load; the ring is in
    # equilibrium and every loaded roller's films fill its gap, eq. (3) of the docstring
    z, pd, fr = 18, 2.5e-5, 150.0
    k = float(line_contact_stiffness(L, 2.28e11))
    fb = 7.0  # centrifugal force [N]
    ld = roller_film_load_distribution(z, pd, fr, _films(5e-6), _films(5e-6), k, k,
                                       body_force=fb)
    psi = ld.azimuth
    assert 0 < ld.n_loaded < z
    assert not ld.loaded[z // 2] and ld.inner_load[z // 2] == 0.0
    assert ld.loaded[0]
    np.testing.assert_allclose([np.sum(ld.inner_load * np.cos(psi)),
                                np.sum(ld.inner_load * np.sin(psi))], [fr, 0.0], atol=1e-6)
    gap = 0.5 * pd - ld.ring_displacement[0] * np.cos(psi) - ld.ring_displacement[1] * np.sin(psi)
    on = ld.loaded
    fill = (_films(5e-6)(ld.inner_load[on]) + _films(5e-6)(ld.outer_load[on])
            - ld.inner_deflection[on] - ld.outer_deflection[on])
    np.testing.assert_allclose(fill, gap[on], rtol=1e-6, atol=1e-12)
    # the unloaded rollers' films do not reach across: 2 x 5 um minus the outer approach
    assert np.all(2 * 5e-6 - ld.outer_deflection[~on] < gap[~on])
    # thick films (limit 1 mm) fill every gap: all rollers loaded, as with flooded films
    thick = roller_film_load_distribution(z, pd, fr, _films(1e-3), _films(1e-3), k, k,
                                          body_force=fb)
    assert thick.n_loaded == z


def test_films_too_thin_for_any_gap_rest_the_ring_on_one_roller():
    # films of at most 1 um in a 12.5 um radial clearance: the ring must travel until it
    # closes the gap of the roller under the load (singular Jacobian on the way: nothing
    # is loaded at the centred start, one roller carries everything at the end)
    k = float(line_contact_stiffness(L, 2.28e11))
    ld = roller_film_load_distribution(18, 2.5e-5, 100.0, _films(1e-6), _films(1e-6), k, k,
                                       body_force=1.0)
    assert ld.n_loaded == 1 and ld.inner_load[0] == pytest.approx(100.0, rel=1e-8)
    assert ld.ring_displacement[0] > 1.25e-5 - 2e-6


@pytest.mark.slow  # 10 s
def test_starved_film_supported_bearing_converges_and_keeps_the_energy_balance(nu214, oil):
    # paper 000 NU214, 150 N, 5000 r/min, 0.08 Pa s: with a 10 um oil layer the films no
    # longer reach across the gaps opposite the load (fewer rollers carry inner films than
    # with flooded films); shaft power = dissipation to 1e-8
    opts = dict(viscosity=0.08, limiting_shear_coefficient=1.0, ring_support="films",
                film_pressure="regime_min", pocket_film="two_faces")
    r = solve_model(build_model(nu214, oil, T, oil_layer=1e-5, **opts), OMEGA, 150.0)
    flooded = solve_model(build_model(nu214, oil, T, **opts), OMEGA, 150.0)
    assert r.converged
    assert flooded.extras["n_loaded"] == 18
    assert r.extras["n_loaded"] < 18
    assert np.all(r.inner_load[r.inner_load > 0] > 0.0)
    assert r.shaft_torque * OMEGA == pytest.approx(r.power_loss["total"], rel=1e-8)


@pytest.mark.slow  # 20 s
def test_starved_film_supported_cage_slows_with_load_through_fewer_driven_rollers(nu214, oil):
    # The starved-film mechanism of the paper 000 case (SOURCE.md): with a 10 um oil layer the
    # load moves the ring off centre, the films opposite the load no longer reach across
    # their gaps, fewer rollers are driven and the cage slows from 100 to 200 N (measured
    # 1483.3 -> 1423.4 r/min, 18 -> 15 driven rollers; paper 000 Table 2: 1292.78 ->
    # 1195.46 r/min). Flooded, every roller keeps its inner film and the cage speeds up
    # slightly (1337.5 -> 1345.2 r/min).
    opts = dict(viscosity=0.08, limiting_shear_coefficient=1.0, ring_support="films",
                film_pressure="regime_min", pocket_film="two_faces")
    starved = build_model(nu214, oil, T, oil_layer=1e-5, **opts)
    r100, r200 = (solve_model(starved, OMEGA, f) for f in (100.0, 200.0))
    assert r200.extras["n_loaded"] < r100.extras["n_loaded"]
    assert r200.cage_speed < r100.cage_speed
    flooded = build_model(nu214, oil, T, **opts)
    f100, f200 = (solve_model(flooded, OMEGA, f) for f in (100.0, 200.0))
    assert f100.extras["n_loaded"] == f200.extras["n_loaded"] == 18
    assert f200.cage_speed > f100.cage_speed
