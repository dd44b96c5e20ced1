"""Shared fixtures of the skidding/load-distribution tests (owner G)."""

from __future__ import annotations

import math

import numpy as np

from thermobearing.geometry import BallBearing, CageGeometry
from thermobearing.materials import BRASS, STEEL_52100


def qj_like(**changes) -> BallBearing:
    """A 220 x 340 x 56 four-point bearing close to QJ1044 (test geometry, values estimated:
    D = 34.925 mm (1 3/8 in), Z = 21, d_m = 280 mm, f = 0.53, shim angle 35 deg, P_d = 0.15 mm)."""
    kw = dict(
        name="QJ_test", kind="four_point", bore=0.220, outer_diameter=0.340, width=0.056,
        ball_diameter=0.034925, n_balls=21, pitch_diameter=0.280, inner_conformity=0.53,
        outer_conformity=0.53, contact_angle=math.radians(35.0), diametral_clearance=0.15e-3,
        ball_material=STEEL_52100, ring_material=STEEL_52100,
        cage=CageGeometry(guidance="outer_ring", width=0.045, inner_diameter=0.262,
                          outer_diameter=0.300, pocket_clearance=0.6e-3,
                          guide_land_diameter=0.302, guide_clearance=1.0e-3, land_width=0.012,
                          material=BRASS),
        source="test geometry")
    kw.update(changes)
    return BallBearing(**kw)




def simple_models(bearing, *, oil_fraction=0.05, pocket_friction=0.1, mu_limit=0.07,
                  temperature=323.15):
    """Force models with explicit physics for tests: Eyring/limiting-shear traction of ISO VG68,
    Hamrock-Dowson film, paper 002 eq. 10 drag with C_d = 0.45 of an oil/air mix of the given
    oil volume fraction, Petroff cage-land torque (paper 002 eq. 5, epsilon = 0)."""
    import warnings

    from thermobearing.film import hamrock_dowson_1977_central
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.ball import BallModels
    from thermobearing.traction import make_traction_law

    lub = load_lubricant("ISO_VG68")
    eta = float(lub.dynamic_viscosity(temperature))
    alpha = float(lub.pressure_viscosity_coefficient(temperature))
    rho = float(lub.density(temperature))
    law = make_traction_law("eyring_limiting_shear", lubricant=lub,
                            limiting_shear_coefficient=mu_limit, eyring_stress=5e6, cap="smooth")
    E = bearing.effective_modulus

    def film(u, Q, rx, ry):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            h = hamrock_dowson_1977_central(np.maximum(u, 1e-3), eta, alpha, np.maximum(Q, 1e-3),
                                            rx, ry, effective_modulus=E)
        return np.maximum(h, 1e-9)

    area = math.pi * bearing.ball_diameter**2 / 4

    def drag(u):
        return 0.5 * 0.45 * rho * oil_fraction * area * u * u

    cage = bearing.cage

    def cage_torque(wc):
        return (math.pi * eta * cage.guide_land_diameter**3 * wc * cage.land_width
                / (2 * cage.guide_clearance))

    return BallModels(traction_law=law, pocket_friction=pocket_friction, ball_drag=drag,
                      cage_torque=cage_torque, film_thickness=film, temperature=temperature)
