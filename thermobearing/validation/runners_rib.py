"""Validation runner of the rib contact / roller dynamics (paper 003 trends, Figs. 7-12).

Case ``paper003_pv_slip_trends``: Zhang et al. 2021 (seed ``003_743e023ae6e45686.txt``),
sections 9-10 and conclusions (1)-(5). The paper gives no tabulated PV or slip numbers
(only figures whose data are not in the text), so the case checks the *trends* it states
as ratios and slopes, and the locations of the PV minima against rib angle (0.55 deg) and
end-face crown radius (550 mm). All points use the reduced model
(:func:`thermobearing.skidding.roller_dynamics.simulate_reduced`); the cost of one
base-case point with the full and the reduced model and their PV/slip ratio are returned
as well.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..units import to_si
from . import RUNNERS


def _list(inputs: dict[str, Any], key: str, kind: str) -> list[float]:
    if key not in inputs:
        raise InputError(f"inputs.{key}", None, f"a list of {kind} quantities")
    return [to_si(v, kind, field=f"inputs.{key}") for v in inputs[key]]


def parabolic_minimum(x: Any, y: Any) -> float:
    """Abscissa of the minimum of sampled ``y(x)``: vertex of the parabola through the
    smallest sample and its two neighbours (the end sample if the minimum is at an end)."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    i = int(np.argmin(y))
    if i == 0 or i == len(x) - 1:
        return float(x[i])
    c = np.polyfit(x[i - 1:i + 2], y[i - 1:i + 2], 2)
    if c[0] <= 0:
        return float(x[i])
    return float(np.clip(-c[1] / (2 * c[0]), x[i - 1], x[i + 1]))


def _pv(row: dict[str, float]) -> float:
    return row["pv_left"] + row["pv_right"]


def _pvc(row: dict[str, float]) -> float:
    """PV averaged over the time each face is in contact, both faces summed [Pa m/s]."""
    return row["pv_contact_left"] + row["pv_contact_right"]


@RUNNERS.register("paper003_pv_slip_trends",
                  references=["zhang2021_abnormal_wear", "archard1953", "gear1971_dae"])
