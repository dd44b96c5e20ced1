"""BM-7: the fidelity ladder -- wall time against temperature and power-loss error.

Problem: the default scene (``configs/scenes/qj1044_rig.toml``: two QJ1044 four-point ball
bearings on one shaft, 1800 r/min, 33 L/min jet, axial load 0-42 kN in 22 steps of 3 min,
four-node network per bearing); ``--quick``: every 6th load step (0, 12, 24, 36 kN).

Levels (all on the same network, stepper and schedule):

- L0: a global friction model, no kinematics: the SKF four-term model or Palmgren's
  M0 + M1 (:mod:`thermobearing.global_friction`), oil viscosity at the bearing's oil-node
  temperature, the whole loss on the oil node (driver in ``benchmarks/_protocol.py``; a
  scene runs the same rung with ``[models] kinematics = "none"`` and the
  ``global_friction`` source);
- L1 race control: quasi-static loads with race-control kinematics
  (``[models] kinematics = "race_control"``) + closed-form film + the local heat sources;
- L1 skidding: the scene's default (skidding solver + closed-form film + heat sources);
- L2 (numerical EHL in the contacts): not run on this scene. It is a ball bearing and the
  package's numerical EHL (``thermobearing.ehl``, registry ``EHL_SOLVERS``) solves line
  contacts only (the scene chain refuses ``[models] film = "numerical_tehl"`` for balls);
  printed as skipped, with the reasons found at run time. The roller problem below runs it.

Reference ("the highest level run", tightest settings): L1 skidding with
``kinematics_tolerance`` 0.003, ``chunk`` 15 s, stepper rtol 1e-8, atol 1e-6 K.

Errors, on the end of every load step: temperature = max |T - T_ref| over the 8 nodes [K];
loss = max |P - P_ref| / P_ref over the bearings' total losses [-]. Budget: 1 K and 5 %
(``--budget-K``, ``--budget-loss``): the script prints the cheapest level (at the scene's
solver settings) and the cheapest solver setting of L1 skidding within the budget.

Solver sweeps of L1 skidding against the same reference: ``solver.kinematics_tolerance``
0.3, 0.1, 0.03, 0.01, 0.003 (at the scene's chunk, 90 s) and ``solver.chunk`` 180, 90, 60,
30, 15 s (at the scene's tolerance, 0.03). ``ratio_vs_anchor`` = (CPU time of the scene's
default, L1 skidding at tolerance 0.03 and chunk 90 s) / (record CPU time): > 1 is cheaper
than the default.

Timing: one warm-up run of a 2-step protocol first (lazy imports, caches) so that no
record pays first-call costs. Each record has the wall time (``time_s``) and the process
CPU time (``cpu_s``); the ratios, the plot and the "cheapest" choice use CPU time, because
on the shared 2-core machine the wall time was up to 10x the CPU time and varied between
identical runs. Ball problem: every run is repeated ``--repeat`` times (default 3) and the
least CPU time kept (the runs are deterministic: the same temperatures each time); its runs
take 0.05-0.3 s of CPU, where one timing moved by ~20 % with the machine's load, enough to
reorder the "cheapest" choice between settings. The roller problem times every run once
(L2 takes minutes).

Roller problem (``--problem roller``; ``all``, the default, runs both):
``configs/scenes/paper001_ladder.toml``, paper 001's D1842926 cylindrical roller bearing
with OIL_4109 (6 L/min jet at 80 degC, starting at 80 degC), three 2-min steps (6000 r/min
8 kN, 6000 r/min 16 kN, 4000 r/min 16 kN), four-node network; ``--quick``: its first step.
Levels: L0 SKF four-term (the 10 series' constants: the SKF table has no 19 series,
D1842926's; an estimate) and Palmgren, by ``_protocol.run_l0``; L1 the scene (skidding +
closed-form film); L2 the scene with ``[models] film = "numerical_tehl"`` (the skidding
solver with the tabulated numerical thermal EHL film and drag,
``ehl.coupling.solve_roller_tehl``; the film table is built during the run and kept for its
later kinematics solves: its node solves are the L2 cost, counted in ``film_table_solves``
and ``film_table_cpu_s``). Errors as above, against L2 (the highest level run) at the
scene's solver settings; with ``--no-l2`` (or if L2 stops with a ConvergenceError, printed
with its operating point) against L1 at the tight settings ``REFERENCE``. Sweep: L1's
``kinematics_tolerance`` 0.3 ... 0.01 against the same reference; ``--l2-sweep``: L2 at
0.3 and 0.1 as well (each a new film table: minutes of CPU). Prints the cheapest
level within the budget for the roller problem; plot ``bm7_fidelity_ladder_roller.png``.
Cost (2026-11-24, shared 2-core machine): L2 75-86 s CPU (1-3.7 min wall), 480 film-table
node solves at n = 512 (0.1-0.5 s CPU each); ``--quick`` L2 65-75 s CPU (288 nodes: the
first step, where the rollers warm ~60 K across the table's 5-K temperature layers, builds
most of the table); L0 and L1 under 1 s CPU; ``--no-l2`` seconds. ``--quick`` runs L2 with
``film_options`` :data:`ROLLER_QUICK_FILM_OPTIONS` (grid_points 256, temperature_step 10 K);
measured on its step alone (2026-11-24, one thread per run, NUMBA_NUM_THREADS=1, two runs
at a time): defaults (n = 512, 5 K) 33.1 and 34.3 s CPU, 288 node solves; n = 256 28.7 s
(dT 0.009 K, total loss 0.05 % from the defaults); 10 K 21.2 s, 180 solves (0.0025 K,
0.016 %); both 18.4 s, 180 solves (0.007 K, 0.036 %); n = 256 and 20 K 11.3 s, 106 solves,
but 0.20 K, 0.13 %. Result: L1 is 4.2 % from L2 on the total loss but 10 K on the rollers
node, so within 1 K / 5 % only L2 itself.

Usage: python benchmarks/bm7_fidelity_ladder.py [--quick] [--json] [--out DIR]
[--problem ball|roller|all] [--no-l2] [--l2-sweep] [--no-sweeps]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from _protocol import (  # noqa: E402
    ROLLER_SCENE,
    default_scene,
    errors,
    roller_scene,
    run_l0,
    run_l1,
    with_models,
    with_solver,
)

KIN_TOLERANCES = (0.3, 0.1, 0.03, 0.01, 0.003)
CHUNKS = (180.0, 90.0, 60.0, 30.0, 15.0)
REFERENCE = {"kinematics_tolerance": 0.003, "chunk": 15.0, "rtol": 1e-8, "atol": 1e-6}
L0_MODELS = ("skf_four_term", "palmgren")
#: roller problem: L0 models and options (the SKF constants have no 19 series, D1842926's:
#: the 10 series' constants are used, an estimate), the L1 tolerance sweep, --quick steps
ROLLER_L0 = (("skf_four_term", {"series": "10"}), ("palmgren", {}))
ROLLER_TOLERANCES = (0.3, 0.1, 0.03, 0.01)
#: --l2-sweep: L2 at looser re-solve tolerances than the scene's 0.03 (a few CPU minutes each)
ROLLER_L2_TOLERANCES = (0.3, 0.1)
ROLLER_QUICK_STEPS = 1
#: --quick: L2's film settings ([models] film_options): a coarser thermal-EHL grid and
#: temperature layer (measured against the defaults n = 512, 5 K in the module docstring)
ROLLER_QUICK_FILM_OPTIONS = {"grid_points": 256, "temperature_step": "10 K"}


def _setting(scene) -> str:
    s = scene.solver
    return (f"kin_tol={s.kinematics_tolerance:g},chunk={s.chunk:g}s,rtol={s.rtol:g},"
            f"atol={s.atol:g}")


def l2_status(scene) -> str:
    """Why L2 (numerical EHL) is not run on this scene (or '' if it could be)."""
    from thermobearing.geometry import load_bearing

    try:
        from thermobearing.ehl import EHL_SOLVERS

        solvers = list(EHL_SOLVERS.names())
    except ImportError:
        solvers = []
    balls = [b for b in scene.bearings
             if hasattr(load_bearing(b.preset or str(scene.resolve_path(b.path))),
                        "ball_diameter")]
    if not balls:
        return ""
    return ("L2 skipped: the scene's bearings are ball bearings and the numerical EHL "
            "(thermobearing.ehl" + (f": {', '.join(solvers)}" if solvers else "")
            + ") solves line contacts only; the roller problem (--problem roller, "
            f"configs/scenes/{ROLLER_SCENE}.toml) runs L2")


def least_cpu(run, repeat: int):
    """``run()`` (a :class:`_protocol.ProtocolRun`) ``repeat`` times: the run with the least
    CPU time (the runs are deterministic, only their timings differ)."""
    return min((run() for _ in range(max(1, repeat))), key=lambda r: r.cpu_s)


def ball_ladder(args: argparse.Namespace) -> list[dict]:
    """The ball-bearing ladder (the default scene): runs, prints, plots; its records."""
    base = default_scene(quick=args.quick, stride=args.stride)
    case = ("qj1044_rig" + ("_quick" if args.quick else "")
            + (f"_stride{args.stride}" if args.stride else ""))
    print(f"== BM-7 {case}: {len(base.schedule.steps)} load steps, "
          f"{base.schedule.duration / 60:.0f} min", file=sys.stderr)
    run_l1("warm-up", default_scene(stride=11))  # first-call costs out of every record

    runs = {}  # (kind, setting) -> ProtocolRun (the default appears in both sweeps: run once)

    repeat = max(1, args.repeat)

    def l1(kind: str, scene):
        key = (kind, _setting(scene))
        if key not in runs:
            runs[key] = least_cpu(lambda: run_l1(f"L1 {kind}", scene), repeat)
            r = runs[key]
            print(f"  {r.label:>20} {key[1]:>40} {r.time_s:8.2f} s ({r.cpu_s:.2f} s CPU), "
                  f"{r.kinematics_solves} kinematics solves", file=sys.stderr)
        return runs[key]

    ref = l1("skidding", with_solver(base, **REFERENCE))
    ladder = []
    for m in L0_MODELS:
        r = least_cpu(lambda m=m: run_l0(f"L0 {m}", base, m), repeat)
        print(f"  {r.label:>20} {'':>40} {r.time_s:8.2f} s ({r.cpu_s:.2f} s CPU)",
              file=sys.stderr)
        ladder.append(("L0", m, r, _setting(base)))
    ladder.append(("L1", "race_control",
                    l1("race_control", with_models(base, kinematics="race_control")),
                    _setting(base)))
    default = l1("skidding", base)
    ladder.append(("L1", "skidding (default)", default, _setting(base)))
    l2_note = l2_status(base)

    records = []

    def record(level: str, method: str, run, setting: str, sweep: str) -> dict:
        dT, dP = errors(run, ref)
        rec = {"benchmark": "BM-7", "case": case, "method": f"{level} {method}",
               "setting": setting, "sweep": sweep, "time_s": run.time_s, "cpu_s": run.cpu_s,
               "max_error_K": dT,
               "error": dP, "kinematics_solves": run.kinematics_solves,
               "ratio_vs_anchor": default.cpu_s / run.cpu_s}
        records.append(rec)
        return rec

    for level, method, run, setting in ladder:
        record(level, method, run, setting, "ladder")
    if not args.no_sweeps:
        for tol in KIN_TOLERANCES:
            sc = with_solver(base, kinematics_tolerance=tol)
            record("L1", "skidding", l1("skidding", sc), _setting(sc), "kinematics_tolerance")
        for chunk in CHUNKS:
            sc = with_solver(base, chunk=chunk)
            record("L1", "skidding", l1("skidding", sc), _setting(sc), "chunk")
    ref_rec = {"benchmark": "BM-7", "case": case, "method": "L1 skidding (reference)",
               "setting": _setting(with_solver(base, **REFERENCE)), "sweep": "reference",
               "time_s": ref.time_s, "cpu_s": ref.cpu_s, "max_error_K": 0.0, "error": 0.0,
               "kinematics_solves": ref.kinematics_solves,
               "ratio_vs_anchor": default.cpu_s / ref.cpu_s}
    records.append(ref_rec)

    if args.json:  # JSON lines: what `thermobearing bench` parses next to the table
        for r in records:
            print(json.dumps(r))
    print(f"{'sweep':>20} {'method':>24} {'setting':>36} {'time [s]':>9} {'cpu [s]':>8} "
          f"{'kin':>4} {'dT max [K]':>11} {'dP/P max':>9} {'default/x':>9}")
    for r in records:
        print(f"{r['sweep']:>20} {r['method']:>24} {r['setting']:>36} {r['time_s']:9.2f} "
              f"{r['cpu_s']:8.2f} {r['kinematics_solves']:4d} {r['max_error_K']:11.3g} "
              f"{r['error']:9.3g} {r['ratio_vs_anchor']:9.2f}")
    print(l2_note or "L2: available but not run by this script")
    budget = f"{args.budget_K:g} K on temperature, {100 * args.budget_loss:g} % on total loss"
    inside = [r for r in records if r["sweep"] == "ladder"
              and r["max_error_K"] <= args.budget_K and r["error"] <= args.budget_loss]
    if inside:
        best = min(inside, key=lambda r: r["cpu_s"])
        print(f"cheapest level within the budget ({budget}): {best['method']} "
              f"({best['cpu_s']:.2f} s CPU, dT {best['max_error_K']:.3g} K, "
              f"dP/P {100 * best['error']:.2g} %)")
    else:
        print(f"no level at the scene's settings stays within the budget ({budget})")
    settings = [r for r in records if r["sweep"] in ("kinematics_tolerance", "chunk")
                and r["max_error_K"] <= args.budget_K and r["error"] <= args.budget_loss]
    if settings:
        best = min(settings, key=lambda r: r["cpu_s"])
        print(f"cheapest L1 skidding setting within the budget: {best['setting']} "
              f"({best['cpu_s']:.2f} s CPU, dT {best['max_error_K']:.3g} K, "
              f"dP/P {100 * best['error']:.2g} %)")
    print(f"reference: {ref_rec['setting']}, {ref.cpu_s:.2f} s CPU; energy imbalance of the "
          f"default run {default.extra.get('energy_imbalance', math.nan):.1e}")
    _plot(records, Path(args.out), case, args.budget_K, args.budget_loss)
    return records


def roller_ladder(steps: int | None = None, l2: bool = True, sweeps: bool = True,
                  log=None, warm_up: bool = True, l2_sweep: bool = False,
                  film_options: dict | None = None) -> tuple[list[dict], dict]:
    """The roller-bearing ladder (:data:`_protocol.ROLLER_SCENE`): its records and notes.

    ``steps``: only the first ``steps`` load steps; ``l2``: run L2 (skidding + numerical
    thermal EHL) and measure every level against it, else the reference is L1 at the tight
    settings :data:`REFERENCE`; ``sweeps``: the L1 kinematics-tolerance sweep
    :data:`ROLLER_TOLERANCES`. ``log``: a print-like callable for progress (None: quiet);
    ``warm_up``: a 1-step run first, so that no record pays first-call costs;
    ``l2_sweep``: also L2 at the looser tolerances :data:`ROLLER_L2_TOLERANCES` (each with
    its own, new film table), against L2 at the scene's tolerance. ``film_options``: L2's
    ``[models] film_options`` (None: the film model's defaults).
    Returns (records, notes): notes has ``case``, ``reference`` (its method), ``l2_error``
    (the ConvergenceError text if L2 stopped, else ''), ``energy_imbalance`` (of the
    reference run) and ``film_table`` (L2's table work, per bearing).
    """
    from thermobearing.errors import ConvergenceError

    say = log or (lambda *a, **k: None)
    base = roller_scene(steps)
    case = ROLLER_SCENE + (f"_{steps}step" if steps is not None else "")
    say(f"== BM-7 {case}: {len(base.schedule.steps)} load steps, "
        f"{base.schedule.duration / 60:.0f} min")
    if warm_up:
        run_l1("warm-up", with_solver(roller_scene(1), kinematics_tolerance=0.3))

    def show(r, setting: str) -> None:
        say(f"  {r.label:>34} {setting:>40} {r.time_s:8.2f} s ({r.cpu_s:.2f} s CPU), "
            f"{r.kinematics_solves} kinematics solves")

    def l2_scene(scene):
        extra = {"film_options": dict(film_options)} if film_options else {}
        return with_models(scene, film="numerical_tehl", **extra)

    def l2_setting(scene, run) -> str:
        grids = run.extra.get("film grid points", {})
        return _setting(scene) + "".join(f",n={g}" for g in sorted(set(grids.values())))

    ladder = []  # (level, method, run, setting, sweep)
    for model, opts in ROLLER_L0:
        note = "".join(f", {k} {v}" for k, v in opts.items())
        r = run_l0(f"L0 {model}{note}", base, model, **opts)
        show(r, "")
        ladder.append(("L0", r.label[3:], r, _setting(base), "ladder"))
    default = run_l1("L1 skidding + closed-form film", base)
    show(default, _setting(base))
    ladder.append(("L1", "skidding + closed-form film (default)", default, _setting(base),
                   "ladder"))
    l2_error = ""
    ref = None
    if l2:
        try:
            ref = run_l1("L2 skidding + numerical_tehl", l2_scene(base))
            show(ref, l2_setting(base, ref))
            asked = (film_options or {}).get("grid_points")
            grids = ref.extra.get("film grid points", {})
            if asked is not None and any(g != asked for g in grids.values()):
                say(f"  note: film_options grid_points = {asked} did not reach the film "
                    f"model (grid {grids}): L2 ran at that grid")
            ladder.append(("L2", "skidding + numerical_tehl", ref, l2_setting(base, ref),
                           "ladder"))
        except ConvergenceError as err:
            l2_error = str(err)
            say(f"  L2 stopped: {l2_error}")
    if ref is None:
        tight = with_solver(base, **REFERENCE)
        ref = run_l1("L1 skidding (tight settings)", tight)
        show(ref, _setting(tight))
        ladder.append(("L1", "skidding, tight settings (reference)", ref, _setting(tight),
                       "reference"))
    if sweeps:
        for tol in ROLLER_TOLERANCES:
            sc = with_solver(base, kinematics_tolerance=tol)
            r = default if math.isclose(tol, base.solver.kinematics_tolerance) else (
                run_l1("L1 skidding + closed-form film", sc))
            if r is not default:
                show(r, _setting(sc))
            ladder.append(("L1", "skidding + closed-form film", r, _setting(sc),
                           "kinematics_tolerance"))
    if l2_sweep and ref.label.startswith("L2"):
        for tol in ROLLER_L2_TOLERANCES:
            sc = with_solver(base, kinematics_tolerance=tol)
            try:
                r = run_l1("L2 skidding + numerical_tehl", l2_scene(sc))
            except ConvergenceError as err:
                say(f"  L2 at {_setting(sc)} stopped: {err}")
                continue
            show(r, l2_setting(sc, r))
            ladder.append(("L2", "skidding + numerical_tehl", r, l2_setting(sc, r),
                           "l2_kinematics_tolerance"))
    records = []
    for level, method, run, setting, sweep in ladder:
        dT, dP = errors(run, ref)
        diff = np.abs(run.temperatures - ref.temperatures)
        step, node = np.unravel_index(int(np.argmax(diff)), diff.shape)
        table = [v for k, v in run.extra.items() if k.endswith(": film table")]
        records.append({
            "benchmark": "BM-7", "case": case, "method": f"{level} {method}", "level": level,
            "setting": setting, "sweep": sweep, "reference": ref.label,
            "time_s": run.time_s, "cpu_s": run.cpu_s, "max_error_K": dT, "error": dP,
            "worst": f"{run.nodes[node]}, step {step + 1}" if dT > 0.0 else "",
            "kinematics_solves": run.kinematics_solves,
            "film_table_solves": sum(t["solves"] for t in table),
            "film_table_cpu_s": sum(t["solve_cpu_s"] for t in table),
            "ratio_vs_anchor": default.cpu_s / run.cpu_s})
    notes = {"case": case, "reference": ref.label, "l2_error": l2_error,
             "energy_imbalance": ref.extra.get("energy_imbalance", math.nan),
             "film_table": {k: v for k, v in ref.extra.items() if k.endswith(": film table")},
             "film_grid_points": ref.extra.get("film grid points", {}),
             "temperatures": ref.temperatures, "nodes": ref.nodes, "losses": ref.losses}
    return records, notes


def roller_main(args: argparse.Namespace) -> list[dict]:
    """The roller ladder from the command line: runs, prints the table, plots."""
    records, notes = roller_ladder(ROLLER_QUICK_STEPS if args.quick else None,
                                   l2=not args.no_l2, sweeps=not args.no_sweeps,
                                   l2_sweep=args.l2_sweep,
                                   film_options=ROLLER_QUICK_FILM_OPTIONS if args.quick
                                   else None,
                                   log=lambda *a: print(*a, file=sys.stderr))
    case = notes["case"]
    if args.json:
        for r in records:
            print(json.dumps(r))
    print(f"{'sweep':>20} {'method':>44} {'setting':>36} {'time [s]':>9} {'cpu [s]':>8} "
          f"{'kin':>4} {'EHL':>4} {'dT max [K]':>11} {'dP/P max':>9} {'default/x':>9}  "
          "dT max at")
    for r in records:
        print(f"{r['sweep']:>20} {r['method']:>44} {r['setting']:>36} {r['time_s']:9.2f} "
              f"{r['cpu_s']:8.2f} {r['kinematics_solves']:4d} {r['film_table_solves']:4d} "
              f"{r['max_error_K']:11.3g} {r['error']:9.3g} {r['ratio_vs_anchor']:9.2f}  "
              f"{r['worst']}")
    if notes["l2_error"]:
        print(f"L2 did not finish: {notes['l2_error']}")
    elif args.no_l2:
        print("L2 not run (--no-l2)")
    grids = notes["film_grid_points"]
    for k, v in notes["film_table"].items():
        grid = grids.get(k.removesuffix(": film table"))
        print(f"L2 {k}: {v['solves']} thermal-EHL node solves ({v['solve_cpu_s']:.1f} s CPU), "
              f"{v['queries']} table queries" + (f", grid n = {grid}" if grid else ""))
    T = notes["temperatures"] - 273.15
    print(f"reference {notes['reference']}: step-end temperatures [degC] "
          + "; ".join(f"{n} " + "/".join(f"{x:.1f}" for x in T[:, j])
                      for j, n in enumerate(notes["nodes"]))
          + "; total loss [W] " + "/".join(f"{x:.0f}" for x in notes["losses"].sum(axis=1))
          + f"; energy imbalance {notes['energy_imbalance']:.1e}")
    budget = f"{args.budget_K:g} K on temperature, {100 * args.budget_loss:g} % on total loss"
    inside = [r for r in records if r["sweep"] in ("ladder", "reference")
              and r["max_error_K"] <= args.budget_K and r["error"] <= args.budget_loss]
    best = min(inside, key=lambda r: r["cpu_s"])
    print(f"roller problem: cheapest level within the budget ({budget}) against "
          f"{notes['reference']}: {best['method']} ({best['cpu_s']:.2f} s CPU, "
          f"dT {best['max_error_K']:.3g} K, dP/P {100 * best['error']:.2g} %)")
    _plot(records, Path(args.out), case, args.budget_K, args.budget_loss,
          reference=notes["reference"], name="bm7_fidelity_ladder_roller.png")
    return records


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="ball: 4 load steps instead of 22; roller: its first step only")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--out", default="benchmarks/out")
    ap.add_argument("--budget-K", type=float, default=1.0, help="temperature budget [K]")
    ap.add_argument("--budget-loss", type=float, default=0.05,
                    help="relative total-loss budget [-]")
    ap.add_argument("--no-sweeps", action="store_true", help="ladder only")
    ap.add_argument("--repeat", type=int, default=3,
                    help="ball problem: runs per setting, the least CPU time kept")
    ap.add_argument("--stride", type=int, default=None,
                    help="ball: keep every N-th load step (overrides --quick; for checks)")
    ap.add_argument("--problem", choices=("ball", "roller", "all"), default="all",
                    help="which ladder problem(s) to run")
    ap.add_argument("--l2-sweep", action="store_true",
                    help="roller: also L2 at kinematics_tolerance 0.3 and 0.1 (minutes each)")
    ap.add_argument("--no-l2", action="store_true",
                    help="roller: skip L2 (minutes of CPU); reference then L1 at tight "
                         "settings")
    args = ap.parse_args(argv)
    if args.problem in ("ball", "all"):
        ball_ladder(args)
    if args.problem in ("roller", "all"):
        roller_main(args)
    return 0


def _plot(records, out: Path, case: str, budget_K: float, budget_loss: float,
          reference: str = "L1 skidding at tight settings",
          name: str = "bm7_fidelity_ladder.png") -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    floor = 1e-4
    for ax, key, label, budget in ((axes[0], "max_error_K", "max temperature error [K]",
                                    budget_K),
                                   (axes[1], "error", "max relative total-loss error [-]",
                                    budget_loss)):
        for r in records:
            if r["sweep"] in ("ladder", "reference"):
                ax.loglog(max(r[key], floor), r["cpu_s"], "o", ms=8, label=r["method"])
        for sweep, marker in (("kinematics_tolerance", "s-"), ("chunk", "^-"),
                              ("l2_kinematics_tolerance", "d-")):
            pts = [r for r in records if r["sweep"] == sweep]
            if pts:
                ax.loglog([max(r[key], floor) for r in pts], [r["cpu_s"] for r in pts],
                          marker, alpha=0.7,
                          label=f"{pts[0]['method'].split(' (')[0]}, {sweep} sweep")
                for r in pts:
                    tag = r["setting"].split(",")[1 if sweep == "chunk" else 0]
                    ax.annotate(tag.split("=")[1], (max(r[key], floor), r["cpu_s"]),
                                fontsize=6)
        ax.axvline(budget, color="k", ls=":", lw=1)
        ax.set_xlabel(label + f" (floor {floor:g})")
        ax.set_ylabel("CPU time [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"BM-7 fidelity ladder, {case}: errors vs {reference}")
    fig.tight_layout()
    path = out / name
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print(f"plot: {path}", file=sys.stderr)


if __name__ == "__main__":
    sys.exit(main())
