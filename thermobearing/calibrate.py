"""Calibration: fit uncertain scene parameters to the scene's measured temperatures.

``calibrate(scene, ["network.parameters.h_oil", "network.parameters.h_air"])`` adjusts the
named scene fields (dotted paths, the same paths ``thermobearing sweep --set`` takes) so
that the predicted node temperatures match the thermocouple readings of the scene's
``[measured]`` table in the least-squares sense, with
:func:`scipy.optimize.least_squares` (trust-region reflective; Virtanen et al. 2020).

Residuals
    r_k = T_pred(node of sensor s, t_k) - T_meas(s, t_k)  [K], for every mapped sensor s
    and every measured time t_k inside the simulated protocol; the prediction is the
    scene's ``temperatures`` table interpolated linearly in time.
Parameters
    Positive quantities (heat-transfer coefficients, dimensions, flows) are fitted as
    z = ln(value / start), so they stay positive and a step means a relative change;
    temperatures are fitted linearly, z = T - T_start in kelvin (other quantities that can
    be negative: z = (value - start) / |start|). z = 0 at the start, so least_squares'
    first trust region (radius 1) allows a factor e or 1 K.
Jacobian
    Forward finite differences in z (default step 0.01 in ln, i.e. 1 %, and 0.1 K for
    temperatures): each Jacobian costs one model run per fitted parameter. The model is a
    transient simulation with adaptive steps; its output is smooth in the parameters at
    that step size (checked for h_oil/h_air on the QJ1044 scene: the 0.1 % and 1 %
    differences agree within 0.5 %); a much smaller step would only resolve solver noise.
Confidence intervals (approximate, linearised)
    cov(z) = s^2 (J^T J)^-1 with s^2 = SSR / (m - p) and J the Jacobian at the optimum;
    the 95 % interval is z +- t_{0.975, m-p} sqrt(cov_jj), mapped back through exp for
    log parameters (so it is asymmetric in the value). This is the classical linearised
    estimate of nonlinear regression (Bates and Watts 1988, ch. 2; Seber and Wild 1989,
    ch. 5): it assumes the model structure is right and the measurement errors are
    independent with equal variance. Thermocouple errors are usually correlated in time,
    so the intervals are optimistic for real rig data; treat them as a lower bound on the
    uncertainty.

Cost: **calibration runs the whole scene once per function evaluation** (plus one run
per fitted parameter for each Jacobian): a few tens of runs for two parameters. The
scene's physics is used as written (models, network, solver settings are not changed);
only its outputs are reduced to the temperature table. Choose cheap settings in the scene
yourself if you want a quick fit (e.g. ``[models] kinematics = "race_control"`` and a
longer ``[solver] chunk``), and say so when you report the result.
"""

from __future__ import annotations

import datetime as _dt
import inspect
import json
import math
import os
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .errors import ConvergenceError, InputError
from .scene import Scene, dumps_toml
from .scene_checks import check_measured_file
from .sweep import DISPLAY_UNITS, assign_path, check_path, get_path
from .units import from_si, to_si, unit_registry

REFERENCES = ("virtanen2020_scipy", "bates_watts1988", "seber_wild1989")

#: kinds of the scene's own numeric fields that can be fitted (path -> unit kind)
_SCENE_KINDS = {
    "supply.flow": "volume_flow",
    "supply.inlet_temperature": "temperature",
    "supply.level": "length",
    "environment.ambient_temperature": "temperature",
    "environment.initial_temperature": "temperature",
    "schedule.speed": "angular_speed",
    "schedule.radial_load": "force",
    "schedule.axial_load": "force",
}
#: template parameters that the scene sets elsewhere (coupled.build_network refuses them)
_SET_ELSEWHERE = {"ambient_temperature": "environment.ambient_temperature",
                  "oil_inlet_temperature": "supply.inlet_temperature",
                  "oil_flow": "supply.flow"}
_DIMENSIONLESS = ("", "-", "dimensionless")


# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class FitParameter:
    """One fitted scene field.

    Attributes
    ----------
    path : dotted scene path (``network.parameters.h_oil``).
    unit : SI unit of the value (pint spelling; ``""`` when dimensionless or unknown).
    display_unit : unit used in tables and in the calibrated scene (``"W/(m**2*K)"``).
    transform : ``"log"`` (z = ln(value / initial)) or ``"linear"``
        (z = (value - initial) / scale).
    initial : starting value [SI]; z = 0 there.
    lower, upper : bounds [SI] (``-inf``/``inf`` when free; ``0`` for log parameters).
    fd_step : finite-difference step in z.
    scale : unit of z for linear parameters (1 K for temperatures, else |initial| or 1).
    """

    path: str
    unit: str
    display_unit: str
    transform: str
    initial: float
    lower: float
    upper: float
    fd_step: float
    scale: float = 1.0

    def to_z(self, value: float) -> float:
        """Fitted coordinate: ln(value / initial) (log) or (value - initial) / scale."""
        if self.transform == "log":
            return math.log(value / self.initial)
        return (float(value) - self.initial) / self.scale

    def from_z(self, z: float) -> float:
        if self.transform == "log":
            try:
                return self.initial * math.exp(z)
            except OverflowError:
                return math.inf
        return self.initial + self.scale * float(z)

    def z_bounds(self) -> tuple[float, float]:
        if self.transform == "log":
            lo = self.to_z(self.lower) if self.lower > 0 else -np.inf
            hi = self.to_z(self.upper) if math.isfinite(self.upper) else np.inf
            return lo, hi
        lo = self.to_z(self.lower) if math.isfinite(self.lower) else -np.inf
        hi = self.to_z(self.upper) if math.isfinite(self.upper) else np.inf
        return lo, hi

    def show(self, value: float) -> float:
        """SI value in the display unit."""
        if self.display_unit in _DIMENSIONLESS or not self.unit:
            return float(value)
        return from_si(value, self.display_unit)

    def scene_value(self, value: float) -> Any:
        """What to write into the scene dict: a unit string when the field has a unit."""
        if self.display_unit in _DIMENSIONLESS or not self.unit:
            return float(value)
        return f"{self.show(value):.10g} {self.display_unit}"


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
                 f"freedom, {self.runs} model runs; {self.message}"]
        if len(self.parameters) > 1:
            names = [p.path.rsplit(".", 1)[-1] for p in self.parameters]
            corr = pd.DataFrame(self.correlation, index=names, columns=names)
            lines += ["", "correlation of the fitted coordinates:", corr.to_string(**fmt)]
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    def calibrated_toml(self, out_dir: Path | str | None = None) -> str:
        """The calibrated scene as TOML with a comment header naming the fit and the data.

        Relative paths in the scene (measured file, bearing or lubricant files) are
        rewritten relative to ``out_dir`` when given, so the file works from there.
        """
        data = self.scene.to_dict()
        shown_file = self.measured_file
        if out_dir is not None:
            _rebase_paths(data, self.scene, Path(out_dir))
            shown_file = data["measured"]["file"] + " (relative to this file's folder)"
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


# ---------------------------------------------------------------------------
def _rebase_paths(data: dict[str, Any], scene: Scene, out_dir: Path) -> None:
    def rel(name: str) -> str:
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


def _template_entry(scene: Scene) -> tuple[str, Any]:
    from .network.templates import TEMPLATES

    name = scene.network.get("template", "four_node_paper002")
    return name, TEMPLATES.entry(name)


def _parse_existing(raw: Any, field_name: str) -> tuple[float, str, str]:
    """(SI value, SI unit, unit as written) of a scene value: a unit string or a number."""
    if isinstance(raw, bool) or not isinstance(raw, int | float | str):
        raise InputError(field_name, raw, "a numeric quantity to fit")
    if isinstance(raw, int | float):
        return float(raw), "", ""
    parts = raw.strip().split(maxsplit=1)
    unit_text = parts[1] if len(parts) == 2 else ""
    ureg = unit_registry()
    try:
        q = ureg.Quantity(float(parts[0]), unit_text or "dimensionless")
        base = q.to_base_units()
    except Exception:  # noqa: BLE001 - pint raises many kinds; report the field
        raise InputError(field_name, raw, "a numeric quantity '<number> <unit>' to fit") from None
    unit = "" if base.dimensionless else f"{base.units:~}"
    return float(base.magnitude), unit, unit_text


