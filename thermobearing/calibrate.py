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

Modules: :mod:`thermobearing.calibrate_params` (fitted scene fields and their
transforms), :mod:`thermobearing.calibrate_model` (scene run reduced to temperatures,
residuals and Jacobian), :mod:`thermobearing.calibrate_result` (result type, tables,
calibrated scene), :mod:`thermobearing.calibrate_synthetic` (labelled synthetic data);
this module keeps the fit and its statistics (:func:`calibrate`, :func:`no_influence`,
:func:`correlation_notes`) and re-exports the names of all four.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

# split modules (names re-exported: callers import them from here)
from .calibrate_model import (  # noqa: F401
    _Model,
    _network_nodes,
    _sensor_table,
    measured_table,
    predicted_temperatures,
)
from .calibrate_params import (  # noqa: F401
    _DIMENSIONLESS,
    _SCENE_KINDS,
    _SET_ELSEWHERE,
    FitParameter,
    _apply,
    _make_parameter,
    _parse_existing,
    _template_entry,
)
from .calibrate_result import (  # noqa: F401
    REFERENCES,
    CalibrationResult,
    FittedParameter,
    _rebase_paths,
)
from .calibrate_synthetic import SYNTHETIC_LABEL, synthetic_measurements  # noqa: F401
from .errors import InputError
from .scene import Scene


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
              on_parameters: Callable[[Sequence[FitParameter]], None] | None = None,
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
    on_parameters : called once, before the first model run, with the fitted
        :class:`FitParameter` objects (their ``display_unit`` is the unit of the callback's
        values).

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
    if on_parameters is not None:
        on_parameters(params)
    model = _Model(scene, params, measured, column_map, callback)
    m = model.n_points
    if m < len(params) + 1:
        raise InputError("measured", f"{m} points inside the protocol",
                         f"at least {len(params) + 1} points to fit {len(params)} parameters")
    notes = list(model.notes)  # the run's notes, e.g. a sensor whose readings are all gaps
    if model.dropped:
        notes.append(f"{model.dropped} measured times outside the simulated protocol "
                     f"(0 .. {scene.schedule.duration:g} s) were not used")
    gaps = {s: n for s, n in model.gaps.items() if n}
    if gaps:
        notes.append("gaps in the measured file (empty cells or dropout flags) left out of "
                     "the fit: " + ", ".join(f"{s} {n}" for s, n in gaps.items()))
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
    TOML header comments do not survive a load/save round trip; ``source`` does) and the
    fitted values after its ``title`` (the heading of its run's report)."""
    data = original.measured.file if original.measured is not None else "measured data"
    what = ", ".join(f"{p.path} = {p.value:.6g} {p.unit}".rstrip() for p in fitted)
    line = (f"Calibrated with thermobearing.calibrate against {data}: "
            f"{what}.")
    text = f"{original.source}\n{line}" if original.source else line
    # the title too: the report of a rerun with the calibrated scene had the same heading
    # as the uncalibrated run's, so two reports side by side could not be told apart
    short = ", ".join(f"{p.path.rsplit('.', 1)[-1]} = {p.value:.4g} {p.unit}".rstrip()
                      for p in fitted)
    base = original.title.split(" (calibrated: ")[0]  # a calibrated scene fitted again
    title = f"{base} (calibrated: {short})" if short else original.title
    return calibrated.with_changes(source=text, title=title)
