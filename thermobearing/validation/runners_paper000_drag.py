"""Validation runner: paper 000's cage speeds with the numerical-EHL drag beside the closed form.

Case ``paper000_numerical_drag`` (issue 7): Li et al. 2018 (seed ``000_3b5ca6eed61dd596.txt``)
replace the closed-form roller-raceway drag by forces integrated over the numerical EHL
pressure and film (its eq. 5: Poiseuille -int h/2 dp/dx dx and Couette (u2 - u1) int eta/h dx).
The runner solves the NU214 roller skidding problem of Tables 2-3 twice per condition, with
the closed-form drag (``drag_model="closed_form"``) and with the numerical one
(``"numerical_ehl"``, :mod:`thermobearing.ehl.drag`), at otherwise identical inputs, and
returns both cage speeds, their errors against the tables and the difference of the mean
absolute errors (the issue asks that the numerical drag be at least as close as before).

Static (no whirl): the whirl-mean cage speed of the closed-form model equals its static value
within 0.1 r/min (1450.5 vs 1450.8 r/min at 150 N, 0.08 Pa s), and a whirl orbit would
multiply the numerical cost (about 30 s CPU per condition) by its sample count.
"""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Any

from . import RUNNERS
from .runners_roller_skidding import CONDITIONS, _get, paper000_eq9_lubricant

#: Tables 2-3 of paper 000: mean cage speed [r/min] per condition tag
PAPER_MEAN_CAGE_SPEED_RPM = {
    "Fr100_eta0.08": 1292.78,
    "Fr150_eta0.08": 1233.70,
    "Fr200_eta0.08": 1195.46,
    "Fr150_eta0.06": 1050.79,
    "Fr150_eta0.10": 1331.10,
}

DRAG_MODELS = ("closed_form", "numerical_ehl")
#: roller-solver options that modify the closed-form drag only
CLOSED_FORM_ONLY = ("film_pressure", "fluid_shear_modulus")


@RUNNERS.register("paper000_numerical_drag",
                  references=["li2018_nu214_skidding", "venner_lubrecht2000"])
def paper000_numerical_drag(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Cage speeds of Tables 2-3 with the closed-form and the numerical-EHL drag (static)."""
    import thermobearing.ehl.drag  # noqa: F401  registers "numerical_ehl"

    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding.roller import solve_roller

    bearing = load_bearing(inputs.get("bearing", "NU214"))
    lubricant = load_lubricant(inputs.get("lubricant", "PAPER000_OIL"))
    speed = _get(inputs, "inner_speed", "angular_speed")
    temperature = _get(inputs, "temperature", "temperature")
    options = dict(inputs.get("model", {}))
    eq9 = bool(inputs.get("paper_eq9_alpha", False))
    rpm = 60.0 / (2.0 * math.pi)
    out: dict[str, float] = {}
    abs_err = {m: [] for m in DRAG_MODELS}
    for (load, eta0), tag in CONDITIONS.items():
        lub = paper000_eq9_lubricant(lubricant, eta0, temperature) if eq9 else lubricant
        for model in DRAG_MODELS:
            # the closed form's Hertz-zone options (film_pressure, fluid_shear_modulus)
            # do not apply to the numerical drag, which integrates its own pressure
            opts = options if model == "closed_form" else {
                k: v for k, v in options.items() if k not in CLOSED_FORM_ONLY}
            t0 = time.process_time()
            res = solve_roller(bearing, lub, speed, load, 0.0, temperature, viscosity=eta0,
                               drag_model=model, **opts)
            cost = time.process_time() - t0
            cage = res.cage_speed * rpm
            out[f"mean_cage_speed_{tag}_{model}"] = res.cage_speed
            out[f"cpu_{tag}_{model}"] = cost
            abs_err[model].append(abs(cage / PAPER_MEAN_CAGE_SPEED_RPM[tag] - 1.0))
    for model in DRAG_MODELS:
        out[f"mean_abs_error_{model}"] = sum(abs_err[model]) / len(abs_err[model])
        out[f"cage_speed_change_Fr100_to_Fr200_{model}"] = (
            out[f"mean_cage_speed_Fr200_eta0.08_{model}"]
            - out[f"mean_cage_speed_Fr100_eta0.08_{model}"])
    out["mean_abs_error_numerical_minus_closed_form"] = (
        out["mean_abs_error_numerical_ehl"] - out["mean_abs_error_closed_form"])
    return out
