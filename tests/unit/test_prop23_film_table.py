"""Property tests, round 5: the interpolation of :class:`thermobearing.ehl.FilmTable`.

The table answers from node values by multilinear interpolation in (ln w', ln u, SRR, T) of
ln h_c, ln h_min and the other outputs (module docstring of :mod:`thermobearing.ehl.cache`).
Invariants of multilinear interpolation (de Boor 2001, ch. XVII, tensor-product linear
interpolation: a convex combination of the cell's corners, exact on functions linear in each
coordinate):

- a film that is a power law h = C w^a u^b exp(c T) and outputs linear in (ln w, ln u, SRR,
  T) come back exactly (to round-off) anywhere;
- with arbitrary node values every answer lies between the smallest and the largest value
  of the corners it is built from (no overshoot), films included (exp is monotone).

Node values are given through the ``stand_in`` hook, so no EHL solve runs (``solves`` stays 0).
"""

from __future__ import annotations

import math
import zlib

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.ehl import FilmPoint, FilmTable
from thermobearing.lubricant import load_lubricant

LUB = load_lubricant("OIL_4109")
_FIELDS = ("central_film", "minimum_film", "max_pressure", "traction", "rolling_traction",
           "max_temperature_rise")
_points = st.tuples(st.floats(math.log(1e4), math.log(1e6)), st.floats(-1.0, 3.0),
                    st.floats(-0.3, 0.3), st.floats(300.0, 400.0))


def _table(steps):
    load_step, speed_step, srr_step, t_step = steps
    return FilmTable("numerical_ehl", 0.01, 2.2e11, lubricant=LUB, load_step=load_step,
                     speed_step=speed_step, srr_step=srr_step, temperature_step=t_step,
                     temperature_origin=313.15)


_steps = st.tuples(st.floats(1.05, 2.0), st.floats(1.05, 2.0), st.floats(0.005, 0.1),
                   st.floats(1.0, 20.0))


@settings(max_examples=40, deadline=None)
@given(_steps, st.lists(st.floats(-2.0, 2.0), min_size=4, max_size=4),
       st.lists(_points, min_size=1, max_size=20))
def test_power_law_films_and_linear_outputs_come_back_exactly(steps, k, points):
    """h_c = 2e-7 w^k0 u^k1 exp(0.01 k2 T), h_min likewise, the other outputs linear in
    (ln w, ln u, SRR, T): answers equal the law to 1e-9 (relative for the films, of the
    output's scale |lin| <~ 1e3, p ~ 1e10 Pa for the others)."""
    tab = _table(steps)

    def law(w, u, s, t):
        lw, lu = math.log(w), math.log(u)
        lin = k[0] * lw + k[1] * lu + k[2] * s + k[3] * t
        return FilmPoint(2e-7 * math.exp(k[0] * lw + k[1] * lu + 0.01 * k[2] * t),
                         1e-7 * math.exp(0.5 * k[1] * lu + 0.1 * k[3] * s),
                         1e9 + 1e7 * lin, lin, -lin + 3.0 * s, 2.0 * lin)

    for lw, lu, s, t in points:
        w, u = math.exp(lw), math.exp(lu)
        got = tab(w, u, s, t, stand_in=lambda idx: law(*tab.node_point(idx)))
        want = law(w, u, s, t)
        for name, scale in zip(_FIELDS, (0.0, 0.0, 1e10, 1e3, 1e3, 1e3), strict=True):
            g, e = getattr(got, name), getattr(want, name)
            assert abs(g - e) <= 1e-9 * (abs(e) + scale), (name, g, e)
    assert tab.solves == 0


@settings(max_examples=40, deadline=None)
@given(_steps, st.integers(0, 2**31 - 1), st.lists(_points, min_size=1, max_size=20))
def test_answers_stay_within_their_corner_values(steps, seed, points):
    """Arbitrary node values (a hash of the node index and the seed): each output within the
    [min, max] of the corners the answer uses (FilmTable.corners)."""
    tab = _table(steps)

    def stand_in(idx):
        rng = np.random.default_rng(zlib.crc32(repr((seed, idx)).encode()))
        v = rng.uniform(-1.0, 1.0, 6)
        return FilmPoint(1e-7 * math.exp(v[0]), 1e-7 * math.exp(v[1]), 1e9 * (2.0 + v[2]),
                         100.0 * v[3], 10.0 * v[4], 5.0 * (1.0 + v[5]))

    for lw, lu, s, t in points:
        w, u = math.exp(lw), math.exp(lu)
        got = tab(w, u, s, t, stand_in=stand_in)
        corners = [stand_in(idx) for idx in tab.corners(w, u, s, t)]
        assert 1 <= len(corners) <= 16
        for name in _FIELDS:
            values = [getattr(c, name) for c in corners]
            lo, hi = min(values), max(values)
            pad = 1e-12 * max(abs(lo), abs(hi))
            assert lo - pad <= getattr(got, name) <= hi + pad, (name, values)
    assert tab.solves == 0
