"""BM-3 hard cases of the network steppers (also run as tests: tests/unit/network).

Cases (each yields records with a pass/fail flag ``ok`` and the measured violation):

1. ``tiny_capacity``: the 20-node stiff bearing network whose oil-film node has C = 0 J/K
   (algebraic) or C = 1e-6 J/K, fixed steps dt = 1 s and 60 s. Checks: finite, within
   [lowest boundary, highest steady temperature], error against a tight TR-BDF2 reference.
2. ``dt_sweep``: constant heat from ambient, dt = 1, 10, 60, 600 s over 10 h. Checks: the
   discrete maximum principle (no temperature below ambient or above the steady state).
3. ``load_drop``: 20 min of load, then zero load for 2 h: temperatures fall back towards
   ambient and never below it.
4. ``steady_limit``: one step of dt = 1e14 s equals the steady Newton solution (to
   C/(dt K) ~ 1e-10 K).

Each case runs ours (backward_euler, tr_bdf2, exprb43 -- the exponential method is exact on
these linear cases, so its bounds hold at any dt) and, to show that the checks bite, explicit
Euler and Crank-Nicolson on the same network and steps: explicit Euler blows up once
dt > 2 C/K of the smallest node (and refuses a C = 0 node), Crank-Nicolson rings (its
amplification tends to -1 on stiff modes; the residual of an algebraic node that is off its
constraint at the start of a step flips sign every step).

Usage: python benchmarks/bm3_hard_cases.py [--quick] [--json] [--out DIR]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from thermobearing.errors import ConvergenceError, InputError
from thermobearing.network import integrate, solve_steady
from thermobearing.network.problems import T_AMBIENT, bearing_network

OURS = ("backward_euler", "tr_bdf2", "exprb43")
OTHERS = ("explicit_euler", "crank_nicolson")


def _heat(net, watts=(800.0, 400.0)):
    q = np.zeros(len(net.state_nodes))
    q[net.state_nodes.index(net.nodes_for_role("elements")[0])] = watts[0]
    q[net.state_nodes.index(net.nodes_for_role("oil")[0])] = watts[1]
    return q


def _run(net, heat, t_end, method, dt, breakpoints=()):
    t0 = time.perf_counter()
    try:
        res = integrate(net, heat, (0.0, t_end), T_AMBIENT, method=method, dt=dt,
                        breakpoints=breakpoints)
    except (ConvergenceError, InputError, FloatingPointError) as exc:
        return None, time.perf_counter() - t0, type(exc).__name__
    if not np.all(np.isfinite(res.temperatures)):
        return None, time.perf_counter() - t0, "non-finite"
    return res, time.perf_counter() - t0, ""


def _record(case, method, setting, t, ok, violation, error=np.nan, note=""):
    return {"benchmark": "BM-3", "case": case, "method": method, "setting": setting,
            "time_s": t, "ok": bool(ok), "violation_K": float(violation),
            "max_error_K": float(error), "note": note, "ratio_vs_anchor": None}


def _bounds_violation(T, low, high):
    return float(max(low - T.min(), T.max() - high, 0.0))


def case_tiny_capacity(quick=False):
    out = []
    for cap in (0.0, 1e-6):
        net = bearing_network(20, film_capacity=cap)
        q = _heat(net)
        steady = solve_steady(net, q).temperatures_vector
        t_end = 1800.0
        ref = integrate(net, q, (0.0, t_end), T_AMBIENT, rtol=1e-10, atol=1e-9)
        for dt in ((60.0,) if quick else (1.0, 60.0)):
            for method in OURS + OTHERS:
                res, t, fail = _run(net, q, t_end, method, dt)
                setting = f"C_film={cap:g},dt={dt:g}"
                if res is None:
                    out.append(_record("tiny_capacity", method, setting, t, False, np.inf,
                                       note=f"failed: {fail}"))
                    continue
                viol = _bounds_violation(res.temperatures, T_AMBIENT - 1e-9, steady.max() + 1e-9)
                err = float(np.max(np.abs(res.temperatures[-1] - ref.temperatures[-1])))
                # within the step's own accuracy: 2nd/1st-order error at this dt
                ok = viol == 0.0 and err < (0.5 if dt <= 60 else 5.0)
                out.append(_record("tiny_capacity", method, setting, t, ok, viol, err))
    return out


def case_dt_sweep(quick=False):
    out = []
    net = bearing_network(20, film_capacity=1e-3)
    q = _heat(net)
    steady = solve_steady(net, q).temperatures_vector
    t_end = 36000.0
    for dt in ((60.0, 600.0) if quick else (1.0, 10.0, 60.0, 600.0)):
        for method in OURS + OTHERS:
            res, t, fail = _run(net, q, t_end, method, dt)
            setting = f"dt={dt:g}"
            if res is None:
                out.append(_record("dt_sweep", method, setting, t, False, np.inf,
                                   note=f"failed: {fail}"))
                continue
            viol = _bounds_violation(res.temperatures, T_AMBIENT - 1e-9, steady.max() + 1e-9)
            err = float(np.max(np.abs(res.temperatures[-1] - steady)))
            note = ""
            if method == "tr_bdf2" and viol > 0:
                note = "TR-BDF2 R(z) < 0 for z < -2.414: bounded overshoot (<= 20.7 %)"
            out.append(_record("dt_sweep", method, setting, t, viol == 0.0, viol, err, note))
    return out


def case_load_drop(quick=False):
    out = []
    net = bearing_network(20, film_capacity=1e-3)
    q = _heat(net, (1500.0, 600.0))
    t_on, t_end = 1200.0, 1200.0 + 7200.0

    def heat(t, T):
        return q if t < t_on else 0.0 * q

    steady = solve_steady(net, q).temperatures_vector
    for method, dt in (("backward_euler", 60.0), ("tr_bdf2", None), ("tr_bdf2", 60.0),
                       ("exprb43", None), ("exprb43", 600.0),
                       ("crank_nicolson", 60.0), ("explicit_euler", 60.0)):
        t0 = time.perf_counter()
        try:
            res = integrate(net, heat, (0.0, t_end), T_AMBIENT, method=method, dt=dt,
                            breakpoints=[t_on], rtol=1e-5, atol=1e-3)
            ok_run = np.all(np.isfinite(res.temperatures))
        except (ConvergenceError, InputError) as exc:
            out.append(_record("load_drop", method, f"dt={dt}", time.perf_counter() - t0,
                               False, np.inf, note=f"failed: {type(exc).__name__}"))
            continue
        t = time.perf_counter() - t0
        tol = 0.0 if dt is not None else 2e-3  # adaptive: within its tolerance
        viol = _bounds_violation(res.temperatures, T_AMBIENT - 1e-9 - tol,
                                 steady.max() + 1e-9 + tol)
        after = res.times >= t_on
        cooling = res.temperatures[after][:, net.state_nodes.index("housing_0")]
        mono = float(max(0.0, np.max(np.diff(cooling)))) if cooling.size > 1 else 0.0
        ok = ok_run and viol == 0.0
        out.append(_record("load_drop", method, "adaptive" if dt is None else f"dt={dt:g}", t,
                           ok, max(viol, 0.0), note=f"housing rise after drop {mono:.2e} K"))
    return out


def case_steady_limit(quick=False):
    out = []
    net = bearing_network(20, film_capacity=0.0)
    q = _heat(net)
    steady = solve_steady(net, q).temperatures_vector
    for method in ("backward_euler", "tr_bdf2", "exprb43", "crank_nicolson"):
        res, t, fail = _run(net, q, 1e14, method, 1e14)
        if res is None:
            out.append(_record("steady_limit", method, "dt=1e14", t, False, np.inf, note=fail))
            continue
        err = float(np.max(np.abs(res.temperatures[-1] - steady)))
        out.append(_record("steady_limit", method, "dt=1e14", t, err < 1e-8, 0.0, err))
    return out


CASES = {"tiny_capacity": case_tiny_capacity, "dt_sweep": case_dt_sweep,
         "load_drop": case_load_drop, "steady_limit": case_steady_limit}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--out", default="benchmarks/out")
    args = ap.parse_args(argv)
    records = []
    for fn in CASES.values():
        records += fn(args.quick)
    if args.json:
        print(json.dumps(records, indent=1))
    print(f"{'case':>14} {'method':>15} {'setting':>20} {'ok':>5} {'violation [K]':>14} "
          f"{'error [K]':>10} {'time [ms]':>10}  note")
    for r in records:
        print(f"{r['case']:>14} {r['method']:>15} {r['setting']:>20} {str(r['ok']):>5} "
              f"{r['violation_K']:14.3e} {r['max_error_K']:10.2e} {1e3 * r['time_s']:10.1f}  "
              f"{r['note']}")
    _plot(args.out)
    return 0


def _plot(out_dir) -> None:
    """Film-node temperature at dt = 60 s: ours vs Crank-Nicolson (ringing) and explicit
    Euler (blow-up)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    net = bearing_network(20, film_capacity=1e-6)
    q = _heat(net)
    fig, ax = plt.subplots(figsize=(7, 4))
    i = net.state_nodes.index("oil_0")
    for method in OURS + ("crank_nicolson",):
        res, _, fail = _run(net, q, 1800.0, method, 60.0)
        if res is not None:
            ax.plot(res.times, res.temperatures[:, i] - 273.15, ".-", label=method)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("oil-film node [degC]")
    ax.set_title("BM-3: C = 1e-6 J/K film node, dt = 60 s")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "bm3_hard_cases.png", dpi=120)
    plt.close(fig)
    print(f"plot: {out / 'bm3_hard_cases.png'}", file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
