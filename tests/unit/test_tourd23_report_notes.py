"""User tour C (session 23): a loss breakdown of an NUP 214 under thrust and of a 7014 C over
speed x load maps, as a bearing application engineer reads the run and sweep reports.

Found on that tour (before -> after):

* a race-control CRB run booked 0 W of cage pockets at every step without a word (the
  raceway column had its note); an angular-contact bearing with a ball-guided cage booked
  0 W of cage guide land without a word -> each says why;
* an NUP (ribs on both rings) under thrust books the rib friction of the inner rib only
  (``heat_sources/rib.py``: the outer rib's contact is not modelled) and the report did not
  say the outer rib's friction is missing from the totals -> a note names the bearing;
* the sweep report listed no model chain (which models ran, their validity) and did not
  say that a sweep keeps neither the heat by component nor the validity warnings of a
  case -> a 'Model chain' section with the validity ranges and that statement;
* the sweep report's catalogue cross-check had no frictional moment M = P / omega, which
  the README says it gives -> a column for the cases that turn at one speed;
* a race-control sweep drew a what-if panel of over-skidding that is 0 % by construction
  -> left out, with a note saying why.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from types import SimpleNamespace

import pandas as pd
import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

#: an NUP 214 (the NU214 preset with ribs on both rings) under 1 kN thrust, losses only
NUP_POINT = """
title = "NUP 214 one loss point"

[[bearings]]
name = "nup"
preset = "NU214"
overrides = { ribbed_ring = "both", end_face_crown_radius = "500 mm", rib_angle = "0.5 deg", \
rib_height = "3 mm", axial_clearance = "0.05 mm" }

[lubricant]
preset = "ISO_VG46"

