"""Property tests, round 6: monotonicity of the contact losses in speed, load and viscosity
on race-control states (session 24), beside the books, mirror image, standstill and
continuity of test_prop22_heat_sources.py (whose state builder is used here).

Raceway shear (``raceway_traction``: the traction law integrated over each Hertz contact,
heat = the tractions' power against the sliding) at a fixed race-control state:

- speed: every sliding speed of race control is proportional to the ring speed, and the
  shear stress of every traction law is non-decreasing in the slide (Newtonian eta dv / h
  with h ~ u^0.67, Eyring, limiting shear: test_prop21_traction.py), so the heat, stress
  times slide, does not fall as the speed rises;
- load: a larger load (radial; a ball bearing's radial and axial together) gives larger
  contacts at higher pressure, and the limiting shear Lambda p rises with the pressure;
- viscosity: the same bearing 2-40 K warmer (every role: oil, rings, elements, cage; the
  oil thinner) does not shear more (tau_N ~ eta / h ~ eta^0.33; the limiting shear does not
  depend on it).

EHL rolling resistance (``ehl_rolling_resistance``, Q_x u with Q_x ~ U^0.7 or ~ U^0.66,
U = eta u / (E' R_x), times the inlet-heating and starvation factors): non-decreasing in
speed and non-increasing in temperature wherever Gupta's (1992) thermal reduction is used
inside its fitted range (thermal loading L <= 10; beyond it the source warns). Beyond it
the reduction outweighs the viscosity: CRB_50x75x16 at 30315 r/min, 173 N, the rolling
resistance is 1669 W at 280 K (L = 409), 1843 W at 285.6 K, 1944 W at 290 K, 2085 W at
300 K and 2072 W at 320 K (L = 23), falling only from 350 K (1720 W, in range); SKF6304 at
10469 r/min, 10.5 kN, 280 K (L = 14.3) books 47.665 W and 1 % faster 47.647 W. These are
the fit's extrapolation, not asserted (the warning is the model's answer there); the
examples keep the raceway shear's monotonicity checked at those states.

Ranges: 3..3e4 r/min, radial 10..4e4 N, 280..400 K; over 900 draws each (three seeds of
300, scratch) no other violation.

Also not asserted (measured on 40 random states, scratch): the rolling resistance of a ball
bearing can fall as the radial load rises (11 of 40 on SKF6304 with an axial load: the sum
of Q^0.47 over the balls is concave, and a radial load added to a thrust-loaded bearing
shifts load from one side to the other); churning and the cage guide jump down at their
documented regime onsets (test_prop19_churning.py, test_prop19_cage_pocket.py); the SKF
four-term model books more at a lower viscosity (boundary friction of mixed lubrication,
its phi_bl) and its replenishment factor falls exponentially with speed.
"""

from __future__ import annotations

import math
import warnings

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from tests.unit.test_prop22_heat_sources import BEARINGS, _is_ball
from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import ValidityWarning
from thermobearing.heat_sources import HeatContext, evaluate_recorded
from thermobearing.kinematic_models import race_control
from thermobearing.state import OilSupply, OperatingPoint

SOURCES = ("raceway_traction", "ehl_rolling_resistance")


def _heat(name, rpm, fr, fa, t, flow) -> tuple[dict[str, float], bool]:
    """{source: total heat [W]} of SOURCES on the race-control state of one bearing with
    every role at ``t`` [K] (the contact and the oil at ``t``), jet oil ``flow`` [l/min];
    and whether Gupta's thermal reduction was asked beyond its fitted range (its warning)."""
    b, lub = load_bearing(name), load_lubricant("ISO_VG46")
    temps = {"inner_ring": t, "outer_ring": t, "elements": t, "cage": t, "oil": t}
    sup = OilSupply("jet", flow / 6e4, t)
    op = OperatingPoint(inner_speed=rpm * math.pi / 30.0, radial_load=fr, axial_load=fa)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        kr = race_control(b, lub, op, contact_temperature=t, oil_temperature=t, supply=sup)
        ctx = HeatContext(temperatures=temps, bearing=b, lubricant=lub, supply=sup, operating=op,
                          kinematics=kr.state, traction=kr.traction, options=kr.heat_options)
        out = evaluate_recorded(SOURCES, ctx)
    beyond = any(issubclass(w.category, ValidityWarning) and "gupta_1992" in str(w.message)
                 for w in caught)
    return {src: sum(res.power_by_role.values())
            for src, (res, _) in zip(SOURCES, out, strict=True)}, beyond


@st.composite
def states(draw):
    """10^0.5..10^4.5 r/min, radial 10..4e4 N (a ball bearing's axial 3..1e4 N), every role
    at 280..400 K, 0.2..30 l/min of jet oil."""
    name = draw(st.sampled_from(BEARINGS))
    rpm = 10.0 ** draw(st.floats(0.5, 4.5))
    fr = 10.0 ** draw(st.floats(1.0, 4.6))
    fa = 10.0 ** draw(st.floats(0.5, 4.0)) if _is_ball(name) else 0.0
    return name, rpm, fr, fa, draw(st.floats(280.0, 400.0)), draw(st.floats(0.2, 30.0))


def _not_below(low: float, high: float, what: str) -> None:
    """high >= low to round-off (1e-9 relative)."""
    assert high >= low - 1e-9 * max(abs(low), 1e-12), (what, low, high)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states(), st.floats(1.01, 3.0))
@example(("SKF6304", 3550.0, 968.0, 1476.0, 362.1, 3.2), 1.3)
@example(("NU214", 904.0, 174.0, 0.0, 333.8, 11.8), 1.3)
@example(("SKF6304", 10469.416979910806, 10469.416979910806, 6.437244428047445, 280.0, 0.8087),
         1.01)
def test_losses_rise_with_speed(state, factor):
    name, rpm, fr, fa, t, flow = state
    base, beyond = _heat(name, rpm, fr, fa, t, flow)
    fast, beyond_fast = _heat(name, factor * rpm, fr, fa, t, flow)
    _not_below(base["raceway_traction"], fast["raceway_traction"], name)
    if not (beyond or beyond_fast):
        _not_below(base["ehl_rolling_resistance"], fast["ehl_rolling_resistance"], name)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states(), st.floats(1.01, 3.0))
@example(("SKF6304", 176.0, 527.0, 2896.0, 343.0, 14.2), 1.3)
def test_raceway_shear_rises_with_load(state, factor):
    name, rpm, fr, fa, t, flow = state
    base = _heat(name, rpm, fr, fa, t, flow)[0]["raceway_traction"]
    heavy = _heat(name, rpm, factor * fr, factor * fa, t, flow)[0]["raceway_traction"]
    _not_below(base, heavy, name)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states(), st.floats(2.0, 40.0))
@example(("CRB_50x75x16", 30315.499047940022, 172.77591470023918, 0.0, 280.0, 1.9),
         5.644576050237348)
def test_losses_fall_as_the_oil_thins(state, warmer):
    name, rpm, fr, fa, t, flow = state
    base, beyond = _heat(name, rpm, fr, fa, t, flow)
    thin, beyond_thin = _heat(name, rpm, fr, fa, t + warmer, flow)
    _not_below(thin["raceway_traction"], base["raceway_traction"], name)
    if not (beyond or beyond_thin):
        _not_below(thin["ehl_rolling_resistance"], base["ehl_rolling_resistance"], name)
