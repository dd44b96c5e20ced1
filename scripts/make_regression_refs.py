"""Write the stored outputs of the regression scenes (tests/regression).

Each scene in ``tests/regression/scenes/*.toml`` is run with ``Simulation(scene).run()`` and
every table of its results is written to ``tests/regression/reference/<scene>/<table>.csv``.
``tests/regression/test_regression.py`` re-runs the scenes and compares (a missing reference
fails there; the test never writes one). Run this only when a change of the results is
intended, and say in the commit what changed and why:

    python scripts/make_regression_refs.py [SCENE ...]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "tests" / "regression" / "scenes"
REFERENCE = ROOT / "tests" / "regression" / "reference"


def main(argv: list[str] | None = None) -> int:
    from thermobearing.scene import load_scene
    from thermobearing.simulation import Simulation

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scenes", nargs="*", help="scene names (default: all)")
    args = ap.parse_args(argv)
    paths = sorted(SCENES.glob("*.toml"))
    if args.scenes:
        paths = [p for p in paths if p.stem in args.scenes]
    for path in paths:
        res = Simulation(load_scene(path), progress=False).run()
        out = REFERENCE / path.stem
        out.mkdir(parents=True, exist_ok=True)
        for old in out.glob("*.csv"):
            old.unlink()
        for name, table in sorted(res.tables.items()):
            table.to_csv(out / f"{name}.csv", index=False, float_format="%.17g")
        print(f"{path.stem}: {', '.join(sorted(res.tables))} -> {out.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
