"""Whirl of a squeeze-film-damper-mounted roller bearing (paper 000 eqs. 1-4).

The outer ring (and with it the bearing centre) moves on a circle of radius ``e`` at the
whirl frequency ``omega_w`` (paper 000, Li et al. 2018, sec. 2.1):

    e_x = e cos(omega_w t),   e_y = e sin(omega_w t)                       (1)-(2)
    e_x'' = -e omega_w^2 cos(omega_w t),  e_y'' = -e omega_w^2 sin(omega_w t)  (3)-(4)

In the frame that translates with the outer ring every roller feels the d'Alembert force
``-m_r e''``: its radial part changes the contact loads (eqs. 20/23), its tangential part
enters the orbital balance and the pocket force (eqs. 21/24); summed over the equally
spaced rollers the tangential parts cancel in the cage equation (eq. 32), so the whirl acts
on the cage speed through the contact loads. Eqs. 20/23 as printed put the same e_y''
(eq. 4) in every roller's radial balance; :attr:`Whirl.radial_inertia` ``"in_phase"``
follows that reading (not the kinematics of a translating whirl; see the attribute). By
default the roller azimuths are frozen (paper 000); optionally they advance with the cage
(:attr:`Whirl.cage_rotation`). At each sample the Z + 1 equations are solved
quasi-statically (paper 000: Newton-Raphson), warm-started from the previous sample; the
result is a time series of cage speed and slip with the min / max / mean / fluctuation
(max - min) of paper 000 Tables 2-3.

References: paper 000 [li2018_nu214_skidding] sec. 2.1 and 3.1; its whirl-skidding
predecessor Li & Chen 2014 [li_chen2014_whirl_skidding].
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_positive
from .roller import RollerModel, RollerSkiddingResult, solve_model

#: readings of the whirl inertia in the rollers' radial balance (see :class:`Whirl`)
RADIAL_INERTIA_MODELS = ("projected", "in_phase")


@dataclass(frozen=True)
class Whirl:
    """Circular whirl orbit of the bearing centre.

    Attributes
    ----------
    radius : e [m] (>= 0).
    frequency : omega_w [rad/s]; None: synchronous with the shaft (paper 000: "the whirling
        frequency is relevant to the shaft speed").
    n_samples : samples per whirl period [-].
    periods : number of whirl periods simulated [-] (statistics over all of them).
    cage_phase : initial azimuth of roller 0 [rad] (0: a roller under the load).
    radial_inertia : how the whirl acceleration enters each roller's radial balance (eqs.
        20/23). ``"projected"`` (default, the kinematics of a translating bearing centre):
        roller j feels -m_r a_w . e_j, its own projection, so the rollers opposite each
        other are pushed out and in by turns and the first-order effect on the cage cancels
        except through the load asymmetry. ``"in_phase"``: eqs. 20/23 (and 26/29) as
        printed, m_r e_y'' with the e_y'' of eq. 4 in every roller's radial balance, the
        same for all rollers (the paper "considered the example of a roller" on the orbit,
        sec. 2.1): a breathing of the centrifugal load of all rollers together; this is not
        the kinematics of a translating whirl. The tangential balance (eqs. 21/24) always
        uses the projection, whose parts cancel in eq. 32 (read in phase too, the cage
        would feel Z m_r e omega_w^2 = 4 N at e = 6e-5 m and fluctuate by ~250 r/min, 45
        times paper 000 Table 2).
    cage_rotation : False (default, as paper 000): the roller azimuths stay at
        ``cage_phase + 2 pi j / Z`` and only the whirl inertia varies in time. True: the
        rollers advance with the cage, so the load zone also changes as rollers pass under
        the load (with clearance only 1-3 rollers carry the load, and the quasi-static cage
        speed then jumps at the roller-pass frequency, which the cage inertia would filter:
        not a quasi-static effect).
    """

    radius: float
    frequency: float | None = None
    n_samples: int = 72
    periods: float = 1.0
    cage_phase: float = 0.0
    cage_rotation: bool = False
    radial_inertia: str = "projected"

    def __post_init__(self) -> None:
        check_positive("whirl.radius", self.radius, allow_zero=True)
        if self.radial_inertia not in RADIAL_INERTIA_MODELS:
            raise InputError("whirl.radial_inertia", self.radial_inertia,
                             RADIAL_INERTIA_MODELS)
        if self.frequency is not None:
            check_positive("whirl.frequency", self.frequency)
        if int(self.n_samples) != self.n_samples or self.n_samples < 2:
            raise InputError("whirl.n_samples", self.n_samples, "an integer >= 2")
        check_positive("whirl.periods", self.periods)
        if int(round(self.n_samples * self.periods)) < 1:
            raise InputError("whirl.periods", self.periods,
                             f"at least one sample: periods > {0.5 / self.n_samples:.6g} "
                             f"with n_samples = {self.n_samples} (the solve runs "
                             f"round(n_samples * periods) samples)")

    def acceleration(self, t: float, omega_w: float) -> tuple[float, float]:
        """Bearing-centre acceleration (e_x'', e_y'') [m/s^2] at time t [s] (eqs. 3-4)."""
        f = -self.radius * omega_w**2
        return f * math.cos(omega_w * t), f * math.sin(omega_w * t)

    def position(self, t: float, omega_w: float) -> tuple[float, float]:
        """Bearing-centre position (e_x, e_y) [m] (eqs. 1-2)."""
        return self.radius * math.cos(omega_w * t), self.radius * math.sin(omega_w * t)


@dataclass(frozen=True)
class SeriesStats:
    """Minimum, maximum, mean and fluctuation (max - min) of a time series."""

    minimum: float
    maximum: float
    mean: float
    fluctuation: float

    @classmethod
    def of(cls, values: np.ndarray, weights: np.ndarray | None = None) -> SeriesStats:
        v = np.asarray(values, dtype=float)
        mean = float(np.clip(np.average(v, weights=weights), v.min(), v.max()))
        return cls(float(v.min()), float(v.max()), mean, float(v.max() - v.min()))


@dataclass(frozen=True)
class WhirlResult:
    """Time series of a whirling roller bearing (SI; paper 000 Tables 2-3, Fig. 4).

    Attributes
    ----------
    times : (N,) [s].  cage_speed : (N,) omega_c [rad/s].  slip : (N,) s_f [-].
    cage_speed_ratio : (N,) [-].  theoretical_cage_speed_ratio : [-].
    states : the N quasi-static :class:`RollerSkiddingResult`.
    cage_speed_stats, slip_stats : :class:`SeriesStats` ([rad/s], [-]).
    converged : all samples converged.  residual_norm : largest residual norm [-].
    whirl : the :class:`Whirl`; whirl_frequency [rad/s].
    """

    times: np.ndarray
    cage_speed: np.ndarray
    slip: np.ndarray
    cage_speed_ratio: np.ndarray
    theoretical_cage_speed_ratio: float
    states: tuple[RollerSkiddingResult, ...]
    cage_speed_stats: SeriesStats
    slip_stats: SeriesStats
    converged: bool
    residual_norm: float
    whirl: Whirl
    whirl_frequency: float

    @property
    def mean_cage_speed_ratio(self) -> float:
        """Time-mean cage speed ratio [-]."""
        return float(np.mean(self.cage_speed_ratio))

    @property
    def cage_speed_ratio_mean(self) -> float:
        """Alias of :attr:`mean_cage_speed_ratio`."""
        return self.mean_cage_speed_ratio

    @property
    def kinematic_states(self) -> tuple:
        """The :class:`thermobearing.state.KinematicState` of every sample (heat sources)."""
        return tuple(s.kinematic_state for s in self.states)

    @property
    def roller_speed(self) -> np.ndarray:
        """(N, Z) roller spin speeds [rad/s]."""
        return np.array([s.roller_speed for s in self.states])

    @property
    def inner_sliding_speed(self) -> np.ndarray:
        """(N, Z) inner-contact sliding speeds [m/s]."""
        return np.array([s.inner_sliding_speed for s in self.states])

    @property
    def outer_sliding_speed(self) -> np.ndarray:
        """(N, Z) outer-contact sliding speeds [m/s]."""
        return np.array([s.outer_sliding_speed for s in self.states])


def solve_whirl(model: RollerModel, omega: float, radial_load: float, whirl: Whirl, *,
                x0: np.ndarray | None = None, tol: float = 1e-9,
                max_iter: int = 60) -> WhirlResult:
    """Quasi-static skidding along the whirl orbit, warm-started sample to sample.

    Parameters
    ----------
    model : prepared :class:`~thermobearing.skidding.roller.RollerModel`.
    omega : inner-ring speed [rad/s].  radial_load : F_r [N].
    whirl : :class:`Whirl`.  x0 : warm start for the first sample.

    Returns
    -------
    WhirlResult
    """
    omega_w = omega if whirl.frequency is None else whirl.frequency
    z = model.n_rollers
    n = int(round(whirl.n_samples * whirl.periods))
    dt = 2.0 * math.pi / omega_w / whirl.n_samples
    base = 2.0 * math.pi * np.arange(z) / z
    phase = whirl.cage_phase
    states = []
    times = []
    x = x0
    ring = None
    for k in range(n):
        t = k * dt
        acc = whirl.acceleration(t, omega_w)
        # in_phase: e_y'' of eq. 4 in every roller's radial balance (eqs. 20/23 as printed)
        radial = np.full(z, acc[1]) if whirl.radial_inertia == "in_phase" else None
        res = solve_model(model, omega, radial_load, azimuth=base + phase,
                          whirl_acceleration=acc, x0=x, tol=tol, max_iter=max_iter,
                          load_x0=ring, radial_acceleration=radial)
        states.append(res)
        times.append(t)
        x = np.append(res.roller_speed, res.cage_speed)
        ring = tuple(float(v) for v in res.extras["ring_displacement"])
        if whirl.cage_rotation:
            phase = (phase + res.cage_speed * dt) % (2.0 * math.pi)
    wc = np.array([s.cage_speed for s in states])
    slip = np.array([s.slip for s in states])
    return WhirlResult(
        times=np.array(times), cage_speed=wc, slip=slip, cage_speed_ratio=wc / omega,
        theoretical_cage_speed_ratio=model.theoretical_cage_speed_ratio,
        states=tuple(states), cage_speed_stats=SeriesStats.of(wc),
        slip_stats=SeriesStats.of(slip), converged=all(s.converged for s in states),
        residual_norm=max(s.residual_norm for s in states), whirl=whirl,
        whirl_frequency=omega_w,
    )
