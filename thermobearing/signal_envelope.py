"""Squared-envelope spectrum of a vibration band and sub-bin peak detection in it.

One job: demodulate a band of an acceleration record into its squared-envelope spectrum
with a local noise floor (:func:`envelope_spectrum`, Randall & Antoni 2011), pool the
spectra of several bands (:func:`combine_envelope_spectra`), and locate spectral lines to a
fraction of a bin (:func:`refine_peak`, :func:`spectral_peak`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import stats

from .errors import InputError
from .signal_input import check_signal
from .signal_kurtogram import kurtogram_band


@dataclass(frozen=True)
class EnvelopeSpectrum:
    """Squared-envelope spectrum of one band.

    Attributes
    ----------
    frequency : [Hz] (zero-padded grid, spacing ``resolution / padding``).
    power : |FFT|^2 of the Hann-windowed squared envelope [(signal unit)^4].
    noise_floor : local mean noise power on the same grid (median / ln 2).
    band : demodulation band (low, high) [Hz].
    resolution : native resolution 1 / T [Hz]; padding : zero-padding factor.
    band_kurtosis : spectral kurtosis of the band when chosen by the kurtogram, else NaN.
    bands : all bands pooled (see :func:`combine_envelope_spectra`), else empty.
    """

    frequency: np.ndarray
    power: np.ndarray
    noise_floor: np.ndarray
    band: tuple[float, float]
    resolution: float
    padding: int
    band_kurtosis: float = math.nan
    bands: tuple[tuple[float, float], ...] = ()

    @property
    def normalised(self) -> np.ndarray:
        """Power over the local noise mean (Exp(1) distributed for noise bins)."""
        return self.power / self.noise_floor

    @property
    def amplitude(self) -> np.ndarray:
        """Square root of the power, for plotting."""
        return np.sqrt(self.power)


def _check_padding(padding: int) -> None:
    if isinstance(padding, bool) or not isinstance(padding, int | np.integer) or padding < 1:
        raise InputError("padding", padding, "a whole zero-padding factor >= 1")


def envelope_spectrum(x, sampling_rate: float, band: tuple[float, float] | None = None, *,
                      max_frequency: float | None = None, padding: int = 8,
                      min_band_frequency: float = 0.0,
                      min_bandwidth: float = 0.0) -> EnvelopeSpectrum:
    """Squared-envelope spectrum of ``x`` in ``band``.

    The band [Hz] is cut from the FFT of ``x``; negative frequencies are dropped (the
    analytic signal, i.e. the Hilbert transform), the band is shifted to base band and
    transformed back at a reduced rate of at least twice the band width (the squared
    envelope ``|z|^2`` has at most that bandwidth, so nothing aliases). The squared
    envelope minus its mean is Hann windowed and zero padded ``padding`` times.
    ``band=None`` picks it with :func:`kurtogram_band` above ``min_band_frequency`` [Hz]
    and at least ``min_bandwidth`` [Hz] wide.
    ``max_frequency`` [Hz] limits the returned grid (default: the envelope Nyquist).

    Reference: Randall RB, Antoni J (2011) Rolling element bearing diagnostics - a tutorial.
    MSSP 25: 485-520 (squared envelope, section 3.3).
    """
    fs = float(sampling_rate)
    arr = check_signal(x, fs)
    _check_padding(padding)
    nyq = fs / 2
    sk = math.nan
    if band is None:
        kg = kurtogram_band(arr, fs, min_frequency=min_band_frequency,
                            min_bandwidth=min_bandwidth)
        band, sk = kg.band, kg.kurtosis
    lo, hi = float(band[0]), float(band[1])
    if not (math.isfinite(lo) and math.isfinite(hi)) or lo < 0 or hi <= lo:
        raise InputError("band", band, "(low, high) in Hz with 0 <= low < high")
    if hi > nyq:
        raise InputError("band", band, f"a band below the Nyquist frequency {nyq:g} Hz")
    n = arr.size
    # the squared envelope's spectrum holds x^4: computed at unit peak and scaled back (a
    # record peaking beyond about 1e+-75 overflowed to inf / underflowed to 0, and its
    # normalised spectrum was NaN without a word)
    peak = float(np.max(np.abs(arr)))
    spec = np.fft.rfft((arr - arr.mean()) / peak)
    df = fs / n
    k_lo = int(math.ceil(lo / df))
    k_hi = int(math.floor(hi / df))
    if k_hi - k_lo < 2:
        raise InputError("band", band, f"a band wider than 2 bins ({2 * df:g} Hz)")
    nb = k_hi - k_lo + 1
    m = 1
    while m < 2 * nb + 2:
        m *= 2
    base = np.zeros(m, dtype=complex)
    base[:nb] = spec[k_lo:k_hi + 1]
    z = np.fft.ifft(base) * (2.0 * m / n)          # complex envelope at rate fs*m/n
    env2 = np.abs(z) ** 2
    env2 -= env2.mean()
    win = np.hanning(m)
    nfft = padding * m
    p = np.abs(np.fft.rfft(env2 * win, nfft)) ** 2
    freq = np.arange(p.size) * (fs / n) * (m / nfft)
    if max_frequency is not None:
        keep = freq <= max_frequency
        freq, p = freq[keep], p[keep]
    floor = _noise_floor(p, block=max(16, 32 * padding))
    if peak != 1.0:
        with np.errstate(over="ignore", under="ignore"):
            gain = float(np.float64(peak) ** 4)
            p, floor = p * gain, floor * gain
        if not (math.isfinite(gain) and gain > 0.0 and np.all(np.isfinite(floor))
                and np.all(floor > 0.0)):
            raise InputError("signal", f"a record peaking at {peak:.3g}",
                             "a record whose fourth power is representable (peak within "
                             "about 1e-75 .. 1e75 in its unit): the envelope power is in "
                             "unit^4; rescale the record (estimate_cage_speed does so itself)")
    return EnvelopeSpectrum(freq, p, floor, (lo, hi), df, padding, sk)


def combine_envelope_spectra(spectra: list[EnvelopeSpectrum]) -> EnvelopeSpectrum:
    """Pool the envelope spectra of disjoint bands (same record, same grid).

    The mean R of the N normalised spectra is, for noise bins of disjoint bands, Gamma(N, 1/N)
    distributed; it is mapped to the equivalent Exp(1) statistic -ln P(Gamma > R) so that the
    returned ``normalised`` has the single-band meaning. ``power`` holds the mean normalised
    power (for peak interpolation).
    """
    if len(spectra) == 1:
        return spectra[0]
    n = len(spectra)
    ref = spectra[0]
    for es in spectra[1:]:
        if es.frequency.size != ref.frequency.size:
            raise InputError("spectra", "different grids", "spectra of one record")
    mean = np.mean([es.normalised for es in spectra], axis=0)
    xg = n * mean
    with np.errstate(divide="ignore", over="ignore"):
        r_eq = -stats.gamma.logsf(xg, n)
    # far tail: -ln Q(n, x) -> x - (n - 1) ln x + ln Gamma(n)
    tail = xg - (n - 1) * np.log(np.maximum(xg, 1e-300)) + math.lgamma(n)
    r_eq = np.where(np.isfinite(r_eq), r_eq, tail)
    floor = np.where(r_eq > 1e-12, mean / np.maximum(r_eq, 1e-12), 1.0)
    floor = np.where(floor > 0, floor, 1.0)
    return EnvelopeSpectrum(ref.frequency, mean, floor, ref.band, ref.resolution, ref.padding,
                            ref.band_kurtosis, tuple(es.band for es in spectra))


def _noise_floor(p: np.ndarray, block: int) -> np.ndarray:
    """Local mean noise power: block medians / ln 2, interpolated (robust to lines)."""
    nblk = max(1, p.size // block)
    edges = np.linspace(0, p.size, nblk + 1).astype(int)
    meds = np.array([np.median(p[a:b]) for a, b in zip(edges[:-1], edges[1:], strict=True)])
    centres = 0.5 * (edges[:-1] + edges[1:])
    floor = np.interp(np.arange(p.size), centres, meds) / math.log(2.0)
    return np.maximum(floor, np.max(floor) * 1e-12 + 1e-300)


def refine_peak(es: EnvelopeSpectrum, frequency: float, half_width: float
                ) -> tuple[float, float]:
    """Sub-bin peak near ``frequency`` [Hz]: (frequency [Hz], normalised power).

    Finds the largest bin of the zero-padded spectrum within ``+- half_width`` [Hz] and
    fits a parabola through the log powers of it and its two neighbours (Gaussian
    interpolation; for a Hann window padded 8x its bias is far below 1e-3 bin). When the
    window holds no local maximum (only the flank of a line outside it) the frequency is
    NaN and the normalised power is capped at 1 (no evidence).
    """
    f = es.frequency
    step = f[1] - f[0]
    i0 = max(1, int(math.floor((frequency - half_width) / step)))
    i1 = min(f.size - 2, int(math.ceil((frequency + half_width) / step)))
    if i1 < i0:
        return math.nan, 0.0
    seg = es.power[i0:i1 + 1]
    i = i0 + int(np.argmax(seg))
    if es.power[i] < es.power[i - 1] or es.power[i] < es.power[i + 1]:
        # no local maximum inside the window: the slope of a line outside it
        j = min(max(int(round(frequency / step)), 0), f.size - 1)
        return math.nan, float(min(es.normalised[j], 1.0))
    a, b, c = (math.log(max(es.power[j], 1e-300)) for j in (i - 1, i, i + 1))
    den = a - 2 * b + c
    delta = 0.5 * (a - c) / den if den < 0 else 0.0
    delta = max(-0.5, min(0.5, delta))
    return float(f[i] + delta * step), float(es.normalised[i])


def spectral_peak(x, sampling_rate: float, low: float, high: float, *, padding: int = 8
                  ) -> tuple[float, float]:
    """Largest line of the raw spectrum in [low, high] Hz: (frequency [Hz], amplitude).

    Hann window, zero padding ``padding`` times, Gaussian (log-parabolic) interpolation of
    the peak bin and its neighbours (sub-bin). The amplitude is that of the peak bin,
    corrected for the window gain (a sine of amplitude A reads about A).
    """
    fs = float(sampling_rate)
    arr = check_signal(x, fs)
    if not (0 <= low < high <= fs / 2):
        raise InputError("range", (low, high), f"0 <= low < high <= Nyquist ({fs / 2:g} Hz)")
    _check_padding(padding)
    w = np.hanning(arr.size)
    nfft = padding * arr.size
    amp = np.abs(np.fft.rfft((arr - arr.mean()) * w, nfft)) * 2.0 / w.sum()
    step = fs / nfft
    i0, i1 = max(1, int(math.ceil(low / step))), min(amp.size - 2, int(high / step))
    if i1 <= i0:
        raise InputError("range", (low, high), f"wider than one bin ({fs / arr.size:g} Hz)")
    i = i0 + int(np.argmax(amp[i0:i1 + 1]))
    a, b, c = (math.log(max(amp[j], 1e-300)) for j in (i - 1, i, i + 1))
    den = a - 2 * b + c
    delta = max(-0.5, min(0.5, 0.5 * (a - c) / den)) if den < 0 else 0.0
    return float((i + delta) * step), float(amp[i])
