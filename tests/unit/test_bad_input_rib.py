"""Bad-input audit, issue 9 (roller end-face / rib contact, roller dynamics with unbalance):
geometry in which the roller cannot touch the rib, a negative clearance and an unbalance
larger than the roller mass each give a clear error naming the field -- through
:func:`thermobearing.rib.rib_geometry`, the dynamics' :func:`build_model` (checks run before
the quasi-static solve) and ``thermobearing rib-map``.
"""

from __future__ import annotations

import pytest

from thermobearing import cli
from thermobearing.errors import InputError, UnknownNameError
from thermobearing.rib import rib_geometry, unbalance_check, with_changes


@pytest.fixture(scope="module")
def crb():
    from thermobearing.geometry import load_bearing

    return load_bearing("CRB_50x75x16")  # paper 003 base case


@pytest.fixture(scope="module")
def oil():
    from thermobearing.lubricant import load_lubricant

    return load_lubricant("MIL_PRF_23699")


def test_rib_lower_than_the_contact_point(crb):
    with pytest.raises(InputError) as info:
        rib_geometry(crb, rib_height=0.3e-3)
    assert info.value.field == "rib.rib_height" and info.value.value == pytest.approx(0.3e-3)
    assert "cannot touch the rib" in info.value.allowed and "H_contact" in info.value.allowed


def test_rib_higher_than_the_roller(crb):
    with pytest.raises(InputError) as info:
        rib_geometry(crb, rib_height=crb.roller_diameter)
    assert info.value.field == "rib.rib_height" and "D_w" in info.value.allowed


@pytest.mark.parametrize(("field", "value"), [("axial_clearance", -1e-5),
                                              ("rib_angle", -0.01)])
def test_negative_clearance_or_rib_angle(crb, field, value):
    with pytest.raises(InputError) as info:
        rib_geometry(crb, **{field: value})
    assert info.value.field == f"rib.{field}" and info.value.value == value


def test_unknown_rib_override_lists_the_fields(crb):
    # before: TypeError "RibGeometry.__init__() got an unexpected keyword argument"
    with pytest.raises(UnknownNameError) as info:
        rib_geometry(crb, rib_hieght=1e-3)
    assert info.value.field == "rib.rib_hieght" and "rib_height" in info.value.known
    geom = rib_geometry(crb)
    with pytest.raises(UnknownNameError):
        with_changes(geom, clearance=1e-5)
    assert with_changes(geom, axial_clearance=4e-5).axial_clearance == 4e-5


@pytest.mark.parametrize("mass", [1.0, -1e-4])
def test_unbalance_larger_than_the_roller_or_negative(crb, mass):
    with pytest.raises(InputError) as info:
        unbalance_check(mass, crb.roller_mass)
    assert info.value.field == "unbalance_mass" and info.value.value == mass


def test_unbalance_message_gives_the_roller_mass(crb):
    with pytest.raises(InputError) as info:
        unbalance_check(5e-3, crb.roller_mass)
    assert f"{crb.roller_mass * 1e3:.4g} g" in info.value.allowed


@pytest.mark.parametrize(("kwargs", "field"), [
    ({"unbalance_mass": 1.0}, "unbalance_mass"),
    ({"unbalance_mass": 0.0, "pocket_clearance": -1e-4}, "pocket_clearance"),
    ({"unbalance_mass": 0.0, "rib": {"axial_clearance": -1e-5}}, "rib.axial_clearance"),
    ({"unbalance_mass": 0.0, "rib": {"rib_height": 0.3e-3}}, "rib.rib_height"),
    ({"unbalance_mass": 0.0, "rib": {"rib_hieght": 0.3e-3}}, "rib.rib_hieght"),
])
def test_roller_dynamics_bad_input_before_any_solve(crb, oil, kwargs, field):
    from thermobearing.skidding.roller_dynamics import build_model

    with pytest.raises(InputError) as info:
        build_model(crb, oil, 3000.0, 3000.0, **kwargs)
    assert info.value.field == field


def test_rib_map_negative_clearance_one_line(capsys, tmp_path):
    code = cli.main(["rib-map", "--param", "axial_clearance", "--values", "-0.03 mm",
                     "--model", "reduced", "--out", str(tmp_path / "out")])
    err = capsys.readouterr().err
    assert code == 1 and "Traceback" not in err
    assert "rib.axial_clearance" in err and ">= 0" in err


def test_rib_friction_outside_0_1_refused_before_the_dynamics(crb, oil):
    # before: accepted by build_model; rib_forces refused it only when the finished run
    # was post-processed
    from thermobearing.skidding.roller_dynamics import build_model

    with pytest.raises(InputError) as info:
        build_model(crb, oil, 3000.0, 3000.0, 0.0, rib_friction=2.0)
    assert info.value.field == "rib_friction" and "[0, 1]" in info.value.allowed


@pytest.mark.parametrize("field", ["skew", "axial_shift", "roller_spin"])
def test_rib_forces_nan_state_is_refused_not_read_as_no_contact(crb, field):
    # before: a NaN skew returned zero forces (every comparison with NaN is False)
    from thermobearing.rib import rib_forces

    state = {"skew": 0.0, "axial_shift": 0.0, "roller_spin": -8000.0}
    state[field] = float("nan")
    with pytest.raises(InputError) as info:
        rib_forces(rib_geometry(crb), state["skew"], state["axial_shift"], inner_speed=3000.0,
                   cage_speed=1300.0, roller_spin=state["roller_spin"])
    assert info.value.field == field and "finite" in info.value.allowed
