"""The unbalance mass's axial excursion in the coupled roller model (paper 003 eq. 18 line 1,
F_cwx): the geometric centre's offset from the centre of mass of roller + unbalance mass,
its rate and the arms with which the axial forces act on the skew and the spin phase."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.skidding.roller_dynamics_coupled_kernels import unbalance_axial_shift

# paper 003 base case: 0.11 g at the right chamfer of the 6 x 6 mm roller (1.33 g)
M_U = 0.11e-6 * 1e3
ROLLER = 1.33e-3
E_U = 2.5e-3
X_U = 2.5e-3
UNB = np.array([M_U / (ROLLER + M_U), E_U, X_U, M_U])


def _mass_position(a: float, psi: float) -> tuple[float, float]:
    """(r_x, r_z) of the unbalance mass in the cage frame, written out independently: the
    point (x_u, e cos psi, e sin psi) of the roller turned by the skew ``a`` about the radial
    axis with rib.py's convention (a skew rate moves the end at x by -a' x along z)."""
    rot = np.array([[math.cos(a), 0.0, math.sin(a)],
                    [0.0, 1.0, 0.0],
                    [-math.sin(a), 0.0, math.cos(a)]])
    r = rot @ np.array([X_U, E_U * math.cos(psi), E_U * math.sin(psi)])
    return float(r[0]), float(r[2])


def test_no_unbalance_gives_no_shift() -> None:
    assert unbalance_axial_shift(np.zeros(4), 0.01, 50.0, 1.0, 15000.0) == (0.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize("psi", [0.0, 0.7, 2.0, 4.5])
def test_unskewed_roller_has_its_centre_of_mass_on_the_geometric_centre_axially(
        psi: float) -> None:
    shift, _, r_z, dpsi = unbalance_axial_shift(UNB, 0.0, 0.0, psi, 15000.0)
    assert shift == 0.0
    assert dpsi == 0.0
    assert r_z == pytest.approx(E_U * math.sin(psi), rel=1e-15)


@pytest.mark.parametrize(("a", "psi"), [(0.0105, 0.3), (-0.0105, 1.9), (0.004, 3.6),
                                        (-0.02, 5.5)])
def test_shift_arms_and_rate_are_the_mass_kinematics(a: float, psi: float) -> None:
    """shift = k (r_x - x_u); r_z = dr_x/da; dpsi = dr_x/dpsi; rate = k (r_z a' + dpsi psi'),
    each against the rotated point and central differences of it."""
    k = UNB[0]
    ad, w = 37.0, 15000.0
    shift, rate, r_z, dpsi = unbalance_axial_shift(UNB, a, ad, psi, w)
    r_x, r_z_ref = _mass_position(a, psi)
    assert shift == pytest.approx(k * (r_x - X_U), rel=1e-12, abs=1e-22)
    assert r_z == pytest.approx(r_z_ref, rel=1e-12)
    h = 1e-7
    d_a = (_mass_position(a + h, psi)[0] - _mass_position(a - h, psi)[0]) / (2 * h)
    d_p = (_mass_position(a, psi + h)[0] - _mass_position(a, psi - h)[0]) / (2 * h)
    assert r_z == pytest.approx(d_a, rel=1e-6)
    assert dpsi == pytest.approx(d_p, rel=1e-6, abs=1e-15)
    # the rate along a motion a(t) = a + a' t, psi(t) = psi + w t
    dt = 1e-9
    s_p = unbalance_axial_shift(UNB, a + ad * dt, ad, psi + w * dt, w)[0]
    s_m = unbalance_axial_shift(UNB, a - ad * dt, ad, psi - w * dt, w)[0]
    assert rate == pytest.approx((s_p - s_m) / (2 * dt), rel=1e-5)


def test_size_of_the_excursion_at_the_rib_skew() -> None:
    """At the 0.6 deg at which the base-case roller reaches its rib the geometric centre sits
    up to k e sin(a) = 1.9 um off the centre of mass axially -- of the size of the rib's Hertz
    approach (~1 um at 100 N), so not negligible against the 15 um half clearance."""
    a = math.radians(0.6)
    shift = unbalance_axial_shift(UNB, a, 0.0, 0.5 * math.pi, 0.0)[0]
    assert shift == pytest.approx(UNB[0] * (E_U * math.sin(a) - X_U * (1 - math.cos(a))),
                                  rel=1e-12)
    assert 1.5e-6 < shift < 2.5e-6


def test_runaway_message_names_the_geometric_centre() -> None:
    """The state's X is the centre of mass of roller + unbalance mass; the 'unstable coupled
    motion' message reports the geometric centre's X (the one the rib sees)."""
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding import roller_dynamics as rd
    from thermobearing.skidding.roller_dynamics_coupled import (
        N_ROLLER_STATES,
        _unbalance_constants,
        _unstable_state,
    )

    bearing = load_bearing("CRB_50x75x16")
    m = rd.build_model(bearing, load_lubricant("MIL_PRF_23699"), 3141.6, 3000.0, 0.11e-3,
                       temperature=353.15, coupling="none")
    unb = np.array(_unbalance_constants(m))
    assert unb[0] == pytest.approx(0.11e-3 / (m.roller_mass + 0.11e-3), rel=1e-12)
    z_n = len(m.azimuth)
    n = N_ROLLER_STATES
    y = np.zeros(z_n * n + 4)
    y[7:z_n * n:n] = 15000.0
    y[0] = 12e-6                          # roller 0: X_c, skew 0.6 deg, psi = pi/2
    y[2] = math.radians(0.6)
    y[6] = 0.5 * math.pi
    state = _unstable_state(m, y, z_n, 0.0, 0, 1400.0, "table")
    shift = unbalance_axial_shift(unb, y[2], 0.0, y[6], 0.0)[0]
    assert state["roller"] == 0
    assert state["roller_axial"] == pytest.approx(12e-6 - shift, rel=1e-12)
    assert 1.5e-6 < shift < 2.5e-6
