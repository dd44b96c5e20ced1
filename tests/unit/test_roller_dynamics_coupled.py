"""Tests of thermobearing.skidding.roller_dynamics_coupled (all rollers + cage, paper 003)."""

import math

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding import roller_dynamics as rd
from thermobearing.skidding import roller_dynamics_coupled as rc
from thermobearing.skidding.roller_fluid import martin_coefficients, pocket_forces

SPEED = 30000 * math.pi / 30


def test_pocket_film_friction_is_paper000_formula():
    k_w, k_q, k_c, _ = martin_coefficients()
    for f, w in ((0.0, 8000.0), (1.7, 8206.0), (13.0, 15000.0), (-4.0, 9000.0)):
        ref = pocket_forces(np.array([f]), np.array([w]), 6e-3, 5.4e-3, 0.0076,
                            0.2e-3).friction[0]
        got = rc._pocket_film_friction(f, w, 3e-3, 5.4e-3, 0.0076, 0.2e-3, k_w,
                                       k_c + 0.5 * k_q, 1e-4)
        assert got == pytest.approx(ref, rel=1e-12)


def test_cage_inertia_estimate():
    b = load_bearing("CRB_50x75x16")
    mass, j, note = rc.cage_inertia(b)
    cage = b.cage
    r_o, r_i = 0.5 * cage.outer_diameter, 0.5 * cage.inner_diameter
    # hand: brass ring 59.685/66 mm x 14 mm minus 24 pockets 6 x 6 x 3.16 mm -> ~51 g
    ring = math.pi * (r_o**2 - r_i**2) * cage.width - 24 * 6e-3 * 6e-3 * (r_o - r_i)
    assert mass == pytest.approx(cage.material.density * ring, rel=1e-12)
    assert 0.04 < mass < 0.06 and "cage_mass" in note
    assert j == pytest.approx(0.5 * mass * (r_o**2 + r_i**2), rel=1e-12)


def test_coupled_run_without_unbalance():
    # no unbalance: no rib contact; the rollers rest on their bars with the quasi-static
    # pocket force. Spin inertia: an unloaded roller's spin relaxes towards its quasi-static
    # value with J_p/k ~ 13 ms, longer than the 3.2 ms it spends in the unloaded zone, so
    # the integrated spins stay between the quasi-static unloaded spin and rolling, and the
    # orbit-mean slip falls below the quasi-static one (paper 000's per-azimuth balance)
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.0)
    r = rc.simulate_coupled(m, b, lub, n_orbits=0.15, warmup_orbits=0.05)
    assert r.pv_left == 0.0 and r.pv_right == 0.0 and r.rib_contact_fraction == 0.0
    spin = r.series["spin"]
    w_roll = (SPEED - m.cage_speed) * m.geom.inner_raceway_diameter / m.geom.roller_diameter
    assert np.min(spin) > 0.99 * np.min(m.spin) and np.max(spin) < 1.01 * w_roll
    u_i = (m.inner_speed - m.cage_speed) * 0.5 * m.geom.inner_raceway_diameter
    qs_slip = float(np.mean(np.abs(u_i - m.spin * 0.5 * m.geom.roller_diameter)))
    assert r.slip_speed < qs_slip
    wc = r.series["cage_speed"]
    assert np.max(np.abs(wc / m.cage_speed - 1.0)) < 0.05
    assert r.model == "coupled" and r.cost_s > 0


@pytest.mark.slow
def test_coupled_refresh_convergence():
    # evaluate path, base case, 0.11 g. (1) The refresh interval converges: from the
    # quasi-static state over 0.05 orbit, before the impacting motion decorrelates the runs,
    # the largest spin difference against a refresh at every step (h = period/400) falls
    # about linearly with the refresh, measured 88 / 41 / 18 rad/s at 16 / 8 / 4 steps
    # (15.8 / 7.9 / 3.9 us; the same to 1 % before the pocket damping's units were fixed,
    # 2026-11-23). (2) Statistics: one-orbit slip and PV at 20 vs 10 us agree within the
    # chaotic motion's scatter over the refresh, measured slip 5.60 / 5.45 / 5.70 / 5.63 /
    # 5.68 m/s at 5 / 10 / 15 / 20 / 25 us (5.60 / 5.60 / 5.56 / 5.62 / 5.67 before that
    # fix), PV 1305-1320 MPa m/s; on the table path a different refresh is a different
    # trajectory too (paper003 SOURCE.md); the table path against the evaluate path:
    # test_table_path_reproduces_...
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.11e-3)
    h = 2.0 * math.pi / float(np.max(m.spin)) / 400

    def short(sub):
        return rc.simulate_coupled(m, b, lub, n_orbits=0.05, warmup_orbits=0.0,
                                   refresh=sub * h, traction="evaluate",
                                   samples_per_period=10**9, fallback=False,
                                   cage_band=None).series

    ref = short(1)
    errs = []
    for sub in (16, 8, 4):
        s = short(sub)
        n = min(len(s["t"]), len(ref["t"])) - 1
        assert abs(s["t"][n] - ref["t"][n]) < 1e-12
        errs.append(float(np.max(np.abs(s["spin"][n] - ref["spin"][n]))))
    assert errs[0] / errs[1] > 1.6 and errs[1] / errs[2] > 1.6, errs
    assert errs[2] < 1e-2 * float(np.max(m.spin)), errs
    r1 = rc.simulate_coupled(m, b, lub, n_orbits=1.0, warmup_orbits=1.5, traction="evaluate")
    r2 = rc.simulate_coupled(m, b, lub, n_orbits=1.0, warmup_orbits=1.5, refresh=10e-6,
                             traction="evaluate")
    assert r2.slip_speed == pytest.approx(r1.slip_speed, rel=0.05)
    assert r2.pv_left + r2.pv_right == pytest.approx(r1.pv_left + r1.pv_right, rel=0.1)


