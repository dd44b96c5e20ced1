"""bm8: the vibration model's integrators against RK4, and the cage-speed analyser's speed.

Part 1 (integrators). Paper 004's SKF 6304 at 2000 r/min, 2000 N, cage slip 5 %, in two
traction regimes: "mild" (mu_m = 0.01, dv_m = 0.1 m/s; spin relaxation ~2e5 1/s) and "steep"
(mu_m = 0.05, dv_m = 0.01 m/s; ~1e7 1/s). Every run integrates 0.03 s of settling and records
0.02 s of the inner-ring x acceleration at 100 kHz. The reference is RK4 at 6.25e-8 s; the error
is max|a - a_ref| / max|a_ref| over the record. Methods: RK4 at the paper's 1e-5 s and at
smaller steps; the Strang split with the exact spin flow (``split``). Cost is CPU time per
simulated second (compiled kernels, warmed up). The equal-accuracy rows take, for error
targets 1e-3 and 1e-4, the cheapest run of each method within the target: their
``ratio_vs_anchor`` is RK4's cost / split's (> 1: split is cheaper, the convention of every
benchmark's ratio) and ``cost_ratio_split_over_rk4`` its inverse. A step-size row's
``ratio_vs_anchor`` is RK4 at 1e-5 s's cost / the row's where RK4 at 1e-5 s converged, else
None (it diverges in both regimes: a ratio against a diverged run compares nothing).

Part 2 (analyser). ``signal.estimate_cage_speed`` on 1 s of a 25.6 kHz record (simulated
6304 signal plus 0 dB noise) against the anchor: one Butterworth band-pass (sosfiltfilt) +
scipy Hilbert envelope + FFT (the textbook envelope spectrum, no band search, no comb), whose
cage speed is read as the textbook does (:func:`anchor_csr`): the highest line of the
envelope spectrum in the ball-pass window (the same slip range as ours' search, -30 % to
+70 %) divided by Z, to the FFT bin. Both errors are |CSR / CSR_true - 1| against the
simulated cage speed; ``ratio_vs_anchor`` = anchor CPU / ours (< 1: ours costs more).
"""

from __future__ import annotations

import argparse
import json
import math
import statistics as stats_mod
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from thermobearing import signal as S  # noqa: E402
from thermobearing import vibration as V  # noqa: E402
from thermobearing.errors import ConvergenceError  # noqa: E402
from thermobearing.traction import make_traction_law  # noqa: E402

WS = 2000.0 * 2 * math.pi / 60.0
LOAD = 2000.0
SLIP = 0.05
REGIMES = {"mild": (0.01, 0.1), "steep": (0.05, 0.01)}


def _run(params, law, method, step, settle, duration):
    t0 = time.process_time()  # CPU time: the machine may be shared; the kernels are serial
    try:
        r = V.simulate(params, WS, LOAD, traction=law, cage_slip=SLIP, duration=duration,
                       settle_time=settle, sampling_rate=1e5, method=method, max_step=step)
        acc = r.acceleration_x
    except ConvergenceError:
        acc = None
    cpu = time.process_time() - t0
    return acc, cpu / (settle + duration)


def integrators(quick: bool) -> list[dict]:
    params = V.paper004_parameters()
    settle, duration = (0.01, 0.01) if quick else (0.03, 0.02)
    rk4_steps = [1e-5, 5e-6, 2.5e-6, 1.25e-6, 6.25e-7] + ([] if quick else [3.125e-7])
    split_steps = [5e-6, 2.5e-6] + ([] if quick else [1.25e-6])
    records = []
    for regime, (mu, dvm) in REGIMES.items():
        law = make_traction_law("linear_saturating", mu_max=mu, slip_speed_max=dvm)
        _run(params, law, "split", 5e-6, 0.001, 0.001)  # warm up both kernels
        _run(params, law, "rk4", 5e-6, 0.001, 0.001)
        ref, _ = _run(params, law, "rk4", 6.25e-8, settle, duration)
        scale = float(np.max(np.abs(ref)))
        anchor = None
        for method, steps in (("rk4", rk4_steps), ("split", split_steps)):
            for h in steps:
                acc, cost = _run(params, law, method, h, settle, duration)
                err = math.inf if acc is None else float(np.max(np.abs(acc - ref)) / scale)
                if method == "rk4" and h == 1e-5:
                    anchor = cost if acc is not None else None  # a diverged run: no anchor
                records.append(dict(benchmark="bm8_vibration", case=f"integrator_{regime}",
                                    method=method, setting=f"h={h:.4g} s", step=h,
                                    time_s=cost, error=err,
                                    ratio_vs_anchor=anchor / cost if anchor else None,
                                    note="diverged" if acc is None else ""))
    return records


