"""The HTML report embeds every figure and has every section."""

from __future__ import annotations

import base64
import re

import numpy as np
import pandas as pd

from thermobearing.report import (
    SECTIONS,
    fig_csr,
    fig_loss_bars,
    fig_temperatures,
    html_report,
    temperature_errors,
)
from thermobearing.results import Results, ResultsWriter


def _results() -> Results:
    t = np.linspace(0, 3600, 61)
    temps = pd.DataFrame({"time [s]": t, "time [min]": t / 60,
                          "housing [degC]": 35 + 10 * (1 - np.exp(-t / 900)),
                          "oil [degC]": 35 + 12 * (1 - np.exp(-t / 600))})
    losses = pd.DataFrame([
        {"step": i, "bearing": "de", "axial load [kN]": 2.0 * i, "source": s,
         "component": s, "role": "oil", "power [W]": p * (1 + 0.1 * i)}
        for i in range(4) for s, p in (("churning", 500.0), ("pocket", 150.0))])
    kin = pd.DataFrame([{"bearing": "de", "speed [rpm]": 1800.0, "axial load [kN]": 2.0 * i,
                         "cage speed ratio [-]": 0.45 + 0.01 * i,
                         "theoretical cage speed ratio [-]": 0.452} for i in range(4)])
    energy = pd.DataFrame({"time [s]": [3600.0], "generated [J]": [1e6], "stored [J]": [2e5],
                           "to ambient [J]": [1e5], "to oil [J]": [7e5],
                           "imbalance [J]": [1e-3]})
    r = Results(tables={"temperatures": temps, "losses": losses, "kinematics": kin,
                        "energy": energy},
                scene_toml='title = "x"\n', chain=[("network", "four_node_paper002")],
                citations=["Ref A"], warnings=["Lambda < 1 at step 0"])
    measured = pd.DataFrame({"time [s]": t[::6], "TC1": temps["housing [degC]"][::6] + 0.5})
    r.figures["temperatures"] = fig_temperatures(temps, measured, {"TC1": "housing"})
    r.figures["losses"] = fig_loss_bars(losses)
    r.figures["csr"] = fig_csr(kin)
    return r


def test_html_has_sections_and_embedded_images(tmp_path):
    r = _results()
    text = html_report(r, "demo")
    for sec in SECTIONS:
        assert f">{sec}</h2>" in text
    imgs = re.findall(r'src="data:image/png;base64,([A-Za-z0-9+/=]+)"', text)
    assert len(imgs) == len(r.figures) == 3
    for data in imgs:
        assert base64.b64decode(data)[:8] == b"\x89PNG\r\n\x1a\n"
    assert "Lambda &lt; 1" in text and "relative imbalance" in text
    out = r.write(tmp_path)
    assert (out / "temperatures.csv").is_file() and (out / "csr.png").is_file()


def test_temperature_errors():
    r = _results()
    t = r["temperatures"]
    measured = pd.DataFrame({"time [s]": t["time [s]"], "TC1": t["housing [degC]"] + 0.5})
    err = temperature_errors(t, measured, {"TC1": "housing"})
    assert err.loc[0, "RMSE [K]"] == 0.5 or abs(err.loc[0, "RMSE [K]"] - 0.5) < 1e-12
    # predicted - measured, signed like the mean error: the model is 0.5 K cold here
    assert abs(err.loc[0, "max error [K]"] + 0.5) < 1e-12
    assert abs(err.loc[0, "mean error [K]"] + 0.5) < 1e-12


def test_writer_appends(tmp_path):
    w = ResultsWriter(tmp_path)
    w.append("losses", [{"a": 1, "b": 2}])
    w.append("losses", [{"a": 3, "b": 4}])
    df = pd.read_csv(tmp_path / "losses.csv")
    assert df["a"].tolist() == [1, 3]


def _steps(rows):
    return pd.DataFrame([{"step": i, "bearing": "b", "speed [rpm]": n, "radial load [kN]": fr,
                          "axial load [kN]": fa, "source": "s", "power [W]": 1.0}
                         for i, (n, fr, fa) in enumerate(rows)])


def test_operating_axis_follows_what_the_schedule_sweeps():
    """The loss bars and the CSR plot lay the steps along the swept quantity; when several
    vary or a value repeats, along the step (three speed steps at 0 kN axial were once
    stacked into one bar at 'axial load 0')."""
    from thermobearing.report import operating_axis

    key, pos, labels, xlabel = operating_axis(_steps([(1800, 1, a) for a in (0, 2, 4)]))
    assert (key, xlabel, labels) == ("step", "axial load [kN]", ["0", "2", "4"])
    key, pos, labels, xlabel = operating_axis(_steps([(n, 2, 0) for n in (3000, 1000, 2000)]))
    assert xlabel == "speed [rpm]" and labels == ["1000", "2000", "3000"]
    assert pos == {1: 0.0, 2: 1.0, 0: 2.0}
    key, pos, labels, xlabel = operating_axis(_steps([(2000, 2, 0), (5000, 2, 0),
                                                      (8000, 0.2, 0)]))
    assert xlabel == "step" and len(set(pos.values())) == 3
    assert labels[2] == "8000 r/min / 0.2 kN radial"
    key, pos, labels, xlabel = operating_axis(_steps([(1000, 1, 0), (2000, 1, 0),
                                                      (1000, 1, 0)]))
    assert xlabel == "step" and labels == ["1000 r/min", "2000 r/min", "1000 r/min"]
    png = fig_loss_bars(_steps([(2000, 2, 0), (5000, 2, 0), (8000, 0.2, 0)]))
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    kin = _steps([(n, 1, a) for n in (900, 1800) for a in (0, 2)]).assign(
        **{"cage speed ratio [-]": 0.4, "theoretical cage speed ratio [-]": 0.45})
    assert fig_csr(kin)[:8] == b"\x89PNG\r\n\x1a\n"


