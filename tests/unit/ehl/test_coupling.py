"""Scene ``film = "numerical_tehl"``: the tabulated thermal EHL in the roller quasi-dynamics.

Fast settings throughout (n = 256 nodes, nearest-node tables); the physics check is the
direction paper 001 (seed 001_5ba4564faedebfb7.txt, section 4.1, Figs. 5-6) shows: at
13218 r/min the thermal film of D1842926 is far below the closed-form (isothermal) film.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.ehl.coupling import TehlFilmModel, roller_film_model, tehl_contact_forces
from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation, plan_chain

SCENE = """
title = "D1842926 TEHL test"
source = "seed paper 001 section 4.1 (test scene)"
[[bearings]]
name = "b"
preset = "D1842926"
[lubricant]
preset = "OIL_4109"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "30 degC"
[environment]
ambient_temperature = "30 degC"
[schedule]
speed = "13218 rpm"
radial_load = "24 kN"
axial_load = "0 kN"
step_duration = "1 min"
[models]
kinematics = "skidding"
film = "numerical_tehl"
[outputs]
mode = "steady"
want = ["{want}"]
"""

BALL_SCENE = SCENE.replace('preset = "D1842926"', 'preset = "QJ1044"').replace(
    'preset = "OIL_4109"', 'preset = "ISO_VG46"')

FAST = {"n": 256, "mode": "nearest", "min_moes_m": 5.0}


def _sim(want: str, **table) -> Simulation:
    sim = Simulation(loads_scene(SCENE.replace("{want}", want)), progress=False)
    b = sim.bearings[0]
    # coarse table for the test (the scene's default is n = 512, multilinear)
    b.kin_options["film_model"] = roller_film_model(b.bearing, sim.lubricant,
                                                    **{**FAST, **table})
    return sim


def test_ball_scene_naming_numerical_tehl_is_an_input_error():
    scene = loads_scene(BALL_SCENE.replace("{want}", "film"))
    with pytest.raises(InputError) as info:
        Simulation(scene, progress=False)
    msg = str(info.value)
    assert "models.film" in msg and "numerical_tehl" in msg
    assert "hamrock_dowson_1977_central" in msg  # the allowed closed-form models are listed
    assert "roller bearings only" in msg
    with pytest.raises(InputError):
        plan_chain(scene, None, is_ball=True)


def test_unknown_film_name_lists_numerical_models():
    scene = loads_scene(SCENE.replace("{want}", "film").replace('"numerical_tehl"', '"tehl"'))
    with pytest.raises(Exception) as info:
        plan_chain(scene, None, is_ball=False)
    assert "numerical_tehl" in str(info.value) and "tehl" in str(info.value)


def test_check_lists_numerical_tehl_with_its_citation():
    sim = Simulation(loads_scene(SCENE.replace("{want}", "film")), progress=False)
    text = sim.describe_chain(with_citations=True)
    assert "ehl_solver: numerical_tehl" in text
    assert "Shi X, Wang L (2015)" in text
    b = sim.bearings[0]
    assert isinstance(b.kin_options["film_model"], TehlFilmModel)
    assert b.kin_options["drag_model"] == "numerical_tehl"


def test_film_only_scene_reports_thermal_film_below_closed_form():
    sim = _sim("film")
    res = sim.run()
    film = res.tables["film"]
    assert set(film["film model"]) == {"numerical_tehl"}
    hc = film["central film [um]"].to_numpy()
    cf = film["closed-form central film [um]"].to_numpy()
    hm = film["minimum film [um]"].to_numpy()
    # paper 001 Figs. 5-6: thermal minimum film 0.445 um at 24 kN, H-D about 4-5x larger;
    # here: thermal central film well below half the closed-form one, minimum <= central
    assert np.all(hc < 0.5 * cf)
    assert np.all(hm <= hc * (1 + 1e-9))
    inner = film[film["race"] == "inner"]["minimum film [um]"].iloc[0]
    assert 0.3 < inner < 0.6  # paper 001: 0.445 um (within its 20 % band and some)
    # the table's work is recorded and summarised (a run sat minutes in thermal
    # solves without a sign); a film-only run books no loss, so no heat-source note
    table = res.stats[f"{sim.bearings[0].name}: film table"]
    model = sim.bearings[0].kin_options["film_model"]
    assert table == {"solves": model.solves, "queries": model.queries,
                     "solve_cpu_s": model.solve_time} and table["solves"] > 0
    assert f"{table['solves']} thermal EHL solves" in sim.summary_text(res)
    assert not any("rib_friction" in w for w in res.warnings)


@pytest.mark.slow
def test_kinematics_scene_runs_end_to_end_with_tehl_film():
    # the first roller solve explores cage speeds between 0 and the shaft's, and the table
    # fills at every near-rolling state it passes through: a few minutes
    sim = _sim("kinematics", load_step=2.0, speed_step=2.0)
    res = sim.run()
    kin = res.tables["kinematics"]
    assert bool(kin["converged"].iloc[0])
    state = sim.bearings[0].last.state
    model = sim.bearings[0].kin_options["film_model"]
    assert model.solves > 0
    for cs in state.contacts:
        h = np.asarray(cs.film_thickness)
        q = np.asarray(cs.normal_load)
        j = int(np.argmax(q))
        assert 0.2e-6 < h[j] < 1.0e-6  # closed form: 2.3-2.5 um at this contact


def _d1842926_inner_contact():
    """Paper 001's bearing and oil at 30 degC: (bearing, lubricant, TEHL film model, inner
    R_x [m], effective length [m], E' [Pa], T [K], eta0 [Pa s], alpha [1/Pa])."""
    bearing = load_bearing("D1842926")
    lub = load_lubricant("OIL_4109")
    T = 303.15
    return (bearing, lub, roller_film_model(bearing, lub, **FAST),
            bearing.curvature("inner")[0], bearing.roller_effective_length,
            bearing.effective_modulus, T, float(lub.dynamic_viscosity(T)),
            float(lub.pressure_viscosity_coefficient(T)))


