"""Demodulation-band selection by the STFT spectral kurtosis (kurtogram).

One job: find the frequency bands where a vibration record is most impulsive
(:func:`kurtogram_bands`, :func:`kurtogram_band`), after Antoni & Randall (2006), for the
envelope spectrum of :mod:`thermobearing.signal_envelope`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import signal as sps

from .errors import InputError
from .signal_input import check_signal


@dataclass(frozen=True)
class KurtogramResult:
    """Demodulation band chosen by the STFT spectral kurtosis.

    Attributes
    ----------
    band : (low, high) [Hz].
    centre : [Hz]; bandwidth : [Hz].
    kurtosis : spectral kurtosis of the chosen cell (0 for Gaussian noise).
    window_lengths : STFT window lengths tried [samples].
    table : SK per (window length, frequency bin) as a tuple of (freqs [Hz], sk) pairs.
    """

    band: tuple[float, float]
    centre: float
    bandwidth: float
    kurtosis: float
    window_lengths: tuple[int, ...]
    table: tuple[tuple[np.ndarray, np.ndarray], ...] = field(repr=False, default=())


def kurtogram_bands(x, sampling_rate: float, n_bands: int = 1, *,
                    min_frequency: float = 0.0, min_bandwidth: float = 0.0,
                    window_lengths: tuple[int, ...] = (8, 16, 32, 64, 128, 256, 512),
                    ) -> list[KurtogramResult]:
    """The ``n_bands`` non-overlapping cells of largest spectral kurtosis (STFT kurtogram).

    ``SK(f) = <|X(t,f)|^4> / <|X(t,f)|^2>^2 - 2`` over STFT frames (Antoni & Randall 2006,
    eq. 2, for complex Gaussian noise SK = 0; impulsive resonances give SK > 0). Every
    window length ``N_w`` gives cells of width ``2 fs / N_w`` (the Hann main lobe) centred
    on the STFT bins; the cells are ranked by SK and taken greedily when they overlap none
    already taken. Only cells whose low edge is above ``min_frequency`` [Hz], whose width is
    at least ``min_bandwidth`` [Hz] (the envelope spectrum of a band of width B reaches B)
    and whose high edge is below Nyquist count.

    Reference: Antoni J, Randall RB (2006) The spectral kurtosis: application to the vibratory
    surveillance and diagnostics of rotating machines. MSSP 20: 308-331.
    """
    fs = float(sampling_rate)
    arr = check_signal(x, fs)
    if isinstance(n_bands, bool) or not isinstance(n_bands, int | np.integer) or n_bands < 1:
        raise InputError("n_bands", n_bands, "a whole number of bands >= 1")
    for name, v in (("min_frequency", min_frequency), ("min_bandwidth", min_bandwidth)):
        if not (math.isfinite(float(v)) and v >= 0):
            raise InputError(name, v, "a finite frequency >= 0 Hz")
    arr = arr - arr.mean()
    cells: list[tuple[float, float, float]] = []
    table = []
    nyq = fs / 2
    for nw in window_lengths:
        if nw * 8 > arr.size or 2 * fs / nw < min_bandwidth:
            continue
        f, _, z = sps.stft(arr, fs=fs, window="hann", nperseg=nw, noverlap=3 * nw // 4,
                           boundary=None, padded=False, detrend=False)
        p2 = np.abs(z) ** 2
        m2 = p2.mean(axis=1)
        m4 = (p2**2).mean(axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            sk = np.where(m2 > 0, m4 / np.maximum(m2, 1e-300) ** 2 - 2.0, 0.0)
        table.append((f, sk))
        half = fs / nw
        ok = (f - half >= min_frequency) & (f + half <= nyq) & (f - half > 0)
        cells += [(float(sk[i]), float(f[i]), 2 * half) for i in np.flatnonzero(ok)]
    if not cells:
        raise InputError("band", f"min_frequency {min_frequency:g} Hz, min_bandwidth "
                         f"{min_bandwidth:g} Hz",
                         f"room for such a band below Nyquist ({nyq:g} Hz)")
    cells.sort(key=lambda c: -c[0])
    chosen: list[KurtogramResult] = []
    for sk_c, centre, bw in cells:
        lo, hi = centre - bw / 2, centre + bw / 2
        if any(lo < k.band[1] and hi > k.band[0] for k in chosen):
            continue
        chosen.append(KurtogramResult((lo, hi), centre, bw, sk_c,
                                      tuple(int(w) for w in window_lengths), tuple(table)))
        if len(chosen) == n_bands:
            break
    return chosen


def kurtogram_band(x, sampling_rate: float, *, min_frequency: float = 0.0,
                   min_bandwidth: float = 0.0,
                   window_lengths: tuple[int, ...] = (8, 16, 32, 64, 128, 256, 512),
                   ) -> KurtogramResult:
    """The cell of largest spectral kurtosis (see :func:`kurtogram_bands`)."""
    return kurtogram_bands(x, sampling_rate, 1, min_frequency=min_frequency,
                           min_bandwidth=min_bandwidth, window_lengths=window_lengths)[0]
