"""Bearing geometry, presets and bad input."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest

from thermobearing import geometry, load_bearing
from thermobearing.errors import InputError, UnknownNameError
from thermobearing.geometry import BallBearing, RollerBearing, bearing_from_dict, preset_names
from thermobearing.materials import STEEL_52100

PRESETS = ("QJ1044", "NU214", "D1842926", "SKF6304", "CRB_50x75x16")


def _ball_dict(**changes):
    data = {
        "name": "T", "kind": "deep_groove", "source": "test", "bore": "20 mm",
        "outer_diameter": "52 mm", "width": "15 mm", "ball_diameter": "9.525 mm", "n_balls": 7,
        "pitch_diameter": "36 mm", "inner_conformity": 0.52, "outer_conformity": 0.53,
        "contact_angle": "0 deg", "diametral_clearance": "15 um",
        "ball_material": "STEEL_52100", "ring_material": "STEEL_52100",
        "cage": {"guidance": "rolling_element", "pocket_clearance": "0.3 mm", "width": "8 mm",
                 "inner_diameter": "32 mm", "outer_diameter": "40 mm", "mass": "8 g"},
    }
    data.update(changes)
    return data


@pytest.mark.parametrize("name", PRESETS)
def test_presets_load_with_sources(name: str) -> None:
    b = load_bearing(name)
    assert b.name == name
    assert b.source.strip()
    assert b.cage.source.strip()
    assert b.estimated  # every preset has estimated fields with reasoning
    assert all(len(v.strip()) > 5 for v in b.estimated.values())
    assert b.element_mass > 0 and b.cage_mass > 0
    assert b.inner_raceway_diameter < b.pitch_diameter < b.outer_raceway_diameter


def test_all_presets_listed() -> None:
    assert set(PRESETS) <= set(preset_names())


def test_nu214_paper000_eq40() -> None:
    # paper 000 eq. 40: n_m = n_i (1 - D_b/d_m)/2 = 5000 (1 - 13/97.5)/2 = 2166.67 r/min
    b = load_bearing("NU214")
    assert isinstance(b, RollerBearing)
    assert 5000 * b.theoretical_cage_speed_ratio() == pytest.approx(2166.6667, rel=1e-6)
    # raceways: d_i = d_m - D - P_d/2 = 97.5 - 13 - 0.0125 mm
    assert b.inner_raceway_diameter == pytest.approx(84.4875e-3, rel=1e-12)
    # roller: m = 7800 pi 0.013^2 0.013 / 4 = 1.3459e-2 kg, J = m D^2/8
    assert b.roller_mass == pytest.approx(7800 * math.pi * 0.013**3 / 4, rel=1e-12)
    assert b.roller_inertia == pytest.approx(b.roller_mass * 0.013**2 / 8, rel=1e-12)


def test_skf6304_paper004_table1() -> None:
    b = load_bearing("SKF6304")
    assert isinstance(b, BallBearing)
    # paper 004 Table 1: J_r = 3.18e-8 kg m^2 (density back-computed in the preset)
    assert b.ball_inertia == pytest.approx(3.18e-8, rel=2e-3)
    # Table 1 raceway diameters 26.475 / 45.538 mm vs d_m -+ D -+ P_d/2 with d_m = 36 mm
    assert b.inner_raceway_diameter == pytest.approx(26.475e-3, abs=1e-5)
    assert b.outer_raceway_diameter == pytest.approx(45.538e-3, abs=1e-5)
    # BPFO = Z/2 (1 - D/d_m) f_s at 2000 r/min = 3.5 * 0.735417 * 33.333 = 85.80 Hz
    f = b.characteristic_frequencies(2000 / 60)
    assert f.bpfo == pytest.approx(85.7986, rel=1e-5)
    assert f.bpfi == pytest.approx(7 * 33.3333 - 85.7986, rel=1e-5)
    # cage slip: f_bpo (1 - s_c) (paper 004 rule after Fig. 11)
    assert b.characteristic_frequencies(2000 / 60, cage_slip=0.02).bpfo == pytest.approx(
        0.98 * f.bpfo, rel=1e-12)
    # ball spin (Harris): (d_m / 2D) f_s (1 - gamma^2)
    g = 9.525 / 36
    assert f.ball_spin == pytest.approx(36 / (2 * 9.525) * 2000 / 60 * (1 - g**2), rel=1e-12)


def test_deep_groove_free_contact_angle_from_clearance() -> None:
    # Harris: cos(a_f) = 1 - P_d / (2 (f_i + f_o - 1) D) = 1 - 0.015 / (2*0.05*9.525)
    b = load_bearing("SKF6304")
    expected = math.acos(1 - 0.015 / (2 * 0.05 * 9.525))
    assert b.free_contact_angle == pytest.approx(expected, rel=1e-12)
    # mounted: a clearance reduction of 10 um leaves 5 um
    assert b.mounted_contact_angle(10e-6) == pytest.approx(
        math.acos(1 - 0.005 / (2 * 0.05 * 9.525)), rel=1e-12)
    with pytest.raises(InputError, match="clearance_reduction"):
        b.mounted_contact_angle(20e-6)


def test_qj1044_csr_and_gothic_arch() -> None:
    b = load_bearing("QJ1044")
    # CSR_th = (1 - D cos 40 / d_m)/2 = (1 - 34.925*0.766044/280)/2 = 0.452225
    assert b.theoretical_cage_speed_ratio() == pytest.approx(0.452225, rel=1e-5)
    assert b.theoretical_cage_speed_ratio() == pytest.approx(0.452, rel=5e-3)
    # gothic arch: centred ball touches both arcs at theta_s, sin = s/((2f - 1) D)
    theta = b.shim_angle("inner")
    assert math.sin(theta) == pytest.approx(1.285e-3 / (0.06 * 34.925e-3), rel=1e-12)
    # the free diagonal angle reproduces 40 deg with the 0.1 mm clearance (within the offset's
    # 1 um rounding)
    assert math.degrees(b.free_contact_angle) == pytest.approx(40.0, abs=0.01)
    # with zero clearance the free angle is the shim angle
    assert b.free_contact_angle_for(0.0) == pytest.approx(theta, rel=1e-12)
    assert b.cage.guidance == "outer_ring"
    for key in ("ball_diameter", "n_balls", "gothic_arch_offset", "cage.guidance"):
        assert key in b.estimated


def test_four_point_offset_derived_when_omitted() -> None:
    data = _ball_dict(kind="four_point", contact_angle="35 deg", diametral_clearance="0.02 mm")
    b = bearing_from_dict(data)  # f_i = 0.52, f_o = 0.53: unequal shim angles
    assert math.degrees(b.free_contact_angle) == pytest.approx(35.0, abs=1e-9)
    assert b.shim_angle("inner") > b.shim_angle("outer")
    sym = bearing_from_dict({**data, "outer_conformity": 0.52})
    a = 0.04 * 9.525e-3
    assert math.cos(sym.shim_angle("outer")) == pytest.approx(
        math.cos(math.radians(35)) + 0.02e-3 / (2 * a), rel=1e-12)
    bad = _ball_dict(kind="four_point", contact_angle="35 deg", gothic_arch_offset="0.1 mm")
    with pytest.raises(InputError, match="gothic_arch_offset"):
        bearing_from_dict(bad)


def test_curvature_and_reduced_radii() -> None:
    b = load_bearing("SKF6304")
    rx_i, ry_i = b.curvature("inner", 0.0)
    d, dm = 9.525e-3, 36e-3
    assert rx_i == pytest.approx(d * (dm - d) / (2 * dm), rel=1e-12)
    assert ry_i == pytest.approx(0.52 * d / 0.04, rel=1e-12)
    rx_o, ry_o = b.curvature("outer", 0.0)
    assert rx_o == pytest.approx(d * (dm + d) / (2 * dm), rel=1e-12)
    assert b.curvature_sum("inner", 0.0) == pytest.approx(1 / rx_i + 1 / ry_i)
    with pytest.raises(UnknownNameError):
        b.curvature("middle")


def test_unequal_angles_use_race_control() -> None:
    b = load_bearing("QJ1044")
    ai, ao = math.radians(50), math.radians(30)
    g = 34.925 / 280
    orc = (1 - g * math.cos(ai)) / (1 + math.cos(ai - ao))
    assert b.theoretical_cage_speed_ratio(ai, ao) == pytest.approx(orc, rel=1e-12)


def test_roller_paper003_fields() -> None:
    b = load_bearing("CRB_50x75x16")
    assert b.cage.guidance == "inner_ring"
    assert b.end_face_crown_radius == pytest.approx(0.3)
    assert math.degrees(b.rib_angle) == pytest.approx(0.3)
    assert b.axial_clearance == pytest.approx(3e-5)
    assert b.ribbed_ring == "inner"
    # paper 003 eq. 4: C_af = (H - D_w/2) tan(theta_f); 10 um radial offset -> 5.236e-8 m
    assert b.rib_axial_clearance_at(3e-3 + 1e-5) == pytest.approx(1e-5 * math.tan(
        math.radians(0.3)), rel=1e-9)


def test_d1842926_table1() -> None:
    b = load_bearing("D1842926")
    assert b.n_rollers == 30
    assert b.roller_effective_length == pytest.approx(10.8e-3)
    assert b.effective_modulus == pytest.approx(218e9 / (1 - 0.09), rel=1e-12)


def test_overrides() -> None:
    b = geometry.load_bearing("SKF6304", overrides={"diametral_clearance": "0.03 mm"})
    assert b.diametral_clearance == pytest.approx(3e-5)


# -- bad input: every error names the field -------------------------------------------------
@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"ball_diameter": "-1 mm"}, "ball_diameter"),
        ({"ball_diameter": "0 mm"}, "ball_diameter"),
        ({"ball_diameter": "17 mm"}, "ball_diameter"),  # larger than the 16 mm section
        ({"n_balls": 2}, "n_balls"),
        ({"n_balls": 30}, "n_balls"),  # would overlap on the pitch circle
        ({"kind": "angular_contact", "contact_angle": "90 deg"}, "contact_angle"),
        ({"kind": "angular_contact", "contact_angle": "-5 deg"}, "contact_angle"),
        ({"bore": "60 mm"}, "outer_diameter"),
        ({"inner_conformity": 0.49}, "inner_conformity"),
        ({"ball_diameter": "9.5 kg"}, "ball_diameter"),
        ({"colour": "red"}, "colour"),
        ({"kind": "tapered"}, "kind"),
        ({"source": ""}, "source"),
        ({"ball_material": "UNOBTAINIUM"}, "material"),
        ({"pitch_diameter": "10 mm"}, "pitch_diameter"),
    ],
)
def test_bad_input_names_field(changes: dict, field: str) -> None:
    with pytest.raises(InputError, match=field):
        bearing_from_dict(_ball_dict(**changes))


def test_unknown_preset_lists_known() -> None:
    with pytest.raises(UnknownNameError) as exc:
        load_bearing("QJ9999")
    assert "QJ1044" in str(exc.value) and "NU214" in str(exc.value)


def test_unknown_cage_key(tmp_path: Path) -> None:
    data = _ball_dict()
    data["cage"] = {**data["cage"], "shape": "round"}
    with pytest.raises(InputError, match="cage.shape"):
        bearing_from_dict(data)


def test_roller_bad_input() -> None:
    b = load_bearing("NU214")
    fields = {f: getattr(b, f) for f in b.__dataclass_fields__}
    with pytest.raises(InputError, match="roller_length"):
        RollerBearing(**{**fields, "roller_length": 0.03})
    with pytest.raises(InputError, match="n_rollers"):
        RollerBearing(**{**fields, "n_rollers": 2})
    with pytest.raises(InputError, match="roller_effective_length"):
        RollerBearing(**{**fields, "roller_effective_length": 0.02})


def test_frozen() -> None:
    b = load_bearing("SKF6304")
    with pytest.raises(AttributeError):
        b.n_balls = 8  # type: ignore[misc]
    c = replace(b, ball_material=STEEL_52100)
    assert c.ball_material.name == "STEEL_52100"


@pytest.mark.parametrize("name", PRESETS)
def test_summary_is_finite(name: str) -> None:
    for key, (value, unit) in load_bearing(name).summary().items():
        assert math.isfinite(value) or key == "ry", key
        assert unit


def test_operating_clearance_thermal_growth() -> None:
    b = geometry.load_bearing("SKF6304")
    g = geometry.STEEL_EXPANSION
    # inner ring 10 K warmer than the outer ring and balls at the reference: the clearance
    # shrinks by G d_i 10 K = 11.9e-6 * 26.4675e-3 * 10 = 3.150e-6 m
    pd = b.operating_clearance(303.15, 293.15, 293.15)
    assert pd == pytest.approx(15e-6 - g * b.inner_raceway_diameter * 10.0, rel=1e-12)
    # uniform heating of a one-material bearing scales P_d by (1 + G dT) (similar geometry)
    pd_u = b.operating_clearance(343.15, 343.15, 343.15)
    assert pd_u == pytest.approx(15e-6 * (1 + g * 50.0), rel=1e-9)
    # a hot inner ring can consume the clearance: negative = preload
    assert b.operating_clearance(393.15, 293.15, 343.15) < 0
    with pytest.raises(InputError, match="inner_ring_temperature"):
        b.operating_clearance(-1.0, 293.15, 293.15)


def test_with_clearance_keeps_gothic_arch() -> None:
    b = geometry.load_bearing("QJ1044")
    c = b.with_clearance(0.2e-3)
    assert c.gothic_arch_offset == b.gothic_arch_offset
    assert c.contact_angle == pytest.approx(b.free_contact_angle_for(0.2e-3))
    assert c.contact_angle > b.contact_angle  # more play, steeper diagonal angle
    # the same through a scene-style override of the preset
    o = geometry.load_bearing("QJ1044", overrides={"diametral_clearance": "0.2 mm"})
    assert o.contact_angle == pytest.approx(c.contact_angle, rel=1e-12)
    assert o.gothic_arch_offset == pytest.approx(b.gothic_arch_offset)
    d = geometry.load_bearing("SKF6304").with_clearance(5e-6)
    assert d.diametral_clearance == 5e-6


def test_raceways_inside_the_rings() -> None:
    # d_m = 31 mm with D = 11 mm: inner raceway 19.99 mm < bore 20 mm (no inner ring left)
    with pytest.raises(InputError, match="pitch_diameter"):
        bearing_from_dict(_ball_dict(pitch_diameter="31 mm", ball_diameter="11 mm"))
    with pytest.raises(InputError, match="pitch_diameter"):
        bearing_from_dict(_ball_dict(pitch_diameter="42.6 mm"))
