"""``thermobearing calibrate SCENE --fit PATH[,PATH...] [--out DIR]``: fit scene parameters to
the scene's measured temperatures.

Example (synthetic data shipped with the repository, see ``examples/README.md``)::

    thermobearing calibrate qj1044_synthetic_measured \\
        --fit network.parameters.h_oil,network.parameters.h_air --out calibrated

Prints the fitted values with approximate (linearised) 95 % confidence intervals, the
residual RMSE per sensor and the number of model runs, and writes ``DIR/<scene>_calibrated.toml``
(the calibrated scene), ``DIR/calibration.csv``, ``DIR/calibration_sensors.csv`` and
``DIR/calibration.json``. Every function evaluation runs the whole scene once; each one's
parameter values and RMSE are appended to ``DIR/calibration_runs.csv`` as it finishes, so
Ctrl-C keeps them (and says where, with the best run so far).
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

from ..errors import InputError
from ._preflight import compile_note, load_scene_argument

NAME = "calibrate"
HELP = "fit scene parameters (e.g. network.parameters.h_oil) to the measured temperatures"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("scene", help="scene TOML path or preset name (needs a [measured] table)")
    parser.add_argument("--fit", required=True, action="append",
                        help="comma-separated dotted scene paths, e.g. "
                             "network.parameters.h_oil,network.parameters.h_air "
                             "(repeatable)")
    parser.add_argument("--out", default=None,
                        help="folder for the calibrated scene and tables "
                             "(default: calibration/<scene name>)")
    parser.add_argument("--x0", action="append", default=[], metavar="PATH=VALUE",
                        help="starting value, e.g. network.parameters.h_air='10 W/(m**2*K)' "
                             "(a bare number is in the parameter's unit, as shown in the "
                             "results table: degC for temperatures, L/min for flows)")
    parser.add_argument("--bounds", action="append", default=[], metavar="PATH=LOW:HIGH",
                        help="bounds, e.g. network.parameters.h_oil=50:5000 or "
                             "supply.inlet_temperature=30:45 (bare numbers in the "
                             "parameter's unit, degC here) or with units")
    parser.add_argument("--max-runs", type=int, default=60,
                        help="limit on least-squares function evaluations (default 60); "
                             "each Jacobian adds one model run per fitted parameter, so "
                             "the runs counted on the terminal can exceed it")
    parser.add_argument("--quiet", action="store_true", help="no per-run progress lines")


def _pairs(items: list[str], option: str) -> dict[str, str]:
    out = {}
    for item in items:
        path, sep, value = item.partition("=")
        if not sep or not path.strip() or not value.strip():
            raise InputError(option, item, "PATH=VALUE")
        out[path.strip()] = value.strip()
    return out


def run(args: argparse.Namespace) -> int:
    from ..calibrate import calibrate

    note = compile_note()  # before anything builds a model (that writes numba cache files)
    scene = load_scene_argument(args.scene)
    fit = [p.strip() for group in args.fit for p in group.split(",") if p.strip()]
    x0 = _pairs(args.x0, "--x0")
    bounds = {}
    for path, value in _pairs(args.bounds, "--bounds").items():
        low, sep, high = value.partition(":")
        if not sep:
            raise InputError("--bounds", value, "LOW:HIGH")
        bounds[path] = (low.strip(), high.strip())  # bare numbers: the parameter's unit
    name = Path(args.scene).stem
    out = Path(args.out) if args.out else Path("calibration") / name

    if args.max_runs < 1:
        raise InputError("--max-runs", args.max_runs, "a number of model runs >= 1")
    runs_csv = out / "calibration_runs.csv"
    runs_csv.unlink(missing_ok=True)
    best: dict[str, object] = {"rmse": math.inf}
    units: dict[str, str] = {}  # path -> display unit of the values the runs report

    def record_units(params: list) -> None:
        units.update({p.path: p.display_unit for p in params
                      if p.unit and p.display_unit not in ("", "-", "dimensionless")})

    def progress(run_no: int, values: dict[str, float], rmse: float) -> None:
        # the folder is made with the first finished run: a fit refused before any run
        # (bad path, bounds, data) leaves nothing behind
        out.mkdir(parents=True, exist_ok=True)
        new = not runs_csv.exists()
        with runs_csv.open("a", newline="", encoding="utf-8") as fh:
            writer = csv.writer(fh)
            if new:  # units in the column names, as in every table of a run
                writer.writerow(["run", *(f"{k} [{units[k]}]" if k in units else k
                                          for k in values), "rmse [K]"])
            writer.writerow([run_no, *values.values(), rmse])
        if rmse < float(best["rmse"]):
            best.update(rmse=rmse, run=run_no, values=dict(values))
        if args.quiet:
            return
        shown = ", ".join(f"{k.rsplit('.', 1)[-1]}={v:.5g}"
                          + (f" {units[k]}" if k in units else "") for k, v in values.items())
        print(f"  run {run_no:3d}: {shown}  RMSE {rmse:.4g} K", file=sys.stderr, flush=True)

    if scene.measured is None:  # before the header, which names the data file
        raise InputError("measured", None, "a [measured] table (file, time_column, unit, "
                         "columns = { csv column = node }) in the scene to calibrate "
                         "against; examples/README.md shows one")
    if not args.quiet:
        print(f"scene: {scene.title}")
        data = scene.resolve_path(scene.measured.file).resolve()
        print(f"fitting {', '.join(fit)} to {data} (one scene run per evaluation)",
              flush=True)
        if note:
            print(note, flush=True)
    try:
        result = calibrate(scene, fit, x0=x0, bounds=bounds, max_runs=args.max_runs,
                           callback=progress, on_parameters=record_units)
    except KeyboardInterrupt:
        if "run" in best:
            shown = ", ".join(f"{k}={v:.6g}" for k, v in best["values"].items())
            again = " ".join(f"--x0 {k}={v:.6g}" for k, v in best["values"].items())
            print(f"\ninterrupted: every finished model run is in {runs_csv}; best so far: "
                  f"run {best['run']}, {shown}, RMSE {best['rmse']:.4g} K (no calibrated "
                  f"scene was written; to go on from there, rerun with {again})",
                  file=sys.stderr)
        else:
            print("\ninterrupted before the first model run finished: nothing was written "
                  f"(the runs would have gone to {runs_csv})", file=sys.stderr)
        return 130
    print(result.summary_text())
    paths = result.write(out, scene_name=f"{name}_calibrated.toml")
    print(f"calibrated scene written to {paths['scene']} (tables in {out}/)")
    # the fit writes tables only: the figures and the report with the measured overlay
    # come from a run of the calibrated scene
    print(f"its temperatures against the measured ones (figures, report): thermobearing run "
          f"{paths['scene']} --out {Path(out) / 'run'}")
    return 0

