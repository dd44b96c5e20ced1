"""Tests of thermobearing.materials."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.materials import (
    GCR15,
    MATERIALS,
    PAPER000_STEEL,
    PAPER001_STEEL,
    SILICON_NITRIDE,
    STEEL_52100,
    Material,
    effective_modulus,
    effective_modulus_from,
    get_material,
)


def test_effective_modulus_identical_steel_hand_value():
    # E' = E/(1 - nu^2) for identical bodies: 203.4 GPa / 0.91 = 223.5 GPa
    e = effective_modulus(STEEL_52100, STEEL_52100)
    assert e == pytest.approx(STEEL_52100.youngs_modulus / 0.91, rel=1e-14)
    assert e == pytest.approx(223.5e9, rel=1e-3)


def test_effective_modulus_is_twice_johnson():
    # Johnson 1985 eq. 4.22: 1/E* = (1-v1^2)/E1 + (1-v2^2)/E2
    e_star = 1.0 / ((1 - 0.27**2) / 310e9 + (1 - 0.3**2) / STEEL_52100.youngs_modulus)
    assert effective_modulus(SILICON_NITRIDE, STEEL_52100) == pytest.approx(2 * e_star)


def test_effective_modulus_symmetric_and_vectorised():
    a = effective_modulus(SILICON_NITRIDE, STEEL_52100)
    b = effective_modulus(STEEL_52100, SILICON_NITRIDE)
    assert a == b
    out = effective_modulus_from(np.array([200e9, 300e9]), 0.3, 200e9, 0.3)
    assert out.shape == (2,) and out[1] > out[0]


def test_paper_values():
    # paper 000 Table 1: E' = 2.28e11 Pa for steel on steel
    assert effective_modulus(PAPER000_STEEL, PAPER000_STEEL) == pytest.approx(2.28e11)
    # paper 001 Table 1: E = 218 GPa, nu = 0.3 -> E' = 239.6 GPa
    assert effective_modulus(PAPER001_STEEL, PAPER001_STEEL) == pytest.approx(218e9 / 0.91)
    assert PAPER001_STEEL.density == 7870 and PAPER001_STEEL.thermal_conductivity == 15


def test_get_material_aliases_and_instances():
    assert get_material("GCr15") is GCR15
    assert get_material("52100") is STEEL_52100
    assert get_material("si3n4") is SILICON_NITRIDE
    assert get_material(STEEL_52100) is STEEL_52100


@pytest.mark.parametrize("name", sorted(MATERIALS))
def test_presets_sane(name):
    m = get_material(name)
    assert m.source
    assert 1e9 < m.youngs_modulus < 500e9
    assert 500 < m.density < 20000
    assert 0 < m.thermal_diffusivity < 1e-4


def test_unknown_material_lists_known():
    with pytest.raises(UnknownNameError) as info:
        get_material("unobtainium")
    assert "STEEL_52100" in str(info.value)


def test_bad_material_values():
    base = dataclasses.asdict(STEEL_52100)
    for field, bad in [("youngs_modulus", -1.0), ("poisson_ratio", 0.5), ("density", 0.0),
                       ("thermal_conductivity", float("nan"))]:
        kw = dict(base)
        kw[field] = bad
        with pytest.raises(InputError, match=field):
            Material(**kw)
    with pytest.raises(InputError):
        effective_modulus(STEEL_52100, "STEEL_52100")


def test_preset_estimated_tables_are_read_only():
    """The presets are module-level objects shared by every bearing that names them: their
    ``estimated`` table is read-only, so one caller's edit cannot leak into later loads."""
    import pytest as _pytest

    from thermobearing.bearing_config import load_bearing

    mat = load_bearing("QJ1044").ring_material
    with _pytest.raises(TypeError):
        mat.estimated["youngs_modulus"] = "edited"
    assert load_bearing("QJ1044").ring_material.estimated.get("youngs_modulus") != "edited"
