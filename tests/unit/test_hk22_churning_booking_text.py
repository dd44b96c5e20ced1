"""Tour R6: the report's model chain (registry summaries) said "heat to the inner ring"
for inner-ring churning, while a scene books it on the oil by default
(``[models] churning_heat_to = "oil"``). The summaries now say where the heat goes in a
scene by default and under the source's own default role (paper 002's booking)."""

from __future__ import annotations

import pytest

from thermobearing.heat_sources import HEAT_SOURCES


@pytest.mark.parametrize("source, own", [("churning_inner_ring", "inner ring"),
                                         ("churning_elements", "elements"),
                                         ("churning_cage", "oil")])
def test_churning_summary_names_the_oil_the_scene_books_it_on(source, own):
    summary = HEAT_SOURCES.entry(source).summary
    assert "oil" in summary and own in summary


def test_inner_ring_summary_does_not_claim_the_inner_ring_alone():
    summary = HEAT_SOURCES.entry("churning_inner_ring").summary
    assert "heat to the inner ring" not in summary
    assert "scene default" in summary
