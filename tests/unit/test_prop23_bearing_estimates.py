"""Property tests, round 5: catalogue bearings with estimated internal geometry
(:mod:`thermobearing.bearing_estimates`).

Invariants:

- ISO 5753-1 Normal-group tables: the bore classes tile the range (each class starts where
  the last ended) and the clearance limits never fall as the bore grows (the standard's
  clearances grow with size), min < max in every class;
- a catalogue bearing the estimator accepts is a bearing that can be built: bore < inner
  raceway < pitch circle < outer raceway < outside diameter, the estimated cage annulus lies
  between the raceways, the clearance is the middle of its ISO class; a value the config
  gives is kept as given and not listed as estimated (module docstring: "a value the config
  gives is never changed"); inputs it refuses are refused with an InputError naming a field.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.bearing_config import bearing_from_dict
from thermobearing.bearing_estimates import (
    CYLINDRICAL_ROLLER_CN,
    DEEP_GROOVE_CN,
    normal_clearance,
)
from thermobearing.errors import InputError


@pytest.mark.parametrize("table", [DEEP_GROOVE_CN, CYLINDRICAL_ROLLER_CN],
                         ids=["deep_groove", "cylindrical"])
def test_iso_tables_tile_the_bores_and_grow_with_them(table):
    rows = list(table)
    for (_, incl, lo, hi), (over, _, lo2, hi2) in zip(rows, rows[1:], strict=False):
        assert incl == over
        assert lo <= lo2 and hi <= hi2
    assert all(lo < hi for _, _, lo, hi in rows)


@st.composite
def catalogue(draw):
    kind = draw(st.sampled_from(["deep_groove", "cylindrical"]))
    bore = draw(st.floats(10.0, 200.0))
    outer = bore * draw(st.floats(1.3, 2.2))
    width = (outer - bore) * draw(st.floats(0.3, 0.8))
    elem = (outer - bore) / 2.0 * draw(st.floats(0.3, 0.8))
    pitch = (bore + outer) / 2.0
    z_max = int(math.pi * pitch / elem)
    z = draw(st.integers(max(3, z_max // 2), max(3, z_max)))
    data = {"name": "catalogue", "kind": kind, "source": "catalogue", "estimate_missing": True,
            "bore": f"{bore!r} mm", "outer_diameter": f"{outer!r} mm",
            "width": f"{width!r} mm"}
    if kind == "deep_groove":
        data.update(ball_diameter=f"{elem!r} mm", n_balls=z)
    else:
        data.update(roller_diameter=f"{elem!r} mm", n_rollers=z,
                    roller_length=f"{elem * draw(st.floats(0.8, 1.5))!r} mm")
    if draw(st.booleans()):
        data["diametral_clearance"] = f"{draw(st.floats(1.0, 80.0))!r} um"
    return data


@settings(max_examples=80, deadline=None)
@given(catalogue())
def test_accepted_catalogue_bearings_are_consistent(data):
    """Raceways, pitch circle, cage and clearance in order; given values kept; refusals by
    field name."""
    try:
        b = bearing_from_dict(data)
    except InputError as err:
        assert err.field.startswith("bearing."), err.field
        return
    assert b.bore < b.inner_raceway_diameter < b.pitch_diameter
    assert b.pitch_diameter < b.outer_raceway_diameter < b.outer_diameter
    assert b.inner_raceway_diameter < b.cage.inner_diameter < b.pitch_diameter
    assert b.pitch_diameter < b.cage.outer_diameter < b.outer_raceway_diameter
    if "diametral_clearance" in data:
        given_um = float(data["diametral_clearance"].split()[0])
        assert b.diametral_clearance == pytest.approx(given_um * 1e-6, rel=1e-12)
        assert "diametral_clearance" not in b.estimated
    else:
        lo, hi = normal_clearance(b.kind, b.bore)
        assert b.diametral_clearance == pytest.approx(0.5 * (lo + hi), rel=1e-12)
        assert "diametral_clearance" in b.estimated
    assert b.pitch_diameter == pytest.approx(0.5 * (b.bore + b.outer_diameter), rel=1e-12)