def test_contact_forces_thermal_film_and_gross_sliding_fallback():
    bearing, lub, model, rx, length, e_p, T, eta0, alpha = _d1842926_inner_contact()
    from thermobearing.skidding.roller import default_traction_law
    from thermobearing.skidding.roller_fluid import closed_form_contact_forces

    law = default_traction_law(lub)
    q = np.array([4500.0, 0.0, 4500.0])
    u_race = np.array([53.3, 53.3, 53.3])
    u_roll = np.array([53.3, 40.0, 40.0])  # rolling, unloaded, gross sliding (SRR 0.28)

    def film(ue, w):
        return model(ue, w, rx, eta0, alpha, e_p)

    f = tehl_contact_forces(q, length, rx, e_p, u_race, u_roll, eta0=eta0, alpha=alpha,
                            film=film, traction_law=law, temperature=T)

    def moes(ue, w):
        from thermobearing.film import moes_line_central

        return moes_line_central(ue, eta0, alpha, w, 1.0, rx, effective_modulus=e_p)

    c = closed_form_contact_forces(q, length, rx, e_p, u_race, u_roll, eta0=eta0, alpha=alpha,
                                   film=moes, traction_law=law, temperature=T)
    assert model.solves >= 1
    # the table remembers: the same contacts again (a later step of a transient) and a
    # nearby load in the same table cell need no new thermal solve
    solves = model.solves
    f2 = tehl_contact_forces(q * 1.01, length, rx, e_p, u_race, u_roll, eta0=eta0,
                             alpha=alpha, film=film, traction_law=law, temperature=T)
    assert model.solves == solves and model.queries > 1
    assert f2.film_thickness[0] == pytest.approx(f.film_thickness[0], rel=0.02)
    # rolling contact: thermal film about 5x below the isothermal closed form (paper 001)
    assert f.film_thickness[0] < 0.3 * c.film_thickness[0]
    # unloaded: no forces; gross sliding: the isothermal closed-form film, no thermal solve
    assert math.isinf(f.film_thickness[1]) and f.traction[1] == 0.0
    assert f.film_thickness[2] == pytest.approx(c.film_thickness[2], rel=1e-12)
    assert np.all(np.isfinite(f.traction)) and f.poiseuille[0] > 0.0
    # a closed-form film model with the numerical_tehl drag is refused
    with pytest.raises(InputError, match="TehlFilmModel"):
        tehl_contact_forces(q, length, rx, e_p, u_race, u_roll, eta0=eta0, alpha=alpha,
                            film=moes, traction_law=law, temperature=T)


def test_film_model_rejects_ball_bearings():
    with pytest.raises(InputError, match="cylindrical"):
        roller_film_model(load_bearing("QJ1044"), load_lubricant("ISO_VG46"))