def _make_parameter(scene: Scene, scene_dict: Mapping[str, Any], path: str,
                    x0: Mapping[str, Any], bounds: Mapping[str, Sequence[Any]],
                    fd_step: Mapping[str, float]) -> FitParameter:
    parts = path.split(".")
    if parts[0] == "network":
        tname, entry = _template_entry(scene)
        if len(parts) != 3 or parts[1] != "parameters":
            raise InputError("fit", path, "network.parameters.<name>, a parameter of template "
                             f"{tname!r}: " + ", ".join(sorted(entry.parameters)))
        name = parts[2]
        if name in _SET_ELSEWHERE:
            raise InputError("fit", path, f"{_SET_ELSEWHERE[name]} (set there, not in the "
                             "network)")
        unit = entry.parameters.get(name)
        if unit is None:
            raise InputError("fit", path, f"a parameter of template {tname!r}: "
                             + ", ".join(sorted(k for k in entry.parameters
                                                if k not in _SET_ELSEWHERE)))
        unit = "" if unit in _DIMENSIONLESS else unit
        raw = scene.network.get("parameters", {}).get(name)
        display = unit
        if raw is None:
            default = inspect.signature(entry.obj).parameters[name].default
            raw = None if default is inspect.Parameter.empty else default
        if isinstance(raw, str):
            _, _, written = _parse_existing(raw, path)
            display = written or unit
            value = to_si(raw, unit or "dimensionless", field=path)
        elif raw is not None:
            value = float(raw)
        else:
            value = None
    else:
        check_path(scene_dict, path, "fit")
        try:
            raw = get_path(scene_dict, path)
        except (KeyError, IndexError, ValueError, TypeError):
            raw = None
        if raw is None and len(parts) >= 4 and parts[0] == "bearings" \
                and parts[2] == "overrides":
            # a bearing value the scene does not override: start from the preset's value
            from .sweep import bearing_file_value

            raw = bearing_file_value(scene_dict, parts[1], parts[3:])
        kind = _SCENE_KINDS.get(path)
        if kind is not None:
            from .units import si_unit

            unit = si_unit(kind)
            display = DISPLAY_UNITS.get(parts[-1], unit)
            value = None if raw is None else to_si(raw, unit, field=path)
        elif raw is None:
            value, unit, display = None, "", ""
        else:
            value, unit, written = _parse_existing(raw, path)
            display = written or unit
    def given(v: Any, field_name: str) -> float:
        """A user's x0 / bound: a bare-number STRING ("40", from the command line) is in the
        parameter's display unit (the scene's unit, as ``sweep --set`` reads bare numbers);
        a Python number is SI; a unit string is converted."""
        if (isinstance(v, str) and unit and display not in _DIMENSIONLESS
                and re.fullmatch(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*", v)):
            v = f"{v.strip()} {display}"
        return to_si(v, unit or "dimensionless", field=field_name)

    if path in x0:
        value = given(x0[path], f"x0[{path}]")
    if value is None:
        raise InputError(f"x0[{path}]", None, "a starting value (--x0 PATH=VALUE): the scene "
                         "does not set this field and its default is not a number (a "
                         "correlation, or a value the models choose)")
    is_temp = unit == "K"
    lo, hi = (0.0, math.inf) if (not is_temp and value > 0) else (-math.inf, math.inf)
    if path in bounds:
        b = bounds[path]
        if len(b) != 2:
            raise InputError(f"bounds[{path}]", b, "a pair (low, high)")
        lo, hi = (given(v, f"bounds[{path}]") for v in b)
        if not lo < hi:
            raise InputError(f"bounds[{path}]", b, "low < high")
        if not lo <= value <= hi:
            shown = display if display not in _DIMENSIONLESS else ""

            def fmt(v: float) -> str:
                if not shown or not unit:
                    return f"{v:g}"
                return f"{from_si(v, shown):g} {shown}"

            where = "given by --x0" if path in x0 else "the scene's value; --x0 PATH=VALUE " \
                "sets another"
            raise InputError(f"x0[{path}]", fmt(value), f"a start inside the bounds "
                             f"{fmt(lo)} .. {fmt(hi)} (the start is {where})")
    transform = "linear" if (is_temp or value <= 0 or lo < 0) else "log"
    scale = 1.0 if (is_temp or value == 0) else abs(value)
    step = fd_step.get(path, 0.1 if is_temp else 0.01)
    if not step > 0:
        raise InputError(f"fd_step[{path}]", step, "a step > 0")
    return FitParameter(path, unit, display, transform, float(value), float(lo), float(hi),
                        float(step), float(scale))


def _apply(scene_dict: Mapping[str, Any], params: Sequence[FitParameter],
           values: Sequence[float], base_dir: Path | None) -> Scene:
    d = json.loads(json.dumps(scene_dict))
    for p, v in zip(params, values, strict=True):
        assign_path(d, p.path, p.scene_value(v))
    return Scene.from_dict(d, base_dir)


def measured_table(scene: Scene, nodes: Sequence[str]) -> pd.DataFrame:
    """The scene's measured temperatures (``time [s]`` + one degC column per sensor),
    checked: every mapped node exists, every value is finite."""
    from .report import read_measured

    if scene.measured is None:
        raise InputError("measured", None, "a [measured] table (file, time_column, unit, "
                         "columns = { csv column = node }) in the scene")
    for col, node in scene.measured.columns.items():
        if node not in nodes:
            raise InputError(f"measured.columns[{col!r}]", node,
                             "a node of the scene's network: " + ", ".join(nodes))
    check_measured_file(scene)  # text cells, times going backwards: named InputErrors
    df = read_measured(scene)
    for col in ["time [s]", *scene.measured.columns]:
        vals = df[col].to_numpy(dtype=float)
        bad = np.flatnonzero(~np.isfinite(vals))
        if bad.size:
            name = scene.measured.time_column if col == "time [s]" else col
            raise InputError(f"measured column {name!r}", f"row {int(bad[0]) + 1}: "
                             f"{vals[bad[0]]}", "finite numbers (no gaps, NaN or inf)")
    return df


def _network_nodes(scene: Scene) -> list[str]:
    from .coupled import build_network
    from .simulation import Simulation

    return list(build_network(Simulation(scene, progress=False)).state_nodes)


def predicted_temperatures(scene: Scene) -> pd.DataFrame:
    """Run the scene (outputs reduced to temperatures) and return its temperature table."""
    from .simulation import Simulation

    run_scene = scene.with_changes(outputs=type(scene.outputs)(
        mode=scene.outputs.mode, want=("temperatures",)))
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

    def values(self, z: np.ndarray) -> list[float]:
        return [p.from_z(float(zi)) for p, zi in zip(self.params, z, strict=True)]

    def scene(self, z: np.ndarray) -> Scene:
        return _apply(self.base, self.params, self.values(z), self.base_dir)

    def _where(self, z: np.ndarray) -> str:
        return ", ".join(f"{p.path} = {p.show(v):.6g}"
                         for p, v in zip(self.params, self.values(z), strict=True))

    def split(self, r: np.ndarray) -> dict[str, np.ndarray]:
        n = len(self.times)
        return {s: r[i * n:(i + 1) * n] for i, s in enumerate(self.column_map)}

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
        parts = []
        for sensor, node in self.column_map.items():
            pred = np.interp(self.times, t_model, temps[f"{node} [degC]"].to_numpy(float))
            parts.append(pred - self.measured[sensor].to_numpy(float)[self.inside])
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


def _sensor_table(model: _Model, r: np.ndarray, r_initial: np.ndarray) -> pd.DataFrame:
    rows = []
    after, before = model.split(r), model.split(r_initial)
    for sensor, node in model.column_map.items():
        e = after[sensor]
        rows.append({"sensor": sensor, "node": node, "points": int(e.size),
                     "RMSE [K]": float(np.sqrt(np.mean(e**2))),
                     "max error [K]": float(np.max(np.abs(e))),
                     "mean error [K]": float(np.mean(e)),
                     "initial RMSE [K]": float(np.sqrt(np.mean(before[sensor]**2)))})
    return pd.DataFrame(rows)


def no_influence(J: np.ndarray, rel: float = 1e-9, abs_tol: float = 1e-12) -> np.ndarray:
    """Columns of the Jacobian ``J`` [K per unit of z] that are zero: parameters whose
    finite-difference step changed no predicted temperature at the sensors by more than
    ``rel`` times the largest column's change (or ``abs_tol`` K per unit z)."""
    J = np.asarray(J, float)
    norms = np.sqrt(np.sum(J**2, axis=0))
    top = float(norms.max()) if norms.size else 0.0
    return ~(norms > max(rel * top, abs_tol))


def correlation_notes(paths: Sequence[str], corr: np.ndarray,
                      threshold: float = 0.95) -> list[str]:
    """A note for every pair of fitted parameters whose estimates are correlated beyond
    ``threshold`` (|r|, linearised): the data then determine mainly a combination of the
    two, and each one's interval is wide because of the other (Bates and Watts 1988,
    sec. 2.3)."""
    out = []
    corr = np.asarray(corr, float)
    for i in range(len(paths)):
        for j in range(i + 1, len(paths)):
            r = corr[i, j]
            if np.isfinite(r) and abs(r) > threshold:
                out.append(f"{paths[i]} and {paths[j]} are strongly correlated (r = {r:.4g}): "
                           "the data determine mainly a combination of the two, so each "
                           "interval is wide; fix one of them, or add a sensor or protocol "
                           "step that tells them apart")
    return out


# ---------------------------------------------------------------------------
def calibrate(scene: Scene, fit: Sequence[str], *, bounds: Mapping[str, Sequence[Any]]
              | None = None, x0: Mapping[str, Any] | None = None,
              fd_step: Mapping[str, float] | None = None, max_runs: int = 60,
              xtol: float = 1e-4, ftol: float = 1e-6, confidence: float = 0.95,
              callback: Callable[[int, dict[str, float], float], None] | None = None,
              ) -> CalibrationResult:
    """Fit scene parameters to the scene's measured temperatures (least squares).

    Parameters
    ----------
    scene : a scene with a ``[measured]`` table (CSV of thermocouple temperatures, a
        time column, the unit, and a map CSV column -> network node) and a transient run.
    fit : dotted paths of the fitted fields, e.g. ``network.parameters.h_oil``,
        ``network.parameters.h_air``, ``supply.inlet_temperature``,
        ``environment.ambient_temperature``.
    bounds : path -> (low, high): unit strings (``("50 W/(m**2*K)", "5000 W/(m**2*K)")``),
        Python numbers in SI, or bare-number strings (``("30", "40")``, as the command line
        gives them) in the parameter's display unit (the scene's unit: degC for
        temperatures, L/min for flows). Default: (0, inf) for positive quantities, free
        otherwise.
    x0 : path -> starting value (read as ``bounds``). Default: the scene's value, or the
        network template's default when the scene does not set the parameter.
    fd_step : path -> finite-difference step in the fitted coordinate (default 0.01 in ln
        for positive quantities, 0.1 K for temperatures).
    max_runs : limit on least_squares function evaluations (each is one scene run; the
        Jacobians add one run per parameter each).
    xtol, ftol : least_squares tolerances (relative change of z and of the cost).
    confidence : level of the reported intervals (default 0.95).
    callback : called after every model run with (run number, {path: value in display
        unit}, RMSE [K]).

    Returns
    -------
    CalibrationResult
        Fitted values with approximate (linearised) confidence intervals, per-sensor
        residuals, the number of model runs and the calibrated scene.

    Raises
    ------
    InputError
        No ``[measured]`` table; a fit path that does not exist or is not numeric; a
        sensor mapped to a node the network does not have (lists the nodes); non-finite
        data; fewer measured points than fitted parameters + 1; a steady-state scene.

    Notes
    -----
    Each function evaluation runs the whole scene (see the module docstring for the cost
    and for what the intervals mean). References: Virtanen et al. 2020 (SciPy
    least_squares), Bates and Watts 1988 and Seber and Wild 1989 (linearised inference).
    """
    from scipy import optimize, stats

    if scene.measured is None:
        raise InputError("measured", None, "a [measured] table (file, time_column, unit, "
                         "columns = { csv column = node }) in the scene to calibrate against")
    if scene.outputs.mode != "transient":
        raise InputError("outputs.mode", scene.outputs.mode,
                         "'transient' (calibration compares temperature histories)")
    fit = [f.strip() for f in fit if f and f.strip()]
    if not fit:
        raise InputError("fit", fit, "at least one dotted scene path")
    if len(set(fit)) != len(fit):
        raise InputError("fit", fit, "each path once")
    x0, bounds, fd_step = dict(x0 or {}), dict(bounds or {}), dict(fd_step or {})
    for name, given in (("x0", x0), ("bounds", bounds), ("fd_step", fd_step)):
        extra = [k for k in given if k not in fit]
        if extra:
            raise InputError(name, extra[0], "one of the fitted paths: " + ", ".join(fit))
    if not 0.0 < confidence < 1.0:
        raise InputError("confidence", confidence, "a level in (0, 1)")
    scene_dict = scene.to_dict()
    params = [_make_parameter(scene, scene_dict, p, x0, bounds, fd_step) for p in fit]
    nodes = _network_nodes(_apply(scene_dict, params, [p.initial for p in params],
                                  Path(scene.base_dir) if scene.base_dir else None))
    measured = measured_table(scene, nodes)
    column_map = dict(scene.measured.columns)
    model = _Model(scene, params, measured, column_map, callback)
    m = len(model.times) * len(column_map)
    if m < len(params) + 1:
        raise InputError("measured", f"{m} points inside the protocol",
                         f"at least {len(params) + 1} points to fit {len(params)} parameters")
    notes = []
    if model.dropped:
        notes.append(f"{model.dropped} measured times outside the simulated protocol "
                     f"(0 .. {scene.schedule.duration:g} s) were not used")
    z0 = np.array([p.to_z(p.initial) for p in params])
    lo = np.array([p.z_bounds()[0] for p in params])
    hi = np.array([p.z_bounds()[1] for p in params])
    r_initial = model.residuals(z0)
    # a parameter that does not change the predicted temperatures at the sensors (e.g. the
    # oil level of a jet-lubricated scene) is left at its start and out of the fit: fitting
    # it would make J^T J singular, leave every interval undetermined and cost runs
    J0 = model.jacobian(z0)
    dead = no_influence(J0)
    for j in np.flatnonzero(dead):
        notes.append(f"{params[j].path} has no influence on the predicted temperatures at "
                     f"the sensors (its Jacobian column is zero at a {params[j].fd_step:g} "
                     "step in the fit coordinate): the data cannot determine it, it was left "
                     "at its start and out of the fit; leave it out of --fit")
    live = np.flatnonzero(~dead)
    if live.size == 0:
        raise InputError("fit", fit, "at least one parameter that changes the predicted "
                         "temperatures at the measured sensors (none of these does: "
                         "check the path, the node map of [measured] and the models)")

    def full(z_live: np.ndarray) -> np.ndarray:
        z_all = z0.copy()
        z_all[live] = z_live
        return z_all

    sol = optimize.least_squares(lambda zl: model.residuals(full(zl)), z0[live],
                                 jac=lambda zl: model.jacobian(full(zl), live),
                                 bounds=(lo[live], hi[live]), method="trf", x_scale=1.0,
                                 xtol=xtol, ftol=ftol, gtol=1e-10, max_nfev=max_runs)
    z = full(np.asarray(sol.x, float))
    r = model.residuals(z)
    J = model.jacobian(z, live)
    dof = m - live.size
    ssr = float(r @ r)
    s2 = ssr / dof
    cov = np.full((len(params), len(params)), np.inf)
    corr = np.full_like(cov, np.nan)
    sv = np.linalg.svd(J, compute_uv=False)
    separable = bool(sv[-1] > 1e-8 * sv[0] and sv[-1] > 0)
    identifiable = separable and not dead.any()
    if separable:
        cov_live = s2 * np.linalg.inv(J.T @ J)
        sd_live = np.sqrt(np.clip(np.diag(cov_live), 0.0, None))
        cov[np.ix_(live, live)] = cov_live
        if np.all(sd_live > 0):
            corr[np.ix_(live, live)] = cov_live / np.outer(sd_live, sd_live)
    else:
        cov[np.ix_(live, live)] = np.inf
        notes.append("the data do not separate the fitted parameters (J^T J is singular): "
                     "fit fewer parameters or add sensors/protocol steps")
    sd = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    notes += correlation_notes([p.path for p in params], corr)
    tq = float(stats.t.ppf(0.5 + confidence / 2.0, dof))
    fitted = []
    for j, p in enumerate(params):
        at_bound = bool(np.isfinite(lo[j]) and abs(z[j] - lo[j]) < 1e-9
                        or np.isfinite(hi[j]) and abs(z[j] - hi[j]) < 1e-9)
        if at_bound:
            notes.append(f"{p.path} ended on its bound: the interval is not meaningful")
        if p.transform == "log" and abs(z[j]) > math.log(100.0):
            notes.append(f"{p.path} moved by more than a factor 100 from its start: the data "
                         "may not determine it, or the model misses something the data show "
                         "(check the model, the sensors and the node map; set bounds)")
        half = tq * sd[j]
        z_lo, z_hi = z[j] - half, z[j] + half
        v_lo = p.from_z(z_lo) if math.isfinite(z_lo) else (0.0 if p.transform == "log"
                                                            else -math.inf)
        v_hi = p.from_z(z_hi) if math.isfinite(z_hi) else math.inf
        fitted.append(FittedParameter(
            path=p.path, unit=p.display_unit, transform=p.transform,
            initial=p.show(p.initial), value=p.show(p.from_z(z[j])),
            ci_low=p.show(v_lo) if math.isfinite(v_lo) else v_lo,
            ci_high=p.show(v_hi) if math.isfinite(v_hi) else v_hi,
            std_error_z=float(sd[j]), at_bound=at_bound, no_influence=bool(dead[j])))
    if not sol.success:
        notes.append(f"least_squares stopped without converging: {sol.message}")
    return CalibrationResult(
        parameters=tuple(fitted), sensors=_sensor_table(model, r, r_initial),
        rmse=float(np.sqrt(np.mean(r**2))),
        initial_rmse=float(np.sqrt(np.mean(r_initial**2))),
        residual_sd=math.sqrt(s2), points=m, dof=dof, runs=model.runs,
        success=bool(sol.success), message=str(sol.message), covariance=cov,
        correlation=corr, identifiable=identifiable,
        scene=_stamped(_apply(model.base, [params[j] for j in live],
                              [params[j].from_z(z[j]) for j in live], model.base_dir),
                       [f for f, d in zip(fitted, dead, strict=True) if not d], scene),
        measured_file=str(scene.resolve_path(scene.measured.file).resolve()),
        column_map=column_map,
        notes=notes)


def _stamped(calibrated: Scene, fitted: Sequence[FittedParameter], original: Scene) -> Scene:
    """The calibrated scene with a line in ``source`` saying what was fitted to what (the
    TOML header comments do not survive a load/save round trip; ``source`` does)."""
    data = original.measured.file if original.measured is not None else "measured data"
    what = ", ".join(f"{p.path} = {p.value:.6g} {p.unit}".rstrip() for p in fitted)
    line = (f"Calibrated with thermobearing.calibrate against {data}: "
            f"{what}.")
    text = f"{original.source}\n{line}" if original.source else line
    return calibrated.with_changes(source=text)


# ---------------------------------------------------------------------------
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