[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "50 degC"

[environment]
ambient_temperature = "25 degC"

[schedule]
axial_load = "1 kN"
speed = "1500 rpm"
radial_load = "5 kN"
steps = [{ duration = "1 min" }]

[models]
kinematics = "race_control"
heat_sources = ["raceway_traction", "churning_elements", "churning_cage", "churning_inner_ring",
                "pocket_friction", "rib_friction"]

[outputs]
want = ["losses", "kinematics", "report"]
"""


def _bearing(ribbed: str = "both", guidance: str = "rolling_element") -> SimpleNamespace:
    return SimpleNamespace(ribbed_ring=ribbed, cage=SimpleNamespace(guidance=guidance))


def _scene(kinematics: str = "race_control", axial: float = 1000.0) -> SimpleNamespace:
    return SimpleNamespace(models={"kinematics": kinematics},
                           schedule=SimpleNamespace(steps=[SimpleNamespace(axial_load=axial)]))


def _frame(**columns: list[float]) -> pd.DataFrame:
    base = {"step": [0, 1], "bearing": ["nup", "nup"], "axial load [kN]": [1.0, 1.0],
            "raceway_traction [W]": [0.0, 0.0], "pocket_friction [W]": [0.0, 0.0],
            "rib_friction [W]": [97.2, 176.2], "cage_guide [W]": [0.0, 0.0]}
    return pd.DataFrame({**base, **columns})


def test_race_control_names_why_the_cage_pockets_book_nothing():
    from thermobearing.report_sections import source_notes

    notes = source_notes(_frame(), _scene(), {"nup": _bearing()})
    (pocket,) = [n for n in notes if n.startswith("cage pockets")]
    assert "0 W at every step: race control gives the cage no pocket forces" in pocket
    assert 'kinematics = "skidding"' in pocket
    # the raceway note of earlier sessions is kept, first
    assert notes[0].startswith("raceway contacts (rolling and sliding shear): 0 W")
    # a skidding run, or pockets that book heat, get no such note
    assert not [n for n in source_notes(_frame(), _scene("skidding"), {"nup": _bearing()})
                if n.startswith("cage pockets")]
    booked = _frame(**{"pocket_friction [W]": [0.0, 1.5]})
    assert not [n for n in source_notes(booked, _scene(), {"nup": _bearing()})
                if n.startswith("cage pockets")]


def test_a_ball_guided_cage_is_said_to_have_no_land():
    from thermobearing.report_sections import source_notes

    frame = _frame().drop(columns=["rib_friction [W]"])
    (land,) = [n for n in source_notes(frame, _scene("skidding"), {"spindle": _bearing()})
               if n.startswith("cage guide land")]
    assert "the cage of spindle is guided on its rolling elements" in land
    # a land-guided cage at 0 W is not explained away by its guidance
    assert not [n for n in source_notes(frame, _scene("skidding"),
                                        {"spindle": _bearing(guidance="inner_ring")})
                if n.startswith("cage guide land")]


def test_the_outer_rib_of_a_bearing_ribbed_on_both_rings_says_what_is_modelled():
    from thermobearing.report_sections import source_notes

    (rib,) = [n for n in source_notes(_frame(), _scene(), {"nup": _bearing()})
              if n.startswith("roller end / rib friction")]
    assert "of nup (ribs on both rings): the outer rib's thrust contact is booked" in rib
    assert "the outer rib's drag and skew contacts are not in the totals" in rib
    # no thrust, or ribs on one ring only: nothing is missing
    no_thrust = _frame(**{"axial load [kN]": [0.0, 0.0]})
    for frame, scene, bearing in ((no_thrust, _scene(axial=0.0), _bearing()),
                                  (_frame(), _scene(), _bearing(ribbed="inner"))):
        assert not [n for n in source_notes(frame, scene, {"nup": bearing})
                    if n.startswith("roller end / rib friction")]
    # a sweep summary carries the thrust in its swept column
    swept = _frame().drop(columns=["axial load [kN]"]).assign(
        **{"schedule.axial_load [kN]": [0.5, 2.0]})
    assert [n for n in source_notes(swept, _scene(axial=0.0), {"nup": _bearing()})
            if n.startswith("roller end / rib friction")]


def test_the_run_report_of_the_nup_says_what_its_losses_leave_out():
    """The report section of a run (tables of the NUP 214 point as the tour's run wrote
    them: race control, 1 kN thrust, 0 W raceway and pocket columns)."""
    from thermobearing.report_context import load_scene_bearings
    from thermobearing.report_sections import losses_html
    from thermobearing.scene import loads_scene

    scene = loads_scene(NUP_POINT)
    bearings, _ = load_scene_bearings(scene)
    point = {"step": 0, "bearing": "nup", "speed [rpm]": 1500.0, "radial load [kN]": 5.0,
             "axial load [kN]": 1.0}
    rows = [("raceway_traction", "inner contact", "inner_ring", 0.0, "load_dependent"),
            ("pocket_friction", "roller pocket", "elements", 0.0, "load_independent"),
            ("churning_elements", "element churning", "oil", 32.0, "load_independent"),
            ("rib_friction", "roller end face / rib", "elements", 40.5, "load_dependent"),
            ("rib_friction", "roller end face / rib", "inner_ring", 56.7, "load_dependent")]
    losses = pd.DataFrame([{**point, "source": s, "component": c, "role": r, "power [W]": p,
                            "load dependence": d} for s, c, r, p, d in rows])
    text = losses_html(losses, {}, scene, bearings, None)
    assert "cage pockets (element / pocket friction): 0 W at every step" in text
    assert "the outer rib&#x27;s thrust contact is booked" in text


def _sweep_folder(tmp_path: Path, skid: float = 0.0) -> Path:
    """A sweep folder of the NUP point over speed x axial load as the tour's sweep wrote
    it (summary.csv, cases.jsonl, scene.toml), with made-up powers."""
    from thermobearing.scene import loads_scene

    (tmp_path / "scene.toml").write_text(loads_scene(NUP_POINT).to_toml(), encoding="utf-8")
    rows, store = [], []
    for i, (n, fa) in enumerate(((1500, 0.5), (1500, 2), (3000, 0.5), (3000, 2))):
        params = {"schedule.speed": f"{n} rpm", "schedule.axial_load": f"{fa} kN"}
        rib = 0.05 * n * fa
        result = {"mean total loss [W]": 0.05 * n + rib, "max total loss [W]": 0.05 * n + rib,
                  "churning_elements [W]": 0.05 * n, "pocket_friction [W]": 0.0,
                  "raceway_traction [W]": 0.0, "rib_friction [W]": rib,
                  "max over-skidding [%]": skid, "min over-skidding [%]": skid}
        rows.append({"case": f"c{i}", **params, **result})
        store.append(json.dumps({"case": f"c{i}", "params": params, "result": result}))
    pd.DataFrame(rows).to_csv(tmp_path / "summary.csv", index=False)
    (tmp_path / "cases.jsonl").write_text("\n".join(store) + "\n", encoding="utf-8")
    return tmp_path


def test_the_sweep_report_names_its_model_chain_and_what_a_sweep_does_not_keep(tmp_path):
    from thermobearing.commands.report import sweep_report

    text = sweep_report(_sweep_folder(tmp_path)).read_text(encoding="utf-8")
    chain = text[text.index("<h2>Model chain</h2>"):]
    for family, model in (("kinematics", "race_control"), ("film", "pan_hamrock_central"),
                          ("heat_source", "rib_friction"), ("heat_source", "pocket_friction")):
        assert f"<td>{family}</td>\n      <td>{model}</td>" in chain
    assert "cylindrical roller bearings with ribs" in chain  # the rib source's validity
    assert "not the heat received by each component, the validity warnings" in chain
    # what the losses leave out, under the case count
    head = text[:text.index("<h2>Figures</h2>")]
    assert "cage pockets (element / pocket friction): 0 W in every case" in head
    assert "raceway contacts (rolling and sliding shear): 0 W in every case" in head
    assert "the outer rib&#x27;s thrust contact is booked" in head
    assert "over-skidding 0 % in every case: race control" in head


def test_the_sweep_report_says_a_swept_model_can_change_the_chain(tmp_path):
    from thermobearing.commands.report import _chain_html

    html = _chain_html(_sweep_folder(tmp_path), ["models.kinematics", "schedule.speed"])
    assert "the swept models.kinematics can change it from case to case" in html
    assert "the swept" not in _chain_html(tmp_path, ["schedule.speed"])
    empty = tmp_path / "empty"
    empty.mkdir()
    assert "(not available: the folder has no scene.toml)" in _chain_html(empty, [])


def test_race_control_over_skidding_panel_is_left_out_only_when_zero(tmp_path, monkeypatch):
    import thermobearing.commands.report as cr

    drawn: list[list[str]] = []

    def fake_whatif(df, x, ys, group=()):
        drawn.append(list(ys))
        return b"png"

    monkeypatch.setattr("thermobearing.report.fig_whatif", fake_whatif)
    cr.sweep_report(_sweep_folder(tmp_path))
    assert drawn and all("max over-skidding [%]" not in ys for ys in drawn)
    drawn.clear()
    other = tmp_path / "skids"
    other.mkdir()
    text = cr.sweep_report(_sweep_folder(other, skid=0.4)).read_text(encoding="utf-8")
    assert drawn and all("max over-skidding [%]" in ys for ys in drawn)
    assert "over-skidding 0 % in every case" not in text


def test_the_sweep_crosscheck_gives_the_frictional_moment_of_a_one_speed_case():
    from thermobearing.report_context import CASE_TORQUE as TORQUE
    from thermobearing.report_context import sweep_catalogue_crosscheck
    from thermobearing.scene import loads_scene

    point = loads_scene((EXAMPLES / "loss_point_6206_oil_bath.toml").read_text("utf-8"),
                        base_dir=EXAMPLES)
    records = [{"case": f"c{n}", "params": {"schedule.speed": f"{n} rpm"},
                "result": {"mean total loss [W]": 10.0}} for n in (1500, 3000)]
    table, _ = sweep_catalogue_crosscheck(point, records)
    # M = P / omega: 10 W at 1500 r/min is 63.66 N mm
    assert table[TORQUE].to_numpy() == pytest.approx(
        [1e3 * 10.0 / (n * math.pi / 30.0) for n in (1500, 3000)], rel=1e-12)
    # a protocol over several speeds has no one omega: no moment
    grid = loads_scene((EXAMPLES / "loss_map_6206_oil_bath.toml").read_text("utf-8"),
                       base_dir=EXAMPLES)
    table, _ = sweep_catalogue_crosscheck(
        grid, [{"case": "c0", "params": {}, "result": {"mean total loss [W]": 10.0}}])
    assert TORQUE not in table


def test_an_estimate_the_scene_overrides_is_marked_not_used():
    """The NUP's report gave the NU 214 preset's reasoning 'NU type: two ribs on the outer
    ring, none on the inner ring' under Estimated inputs although the scene ran it with
    ribs on both rings."""
    from thermobearing.report import overridden_estimates
    from thermobearing.scene import loads_scene

    scene = loads_scene(NUP_POINT.replace(
        'axial_clearance = "0.05 mm" }',
        'axial_clearance = "0.05 mm", cage = { pocket_clearance = "0.4 mm" } }'))
    entries = {"ribbed_ring": "NU type: two ribs on the outer ring, none on the inner ring",
               "cage.pocket_clearance": "about 2 % of the roller diameter",
               "cage.width": "0.75 of the ring width"}
    out = overridden_estimates("bearing nup (NU214)", entries, scene)
    assert out["ribbed_ring"].startswith("not used: the scene overrides it (ribbed_ring = both)")
    assert out["cage.pocket_clearance"].startswith(
        "not used: the scene overrides it (cage.pocket_clearance = 0.4 mm)")
    assert out["cage.width"] == entries["cage.width"]
    # the lubricant's entries, another bearing's, or no scene: unchanged
    assert overridden_estimates("lubricant (ISO_VG46)", entries, scene) == entries
    assert overridden_estimates("bearing other (NU214)", entries, scene) == entries
    assert overridden_estimates("bearing nup (NU214)", entries, None) == entries


def test_report_of_a_file_names_the_folder_holding_it(tmp_path, capsys):
    """``thermobearing report DIR/report.html`` was answered 'an existing folder (no such
    folder here ...)' beside the file the user had just opened."""
    from thermobearing.cli import main

    (tmp_path / "scene.toml").write_text(NUP_POINT, encoding="utf-8")
    (tmp_path / "report.html").write_text("<html></html>", encoding="utf-8")
    assert main(["report", str(tmp_path / "report.html")]) != 0
    err = capsys.readouterr().err
    assert "a results folder, not a file: give the folder holding it" in err
    assert f"`thermobearing report {tmp_path}`" in err and "no such folder" not in err
    scene = tmp_path / "elsewhere" / "nup.toml"
    scene.parent.mkdir()
    scene.write_text(NUP_POINT, encoding="utf-8")
    assert main(["report", str(scene)]) != 0
    err = capsys.readouterr().err
    assert f"a scene is run with `thermobearing run {scene} --out DIR`" in err