def test_table_path_reproduces_evaluate_path():
    # the fast path (paper 000 traction tabulated, refreshed inside the jitted loop) against
    # the reference (evaluate() called from Python at every refresh), same RK4 loop, short
    # run before the impacting motion decorrelates: measured slip 19.2626 vs 19.2635 m/s,
    # PV 962.5 vs 959.3 MPa m/s, cage speed within 3e-4 and every spin within 0.3 % at every
    # sample (the table's interpolation error, test_roller_dynamics_table). Both on the
    # explicit RK4 loop: the default ETDRK4 also renews a roller's linearisation inside the
    # kernel on the table path only (SPIN_TRUST), which the evaluate path cannot; measured
    # there slip 19.2243 (table, ETDRK4) against the evaluate path's 19.2635 / 19.2486 /
    # 19.2405 m/s at 20 / 5 / 2.5 us refresh (the refresh-converged value)
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.11e-3, coupling="none")
    fast = rc.simulate_coupled(m, b, lub, n_orbits=0.1, warmup_orbits=0.05,
                               integrator="rk4")
    ref = rc.simulate_coupled(m, b, lub, n_orbits=0.1, warmup_orbits=0.05,
                              traction="evaluate", integrator="rk4")
    assert fast.series["table_builds"][0] >= 1 and ref.series["table_builds"][0] == 0
    assert fast.slip_speed == pytest.approx(ref.slip_speed, rel=1e-3)
    assert np.allclose(fast.series["cage_speed"], ref.series["cage_speed"], rtol=1e-3)
    assert np.allclose(fast.series["spin"], ref.series["spin"], rtol=1e-2)
    pv_f, pv_r = fast.pv_left + fast.pv_right, ref.pv_left + ref.pv_right
    assert pv_r > 0 and pv_f == pytest.approx(pv_r, rel=0.03)
    assert fast.rib_contact_fraction == pytest.approx(ref.rib_contact_fraction, abs=0.01)


def test_bad_traction_option():
    from thermobearing.errors import InputError

    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.0)
    with pytest.raises(InputError):
        rc.simulate_coupled(m, b, lub, traction="spline")


def test_axially_free_inner_ring():
    # paper 003 eq. 20 line 1: the inner ring (68 g, estimated) free axially under the rib
    # and inner-raceway axial forces of all rollers. Short run: it moves (less than the
    # axial clearance), and PV and slip stay close to the held ring (measured over 2 + 3
    # orbits at 0.01-0.09 mm axial clearance: within 1-3 %, SOURCE.md)
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    mass, note = rc.inner_ring_mass(b)
    assert 0.05 < mass < 0.09 and "inner_ring_mass" in note
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.11e-3, coupling="none")
    held = rc.simulate_coupled(m, b, lub, n_orbits=0.1, warmup_orbits=0.05)
    free = rc.simulate_coupled(m, b, lub, n_orbits=0.1, warmup_orbits=0.05, ring_axial=True)
    ring = free.series["ring_axial"]
    assert np.all(np.isfinite(ring)) and np.max(np.abs(ring)) > 0.0
    assert np.max(np.abs(ring - ring[0])) < 0.5 * m.geom.axial_clearance
    assert np.all(held.series["ring_axial"] == 0.0)
    assert free.slip_speed == pytest.approx(held.slip_speed, rel=0.02)


def test_cage_land_coefficient_is_petroff():
    # pi eta D_g^3 B_c / (4 c): inner-ring-guided cage of the preset, D_g 59.485 mm, two
    # 2 mm lands, c = 0.1 mm, the rib-gap oil/air mixture viscosity (paper 002 eq. 5)
    b = load_bearing("CRB_50x75x16")
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, SPEED, 3000.0, 0.0)
    k, w_g = rc.cage_land_coefficient(b, m)
    cage = b.cage
    ref = (math.pi * m.mixture_viscosity * cage.guide_land_diameter**3 * cage.land_width
           / (4.0 * 0.5 * cage.guide_clearance))
    assert k == pytest.approx(ref, rel=1e-12) and w_g == SPEED


