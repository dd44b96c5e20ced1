"""Test of the ``thermobearing rib-map`` command (CSV + PNG of paper 003 style maps)."""

import csv

from thermobearing.cli import main


def test_rib_map_writes_csv_and_png(tmp_path, capsys):
    rc = main(["rib-map", "--param", "rib_angle", "--values", "0.3,0.5 deg",
               "--unbalance", "0.11 g", "--out", str(tmp_path)])
    assert rc == 0
    rows = list(csv.reader((tmp_path / "rib_map_rib_angle.csv").open()))
    assert rows[0][0] == "rib_angle [deg]" and len(rows) == 3
    assert float(rows[1][0]) == 0.3 and float(rows[2][0]) == 0.5
    col = {name: j for j, name in enumerate(rows[0])}
    for r in rows[1:]:
        assert float(r[col["pv_left [MPa m/s]"]]) > 0
        assert float(r[col["slip_speed [m/s]"]]) > 0
        # peak >= time mean; the mean while in contact >= the time mean
        assert float(r[col["pv_peak_left [MPa m/s]"]]) >= float(r[col["pv_left [MPa m/s]"]])
        assert float(r[col["pv_contact_left [MPa m/s]"]]) >= float(r[col["pv_left [MPa m/s]"]])
    assert (tmp_path / "rib_map_rib_angle.png").stat().st_size > 1000
    assert "PV L" in capsys.readouterr().out


def test_rib_map_reduced_model_and_bad_orbits(tmp_path, capsys):
    rc = main(["rib-map", "--param", "axial_clearance", "--values", "0.03 mm", "--model",
               "reduced", "--unbalance", "0.11 g", "--out", str(tmp_path), "--no-plot"])
    assert rc == 0
    rows = list(csv.reader((tmp_path / "rib_map_axial_clearance.csv").open()))
    assert len(rows) == 2 and float(rows[1][0]) == 0.03
    assert main(["rib-map", "--orbits", "2", "--out", str(tmp_path), "--no-plot"]) != 0
    assert "--orbits" in capsys.readouterr().err


def test_rib_map_ctrl_c_keeps_finished_points_and_says_where(tmp_path, capsys, monkeypatch):
    """Each point is written as soon as it is computed; Ctrl-C during the second point keeps
    the first in the CSV and names the file."""
    import thermobearing.skidding.roller_dynamics_map as rdm

    real = rdm.simulate
    calls = []

    def interrupt_second(*args, **kwargs):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(*args, **kwargs)

    monkeypatch.setattr(rdm, "simulate", interrupt_second)
    rc = main(["rib-map", "--param", "axial_clearance", "--values", "0.03,0.05 mm", "--model",
               "reduced", "--unbalance", "0.11 g", "--out", str(tmp_path), "--no-plot"])
    assert rc == 130
    path = tmp_path / "rib_map_axial_clearance.csv"
    rows = list(csv.reader(path.open()))
    assert len(rows) == 2 and float(rows[1][0]) == 0.03
    err = capsys.readouterr().err
    assert "interrupted" in err and str(path) in err
