"""Result type, statistics and spectrum of the lumped vibration model.

One job: what a run of :func:`thermobearing.vibration.simulate` returns
(:class:`VibrationResult`) and the indicators computed from a record: peak-to-peak, RMS and
kurtosis (:func:`statistics`, :class:`VibrationStatistics`) and the Hann-windowed amplitude
spectrum (:func:`amplitude_spectrum`).

Sources: Luo et al. 2022 (seed paper 004) section 4.3 and Table 2 (PTP, RMS, kurtosis),
eq. 27 (BPFO); Pearson's kurtosis; Hann window with amplitude correction (Harris 1978,
Proc. IEEE 66: 51). Split out of ``vibration.py`` (names re-exported there). Units: SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from .errors import InputError
from .vibration_params import VibrationParameters

__all__ = ["VibrationResult", "VibrationStatistics", "amplitude_spectrum", "statistics"]


# ---------------------------------------------------------------------------
# results and statistics
# ---------------------------------------------------------------------------
class VibrationStatistics(NamedTuple):
    """Statistical indicators of an acceleration record (paper 004 section 4.3)."""

    ptp: float  #: peak-to-peak [m/s^2]
    rms: float  #: root mean square [m/s^2]
    kurtosis: float  #: Pearson kurtosis [-] (3 for Gaussian)


def statistics(acceleration: Any) -> VibrationStatistics:
    """Peak-to-peak, RMS and kurtosis of a record (paper 004 section 4.3, Table 2).

    PTP = max - min; RMS = sqrt(mean(a^2)) (about zero, as a vibration level);
    kurtosis = mean((a - mean)^4) / var^2 (Pearson's, 3 for a Gaussian signal).
    ``acceleration``: a 1-D record of samples [m/s^2], e.g. a
    :class:`~thermobearing.vibration.VibrationResult`'s ``acceleration_x`` (whose statistics
    the result carries as ``statistics_x``).
    """
    try:
        a = np.asarray(acceleration, dtype=float)
    except (TypeError, ValueError):  # a VibrationResult, a string...: say what is expected
        raise InputError("acceleration", type(acceleration).__name__,
                         "a 1-D record of samples [m/s^2] (of a VibrationResult: its "
                         "acceleration_x; its statistics_x holds these statistics)") from None
    if a.ndim != 1 or a.size < 4 or not np.all(np.isfinite(a)):
        raise InputError("acceleration", f"shape {a.shape}", "a finite 1-D record")
    d = a - a.mean()
    var = float(np.mean(d * d))
    if var <= 0.0:
        raise InputError("acceleration", "a constant record", "a varying record")
    return VibrationStatistics(float(a.max() - a.min()), float(np.sqrt(np.mean(a * a))),
                               float(np.mean(d**4) / var**2))


def amplitude_spectrum(x: Any, sampling_rate: float) -> tuple[np.ndarray, np.ndarray]:
    """One-sided amplitude spectrum (Hann window, amplitude-corrected): (f [Hz], |A|)."""
    a = np.asarray(x, dtype=float)
    a = a - a.mean()
    w = np.hanning(a.size)
    spec = np.abs(np.fft.rfft(a * w)) * 2.0 / w.sum()
    return np.fft.rfftfreq(a.size, 1.0 / sampling_rate), spec


@dataclass(frozen=True)
class VibrationResult:
    """Time series of one simulation (after the settling time).

    Attributes
    ----------
    time : [s] (from the start of the simulation). sampling_rate : output rate [Hz].
    acceleration_x, acceleration_y : inner-ring acceleration [m/s^2] (x along the load).
    displacement_x, displacement_y : inner-ring displacement [m].
    first_ball_inner_load, first_ball_inner_friction : Q_in and F_in of ball 1 [N].
    shaft_speed, cage_speed : [rad/s]; cage_slip : s_c [-].
    method, step : integrator and its step [s]; rhs_evaluations; wall_time [s].
    parameters : the :class:`VibrationParameters`.
    """

    time: np.ndarray
    sampling_rate: float
    acceleration_x: np.ndarray
    acceleration_y: np.ndarray
    displacement_x: np.ndarray
    displacement_y: np.ndarray
    first_ball_inner_load: np.ndarray
    first_ball_inner_friction: np.ndarray
    shaft_speed: float
    cage_speed: float
    cage_slip: float
    radial_load: float
    method: str
    step: float
    rhs_evaluations: int
    wall_time: float
    parameters: VibrationParameters = field(repr=False)

    @property
    def statistics_x(self) -> VibrationStatistics:
        """PTP, RMS, kurtosis of the x acceleration (paper 004 Table 2)."""
        return statistics(self.acceleration_x)

    @property
    def ball_pass_frequency_outer(self) -> float:
        """Z omega_c / 2 pi [Hz] of this run (paper 004 eq. 27)."""
        return self.parameters.n_balls * self.cage_speed / (2.0 * math.pi)

    def spectrum(self, component: str = "x") -> tuple[np.ndarray, np.ndarray]:
        """Amplitude spectrum of the ring acceleration ("x" or "y")."""
        a = self.acceleration_x if component == "x" else self.acceleration_y
        return amplitude_spectrum(a, self.sampling_rate)
