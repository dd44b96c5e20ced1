"""A FilmTable query at a node's own point is answered from that node alone.

The node's (w', u, SRR, T) come back through log/exp with ~1e-15 of a cell of round-off;
before the coordinates were snapped (ehl.cache.SNAP) about a third of the nodes listed 2-16
corners with weights ~1e-16, and each extra corner cost an EHL solve."""

from __future__ import annotations

import itertools

from thermobearing.ehl import FilmPoint, FilmTable
from thermobearing.lubricant import load_lubricant

LUB = load_lubricant("OIL_4109")


def test_query_at_every_node_uses_that_node_only():
    table = FilmTable("numerical_ehl", 0.01, 2.2e11, lubricant=LUB, load_step=1.5,
                      speed_step=1.25, srr_step=0.05, temperature_step=5.0,
                      temperature_origin=313.15)
    asked = []

    def stand_in(idx):
        asked.append(idx)
        return FilmPoint(1e-7, 8e-8, 1e9, 10.0, 1.0, 2.0)

    n = 0
    for idx in itertools.product(range(25, 31), range(-3, 3), range(-3, 4), range(0, 4)):
        point = table.node_point(idx)
        assert table.corners(*point) == [idx]
        asked.clear()
        got = table(*point, stand_in=stand_in)
        assert asked == [idx]
        assert abs(got.central_film - 1e-7) < 1e-20  # exp(log(h)) round trip
        n += 1
    assert n == 6 * 6 * 7 * 4 and table.solves == 0


def test_a_point_off_the_node_still_interpolates_between_two():
    table = FilmTable("numerical_ehl", 0.01, 2.2e11, lubricant=LUB, temperature_origin=313.15)
    w, u, s, t = table.node_point((30, 0, 0, 0))
    assert len(table.corners(w * 1.25 ** 0.5, u, s, t)) == 2
