"""Cage-guide source: paper 002 eqs. 1-5 by hand (Petroff/Ocvirk), regimes, eccentricity solve."""

from __future__ import annotations

import math

import pytest

from thermobearing.errors import InputError
from thermobearing.heat_sources import cage_guide as cg

from .conftest import make_context, uniform_state


def test_petroff_torque_by_hand():
    # eq. 5 (consistent form): M = pi eta D^3 dw B / (4 c sqrt(1-eps^2))
    # eta 0.03, D 0.3, dw 100, B 0.01, c 3e-4, eps 0: pi*0.03*0.027*100*0.01/(1.2e-3) = 2.1206
    m = cg.land_drag_torque(0.03, 0.3, 100.0, 0.0, 0.01, 3e-4, 0.0)
    assert m == pytest.approx(math.pi * 0.03 * 0.027 * 100 * 0.01 / 1.2e-3, rel=1e-12)
    assert m == pytest.approx(2.1206, rel=1e-4)
    # eps = 0.6: divided by sqrt(1 - 0.36) = 0.8
    assert cg.land_drag_torque(0.03, 0.3, 100.0, 0.0, 0.01, 3e-4, 0.6) == pytest.approx(m / 0.8)


def test_ocvirk_forces_by_hand():
    # eq. 4 with eps = 0.5: F_t = pi eta D s B^3 eps / (8 c^2 (0.75)^1.5), s = w_g + w_c
    f = cg.short_bearing_forces(0.03, 0.3, 0.0, 80.0, 0.01, 3e-4, 0.5)
    s = 0.3 * 80.0
    assert f.tangential == pytest.approx(math.pi * 0.03 * s * 1e-6 * 0.5 / (8 * 9e-8 * 0.75 ** 1.5))
    assert f.radial == pytest.approx(0.03 * s * 1e-6 * 0.25 / (2 * 9e-8 * 0.75 ** 2))
    with pytest.raises(InputError):
        cg.short_bearing_forces(0.03, 0.3, 0.0, 80.0, 0.01, 3e-4, 1.0)


def test_contact_force_eq1():
    # eq. 1: F = E B^(8/9)/4 (delta/0.39)^(10/9); E = 1e11, B = 0.01, delta = 1e-6
    f = cg.contact_force(1e11, 0.01, 1e-6)
    assert f == pytest.approx(1e11 * 0.01 ** (8 / 9) / 4 * (1e-6 / 0.39) ** (10 / 9))
    assert cg._penetration_for_force(1e11, 0.01, f) == pytest.approx(1e-6, rel=1e-9)
    assert cg.contact_force(1e11, 0.01, -1e-6) == 0.0


def test_source_hydrodynamic_centred(qj1044, vg46, race_control_state):
    op, _ = race_control_state
    ks = uniform_state(qj1044.n_elements, cage_speed=85.0)
    r = cg.cage_guide(make_context(qj1044, vg46, op, ks))
    cage = qj1044.cage
    eta = float(vg46.dynamic_viscosity(318.15))
    m = cg.land_drag_torque(eta, cage.guide_land_diameter, 0.0, 85.0, cage.land_width,
                            cage.guide_clearance / 2, 0.0)
    assert r.total == pytest.approx(abs(m) * 85.0, rel=1e-12)
    assert r.power_by_role == {"outer_ring": pytest.approx(r.total), "cage": 0.0}
    assert r.details["regime"] == "hydrodynamic"
    assert r.force_pairs[0].power == pytest.approx(r.total, rel=1e-12)


def test_source_load_sets_eccentricity_or_contact(qj1044, vg46, race_control_state):
    op, _ = race_control_state
    ks = uniform_state(qj1044.n_elements, cage_speed=85.0)
    light = cg.cage_guide(make_context(qj1044, vg46, op, ks,
                                       options={"cage_guide": {"load": 50.0}}))
    assert light.details["regime"] == "hydrodynamic"
    assert 0 < light.details["eccentricity_ratio"] < 1
    assert light.details["film_force"] == pytest.approx(50.0, rel=1e-8)
    heavy = cg.cage_guide(make_context(qj1044, vg46, op, ks,
                                       options={"cage_guide": {"load": 1e7}}))
    assert heavy.details["regime"] == "contact"
    d_g = qj1044.cage.guide_land_diameter
    assert heavy.total == pytest.approx(0.1 * 1e7 * d_g / 2 * 85.0, rel=1e-12)


def test_bad_friction_coefficient(qj1044, vg46, race_control_state):
    op, _ = race_control_state
    ks = uniform_state(qj1044.n_elements)
    with pytest.raises(InputError, match="boundary_friction"):
        cg.cage_guide(make_context(qj1044, vg46, op, ks,
                                   options={"cage_guide": {"boundary_friction": 1.5}}))
    with pytest.raises(InputError, match="friction_coefficient"):
        cg.cage_guide(make_context(qj1044, vg46, op, ks,
                                   options={"cage_guide": {"form": "paper002_eq18"}}))
