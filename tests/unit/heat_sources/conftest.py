"""Shared fixtures of the heat-source tests: the QJ1044 of paper 002 and an ISO VG46 oil."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermobearing.errors import ValidityWarning
from thermobearing.heat_sources import HeatContext
from thermobearing.state import KinematicState, OilSupply, OperatingPoint

RPM = math.pi / 30.0


@pytest.fixture(scope="session")
def qj1044():
    from thermobearing.geometry import load_bearing

    return load_bearing("QJ1044")


@pytest.fixture(scope="session")
def vg46():
    from thermobearing.lubricant import load_lubricant

    return load_lubricant("ISO_VG46")


@pytest.fixture(scope="session")
def race_control_state(qj1044, vg46):
    op = OperatingPoint(inner_speed=1800 * RPM, radial_load=1000.0, axial_load=20000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        ks = KinematicState.from_race_control(qj1044, op, lubricant=vg46, temperature=318.15)
    return op, ks


def make_context(bearing, oil, op, ks, *, flow=33.0, traction=None, options=None,
                 temperature=318.15, method="jet", level=None):
    supply = OilSupply(method, flow / 6.0e4, 308.15, level)
    return HeatContext.isothermal(temperature, bearing=bearing, lubricant=oil, supply=supply,
                                  operating=op, kinematics=ks, traction=traction,
                                  options=options or {})


def uniform_state(z, *, cage_speed=80.0, orbital=None, spin=-500.0, pocket_force=0.0,
                  contacts=()):
    return KinematicState(inner_speed=188.5, outer_speed=0.0, cage_speed=cage_speed,
                          orbital_speed=np.full(z, cage_speed) if orbital is None else orbital,
                          element_spin=spin, contacts=contacts,
                          pocket_normal_force=pocket_force)