def test_the_sweep_summary_names_each_source_column_of_summary_csv(tmp_path):
    """The sweep report said 'summary.csv has their registered names' and named them
    nowhere: a reader of summary.csv could not tell which column was 'roller end / rib
    friction'."""
    from thermobearing.commands.report import sweep_report

    text = sweep_report(_sweep_folder(tmp_path)).read_text(encoding="utf-8")
    summary = text[text.index("<h2>Summary</h2>"):text.index("<h2>Model chain</h2>")]
    for column, words in (("rib_friction [W]", "roller end / rib friction"),
                          ("pocket_friction [W]", "cage pockets (element / pocket friction)"),
                          ("churning_elements [W]",
                           "oil drag on the rolling elements (churning)")):
        assert f"<td>{column}</td>\n      <td>{words}</td>" in summary


def test_the_crosscheck_says_palmgren_leaves_out_the_thrust_of_a_roller_bearing(tmp_path):
    """An NUP 214 at 1500 r/min under 0.5 / 1 / 2 kN axial: Palmgren gave 133 W at every
    thrust beside the run's 135-281 W (P1 = F_r for a cylindrical roller bearing), and the
    cross-check did not say its estimate cannot see the axial load."""
    from thermobearing.global_friction import palmgren
    from thermobearing.report_context import (
        catalogue_crosscheck,
        cylindrical_thrust_notes,
        load_scene_bearings,
        load_scene_lubricant,
        sweep_catalogue_crosscheck,
    )
    from thermobearing.scene import loads_scene

    scene = loads_scene(NUP_POINT)
    bearings, _ = load_scene_bearings(scene)
    lubricant = load_scene_lubricant(scene)
    # the model's own independence of the thrust, which the note states
    omega, nu = 1500 * math.pi / 30.0, 30e-6
    powers = {fa: palmgren(bearings["nup"], nu, omega, 5e3, fa).power for fa in (0.0, 2e3)}
    assert powers[0.0] == pytest.approx(powers[2e3], rel=1e-12)
    (note,) = cylindrical_thrust_notes(bearings, {"nup"})
    assert "takes the radial load only (P1 = F_r)" in note
    assert cylindrical_thrust_notes(bearings, set()) == []
    # a run's cross-check: said under a thrust, not without one
    point = {"step": 0, "bearing": "nup", "speed [rpm]": 1500.0, "radial load [kN]": 5.0,
             "source": "rib_friction", "power [W]": 97.2}
    for axial, said in ((1.0, True), (0.0, False)):
        losses = pd.DataFrame([{**point, "axial load [kN]": axial}])
        _, notes = catalogue_crosscheck(losses, {}, scene, bearings, lubricant)
        assert any("P1 = F_r" in n for n in notes) is said
    # a sweep's: once, however many cases
    records = [{"case": f"c{fa}", "params": {"schedule.axial_load": f"{fa} kN"},
                "result": {"mean total loss [W]": 100.0 + fa}} for fa in (0.5, 2)]
    table, notes = sweep_catalogue_crosscheck(scene, records)
    assert sum("P1 = F_r" in n for n in notes) == 1
    assert table["Palmgren M0 + M1 [W]"].nunique() == 1  # the same at both thrusts


