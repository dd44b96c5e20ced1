"""A calibration that stops without converging says so once (least_squares' message was on
the summary line and again in the note)."""

from dataclasses import replace

import numpy as np
import pandas as pd

from thermobearing.calibrate_result import CalibrationResult

MSG = "The maximum number of function evaluations is exceeded."


def _result(success: bool, notes: list[str]) -> CalibrationResult:
    return CalibrationResult(
        parameters=(), sensors=pd.DataFrame({"sensor": ["TC1"], "RMSE [K]": [0.5]}),
        rmse=0.5, initial_rmse=2.0, residual_sd=0.6, points=10, dof=9, runs=7,
        success=success, message=MSG, covariance=np.zeros((0, 0)),
        correlation=np.zeros((0, 0)), identifiable=True, scene=None, measured_file="m.csv",
        column_map={}, notes=notes)


def test_message_printed_once_when_not_converged():
    text = _result(False, [f"least_squares stopped without converging: {MSG}"]).summary_text()
    assert text.count(MSG) == 1
    assert "7 model runs; stopped without converging (note below)" in text


def test_converged_fit_keeps_the_solver_message_on_the_summary_line():
    ok = "`ftol` termination condition is satisfied."
    text = replace(_result(True, []), message=ok).summary_text()
    assert f"7 model runs; {ok}" in text
