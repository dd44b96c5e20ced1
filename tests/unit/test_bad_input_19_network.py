"""Network template parameters with a user's mistakes (session-19 fuzz probes of the
[network] table): ``oil_fill = "50 %"`` stopped with a TypeError in the template;
``fit_conductance = 0`` was refused as ``contact_fit.contact_conductance`` and a misspelt
``housing_material`` as ``material``: names the scene's [network] parameters do not
have."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.network.templates import four_node_paper002, seven_node

DIMS = {"housing_outer_diameter": 0.1, "housing_length": 0.03}


@pytest.fixture(scope="module")
def parts():
    return load_bearing("SKF6304"), load_lubricant("ISO_VG46")


def test_oil_fill_as_a_percentage(parts):
    pct = four_node_paper002(*parts, **DIMS, oil_fill="50 %")
    num = four_node_paper002(*parts, **DIMS, oil_fill=0.5)
    assert pct.capacity("oil") == pytest.approx(num.capacity("oil"), rel=1e-12)


@pytest.mark.parametrize(("template", "key", "value"), [
    (four_node_paper002, "oil_fill", "150 %"), (four_node_paper002, "oil_fill", -0.5),
    (seven_node, "fit_conductance", 0.0), (seven_node, "fit_conductance", -1.0),
])
def test_refusal_names_the_template_parameter(parts, template, key, value):
    with pytest.raises(InputError) as info:
        template(*parts, **DIMS, **{key: value})
    assert info.value.field == key


def test_unknown_housing_material_names_the_parameter_and_lists_the_presets(parts):
    with pytest.raises(UnknownNameError) as info:
        four_node_paper002(*parts, **DIMS, housing_material="steel")
    assert info.value.field == "housing_material"
    assert "STEEL_52100" in info.value.known
