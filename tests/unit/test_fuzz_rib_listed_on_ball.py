"""``rib_friction`` listed in ``[models] heat_sources`` of a scene whose bearings cannot all
host it (found by the scene fuzzer: a CRB beside a 6206 on one shaft): the run solved the
kinematics and stopped at the first heat evaluation with "bearing = '6206' is not allowed",
naming no scene field. It is now refused before anything is solved, naming
models.heat_sources, the bearing and the reason."""

from __future__ import annotations

import pytest

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "rib source listed"
[[bearings]]
name = "crb"
preset = "CRB_50x75x16"
[[bearings]]
name = "other"
preset = "{other}"
load_share = {{ axial = 0 }}
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "2 L/min"
[environment]
ambient_temperature = "40 degC"
[schedule]
steps = [{{ speed = "3000 rpm", radial_load = "1 kN", axial_load = "0 kN", duration = "1 min" }}]
[models]
kinematics = "race_control"
heat_sources = ["raceway_traction", "rib_friction"]
[outputs]
mode = "steady"
want = ["losses"]
"""


@pytest.mark.parametrize(("other", "why"), [
    ("SKF6304", "not a cylindrical roller bearing"),
    ("NU214", "ribs on the outer ring only"),
])
def test_listed_rib_source_is_refused_before_the_run(other, why):
    scene = loads_scene(SCENE.format(other=other))
    with pytest.raises(InputError, match=r"models\.heat_sources = 'rib_friction'.*'other' "
                                         rf"\({other}\).*{why}"):
        Simulation(scene, progress=False)