def paper003_pv_slip_trends(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """PV and slip trends of paper 003 (unbalance, load, speed, clearances, rib, crown)."""
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding import roller_dynamics as rd

    bearing = load_bearing(inputs.get("bearing", "CRB_50x75x16"))
    lub = load_lubricant(inputs.get("lubricant", "MIL_PRF_23699"))
    temperature = to_si(inputs.get("temperature", "80 degC"), "temperature",
                        field="inputs.temperature")
    m_lo, m_hi = _list(inputs, "unbalance", "mass")
    slide = inputs.get("slide", "offset")
    pocket_dof = bool(inputs.get("pocket_dof", True))
    cache: dict = {}
    out: dict[str, float] = {}

    def sweep(parameter: str, values: list[float], masses: list[float],
              spin: str = "skidding") -> list[dict]:
        return rd.pv_slip_map(bearing, lub, parameter, values, masses,
                              temperature=temperature, cache=cache, spin=spin, slide=slide,
                              pocket_dof=pocket_dof)

    # unbalance at the base case (Fig. 7 at 3000 N): PV and slip grow, unbalance side larger
    base = sweep("radial_load", [rd.PAPER003_BASE["radial_load"]], [0.0, m_lo, m_hi])
    out["pv_ratio_unbalance_high_vs_low"] = _pv(base[2]) / _pv(base[1])
    out["slip_ratio_unbalance_high_vs_low"] = base[2]["slip_speed"] / base[1]["slip_speed"]
    out["slip_ratio_unbalance_high_vs_none"] = base[2]["slip_speed"] / base[0]["slip_speed"]
    out["pv_right_over_left_high_unbalance"] = base[2]["pv_right"] / base[2]["pv_left"]
    out["pv_right_over_left_low_unbalance"] = base[1]["pv_right"] / base[1]["pv_left"]
    out["pv_contact_ratio_unbalance_high_vs_low"] = _pvc(base[2]) / _pvc(base[1])
    out["pv_contact_right_over_left_high_unbalance"] = (base[2]["pv_contact_right"]
                                                        / base[2]["pv_contact_left"])
    out["base_pv_high_unbalance"] = _pv(base[2]) / 2.0
    out["base_slip_speed_high_unbalance"] = base[2]["slip_speed"]

    # radial load (Fig. 7, no unbalance): slip falls and flattens above 5000 N
    loads = _list(inputs, "radial_loads", "force")
    rows = sweep("radial_load", loads, [0.0])
    s = [r["slip_speed"] for r in rows]
    i5 = int(np.argmin(np.abs(np.asarray(loads) - 5000.0)))
    out["slip_ratio_load_low_vs_5000N"] = s[0] / s[i5]
    out["slip_flattening_above_5000N"] = abs(s[-1] - s[i5]) / max(abs(s[0] - s[i5]), 1e-12)

    # speed (Fig. 8): PV and slip rise
    speeds = _list(inputs, "speeds", "angular_speed")
    rows = sweep("speed", speeds, [m_hi])
    out["pv_ratio_speed_high_vs_low"] = _pv(rows[-1]) / max(_pv(rows[0]), 1e-30)
    out["slip_ratio_speed_high_vs_low"] = rows[-1]["slip_speed"] / rows[0]["slip_speed"]

    # axial clearance (Fig. 9): PV rises, slip falls, both flatten above 0.05 mm
    ca = _list(inputs, "axial_clearances", "length")
    rows = sweep("axial_clearance", ca, [m_hi])
    pv = [_pv(r) for r in rows]
    s = [r["slip_speed"] for r in rows]
    j5 = int(np.argmin(np.abs(np.asarray(ca) - 0.05e-3)))
    out["pv_ratio_axial_clearance_0.05_vs_min"] = pv[j5] / pv[0]
    out["slip_ratio_axial_clearance_min_vs_0.05"] = s[0] / s[j5]
    out["pv_flattening_above_0.05mm"] = abs(pv[-1] - pv[j5]) / max(abs(pv[j5] - pv[0]), 1e-12)
    pvc = [_pvc(r) for r in rows]
    out["pv_contact_ratio_axial_clearance_0.05_vs_min"] = pvc[j5] / pvc[0]
    out["pv_contact_flattening_above_0.05mm"] = (abs(pvc[-1] - pvc[j5])
                                                 / max(abs(pvc[j5] - pvc[0]), 1e-12))

    # pocket clearance (Fig. 10): both rise, flatten above ~0.35 mm
    cp = _list(inputs, "pocket_clearances", "length")
    rows = sweep("pocket_clearance", cp, [m_hi])
    pv = [_pv(r) for r in rows]
    s = [r["slip_speed"] for r in rows]
    k35 = int(np.argmin(np.abs(np.asarray(cp) - 0.35e-3)))
    out["pv_ratio_pocket_0.35_vs_min"] = pv[k35] / pv[0]
    out["slip_ratio_pocket_0.35_vs_min"] = s[k35] / s[0]
    out["pv_flattening_above_0.35mm"] = abs(pv[-1] - pv[k35]) / max(abs(pv[k35] - pv[0]), 1e-12)

    # rib angle (Fig. 11) and crown radius (Fig. 12): PV minima, slip rising
    for key, par, kind in (("rib_angles", "rib_angle", "angle"),
                           ("crown_radii", "crown_radius", "length")):
        vals = _list(inputs, key, kind)
        rows = sweep(par, vals, [m_hi])
        pv = [_pv(r) for r in rows]
        out[f"pv_minimum_{par}"] = parabolic_minimum(vals, pv)
        out[f"pv_contact_minimum_{par}"] = parabolic_minimum(vals, [_pvc(r) for r in rows])
        out[f"slip_ratio_{par}_last_vs_first"] = rows[-1]["slip_speed"] / rows[0]["slip_speed"]
        # sensitivity: every roller at its pure-rolling spin (SOURCE.md, point 3)
        rows = sweep(par, vals, [m_hi], spin="rolling")
        out[f"pv_minimum_{par}_rolling_spin"] = parabolic_minimum(vals, [_pv(r) for r in rows])

    # cost of one base-case point, full vs reduced
    m = rd.build_model(bearing, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                       m_hi, temperature=temperature, quasi_static=cache.get(
                           (round(rd.PAPER003_BASE["speed"], 6),
                            round(rd.PAPER003_BASE["radial_load"], 6))),
                       rib={"slide": slide}, pocket_dof=pocket_dof)
    full = rd.simulate_full(m)
    red = rd.simulate_reduced(m)
    out["cost_full_s"] = full.cost_s
    out["cost_reduced_s"] = red.cost_s
    out["reduced_vs_full_pv"] = (red.pv_left + red.pv_right) / (full.pv_left + full.pv_right)
    out["reduced_vs_full_slip"] = red.slip_speed / full.slip_speed
    return out
