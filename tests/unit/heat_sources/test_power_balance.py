"""Must-show: for any kinematic state, the heat of every source equals the power of its force
pairs (force x relative sliding speed), to 1e-9 relative (hypothesis over random states)."""

from __future__ import annotations

import warnings

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import ValidityWarning
from thermobearing.heat_sources import HEAT_SOURCES, evaluate
from thermobearing.state import ContactSet, KinematicState
from thermobearing.traction import make_traction_law

from .conftest import make_context

SOURCES = ["raceway_traction", "ehl_rolling_resistance", "churning_cage", "churning_elements",
           "churning_inner_ring", "cage_guide", "pocket_friction"]


def _random_state(rng, z):
    contacts = []
    for race in ("inner", "outer"):
        load = rng.uniform(0, 5000, z) * (rng.uniform(size=z) > 0.2)
        a = rng.uniform(1.5e-4, 3e-4, z) * np.cbrt(load)
        contacts.append(ContactSet(
            race=race, normal_load=load, semi_major=a, semi_minor=a * rng.uniform(0.1, 0.5, z),
            max_pressure=1e9, contact_angle=rng.uniform(0.3, 1.0, z),
            entrainment_speed=rng.uniform(1, 20, z), sliding_speed=rng.normal(0, 1, z),
            transverse_sliding_speed=rng.normal(0, 0.3, z), spin_speed=rng.normal(0, 100, z),
            roll_speed=rng.normal(0, 800, z), tilt_speed=rng.normal(0, 50, z),
            deformed_radius=rng.uniform(0.01, 0.05, z), film_thickness=rng.uniform(1e-7, 2e-6, z),
            temperature=rng.uniform(300, 380, z)))
    cage = rng.uniform(-100, 100)
    return KinematicState(
        inner_speed=rng.uniform(50, 250), outer_speed=rng.uniform(-20, 20), cage_speed=cage,
        orbital_speed=cage + rng.normal(0, 5, z), element_spin=rng.normal(-500, 200, z),
        contacts=tuple(contacts), pocket_normal_force=rng.uniform(0, 300, z),
        cage_eccentricity=rng.uniform(0, 0.99), origin="skidding")


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), law=st.sampled_from(["coulomb", "adore", "eyring"]))
def test_heat_equals_force_times_sliding_speed(qj1044, vg46, race_control_state, seed, law):
    rng = np.random.default_rng(seed)
    op, _ = race_control_state
    ks = _random_state(rng, qj1044.n_elements)
    traction = {
        "coulomb": make_traction_law("linear_saturating", mu_max=0.07, slip_speed_max=0.2),
        "adore": make_traction_law("four_parameter", mu_zero=0.01, mu_max=0.06,
                                   slip_speed_at_max=0.5, mu_infinity=0.03),
        "eyring": make_traction_law("eyring_limiting_shear", lubricant=vg46),
    }[law]
    ctx = make_context(qj1044, vg46, op, ks, traction=traction, options={
        "pocket_friction": {"friction_coefficient": float(rng.uniform(0, 1))},
        "churning_elements": {"form": str(rng.choice(["paper002", "harris"]))}})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        results = evaluate(SOURCES, ctx)
    heat = sum(r.total for r in results)
    pairs = sum(p.power for r in results for p in r.force_pairs)
    assert heat > 0
    assert abs(heat - pairs) <= 1e-9 * heat
    for r in results:  # and source by source
        assert abs(r.total - sum(p.power for p in r.force_pairs)) <= 1e-9 * max(heat, 1.0)


def test_all_my_sources_are_in_the_balance():
    assert set(SOURCES) <= set(HEAT_SOURCES)
