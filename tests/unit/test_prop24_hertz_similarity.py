"""Property tests, round 6: dimensional similarity of the Hertz contacts
(:mod:`thermobearing.hertz`, session 24), beside the load power laws of
test_property_contact.py, the principal-direction symmetry of test_prop19_hertz_film.py and
the limits of test_prop20_hertz_loads.py.

Hertz theory (Johnson 1985, sec. 4.2; Hamrock, Schmid & Jacobson 2004, ch. 17) has no
length or stress of its own: with every length (radii, contact and crown lengths) scaled by
L and the modulus by E, a load scaled by E L^2 gives the same contact scaled, half-axes
and half-width by L, pressure by E, approach by L, ellipticity unchanged, for every method
(the exact solution and the Hamrock-Brewe and Brewe-Hamrock fits are functions of
R_y / R_x alone). Palmgren's roller approach delta = 3.84e-5 Q^0.9 l^-0.8 (mm, N; steel)
is an empirical law for one modulus: it scales as L^(1.8 - 0.8) = L with the load E L^2 at
E = 1 only, and so does the sliced roller built on it (slice loads by L^2, line loads by L,
approach and loaded length by L, the line-contact pressure unchanged).

Defect found (hertz.sliced_roller_contact, fixed): an uncrowned roller whose straight part
ends on a slice centre (l_s / 2 = (k + 1/2) w: 10 slices, l_s = 0.3 L) let the round-off of
the centre and of l_s / 2 decide whether the two end slices carried load, so the same roller
scaled in size had its approach 30 % apart (31.25 mm roller, 10 N: 5.74e-8 m with 3 slices
loaded, one end slice in and the other out; scaled by 0.0234: 4.43e-8 m x 0.0234 with 4).
A centre on the end within round-off now counts as on the straight part, at every size.

Asserted to 1e-12 relative (round-off: 700 draws of each property passed at that
tolerance, scratch); scale factors 1e-2..1e2.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from thermobearing import hertz

EP = 2.28e11  # E' of steel on steel [Pa]
scales = st.floats(1e-2, 1e2)
REL = 1e-12


def _close(got, ref) -> None:
    np.testing.assert_allclose(np.asarray(got, float), np.asarray(ref, float), rtol=REL,
                               atol=0.0)


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")
@settings(max_examples=60, deadline=None)
@given(q=st.floats(1.0, 1e5), rx=st.floats(1e-3, 5e-2), ratio=st.floats(1.0, 60.0),
       method=st.sampled_from(["exact", "hamrock_brewe", "brewe_hamrock_1977"]),
       length=scales, modulus=scales)
def test_a_similar_point_contact_is_the_contact_scaled(q, rx, ratio, method, length, modulus):
    ref = hertz.point_contact(q, rx, rx * ratio, EP, method=method)
    got = hertz.point_contact(q * modulus * length**2, rx * length, rx * ratio * length,
                              EP * modulus, method=method)
    _close(got.a, length * ref.a)
    _close(got.b, length * ref.b)
    _close(got.max_pressure, modulus * ref.max_pressure)
    _close(got.approach, length * ref.approach)
    _close(got.ellipticity, ref.ellipticity)
    _close(hertz.point_contact_stiffness(rx * length, rx * ratio * length, EP * modulus,
                                         method=method),
           modulus * length**0.5 * hertz.point_contact_stiffness(rx, rx * ratio, EP,
                                                                 method=method))


@pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")
@settings(max_examples=60, deadline=None)
@given(q=st.floats(1.0, 1e5), rx=st.floats(1e-3, 5e-2), contact=st.floats(5e-3, 5e-2),
       crown=st.one_of(st.none(), st.floats(0.05, 5.0)), length=scales,
       modulus=st.one_of(st.just(1.0), scales))
def test_a_similar_line_contact_is_the_contact_scaled(q, rx, contact, crown, length, modulus):
    """Straight and crowned (elliptical while 2a < l) contacts; the approach at E = 1 only
    (Palmgren)."""
    ref = hertz.line_contact(q, contact, rx, EP, crown_radius=crown)
    got = hertz.line_contact(q * modulus * length**2, contact * length, rx * length,
                             EP * modulus, crown_radius=None if crown is None else crown * length)
    _close(got.half_width, length * ref.half_width)
    _close(got.max_pressure, modulus * ref.max_pressure)
    _close(got.contact_length, length * ref.contact_length)
    assert bool(got.point_regime) == bool(ref.point_regime)
    if modulus == 1.0:
        _close(got.approach, length * ref.approach)


@settings(max_examples=30, deadline=None)
@example(q=10.0, total=0.03125, straight=0.3, crown=None, rx=0.015625, slices=10,
         length=0.0234375)
@given(q=st.floats(10.0, 1e5), total=st.floats(5e-3, 5e-2), straight=st.floats(0.3, 1.0),
       crown=st.one_of(st.none(), st.floats(0.05, 5.0)), rx=st.floats(2e-3, 3e-2),
       slices=st.integers(5, 41), length=scales)
def test_a_similar_sliced_roller_is_the_roller_scaled(q, total, straight, crown, rx, slices,
                                                      length):
    ref = hertz.sliced_roller_contact(q, total, straight * total, crown, rx, EP,
                                      n_slices=slices)
    got = hertz.sliced_roller_contact(q * length**2, total * length, straight * total * length,
                                      None if crown is None else crown * length, rx * length,
                                      EP, n_slices=slices)
    _close(got.approach, length * ref.approach)
    np.testing.assert_allclose(got.slice_centres, length * np.asarray(ref.slice_centres),
                               rtol=0, atol=REL * length * total)   # the centre slice at 0
    np.testing.assert_allclose(got.slice_loads, length**2 * np.asarray(ref.slice_loads),
                               rtol=0, atol=REL * length**2 * q)
    _close(got.max_line_load, length * ref.max_line_load)
    _close(got.max_pressure, ref.max_pressure)
    _close(got.loaded_length, length * ref.loaded_length)


@pytest.mark.parametrize("size", [1.0, 0.0234375, 3.0, 0.1])
def test_an_end_slice_centred_on_the_straight_ends_carries_load_at_every_size(size):
    """The module docstring's roller: four of ten slices loaded at every size, each with a
    quarter of the load, so Q / 4 = K_l(L) (w / L) delta^(10/9) (the slice law)."""
    q, total = 10.0 * size**2, 0.03125 * size
    r = hertz.sliced_roller_contact(q, total, 0.009375 * size, None, 0.015625 * size, EP,
                                    n_slices=10)
    assert np.count_nonzero(r.slice_loads) == 4
    assert r.loaded_length == pytest.approx(0.4 * total, rel=1e-12)
    k_slice = float(hertz.line_contact_stiffness(total, EP)) / 10.0
    assert r.approach == pytest.approx((q / (4.0 * k_slice)) ** 0.9, rel=1e-12)
