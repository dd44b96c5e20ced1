"""Scene fuzzing (scripts/fuzz_scenes.py, seed 1 after the first fixes, case 43): a CRB
50x75x16 turning without radial load under race control stopped in the default
rib_friction source with "roller_skidding did not converge (residual inf): no roller
touches the inner ring": the coupled roller dynamics start from the roller skidding
solver, which has nothing to solve there. The source now books the thrust share and the
lubricant drag at the kinematics' spins (the reduced path) and says why."""

from __future__ import annotations

import numpy as np

from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = """
title = "fuzz case"

[[bearings]]
name = "a"
preset = "CRB_50x75x16"

[lubricant]
preset = "ISO_VG32"

[supply]
method = "oil_air"
flow = "18.0327 mm**3/h"

[environment]
ambient_temperature = "24.15 degC"
initial_temperature = "48.3 degC"

[schedule]
steps = [
  { speed = "10.3833 rpm", radial_load = "0 N", axial_load = "0 N", duration = "264.947 s" },
]

[models]
kinematics = "race_control"

[outputs]
mode = "steady"
want = ["kinematics", "losses"]
"""


def test_rib_source_without_radial_load_books_drag_and_says_so():
    res = Simulation(loads_scene(SCENE), progress=False).run()
    losses = res.tables["losses"]
    rib = losses[losses["source"] == "rib_friction"]["power [W]"].to_numpy()
    assert rib.size and np.all(np.isfinite(rib)) and np.all(rib >= 0.0)
    assert rib.sum() > 0.0   # the lubricant drag on the end faces
    assert any("rib_friction: no radial load on CRB_50x75x16" in w
               and "coupled roller dynamics" in w for w in res.warnings)
