"""Validation runner of the ball skidding / over-skidding solver.

Case ``paper002_csr_vs_axial_load``: QJ1044 CSR against axial load at 600-1800 r/min and
33 / 15 L/min (Gao et al. 2022, seed paper 002 section 4.1, Fig. 10). The parameters the paper
does not give were fitted at 1800 r/min / 33 L/min only (``configs/bearings/
QJ1044.calibration.toml``); the other speeds and the 15 L/min flow are predictions.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from ..units import to_si
from . import RUNNERS


def _curves(inputs: dict[str, Any]):
    from ..skidding.qj1044 import paper002_curves

    speeds = [to_si(v, "angular_speed", field="speeds") * 30 / math.pi for v in inputs["speeds"]]
    flows = [to_si(v, "volume_flow", field="flows") * 60000 for v in inputs["flows"]]
    loads = [to_si(v, "force", field="axial_loads") for v in inputs["axial_loads"]]
    fr = to_si(inputs.get("radial_load", "1 kN"), "force", field="radial_load")
    return paper002_curves(speeds, flows, loads, radial_load=fr,
                           calibration=inputs.get("calibration"),
                           lubricant=inputs.get("lubricant"))


@RUNNERS.register("paper002_csr_vs_axial_load",
                  references=["gao2022_overskidding", "harris_kotzalas2007", "jones1960"])
def paper002_csr_vs_axial_load(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """CSR(F_a) of the QJ1044 at five speeds and two flows; peaks, limits, failures.

    Quantities: ``csr_fa0_<n>_<q>`` CSR at F_a = 0; ``overskid_peak_<n>_<q>`` the largest
    CSR/CSR_th - 1 for 0.5 kN <= F_a <= 6 kN; ``overskid_high_load_<n>_<q>`` the largest
    |CSR/CSR_th - 1| for F_a >= 36 kN; ``peak_order_33`` 1 if the 33 L/min peaks fall with
    speed (1800 > 1500 > 1200) else 0; ``failed_points`` non-converged points.
    """
    curves = _curves(inputs)
    out: dict[str, float] = {}
    failed = 0
    for (n, q), c in curves.items():
        tag = f"{n}_{q}"
        failed += int(np.sum(~c.converged))
        os_ = c.over_skid
        fa = c.axial_load
        i0 = np.flatnonzero(fa == 0.0)
        if i0.size:
            out[f"csr_fa0_{tag}"] = float(c.cage_speed_ratio[i0[0]])
        win = (fa >= 500.0) & (fa <= 6000.0) & np.isfinite(os_)
        if np.any(win):
            out[f"overskid_peak_{tag}"] = float(np.max(os_[win]))
            out[f"overskid_peak_load_{tag}"] = float(fa[win][np.argmax(os_[win])])
        hi = (fa >= 36000.0) & np.isfinite(os_)
        if np.any(hi):
            out[f"overskid_high_load_{tag}"] = float(np.max(np.abs(os_[hi])))
    peaks = [out.get(f"overskid_peak_{n}_33", np.nan) for n in (1800, 1500, 1200)]
    out["peak_order_33"] = float(peaks[0] > peaks[1] > peaks[2])
    out["failed_points"] = float(failed)
    return out