def test_whatif_panels_say_when_their_curves_coincide(monkeypatch):
    """The NUP sweep's film parameter does not move with the axial load: three curves drawn
    one over the other showed only the last colour beside a legend of three."""
    import thermobearing.report as rep

    figs = []
    monkeypatch.setattr(rep, "_png", lambda fig: figs.append(fig) or b"png")
    rows = [{"schedule.speed [rpm]": n, "schedule.axial_load [kN]": fa,
             "mean total loss [W]": 0.1 * n + 50.0 * fa, "min film parameter [-]": n / 500.0}
            for n in (1500, 3000, 4500) for fa in (0.5, 1.0, 2.0)]
    rep.fig_whatif(pd.DataFrame(rows), "schedule.speed [rpm]",
                   ["mean total loss [W]", "min film parameter [-]"],
                   group=["schedule.axial_load [kN]"])
    loss, film = figs[0].axes[:2]
    assert [t.get_text() for t in film.texts] == ["the 3 curves coincide"]
    assert len(loss.texts) == 0
    # one curve: nothing to say
    figs.clear()
    rep.fig_whatif(pd.DataFrame(rows[:3]), "schedule.speed [rpm]", ["min film parameter [-]"])
    assert len(figs[0].axes[0].texts) == 0


def test_a_roller_bearing_under_thrust_is_told_its_zero_columns_are_not_computed():
    """The race-control notes send the reader to the skidding solver, which refuses a
    cylindrical roller bearing under an axial load: for the NUP the 0 W columns are 'not
    modelled', not 'no loss', and the report now says so."""
    from thermobearing.report_sections import source_notes

    nup = SimpleNamespace(kind="cylindrical", ribbed_ring="both",
                          cage=SimpleNamespace(guidance="rolling_element"))
    notes = source_notes(_frame(), _scene(), {"nup": nup})
    (said,) = [n for n in notes if "carries no rib thrust" in n]
    assert said.startswith("nup: the skidding solver carries no rib thrust")
    assert ("the raceway contacts (rolling and sliding shear) and the cage pockets (element "
            "/ pocket friction) of this run are not computed") in said
    # no thrust, a ball bearing, or skidding: not said
    for frame, scene, bearing in (
            (_frame(**{"axial load [kN]": [0.0, 0.0]}), _scene(axial=0.0), nup),
            (_frame(), _scene(), SimpleNamespace(kind="angular_contact", ribbed_ring=None,
                                                 cage=nup.cage)),
            (_frame(), _scene("skidding"), nup)):
        assert not [n for n in source_notes(frame, scene, {"nup": bearing})
                    if "carries no rib thrust" in n]


