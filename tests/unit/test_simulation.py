"""Orchestrator: the chain holds only what the outputs need; runs produce the tables."""

from __future__ import annotations

import numpy as np
import pytest
from scene_parts import PAPER002_OIL, QJ1044_DE, RACE_CONTROL, scene_title

from thermobearing.errors import InputError
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation, plan_chain

BASE = scene_title("t") + QJ1044_DE + PAPER002_OIL + """[schedule]
speed = "1800 rpm"
radial_load = "1 kN"
step_duration = "3 min"
axial_load_steps = { start = "2 kN", stop = "6 kN", step = "4 kN" }
""" + RACE_CONTROL


def scene(want, mode="steady"):
    return loads_scene(BASE + f'[outputs]\nmode = "{mode}"\nwant = {want!r}\n'.replace("'", '"'))


def test_film_scene_runs_no_kinematics_no_network():
    sim = Simulation(scene(["film"]), progress=False)
    families = [link.family for link in sim.chain]
    assert "film" in families
    assert "kinematics" not in families and "heat_source" not in families
    assert "network_template" not in families and "stepper" not in families
    res = sim.run()
    film = res.tables["film"]
    assert set(film["race"]) >= {"inner", "outer"} or len(film) >= 2
    assert (film["central film [um]"] > 0).all()
    # Lambda = h / (0.1^2 + 0.025^2)^(1/2) um with the QJ1044 preset's roughness estimates
    np.testing.assert_allclose(film["film parameter [-]"],
                               film["central film [um]"] / np.hypot(0.1, 0.025), rtol=1e-12)
    assert "kinematics" not in res.tables


def test_losses_scene_has_no_network_and_balances_roles():
    sim = Simulation(scene(["kinematics", "losses"]), progress=False)
    families = [link.family for link in sim.chain]
    assert "heat_source" in families and "network_template" not in families
    res = sim.run()
    kin = res.tables["kinematics"]
    assert len(kin) == 2
    assert kin["cage speed ratio [-]"].between(0.4, 0.5).all()
    losses = res.tables["losses"]
    assert (losses["power [W]"] >= 0).all()
    assert set(losses["source"]) >= {"raceway_traction", "churning_elements"}
    assert res.citations


def test_oil_bath_says_its_inlet_temperature_is_unused():
    bath = loads_scene(BASE.replace('flow = "33 L/min"', 'method = "oil_bath"\nlevel = "20 mm"')
                       .replace('inlet_temperature = "35 degC"', 'inlet_temperature = "50 degC"')
                       + '[outputs]\nmode = "steady"\nwant = ["losses"]\n')
    sim = Simulation(bath, progress=False)
    assert any("supply.inlet_temperature (50 degC) is not used" in n for n in sim.notes)
    assert "supply.inlet_temperature" in sim.describe_chain()
    assert not any("inlet_temperature" in n
               for n in Simulation(scene(["losses"]), progress=False).notes)
    # an oil bath that leaves the inlet temperature at its default (the ambient) gets no note
    default = loads_scene(BASE.replace('flow = "33 L/min"', 'method = "oil_bath"\nlevel = "20 mm"')
                          .replace('inlet_temperature = "35 degC"\n', '')
                          + '[outputs]\nmode = "steady"\nwant = ["losses"]\n')
    assert default.supply.inlet_temperature == default.environment.ambient_temperature
    assert not any("inlet_temperature" in n for n in Simulation(default, progress=False).notes)


def test_unknown_model_family_is_an_error():
    bad = loads_scene(BASE.replace('kinematics = "race_control"',
                                   'kinematics = "race_control"\ncolour = "red"'))
    with pytest.raises(InputError) as info:
        plan_chain(bad)
    assert "models.colour" in str(info.value)


def test_unknown_kinematics_lists_known():
    bad = loads_scene(BASE.replace('"race_control"', '"magic"'))
    with pytest.raises(InputError) as info:
        Simulation(bad, progress=False)
    assert "race_control" in str(info.value) and "skidding" in str(info.value)


