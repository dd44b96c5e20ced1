"""User tour 21: Ctrl-C on ``thermobearing run`` of the default rig after its last step, while
the figures and the report were drawn (several seconds on a busy machine). The folder kept
the step tables but no metadata.json, no loss_breakdown.csv and no report; the command did
not name ``thermobearing report DIR``, and that report then had no model chain and no
validity warnings, reading as a finished run without any.
"""

from __future__ import annotations

import json

import pytest
from nu214_scene import nu214_jet_scene

from thermobearing import report as report_module
from thermobearing.commands.report import run_report
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

SCENE = nu214_jet_scene(title="tour 21 interrupt", schedule="""radial_load = "1 kN"
axial_load = "0 kN"
step_duration = "1 min"
steps = [{ speed = "2000 rpm" }, { speed = "10000 rpm" }]""",
                        want='["losses", "kinematics", "report"]')


def test_ctrl_c_while_the_figures_are_drawn_keeps_metadata_and_breakdown(tmp_path,
                                                                          monkeypatch):
    def interrupted(results, scene):
        raise KeyboardInterrupt

    monkeypatch.setattr(report_module, "attach_figures", interrupted)
    sim = Simulation(loads_scene(SCENE), progress=False)
    with pytest.raises(KeyboardInterrupt):
        sim.run(out_dir=tmp_path)
    meta = json.loads((tmp_path / "metadata.json").read_text(encoding="utf-8"))
    assert ["heat_source", "raceway_traction"] in meta["chain"]
    assert any("cage skidding" in w for w in meta["warnings"])  # 10000 r/min, 1 kN
    assert "stopped" not in meta["stats"]  # every step was computed
    assert "every step was computed" in meta["stats"]["output_interrupted"]
    assert (tmp_path / "loss_breakdown.csv").is_file()
    assert len((tmp_path / "kinematics.csv").read_text().splitlines()) == 3


def test_report_of_that_folder_has_the_chain_and_the_warnings(tmp_path, monkeypatch):
    def interrupted(results, scene):
        raise KeyboardInterrupt

    with monkeypatch.context() as m:
        m.setattr(report_module, "attach_figures", interrupted)
        with pytest.raises(KeyboardInterrupt):
            Simulation(loads_scene(SCENE), progress=False).run(out_dir=tmp_path)
    html = run_report(tmp_path).read_text(encoding="utf-8")
    chain = html[html.index("<h2 id='model-chain'>Model chain</h2>"):]
    chain = chain[:chain.index("<h2", 5)]
    assert "(empty)" not in chain and "raceway_traction" in chain
    assert "crb: cage skidding" in html  # the check's warning line, not only the thresholds
    assert "This run did not finish" not in html
