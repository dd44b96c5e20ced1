"""Cost of the coupled rib_friction heat source in a scene: the running-mean stop against the
fixed window, measured in the same run.

Problem: the rib_friction source (:mod:`thermobearing.heat_sources.rib`, model "coupled")
books the time-mean friction power of the coupled all-roller + cage dynamics of paper 003
eqs. 18-19 (:mod:`thermobearing.skidding.roller_dynamics_heat`), one integration per
operating state (speed, radial load) and 5 K temperature node. The scene here is paper 003's
CRB 50x75x16 as in ``configs/scenes/crb_rib_example.toml`` (MIL-PRF-23699, jet 2 L/min at
80 degC, both ribs, race control, the default heat sources) with a short schedule of
speed / load steps (``STEPS``, 0.2 kN axial, ``--duration`` s each; ``--quick``: the first
two steps) and no unbalance (every scene's default; ``--unbalance`` [g] sets the
rib_friction option ``unbalance_mass``: the chaotic impacting motion).

Paths, each from an empty dynamics cache, the process warmed by a tiny run first (numba
loads its cached kernels then: timed separately as ``first_call_s``):

- ``fixed``: rib_friction options ``convergence = 0``, ``table_retries = 0`` and
  ``warm_start_nodes = 0``, the previous path (2 warm-up + 3 statistics cage orbits per
  node from the quasi-static state; a run that enters the cage runaway re-run whole on the
  evaluate traction path);
- ``cold``: the defaults but ``warm_start_nodes = 0`` (every node from the quasi-static
  state, the default before 2026-11-24);
- ``converged``: the defaults, every node without unbalance from the end state of the
  nearest node of its operating state already run (``warm_start_nodes``,
  :data:`~thermobearing.skidding.roller_dynamics_heat.DEFAULT_WARM_START_NODES`), the
  running-mean stop at
  :data:`~thermobearing.skidding.roller_dynamics_heat.DEFAULT_CONVERGENCE`
  (:mod:`~thermobearing.skidding.roller_dynamics_convergence`) and up to
  :data:`~thermobearing.skidding.roller_dynamics_heat.DEFAULT_TABLE_RETRIES` other
  table-path trajectories before the evaluate path (unbalanced runs only: without an
  unbalance no run met the runaway).

Printed per path: CPU of the scene run, dynamics runs (cache misses) and hits, per run the
operating state, node temperature, CPU, orbits integrated, step size, heat and rib slide
speed; with ``--profile`` the cProfile split (process CPU time) of the path: time loop
kernel, traction table, quasi-static solve, dynamics set-up, post-processing, from a second
run of the path under the profiler (the profiler inflates the Python-heavy parts, the
quasi-static solve ~4x: roller_dynamics_heat notes; the timed runs are not profiled: the
scene CPU was taken under the profiler before, which inflated the paths with the smaller
kernel share, the warm-started ones, more than the fixed window). Then the
ratios fixed / converged and cold / converged of the CPU times and the change in the rib
heat: per dynamics node present in both runs, |heat / heat_fixed - 1|
and the same for the rib slide speed (which sets the thrust share's heat), and the booked
rib_friction power of the scene at the end of every step (both transients follow their own
temperatures, so this also holds the feedback of the small heat change). These are changes
between paths, not errors. With ``--reference-orbits N`` a fourth path runs the fixed window
with N statistics orbits per node instead of 3 (``reference``; the warm-up as the fixed
window's, every node from the quasi-static state) and each path's ``error`` is the largest
|heat / heat_reference - 1| over the nodes it shares with it (``error_slide`` the same for
the slide speed): the error axis against a long time mean (minutes of CPU: N = 20 is about
4x the fixed window).

Usage: python benchmarks/bm_rib_friction.py [--quick] [--duration S] [--unbalance G]
       [--reference-orbits N] [--profile] [--json] [--out FILE]
(``--json``: the records on stdout, one per path plus a summary record; ``--out FILE``:
the records written to FILE as well.)
"""

from __future__ import annotations

import argparse
import cProfile
import json
import math
import pstats
import sys
import time
import warnings
from dataclasses import replace
from typing import Any

RPM = math.pi / 30.0
#: (r/min, radial load N) of the schedule's steps
STEPS = ((20000.0, 3000.0), (5000.0, 2000.0), (10000.0, 6000.0))
SCENE = "configs/scenes/crb_rib_example.toml"
#: function names of the cProfile split (cumulative process CPU time)
SPLIT = {"time loop kernel (_integrate)": "_integrate",
         "traction table (build_traction_table)": "build_traction_table",
         "quasi-static solve (solve_roller)": "solve_roller",
         "dynamics set-up (build_model)": "build_model",
         "post-processing (_post)": "_post"}


