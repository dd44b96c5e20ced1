"""The thermal network's own correlation warnings reach the run's warnings (they went to
Python's warning stream only): an 8 m housing puts the housing-air Rayleigh number beyond
Churchill-Chu's 1e12."""

from __future__ import annotations

import pytest
from probe_scene import probe_scene

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation


def _scene(diameter: str, mode: str, ambient: str = "20 degC") -> str:
    return probe_scene(
        title="network warning probe",
        environment=f'ambient_temperature = "{ambient}"\ninitial_temperature = "90 degC"',
        axial='axial_load = "0 N"',
        network=('[network]\ntemplate = "four_node_paper002"\nparameters = { '
                 f'housing_outer_diameter = "{diameter}", housing_length = "140 mm" }}'),
        mode=mode, want='["temperatures", "losses"]')


@pytest.mark.parametrize("mode", ["transient", "steady"])
def test_a_network_correlation_out_of_range_is_a_run_warning(mode: str) -> None:
    # steady runs start from the ambient: a cold ambient keeps the housing hot enough
    text = _scene("8 m", mode, "-40 degC" if mode == "steady" else "20 degC")
    results = Simulation(loads_scene(text), progress=False).run()
    lines = [w for w in results.warnings if "Churchill-Chu" in w]
    assert len(lines) == 1 and lines[0].startswith("network: Ra = ")


def test_no_network_warning_inside_the_range() -> None:
    results = Simulation(loads_scene(_scene("510 mm", "transient")),
                         progress=False).run()
    assert not [w for w in results.warnings if w.startswith("network:")]
