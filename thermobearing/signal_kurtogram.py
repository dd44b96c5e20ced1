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
    # SK is scale-free, its fourth moments are not representable beyond |x| ~ 1e+-75:
    # analysed at unit peak (a record peaking at 1e80 or 1e-90 had every SK NaN)
    arr = arr / float(np.max(np.abs(arr)))
    cells: list[tuple[float, float, float, int, int]] = []
    table = []
    nyq = fs / 2
    # cell edges in whole units of fs / L (L: the window lengths' least common multiple):
    # whether two cells overlap or only touch is decided exactly (in Hz, adjacent cells of
    # two window lengths overlapped by an ulp at some sampling rates and not at others)
    unit = math.lcm(*(int(w) for w in window_lengths))
    for nw in window_lengths:
        if nw * 8 > arr.size or 2 * fs / nw < min_bandwidth:
            continue
        f, m2, m4 = _stft_moments(arr, fs, nw)
        with np.errstate(divide="ignore", invalid="ignore"):
            sk = np.where(m2 > 0, m4 / np.maximum(m2, 1e-300) ** 2 - 2.0, 0.0)
        table.append((f, sk))
        half = fs / nw
        # the cell of bin k spans bins k - 1 .. k + 1: inside (0, Nyquist] in whole bins
        # (k > 1, 2 (k + 1) <= nw), exact whatever fs is (in Hz, the top cell's edge
        # (k + 1) fs / nw = fs / 2 came out a few ulp above or below Nyquist with fs)
        k = np.arange(f.size)
        ok = (f - half >= min_frequency) & (2 * (k + 1) <= nw) & (k > 1)
        per = unit // int(nw)
        cells += [(float(sk[i]), float(f[i]), 2 * half, (int(i) - 1) * per, (int(i) + 1) * per)
                  for i in np.flatnonzero(ok)]
    if not cells:
        raise InputError("band", f"min_frequency {min_frequency:g} Hz, min_bandwidth "
                         f"{min_bandwidth:g} Hz",
                         f"room for such a band below Nyquist ({nyq:g} Hz)")
    cells.sort(key=lambda c: -c[0])
    chosen: list[KurtogramResult] = []
    taken: list[tuple[int, int]] = []
    for sk_c, centre, bw, lo_u, hi_u in cells:
        if any(lo_u < b and hi_u > a for a, b in taken):
            continue
        taken.append((lo_u, hi_u))
        lo, hi = centre - bw / 2, centre + bw / 2
        chosen.append(KurtogramResult((lo, hi), centre, bw, sk_c,
                                      tuple(int(w) for w in window_lengths), tuple(table)))
        if len(chosen) == n_bands:
            break
    return chosen


#: STFT values held at once by :func:`_stft_moments` (complex: 16 bytes each)
_CHUNK_VALUES = 1 << 22


def _stft_moments(arr: np.ndarray, fs: float, nw: int
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Frequencies [Hz] and the frame means of |X|^2 and |X|^4 of the Hann STFT with
    ``nw`` samples per frame and hop ``nw / 4`` (frames wholly inside the record, no
    detrending: ``scipy.signal.stft(..., boundary=None, padded=False, detrend=False)``),
    accumulated over chunks of frames so that the memory stays bounded for long records
    (a 60 s, 51.2 kHz record held 0.55 GB of STFT at once before). The scaling of the
    window does not matter: SK is a ratio of moments."""
    hop = nw - 3 * nw // 4
    win = sps.get_window("hann", nw)
    n_frames = (arr.size - nw) // hop + 1
    per = max(1, _CHUNK_VALUES // (nw // 2 + 1))
    s2 = np.zeros(nw // 2 + 1)
    s4 = np.zeros(nw // 2 + 1)
    for k0 in range(0, n_frames, per):
        k1 = min(n_frames, k0 + per)
        seg = arr[k0 * hop:(k1 - 1) * hop + nw]
        frames = np.lib.stride_tricks.sliding_window_view(seg, nw)[::hop]
        p2 = np.abs(np.fft.rfft(frames * win, axis=1)) ** 2
        s2 += p2.sum(axis=0)
        s4 += (p2 * p2).sum(axis=0)
    return np.fft.rfftfreq(nw, 1.0 / fs), s2 / n_frames, s4 / n_frames


def kurtogram_band(x, sampling_rate: float, *, min_frequency: float = 0.0,
                   min_bandwidth: float = 0.0,
                   window_lengths: tuple[int, ...] = (8, 16, 32, 64, 128, 256, 512),
                   ) -> KurtogramResult:
    """The cell of largest spectral kurtosis (see :func:`kurtogram_bands`)."""
    return kurtogram_bands(x, sampling_rate, 1, min_frequency=min_frequency,
                           min_bandwidth=min_bandwidth, window_lengths=window_lengths)[0]