def test_global_friction_rung_runs_without_kinematics():
    """L0 of the fidelity ladder: [models] kinematics = "none" with the global model."""
    text = BASE.replace('kinematics = "race_control"', 'kinematics = "none"') + (
        '[outputs]\nmode = "steady"\nwant = ["kinematics", "losses"]\n')
    sim = Simulation(loads_scene(text), progress=False)
    names = [(link.family, link.name) for link in sim.chain]
    assert ("heat_source", "global_friction") in names
    assert ("heat_source", "raceway_traction") not in names
    res = sim.run()
    losses = res.tables["losses"]
    assert set(losses["source"]) == {"global_friction"}
    assert (losses["power [W]"] > 0).all()
    kin = res.tables["kinematics"]
    assert (kin["over-skidding [%]"] == 0).all()


def test_skidding_heat_sources_book_the_solver_shaft_power():
    """At the temperatures the skidding solver ran at, the scene's heat sources (raceway
    shear with the solver's own traction law, churning, cage guide, pocket) add up to the
    solver's shaft power omega_i M_shaft to 1e-8 relative (issue 5's energy identity, through
    the scene's kinematics and heat-source chain)."""
    text = BASE.replace('kinematics = "race_control"', 'kinematics = "skidding"')
    sim = Simulation(loads_scene(text + '[outputs]\nmode = "steady"\nwant = ["losses"]\n'),
                     progress=False)
    b = sim.bearings[0]
    step = sim.scene.schedule.steps[0]
    temps = dict.fromkeys(("inner_ring", "outer_ring", "elements", "cage", "oil"), 320.0)
    kin = sim.solve_kinematics(b, 0, step, temps)
    assert kin.traction is kin.raw.extra["traction_law"]
    ev = sim.evaluate_heat(b, step, kin, temps)
    shaft_power = kin.raw.shaft_torque * step.speed
    assert sum(ev.by_role.values()) == pytest.approx(shaft_power, rel=1e-8)


def test_run_warns_of_skidding_steps_in_its_results():
    """The QJ1044 at 1800 r/min skids at zero axial load (CSR about 0.21 against 0.45) and
    over-skids at 4 kN (paper 002's bulge): the run's warnings name the bearing and the
    steps (operating_checks); the film parameter is checked (the preset gives its
    roughness) and nothing else is flagged."""
    sc = loads_scene(BASE.replace('kinematics = "race_control"', 'kinematics = "skidding"')
                     .replace('start = "2 kN"', 'start = "0 kN"')
                     + '[outputs]\nmode = "steady"\nwant = ["kinematics"]\n')
    sim = Simulation(sc, progress=False)
    res = sim.run()
    lines = [w for w in res.warnings if w.startswith("de: ")]
    assert len(lines) == 2, res.warnings
    text = sim.summary_text(res)
    assert f"validity warnings ({len(res.warnings)}; all in the report):" in text
    assert f"  - {lines[0]}" in text
    assert "cage skidding" in lines[0] and "(step 0)" in lines[0]
    assert "cage over-skidding" in lines[1] and "(step 1)" in lines[1]


def test_sweep_summary_carries_the_validity_extremes():
    """summarize_scene (the sweep runner) reports the largest Hertz pressure and the
    smallest film parameter of the solved states, so a sweep can map them."""
    from thermobearing.simulation import summarize_scene

    out = summarize_scene(scene(["kinematics", "losses"]).to_toml())
    # QJ1044 at 2 and 6 kN axial + 1 kN radial: about 0.8-1 GPa, Lambda well above 3
    assert 500.0 < out["max contact pressure [MPa]"] < 2000.0
    assert out["min film parameter [-]"] > 3.0
    assert out["mean total loss [W]"] > 0.0


