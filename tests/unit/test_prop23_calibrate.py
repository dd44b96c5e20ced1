"""Property tests, round 5: calibration recovers a known parameter (:mod:`thermobearing.calibrate`).

Invariant (identifiability of a least-squares fit, Bates & Watts 1988, sec. 2.1): data made
by the model itself with a parameter value theta* and no noise have residual zero at
theta*, so a converged fit from another start returns theta* (to the finite-difference and
solver tolerances) and an RMSE near zero, for any theta* inside the bounds. The "measured"
data are SYNTHETIC (:func:`thermobearing.calibrate.synthetic_measurements`).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing.calibrate import calibrate, synthetic_measurements
from thermobearing.scene import Scene, load_scene

SENSORS = {"TC_DE": "drive_end.housing", "TC_oil": "non_drive_end.oil"}


def _scene(folder: Path, measured: bool) -> Scene:
    """The synthetic-measured example cut to two 15-min steps (0 and 28 kN)."""
    d = load_scene("qj1044_synthetic_measured").to_dict()
    d["schedule"]["steps"] = d["schedule"]["steps"][::2]
    d.pop("measured", None)
    if measured:
        d["measured"] = {"file": "rig.csv", "time_column": "time [min]", "unit": "degC",
                         "columns": dict(SENSORS)}
    return Scene.from_dict(d, folder)


@settings(max_examples=3, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(log_h=st.floats(math.log(120.0), math.log(1500.0)))
def test_noise_free_synthetic_data_give_back_the_generating_h_oil(tmp_path, log_h):
    """h_oil* in 120..1500 W/(m^2 K) (the example starts at 270): the fit returns h_oil* to
    0.5 % and an RMSE below 1e-3 K (data written to 1e-6 K)."""
    h_true = math.exp(log_h)
    gen = _scene(tmp_path, measured=False)
    truth = {"network.parameters.h_oil": f"{h_true!r} W/(m**2*K)"}
    data = synthetic_measurements(gen, SENSORS, values=truth, noise_sd=0.0, every=300.0,
                                  decimals=6)
    data.to_csv(tmp_path / "rig.csv", index=False)
    res = calibrate(_scene(tmp_path, measured=True), list(truth))
    (h_oil,) = res.parameters
    assert h_oil.value == pytest.approx(h_true, rel=5e-3)
    assert h_oil.ci_low <= h_oil.value <= h_oil.ci_high
    assert res.rmse < 1e-3
