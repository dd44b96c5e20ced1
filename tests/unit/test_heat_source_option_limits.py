"""Documented intervals of heat-source parameters (registry ``limits``).

A scene's ``[models] heat_source_options`` value outside its interval is refused when the
scene is turned into a Simulation (what ``thermobearing check`` and ``run`` do first), with
the field, the value as written and the interval; a value set elsewhere (a kinematics model's
options) is checked where the source reads it. Before, a negative cage gap ended in Python's
"math domain error" and a negative shoulder length or critical film ran silently.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_parts import PAPER002_AMBIENT, QJ1044_DE, scene_title

from thermobearing.errors import InputError
from thermobearing.heat_sources import HEAT_SOURCES
from thermobearing.registry import Interval, Registry
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = scene_title("option limits") + QJ1044_DE + """[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "15 L/min"
inlet_temperature = "35 degC"
""" + PAPER002_AMBIENT + """[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "10 kN"
steps = [{ duration = "5 min" }]
[models]
kinematics = "race_control"
heat_source_options = { %s }
[outputs]
want = ["losses"]
"""


def simulation(options: str) -> Simulation:
    return Simulation(loads_scene(SCENE % options), progress=False)


@pytest.mark.parametrize("text, inside, outside", [
    ("[0, 1]", [0.0, 0.5, 1.0], [-1e-12, 1.0 + 1e-12, math.nan, math.inf]),
    ("(0, inf)", [1e-300, 1e300], [0.0, -1.0, math.inf, math.nan]),
    ("[2, 256]", [2, 256], [1, 257]),
    ("[0, inf)", [0.0, 5.0], [-5.0, math.inf]),
])
def test_interval_bounds(text, inside, outside):
    iv = Interval.parse(text)
    assert all(iv.contains(v) for v in inside)
    assert not any(iv.contains(v) for v in outside)


@pytest.mark.parametrize("bad", ["0, 1", "[1, 0]", "[a, 1]", "{0, 1}"])
def test_interval_syntax_is_checked(bad):
    with pytest.raises(ValueError):
        Interval.parse(bad)


def test_limits_must_name_documented_parameters():
    reg: Registry = Registry("demo")
    with pytest.raises(ValueError, match="undocumented"):
        reg.register("m", references=["x"], parameters={"a": "m"}, limits={"b": "[0, 1]"})(
            lambda: None)


@pytest.mark.parametrize("option, field, interval", [
    ('churning_cage = { gap = "-1 mm" }', "churning_cage.gap", "[1e-06, inf)"),
    ('churning_cage = { gap = "1e-30 mm" }', "churning_cage.gap", "[1e-06, inf)"),
    ('churning_inner_ring = { shoulder_length = "-5 mm" }',
     "churning_inner_ring.shoulder_length", "[0, inf)"),
    ('churning_elements = { oil_fraction = 1.5 }', "churning_elements.oil_fraction", "[0, 1]"),
    ('cage_guide = { critical_film = "-1 um" }', "cage_guide.critical_film", "(0, inf)"),
    ('pocket_friction = { element_share = "150 %" }', "pocket_friction.element_share",
     "[0, 1]"),
    ('raceway_traction = { n_major = 1 }', "raceway_traction.n_major", "[2, 256]"),
])
def test_scene_value_outside_its_interval_is_refused_at_check(option, field, interval):
    with pytest.raises(InputError) as err:
        simulation(option)
    msg = str(err.value)
    assert f"models.heat_source_options.{field}" in msg
    assert interval in msg
    written = option.split("=", 2)[2].strip(" }")
    assert written.strip('"') in msg  # the value as the user wrote it


def test_values_inside_their_interval_are_converted_and_kept():
    # (oil_fraction is the ball kinematics' own, and with it parker_constant, which it would
    # leave unused: refused, test_option_clash_at_build.py, test_lead18_roller_drag_options)
    sim = simulation('churning_cage = { gap = "0.5 mm" }, '
                     'pocket_friction = { element_share = "50 %" }')
    assert sim.source_options["churning_cage"] == {"gap": pytest.approx(5e-4)}
    assert sim.source_options["pocket_friction"]["element_share"] == pytest.approx(0.5)


def test_value_set_by_a_model_is_checked_where_the_source_reads_it():
    """Options that do not come from the scene (e.g. a kinematics model's force-model
    options) meet the same interval at HeatContext.option."""
    from thermobearing.heat_sources import HeatContext
    from thermobearing.state import KinematicState, OilSupply, OperatingPoint

    ctx = HeatContext.isothermal(320.0, bearing=None, lubricant=None,
                                 supply=OilSupply("jet", 5e-4, 308.15),
                                 operating=OperatingPoint(188.5, 1000.0, 0.0),
                                 kinematics=KinematicState(
                                     inner_speed=188.5, outer_speed=0.0, cage_speed=80.0,
                                     orbital_speed=np.full(3, 80.0), element_spin=0.0,
                                     contacts=()), traction=None,
                                 options={"churning_cage": {"gap": -2e-3, "oil_fraction": 0.3}})
    assert ctx.option("churning_cage", "oil_fraction", 0.0) == 0.3
    assert ctx.option("churning_cage", "parker_constant", 7.0) == 7.0  # default, unchecked
    with pytest.raises(InputError, match=r"options\[churning_cage\]\.gap"):
        ctx.option("churning_cage", "gap", 1e-3)


def test_every_limit_is_an_interval_of_a_documented_numeric_parameter():
    for e in HEAT_SOURCES.entries():
        for key, iv in e.limits.items():
            assert key in e.parameters
            assert isinstance(iv, Interval) and iv.low <= iv.high
    assert np.all([bool(e.limits) for e in HEAT_SOURCES.entries()
                   if e.name in ("churning_cage", "churning_elements", "churning_inner_ring",
                                 "cage_guide", "pocket_friction", "rib_friction",
                                 "raceway_traction")])
