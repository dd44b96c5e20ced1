"""The pieces that the contact kernels, the network steppers and the catalogue friction models
share since session 23 (one function each instead of copies): checked against the equations
they stand for, independently of the kernels that call them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.contact_traction import _node_slip, _slip_coefficients, _store_forces
from thermobearing.errors import ConvergenceError, InputError, UnknownNameError
from thermobearing.global_friction import BearingEnvelope, _catalogue_inputs
from thermobearing.network.steppers import STEP_UNDERFLOW, clip_step, stepper_failure


def test_node_slip_is_the_rigid_body_slip_on_the_deformed_surface():
    """dv = V + Omega x r at r = (x, y, x^2 / (2 R_d)) (contact_traction module docstring)."""
    rng = np.random.default_rng(23)
    for _ in range(50):
        a, b = rng.uniform(1e-4, 3e-3, 2)
        rd = rng.uniform(5e-3, 0.2) * rng.choice([-1.0, 1.0])
        vx, vy = rng.normal(0.0, 2.0, 2)
        omega = rng.normal(0.0, 300.0, 3)          # Omega_x, Omega_y, Omega_z
        xg, yg = rng.uniform(-1.0, 1.0, 2)
        ab, a2c, cx2, cy, cx, cy2 = _slip_coefficients.py_func(a, b, 1.0 / rd, omega[1],
                                                               omega[2], omega[0])
        xg2, dvx, dvy = _node_slip.py_func(vx, vy, cx2, cy, cx, cy2, xg, yg)
        x, y = a * xg, b * yg
        z = x * x / (2.0 * rd)
        expected = np.array([vx, vy, 0.0]) + np.cross(omega, [x, y, z])
        scale = abs(vx) + abs(vy) + np.abs(omega).sum() * a
        assert ab == pytest.approx(a * b, rel=1e-15)
        assert a2c * xg2 == pytest.approx(z, rel=1e-12, abs=1e-30)
        assert dvx == pytest.approx(expected[0], rel=1e-12, abs=1e-13 * scale)
        assert dvy == pytest.approx(expected[1], rel=1e-12, abs=1e-13 * scale)


def test_stored_forces_are_the_sums_of_the_node_forces_and_their_moments():
    """F = sum t dA and M = sum r x t dA about the contact centre, with the node sums of
    -t dA the kernels accumulate (px, py)."""
    rng = np.random.default_rng(230)
    a, b, rd = 2e-3, 4e-4, 0.02
    ab, a2c, *_ = _slip_coefficients.py_func(a, b, 1.0 / rd, 0.0, 0.0, 0.0)
    xg, yg = rng.uniform(-1.0, 1.0, (2, 40))
    t = rng.normal(0.0, 5.0, (40, 2))              # node forces t dA on the element [N]
    px, py = -t[:, 0], -t[:, 1]
    out = np.full((3, 6), np.nan)
    _store_forces.py_func(out, 1, a, b, a2c, px.sum(), (px * xg**2).sum(), (px * yg).sum(),
                          py.sum(), (py * xg**2).sum(), (py * xg).sum())
    r = np.column_stack([a * xg, b * yg, a * a * xg**2 / (2.0 * rd)])
    f3 = np.column_stack([t, np.zeros(40)])
    moment = np.cross(r, f3).sum(axis=0)
    np.testing.assert_allclose(out[1, :2], t.sum(axis=0), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(out[1, 2:5], moment, rtol=1e-12, atol=1e-15)
    assert np.isnan(out[0]).all() and np.isnan(out[2]).all() and np.isnan(out[1, 5])


@pytest.mark.parametrize("t, h, t1, step, last", [
    (0.0, 1.0, 10.0, 1.0, False),
    (9.0, 1.0, 10.0, 1.0, True),                 # lands on the end
    (9.0, 0.9995, 10.0, 1.0, True),              # would leave a 5e-4 h sliver: stretched
    (9.0, 0.99, 10.0, 0.99, False),              # 1e-2 h short of the end: an ordinary step
    (9.5, 2.0, 10.0, 0.5, True),                 # beyond the end: cut
])
def test_clip_step_leaves_no_sliver_before_the_segment_end(t, h, t1, step, last):
    got_h, got_last = clip_step(t, h, t1)
    assert got_last is last
    assert got_h == pytest.approx(step, rel=1e-14)
    if last:
        assert t + got_h == t1


def test_stepper_failure_names_the_stepper_the_residual_and_the_state():
    y = np.array([300.0, 310.0])
    err = stepper_failure("exprb43", 3.5, STEP_UNDERFLOW, 12.0, 1e-9, y)
    assert isinstance(err, ConvergenceError)
    text = str(err)
    assert "exprb43" in text and "3.5" in text and "underflow" in text


def test_catalogue_inputs_convert_to_catalogue_units_and_name_bad_fields():
    brg = BearingEnvelope("deep_groove", 0.020, 0.052, 0.015, 9.525e-3, "SKF6304")
    env, lub, n, nu = _catalogue_inputs(brg, 2000 * 2 * math.pi / 60, 20e-6, 1000.0, 0.0, "jet")
    assert env is brg and lub == "oil_jet"
    assert n == pytest.approx(2000.0, rel=1e-14) and nu == pytest.approx(20.0, rel=1e-14)
    for args, field in (((-1.0, 20e-6, 1.0, 0.0), "speed"),
                        ((1.0, 0.0, 1.0, 0.0), "kinematic_viscosity"),
                        ((1.0, 20e-6, -1.0, 0.0), "radial_load"),
                        ((1.0, 20e-6, 1.0, math.nan), "axial_load")):
        with pytest.raises(InputError, match=field):
            _catalogue_inputs(brg, *args, "oil_jet")
    with pytest.raises(UnknownNameError, match="lubrication"):
        _catalogue_inputs(brg, 1.0, 20e-6, 1.0, 0.0, "mist")
