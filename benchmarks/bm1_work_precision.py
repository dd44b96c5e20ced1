"""BM-1 work-precision of the network steppers against scipy's solve_ivp.

Problem (thermobearing.network.problems): the stiff bearing network with 4, 20 or 100 state
nodes (an oil stream of 946 W/K, capacities from 0.1 J/K to 6e4 J/K), a 66-min protocol of
22 load steps (3 min each, two of them to zero load), and heat sources that fall with
temperature as a viscous loss: q_i = P(t) share_i exp(-0.03 (T_i - T_ref)).

Solvers, each timed in the same process by CPU time (best of ``--repeat`` rounds; the
rounds are interleaved -- every solver once per round -- so that a change of machine load
hits all solvers alike):
- ours: ``integrate(..., method="exprb43" | "tr_bdf2" | "backward_euler",
  breakpoints=step times, heat_jacobian=analytic diagonal, heat_time_dependent=False)``
  (the source is piecewise constant in t, which the flag tells the solver); ``exprb43`` is
  the exponential Rosenbrock method (thermobearing.network.exponential), exact on the
  stiff linear network, with its own exact dense output;
- anchors: ``scipy.integrate.solve_ivp`` with LSODA, BDF and Radau, analytic Jacobian,
  restarted at every load step (one call per step, heat frozen in the step).
Tolerances: the same (rtol, atol = 100 rtol [K]) pairs for everyone.
Error: max over all nodes and a 10-s grid of |T - T_ref|, each solver using its own dense
output (TR-BDF2 and backward Euler: limited cubic Hermite; exprb43: its exact dense
output). Reference: Radau at rtol 1e-12 (restarted), checked against our TR-BDF2 at rtol
1e-11 and exprb43 at rtol 1e-10; the differences are printed.
Ratios: each solver's time at max error = 0.01 K is interpolated (log-log) on its curve;
``ratio_vs_anchor`` of a record is (LSODA time at the record's error) / (record time),
i.e. the speed-up over LSODA at equal error (1 for LSODA itself). The summary prints, for
each of our steppers, (LSODA | BDF | Radau time at 0.01 K) / (ours at 0.01 K).

Usage: python benchmarks/bm1_work_precision.py [--quick] [--json] [--out DIR]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from thermobearing.network import assemble, integrate
from thermobearing.network.problems import bearing_network, load_protocol, viscous_heat_for

TARGET_ERROR = 0.01  # K


def make_case(n: int):
    net = bearing_network(n)
    edges, powers = load_protocol(22, 180.0)
    heat = viscous_heat_for(net, edges, powers)
    T0 = np.full(len(net.state_nodes), 308.15)
    grid = np.linspace(0.0, edges[-1], int(edges[-1] / 10.0) + 1)
    return net, edges, heat, T0, grid


def run_ours(case, method: str, rtol: float, atol: float):
    net, edges, heat, T0, grid = case
    res = integrate(net, heat, (0.0, edges[-1]), T0, method=method, rtol=rtol, atol=atol,
                    breakpoints=edges, heat_jacobian=heat.jacobian,
                    heat_with_jacobian=heat.with_jacobian, heat_time_dependent=False)
    return res.sample(grid), res.stats["heat_evaluations"]


def run_scipy(case, method: str, rtol: float, atol: float):
    net, edges, heat, T0, grid = case
    sys_ = assemble(net)
    C, s = sys_.C, sys_.s
    K = sys_.K if sys_.dense else sys_.K.toarray()
    invC = 1.0 / C
    y = T0.copy()
    out = []
    nsteps = 0
    for k in range(len(edges) - 1):
        q, jq = heat.at_segment(k)

        def fun(t, T, q=q):
            return (s - K @ T + q(t, T)) * invC

        def jac(t, T, jq=jq):
            J = -K.copy()
            J[np.diag_indices_from(J)] += jq(t, T)
            return J * invC[:, None]

        a, b = edges[k], edges[k + 1]
        te, n_out = segment_eval(grid, a, b, last=k == len(edges) - 2)
        r = solve_ivp(fun, (a, b), y, method=method, rtol=rtol, atol=atol, jac=jac,
                      t_eval=te)
        if not r.success:
            raise RuntimeError(f"{method} failed: {r.message}")
        out.append(r.y.T[:n_out])
        y = r.y[:, -1].copy()  # te ends at b: the state the next segment restarts from
        nsteps += r.nfev
    return np.vstack(out), nsteps


def segment_eval(grid: np.ndarray, a: float, b: float, last: bool) -> tuple[np.ndarray, int]:
    """Output times of one restarted segment and how many of them are grid output.

    The grid points of [a, b) ([a, b] for the last segment) are the segment's output; the
    returned times end at b whether or not b is a grid point, so that one ``solve_ivp`` call
    gives both the output and the end state the next segment restarts from (the solver's
    steps do not depend on ``t_eval``: it only samples the dense output). Returns
    (t_eval [s], n_out): the first ``n_out`` columns of the solution are the grid output.
    Before, a segment whose end was not an output point (every one but the last) was solved
    a second time for its end state, which doubled the anchors' times.
    """
    inside = grid[(grid >= a) & ((grid <= b) if last else (grid < b))]
    if inside.size and inside[-1] == b:
        return inside, int(inside.size)
    return np.append(inside, b), int(inside.size)


def timed(fn, repeat: int):
    best = np.inf
    out = None
    for _ in range(repeat):
        t0 = time.process_time()
        out = fn()
        best = min(best, time.process_time() - t0)
    return best, out


def time_at_error(records, target=TARGET_ERROR):
    """Log-log interpolation of time at max error = target on one solver's curve."""
    pts = sorted((r["max_error_K"], r["time_s"]) for r in records if r["max_error_K"] > 0)
    if not pts:
        return np.nan
    errs = np.log([p[0] for p in pts])
    times = np.log([p[1] for p in pts])
    lt = np.log(target)
    if lt < errs[0] or lt > errs[-1]:
        return np.nan  # not bracketed: no extrapolation
    return float(np.exp(np.interp(lt, errs, times)))


