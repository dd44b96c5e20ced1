"""Scene-level validation of seed paper 002 (Gao et al.): losses and temperatures of the rig.

Both runners start from the embedded default scene (``configs/scenes/qj1044_rig.toml``)
and change only what the paper's test matrix changes: speed (600-1800 r/min) and oil
flow (15 / 33 L/min). The losses come from the full chain (skidding solver + heat
sources); the temperatures from the coupled transient over the 66-min protocol.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ..scene import Scene, load_scene
from ..simulation import Simulation
from ..units import to_si
from . import RUNNERS


def _variant(base: Scene, *, speed: float | None = None, flow: float | None = None,
             want: list[str] | None = None, mode: str | None = None,
             single_bearing: bool = False, kinematics: str | None = None) -> Scene:
    """A copy of ``base`` with the speed of every step, the oil flow, outputs changed."""
    d = base.to_dict()
    if speed is not None:
        for step in d["schedule"]["steps"]:
            step["speed"] = f"{speed * 30.0 / math.pi:.10g} rpm"
    if flow is not None:
        d["supply"]["flow"] = f"{flow * 6e4:.10g} L/min"
    if want is not None:
        d["outputs"]["want"] = want
    if mode is not None:
        d["outputs"]["mode"] = mode
    if single_bearing:
        d["bearings"] = d["bearings"][:1]
        # one bearing sits on no shaft link (a link joins two or more)
        if isinstance(d.get("network"), dict):
            d["network"].pop("shaft_link", None)
    if kinematics is not None:
        d.setdefault("models", {})["kinematics"] = kinematics
    return Scene.from_dict(d, Path(base.base_dir) if base.base_dir else None)


def _losses(scene: Scene) -> pd.DataFrame:
    """Per-step loss by source [W] of the first bearing (steps as rows)."""
    res = Simulation(scene, progress=False).run()
    losses = res.tables["losses"]
    first = losses[losses["bearing"] == losses["bearing"].iloc[0]]
    table = first.pivot_table(index="axial load [kN]", columns="source", values="power [W]",
                              aggfunc="sum").fillna(0.0)
    kin = res.tables["kinematics"]
    kin = kin[kin["bearing"] == kin["bearing"].iloc[0]].set_index("axial load [kN]")
    table["over-skidding [%]"] = kin["over-skidding [%]"]
    return table


_CHURNING = ("churning_elements", "churning_cage", "churning_inner_ring")


@RUNNERS.register(
    "paper002_loss_ratios",
    references=["gao2022_overskidding"],
    summary="Paper 002 loss ratios: flow 15/33 L/min, speed 600/1800 r/min, shares at the peak.",
)
def paper002_loss_ratios(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Protocol-mean total loss ratios and the loss shares at the over-skidding peak.

    Paper 002 section 4.3: total loss at 15 L/min about 75 % of that at 33 L/min; at
    600 r/min about 1/5 of that at 1800 r/min; ball-pocket about 30 % of the total at
    over-skidding, churning 60-80 %, cage-guide about 1/5 of ball-pocket (Figs. 15-17).
    """
    base = load_scene(inputs.get("scene"))
    low = to_si(inputs["low_flow"], "volume_flow", field="low_flow")
    high = to_si(inputs["high_flow"], "volume_flow", field="high_flow")
    n_low = to_si(inputs["low_speed"], "angular_speed", field="low_speed")
    n_high = to_si(inputs["high_speed"], "angular_speed", field="high_speed")
    kw = {"want": ["kinematics", "losses"], "mode": "steady", "single_bearing": True}
    at_high = _losses(_variant(base, speed=n_high, flow=high, **kw))
    at_low_flow = _losses(_variant(base, speed=n_high, flow=low, **kw))
    at_low_speed = _losses(_variant(base, speed=n_low, flow=high, **kw))

    def total(t: pd.DataFrame) -> pd.Series:
        return t.drop(columns=["over-skidding [%]"]).sum(axis=1)

    peak = at_high["over-skidding [%]"].idxmax()
    row = at_high.loc[peak]
    tot = float(total(at_high).loc[peak])
    churn = float(sum(row.get(c, 0.0) for c in _CHURNING))
    pocket = float(row.get("pocket_friction", 0.0))
    guide = float(row.get("cage_guide", 0.0))
    paper = _paper_bookkeeping_at(float(peak) * 1e3, n_high, high,
                                  float(inputs.get("guide_friction", 0.1)))
    return {
        **paper,
        "total_ratio_flow_15_over_33": float(total(at_low_flow).mean() / total(at_high).mean()),
        "total_ratio_speed_600_over_1800": float(total(at_low_speed).mean()
                                                 / total(at_high).mean()),
        "pocket_share_at_peak": pocket / tot,
        "churning_share_at_peak": churn / tot,
        "cage_guide_over_pocket_at_peak": guide / pocket if pocket > 0 else math.inf,
        "peak_axial_load": float(peak) * 1e3,
        "total_loss_at_peak": tot,
    }


