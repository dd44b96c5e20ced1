"""One NU 214 tour scene: the NU214 preset on a 1 L/min jet of ISO VG 32 at 40 degC,
ambient 25 degC. The tests give the schedule and outputs (TOML text of each part)."""

from __future__ import annotations

NU214_JET = """title = "{title}"
[[bearings]]
name = "crb"
preset = "NU214"
[lubricant]
preset = "ISO_VG32"
[supply]
method = "jet"
flow = "1 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "25 degC"
{environment}
[schedule]
{schedule}
[outputs]
want = {want}
"""

#: the supply lines, for tests that replace the supply
JET_SUPPLY = 'method = "jet"\nflow = "1 L/min"\ninlet_temperature = "40 degC"'


def nu214_jet_scene(*, title: str, schedule: str, want: str,
                    environment: str = "") -> str:
    """The NU 214 tour scene's TOML text with the given parts."""
    return NU214_JET.format(title=title, schedule=schedule, want=want,
                            environment=environment)
