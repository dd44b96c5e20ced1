"""The roller's radial position and tilt in the coupled model (paper 003 eq. 18, 6 DOF):
raceway slices, tilt moments, the rib approach's tilt term and the decoupled limit
(thermobearing.skidding.roller_dynamics_tilt)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.hertz import line_contact_stiffness
from thermobearing.lubricant import load_lubricant
from thermobearing.rib import F_Q, face_values
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_coupled as rc
from thermobearing.skidding import roller_dynamics_tilt as rt
from thermobearing.skidding.roller_dynamics_rhs import _params, _rhs_ring


def _tp(xs, ks=1e8, drop=None, co=0.0, ci=0.0, floor=1e-6, jt=7e-9, mass=1.3e-3, jp=6e-9,
        tq=1.5e-3, xu=0.0, mue=0.0, mu=0.0, dm2=0.03, rh=0.297):
    n = len(xs)
    tp = np.zeros(rt.TP_HEAD + 2 * n)
    tp[rt.TP_JT], tp[rt.TP_MASS], tp[rt.TP_JP], tp[rt.TP_TQ] = jt, mass, jp, tq
    tp[rt.TP_XU], tp[rt.TP_MUE], tp[rt.TP_MU], tp[rt.TP_DM2] = xu, mue, mu, dm2
    tp[rt.TP_KS], tp[rt.TP_CO], tp[rt.TP_CI], tp[rt.TP_FLOOR] = ks, co, ci, floor
    tp[rt.TP_RH] = rh
    tp[rt.TP_FLOOR_I] = floor
    tp[rt.TP_N] = n
    tp[rt.TP_HEAD:rt.TP_HEAD + n] = xs
    tp[rt.TP_HEAD + n:] = 0.0 if drop is None else drop
    return tp


@pytest.fixture(scope="module")
def base():
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                       0.11e-3, temperature=353.15, coupling="none", tilt=True)
    return b, lub, m


def test_three_slices_by_hand():
    """Slices at -1, 0, +1 mm, k_s = 1e8 N/m^(10/9); y_r = 1 um, tilt 1e-3 rad: outer
    approaches 0, 1, 2 um -> 1e8 (1e-6)^(10/9) = 21.544 N and 1e8 (2e-6)^(10/9) = 46.538 N
    inwards, the second at +1 mm: moment -0.046538 N m; the inner gap 10 um stays open."""
    tp = _tp([-1e-3, 0.0, 1e-3])
    f, mt, n_o, n_i = rt.raceway_slices(tp, 1e-6, 0.0, 1e-3, 0.0, 10e-6)
    q1 = 1e8 * (1e-6) ** (10.0 / 9.0)
    q2 = 1e8 * (2e-6) ** (10.0 / 9.0)
    assert q1 == pytest.approx(21.544, rel=1e-4)
    assert q2 == pytest.approx(46.538, rel=1e-4)
    assert f == pytest.approx(-(q1 + q2), rel=1e-12)
    assert mt == pytest.approx(-1e-3 * q2, rel=1e-12)
    assert n_o == pytest.approx(q1 + q2, rel=1e-12) and n_i == 0.0
    # pressed inwards past the inner gap (-12 um, gap 10 um): inner approaches 2 um each
    f, mt, n_o, n_i = rt.raceway_slices(tp, -12e-6, 0.0, 0.0, 0.0, 10e-6)
    assert n_o == 0.0 and f == pytest.approx(3 * q2, rel=1e-12) and mt == pytest.approx(0.0)


def test_slices_sum_to_palmgren_line_law(base):
    """A uniform approach d of all slices carries K_l(L_e) d^(10/9) (the slice law sums to
    Palmgren's line contact, hertz.line_contact_stiffness), with no tilt moment."""
    b, _, m = base
    tp, _ = rt.tilt_parameters(m, b)
    d = 3e-6
    f, mt, n_o, n_i = rt.raceway_slices(tp, d, 0.0, 0.0, 0.0, 50e-6)
    k_l = float(line_contact_stiffness(m.effective_length))
    assert n_o == pytest.approx(k_l * d ** (10.0 / 9.0), rel=1e-12)
    assert f == pytest.approx(-n_o, rel=1e-12)
    assert abs(mt) < 1e-12 * n_o * m.effective_length


def test_inner_gap_reproduces_quasi_static_loads(base):
    """The ring's play fitted to the quasi-static solution: a roller resting at its
    azimuth's quasi-static outer approach carries that azimuth's inner load (load zone) and
    has an open inner gap outside it."""
    b, _, m = base
    tp, gap = rt.tilt_parameters(m, b)
    y0 = rt.start_states(m, tp, gap)
    for j in range(len(m.azimuth)):
        _, _, n_o, n_i = rt.raceway_slices(tp, y0[j, 0], 0.0, 0.0, 0.0, gap[j])
        assert n_o == pytest.approx(m.outer_load[j], rel=1e-9)
        if m.inner_load[j] > 100.0:     # the two fitted azimuths exactly, the others close
            assert n_i == pytest.approx(m.inner_load[j], rel=0.03)
        if m.inner_load[j] == 0.0:
            assert n_i == 0.0 and gap[j] > 0.0
    # the fitted play (mean of the gaps at 0 and 180 deg) is the bearing's P_d/2 = 15 um
    assert m.azimuth[0] == 0.0 and m.azimuth[12] == pytest.approx(math.pi)
    assert 0.5 * (gap[0] + gap[12]) == pytest.approx(0.5 * b.diametral_clearance, rel=0.01)


def test_squeeze_film_of_a_closing_slice():
    """A closing outer gap h = 4 um (> floor) at 0.1 m/s: c_o v / h^1.5 inwards; opening:
    no force (cavitation); in contact the gap is the floor."""
    tp = _tp([0.0], ks=1e8, co=2.0, ci=3.0, floor=1e-6)
    f, _, _, _ = rt.raceway_slices(tp, -4e-6, 0.1, 0.0, 0.0, 1.0)
    assert f == pytest.approx(-2.0 * 0.1 / (4e-6) ** 1.5, rel=1e-12)
    f, _, _, _ = rt.raceway_slices(tp, -4e-6, -0.1, 0.0, 0.0, 1.0)
    assert f == pytest.approx(3.0 * 0.1 / (1.0 - 4e-6) ** 1.5, rel=1e-12)  # inner only
    f, _, _, _ = rt.raceway_slices(tp, 1e-6, 0.1, 0.0, 0.0, 1.0)
    assert f == pytest.approx(-(1e8 * (1e-6) ** (10.0 / 9.0) + 2.0 * 0.1 / (1e-6) ** 1.5),
                              rel=1e-12)
    f, _, _, _ = rt.raceway_slices(tp, -4e-6, -0.1, 0.0, 0.0, 6e-6)   # inner gap 2 um
    assert f == pytest.approx(3.0 * 0.1 / (2e-6) ** 1.5, rel=1e-12)


def test_tilt_moments_by_hand():
    """Free roller (no slice in contact): the rib's axial force F_x acts on the tilt with
    t_q F_x; the unbalance's spinning force at psi = 0 is -m_u e_u Omega^2 radially at x_u;
    the orbital force m_u omega_c^2 d_m/2 and the roller's m omega_c^2 d_m/2 act outwards;
    the gyroscopic moment J_p Omega alpha' on the tilt, -J_p Omega alpha_e' on the skew."""
    jt, mass, jp, tq = 7e-9, 1.3e-3, 6e-9, 1.5e-3
    tp = _tp([0.0], jt=jt, mass=mass, jp=jp, tq=tq)
    ydd, edd, gyro = rt.tilt_rates(tp, -5e-6, 0.0, 0.0, 0.0, 40e-6, 100.0, 0.0, 0.0, 0.0,
                                   0.0, 0.0)
    assert ydd == 0.0 and gyro == 0.0
    assert edd == pytest.approx(tq * 100.0 / jt, rel=1e-14)
    xu, mue, mu, dm2, w, wc = 2.5e-3, 1.1e-4 * 2.5e-3, 1.1e-4, 0.03125, 15000.0, 1400.0
    tp = _tp([0.0], jt=jt, mass=mass, jp=jp, tq=tq, xu=xu, mue=mue, mu=mu, dm2=dm2)
    ydd, edd, gyro = rt.tilt_rates(tp, -5e-6, 0.0, 0.0, 2.0, 40e-6, 0.0, 0.0, 0.0, w, wc,
                                   100.0)
    omega = wc - w
    f_cw = -mue * omega**2
    f_orb = mu * wc**2 * dm2
    assert f_cw == pytest.approx(-50.86, rel=1e-3)      # 0.11 g at 2.5 mm, 13600 rad/s
    assert ydd * mass == pytest.approx(mass * wc**2 * dm2 + f_orb + f_cw, rel=1e-12)
    assert edd * jt == pytest.approx(xu * (f_cw + f_orb) + jp * omega * 100.0, rel=1e-12)
    assert gyro * jt == pytest.approx(-jp * omega * 2.0, rel=1e-12)
    # the approach's second-order tilt term: a right-face normal force of 300 N (axial
    # force -300 cos(0.3 deg) N, F_R - F_L the same) at 3e-3 rad tilt, arm 0.297 m x
    # sin(3e-3): -0.26730 N m (restoring)
    tp = _tp([0.0], jt=jt, mass=mass, jp=jp, tq=tq, rh=0.297)
    f_x = -300.0 * math.cos(math.radians(0.3))
    _, edd, _ = rt.tilt_rates(tp, -5e-6, 0.0, 3e-3, 0.0, 40e-6, 0.0, f_x, 0.0, 0.0, 0.0,
                              0.0)
    assert edd * jt == pytest.approx(-0.26730, rel=1e-4)
    dca, rate = rt.tilt_clearance(tp, 3e-3, 20.0)
    assert dca == pytest.approx(0.297 * (1.0 - math.cos(3e-3)), rel=1e-12)
    assert dca == pytest.approx(1.3365e-6, rel=1e-4)
    assert rate == pytest.approx(0.297 * math.sin(3e-3) * 20.0, rel=1e-12)


def test_rib_approach_tilt_term(base):
    """The tilt moves the end-face contact point axially: for the paper's sphere the right
    face's support along its rib normal grows by sin(theta_f)(R_s - L_r/2) alpha_e (the
    sphere centre at x = -(R_s - L_r/2) moves radially by -(R_s - L_r/2) alpha_e), the left
    face's falls by as much: the axial shift t_q alpha_e with t_q = tan(theta_f)(R_s -
    L_r/2) = 1.5551 mm/rad at the base case (0.3 deg, 300 mm, 6 mm roller)."""
    b, _, m = base
    g = m.geom
    tp, _ = rt.tilt_parameters(m, b)
    tq = tp[rt.TP_TQ]
    assert tq == pytest.approx(math.tan(math.radians(0.3)) * 0.297, rel=1e-12)
    assert tq == pytest.approx(1.5551e-3, rel=1e-4)
    ct, st = math.cos(g.rib_angle), math.sin(g.rib_angle)
    rc0 = 0.5 * g.inner_raceway_diameter + 0.5 * g.roller_diameter
    hl, rs = 0.5 * g.roller_length, g.crown_radius

    def exact(side, ae):
        # the tilted sphere's centre (x0 cos ae, x0 sin ae, 0): depth past the rib cone
        x0 = side * (hl - rs)
        cx, cy = x0 * math.cos(ae), x0 * math.sin(ae)
        return side * ct * cx - st * (abs(rc0 + cy) - rc0) + rs

    ae = 1e-4
    left0, right0 = g.approach(0.0, 0.0)
    left, right = g.approach(0.0, tq * ae)
    assert right - right0 == pytest.approx(ct * tq * ae, rel=1e-12)
    assert right - right0 == pytest.approx(0.15551e-6, rel=1e-3)
    # with the symmetric second-order term the model's approach is the exact tilted
    # sphere's to ~1e-5 at 1e-4 and 3e-3 rad (the residue is of third order)
    for ae in (1e-4, 3e-3):
        sym = ct * tp[rt.TP_RH] * (1.0 - math.cos(ae))
        for side in (-1, 1):
            model = side * ct * tq * ae + sym
            assert model == pytest.approx(exact(side, ae) - exact(side, 0.0), rel=2e-5)
    # face_values: dca acts on the right face as +dca of axial shift, on the left as -dca
    gp = g.params()
    for side in (-1, 1):
        q_d = face_values(gp, side, 0.012, side * 2e-6, 0.0, 0.0, 0.0, 0.0, 0.05, 0.0, 0.0,
                          1.3e-6)[F_Q]
        q_x = face_values(gp, side, 0.012, side * 3.3e-6, 0.0, 0.0, 0.0, 0.0, 0.05, 0.0,
                          0.0)[F_Q]
        assert q_d > 0.0 and q_d == pytest.approx(q_x, rel=1e-9)


def test_rib_axial_force_and_power_in_the_shifted_coordinate(base):
    """_rhs_ring evaluates the faces at X + t_q alpha_e (speed X' + t_q alpha_e') and
    returns their axial force, the tilt's rib moment divided by t_q; the faces' forces
    equal those of a roller shifted by t_q alpha_e without tilt, so the rib's power on
    (X, alpha_e) is F_x (X' + t_q alpha_e'), the shifted face's."""
    b, _, m = base
    p = _params(m)
    tq = 1.5551e-3
    a, ad, spin, x, xd, ae, aed = 0.011, 30.0, 14900.0, 8e-6, 0.05, 2e-3, 25.0
    r_t = _rhs_ring(p, x, xd, a, ad, 0.0, 0.0, 0.0, 80.0, spin, 0.3, 0.0, 0.0, 0.0,
                    tq * ae, tq * aed, 0.0, 0.0)
    r_s = _rhs_ring(p, x + tq * ae, xd + tq * aed, a, ad, 0.0, 0.0, 0.0, 80.0, spin, 0.3,
                    0.0, 0.0, 0.0)
    assert r_t[8] != 0.0                             # the right face is in contact
    assert r_t[8] == r_s[8]
    assert r_t[3] == r_s[3] and r_t[6] == r_s[6]     # skew and spin moments
    assert r_t[9] < 0.0 and r_t[9] == r_s[9]          # F_x,R - F_x,L (right face in contact)
    r_0 = _rhs_ring(p, x, xd, a, ad, 0.0, 0.0, 0.0, 80.0, spin, 0.3, 0.0, 0.0, 0.0)
    assert r_0[8] != r_t[8]


def test_slice_oscillator_conserves_energy():
    """Radial + tilt motion on elastic slices (no squeeze, unbalance, rib or gyroscopic
    term, no centrifugal load): the slice forces and the tilt moment derive from one
    potential sum k_s (9/19) d^(19/9), so kinetic + elastic energy is constant along an
    RK4 trajectory with contacts opening and closing (to 1e-6 relative)."""
    xs = np.linspace(-2.5e-3, 2.5e-3, 11)
    tp = _tp(xs, ks=3.7e7, jt=7e-9, mass=1.33e-3, jp=0.0, tq=0.0)
    gap = 10e-6

    def energy(s):
        yr, yd, ae, ad = s
        u = yr + ae * xs
        e = 0.5 * 1.33e-3 * yd**2 + 0.5 * 7e-9 * ad**2
        for d in (u, -u - gap):
            dp = np.maximum(d, 0.0)
            e += np.sum(3.7e7 * 9.0 / 19.0 * dp ** (19.0 / 9.0))
        return e

    def f(s):
        ydd, edd, _ = rt.tilt_rates(tp, s[0], s[1], s[2], s[3], gap, 0.0, 0.0, 0.0, 0.0,
                                    0.0, 0.0)
        return np.array([s[1], ydd, s[3], edd])

    s = np.array([2e-6, -0.3, 1e-3, 50.0])
    e0 = energy(s)
    h = 2e-8
    for _ in range(20000):
        k1 = f(s)
        k2 = f(s + 0.5 * h * k1)
        k3 = f(s + 0.5 * h * k2)
        k4 = f(s + h * k3)
        s = s + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    assert energy(s) == pytest.approx(e0, rel=1e-6)


def test_decoupled_tilt_reproduces_the_five_dof_run(base, monkeypatch):
    """With the tilt's couplings to the other DOFs cut (t_q = 0, R_s - L_r/2 = 0, J_p = 0) the
    coupled run with tilt=True follows the tilt=False trajectory exactly: the tilt block is
    added without touching the default path. With them on, the run is finite, the rollers tilt
    (rms 0.1-10 mrad) and move radially within the play."""
    b, lub, m = base
    m_off = rd.build_model(b, lub, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                           0.11e-3, temperature=353.15, coupling="none",
                           quasi_static=m.extras["quasi_static"], tilt=False)
    opts = dict(n_orbits=0.2, warmup_orbits=0.1)
    r_off = rc.simulate_coupled(m_off, b, lub, **opts)
    orig = rt.tilt_parameters

    def cut(mm, bearing, n_slices=rt.TILT_SLICES):
        tp, gap = orig(mm, bearing, n_slices)
        tp[rt.TP_TQ] = 0.0
        tp[rt.TP_RH] = 0.0
        tp[rt.TP_JP] = 0.0
        return tp, gap

    monkeypatch.setattr(rc, "tilt_parameters", cut)
    r_cut = rc.simulate_coupled(m, b, lub, **opts)
    assert r_cut.pv_left == r_off.pv_left and r_cut.slip_speed == r_off.slip_speed
    assert np.array_equal(r_cut.series["skew"], r_off.series["skew"])
    monkeypatch.setattr(rc, "tilt_parameters", orig)
    r_on = rc.simulate_coupled(m, b, lub, **opts)
    tilt = r_on.series["tilt"]
    assert np.all(np.isfinite(tilt)) and np.all(np.isfinite(r_on.series["radial"]))
    rms = float(np.sqrt(np.mean(tilt**2)))
    assert 1e-4 < rms < 1e-2
    _, gap = rt.tilt_parameters(m, b)
    assert np.max(r_on.series["radial"]) < 10e-6
    assert np.min(r_on.series["radial"]) > -np.max(gap) - 2e-6
    assert r_on.series["end_state"].size == r_off.series["end_state"].size + 4 * len(m.azimuth)


@pytest.mark.parametrize("state", [
    (0.011, 8e-6, 2e-3, 30.0, 0.05, 25.0, 14900.0),
    (-0.0105, -9e-6, -3e-3, -80.0, -0.2, 40.0, 12000.0),
    (0.012, 5e-6, 4e-3, 10.0, 0.1, -60.0, 16000.0),
])
def test_rib_power_balance_with_tilt(base, state):
    """Per face the rib forces' power on the roller's DOFs (X', alpha', alpha_e', spin) and
    on the rib, the booked heat and the elastic power Q d delta/dt (delta with the tilt's
    axial shift and its symmetric second-order term, finite differences in alpha and alpha_e)
    add up to zero (measured 4e-11..3e-10 of the heat; 2e-6..8e-6 with the tilt moment of
    the normal forces alone): the tilt moment t_q F_x + (F_x,R - F_x,L)(R_s - L_r/2) sin alpha_e of
    :func:`tilt_rates` is the virtual work of the faces as :func:`_rhs_ring` evaluates them
    (each face at X + t_q alpha_e + K (R_s - L_r/2)(1 - cos alpha_e), its axial speed
    including that point's rate). The rib's power and the heat are those of the face kernel
    (test_prop20_rib._powers)."""
    from tests.unit.test_prop20_rib import _powers

    b, _, m = base
    g = m.geom
    p = _params(m)
    tp, _ = rt.tilt_parameters(m, b)
    tq = tp[rt.TP_TQ]
    a, x, ae, ad, xd, aed, spin = state
    om = m.inner_speed - m.cage_speed
    dca, dca_rate = rt.tilt_clearance(tp, ae, aed)
    r = _rhs_ring(p, x, xd, a, ad, 0.0, 0.0, 0.0, 80.0, spin, 0.3, 0.0, 0.0, 0.0, tq * ae,
                  tq * aed, dca, dca_rate)
    tp0 = tp.copy()
    tp0[rt.TP_XU] = tp0[rt.TP_MUE] = tp0[rt.TP_MU] = tp0[rt.TP_JP] = 0.0
    tp0[rt.TP_MASS] = 1.0
    # the rib's tilt moment alone: no slice in contact (far inside the play), nothing else
    _, edd, _ = rt.tilt_rates(tp0, -1.0, 0.0, ae, 0.0, 2.0, r[8], r[9], 0.0, 0.0, 0.0, 0.0)
    m_tilt = edd * tp0[rt.TP_JT]
    total = 0.0
    scale = 0.0
    for side in (-1, 1):
        shift = x + tq * ae + side * dca
        speed = xd + tq * aed + side * dca_rate
        p_rol, p_rib, heat, elastic, _ = _powers(g, side, a, shift, ad, spin, om, speed,
                                                 p[rt_mu_index()], p[rt_fg_index()], 0.05)
        total += p_rib + heat + elastic
        scale = max(scale, abs(p_rib), heat, abs(elastic), abs(p_rol))
    o_l = face_values(g.params(), -1, a, x + tq * ae, ad, spin, om, xd + tq * aed - dca_rate,
                      p[rt_mu_index()], p[rt_fg_index()], 0.05, dca)
    o_r = face_values(g.params(), 1, a, x + tq * ae, ad, spin, om, xd + tq * aed + dca_rate,
                      p[rt_mu_index()], p[rt_fg_index()], 0.05, dca)
    p_model = (r[8] * xd + m_tilt * aed + (o_l[4] + o_r[4]) * ad
               + (o_l[5] + o_r[5]) * spin)
    assert r[8] == o_l[1] + o_r[1]
    assert abs(p_model + total) <= 1e-8 * scale


def rt_mu_index():
    from thermobearing.skidding.roller_dynamics_rhs import _MU
    return _MU


def rt_fg_index():
    from thermobearing.skidding.roller_dynamics_rhs import _FG
    return _FG
