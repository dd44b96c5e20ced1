"""Load distribution without external load at creeping speeds: rings centred, every ball
held in the outer groove by its centrifugal force alone (thermobearing.loads.centred_seat).

The catalogue 6206 at 0.5-5 r/min used to stop at a residual of about the centrifugal force
(5e-8 N at 0.5 r/min): the start put the ring at its axial touching position. These tests pin
the converged state's invariants, not a solver path."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from thermobearing import load_bearing
from thermobearing.loads import INNER, ball_arcs, ball_load_distribution

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _bearing(name: str):
    return load_bearing(str(EXAMPLES / name) if name.endswith(".toml") else name)


@pytest.mark.parametrize("name", ["catalogue_bearing_6206.toml", "spindle_7014C_catalogue.toml",
                                  "SKF6304", "QJ1044"])
@pytest.mark.parametrize("rpm", [0.5, 1.0, 2.0, 5.0, 100.0])
def test_zero_load_is_centrifugal_seat(name: str, rpm: float) -> None:
    b = _bearing(name)
    w = rpm * math.pi / 30.0
    ld = ball_load_distribution(b, 0.0, 0.0, w)
    Z = b.n_balls
    # the solver's own tolerance: 1e-9 of the load scale (1 N here) on the 2Z + 2 residuals
    assert ld.converged and ld.residual_norm <= 1e-9 * math.sqrt(2 * Z + 2)
    # no ball touches the inner ring, the ring carries nothing
    assert np.all(ld.inner_load == 0.0)
    # rings centred: no radial displacement, the inner arcs' axial centre on the outer ones'
    arcs = ball_arcs(b)
    inner = arcs.ring == INNER
    centre_out = float(np.mean(arcs.centre_x[~inner]))
    assert ld.delta_r == 0.0
    assert ld.delta_a == pytest.approx(centre_out - float(np.mean(arcs.centre_x[inner])),
                                       abs=1e-12)
    # balls on the groove's axial centre, pressed out by F_c = m omega_m^2 r_b only
    assert np.allclose(ld.ball_x, centre_out, atol=1e-12)
    fc = ld.centrifugal_force
    gam = b.ball_diameter * math.cos(b.contact_angle) / b.pitch_diameter
    wm = 0.5 * w * (1.0 - gam)
    assert np.allclose(fc, b.ball_mass * wm**2 * ld.ball_r, rtol=1e-12)
    radial = np.sum(ld.contacts.load * ld.contacts.normal_r, axis=1)   # -Q n on the ball
    # the radial balance of each ball to the residual's absolute tolerance [N]
    assert np.all(np.abs(radial - fc) <= 1e-9 * math.sqrt(2 * Z + 2))
    assert np.all(ld.outer_load > 0.0)


def test_zero_load_at_rest_touches_nothing() -> None:
    ld = ball_load_distribution(_bearing("catalogue_bearing_6206.toml"), 0.0, 0.0, 0.0)
    assert ld.converged and ld.residual_norm < 1e-12
    assert np.all(ld.inner_load == 0.0) and np.all(ld.outer_load < 1e-12)
