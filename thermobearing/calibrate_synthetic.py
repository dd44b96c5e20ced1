"""Clearly labelled synthetic thermocouple data for calibration and sensor planning.

One job: :func:`synthetic_measurements` -- the scene's predicted node temperatures
(:func:`thermobearing.calibrate_model.predicted_temperatures`) at chosen "true" parameter
values plus seeded Gaussian noise (``numpy.random.default_rng``), every row labelled
``SYNTHETIC`` (:data:`SYNTHETIC_LABEL`) so it can never pass for rig data. Used to exercise
import, overlay and calibration, and to check before a rig test that a planned set of
sensors can identify a parameter. Split out of ``calibrate.py`` (names re-exported there).
Units: degC and minutes in the table, as a rig's file would have them.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .calibrate_model import predicted_temperatures
from .errors import InputError
from .scene import Scene
from .sweep_params import assign_path, check_path

__all__ = ["SYNTHETIC_LABEL", "synthetic_measurements"]


SYNTHETIC_LABEL = ("SYNTHETIC: thermobearing model output + Gaussian noise "
                   "(sd {sd:g} K, seed {seed}); not measured data")


def synthetic_measurements(scene: Scene, sensors: Mapping[str, str], *,
                           values: Mapping[str, Any] | None = None, noise_sd: float = 0.1,
                           seed: int = 0, every: float | None = None,
                           decimals: int = 2) -> pd.DataFrame:
    """Clearly labelled synthetic thermocouple data: the scene's predicted node
    temperatures plus seeded Gaussian noise, for exercising import, overlay and
    calibration (and for checking that a planned set of sensors can identify a parameter
    before a rig test).

    Parameters
    ----------
    scene : the scene to run (its ``[measured]`` table, if any, is ignored).
    sensors : column name -> node (``{"TC_DE": "drive_end.housing"}``).
    values : dotted path -> value set in the scene before the run (the "true" values).
    noise_sd : standard deviation of the added noise [K].
    seed : seed of ``numpy.random.default_rng``.
    every : keep only output times that are multiples of this interval [s] (default:
        every output row of the run).
    decimals : rounding of the written temperatures [degC].

    Returns
    -------
    DataFrame with ``time [min]``, one degC column per sensor and a ``data_origin`` column
    that says on every row that the numbers are synthetic.
    """
    if noise_sd < 0 or not math.isfinite(noise_sd):
        raise InputError("noise_sd", noise_sd, "a standard deviation >= 0 K")
    d = json.loads(json.dumps(scene.to_dict()))  # deep copy: to_dict shares nested tables
    d.pop("measured", None)
    for path, v in (values or {}).items():
        check_path(d, path, "values")
        assign_path(d, path, v)
    sc = Scene.from_dict(d, Path(scene.base_dir) if scene.base_dir else None)
    temps = predicted_temperatures(sc)
    for col, node in sensors.items():
        if f"{node} [degC]" not in temps:
            nodes = [c[:-7] for c in temps.columns if c.endswith(" [degC]")]
            raise InputError(f"sensors[{col!r}]", node, "a node: " + ", ".join(nodes))
    t = temps["time [s]"].to_numpy(float)
    keep = np.ones(t.size, bool)
    if every is not None:
        if not every > 0:
            raise InputError("every", every, "an interval > 0 s")
        keep = np.abs(t / every - np.round(t / every)) < 1e-6
    rng = np.random.default_rng(seed)
    out = pd.DataFrame({"time [min]": np.round(t[keep] / 60.0, 6)})
    for col, node in sensors.items():
        clean = temps[f"{node} [degC]"].to_numpy(float)[keep]
        out[col] = np.round(clean + rng.normal(0.0, noise_sd, clean.size), decimals)
    out["data_origin"] = SYNTHETIC_LABEL.format(sd=noise_sd, seed=seed)
    return out
