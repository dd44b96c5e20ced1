"""Tour R7: the four-node and seven-node templates accepted a shaft wider than the bore
(60 mm in a 50 mm bore) and a housing shorter than the ring width (10 mm < 20 mm); they
are now refused naming the parameter, its value and the allowed range."""

from __future__ import annotations

import pytest

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import InputError
from thermobearing.network.templates import four_node_paper002, seven_node

BASE = {"housing_outer_diameter": 0.15, "housing_length": 0.04}


@pytest.fixture(scope="module")
def bearing_and_oil():
    return load_bearing("SKF6304"), load_lubricant("ISO_VG68")


@pytest.mark.parametrize("template", [four_node_paper002, seven_node])
def test_shaft_wider_than_the_bore_is_refused(bearing_and_oil, template):
    b, lub = bearing_and_oil
    wide = b.bore + 0.01
    with pytest.raises(InputError) as err:
        template(b, lub, **BASE, shaft_diameter=wide)
    text = str(err.value)
    assert "shaft_diameter" in text and f"{wide}" in text
    assert f"{1e3 * b.bore:g} mm" in text and "<=" in text


@pytest.mark.parametrize("template", [four_node_paper002, seven_node])
def test_housing_shorter_than_the_ring_is_refused(bearing_and_oil, template):
    b, lub = bearing_and_oil
    short = 0.5 * b.width
    with pytest.raises(InputError) as err:
        template(b, lub, housing_outer_diameter=0.15, housing_length=short)
    text = str(err.value)
    assert "housing_length" in text and f"{short}" in text
    assert f"{1e3 * b.width:g} mm" in text and ">=" in text


def test_seat_equal_to_the_bearing_is_accepted(bearing_and_oil):
    b, lub = bearing_and_oil
    net = four_node_paper002(b, lub, housing_outer_diameter=0.15, housing_length=b.width,
                             shaft_diameter=b.bore)
    assert "shaft" in net.graph and "housing" in net.graph
