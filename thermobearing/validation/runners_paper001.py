"""Paper 001 (Shi & Wang): trends of the cage sliding ratio of the D1842926 roller bearing.

The paper's Figs. 7, 9 and 11 show the cage sliding ratio (actual minus theoretical cage
speed over the theoretical one, its section 4.2) falling with radial load, rising with
speed and rising with radial clearance. Here the roller skidding solver
(``skidding.solve`` -> paper 000's Z+1 equations with the closed-form EHL drag) is run on
the D1842926 preset with oil 4109 and the slip 1 - CSR/CSR_th is reported; the trends are
checked by sign. The figures carry no readable numbers, so the values are printed, not
compared. Figs. 7 and 9 are at 18 kN (``radial_load``), Fig. 11 at the paper's "Case 4",
24 kN (``clearance_radial_load``); ``[inputs.model]`` options go to the roller solver.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from .. import load_bearing, load_lubricant
from ..units import to_si
from . import RUNNERS


def _slip(bearing: Any, lubricant: Any, speed: float, radial_load: float,
          temperature: float, options: dict[str, Any]) -> float:
    from ..skidding import solve

    res = solve(bearing, lubricant, speed, radial_load, 0.0, temperature, **options)
    return 1.0 - res.cage_speed_ratio / res.theoretical_cage_speed_ratio


@RUNNERS.register(
    "paper001_cage_sliding_trends",
    references=["shi2015_tehl_roller", "li2018_nu214_skidding"],
    summary="Paper 001 cage sliding ratio vs radial load, speed and clearance (signs of trends).",
)
def paper001_cage_sliding_trends(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Cage sliding ratio at the paper's loads, speeds and clearances, and the trend signs
    (+1 when the trend has the paper's direction over the whole sweep, -1 otherwise)."""
    lub = load_lubricant(inputs["lubricant"])
    name = inputs["bearing"]
    t = to_si(inputs["temperature"], "temperature", field="temperature")
    w0 = to_si(inputs["speed"], "angular_speed", field="speed")
    f0 = to_si(inputs["radial_load"], "force", field="radial_load")
    f_clear = to_si(inputs.get("clearance_radial_load", inputs["radial_load"]), "force",
                    field="clearance_radial_load")
    options = dict(inputs.get("model", {}))
    loads = [to_si(x, "force", field="loads") for x in inputs["loads"]]
    speeds = [to_si(x, "angular_speed", field="speeds") for x in inputs["speeds"]]
    clear = [to_si(x, "length", field="diametral_clearances")
             for x in inputs["diametral_clearances"]]
    base = load_bearing(name)
    out: dict[str, float] = {}
    by_load = [_slip(base, lub, w0, f, t, options) for f in loads]
    by_speed = [_slip(base, lub, w, f0, t, options) for w in speeds]
    by_clear = [_slip(load_bearing(name, overrides={"diametral_clearance": c}), lub, w0,
                      f_clear, t, options) for c in clear]
    for f, v in zip(loads, by_load, strict=True):
        out[f"sliding_ratio_{f / 1e3:g}kN"] = v
    for w, v in zip(speeds, by_speed, strict=True):
        out[f"sliding_ratio_{round(w * 30 / math.pi)}rpm"] = v
    for c, v in zip(clear, by_clear, strict=True):
        out[f"sliding_ratio_Pd_{c * 1e6:g}um"] = v

    def trend(values: list[float], rising: bool) -> float:
        pairs = zip(values[:-1], values[1:], strict=True)
        ok = all((b > a) if rising else (b < a) for a, b in pairs)
        return 1.0 if ok else -1.0

    out["falls_with_load"] = trend(by_load, rising=False)
    out["rises_with_speed"] = trend(by_speed, rising=True)
    out["rises_with_clearance"] = trend(by_clear, rising=True)
    return out
