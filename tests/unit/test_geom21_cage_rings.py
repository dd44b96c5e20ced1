"""The cage lies between the rings and runs on a land that exists (session 21).

The D1842926 preset estimated its outer-ring guide land as raceway + 2 x rib = 170 mm, beyond
the 167.03 mm outer raceway, and a 169.6 mm cage across the raceway; the cage-between-rings
check trusted the guide land and passed it. The check now compares the guide land and the
cage with the ring surfaces: the guide land must be the guiding ring's land (its rib bore or
diameter with ``rib_height`` given, the raceway of a ring without ribs, a given ball
shoulder) within half the guide clearance, or lie inside the raceway where the land is not
given; the cage must clear the guide land and the ring surfaces. Hand values from
configs/bearings/*.toml (mm)."""

from __future__ import annotations

import dataclasses

import pytest

from thermobearing.bearing_config import load_bearing, preset_names
from thermobearing.errors import InputError
from thermobearing.geometry_common import _cage_land, _ring_surface


def test_d1842926_cage_is_guided_on_its_outer_ribs_between_the_rings() -> None:
    b = load_bearing("D1842926")
    # d_o = 155 + 12 + 0.06/2 = 167.03; rib bore 167.03 - 2 x 2.4 = 162.23; d_i = 142.97
    assert b.outer_raceway_diameter * 1e3 == pytest.approx(167.03, abs=1e-9)
    assert b.outer_land_diameter * 1e3 == pytest.approx(162.23, abs=1e-9)
    assert b.inner_raceway_diameter * 1e3 == pytest.approx(142.97, abs=1e-9)
    cage = b.cage
    assert cage.guide_land_diameter * 1e3 == pytest.approx(162.23, abs=1e-9)
    # cage 150 / 161.83 = 162.23 - 0.4 (guide clearance)
    assert cage.outer_diameter * 1e3 == pytest.approx(161.83, abs=1e-9)
    assert cage.inner_diameter * 1e3 == pytest.approx(150.0, abs=1e-9)
    assert b.inner_raceway_diameter < cage.inner_diameter < b.pitch_diameter
    assert b.pitch_diameter < cage.outer_diameter < b.outer_land_diameter
    assert b.outer_land_diameter < b.outer_raceway_diameter
    # every estimate is recorded with its basis
    for key in ("rib_height", "cage.guide_land_diameter", "cage.outer_diameter",
                "cage.inner_diameter"):
        assert key in b.estimated
    assert "162.23" in b.estimated["cage.guide_land_diameter"]


def test_the_former_d1842926_cage_beyond_the_outer_raceway_is_refused() -> None:
    """The preset as it was: no rib height, a 170 mm guide land and a 169.6 mm cage."""
    b = load_bearing("D1842926")
    cage = dataclasses.replace(b.cage, guide_land_diameter=0.170, outer_diameter=0.1696)
    with pytest.raises(InputError) as info:
        dataclasses.replace(b, rib_height=None, cage=cage)
    assert info.value.field == "cage.guide_land_diameter"
    msg = str(info.value)
    assert "'170 mm'" in msg and "outer raceway diameter, 167.03 mm" in msg


def test_a_guide_land_inside_the_rib_material_is_refused_naming_the_rib() -> None:
    # 164 mm lies between the 162.23 mm rib bore and the 167.03 mm raceway: no surface there
    with pytest.raises(InputError) as info:
        load_bearing("D1842926", {"cage": {"guide_land_diameter": "164 mm"}})
    assert info.value.field == "cage.guide_land_diameter"
    msg = str(info.value)
    assert "'164 mm'" in msg and "162.23 mm" in msg and "rib_height = 2.4 mm" in msg
    assert "within half the guide clearance (0.2 mm)" in msg


def test_a_cage_across_the_outer_ribs_is_refused() -> None:
    with pytest.raises(InputError) as info:
        load_bearing("D1842926", {"cage": {"outer_diameter": "162.3 mm"}})
    assert info.value.field == "cage.outer_diameter"
    assert "below 162.23 mm, cage.guide_land_diameter" in str(info.value)


def test_the_rib_moves_with_the_clearance_within_the_guide_play() -> None:
    """The raceways (and ribs) follow diametral_clearance; the paper 001 clearance sweeps
    (40-200 um) keep the 162.23 mm land within 0.2 mm of the rib bore, 0.5 mm does not."""
    for pd in ("0.04 mm", "0.16 mm", "0.2 mm"):
        b = load_bearing("D1842926", {"diametral_clearance": pd})
        assert abs(b.outer_land_diameter - b.cage.guide_land_diameter) <= 0.2e-3
    with pytest.raises(InputError) as info:
        load_bearing("D1842926", {"diametral_clearance": "0.5 mm"})
    assert info.value.field == "cage.guide_land_diameter"
    assert "= 162.45 mm" in str(info.value)  # 155 + 12 + 0.5/2 - 2 x 2.4


def test_a_land_of_a_ring_without_ribs_is_its_raceway() -> None:
    """NU214 (ribs on the outer ring only) with its cage guided by the inner ring: the inner
    ring is a plain cylinder of the raceway diameter, 97.5 - 13 - 0.0125 = 84.4875 mm."""
    ok = {"cage": {"guidance": "inner_ring", "guide_land_diameter": "84.4875 mm",
                   "guide_clearance": "0.3 mm", "land_width": "4 mm",
                   "inner_diameter": "84.7875 mm"}}
    b = load_bearing("NU214", ok)
    assert _cage_land(b, "inner")[0] * 1e3 == pytest.approx(84.4875, abs=1e-9)
    bad = {"cage": dict(ok["cage"], guide_land_diameter="86 mm", inner_diameter="86.3 mm")}
    with pytest.raises(InputError) as info:
        load_bearing("NU214", bad)
    assert info.value.field == "cage.guide_land_diameter"
    assert "the inner raceway diameter, the outside of a ring without ribs" in str(info.value)


def test_a_ball_cage_land_beyond_the_groove_bottom_is_refused() -> None:
    """SKF6304 gives no shoulder: an outer-ring guide land must lie inside the outer groove
    bottom (36 + 9.525 + 0.0075 = 45.5325 mm); 46 mm is refused, 42 mm is accepted."""
    guided = {"guidance": "outer_ring", "guide_clearance": "0.3 mm", "land_width": "2 mm"}
    b = load_bearing("SKF6304", {"cage": dict(guided, guide_land_diameter="42 mm")})
    assert b.cage.guide_land_diameter == pytest.approx(0.042)
    with pytest.raises(InputError) as info:
        load_bearing("SKF6304", {"cage": dict(guided, guide_land_diameter="46 mm")})
    assert info.value.field == "cage.guide_land_diameter"
    assert "below the outer raceway diameter, 45.5325 mm" in str(info.value)


@pytest.mark.parametrize("name", preset_names())
def test_every_preset_guide_land_is_a_surface_of_its_ring(name) -> None:
    b = load_bearing(name)
    cage = b.cage
    for side in ("inner", "outer"):
        surface, _, land = _ring_surface(b, side)
        if cage.guidance == f"{side}_ring":
            if land:
                assert abs(cage.guide_land_diameter - surface) <= 0.5 * cage.guide_clearance
            elif side == "outer":
                assert cage.guide_land_diameter < surface
            else:
                assert cage.guide_land_diameter > surface
    assert cage.inner_diameter > _cage_land(b, "inner")[0]
    assert cage.outer_diameter < _cage_land(b, "outer")[0]
