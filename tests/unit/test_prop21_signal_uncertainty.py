"""Property tests of the line-frequency uncertainty (:mod:`thermobearing.signal_uncertainty`,
session 21).

:func:`combined_frequency_std` (weighted mean, its variance sum w^2 s^2 / (sum w)^2, Birge
ratio sqrt(chi^2 / (n - 1))):

- invariant under a common factor of the weights and under a permutation of the lines;
- equivariant: shifting every estimate by c shifts the mean by c and leaves the
  uncertainty; scaling estimates and sigmas by c scales the mean and the uncertainty by c;
- inverse-variance weights give the textbook statistical error 1 / sqrt(sum 1 / s^2);
- the mean lies between the smallest and the largest estimate, the uncertainty is at least
  the statistical one;
- a non-finite estimate or weight is an InputError naming the field: a NaN estimate gave a
  NaN mean with a finite uncertainty (max(1, NaN) = 1 dropped the Birge ratio).

:func:`line_frequency_std`: c_H / (T sqrt(R - 1)) falls as 1 / T and as 1 / sqrt(R - 1).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import InputError
from thermobearing.signal_uncertainty import (
    HANN_PEAK,
    combined_frequency_std,
    line_frequency_std,
)


@st.composite
def lines(draw):
    n = draw(st.integers(1, 8))
    est = draw(st.lists(st.floats(1.0, 100.0), min_size=n, max_size=n))
    sig = draw(st.lists(st.floats(1e-4, 1.0), min_size=n, max_size=n))
    wts = draw(st.lists(st.floats(0.1, 100.0), min_size=n, max_size=n))
    return np.array(est), np.array(sig), np.array(wts)


def _same(a, b, rel=1e-10):
    for field in ("value", "std", "statistical", "birge"):
        x, y = getattr(a, field), getattr(b, field)
        assert x == pytest.approx(y, rel=rel, abs=1e-12 * max(1.0, abs(y))), field


@settings(max_examples=80, deadline=None)
@given(case=lines(), factor=st.floats(1e-3, 1e3), seed=st.integers(0, 2**31 - 1))
def test_weights_scale_and_line_order_do_not_matter(case, factor, seed):
    e, s, w = case
    ref = combined_frequency_std(e, s, w)
    _same(combined_frequency_std(e, s, factor * w), ref)
    order = np.random.default_rng(seed).permutation(e.size)
    _same(combined_frequency_std(e[order], s[order], w[order]), ref)


@settings(max_examples=80, deadline=None)
@given(case=lines(), shift=st.floats(-50.0, 50.0), scale=st.floats(1e-3, 1e3))
def test_shift_and_scale_equivariance(case, shift, scale):
    e, s, w = case
    ref = combined_frequency_std(e, s, w)
    moved = combined_frequency_std(e + shift, s, w)
    assert moved.value == pytest.approx(ref.value + shift, rel=1e-12, abs=1e-9)
    assert moved.statistical == pytest.approx(ref.statistical, rel=1e-12)
    # the Birge ratio of a shifted set: the same residuals up to the round-off of the shift
    resolution = 1e-14 * float(np.max(np.abs(e)) + abs(shift)) / float(np.min(s)) * e.size
    assert moved.birge == pytest.approx(ref.birge, rel=1e-6, abs=resolution)
    scaled = combined_frequency_std(scale * e, scale * s, w)
    assert scaled.value == pytest.approx(scale * ref.value, rel=1e-12)
    assert scaled.std == pytest.approx(scale * ref.std, rel=1e-10)
    # chi^2 of residuals at round-off (equal estimates): eps |e| / s each
    resolution = 1e-14 * float(np.max(np.abs(e)) / np.min(s)) * e.size
    assert scaled.birge == pytest.approx(ref.birge, rel=1e-10, abs=resolution)


@settings(max_examples=80, deadline=None)
@given(case=lines())
def test_bounds_and_inverse_variance_weights(case):
    e, s, w = case
    out = combined_frequency_std(e, s, w)
    assert e.min() * (1 - 1e-15) <= out.value <= e.max() * (1 + 1e-15)
    assert out.std >= out.statistical
    assert out.n == e.size
    inv = combined_frequency_std(e, s, 1.0 / s**2)
    assert inv.statistical == pytest.approx(1.0 / math.sqrt(float(np.sum(1.0 / s**2))),
                                            rel=1e-12)


@pytest.mark.parametrize(("field", "args"), [
    ("estimates", ([math.nan, 1.0], [1.0, 1.0], [1.0, 1.0])),
    ("estimates", ([math.inf, 1.0], [1.0, 1.0], [1.0, 1.0])),
    ("weights", ([1.0, 1.0], [1.0, 1.0], [math.nan, 1.0])),
    ("weights", ([1.0, 1.0], [1.0, 1.0], [math.inf, 1.0])),
    ("weights", ([1.0, 1.0], [1.0, 1.0], [0.0, 1.0])),
    ("sigmas", ([1.0, 1.0], [math.nan, 1.0], [1.0, 1.0])),
])
def test_non_finite_inputs_name_their_field(field, args):
    with pytest.raises(InputError, match=field):
        combined_frequency_std(*args)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(1.001, 1e8), t=st.floats(0.01, 100.0), k=st.floats(1.5, 10.0))
def test_line_std_scales_with_duration_and_snr(r, t, k):
    base = line_frequency_std(r, t)
    assert base == pytest.approx(HANN_PEAK / (t * math.sqrt(r - 1.0)), rel=1e-12)
    assert line_frequency_std(r, k * t) == pytest.approx(base / k, rel=1e-12)
    assert line_frequency_std(1.0 + k * k * (r - 1.0), t) == pytest.approx(base / k, rel=1e-9)
    assert line_frequency_std(1.0, t) == math.inf
