"""Property tests of the heat sources on race-control states (thermobearing.heat_sources,
session 22): every registered source on the ball bearings SKF6304, QJ1044 and the roller
bearings NU214, CRB_50x75x16 at random speeds, loads, temperatures and oil flows.

- the books: each watt is a force times a sliding speed (the force pairs' power is the
  total, HeatResult's contract), per role >= 0, and the loss table's rows
  (HeatResult.split) add up to the heat per role;
- the read-set contract (RoleTemperatures): a source's heat does not change when the
  temperature of a role it did not read changes (the coupled transient re-evaluates a
  source only when a role it read changed);
- the mirror image: a bearing turning the other way (both rings' speeds negated) is the
  mirror image of the first and books the same heat per source and role; so does the outer
  ring driven either way. Defect found (heat_sources/rib.py, fixed): rib_friction took the
  roller spin positive whichever way the bearing turned, so backwards (or with the outer
  ring driven forward) the end face's and the rib's surface speeds added instead of
  cancelling: the reduced model booked 3.0x the heat (CRB_50x75x16, 524 rad/s, 3 kN:
  0.904 W for 0.302 W; with 500 N thrust 320 W for 107 W), and the default coupled model
  raised InputError 'speed = -524.0' (it was called with the negative relative speed);
- towards standstill the heat vanishes at least as fast as the speed (every loss is a
  moment or force that stays bounded times a speed): heat(omega / 1000) <= heat(omega) /
  1000, continuous with the 0 W booked at rest;
- continuity: a relative change of 1e-6 in speed or load changes the heat of the sources
  without documented regime switches by at most 1e-4 relative (churning and the cage
  guide jump at their regime onsets as printed: test_prop19_churning.py,
  test_prop19_cage_pocket.py).
"""

from __future__ import annotations

import math
import warnings

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import InputError
from thermobearing.heat_sources import HEAT_SOURCES, ROLES, HeatContext, evaluate_recorded
from thermobearing.kinematic_models import race_control
from thermobearing.state import OilSupply, OperatingPoint

BEARINGS = ("SKF6304", "QJ1044", "NU214", "CRB_50x75x16")
#: per-bearing options the sources need (SKF's series and C0 for the 6304; the rib
#: dynamics' reduced model, the coupled one runs seconds per state)
OPTIONS = {"SKF6304": {"global_friction": {"series": "63", "static_load_rating": 7800.0}},
           "CRB_50x75x16": {"rib_friction": {"model": "reduced"}}}
#: sources with documented regime jumps (continuity is not asked of them)
JUMPING = ("churning_cage", "churning_elements", "churning_inner_ring", "cage_guide")


def _is_ball(name: str) -> bool:
    return name in ("SKF6304", "QJ1044")


def _heat(name, rpm, fr, fa, temps, flow, outer_rpm=0.0, oil="ISO_VG46", kinematics=None):
    """{source: (HeatResult, roles read)} of every source that applies to the bearing;
    the race-control state at ``kinematics`` (role temperatures; default ``temps``)."""
    b, lub = load_bearing(name), load_lubricant(oil)
    kin = temps if kinematics is None else kinematics
    sup = OilSupply("jet", flow / 6e4, kin["oil"])
    op = OperatingPoint(inner_speed=rpm * math.pi / 30.0, outer_speed=outer_rpm * math.pi / 30,
                        radial_load=fr, axial_load=fa)
    kr = race_control(b, lub, op, contact_temperature=kin["elements"],
                      oil_temperature=kin["oil"], supply=sup)
    opts = {**kr.heat_options, **OPTIONS.get(name, {})}
    ctx = HeatContext(temperatures=temps, bearing=b, lubricant=lub, supply=sup, operating=op,
                      kinematics=kr.state, traction=kr.traction, options=opts)
    out = {}
    for src in HEAT_SOURCES.names():
        try:
            (res, reads), = evaluate_recorded([src], ctx)
        except InputError as exc:  # a source that does not apply to this bearing says so
            assert "not allowed" in str(exc) or "is missing" in str(exc), str(exc)
            continue
        out[src] = (res, reads)
    return out


