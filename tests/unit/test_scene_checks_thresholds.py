"""The thresholds of the run's validity checks as scene options (``[checks]``).

Parsing with and without units, the round trip through ``Scene.to_toml``, bad values named
by field, the summary wording of set thresholds, and a short race-control run (QJ1044,
two steady steps) in which set thresholds raise warnings the defaults do not, while the
tables stay the same.
"""

from __future__ import annotations

import json
import math

import pandas as pd
import pytest

from tests.unit.test_simulation import BASE as SIMULATION_BASE
from thermobearing.errors import InputError
from thermobearing.operating_checks import (
    ISO76_STRESS,
    LAMBDA_BOUNDARY,
    SKID_LIMIT,
    CheckLimits,
    CheckLog,
    StateCheck,
)
from thermobearing.report import html_report
from thermobearing.scene import load_scene, loads_scene
from thermobearing.simulation import Simulation

# the steady race-control scene of tests/unit/test_simulation.py (QJ1044, 1800 r/min,
# 1 kN radial, 2 and 6 kN axial): kinematics only, about 2 s
BASE = SIMULATION_BASE + """[outputs]
mode = "steady"
want = ["kinematics"]
"""


def with_checks(body: str) -> str:
    return BASE + "[checks]\n" + body + "\n"


# ------------------------------------------------------------------ parsing
def test_no_checks_table_means_the_defaults():
    scene = loads_scene(BASE)
    assert scene.checks is None
    assert "[checks]" not in scene.to_toml()
    assert "[checks]" not in load_scene().to_toml()  # the default scene writes none
    assert Simulation(scene, progress=False).check_limits == CheckLimits()
    d = CheckLimits()
    assert (d.skid_limit, d.min_film_parameter) == (SKID_LIMIT, LAMBDA_BOUNDARY)
    assert [d.stress_limit(f) for f in ISO76_STRESS] == list(ISO76_STRESS.values())


def test_checks_with_units():
    scene = loads_scene(with_checks('skid_limit = "2 %"\ncontact_stress_limit = "3500 MPa"\n'
                                    "min_film_parameter = 1.5"))
    c = scene.checks
    assert c.skid_limit == pytest.approx(0.02, rel=1e-15)
    assert c.ball_stress_limit == c.self_aligning_ball_stress_limit \
        == c.roller_stress_limit == pytest.approx(3.5e9, rel=1e-15)
    assert c.min_film_parameter == 1.5
    assert c.source == "scene [checks]"
    # other spellings of the same quantities: "percent", GPa, a unit-less string
    again = loads_scene(with_checks('skid_limit = "2 percent"\n'
                                    'contact_stress_limit = "3.5 GPa"\n'
                                    'min_film_parameter = "1.5"'))
    assert again.checks.skid_limit == pytest.approx(0.02, rel=1e-15)
    assert again.checks.roller_stress_limit == pytest.approx(3.5e9, rel=1e-15)
    assert again.checks.min_film_parameter == 1.5


def test_checks_bare_numbers_are_si():
    c = loads_scene(with_checks("skid_limit = 0.02\ncontact_stress_limit = 3.5e9\n"
                                "min_film_parameter = 2")).checks
    assert (c.skid_limit, c.ball_stress_limit, c.min_film_parameter) == (0.02, 3.5e9, 2.0)


def test_stress_limit_per_family_keeps_the_others():
    c = loads_scene(with_checks('contact_stress_limit = { roller = "3000 MPa", '
                                'ball = "3.8 GPa" }')).checks
    assert c.roller_stress_limit == pytest.approx(3.0e9)
    assert c.ball_stress_limit == pytest.approx(3.8e9)
    assert c.self_aligning_ball_stress_limit == ISO76_STRESS["self_aligning_ball"]
    assert c.skid_limit == SKID_LIMIT and c.min_film_parameter == LAMBDA_BOUNDARY


@pytest.mark.parametrize("body", [
    'skid_limit = "2 %"\ncontact_stress_limit = "3500 MPa"\nmin_film_parameter = 1.5',
    'contact_stress_limit = { roller = "3000 MPa" }',
    'skid_limit = 0.0275\ncontact_stress_limit = { ball = "3.8 GPa", roller = "3.1 GPa" }',
    "",  # an empty [checks]: kept, written back empty
])
def test_round_trip(body):
    scene = loads_scene(with_checks(body))
    text = scene.to_toml()
    assert "[checks]" in text
    again = loads_scene(text)
    assert again.checks == scene.checks
    assert again.to_toml() == text