def _paper_bookkeeping_at(axial_load: float, speed: float, flow: float,
                          guide_friction: float) -> dict[str, float]:
    """The peak state solved directly (:mod:`.paper002_peak`, the scene's first bearing at
    the inlet temperature) and booked the way paper 002 books it
    (:func:`thermobearing.losses.paper002_bookkeeping`: ball churning by its eq. 16, cage guide
    by its eq. 18 with ``guide_friction`` = mu_c, not given by the paper, and the land carrying
    the cage weight): the shares of that booking and the share of the shaft power it leaves
    unbooked."""
    from ..losses import paper002_bookkeeping
    from .paper002_peak import loss_shares, solve_rig

    state = solve_rig(axial_load, speed, flow)
    shares = loss_shares(paper002_bookkeeping(state.context, guide_friction=guide_friction))
    shaft = state.result.shaft_torque * state.result.inner_speed
    return {
        "pocket_share_at_peak_paper_bookkeeping": shares["pocket_share"],
        "churning_share_at_peak_paper_bookkeeping": shares["churning_share"],
        "cage_guide_over_pocket_at_peak_paper_bookkeeping": shares["cage_guide_over_pocket"],
        "unbooked_share_paper_bookkeeping": 1.0 - shares["total"] / shaft,
    }


@RUNNERS.register(
    "paper002_temperature_rise",
    references=["gao2022_overskidding"],
    summary="Paper 002 temperature rise of the housing over the 66-min protocol vs speed and flow.",
)
def paper002_temperature_rise(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Housing (outer-ring thermocouple) temperature rise after the 66-min protocol.

    Paper 002 Figs. 18-19: the rise grows roughly linearly with speed, is lower at 33 than at
    15 L/min, and at 1500-1800 r/min the temperature rises fastest in the first minutes.
    Returns the rise [K] per speed and flow, the linearity (R^2 of rise vs speed at 33 L/min),
    the flow difference and the ratio of the early to the late heating rate at the top speed.
    """
    base = load_scene(inputs.get("scene"))
    speeds = [to_si(s, "angular_speed", field="speeds") for s in inputs["speeds"]]
    flows = [to_si(q, "volume_flow", field="flows") for q in inputs["flows"]]
    node = inputs.get("node", "drive_end.housing") + " [degC]"
    kin = inputs.get("kinematics")
    out: dict[str, float] = {}
    rises: dict[tuple[int, int], float] = {}
    for i, w in enumerate(speeds):
        for j, q in enumerate(flows):
            sc = _variant(base, speed=w, flow=q, want=["temperatures", "energy"],
                          single_bearing=True, kinematics=kin)
            res = Simulation(sc, progress=False).run()
            temps = res.tables["temperatures"]
            t = temps["time [s]"].to_numpy()
            y = temps[node].to_numpy()
            rise = float(y[-1] - y[0])
            rises[(i, j)] = rise
            rpm = round(w * 30 / math.pi)
            lpm = round(q * 6e4)
            out[f"rise_{rpm}rpm_{lpm}Lmin"] = rise
            if i == len(speeds) - 1 and j == 0:
                early = np.interp(600.0, t, y) - y[0]
                late = y[-1] - np.interp(t[-1] - 600.0, t, y)
                out["early_over_late_heating_top_speed"] = float(early / max(late, 1e-9))
    j_ref = 0
    x = np.array([w * 30 / math.pi for w in speeds])
    r = np.array([rises[(i, j_ref)] for i in range(len(speeds))])
    fit = np.polyfit(x, r, 1)
    resid = r - np.polyval(fit, x)
    out["linearity_r2_first_flow"] = float(1.0 - np.sum(resid**2) / np.sum((r - r.mean())**2))
    if len(flows) > 1:
        diffs = [rises[(i, 1)] - rises[(i, 0)] for i in range(len(speeds))]
        out["min_rise_difference_second_minus_first_flow"] = float(min(diffs))
    return out
