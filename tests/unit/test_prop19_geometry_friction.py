"""Property tests of the bearing geometry's kinematic frequencies and of the global
(catalogue) friction models (session 19).

Geometry (:mod:`thermobearing.geometry_common`): the pure-rolling cage ratio (1 - gamma)/2 lies
in (0, 1/2); BPFO + BPFI = Z |f_i - f_o|; the element spin is Harris' (d_m / 2D) f (1 -
gamma^2); without cage slip every frequency relative to the rings depends only on the
relative ring speed (turning the whole bearing adds the same speed to the cage and changes
nothing else); with slip the cage frequency scales by (1 - s_c) (paper 004).

Global friction (:mod:`thermobearing.global_friction`): every SKF component is non-negative
and the power is torque x speed; the rolling and sliding moments rise with either load; at
standstill only the sliding moment (boundary friction) remains; Palmgren's M0 is continuous
in nu n except for the published formula's own step at nu n = 2000 (160 / 2000^(2/3) =
1.0079, pinned); Palmgren's P1 is never below F_r.
"""

from __future__ import annotations

import math
import warnings

from hypothesis import given, settings
from hypothesis import strategies as st

from thermobearing.errors import ValidityWarning
from thermobearing.geometry import load_bearing
from thermobearing.global_friction import (
    palmgren,
    palmgren_equivalent_load,
    skf_drag_factor,
    skf_four_term,
)

NAMES = ("QJ1044", "SKF6304", "NU214", "D1842926", "CRB_50x75x16")
BEARINGS = {n: load_bearing(n) for n in NAMES}


@settings(max_examples=80, deadline=None)
@given(name=st.sampled_from(NAMES), f_i=st.floats(0.0, 500.0), f_o=st.floats(-100.0, 100.0),
       shift=st.floats(0.0, 200.0))
def test_frequencies_depend_on_the_relative_ring_speed(name, f_i, f_o, shift):
    b = BEARINGS[name]
    fr = b.characteristic_frequencies(f_i, outer_speed_hz=f_o)
    g = float(b.gamma())
    z = b.n_elements
    assert 0.0 < float(b.theoretical_cage_speed_ratio()) < 0.5
    assert math.isclose(fr.bpfo + fr.bpfi, z * abs(f_i - f_o), rel_tol=1e-12, abs_tol=1e-12)
    harris = b.pitch_diameter / (2 * b.element_diameter) * abs(f_i - f_o) * (1 - g * g)
    assert math.isclose(fr.ball_spin, harris, rel_tol=1e-12, abs_tol=1e-12)
    moved = b.characteristic_frequencies(f_i + shift, outer_speed_hz=f_o + shift)
    assert math.isclose(moved.cage, fr.cage + shift, rel_tol=1e-12, abs_tol=1e-9)
    for f in ("bpfo", "bpfi", "ball_spin"):
        assert math.isclose(getattr(moved, f), getattr(fr, f), rel_tol=1e-12, abs_tol=1e-9), f


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(NAMES), f_i=st.floats(0.1, 500.0), slip=st.floats(-0.5, 0.9))
def test_cage_slip_scales_the_cage_and_its_pass_frequencies(name, f_i, slip):
    b = BEARINGS[name]
    base = b.characteristic_frequencies(f_i)
    fr = b.characteristic_frequencies(f_i, cage_slip=slip)
    assert math.isclose(fr.cage, (1 - slip) * base.cage, rel_tol=1e-12)
    assert math.isclose(fr.bpfo, (1 - slip) * base.bpfo, rel_tol=1e-12)
    assert math.isclose(fr.bpfi, b.n_elements * abs(f_i - fr.cage), rel_tol=1e-12)


# ------------------------------------------------------------------------ global friction
SKF_NAMES = ("QJ1044", "SKF6304", "NU214")


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(SKF_NAMES), rpm=st.floats(0.0, 10000.0), nu=st.floats(2e-6, 5e-4),
       fr=st.floats(0.0, 3e4), fa=st.floats(0.0, 1e4), more=st.floats(1.0, 3.0),
       lub=st.sampled_from(["oil_jet", "circulating", "oil_air", "oil_bath"]))
def test_skf_four_term_non_negative_and_rising_with_load(name, rpm, nu, fr, fa, more, lub):
    b = BEARINGS[name]
    w = rpm * math.pi / 30
    if b.kind == "cylindrical":
        fa = 0.0
    kw = dict(lubrication=lub, oil_level=0.3 * b.element_diameter if lub == "oil_bath" else None,
              # SKF 6304: C0 = 7.8 kN (catalogue), needed for alpha_F under axial load
              static_load_rating=7.8e3 if name == "SKF6304" else None)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        r = skf_four_term(b, nu, w, fr, fa, **kw)
        r2 = skf_four_term(b, nu, w, fr * more + 1.0, fa * more, **kw)
    assert all(v >= 0.0 for v in r.components.values())
    assert math.isclose(r.torque, sum(r.components.values()), rel_tol=1e-12)
    assert math.isclose(r.power, r.torque * w, rel_tol=1e-12, abs_tol=1e-300)
    assert r2.components["rolling"] >= r.components["rolling"] * (1 - 1e-12)
    assert r2.components["sliding"] >= r.components["sliding"] * (1 - 1e-12)
    assert r2.components["drag"] == r.components["drag"]
    if rpm == 0.0:
        assert r.components["rolling"] == 0.0 and r.components["drag"] == 0.0


@settings(max_examples=60, deadline=None)
@given(level=st.floats(0.0, 2.0), dl=st.floats(0.0, 0.5),
       family=st.sampled_from(["ball", "roller"]))
def test_skf_drag_factor_monotone_in_the_level(level, dl, family):
    v = skf_drag_factor(level, family)
    assert v >= 0.0
    assert skf_drag_factor(level + dl, family) >= v * (1 - 1e-12)


@settings(max_examples=60, deadline=None)
@given(name=st.sampled_from(NAMES), fr=st.floats(0.0, 5e4), fa=st.floats(0.0, 5e4))
def test_palmgren_equivalent_load_at_least_radial(name, fr, fa):
    kind = BEARINGS[name].kind
    assert palmgren_equivalent_load(kind, fr, fa) >= fr


def test_palmgren_m0_step_at_nu_n_2000_is_the_published_one():
    """M0 = 1e-7 f0 (nu n)^(2/3) d_m^3 above nu n = 2000 and 160e-7 f0 d_m^3 below: the two
    branches differ by 160 / 2000^(2/3) = 1.0079 at the switch (Palmgren 1959 as quoted by
    Harris & Kotzalas; the formula's own step, not an implementation's). Elsewhere M0 rises
    with nu n."""
    b = BEARINGS["SKF6304"]
    nu = 1e-5  # 10 mm^2/s
    n_switch = 200.0  # r/min: nu n = 2000
    w = n_switch * math.pi / 30
    below = palmgren(b, nu, w * (1 - 1e-9), 0.0).components["M0"]
    above = palmgren(b, nu, w * (1 + 1e-9), 0.0).components["M0"]
    assert math.isclose(below / above, 160.0 / 2000.0 ** (2 / 3), rel_tol=1e-6)
    prev = 0.0
    for rpm in (250.0, 400.0, 1000.0, 5000.0):
        m0 = palmgren(b, nu, rpm * math.pi / 30, 0.0).components["M0"]
        assert m0 > prev
        prev = m0
