"""Session-24 user tour F: ``calibrate``'s model runs dropped the scene's ``[outputs]
interval``, so the fit compared a 30-s thermocouple log with straight lines between the
chunk ends while ``run`` compared it with the interval's rows: the oil sensor's initial
RMSE was 0.79 K in the fit and 0.37 K in the run of the same scene (QJ1044 rig, 3 steps,
43-s chunks, a 1-min interval)."""

from __future__ import annotations

import dataclasses

import numpy as np

from thermobearing import load_scene
from thermobearing.calibrate_model import predicted_temperatures
from thermobearing.simulation import Simulation


def _scene(interval: float | None):
    scene = load_scene("qj1044_synthetic_measured")
    steps = tuple(dataclasses.replace(s, duration=120.0) for s in scene.schedule.steps[:2])
    return scene.with_changes(
        schedule=dataclasses.replace(scene.schedule, steps=steps),
        solver=dataclasses.replace(scene.solver, chunk=60.0),
        outputs=dataclasses.replace(scene.outputs, interval=interval,
                                    want=("temperatures", "losses")))


def test_the_fit_runs_the_scene_with_its_interval():
    scene = _scene(20.0)
    fit = predicted_temperatures(scene)
    run = Simulation(scene, progress=False).run().tables["temperatures"]
    t = fit["time [s]"].to_numpy(float)
    # the interval's rows are there (not the 60-s chunk ends only) ...
    assert np.all(np.isin(np.arange(0.0, 240.0 + 1e-9, 20.0), np.round(t, 9)))
    # ... and the fit's curve is the run's
    assert np.array_equal(t, run["time [s]"].to_numpy(float))
    for col in fit.columns:
        np.testing.assert_allclose(fit[col].to_numpy(float), run[col].to_numpy(float),
                                   rtol=0, atol=1e-9)


def test_without_an_interval_the_chunk_ends_only():
    t = predicted_temperatures(_scene(None))["time [s]"].to_numpy(float)
    assert not np.isin(20.0, np.round(t, 9))
    assert t[-1] == 240.0
