"""Issue 9: the rib contact's numbers in a run's outputs (the ``rib`` table, ``rib.csv``, and
the summaries), taken from the rib_friction source's own heat evaluation; the film-range
warning of a roller state naming its contacts.

Before: a scene run with the rib_friction source kept everything but the heat inside the
source (which model ran, mu, the faces' PV, the slip speed, the thrust share); the
``pan_hamrock_central: W in [...]`` warning of a roller rig did not say which raceway's
contacts left the formula's range.
"""

from __future__ import annotations

import csv
import math
import warnings

import numpy as np
import pandas as pd
import pytest

from thermobearing.errors import InputError, ValidityWarning
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation

#: an NU 214 made NJ-type (ribs on both rings, rib geometry), as tests/unit/test_toure23_rig.py
NJ214 = """title = "NJ 214 rib table"
[[bearings]]
name = "test"
preset = "NU214"
overrides = {{ ribbed_ring = "both", end_face_crown_radius = "500 mm", rib_angle = "0.5 deg", \
rib_height = "3 mm", axial_clearance = "0.05 mm" }}
[lubricant]
preset = "ISO_VG46"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "40 degC"
[environment]
ambient_temperature = "25 degC"
[schedule]
radial_load = "8 kN"
axial_load = "0.5 kN"
step_duration = "{duration}"
steps = [{{ speed = "2000 rpm" }}, {{ speed = "4000 rpm", axial_load = "1 kN" }}]
[models]
kinematics = "race_control"
heat_sources = [{sources}]
{options}
{network}
[outputs]
{mode}
want = [{want}]
"""
SOURCES = '"raceway_traction", "churning_elements", "rib_friction"'
REDUCED = 'heat_source_options = { rib_friction = { model = "reduced" } }'
NETWORK = """[network]
template = "four_node_paper002"
parameters = { housing_outer_diameter = "180 mm", housing_length = "50 mm" }"""

#: paper 003's bearing at 20000 r/min, the coupled rib model (configs/scenes/crb_rib_example)
CRB = """title = "CRB 50x75x16 rib table, coupled model"
[[bearings]]
name = "crb"
preset = "CRB_50x75x16"
overrides = { ribbed_ring = "both", cage = { outer_diameter = "65 mm" } }
[lubricant]
preset = "MIL_PRF_23699"
[supply]
method = "jet"
flow = "2 L/min"
inlet_temperature = "80 degC"
[environment]
ambient_temperature = "35 degC"
initial_temperature = "80 degC"
[schedule]
radial_load = "3 kN"
step_duration = "1 min"
steps = [{ speed = "20000 rpm", axial_load = "0.2 kN" }]
[models]
kinematics = "race_control"
heat_sources = ["churning_elements", "rib_friction"]
[outputs]
want = ["losses"]
"""

#: the rib table's columns after the step columns, in order, with their units
RIB_COLUMNS = [
    "rib model", "roller dynamics", "friction coefficient [-]", "elements temperature [degC]",
    "thrust normal force [N]", "thrust max pressure [MPa]", "thrust contact area [mm^2]",
    "thrust slide speed [m/s]", "thrust PV [MPa m/s]", "thrust heat [W]",
    "outer rib slide speed [m/s]", "outer rib heat [W]", "drag heat [W]",
    "left face PV [MPa m/s]", "right face PV [MPa m/s]", "left face heat [W]",
    "right face heat [W]", "rib slide speed [m/s]", "dynamics orbits [-]",
    "slip speed [m/s]", "rib heat [W]", "heat to rollers [-]"]
STEP_COLUMNS = ["step", "bearing", "speed [rpm]", "radial load [kN]", "axial load [kN]"]


def _nj214(*, sources=SOURCES, want='"losses"', network="", duration="5 min", mode=""):
    return loads_scene(_nj214_text(sources=sources, want=want, network=network,
                                   duration=duration, mode=mode))


def _nj214_text(*, sources=SOURCES, want='"losses"', network="", duration="5 min", mode=""):
    options = REDUCED if "rib_friction" in sources else ""
    return NJ214.format(sources=sources, want=want, network=network, duration=duration,
                        options=options, mode=mode)


def _rib_losses(losses: pd.DataFrame) -> pd.Series:
    rib = losses[losses["source"] == "rib_friction"]
    return rib.groupby(["step", "bearing"], sort=True)["power [W]"].sum()


@pytest.fixture(scope="module")
def reduced_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("rib_reduced")
    sim = Simulation(_nj214(), progress=False)
    return sim, sim.run(out), out


