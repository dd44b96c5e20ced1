"""Defects met running a cylindrical roller bearing rig (NU 214 and friends): a protocol
with a stop, jet and oil bath, two bearings on one shaft, the report's loss tables."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from scene_parts import ROOM_22C, VG46_2LPM, scene_title

from thermobearing.errors import InputError
from thermobearing.report_losses import glossary, loss_class_of
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

# both rings ribbed: the cage must then clear the outer ribs (65.515 mm bore)
BOTH = 'overrides = { ribbed_ring = "both", cage = { outer_diameter = "65 mm" } }'


def _losses_with_a_stop() -> pd.DataFrame:
    """A losses table as a run writes it: step 0 turning (each component classed), step 1 at
    rest (every source books one 0 W row with an empty class cell)."""
    rows = []
    for src, comp, cls in (("raceway_traction", "outer contact", "load_dependent"),
                           ("churning_elements", "element churning", "load_independent"),
                           ("pocket_friction", "roller pocket", "load_independent")):
        rows.append({"step": 0, "bearing": "test", "speed [rpm]": 3000.0, "source": src,
                     "component": comp, "role": "oil", "power [W]": 10.0,
                     "load dependence": cls})
        rows.append({"step": 1, "bearing": "test", "speed [rpm]": 0.0, "source": src,
                     "component": "at rest", "role": "oil", "power [W]": 0.0,
                     "load dependence": ""})
    return pd.DataFrame(rows)


def test_a_stop_in_the_protocol_does_not_make_every_source_mixed():
    losses = _losses_with_a_stop()
    assert loss_class_of(losses) == {"raceway_traction": "load-dependent",
                                     "churning_elements": "load-independent",
                                     "pocket_friction": "load-independent"}
    # read back from the CSV the empty cells are NaN: same classes
    nan = losses.assign(**{"load dependence": losses["load dependence"].replace("", None)})
    assert loss_class_of(nan) == loss_class_of(losses)
    table = glossary(losses).set_index("in the CSV files")["class"]
    assert table["raceway_traction"] == "load-dependent"


def test_a_source_with_two_classes_is_mixed_and_one_without_any_is_blank():
    losses = _losses_with_a_stop()
    extra = pd.DataFrame([
        {"step": 0, "bearing": "test", "speed [rpm]": 3000.0, "source": "churning_elements",
         "component": "other", "role": "oil", "power [W]": 1.0,
         "load dependence": "load_dependent"},
        {"step": 0, "bearing": "test", "speed [rpm]": 3000.0, "source": "plugin_source",
         "component": "x", "role": "oil", "power [W]": 1.0, "load dependence": ""}])
    classes = loss_class_of(pd.concat([losses, extra], ignore_index=True))
    assert classes["churning_elements"] == "mixed"
    assert classes["plugin_source"] == ""


def _crb_scene(bearing: str, kinematics: str, axial: str = "2 kN", extra_models: str = "",
               overrides: str = "") -> str:
    return f"""
