"""Validity checks of solved states: skidding, ISO 76 contact stress, film parameter."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from thermobearing import load_lubricant
from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.kinematic_models import KINEMATICS
from thermobearing.operating_checks import (
    CheckLog,
    StateCheck,
    _ranges,
    check_state,
    composite_roughness,
    stress_limit,
)
from thermobearing.state import OilSupply, OperatingPoint

pytestmark = pytest.mark.filterwarnings("ignore::thermobearing.errors.ValidityWarning")


def _race_control(bearing, rpm, radial, temperature):
    lub = load_lubricant("ISO_VG32")
    op = OperatingPoint(inner_speed=rpm * math.pi / 30, radial_load=radial, axial_load=0.0)
    supply = OilSupply("jet", 1e-5, temperature)
    return KINEMATICS.get("race_control")(bearing, lub, op, contact_temperature=temperature,
                                          oil_temperature=temperature, supply=supply,
                                          guess=None, options={})


def test_ranges_text():
    assert _ranges([3]) == "step 3"
    assert _ranges([0, 1, 2, 5, 7, 8]) == "steps 0-2, 5, 7-8"


def test_check_state_reads_the_loaded_contacts():
    """p0 and Lambda are the extremes over the loaded contacts: Lambda = min h / sigma with
    sigma = (Rq_race^2 + Rq_ball^2)^(1/2) of the preset (0.1 and 0.025 um)."""
    b = load_bearing("SKF6304")
    kin = _race_control(b, 3000, 2000.0, 333.15)
    c = check_state(b, kin)
    sigma = composite_roughness(b)
    assert sigma == pytest.approx(math.hypot(0.1e-6, 0.025e-6))
    loaded = [(cs, np.asarray(cs.normal_load) > 0) for cs in kin.state.contacts]
    p0 = max(float(np.max(np.asarray(cs.max_pressure)[m])) for cs, m in loaded if m.any())
    h = min(float(np.min(np.asarray(cs.film_thickness)[m])) for cs, m in loaded if m.any())
    assert c.max_pressure == pytest.approx(p0)
    assert c.film_parameter == pytest.approx(h / sigma)
    assert c.stress_limit == 4.2e9 and stress_limit(load_bearing("NU214")) == 4.0e9
    assert c.slip == pytest.approx(kin.over_skid)


def test_summary_reports_high_stress_and_thin_film():
    """A 6304 at 12 kN radial (about 1.5 x its static rating) exceeds 4200 MPa; at
    100 r/min in ISO VG 32 at 100 degC the film is thinner than the roughness."""
    b = load_bearing("SKF6304")
    log = CheckLog("b", composite_roughness(b))
    log.record(0, check_state(b, _race_control(b, 3000, 2000.0, 333.15)))
    log.record(1, check_state(b, _race_control(b, 3000, 12000.0, 333.15)))
    log.record(2, check_state(b, _race_control(b, 100, 2000.0, 373.15)))
    lines = log.summary()
    assert len(lines) == 2, lines
    assert "ISO 76 static-rating stress 4200 MPa at 1 of 3 steps (step 1)" in lines[0]
    assert "Lambda < 1 (boundary lubrication) at 1 of 3 steps (step 2)" in lines[1]
    assert log.steps[1][0].max_pressure > 4.2e9 > log.steps[0][0].max_pressure
    assert log.steps[2][0].film_parameter < 1.0 < log.steps[0][0].film_parameter


def test_summary_skidding_and_no_roughness():
    def sc(slip):
        return StateCheck(slip, 0.4 * (1 + slip), 0.4, 1e9, 4.2e9, None)

    log = CheckLog("de", None)
    for i, s in enumerate((-0.5, -0.2, 0.01, 0.08, 0.02)):
        log.record(i, sc(s))
    log.record(1, sc(-0.01))  # a re-solve of step 1: the worst state counts
    lines = log.summary()
    assert "cage skidding (cage slower than epicyclic) by more than 5% at 2 of 5 steps " \
        "(steps 0-1); largest -50.0 % at step 0" in lines[0]
    assert "over-skidding" in lines[1] and "(step 3); largest +8.0 % at step 3" in lines[1]
    assert lines[2] == "de: film parameter Lambda not checked: the bearing gives no " \
        "raceway_roughness / element_roughness"
    assert len(lines) == 3


def test_roughness_fields_are_checked():
    b = load_bearing("SKF6304")
    with pytest.raises(InputError, match="bearing.element_roughness is missing"):
        replace(b, element_roughness=None)
    with pytest.raises(InputError, match="bearing.raceway_roughness"):
        replace(b, raceway_roughness=-1e-7)
    with pytest.raises(InputError, match="at least one"):
        replace(b, raceway_roughness=0.0, element_roughness=0.0)
    assert composite_roughness(replace(b, raceway_roughness=None, element_roughness=None)) \
        is None
