"""TOML tables that many unit-test scenes share, written once (text of whole tables, each
ending in a newline; none but :data:`PAPER002_NETWORK` holds a brace, so that a
``str.format`` template can hold them).
A test builds its scene by concatenation, e.g.
``scene_title("t") + QJ1044_DE + PAPER002_OIL + ...``, and writes out what is particular to
it (schedule, models, outputs)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

#: the paper 002 rig's bearing (QJ1044), named "de" (drive end) and "nde" (the second of a
#: pair on one shaft)
QJ1044_DE = '[[bearings]]\nname = "de"\npreset = "QJ1044"\n'
QJ1044_NDE = '[[bearings]]\nname = "nde"\npreset = "QJ1044"\n'

#: the paper 002 rig's oil: ISO VG 46, 33 L/min at 35 degC (no method: the scene default)
PAPER002_OIL = ('[lubricant]\npreset = "ISO_VG46"\n'
                '[supply]\nflow = "33 L/min"\ninlet_temperature = "35 degC"\n')
#: the same oil on a jet
PAPER002_JET = ('[lubricant]\npreset = "ISO_VG46"\n'
                '[supply]\nmethod = "jet"\nflow = "33 L/min"\ninlet_temperature = "35 degC"\n')
#: the paper 002 rig's ambient, the oil's inlet temperature
PAPER002_AMBIENT = '[environment]\nambient_temperature = "35 degC"\n'
#: the paper 002 rig's four-node network, housing 510 mm x 140 mm (an inline table: braces)
PAPER002_NETWORK = ('[network]\ntemplate = "four_node_paper002"\nparameters = '
                    '{ housing_outer_diameter = "510 mm", housing_length = "140 mm" }\n')

#: the SKF 6304 of the input probes and fuzz regressions, named "a"
SKF6304_A = '[[bearings]]\nname = "a"\npreset = "SKF6304"\n'
#: a QJ1044 named "a"
QJ1044_A = '[[bearings]]\nname = "a"\npreset = "QJ1044"\n'

#: the oil of scene-fuzz case 17 (scripts/fuzz_scenes.py, L0 rung): ISO VG 68 circulated at
#: 8.67869 L/min in 112.6 degC air
FUZZ17_OIL = ('[lubricant]\npreset = "ISO_VG68"\n'
              '[supply]\nmethod = "circulation"\nflow = "8.67869 L/min"\n'
              '[environment]\nambient_temperature = "112.6 degC"\n')
#: the global-friction model alone (no kinematics), the L0 rung
GLOBAL_FRICTION_ONLY = '[models]\nkinematics = "none"\nheat_sources = ["global_friction"]\n'
#: ISO VG 46 on a 5 L/min jet at 35 degC
VG46_JET_5LPM = ('[lubricant]\npreset = "ISO_VG46"\n'
                 '[supply]\nmethod = "jet"\nflow = "5 L/min"\ninlet_temperature = "35 degC"\n')

#: the lines of a [supply] table: a 1 L/min jet (inlet temperature: the scene default), and
#: the same at 40 degC
JET_1LPM = 'method = "jet"\nflow = "1 L/min"\n'
JET_1LPM_40C = JET_1LPM + 'inlet_temperature = "40 degC"\n'
#: ISO VG 32 on a 1 L/min jet; the [supply] table is last, so that an inlet temperature line
#: may follow
VG32_JET_1LPM = '[lubricant]\npreset = "ISO_VG32"\n[supply]\n' + JET_1LPM
#: ISO VG 46 on a 1 L/min jet (inlet temperature: the scene default)
VG46_JET_1LPM = '[lubricant]\npreset = "ISO_VG46"\n[supply]\n' + JET_1LPM
#: ISO VG 68 on a 1 L/min jet (the [supply] table last, as in VG32_JET_1LPM)
VG68_JET_1LPM = '[lubricant]\npreset = "ISO_VG68"\n[supply]\n' + JET_1LPM
#: ISO VG 32 on a 1 L/min jet at 40 degC
VG32_JET = '[lubricant]\npreset = "ISO_VG32"\n[supply]\n' + JET_1LPM_40C

#: ISO VG 46 on a 2 L/min jet at 40 degC
VG46_JET_2LPM = ('[lubricant]\npreset = "ISO_VG46"\n'
                 '[supply]\nmethod = "jet"\nflow = "2 L/min"\ninlet_temperature = "40 degC"\n')
#: ISO VG 46, 2 L/min at 40 degC (no method: the scene default)
VG46_2LPM = ('[lubricant]\npreset = "ISO_VG46"\n'
             '[supply]\nflow = "2 L/min"\ninlet_temperature = "40 degC"\n')

#: ISO VG 32 as oil-air, 30 mm^3/h (the spindle tours)
VG32_OIL_AIR = ('[lubricant]\npreset = "ISO_VG32"\n'
                '[supply]\nmethod = "oil_air"\nflow = "30 mm3/h"\n')

#: a 22 degC room (the roller-rig and spindle tours)
ROOM_22C = '[environment]\nambient_temperature = "22 degC"\n'

#: the race-control kinematics
RACE_CONTROL = '[models]\nkinematics = "race_control"\n'


def scene_title(text: str) -> str:
    """The scene's title line (after a newline, as the tests' scene texts start)."""
    return f'\ntitle = "{text}"\n'


def scene_strings(doc: Any) -> Iterator[str]:
    """Every string value in a parsed scene document (tables, arrays, nested), depth first."""
    if isinstance(doc, dict):
        for v in doc.values():
            yield from scene_strings(v)
    elif isinstance(doc, list):
        for v in doc:
            yield from scene_strings(v)
    elif isinstance(doc, str):
        yield doc