@st.composite
def states(draw):
    name = draw(st.sampled_from(BEARINGS))
    rpm = 10.0 ** draw(st.floats(1.5, 4.0))
    fr = 10.0 ** draw(st.floats(2.0, 4.3))
    fa = 10.0 ** draw(st.floats(1.5, 3.7)) if _is_ball(name) else 0.0
    t = draw(st.floats(305.0, 370.0))
    temps = {"inner_ring": t + draw(st.floats(0.0, 10.0)), "outer_ring": t,
             "elements": t + draw(st.floats(0.0, 12.0)), "cage": t + draw(st.floats(0.0, 8.0)),
             "oil": t - draw(st.floats(0.0, 8.0))}
    flow = draw(st.floats(0.2, 30.0))
    return name, rpm, fr, fa, temps, flow


def _quiet():
    w = warnings.catch_warnings()
    w.__enter__()
    warnings.simplefilter("ignore")
    return w


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states(), st.sampled_from(ROLES), st.floats(5.0, 30.0))
@example(("NU214", 100.0, 100.0, 0.0, dict.fromkeys(ROLES, 305.0), 1.0), "elements", 5.0)
@example(("SKF6304", 3000.0, 2000.0, 300.0, dict.fromkeys(ROLES, 330.0), 5.0), "oil", 10.0)
def test_books_and_the_roles_read(state, role, dt):
    name, rpm, fr, fa, temps, flow = state
    w = _quiet()
    try:
        base = _heat(name, rpm, fr, fa, temps, flow)
        # the same kinematic state (and supply): only the node temperatures change
        other = _heat(name, rpm, fr, fa, {**temps, role: temps[role] + dt}, flow,
                      kinematics=temps)
    finally:
        w.__exit__(None, None, None)
    for src, (res, reads) in base.items():
        assert all(p >= 0.0 for p in res.power_by_role.values())
        # the loss table's rows (HeatResult.split) put each role's heat where the source says
        per_role = dict.fromkeys(ROLES, 0.0)
        for _, r, w in res.split():
            per_role[r] += w
        for r in ROLES:
            assert per_role[r] == pytest.approx(res.power_by_role.get(r, 0.0), rel=1e-9,
                                                abs=1e-12), (src, r)
        if res.force_pairs:
            booked = sum(p.power for p in res.force_pairs)
            assert booked == pytest.approx(res.total, rel=1e-9, abs=1e-12), src
        if role not in reads:
            assert other[src][0].total == pytest.approx(res.total, rel=1e-12, abs=1e-15), (
                f"{src} did not read {role} but its heat changed")


def _same(a, b, rel):
    assert a.keys() == b.keys()
    for src in a:
        ra, rb = a[src][0], b[src][0]
        assert rb.total == pytest.approx(ra.total, rel=rel, abs=1e-12), src
        for role, p in ra.power_by_role.items():
            assert rb.power_by_role.get(role, 0.0) == pytest.approx(p, rel=rel, abs=1e-12), \
                (src, role)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states())
def test_the_mirror_image_books_the_same_heat(state):
    name, rpm, fr, fa, temps, flow = state
    w = _quiet()
    try:
        forward = _heat(name, rpm, fr, fa, temps, flow)
        backward = _heat(name, -rpm, fr, fa, temps, flow)
        outer = _heat(name, 0.0, fr, fa, temps, flow, outer_rpm=rpm)
        outer_back = _heat(name, 0.0, fr, fa, temps, flow, outer_rpm=-rpm)
    finally:
        w.__exit__(None, None, None)
    _same(forward, backward, 1e-9)
    _same(outer, outer_back, 1e-9)


def test_rib_heat_of_the_outer_ring_driven_forward_is_the_mirror_image():
    """The measured case of the defect (reduced model, with and without thrust) and the
    default coupled model, which refused the negative relative speed."""
    w = _quiet()
    try:
        for fa, forward_w in ((0.0, 0.302), (500.0, 107.1)):
            runs = [_heat("CRB_50x75x16", wi, 3000.0, fa, dict.fromkeys(ROLES, 330.0), 6.0,
                          outer_rpm=wo)["rib_friction"][0]
                    for wi, wo in ((5004.0, 0.0), (-5004.0, 0.0), (0.0, 5004.0))]
            assert runs[0].total == pytest.approx(forward_w, rel=2e-3)
            for r in runs[1:]:
                assert r.total == pytest.approx(runs[0].total, rel=1e-12)
                assert r.power_by_role == pytest.approx(runs[0].power_by_role, rel=1e-12)
    finally:
        w.__exit__(None, None, None)


