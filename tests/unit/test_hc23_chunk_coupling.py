"""The chunk model carries the held kinematic state's temperature dependence
(thermobearing.coupled_secant): no saw-tooth of the roller node at the kinematics solves.

The NU 214 tour scene (3000 then 6000 r/min, 5 kN, ISO VG 32 jet at 40 degC, default
solver) held each chunk's kinematics, and so its heat, at the cooler start of the chunk:
the roller node fell 0.21 K in the 9.4 s last chunk of each step and by up to 0.30 K in
5 s after every solve, and ran up to 1.4 K above a finely coupled run."""

from __future__ import annotations

import numpy as np
import pytest
from nu214_scene import nu214_jet_scene

from thermobearing.coupled import _Linear
from thermobearing.coupled_secant import KinematicSecant
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCHEDULE = """radial_load = "5 kN"
axial_load = "0 kN"
step_duration = "5 min"
steps = [{ speed = "3000 rpm" }, { speed = "6000 rpm" }]"""
NETWORK = """[network]
template = "four_node_paper002"
parameters = { housing_outer_diameter = "190 mm", housing_length = "60 mm", \
shaft_diameter = "70 mm", shaft_length = "200 mm" }
"""


def _run(solver: str = "", interval: str = "5 s") -> tuple[object, object]:
    text = nu214_jet_scene(title="NU 214 chunk coupling", schedule=SCHEDULE,
                           want='["temperatures"]\ninterval = "' + interval + '"',
                           environment='initial_temperature = "40 degC"')
    text += NETWORK + (f"[solver]\n{solver}\n" if solver else "")
    res = Simulation(loads_scene(text), progress=False).run()
    temps = res.tables["temperatures"].drop_duplicates("time [s]").set_index("time [s]")
    return temps, res.stats


def test_roller_node_rises_through_each_step_without_a_sawtooth():
    """A warming transient: after each step's first minute the roller node rises at
    every 5 s sample and through the step's last (short) chunk; it fell by up to 0.30 K
    after each kinematics solve (0.21 K over 590.6-600 s). One kinematics probe per step
    (the operating point's first secant), the kinematics solves as before."""
    temps, stats = _run()
    rollers = temps["crb.rollers [degC]"]
    rise = rollers.diff()
    t = rise.index.to_numpy()
    later = ((t > 60.0) & (t <= 300.0)) | (t > 360.0)
    assert later.sum() > 90
    # every row: the 5 s samples and the chunk ends (the last chunk of a step included)
    assert float(rise[later].min()) > 0.0, rise[later].idxmin()
    assert rollers.loc[600.0] - rollers.loc[590.0] > 0.1  # was 89.37 -> 89.18 degC
    assert stats["kinematic_probes"] == 2


@pytest.mark.slow
def test_chunk_coupling_error_against_a_fine_coupling():
    """Against 1 s chunks with a 0.1 % kinematics tolerance (460 solves; measured ~30 s):
    the default coupling's largest node error over the run, sampled every 5 s, was 1.38 K
    (rollers, 10 s after the speed step) and 0.45 K at the end; now 0.25 K and 0.05 K."""
    temps, _ = _run()
    fine, _ = _run('chunk = "1 s"\nkinematics_tolerance = 0.001')
    common = temps.index.intersection(fine.index)
    nodes = [c for c in fine.columns if c.endswith("[degC]")]
    err = (temps.loc[common, nodes] - fine.loc[common, nodes]).abs()
    assert float(err.to_numpy().max()) < 0.3
    assert float(err.iloc[-1].max()) < 0.1


def test_secant_predicts_a_kinematic_heat_change_along_the_warming():
    """Broyden's secant on the kinematic nodes: the heat change between two solves is
    predicted exactly along their temperature change, nothing across it, and a node the
    kinematics do not read (index 3) is left out."""
    sec = KinematicSecant(4, {"b": [0, 1, 2]})
    T0 = np.full(4, 320.0)
    slope = np.array([-2.0, -0.5, -1.0, 0.0])  # heat [W] per K of the direction (1, 1, 0, 0)
    # probe: rings/elements +0.5 K, heat of the probe state minus the held state's
    sec.restart("b", T0, (T0 + [0.5, 0.5, 0.0, 0.0], 0.5 * slope, np.zeros(4)))
    K, c = sec.terms()
    d = np.array([2.0, 2.0, 0.0, 0.0])
    np.testing.assert_allclose(K @ (T0 + d) - c, 2.0 * slope, atol=1e-12)
    np.testing.assert_allclose(K @ np.array([1.0, -1.0, 0.0, 5.0]), 0.0, atol=1e-12)
    # a re-solve at T0 + d whose heat changed by 2 slope + e: e is taken into K along d
    e = np.array([0.3, 0.0, -0.1, 0.0])
    sec.resolved("b", T0 + d, 2.0 * slope + e, np.zeros(4))
    K, c = sec.terms()
    np.testing.assert_allclose(K @ (T0 + d) - c, 0.0, atol=1e-9)  # origin moved there
    np.testing.assert_allclose(K @ d, 2.0 * slope + e, atol=1e-12)
    sec.restart("b", T0)
    assert sec.terms() == (None, None)


def test_chunk_model_jacobian_includes_the_kinematic_term():
    """heat_and_jac of the chunk model with K: the heat is q0 + J (T - T0) + K T - c and
    its Jacobian matches central differences."""
    rng = np.random.default_rng(3)
    n = 3
    J, K = rng.normal(size=(n, n)), rng.normal(size=(n, n))
    T0 = np.full(n, 330.0)
    H = np.zeros((n, n))
    H[:, 1] = rng.normal(size=n)
    lin = _Linear(np.full(n, 50.0), J, T0, H).with_kinematics(K, K @ T0)
    T = T0 + np.array([0.7, -0.4, 0.2])
    q, jac = lin.heat_and_jac(0.0, T)
    np.testing.assert_allclose(q, lin.heat(0.0, T))
    base = _Linear(np.full(n, 50.0), J, T0, H).heat(0.0, T)
    np.testing.assert_allclose(q, base + K @ (T - T0), rtol=1e-12)
    h = 1e-5
    e = np.eye(n)
    fd = np.column_stack([(lin.heat(0.0, T + h * e[j]) - lin.heat(0.0, T - h * e[j])) / (2 * h)
                          for j in range(n)])
    np.testing.assert_allclose(jac, fd, rtol=1e-6, atol=1e-6)
    moved = lin.moved(base, T).with_kinematics(K, K @ T0)
    np.testing.assert_allclose(moved.heat(0.0, T), q, rtol=1e-12)
