"""Rib heat from the coupled roller dynamics (paper 003): energy identity, cache, heat source."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError, ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.rib import SIGN_REGULARISATION, lubricant_drag, rib_forces, rib_geometry
from thermobearing.skidding import roller_dynamics_heat as rdh

W = 30000 * math.pi / 30          # paper 003 base case: 30000 r/min, 3000 N, 0.11 g
UNBALANCE = 1.1e-4
_STATE = {}


@pytest.fixture(scope="module")
def crb():
    return load_bearing("CRB_50x75x16"), load_lubricant("MIL_PRF_23699")


def _trap_mean(v, t):
    return np.trapezoid(v, t, axis=0) / (t[-1] - t[0])


def test_coupled_heat_is_the_work_of_the_model_rib_forces(crb):
    """Per sample and face: heat = mu Q v^2 / sqrt(v^2 + v_s^2) + F_G tanh(v_g/v_s) v_g
    (the Coulomb force the integrator applies, mu Q along the regularised direction, times
    the tangential slide v of eq. 24; the eq. 14 drag times the slide v_g at the rib
    mid-height, v_g written out by hand below); its time mean over each roller and the mean
    over the rollers is the run's per-roller heat."""
    from thermobearing.lubricant_properties import air_properties

    b, lub = crb
    dyn, resp = rdh.run_dynamics(b, lub, W, 3000.0, 353.15, UNBALANCE, model="coupled",
                                 warmup_orbits=0.3, orbits=0.5)
    s = resp.series
    g = rib_geometry(b)
    eta = 0.05 * float(lub.dynamic_viscosity(353.15)) + 0.95 * air_properties(
        353.15).dynamic_viscosity
    wc = float(np.mean(s["cage_speed"]))       # _post evaluates at the mean cage speed
    rf = rib_forces(g, s["skew"], s["axial"], inner_speed=W, cage_speed=wc,
                    roller_spin=s["spin"], skew_rate=s["skew_rate"],
                    axial_speed=s["axial_speed"], friction_coefficient=0.05,
                    mixture_viscosity=eta, smooth_sign=SIGN_REGULARISATION)
    f_g = abs(float(lubricant_drag(g, W, wc, eta)[0]))
    vs = SIGN_REGULARISATION
    om = W - wc
    r, hf, hl = 0.5 * g.roller_diameter, g.rib_height, 0.5 * g.roller_length
    ca = np.cos(s["skew"])
    means = []
    for side, q, v, heat in ((-1, rf.normal_left, rf.slide_speed_left, rf.heat_left),
                             (1, rf.normal_right, rf.slide_speed_right, rf.heat_right)):
        vg = (om * (0.5 * g.inner_raceway_diameter + 0.5 * hf) - s["spin"] * ca * (r - 0.5 * hf)
              + s["skew_rate"] * side * hl * ca)
        hand = 0.05 * q * v**2 / np.sqrt(v**2 + vs**2) + f_g * np.tanh(vg / vs) * vg
        np.testing.assert_allclose(heat, hand, rtol=1e-9, atol=1e-12)
        means.append(float(np.mean(_trap_mean(hand, s["t"]))))
    assert np.any(rf.normal_right > 0) and np.any(rf.normal_left > 0)   # rib contacts occur
    assert dyn.heat_left == pytest.approx(means[0], rel=1e-9)
    assert dyn.heat_right == pytest.approx(means[1], rel=1e-9)
    # the slide a thrust share would have: mean |v_i - v_r| at the eq. 11 contact point
    h = g.contact_height()
    v_thrust = ((W - s["cage_speed"][:, None]) * (0.5 * g.inner_raceway_diameter + h)
                - s["spin"] * (r - h))
    assert dyn.rib_slide_speed == pytest.approx(float(np.mean(np.abs(v_thrust))), rel=1e-12)
    _STATE["run"] = dyn


def _ctx(b, lub, temperature, axial_load=0.0, options=None):
    from thermobearing.heat_sources import HeatContext
    from thermobearing.skidding.roller import solve_roller
    from thermobearing.state import OilSupply, OperatingPoint

    if "kin" not in _STATE:
        _STATE["kin"] = solve_roller(b, lub, W, 3000.0, 0.0, 353.15).kinematic_state
    return HeatContext.isothermal(
        temperature, bearing=b, lubricant=lub,
        supply=OilSupply(method="jet", flow_rate=1e-5, inlet_temperature=353.15, level=None),
        operating=OperatingPoint(inner_speed=W, radial_load=3000.0, axial_load=axial_load),
        kinematics=_STATE["kin"],
        options={"rib_friction": {"unbalance_mass": UNBALANCE, **(options or {})}})


