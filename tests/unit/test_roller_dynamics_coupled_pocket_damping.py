"""Units of the coupled roller dynamics' pocket damping c_z [N s/m] (paper 003 eq. 18): the
raceway tractions' resistance to the roller centre's circumferential speed z', pinned
against hand finite differences of paper 000's traction model and of the traction table."""

import math

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_coupled as rc
from thermobearing.skidding.roller import build_model as race_model
from thermobearing.skidding.roller_dynamics_coupling import _race_eval
from thermobearing.skidding.roller_dynamics_table import build_traction_table, table_eval

SPEED = 30000 * math.pi / 30


@pytest.fixture(scope="module")
def base():
    """Paper 003 base case (30000 r/min, 3 kN, 0.11 g, MIL-PRF-23699 at 80 degC): the
    quasi-static state the coupled integration starts from, and paper 000's model."""
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.11e-3, coupling="none")
    rm = race_model(b, lub, m.extras.get("temperature", 353.15))
    return m, rm


def _hand_contacts(rm, m, dz):
    """(inner, outer contact forces, paper 000's evaluate at the state) of every roller whose
    centre moves at dz [m/s] along the orbit relative to the cage, by hand from the contact
    forces: the roller surface speed along the inner race velocity becomes u_roll + dz,
    along the outer race velocity (opposite in the cage frame) u_roll - dz; the inner and
    outer loads as in evaluate, with the model's inlet-heating reduction of the rolling
    force (``inlet_heating``) where it has one, as evaluate applies it."""
    half = 0.5 * rm.roller_diameter
    w, wc = m.spin, m.cage_speed
    e0 = _race_eval(rm, m, w, wc)
    u_ri = np.full_like(w, 0.5 * (rm.pitch_diameter - rm.roller_diameter) * (m.inner_speed - wc))
    u_ro = np.full_like(w, 0.5 * (rm.pitch_diameter + rm.roller_diameter) * wc)
    common = dict(eta0=rm.eta0, alpha=rm.alpha, traction_law=rm.traction_law,
                  temperature=rm.temperature, rolling_force=rm.rolling_force,
                  oil_layer=rm.oil_layer)
    if rm.inlet_heating is not None:
        common["inlet_heating"] = rm.inlet_heating
    fi = rm.contact_forces(m.inner_load, rm.length, rm.radius_inner, rm.effective_modulus,
                           u_ri, half * w + dz, film=rm.film_inner, **common)
    fo = rm.contact_forces(e0.q_o, rm.length, rm.radius_outer, rm.effective_modulus,
                           u_ro, half * w - dz, film=rm.film_outer, **common)
    return fi, fo, e0


def _orbital_force(rm, m, dz):
    """(net orbital force F_d, shear-only part S_i - S_o) [N] of every roller whose centre
    moves at dz [m/s] along the orbit relative to the cage, by hand (_hand_contacts; the
    dz = 0 case must reproduce paper 000's evaluate)."""
    half = 0.5 * rm.roller_diameter
    fi, fo, e0 = _hand_contacts(rm, m, dz)
    f_d = fi.orbital_force(rm.radius_inner / half) - fo.orbital_force(rm.radius_outer / half)
    return f_d, fi.shear_force - fo.shear_force, e0


def _refresh_most_loaded(m, rm, body_force):
    """The in-kernel table refresh (_refresh_roller) of the most loaded roller on a table
    around its spin: (half roller diameter [m], roller index, spin [rad/s], N_i [N], cage
    speed [rad/s], table, linearisation row, c_z [N s/m])."""
    half = 0.5 * rm.roller_diameter
    j = int(np.argmax(m.inner_load))
    w, n_i, wc = float(m.spin[j]), float(m.inner_load[j]), float(m.cage_speed)
    tab = build_traction_table(rm, SPEED, body_force, (w - 400.0, w + 400.0), n_i, wc)
    n = rc.N_ROLLER_STATES
    y = np.zeros(n + 4)
    y[7] = w
    y[n + 1] = wc
    lin = np.zeros((1, 7))
    w0, q_o, c_z = np.zeros(1), np.zeros(1), np.zeros(1)
    st = rc._refresh_roller(0, y, 1, np.zeros(1), np.array([0.0, 2.0 * math.pi]),
                            np.array([n_i, n_i]), tab.spin0, tab.spin_step, tab.loads,
                            tab.cage, tab.values, lin, w0, wc, q_o, c_z, half)
    assert st == 0
    return half, j, w, n_i, wc, tab, lin, c_z


