"""The model that calibration fits: a scene run reduced to temperatures, and its residuals.

One job: read and check the scene's measured temperatures (:func:`measured_table`), run a
scene with its outputs reduced to the temperature table (:func:`predicted_temperatures`),
and evaluate the residuals r_k = T_pred(node of sensor s, t_k) - T_meas(s, t_k) [K] and
their forward-difference Jacobian over the fitted coordinates (:class:`_Model`, with a run
counter and a cache), plus the per-sensor error table (:func:`_sensor_table`). The
definitions are those of the docstring of :mod:`thermobearing.calibrate` (least squares of
Virtanen et al. 2020, scipy). Split out of ``calibrate.py`` (names re-exported there).
Units: SI (K, s) inside; the measured table in degC as the scene's files give it.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from .calibrate_params import FitParameter, _apply
from .errors import ConvergenceError, InputError
from .report_measured import largest_error
from .scene import Scene

__all__ = ["measured_table", "predicted_temperatures"]


def measured_table(scene: Scene, nodes: Sequence[str]) -> pd.DataFrame:
    """The scene's measured temperatures (``time [s]`` + one degC column per sensor),
    checked: every mapped node exists. Gaps (empty cells, dropout flags: NaN) are kept; the
    fit leaves each sensor's gaps out of its residuals (a single dropout made a logger file
    unusable for calibration), and a sensor whose every reading is a gap out of the fit
    altogether, as ``thermobearing run`` leaves it out of the comparison, with the same
    note (:func:`thermobearing.measured.measured_notes`; :attr:`_Model.notes`)."""
    from .measured import read_scene_measured

    if scene.measured is None:
        raise InputError("measured", None, "a [measured] table (file, time_column, unit, "
                         "columns = { csv column = node }) in the scene")
    for col, node in scene.measured.columns.items():
        if node not in nodes:
            raise InputError(f"measured.columns[{col!r}]", node,
                             "a node of the scene's network: " + ", ".join(nodes))
    # one reader (thermobearing.measured): text cells, times going backwards, unreadable
    # times are named InputErrors there; empty cells and dropout flags come back as NaN
    return read_scene_measured(scene)


def _network_nodes(scene: Scene) -> list[str]:
    from .coupled import build_network
    from .simulation import Simulation

    return list(build_network(Simulation(scene, progress=False)).state_nodes)


def predicted_temperatures(scene: Scene) -> pd.DataFrame:
    """Run the scene (outputs reduced to temperatures, its ``interval`` kept) and return its
    temperature table. The interval's rows are the curve ``run`` compares with the sensors:
    without them the fit met the chunk ends only (a 30-s oil log against 43-s chunk ends:
    the oil sensor's RMSE 0.79 K in the fit, 0.37 K in the run of the same scene)."""
    from .simulation import Simulation

    run_scene = scene.with_changes(outputs=dataclasses.replace(
        scene.outputs, want=("temperatures",)))
    res = Simulation(run_scene, progress=False).run()
    return res.tables["temperatures"]


class _Model:
    """Residual function over the fitted coordinates, with a run counter and a cache."""

    def __init__(self, scene: Scene, params: Sequence[FitParameter], measured: pd.DataFrame,
                 column_map: Mapping[str, str],
                 callback: Callable[[int, dict[str, float], float], None] | None) -> None:
        self.base = scene.to_dict()
        self.base_dir = Path(scene.base_dir) if scene.base_dir else None
        self.params = list(params)
        self.measured = measured
        self.column_map = dict(column_map)
        self.runs = 0
        self.callback = callback
        self._cache: dict[bytes, np.ndarray] = {}
        t_end = scene.schedule.duration
        t = measured["time [s]"].to_numpy(float)
        self.inside = (t >= 0.0) & (t <= t_end * (1 + 1e-12))
        self.dropped = int((~self.inside).sum())
        self.times = t[self.inside]
        # per sensor: the samples inside the protocol that are readings (gaps left out)
        self.keep = {s: self.inside & np.isfinite(measured[s].to_numpy(float))
                     for s in self.column_map}
        self.gaps = {s: int((self.inside & ~k).sum()) for s, k in self.keep.items()}
        self.n_points = sum(int(k.sum()) for k in self.keep.values())
        #: what the fit left out beyond single gaps: a sensor whose every reading is a gap
        #: (no residual, its row in the sensor table with 0 points), in the words of the
        #: run's measured-vs-predicted notes
        self.notes = _all_gap_notes(measured, self.column_map)

    def values(self, z: np.ndarray) -> list[float]:
        return [p.from_z(float(zi)) for p, zi in zip(self.params, z, strict=True)]

    def scene(self, z: np.ndarray) -> Scene:
        return _apply(self.base, self.params, self.values(z), self.base_dir)

    def _where(self, z: np.ndarray) -> str:
        return ", ".join(f"{p.path} = {p.show(v):.6g}"
                         for p, v in zip(self.params, self.values(z), strict=True))

    def split(self, r: np.ndarray) -> dict[str, np.ndarray]:
        out, start = {}, 0
        for s in self.column_map:
            n = int(self.keep[s].sum())
            out[s], start = r[start:start + n], start + n
        return out

    def residuals(self, z: np.ndarray) -> np.ndarray:
        key = np.asarray(z, float).tobytes()
        hit = self._cache.get(key)
        if hit is not None:
            return hit
        try:
            sc = self.scene(z)
            temps = predicted_temperatures(sc)
        except InputError as exc:
            raise InputError(exc.field, exc.value, f"{exc.allowed} (model run at "
                             f"{self._where(z)}; narrow the bounds of the fit)") from exc
        except ConvergenceError as exc:
            raise ConvergenceError("calibration model run", exc.residual,
                                   f"{exc} (at {self._where(z)})", exc.state) from exc
        self.runs += 1
        t_model = temps["time [s]"].to_numpy(float)
        t_meas = self.measured["time [s]"].to_numpy(float)
        parts = []
        for sensor, node in self.column_map.items():
            keep = self.keep[sensor]
            pred = np.interp(t_meas[keep], t_model, temps[f"{node} [degC]"].to_numpy(float))
            parts.append(pred - self.measured[sensor].to_numpy(float)[keep])
        r = np.concatenate(parts)
        if not np.all(np.isfinite(r)):
            raise ConvergenceError("calibration", math.inf, "non-finite predicted temperature",
                                   {"values": self.values(z)})
        if len(self._cache) > 64:
            self._cache.clear()
        self._cache[key] = r
        if self.callback is not None:
            self.callback(self.runs, {p.path: p.show(v) for p, v in
                                      zip(self.params, self.values(z), strict=True)},
                          float(np.sqrt(np.mean(r**2))))
        return r

    def jacobian(self, z: np.ndarray, columns: Sequence[int] | None = None) -> np.ndarray:
        """Forward differences in z (backward where the forward step leaves the bounds);
        ``columns``: only these parameters' columns (one model run each), in that order."""
        z = np.asarray(z, float)
        r0 = self.residuals(z)
        cols = list(range(z.size)) if columns is None else list(columns)
        J = np.empty((r0.size, len(cols)))
        for k, j in enumerate(cols):
            p = self.params[j]
            lo, hi = p.z_bounds()
            h = p.fd_step if z[j] + p.fd_step <= hi else -p.fd_step
            if not lo <= z[j] + h <= hi:
                h = p.fd_step
            zp = z.copy()
            zp[j] += h
            J[:, k] = (self.residuals(zp) - r0) / h
        return J


def _all_gap_notes(measured: pd.DataFrame, column_map: Mapping[str, str]) -> list[str]:
    """The reader's note (:func:`thermobearing.measured.measured_notes`) of each mapped
    sensor whose every reading is a gap ("TC1: every reading (120) is a gap (120 empty
    cells); this sensor is not compared with the model"); a file read without the
    reader's gap counts gets a note of the same words."""
    from .measured import measured_notes

    empty = [s for s in column_map if not np.isfinite(measured[s].to_numpy(float)).any()]
    if not empty:
        return []
    said = measured_notes(measured)
    out = []
    for sensor in empty:
        mine = [n for n in said if n.startswith(f"{sensor}: every reading")]
        out += mine or [f"{sensor}: every reading ({len(measured)}) is a gap; this sensor "
                        "is not compared with the model"]
    return out


def _sensor_table(model: _Model, r: np.ndarray, r_initial: np.ndarray) -> pd.DataFrame:
    """Per sensor: points and the errors after / before the fit [K]; a sensor without a
    reading in the fit keeps its row with 0 points and no errors (NaN)."""
    rows = []
    after, before = model.split(r), model.split(r_initial)
    for sensor, node in model.column_map.items():
        e, e0 = after[sensor], before[sensor]
        if e.size == 0:
            rows.append({"sensor": sensor, "node": node, "points": 0,
                         "RMSE [K]": math.nan, "max error [K]": math.nan,
                         "mean error [K]": math.nan, "initial RMSE [K]": math.nan})
            continue
        rows.append({"sensor": sensor, "node": node, "points": int(e.size),
                     "RMSE [K]": float(np.sqrt(np.mean(e**2))),
                     "max error [K]": largest_error(e),
                     "mean error [K]": float(np.mean(e)),
                     "initial RMSE [K]": float(np.sqrt(np.mean(e0**2)))})
    return pd.DataFrame(rows)