def test_sweep_report_separates_every_swept_parameter(tmp_path):
    """Three swept parameters: the what-if curves have one curve per combination of the
    other two, and the loss maps over the first two numeric ones are drawn per value of
    the third (they were once averaged over it)."""
    import itertools
    import json

    from thermobearing.commands.report import sweep_report

    rows, store = [], []
    for i, (n, fa, q) in enumerate(itertools.product((600, 1200, 1800), (2, 10), (15, 33))):
        params = {"schedule.speed": f"{n} rpm", "schedule.axial_load": f"{fa} kN",
                  "supply.flow": f"{q} L/min"}
        result = {"mean total loss [W]": n * (1 + fa / 100) * q / 33, "churning [W]": n * q / 66,
                  "pocket [W]": n * fa / 100, "max over-skidding [%]": fa / n}
        rows.append({"case": f"c{i}", **params, **result})
        store.append(json.dumps({"case": f"c{i}", "params": params, "result": result}))
    pd.DataFrame(rows).to_csv(tmp_path / "summary.csv", index=False)
    (tmp_path / "cases.jsonl").write_text("\n".join(store) + "\n", encoding="utf-8")
    text = sweep_report(tmp_path).read_text(encoding="utf-8")
    captions = re.findall(r"<figcaption>([^<]*)</figcaption>", text)
    assert "loss maps (supply.flow [L/min] = 15.0)" in captions
    assert "loss maps (supply.flow [L/min] = 33.0)" in captions
    assert sum(c.startswith("what-if") for c in captions) == 3
    # and one stacked-bar figure of every case's loss by source
    assert sum(c.startswith("loss by source") for c in captions) == 1
    assert len(re.findall(r'src="data:image/png;base64,', text)) == len(captions) == 6


def test_sweep_report_keeps_the_sweeps_numeric_columns():
    """A summary with mixed units of one swept quantity (15 L/min, 0.5 L/s): the sweep writes
    'supply.flow [L/min]' converted value by value; the report keeps it (earlier versions
    re-read the text with the first row's unit, 0.5 L/s became 0.5 L/min). A parameter held
    at one value draws no what-if curve; a text parameter (oil grade) does."""
    import pandas as pd

    from thermobearing.commands.report import _numeric_params

    df = pd.DataFrame({"case": ["a", "b"], "supply.flow": ["15 L/min", "0.5 L/s"],
                       "supply.flow [L/min]": [15.0, 30.0],
                       "supply.inlet_temperature": ["35 degC", "40 degC"],
                       "mean total loss [W]": [1.0, 2.0]})
    out = _numeric_params(df, ["supply.flow", "supply.inlet_temperature"])
    assert list(out["supply.flow [L/min]"]) == [15.0, 30.0] and "supply.flow" not in out
    assert list(out["supply.inlet_temperature [degC]"]) == [35.0, 40.0]  # older summaries


def test_loss_map_slices_share_one_colour_scale(monkeypatch):
    """fig_loss_maps(ranges=...): the contour levels span the given range, so the maps of
    the slices of a three-parameter sweep can be compared by colour (each map
    had its own scale)."""
    import matplotlib.axes
    import numpy as np
    import pandas as pd

    from thermobearing.report import fig_loss_maps

    seen = []
    orig = matplotlib.axes.Axes.contourf

    def spy(self, *args, **kw):
        seen.append(kw.get("levels"))
        return orig(self, *args, **kw)

    monkeypatch.setattr(matplotlib.axes.Axes, "contourf", spy)
    df = pd.DataFrame([{"q": q, "n": n, "churning [W]": q * n} for q in (15.0, 33.0)
                       for n in (600.0, 1800.0)])
    fig_loss_maps(df, "q", "n", ["churning [W]"], ranges={"churning [W]": (0.0, 1e5)})
    # round levels covering the range (tour 20: linspace levels read 866.9, 1013.4 ... W)
    assert seen[-1][0] <= 0.0 and seen[-1][-1] >= 1e5
    assert np.allclose(seen[-1], np.arange(0.0, 1e5 + 1.0, 1e4))
    fig_loss_maps(df, "q", "n", ["churning [W]"])
    assert seen[-1] == 12


def test_sweep_report_names_the_sources_in_words_and_says_what_it_does_not_record(tmp_path):
    import json

    from thermobearing.commands.report import sweep_report

    rows, store = [], []
    for i, (n, fr) in enumerate(((600, 1), (600, 5), (1800, 1), (1800, 5))):
        params = {"schedule.speed": f"{n} rpm", "schedule.radial_load": f"{fr} kN"}
        result = {"mean total loss [W]": n * 1.1, "raceway_traction [W]": n * 0.1 * fr,
                  "churning_elements [W]": n * (1.1 - 0.1 * fr)}
        rows.append({"case": f"c{i}", **params, **result})
        store.append(json.dumps({"case": f"c{i}", "params": params, "result": result}))
    pd.DataFrame(rows).to_csv(tmp_path / "summary.csv", index=False)
    (tmp_path / "cases.jsonl").write_text("\n".join(store) + "\n", encoding="utf-8")
    text = sweep_report(tmp_path).read_text(encoding="utf-8")
    summary = text[text.index("<h2>Summary</h2>"):]
    assert "<th>raceway contacts (rolling and sliding shear) [W]</th>" in summary
    assert "<th>raceway_traction [W]</th>" not in summary
    assert "has no scene.toml" in text
    captions = re.findall(r"<figcaption>([^<]*)</figcaption>", text)
    assert captions[0].startswith("loss by source [W] of every case")
