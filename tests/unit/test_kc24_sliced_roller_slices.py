"""hertz.sliced_roller_contact takes any integer slice count >= 5, odd or even (its check
and its docstring agree): the slices are elastically uncoupled and centred at
x_k = (k + 1/2) w - L/2, so parity only decides whether a slice sits at x = 0."""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing import hertz
from thermobearing.errors import InputError

EP = 2.28e11


@pytest.mark.parametrize("n", [5, 6, 10, 41, 42])
def test_a_straight_roller_is_palmgren_at_any_slice_count(n):
    # l_s = L: every slice on the straight part, sum_k (w / L) K_l delta^(10/9) = K_l
    # delta^(10/9) (Palmgren's law, the docstring's exactness claim) at odd and even n
    q, length = 2000.0, 0.0108
    r = hertz.sliced_roller_contact(q, length, length, None, 5.5e-3, EP, n_slices=n)
    k_l = float(hertz.line_contact_stiffness(length, EP))
    assert r.approach == pytest.approx((q / k_l) ** 0.9, rel=1e-12)
    assert np.count_nonzero(r.slice_loads) == n
    np.testing.assert_allclose(r.slice_loads, q / n, rtol=1e-12)


@pytest.mark.parametrize("n", [6, 7])
def test_a_crowned_point_middle_carries_the_load_at_either_parity(n):
    # a fully crowned roller (straight part 1 nm): the odd count loads its middle slice at
    # x = 0 first, the even count its two middle slices at +-w/2 (drop (w/2)^2 / (2 R_c))
    q, length, crown = 5.0, 0.01, 1.0
    r = hertz.sliced_roller_contact(q, length, 1e-9, crown, 5e-3, EP, n_slices=n)
    assert float(np.sum(r.slice_loads)) == pytest.approx(q, rel=1e-12)
    loads = np.asarray(r.slice_loads)
    top = np.flatnonzero(loads == loads.max())
    assert list(top) == ([n // 2] if n % 2 else [n // 2 - 1, n // 2])


@pytest.mark.parametrize("bad", [4, 0, -7, 5.0, 7.5, True, "9", None])
def test_a_slice_count_that_is_not_an_integer_of_at_least_5_is_refused(bad):
    with pytest.raises(InputError, match=r"n_slices.*integer >= 5"):
        hertz.sliced_roller_contact(100.0, 0.01, 0.01, None, 5e-3, EP, n_slices=bad)


def test_an_even_count_with_no_slice_on_a_short_straight_part_names_it():
    # uncrowned, l_s shorter than a slice: 6 slices have no centre on it, 7 have the middle
    with pytest.raises(InputError, match="straight_length"):
        hertz.sliced_roller_contact(100.0, 0.012, 1e-3, None, 5e-3, EP, n_slices=6)
    r = hertz.sliced_roller_contact(100.0, 0.012, 1e-3, None, 5e-3, EP, n_slices=7)
    assert np.count_nonzero(r.slice_loads) == 1
