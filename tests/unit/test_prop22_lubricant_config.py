"""Property tests of the lubricant config reader's units (thermobearing.lubricant,
session 22): every quantity of every lubricant preset written in another unit of its kind
gives the same oil (viscosity, density, c_p, k at a few temperatures), and one of another
kind is an InputError naming the field; the parameters of the Vogel and exponential laws
likewise.

Defect found (lubricant._SECTION_UNITS, fixed): Vogel's b of eta = a exp(b / (T - c)) is a
temperature difference but was read as a temperature: b = "1000 degC" became 1273.15 K
(the oil 5.3x as viscous at 40 degC with a = 5e-5 Pa s, c = 150 K) and "1800 degF" a third
value; both are now 1000 K.
"""

from __future__ import annotations

import tomllib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import InputError
from thermobearing.lubricant import lubricant_config_dir, lubricant_from_dict, preset_names
from thermobearing.units import to_si

#: (SI unit of the section key, units of its kind with their SI factor and offset)
KINDS = {
    "m**2/s": {"m**2/s": (1.0, 0.0), "mm**2/s": (1e-6, 0.0), "cSt": (1e-6, 0.0),
               "St": (1e-4, 0.0)},
    "kg/m**3": {"kg/m**3": (1.0, 0.0), "g/cm**3": (1e3, 0.0), "kg/L": (1e3, 0.0)},
    "K": {"K": (1.0, 0.0), "degC": (1.0, 273.15), "degF": (5.0 / 9.0, 255.3722222222222)},
    "1/Pa": {"1/Pa": (1.0, 0.0), "1/GPa": (1e-9, 0.0), "1/MPa": (1e-6, 0.0)},
    "Pa": {"Pa": (1.0, 0.0), "MPa": (1e6, 0.0), "GPa": (1e9, 0.0)},
    "Pa*s": {"Pa*s": (1.0, 0.0), "mPa*s": (1e-3, 0.0), "cP": (1e-3, 0.0)},
    "1/K": {"1/K": (1.0, 0.0), "1/degC": (1.0, 0.0), "1/degF": (1.8, 0.0)},
    "J/(kg*K)": {"J/(kg*K)": (1.0, 0.0), "kJ/(kg*K)": (1e3, 0.0)},
    "W/(m*K)": {"W/(m*K)": (1.0, 0.0), "mW/(m*K)": (1e-3, 0.0)},
}
WRONG = {"m**2/s": "46 Pa", "kg/m**3": "876 kg", "K": "40 m", "1/Pa": "2e-8 1/K",
         "Pa": "200 K", "Pa*s": "0.05 m**2/s", "1/K": "7e-4 1/Pa", "J/(kg*K)": "2000 W",
         "W/(m*K)": "0.13 J"}
SECTION_UNITS = {
    "viscosity": {"nu40": "m**2/s", "nu100": "m**2/s", "T1": "K", "T2": "K", "eta0": "Pa*s",
                  "beta": "1/K", "T0": "K", "a": "Pa*s", "c": "K"},
    "pressure_viscosity": {"alpha": "1/Pa", "p0": "Pa", "reference_temperature": "K"},
    "density": {"value": "kg/m**3", "reference_temperature": "K", "expansion": "1/K"},
    "thermal": {"specific_heat": "J/(kg*K)", "thermal_conductivity": "W/(m*K)"},
}
PROBE_T = (300.0, 333.15, 373.15)


def _raw(name: str) -> dict:
    return tomllib.loads((lubricant_config_dir() / f"{name}.toml").read_text("utf-8"))


def _fields(name: str) -> list[tuple[str, str, str]]:
    d = _raw(name)
    return [(sec, key, unit) for sec, keys in SECTION_UNITS.items()
            for key, unit in keys.items() if isinstance(d.get(sec), dict) and key in d[sec]
            and isinstance(d[sec][key], str)]


