"""Operating points the kinematics models meet through the API (session 22): a bearing
turning backwards, or with its outer ring driven (OperatingPoint.outer_speed).

Race control takes any ring speeds (its heat is the mirror image's:
test_prop22_heat_sources.py). The skidding model solves the inner ring driven forward
only; for the other points it says so, naming the operating field (it passed the
inner-ring speed on and the solvers refused it as 'speed = 0.0 is not allowed: a value > 0'
for an outer ring driven at 300 rad/s, without naming outer_speed).
"""

from __future__ import annotations

import warnings

import pytest

from thermobearing import load_bearing, load_lubricant
from thermobearing.errors import InputError
from thermobearing.kinematic_models import race_control, skidding
from thermobearing.state import OilSupply, OperatingPoint

POINTS = [(300.0, 0.0), (-300.0, 0.0), (0.0, 300.0), (0.0, -300.0), (300.0, 100.0)]


def _race_control(name, wi, wo):
    b, oil = load_bearing(name), load_lubricant("ISO_VG46")
    op = OperatingPoint(inner_speed=wi, outer_speed=wo, radial_load=2000.0,
                        axial_load=300.0 if name == "SKF6304" else 0.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return race_control(b, oil, op, contact_temperature=330.0, oil_temperature=325.0,
                            supply=OilSupply("jet", 1e-4, 320.0))


@pytest.mark.parametrize("name", ["SKF6304", "NU214"])
@pytest.mark.parametrize(("wi", "wo"), POINTS)
def test_race_control_takes_any_ring_speeds(name, wi, wo):
    """The cage turns between the rings at the state's ratio of their difference, the
    same ratio as the mirror image's (both speeds negated)."""
    k = _race_control(name, wi, wo)
    csr = k.cage_speed_ratio
    assert 0.0 < csr < 1.0
    assert k.state.cage_speed == pytest.approx(wo + csr * (wi - wo), rel=1e-9, abs=1e-12)
    mirror = _race_control(name, -wi, -wo)
    assert mirror.cage_speed_ratio == pytest.approx(csr, rel=1e-12)
    assert mirror.state.cage_speed == pytest.approx(-k.state.cage_speed, rel=1e-12)


@pytest.mark.parametrize("name", ["SKF6304", "NU214"])
def test_skidding_with_the_outer_ring_driven_names_the_outer_speed(name):
    b, oil = load_bearing(name), load_lubricant("ISO_VG46")
    op = OperatingPoint(inner_speed=0.0, outer_speed=300.0, radial_load=2000.0,
                        axial_load=300.0 if name == "SKF6304" else 0.0)
    with pytest.raises(InputError, match="outer_speed"):
        skidding(b, oil, op, contact_temperature=330.0, oil_temperature=325.0,
                 supply=OilSupply("jet", 1e-4, 320.0))