def test_scene_built_in_python_round_trips_equal():
    """A scene given ``CheckLimits`` in Python (source "CheckLimits") reads back from its TOML
    with the source "scene [checks]": the thresholds are what equality compares, so the two
    scenes are equal (earlier versions compared them unequal on the source text)."""
    import dataclasses

    base = loads_scene(with_checks(""))
    limits = CheckLimits(skid_limit=0.02, roller_stress_limit=3.1e9)
    scene = dataclasses.replace(base, checks=limits)
    again = loads_scene(scene.to_toml())
    assert again.checks.source == "scene [checks]" and limits.source != again.checks.source
    assert again.checks == limits and again == scene
    assert CheckLimits(skid_limit=0.03) != limits


def test_only_set_thresholds_are_written():
    text = loads_scene(with_checks('contact_stress_limit = { roller = "3000 MPa" }')).to_toml()
    block = text.split("[checks]\n", 1)[1].split("\n[", 1)[0]
    assert block.strip() == 'contact_stress_limit = { roller = "3000 MPa" }'
    text = loads_scene(with_checks('skid_limit = "2 %"\ncontact_stress_limit = "3500 MPa"')
                       ).to_toml()
    block = text.split("[checks]\n", 1)[1].split("\n[", 1)[0]
    assert block.strip().splitlines() == ['skid_limit = "2 %"',
                                          'contact_stress_limit = "3500 MPa"']
    # a fraction whose percent string would not read back exactly is written as a number
    odd = 0.1 + 0.2 - 0.3 + 0.0275
    text = loads_scene(with_checks(f"skid_limit = {odd!r}")).to_toml()
    assert loads_scene(text).checks.skid_limit == odd


@pytest.mark.parametrize(("body", "field", "allowed"), [
    ('skid_limit = "-2 %"', "checks.skid_limit", "a fraction in (0, 1)"),
    ("skid_limit = 0", "checks.skid_limit", "a fraction in (0, 1)"),
    ('skid_limit = "150 %"', "checks.skid_limit", "a fraction in (0, 1)"),
    ("skid_limit = nan", "checks.skid_limit", "finite"),
    ('skid_limit = "2 mm"', "checks.skid_limit", "dimensionless"),
    ("skid_limit = true", "checks.skid_limit", "a number"),
    ('contact_stress_limit = "-3500 MPa"', "checks.contact_stress_limit", "a stress >= 1 MPa"),
    ('contact_stress_limit = "3500 mm"', "checks.contact_stress_limit", "Pa"),
    ("contact_stress_limit = 3500", "checks.contact_stress_limit", "a bare number is in Pa"),
    ("contact_stress_limit = inf", "checks.contact_stress_limit", "finite"),
    ('contact_stress_limit = { needle = "3 GPa" }', "checks.contact_stress_limit.needle",
     "self_aligning_ball"),
    ('contact_stress_limit = { roller = "3 kN" }', "checks.contact_stress_limit.roller", "Pa"),
    ("contact_stress_limit = {}", "checks.contact_stress_limit", "one or more of ball"),
    ("min_film_parameter = -1", "checks.min_film_parameter", "Lambda > 0"),
    ("min_film_parameter = nan", "checks.min_film_parameter", "finite"),
    ('min_film_parameter = "1.5 MPa"', "checks.min_film_parameter", "dimensionless"),
    ('colour = "red"', "checks.colour",
     "skid_limit, contact_stress_limit, min_film_parameter"),
])
def test_bad_checks_name_the_field(body, field, allowed):
    with pytest.raises(InputError) as info:
        loads_scene(with_checks(body))
    msg = str(info.value)
    assert field in msg and allowed in msg, msg


def test_checks_must_be_a_table():
    with pytest.raises(InputError, match="checks"):
        loads_scene(BASE.replace('title = "t"', 'title = "t"\nchecks = 0.02'))