CASES = [(name, *f) for name in preset_names() for f in _fields(name)]


def _with(d: dict, sec: str, key: str, value) -> dict:
    out = {k: (dict(v) if isinstance(v, dict) else v) for k, v in d.items()}
    out[sec][key] = value
    return out


def _state(oil) -> list[float]:
    return [f(t) for t in PROBE_T for f in (oil.dynamic_viscosity, oil.density,
                                            oil.specific_heat, oil.thermal_conductivity)]


def test_every_preset_has_quantities_to_check():
    assert len(CASES) >= 2 * len(preset_names())


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(CASES), st.data())
def test_a_field_in_another_unit_of_its_kind_is_the_same_oil(case, data):
    name, sec, key, unit = case
    raw = _raw(name)
    si = to_si(raw[sec][key], unit)
    other = data.draw(st.sampled_from(sorted(KINDS[unit])))
    factor, offset = KINDS[unit][other]
    written = f"{(si - offset) / factor!r} {other}"
    base = _state(lubricant_from_dict(raw))
    again = _state(lubricant_from_dict(_with(raw, sec, key, written)))
    assert again == pytest.approx(base, rel=1e-9)


@pytest.mark.parametrize(("name", "sec", "key", "unit"), CASES,
                         ids=[f"{n}-{s}.{k}" for n, s, k, _ in CASES])
def test_a_field_in_a_unit_of_another_kind_names_the_field(name, sec, key, unit):
    with pytest.raises(InputError) as info:
        lubricant_from_dict(_with(_raw(name), sec, key, WRONG[unit]))
    assert f"{sec}.{key}" in str(info.value) and WRONG[unit] in str(info.value)


def _law(viscosity: dict) -> dict:
    raw = _raw("ISO_VG46")
    raw["viscosity"] = viscosity
    return raw


@pytest.mark.parametrize("b", ["1000 K", "1000 degC", "1000 delta_degC", "1800 degF", 1000.0])
def test_vogel_b_is_a_temperature_difference(b):
    oil = lubricant_from_dict(_law({"law": "vogel", "a": "5e-5 Pa*s", "b": b, "c": "150 K"}))
    ref = lubricant_from_dict(_law({"law": "vogel", "a": "5e-5 Pa*s", "b": 1000.0,
                                    "c": "-123.15 degC"}))
    assert oil.dynamic_viscosity(313.15) == pytest.approx(ref.dynamic_viscosity(313.15),
                                                          rel=1e-12)
    assert oil.dynamic_viscosity(313.15) == pytest.approx(5e-5 * 2.718281828459045 ** (
        1000.0 / (313.15 - 150.0)), rel=1e-12)


def test_vogel_b_of_another_kind_names_the_field():
    with pytest.raises(InputError, match=r"viscosity\.b"):
        lubricant_from_dict(_law({"law": "vogel", "a": "5e-5 Pa*s", "b": "1000 kg",
                                  "c": "150 K"}))


@settings(max_examples=30, deadline=None)
@given(beta=st.floats(0.01, 0.05), unit=st.sampled_from(["1/K", "1/degC", "1/degF"]),
       t0=st.floats(20.0, 80.0))
def test_the_exponential_law_in_any_units(beta, unit, t0):
    """eta = eta0 exp(-beta (T - T0)): beta per kelvin, per degC (the same) or per degF
    (1.8 x), T0 in degC."""
    per = {"1/K": 1.0, "1/degC": 1.0, "1/degF": 1.0 / 1.8}[unit]
    oil = lubricant_from_dict(_law({"law": "exponential", "eta0": "40 mPa*s",
                                    "beta": f"{beta * per!r} {unit}", "T0": f"{t0!r} degC"}))
    t = t0 + 273.15 + 10.0
    assert oil.dynamic_viscosity(t) == pytest.approx(0.04 * 2.718281828459045 ** (-beta * 10.0),
                                                     rel=1e-9)