def test_sweep_summary_weights_steps_by_duration_and_counts_flagged_steps():
    """summarize_scene: ``mean total loss [W]`` is the scene's loss (every bearing) averaged
    over the protocol with each step weighted by its duration, per-bearing totals beside it;
    ``steps over ... limit [-]`` count the steps the [checks] thresholds flag (earlier versions:
    the loss was the plain step mean of the first bearing, and a sweep of the thresholds
    gave identical rows). Hand check: the step losses from the losses table."""
    import pandas as pd

    from thermobearing.simulation import summarize_scene

    two = BASE.replace('[lubricant]', '[[bearings]]\nname = "nde"\npreset = "QJ1044"\n'
                       '[lubricant]').replace(
        'step_duration = "3 min"\naxial_load_steps = { start = "2 kN", stop = "6 kN", '
        'step = "4 kN" }',
        'steps = [{ duration = "1 min", axial_load = "2 kN" }, '
        '{ duration = "3 min", axial_load = "6 kN" }]')
    text = two + '[outputs]\nmode = "steady"\nwant = ["losses", "kinematics"]\n'
    res = Simulation(loads_scene(text), progress=False).run()
    per_step = res.tables["losses"].groupby("step")["power [W]"].sum()
    out = summarize_scene(loads_scene(text).to_toml())
    assert out["mean total loss [W]"] == pytest.approx(
        0.25 * per_step[0] + 0.75 * per_step[1], rel=1e-12)
    assert out["max total loss [W]"] == pytest.approx(per_step.max(), rel=1e-12)
    assert out["mean total loss de [W]"] + out["mean total loss nde [W]"] == pytest.approx(
        out["mean total loss [W]"], rel=1e-12)
    sources = [k for k in out if k.endswith("[W]") and not k.startswith(("mean total", "max"))]
    assert sum(out[k] for k in sources) == pytest.approx(out["mean total loss [W]"], rel=1e-12)
    assert out["steps over skid limit [-]"] == 0.0 and out["steps over stress limit [-]"] == 0
    strict = summarize_scene(loads_scene(
        text + '[checks]\nskid_limit = "0.01 %"\ncontact_stress_limit = "100 MPa"\n').to_toml())
    # race control runs 2-4 % off paper 002's CSR_th but rolls by construction: no step
    # skids under any limit
    assert strict["steps over skid limit [-]"] == 0.0
    # both steps of both bearings are over 100 MPa: each step counts once, however many
    # bearings it flags (earlier versions summed over the bearings: 4 for a 2-step protocol)
    assert strict["steps over stress limit [-]"] == 2.0
    # thresholds change no physics
    assert strict["mean total loss [W]"] == out["mean total loss [W]"]
    assert isinstance(pd.Series(out).sum(), float)


def test_sweep_summary_of_a_film_only_scene_gives_the_films():
    from thermobearing.simulation import summarize_scene

    """A film-only sweep case gives the film table's smallest central film and film
    parameter (only the check extremes; the QJ1044 rows here are about 2.6 um
    and Lambda about 25, as in test_film_scene_runs_no_kinematics_no_network)."""
    out = summarize_scene(scene(["film"]).to_toml())
    assert 1.0 < out["min central film [um]"] < 5.0
    assert out["min film parameter [-]"] > 3.0
    assert "mean total loss [W]" not in out and "max over-skidding [%]" not in out


def test_global_friction_books_each_term_with_its_load_class():
    """The L0 source books the SKF model's terms (rolling, sliding, drag; no seal row for an
    open bearing) as components with their FVA load class, adding up to M omega."""
    text = BASE.replace('kinematics = "race_control"', 'kinematics = "none"') + (
        '[outputs]\nmode = "steady"\nwant = ["losses"]\n')
    losses = Simulation(loads_scene(text), progress=False).run().tables["losses"]
    step0 = losses[losses["step"] == 0]
    by_comp = step0.groupby("component")["power [W]"].sum()
    assert set(by_comp.index) == {"skf_four_term rolling", "skf_four_term sliding",
                                  "skf_four_term drag"}
    classes = dict(zip(step0["component"], step0["load dependence"], strict=False))
    assert classes["skf_four_term drag"] == "load_independent"
    assert classes["skf_four_term rolling"] == classes["skf_four_term sliding"] == \
        "load_dependent"
    assert (by_comp > 0).all()