def equal_accuracy(records: list[dict], targets=(1e-3, 1e-4)) -> list[dict]:
    """Cheapest run of each method whose error is within a target; ``ratio_vs_anchor``
    RK4's cost / split's (> 1: split is cheaper), ``cost_ratio_split_over_rk4`` its
    inverse (NaN where a method has no run within the target)."""
    out = []
    for regime in REGIMES:
        rows = [r for r in records if r["case"] == f"integrator_{regime}"]
        for target in targets:
            best = {}
            for method in ("rk4", "split"):
                ok = [r for r in rows if r["method"] == method and r["error"] <= target]
                best[method] = min(ok, key=lambda r: r["time_s"]) if ok else None
            b_s, b_r = best["split"], best["rk4"]
            note = "; ".join(f"{m}: {'none within target' if b is None else b['setting']}"
                             for m, b in best.items())
            both = b_s is not None and b_r is not None
            out.append(dict(benchmark="bm8_vibration", case=f"equal_accuracy_{regime}",
                            method="split vs rk4", setting=f"error <= {target:g}",
                            time_s=b_s["time_s"] if b_s else math.nan,
                            error=b_s["error"] if b_s else math.nan,
                            rk4_error=b_r["error"] if b_r else math.nan,
                            ratio_vs_anchor=(b_r["time_s"] / b_s["time_s"] if both
                                             else math.nan),
                            cost_ratio_split_over_rk4=(b_s["time_s"] / b_r["time_s"] if both
                                                       else math.nan),
                            rk4_time_s=b_r["time_s"] if b_r else math.nan, note=note))
    return out


def anchor_csr(spectrum: np.ndarray, n: int, fs: float, shaft_hz: float, n_balls: int,
               csr_theoretical: float, search: tuple[float, float] = (0.3, 1.3)
               ) -> float:
    """The textbook cage speed ratio from an envelope spectrum (``|rfft|`` of an ``n``-sample
    envelope at ``fs`` [Hz]): the frequency of its highest line in the ball-pass window
    ``search * Z * csr_theoretical * shaft_hz`` [Hz], over Z and the shaft frequency [-]
    (to the FFT bin, fs / n; NaN where the window holds no bin)."""
    f = np.fft.rfftfreq(n, 1.0 / fs)
    lo, hi = (k * n_balls * csr_theoretical * shaft_hz for k in search)
    idx = np.flatnonzero((f >= lo) & (f <= hi))
    if idx.size == 0:
        return math.nan
    peak = idx[int(np.argmax(spectrum[idx]))]
    return float(f[peak] / (n_balls * shaft_hz))


