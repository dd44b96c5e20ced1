"""Lubricant files with a user's mistakes (session-19 fuzz probes of lubricant files): every
refusal names the file's key, shows the value as written and says what is allowed.

Before: ``nu100 = "1e-9 mm**2/s"`` raised a bare ``ValueError: math domain error`` in
``walther_constants``; ``nu40 = 46`` (cSt meant, read as 46 m^2/s) was refused as the scene's
*ambient temperature* below the oil's pour point; swapped nu40 / nu100, ``density.value``,
``density.reference_temperature`` and ``thermal.model`` errors named the dataclass
attributes (``viscosity at 373.15 K``, ``nu1``, ``ISO_VG46.density_reference_temperature``,
``lubricant_thermal model``), not the keys of the file."""

from __future__ import annotations

import copy
import math
import tomllib
from typing import Any

import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.lubricant import lubricant_config_dir, lubricant_from_dict
from thermobearing.viscosity_laws import walther_constants

WHERE = "lubricant[my_oil]"


def _oil(**edits: Any) -> dict[str, Any]:
    data = tomllib.loads((lubricant_config_dir() / "ISO_VG46.toml").read_text("utf-8"))
    data = copy.deepcopy(data)
    for path, value in edits.items():
        *heads, last = path.split("__")
        table = data
        for head in heads:
            table = table.setdefault(head, {})
        if value is None:
            table.pop(last, None)
        else:
            table[last] = value
    return data


def _refusal(**edits: Any) -> InputError:
    with pytest.raises(InputError) as info:
        lubricant_from_dict(_oil(**edits), where=WHERE)
    return info.value


def test_the_preset_loads() -> None:
    oil = lubricant_from_dict(_oil(), where=WHERE)
    assert math.isclose(oil.kinematic_viscosity(313.15), 46e-6, rel_tol=1e-9)


@pytest.mark.parametrize(("edits", "field", "value", "says"), [
    ({"viscosity__nu100": "1e-9 mm**2/s"}, "viscosity.nu100", "1e-9 mm**2/s", "0.21 to 1e6 cSt"),
    ({"viscosity__nu40": "1e9 mm**2/s"}, "viscosity.nu40", "1e9 mm**2/s", "0.21 to 1e6 cSt"),
    ({"viscosity__nu40": 46}, "viscosity.nu40", 46, "bare number in a lubricant file is SI"),
    ({"viscosity__nu40": "6.8 mm**2/s", "viscosity__nu100": "46 mm**2/s"},
     "viscosity.nu100", "46 mm**2/s", "oil thins as it heats"),
    ({"viscosity__nu40": "0 mm**2/s"}, "viscosity.nu40", "0 mm**2/s", "> 0"),
    ({"density__value": "8760 kg/m**3"}, "density.value", "8760 kg/m**3", "800-1164"),
    ({"density__reference_temperature": "1500 degC"}, "density.reference_temperature",
     "1500 degC", "15 degC"),
    ({"density__expansion": "-1 1/K"}, "density.expansion", "-1 1/K", "[0, 5e-3)"),
])
def test_refusal_names_the_file_key(edits: dict[str, Any], field: str, value: Any,
                                    says: str) -> None:
    exc = _refusal(**edits)
    assert exc.field == f"{WHERE}.{field}"
    assert exc.value == value
    assert says in exc.allowed


def test_unknown_thermal_model_names_the_key_and_lists_the_models() -> None:
    exc = _refusal(thermal__model="foo")
    assert isinstance(exc, UnknownNameError)
    assert exc.field == f"{WHERE}.thermal.model"
    assert "cragoe" in exc.known


def test_empty_viscosity_table_asks_for_nu40_and_nu100() -> None:
    data = _oil()
    data["viscosity"] = {}
    with pytest.raises(InputError) as info:
        lubricant_from_dict(data, where=WHERE)
    assert info.value.field == f"{WHERE}.viscosity"
    assert "nu40 and nu100" in info.value.allowed


def test_walther_constants_refuse_a_viscosity_outside_the_law() -> None:
    with pytest.raises(InputError) as info:
        walther_constants(46e-6, 313.15, 1e-15, 373.15)
    assert info.value.field == "nu2"
    with pytest.raises(InputError):
        walther_constants(2.0, 313.15, 6.8e-6, 373.15)
