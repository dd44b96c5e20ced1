"""The coupled transient's chunk heat model at a cold start at high speed (found by the scene
fuzzer): a 6304 at 42000 r/min started at 7.8 degC had its inner ring at -36 degC after one
0.1 s chunk (-1681 degC after 11 s), because the affine model of losses that fall steeply
with temperature turned negative; the drift check then stopped the run with 'temperature =
23.3 K is not allowed' from the viscosity law instead of repeating the chunk shorter."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from thermobearing.coupled import Coupler, _Linear
from thermobearing.lubricant import load_lubricant


def test_chunk_heat_model_does_not_go_below_its_floor():
    q0 = np.array([100.0, 0.0, -5.0])
    J = np.diag([-50.0, 0.0, -1.0])
    H = np.zeros((3, 3))
    H[0, 0] = 4.0
    T0 = np.full(3, 300.0)
    for lin in (_Linear(q0, J, T0), _Linear(q0, J, T0, H)):
        T = T0 + np.array([5.0, 0.0, 10.0])
        q, jac = lin.heat_and_jac(0.0, T)
        # a loss never turns into cooling; a node with negative heat keeps its own floor
        assert q[0] == 0.0 and np.all(jac[0] == 0.0)
        assert q[2] == -5.0 and np.all(jac[2] == 0.0)
        assert np.array_equal(lin.heat(0.0, T), q)
        assert np.array_equal(lin.jac(0.0, T), jac)
        # near T0 the model is the unclamped one
        q1, jac1 = lin.heat_and_jac(0.0, T0 + np.array([0.5, 0.0, 0.0]))
        assert q1[0] == 100.0 - 25.0 + (0.5 * 4.0 * 0.25 if lin.H is not None else 0.0)
        assert jac1[0, 0] < 0.0
        # re-centring keeps the model's own slope (not the clamped zero row)
        assert lin.moved(q, T).J[0, 0] < 0.0


def test_drift_out_of_the_viscosity_range_rejects_the_chunk():
    oil = load_lubricant("ISO_VG68")
    b = SimpleNamespace(last=SimpleNamespace(state=SimpleNamespace(origin="solved")),
                        last_viscosity=float(oil.dynamic_viscosity(281.0)),
                        kinematics_name="skidding")
    coupler = SimpleNamespace(
        sim=SimpleNamespace(bearings=[b], lubricant=oil),
        role_temperatures=lambda _b, T: {r: float(T[0]) for r in
                                          ("inner_ring", "outer_ring", "elements")})
    assert Coupler.viscosity_drift(coupler, np.array([290.0])) < 1.0
    assert Coupler.viscosity_drift(coupler, np.array([23.3])) == math.inf
