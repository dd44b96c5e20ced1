"""One small scene for input and warning probes: an SKF 6304 on a 2 L/min jet of ISO VG 68 at
40 degC, 3000 r/min, 1 kN radial, one 2-min step. The tests change what they probe through
the keyword arguments (TOML text of each part)."""

from __future__ import annotations

PROBE = """
title = "{title}"
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
{environment}
[schedule]
speed = "3000 rpm"
radial_load = "1000 N"
{axial}
step_duration = "2 min"
[models]
{models}
{network}
[outputs]
mode = "{mode}"
want = {want}
"""


def probe_scene(*, title: str = "probe", environment: str = 'ambient_temperature = "30 degC"',
                axial: str = 'axial_load = "200 N"',
                models: str = 'kinematics = "race_control"', network: str = "",
                mode: str = "steady", want: str = '["losses"]') -> str:
    """The probe scene's TOML text with the given parts."""
    return PROBE.format(title=title, environment=environment, axial=axial, models=models,
                        network=network, mode=mode, want=want)
