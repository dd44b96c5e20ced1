"""Coupled kinematics -> heat sources -> network runs: energy books, no NaN, steady limit."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from scene_parts import (
    PAPER002_AMBIENT,
    PAPER002_NETWORK,
    PAPER002_OIL,
    QJ1044_DE,
    QJ1044_NDE,
    RACE_CONTROL,
    scene_title,
)

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

BASE = (scene_title("coupled") + QJ1044_DE + QJ1044_NDE + PAPER002_OIL + PAPER002_AMBIENT
        + RACE_CONTROL + PAPER002_NETWORK + '[solver]\nchunk = "90 s"\n')
#: 1800 r/min under 1 kN radial, two 3-min steps of 4 and 8 kN axial
AXIAL_STEPS = """
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
step_duration = "3 min"
axial_load_steps = { start = "4 kN", stop = "8 kN", step = "4 kN" }
"""
#: the CRB scenes' oil (MIL-PRF-23699, 4 L/min at 80 degC), air (35 degC), speed and radial load
CRB_RUN = """[lubricant]
preset = "MIL_PRF_23699"
[supply]
flow = "4 L/min"
inlet_temperature = "80 degC"
[environment]
ambient_temperature = "35 degC"
[schedule]
speed = "10000 rpm"
radial_load = "3 kN"
"""


def test_transient_two_bearings_energy_and_monotone_rise(tmp_path):
    text = BASE + AXIAL_STEPS + """[outputs]
want = ["temperatures", "losses", "kinematics", "energy", "report"]
"""
    res = Simulation(loads_scene(text), progress=False).run(out_dir=tmp_path)
    temps = res.tables["temperatures"]
    cols = [c for c in temps.columns if c.endswith("[degC]")]
    assert len(cols) == 8  # four nodes per bearing, two bearings
    values = temps[cols].to_numpy()
    assert np.all(np.isfinite(values))
    assert np.all(values[-1] > values[0])  # every node warms up from 35 degC
    assert np.all(np.diff(temps["de.housing [degC]"].to_numpy()) >= -1e-9)
    # identical bearings under identical loads stay identical
    assert np.allclose(temps["de.oil [degC]"], temps["nde.oil [degC]"])
    e = res.tables["energy"].iloc[-1]
    # closes to the stepper tolerance (temperature-dependent convection is lagged per step)
    assert abs(e["imbalance [J]"]) <= 1e-4 * e["generated [J]"]
    assert e["to oil [J]"] > 0.5 * e["generated [J]"] - e["stored [J]"]
    for name in ("temperatures.csv", "losses.csv", "kinematics.csv", "energy.csv",
                 "scene.toml", "report.html"):
        assert (tmp_path / name).is_file()


def test_steady_equals_long_transient():
    sched = """
[schedule]
speed = "1200 rpm"
radial_load = "1 kN"
axial_load = "10 kN"
duration = "{dur}"
"""
    steady = Simulation(loads_scene(BASE + sched.format(dur="1 min") + """
[outputs]
mode = "steady"
want = ["temperatures", "losses"]
"""), progress=False).run()
    long = Simulation(loads_scene(BASE.replace('chunk = "90 s"', 'chunk = "10 h"')
                                  + sched.format(dur="200 h") + """
[outputs]
want = ["temperatures"]
"""), progress=False).run()
    st = steady.tables["steady_temperatures"].iloc[0]
    tr = long.tables["temperatures"].iloc[-1]
    for node in ("de.balls", "de.housing", "de.shaft", "de.oil"):
        assert tr[f"{node} [degC]"] == pytest.approx(st[f"{node} [degC]"], abs=0.05)


def test_measured_column_to_unknown_node_is_an_error(tmp_path):
    from thermobearing.errors import InputError

    (tmp_path / "rig.csv").write_text("time [min],T1\n0,35\n1,36\n", encoding="utf-8")
    text = BASE + """
