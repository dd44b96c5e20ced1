"""Write a SYNTHETIC accelerometer record (not a measurement) to try ``thermobearing cage-speed``.

The record is the output of thermobearing's own lumped vibration model (seed paper 004,
:func:`thermobearing.vibration.simulate`) for an SKF 6304 with one ball 2 um oversize (it
puts the cage frequency into the signal), 2000 N radial load, a cage slip you choose,
recorded as a data-acquisition system with an anti-aliasing filter would
(``anti_alias=True``), plus seeded white noise at a signal-to-noise ratio you choose. It is
written as a DAQ would export it: a time column and the channel, a header and a units row,
comma- or semicolon-separated (decimal commas with ``--sep ';'``).

Because the true cage speed is known, the file checks the analyser end to end::

    python examples/make_synthetic_vibration.py --slip 0.08 --out skf6304_synthetic.csv
    thermobearing cage-speed skf6304_synthetic.csv --rpm 1800 --bearing SKF6304
    # prints CSR 0.3383 (= (1 - 0.08) x 0.3677) and slip +8.00 %, and a note that nothing
    # in the record confirms the shaft frequency (the model's rings are round and balanced:
    # no shaft line), so the CSR rests on --rpm

Nothing here is data of paper 004's (or any) test rig.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--slip", type=float, default=0.08, help="cage slip s_c [-] (default 0.08)")
    ap.add_argument("--rpm", type=float, default=1800.0, help="shaft speed [r/min]")
    ap.add_argument("--load", type=float, default=2000.0, help="radial load [N]")
    ap.add_argument("--duration", type=float, default=4.0, help="record length [s]")
    ap.add_argument("--fs", type=float, default=25600.0, help="sampling rate [Hz]")
    ap.add_argument("--snr", type=float, default=0.0, help="signal-to-noise ratio [dB]")
    ap.add_argument("--sep", default=",", choices=(",", ";"), help="column separator")
    ap.add_argument("--seed", type=int, default=2022)
    ap.add_argument("--out", default="skf6304_synthetic.csv")
    args = ap.parse_args(argv)

    from thermobearing import vibration as V
    from thermobearing.traction import make_traction_law

    params = V.paper004_parameters(ball_diameter_deviation=(2e-6,) + (0.0,) * 6)
    law = make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)  # paper 004
    ws = args.rpm * math.pi / 30.0
    r = V.simulate(params, ws, args.load, traction=law, cage_slip=args.slip,
                   duration=args.duration, sampling_rate=args.fs, anti_alias=True)
    x = r.acceleration_x
    rng = np.random.default_rng(args.seed)
    x = x + rng.normal(scale=math.sqrt(np.mean(x * x) / 10 ** (args.snr / 10)), size=x.size)
    t = np.arange(x.size) / args.fs
    dec = "," if args.sep == ";" else "."
    lines = [f"# SYNTHETIC: thermobearing vibration model (paper 004), SKF6304, {args.rpm:g} "
             f"r/min, {args.load:g} N, cage slip {args.slip:g}, CSR "
             f"{r.cage_speed / ws:.6f}, noise at {args.snr:g} dB, seed {args.seed}",
             args.sep.join(["time", "accel_x_synthetic"]), args.sep.join(["s", "m/s^2"])]
    lines += [args.sep.join([f"{a:.7f}", f"{b:.6f}"]).replace(".", dec) for a, b in zip(
        t, x, strict=True)]
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print(f"{args.out}: {x.size} samples at {args.fs:g} Hz, true CSR {r.cage_speed / ws:.4f} "
          f"(pure rolling {params.theoretical_cage_speed_ratio:.4f}, slip {args.slip:+.2%})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
