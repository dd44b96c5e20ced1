"""Property tests of the bearing config reader's units (thermobearing.bearing_config,
session 22): every quantity field of every bearing preset (lengths, angles, the cage's
lengths and mass, the materials' properties) written in another unit of its kind gives
the same bearing, and written in a unit of another kind is an InputError that names the
field, the value and the kind it needs.
"""

from __future__ import annotations

import math
import tomllib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.bearing_config import configs_dir, preset_names
from thermobearing.errors import InputError
from thermobearing.geometry import bearing_from_dict
from thermobearing.units import to_si

#: units of each kind and their SI factor
UNITS = {
    "length": {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "in": 0.0254, "inch": 0.0254},
    "angle": {"rad": 1.0, "deg": math.pi / 180.0, "degree": math.pi / 180.0,
              "arcmin": math.pi / 10800.0},
    "mass": {"kg": 1.0, "g": 1e-3, "lb": 0.45359237},
    "pressure": {"Pa": 1.0, "MPa": 1e6, "GPa": 1e9, "psi": 6894.757293168361},
    "density": {"kg/m**3": 1.0, "g/cm**3": 1e3, "kg/m3": 1.0},
    "specific_heat": {"J/(kg*K)": 1.0, "kJ/(kg*K)": 1e3},
    "thermal_conductivity": {"W/(m*K)": 1.0, "mW/(m*K)": 1e-3},
}
WRONG = {"length": "20 kg", "angle": "0.1 m", "mass": "3 mm", "pressure": "2 kg",
         "density": "7800 kg", "specific_heat": "470 W/(m*K)",
         "thermal_conductivity": "47 J/(kg*K)"}
LENGTHS = ("bore", "outer_diameter", "width", "ball_diameter", "pitch_diameter",
           "diametral_clearance", "gothic_arch_offset", "roller_diameter", "roller_length",
           "roller_effective_length", "crown_radius", "end_face_crown_radius",
           "axial_clearance", "rib_height", "raceway_roughness", "element_roughness")
ANGLES = ("contact_angle", "rib_angle")
CAGE_LENGTHS = ("guide_land_diameter", "guide_clearance", "land_width", "pocket_clearance",
                "width", "inner_diameter", "outer_diameter")
MATERIAL_UNITS = {"youngs_modulus": "pressure", "density": "density",
                  "specific_heat": "specific_heat", "thermal_conductivity": "thermal_conductivity"}


def _raw(name: str) -> dict:
    return tomllib.loads((configs_dir() / "bearings" / f"{name}.toml").read_text("utf-8"))


def _fields(name: str) -> list[tuple[tuple[str, ...], str]]:
    """(key path, kind) of every quantity the preset writes."""
    d = _raw(name)
    out = [((k,), "length") for k in LENGTHS if k in d]
    out += [((k,), "angle") for k in ANGLES if k in d]
    cage = d.get("cage", {})
    out += [(("cage", k), "length") for k in CAGE_LENGTHS if k in cage]
    if "mass" in cage:
        out.append((("cage", "mass"), "mass"))
    for table in ("ball_material", "roller_material", "ring_material"):
        if isinstance(d.get(table), dict):
            out += [((table, k), kind) for k, kind in MATERIAL_UNITS.items() if k in d[table]]
    return out


CASES = [(name, path, kind) for name in preset_names() for path, kind in _fields(name)]


def _set(d: dict, path: tuple[str, ...], value) -> dict:
    out = {k: (dict(v) if isinstance(v, dict) else v) for k, v in d.items()}
    cur = out
    for k in path[:-1]:
        cur = cur[k]
    cur[path[-1]] = value
    return out


def _get(bearing, path: tuple[str, ...]) -> float:
    cur = bearing
    for k in path:
        cur = getattr(cur, k)
    return float(cur)


def test_every_preset_has_quantities_to_check():
    assert {name for name, _, _ in CASES} == set(preset_names())
    assert len(CASES) > 50


@settings(max_examples=120, deadline=None)
@given(st.sampled_from(CASES), st.data())
def test_a_field_in_another_unit_of_its_kind_is_the_same_bearing(case, data):
    name, path, kind = case
    raw = _raw(name)
    cur = raw
    for k in path:
        cur = cur[k]
    si = to_si(cur, kind)
    unit = data.draw(st.sampled_from(sorted(UNITS[kind])))
    written = f"{si / UNITS[kind][unit]!r} {unit}"
    base = bearing_from_dict(raw)
    other = bearing_from_dict(_set(raw, path, written))
    assert _get(other, path) == pytest.approx(_get(base, path), rel=1e-12, abs=1e-300)


@pytest.mark.parametrize(("name", "path", "kind"), CASES,
                         ids=[f"{n}-{'.'.join(p)}" for n, p, _ in CASES])
def test_a_field_in_a_unit_of_another_kind_names_the_field(name, path, kind):
    raw = _raw(name)
    with pytest.raises(InputError) as info:
        bearing_from_dict(_set(raw, path, WRONG[kind]))
    text = str(info.value)
    assert ".".join(path) in text and WRONG[kind] in text, text
