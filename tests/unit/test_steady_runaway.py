"""Steady mode stops at the runaway limit like the transient (coupled._run_steady)."""

from __future__ import annotations

from pathlib import Path

import pytest

from thermobearing.errors import ConvergenceError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

SCENE = f"""
title = "6206 at 17600 r/min and 7.5 kN axial on oil-air, Palmgren, steady"
[[bearings]]
name = "a"
path = "{(EXAMPLES / 'catalogue_bearing_6206.toml').as_posix()}"
[lubricant]
preset = "PAPER000_OIL"
[supply]
method = "oil_air"
flow = "20.7797 mm**3/h"
[environment]
ambient_temperature = "79.99 degC"
[schedule]
speed = "17612.4 rpm"
radial_load = "0 N"
axial_load = "7520.65 N"
duration = "20 s"
[models]
kinematics = "none"
heat_sources = ["global_friction"]
heat_source_options = {{ global_friction = {{ model = "palmgren" }} }}
[outputs]
mode = "steady"
want = ["temperatures", "losses"]
[network]
template = "seven_node"
[network.parameters]
housing_outer_diameter = "150.316 mm"
housing_length = "44.8247 mm"
h_oil = "136.904 W/(m**2*K)"
"""


def test_a_steady_state_above_the_runaway_limit_is_refused():
    """A scene found by the scene fuzzer: the steady solve returned a fixed point at about
    1210 degC (and another case left the viscosity law's range on the way); it now stops
    with the transient's runaway wording once a pass or the fixed point passes 300 degC."""
    with pytest.raises(ConvergenceError, match="no steady state below the runaway limit"):
        Simulation(loads_scene(SCENE), progress=False).run()
