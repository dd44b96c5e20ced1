"""Property tests of the thermal network templates at steady state (session 22), beside the
oil-stream books of test_prop21_network.py: every template (the registry's), ball and
roller bearings, with or without an oil stream, both contact models, heat on every role.

- the books: heat in = heat out to the ambient and the oil stream;
- the maximum principle: without heat every node lies between the coldest and the
  warmest boundary (ambient, oil inlet);
- monotonicity: more heat (the same split, scaled up; or heat added on one role) raises no
  node's temperature less than zero (conductances of free convection rise with the
  temperature difference, the Hertz constrictions do not depend on it: the steady map
  from heat to temperature stays monotone);
- the hottest node is one that is heated (a node without heat is a weighted mean of its
  neighbours).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import ValidityWarning
from thermobearing.network import solve_steady
from thermobearing.network.templates import TEMPLATES

HEATED_ROLES = ("inner_ring", "outer_ring", "elements", "cage", "oil")


@st.composite
def template_cases(draw):
    name = draw(st.sampled_from(("SKF6304", "QJ1044", "NU214", "CRB_50x75x16")))
    template = draw(st.sampled_from(TEMPLATES.names()))
    flow = draw(st.one_of(st.just(0.0), st.floats(1e-7, 1e-3)))
    t_amb = draw(st.floats(280.0, 330.0))
    t_in = t_amb + draw(st.floats(-20.0, 20.0))
    contact = draw(st.sampled_from(("hertz_constriction", "hertz_contact_paper002")))
    split = {r: draw(st.floats(0.0, 1.0)) for r in HEATED_ROLES}
    if sum(split.values()) == 0.0:
        split["elements"] = 1.0
    rise = draw(st.floats(0.5, 60.0))  # warmest node's rise [K], sets the power (below)
    return name, template, flow, t_amb, t_in, contact, split, rise


def _network(case):
    name, template, flow, t_amb, t_in, contact, _, _ = case
    b = load_bearing(name)
    return TEMPLATES.get(template)(
        b, load_lubricant("ISO_VG46"), housing_outer_diameter=1.6 * b.outer_diameter,
        housing_length=2.0 * b.width, oil_flow=flow, oil_inlet_temperature=t_in,
        ambient_temperature=t_amb, contact_model=contact)


def _solve(net, by_role):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return solve_steady(net, net.distribute(by_role))


def _roles(split, power):
    total = sum(split.values())
    return {r: power * w / total for r, w in split.items()}


def _power(net, split, rise):
    """Heat [W] of the split that warms the warmest node by about ``rise`` above the
    unheated state (the bearings differ by 100x in their conductance to the ambient: a
    fixed heat put a small bearing without oil flow at 4000 K, out of the air's model)."""
    cold = _solve(net, dict.fromkeys(HEATED_ROLES, 0.0)).temperatures_vector
    one = _solve(net, _roles(split, 1.0)).temperatures_vector
    return rise / max(float(np.max(one - cold)), 1e-6)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(template_cases())
def test_books_and_the_maximum_principle(case):
    name, template, flow, t_amb, t_in, contact, split, rise = case
    net = _network(case)
    power = _power(net, split, rise)
    res = _solve(net, _roles(split, power))
    assert res.generated == pytest.approx(power, rel=1e-12)
    assert res.to_boundaries + res.to_streams == pytest.approx(power, rel=1e-8)
    cold = _solve(net, dict.fromkeys(HEATED_ROLES, 0.0)).temperatures_vector
    lo, hi = min(t_amb, t_in), max(t_amb, t_in)
    slack = 1e-9 * hi
    if flow == 0.0:  # no stream: the inlet is not connected
        lo = hi = t_amb
    assert np.all(cold >= lo - slack) and np.all(cold <= hi + slack)
    assert np.all(res.temperatures_vector >= cold - slack)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(template_cases(), st.floats(1.01, 3.0), st.sampled_from(HEATED_ROLES),
       st.floats(0.01, 1.0))
def test_more_heat_raises_every_temperature(case, more, role, extra):
    _, _, _, _, _, _, split, rise = case
    net = _network(case)
    power = _power(net, split, rise)
    base = _roles(split, power)
    t0 = _solve(net, base).temperatures_vector
    t1 = _solve(net, {r: more * p for r, p in base.items()}).temperatures_vector
    added = dict(base)
    added[role] += extra * power
    t2 = _solve(net, added).temperatures_vector
    slack = 1e-9 * float(np.max(t0))
    assert np.all(t1 >= t0 - slack)
    assert np.all(t2 >= t0 - slack)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(template_cases())
def test_the_hottest_node_is_heated(case):
    _, _, _, t_amb, t_in, _, split, rise = case
    net = _network(case)
    power = _power(net, split, rise)
    by_role = _roles(split, power)
    heat = net.distribute(by_role)
    res = _solve(net, by_role)
    temps = res.temperatures
    hottest = max(temps, key=temps.get)
    q = heat if isinstance(heat, dict) else dict(zip(temps, np.asarray(heat), strict=True))
    assert q.get(hottest, 0.0) > 0.0 or temps[hottest] <= max(t_amb, t_in) + 1e-9
