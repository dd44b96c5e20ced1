"""Envelope analysis of bearing vibration and the cage speed measured from it.

Paper 002 (Gao et al. 2022, ``../shared/seeds/002_0add79adaca5495c.txt``, section 4.2)
measures the cage speed of a QJ1044 bearing *indirectly*: the envelope spectrum of the
housing acceleration carries the cage rotation frequency (CRF) and its harmonics and
sidebands of the shaft frequency (``2 f_i - 1 CRF``, ``2 f_i + 1 CRF``), so the cage speed
ratio is ``CSR = CRF / f_i`` (their Fig. 12: 6.93 Hz at f_i = 30.2 Hz -> CSR 0.229).
Paper 004 (Luo et al. 2022, ``004_0105d7aba121b014.txt`` eq. 27) adds that the ball-pass
frequency of the outer race falls as ``(1 - s_c)``: ``BPFO = Z * f_cage``. This module
turns an acceleration record into those frequencies.

The analysis lives in modules with one job each, re-exported here (the command-facing API,
``from thermobearing.signal import X`` / ``from thermobearing import signal as S``):

* :mod:`thermobearing.signal_input`: reading files, checking records
  (:func:`load_acceleration`, :func:`check_signal`, :class:`AccelerationRecord`);
* :mod:`thermobearing.signal_kurtogram`: band selection by spectral kurtosis
  (:func:`kurtogram_bands`, :func:`kurtogram_band`);
* :mod:`thermobearing.signal_envelope`: squared-envelope spectrum and peak detection
  (:func:`envelope_spectrum`, :func:`combine_envelope_spectra`, :func:`refine_peak`,
  :func:`spectral_peak`);
* :mod:`thermobearing.signal_cage`: cage-speed estimation (:func:`estimate_cage_speed`, its
  pipeline, :func:`cage_speed_ratio`, :func:`cage_slip`);
* :mod:`thermobearing.signal_uncertainty`: standard uncertainty of a line frequency and of
  the cage frequency combined from several lines;
* :mod:`thermobearing.signal_checks`: the bearing's element count checked against the
  spectrum.

Conventions: frequencies in Hz; the cage speed ratio and the cage slip (paper 004 eq. 2) as
defined in :mod:`thermobearing.signal_cage`.
"""

from __future__ import annotations

from .signal_cage import (
    CageSpeedEstimate,
    DetectedLine,
    cage_slip,
    cage_speed_ratio,
    estimate_cage_speed,
)
from .signal_envelope import (
    EnvelopeSpectrum,
    combine_envelope_spectra,
    envelope_spectrum,
    refine_peak,
    spectral_peak,
)
from .signal_input import MIN_SAMPLES, AccelerationRecord, check_signal, load_acceleration
from .signal_kurtogram import KurtogramResult, kurtogram_band, kurtogram_bands

__all__ = [
    "AccelerationRecord",
    "MIN_SAMPLES",
    "CageSpeedEstimate",
    "DetectedLine",
    "EnvelopeSpectrum",
    "KurtogramResult",
    "cage_slip",
    "cage_speed_ratio",
    "check_signal",
    "envelope_spectrum",
    "estimate_cage_speed",
    "combine_envelope_spectra",
    "kurtogram_band",
    "kurtogram_bands",
    "load_acceleration",
    "refine_peak",
    "spectral_peak",
]
