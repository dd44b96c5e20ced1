"""User tour 22, the reports of an oil-flow what-if (QJ1044 jet scene, NU 214 jet scene).

* The run report captioned its temperature figure "node temperatures [degC] against time
  [min] (measured points overlaid)" under every transient run, also a scene without a
  [measured] file (nothing overlaid).
* A sweep interrupted after its first case (or one with a single value of one of its two
  numeric axes) draws its loss maps as curves; their axes repeated the registered source
  name (``raceway_traction [W]``) under the panel title that names it in words.
"""

from __future__ import annotations

import html

import pandas as pd
import pytest
from nu214_scene import nu214_jet_scene

import thermobearing.report as report
from thermobearing.report import TEMPERATURES_CAPTION, fig_loss_maps, html_report
from thermobearing.results import Results
from thermobearing.scene import loads_scene

SCHEDULE = """radial_load = "5 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{ speed = "3000 rpm" }]"""
TEMPS = pd.DataFrame({"time [s]": [0.0, 60.0], "time [min]": [0.0, 1.0],
                      "crb.oil [degC]": [40.0, 45.0]})


def _captions(text: str) -> list[str]:
    import re

    return re.findall(r"<figcaption>(.*?)</figcaption>", text)


def test_temperature_caption_names_no_measured_points_without_a_measured_file():
    scene = loads_scene(nu214_jet_scene(title="tour 22 caption", schedule=SCHEDULE,
                                        want='["temperatures", "losses", "report"]'))
    assert scene.measured is None
    res = Results(tables={"temperatures": TEMPS}, figures={"temperatures": b"\x89PNG"})
    for kwargs in ({}, {"scene": scene}):
        caps = _captions(html_report(res, "t", **kwargs))
        assert caps == [TEMPERATURES_CAPTION]
        assert "measured" not in caps[0]


def test_temperature_caption_with_a_measured_file_says_the_points_are_overlaid():
    assert report._caption("temperatures", measured=True) == (
        f"{TEMPERATURES_CAPTION} (measured points overlaid)")
    assert report._caption("temperatures") == TEMPERATURES_CAPTION


@pytest.fixture()
def captured(monkeypatch):
    """The matplotlib figures fig_loss_maps would encode (instead of their PNG)."""
    figs = []

    def keep(fig):
        figs.append(fig)
        return b"\x89PNG"

    monkeypatch.setattr(report, "_png", keep)
    return figs


def test_loss_maps_drawn_as_curves_give_the_unit_on_the_axis(captured):
    # an NU 214 flow sweep at one inlet temperature (or interrupted after one inlet)
    summary = pd.DataFrame({"supply.flow [L/min]": [0.5, 1.0, 2.0],
                            "supply.inlet_temperature [degC]": [30.0, 30.0, 30.0],
                            "mean total loss [W]": [583.0, 668.0, 774.0],
                            "raceway_traction [W]": [45.6, 48.2, 52.1]})
    titles = {"raceway_traction [W]": "raceway contacts (rolling and sliding shear) [W]"}
    fig_loss_maps(summary, "supply.flow [L/min]", "supply.inlet_temperature [degC]",
                  ["mean total loss [W]", "raceway_traction [W]"], titles=titles)
    panels = captured[-1].axes[:2]
    assert [ax.get_ylabel() for ax in panels] == ["W", "W"]
    assert panels[1].get_title().startswith("raceway contacts")
    assert [ax.get_xlabel() for ax in panels] == ["supply.flow [L/min]"] * 2
    line = panels[1].get_lines()[0]
    assert list(line.get_ydata()) == [45.6, 48.2, 52.1]
    assert line.get_label() == "supply.inlet_temperature [degC] = 30"


