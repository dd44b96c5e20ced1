"""A schedule step with both rings at rest (a stop in a rig protocol): no solver runs, no
source dissipates, the network keeps cooling (kinematic_models.standstill)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scene_parts import (
    PAPER002_AMBIENT,
    PAPER002_NETWORK,
    PAPER002_OIL,
    QJ1044_DE,
    RACE_CONTROL,
    scene_title,
)

from thermobearing.geometry import load_bearing
from thermobearing.heat_sources import HEAT_SOURCES, HeatContext, evaluate_recorded
from thermobearing.kinematic_models import KINEMATICS, standstill
from thermobearing.lubricant import load_lubricant
from thermobearing.scene import loads_scene
from thermobearing.simulation import Simulation
from thermobearing.state import OilSupply, OperatingPoint

OIL = load_lubricant("ISO_VG46")
SUPPLY = OilSupply("jet", 33 / 60000, 308.15)
STOP_SCENE = scene_title("run, stop, run") + QJ1044_DE + PAPER002_OIL + PAPER002_AMBIENT + """\
[schedule]
radial_load = "1 kN"
axial_load = "10 kN"
step_duration = "10 min"
steps = [{ speed = "1800 rpm" }, { speed = "0 rpm" }, { speed = "1200 rpm" }]
""" + RACE_CONTROL + PAPER002_NETWORK + """[outputs]
want = ["temperatures", "losses", "kinematics", "energy"]
"""


@pytest.mark.parametrize("model", ["race_control", "skidding", "none"])
@pytest.mark.parametrize("name, fr, fa", [("QJ1044", 1000.0, 10000.0), ("NU214", 5000.0, 0.0)])
def test_every_kinematics_model_returns_the_rest_state(model, name, fr, fa):
    bearing = load_bearing(name)
    op = OperatingPoint(inner_speed=0.0, radial_load=fr, axial_load=fa)
    res = KINEMATICS.get(model)(bearing, OIL, op, contact_temperature=308.15,
                                oil_temperature=308.15, supply=SUPPLY)
    st = res.state
    assert st.origin == "standstill" and res.converged
    assert math.isnan(res.cage_speed_ratio) and math.isnan(res.over_skid)
    assert 0.0 < res.theoretical_cage_speed_ratio < 0.5
    assert st.cage_speed == 0.0 and np.all(np.asarray(st.orbital_speed) == 0.0)
    inner = [cs for cs in st.contacts if cs.race.startswith("inner")]
    loads = np.concatenate([np.atleast_1d(cs.normal_load) for cs in inner])
    # the static load distribution carries the loads: Hertz pressures for the stress check,
    # no film (Lambda is undefined at rest), nothing slides
    assert loads.max() > 0.0
    for cs in st.contacts:
        assert cs.film_thickness is None
        assert np.all(np.asarray(cs.sliding_speed) == 0.0)
        assert np.all(np.asarray(cs.entrainment_speed) == 0.0)
    # the loads' resultant: radial = sum Q cos(alpha) cos(psi) over the inner contacts
    psi = st.azimuth if st.azimuth is not None else 2 * np.pi * np.arange(loads.size) / loads.size
    if fa == 0.0:
        radial = sum(float(np.sum(np.asarray(cs.normal_load) * np.cos(cs.contact_angle)
                                  * np.cos(psi))) for cs in inner)
        assert radial == pytest.approx(fr, rel=1e-6)


def test_unloaded_bearing_at_rest_has_no_contacts():
    res = standstill(load_bearing("QJ1044"), OperatingPoint(inner_speed=0.0))
    assert res.state.contacts == () and math.isnan(res.cage_speed_ratio)


def test_every_source_books_zero_at_rest():
    bearing = load_bearing("QJ1044")
    op = OperatingPoint(inner_speed=0.0, radial_load=1000.0, axial_load=10000.0)
    ctx = HeatContext.isothermal(308.15, bearing=bearing, lubricant=OIL, supply=SUPPLY,
                                 operating=op, kinematics=standstill(bearing, op).state)
    names = [n for n in HEAT_SOURCES.names() if n != "global_friction"]
    for result, reads in evaluate_recorded(names, ctx):
        assert result.total == 0.0 and not reads


def test_protocol_with_a_stop_cools_during_it_and_closes_the_energy_books(tmp_path):
    scene = loads_scene(STOP_SCENE)

    res = Simulation(scene, progress=False).run(out_dir=tmp_path)
    losses = res.tables["losses"]
    stop = losses[losses["step"] == 1]
    assert len(stop) and float(stop["power [W]"].abs().sum()) == 0.0
    assert float(losses[losses["step"] == 0]["power [W]"].sum()) > 100.0
    kin = res.tables["kinematics"]
    assert kin.loc[kin["step"] == 1, "cage speed ratio [-]"].isna().all()
    assert kin.loc[kin["step"] != 1, "cage speed ratio [-]"].notna().all()
    temps = res.tables["temperatures"]
    t = temps["time [s]"].to_numpy()
    housing = temps["de.housing [degC]"].to_numpy()
    during = (t >= 600.0) & (t <= 1200.0)
    assert housing[during][-1] < housing[during][0]          # it cools while at rest
    assert np.all(np.diff(housing[during]) <= 1e-9)
    e = res.tables["energy"].iloc[-1]
    assert abs(e["imbalance [J]"]) <= 1e-4 * e["generated [J]"]


def test_report_of_a_protocol_with_a_stop_has_no_nan(tmp_path):
    """The report's tables show undefined values at rest as a dash and the catalogue
    cross-check leaves the stop out with a note (its ratio would be 0 / 0)."""
    from thermobearing.report_context import catalogue_crosscheck

    scene = loads_scene(STOP_SCENE.replace('want = ["temperatures", "losses", "kinematics", '
                                           '"energy"]', 'want = ["losses", "report"]'))
    res = Simulation(scene, progress=False).run(out_dir=tmp_path)
    import re

    # the text of the page (the embedded figures' base64 may hold any letters)
    html = re.sub(r"data:image/png;base64,[^\"']*", "", (tmp_path / "report.html").read_text())
    assert "NaN" not in html and ">nan<" not in html
    sim = Simulation(scene, progress=False)
    table, notes = catalogue_crosscheck(res.tables["losses"], res.tables, scene,
                                        {b.name: b.bearing for b in sim.bearings},
                                        sim.lubricant)
    assert list(table["step"]) == [0, 2]
    assert any("steps at rest (0 r/min) left out" in n and "(steps 1)" in n for n in notes)
