"""The loss class of the EHL rolling resistance follows Palmgren's M0 / M1 split.

M0 is the loss without external load, M1 what the load adds. The source books each outer
race's no-load share (the centrifugally seated contacts) as load-independent and the rest
as load-dependent (heat_sources/raceway.py module docstring). CRB 50x75x16 of seed
paper 003, race control, MIL-PRF-23699 jet 2 L/min, everything at 80 degC.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pandas as pd
import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.heat_sources import HeatContext, evaluate, raceway
from thermobearing.losses import loss_breakdown, loss_totals
from thermobearing.lubricant import load_lubricant
from thermobearing.state import KinematicState, OilSupply, OperatingPoint

T_OIL = 353.15
#: the numbers below are those of the isothermal closed forms (the default reduces them by
#: Gupta's phi_T: 215.5 -> 195.3 W, 317.0 -> 281.0 W, no-load share 127.0 -> 117.6 W)
ISOTHERMAL = {"ehl_rolling_resistance": {"thermal_reduction": "none"}}
RPM = math.pi / 30.0


def _context(radial_load: float, speed_rpm: float = 10000.0, name: str = "CRB_50x75x16",
             oil: str = "MIL_PRF_23699", options=None):
    bearing = load_bearing(name)
    lub = load_lubricant(oil)
    op = OperatingPoint(inner_speed=speed_rpm * RPM, radial_load=radial_load, axial_load=0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(bearing, op, lubricant=lub, temperature=T_OIL)
    supply = OilSupply("jet", 2e-3 / 60.0, T_OIL, None)
    return HeatContext.isothermal(T_OIL, bearing=bearing, lubricant=lub, supply=supply,
                                  operating=op, kinematics=ks, options=options or ISOTHERMAL)


def _rolling(ctx):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        return evaluate(["ehl_rolling_resistance"], ctx)[0]


def _by_class(result):
    out = {"load_dependent": 0.0, "load_independent": 0.0}
    for comp, power in result.components.items():
        out[result.loss_class[comp]] += power
    return out


def test_no_load_reference_is_the_centrifugal_seat_by_hand():
    ctx = _context(3000.0)
    b = ctx.bearing
    # m = 7833.4 * pi * 0.006^2 * 0.006 / 4 = 1.3289e-3 kg; omega_m = (1047.2/2)(1 - 0.096)
    # = 473.33 rad/s; F_c = m (d_m/2) omega_m^2 = 1.3289e-3 * 0.03125 * 473.33^2 = 9.304 N
    assert b.roller_mass == pytest.approx(1.3289e-3, rel=1e-4)
    q0 = raceway.no_load_contact_loads(b, ctx.kinematics)
    races = [cs.race for cs in ctx.kinematics.contacts]
    assert races == ["inner", "outer"]
    assert np.all(q0[0] == 0.0)  # nothing presses a roller on the inner race without load
    assert np.allclose(q0[1], 9.304, rtol=1e-3)
    # never above the contact's actual load
    for cs, q in zip(ctx.kinematics.contacts, q0, strict=True):
        assert np.all(q <= np.asarray(cs.normal_load) + 1e-12)


def test_load_independent_share_does_not_move_with_the_load():
    lo, hi = _rolling(_context(500.0)), _rolling(_context(3000.0))
    # the source total is the one booked before the split (215.5 -> 317.0 W, +47 %)
    assert lo.total == pytest.approx(215.5, rel=2e-3)
    assert hi.total == pytest.approx(317.0, rel=2e-3)
    a, b = _by_class(lo), _by_class(hi)
    assert a["load_independent"] == pytest.approx(b["load_independent"], rel=1e-9)
    assert a["load_independent"] == pytest.approx(127.0, rel=2e-3)
    # the growth is all in the load-dependent share (inner race loaded zone, outer contacts
    # pressed above the centrifugal seat)
    assert b["load_dependent"] - a["load_dependent"] == pytest.approx(hi.total - lo.total,
                                                                      rel=1e-9)
    assert set(lo.components) == {"inner rolling resistance, load",
                                  "outer rolling resistance, no load",
                                  "outer rolling resistance, load"}
    # the split is bookkeeping: the force pairs still carry the whole power
    for r in (lo, hi):
        assert sum(p.power for p in r.force_pairs) == pytest.approx(r.total, rel=1e-12)
        assert sum(r.power_by_role.values()) == pytest.approx(r.total, rel=1e-12)


def test_no_load_share_by_hand_on_one_outer_contact():
    ctx = _context(3000.0)
    r = _rolling(ctx)
    cs = ctx.kinematics.contact("outer")
    lub = ctx.lubricant
    eta = float(lub.dynamic_viscosity(T_OIL))
    alpha = float(lub.pressure_viscosity_coefficient(T_OIL))
    u = np.abs(cs.entrainment_speed)  # race control: no sliding, u_e = u_r = u
    rx = np.asarray(cs.reduced_radius_x, float) * np.ones(cs.n_elements)
    length = 2.0 * np.asarray(cs.semi_major, float) * np.ones(cs.n_elements)
    q0 = raceway.no_load_contact_loads(ctx.bearing, ctx.kinematics)[1]
    dh = raceway.rolling_force_paper000(u, eta, alpha, ctx.bearing.effective_modulus, rx,
                                        length)
    ri = raceway.rolling_force_rigid_isoviscous(2.0 * u, eta, q0, rx, length)
    expected = float(np.sum(np.minimum(dh, ri) * u))  # Q_x(F_c) * u per roller
    assert r.components["outer rolling resistance, no load"] == pytest.approx(expected,
                                                                             rel=1e-12)


def test_without_external_load_all_of_it_is_load_independent():
    r = _rolling(_context(0.0))
    c = _by_class(r)
    assert c["load_independent"] > 0.0
    assert c["load_dependent"] == pytest.approx(0.0, abs=1e-9 * c["load_independent"])


def test_loss_totals_columns_follow_the_split():
    rows = []
    for i, load in enumerate((500.0, 3000.0)):
        rows.append(loss_breakdown([_rolling(_context(load))], point=i))
    totals = loss_totals(pd.concat(rows, ignore_index=True))
    indep = totals["load_independent [W]"].to_numpy()
    dep = totals["load_dependent [W]"].to_numpy()
    assert indep[0] == pytest.approx(indep[1], rel=1e-9)
    assert dep[1] > 2.0 * dep[0]


@pytest.mark.parametrize("options", [{}, {"ehl_rolling_resistance": {"rolling_force": "harris"}}])
def test_ball_bearing_split_keeps_the_total(options):
    """QJ1044 (four-point ball), 1800 r/min, 1 kN radial: the mean-chord line form and the
    point-contact form both split into a no-load and a load share that add up to the
    force pairs' power."""
    ctx = _context(1000.0, speed_rpm=1800.0, name="QJ1044", oil="ISO_VG46", options=options)
    r = _rolling(ctx)
    c = _by_class(r)
    assert c["load_independent"] > 0.0 and c["load_dependent"] > 0.0
    assert sum(p.power for p in r.force_pairs) == pytest.approx(r.total, rel=1e-12)
    for comp, power in r.components.items():
        assert power >= -1e-12, comp
