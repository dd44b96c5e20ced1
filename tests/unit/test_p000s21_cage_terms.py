"""Paper 000 cage equation split into each roller's forces (skidding/roller_diagnostics.py,
``cage_force_terms``; Li et al. 2018 eqs. 27-28/30-32, seed ``000_3b5ca6eed61dd596.txt``).

With every roller in moment balance the outer shear drops out of the cage equation: each
roller's term is 2 S_i + s_i Q_xi - s_o Q_xo - (1 + D/d_m) f_d + body forces. The tests pin
that bookkeeping against the solver's own residual (dry load zone and film-supported ring of
the paper 000 case) and the sign structure of the NU214 light-load state (inner shear drives,
outer rolling force and pocket friction hold back)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model, solve_model
from thermobearing.skidding.roller_diagnostics import cage_force_balance, cage_force_terms

OMEGA = 5000.0 * math.pi / 30.0  # paper 000: n_i = 5000 r/min
CASE = {"limiting_shear_coefficient": 1.0, "film_pressure": "regime_min",
        "pocket_film": "two_faces"}


@pytest.fixture(scope="module", params=["contacts", "films"])
def model(request):
    return build_model(load_bearing("NU214"), load_lubricant("PAPER000_OIL"), 313.15,
                       viscosity=0.08, ring_support=request.param, **CASE)


def test_terms_add_up_to_the_cage_equation_at_a_prescribed_speed(model):
    wc = 1233.7 * math.pi / 30.0  # paper 000 Table 2, 150 N
    t = cage_force_terms(model, OMEGA, 150.0, wc)
    bal = cage_force_balance(model, OMEGA, 150.0, wc)
    scale = float(np.sum(np.abs(t.outer_pressure)))
    assert scale > 1.0
    assert float(np.sum(t.cage_terms)) == pytest.approx(bal.residual, abs=1e-9 * scale)
    # rollers in moment balance, and the reduced form equals the cage terms
    assert np.max(np.abs(t.moment_imbalance)) < 1e-8 * scale
    np.testing.assert_allclose(t.reduced, t.cage_terms + t.moment_imbalance,
                               rtol=0.0, atol=1e-12 * scale)
    # shear = Couette - Poiseuille along the entrainment (inner and outer)
    np.testing.assert_allclose(t.inner_shear, t.inner_couette - t.inner_poiseuille,
                               atol=1e-12 * scale)
    loaded = t.inner_load > 0.0
    assert np.all(t.inner_couette[loaded] > 0.0) and np.all(t.inner_pressure[~loaded] == 0.0)
    assert np.all(t.outer_pressure > 0.0) and np.all(t.pocket_friction > 0.0)


def test_at_the_solved_speed_the_terms_balance(model):
    res = solve_model(model, OMEGA, 150.0)
    t = cage_force_terms(model, OMEGA, 150.0, res.cage_speed)
    drive = float(np.sum(2.0 * t.inner_shear + t.inner_pressure))
    hold = float(np.sum(t.outer_pressure + t.pocket_friction))
    assert drive > 0.0 and hold > 0.0
    assert float(np.sum(t.reduced)) == pytest.approx(0.0, abs=1e-6 * hold)
