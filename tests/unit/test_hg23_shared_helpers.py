"""What the session-23 de-duplication wrote once keeps meaning the same in every caller:
the film formulas' range warnings point at the caller's line (the groups moved into
_point_groups / _line_groups / _inlet_groups, one frame deeper), the templates' ring heat
capacities are the ring annuli of both templates, and the presets written as
``dataclasses.replace`` of another differ from it in the named fields only."""

from __future__ import annotations

import dataclasses
import inspect
import math
import warnings

import numpy as np
import pytest

from thermobearing import film, materials
from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.network.templates import four_node_paper002, seven_node

# far outside every fitted range: U ~ 1e-8, W ~ 1e-9 / W' ~ 1e-8
_POINT = dict(entrainment_speed=np.array([50.0]), dynamic_viscosity=1.0,
              pressure_viscosity_coefficient=2e-8, load=np.array([1e-3]),
              reduced_radius_x=np.array([5e-3]), effective_modulus=2.28e11)
_LINE = dict(_POINT, length=0.01)
_THERMAL = dict(entrainment_speed=np.array([200.0]), dynamic_viscosity=1.0,
                temperature_viscosity_coefficient=0.05, thermal_conductivity=0.13,
                slide_to_roll=5.0)


def _range_warnings(rec, name: str) -> list[tuple[str, int]]:
    """(file, line) of the ValidityWarnings recorded in ``rec`` that name ``name``."""
    return [(r.filename, r.lineno) for r in rec
            if issubclass(r.category, ValidityWarning) and str(r.message).startswith(f"{name}: ")]


@pytest.mark.parametrize("name, kwargs", [
    ("hamrock_dowson_1977_central", dict(_POINT, reduced_radius_y=np.array([0.1]))),
    ("hamrock_dowson_1977_minimum", dict(_POINT, ellipticity=3.0)),
    ("dowson_higginson_minimum", _LINE),
    ("pan_hamrock_minimum", _LINE),
    ("pan_hamrock_central", _LINE),
    ("wilson_sheu_1983", _THERMAL),
    ("gupta_1992", dict(_THERMAL, max_pressure=1e10, effective_modulus=2.28e11)),
])
def test_range_warnings_name_the_formula_at_the_callers_line(name, kwargs):
    formula = getattr(film, name)
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        here = (__file__, inspect.currentframe().f_lineno + 1)
        formula(**kwargs)
    found = _range_warnings(rec, name)
    assert found and all(loc == here for loc in found), (found, here)


def test_moes_line_formula_has_no_fitted_range_to_warn_of():
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        film.moes_line_central(**_LINE)
    assert not [r for r in rec if issubclass(r.category, ValidityWarning)]


@pytest.mark.parametrize("preset", ["QJ1044", "NU214"])
def test_ring_capacities_are_the_ring_annuli_in_both_templates(preset):
    """Four-node housing = housing annulus pi/4 (D_h^2 - D^2) L_h + outer ring pi/4 (D^2 -
    D_Lo^2) B; seven-node outer_ring / inner_ring = the annuli D-D_Lo and D_Li-d over B
    (rho c of the ring material), by hand from the bearing."""
    b, lub = load_bearing(preset), load_lubricant("ISO_VG46")
    d_h, l_h = 1.6 * b.outer_diameter, 2.5 * b.width
    kw = dict(housing_outer_diameter=d_h, housing_length=l_h, oil_flow=1e-4)
    ring = b.ring_material
    rho_c = ring.density * ring.specific_heat
    outer = rho_c * math.pi / 4.0 * (b.outer_diameter**2 - b.outer_land_diameter**2) * b.width
    inner = rho_c * math.pi / 4.0 * (b.inner_land_diameter**2 - b.bore**2) * b.width
    steel = materials.STEEL_52100
    house = steel.density * steel.specific_heat * math.pi / 4.0 * (d_h**2 - b.outer_diameter**2) \
        * l_h
    four = four_node_paper002(b, lub, **kw)
    seven = seven_node(b, lub, **kw)
    assert outer > 0 and inner > 0
    assert four.capacity("housing") == pytest.approx(house + outer, rel=1e-12)
    assert seven.capacity("outer_ring") == pytest.approx(outer, rel=1e-12)
    assert seven.capacity("inner_ring") == pytest.approx(inner, rel=1e-12)
    assert seven.capacity("housing") == pytest.approx(house, rel=1e-12)


@pytest.mark.parametrize("derived, base, changed", [
    ("GCR15", "STEEL_52100", {"name", "source"}),
    ("PAPER001_CAGE", "PAPER001_STEEL", {"name", "source", "youngs_modulus", "estimated"}),
    ("PAPER004_STEEL", "STEEL_52100", {"name", "source", "youngs_modulus", "estimated"}),
])
def test_derived_presets_differ_from_their_base_in_the_named_fields_only(derived, base, changed):
    a, b = materials.MATERIALS[derived], materials.MATERIALS[base]
    differ = {f.name for f in dataclasses.fields(a) if getattr(a, f.name) != getattr(b, f.name)}
    assert differ == changed
    assert a.name == derived
    with pytest.raises(TypeError, match="read-only"):
        a.estimated["x"] = "y"          # the copy is a read-only table as every preset's
    assert a.estimated is not b.estimated
