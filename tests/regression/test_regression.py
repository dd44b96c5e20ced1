"""Regression against stored outputs: every scene in ``scenes/`` is run and each table of
its results is compared with ``reference/<scene>/<table>.csv``.

The references are written only by ``scripts/make_regression_refs.py`` (run it when a change
of the results is intended, and say why in the commit); a missing reference fails here. The
scenes cover the chains a user runs: the default rig's coupled transient on the skidding
solver (shortened), race control in steady mode, the roller skidding solver of paper 000,
the rib-friction source of paper 003 on its reduced dynamics, and a film-only scene.

Tolerances are far below any physical change and above platform round-off amplified by the
iterative solvers (their tolerances 1e-10 relative, the stepper's 1e-7 / 1e-5 K):
temperatures 1e-4 K, every other number 1e-6 relative to its column's magnitude (an energy
imbalance, round-off, to the table's energies); solver diagnostics (residual norms,
iteration counts) are not compared; text columns must match. Perturbing the scenes'
temperatures by 1e-9 and 1e-7 K changes nothing beyond these tolerances.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.scene import load_scene
from thermobearing.simulation import Simulation

HERE = Path(__file__).parent
SCENES = sorted((HERE / "scenes").glob("*.toml"))
REFERENCE = HERE / "reference"

#: columns that are solver diagnostics, not results
SKIP = ("residual", "iterations")
TEMPERATURE_ATOL = 1e-4  # K
RTOL = 1e-6


def _tolerance(column: str, ref: np.ndarray, table_scale: float) -> float:
    """Absolute tolerance of one numeric column. An energy imbalance is round-off of the
    table's energies (the audit's own tests bound it): compared on their scale."""
    if column.endswith("[degC]") or column.endswith("[K]"):
        return TEMPERATURE_ATOL
    if "imbalance" in column:
        return RTOL * table_scale
    finite = np.abs(ref[np.isfinite(ref)])  # empty cells (NaN) have no magnitude
    return RTOL * max(float(np.max(finite)) if finite.size else 0.0, 1e-300)


def compare_table(name: str, got: pd.DataFrame, ref: pd.DataFrame) -> list[str]:
    """Differences between a result table and its reference (empty when equal)."""
    problems = []
    if list(got.columns) != list(ref.columns):
        return [f"{name}: columns {list(got.columns)} != reference {list(ref.columns)}"]
    if len(got) != len(ref):
        return [f"{name}: {len(got)} rows != reference {len(ref)}"]
    numeric = ref.select_dtypes("number")
    table_scale = float(np.nanmax(np.abs(numeric.to_numpy(dtype=float)))) if numeric.size else 0.0
    for col in ref.columns:
        if any(s in col for s in SKIP):
            continue
        r = ref[col]
        g = got[col]
        if pd.api.types.is_numeric_dtype(r) and not pd.api.types.is_bool_dtype(r):
            rv = r.to_numpy(dtype=float)
            gv = pd.to_numeric(g, errors="coerce").to_numpy(dtype=float)
            tol = _tolerance(col, rv, table_scale)
            diff = np.abs(gv - rv)
            # an empty cell in both (NaN: a number the model does not have) is equal
            bad = ~(diff <= tol) & ~(np.isnan(gv) & np.isnan(rv))
            if np.any(bad):
                i = int(np.argmax(np.where(bad, diff, -1.0)))
                problems.append(f"{name}[{col}]: row {i} {gv[i]!r} vs reference {rv[i]!r} "
                                f"(|diff| {diff[i]:.3g} > {tol:.3g}; {int(bad.sum())} rows)")
        elif not (g.astype(str).to_numpy() == r.astype(str).to_numpy()).all():
            problems.append(f"{name}[{col}]: text differs from the reference")
    return problems


@pytest.mark.parametrize("scene_path", SCENES, ids=[p.stem for p in SCENES])
def test_scene_matches_stored_outputs(scene_path):
    ref_dir = REFERENCE / scene_path.stem
    refs = sorted(ref_dir.glob("*.csv"))
    assert refs, (f"no stored outputs for {scene_path.stem}: run "
                  "scripts/make_regression_refs.py (and commit them with the reason)")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        res = Simulation(load_scene(scene_path), progress=False).run()
    assert sorted(res.tables) == sorted(p.stem for p in refs)
    problems = []
    for path in refs:
        problems += compare_table(path.stem, res.tables[path.stem], pd.read_csv(path))
    assert not problems, "\n".join(problems)


def test_comparison_catches_a_change():
    """The comparison itself: a 2e-4 K temperature change, a 1e-5 relative power change and
    a changed text cell are reported; changes inside the tolerances and diagnostics are
    not."""
    ref = pd.DataFrame({"node [degC]": [40.0, 41.0], "power [W]": [100.0, 1e-3],
                        "source": ["a", "b"], "residual": [1e-12, 1e-11]})
    ok = ref.copy()
    ok["node [degC]"] += 5e-5
    ok["power [W]"] *= 1 + 5e-7
    ok["residual"] = [1e-9, 1e-9]
    assert compare_table("t", ok, ref) == []
    for col, value in (("node [degC]", [40.0002, 41.0]), ("power [W]", [100.001, 1e-3]),
                       ("source", ["a", "c"])):
        bad = ref.copy()
        bad[col] = value
        assert len(compare_table("t", bad, ref)) == 1
    assert compare_table("t", ref.iloc[:1], ref)
    # empty cells: equal where both are empty, a change where one is
    gap = pd.DataFrame({"pv [MPa m/s]": [np.nan, 2.0]})
    assert compare_table("t", gap.copy(), gap) == []
    assert len(compare_table("t", pd.DataFrame({"pv [MPa m/s]": [1.0, 2.0]}), gap)) == 1
    assert len(compare_table("t", gap, pd.DataFrame({"pv [MPa m/s]": [1.0, 2.0]}))) == 1
