"""One NU 214 tour scene: the NU214 preset on a 1 L/min jet of ISO VG 32 at 40 degC,
ambient 25 degC. The tests give the schedule and outputs (TOML text of each part)."""

from __future__ import annotations

from scene_parts import JET_1LPM_40C, VG32_JET

NU214_JET = """title = "{title}"
[[bearings]]
name = "crb"
preset = "NU214"
""" + VG32_JET + """[environment]
ambient_temperature = "25 degC"
{environment}
[schedule]
{schedule}
[outputs]
want = {want}
"""

#: the supply lines, for tests that replace the supply
JET_SUPPLY = JET_1LPM_40C.rstrip("\n")


def nu214_jet_scene(*, title: str, schedule: str, want: str,
                    environment: str = "") -> str:
    """The NU 214 tour scene's TOML text with the given parts."""
    return NU214_JET.format(title=title, schedule=schedule, want=want,
                            environment=environment)
