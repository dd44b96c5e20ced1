"""Result of a calibration: fitted values, tables, summary and the calibrated scene.

One job: what :func:`thermobearing.calibrate.calibrate` returns -- per-parameter values with
their linearised 95 % confidence intervals (:class:`FittedParameter`; Bates and Watts 1988,
ch. 2; Seber and Wild 1989, ch. 5) and :class:`CalibrationResult` with its parameter table,
summary text, and the calibrated scene as TOML (file paths re-based to the output folder,
:func:`_rebase_paths`) written next to the tables. No fitting here. Split out of
``calibrate.py`` (names re-exported there). Units: display units of the scene.
"""

from __future__ import annotations

import datetime as _dt
import json
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .scene import Scene, dumps_toml

__all__ = ["REFERENCES", "CalibrationResult", "FittedParameter"]

#: citation keys of the method (least_squares; linearised intervals)
REFERENCES = ("virtanen2020_scipy", "bates_watts1988", "seber_wild1989")


@dataclass(frozen=True)
class FittedParameter:
    """Result for one parameter (values in the display unit).

    ``ci_low``/``ci_high`` bound the approximate (linearised) 95 % confidence interval;
    ``std_error_z`` is the standard error in the fitted coordinate (in ln for log
    parameters, i.e. roughly a relative standard error; in K for temperatures).
    ``no_influence``: the parameter did not change the predicted temperatures at the
    sensors (zero Jacobian column at the start); it was left at its start, out of the fit,
    with an unbounded interval.
    """

    path: str
    unit: str
    transform: str
    initial: float
    value: float
    ci_low: float
    ci_high: float
    std_error_z: float
    at_bound: bool = False
    no_influence: bool = False