@pytest.mark.slow
def test_coupled_rib_heat_backwards_is_the_forward_heat():
    """The default (coupled) rib model backwards: was InputError 'speed = -524.0 is not
    allowed' (measured forward 0.2348 W, CRB_50x75x16 at 524 rad/s, 3 kN, 330 K, ~25 s)."""
    from thermobearing.heat_sources import evaluate

    b, lub = load_bearing("CRB_50x75x16"), load_lubricant("ISO_VG46")
    sup = OilSupply("jet", 1e-4, 320.0)
    totals = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for wi, wo in ((524.0, 0.0), (-524.0, 0.0), (0.0, 524.0)):
            op = OperatingPoint(inner_speed=wi, outer_speed=wo, radial_load=3000.0)
            kr = race_control(b, lub, op, contact_temperature=330.0, oil_temperature=325.0,
                              supply=sup)
            ctx = HeatContext.isothermal(330.0, bearing=b, lubricant=lub, supply=sup,
                                         operating=op, kinematics=kr.state,
                                         traction=kr.traction)
            res = evaluate(["rib_friction"], ctx)[0]
            assert res.details["model"] == "coupled"
            totals.append(res.total)
    assert totals[1] == pytest.approx(totals[0], rel=1e-12)
    assert totals[2] == pytest.approx(totals[0], rel=1e-12)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states())
def test_the_heat_vanishes_towards_standstill(state):
    name, rpm, fr, fa, temps, flow = state
    w = _quiet()
    try:
        fast = _heat(name, rpm, fr, fa, temps, flow)
        slow = _heat(name, rpm * 1e-3, fr, fa, temps, flow)
    finally:
        w.__exit__(None, None, None)
    for src, (res, _) in fast.items():
        assert slow[src][0].total <= 1e-3 * res.total * (1.0 + 1e-6) + 1e-12, src


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(states(), st.sampled_from(["speed", "load"]))
def test_the_heat_is_continuous_in_speed_and_load(state, which):
    name, rpm, fr, fa, temps, flow = state
    f = 1.0 + 1e-6
    w = _quiet()
    try:
        a = _heat(name, rpm, fr, fa, temps, flow)
        b = (_heat(name, rpm * f, fr, fa, temps, flow) if which == "speed"
             else _heat(name, rpm, fr * f, fa * f, temps, flow))
    finally:
        w.__exit__(None, None, None)
    for src, (res, _) in a.items():
        if src in JUMPING:
            continue
        assert b[src][0].total == pytest.approx(res.total, rel=1e-4, abs=1e-12), src


@pytest.mark.parametrize(("written", "kelvin"), [("5 K", 5.0), ("5 degC", 5.0), ("9 degF", 5.0),
                                                 ("5 delta_degC", 5.0), (5, 5.0)])
def test_a_temperature_step_option_is_a_temperature_difference(written, kelvin):
    """Defect found (heat_sources/rib.py, fixed): the rib source documented its
    temperature_step (the spacing of its temperature table) in "K" read as a temperature,
    so [models] heat_source_options = { rib_friction = { temperature_step = "5 degC" } }
    gave a 278.15 K step ("9 degF" 260.37 K)."""
    from types import SimpleNamespace

    from thermobearing.simulation_chain import scene_heat_source_options

    scene = SimpleNamespace(models={"heat_source_options": {
        "rib_friction": {"temperature_step": written}}})
    opts = scene_heat_source_options(scene, ["rib_friction"])
    assert opts["rib_friction"]["temperature_step"] == pytest.approx(kelvin, rel=1e-12)


def test_a_negative_temperature_step_names_the_option():
    from types import SimpleNamespace

    from thermobearing.simulation_chain import scene_heat_source_options

    scene = SimpleNamespace(models={"heat_source_options": {
        "rib_friction": {"temperature_step": "-5 degC"}}})
    with pytest.raises(InputError, match=r"rib_friction\.temperature_step"):
        scene_heat_source_options(scene, ["rib_friction"])
