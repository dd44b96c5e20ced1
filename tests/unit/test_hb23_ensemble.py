"""Ensemble statistics of validation rows from chaotic runs (thermobearing.validation.ensemble):
mean and standard error of one point, the first-order standard error of a ratio of means of
independent and of paired (same trajectories) quantities, hand-checked."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermobearing.errors import InputError
from thermobearing.validation.ensemble import PointEnsemble, delta_method


def test_mean_and_standard_error_of_one_point():
    # samples 1, 2, 3, 4: mean 2.5, s^2 = (2.25 + 0.25 + 0.25 + 2.25) / 3 = 5/3, SE = s / 2
    p = PointEnsemble({"x": np.array([1.0, 2.0, 3.0, 4.0])})
    assert p.size == 4
    assert p.mean()["x"] == pytest.approx(2.5, rel=1e-15)
    assert p.stderr("x") == pytest.approx(math.sqrt(5.0 / 3.0) / 2.0, rel=1e-14)


def test_ratio_of_means_of_two_independent_points():
    # a = 2, 4 (mean 3, s^2 = 2, SE^2 = 1); b = 1, 3 (mean 2, SE^2 = 1)
    # R = 1.5, SE(R)^2 = R^2 (1/9 + 1/4) = 0.8125
    a = PointEnsemble({"v": np.array([2.0, 4.0])})
    b = PointEnsemble({"v": np.array([1.0, 3.0])})
    value, se = delta_method(lambda p: p[0]["v"] / p[1]["v"], [a, b])
    assert value == pytest.approx(1.5, rel=1e-15)
    assert se == pytest.approx(math.sqrt(0.8125), rel=1e-8)


def test_ratio_of_paired_means_takes_their_covariance():
    # one point, a = 1, 2, 3 and b = 3, 1, 2 from the same trajectories: means 2 / 2,
    # var 1 / 1, cov(a, b) = (-1 * 1 + 0 * -1 + 1 * 0) / 2 = -0.5; over K = 3:
    # SE(R)^2 = 1 * (1/3 / 4 + 1/3 / 4 - 2 * (-0.5 / 3) / 4) = 0.25
    p = PointEnsemble({"a": np.array([1.0, 2.0, 3.0]), "b": np.array([3.0, 1.0, 2.0])})
    value, se = delta_method(lambda q: q[0]["a"] / q[0]["b"], [p])
    assert value == pytest.approx(1.0, rel=1e-15)
    assert se == pytest.approx(0.5, rel=1e-8)
    # proportional samples (a = 2 b on every trajectory): the ratio has no scatter
    q = PointEnsemble({"a": np.array([2.0, 4.0, 6.0]), "b": np.array([1.0, 2.0, 3.0])})
    value, se = delta_method(lambda r: r[0]["a"] / r[0]["b"], [q])
    assert value == pytest.approx(2.0, rel=1e-15)
    assert se < 1e-6 * value


def test_a_deterministic_point_adds_no_variance_and_one_trajectory_gives_no_error():
    chaotic = PointEnsemble({"v": np.array([3.2, 3.3, 3.4])})
    steady = PointEnsemble({"v": np.array([3.0])}, deterministic=True)
    value, se = delta_method(lambda p: p[0]["v"] / p[1]["v"], [chaotic, steady])
    assert value == pytest.approx(1.1, rel=1e-14)
    # SE(3.3) = 0.1 / sqrt(3), divided by the deterministic 3.0
    assert se == pytest.approx(0.1 / math.sqrt(3.0) / 3.0, rel=1e-8)
    single = PointEnsemble({"v": np.array([3.3])})
    value, se = delta_method(lambda p: p[0]["v"] / p[1]["v"], [single, steady])
    assert value == pytest.approx(1.1, rel=1e-14)
    assert math.isnan(se)
    assert math.isnan(single.stderr("v"))


def test_a_point_the_row_does_not_use_is_not_needed():
    # a sweep's middle point with one finished trajectory does not void the end-to-end
    # ratio's standard error
    ends = [PointEnsemble({"v": np.array([2.0, 4.0])}), PointEnsemble({"v": np.array([1.0, 3.0])})]
    middle = PointEnsemble({"v": np.array([7.0])})
    value, se = delta_method(lambda p: p[0]["v"] / p[2]["v"], [ends[0], middle, ends[1]])
    assert value == pytest.approx(1.5, rel=1e-15)
    assert se == pytest.approx(math.sqrt(0.8125), rel=1e-8)


def test_a_point_without_trajectories_gives_no_value():
    empty = PointEnsemble({"v": np.array([])})
    other = PointEnsemble({"v": np.array([1.0, 2.0])})
    value, se = delta_method(lambda p: p[0]["v"] / p[1]["v"], [empty, other])
    assert math.isnan(value)
    assert math.isnan(se)


def test_bad_ensembles_are_refused_naming_the_field():
    with pytest.raises(InputError, match=r"PointEnsemble\.samples"):
        PointEnsemble({"a": np.array([1.0, 2.0]), "b": np.array([1.0])})
    with pytest.raises(InputError, match=r"PointEnsemble\.deterministic"):
        PointEnsemble({"a": np.array([1.0, 2.0])}, deterministic=True)
