"""Cost of one thermal-EHL table node against the plain fixed point, measured in the same run.

Ours: :func:`thermobearing.ehl.thermal.solve_thermal_line_contact` as the quasi-dynamic film
table calls it (``ehl.coupling.TehlFilmModel``: n = 512 minimum, Eyring 5 MPa, the default
tolerance). The anchor ("plain"): the same solver with the column scan of the film energy
equation sweeping downstream only (each column's tridiagonal system factored in every sweep) to
1e-4 K in every outer iteration, no limit on the first temperature update and
``tol_temperature`` 0.1 K -- the solve before the alternating scan. Reference: the fixed point
solved to 1e-3 K (alternating scan, inner sweeps to 1e-6 K), against which both report the
relative change of the central and minimum film, the maximum pressure, the shear (traction) and
rolling forces, and the change of the maximum temperature [K].

Nodes: D1842926 with OIL_4109 at 30 degC (paper 001, 13218 r/min, up to 24 kN): inner and outer
race contacts from 40 to 430 kN/m, 20-55 m/s, SRR 0 to 0.05 (n = 512 / 1024 / 2048 by the
solver's ``nodes_for``). ``--quick``: three of them (one per grid size).

Printed per node: CPU seconds and outer iterations of ours and of the plain solve, the ratio
plain / ours (> 1: ours is faster) and the largest relative change against the reference.
Timing: process CPU time with one BLAS thread (set before numpy is imported).

Usage: python benchmarks/bm_tehl_node.py [--quick] [--no-reference] [--json]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
import warnings

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
from numba import njit  # noqa: E402

T_IN = 303.15
#: name: (load per length [N/m], race, entrainment speed [m/s], SRR [-])
NODES = {
    "inner 430 kN/m 44 m/s roll": (4.3e5, "inner", 44.4, 0.0),
    "inner 430 kN/m 44 m/s SRR .05": (4.3e5, "inner", 44.4, 0.05),
    "inner 40 kN/m 44 m/s roll": (4.0e4, "inner", 44.4, 0.0),
    "outer 150 kN/m 55 m/s roll": (1.5e5, "outer", 55.0, 0.0),
    "outer 150 kN/m 55 m/s SRR .05": (1.5e5, "outer", 55.0, 0.05),
    "outer 300 kN/m 55 m/s roll": (3.0e5, "outer", 55.0, 0.0),
    "outer 300 kN/m 55 m/s SRR .05": (3.0e5, "outer", 55.0, 0.05),
    "outer 100 kN/m 20 m/s SRR .02": (1.0e5, "outer", 20.0, 0.02),
}
QUICK = ("inner 430 kN/m 44 m/s SRR .05", "outer 150 kN/m 55 m/s roll",
         "outer 300 kN/m 55 m/s roll")
FIELDS = ("central_film", "minimum_film", "max_pressure", "shear_force", "rolling_force")


@njit(cache=True)
def _plain_scan(T, u, adv, g, src, lin, dx, t_in, sweeps, tol):  # pragma: no cover - numba
    """The column scan before the change: downstream sweeps only, every column's tridiagonal
    system assembled and solved (Thomas) in every sweep; same arguments and equations as
    :func:`thermobearing.ehl.thermal._column_scan`."""
    n, nc = T.shape
    a = np.empty(nc)
    b = np.empty(nc)
    c = np.empty(nc)
    d = np.empty(nc)
    change = 0.0
    for _sweep in range(sweeps):
        change = 0.0
        for i in range(1, n):
            for k in range(nc):
                if k == 0 or k == nc - 1:
                    a[k] = 0.0
                    c[k] = 0.0
                    b[k] = 1.0
                    d[k] = t_in
                    continue
                coef = adv[i, k] * abs(u[i, k]) / dx
                if u[i, k] >= 0.0:
                    up = T[i - 1, k]
                elif i < n - 1:
                    up = T[i + 1, k]
                else:
                    up = T[i, k]
                    coef = 0.0
                a[k] = -g[i, k - 1]
                c[k] = -g[i, k]
                b[k] = g[i, k - 1] + g[i, k] + coef - lin[i, k]
                d[k] = src[i, k] + coef * up
            for k in range(1, nc):
                m = a[k] / b[k - 1]
                b[k] -= m * c[k - 1]
                d[k] -= m * d[k - 1]
            new = d[nc - 1] / b[nc - 1]
            change = max(change, abs(new - T[i, nc - 1]))
            T[i, nc - 1] = new
            for k in range(nc - 2, -1, -1):
                new = (d[k] - c[k] * T[i, k + 1]) / b[k]
                change = max(change, abs(new - T[i, k]))
                T[i, k] = new
        if change < tol:
            break
    return change


def _setup():
    from thermobearing.ehl import coupling
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant

    lub = load_lubricant("OIL_4109")
    bearing = load_bearing("D1842926")
    solids = coupling.roller_film_model(bearing, lub).solids
    radius = {race: bearing.curvature(race)[0] for race in ("inner", "outer")}
    return lub, bearing.effective_modulus, solids, radius


def _solve(node, lub, e_prime, solids, radius, variant):
    from thermobearing.ehl import thermal

    w, race, u, srr = node
    saved = thermal._column_scan, thermal.MAX_FIRST_TEMPERATURE_STEP
    kw = {}
    if variant == "plain":
        thermal._column_scan = (lambda T, u_, adv, g, src, lin, dx, t_in, sweeps, tol:
                                _plain_scan(T, u_, adv, g, src, lin, dx, t_in, 50, 1e-4))
        thermal.MAX_FIRST_TEMPERATURE_STEP = math.inf
        kw["tol_temperature"] = 0.1
    elif variant == "reference":
        real = saved[0]
        thermal._column_scan = (lambda T, u_, adv, g, src, lin, dx, t_in, sweeps, tol:
                                real(T, u_, adv, g, src, lin, dx, t_in, 3000, 1e-6))
        kw.update(tol_temperature=1e-3, max_outer=400)
    try:
        t0 = time.process_time()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            sol = thermal.solve_thermal_line_contact(
                w, radius[race], e_prime, u, srr, lub, T_IN, solid1=solids[0],
                solid2=solids[1], n=512, eyring_stress=5e6, **kw)
        return sol, time.process_time() - t0
    finally:
        thermal._column_scan, thermal.MAX_FIRST_TEMPERATURE_STEP = saved


def _change(sol, ref):
    rel = max(abs(getattr(sol, f) / getattr(ref, f) - 1.0) for f in FIELDS)
    return rel, abs(sol.max_temperature - ref.max_temperature)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--no-reference", action="store_true")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args(argv)
    lub, e_prime, solids, radius = _setup()
    names = QUICK if args.quick else tuple(NODES)
    # compile / load the numba caches outside the timings
    _solve(NODES[QUICK[0]], lub, e_prime, solids, radius, "ours")
    _solve(NODES[QUICK[0]], lub, e_prime, solids, radius, "plain")
    records, ratios = [], []
    for name in names:
        node = NODES[name]
        rec = {"node": name}
        sols = {}
        for variant in ("ours", "plain") + (() if args.no_reference else ("reference",)):
            try:
                sol, cpu = _solve(node, lub, e_prime, solids, radius, variant)
            except Exception as err:  # a failed solve is a result of the benchmark
                rec[f"{variant}_error"] = str(err)[:160]
                continue
            sols[variant] = sol
            rec[f"{variant}_cpu_s"] = cpu
            rec[f"{variant}_outer"] = sol.outer_iterations
            rec["n"] = int(sol.x.size)
        if "ours" in sols and "plain" in sols:
            rec["ratio"] = rec["plain_cpu_s"] / rec["ours_cpu_s"]
            ratios.append(rec["ratio"])
        for variant in ("ours", "plain"):
            if variant in sols and "reference" in sols:
                rel, dt = _change(sols[variant], sols["reference"])
                rec[f"{variant}_rel_change"], rec[f"{variant}_dTmax_K"] = rel, dt
        records.append(rec)
        if args.json:
            print(json.dumps(rec), flush=True)
            continue
        line = f"{name:32s} n={rec.get('n', '?'):>4}"
        for variant in ("ours", "plain"):
            if f"{variant}_cpu_s" in rec:
                line += (f"  {variant} {rec[f'{variant}_cpu_s']:5.2f} s "
                         f"({rec[f'{variant}_outer']:3d} outer)")
                if f"{variant}_rel_change" in rec:
                    line += (f" d={rec[f'{variant}_rel_change']:.1e}"
                             f"/{rec[f'{variant}_dTmax_K']:.3f} K")
            else:
                line += f"  {variant} FAILED ({rec.get(f'{variant}_error', '')[:60]})"
        if "ratio" in rec:
            line += f"  plain/ours {rec['ratio']:4.1f}"
        print(line, flush=True)
    if ratios and not args.json:
        print(f"plain/ours CPU ratio: median {float(np.median(ratios)):.2f}, "
              f"range {min(ratios):.2f}-{max(ratios):.2f} over {len(ratios)} nodes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
