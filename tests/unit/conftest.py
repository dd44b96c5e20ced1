"""Fixtures shared by the unit tests: the paper 000 NU214 bearing and its oil, and the
scene fuzzer's generator (``scripts/fuzz_scenes.py``) and the BM-7 benchmark script as
modules."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant


@pytest.fixture(scope="session")
def nu214():
    """NU214 preset (paper 000 Table 1)."""
    return load_bearing("NU214")


@pytest.fixture(scope="session")
def oil():
    """PAPER000_OIL preset (paper 000 Table 1)."""
    return load_lubricant("PAPER000_OIL")


@pytest.fixture(scope="session")
def fuzz():
    """``scripts/fuzz_scenes.py`` loaded as the module ``fuzz_scenes`` (registered before it
    runs: its dataclasses look their module up)."""
    path = Path(__file__).resolve().parents[2] / "scripts" / "fuzz_scenes.py"
    spec = importlib.util.spec_from_file_location("fuzz_scenes", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("fuzz_scenes", module)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def bm7():
    """``benchmarks/bm7_fidelity_ladder.py`` loaded as a module; ``benchmarks/`` goes on
    ``sys.path`` first (the script, and tests, import its sibling ``_protocol``)."""
    bench = Path(__file__).resolve().parents[2] / "benchmarks"
    if str(bench) not in sys.path:
        sys.path.insert(0, str(bench))
    spec = importlib.util.spec_from_file_location("bm7_fidelity_ladder",
                                                  bench / "bm7_fidelity_ladder.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="session")
def crb_rib_run():
    """The rib heat source's coupled roller dynamics of paper 003's base case without
    unbalance (CRB_50x75x16, MIL_PRF_23699, 3 kN radial, ``roller_dynamics_heat.run_dynamics``
    with its default settings and a cold start), one run per (inner-ring speed [rad/s],
    temperature [K]) for the whole session: several test files check the same run (the
    375 K node at 20000 r/min, the 400 K node at 30000 r/min; ~1-2 s each). Returns
    ``run(speed, temperature) -> (RibDynamicsHeat, response)``; the results are read-only."""
    from thermobearing.skidding import roller_dynamics_heat as rdh

    bearing, lubricant = load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699")
    runs: dict[tuple[float, float], tuple] = {}

    def run(speed: float, temperature: float):
        key = (float(speed), float(temperature))
        if key not in runs:
            runs[key] = rdh.run_dynamics(bearing, lubricant, speed, 3000.0, temperature)
        return runs[key]

    return run
