"""Cold starts of the roller skidding solver against the bracketed solve and root(hybr).

Ours: :func:`thermobearing.skidding.roller.solve_model` as every caller runs it (Newton
attempts from cold guesses and pure rolling, a stalled iterate accepted when every equation
is within 4 times its own one-ulp change -- ``extras["method"] == "newton_round_off"`` --,
the bracketed solve only when all fail). The anchor, measured in the same run on the same
model from the same cold start: ``solve_model(method="bracketed")``, the robust path the
solver took before the round-off acceptance (Brent on the cage equation over its whole range
with every roller bisected over its whole range, then a Newton polish). Also
:func:`scipy.optimize.root` (method "hybr", finite-difference Jacobian) on the same scaled
Z + 1 residual from the same cold guess (0.8 of the epicyclic cage speed), inside the same
outer fixed point on the centrifugal loads as ours; it fails when it raises, reports no
success, ends above max(tol, 4 round-off floors of the anchor's state) ("not converged") or
ends at a state more than 1e-6 (relative) from the anchor's ("other state").

Bearings: the roller presets (NU214 with the paper 000 oil, D1842926 with OIL_4109) and a
catalogue NU 206 (``estimate_missing``, ISO VG 68) over a grid of inner-ring speeds
(500-30000 r/min), radial loads (100 N to about 0.3 C of each bearing) and oil temperatures
(20-140 degC). The load lists: NU214 100 kN is about 0.7 C (tests/unit/test_property_skidding.py),
so 45 kN is about 0.3 C; D1842926 (30 rollers of 12 mm on a 155 mm pitch) takes the same
list; the NU 206 (13 rollers of 7.5 mm) a list ending at 13 kN (about 0.3 of the catalogue C
of its size, 44 kN). ``--quick``: 10 points, among them the heavy ones that needed the
bracketed solve before the round-off acceptance (NU214 45 kN; NU 206 6-13 kN at 20-60 degC).

Per point: the process CPU time of ours, of the anchor and of hybr, the ratios anchor / ours
and hybr / ours (> 1: ours is faster), and the error of ours (and of hybr) against the
anchor's state: |CSR / CSR_anchor - 1| and max_j |w_j / w_j,anchor - 1| over the roller
speeds w_j (record fields ``csr_error``, ``roller_error``; ``error`` the larger). Ours stops
at the scaled residual tol 1e-9 when Newton meets it: the speeds of nearly standing
unloaded rollers, whose moment balances are tiny beside the force scale (the largest roller
load), are then off by up to ~1e-4 of their own speed, the CSR by up to ~1e-7 (light load,
high speed).
Printed: one line per point, then per bearing the median and range of the ratios, the
largest errors and the failures of each method.

Usage: python benchmarks/bm_roller_cold.py [--quick] [--bearing NAME ...] [--limit N]
       [--no-hybr] [--json] [--out FILE]
(``--json``: the records on stdout, one per point, as ``thermobearing bench`` reads them;
``--out FILE``: the records written to FILE as well.)
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
import warnings
from collections import defaultdict

import numpy as np

RPM = math.pi / 30.0
SPEEDS = (500.0, 2000.0, 8000.0, 30000.0)
TEMPERATURES = (20.0, 60.0, 140.0)
LOADS = {"NU214": (100.0, 1000.0, 5000.0, 20000.0, 45000.0),
         "D1842926": (100.0, 1000.0, 5000.0, 20000.0, 45000.0),
         "NU206": (100.0, 500.0, 2000.0, 6000.0, 13000.0)}
#: --quick: (bearing, r/min, N, degC). Heavy points that took the bracketed solve before the
#: round-off acceptance (NU214 45 kN; NU 206 6 kN / 20 degC and 13 kN at 20 and 60 degC,
#: two of which end at a residual norm of 0.1), and light and medium ones of each bearing.
QUICK = (("NU214", 8000.0, 45000.0, 20.0), ("NU214", 30000.0, 45000.0, 60.0),
         ("NU214", 2000.0, 1000.0, 60.0),
         ("D1842926", 2000.0, 5000.0, 60.0), ("D1842926", 8000.0, 100.0, 140.0),
         ("NU206", 500.0, 6000.0, 20.0), ("NU206", 2000.0, 13000.0, 20.0),
         ("NU206", 30000.0, 13000.0, 20.0), ("NU206", 2000.0, 13000.0, 60.0),
         ("NU206", 8000.0, 2000.0, 140.0))


#: a root(hybr) state that meets its residual test but differs from the anchor's by more than
#: this (relative, :func:`state_error`) counts as a failure ("other state"): measured, hybr
#: stops on the flat side of a saturated traction with norm 0.1-0.4 and rollers 1e3 off
WRONG_STATE = 1e-6


def _bearings():
    from thermobearing.bearing_config import bearing_from_dict
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant

    nu206 = bearing_from_dict({
        "name": "NU206", "kind": "cylindrical", "source": "catalogue", "estimate_missing": True,
        "bore": "30 mm", "outer_diameter": "62 mm", "width": "16 mm",
        "roller_diameter": "7.5 mm", "roller_length": "7.5 mm", "n_rollers": 13})
    return {"NU214": (load_bearing("NU214"), load_lubricant("PAPER000_OIL")),
            "D1842926": (load_bearing("D1842926"), load_lubricant("OIL_4109")),
            "NU206": (nu206, load_lubricant("ISO_VG68"))}


def state_errors(cage: float, rollers: np.ndarray, ref_cage: float,
                 ref_rollers: np.ndarray) -> tuple[float, float]:
    """Relative distance [-] of a state from the reference: (|CSR / CSR_ref - 1|,
    max_j |w_j / w_j,ref - 1|), each roller speed relative to the reference's own (an
    unloaded roller that nearly stands counts as much as a loaded one)."""
    ref = np.asarray(ref_rollers, dtype=float)
    d_r = np.abs(np.asarray(rollers, dtype=float) - ref) / np.maximum(np.abs(ref), 1e-300)
    return abs(cage / ref_cage - 1.0), float(np.max(d_r))


def state_error(cage: float, rollers: np.ndarray, ref_cage: float, ref_rollers: np.ndarray
                ) -> float:
    """The larger of the two :func:`state_errors` [-]."""
    return max(state_errors(cage, rollers, ref_cage, ref_rollers))


def hybr_solve(model, omega: float, load: float, tol: float = 1e-9):
    """root(hybr) on the scaled Z + 1 residual (``roller_solvers._newton``'s scaling) from
    the cold guess 0.8 of the epicyclic cage speed, at the loads of its cage speed, repeated
    (from its last root) while the cage speed moves by more than 1e-8 omega (at most 8
    rounds, as ours). Returns (x (Z+1,), scaled norm, hybr reported success)."""
    from scipy.optimize import root

    from thermobearing.skidding.roller import evaluate, initial_guess
    from thermobearing.skidding.roller_loads import _gapped, _load_distribution
    from thermobearing.skidding.roller_solvers import _force_scale

    z = model.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    acc = (0.0, 0.0)
    x = initial_guess(model, omega, 0.8)
    ring, q = None, None
    success, norm = False, math.inf
    for _outer in range(8):
        ld, fb = _load_distribution(model, omega, load, float(x[z]), x[:z], psi, acc, ring, q)
        ring, q = tuple(ld.ring_displacement), ld.inner_load
        mg = _gapped(model, ld)
        scale = _force_scale(model, omega, ld.inner_load)

        def f(y, mg=mg, ld=ld, fb=fb, scale=scale):
            e = evaluate(mg, omega, y[:z], y[z], ld.inner_load, fb, psi, acc)
            return np.append(e.roller_eq, e.cage_eq) / scale

        x_old = x
        sol = root(f, x, method="hybr")
        x, success = np.asarray(sol.x, dtype=float), bool(sol.success)
        norm = float(np.linalg.norm(f(x)))
        if not (success and np.all(np.isfinite(x))) or abs(x[z] - x_old[z]) <= 1e-8 * omega:
            break
    return x, norm, success


def solve_point(bearing, oil, name: str, rpm: float, load: float, t_c: float,
                hybr: bool = True) -> dict:
    """Ours, the bracketed anchor and (``hybr``) root(hybr), each from the cold start on one
    model; a dict with their CPU times [s], ratios, errors, paths and failures."""
    from thermobearing.errors import ConvergenceError, ValidityWarning
    from thermobearing.skidding.roller import build_model, solve_model

    omega = rpm * RPM
    row: dict = {"bearing": name, "rpm": rpm, "load": load, "t_c": t_c}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        model = build_model(bearing, oil, t_c + 273.15)
        results = {}
        for key, method in (("ours", "newton"), ("anchor", "bracketed")):
            t0 = time.process_time()
            try:
                results[key] = solve_model(model, omega, load, method=method)
                row[f"{key}_norm"] = results[key].residual_norm
            except ConvergenceError as err:
                results[key] = None
                row[f"{key}_norm"] = err.residual
            row[f"{key}_cpu"] = time.process_time() - t0
        ours, anchor = results["ours"], results["anchor"]
        row["path"] = ("failed" if ours is None
                       else f"{ours.extras['method']}:{ours.extras['start']}")
        row["anchor_ok"] = anchor is not None
        row["ratio"] = row["anchor_cpu"] / row["ours_cpu"]
        errs = (state_errors(ours.cage_speed, ours.roller_speed, anchor.cage_speed,
                             anchor.roller_speed)
                if ours is not None and anchor is not None else (None, None))
        row["csr_error"], row["roller_error"] = errs
        row["error"] = None if errs[0] is None else max(errs)
        row["csr"] = None if ours is None else ours.cage_speed_ratio
        if hybr:
            t0 = time.process_time()
            try:
                x, norm, success = hybr_solve(model, omega, load)
            except Exception:  # noqa: BLE001 - any failure of the alternative is counted
                x, norm, success = None, math.inf, False
            row["hybr_cpu"] = time.process_time() - t0
            floor = anchor.extras["round_off_floor"] if anchor is not None else 0.0
            z = model.n_rollers
            row["hybr_norm"] = norm
            row["hybr_ratio"] = row["hybr_cpu"] / row["ours_cpu"]
            row["hybr_error"] = (state_error(x[z], x[:z], anchor.cage_speed,
                                             anchor.roller_speed)
                                 if x is not None and anchor is not None
                                 and np.all(np.isfinite(x)) else None)
            if not (success and x is not None and np.all(np.isfinite(x))
                    and norm <= max(1e-9, 4.0 * floor)):
                row["hybr_outcome"] = "not converged"
            elif row["hybr_error"] is not None and row["hybr_error"] > WRONG_STATE:
                row["hybr_outcome"] = "other state"
            else:
                row["hybr_outcome"] = "ok"
            row["hybr_ok"] = row["hybr_outcome"] == "ok"
    return row


def _warm_up(bearing, oil) -> None:
    """One light solve, so that imports and first-call caches stay out of the times."""
    from thermobearing.errors import ValidityWarning
    from thermobearing.skidding.roller import build_model, solve_model

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        solve_model(build_model(bearing, oil, 313.15), 1000.0 * RPM, 1000.0)


def record(row: dict) -> dict:
    """The ``thermobearing bench`` record of one point."""
    return dict(benchmark="bm_roller_cold",
                case=f"{row['bearing']} {row['rpm']:g}rpm {row['load']:g}N {row['t_c']:g}C",
                method="solve_model", setting=row["path"], time_s=row["ours_cpu"],
                error=row["error"], csr_error=row["csr_error"],
                roller_error=row["roller_error"], ratio_vs_anchor=row["ratio"],
                anchor="bracketed",
                anchor_time_s=row["anchor_cpu"], anchor_converged=row["anchor_ok"],
                residual_norm=row["ours_norm"], anchor_residual_norm=row["anchor_norm"],
                hybr_time_s=row.get("hybr_cpu"), hybr_converged=row.get("hybr_ok"),
                hybr_error=row.get("hybr_error"), hybr_outcome=row.get("hybr_outcome"),
                ratio_vs_hybr=row.get("hybr_ratio"))


def points(quick: bool, names: list[str]) -> list[tuple[str, float, float, float]]:
    """The (bearing, r/min, N, degC) points of a run."""
    if quick:
        return [p for p in QUICK if p[0] in names]
    return [(n, rpm, load, t) for n in names for rpm in SPEEDS for load in LOADS[n]
            for t in TEMPERATURES]


def _fmt(v, spec: str) -> str:
    return "-" if v is None else format(v, spec)


def summary(rows: list[dict], out=sys.stdout) -> None:
    """Per bearing: median and range of the ratios, the largest errors, failures."""
    by = defaultdict(list)
    for r in rows:
        by[r["bearing"]].append(r)
    print(f"\n{len(rows)} cold points; ratio = method's CPU / ours' (> 1: ours faster); "
          "error = relative state difference from the bracketed anchor", file=out)
    for name, rs in by.items():
        ratios = [r["ratio"] for r in rs]
        e_c = [r["csr_error"] for r in rs if r["csr_error"] is not None]
        e_r = [r["roller_error"] for r in rs if r["roller_error"] is not None]
        line = (f"{name:9s} {len(rs):3d} points  bracketed/ours median "
                f"{statistics.median(ratios):6.1f}x ({min(ratios):.1f}-{max(ratios):.1f}x)  "
                f"max error CSR {_fmt(max(e_c, default=None), '.1e')}, rollers "
                f"{_fmt(max(e_r, default=None), '.1e')}"
                f"  failures: ours {sum(r['path'] == 'failed' for r in rs)}, "
                f"bracketed {sum(not r['anchor_ok'] for r in rs)}")
        if "hybr_ok" in rs[0]:
            # over the points hybr solves (a failure often ends early and looks cheap)
            h = [r["hybr_ratio"] for r in rs if r["hybr_ok"]]
            line += (f", hybr {sum(not r['hybr_ok'] for r in rs)} "
                     f"({sum(r['hybr_outcome'] == 'other state' for r in rs)} at another state)")
            if h:
                line += (f"  |  hybr/ours median {statistics.median(h):.1f}x "
                         f"({min(h):.1f}-{max(h):.1f}x) over its {len(h)} solved points")
        print(line, file=out)
    paths = defaultdict(list)
    for r in rows:
        paths[r["path"]].append(r["ours_cpu"])
    for path, ts in sorted(paths.items()):
        print(f"  ours by {path:28s} {len(ts):4d} points, CPU median {statistics.median(ts):.3f} s,"
              f" max {max(ts):.2f} s", file=out)
    total_o = sum(r["ours_cpu"] for r in rows)
    total_a = sum(r["anchor_cpu"] for r in rows)
    print(f"  CPU in all: ours {total_o:.1f} s, bracketed {total_a:.1f} s "
          f"({total_a / max(total_o, 1e-12):.1f}x)", file=out)


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help=f"the {len(QUICK)} points of QUICK")
    ap.add_argument("--bearing", action="append", choices=list(LOADS),
                    help="NU214, D1842926, NU206 (repeatable; default all)")
    ap.add_argument("--limit", type=int, default=None, help="only the first N points")
    ap.add_argument("--no-hybr", action="store_true", help="skip the root(hybr) alternative")
    ap.add_argument("--json", action="store_true",
                    help="print the records (one per point) as a JSON array on stdout")
    ap.add_argument("--out", help="also write the records to this file (JSON array)")
    args = ap.parse_args(argv)
    bearings = _bearings()
    names = args.bearing or list(LOADS)
    todo = points(args.quick, names)[:args.limit]
    # the table goes to stderr with --json, so that stdout holds the records only
    log = sys.stderr if args.json else sys.stdout
    warmed = set()
    rows = []
    for name, rpm, load, t_c in todo:
        bearing, oil = bearings[name]
        if name not in warmed:  # imports and caches out of the times
            _warm_up(bearing, oil)
            warmed.add(name)
        row = solve_point(bearing, oil, name, rpm, load, t_c, hybr=not args.no_hybr)
        rows.append(row)
        print(f"{name:9s} {rpm:6.0f} r/min {load:6.0f} N {t_c:4.0f} degC  {row['path']:30s} "
              f"ours {row['ours_cpu']:6.2f} s  bracketed {row['anchor_cpu']:6.2f} s "
              f"{row['ratio']:6.1f}x  error {_fmt(row['error'], '.1e')}  norm "
              f"{row['ours_norm']:.1e}"
              + (f"  hybr {row['hybr_cpu']:5.2f} s {row['hybr_outcome']}"
                 f" error {_fmt(row['hybr_error'], '.1e')}" if "hybr_ok" in row else ""),
              file=log, flush=True)
    summary(rows, out=log)
    records = [record(r) for r in rows]
    if args.out:
        with open(args.out, "w") as fh:
            json.dump(records, fh, indent=1)
    if args.json:
        print(json.dumps(records, indent=1))


if __name__ == "__main__":
    main()
