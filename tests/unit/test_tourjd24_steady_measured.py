"""Session-24 user tour F: a steady scene with a thermocouple file ran, ``check`` read and
described the file, and nothing was compared, without a word. The scene now says that
``[measured]`` is not used by a steady run; a transient run keeps no such note."""

from __future__ import annotations

import dataclasses

from thermobearing import load_scene
from thermobearing.simulation import Simulation

NOTE = "[measured] is not used: a steady run"


def _notes(mode: str) -> list[str]:
    scene = load_scene("qj1044_synthetic_measured")
    scene = scene.with_changes(outputs=dataclasses.replace(scene.outputs, mode=mode,
                                                           want=("temperatures", "losses")))
    return [str(n) for n in Simulation(scene, progress=False).notes]


def test_a_steady_run_says_its_measured_file_is_not_used():
    hits = [n for n in _notes("steady") if n.startswith(NOTE)]
    assert len(hits) == 1
    assert 'outputs.mode = "transient"' in hits[0]


def test_a_transient_run_has_no_such_note():
    assert not any(n.startswith(NOTE) for n in _notes("transient"))
