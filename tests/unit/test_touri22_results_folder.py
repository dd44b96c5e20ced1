"""User tour 22 from Python: ``Simulation(scene).run().write(folder)`` of a losses-only NU 214
scene into the folder of a transient run of the same bearing kept the transient's
``temperatures.csv``, ``energy.csv`` and figures; ``thermobearing report folder`` then drew
the old temperatures and energy audit beside the new losses and said that the losses were
evaluated at the node temperatures the network reached.
"""

from __future__ import annotations

import pandas as pd

from thermobearing.results import Results

LOSSES = pd.DataFrame({"step": [0], "bearing": ["crb"], "speed [rpm]": [3000.0],
                       "radial load [kN]": [5.0], "axial load [kN]": [0.0],
                       "source": ["churning_elements"], "component": ["element churning"],
                       "role": ["oil"], "power [W]": [99.0],
                       "load dependence": ["load_independent"]})
TEMPS = pd.DataFrame({"time [s]": [0.0, 300.0], "time [min]": [0.0, 5.0],
                      "crb.oil [degC]": [40.0, 46.7]})
ENERGY = pd.DataFrame({"time [s]": [300.0], "generated [J]": [1.1e5], "stored [J]": [6.3e4],
                       "to ambient [J]": [5.2e3], "to oil [J]": [4.6e4],
                       "imbalance [J]": [0.0]})


def _transient_folder(folder):
    Results(tables={"temperatures": TEMPS, "energy": ENERGY, "losses": LOSSES},
            figures={"temperatures": b"\x89PNG", "power_losses": b"\x89PNG"}).write(folder)
    (folder / "report.html").write_text("<html>transient run</html>", encoding="utf-8")
    (folder / "measured_vs_predicted.csv").write_text("time [s]\n0\n", encoding="utf-8")
    (folder / "loss_maps_crb.png").write_bytes(b"\x89PNG")
    (folder / "my_notes.txt").write_text("mine", encoding="utf-8")


def test_results_replace_what_an_earlier_run_left(tmp_path):
    _transient_folder(tmp_path)
    Results(tables={"losses": LOSSES, "kinematics": pd.DataFrame({"step": [0]})},
            figures={"power_losses": b"\x89PNG"}).write(tmp_path)
    names = sorted(p.name for p in tmp_path.iterdir())
    for gone in ("temperatures.csv", "energy.csv", "temperatures.png", "report.html",
                 "measured_vs_predicted.csv", "loss_maps_crb.png"):
        assert gone not in names
    for kept in ("losses.csv", "loss_breakdown.csv", "kinematics.csv", "power_losses.png",
                 "metadata.json", "my_notes.txt"):
        assert kept in names


def test_a_run_without_losses_leaves_no_breakdown_of_the_earlier_one(tmp_path):
    _transient_folder(tmp_path)
    Results(tables={"temperatures": TEMPS}).write(tmp_path)
    assert not (tmp_path / "loss_breakdown.csv").exists()
    assert not (tmp_path / "losses.csv").exists()


def test_metadata_without_tables_adds_to_the_tables_on_disk(tmp_path):
    # a run stopped before its end: the results writer put its step tables on disk and
    # Simulation writes only the metadata (chain, warnings, why it stopped)
    _transient_folder(tmp_path)
    Results(stats={"stopped": "interrupted (Ctrl-C)"}).write(tmp_path)
    for kept in ("temperatures.csv", "energy.csv", "losses.csv", "loss_breakdown.csv"):
        assert (tmp_path / kept).is_file()