def test_a_case_at_rest_has_no_catalogue_estimate_and_the_moment_stands_by_the_total():
    """A 7014 C sweep over 0 and 4000 r/min: the case at rest read 'SKF four-term 0 W' for a
    bearing the SKF constants do not cover, and the moment column, missing from that first
    row, stood after the models' columns."""
    from thermobearing.report_context import CASE_TORQUE as TORQUE
    from thermobearing.report_context import sweep_catalogue_crosscheck
    from thermobearing.scene import loads_scene

    point = loads_scene((EXAMPLES / "loss_point_6206_oil_bath.toml").read_text("utf-8"),
                        base_dir=EXAMPLES)
    records = [{"case": f"c{n}", "params": {"schedule.speed": f"{n} rpm"},
                "result": {"mean total loss [W]": 0.0 if n == 0 else 10.0}} for n in (0, 3000)]
    table, notes = sweep_catalogue_crosscheck(point, records)
    cols = list(table.columns)
    assert cols[cols.index("this case [W]") + 1] == TORQUE
    rest, turning = table.iloc[0], table.iloc[1]
    for label in ("SKF four-term [W]", "Palmgren M0 + M1 [W]"):
        assert math.isnan(rest[label]) and turning[label] > 0.0
    assert math.isnan(rest[TORQUE])
    assert any(n.startswith("cases at rest throughout (0 r/min) have no catalogue estimate")
               and "(c0)" in n for n in notes)


def test_the_model_chain_of_a_base_scene_whose_bearing_file_moved_is_said_unavailable(
        tmp_path):
    from thermobearing.commands.report import _chain_html

    moved = NUP_POINT.replace('preset = "NU214"', f'path = "{tmp_path / "gone.toml"}"')
    (tmp_path / "scene.toml").write_text(moved, encoding="utf-8")
    html = _chain_html(tmp_path, ["schedule.speed"])
    assert "<h2>Model chain</h2>" in html and "(not available: " in html
    assert "gone.toml" in html and "a sweep keeps per case" in html