OURS = ("exprb43", "tr_bdf2", "backward_euler")
ANCHORS = ("LSODA", "BDF", "Radau")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="4 and 20 nodes, fewer tolerances")
    ap.add_argument("--json", action="store_true", help="print JSON records")
    ap.add_argument("--out", default="benchmarks/out", help="folder for the PNG plot")
    ap.add_argument("--repeat", type=int, default=None)
    ap.add_argument("--sizes", type=int, nargs="*", default=None,
                    help="network sizes (default 4 20 100; --quick: 4 20)")
    args = ap.parse_args(argv)
    sizes = args.sizes or ([4, 20] if args.quick else [4, 20, 100])
    repeat = args.repeat or (3 if args.quick else 5)
    exp_rtols = [3e-3, 1e-3, 3e-4, 1e-4] if args.quick else [1e-2, 3e-3, 1e-3, 3e-4, 1e-4,
                                                              1e-5]
    ours_rtols = [1e-4, 3e-5, 1e-5] if args.quick else [1e-4, 3e-5, 1e-5, 3e-6, 1e-6]
    scipy_rtols = [1e-3, 1e-4, 1e-5, 1e-6] if args.quick else [1e-3, 1e-4, 1e-5, 1e-6, 1e-7]
    solvers = [("exprb43", "ours", exp_rtols), ("tr_bdf2", "ours", ours_rtols),
               ("backward_euler", "ours", [1e-6] if args.quick else [1e-5, 1e-6]),
               ("LSODA", "scipy", scipy_rtols), ("BDF", "scipy", scipy_rtols),
               ("Radau", "scipy", scipy_rtols)]
    records = []
    summary = []
    for n in sizes:
        case = make_case(n)
        t_ref, (ref, _) = timed(lambda c=case: run_scipy(c, "Radau", 1e-12, 1e-10), 1)
        ours_tight, _ = run_ours(case, "tr_bdf2", 1e-11, 1e-9)
        # (this tight run also loads exprb43's compiled kernels before anything is timed)
        exp_tight, _ = run_ours(case, "exprb43", 1e-10, 1e-8)
        ref_diff = float(np.max(np.abs(ours_tight - ref)))
        exp_diff = float(np.max(np.abs(exp_tight - ref)))
        print(f"\n== {n} nodes: reference Radau(1e-12) in {t_ref:.1f} s; "
              f"|tr_bdf2(1e-11) - ref| = {ref_diff:.2e} K, |exprb43(1e-10) - ref| = "
              f"{exp_diff:.2e} K", file=sys.stderr)
        configs = [(m, kind, rtol) for m, kind, rtols in solvers for rtol in rtols]
        best = {c: np.inf for c in configs}
        outs: dict = {}
        for _ in range(repeat):  # interleaved rounds: every configuration once per round
            for c in configs:
                m, kind, rtol = c
                if c in outs and outs[c] is None:
                    continue  # failed before
                runner = run_ours if kind == "ours" else run_scipy
                try:
                    t, out = timed(lambda r=runner, k=case, m=m, a=rtol: r(k, m, a, 100.0 * a), 1)
                except Exception as exc:  # a solver failure is a result, not a crash
                    print(f"{m} rtol={rtol:g} failed: {exc}", file=sys.stderr)
                    outs[c] = None
                    continue
                best[c] = min(best[c], t)
                outs[c] = out
        case_recs = []
        for c in configs:
            if outs.get(c) is None:
                continue
            m, _, rtol = c
            Y, steps = outs[c]
            err = float(np.max(np.abs(Y - ref)))
            case_recs.append({"benchmark": "BM-1", "case": f"{n}_nodes", "method": m,
                              "setting": f"rtol={rtol:g},atol={100 * rtol:g}",
                              "time_s": best[c], "max_error_K": err, "f_evals": int(steps),
                              "reference_uncertainty_K": max(ref_diff, exp_diff)})
        lsoda = [r for r in case_recs if r["method"] == "LSODA"]
        for r in case_recs:
            t_l = time_at_error(lsoda, r["max_error_K"])
            r["ratio_vs_anchor"] = (t_l / r["time_s"]) if np.isfinite(t_l) else None
        at = {m: time_at_error([r for r in case_recs if r["method"] == m])
              for m, _, _ in solvers}
        summary.append((n, at))
        records += case_recs
    # ------------------------------------------------------------------ output
    if args.json:
        print(json.dumps(records, indent=1))
    print(f"\n{'case':>10} {'method':>15} {'setting':>22} {'time [ms]':>10} {'fevals':>6} "
          f"{'max err [K]':>12} {'x LSODA':>8}")
    for r in records:
        ratio = "" if r["ratio_vs_anchor"] is None else f"{r['ratio_vs_anchor']:.2f}"
        print(f"{r['case']:>10} {r['method']:>15} {r['setting']:>22} "
              f"{1e3 * r['time_s']:10.1f} {r['f_evals']:6d} {r['max_error_K']:12.3e} {ratio:>8}")
    print(f"\nTime at max error {TARGET_ERROR} K (interpolated on each curve; nan = not "
          "bracketed) and speed-up of our steppers (anchor time / ours):")
    for n, at in summary:
        parts = [f"{m} {1e3 * v:.1f} ms" for m, v in at.items()]
        print(f"  {n:3d} nodes: " + ", ".join(parts))
        for ours in ("exprb43", "tr_bdf2"):
            if not np.isfinite(at.get(ours, np.nan)):
                continue
            ratios = [f"{m}/{ours} = {at[m] / at[ours]:.1f}x" for m in ANCHORS
                      if np.isfinite(at.get(m, np.nan))]
            print("             " + ", ".join(ratios))
    if args.json:
        print(json.dumps([{"benchmark": "BM-1", "case": f"{n}_nodes", "summary": True,
                           "time_at_0.01K_s": {m: (v if np.isfinite(v) else None)
                                               for m, v in at.items()}}
                          for n, at in summary], indent=1))
    _plot(records, sizes, Path(args.out))
    return 0


def _plot(records, sizes, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(1, len(sizes), figsize=(5 * len(sizes), 4), squeeze=False)
    for ax, n in zip(axes[0], sizes, strict=True):
        for m in (*OURS, *ANCHORS):
            rs = sorted((r["max_error_K"], r["time_s"]) for r in records
                        if r["case"] == f"{n}_nodes" and r["method"] == m)
            if rs:
                ax.loglog([x[0] for x in rs], [x[1] for x in rs], "o-", label=m)
        ax.axvline(TARGET_ERROR, color="k", lw=0.8, ls="--")
        ax.set_xlabel("max error [K]")
        ax.set_ylabel("time [s]")
        ax.set_title(f"BM-1: {n} nodes, 22 load steps")
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "bm1_work_precision.png", dpi=120)
    plt.close(fig)
    print(f"plot: {out / 'bm1_work_precision.png'}", file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