title = "CRB rig, axial load"
[[bearings]]
name = "de"
preset = "{bearing}"
{overrides}
{VG46_2LPM}{ROOM_22C}[schedule]
radial_load = "8 kN"
step_duration = "3 min"
speed = "3000 rpm"
steps = [{{ axial_load = "0 kN" }}, {{ axial_load = "{axial}" }}]
[models]
kinematics = "{kinematics}"
{extra_models}
[network]
template = "four_node_paper002"
parameters = {{ housing_outer_diameter = "200 mm", housing_length = "50 mm" }}
[outputs]
want = ["temperatures", "losses"]
"""


@pytest.mark.parametrize("kinematics", ["race_control", "skidding", "none"])
def test_an_axial_load_on_an_nu_bearing_is_refused_before_the_solve(kinematics):
    """NU 214 (ribbed_ring = "outer"): no inner-ring rib, no path for an axial load. Race
    control used to run it and book nothing for it; the skidding solver refused it only
    at the step, in N. Now Simulation (and so `check`) names the step, the value in kN and
    what to change."""
    extra = ('heat_sources = ["global_friction"]' if kinematics == "none" else "")
    with pytest.raises(InputError) as err:
        Simulation(loads_scene(_crb_scene("NU214", kinematics, extra_models=extra)),
                   progress=False)
    msg = str(err.value)
    assert "schedule step 1 axial_load (bearing 'de', NU214) = '2 kN'" in msg
    assert "NU-type" in msg and "ribbed_ring = 'both'" in msg


def test_an_axial_load_under_the_roller_skidding_solver_says_to_use_race_control():
    scene = _crb_scene("CRB_50x75x16", "skidding", overrides=BOTH)
    with pytest.raises(InputError, match="kinematics = 'race_control'") as err:
        Simulation(loads_scene(scene), progress=False)
    assert "= '2 kN'" in str(err.value)


def test_race_control_axial_load_without_the_rib_source_is_warned():
    scene = _crb_scene("CRB_50x75x16", "race_control",
                       overrides=BOTH,
                       extra_models='heat_sources = ["raceway_traction", "churning_elements"]')
    sim = Simulation(loads_scene(scene), progress=False)
    assert any("axial load of steps 1 books no loss" in w for w in sim.warnings)
    # with the rib source named (the default set includes it) nothing is said
    ok = Simulation(loads_scene(_crb_scene("CRB_50x75x16", "race_control",
                                           overrides=BOTH)),
                    progress=False)
    assert not any("books no loss" in w for w in ok.warnings)
    # no axial load anywhere: no check at all (NU 214, the usual radial rig)
    plain = Simulation(loads_scene(_crb_scene("NU214", "skidding", axial="0 kN")),
                       progress=False)
    assert not any("axial" in w for w in plain.warnings)


def test_race_control_film_range_check_sees_only_the_loaded_rollers():
    """NU 214 under a radial load: the rollers outside the load zone carry nothing. They went
    into the film formula at a stand-in load of 1 N, so every race-control run warned of a load
    parameter W' (~6e-8) far below Pan-Hamrock's range, taken from no real contact. The
    range warning now sees the loaded rollers only: its lower end is the smallest loaded
    roller's W' = Q / (E' R_x L)."""
    import re
    import warnings

    from thermobearing.errors import ValidityWarning
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.state import OperatingPoint, race_control_state

    b = load_bearing("NU214")
    op = OperatingPoint(inner_speed=3000 * np.pi / 30, radial_load=8000.0, axial_load=0.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        state = race_control_state(b, op, lubricant=load_lubricant("ISO_VG46"),
                                   temperature=323.15)
    lows = {}
    for w in caught:
        m = re.search(r"pan_hamrock_central: W in \[([0-9.e+-]+),", str(w.message))
        if m and issubclass(w.category, ValidityWarning):
            lows[len(lows)] = float(m.group(1))
    loaded_w = []
    # the inner contacts have an unloaded zone (the outer ones carry the rollers'
    # centrifugal force all round)
    assert (np.asarray(state.contacts[0].normal_load) == 0).any()
    for c in state.contacts:
        q = np.asarray(c.normal_load, float)
        h = np.asarray(c.film_thickness, float)
        assert np.all(h[q == 0] == 0.0) and np.all(np.isfinite(h)) and np.all(h[q > 0] > 0)
        rx = np.broadcast_to(np.asarray(c.reduced_radius_x, float), q.shape)
        loaded_w.append(q[q > 0] / (b.effective_modulus * rx[q > 0]
                                    * b.roller_effective_length))
    w_one_newton = 1.0 / (b.effective_modulus * float(np.min(rx)) * b.roller_effective_length)
    smallest = min(float(np.min(w)) for w in loaded_w)
    assert smallest > 5 * w_one_newton
    for low in lows.values():
        assert low >= smallest * (1 - 1e-3)


_STOPPED_SCENE = scene_title("NU 214 rig, two speed steps") + """[[bearings]]
name = "test"
preset = "NU214"
""" + VG46_2LPM + ROOM_22C + """[schedule]
radial_load = "8 kN"
axial_load = "0 kN"
step_duration = "3 min"
steps = [{ speed = "3000 rpm" }, { speed = "6000 rpm" }]
[network]
template = "four_node_paper002"
parameters = { housing_outer_diameter = "200 mm", housing_length = "50 mm" }
[outputs]
want = ["temperatures", "losses", "kinematics", "energy"]
"""


def test_a_run_stopped_by_an_error_says_where_its_steps_are_and_its_report_says_why(
        tmp_path, capsys, monkeypatch):
    """A transient that stops (here a thermal runaway raised in the second step) used to
    leave a folder whose `thermobearing report` read as a finished run: no validity
    warnings (the cage skid checks of the solved steps lost), no model chain, no estimated
    inputs and no word of the stop; the terminal did not say where the steps were."""
    import json

    import thermobearing.network as network
    from thermobearing.cli import main
    from thermobearing.errors import ConvergenceError

    advance = network.TransientStepper.advance
    calls = []

    def runaway(self, t, *args, **kwargs):
        calls.append(t)
        if t >= 180.0 - 1e-9:  # any chunk of the second step (and its tr_bdf2 retry)
            raise ConvergenceError("coupled transient", 116.0, "thermal runaway: node "
                                   "'test.rollers' reached 416 degC", {"step": 1})
        return advance(self, t, *args, **kwargs)

    monkeypatch.setattr(network.TransientStepper, "advance", runaway)
    scene = tmp_path / "rig.toml"
    scene.write_text(_STOPPED_SCENE, encoding="utf-8")
    out = tmp_path / "res"
    code = main(["run", str(scene), "--out", str(out), "--quiet"])
    err = capsys.readouterr().err
    assert code == 1
    assert "thermobearing run: error: coupled transient did not converge" in err
    assert f"the steps computed before the error are in {out}/" in err
    meta = json.loads((out / "metadata.json").read_text())
    assert meta["warnings"][0].startswith("run stopped by an error: coupled transient")
    assert ["kinematics", "skidding"] in meta["chain"]
    assert "bearing test (NU214)" in meta["estimated"]
    assert (out / "temperatures.csv").is_file() and (out / "losses.csv").is_file()
    assert main(["report", str(out)]) == 0
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "run stopped by an error" in html and "pan_hamrock_central" in html


def test_terminal_csr_line_skips_steps_at_rest_and_names_each_bearing():
    """A protocol starting at rest printed "CSR at first step: nan"; a two-bearing shaft
    printed the first bearing's ratio only, unnamed."""
    from thermobearing.simulation import _first_csr_lines

    def row(step, bearing, csr, theo, skid):
        return {"step": step, "bearing": bearing, "cage speed ratio [-]": csr,
                "theoretical cage speed ratio [-]": theo, "over-skidding [%]": skid}

    nan = float("nan")
    one = pd.DataFrame([row(0, "test", nan, 0.4333, nan), row(1, "test", 0.4321, 0.4333, -0.28)])
    lines = _first_csr_lines(one)
    assert lines[0] == "CSR at first turning step: 0.4321 (theoretical 0.4333, step 1)"
    assert "nan" not in " ".join(lines)
    assert lines[1] == "over-skidding: max -0.28 %, min -0.28 %"
    two = pd.DataFrame([row(0, "de", 0.4214, 0.4214, 0.0), row(0, "nde", 0.3701, 0.3677, 0.66)])
    assert _first_csr_lines(two)[0] == ("CSR at first turning step: de 0.4214 (theoretical "
                                        "0.4214), nde 0.3701 (theoretical 0.3677)")
    assert _first_csr_lines(one.iloc[:1]) == ["cage speed ratio: every step at rest "
                                              "(undefined)"]
    assert _first_csr_lines(one.iloc[1:].assign(step=0))[0].startswith("CSR at first step: ")


def test_a_turning_step_without_radial_load_under_roller_skidding_is_refused_at_check():
    """NU 214 (clearance 25 um) at 0 kN radial: the roller skidding solver stopped at the
    step ("no roller touches the inner ring ... the cage speed is undetermined") after
    `check` had passed it, with no word of what to change."""
    text = _crb_scene("NU214", "skidding", axial="0 kN").replace(
        'steps = [{ axial_load = "0 kN" }, { axial_load = "0 kN" }]',
        'axial_load = "0 kN"\nsteps = [{ speed = "0 rpm", radial_load = "0 kN" }, '
        '{ radial_load = "0 kN" }]')
    assert 'radial_load = "0 kN" }]' in text
    with pytest.raises(InputError) as err:
        Simulation(loads_scene(text), progress=False)
    msg = str(err.value)  # step 0 is at rest: no solver runs there, so step 1 is named
    assert "schedule step 1 radial_load (bearing 'de', NU214) = '0 kN'" in msg
    assert "kinematics = 'race_control'" in msg and "0.025 mm" in msg
    # race control runs it (the ring is centred; nothing to solve for the cage)
    ok = Simulation(loads_scene(text.replace('kinematics = "skidding"',
                                             'kinematics = "race_control"')), progress=False)
    assert ok.bearings[0].kinematics_name == "race_control"


def test_a_shaft_with_a_ball_and_a_roller_bearing_lists_the_models_of_both():
    """Ball bearing at the non-drive end named first, NU 214 at the drive end: the model
    chain (`check`, the report's model table and citations) was planned for the first
    bearing's kind only, so it left out the roller bearing's film model and its EHL
    rolling resistance, which the run did use."""
    text = _crb_scene("NU214", "skidding", axial="0 kN").replace(
        '[[bearings]]\nname = "de"',
        '[[bearings]]\nname = "nde"\npreset = "SKF6304"\n[[bearings]]\nname = "de"')
    sim = Simulation(loads_scene(text), progress=False)
    assert [b.is_ball for b in sim.bearings] == [True, False]
    chain = [(link.family, link.name) for link in sim.chain]
    assert ("film", "hamrock_dowson_1977_central") in chain
    assert ("film", "pan_hamrock_central") in chain
    assert ("heat_source", "ehl_rolling_resistance") in chain
    assert "ehl_rolling_resistance" in sim.bearings[1].sources
    text_chain = sim.describe_chain()
    assert "(roller bearings)" in text_chain and "(ball bearings)" in text_chain
    # one kind: one film line, worded as before
    single = Simulation(loads_scene(_crb_scene("NU214", "skidding", axial="0 kN")),
                        progress=False)
    films = [link for link in single.chain if link.family == "film"]
    assert [f.purpose for f in films] == ["film thickness of the raceway contacts"]


def test_catalogue_roller_bearing_lists_its_rib_type_and_straight_length_as_estimated():
    """An NU 2xx page gives d, D, B and the roller set; estimate_missing filled the ribs
    (NU type) and the straight roller length through the geometry's defaults without
    listing them, so `check` did not show that an NJ / NUP bearing must say so."""
    from thermobearing.bearing_config import bearing_from_dict

    page = {"name": "NU 210", "kind": "cylindrical", "source": "catalogue page",
            "estimate_missing": True, "bore": "50 mm", "outer_diameter": "90 mm",
            "width": "20 mm", "roller_diameter": "11 mm", "roller_length": "11 mm",
            "n_rollers": 14}
    b = bearing_from_dict(page)
    assert b.ribbed_ring == "outer" and b.roller_effective_length == pytest.approx(0.011)
    assert b.estimated["ribbed_ring"].startswith("estimate_missing: 'outer': NU type")
    assert "11 mm" in b.estimated["roller_effective_length"]
    # values the page gives are kept and not marked
    nj = bearing_from_dict({**page, "ribbed_ring": "both", "roller_effective_length": "10 mm"})
    assert nj.ribbed_ring == "both" and nj.roller_effective_length == pytest.approx(0.010)
    assert "ribbed_ring" not in nj.estimated and "roller_effective_length" not in nj.estimated


def _oil_node_network():
    from thermobearing.network import ThermalNetwork

    net = ThermalNetwork()
    net.add_boundary("ambient", 300.0)
    net.add_node("oil", 5e3, role="oil")
    net.add_edge("oil", "ambient", 5.0)
    return net


def test_steady_pass_without_a_steady_state_is_retried_with_the_heat_held_near_t0():
    """The chunk model of NU 214 at 16 kN / 3000 r/min, measured on the steady run that
    stopped ('network steady Newton did not converge ... line search failed'): heat to the
    oil 150.7 W at 338.3 K, slope -10.45 W/K, curvature -39.9 W/K^2 (a churning regime
    jump inside the difference stencil), continued linearly beyond 2 K. On one oil node
    with 5 W/K to 300 K it has no steady state where it gives heat (the heat floor of the
    chunk model leaves only the heat-free state at the ambient); held beyond 10 K of T0 it
    has one, which balances the held heat, and where the model has a root near T0 the held
    model has the same one."""
    from thermobearing.coupled import STEADY_TRUST_REGION, _HeldBeyond, _Linear
    from thermobearing.errors import ConvergenceError
    from thermobearing.network import solve_steady

    net = _oil_node_network()
    lin = _Linear(q0=np.array([150.7]), J=np.array([[-10.45]]), T0=np.array([338.3]),
                  H=np.array([[-39.9]]))
    d = np.linspace(-200.0, 200.0, 4001)
    q = np.array([lin.heat(0.0, np.array([338.3 + x]))[0] for x in d])
    f = -5.0 * (338.3 + d - 300.0) + q
    assert max(f[q > 0.0]) < 0  # no root where the model gives heat
    # the model's heat is floored at min(q0, 0) = 0 (coupled._Linear), so its only steady
    # state is the spurious one where the extrapolated heat has been floored away: the oil
    # at the ambient with no heat at all, 38 K outside the region the model is trusted in
    try:
        spurious = solve_steady(net, lin.heat, T_guess=np.array([338.3]),
                                heat_jacobian=lin.jac).temperatures["oil"]
    except ConvergenceError:
        spurious = None
    if spurious is not None:
        assert lin.heat(0.0, np.array([spurious]))[0] == 0.0
        assert abs(spurious - 338.3) > STEADY_TRUST_REGION
    held = _HeldBeyond(lin, STEADY_TRUST_REGION)
    res = solve_steady(net, held.heat, T_guess=np.array([338.3]), heat_jacobian=held.jac)
    t_oil = res.temperatures["oil"]
    assert 5.0 * (t_oil - 300.0) == pytest.approx(held.heat(0.0, np.array([t_oil]))[0],
                                                  abs=1e-6)
    # a model with a root inside the region: the same root with and without holding
    mild = _Linear(q0=np.array([150.7]), J=np.array([[-10.45]]), T0=np.array([330.0]))
    a = solve_steady(net, mild.heat, T_guess=np.array([330.0]), heat_jacobian=mild.jac)
    kept = _HeldBeyond(mild, STEADY_TRUST_REGION)
    b = solve_steady(net, kept.heat, T_guess=np.array([330.0]), heat_jacobian=kept.jac)
    assert abs(a.temperatures["oil"] - 330.0) < STEADY_TRUST_REGION
    assert b.temperatures["oil"] == pytest.approx(a.temperatures["oil"], abs=1e-9)


@pytest.mark.slow
def test_nu214_steady_state_at_16_kn_is_found():
    """The steady run that stopped in a sweep over the radial load (NU 214, 3000 r/min,
    16 kN, 2 L/min jet) now finds the steady state; the transient's hour at the same
    point (measured: rollers 81.48 degC, still rising by < 2e-3 K per 5 min) ends within
    the kinematics tolerance of it (3 % viscosity: measured 81.2 degC steady)."""
    text = _STOPPED_SCENE.replace('steps = [{ speed = "3000 rpm" }, { speed = "6000 rpm" }]',
                                  'speed = "3000 rpm"').replace('"8 kN"', '"16 kN"')
    steady_text = text.replace('want = ["temperatures", "losses", "kinematics", "energy"]',
                               'mode = "steady"\nwant = ["temperatures", "losses"]')
    assert 'mode = "steady"' in steady_text
    steady = Simulation(loads_scene(steady_text), progress=False).run()
    t = steady.tables["steady_temperatures"]
    assert np.all(np.isfinite(t.filter(like="[degC]").to_numpy()))
    transient = Simulation(loads_scene(text.replace('step_duration = "3 min"',
                                                    'step_duration = "60 min"')),
                           progress=False).run()
    end = transient.tables["temperatures"].iloc[-1]
    assert abs(t["test.rollers [degC]"].iloc[0] - end["test.rollers [degC]"]) < 1.0
    assert abs(t["test.oil [degC]"].iloc[0] - end["test.oil [degC]"]) < 0.5


def test_steady_outer_passes_are_relaxed_and_never_visit_absurd_temperatures(monkeypatch):
    """NU 214 at 10000 r/min after a step at 3000 r/min, steady mode: the outer passes
    (kinematics held, network solved) used to jump from 39 to 745 degC and oscillate for 20
    passes (745, 97, 312, 126, ... degC), and the 745 degC pass left a lubricant warning of
    a state the run never reached. Measured now: 6 passes at 3000 r/min, no pass above the
    solution by more than 100 K, and the steady state within 0.3 K of a 90-min transient
    (rollers 66.85 degC steady, 67.06 degC transient at 3000 r/min, 8 kN; the kinematics at
    the contacts' inlet temperature, kinematic_models.contact_temperature; the transient's
    spread is its kinematics tolerance. 73.74 / 73.68 degC until 2026-11-23, when the roller
    sources booked the solver's inlet/outlet shear and pocket film force and eq. 35 took the
    mean speed; 66.85 degC until 2026-11-24, when the skidding solver took the heat
    source's default Gupta inlet-heating reduction of the rolling force: 65.83 degC, the
    transient not re-run)."""
    import thermobearing.network as network

    seen = []
    solve = network.solve_steady

    def spy(*args, **kwargs):
        res = solve(*args, **kwargs)
        seen.append(float(np.max(res.temperatures_vector)))
        return res

    monkeypatch.setattr(network, "solve_steady", spy)
    text = _STOPPED_SCENE.replace(
        'steps = [{ speed = "3000 rpm" }, { speed = "6000 rpm" }]', 'speed = "3000 rpm"'
    ).replace('want = ["temperatures", "losses", "kinematics", "energy"]',
              'mode = "steady"\nwant = ["temperatures", "losses"]')
    assert 'mode = "steady"' in text
    sim = Simulation(loads_scene(text), progress=False)
    res = sim.run()
    rollers = float(res.tables["steady_temperatures"]["test.rollers [degC]"].iloc[0])
    assert abs(rollers - 65.83) < 0.5
    assert res.stats["outer_iterations"] <= 8
    assert max(seen) - 273.15 < rollers + 100.0
    assert not any("alpha fit used outside" in w for w in sim.warnings)


def test_a_bath_level_left_in_a_jet_scene_is_noted():
    """Switching a scene from oil bath to jet and leaving `level` in [supply] ran without a
    word (the jet's oil fraction comes from its flow)."""
    text = _crb_scene("NU214", "skidding", axial="0 kN").replace(
        'inlet_temperature = "40 degC"', 'inlet_temperature = "40 degC"\nlevel = "10 mm"')
    sim = Simulation(loads_scene(text), progress=False)
    assert sim.notes == ['supply.level (10 mm) is not used by the jet supply: only an oil '
                         'bath (supply.method = "oil_bath") has a level']
    assert "note: supply.level (10 mm)" in sim.describe_chain()
    plain = Simulation(loads_scene(_crb_scene("NU214", "skidding", axial="0 kN")),
                       progress=False)
    assert plain.notes == []


def test_an_oil_bath_level_above_the_bearing_is_noted():
    """`level = 5` (no unit: 5 m) ran as a fully immersed bearing without a word; a level
    above the top of the outer raceway is now noted (with the unit hint), a normal one not."""
    def bath(level: str) -> str:
        return _crb_scene("NU214", "race_control", axial="0 kN").replace(
            'flow = "2 L/min"', f'method = "oil_bath"\nflow = "0 L/min"\nlevel = {level}')

    sim = Simulation(loads_scene(bath("5")), progress=False)
    notes = [n for n in sim.notes if n.startswith("supply.level (5000 mm) is above")]
    assert len(notes) == 1 and "fully immersed" in notes[0] and '"5 mm"' in notes[0]
    normal = Simulation(loads_scene(bath('"10 mm"')), progress=False)
    assert not any("is above the top" in n for n in normal.notes)