@pytest.mark.parametrize(("kw", "field"), [
    ({"skid_limit": -0.1}, "CheckLimits.skid_limit"),
    ({"skid_limit": 1.0}, "CheckLimits.skid_limit"),
    ({"roller_stress_limit": math.inf}, "CheckLimits.roller_stress_limit"),
    ({"ball_stress_limit": 0.0}, "CheckLimits.ball_stress_limit"),
    ({"min_film_parameter": math.nan}, "CheckLimits.min_film_parameter"),
    ({"min_film_parameter": "1.5"}, "CheckLimits.min_film_parameter"),
])
def test_check_limits_validate_on_construction(kw, field):
    with pytest.raises(InputError, match=field.replace(".", r"\.")):
        CheckLimits(**kw)


def test_as_dict_round_trip_and_unknown_key():
    c = CheckLimits(skid_limit=0.02, roller_stress_limit=3.1e9, source="scene [checks]")
    d = c.as_dict()
    assert d["skid_limit"] == 0.02 and d["roller_stress_limit"] == 3.1e9
    assert d["source"] == "scene [checks]"
    assert CheckLimits.from_dict(d) == c
    assert CheckLimits().as_dict()["source"] == "default"
    with pytest.raises(InputError, match="check_limits.colour"):
        CheckLimits.from_dict({"colour": 1})


def test_limits_apply_by_bearing_family():
    """The stress limit of a state is its bearing family's: the NU214 is a roller bearing,
    the QJ1044 a ball bearing (presets); integers are stored as floats."""
    from thermobearing.geometry import load_bearing
    from thermobearing.operating_checks import bearing_family, stress_limit

    limits = CheckLimits(ball_stress_limit=3_800_000_000, roller_stress_limit=3.1e9)
    assert isinstance(limits.ball_stress_limit, float)
    assert bearing_family(load_bearing("NU214")) == "roller"
    assert stress_limit(load_bearing("NU214"), limits) == 3.1e9
    assert stress_limit(load_bearing("QJ1044"), limits) == 3.8e9
    assert stress_limit(load_bearing("QJ1044")) == ISO76_STRESS["ball"]
    with pytest.raises(InputError, match="family"):
        limits.stress_limit("needle")


# ------------------------------------------------------------------ wording
def _state(slip=0.0, p=1e9, limit=4.2e9, lam=None, family="ball"):
    return StateCheck(slip, 0.45 * (1 + slip), 0.45, p, limit, lam, "inner", family)


def test_set_skid_limit_is_named_with_its_source():
    """A 3 % over-skid passes the default 5 % and fails a set 2 %."""
    states = [_state(0.01), _state(0.03)]
    default = CheckLog("sp", None)
    strict = CheckLog("sp", None, limits=CheckLimits(skid_limit=0.02, source="scene [checks]"))
    for i, s in enumerate(states):
        default.record(i, s)
        strict.record(i, s)
    assert not any("skidding" in line for line in default.summary())
    line = strict.summary()[0]
    assert line.startswith("sp: cage over-skidding (cage faster than epicyclic) by more "
                           "than 2% (scene [checks]) at 1 of 2 steps (step 1); largest "
                           "+3.0 % at step 1")


def test_set_stress_limit_says_how_it_stands_to_iso76():
    limits = CheckLimits(ball_stress_limit=3.5e9, source="scene [checks]")
    below, above = CheckLog("b", None, limits=limits), CheckLog("b", None, limits=limits)
    below.record(0, _state(p=3.8e9, limit=3.5e9))
    above.record(0, _state(p=4.4e9, limit=3.5e9))
    assert below.summary()[0] == (
        "b: contact pressure above the stress limit 3500 MPa (scene [checks]) at 1 of 1 "
        "steps (step 0); largest 3800 MPa at step 0 (below the ISO 76 static-rating "
        "stress 4200 MPa)")
    assert above.summary()[0].endswith(": above the ISO 76 static-rating stress 4200 MPa "
                                       "too (permanent raceway deformation)")


