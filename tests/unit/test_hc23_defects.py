"""Session-23 defects: Vogel's b documented as a temperature difference, roller azimuths
that cannot carry the radial load refused by name."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.loads_roller import roller_film_load_distribution, roller_load_distribution
from thermobearing.lubricant import lubricant_config_dir, lubricant_from_dict
from thermobearing.scene import load_scene
from thermobearing.simulation import Simulation
from thermobearing.units import to_si
from thermobearing.viscosity_laws import VISCOSITY_TEMPERATURE, vogel_viscosity


def test_vogel_b_registry_unit_is_a_temperature_difference():
    """The registry documents b in the unit the lubricant loader reads it in: a
    difference ("1000 degC" is 1000 K), while c stays an absolute temperature."""
    units = VISCOSITY_TEMPERATURE.entry("vogel").parameters
    assert to_si("1000 degC", units["b"]) == pytest.approx(1000.0)
    assert to_si("1000 K", units["b"]) == pytest.approx(1000.0)
    assert to_si("-123.15 degC", units["c"]) == pytest.approx(150.0)
    raw = tomllib.loads((lubricant_config_dir() / "ISO_VG46.toml").read_text())
    raw["viscosity"] = {"law": "vogel", "a": "5e-5 Pa*s", "b": "1000 degC", "c": "150 K"}
    oil = lubricant_from_dict(raw)
    assert oil.viscosity_parameters["b"] == pytest.approx(to_si("1000 degC", units["b"]))
    assert float(oil.dynamic_viscosity(313.15)) == pytest.approx(
        float(vogel_viscosity(313.15, 5e-5, 1000.0, 150.0)), rel=1e-12)


ONE_SIDE = np.linspace(0.5 * math.pi + 0.1, 1.5 * math.pi - 0.1, 14)


def _film(q: np.ndarray) -> np.ndarray:
    return np.full_like(np.asarray(q, dtype=float), 1e-6)


@pytest.mark.parametrize("solve", [
    lambda psi, fr: roller_load_distribution(14, 20e-6, fr, 1e9, 1e9, azimuth=psi),
    lambda psi, fr: roller_film_load_distribution(14, 20e-6, fr, _film, _film, 1e9, 1e9,
                                                  azimuth=psi),
], ids=["dry", "film"])
def test_azimuths_not_spanning_the_load_are_refused_by_name(solve):
    """Rollers all on the far side of the load (a gap of 3.34 rad around psi = 0) cannot
    carry it: the dry solver returned an infinite ring displacement with residual = F_r;
    now an InputError names the field and the gap."""
    with pytest.raises(InputError) as err:
        solve(ONE_SIDE, 5000.0)
    assert err.value.field == "azimuth"
    assert "3.342 rad >= pi" in str(err.value)
    # without a load the same azimuths are a valid (unloaded) state
    assert roller_load_distribution(14, 20e-6, 0.0, 1e9, 1e9, azimuth=ONE_SIDE).residual == 0.0


def test_uneven_azimuths_that_span_the_load_still_solve():
    """A gap below pi around the load direction (0.1 rad ahead, 0.28 rad behind) is
    accepted and balances the ring."""
    psi = np.array([0.1, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0])
    res = roller_load_distribution(7, 20e-6, 5000.0, 1e9, 1e9, azimuth=psi)
    assert np.sum(res.inner_load * np.cos(psi)) == pytest.approx(5000.0, rel=1e-8)
    assert abs(np.sum(res.inner_load * np.sin(psi))) < 1e-6


STEADY_SCENE = Path(__file__).parents[1] / "regression" / "scenes" / \
    "qj1044_race_control_steady.toml"


def test_steady_temperatures_rows_name_their_operating_point():
    """Each steady_temperatures row carries its step's speed and loads (the kinematics
    table's columns and units), before the node temperatures; the rows were 'step' and
    temperatures only."""
    scene = load_scene(STEADY_SCENE)
    res = Simulation(scene, progress=False).run()
    steady = res.tables["steady_temperatures"]
    assert list(steady.columns[:4]) == ["step", "speed [rpm]", "radial load [kN]",
                                        "axial load [kN]"]
    assert all(c.endswith(" [degC]") for c in steady.columns[4:])
    assert steady["speed [rpm]"].tolist() == [900.0, 1800.0]
    assert steady["radial load [kN]"].tolist() == [1.0, 1.0]
    assert steady["axial load [kN]"].tolist() == [10.0, 10.0]
    kin = res.tables["kinematics"].set_index("step")
    for col in ("speed [rpm]", "radial load [kN]", "axial load [kN]"):
        assert steady.set_index("step")[col].equals(kin[col])


ROLLER_LOSSES = """title = "NU 214 element churning"
[[bearings]]
name = "crb"
preset = "NU214"
[lubricant]
preset = "{oil}"
[supply]
method = "jet"
flow = "1 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "25 degC"
[schedule]
radial_load = "5 kN"
axial_load = "0 kN"
speed = "6000 rpm"
step_duration = "1 min"
[models]
kinematics = "race_control"
[outputs]
want = ["losses"]
"""


def test_roller_element_churning_is_the_cited_constant_drag_coefficient_model():
    """Paper 002 eq. 10 with a constant c_d (the drag plateau; churning_elements'
    docstring): at the same kinematics (race control) ISO VG 100 and ISO VG 32 at 40 degC,
    3.2x apart in viscosity, churn in the ratio of their densities only."""
    from thermobearing.lubricant import load_lubricant
    from thermobearing.scene import loads_scene

    power, oils = {}, {}
    for oil in ("ISO_VG32", "ISO_VG100"):
        res = Simulation(loads_scene(ROLLER_LOSSES.format(oil=oil)), progress=False).run()
        losses = res.tables["losses"]
        power[oil] = float(losses.loc[losses["source"] == "churning_elements",
                                      "power [W]"].sum())
        oils[oil] = load_lubricant(oil)
    eta = {k: float(v.dynamic_viscosity(313.15)) for k, v in oils.items()}
    rho = {k: float(v.density(313.15)) for k, v in oils.items()}
    assert eta["ISO_VG100"] / eta["ISO_VG32"] > 3.0
    assert power["ISO_VG32"] > 100.0
    assert power["ISO_VG100"] / power["ISO_VG32"] == pytest.approx(
        rho["ISO_VG100"] / rho["ISO_VG32"], rel=1e-9)
