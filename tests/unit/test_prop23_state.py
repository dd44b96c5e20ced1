"""Property tests, round 5: the contact-set record of :mod:`thermobearing.state`.

Invariant (the project's bad-input rule, and the physics of each field): a
:class:`ContactSet` accepts every physically possible set of per-element arrays and refuses
every impossible one with an :class:`InputError` naming that field. Allowed: loads, Hertz
half-axes, pressure and film >= 0 and finite; speeds and angles any finite value; a
temperature > 0 K; the deformed radius and R_y > 0 with ``inf`` for a flat / straight
surface; R_x = 1/(1/r_element + 1/r_race) finite and > 0 (Hertz 1881: both bodies convex in
the rolling direction, or a ball in a larger concave ring; no bearing contact is flat there).
Before session 23 an R_x of 0 or -1 m was accepted while R_y's was refused.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import InputError
from thermobearing.state import ContactSet

_NON_NEGATIVE = ("normal_load", "semi_major", "semi_minor", "max_pressure", "film_thickness")
_FREE = ("contact_angle", "entrainment_speed", "sliding_speed", "transverse_sliding_speed",
         "spin_speed", "roll_speed", "tilt_speed")
_FLAT_ALLOWED = ("deformed_radius", "reduced_radius_y")
_POSITIVE = ("temperature", "reduced_radius_x")
_FIELDS = _NON_NEGATIVE + _FREE + _FLAT_ALLOWED + _POSITIVE


def _allowed(name: str, v: float) -> bool:
    if math.isnan(v):
        return False
    if name in _FLAT_ALLOWED:
        return v > 0.0
    if math.isinf(v):
        return False
    if name in _NON_NEGATIVE:
        return v >= 0.0
    if name in _POSITIVE:
        return v > 0.0
    return True


def _valid(n: int, rng: np.random.Generator) -> dict:
    out = {name: rng.uniform(0.0, 2.0, n) for name in _NON_NEGATIVE}
    out.update({name: rng.uniform(-5.0, 5.0, n) for name in _FREE})
    out.update({name: rng.uniform(1e-3, 1.0, n) for name in _FLAT_ALLOWED + _POSITIVE})
    return out


@settings(max_examples=200, deadline=None)
@given(st.integers(1, 6), st.integers(0, 2**32 - 1), st.sampled_from(_FIELDS),
       st.sampled_from([0.0, -0.0, -1.0, 1.0, 1e300, -1e300, math.inf, -math.inf, math.nan]),
       st.data(), st.sampled_from(["inner", "outer", "inner_2"]))
def test_one_field_is_refused_by_name_exactly_when_it_is_impossible(n, seed, name, bad, data,
                                                                    race):
    """A valid set with one entry of one field replaced by ``bad``: accepted when ``bad`` is
    allowed for that field, else InputError naming contacts[race].field."""
    rng = np.random.default_rng(seed)
    fields = _valid(n, rng)
    i = data.draw(st.integers(0, n - 1))
    fields[name][i] = bad
    if _allowed(name, bad):
        cs = ContactSet(race=race, **fields)
        assert cs.n_elements == n
        np.testing.assert_array_equal(getattr(cs, name), fields[name])
        return
    with pytest.raises(InputError) as info:
        ContactSet(race=race, **fields)
    assert info.value.field == f"contacts[{race}].{name}"


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 6), st.integers(0, 2**32 - 1))
def test_slide_to_roll_is_sliding_over_entrainment_and_zero_at_rest(n, seed):
    """SRR = V_y / u where u != 0, 0 where u = 0 (the contract of slide_to_roll)."""
    rng = np.random.default_rng(seed)
    fields = _valid(n, rng)
    fields["entrainment_speed"][rng.random(n) < 0.3] = 0.0
    cs = ContactSet(race="outer", **fields)
    u, v = fields["entrainment_speed"], fields["sliding_speed"]
    expect = np.where(u != 0.0, v / np.where(u != 0.0, u, 1.0), 0.0)
    np.testing.assert_allclose(cs.slide_to_roll, expect, rtol=1e-15, atol=0)