def test_pocket_damping_is_the_traction_slope_against_the_pocket_speed(base):
    """c_z from the spin slope dS/d omega (what both refresh paths have) equals minus the
    slope of the raceways' net orbital force against the pocket speed z' [N s/m], computed
    by hand: 6.41 N s/m for the most loaded roller (6.45 with the isothermal eq. 35; not
    the 0.0194 of dS/d omega, N s/rad, the coupled model used before 2026-11-23)."""
    m, rm = base
    half = 0.5 * rm.roller_diameter
    w = m.spin
    dw = 1e-4 * np.maximum(np.abs(w), 1.0)
    e0 = _race_eval(rm, m, w, m.cage_speed)
    e1 = _race_eval(rm, m, w + dw, m.cage_speed)
    slope = (e1.roller_eq + e1.friction - e0.roller_eq - e0.friction) / dw   # N s/rad
    c_z = np.array([rc.pocket_damping(float(k), half) for k in slope])
    f0, s0, ev = _orbital_force(rm, m, 0.0)
    assert np.array_equal(f0, ev.pocket)                  # the hand forces are evaluate's
    dz = 1e-4                                             # m/s
    f1, s1, _ = _orbital_force(rm, m, dz)
    shear_hand = -(s1 - s0) / dz
    full_hand = -(f1 - f0) / dz
    loaded = m.inner_load > 600.0
    assert np.sum(loaded) == 3
    # the shear part: the same traction slope, only the finite-difference steps differ
    assert c_z == pytest.approx(shear_hand, rel=1e-3)
    # with the film-pressure (rolling) share of F_d, the part pocket_damping leaves out:
    # isothermal eq. 35 (slide-free) measured -0.8 / -1.0 / -2.7 % at N_i = 777 / 691 /
    # 445 N, -20 % unloaded (0.046 against 0.057 N s/m); with the default Gupta inlet
    # heating (since 2026-11-24) phi_T falls with the slide-to-roll ratio, so the rolling
    # force falls as the pocket speed raises the slide and its share adds to the damping
    # of the loaded rollers: +0.06 / +0.10 / +0.68 %, rollers without inner load -22 %
    # (0.0417 against 0.0536 N s/m)
    assert c_z[loaded] == pytest.approx(full_hand[loaded], rel=0.02)
    assert np.all(full_hand > 0.7 * c_z)
    unloaded = m.inner_load <= 0.0
    assert np.sum(unloaded) > 0
    assert np.all(full_hand[unloaded] <= c_z[unloaded])
    j = int(np.argmax(m.inner_load))
    assert 5.0 < c_z[j] < 8.0 and c_z[j] == pytest.approx(-slope[j] / half, rel=1e-12)
    # a slope driving the motion gives no damping (never negative damping)
    assert rc.pocket_damping(0.01, half) == 0.0


def test_table_refresh_pocket_damping_units(base):
    """The in-kernel table refresh (_refresh_roller) sets c_z [N s/m] to minus the table
    shear's slope against a sliding-speed perturbation dV of the roller surface, dS/dV
    (central difference here, forward difference of the spin there)."""
    m, rm = base
    half, j, w, n_i, wc, tab, lin, c_z = _refresh_most_loaded(m, rm, lambda _: 0.0)
    dv = 3e-3                                             # m/s of surface speed
    s_p = table_eval(tab.spin0, tab.spin_step, tab.loads, tab.cage, tab.values,
                     w + dv / half, n_i, wc)
    s_m = table_eval(tab.spin0, tab.spin_step, tab.loads, tab.cage, tab.values,
                     w - dv / half, n_i, wc)
    assert s_p[3] == 0 and s_m[3] == 0
    ds_dv = (s_p[0] - s_m[0]) / (2.0 * dv)                # N s/m
    assert c_z[0] == pytest.approx(-ds_dv, rel=1e-2)
    assert 5.0 < c_z[0] < 8.0


def _raceway_shear(rm, m, dz):
    """S = S_i + S_o [N] on every roller's surface (the spin equation's raceway shear) with
    the roller centre moving at dz [m/s] along the orbit, by hand as in _orbital_force."""
    fi, fo, e0 = _hand_contacts(rm, m, dz)
    return fi.shear_force + fo.shear_force, e0


def test_spin_pocket_coupling_is_the_shear_slope_against_the_pocket_speed(base):
    """dS/dz' of the spin equation (spin_pocket_coupling, from each contact's spin slope)
    equals a central difference of paper 000's shear against the pocket speed by hand, for
    every roller; the summed shear's slope alone cannot give it (the two contacts' slopes
    enter with opposite signs): most loaded roller -0.30 N s/m against c_z = 6.45."""
    m, rm = base
    half = 0.5 * rm.roller_diameter
    dv = 1e-3
    s_p, e0 = _raceway_shear(rm, m, dv)
    s_m, _ = _raceway_shear(rm, m, -dv)
    s_0, _ = _raceway_shear(rm, m, 0.0)
    assert np.allclose(s_0, e0.roller_eq + e0.friction, rtol=1e-9, atol=1e-12)
    by_hand = (s_p - s_m) / (2.0 * dv)
    dw = 1e-4 * m.spin
    e1 = _race_eval(rm, m, m.spin + dw, m.cage_speed)
    ds = (e1.roller_eq + e1.friction - e0.roller_eq - e0.friction) / dw
    dso = (e1.outer.shear_force - e0.outer.shear_force) / dw
    got = np.array([rc.spin_pocket_coupling(float(a), float(o), half)
                    for a, o in zip(ds, dso, strict=True)])
    scale = np.max(np.abs(by_hand))
    assert np.max(np.abs(got - by_hand)) < 2e-3 * max(scale, 1.0)
    j = int(np.argmax(m.inner_load))
    assert -0.35 < got[j] < -0.25
    assert abs(got[j]) < 0.1 * rc.pocket_damping(float(ds[j]), half)


def test_table_refresh_spin_pocket_coupling(base):
    """The in-kernel table refresh fills lin[:, 6] = dS/dz' from the table's outer-shear
    column, equal to the hand slope (the spin on a table node here; measured -0.30237 against
    -0.30237 N s/m; without the unbalance's 6.5 N body force in the table it was -0.359: the
    value is the difference of two spin slopes of ~6.4 N s/m each, sensitive to 1 %
    changes of either)."""
    from thermobearing.skidding.roller_dynamics_coupling import unbalance_orbital_force

    m, rm = base
    half, j, w, n_i, wc, tab, lin, c_z = _refresh_most_loaded(
        m, rm, lambda c: unbalance_orbital_force(m, c))
    s_p, _ = _raceway_shear(rm, m, 1e-3)
    s_m, _ = _raceway_shear(rm, m, -1e-3)
    hand = (s_p[j] - s_m[j]) / 2e-3
    assert abs(lin[0, 6] - hand) < 2e-3 * c_z[0]