def analyser(quick: bool) -> list[dict]:
    from scipy import signal as sps

    params = V.paper004_parameters()
    law = make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)
    fs = 25600.0
    r = V.simulate(params, WS, LOAD, traction=law, cage_slip=0.1, duration=1.0,
                   settle_time=0.03, sampling_rate=fs)
    a = r.acceleration_x - r.acceleration_x.mean()
    x = a + np.random.default_rng(8).normal(scale=math.sqrt(float(np.mean(a * a))),
                                            size=a.size)
    csr_th = params.theoretical_cage_speed_ratio

    def ours():
        return S.estimate_cage_speed(x, fs, WS / (2 * math.pi), 7, csr_th)

    def anchor():
        sos = sps.butter(4, (800.0, 2400.0), btype="bandpass", fs=fs, output="sos")
        env = np.abs(sps.hilbert(sps.sosfiltfilt(sos, x))) ** 2
        return np.abs(np.fft.rfft((env - env.mean()) * np.hanning(env.size)))

    reps = 3 if quick else 7
    def anchor_estimate():
        return anchor_csr(anchor(), x.size, fs, WS / (2 * math.pi), 7, csr_th)

    est = ours()
    csr_anchor = anchor_estimate()
    t_ours = stats_mod.median(_timed(ours) for _ in range(reps))
    t_anchor = stats_mod.median(_timed(anchor_estimate) for _ in range(reps))
    w_ours = stats_mod.median(_timed(ours, wall=True) for _ in range(reps))
    csr_true = r.cage_speed / WS
    err = abs(est.csr / csr_true - 1) if est.detected else math.inf
    err_anchor = abs(csr_anchor / csr_true - 1) if math.isfinite(csr_anchor) else math.inf
    return [dict(benchmark="bm8_vibration", case="analyser_1s_25.6kHz", method="anchor",
                 setting="butter+hilbert+fft, one band, ball-pass peak / Z",
                 time_s=t_anchor, error=err_anchor, ratio_vs_anchor=1.0,
                 note="error = |CSR/CSR_true - 1| at 0 dB (to the 1-Hz bin)"),
            dict(benchmark="bm8_vibration", case="analyser_1s_25.6kHz",
                 method="estimate_cage_speed", setting="3 kurtogram bands, comb, sub-bin",
                 time_s=t_ours, error=err, ratio_vs_anchor=t_anchor / t_ours,
                 note=f"wall {w_ours:.3g} s; error = |CSR/CSR_true - 1| at 0 dB")]


def _timed(fn, wall: bool = False) -> float:
    clock = time.perf_counter if wall else time.process_time
    t0 = clock()
    fn()
    return clock() - t0


def _plot(records: list[dict], out: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    for ax, regime in zip(axes, REGIMES, strict=True):
        for method, mk in (("rk4", "o-"), ("split", "s-")):
            rows = [r for r in records if r["case"] == f"integrator_{regime}"
                    and r["method"] == method and math.isfinite(r["error"])]
            if rows:
                ax.loglog([r["time_s"] for r in rows], [r["error"] for r in rows], mk,
                          label=method)
                for r in rows:
                    ax.annotate(f"{r['step']:.2g}", (r["time_s"], r["error"]), fontsize=7)
        ax.set_xlabel("CPU time per simulated second [s]")
        ax.set_ylabel("max error / max |a_ref|")
        ax.set_title(f"{regime} traction (labels: step [s])")
        ax.legend()
    out.mkdir(parents=True, exist_ok=True)
    path = out / "bm8_vibration.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="short run")
    parser.add_argument("--json", action="store_true", help="print JSON records")
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "out"), help="plot folder")
    args = parser.parse_args(argv)
    records = integrators(args.quick)
    records += equal_accuracy(records)
    records += analyser(args.quick)
    path = _plot(records, Path(args.out))
    if args.json:
        print(json.dumps(records, indent=1, default=lambda v: None))
        return 0
    print(f"{'case':<24} {'method':<20} {'setting':<32} {'time_s':>10} {'error':>10} "
          f"{'ratio':>8}  note")
    for r in records:
        ratio = r["ratio_vs_anchor"]
        ratio = "-" if ratio is None else f"{ratio:.3g}"
        print(f"{r['case']:<24} {r['method']:<20} {r['setting']:<32} {r['time_s']:>10.4g} "
              f"{r['error']:>10.3g} {ratio:>8}  {r.get('note', '')}")
    print("time_s: integrators = CPU s per simulated s; analyser = CPU s per 1 s record. "
          "ratio = anchor cost / this row's (> 1: cheaper than the anchor): integrators vs "
          "RK4 at 1e-5 s (the paper's; '-' where it diverged), equal_accuracy = RK4 / split "
          "at the cheapest run of each within the target (error: split's), analyser = the "
          "one-band Hilbert anchor / ours.")
    print(f"plot: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
