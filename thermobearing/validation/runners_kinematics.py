"""Validation runners for the kinematic and geometric cases.

Cases: ``paper004_bpfo`` (Luo et al. 2022 BPFO 85.5 Hz at 2000 r/min, no slip),
``paper000_cage_speed_theoretical`` (Li et al. 2018 eq. 40, n_m = 2166.7 r/min at 5000 r/min),
``paper002_csr_theoretical`` (Gao et al. 2022 CSR_th = 0.452 for the QJ1044 preset).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..geometry import load_bearing
from ..units import to_si
from . import RUNNERS

_TWO_PI = 6.283185307179586


@RUNNERS.register("paper004_bpfo", references=["luo2022_cage_slip_vibration"])
def paper004_bpfo(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """BPFO, BPFI, cage frequency and ball inertia of the SKF 6304 preset (paper 004 Table 1).

    BPFO = Z/2 (1 - s_c) (1 - D cos(a)/d_m) f_s (paper 004, rule after Fig. 11).
    """
    bearing = load_bearing(inputs.get("bearing", "SKF6304"))
    shaft_hz = to_si(inputs["shaft_speed"], "angular_speed", field="shaft_speed") / _TWO_PI
    angle = to_si(inputs.get("contact_angle", 0.0), "angle", field="contact_angle")
    out: dict[str, float] = {}
    f = bearing.characteristic_frequencies(shaft_hz, contact_angle=angle)
    out.update(bpfo=f.bpfo, bpfi=f.bpfi, cage_frequency=f.cage, ball_spin_frequency=f.ball_spin)
    for slip in inputs.get("cage_slips", []):
        fs = bearing.characteristic_frequencies(shaft_hz, contact_angle=angle,
                                                cage_slip=float(slip))
        out[f"bpfo_slip_{float(slip):g}"] = fs.bpfo
    out["ball_inertia"] = bearing.element_inertia
    out["inner_raceway_diameter"] = bearing.inner_raceway_diameter
    out["outer_raceway_diameter"] = bearing.outer_raceway_diameter
    return out


@RUNNERS.register("paper000_cage_speed_theoretical", references=["li2018_nu214_skidding"])
def paper000_cage_speed_theoretical(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Theoretical cage speed n_m = n_i (1 - D_b/d_m)/2 of the NU214 preset (paper 000 eq. 40)."""
    bearing = load_bearing(inputs.get("bearing", "NU214"))
    w_i = to_si(inputs["inner_speed"], "angular_speed", field="inner_speed")
    return {"theoretical_cage_speed": w_i * bearing.theoretical_cage_speed_ratio(),
            "cage_speed_ratio": bearing.theoretical_cage_speed_ratio()}


@RUNNERS.register("paper002_csr_theoretical", references=["gao2022_overskidding"])
def paper002_csr_theoretical(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Epicyclic CSR_th = (1 - D cos(a)/d_m)/2 of the QJ1044 preset at the nominal 40 deg."""
    bearing = load_bearing(inputs.get("bearing", "QJ1044"))
    angle = to_si(inputs.get("contact_angle", "40 deg"), "angle", field="contact_angle")
    out = {"csr_theoretical": float(bearing.theoretical_cage_speed_ratio(angle)),
           "gamma": float(bearing.gamma(angle)),
           "free_contact_angle": bearing.free_contact_angle}
    return out
