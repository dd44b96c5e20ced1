"""State objects (thermobearing.state): validation of supplies, operating points, contacts."""

from __future__ import annotations

import numpy as np
import pytest

from thermobearing.errors import InputError, UnknownNameError
from thermobearing.state import ContactSet, KinematicState, OilSupply, OperatingPoint


def test_oil_supply_rules():
    s = OilSupply("jet", 33e-3 / 60, 308.15)
    assert s.flow_rate == pytest.approx(5.5e-4)
    with pytest.raises(InputError, match="flow_rate"):
        OilSupply("jet", -1e-5, 308.15)
    with pytest.raises(InputError, match="flow_rate"):
        OilSupply("circulation", 0.0, 308.15)
    OilSupply("grease", 0.0, 308.15)
    OilSupply("oil_bath", 0.0, 308.15, level=0.01)
    with pytest.raises(InputError, match="level"):
        OilSupply("oil_bath", 0.0, 308.15)
    with pytest.raises(UnknownNameError):
        OilSupply("mist", 1e-6, 308.15)
    with pytest.raises(InputError, match="inlet_temperature"):
        OilSupply("jet", 1e-5, -3.0)


def test_operating_point():
    op = OperatingPoint(inner_speed=188.5, radial_load=1000, axial_load=2000)
    assert op.outer_speed == 0.0
    with pytest.raises(InputError):
        OperatingPoint(inner_speed=10.0, radial_load=-1.0)


def _cs(race="inner", z=4, **kw):
    return ContactSet(race=race, normal_load=np.full(z, 100.0), semi_major=1e-3, semi_minor=1e-4,
                      max_pressure=1e9, **kw)


def test_contact_set_broadcast_and_roles():
    cs = _cs(entrainment_speed=2.0, sliding_speed=[0.1, 0.0, -0.1, 0.2])
    assert cs.n_elements == 4 and cs.semi_major.shape == (4,)
    np.testing.assert_allclose(cs.slide_to_roll, [0.05, 0.0, -0.05, 0.1])
    assert _cs("outer_2").ring_role == "outer_ring"
    with pytest.raises(InputError, match="ring_role"):
        _cs("rib")
    with pytest.raises(InputError, match="film_thickness"):
        _cs(film_thickness=-1e-7)
    with pytest.raises(InputError, match="sliding_speed"):
        _cs(sliding_speed=[1.0, 2.0])
    with pytest.raises(InputError, match="deformed_radius"):
        _cs(deformed_radius=0.0)


def test_kinematic_state():
    ks = KinematicState(inner_speed=100.0, outer_speed=0.0, cage_speed=45.2,
                        orbital_speed=np.full(4, 45.2), element_spin=400.0,
                        contacts=(_cs("inner"), _cs("outer")), origin="race_control")
    assert ks.cage_speed_ratio == pytest.approx(0.452)
    assert ks.contact("outer").race == "outer"
    assert ks.azimuth.shape == (4,)
    with pytest.raises(UnknownNameError):
        ks.contact("rib")
    with pytest.raises(InputError, match="elements"):
        KinematicState(100.0, 0.0, 45.0, np.full(5, 45.0), 0.0, contacts=(_cs(),))
    with pytest.raises(InputError, match="distinct"):
        KinematicState(100.0, 0.0, 45.0, np.full(4, 45.0), 0.0, contacts=(_cs(), _cs()))
    with pytest.raises(InputError, match="eccentricity"):
        KinematicState(100.0, 0.0, 45.0, np.full(4, 45.0), 0.0, contacts=(), cage_eccentricity=1)
