"""Ensemble statistics of validation rows computed from chaotic simulations.

A point whose motion is chaotic (paper 003's rib rattle with an unbalance) gives a different
time mean on every trajectory; one trajectory's value is one draw. A point is therefore run
as an ensemble of K trajectories (:class:`PointEnsemble`: K values per quantity) and a
validation row -- a function f of the points' quantities, e.g. a ratio of two points' PV --
is f evaluated at the ensemble *means* (a ratio of means, not a mean of ratios), with the
first-order (delta-method) standard error

    SE(f)^2 = g^T C g,   g = df/dmu at the means,   C = block-diag(C_p),
    C_p = cov(samples of point p, ddof = 1) / K_p,

the covariance of point p's sample means (the quantities of one point come from the same
trajectories and are correlated, e.g. the left and right end-face PV; different points are
independent runs). For a ratio of means R = a/b this is the textbook result
SE(R)^2 = R^2 [SE(a)^2/a^2 + SE(b)^2/b^2 - 2 cov(a, b)/(K a b)] (e.g. Kendall & Stuart,
"The advanced theory of statistics", vol. 1, ratio estimator, first-order term). A
deterministic point (no chaos: one run is its value, measured in the case's SOURCE.md)
contributes no variance; a chaotic point with fewer than two finished trajectories gives
an unknown (NaN) standard error. The gradient is taken by central differences of f.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError

#: relative step of the central differences of the delta method (f is smooth in the means)
GRADIENT_STEP = 1e-6


@dataclass(frozen=True)
class PointEnsemble:
    """The finished trajectories of one operating point.

    ``samples``: quantity -> (K,) values, one per trajectory (same order in every quantity);
    ``deterministic``: True for a point without chaotic motion (its one run is its value,
    no scatter; the caller states where that was measured).
    """

    samples: Mapping[str, np.ndarray] = field(default_factory=dict)
    deterministic: bool = False

    def __post_init__(self) -> None:
        sizes = {k: np.asarray(v, float).shape for k, v in self.samples.items()}
        if len({s for s in sizes.values()}) > 1 or any(len(s) != 1 for s in sizes.values()):
            raise InputError("PointEnsemble.samples", sizes,
                             "one (K,) array per quantity, the same K for all")
        if self.deterministic and self.size > 1:
            raise InputError("PointEnsemble.deterministic", self.size,
                             "one run for a deterministic point")

    @property
    def size(self) -> int:
        """K, the number of finished trajectories (0 for a point that did not run)."""
        return next((len(np.atleast_1d(v)) for v in self.samples.values()), 0)

    def mean(self) -> dict[str, float]:
        """Ensemble mean of every quantity (NaN for a point without trajectories)."""
        return {k: (float(np.mean(v)) if self.size else math.nan)
                for k, v in self.samples.items()}

    def stderr(self, quantity: str) -> float:
        """Standard error of the ensemble mean of ``quantity``: s / sqrt(K), s the sample
        standard deviation (ddof = 1); 0 for a deterministic point, NaN with K < 2."""
        return float(math.sqrt(self.mean_covariance([quantity])[0, 0]))

    def mean_covariance(self, quantities: Sequence[str]) -> np.ndarray:
        """Covariance matrix of the ensemble means of ``quantities``: cov(samples, ddof=1)/K
        (zeros for a deterministic point, NaN with K < 2)."""
        q = len(quantities)
        if self.deterministic:
            return np.zeros((q, q))
        k = self.size
        if k < 2:
            return np.full((q, q), math.nan)
        x = np.array([np.asarray(self.samples[name], float) for name in quantities])
        return np.atleast_2d(np.cov(x, ddof=1)) / k


def delta_method(f: Callable[[Sequence[Mapping[str, float]]], float],
                 points: Sequence[PointEnsemble]) -> tuple[float, float]:
    """(f at the points' ensemble means, its first-order standard error) -- module notes.

    ``f`` takes one mapping of quantity -> mean per point (in the order of ``points``) and
    returns the row's value. NaN value when a point it needs has no finished trajectory;
    NaN standard error when a chaotic point it depends on has fewer than two (a point f does
    not depend on, zero gradient, is not needed).
    """
    means = [p.mean() for p in points]
    value = float(f(means))
    if not math.isfinite(value):
        return value, math.nan
    var = 0.0
    for i, p in enumerate(points):
        if p.deterministic:
            continue
        names = list(means[i])
        cov = p.mean_covariance(names)
        scale = np.sqrt(np.where(np.isfinite(np.diag(cov)), np.diag(cov), 0.0))
        grad = np.zeros(len(names))
        for j, name in enumerate(names):
            mu = means[i][name]
            h = GRADIENT_STEP * max(abs(mu), float(scale[j]), 1e-300)
            hi = [dict(m) for m in means]
            lo = [dict(m) for m in means]
            hi[i][name] = mu + h
            lo[i][name] = mu - h
            grad[j] = (float(f(hi)) - float(f(lo))) / (2.0 * h)
        if not np.any(grad):
            continue  # f does not depend on this point
        if not np.all(np.isfinite(cov[np.ix_(grad != 0, grad != 0)])):
            return value, math.nan
        var += float(grad @ np.where(np.isfinite(cov), cov, 0.0) @ grad)
    return value, math.sqrt(max(var, 0.0))