@dataclass
class CalibrationResult:
    """Everything a calibration produced.

    Attributes
    ----------
    parameters : fitted values with their approximate 95 % confidence intervals.
    sensors : per-sensor table after the fit: sensor, node, points, ``RMSE [K]``,
        ``max error [K]``, ``mean error [K]`` (bias), and ``initial RMSE [K]``.
    rmse : RMSE of all residuals [K] after the fit; ``initial_rmse`` before.
    residual_sd : s = sqrt(SSR / (m - p)) [K].
    points, dof : residual count m and m - p.
    runs : number of model runs (scene simulations) the fit used.
    success, message : from least_squares.
    covariance, correlation : of the fitted coordinates z (linearised).
    identifiable : False when J^T J is (numerically) singular: the data cannot separate
        the parameters (the intervals are then infinite), or when a parameter has no
        influence (``FittedParameter.no_influence``; the others keep their intervals).
    scene : the calibrated scene.
    notes : what the user should know (dropped points, bounds hit, ...).
    """

    parameters: tuple[FittedParameter, ...]
    sensors: pd.DataFrame
    rmse: float
    initial_rmse: float
    residual_sd: float
    points: int
    dof: int
    runs: int
    success: bool
    message: str
    covariance: np.ndarray
    correlation: np.ndarray
    identifiable: bool
    scene: Scene
    measured_file: str
    column_map: Mapping[str, str]
    notes: list[str] = field(default_factory=list)
    references: tuple[str, ...] = REFERENCES

    def table(self) -> pd.DataFrame:
        """The fitted parameters as a DataFrame (display units)."""
        return pd.DataFrame([{
            "parameter": p.path, "unit": p.unit, "initial": p.initial, "fitted": p.value,
            "95% CI low": p.ci_low, "95% CI high": p.ci_high,
            "std error (fit coord.)": p.std_error_z, "fit coord.": p.transform,
            "at bound": p.at_bound} for p in self.parameters])

    def summary_text(self) -> str:
        """Parameter table, per-sensor residuals and the fit statistics as text."""
        fmt = {"float_format": lambda v: f"{v:.4g}"}
        lines = ["fitted parameters (95 % confidence intervals are linearised estimates, "
                 "(J^T J)^-1 s^2):",
                 self.table().to_string(index=False, **fmt), "",
                 "residuals per sensor (predicted - measured):",
                 self.sensors.to_string(index=False, **fmt), "",
                 f"RMSE {self.rmse:.4g} K (before {self.initial_rmse:.4g} K), s = "
                 f"{self.residual_sd:.4g} K, {self.points} points, {self.dof} degrees of "
                 f"freedom, {self.runs} model runs; "
                 + (self.message if self.success else
                    "stopped without converging (note below)")]
        if len(self.parameters) > 1:
            names = [p.path.rsplit(".", 1)[-1] for p in self.parameters]
            corr = pd.DataFrame(self.correlation, index=names, columns=names)
            lines += ["", "correlation of the fitted coordinates:", corr.to_string(**fmt)]
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    def calibrated_toml(self, out_dir: Path | str | None = None) -> str:
        """The calibrated scene as TOML with a comment header naming the fit and the data.

        Relative paths in the scene (measured file, bearing or lubricant files) are
        rewritten relative to ``out_dir`` when given, so the file works from there;
        absolute paths stay as written (a path climbing out of ``out_dir`` to the root
        would break when the calibrated scene is moved).
        """
        data = self.scene.to_dict()
        shown_file = self.measured_file
        if out_dir is not None:
            _rebase_paths(data, self.scene, Path(out_dir))
            shown_file = data["measured"]["file"]
            if not Path(shown_file).is_absolute():
                shown_file += " (relative to this file's folder)"
        stamp = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
        head = [
            f"# Calibrated scene written by thermobearing.calibrate on {stamp}.",
            f"# Fitted to the measured temperatures in {shown_file}",
            "# (" + ", ".join(f"{s} -> {n}" for s, n in self.column_map.items())
            + f"; {self.points} points).",
            f"# scipy.optimize.least_squares, residual = predicted - measured [K], "
            f"{self.runs} model runs; {self.message}",
        ]
        for p in self.parameters:
            head.append(f"# {p.path}: {p.initial:.6g} -> {p.value:.6g} {p.unit} "
                        f"(95 % CI {p.ci_low:.4g} .. {p.ci_high:.4g}, linearised)")
        head.append(f"# RMSE {self.rmse:.4g} K after the fit, {self.initial_rmse:.4g} K before.")
        head.append("# The intervals are linearised estimates ((J^T J)^-1 s^2): they assume a "
                    "correct model and")
        head.append("# independent measurement errors, and are optimistic otherwise.")
        head += [f"# note: {n}" for n in self.notes]
        return "\n".join(head) + "\n\n" + dumps_toml(data)

    def write(self, out_dir: Path | str, scene_name: str = "calibrated_scene.toml"
              ) -> dict[str, Path]:
        """Write the calibrated scene, the parameter table, the per-sensor residuals and a
        JSON summary to ``out_dir``; returns the paths."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        paths = {"scene": out / scene_name, "parameters": out / "calibration.csv",
                 "sensors": out / "calibration_sensors.csv",
                 "summary": out / "calibration.json"}
        paths["scene"].write_text(self.calibrated_toml(out), encoding="utf-8")
        self.table().to_csv(paths["parameters"], index=False)
        self.sensors.to_csv(paths["sensors"], index=False)
        summary = {"rmse_K": self.rmse, "initial_rmse_K": self.initial_rmse,
                   "residual_sd_K": self.residual_sd, "points": self.points, "dof": self.dof,
                   "runs": self.runs, "success": self.success, "message": self.message,
                   "identifiable": self.identifiable, "notes": self.notes,
                   "correlation": np.asarray(self.correlation).tolist(),
                   "measured_file": self.measured_file,
                   "parameters": [vars(p) for p in self.parameters]}
        paths["summary"].write_text(json.dumps(summary, indent=1, default=float),
                                    encoding="utf-8")
        return paths


def _rebase_paths(data: dict[str, Any], scene: Scene, out_dir: Path) -> None:
    def rel(name: str) -> str:
        if Path(name).is_absolute():  # the user's absolute path: kept
            return name
        p = scene.resolve_path(name).resolve()
        try:
            return os.path.relpath(p, out_dir.resolve())
        except ValueError:  # other drive (Windows)
            return str(p)

    if "measured" in data:
        data["measured"]["file"] = rel(data["measured"]["file"])
    for b in data.get("bearings", []):
        if "path" in b:
            b["path"] = rel(b["path"])
    if "path" in data.get("lubricant", {}):
        data["lubricant"]["path"] = rel(data["lubricant"]["path"])
