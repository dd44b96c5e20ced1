"""Registry-wide test: every registered model loads, cites known references and gives
every documented parameter a unit that converts."""

from __future__ import annotations

import pytest

from thermobearing.citations import reference
from thermobearing.registry import all_registries
from thermobearing.units import unit_registry

REGISTRIES = all_registries()
ENTRIES = [(fam, name) for fam, reg in REGISTRIES.items() for name in reg.names()]


def test_there_are_registries():
    assert "validation" in REGISTRIES


@pytest.mark.parametrize(("family", "name"), ENTRIES)
def test_entry(family, name):
    entry = REGISTRIES[family].entry(name)
    assert callable(entry.obj)
    assert entry.references, f"{family}/{name} has no references"
    for key in entry.references:
        assert reference(key).title
    assert entry.summary, f"{family}/{name} has no one-line summary"
    ureg = unit_registry()
    for param, unit in entry.parameters.items():
        assert unit, f"{family}/{name}: parameter {param} has no unit"
        if unit not in ("-", "1", "dimensionless"):
            ureg.Quantity(1.0, unit)  # raises if pint does not know the unit