def make_scene(duration: float, quick: bool, unbalance_g: float, convergence: float,
               retries: int, warm_nodes: int) -> Any:
    """The benchmark scene (module notes) with the rib_friction options set."""
    from thermobearing.scene import Schedule, load_scene
    from thermobearing.scene_schedule import Step

    scene = load_scene(SCENE)
    steps = [Step(duration=duration, speed=rpm * RPM, radial_load=load, axial_load=200.0)
             for rpm, load in (STEPS[:2] if quick else STEPS)]
    opts: dict[str, Any] = {"convergence": convergence, "table_retries": retries,
                            "warm_start_nodes": warm_nodes}
    if unbalance_g > 0:
        opts["unbalance_mass"] = unbalance_g * 1e-3
    models = dict(scene.models)
    models["heat_source_options"] = {"rib_friction": opts}
    return replace(scene, schedule=Schedule(steps=steps), models=models)


def _profile_split(prof: cProfile.Profile, total: float) -> dict[str, float]:
    stats = pstats.Stats(prof).stats  # type: ignore[attr-defined]
    out = {}
    for label, fn in SPLIT.items():
        # the largest cumulative time of an entry of that name (numba dispatchers and
        # wrappers repeat a compiled function's name along the same call chain)
        out[label] = max((v[3] for k, v in stats.items() if k[2] == fn), default=0.0)
    out["rest of the scene run"] = max(total - sum(out.values()), 0.0)
    return out


def run_path(name: str, scene: Any, profile: bool = False,
             orbits: float | None = None) -> dict[str, Any]:
    """One scene run from an empty dynamics cache, with every dynamics run logged; its
    CPU time unprofiled. With ``profile`` the same run again from an empty cache under
    cProfile for the split (``profile`` of the record; else empty). ``orbits``: every
    dynamics run averages over that many cage orbits (its ``orbits`` argument; None: the
    source's own)."""
    from thermobearing.errors import ConvergenceError
    from thermobearing.simulation import Simulation
    from thermobearing.skidding import roller_dynamics_heat as rdh

    rdh.clear_cache()
    log: list[dict[str, Any]] = []
    original = rdh.run_dynamics

    def logged(*args: Any, **kwargs: Any) -> Any:
        state = {"speed_rpm": args[2] / RPM, "radial_load": args[3], "temperature": args[4]}
        t0 = time.process_time()
        try:
            out, resp = original(*args, **(kwargs if orbits is None
                                           else {**kwargs, "orbits": float(orbits)}))
        except ConvergenceError:
            # a node whose motion ran away on every path (its neighbour's value is booked)
            log.append({**state, "cpu_s": time.process_time() - t0, "orbits": math.nan,
                        "step_s": math.nan, "heat": math.nan, "slide": math.nan,
                        "fallback": 1, "retries": -1, "finished_on": "", "failed": True,
                        "warm": 0})
            raise
        log.append({**state, "cpu_s": out.cost_s, "orbits": out.orbits,
                    "warm": out.warm_starts,
                    "step_s": float(resp.series.get("step", [math.nan])[0]),
                    "heat": out.heat, "slide": out.rib_slide_speed,
                    "fallback": out.fallbacks,
                    "retries": int(resp.series.get("table_retries", [0])[0]),
                    "finished_on": str(resp.series.get("fallback_traction", ["table"])[0]),
                    "failed": False})
        return out, resp

    rdh.run_dynamics = logged
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t0 = time.process_time()
            res = Simulation(scene).run()
            cpu = time.process_time() - t0
    finally:
        rdh.run_dynamics = original
    split: dict[str, float] = {}
    if profile:  # the split from a second, profiled run (the timing above is unprofiled)
        rdh.clear_cache()
        prof = cProfile.Profile(time.process_time)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t1 = time.process_time()
            prof.enable()
            Simulation(scene).run()
            prof.disable()
            split = _profile_split(prof, time.process_time() - t1)
    info = rdh.cache_info()
    losses = res.tables["losses"]
    rib = losses[losses["source"] == "rib_friction"]
    last = rib.groupby("step")["time [s]"].transform("max") == rib["time [s]"]
    booked = rib[last].groupby("step")["power [W]"].sum()
    temps = res.tables["temperatures"]
    return {"path": name, "cpu_s": cpu, "runs": info["runs"], "hits": info["hits"],
            "nodes": log, "booked_rib_W": [float(v) for v in booked.values],
            "final_rollers_degC": float(temps.iloc[-1]["crb.rollers [degC]"]),
            "profile": split}