# --- cage band and the table path's fallback (D3) -------------------------------
# The state that stopped configs/scenes/crb_rib_example.toml with 0.06 g: paper 003's bearing
# as the scene's NUP variant, 20000 r/min, 3 kN, MIL-PRF-23699 at 420 K (the "elements" node
# the scene's transient probed). On the table path the cage ran away (886 -> 1840 rad/s, one
# roller rattling between its ribs 3x deeper than the others, pinned on its front bar) and the
# table was rebuilt > 20 times; on the evaluate path it stays at 941-987 rad/s.
FAIL_SPEED = 20000 * math.pi / 30


def _failing_state():
    b = load_bearing("CRB_50x75x16", {"ribbed_ring": "both",
                                     "cage": {"outer_diameter": "65 mm"}})
    lub = load_lubricant("MIL_PRF_23699")
    m = rd.build_model(b, lub, FAIL_SPEED, 3000.0, 0.06e-3, temperature=420.0,
                       coupling="none")
    return b, lub, m


def test_cage_outside_band_on_both_paths_is_a_clear_error():
    # a band far tighter than the motion's own cage fluctuation (from the quasi-static start
    # the cage speeds up by ~1 % in the first 0.3 orbit, measured): the table path stops,
    # the evaluate path leaves the band too, and the error names the unstable motion and its
    # state instead of the table
    b, lub, m = _failing_state()
    with pytest.raises(rc.ConvergenceError) as info:
        rc.simulate_coupled(m, b, lub, n_orbits=0.02, warmup_orbits=0.0, cage_band=1e-4)
    msg = str(info.value)
    assert "unstable coupled motion" in msg and "evaluate" in msg
    state = info.value.state
    assert state["traction"] == "evaluate" and abs(state["cage_ratio"] - 1.0) > 1e-4
    assert 0 <= state["roller"] < m.azimuth.size and state["cage_speed"] > 0
    with pytest.raises(rc.ConvergenceError, match="fallback=False"):
        rc.simulate_coupled(m, b, lub, n_orbits=0.02, warmup_orbits=0.0, cage_band=1e-4,
                            fallback=False)


def test_table_path_stop_reruns_the_evaluate_path(monkeypatch):
    # the fallback re-runs the whole integration on the evaluate path: the same result as
    # asking for it (bit for bit: deterministic), flagged in the series with where the
    # table path stopped
    b, lub, m = _failing_state()
    ref = rc.simulate_coupled(m, b, lub, n_orbits=0.03, warmup_orbits=0.0,
                              traction="evaluate")
    assert ref.series["traction_fallback"][0] == 0
    real = rc._simulate_coupled_path

    def stop_on_table(*args, traction, **kwargs):
        if traction == "table":
            raise rc._TableCannotFollow("test", {"t": 1e-3, "cage_speed": 1234.0})
        return real(*args, traction=traction, **kwargs)

    monkeypatch.setattr(rc, "_simulate_coupled_path", stop_on_table)
    got = rc.simulate_coupled(m, b, lub, n_orbits=0.03, warmup_orbits=0.0)
    assert got.series["traction_fallback"][0] == 1
    assert got.series["fallback_cage_speed"][0] == 1234.0
    assert got.series["fallback_time"][0] == 1e-3
    assert got.series["table_builds"][0] == 0
    np.testing.assert_array_equal(got.series["cage_speed"], ref.series["cage_speed"])
    assert got.pv_left == ref.pv_left and got.slip_speed == ref.slip_speed


@pytest.mark.slow
def test_failing_scene_state_finishes_in_band_or_stops_clearly():
    # the full run the scene needs (2 + 3 orbits, ~20 s CPU with the fallback). At this
    # state an unloaded roller can wedge between its ribs and rattle, fed by the rib
    # friction with nothing damping the skew (paper003 SOURCE.md, 2026-11-23): whether one
    # trajectory does is round-off (measured 2 of 10 trajectories before eq. 35 took the
    # mean speed, 4 of 10 after; until 2026-11-23 the table path ran away here and the
    # evaluate path finished, cage within 11.5 %, rib heat 19.6 W per roller). So the run
    # either finishes with the cage inside the band and rib heat, or stops with the error
    # that names the unstable motion (the rib source then hands the state to the reduced
    # model with a warning: test_rib_coupled_fallbacks.py)
    b, lub, m = _failing_state()
    try:
        r = rc.simulate_coupled(m, b, lub, n_orbits=3.0, warmup_orbits=2.0)
    except rc.ConvergenceError as exc:
        assert "unstable coupled motion" in str(exc)
        assert np.isfinite(exc.state["cage_speed"]) and exc.state["cage_speed"] > 0
        return
    wc = r.series["cage_speed"]
    assert np.max(np.abs(wc / m.cage_speed - 1.0)) < rc.DEFAULT_CAGE_BAND
    assert r.rib_heat_left + r.rib_heat_right > 0
