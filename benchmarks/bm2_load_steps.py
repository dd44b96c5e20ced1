"""BM-2: 120 abrupt load steps, ours against solve_ivp with and without restarts.

Problem: the 4-node (and, without --quick, 20-node) stiff bearing network of BM-1 with
120 load steps of 30 s (60 min) and the viscous heat source of BM-1
(thermobearing.network.problems). Solvers at the same tolerances (rtol = 1e-5, atol = 1e-3 K,
and rtol = 1e-6, atol = 1e-4 K):

- ours: TR-BDF2 and the exponential Rosenbrock exprb43 with ``breakpoints`` at the 120
  steps (exact restarts);
- scipy LSODA / BDF / Radau *with* restarts (one solve_ivp call per load step, analytic
  Jacobian) and *without* (one call over the hour with the discontinuous heat source: the
  error control has to find the jumps).

Error: max over all nodes of |T - T_ref| on a 5-s grid; reference: our TR-BDF2 at rtol 1e-11
with restarts, cross-checked against Radau at rtol 1e-12 with restarts (difference printed;
skipped with --quick). Note: without restarts LSODA may step over the whole protocol when
the first load step is zero (the state is then an equilibrium): that is the failure mode
restarts exist for, and it shows up as a large error here.
``ratio_vs_anchor`` = (LSODA-with-restarts time at the same setting) / (record time): a
ratio at equal tolerance, where the errors differ (ours' exprb43 is ~60x more accurate than
LSODA at rtol 1e-5). The work-precision figure: LSODA with restarts also runs at rtol 1e-4 ...
1e-9 (atol = 100 rtol K, ``LSODA_CURVE``, timed as the others) and each record gets
``ratio_at_equal_error`` = (LSODA's time interpolated log-log on that curve at the record's
error) / (record time), None where the curve does not bracket the error (no extrapolation).

Usage: python benchmarks/bm2_load_steps.py [--quick] [--json] [--out DIR]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bm1_work_precision import run_ours, run_scipy, time_at_error, timed  # noqa: E402

from thermobearing.network import assemble  # noqa: E402
from thermobearing.network.problems import (  # noqa: E402
    bearing_network,
    load_protocol,
    viscous_heat_for,
)

#: rtol of the LSODA-with-restarts work-precision curve (atol = 100 rtol [K])
LSODA_CURVE = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9)


def make_case(n: int):
    net = bearing_network(n)
    edges, powers = load_protocol(120, 30.0)
    rng = np.random.default_rng(2)
    powers = powers * rng.uniform(0.3, 1.3, size=powers.size)  # abrupt, irregular steps
    powers[::17] = 0.0
    heat = viscous_heat_for(net, edges, powers)
    T0 = np.full(len(net.state_nodes), 308.15)
    grid = np.linspace(0.0, edges[-1], int(edges[-1] / 5.0) + 1)
    return net, edges, heat, T0, grid


def run_scipy_no_restart(case, method: str, rtol: float, atol: float):
    net, edges, heat, T0, grid = case
    sys_ = assemble(net)
    C, s = sys_.C, sys_.s
    K = sys_.K if sys_.dense else sys_.K.toarray()
    invC = 1.0 / C

    def fun(t, T):
        return (s - K @ T + heat(t, T)) * invC

    def jac(t, T):
        J = -K.copy()
        J[np.diag_indices_from(J)] += heat.jacobian(t, T)
        return J * invC[:, None]

    r = solve_ivp(fun, (0.0, edges[-1]), T0, method=method, rtol=rtol, atol=atol, jac=jac,
                  t_eval=grid)
    if not r.success:
        raise RuntimeError(r.message)
    return r.y.T, r.nfev


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--out", default="benchmarks/out")
    ap.add_argument("--repeat", type=int, default=None)
    args = ap.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 3)
    sizes = [4] if args.quick else [4, 20]
    settings = [(1e-5, 1e-3)] if args.quick else [(1e-5, 1e-3), (1e-6, 1e-4)]
    records = []
    for n in sizes:
        case = make_case(n)
        ref, _ = run_ours(case, "tr_bdf2", 1e-11, 1e-9)
        run_ours(case, "exprb43", 1e-3, 1e-1)  # warm-up: load exprb43's compiled kernels
        # run_scipy returns the grid points of [a, b) per segment ([a, b] the last): compare
        grid = case[4]
        seg_grid = np.concatenate([grid[(grid >= a) & ((grid < b) | (b == case[1][-1]))]
                                   for a, b in zip(case[1][:-1], case[1][1:], strict=True)])
        ref_seg = _sample_ref(case, seg_grid)
        if not args.quick:
            t_rad, (rad, _) = timed(lambda c=case: run_scipy(c, "Radau", 1e-12, 1e-10), 1)
            print(f"== {n} nodes: |ours(1e-11) - Radau(1e-12)| = "
                  f"{np.max(np.abs(rad - ref_seg)):.2e} K (Radau ref in {t_rad:.1f} s)",
                  file=sys.stderr)
        for rtol, atol in settings:
            setting = f"rtol={rtol:g},atol={atol:g}"
            rows = []
            runs = [("tr_bdf2", "restarts", lambda c=case, a=rtol, b=atol:
                     run_ours(c, "tr_bdf2", a, b), ref),
                    ("exprb43", "restarts", lambda c=case, a=rtol, b=atol:
                     run_ours(c, "exprb43", a, b), ref)]
            for m in ("LSODA", "BDF", "Radau"):
                runs.append((m, "restarts", lambda c=case, m=m, a=rtol, b=atol:
                             run_scipy(c, m, a, b), ref_seg))
                runs.append((m, "no restarts", lambda c=case, m=m, a=rtol, b=atol:
                             run_scipy_no_restart(c, m, a, b), ref))
            for method, mode, fn, r in runs:
                try:
                    t, (Y, nfev) = timed(fn, repeat)
                    err = float(np.max(np.abs(Y - r)))
                except Exception as exc:  # a failure is a result
                    print(f"{method} {mode} failed: {exc}", file=sys.stderr)
                    continue
                rows.append({"benchmark": "BM-2", "case": f"{n}_nodes", "method": method,
                             "setting": f"{setting},{mode}", "time_s": t,
                             "max_error_K": err, "f_evals": int(nfev)})
            anchor = [r for r in rows if r["method"] == "LSODA"
                      and r["setting"].endswith(",restarts")]
            for r in rows:
                r["ratio_vs_anchor"] = anchor[0]["time_s"] / r["time_s"] if anchor else None
            records += rows
        curve = []  # LSODA with restarts over tolerances: its time against its error
        for rtol in LSODA_CURVE:
            t, (Y, nfev) = timed(lambda c=case, a=rtol: run_scipy(c, "LSODA", a, 100.0 * a),
                                 repeat)
            curve.append({"benchmark": "BM-2", "case": f"{n}_nodes", "method": "LSODA",
                          "setting": f"rtol={rtol:g},atol={100 * rtol:g},restarts,curve",
                          "time_s": t, "max_error_K": float(np.max(np.abs(Y - ref_seg))),
                          "f_evals": int(nfev), "ratio_vs_anchor": None})
        for r in [x for x in records if x["case"] == f"{n}_nodes"] + curve:
            t_l = time_at_error(curve, r["max_error_K"])
            r["ratio_at_equal_error"] = t_l / r["time_s"] if np.isfinite(t_l) else None
        records += curve
    if args.json:
        print(json.dumps(records, indent=1))
    print(f"{'case':>9} {'method':>8} {'setting':>42} {'time [ms]':>10} {'fevals':>7} "
          f"{'max err [K]':>12} {'LSODA/x':>8} {'at err':>7}")
    for r in records:
        ratio = "" if r["ratio_vs_anchor"] is None else f"{r['ratio_vs_anchor']:.2f}"
        eq = r.get("ratio_at_equal_error")
        eq = "" if eq is None else f"{eq:.2f}"
        print(f"{r['case']:>9} {r['method']:>8} {r['setting']:>42} {1e3 * r['time_s']:10.1f} "
              f"{r['f_evals']:7d} {r['max_error_K']:12.3e} {ratio:>8} {eq:>7}")
    print("LSODA/x: LSODA with restarts at the same setting / x (equal tolerance); at err: "
          "LSODA with restarts interpolated at x's error on its rtol 1e-4 ... 1e-9 curve / x "
          "(equal error; empty: not bracketed)")
    _plot(records, Path(args.out))
    return 0


def _sample_ref(case, tgrid):
    from thermobearing.network import integrate

    net, edges, heat, T0, grid = case
    res = integrate(net, heat, (0.0, edges[-1]), T0, rtol=1e-11, atol=1e-9, breakpoints=edges,
                    heat_jacobian=heat.jacobian)
    # a grid point on a breakpoint that closes a segment is the left limit (continuous T)
    return res.sample(tgrid)


def _plot(records, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for case in dict.fromkeys(r["case"] for r in records):
        pts = sorted((r["max_error_K"], r["time_s"]) for r in records
                     if r["case"] == case and r["setting"].endswith(",curve"))
        if pts:
            ax.loglog(*zip(*pts, strict=True), "k-", lw=0.8,
                      label=f"{case} LSODA restarts, rtol 1e-4...1e-9")
    for r in records:
        if r["setting"].endswith(",curve"):
            continue
        marker = "o" if r["setting"].endswith(",restarts") else "x"
        ax.loglog(r["max_error_K"], r["time_s"], marker, label=f"{r['case']} {r['method']} "
                  f"{r['setting'].split(',')[-1]} {r['setting'].split(',')[0]}")
    ax.set_xlabel("max error [K]")
    ax.set_ylabel("time [s]")
    ax.set_title("BM-2: 120 load steps (o restarts, x no restarts)")
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(out / "bm2_load_steps.png", dpi=120)
    plt.close(fig)
    print(f"plot: {out / 'bm2_load_steps.png'}", file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