def first_call() -> float:
    """CPU of a tiny coupled run in this fresh process (imports, numba cache loads)."""
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.roller_dynamics import build_model
    from thermobearing.skidding.roller_dynamics_coupled import simulate_coupled

    t0 = time.process_time()
    b, lub = load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699")
    m = build_model(b, lub, 20000 * RPM, 3000.0, 0.0, coupling="none")
    simulate_coupled(m, b, lub, n_orbits=0.01, warmup_orbits=0.0)
    return time.process_time() - t0


def compare(fixed: dict[str, Any], conv: dict[str, Any]) -> dict[str, Any]:
    """Ratios and heat changes of the converged path against the fixed one."""
    def key(r: dict[str, Any]) -> tuple:
        return (round(r["speed_rpm"], 6), round(r["radial_load"], 6),
                round(r["temperature"], 6))

    ref = {key(r): r for r in fixed["nodes"] if not r["failed"]}
    d_heat, d_slide = [], []
    for r in conv["nodes"]:
        f = None if r["failed"] else ref.get(key(r))
        if f is not None:
            d_heat.append(abs(r["heat"] / f["heat"] - 1.0) if f["heat"] else 0.0)
            d_slide.append(abs(r["slide"] / f["slide"] - 1.0) if f["slide"] else 0.0)
    booked = [abs(c / f - 1.0) for f, c in zip(fixed["booked_rib_W"], conv["booked_rib_W"],
                                                strict=True) if f]
    dyn_f = sum(r["cpu_s"] for r in fixed["nodes"])
    dyn_c = sum(r["cpu_s"] for r in conv["nodes"])
    return {"path": "summary", "ratio_scene_cpu": fixed["cpu_s"] / conv["cpu_s"],
            "ratio_dynamics_cpu": dyn_f / dyn_c if dyn_c else math.nan,
            "ratio_per_run": (dyn_f / len(fixed["nodes"])) / (dyn_c / len(conv["nodes"]))
            if conv["nodes"] else math.nan,
            "common_nodes": len(d_heat),
            "max_node_heat_change": max(d_heat, default=math.nan),
            "max_node_slide_change": max(d_slide, default=math.nan),
            "max_booked_rib_change": max(booked, default=math.nan),
            "final_rollers_change_K": conv["final_rollers_degC"] - fixed["final_rollers_degC"]}


