"""Scene variants of the scene-based validation runners (thermobearing.validation.runners_scene)."""

from __future__ import annotations

from thermobearing.scene import load_scene
from thermobearing.simulation import Simulation
from thermobearing.validation.runners_scene import _variant


def test_single_bearing_variant_of_the_default_rig_drops_the_shaft_link():
    """The default rig links its two bearings on one shaft; the runners that keep one
    bearing (paper002_loss_ratios, paper002_temperature_rise) must drop the link, which
    joins two or more bearings (they stopped with an InputError naming shaft_link)."""
    base = load_scene("qj1044_rig")
    assert "shaft_link" in base.network
    one = _variant(base, single_bearing=True, want=["losses"], mode="steady")
    assert [b.name for b in one.bearings] == ["drive_end"]
    assert "shaft_link" not in one.network
    Simulation(one, progress=False)  # builds without the link error
    both = _variant(base, want=["losses"], mode="steady")
    assert both.network["shaft_link"] == base.network["shaft_link"]
