"""Session-24 user tour, report and units details: a run whose steps raise speed and load
together gets no loss map (a 3 x 3 map of three dots, six crosses and no contour) but a
note pointing to the loss per step; a sensor whose readings are all gaps is named once in
the report's notes; a temperature written as a bare number in text is suggested in degC."""

from __future__ import annotations

import pandas as pd
import pytest

from thermobearing.errors import InputError
from thermobearing.measured import read_measured_file
from thermobearing.report import FIGURE_CAPTIONS, _run_loss_maps, html_report, loss_map_notes
from thermobearing.report_losses import (
    MAP_MIN_FILLED,
    breakdown_by_source,
    map_coverage,
    map_gap,
)
from thermobearing.report_measured import ALL_GAPS, comparison_notes, terminal_lines
from thermobearing.results import Results
from thermobearing.units import to_si

#: (source, role, W at 1000 rpm and 1 kN); the power scales with speed x (1 + load)
_SOURCES = (("raceway_traction", "inner_ring", 10.0), ("churning_elements", "oil", 20.0))


def _protocol(points, bearings=("de", "nde")) -> pd.DataFrame:
    """A long losses table with one step per (speed [rpm], axial load [kN]) point."""
    rows = []
    for b in bearings:
        for i, (n, fa) in enumerate(points):
            for src, role, w in _SOURCES:
                rows.append({"step": i, "time [s]": 600.0 * (i + 1), "bearing": b,
                             "speed [rpm]": float(n), "radial load [kN]": 1.0,
                             "axial load [kN]": float(fa), "source": src,
                             "component": src, "role": role,
                             "power [W]": w * n / 1000.0 * (1.0 + fa),
                             "load dependence": "load_dependent"})
    return pd.DataFrame(rows)


# --- 1. loss maps of a protocol whose points lie on one line -------------------------------
def test_speed_and_load_raised_together_get_no_map_but_a_note():
    """The rig tour's protocol (900 r/min at 5 kN, 1500 at 15, 1800 at 25) drew for each
    bearing a 3 x 3 map with 6 of 9 points crossed and no contour."""
    losses = _protocol([(900, 5), (1500, 15), (1800, 25)])
    wide = breakdown_by_source(losses)
    de = wide[wide["bearing"] == "de"]
    assert map_coverage(de, "speed [rpm]", "axial load [kN]") == (3, 9, 0)
    assert _run_loss_maps(losses) == {}
    (note,) = loss_map_notes(losses)  # the two bearings' identical reasons: one note
    assert note.startswith("bearings de, nde: no loss map over speed and axial load: ")
    assert "3 of the 9 combinations" in note and "each speed ran at one load" in note
    assert FIGURE_CAPTIONS["power_losses"] in note  # where the loss per step is instead
    page = html_report(Results(tables={"losses": losses}), "t")
    assert "no loss map over speed and axial load" in page


def test_an_l_shaped_protocol_covers_no_block_and_gets_no_map():
    """A speed ramp at 5 kN, then 20 and 40 kN at the top speed: 5 of 9 combinations ran
    but no 2 x 2 block, so contourf drew nothing between the dots."""
    losses = _protocol([(600, 5), (1200, 5), (1800, 5), (1800, 20), (1800, 40), (0, 0)],
                       bearings=("test",))
    assert _run_loss_maps(losses) == {}
    (note,) = loss_map_notes(losses)
    assert note.startswith("bearing test: ") and "5 of the 9 combinations" in note
    assert "each speed ran at one load" not in note  # 1800 r/min ran at three loads


