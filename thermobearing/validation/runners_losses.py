"""Validation runners for the power-loss sources.

Cases
-----
``paper002_churning_flow_ratio``
    QJ1044 of paper 002 at 1800 r/min: churning sources (cage, balls, inner ring; eqs. 15-17
    with the Parker oil fraction) at 15 and 33 L/min, their ratio, and the churning share of
    the local total at both flows (paper 002: total loss at 15 L/min about 75 % of 33 L/min,
    churning 60-80 % of it).
``crosscheck_global_friction``
    Local heat-source total (race-control kinematics) beside the SKF four-term model and
    Palmgren M0 + M1 (``global_friction.py``) for the SKF 6304 of paper 004 and
    the QJ1044 of paper 002 at three speeds each, with their ratios.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

from ..errors import ValidityWarning
from ..geometry import load_bearing
from ..heat_sources import HeatContext, evaluate
from ..lubricant import load_lubricant
from ..state import KinematicState, OilSupply, OperatingPoint
from ..traction import make_traction_law
from ..units import to_si
from . import RUNNERS

CHURNING = ("churning_cage", "churning_elements", "churning_inner_ring")
LOCAL = ("raceway_traction", "ehl_rolling_resistance", *CHURNING, "cage_guide",
         "pocket_friction")


def _state(bearing, op, oil, temperature):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return KinematicState.from_race_control(bearing, op, lubricant=oil,
                                                temperature=temperature)


def _local(bearing, oil, op, ks, supply, temperature, sources=LOCAL, options=None):
    ctx = HeatContext.isothermal(
        temperature, bearing=bearing, lubricant=oil, supply=supply, operating=op,
        kinematics=ks, traction=make_traction_law("eyring_limiting_shear", lubricant=oil),
        options=options or {})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return {r.source: r.total for r in evaluate(sources, ctx)}


@RUNNERS.register("paper002_churning_flow_ratio",
                  references=["gao2022_overskidding", "parker1984_tp2275"])
def paper002_churning_flow_ratio(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Churning sum at 15 and 33 L/min for the QJ1044 at 1800 r/min and their ratio."""
    bearing = load_bearing(inputs.get("bearing", "QJ1044"))
    oil = load_lubricant(inputs.get("lubricant", "ISO_VG46"))
    speed = to_si(inputs["inner_speed"], "angular_speed", field="inner_speed")
    op = OperatingPoint(inner_speed=speed,
                        radial_load=to_si(inputs["radial_load"], "force", field="radial_load"),
                        axial_load=to_si(inputs["axial_load"], "force", field="axial_load"))
    t_in = to_si(inputs["inlet_temperature"], "temperature", field="inlet_temperature")
    t_op = to_si(inputs["operating_temperature"], "temperature", field="operating_temperature")
    ks = _state(bearing, op, oil, t_op)
    out: dict[str, float] = {}
    # default: ball churning by paper 002 eq. 16 (SI); sensitivity: plain eq. 10 drag
    for suffix, form in (("", "paper002"), ("_eq10_drag", "harris")):
        res = {}
        for label, key in (("low", "low_flow"), ("high", "high_flow")):
            flow = to_si(inputs[key], "volume_flow", field=key)
            parts = _local(bearing, oil, op, ks, OilSupply("jet", flow, t_in), t_op,
                           options={"churning_elements": {"form": form}})
            churn = sum(parts[s] for s in CHURNING)
            total = sum(parts.values())
            res[label] = (churn, total)
            out[f"churning_{label}_flow{suffix}"] = churn
            out[f"total_{label}_flow{suffix}"] = total
            out[f"churning_share_{label}_flow{suffix}"] = churn / total
        out[f"churning_ratio_low_over_high{suffix}"] = res["low"][0] / res["high"][0]
        out[f"total_ratio_low_over_high{suffix}"] = res["low"][1] / res["high"][1]
        out[f"churning_share_drop{suffix}"] = (out[f"churning_share_high_flow{suffix}"]
                                               - out[f"churning_share_low_flow{suffix}"])
    return out


@RUNNERS.register("crosscheck_global_friction",
                  references=["gao2022_overskidding", "luo2022_cage_slip_vibration",
                              "skf_catalogue_friction", "palmgren1959"])
def crosscheck_global_friction(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Local heat-source total vs SKF four-term vs Palmgren at three speeds per bearing."""
    from ..global_friction import global_friction

    out: dict[str, float] = {}
    for key, spec in inputs["bearings"].items():
        bearing = load_bearing(spec["preset"])
        oil = load_lubricant(spec["lubricant"])
        t_op = to_si(spec["temperature"], "temperature", field=f"{key}.temperature")
        fr = to_si(spec["radial_load"], "force", field=f"{key}.radial_load")
        fa = to_si(spec.get("axial_load", 0.0), "force", field=f"{key}.axial_load")
        method = spec["method"]
        flow = to_si(spec.get("flow", 0.0), "volume_flow", field=f"{key}.flow")
        level = None
        lubrication = "oil_jet"
        if method == "oil_bath":
            # SKF guidance: static level at the centre of the lowest rolling element
            level = 0.5 * bearing.element_diameter
            lubrication = "oil_bath"
        supply = OilSupply(method, flow, t_op, level)
        locals_by_rpm = {}
        for rpm_text in spec["speeds"]:
            w = to_si(rpm_text, "angular_speed", field=f"{key}.speeds")
            rpm = round(w * 30.0 / math.pi)
            op = OperatingPoint(inner_speed=w, radial_load=fr, axial_load=fa)
            ks = _state(bearing, op, oil, t_op)
            local = sum(_local(bearing, oil, op, ks, supply, t_op).values())
            opts = {"oil_level": level} if level is not None else {}
            skf = global_friction("skf_four_term", bearing, oil, t_op, w, fr, fa,
                                  lubrication=lubrication, **opts).power
            pal = global_friction("palmgren", bearing, oil, t_op, w, fr, fa,
                                  lubrication=lubrication).power
            tag = f"{key}_{rpm}rpm"
            out[f"local_{tag}"] = local
            out[f"skf_{tag}"] = skf
            out[f"palmgren_{tag}"] = pal
            out[f"local_over_skf_{tag}"] = local / skf
            out[f"local_over_palmgren_{tag}"] = local / pal
            locals_by_rpm[rpm] = local
        lo, hi = min(locals_by_rpm), max(locals_by_rpm)
        out[f"local_{lo}_over_{hi}_{key}"] = locals_by_rpm[lo] / locals_by_rpm[hi]
    return out