def _print_path(r: dict[str, Any]) -> None:
    print(f"\n[{r['path']}] scene CPU {r['cpu_s']:.2f} s, dynamics runs {r['runs']}, "
          f"cache hits {r['hits']}, final rollers {r['final_rollers_degC']:.2f} degC")
    print("   r/min    load N   node K   CPU s  orbits  step us   heat W/roller  slide m/s"
          "  start")
    for n in r["nodes"]:
        print(f"  {n['speed_rpm']:7.0f} {n['radial_load']:8.0f} {n['temperature']:8.2f} "
              f"{n['cpu_s']:7.2f} {n['orbits']:7.2f} {1e6 * n['step_s']:8.3f} "
              f"{n['heat']:14.5g} {n['slide']:10.5g}  {'warm' if n.get('warm') else 'cold'}"
              + ("  (ran away on every path)" if n["failed"] else
                 f"  (runaway met: {n['retries']} table retries, finished on the "
                 f"{n['finished_on']} path)" if n["fallback"] else ""))
    print("  booked rib_friction at step ends [W]: "
          + ", ".join(f"{v:.3f}" for v in r["booked_rib_W"]))
    if r["profile"]:
        print("  profile (cumulative CPU s of a second, profiled run): " + "; ".join(
            f"{k} {v:.2f}" for k, v in r["profile"].items()))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="the first two steps only")
    parser.add_argument("--duration", type=float, default=10.0, help="step duration [s]")
    parser.add_argument("--unbalance", type=float, default=0.0,
                        help="rib_friction unbalance_mass [g] (default 0)")
    parser.add_argument("--reference-orbits", type=float, default=None,
                        help="also run a reference path: the fixed window with this many "
                             "statistics orbits per node; every path's error against it")
    parser.add_argument("--profile", action="store_true",
                        help="run each path a second time under cProfile for its CPU split "
                             "(the timed runs stay unprofiled)")
    parser.add_argument("--json", action="store_true", help="records on stdout")
    parser.add_argument("--out", type=str, default=None, help="records to this file too")
    args = parser.parse_args(argv)
    from thermobearing.skidding.roller_dynamics_heat import (
        DEFAULT_CONVERGENCE,
        DEFAULT_TABLE_RETRIES,
        DEFAULT_WARM_START_NODES,
    )

    warm = first_call()
    fixed = run_path("fixed", make_scene(args.duration, args.quick, args.unbalance, 0.0, 0,
                                         0), args.profile)
    cold = run_path("cold", make_scene(args.duration, args.quick, args.unbalance,
                                       DEFAULT_CONVERGENCE, DEFAULT_TABLE_RETRIES, 0),
                    args.profile)
    conv = run_path("converged", make_scene(args.duration, args.quick, args.unbalance,
                                            DEFAULT_CONVERGENCE, DEFAULT_TABLE_RETRIES,
                                            DEFAULT_WARM_START_NODES), args.profile)
    summary = compare(fixed, conv)
    vs_cold = compare(cold, conv)
    summary.update({f"cold_{k}": v for k, v in vs_cold.items() if k != "path"})
    summary.update(first_call_s=warm, convergence=DEFAULT_CONVERGENCE,
                   table_retries=DEFAULT_TABLE_RETRIES,
                   warm_start_nodes=DEFAULT_WARM_START_NODES,
                   duration_s=args.duration, unbalance_g=args.unbalance, quick=args.quick)
    case = f"CRB 50x75x16 {'2' if args.quick else '3'} steps, {args.unbalance:g} g"
    for r in (fixed, cold, conv):  # the fields `thermobearing bench` tabulates
        r.update(benchmark="rib_friction", case=case, method=r["path"],
                 setting=f"{args.duration:g} s steps", time_s=r["cpu_s"],
                 ratio_vs_anchor=fixed["cpu_s"] / r["cpu_s"])
    conv["error"] = summary["max_node_heat_change"]  # relative, against the fixed path
    cold["error"] = compare(fixed, cold)["max_node_heat_change"]
    records = [fixed, cold, conv, summary]
    ref = None
    if args.reference_orbits:
        ref = run_path("reference", make_scene(args.duration, args.quick, args.unbalance,
                                               0.0, 0, 0), orbits=args.reference_orbits)
        ref.update(benchmark="rib_friction", case=case, method="reference",
                   setting=f"fixed window, {args.reference_orbits:g} orbits",
                   time_s=ref["cpu_s"], ratio_vs_anchor=fixed["cpu_s"] / ref["cpu_s"],
                   error=0.0)
        for r in (fixed, cold, conv):
            c = compare(ref, r)
            r.update(error=c["max_node_heat_change"], error_slide=c["max_node_slide_change"],
                     error_nodes=c["common_nodes"], error_booked=c["max_booked_rib_change"],
                     error_against="reference")
        records.insert(3, ref)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as fh:
            for r in records:
                fh.write(json.dumps(r) + "\n")
    if args.json:
        for r in records:
            print(json.dumps(r))
        return 0
    print(f"first call (imports, numba cache loads, tiny run): {warm:.2f} s CPU")
    _print_path(fixed)
    _print_path(cold)
    _print_path(conv)
    if ref is not None:
        _print_path(ref)
        print(f"\nerror against the reference ({args.reference_orbits:g} orbits per node, "
              f"{ref['cpu_s']:.1f} s CPU): " + "; ".join(
                  f"{r['path']} max |dheat| {100 * r['error']:.3f} %, |dslide| "
                  f"{100 * r['error_slide']:.3f} % ({r['error_nodes']} nodes), booked rib "
                  f"heat {100 * r['error_booked']:.3f} %" for r in (fixed, cold, conv)))
    s = summary
    print(f"\nconverged (tol {DEFAULT_CONVERGENCE}) vs fixed window, same run: scene CPU "
          f"ratio {s['ratio_scene_cpu']:.2f}, dynamics CPU ratio {s['ratio_dynamics_cpu']:.2f},"
          f" per dynamics run {s['ratio_per_run']:.2f}")
    print(f"rib heat change: nodes in both runs {s['common_nodes']}, max |dheat| "
          f"{100 * s['max_node_heat_change']:.3f} %, max |dslide| "
          f"{100 * s['max_node_slide_change']:.3f} %; booked rib_friction at step ends max "
          f"{100 * s['max_booked_rib_change']:.3f} %; final roller temperature "
          f"{s['final_rollers_change_K']:+.4f} K")
    print(f"warm starts (nearest node <= {DEFAULT_WARM_START_NODES} steps) vs cold starts, "
          f"same run: scene CPU ratio {s['cold_ratio_scene_cpu']:.2f}, dynamics CPU ratio "
          f"{s['cold_ratio_dynamics_cpu']:.2f}; nodes in both {s['cold_common_nodes']}, max "
          f"|dheat| {100 * s['cold_max_node_heat_change']:.3f} %, max |dslide| "
          f"{100 * s['cold_max_node_slide_change']:.3f} %, booked rib_friction at step ends "
          f"max {100 * s['cold_max_booked_rib_change']:.3f} %, final roller temperature "
          f"{s['cold_final_rollers_change_K']:+.4f} K")
    return 0


if __name__ == "__main__":
    sys.exit(main())