def test_a_folder_without_losses_of_a_scene_that_books_them_says_no_step_finished():
    # `thermobearing report DIR` on a sweep folder interrupted before its first case
    # finished (only the sweep's scene.toml): the run report said "the scene's outputs ask
    # for no losses" of a scene whose outputs ask for losses
    from thermobearing.report_sections import no_losses_text

    books = loads_scene(nu214_jet_scene(title="t", schedule=SCHEDULE,
                                        want='["temperatures", "losses", "report"]'))
    text = html_report(Results(), "t", scene=books)
    assert "ask for no losses" not in text
    assert html.escape(no_losses_text(books)) in text
    assert "no step finished here" in no_losses_text(books)
    film_only = loads_scene(nu214_jet_scene(title="t", schedule=SCHEDULE, want='["film"]'))
    assert no_losses_text(film_only) == ("no losses table: the scene's outputs ask for no "
                                         "losses")
    assert no_losses_text(None) == no_losses_text(film_only)


def test_whatif_over_oil_grades_puts_the_grades_in_viscosity_order(captured):
    # "--set lubricant.preset=ISO_VG68,ISO_VG32,ISO_VG100" drew the grades in the typed
    # order (68, 32, 100) and each curve zigzagged
    from thermobearing.report import fig_whatif, natural_key

    summary = pd.DataFrame({"lubricant.preset": ["ISO_VG68", "ISO_VG32", "ISO_VG100"] * 2,
                            "supply.flow [L/min]": [1.0] * 3 + [2.0] * 3,
                            "mean total loss [W]": [775.0, 670.0, 850.0,
                                                    885.0, 770.0, 960.0]})
    fig_whatif(summary, "lubricant.preset", ["mean total loss [W]"],
               group=["supply.flow [L/min]"])
    ax = captured[-1].axes[0]
    assert [t.get_text() for t in ax.get_xticklabels()] == ["ISO_VG32", "ISO_VG68",
                                                            "ISO_VG100"]
    for line, losses in zip(ax.get_lines(), ([670.0, 775.0, 850.0], [770.0, 885.0, 960.0]),
                            strict=True):
        assert list(line.get_xdata()) == [0, 1, 2]
        assert list(line.get_ydata()) == losses
    assert sorted(["OIL_4109", "ISO_VG46", "MIL_PRF_23699"], key=natural_key) == [
        "ISO_VG46", "MIL_PRF_23699", "OIL_4109"]


def test_swept_oil_files_are_labelled_by_their_file_names(captured, monkeypatch):
    # '--set lubricant.path=my_vg150.toml,<configs>/ISO_VG46.toml': the sweep makes the
    # files absolute, and the what-if and bar figures wrote both full paths as tick
    # labels that overlapped and squeezed the panels
    import thermobearing.report_losses as report_losses
    from thermobearing.report import category_labels, fig_whatif

    monkeypatch.setattr(report_losses, "_png", report._png)  # captured as well
    paths = ["/work/oils/my_vg150.toml", "/opt/thermobearing/configs/ISO_VG46.toml"]
    summary = pd.DataFrame({"case": ["a", "b"], "lubricant.path": paths,
                            "mean total loss [W]": [1464.0, 1032.0],
                            "churning_elements [W]": [250.0, 248.0],
                            "ehl_rolling_resistance [W]": [868.0, 586.0]})
    fig_whatif(summary, "lubricant.path", ["mean total loss [W]"])
    ticks = [t.get_text() for t in captured[-1].axes[0].get_xticklabels()]
    assert ticks == ["ISO_VG46.toml", "my_vg150.toml"]
    report_losses.fig_sweep_breakdown(summary, ["lubricant.path"])
    ticks = [t.get_text() for t in captured[-1].axes[0].get_xticklabels()]
    assert sorted(ticks) == ["ISO_VG46.toml", "my_vg150.toml"]
    # two files of one name in different folders keep their paths; presets stay as named
    same = ["/a/oil.toml", "/b/oil.toml"]
    assert category_labels(same) == same
    assert category_labels(["ISO_VG32", "ISO_VG68"]) == ["ISO_VG32", "ISO_VG68"]
