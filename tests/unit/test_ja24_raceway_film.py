"""Normal damping of the 6-DOF roller's raceway slices: the line contact's Reynolds squeeze
film at the rolling contact's central film thickness
(thermobearing.skidding.roller_dynamics_raceway_film)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.film import moes_line_central
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_tilt as rt
from thermobearing.skidding.roller import build_model as race_model
from thermobearing.skidding.roller_dynamics_coupled import simulate_coupled
from thermobearing.skidding.roller_dynamics_raceway_film import (
    line_squeeze_coefficient,
    raceway_film_thickness,
)

T_BASE = 353.15


@pytest.fixture(scope="module")
def base():
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                       0.11e-3, temperature=T_BASE, coupling="none")
    return b, lub, m


def test_line_squeeze_coefficient_by_hand():
    """eta = 0.01 Pa s, R_x = 3 mm, h = 1 um: 3 sqrt(2) pi = 13.32865, (R/h)^1.5 =
    3000^1.5 = 164316.8, c' = 13.32865 * 0.01 * 164316.8 = 21901.2 N s/m^2; h^-3/2 scaling;
    bad input names the field."""
    assert line_squeeze_coefficient(0.01, 3e-3, 1e-6) == pytest.approx(21901.2, rel=1e-5)
    assert (line_squeeze_coefficient(0.01, 3e-3, 0.25e-6)
            == pytest.approx(8.0 * 21901.2, rel=1e-5))
    with pytest.raises(InputError, match="gap"):
        line_squeeze_coefficient(0.01, 3e-3, 0.0)
    with pytest.raises(InputError, match="viscosity"):
        line_squeeze_coefficient(-1.0, 3e-3, 1e-6)


def test_film_thickness_is_the_film_modules(base):
    """h_c of each race = Moes' line-contact central film (the roller solver's film model) at
    the unloaded zone's outer load per unit effective length and that race's entrainment
    speed (quasi-static solution), at the race model's eta0, alpha and E'."""
    b, lub, m = base
    qs = m.extras["quasi_static"]
    h_o, h_i = raceway_film_thickness(b, lub, T_BASE, qs)
    assert m.raceway_film == (h_o, h_i)
    rm = race_model(b, lub, T_BASE)
    j = int(np.argmin(qs.outer_load))
    w = float(qs.outer_load[j]) / b.roller_effective_length
    # the unloaded zone: the roller's centrifugal force m omega_c^2 d_m / 2 (79.2 N)
    assert float(qs.outer_load[j]) == pytest.approx(
        b.roller_mass * qs.cage_speed**2 * 0.5 * b.pitch_diameter, rel=0.02)
    for h, ue, r in ((h_o, qs.outer_entrainment_speed[j], rm.radius_outer),
                     (h_i, qs.inner_entrainment_speed[j], rm.radius_inner)):
        ref = float(moes_line_central(float(ue), rm.eta0, rm.alpha, w, 1.0, r,
                                      effective_modulus=rm.effective_modulus))
        assert h == pytest.approx(ref, rel=1e-12)
    # base case: 0.71 / 0.66 um, thinner than the bars' 1 um floor it replaces
    assert 0.6e-6 < h_i < h_o < 0.8e-6


def test_slices_carry_the_law_at_the_film(base):
    """tilt_parameters puts each race's film as the squeeze floor; a slice in Hertz contact
    closing at v carries c' w v more than at rest, c' = line_squeeze_coefficient(eta, R_x,
    h_c) (one code path); "floor" keeps the bars' 1 um, "none" has no squeeze."""
    b, lub, m = base
    tp, gap = rt.tilt_parameters(m, b)
    h_o, h_i = m.raceway_film
    assert tp[rt.TP_FLOOR] == h_o and tp[rt.TP_FLOOR_I] == h_i
    n = int(tp[rt.TP_N])
    w = m.effective_length / n
    r = 0.5 * m.geom.roller_diameter
    ro = 0.5 * m.outer_raceway_diameter
    rx_o = r * ro / (ro - r)
    # the roller pressed 1 um into the outer race, untilted, moving outwards at 1 mm/s
    y0 = 1e-6
    v = 1e-3
    f0, _, _, _ = rt.raceway_slices(tp, y0, 0.0, 0.0, 0.0, float(gap[0]))
    f1, _, _, _ = rt.raceway_slices(tp, y0, v, 0.0, 0.0, float(gap[0]))
    c = n * w * line_squeeze_coefficient(m.pocket_viscosity, rx_o, h_o)
    assert f0 - f1 == pytest.approx(c * v, rel=1e-9)
    # per roller at the base case: 172 N s/m (outer), against 103 N s/m at the 1 um floor
    assert c == pytest.approx(171.6, rel=2e-3)
    mf = rd.build_model(b, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                        0.11e-3, temperature=T_BASE, coupling="none",
                        quasi_static=m.extras["quasi_static"], raceway_damping="floor")
    tpf, _ = rt.tilt_parameters(mf, b)
    assert mf.raceway_film is None and tpf[rt.TP_FLOOR] == tpf[rt.TP_FLOOR_I] == 1e-6
    cf = n * tpf[rt.TP_CO] / 1e-6**1.5
    assert cf == pytest.approx(c * (h_o / 1e-6) ** 1.5, rel=1e-12)
    mn = rd.build_model(b, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                        0.11e-3, temperature=T_BASE, coupling="none",
                        quasi_static=m.extras["quasi_static"], raceway_damping="none")
    tpn, _ = rt.tilt_parameters(mn, b)
    assert tpn[rt.TP_CO] == 0.0 and tpn[rt.TP_CI] == 0.0
    with pytest.raises(InputError, match="raceway_damping"):
        rd.build_model(b, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                       0.11e-3, temperature=T_BASE, coupling="none",
                       quasi_static=m.extras["quasi_static"], raceway_damping="ehl")


def test_damping_rate_inside_the_step(base):
    """The squeeze's rate c/m at the film against the default step (400 per spin period at
    the fastest spin): h c/m well inside RK4's real-axis bound 2.79 (base case ~0.13)."""
    b, _, m = base
    tp, _ = rt.tilt_parameters(m, b)
    n = int(tp[rt.TP_N])
    c_max = n * max(tp[rt.TP_CO] / tp[rt.TP_FLOOR] ** 1.5, tp[rt.TP_CI] / tp[rt.TP_FLOOR_I] ** 1.5)
    step = 2.0 * math.pi / (400.0 * float(np.max(np.abs(m.spin))))
    assert step * c_max / m.roller_mass < 0.5


def test_short_coupled_run_is_finite(base):
    """Half an orbit of the coupled 6-DOF model with the film law: finite PV and slip."""
    b, lub, m = base
    r = simulate_coupled(m, b, lub, n_orbits=0.5, warmup_orbits=0.5)
    assert math.isfinite(r.slip_speed) and r.slip_speed > 0.0
    assert math.isfinite(r.pv_left) and math.isfinite(r.pv_right)
    assert r.pv_left + r.pv_right > 0.0
