"""Bad-input audit, issue 4 (force models and heat sources): oil flow, friction coefficients
outside [0, 1], a traction law asked outside its validity, heat-source options a scene gives
(unknown source / parameter / unit) -- through :class:`OilSupply`, :func:`make_traction_law`,
the heat sources with their documented options and ``thermobearing check``.
"""

from __future__ import annotations

import math
import warnings

import pytest

from thermobearing import cli
from thermobearing.errors import InputError, UnknownNameError, ValidityWarning
from thermobearing.state import KinematicState, OilSupply, OperatingPoint
from thermobearing.traction import make_traction_law

RPM = math.pi / 30.0


@pytest.fixture(scope="module", autouse=True)
def _warm_imports():
    """Import every sub-command module (~3 s once) outside the timed tests."""
    cli.build_parser()


@pytest.mark.parametrize("method", ["jet", "circulation", "oil_air"])
@pytest.mark.parametrize("flow", [0.0, -1e-5])
def test_zero_or_negative_flow_for_a_flowing_supply(method, flow):
    with pytest.raises(InputError) as info:
        OilSupply(method, flow, 308.15)
    assert info.value.field == "supply.flow_rate" and info.value.value == flow
    assert repr(method) in info.value.allowed and "oil_bath or grease" in info.value.allowed


def test_zero_flow_allowed_for_oil_bath_and_grease_negative_never():
    assert OilSupply("oil_bath", 0.0, 308.15, 0.01).flow_rate == 0.0
    assert OilSupply("grease", 0.0, 308.15).flow_rate == 0.0
    with pytest.raises(InputError):
        OilSupply("grease", -1e-6, 308.15)


def test_nan_flow_and_unknown_method():
    with pytest.raises(InputError) as info:
        OilSupply("jet", math.nan, 308.15)
    assert info.value.field == "supply.flow_rate" and "finite" in info.value.allowed
    with pytest.raises(UnknownNameError) as info:
        OilSupply("spray", 1e-4, 308.15)
    assert info.value.value == "spray" and "jet" in info.value.known


@pytest.mark.parametrize(("name", "params", "field"), [
    ("linear_saturating", {"mu_max": 1.5, "slip_speed_max": 1.0}, "traction.mu_max"),
    ("linear_saturating", {"mu_max": -0.1, "slip_speed_max": 1.0}, "traction.mu_max"),
    ("four_parameter", {"mu_zero": 0.0, "mu_max": 2.0, "slip_speed_at_max": 1.0,
                        "mu_infinity": 0.01}, "traction.mu_max"),
])
def test_traction_coefficient_outside_0_1(name, params, field):
    with pytest.raises(InputError) as info:
        make_traction_law(name, **params)
    assert info.value.field == field and "[0, 1]" in info.value.allowed


def test_unknown_traction_law_and_parameter():
    with pytest.raises(UnknownNameError) as info:
        make_traction_law("eyring")
    assert "eyring_limiting_shear" in info.value.known
    with pytest.raises(InputError) as info:
        make_traction_law("linear_saturating", mu_mx=0.1, slip_speed_max=1.0)
    assert info.value.value == ["mu_mx", "slip_speed_max"] and "mu_mx" in info.value.allowed


def test_traction_law_asked_outside_its_validity_without_film():
    from thermobearing.lubricant import load_lubricant

    law = make_traction_law("eyring_limiting_shear", lubricant=load_lubricant("ISO_VG46"),
                            limiting_shear_coefficient=0.08, eyring_stress=5e6)
    with pytest.raises(InputError) as info:
        law.shear_stress(1.0, 1e9)
    assert info.value.field == "traction[eyring_limiting_shear].film_thickness"
    with pytest.raises(InputError) as info:
        law.shear_stress(1.0, 1e9, film_thickness=1e-7)
    assert info.value.field == "traction[eyring_limiting_shear].temperature"


@pytest.fixture(scope="module")
def qj_context():
    from thermobearing.geometry import load_bearing
    from thermobearing.heat_sources import HeatContext
    from thermobearing.lubricant import load_lubricant

    bearing, oil = load_bearing("QJ1044"), load_lubricant("ISO_VG46")
    op = OperatingPoint(inner_speed=1800 * RPM, radial_load=1000.0, axial_load=20000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(bearing, op, lubricant=oil, temperature=318.15)

    def make(options):
        return HeatContext.isothermal(318.15, bearing=bearing, lubricant=oil,
                                      supply=OilSupply("jet", 33.0 / 6e4, 308.15),
                                      operating=op, kinematics=ks, options=options)
    return make


@pytest.mark.parametrize("mu", [1.5, -0.2])
def test_pocket_friction_coefficient_outside_0_1(qj_context, mu):
    from thermobearing.heat_sources import HEAT_SOURCES

    with pytest.raises(InputError) as info:
        HEAT_SOURCES.get("pocket_friction")(
            qj_context({"pocket_friction": {"friction_coefficient": mu}}))
    assert info.value.field == "options[pocket_friction].friction_coefficient"
    assert info.value.value == mu and "[0, 1]" in info.value.allowed


def test_cage_guide_boundary_friction_outside_0_1(qj_context):
    from thermobearing.heat_sources import HEAT_SOURCES

    with pytest.raises(InputError) as info:
        HEAT_SOURCES.get("cage_guide")(qj_context({"cage_guide": {"boundary_friction": 1.5}}))
    assert info.value.field == "options[cage_guide].boundary_friction"


def test_cage_guide_friction_coefficient_outside_0_1_is_not_ignored(qj_context):
    from thermobearing.heat_sources import HEAT_SOURCES

    with pytest.raises(InputError):
        HEAT_SOURCES.get("cage_guide")(qj_context({"cage_guide": {"friction_coefficient": 1.5}}))
    # a valid value the default form would not use is refused too, naming the form
    with pytest.raises(InputError) as info:
        HEAT_SOURCES.get("cage_guide")(qj_context({"cage_guide": {"friction_coefficient": 0.05}}))
    assert "paper002_eq18" in str(info.value)
    assert info.value.field == "options[cage_guide].friction_coefficient"


@pytest.mark.parametrize(("options", "words"), [
    ({"bogus_source": {"x": 1}}, ["models.heat_source_options.bogus_source", "cage_guide"]),
    ({"cage_guide": {"colour": 1}}, ["models.heat_source_options.cage_guide.colour",
                                     "boundary_friction"]),
    ({"cage_guide": {"critical_film": "3 kg"}},
     ["models.heat_source_options.cage_guide.critical_film", "'3 kg'"]),
])
def test_scene_heat_source_options_checked_by_check(tmp_path, capsys, options, words):
    from tests.unit.test_bad_input_scene import edited
    from thermobearing.scene import dumps_toml

    scene = tmp_path / "scene.toml"
    scene.write_text(dumps_toml(edited("models.heat_source_options", options)))
    code = cli.main(["check", str(scene)])
    err = capsys.readouterr().err
    assert code == 1 and "Traceback" not in err
    for w in words:
        assert w in err
