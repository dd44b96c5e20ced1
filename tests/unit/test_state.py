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


def test_race_control_state_ball_and_roller():
    import math
    import warnings

    from thermobearing.errors import ValidityWarning
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.state import deformed_surface_radius

    oil = load_lubricant("ISO_VG46")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        b = load_bearing("QJ1044")
        op = OperatingPoint(inner_speed=1800 * math.pi / 30, radial_load=1000, axial_load=20000)
        ks = KinematicState.from_race_control(b, op, lubricant=oil, temperature=318.15)
        assert ks.origin == "race_control" and len(ks.contacts) == 2
        # outer-race control: no spin at the outer contact
        np.testing.assert_allclose(ks.contact("outer").spin_speed, 0.0, atol=1e-9)
        assert np.all(ks.contact("inner").film_thickness > 0)
        assert ks.contact("inner").deformed_radius[0] == pytest.approx(
            deformed_surface_radius(b.inner_conformity, b.ball_diameter))
        assert np.all(ks.contact("inner").sliding_speed == 0)
        r = load_bearing("NU214")
        op = OperatingPoint(inner_speed=5000 * math.pi / 30, radial_load=150)
        ks = KinematicState.from_race_control(r, op, lubricant=oil, temperature=330.0)
    cs = ks.contact("outer")
    assert cs.kind == "line" and np.all(np.isinf(cs.deformed_radius))
    assert np.all(cs.normal_load > 0)  # centrifugal force loads every outer contact
    assert ks.cage_speed_ratio == pytest.approx(r.theoretical_cage_speed_ratio(), rel=1e-9)


def test_deformed_radius_formula():
    from thermobearing.state import deformed_surface_radius

    # 2 f D / (2 f + 1): f = 0.53, D = 35 mm -> 18.01 mm ... = 0.515 D
    assert deformed_surface_radius(0.53, 0.035) == pytest.approx(2 * 0.53 * 0.035 / 2.06)


@pytest.mark.parametrize(("field", "value", "allowed"), [
    ("normal_load", np.array([100.0, -1.0, 5.0, 0.0]), ">= 0"),
    ("semi_minor", np.nan, "finite"),
    ("max_pressure", -1e9, ">= 0"),
    ("spin_speed", np.array([0.0, np.inf, 0.0, 0.0]), "finite"),
    ("contact_angle", np.nan, "finite"),
    ("film_thickness", -1e-7, ">= 0"),
    ("temperature", 0.0, "absolute zero"),
    ("temperature", np.nan, "finite"),
    ("deformed_radius", 0.0, "radii > 0"),
    ("reduced_radius_y", np.nan, "radii > 0"),
    ("reduced_radius_x", np.inf, "finite"),
])
def test_contact_set_names_the_bad_field(field, value, allowed):
    """The vectorised block check of ContactSet refuses every bad field and names it."""
    base = {"normal_load": np.full(4, 100.0), "semi_major": 1e-3, "semi_minor": 1e-4,
            "max_pressure": 1e9}
    base[field] = value
    with pytest.raises(InputError, match=allowed) as info:
        ContactSet(race="outer", **base)
    assert f"contacts[outer].{field}" in str(info.value)


def test_contact_set_fields_read_only_and_infinite_radii_allowed():
    cs = _cs(deformed_radius=np.inf, reduced_radius_y=np.inf, temperature=330.0,
             film_thickness=np.array([0.0, 1e-7, 2e-7, 3e-7]))
    assert np.all(np.isinf(cs.deformed_radius)) and cs.temperature.shape == (4,)
    with pytest.raises(ValueError):
        cs.sliding_speed[0] = 1.0
    moved = cs.with_(sliding_speed=np.array([0.1, 0.2, 0.3, 0.4]))
    assert moved.sliding_speed[3] == 0.4 and cs.sliding_speed[3] == 0.0


@pytest.mark.parametrize("bad", [np.ones(3), np.ones((1, 4)), np.ones((4, 4)), "fast", [1.0, 2.0]])
def test_contact_set_refuses_a_field_of_the_wrong_shape(bad):
    """A field that does not broadcast to (Z,) is named, with the shape allowed."""
    with pytest.raises(InputError, match=r"(?s)contacts\[inner\]\.sliding_speed.*shape \(4,\)"):
        _cs(sliding_speed=bad)


def test_contact_set_accepts_scalars_lists_and_length_one_arrays():
    cs = _cs(sliding_speed=np.array([0.5]), spin_speed=[1.0, 2.0, 3.0, 4.0], roll_speed=3)
    np.testing.assert_array_equal(cs.sliding_speed, np.full(4, 0.5))
    np.testing.assert_array_equal(cs.spin_speed, [1.0, 2.0, 3.0, 4.0])
    np.testing.assert_array_equal(cs.roll_speed, np.full(4, 3.0))
    assert not cs.spin_speed.flags.writeable
