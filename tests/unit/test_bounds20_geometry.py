"""The cage must run between the rings, clear of their lands (session 20 geometry check):
CRB_50x75x16 with ``ribbed_ring = "both"`` put a 66 mm cage across the 65.515 mm bore of
the outer ribs and nothing said so. The bearing now refuses a cage whose bore is not above
the inner ring's land (the guide land when inner-ring guided, else the rib diameter with a
given rib height, the given shoulder, or the raceway) or whose outside diameter is not below
the outer ring's, naming the cage field and both diameters."""

from __future__ import annotations

import pytest

from thermobearing.bearing_config import load_bearing, preset_names
from thermobearing.errors import InputError
from thermobearing.geometry_common import _cage_land


@pytest.mark.parametrize("name", preset_names())
def test_every_preset_cage_clears_its_rings(name) -> None:
    b = load_bearing(name)
    assert b.cage.inner_diameter > _cage_land(b, "inner")[0]
    assert b.cage.outer_diameter < _cage_land(b, "outer")[0]


def test_a_cage_across_the_outer_ribs_is_refused_naming_both_diameters() -> None:
    with pytest.raises(InputError) as info:
        load_bearing("CRB_50x75x16", {"ribbed_ring": "both", "cage": {"outer_diameter": "66 mm"}})
    assert info.value.field == "cage.outer_diameter"
    msg = str(info.value)
    assert "'66 mm'" in msg and "below 65.515 mm" in msg
    assert "ribbed_ring = 'both'" in msg and "rib_height = 1.5 mm" in msg


def test_the_example_scenes_both_ribbed_variant_is_a_consistent_bearing() -> None:
    """configs/scenes/crb_rib_example.toml (and the regression scene crb_rib_reduced): the
    NUP variant with a 65 mm cage, 0.26 mm radially inside the outer ribs."""
    from pathlib import Path

    from thermobearing.scene import load_scene

    root = Path(__file__).resolve().parents[2]
    for path in (root / "configs" / "scenes" / "crb_rib_example.toml",
                 root / "tests" / "regression" / "scenes" / "crb_rib_reduced.toml"):
        overrides = load_scene(path).bearings[0].overrides
        assert overrides["ribbed_ring"] == "both"
        b = load_bearing("CRB_50x75x16", overrides)
        assert b.outer_land_diameter == pytest.approx(0.065515, rel=1e-12)
        assert b.cage.outer_diameter == pytest.approx(0.065, rel=1e-12)
        assert b.cage.inner_diameter > b.cage.guide_land_diameter


def test_an_inner_guided_cage_bore_on_its_land_is_refused() -> None:
    with pytest.raises(InputError) as info:
        load_bearing("CRB_50x75x16", {"cage": {"inner_diameter": "59.4 mm"}})
    assert info.value.field == "cage.inner_diameter"
    assert "above 59.485 mm, cage.guide_land_diameter" in str(info.value)


def test_an_outer_guided_cage_beyond_its_guide_land_is_refused() -> None:
    with pytest.raises(InputError) as info:
        load_bearing("QJ1044", {"cage": {"outer_diameter": "301.2 mm"}})
    assert info.value.field == "cage.outer_diameter"
    assert "below 301 mm, cage.guide_land_diameter" in str(info.value)


def test_a_rolling_element_guided_cage_is_bounded_by_the_raceways_without_given_lands() -> None:
    """SKF6304 gives no shoulder diameters: the estimated ones (d_m -+ 0.6 D) are no
    ground to refuse; the raceways bound the cage."""
    b = load_bearing("SKF6304")
    too_big = f"{b.outer_raceway_diameter * 1e3 + 0.1} mm"
    too_small = f"{b.inner_raceway_diameter * 1e3 - 0.1} mm"
    with pytest.raises(InputError) as info:
        load_bearing("SKF6304", {"cage": {"outer_diameter": too_big}})
    assert info.value.field == "cage.outer_diameter"
    assert "the outer raceway diameter" in str(info.value)
    with pytest.raises(InputError) as info:
        load_bearing("SKF6304", {"cage": {"inner_diameter": too_small}})
    assert info.value.field == "cage.inner_diameter"
    assert "the inner raceway diameter" in str(info.value)
