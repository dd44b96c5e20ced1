"""Property tests, round 6: the scene reader's units (:mod:`thermobearing.scene`, session 24),
beside the bearing and lubricant readers' units of test_prop22_bearing_config.py /
test_prop22_lubricant_config.py, the unit conversions of test_prop21_units.py and the TOML
writer of test_prop23_toml.py.

The quantities of a scene (the default ``qj1044_rig``: oil flow and inlet temperature,
ambient and start temperatures, shaft speed, radial load, step duration and the axial-load
ladder's start / stop / step) are drawn at random and written each in a random unit of its
kind (e.g. a flow in L/min, m^3/s, gal/min; a temperature in degC, K, degF, degR; a speed
in rpm, rad/s, rev/s, deg/s; a force in N, kN, lbf, kgf; a time in s, min, h, ms, day):

- reading: the scene holds the same SI values as the same scene written in SI (to 1e-12:
  the decimal text of a value in another unit, 17 significant digits, is the value to
  round-off);
- round trip: :meth:`Scene.to_toml` then :func:`loads_scene` gives the same SI values (to
  1e-11: written back in the user's units to 12 digits, scene_values._fmt) and writes each
  field in the unit it was read in, in pint's spelling (``r/min`` as ``rpm``; the schedule
  as its list of steps).
"""

from __future__ import annotations

import copy
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.scene import Scene, configs_dir, loads_scene
from thermobearing.units import from_si, quantity_unit

UNITS = {
    "volume_flow": ["m**3/s", "L/min", "l/min", "mL/min", "L/h", "gal/min", "cm3/min"],
    "temperature": ["K", "degC", "degF", "degR", "\u00b0C", "kelvin"],
    "angular_speed": ["rad/s", "rpm", "r/min", "rev/min", "rev/s", "deg/s"],
    "force": ["N", "kN", "lbf", "kgf", "MN"],
    "time": ["s", "min", "h", "ms", "day"],
}

#: (path in the scene's TOML, kind, SI range of the random value)
FIELDS = [
    (("supply", "flow"), "volume_flow", (1e-6, 1e-3)),
    (("supply", "inlet_temperature"), "temperature", (280.0, 360.0)),
    (("environment", "ambient_temperature"), "temperature", (280.0, 330.0)),
    (("environment", "initial_temperature"), "temperature", (280.0, 330.0)),
    (("schedule", "speed"), "angular_speed", (10.0, 1000.0)),
    (("schedule", "radial_load"), "force", (10.0, 5e4)),
    (("schedule", "step_duration"), "time", (10.0, 3600.0)),
]


def _base() -> dict:
    with open(configs_dir() / "scenes" / "qj1044_rig.toml", "rb") as fh:
        return tomllib.load(fh)


def _set(d: dict, path: tuple[str, ...], value) -> None:
    for key in path[:-1]:
        d = d[key]
    d[path[-1]] = value


def _written(value: float, unit: str, kind: str) -> str:
    """``value`` [SI] as the text a user writes in ``unit`` (17 significant digits)."""
    return f"{from_si(value, unit, kind):.17g} {unit}"


def _si(scene: Scene) -> list[float]:
    """The scene's SI values of FIELDS and of the axial ladder (one per step)."""
    steps = scene.schedule.steps
    return [scene.supply.flow, scene.supply.inlet_temperature,
            scene.environment.ambient_temperature, scene.environment.initial_temperature,
            steps[0].speed, steps[0].radial_load, steps[0].duration,
            *[s.axial_load for s in steps]]


@st.composite
def scenes(draw):
    """(scene dict in SI, the same scene in random units, the unit of each field)."""
    si, mixed, units = _base(), _base(), {}
    for path, kind, (lo, hi) in FIELDS:
        value = draw(st.floats(lo, hi))
        unit = draw(st.sampled_from(UNITS[kind]))
        _set(si, path, _written(value, "s" if kind == "time" else _SI[kind], kind))
        _set(mixed, path, _written(value, unit, kind))
        units[path] = unit
    # the axial ladder: 2..8 steps of 100..5000 N from 0..2000 N, each end in its own unit
    a0 = draw(st.floats(0.0, 2000.0))
    da = draw(st.floats(100.0, 5000.0))
    a1 = a0 + draw(st.integers(1, 7)) * da
    ladder_si, ladder = {}, {}
    for key, value in (("start", a0), ("stop", a1), ("step", da)):
        unit = draw(st.sampled_from(UNITS["force"]))
        ladder_si[key] = _written(value, "N", "force")
        ladder[key] = _written(value, unit, "force")
    si["schedule"]["axial_load_steps"] = ladder_si
    mixed["schedule"]["axial_load_steps"] = ladder
    return si, mixed, units


_SI = {"volume_flow": "m**3/s", "temperature": "K", "angular_speed": "rad/s", "force": "N"}


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scenes())
def test_a_scene_in_any_units_is_the_same_scene_and_writes_its_units_back(case):
    si, mixed, units = case
    ref = Scene.from_dict(copy.deepcopy(si))
    got = Scene.from_dict(copy.deepcopy(mixed))
    assert len(got.schedule.steps) == len(ref.schedule.steps)
    assert _si(got) == pytest.approx(_si(ref), rel=1e-12, abs=1e-12)
    back = loads_scene(got.to_toml())
    assert _si(back) == pytest.approx(_si(got), rel=1e-11, abs=1e-11)
    written = tomllib.loads(got.to_toml())
    step_key = {"speed": "speed", "radial_load": "radial_load", "step_duration": "duration"}
    for path, unit in units.items():
        if path[0] == "schedule":   # written back as the list of steps
            values = [step[step_key[path[1]]] for step in written["schedule"]["steps"]]
        else:
            values = [written[path[0]][path[1]]]
        # in pint's spelling of that unit (quantity_unit: "r/min" is written "rpm")
        assert {quantity_unit(v) for v in values} == {quantity_unit(f"1 {unit}")}, \
            (path, values)
