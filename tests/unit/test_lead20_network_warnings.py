"""The thermal network's own correlation warnings reach the run's warnings (they went to
Python's warning stream only): an 8 m housing puts the housing-air Rayleigh number beyond
Churchill-Chu's 1e12."""

from __future__ import annotations

import pytest

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "network warning probe"
[[bearings]]
name = "a"
preset = "SKF6304"
[lubricant]
preset = "ISO_VG68"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "20 degC"
initial_temperature = "90 degC"
[schedule]
speed = "3000 rpm"
radial_load = "1000 N"
axial_load = "0 N"
step_duration = "2 min"
[models]
kinematics = "race_control"
[network]
template = "four_node_paper002"
parameters = {{ housing_outer_diameter = "{diameter}", housing_length = "140 mm" }}
[outputs]
mode = "{mode}"
want = ["temperatures", "losses"]
"""


@pytest.mark.parametrize("mode", ["transient", "steady"])
def test_a_network_correlation_out_of_range_is_a_run_warning(mode: str) -> None:
    text = SCENE.format(diameter="8 m", mode=mode)
    if mode == "steady":  # steady runs start from the ambient: keep the housing hot enough
        text = text.replace('ambient_temperature = "20 degC"',
                            'ambient_temperature = "-40 degC"')
    results = Simulation(loads_scene(text), progress=False).run()
    lines = [w for w in results.warnings if "Churchill-Chu" in w]
    assert len(lines) == 1 and lines[0].startswith("network: Ra = ")


def test_no_network_warning_inside_the_range() -> None:
    results = Simulation(loads_scene(SCENE.format(diameter="510 mm", mode="transient")),
                         progress=False).run()
    assert not [w for w in results.warnings if w.startswith("network:")]
