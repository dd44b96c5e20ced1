"""The power-loss breakdown report over a speed x load map, as a bearing engineer reads it.

Found by running the catalogue 6206 in an oil bath over 1500 / 3000 / 6000 r/min and 1 / 3
kN radial (`thermobearing run`, `sweep --set schedule.speed=... --set
schedule.radial_load=...`, `report DIR`):

- the stacked bars labelled their six steps ``1500 r/min / 1 kN radial`` side by side on
  one line, each label running into its neighbours;
- the loss maps drew a source with 0 W everywhere (the cage land of an element-guided
  cage) as a contour with a colour bar of round-off levels (-2e-14 to 2e-14 W), did not
  show which points were computed (the contours between them are interpolated), and a
  grid point whose case failed under ``--keep-going`` was a blank corner, unmentioned;
- the sweep report had no catalogue (SKF four-term / Palmgren) cross-check, which the run
  report has for the same points, and listed the sources alphabetically.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pandas as pd
import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _grid_losses() -> pd.DataFrame:
    """A long losses table of one bearing over a 3 x 2 speed x radial-load grid, with a
    source that books 0 W at every point."""
    rows = []
    step = 0
    for load in (1.0, 3.0):
        for n in (1500.0, 3000.0, 6000.0):
            for src, cls, p in (("raceway_traction", "load_dependent", 1e-3 * n * load),
                                ("churning_elements", "load_independent", 1e-7 * n ** 2),
                                ("cage_guide", "load_independent", 0.0)):
                rows.append({"step": step, "time [s]": 0.0, "bearing": "test",
                             "speed [rpm]": n, "radial load [kN]": load,
                             "axial load [kN]": 0.0, "source": src, "component": src,
                             "role": "oil", "power [W]": p, "load dependence": cls})
            step += 1
    return pd.DataFrame(rows)


@pytest.fixture
def captured(monkeypatch):
    """The matplotlib figures the report modules would encode (instead of their PNG)."""
    import thermobearing.report as report
    import thermobearing.report_losses as report_losses

    figs = []

    def keep(fig):
        figs.append(fig)
        return b"\x89PNG"

    monkeypatch.setattr(report_losses, "_png", keep)
    monkeypatch.setattr(report, "_png", keep)
    return figs


def _overlaps(boxes) -> bool:
    boxes = sorted(boxes, key=lambda b: b.x0)
    return any(a.x1 > b.x0 + 0.5 for a, b in zip(boxes, boxes[1:], strict=False))


def test_the_stacked_bars_tick_labels_of_a_speed_by_load_grid_do_not_overlap(captured):
    from thermobearing.report_losses import fig_destinations, fig_loss_bars

    fig_loss_bars(_grid_losses())
    fig_destinations(_grid_losses())
    assert len(captured) == 2
    for fig in captured:
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        ax = fig.axes[0]
        labels = [t for t in ax.get_xticklabels() if t.get_text()]
        assert len(labels) == 6
        # every label names its point: speed and radial load
        assert all("r/min" in t.get_text() and "kN radial" in t.get_text() for t in labels)
        assert not _overlaps([t.get_window_extent(renderer) for t in labels])


def test_tick_layout_keeps_short_labels_and_turns_long_one_line_labels_upright():
    from thermobearing.report_losses import tick_layout

    short = [f"{v:g}" for v in range(0, 44, 2)]
    assert tick_layout(short, 430.0) == (short, 0)
    stacked, rot = tick_layout(["1500 r/min / 1 kN radial"] * 6, 430.0)
    assert rot == 0 and all(s == "1500 r/min\n1 kN radial" for s in stacked)
    long_ = ["step with a long name and no separator"] * 12
    assert tick_layout(long_, 430.0) == (long_, 90)


def test_loss_maps_mark_the_points_say_a_constant_source_and_cross_a_failed_point(
        captured):
    from thermobearing.report import fig_loss_maps
    from thermobearing.report_losses import breakdown_by_source

    wide = breakdown_by_source(_grid_losses())
    # the case at 6000 r/min, 3 kN failed: no row
    wide = wide[~((wide["speed [rpm]"] == 6000.0) & (wide["radial load [kN]"] == 3.0))]
    comps = ["total [W]", "raceway_traction [W]", "cage_guide [W]"]
    fig_loss_maps(wide, "speed [rpm]", "radial load [kN]", comps)
    fig = captured[-1]
    panels = fig.axes[:3]  # the colour bars come after the panels
    texts = [[t.get_text() for t in ax.texts] for ax in panels]
    # the 0 W source is said, not contoured (no colour bar of round-off levels)
    assert "0 W at every point" in texts[2]
    assert not panels[2].collections or all(
        not hasattr(c, "levels") for c in panels[2].collections)
    colourbars = [ax for ax in fig.axes if ax.get_ylabel() == "W"]
    assert len(colourbars) == 2
    for ax, t in zip(panels, texts, strict=True):
        # the five computed points dotted, the missing one crossed and counted
        lines = ax.get_lines()
        dots = [ln for ln in lines if ln.get_marker() == "o"]
        crosses = [ln for ln in lines if ln.get_marker() == "x"]
        assert len(dots) == 1 and len(dots[0].get_xdata()) == 5
        assert len(crosses) == 1
        assert (float(crosses[0].get_xdata()[0]), float(crosses[0].get_ydata()[0])) == (
            6000.0, 3.0)
        assert any("no result at 1 of 6 grid points" in s for s in t)


def test_sweep_report_names_the_missing_combinations():
    from thermobearing.commands.report import missing_combinations

    df = pd.DataFrame({"n [rpm]": [1500.0, 1500.0, 3000.0], "F [kN]": [1.0, 3.0, 1.0]})
    (note,) = missing_combinations(df, ["n [rpm]", "F [kN]"])
    assert note.startswith("1 of 4 combinations")
    assert "n [rpm] = 3000, F [kN] = 3" in note
    assert missing_combinations(df.iloc[:2], ["n [rpm]", "F [kN]"]) == []


def _losses_only_base():
    from thermobearing.scene import loads_scene

    text = (EXAMPLES / "catalogue_bearing_rig.toml").read_text(encoding="utf-8")
    text = text.replace('want = ["temperatures", "losses", "kinematics", "energy", "report"]',
                        'want = ["losses", "report"]')
    assert 'want = ["losses", "report"]' in text
    # absolute, as the scene.toml a sweep writes into its folder
    text = text.replace('path = "catalogue_bearing_6206.toml"',
                        f'path = "{(EXAMPLES / "catalogue_bearing_6206.toml").as_posix()}"')
    return loads_scene(text, base_dir=EXAMPLES)


def test_sweep_crosscheck_is_the_protocol_average_of_the_catalogue_models():
    """Each case's SKF / Palmgren estimate is the duration-weighted mean over its steps of
    global_friction at the step's speed and loads and the scene's initial temperature
    (a losses-only scene evaluates its losses there), as its total is averaged."""
    from thermobearing.global_friction import global_friction
    from thermobearing.report_context import (
        load_scene_bearings,
        load_scene_lubricant,
        sweep_catalogue_crosscheck,
    )

    base = _losses_only_base()
    records = [{"case": f"c{i}", "params": {"schedule.radial_load": load},
                "result": {"mean total loss [W]": 10.0}}
               for i, load in enumerate(("1 kN", "4 kN"))]
    table, notes = sweep_catalogue_crosscheck(base, records)
    assert list(table["case"]) == ["c0", "c1"] and notes == []
    bearings, _ = load_scene_bearings(base)
    lub = load_scene_lubricant(base)
    T = base.environment.initial_temperature
    for row, load in zip(table.itertuples(index=False), (1e3, 4e3), strict=True):
        steps = base.schedule.steps
        for model, col in (("skf_four_term", "SKF four-term [W]"),
                           ("palmgren", "Palmgren M0 + M1 [W]")):
            opts = {"oil_level": base.supply.level} if model == "skf_four_term" else {}
            want = sum(global_friction(model, bearings["test"], lub, T, s.speed, load, 0.0,
                                       lubrication=base.supply.method, **opts).power
                       * s.duration for s in steps) / sum(s.duration for s in steps)
            got = table.loc[table["case"] == row.case, col].item()
            assert got == pytest.approx(want, rel=1e-12)
            pct = table.loc[table["case"] == row.case, f"this case vs {col[:-4]} [%]"].item()
            assert pct == pytest.approx(100.0 * (10.0 / want - 1.0))
    # more load, more loss in both models
    assert (table["SKF four-term [W]"].diff().iloc[1] > 0
            and table["Palmgren M0 + M1 [W]"].diff().iloc[1] > 0)
    assert table["oil [degC]"].to_numpy() == pytest.approx([T - 273.15] * 2)


def test_sweep_crosscheck_of_a_scene_with_a_network_says_why_there_is_none():
    from thermobearing.report_context import sweep_catalogue_crosscheck
    from thermobearing.scene import loads_scene

    text = (EXAMPLES / "catalogue_bearing_rig.toml").read_text(encoding="utf-8")
    base = loads_scene(text, base_dir=EXAMPLES)
    table, notes = sweep_catalogue_crosscheck(
        base, [{"case": "c0", "params": {}, "result": {"mean total loss [W]": 1.0}}])
    assert table.empty and "thermal network" in notes[0]


def test_sweep_report_has_the_crosscheck_the_missing_cases_and_sources_in_order(tmp_path):
    from thermobearing.commands.report import sweep_report

    base = _losses_only_base()
    (tmp_path / "scene.toml").write_text(base.to_toml(), encoding="utf-8")
    rows, store = [], []
    for i, (n, fr) in enumerate(((1500, 1), (1500, 3), (3000, 1))):  # 3000 x 3 failed
        params = {"schedule.speed": f"{n} rpm", "schedule.radial_load": f"{fr} kN"}
        result = {"mean total loss [W]": 1e-3 * n * (1 + fr),
                  "cage_guide [W]": 0.0, "churning_elements [W]": 1e-3 * n,
                  "raceway_traction [W]": 1e-3 * n * fr}
        rows.append({"case": f"c{i}", **params, **result})
        store.append(json.dumps({"case": f"c{i}", "params": params, "result": result}))
    pd.DataFrame(rows).to_csv(tmp_path / "summary.csv", index=False)
    (tmp_path / "cases.jsonl").write_text("\n".join(store) + "\n", encoding="utf-8")
    text = sweep_report(tmp_path).read_text(encoding="utf-8")
    assert "1 of 4 combinations of the swept values have no result" in text
    assert "schedule.speed [rpm] = 3000, schedule.radial_load [kN] = 3" in text
    cross = text[text.index("<h2>Catalogue cross-check</h2>"):text.index("<h2>Summary</h2>")]
    assert "<th>SKF four-term [W]</th>" in cross and "<th>Palmgren M0 + M1 [W]</th>" in cross
    assert len(re.findall(r"</tr>", cross)) == 1 + 3  # header and the three cases
    summary = text[text.index("<h2>Summary</h2>"):]
    heads = re.findall(r"<th>([^<]*)</th>", summary)
    # the sources in the fixed order of every loss table: raceways, cage, oil drag
    order = [h for h in heads if h.startswith(("raceway contacts", "cage guide", "oil drag"))]
    assert order == ["raceway contacts (rolling and sliding shear) [W]",
                     "cage guide land (film shear) [W]",
                     "oil drag on the rolling elements (churning) [W]"]


def _pocket_grows_with_load() -> pd.DataFrame:
    """The grid of :func:`_grid_losses` with a pocket friction classed load-independent
    (as the source declares it) that grows with the load, as the 6206's does (0.24 to
    0.85 W from 1 to 3 kN at 1500 r/min)."""
    df = _grid_losses()
    pocket = df[df["source"] == "churning_elements"].copy()
    pocket["source"] = pocket["component"] = "pocket_friction"
    pocket["power [W]"] = 1e-4 * pocket["speed [rpm]"] * pocket["radial load [kN]"]
    return pd.concat([df, pocket], ignore_index=True)


def test_the_glossary_says_how_each_source_moved_with_the_load_and_flags_the_class():
    from thermobearing.report_losses import class_notes, glossary

    g = glossary(_pocket_grows_with_load()).set_index("in the CSV files")
    change = g["change with the load in this run"]
    assert change["raceway_traction"].startswith("+200 % from 1 to 3 kN radial")
    assert change["pocket_friction"].startswith("+200 % from 1 to 3 kN radial")
    assert change["churning_elements"].startswith("+0 %")
    assert change["cage_guide"] == ""  # 0 W: no ratio
    assert g.loc["pocket_friction", "class"] == "load-independent"
    (note,) = class_notes(_pocket_grows_with_load())
    assert "cage pockets" in note and "+200 %" in note
    assert "oil drag" not in note and "raceway" not in note
    assert class_notes(_grid_losses()) == []  # the churning does not move: no note


def test_a_global_friction_run_gets_no_cage_speed_figure_and_says_it_is_compared_with_itself():
    from thermobearing.report import attach_figures
    from thermobearing.report_context import _percent, _self_comparison_notes
    from thermobearing.results import Results

    kin = pd.DataFrame({"step": [0, 1], "bearing": ["b", "b"], "speed [rpm]": [1500.0, 3000.0],
                        "radial load [kN]": [1.0, 1.0], "axial load [kN]": [0.0, 0.0],
                        "cage speed ratio [-]": [0.3965, 0.3965],
                        "theoretical cage speed ratio [-]": [0.3965, 0.3965],
                        "over-skidding [%]": [0.0, 0.0]})
    for chain, has_csr in (([("kinematics", "none"), ("heat_source", "global_friction")],
                            False), ([("kinematics", "skidding")], True)):
        res = Results(tables={"kinematics": kin}, chain=chain)
        attach_figures(res, None)
        assert ("cage_speed_ratio" in res.figures) is has_csr
    losses = pd.DataFrame({"source": ["global_friction"] * 2,
                           "component": ["skf_four_term rolling", "skf_four_term drag"]})
    (note,) = _self_comparison_notes(losses)
    assert "SKF four-term" in note and "with itself" in note
    assert _self_comparison_notes(losses.assign(source="raceway_traction")) == []
    assert _percent(5.5 * (1 + 2e-16), 5.5) == 0.0 and _percent(11.0, 10.0) == pytest.approx(10.0)


def test_report_of_a_run_folder_rewrites_its_figure_files(tmp_path):
    """``thermobearing report DIR`` re-renders the figures: the PNG files beside
    report.html are those figures (they stayed the run's older ones)."""
    import base64

    from thermobearing.commands.report import run_report
    from thermobearing.results import Results

    base = _losses_only_base()
    res = Results(tables={"losses": _grid_losses()}, scene_toml=base.to_toml())
    res.write(tmp_path)
    (tmp_path / "power_losses.png").write_bytes(b"stale")
    text = run_report(tmp_path).read_text(encoding="utf-8")
    for name in ("power_losses", "loss_maps_test"):
        png = (tmp_path / f"{name}.png").read_bytes()
        assert png[:4] == b"\x89PNG"
        embedded = re.search(rf'<img alt="{name}" src="data:image/png;base64,([^"]+)"', text)
        assert embedded and base64.b64decode(embedded.group(1)) == png
    # a loss map the report no longer draws is removed with the rewrite (it stayed beside a
    # report.html that did not show it)
    (tmp_path / "loss_maps_gone.png").write_bytes(b"stale")
    run_report(tmp_path)
    assert not (tmp_path / "loss_maps_gone.png").exists()
    assert (tmp_path / "loss_maps_test.png").read_bytes()[:4] == b"\x89PNG"


def test_the_sweeps_mean_totals_are_not_sources():
    """summary.csv's ``mean total loss [W]`` (and per bearing) is a total: stacked as a
    source it doubled every bar and drew the total map twice."""
    from thermobearing.report_losses import summary_sources

    cols = ["mean total loss [W]", "mean total loss de [W]", "max total loss [W]",
            "total loss [W]", "churning_cage [W]", "raceway_traction [W]"]
    assert summary_sources(cols) == ["raceway_traction", "churning_cage"]


def test_the_sweep_report_names_the_cases_its_checks_flag():
    """An NU 214 at 0.2 kN skids (over-skidding -19 % at 2000 r/min, -43 % at 6000 r/min):
    the sweep printed it, its report said nothing."""
    from thermobearing.commands.report import flagged_cases

    df = pd.DataFrame({"n [rpm]": [2000.0, 2000.0, 6000.0], "F [kN]": [0.2, 5.0, 0.2],
                       "steps over skid limit [-]": [1, 0, 1],
                       "steps over stress limit [-]": [0, 0, 0]})
    (note,) = flagged_cases(df, ["n [rpm]", "F [kN]"])
    assert note.startswith("2 of 3 cases have steps with cage skidding")
    assert "n [rpm] = 2000, F [kN] = 0.2; n [rpm] = 6000, F [kN] = 0.2" in note
    assert flagged_cases(df.iloc[[1]], ["n [rpm]", "F [kN]"]) == []


def test_report_of_a_folder_that_does_not_exist_says_so_and_where_run_writes(tmp_path):
    import argparse

    from thermobearing.commands.report import run
    from thermobearing.errors import InputError

    with pytest.raises(InputError, match="no such folder.*results/<scene file name>"):
        run(argparse.Namespace(folder=str(tmp_path / "typo")))


def test_the_run_crosscheck_gives_the_runs_loss_as_a_catalogue_frictional_moment():
    """A catalogue's friction calculator gives a moment in N mm: the cross-check sets the
    run's total beside it as M = P / omega."""
    from thermobearing.report_context import (
        TORQUE,
        catalogue_crosscheck,
        load_scene_bearings,
        load_scene_lubricant,
    )

    base = _losses_only_base()
    bearings, _ = load_scene_bearings(base)
    table, _ = catalogue_crosscheck(_grid_losses(), {}, base, bearings,
                                    load_scene_lubricant(base))
    omega = table["speed [rpm]"] * 3.141592653589793 / 30.0
    assert (table[TORQUE] * omega / 1e3).to_numpy() == pytest.approx(
        table["this run [W]"].to_numpy(), rel=1e-12)


def test_the_loss_map_examples_cover_the_grid_their_readme_names():
    """examples/loss_map_6206_oil_bath.toml is a 3 x 3 speed x radial-load grid of one run
    (the report draws maps from it); loss_point_6206_oil_bath.toml swept as its README
    says gives the same nine points."""
    from thermobearing.report_losses import map_axes
    from thermobearing.scene import load_scene
    from thermobearing.sweep_cases import expand, scene_from_case
    from thermobearing.sweep_params import parse_set

    grid = load_scene(str(EXAMPLES / "loss_map_6206_oil_bath.toml"))
    points = {(round(s.speed * 30 / 3.141592653589793, 6), s.radial_load)
              for s in grid.schedule.steps}
    assert len(points) == 9 == len(grid.schedule.steps)
    table = pd.DataFrame([{"step": i, "bearing": "test", "speed [rpm]": n,
                           "radial load [kN]": f / 1e3, "axial load [kN]": 0.0}
                          for i, (n, f) in enumerate(sorted(points))])
    assert map_axes(table) == ("speed [rpm]", "radial load [kN]")
    assert "temperatures" not in grid.outputs.want  # losses only, as its comment says
    point = load_scene(str(EXAMPLES / "loss_point_6206_oil_bath.toml"))
    d = point.to_dict()
    cases = expand(point, [parse_set("schedule.speed=1500,3000,6000", d),
                           parse_set("schedule.radial_load=1,2,3", d)])
    swept = set()
    for case in cases:
        (step,) = scene_from_case(case).schedule.steps
        swept.add((round(step.speed * 30 / 3.141592653589793, 6), step.radial_load))
    assert swept == points
    text = (EXAMPLES / "README.md").read_text(encoding="utf-8")
    assert "loss_point_6206_oil_bath.toml" in text and "loss_map_6206_oil_bath.toml" in text


def test_the_crosscheck_says_what_of_the_supply_the_catalogue_models_see():
    """It said the models do not see 'the oil jet's flow' on an oil-bath scene, whose
    level the SKF drag term does see."""
    from thermobearing.report_sections import _crosscheck_html

    head = _crosscheck_html(_grid_losses(), {}, None, {}, None)
    assert "oil jet's flow" not in head
    assert "only the lubrication method" in head and "an oil bath's level" in head


def test_the_run_statistics_read_in_words_and_a_global_friction_run_solves_no_kinematics():
    from thermobearing.report import html_report
    from thermobearing.results import Results

    stats = {"steps": 6, "wall_time_s": 0.5996, "kinematics_solves": 6}
    text = html_report(Results(tables={}, chain=[("kinematics", "skidding")], stats=stats),
                       "t", {})
    assert "steps 6, wall time 0.6 s, kinematics solves 6" in text
    assert "wall_time_s" not in text
    text = html_report(Results(tables={}, chain=[("kinematics", "none")], stats=stats),
                       "t", {})
    assert "kinematics solves: none" in text and "kinematics solves 6" not in text


def test_sweep_crosscheck_of_one_point_steady_cases_takes_their_steady_oil_temperature():
    """A steady case with one operating point is compared at its steady oil node (the
    summary's ``final <bearing>.oil [degC]``), as the run report compares a steady run."""
    from thermobearing.global_friction import global_friction
    from thermobearing.report_context import (
        load_scene_bearings,
        load_scene_lubricant,
        sweep_catalogue_crosscheck,
    )
    from thermobearing.scene import loads_scene

    text = (EXAMPLES / "loss_point_6206_oil_bath.toml").read_text(encoding="utf-8")
    text = text.replace('want = ["losses", "kinematics", "report"]',
                        'mode = "steady"\nwant = ["temperatures", "losses", "report"]')
    base = loads_scene(text, base_dir=EXAMPLES)
    rec = {"case": "c0", "params": {"schedule.speed": "6000 rpm"},
           "result": {"mean total loss [W]": 15.0, "final test.oil [degC]": 59.5}}
    table, notes = sweep_catalogue_crosscheck(base, [rec])
    assert notes == [] and table["oil [degC]"].item() == pytest.approx(59.5)
    bearings, _ = load_scene_bearings(base)
    want = global_friction("skf_four_term", bearings["test"], load_scene_lubricant(base),
                           59.5 + 273.15, 6000 * 3.141592653589793 / 30, 2e3, 0.0,
                           lubrication="oil_bath", oil_level=base.supply.level).power
    assert table["SKF four-term [W]"].item() == pytest.approx(want, rel=1e-12)
    # without the oil node in the summary: no oil temperature, no comparison, a note
    table, notes = sweep_catalogue_crosscheck(
        base, [{**rec, "result": {"mean total loss [W]": 15.0}}])
    assert table.empty and "steady oil temperature" in notes[0]


def test_the_glossary_names_the_catalogue_model_of_a_global_friction_run():
    from thermobearing.report_losses import glossary

    rows = [{"step": 0, "bearing": "b", "speed [rpm]": 1500.0, "radial load [kN]": 1.0,
             "axial load [kN]": 0.0, "source": "global_friction", "component": comp,
             "role": "oil", "power [W]": p, "load dependence": cls}
            for comp, p, cls in (("palmgren M0", 6.7, "load_independent"),
                                 ("palmgren M1", 1.6, "load_dependent"))]
    (loss,) = glossary(pd.DataFrame(rows))["loss"]
    assert loss == "whole bearing (catalogue friction model): Palmgren M0 + M1"
    assert glossary(_grid_losses())["loss"].str.contains("Palmgren|SKF").sum() == 0
