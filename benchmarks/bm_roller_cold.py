"""Cold starts of the roller skidding solver: which path converges, CPU per point, failures.

:func:`thermobearing.skidding.solve` on the roller presets (NU214 with the paper 000 oil,
D1842926 with OIL_4109) and a catalogue NU 206 (``estimate_missing``, ISO VG 68) over a grid
of inner-ring speeds (500-30000 r/min), radial loads (100 N to the heaviest load of each
bearing's list, about 0.3 C) and oil temperatures (20-140 degC), each point solved cold (no
warm start). Per point: the path that converged (``extras["method"]``: Newton or the
bracketed fallback; ``extras["start"]``: the start whose Newton converged), the process CPU
time and, for a failure, the ConvergenceError's residual. Printed: counts per path, CPU per
path (median, max, total) and the share of the total CPU the bracketed fallback takes.

The load lists: NU214 100 kN is about 0.7 C (tests/unit/test_property_skidding.py), so
45 kN is about 0.3 C; D1842926 (30 rollers of 12 mm on a 155 mm pitch) takes the same list;
the NU 206 (13 rollers of 7.5 mm) a list ending at 13 kN (about 0.3 of the catalogue C of
its size, 44 kN).

Usage: python benchmarks/bm_roller_cold.py [--quick] [--bearing NAME] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import time
import warnings
from collections import Counter, defaultdict

RPM = math.pi / 30.0
SPEEDS = (500.0, 2000.0, 8000.0, 30000.0)
TEMPERATURES = (20.0, 60.0, 140.0)
LOADS = {"NU214": (100.0, 1000.0, 5000.0, 20000.0, 45000.0),
         "D1842926": (100.0, 1000.0, 5000.0, 20000.0, 45000.0),
         "NU206": (100.0, 500.0, 2000.0, 6000.0, 13000.0)}


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


def solve_point(bearing, oil, rpm, load, t_c):
    """One cold solve; a dict with the path, CPU time [s] and the result or the error."""
    from thermobearing.errors import ConvergenceError, ValidityWarning
    from thermobearing.skidding import solve
    from thermobearing.state import OilSupply

    t = t_c + 273.15
    t0 = time.process_time()
    row = {"rpm": rpm, "load": load, "t_c": t_c}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            r = solve(bearing, oil, rpm * RPM, load, 0.0, t,
                      supply=OilSupply("jet", 33 / 60000, t))
        row.update(path=f"{r.extras['method']}:{r.extras.get('start', '?')}",
                   csr=r.cage_speed_ratio, slip=r.slip, norm=r.residual_norm,
                   attempts=r.extras.get("attempts"))
    except ConvergenceError as err:
        row.update(path="failed", norm=err.residual)
    row["cpu"] = time.process_time() - t0
    return row


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="2 speeds x 3 loads x 2 temperatures")
    ap.add_argument("--bearing", action="append", help="NU214, D1842926, NU206 (repeatable)")
    ap.add_argument("--json", help="write the rows to this file")
    args = ap.parse_args()
    bearings = _bearings()
    names = args.bearing or list(bearings)
    rows = []
    for name in names:
        bearing, oil = bearings[name]
        speeds = SPEEDS[1::2] if args.quick else SPEEDS
        loads = LOADS[name][::2] if args.quick else LOADS[name]
        temps = TEMPERATURES[::2] if args.quick else TEMPERATURES
        solve_point(bearing, oil, 1000.0, 1000.0, 40.0)  # imports and caches out of the times
        for rpm in speeds:
            for load in loads:
                for t_c in temps:
                    row = solve_point(bearing, oil, rpm, load, t_c)
                    row["bearing"] = name
                    rows.append(row)
                    print(f"{name:9s} {rpm:7.0f} r/min {load:8.0f} N {t_c:5.0f} degC  "
                          f"{row['path']:26s} cpu {row['cpu']:6.2f} s  "
                          f"norm {row['norm']:.2e}", flush=True)
    counts = Counter(r["path"] for r in rows)
    cpu = defaultdict(list)
    for r in rows:
        cpu[r["path"]].append(r["cpu"])
    total = sum(r["cpu"] for r in rows)
    print(f"\n{len(rows)} cold points, {total:.1f} s CPU in all")
    print(f"{'path':28s} {'points':>6s} {'median s':>9s} {'max s':>8s} {'total s':>8s} "
          f"{'share':>6s}")
    for path, n in counts.most_common():
        ts = cpu[path]
        print(f"{path:28s} {n:6d} {statistics.median(ts):9.3f} {max(ts):8.2f} {sum(ts):8.1f} "
              f"{sum(ts) / total:6.1%}")
    brk = [r for r in rows if r["path"].startswith("bracketed")]
    print(f"bracketed: {len(brk)} of {len(rows)} points, "
          f"{sum(r['cpu'] for r in brk) / max(total, 1e-12):.1%} of the CPU")
    for r in rows:
        if r["path"] == "failed":
            print(f"failed: {r['bearing']} {r['rpm']:g} r/min {r['load']:g} N {r['t_c']:g} degC "
                  f"residual {r['norm']:.3g}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(rows, fh, indent=1)


if __name__ == "__main__":
    main()
