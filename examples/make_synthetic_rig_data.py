"""Make the SYNTHETIC thermocouple file ``examples/synthetic_rig_temperatures.csv``.

The numbers are thermobearing model output plus seeded Gaussian noise, NOT measurements
(in particular not the data of seed paper 002). They exist to exercise the measured-data
import, the measured-vs-predicted overlay of the report and ``thermobearing calibrate``
with parameters whose true values are known.

Recipe: the scene ``configs/scenes/qj1044_synthetic_measured.toml`` (two QJ1044 bearings,
race-control kinematics, 4 steps of 15 min at 1800 r/min, 0-42 kN axial, 15 L/min jet) is
run with the KNOWN values below in place of the scene's nominal ones, with a finer
coupling interval (60 s) than the scene's own (300 s); the housing temperature of each
bearing (where paper 002 put its thermocouples, on top of the outer ring) is sampled
every minute and N(0, 0.1 K) noise with seed 2022 is added; values are rounded to 0.01 K.
Every row carries a ``data_origin`` column saying so.

Usage: ``python examples/make_synthetic_rig_data.py [--out PATH]``
"""

from __future__ import annotations

import argparse
from pathlib import Path

from thermobearing.calibrate import synthetic_measurements
from thermobearing.scene import load_scene

HERE = Path(__file__).resolve().parent
SCENE = HERE.parent / "configs" / "scenes" / "qj1044_synthetic_measured.toml"

#: the known ("true") parameter values the synthetic data are generated with
TRUE_VALUES = {
    "network.parameters.h_oil": "400 W/(m**2*K)",
    "network.parameters.h_air": "15 W/(m**2*K)",
}
#: generation settings that differ from the scene (a finer model than the one fitted)
GENERATION = {"solver.chunk": "60 s"}
SENSORS = {"TC_DE_synthetic": "drive_end.housing", "TC_NDE_synthetic": "non_drive_end.housing"}
NOISE_SD = 0.1  # K
SEED = 2022
EVERY = 60.0  # s, one reading a minute as on the rig of paper 002 (its sec. 3)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(HERE / "synthetic_rig_temperatures.csv"))
    args = ap.parse_args(argv)
    scene = load_scene(SCENE)
    df = synthetic_measurements(scene, SENSORS, values={**TRUE_VALUES, **GENERATION},
                                noise_sd=NOISE_SD, seed=SEED, every=EVERY)
    out = Path(args.out)
    df.to_csv(out, index=False)
    print(f"wrote {len(df)} rows of SYNTHETIC data to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