def test_a_sparse_grid_with_one_block_is_left_out_below_the_filled_share():
    """One complete 2 x 2 block of a 4 x 4 grid and a diagonal beside it: 6 of 16 ran."""
    points = [(1000, 1), (2000, 1), (1000, 2), (2000, 2), (3000, 3), (4000, 4)]
    losses = _protocol(points, bearings=("test",))
    wide = breakdown_by_source(losses)
    ran, total, cells = map_coverage(wide, "speed [rpm]", "axial load [kN]")
    assert (ran, total, cells) == (6, 16, 1) and ran < MAP_MIN_FILLED * total
    assert "less than 50 % of them" in map_gap(wide, "speed [rpm]", "axial load [kN]")
    assert _run_loss_maps(losses) == {} and len(loss_map_notes(losses)) == 1


def test_a_full_grid_and_a_grid_with_one_corner_missing_keep_their_maps():
    full = [(n, fa) for n in (1000, 2000, 3000) for fa in (1, 3)]
    losses = _protocol(full)
    assert sorted(_run_loss_maps(losses)) == ["loss_maps_de", "loss_maps_nde"]
    assert loss_map_notes(losses) == []
    losses = _protocol(full[:-1], bearings=("test",))  # 5 of 6, two blocks, one complete
    assert list(_run_loss_maps(losses)) == ["loss_maps_test"]
    assert loss_map_notes(losses) == []


def test_one_quantity_varying_gets_neither_map_nor_note():
    """A speed ramp at one load has its loss against speed in the bars: nothing to say."""
    losses = _protocol([(1000, 5), (2000, 5), (3000, 5)])
    assert _run_loss_maps(losses) == {} and loss_map_notes(losses) == []


# --- 2. a sensor whose readings are all gaps, named once -----------------------------------
def test_a_sensor_of_empty_cells_is_named_once_in_the_notes(tmp_path):
    path = tmp_path / "log.csv"
    path.write_text("time [min],TC1,TC2\n0,24.0,\n1,25.0,\n2,26.0,\n3,27.0,\n",
                    encoding="utf-8")
    columns = {"TC1": "de.oil", "TC2": "de.housing"}
    measured = read_measured_file(path, "time [min]", columns)
    temps = pd.DataFrame({"time [s]": [0.0, 180.0], "de.oil [degC]": [24.0, 27.0],
                          "de.housing [degC]": [24.0, 26.0]})
    notes = comparison_notes(measured, temps, columns)
    about = [n for n in notes if n.startswith("TC2")]
    # it was said twice: the reader's "every reading (4) is a gap (4 empty cells) ..."
    # and "TC2: all readings are gaps (left out of the errors)"
    assert about == ["TC2: every reading (4) is a gap (4 empty cells); this sensor is not "
                     "compared with the model"]
    lines = terminal_lines(measured, temps, columns)
    assert f"TC2 {ALL_GAPS}" in lines[0]  # the errors line still says why it has none
    assert lines[1] == "measured data notes (1):"


# --- 3. a temperature written as a bare number in text -------------------------------------
@pytest.mark.parametrize(("text", "suggested"), [
    ("38", "'38 degC'"),              # an oil inlet: was '38 K'
    ("-20", "'-20 degC'"),            # a cold start
    ("250", "'250 degC' or '250 K'"),  # both plausible
    ("313.15", "'313.15 K'"),         # plausible kelvin only
])
def test_a_bare_temperature_in_text_is_suggested_in_its_plausible_unit(text, suggested):
    with pytest.raises(InputError) as err:
        to_si(text, "temperature", field="supply.inlet_temperature")
    msg = str(err.value)
    assert "supply.inlet_temperature" in msg and repr(text) in msg
    assert f"needs its unit: {suggested})" in msg


def test_a_bare_number_below_absolute_zero_and_a_difference_and_a_pressure():
    with pytest.raises(InputError, match=r"-300 is below absolute zero in degC and in K"):
        to_si("-300", "K", field="supply.inlet_temperature")
    with pytest.raises(InputError, match=r"needs its unit: '5 K'\)"):
        to_si("5", "delta_degC", field="b")
    with pytest.raises(InputError, match=r"needs its unit: '-1 Pa'\)"):
        to_si("-1", "Pa", field="--pressure")
    assert to_si("38 degC", "temperature") == pytest.approx(311.15)
