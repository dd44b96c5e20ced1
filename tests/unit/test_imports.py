"""Split modules import on their own in a fresh interpreter (an import cycle shows only
when the cycle's later module is imported first), and the facades keep their public names."""

from __future__ import annotations

import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import pytest

FIRST_IMPORTS = (
    "thermobearing.geometry_ball",
    "thermobearing.geometry_roller",
    "thermobearing.skidding.roller_dynamics_coupled",
    "thermobearing.skidding.roller_dynamics_coupled_kernels",
    "thermobearing.skidding.roller_dynamics_etd",
    "thermobearing.skidding.ball_jacobian_traction",
    "thermobearing.skidding.roller_pocket_film",
    "thermobearing.skidding.roller_fluid_coefficients",
    "thermobearing.rolling_resistance",
    "thermobearing.skidding.roller_dynamics_integrate",
    "thermobearing.skidding.roller_dynamics_map",
    "thermobearing.skidding.ball_newton_kernels",
    "thermobearing.network.stepper_core",
    "thermobearing.loads_arcs",
    "thermobearing.loads_kernels",
    "thermobearing.vibration_params",
    "thermobearing.vibration_kernels",
    "thermobearing.vibration_results",
    "thermobearing.calibrate_params",
    "thermobearing.calibrate_model",
    "thermobearing.calibrate_result",
    "thermobearing.calibrate_synthetic",
    "thermobearing.skidding.ball_seat",
    "thermobearing.skidding.ball_coulomb",
    "thermobearing.skidding.ball_damped_step",
    "thermobearing.signal_uncertainty",
    "thermobearing.signal_checks",
)


def _import_alone(module: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", f"import {module}"], capture_output=True,
                          text=True, timeout=300)


@pytest.fixture(scope="module")
def fresh_imports() -> dict[str, subprocess.CompletedProcess]:
    """Each module imported first, each in its own fresh interpreter; the interpreters run
    side by side (one per core: ~0.5-1 s each, mostly interpreter and numba start-up)."""
    with ThreadPoolExecutor(max_workers=max(2, os.cpu_count() or 1)) as pool:
        return dict(zip(FIRST_IMPORTS, pool.map(_import_alone, FIRST_IMPORTS), strict=True))


@pytest.mark.parametrize("module", FIRST_IMPORTS)
def test_module_imports_first_in_a_fresh_interpreter(module, fresh_imports):
    out = fresh_imports[module]
    assert out.returncode == 0, out.stderr[-2000:]


def test_facades_re_export_their_public_names():
    from thermobearing import geometry
    from thermobearing.skidding import roller_dynamics

    for mod in (geometry, roller_dynamics):
        missing = [n for n in mod.__all__ if not hasattr(mod, n)]
        assert not missing, (mod.__name__, missing)
    assert geometry.BallBearing.__module__ == "thermobearing.geometry_ball"
    assert geometry.load_bearing("NU214").__class__ is geometry.RollerBearing