def test_rigid_regime_pressure_peak_is_martins_not_hertzs():
    # the reason the TEHL drag shears the Hertz zone at min(p_H, Martin peak): paper 001's
    # inner contact has L = 31.8 (OIL_4109 at 30 degC, 53 m/s); a lightly loaded roller at
    # M = 0.14 (~100 N) is in the rigid regime. The numerical line-contact solution (this
    # package) puts its pressure peak within 15 % of the rigid-isoviscous (Martin) peak
    # (measured 0.101 against 0.095 p_H), far below p_H, and only ~6 % of the load inside
    # |x| < b.
    from thermobearing.ehl.line import nodes_for, solve_dimensionless
    from thermobearing.skidding.roller_pressure import rigid_peak_pressure

    M, L = 0.14, 31.8
    sol = solve_dimensionless(M, L, n=nodes_for(M, 512, L), max_grid_error=math.inf)
    # Martin's peak over p_H for the same M (any dimensional case: E' R = 1, U = 1e-10)
    e_p, r, two_u = 1.0, 1.0, 2e-10
    w = M * math.sqrt(two_u) * e_p * r
    p_h = e_p * math.sqrt(w / (e_p * r) / (2 * math.pi))
    eta0, u_sum = 1.0, two_u * e_p * r  # U = eta0 u_m/(E' R), u_sum = 2 u_m
    martin = float(rigid_peak_pressure(w, u_sum, r, eta0)) / p_h
    assert 0.05 < martin < 0.15
    assert sol.max_pressure == pytest.approx(martin, rel=0.15)
    inside = np.abs(sol.X) <= 1.0
    share = np.trapezoid(np.where(inside, sol.P, 0.0), sol.X) / np.trapezoid(sol.P, sol.X)
    assert share < 0.1


def test_tehl_drag_shears_light_rollers_at_the_film_pressure():
    # regime_min (default) against the former Hertz-pressure shear, on grossly sliding
    # contacts (closed-form film, no thermal solve): at 100 N (Moes M ~ 0.14) the Hertz zone
    # is sheared at Martin's peak pressure, an independent Gauss-Legendre integral of the
    # traction law over the semi-ellipse with that peak; at 4500 N (M ~ 6, Martin's peak
    # above p_H) both models shear at p_H (equal to the quadrature difference, < 1 %).
    from scipy.special import roots_legendre

    from thermobearing.hertz import line_contact
    from thermobearing.skidding.roller import default_traction_law
    from thermobearing.skidding.roller_pressure import rigid_peak_pressure

    bearing, lub, model, rx, length, e_p, T, eta0, alpha = _d1842926_inner_contact()
    law = default_traction_law(lub)
    q = np.array([100.0, 4500.0])
    u_race = np.array([53.3, 53.3])
    u_roll = np.array([40.0, 40.0])  # SRR 0.28: gross sliding

    def film(ue, w):
        return model(ue, w, rx, eta0, alpha, e_p)

    kw = {"eta0": eta0, "alpha": alpha, "film": film, "traction_law": law, "temperature": T}
    new = tehl_contact_forces(q, length, rx, e_p, u_race, u_roll, **kw)
    old = tehl_contact_forces(q, length, rx, e_p, u_race, u_roll, film_pressure="hertz", **kw)
    assert model.solves == 0
    # the film and the rolling force do not depend on the Hertz-zone pressure
    assert np.allclose(new.film_thickness, old.film_thickness, rtol=1e-12)
    assert np.allclose(new.rolling_force, old.rolling_force, rtol=1e-12)
    # light roller: Hertz-zone traction at Martin's peak
    hz = line_contact(q[0], length, rx, e_p)
    u_sum = u_race[0] + u_roll[0]
    peak = float(rigid_peak_pressure(q[0] / length, u_sum, rx, eta0))
    assert peak < 0.2 * float(hz.max_pressure)
    xg, wg = roots_legendre(48)
    tau, _ = law.shear_stress(np.full(48, u_race[0] - u_roll[0]), peak * np.sqrt(1 - xg**2),
                              np.full(48, new.film_thickness[0]), np.full(48, T))
    expected = length * float(hz.half_width) * float(np.sum(np.asarray(tau) * wg))
    assert new.hertz_traction[0] == pytest.approx(expected, rel=0.01)
    assert new.hertz_traction[0] < 0.5 * old.hertz_traction[0]
    # the traction changes by the Hertz-zone difference only (inlet/outlet shear unchanged)
    assert new.traction[0] - old.traction[0] == pytest.approx(
        new.hertz_traction[0] - old.hertz_traction[0], rel=1e-9)
    # heavy roller: both shear at p_H
    assert new.hertz_traction[1] == pytest.approx(old.hertz_traction[1], rel=0.01)
    with pytest.raises(InputError, match="film_pressure"):
        tehl_contact_forces(q, length, rx, e_p, u_race, u_roll, film_pressure="x", **kw)