def test_the_rib_table_has_one_row_per_step_and_bearing_with_units_in_its_columns(
        reduced_run):
    sim, res, out = reduced_run
    rib = res.tables["rib"]
    assert list(rib.columns) == STEP_COLUMNS + RIB_COLUMNS
    assert list(rib["step"]) == [0, 1] and set(rib["bearing"]) == {"test"}
    assert list(rib["rib model"]) == ["reduced", "reduced"]
    assert list(rib["roller dynamics"]) == ["none", "none"]
    # the file a run writes as it goes: the same header and rows
    with (out / "rib.csv").open(encoding="utf-8") as fh:
        header = next(csv.reader(fh))
    assert header == STEP_COLUMNS + RIB_COLUMNS
    on_disk = pd.read_csv(out / "rib.csv")
    np.testing.assert_allclose(on_disk["rib heat [W]"], rib["rib heat [W]"], rtol=1e-12)


def test_the_rib_heat_is_the_loss_tables_rib_friction_and_its_parts_add_up(reduced_run):
    _, res, _ = reduced_run
    rib = res.tables["rib"].set_index(["step", "bearing"]).sort_index()
    booked = _rib_losses(res.tables["losses"])
    np.testing.assert_allclose(rib["rib heat [W]"].to_numpy(), booked.to_numpy(), rtol=1e-12)
    # no roller dynamics: the heat is the thrust share plus the lubricant drag (eq. 14)
    parts = rib["thrust heat [W]"] + rib["drag heat [W]"] + rib["outer rib heat [W]"].fillna(0.0)
    np.testing.assert_allclose(parts.to_numpy(), rib["rib heat [W]"].to_numpy(), rtol=1e-12)
    assert (rib["drag heat [W]"] > 0).all() and (rib["thrust heat [W]"] > 0).all()
    # the dynamics' columns are empty, not 0: no dynamics ran
    for col in ("left face PV [MPa m/s]", "right face PV [MPa m/s]", "left face heat [W]",
                "right face heat [W]", "rib slide speed [m/s]", "dynamics orbits [-]"):
        assert rib[col].isna().all(), col
    assert (rib["slip speed [m/s]"] >= 0).all()


def test_the_thrust_share_and_its_pv_are_those_of_the_heat(reduced_run):
    """Q = F_a / (Z cos theta_f) per roller; mu Q |v| = mu (2/3) (pi a b) P |v|: the heat
    booked for the thrust share is mu x 2/3 of the Hertz area x the PV in the table."""
    sim, res, _ = reduced_run
    bearing = sim.bearings[0].bearing
    rib = res.tables["rib"]
    z = bearing.n_rollers
    q = rib["axial load [kN]"] * 1e3 / (z * math.cos(math.radians(0.5)))
    np.testing.assert_allclose(rib["thrust normal force [N]"], q, rtol=1e-12)
    mu = rib["friction coefficient [-]"]
    heat = (z * mu * (2.0 / 3.0) * rib["thrust contact area [mm^2]"] * 1e-6
            * rib["thrust PV [MPa m/s]"] * 1e6)
    np.testing.assert_allclose(heat, rib["thrust heat [W]"], rtol=1e-9)
    np.testing.assert_allclose(rib["thrust PV [MPa m/s]"],
                               rib["thrust max pressure [MPa]"]
                               * rib["thrust slide speed [m/s]"], rtol=1e-12)


def test_the_run_summary_gives_the_rib_contact(reduced_run):
    sim, res, _ = reduced_run
    line = [x for x in sim.summary_text(res).splitlines() if x.startswith("rib contact")]
    rib = res.tables["rib"]
    assert len(line) == 1
    assert line[0].startswith("rib contact test (reduced model, no roller dynamics): mu 0.05")
    lo, hi = rib["thrust PV [MPa m/s]"].min(), rib["thrust PV [MPa m/s]"].max()
    assert f"at PV {lo:.4g}-{hi:.4g} MPa m/s" in line[0]
    assert "end-face PV" not in line[0]  # no dynamics, no face PV


def test_the_sweep_summary_gives_the_rib_maxima():
    from thermobearing.simulation_summary import summarize_scene

    text = _nj214_text()
    out = summarize_scene(text)
    res = Simulation(loads_scene(text), progress=False).run()
    rib = res.tables["rib"]
    assert out["max rib thrust PV [MPa m/s]"] == pytest.approx(
        rib["thrust PV [MPa m/s]"].max(), rel=1e-12)
    assert out["max rib heat [W]"] == pytest.approx(rib["rib heat [W]"].max(), rel=1e-12)
    assert "max rib end-face PV [MPa m/s]" not in out  # no roller dynamics ran


def test_a_transient_writes_the_rib_table_as_it_goes_from_the_step_ends_heat(tmp_path):
    scene = _nj214(want='"temperatures", "losses"', network=NETWORK, duration="20 s")
    sim = Simulation(scene, progress=False)
    res = sim.run(tmp_path)
    rib = res.tables["rib"]
    assert list(rib.columns) == (STEP_COLUMNS[:1] + ["time [s]"] + STEP_COLUMNS[1:]
                                 + RIB_COLUMNS)
    assert list(rib["time [s]"]) == pytest.approx([20.0, 40.0])
    booked = _rib_losses(res.tables["losses"])
    np.testing.assert_allclose(rib.sort_values("step")["rib heat [W]"].to_numpy(),
                               booked.to_numpy(), rtol=1e-12)
    # the models ran at the roller node's temperature of the step end, above the start
    assert (rib["elements temperature [degC]"] > 25.0).all()
    assert len(pd.read_csv(tmp_path / "rib.csv")) == 2


