"""A roller-bearing skidding scene that names the inlet-heating reduction for the rolling
resistance (``[models.heat_source_options.ehl_rolling_resistance] thermal_reduction``) passes
it to the roller solver, so the force the solver balances and the heat the source books are
one force (NU214, ISO VG 46 jet at 50 degC, 6000 r/min, 10 kN; measured 2026-11-24: rolling
resistance 1039.7 -> 755.9 W, total 1846.5 -> 1520.5 W, cage speed ratio unchanged)."""

from __future__ import annotations

import pytest

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "NU214 skidding, inlet heating"
[[bearings]]
name = "nu"
preset = "NU214"
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "50 degC"
[environment]
ambient_temperature = "30 degC"
[schedule]
speed = "6000 rpm"
radial_load = "10 kN"
axial_load = "0 kN"
step_duration = "1 min"
[models]
kinematics = "skidding"
{options}
[outputs]
mode = "steady"
want = ["losses", "kinematics"]
"""
GUPTA = ('[models.heat_source_options.ehl_rolling_resistance]\n'
         'thermal_reduction = "gupta_1992"')
NONE = ('[models.heat_source_options.ehl_rolling_resistance]\n'
        'thermal_reduction = "none"')


def _run(options: str):
    res = Simulation(loads_scene(SCENE.format(options=options)), progress=False).run()
    by_source = res.tables["losses"].groupby("source")["power [W]"].sum()
    return by_source, res.tables["kinematics"].iloc[0]


@pytest.fixture(scope="module")
def runs():
    """(isothermal named, Gupta named, no option: the heat source's and the solver's
    default, Gupta since 2026-11-24)."""
    return _run(NONE), _run(GUPTA), _run("")


def test_scene_option_reaches_the_roller_solver(runs):
    (iso, kin_iso), (hot, kin_hot), _ = runs
    ratio = hot["ehl_rolling_resistance"] / iso["ehl_rolling_resistance"]
    # Gupta's phi_T at 6000 r/min: 0.727 on the solver's force (race control 0.747)
    assert 0.65 < ratio < 0.80
    # the solver balanced the reduced force: its traction changed with it (the rolling
    # force is what the inner-ring traction pays for), the churning did not
    assert hot["raceway_traction"] < iso["raceway_traction"]
    assert hot["churning_elements"] == pytest.approx(iso["churning_elements"], rel=1e-4)
    assert kin_hot["converged"] and kin_iso["converged"]
    assert kin_hot["cage speed ratio [-]"] == pytest.approx(kin_iso["cage speed ratio [-]"],
                                                           abs=1e-4)


def test_scene_without_the_option_is_the_gupta_default(runs):
    """Without the option the solver and the source both take the one default (Gupta):
    the same losses as naming it."""
    _, (hot, kin_hot), (default, kin_default) = runs
    for source, power in hot.items():
        assert default[source] == pytest.approx(power, rel=1e-9, abs=1e-9), source
    assert kin_default["cage speed ratio [-]"] == pytest.approx(
        kin_hot["cage speed ratio [-]"], rel=1e-9)
