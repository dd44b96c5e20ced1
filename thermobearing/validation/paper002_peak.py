"""The QJ1044 rig state at paper 002's over-skidding peak, solved directly (no scene).

Same inputs as the default scene's first bearing in the steady loss runs of
``paper002_loss_ratios``: QJ1044 with the calibrated ball parameters and mounted clearance of
``configs/bearings/QJ1044.calibration.toml``, ISO VG 46 at the jet inlet temperature
everywhere, 1 kN radial load. Used by the runner for the loss shares booked the way paper 002
books them (:func:`thermobearing.losses.paper002_bookkeeping`) and by the case's
``diagnose.py`` (hand checks quoted in its SOURCE.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..heat_sources import HeatContext

#: paper 002's rig (section 3): oil inlet 35 degC, radial load 1 kN
INLET_TEMPERATURE = 308.15  # K
RADIAL_LOAD = 1000.0  # N


@dataclass(frozen=True)
class PeakState:
    """A solved rig state and the heat context its sources are evaluated in."""

    bearing: Any
    lubricant: Any
    supply: Any
    params: Any
    temperature: float  # K
    result: Any  # skidding.BallSkiddingResult
    context: HeatContext


def rig_inputs(flow: float, temperature: float = INLET_TEMPERATURE):
    """(bearing, lubricant, jet supply, calibrated ball parameters) of the rig.

    flow : jet oil flow [m^3/s]; temperature : inlet (and part) temperature [K]."""
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding.qj1044 import load_calibration, with_clearance
    from ..state import OilSupply

    cal = load_calibration()
    bearing = with_clearance(load_bearing("QJ1044"), cal["diametral_clearance"])
    return (bearing, load_lubricant("ISO_VG46"), OilSupply("jet", flow, temperature),
            cal["params"])


def solve_rig(axial_load: float, speed: float, flow: float,
              temperature: float = INLET_TEMPERATURE) -> PeakState:
    """Skidding solve of the rig at one operating point (SI: N, rad/s, m^3/s, K) and the
    heat context of the ball-bearing sources at that state."""
    from ..skidding import solve
    from ..skidding.ball_models import heat_context_options
    from ..state import OperatingPoint

    bearing, lub, supply, params = rig_inputs(flow, temperature)
    res = solve(bearing, lub, speed, RADIAL_LOAD, axial_load, temperature, supply=supply,
                params=params, oil_temperature=temperature)
    op = OperatingPoint(inner_speed=res.inner_speed, radial_load=RADIAL_LOAD,
                        axial_load=axial_load)
    opts = heat_context_options(bearing, supply, res.inner_speed, params)
    ctx = HeatContext.isothermal(temperature, bearing=bearing, lubricant=lub, supply=supply,
                                 operating=op, kinematics=res.kinematic_state, options=opts,
                                 traction=res.extra["traction_law"])
    return PeakState(bearing, lub, supply, params, temperature, res, ctx)


def loss_shares(heat: dict[str, float]) -> dict[str, float]:
    """Paper 002 section 4.3's ratios of one state's heat per source [W]: the ball-pocket and
    churning shares of the booked total and the cage-guide / ball-pocket ratio."""
    total = sum(heat.values())
    churn = sum(heat.get(k, 0.0) for k in ("churning_elements", "churning_cage",
                                          "churning_inner_ring"))
    pocket = heat.get("pocket_friction", 0.0)
    guide = heat.get("cage_guide", 0.0)
    return {"pocket_share": pocket / total, "churning_share": churn / total,
            "cage_guide_over_pocket": guide / pocket if pocket > 0 else float("inf"),
            "total": total}