def test_state_without_family_under_set_limits_says_stress_limit():
    """A StateCheck built without its family (older callers) is named by the set limit, not
    as the ISO 76 stress; with the default limits the wording is the ISO 76 one."""
    limits = CheckLimits(ball_stress_limit=3.5e9, source="scene [checks]")
    log = CheckLog("b", None, limits=limits)
    log.record(0, _state(p=3.8e9, limit=3.5e9, family=""))
    assert log.summary()[0] == ("b: contact pressure above the stress limit 3500 MPa "
                                "(scene [checks]) at 1 of 1 steps (step 0); largest 3800 MPa "
                                "at step 0")
    legacy = CheckLog("b", None)
    legacy.record(0, _state(p=4.4e9, family=""))
    assert "ISO 76 static-rating stress 4200 MPa at 1 of 1 steps" in legacy.summary()[0]


def test_set_film_parameter_names_the_regime():
    """Lambda 1.2 passes the default boundary (1) and fails a set 1.5: mixed lubrication
    (1-3, the bands of thermobearing.film.film_parameter)."""
    log = CheckLog("b", 1e-7, limits=CheckLimits(min_film_parameter=1.5,
                                                 source="scene [checks]"))
    log.record(0, _state(lam=1.2))
    log.record(1, _state(lam=4.0))
    (line,) = log.summary()
    assert line.startswith("b: film parameter Lambda < 1.5 (scene [checks]) at 1 of 2 steps "
                           "(step 0); smallest 1.20 at step 0 (inner contact")
    assert line.endswith("mixed lubrication (1 <= Lambda < 3): the asperities carry part "
                         "of the load")
    default = CheckLog("b", 1e-7)
    default.record(0, _state(lam=1.2))
    assert default.summary() == []


# ------------------------------------------------------------------ a run
@pytest.fixture(scope="module")
def default_run():
    sim = Simulation(loads_scene(BASE), progress=False)
    return sim, sim.run()


def test_film_only_run_checks_stress_and_film():
    """A film-only scene (race control, no skidding solver) checks the contact stress and
    the film parameter of its film table's rows (the most loaded element per raceway), so a
    set limit flags the step and the limits are recorded; the worst values are the table's.
    (Earlier versions checked nothing in film-only runs.)"""
    film_only = 'want = ["film"]'
    text = with_checks('min_film_parameter = 1000\ncontact_stress_limit = "100 MPa"').replace(
        'want = ["kinematics"]', film_only)
    res = Simulation(loads_scene(text), progress=False).run()
    film = res.tables["film"]
    assert res.check_limits["min_film_parameter"] == 1000.0
    lines = _check_lines(res)
    stress = [w for w in lines if "stress limit 100 MPa (scene [checks])" in w]
    lam = [w for w in lines if "Lambda < 1000 (scene [checks])" in w]
    assert len(stress) == 1 and len(lam) == 1
    assert f"largest {film['max pressure [GPa]'].max() * 1e3:.0f} MPa" in stress[0]
    assert f"smallest {film['film parameter [-]'].min():.2f}" in lam[0]
    assert "thresholds of the operating checks" in html_report(res, "t")
    # the default limits flag nothing in this scene (0.8 GPa, Lambda about 25)
    default = Simulation(loads_scene(BASE.replace('want = ["kinematics"]', film_only)),
                         progress=False).run()
    assert _check_lines(default) == [] and default.check_limits["source"] == "default"


def _check_lines(results):
    return [w for w in results.warnings if w.startswith("de: ")]


def test_default_limits_leave_the_run_unchanged(default_run):
    """A [checks] table that restates the defaults changes no table, no warning, and the
    recorded limits say "default"."""
    _, res = default_run
    iso = ", ".join(f'{f} = "{v / 1e6:g} MPa"' for f, v in ISO76_STRESS.items())
    same = Simulation(loads_scene(with_checks(
        f'skid_limit = "5 %"\ncontact_stress_limit = {{ {iso} }}\nmin_film_parameter = 1')),
        progress=False).run()
    pd.testing.assert_frame_equal(same.tables["kinematics"], res.tables["kinematics"])
    assert same.warnings == res.warnings
    assert res.check_limits == CheckLimits().as_dict() == same.check_limits
    assert res.check_limits["source"] == "default"