[schedule]
speed = "600 rpm"
radial_load = "1 kN"
axial_load = "4 kN"
duration = "1 min"
[measured]
file = "rig.csv"
columns = { T1 = "de.gearbox" }
"""
    sim = Simulation(loads_scene(text, base_dir=tmp_path), progress=False)
    with pytest.raises(InputError) as info:
        sim.run()
    assert "de.gearbox" in str(info.value) and "de.housing" in str(info.value)


def test_cylindrical_roller_scene_books_rib_friction_in_the_network():
    """Issue 9: the rib friction heat enters the network of a CRB scene as its own loss."""
    text = scene_title("CRB with axial load") + """[[bearings]]
name = "crb"
preset = "CRB_50x75x16"
""" + CRB_RUN + """axial_load = "0.2 kN"
duration = "2 min"
""" + RACE_CONTROL + """\
heat_source_options = { rib_friction = { model = "reduced", friction_coefficient = 0.08 } }
[network]
template = "four_node_paper002"
parameters = { housing_outer_diameter = "110 mm", housing_length = "30 mm" }
[outputs]
want = ["temperatures", "losses", "energy"]
"""
    # the scene's heat_source_options pick the cheap reduced rib model here (the coupled
    # default is exercised by tests/unit/test_rib_scene.py)
    res = Simulation(loads_scene(text), progress=False).run()
    losses = res.tables["losses"]
    rib = losses[losses["source"] == "rib_friction"].groupby("step")["power [W]"].sum()
    assert len(rib) == 1 and rib.iloc[0] > 0   # one step, rows per heated role
    temps = res.tables["temperatures"]
    assert np.all(np.isfinite(temps.filter(like="[degC]").to_numpy()))
    e = res.tables["energy"].iloc[-1]
    assert abs(e["imbalance [J]"]) <= 1e-4 * e["generated [J]"]


def test_thermal_runaway_stops_with_a_clear_error():
    """12 kW in a 50 mm bearing with 1 L/min of oil: stopped at 300 degC, never NaN."""
    from thermobearing.errors import ConvergenceError

    text = """
title = "runaway"
[[bearings]]
name = "crb"
preset = "CRB_50x75x16"
[lubricant]
preset = "MIL_PRF_23699"
[supply]
flow = "1 L/min"
inlet_temperature = "80 degC"
[schedule]
speed = "30000 rpm"
radial_load = "3 kN"
axial_load = "0.2 kN"
duration = "3 min"
[models]
kinematics = "race_control"
# the rib source's coupled dynamics would run at every 5 K node of the runaway (~50 s CPU)
heat_source_options = { rib_friction = { model = "reduced" } }
[network]
parameters = { housing_outer_diameter = "110 mm", housing_length = "30 mm" }
[outputs]
want = ["temperatures"]
"""
    with pytest.raises(ConvergenceError) as info:
        Simulation(loads_scene(text), progress=False).run()
    assert "thermal runaway" in str(info.value) and "crb." in str(info.value)


@pytest.mark.parametrize("kinematics", ["race_control", "skidding"])
def test_linearisation_over_read_roles_equals_full_finite_differences(kinematics):
    """The heat Jacobian is differentiated only in the nodes of the roles the sources read
    (heat_sources.RoleTemperatures); every other column must be exactly zero, and the
    read columns equal a brute-force difference over every node."""
    from thermobearing import coupled

    text = BASE.replace('kinematics = "race_control"', f'kinematics = "{kinematics}"') + """
