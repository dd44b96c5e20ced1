"""Tests of the paper 002 helpers (clearance variant, Fig. 10 plot, calibration file I/O)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.geometry import load_bearing
from thermobearing.skidding.qj1044 import (
    CSRCurve,
    load_calibration,
    plot_csr_vs_axial_load,
    with_clearance,
)


def test_with_clearance_keeps_the_free_contact_angle():
    b = load_bearing("QJ1044")
    for pd in (0.05e-3, 0.2e-3, 0.3e-3):
        b2 = with_clearance(b, pd)
        assert math.isclose(b2.free_contact_angle, b.free_contact_angle, abs_tol=1e-9)
        assert b2.shim_angle() < b.free_contact_angle
    # more clearance -> smaller shim angle (the outer angle floor of three-point contact)
    assert with_clearance(b, 0.3e-3).shim_angle() < with_clearance(b, 0.1e-3).shim_angle()
    with pytest.raises(InputError):
        with_clearance(b, 50e-3)


def test_plot_writes_png(tmp_path):
    fa = np.array([0.0, 2e3, 10e3, 36e3])
    th = np.full(4, 0.452)
    c = CSRCurve(1800 * math.pi / 30, 33 / 60000, fa, np.array([0.22, 0.5, 0.47, 0.452]), th,
                 th, np.ones(4, int), np.ones(4), np.ones(4, bool))
    p = plot_csr_vs_axial_load([c], tmp_path / "fig10.png", measured={"paper": ([0, 1e3],
                                                                                 [0.22, 0.501])})
    assert p.exists() and p.stat().st_size > 10_000
    assert np.allclose(c.over_skid, [0.22 / 0.452 - 1, 0.5 / 0.452 - 1, 0.47 / 0.452 - 1, 0])


def test_missing_calibration_file_is_an_input_error(tmp_path):
    with pytest.raises(InputError):
        load_calibration(tmp_path / "nope.toml")