@pytest.mark.slow  # 13 s
def test_coupled_heat_source_books_the_model_heat_and_caches_per_state(crb):
    from thermobearing.heat_sources import HEAT_SOURCES

    b, lub = crb
    src = HEAT_SOURCES.get("rib_friction")
    rdh.clear_cache()
    r1 = src(_ctx(b, lub, 353.15))                  # nodes 350 and 355 K: two runs
    assert rdh.cache_info()["runs"] == 2 and r1.details["dynamics_runs"] == 2
    assert r1.details["model"] == "coupled"
    # the same state again, and anywhere inside the same 5 K cell: no run
    r2 = src(_ctx(b, lub, 353.15))
    r3 = src(_ctx(b, lub, 354.9))
    info = rdh.cache_info()
    assert info["runs"] == 2 and info["hits"] == 4
    assert r2.total == r1.total and r2.details["dynamics_runs"] == 0
    # heat = Z x the model's per-roller heat, linearly interpolated between the nodes
    # (hand weights: (353.15 - 350) / 5 = 0.63 on the 355 K node)
    z = b.n_rollers
    n350 = rdh.rib_dynamics_heat(b, lub, W, 3000.0, 350.0, UNBALANCE)
    n355 = rdh.rib_dynamics_heat(b, lub, W, 3000.0, 355.0, UNBALANCE)
    assert n350.runs == 0 and n355.runs == 0
    assert r1.total == pytest.approx(z * (0.37 * n350.heat + 0.63 * n355.heat), rel=1e-12)
    assert r3.total == pytest.approx(z * (0.02 * n350.heat + 0.98 * n355.heat), rel=1e-9)
    assert r1.details["heat_left"] + r1.details["heat_right"] == pytest.approx(r1.total)
    assert sum(p.power for p in r1.force_pairs) == pytest.approx(r1.total, rel=1e-9)
    assert sum(r1.power_by_role.values()) == pytest.approx(r1.total, rel=1e-12)
    # the skew contacts of 0.11 g dominate the drag (hand scale: 24 rollers x ~70 W)
    assert 500.0 < r1.total < 5000.0
    # a new cell adds one node
    src(_ctx(b, lub, 356.0))
    assert rdh.cache_info()["runs"] == 3
    # thrust share: Z mu Q v with Q = F_a / (Z cos theta_f) at the coupled mean rib slide;
    # the paper's bearing has no axial load path (ribs on the inner ring only): warned
    with pytest.warns(ValidityWarning, match="no path"):
        rt = src(_ctx(b, lub, 353.15, axial_load=480.0))
    g = rib_geometry(b)
    q = 480.0 / (z * math.cos(g.rib_angle))
    interp = 0.37 * n350.rib_slide_speed + 0.63 * n355.rib_slide_speed
    assert rt.details["thrust_heat"] == pytest.approx(z * 0.05 * q * interp, rel=1e-12)
    assert rt.total == pytest.approx(r1.total + rt.details["thrust_heat"], rel=1e-12)
    assert rdh.cache_info()["runs"] == 3                   # axial load is not in the key
    with pytest.raises(InputError, match="temperature_step"):
        src(_ctx(b, lub, 353.15, options={"temperature_step": 0.0}))


def test_reduced_option_is_the_reduced_model(crb):
    from thermobearing.heat_sources import HEAT_SOURCES

    b, lub = crb
    red = HEAT_SOURCES.get("rib_friction")(_ctx(b, lub, 355.0, options={"model": "reduced"}))
    n = rdh.rib_dynamics_heat(b, lub, W, 3000.0, 355.0, UNBALANCE, model="reduced")
    assert red.details["model"] == "reduced"
    assert red.total == pytest.approx(b.n_rollers * n.heat, rel=1e-12)
    with pytest.raises(InputError, match="model"):
        rdh.rib_dynamics_heat(b, lub, W, 3000.0, 355.0, model="full")