def test_a_steady_run_writes_the_rib_table_of_its_steady_states(tmp_path):
    scene = _nj214(want='"temperatures", "losses"', network=NETWORK, mode='mode = "steady"')
    res = Simulation(scene, progress=False).run(tmp_path)
    rib = res.tables["rib"]
    assert list(rib.columns) == STEP_COLUMNS + RIB_COLUMNS  # a steady state has no time
    booked = _rib_losses(res.tables["losses"])
    np.testing.assert_allclose(rib.sort_values("step")["rib heat [W]"].to_numpy(),
                               booked.to_numpy(), rtol=1e-12)
    assert len(pd.read_csv(tmp_path / "rib.csv")) == 2


def test_a_scene_without_the_rib_source_has_no_rib_table_and_leaves_no_old_file(
        reduced_run, tmp_path):
    _, _, out = reduced_run
    folder = tmp_path / "run"
    folder.mkdir()
    (folder / "rib.csv").write_text((out / "rib.csv").read_text(encoding="utf-8"),
                                    encoding="utf-8")
    sim = Simulation(_nj214(sources='"raceway_traction", "churning_elements"'),
                     progress=False)
    res = sim.run(folder)
    assert "rib" not in res.tables
    assert not (folder / "rib.csv").exists()
    assert "rib contact" not in sim.summary_text(res)


def test_the_coupled_model_books_its_face_heats_and_pv_in_the_table():
    """Paper 003's bearing at 20000 r/min, no unbalance: the coupled dynamics run (no skew
    contacts: face PV 0, the face heat is the lubricant drag of eq. 14); the thrust share
    slides at the dynamics' mean rib slide speed."""
    sim = Simulation(loads_scene(CRB), progress=False)
    res = sim.run()
    rib = res.tables["rib"].iloc[0]
    assert rib["rib model"] == "coupled" and rib["roller dynamics"] == "coupled"
    assert math.isnan(rib["drag heat [W]"])  # in the face heats
    parts = (rib["thrust heat [W]"] + rib["left face heat [W]"] + rib["right face heat [W]"]
             + (0.0 if math.isnan(rib["outer rib heat [W]"]) else rib["outer rib heat [W]"]))
    assert parts == pytest.approx(rib["rib heat [W]"], rel=1e-12)
    assert rib["rib heat [W]"] == pytest.approx(float(_rib_losses(res.tables["losses"]).iloc[0]),
                                                rel=1e-12)
    assert rib["left face PV [MPa m/s]"] >= 0.0 and rib["right face PV [MPa m/s]"] >= 0.0
    assert rib["left face heat [W]"] > 0.0 and rib["dynamics orbits [-]"] >= 1.0
    assert rib["thrust slide speed [m/s]"] == pytest.approx(rib["rib slide speed [m/s]"],
                                                            rel=1e-12)
    assert rib["slip speed [m/s]"] > 0.0
    line = [x for x in sim.summary_text(res).splitlines() if x.startswith("rib contact")][0]
    assert "rib contact crb (coupled model)" in line and "end-face PV of the dynamics" in line


def test_thrust_contact_of_no_load_and_a_negative_load():
    from thermobearing.geometry import load_bearing
    from thermobearing.heat_sources.rib import thrust_contact
    from thermobearing.rib import rib_geometry

    geom = rib_geometry(load_bearing("CRB_50x75x16"))
    assert thrust_contact(geom, 0.0) == (0.0, 0.0)
    p, area = thrust_contact(geom, 14.0)
    assert (2.0 / 3.0) * p * area == pytest.approx(14.0, rel=1e-12)
    with pytest.raises(InputError) as info:
        thrust_contact(geom, -1.0)
    assert info.value.field == "normal_force"


def test_the_roller_film_range_warning_names_the_contacts_it_checked():
    """NU 214 at 3000 r/min, 8 kN: the rollers outside the load zone press on the outer
    raceway with their centrifugal force only (W far below the fitted range); the warning
    says it is the outer raceway's contacts."""
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.state import OperatingPoint, race_control_state

    op = OperatingPoint(inner_speed=3000 * np.pi / 30, radial_load=8000.0, axial_load=0.0)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        race_control_state(load_bearing("NU214"), op, lubricant=load_lubricant("ISO_VG46"),
                           temperature=323.15)
    film = [str(w.message) for w in caught if issubclass(w.category, ValidityWarning)
            and "pan_hamrock_central: W in [" in str(w.message)]
    assert film, [str(w.message) for w in caught]
    assert all(m.startswith(("roller / inner raceway line contacts, pan_hamrock_central: ",
                             "roller / outer raceway line contacts, pan_hamrock_central: "))
               for m in film)
    assert any(m.startswith("roller / outer raceway") for m in film)