[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
axial_load = "6 kN"
duration = "3 min"
"""
    sim = Simulation(loads_scene(text), progress=False)
    net = coupled.build_network(sim)
    sim.network = net
    cp = coupled.Coupler(sim, net)
    step = sim.scene.schedule.steps[0]
    T = np.linspace(315.0, 330.0, len(cp.names))
    cp.kinematics(0, step, T)
    lin = cp.linearize(step, T, dT=0.5)
    full = np.zeros_like(lin.J)
    curv = np.zeros_like(lin.J)
    q0 = cp.heat(step, T)
    for j in range(len(T)):
        Tp, Tm = T.copy(), T.copy()
        Tp[j] += 0.5
        Tm[j] -= 0.5
        qp, qm = cp.heat(step, Tp), cp.heat(step, Tm)
        full[:, j] = (qp - qm) / 1.0
        curv[:, j] = (qp - 2.0 * q0 + qm) / 0.25
    np.testing.assert_allclose(lin.q0, q0, rtol=1e-12)
    np.testing.assert_allclose(lin.J, full, rtol=1e-9, atol=1e-9 * np.abs(full).max())
    np.testing.assert_allclose(lin.H, curv, rtol=1e-9, atol=1e-9 * np.abs(curv).max())
    # the model reproduces the exact heat at the difference points (quadratic through
    # three points per read column) and its Jacobian is the model's derivative
    j_oil = cp.role_nodes[sim.bearings[0].name]["oil"][0]
    for d in (-0.5, 0.5):
        Td = T.copy()
        Td[j_oil] += d
        np.testing.assert_allclose(lin.heat(0.0, Td), cp.heat(step, Td), rtol=1e-10,
                                   atol=1e-9 * np.abs(q0).max())
    Td = T.copy()
    Td[j_oil] += 0.2
    np.testing.assert_allclose(lin.jac(0.0, Td)[:, j_oil],
                               lin.J[:, j_oil] + 0.2 * lin.H[:, j_oil], rtol=1e-12)
    moved = lin.moved(cp.heat(step, Td), Td)
    np.testing.assert_allclose(moved.J, lin.jac(0.0, Td), rtol=1e-12)
    np.testing.assert_array_equal(moved.H, lin.H)
    reads = sim.evaluate_heat(sim.bearings[0], step, sim.bearings[0].last,
                              cp.role_temperatures(sim.bearings[0], T)).reads
    assert "oil" in reads  # churning and the cage guide read the oil temperature
    if kinematics == "skidding":  # raceway shear at the solver's contact temperature
        assert not {"elements", "inner_ring", "outer_ring"} & reads


def test_role_temperatures_record_reads():
    from thermobearing.heat_sources import RoleTemperatures

    t = RoleTemperatures({"oil": 310.0, "elements": 320.0})
    assert not t.reads
    assert t["oil"] == 310.0 and t.get("cage") is None
    assert t.reads == {"oil", "cage"}
    t.reads.clear()
    dict(t.items())
    assert t.reads == {"oil", "elements"}


def test_exprb43_refusal_falls_back_to_tr_bdf2_with_a_warning(monkeypatch):
    import thermobearing.network as network
    from thermobearing.errors import ConvergenceError

    real = network.TransientStepper

    class Refusing(real):
        def __init__(self, net, method="tr_bdf2", **kw):
            super().__init__(net, method=method, **kw)
            self.method = method

        def advance(self, *args, **kwargs):
            if self.method == "exprb43":
                raise ConvergenceError("exprb43", float("inf"), "near-defective Jacobian", {})
            return super().advance(*args, **kwargs)

    monkeypatch.setattr(network, "TransientStepper", Refusing)
    text = BASE.replace('chunk = "90 s"', 'chunk = "90 s"\nstepper = "exprb43"') + """
[schedule]
speed = "1200 rpm"
radial_load = "1 kN"
axial_load = "6 kN"
duration = "3 min"
"""
    sim = Simulation(loads_scene(text), progress=False)
    res = sim.run()
    temps = res.tables["temperatures"]
    assert np.all(np.isfinite(temps.filter(like="[degC]").to_numpy()))
    assert any("exprb43 failed" in w and "tr_bdf2" in w for w in sim.warnings)


_CRB_SCENE = scene_title("CRB") + """[[bearings]]
name = "crb"
preset = "{preset}"
""" + CRB_RUN + """axial_load = "0 kN"
duration = "1 min"
""" + RACE_CONTROL + """{models}
[outputs]
want = ["losses"]
"""


def test_heat_source_options_reach_the_source_in_si():
    """[models] heat_source_options: unit strings converted with the registry's unit."""
    from thermobearing.simulation import scene_heat_source_options

    scene = loads_scene(_CRB_SCENE.format(
        preset="CRB_50x75x16",
        models='heat_source_options = { rib_friction = { unbalance_mass = "0.11 g", '
               'model = "reduced", temperature_step = 2 } }'))
    opts = scene_heat_source_options(scene, ("raceway_traction", "rib_friction"))
    assert opts == {"rib_friction": {"unbalance_mass": pytest.approx(1.1e-4),
                                     "model": "reduced", "temperature_step": 2.0}}
    assert "heat_source_options" in scene.to_toml()


@pytest.mark.parametrize("models, field", [
    ('heat_source_options = { not_a_source = { x = 1 } }', "heat_source_options.not_a_source"),
    ('heat_source_options = { rib_friction = { colour = 1 } }', "rib_friction.colour"),
    ('heat_source_options = { rib_friction = { unbalance_mass = "3 m" } }',
     "rib_friction.unbalance_mass"),
    ('heat_source_options = { rib_friction = 3 }', "heat_source_options.rib_friction"),
])
def test_bad_heat_source_options_name_the_field(models, field):
    scene = loads_scene(_CRB_SCENE.format(preset="CRB_50x75x16", models=models))
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        Simulation(scene, progress=False)


def test_heat_source_option_set_by_the_kinematics_is_refused():
    """The solver's own force-model options (here the pocket friction of the QJ1044's
    skidding solver) cannot be overridden: the heat would no longer be the power of the
    forces the solver balanced. Refused when the scene is built (``thermobearing check``),
    not at the first heat evaluation."""
    from thermobearing.scene import load_scene

    scene = load_scene()
    models = dict(scene.models)
    models["heat_source_options"] = {"pocket_friction": {"friction_coefficient": 0.1}}
    with pytest.raises(InputError, match="pocket_friction.friction_coefficient"):
        Simulation(dataclasses.replace(scene, models=models), progress=False)


def test_default_rib_friction_left_out_where_the_geometry_cannot_host_it():
    """NU214 (ribs on the outer ring, no end-face crown radius): the default roller sources
    run without rib_friction, and the run says so; naming it explicitly keeps the clear
    error."""
    sim = Simulation(loads_scene(_CRB_SCENE.format(preset="NU214", models="")), progress=False)
    assert "rib_friction" not in sim.bearings[0].sources
    assert all(link.name != "rib_friction" for link in sim.chain)
    said = [w for w in sim.warnings if "rib_friction left out" in w]
    assert len(said) == 1 and "ribs on the outer ring" in said[0]
    # no key of the bearing can fix outer-ring ribs: no hint to add geometry
    assert "end_face_crown_radius" not in said[0]
    named = _CRB_SCENE.format(preset="NU214", models='heat_sources = ["rib_friction"]')
    with pytest.raises(InputError, match=r"models\.heat_sources.*ribs on the outer ring"):
        Simulation(loads_scene(named), progress=False)  # before anything is solved


def test_output_interval_adds_dense_rows_without_changing_the_run(tmp_path):
    """[outputs] interval: temperature rows at every multiple of it from the stepper's dense
    output; the chunk-end rows are those of the run without it (bit for bit), the rows come
    in time order, the file holds them too, and the interval round-trips through TOML."""
    text = BASE + AXIAL_STEPS + """[outputs]
want = ["temperatures", "energy"]
"""
    plain = Simulation(loads_scene(text), progress=False).run()
    scene = loads_scene(text.replace('want = ["temperatures", "energy"]',
                                     'want = ["temperatures", "energy"]\ninterval = "20 s"'))
    assert scene.outputs.interval == 20.0
    assert loads_scene(scene.to_toml()).outputs.interval == 20.0
    dense = Simulation(scene, progress=False).run(out_dir=tmp_path)
    t0, t1 = plain.tables["temperatures"], dense.tables["temperatures"]
    times = t1["time [s]"].to_numpy()
    assert np.all(np.diff(times) > 0)
    expected = np.union1d(t0["time [s]"].to_numpy(), np.arange(0.0, 360.0 + 1e-9, 20.0))
    np.testing.assert_allclose(times, expected, rtol=0, atol=1e-9)
    ends = t1[t1["time [s]"].isin(t0["time [s]"])]
    assert ends.drop(columns=["time [min]"]).to_numpy().tolist() == \
        t0.drop(columns=["time [min]"]).to_numpy().tolist()
    col = "de.oil [degC]"
    # interior rows lie on the curve: between the neighbouring rows' range, and the first
    # 20 s of the oil's fast rise after the start are resolved (not a straight 90-s chord)
    assert t1[col].iloc[1] > t0[col].iloc[0] + 0.5 * (t0[col].iloc[1] - t0[col].iloc[0])
    written = np.loadtxt(tmp_path / "temperatures.csv", delimiter=",", skiprows=1,
                         usecols=0)
    np.testing.assert_allclose(written, times)
    # the energy rows stay per chunk
    assert len(dense.tables["energy"]) == len(plain.tables["energy"])


def test_stepper_samples_equal_the_dense_output_of_integrate():
    """TransientStepper.advance(sample_times=...) gives the temperatures integrate() gives
    at the same times for the same heat (one segment, same method and tolerances)."""
    from thermobearing.network import TransientStepper, integrate
    from thermobearing.network.problems import bearing_network

    net = bearing_network(4)
    n = len(net.state_nodes)

    def heat(t, T):
        return np.full(n, 80.0) * (1.0 + 3e-3 * (T - 308.15))

    ts = np.linspace(5.0, 295.0, 30)
    st = TransientStepper(net, method="exprb43", rtol=1e-7, atol=1e-5)
    out = st.advance(0.0, np.full(n, 308.15), 300.0, heat, sample_times=ts)
    ref = integrate(net, heat, (0.0, 300.0), 308.15, method="exprb43", rtol=1e-7,
                    atol=1e-5)
    np.testing.assert_allclose(out.samples, ref.sample(ts), rtol=0, atol=1e-9)
    np.testing.assert_allclose(out.temperatures, ref.temperatures[-1], rtol=0, atol=1e-12)
    with pytest.raises(InputError, match="sample_times"):
        st.advance(300.0, out.temperatures, 60.0, heat, sample_times=[10.0])


def test_loss_table_only_when_an_output_needs_it(monkeypatch):
    """The per-step loss table costs one evaluation of every source per step: it is made
    when the scene wants losses or the report, not for a temperatures-only scene (whose
    temperatures are the same)."""
    sched = AXIAL_STEPS + """[outputs]
want = [%s]
"""
    calls = []
    real = Simulation.evaluate_heat

    def counted(self, *a, **k):
        calls.append(bool(k.get("with_rows")))
        return real(self, *a, **k)

    monkeypatch.setattr(Simulation, "evaluate_heat", counted)
    full = Simulation(loads_scene(BASE + sched % '"temperatures", "losses"'),
                      progress=False).run()
    n_full, rows_full = len(calls), sum(calls)
    calls.clear()
    lean = Simulation(loads_scene(BASE + sched % '"temperatures"'), progress=False).run()
    assert "losses" in full.tables and "losses" not in lean.tables
    assert rows_full > 0 and sum(calls) == 0 and len(calls) == n_full - rows_full
    cols = [c for c in full.tables["temperatures"].columns if c.endswith("[degC]")]
    np.testing.assert_array_equal(lean.tables["temperatures"][cols].to_numpy(),
                                  full.tables["temperatures"][cols].to_numpy())
