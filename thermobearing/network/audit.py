"""Energy audit and result containers of the network solvers.

Per step k the audit records (all in J, integrated with the quadrature weights of the
stepper's own stages, so that on a linear network the books close to round-off):

- ``generated``: integral of the heat sources sum_i q_i;
- ``stored``: sum_i C_i (T_i(t_{k+1}) - T_i(t_k));
- ``to_boundaries``: heat conducted into fixed-temperature nodes (ambient, ...);
- ``to_streams``: heat carried away by the enthalpy streams, W (T_last - T_inlet).

``imbalance = generated - stored - to_boundaries - to_streams`` is the Newton residual
left in the stage equations: round-off on a linear network, of the order of the solver
tolerance on a nonlinear one.

:meth:`EnergyAudit.relative_imbalance` divides it by the largest flow through the books,
but never by less than the audit's ``floor`` [J] (:func:`roundoff_floor`: the energy of a
temperature change of the stepper's absolute tolerance at every node). Without it a run
with no heat that starts at equilibrium divides round-off by round-off (measured
1.0-1.5 on such runs of the coupled transient with TR-BDF2 and backward Euler, and up to
1.9 on random networks with :func:`thermobearing.network.integrate`), an "imbalance"
that says nothing about the books.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError


def roundoff_floor(capacities: np.ndarray, atol: float) -> float:
    """Energy below which a run's books are the stepper's resolution, not its flows [J]:

        E_floor = atol * sum_i C_i

    with C_i the node heat capacities [J/K] and atol the stepper's absolute tolerance [K]
    (its error scale is atol + rtol |T_i| per step, so a temperature change below atol is
    not resolved; this package's choice, no paper's). Flows this small are round-off or
    tolerance-sized; an imbalance over them is no measure of the books. 0 for a network
    without capacity (the ratio then has no floor)."""
    caps = np.asarray(capacities, dtype=float)
    if not np.all(np.isfinite(caps)) or np.any(caps < 0.0):
        raise InputError("capacities", caps, "finite heat capacities >= 0 [J/K]")
    if not (math.isfinite(atol) and atol > 0.0):
        raise InputError("atol", atol, "an absolute tolerance > 0 [K]")
    return float(atol * np.sum(caps))


@dataclass(frozen=True)
class EnergyAudit:
    """Per-step energy flows [J] (arrays of length = number of steps).

    ``floor`` [J]: the smallest denominator of :meth:`relative_imbalance`
    (:func:`roundoff_floor`; 0: none)."""

    step_end_times: np.ndarray
    generated: np.ndarray
    stored: np.ndarray
    to_boundaries: np.ndarray
    to_streams: np.ndarray
    floor: float = 0.0

    @property
    def imbalance(self) -> np.ndarray:
        """generated - stored - to_boundaries - to_streams per step [J]."""
        return self.generated - self.stored - self.to_boundaries - self.to_streams

    def cumulative(self) -> dict[str, np.ndarray]:
        """Cumulative flows [J] at the step end times."""
        return {
            "generated": np.cumsum(self.generated),
            "stored": np.cumsum(self.stored),
            "to_boundaries": np.cumsum(self.to_boundaries),
            "to_streams": np.cumsum(self.to_streams),
            "imbalance": np.cumsum(self.imbalance),
        }

    def totals(self) -> dict[str, float]:
        """Run totals [J]."""
        return {k: float(v[-1]) if len(v) else 0.0 for k, v in self.cumulative().items()}

    def relative_imbalance(self) -> float:
        """max |cumulative imbalance| / max(total |flow| through the books, ``floor``) [-].

        The flows: the total |generated|, the total |to_boundaries| + |to_streams| and the
        largest |cumulative stored|. The ``floor`` (:func:`roundoff_floor`) keeps a run
        whose every flow is round-off (no heat, starting at equilibrium) near 0 instead of
        round-off over round-off; a run whose flows exceed it is unchanged."""
        scale = max(float(np.sum(np.abs(self.generated))),
                    float(np.sum(np.abs(self.to_boundaries) + np.abs(self.to_streams))),
                    float(np.max(np.abs(np.cumsum(self.stored)))) if len(self.stored) else 0.0,
                    float(self.floor), 1e-300)
        cum = np.cumsum(self.imbalance)
        return float(np.max(np.abs(cum))) / scale if len(cum) else 0.0

    @staticmethod
    def concatenate(parts: list[EnergyAudit]) -> EnergyAudit:
        """Join audits of consecutive intervals (the floor: the largest of the parts')."""
        if not parts:
            e = np.zeros(0)
            return EnergyAudit(e, e, e, e, e)
        return EnergyAudit(*(np.concatenate([getattr(p, f) for p in parts]) for f in (
            "step_end_times", "generated", "stored", "to_boundaries", "to_streams")),
            floor=max(float(p.floor) for p in parts))


@dataclass(frozen=True)
class TransientResult:
    """Result of :func:`thermobearing.network.integrate`.

    Attributes
    ----------
    names : state node names (columns of ``temperatures``).
    boundary : boundary node -> fixed temperature [K].
    times : accepted step times [s], shape (m,) (a breakpoint where zero-capacity nodes
        jump appears twice: left and right values).
    temperatures : state temperatures [K], shape (m, n).
    rates : dT/dt [K/s] at the step points (0 for zero-capacity nodes), shape (m, n).
    audit : the :class:`EnergyAudit`.
    stats : solver counters (steps, rejected, heat evaluations, Jacobians, LU factorizations).
    method : stepper name.
    dense : the stepper's own dense output, one callable piece per accepted step with
        attributes ``t0``, ``h`` (``exprb43``: the exact solution of the linearised step);
        empty for the other steppers, which :meth:`sample` interpolates (cubic Hermite).
    """

    names: tuple[str, ...]
    boundary: dict[str, float]
    times: np.ndarray
    temperatures: np.ndarray
    rates: np.ndarray
    audit: EnergyAudit
    stats: dict[str, int] = field(default_factory=dict)
    method: str = ""
    dense: tuple = ()

    def temperature(self, name: str) -> np.ndarray:
        """Temperature history [K] of node ``name`` (constant for a boundary node)."""
        if name in self.boundary:
            return np.full(len(self.times), self.boundary[name])
        try:
            i = self.names.index(name)
        except ValueError:
            from ..errors import UnknownNameError

            raise UnknownNameError("node", name, list(self.names) + list(self.boundary)) \
                from None
        return self.temperatures[:, i]

    @property
    def final(self) -> dict[str, float]:
        """Final temperature [K] per state node."""
        return {n: float(v) for n, v in zip(self.names, self.temperatures[-1], strict=True)}

    def sample(self, t: np.ndarray) -> np.ndarray:
        """Temperatures [K] at times ``t`` [s]: limited cubic Hermite within each step.

        End values and rates of the step containing t; the rates are limited as in
        Fritsch & Carlson (1980) (zero if their sign differs from the secant, scaled so
        that alpha^2 + beta^2 <= 9), so that a stiff node whose rate f/C is dominated by
        the Newton residual divided by a tiny C is interpolated monotonically instead of
        overshooting. Shape (len(t), n).
        """
        t = np.atleast_1d(np.asarray(t, dtype=float))
        ts = self.times
        lo, hi = (float(t.min()), float(t.max())) if t.size else (ts[0], ts[0])
        if not (lo >= ts[0] - 1e-9 * max(1.0, abs(ts[0]))
                and hi <= ts[-1] + 1e-9 * max(1.0, abs(ts[-1]))):  # (NaN fails too)
            from ..errors import InputError

            raise InputError("sample times", (float(t.min()), float(t.max())),
                             f"times within [{ts[0]}, {ts[-1]}]")
        if self.dense:
            return self._sample_dense(t)
        # right-most interval with ts[k] <= t < ts[k+1]; duplicates (jumps) take the right side
        k = np.searchsorted(ts, t, side="right") - 1
        k = np.clip(k, 0, len(ts) - 2)
        t0 = ts[k]
        t1 = ts[k + 1]
        h = t1 - t0
        h_safe = np.where(h > 0, h, 1.0)
        s = np.clip((t - t0) / h_safe, 0.0, 1.0)[:, None]
        y0 = self.temperatures[k]
        y1 = self.temperatures[k + 1]
        dy = y1 - y0
        d0 = self.rates[k] * h_safe[:, None]
        d1 = self.rates[k + 1] * h_safe[:, None]
        flat = dy == 0.0
        dy_safe = np.where(flat, 1.0, dy)
        a = np.where(flat, 0.0, d0 / dy_safe)
        b = np.where(flat, 0.0, d1 / dy_safe)
        a = np.maximum(a, 0.0)
        b = np.maximum(b, 0.0)
        r = np.hypot(a, b)
        lim = np.where(r > 3.0, 3.0 / np.where(r > 0, r, 1.0), 1.0)
        d0 = a * lim * dy
        d1 = b * lim * dy
        h00 = 2 * s**3 - 3 * s**2 + 1
        h10 = s**3 - 2 * s**2 + s
        h01 = -2 * s**3 + 3 * s**2
        h11 = s**3 - s**2
        out = h00 * y0 + h10 * d0 + h01 * y1 + h11 * d1
        zero_h = h <= 0
        if np.any(zero_h):
            out[zero_h] = y1[zero_h]
        return out

    def _sample_dense(self, t: np.ndarray) -> np.ndarray:
        """Sample the stepper's own dense output (a right-continuous piece at a step start)."""
        batch = getattr(type(self.dense[0]), "sample_batch", None)
        if batch is not None:  # the pieces know how to evaluate many steps at once
            return batch(self.dense, t)
        starts = np.array([p.t0 for p in self.dense])
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, len(starts) - 1)
        order = np.argsort(k, kind="stable")
        ks = k[order]
        cuts = np.flatnonzero(np.diff(ks)) + 1
        out = np.empty((len(t), self.temperatures.shape[1]))
        for lo, hi in zip(np.r_[0, cuts], np.r_[cuts, len(ks)], strict=True):
            idx = order[lo:hi]
            out[idx] = self.dense[ks[lo]](t[idx])
        return out

    def to_dataframe(self):
        """pandas DataFrame: time [s] and one '<node> temperature [K]' column per node."""
        import pandas as pd

        data = {"time [s]": self.times}
        for i, n in enumerate(self.names):
            data[f"{n} temperature [K]"] = self.temperatures[:, i]
        return pd.DataFrame(data)


@dataclass(frozen=True)
class SteadyResult:
    """Result of :func:`thermobearing.network.solve_steady`.

    Attributes
    ----------
    names : state node names.
    temperatures_vector : state temperatures [K], shape (n,).
    generated, to_boundaries, to_streams : heat rates [W] at the solution.
    iterations : Newton iterations; residual : final max |f| [W].
    """

    names: tuple[str, ...]
    temperatures_vector: np.ndarray
    generated: float
    to_boundaries: float
    to_streams: float
    iterations: int
    residual: float

    @property
    def temperatures(self) -> dict[str, float]:
        """Temperature [K] per state node."""
        return {n: float(v) for n, v in zip(self.names, self.temperatures_vector, strict=True)}
