"""User tour 21, loss breakdown of an NU214 over a speed x load map (losses only, jet at
40 degC, ambient 25 degC, no initial temperature in the scene): the report's conditions
line said 'initial temperature 25 degC' while its breakdown said the losses were evaluated
at the 40 degC inlet because the scene sets no initial temperature; the sweep report's base
scene said the same 25 degC and nothing else on the temperature.
"""

from __future__ import annotations

from nu214_scene import JET_SUPPLY, nu214_jet_scene

from thermobearing.report_context import supply_text
from thermobearing.scene import loads_scene

SCHEDULE = """speed = "5000 rpm"
radial_load = "5 kN"
axial_load = "0 kN"
step_duration = "1 min"
"""


def _text(want: str, initial: str = "") -> str:
    return nu214_jet_scene(title="tour 21 conditions", schedule=SCHEDULE, want=want,
                           environment=initial)


def _scene(want: str, initial: str = ""):
    return loads_scene(_text(want, initial))


def test_losses_only_without_initial_temperature_names_the_inlet():
    text = supply_text(_scene('["losses", "kinematics"]'), None)
    assert "initial temperature 25 degC" not in text
    assert text.endswith("ambient 25 degC; no initial temperature set and no thermal "
                         "network: parts and oil at the inlet temperature, 40 degC")


def test_losses_only_with_an_initial_temperature_keeps_it():
    text = supply_text(_scene('["losses"]', 'initial_temperature = "60 degC"'), None)
    assert text.endswith("ambient 25 degC, initial temperature 60 degC")


def test_network_run_without_initial_temperature_says_it_is_the_ambient():
    text = supply_text(_scene('["temperatures", "losses"]'), None)
    assert text.endswith("ambient 25 degC, initial temperature 25 degC (the ambient: the "
                         "scene sets none)")


def test_oil_bath_losses_only_runs_at_the_ambient():
    scene = loads_scene(_text('["losses"]').replace(
        JET_SUPPLY,
        'method = "oil_bath"\nlevel = "5 mm"'))
    text = supply_text(scene, None)
    assert text.endswith("no initial temperature set and no thermal network: parts and oil "
                         "at the ambient, 25 degC")