def test_set_limits_warn_where_the_defaults_do_not(default_run, tmp_path):
    """Race control of the QJ1044 runs 2-4 % off the epicyclic cage speed at 0.7-0.8 GPa
    and Lambda about 25 (these numbers are read from the default run): nothing to warn
    of by default; thresholds set between the two steps' values flag exactly one step
    each, and the lines name the threshold and its source. Race control rolls by
    construction, so its departure from CSR_th is named as such, not as gross sliding."""
    sim0, res0 = default_run
    assert _check_lines(res0) == []
    kin = res0.tables["kinematics"]
    skid = kin["over-skidding [%]"].to_numpy()
    p0 = kin["max contact pressure [MPa]"].to_numpy()
    lam = kin["min film parameter [-]"].to_numpy()
    assert 0 < min(skid) < max(skid) < 100 * SKID_LIMIT  # both steps pass the default
    assert max(p0) < ISO76_STRESS["ball"] / 1e6 and min(lam) > LAMBDA_BOUNDARY
    hi_skid, hi_p, lo_lam = (int(skid.argmax()), int(p0.argmax()), int(lam.argmin()))
    skid_lim = round(float(skid.mean()), 3)   # [%], between the two steps
    p_lim = round(float(p0.mean()))           # [MPa]
    lam_lim = round(float(lam.mean()), 3)
    scene = loads_scene(with_checks(f'skid_limit = "{skid_lim} %"\n'
                                    f'contact_stress_limit = "{p_lim} MPa"\n'
                                    f"min_film_parameter = {lam_lim}"))
    sim = Simulation(scene, progress=False)
    res = sim.run()
    pd.testing.assert_frame_equal(res.tables["kinematics"], kin)  # limits change no number
    lines = _check_lines(res)
    assert len(lines) == 3, res.warnings
    assert lines[0].startswith(f"de: cage speed ratio more than {skid_lim:.4g}% (scene "
                               f"[checks]) from CSR_th at 1 of 2 steps (step {hi_skid})")
    assert "without gross sliding" in lines[0] and "+0.0 % from it" in lines[0]
    assert lines[1].startswith(f"de: contact pressure above the stress limit {p_lim} MPa "
                               f"(scene [checks]) at 1 of 2 steps (step {hi_p})")
    assert lines[1].endswith("(below the ISO 76 static-rating stress 4200 MPa)")
    assert lines[2].startswith(f"de: film parameter Lambda < {lam_lim:g} (scene [checks]) "
                               f"at 1 of 2 steps (step {lo_lam})")
    assert lines[2].endswith("full-film lubrication (Lambda >= 3), below the set threshold")
    # the limits used are recorded in the results, their metadata and the report
    assert res.check_limits["skid_limit"] == pytest.approx(skid_lim / 100, rel=1e-12)
    assert res.check_limits["ball_stress_limit"] == pytest.approx(p_lim * 1e6, rel=1e-12)
    assert res.check_limits["source"] == "scene [checks]"
    meta = json.loads((res.write(tmp_path) / "metadata.json").read_text(encoding="utf-8"))
    assert meta["check_limits"] == res.check_limits
    page = html_report(res, "t")
    assert (f"thresholds of the operating checks: cage skidding / over-skidding "
            f"|CSR/CSR_ref - 1| &gt; {skid_lim:.4g}% (scene [checks]; CSR_ref") in page
    assert f"{p_lim:.4g} MPa ball (scene [checks])" in page
    assert f"  - {lines[0]}" in sim.summary_text(res)


def test_report_of_a_folder_shows_the_limits_the_run_applied(default_run, tmp_path):
    """``thermobearing report DIR`` re-renders a run folder with the thresholds recorded in
    its ``metadata.json`` (the ones its warnings were made with), not with a ``[checks]``
    table added to the folder's scene.toml afterwards (earlier versions read the scene)."""
    from thermobearing.commands.report import run_report

    _, res = default_run
    folder = res.write(tmp_path / "run")
    scene = folder / "scene.toml"
    scene.write_text(scene.read_text(encoding="utf-8")
                     + '\n[checks]\nskid_limit = "0.5 %"\n', encoding="utf-8")
    page = run_report(folder).read_text(encoding="utf-8")
    assert "|CSR/CSR_ref - 1| &gt; 5% (default; CSR_ref" in page
    assert "0.5% (scene [checks])" not in page
