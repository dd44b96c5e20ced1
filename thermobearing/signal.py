"""Envelope analysis of bearing vibration and the cage speed measured from it.

Paper 002 (Gao et al. 2022, ``../shared/seeds/002_0add79adaca5495c.txt``, section 4.2)
measures the cage speed of a QJ1044 bearing *indirectly*: the envelope spectrum of the
housing acceleration carries the cage rotation frequency (CRF) and its harmonics and
sidebands of the shaft frequency (``2 f_i - 1 CRF``, ``2 f_i + 1 CRF``), so the cage speed
ratio is ``CSR = CRF / f_i`` (their Fig. 12: 6.93 Hz at f_i = 30.2 Hz -> CSR 0.229).
Paper 004 (Luo et al. 2022, ``004_0105d7aba121b014.txt`` eq. 27) adds that the ball-pass
frequency of the outer race falls as ``(1 - s_c)``: ``BPFO = Z * f_cage``. This module
turns an acceleration record into those frequencies.

Pipeline (:func:`estimate_cage_speed`)
--------------------------------------
1. checks: finite, non-constant, 1-D, long enough, a rate high enough for the band.
2. demodulation band: given, or chosen by the STFT spectral kurtosis (the kurtogram of
   Antoni & Randall 2006): the disjoint cells of largest SK, whose envelope spectra are
   pooled (a single band's envelope can miss a harmonic that another band carries).
3. squared envelope of the band (analytic signal by FFT, shifted to base band so that the
   envelope is computed at a reduced rate), Hann window, zero padding.
4. a harmonic-comb search over candidate cage frequencies: the comb holds the cage
   harmonics ``k f_c``, the ball-pass harmonics ``m Z f_c``, the cage modulation sidebands
   of the ball pass ``(Z -+ 1) f_c`` and the shaft sidebands
   ``n f_s +- f_c``; each line's power is normalised by the local noise floor (median of the
   spectrum, which for noise bins is exponentially distributed: mean = median / ln 2); the
   comb score is the weighted mean of log(1 + normalised power) over its teeth (primary
   teeth, the cage fundamental and ball-pass harmonics, weigh 1, the others 0.5), so that a
   candidate
   needs several lines (a sub-multiple of the cage frequency that catches only the strong
   ball-pass line scores low).
5. the best comb, corrected for octave errors (``2 f_c`` has a comb that is a subset of the
   true one, ``f_c / 2`` a superset: a move is made only when the teeth that one comb has
   and the other lacks hold a line above the noise), is refined: each
   line's frequency by Gaussian (log-parabolic) interpolation of the zero-padded Hann
   spectrum (sub-bin), then ``f_c`` by weighted least squares over the detected lines.
6. confidence: Fisher's combination of the per-line false-alarm probabilities, Bonferroni
   corrected for the number of independent candidates searched; ``detected`` only when
   the family-wise false-alarm probability is below ``alpha``, at least two lines stand
   above the per-line threshold, at least half of them agree with the estimate within half
   a bin, a fundamental (the ball-pass fundamental ``Z f_c`` or the cage line ``f_c``)
   is among them, and at least one strong line is away from every shaft harmonic ``m f_s``
   (a comb sitting only on shaft harmonics is a once-per-revolution signal). Otherwise the result is
   flagged not detected and carries no frequency (never a made-up one).

Conventions: frequencies in Hz, cage speed ratio ``CSR = f_cage / f_shaft`` (outer ring
fixed), cage slip ``s_c = 1 - CSR / CSR_th`` (paper 004 eq. 2; negative = over-skidding).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import signal as sps
from scipy import stats

from .errors import InputError

__all__ = [
    "AccelerationRecord",
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

#: minimum number of samples an analysis accepts.
MIN_SAMPLES = 256


# ---------------------------------------------------------------------------
# input
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class AccelerationRecord:
    """A uniformly sampled acceleration record.

    Attributes
    ----------
    data : samples [m/s^2] (or any consistent unit: the analysis is scale-free).
    sampling_rate : [Hz].
    source : file name or description.
    """

    data: np.ndarray
    sampling_rate: float
    source: str = ""

    @property
    def duration(self) -> float:
        """Record length [s]."""
        return self.data.size / self.sampling_rate


def check_signal(x, sampling_rate: float, field: str = "signal") -> np.ndarray:
    """Validate a record and return it as a 1-D float array.

    Raises :class:`InputError` for a non-1-D array, fewer than ``MIN_SAMPLES`` samples,
    NaN/inf samples, a constant signal or a non-positive sampling rate [Hz].
    """
    if not (isinstance(sampling_rate, int | float | np.floating | np.integer)
            and math.isfinite(float(sampling_rate)) and float(sampling_rate) > 0):
        raise InputError(f"{field}.sampling_rate", sampling_rate, "a finite rate > 0 Hz")
    arr = np.asarray(x, dtype=float)
    if arr.ndim != 1:
        raise InputError(f"{field}.shape", arr.shape, "a one-dimensional record")
    if arr.size < MIN_SAMPLES:
        raise InputError(f"{field}.length", arr.size, f"at least {MIN_SAMPLES} samples")
    bad = ~np.isfinite(arr)
    if bad.any():
        raise InputError(f"{field}", f"{int(bad.sum())} NaN/inf samples (first at index "
                         f"{int(np.argmax(bad))})", "finite samples only")
    spread = float(np.ptp(arr))
    scale = max(float(np.max(np.abs(arr))), 1e-300)
    if spread <= 1e-12 * scale or spread == 0.0:
        raise InputError(f"{field}", "a constant signal", "a signal that varies in time")
    return arr


def load_acceleration(path: str | Path, sampling_rate: float | None = None,
                      column: int | str | None = None) -> AccelerationRecord:
    """Read an acceleration record from ``.npy``, ``.npz`` or ``.csv``.

    Parameters
    ----------
    path : file. ``.npy``: a 1-D array (``sampling_rate`` required). ``.npz``: arrays
        ``acceleration`` (or ``data``/``x``) and ``sampling_rate`` (or ``fs``).
        ``.csv``: one column of samples (``sampling_rate`` required) or a time column
        [s] first and the samples second (the rate is (n - 1) / time span; every step must
        be within half a step of the mean, i.e. no gaps); a non-numeric first row is a
        header.
    sampling_rate : [Hz]; overrides nothing: if the file carries a rate that differs by
        more than 1e-4 relative, that is an error.
    column : CSV column (index or header name) holding the samples.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("file", str(p), "an existing .npy, .npz or .csv file")
    suffix = p.suffix.lower()
    file_rate: float | None = None
    if suffix == ".npy":
        data = np.load(p, allow_pickle=False)
    elif suffix == ".npz":
        with np.load(p, allow_pickle=False) as z:
            key = next((k for k in ("acceleration", "data", "x") if k in z), None)
            if key is None:
                raise InputError("file", str(p), "an .npz with an 'acceleration' array")
            data = z[key]
            rk = next((k for k in ("sampling_rate", "fs") if k in z), None)
            file_rate = float(z[rk]) if rk else None
    elif suffix in (".csv", ".txt"):
        data, file_rate = _read_csv(p, column)
    else:
        raise InputError("file", str(p), "a .npy, .npz or .csv file")
    if file_rate is not None and sampling_rate is not None:
        if abs(file_rate - sampling_rate) > 1e-4 * sampling_rate:
            raise InputError("sampling_rate", sampling_rate,
                             f"the rate of the file ({file_rate:g} Hz) or none")
    rate = sampling_rate if sampling_rate is not None else file_rate
    if rate is None:
        raise InputError("sampling_rate", None,
                         "a sampling rate in Hz (the file carries no time column)")
    arr = check_signal(np.ravel(data) if np.ndim(data) == 2 and 1 in np.shape(data) else data,
                       float(rate), field=p.name)
    return AccelerationRecord(arr, float(rate), str(p))


def _read_csv(p: Path, column: int | str | None) -> tuple[np.ndarray, float | None]:
    with p.open(newline="", encoding="utf-8") as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    if not rows:
        raise InputError("file", str(p), "a CSV with at least one row of numbers")
    header = None
    try:
        [float(c) for c in rows[0]]
    except ValueError:
        header = [c.strip() for c in rows[0]]
        rows = rows[1:]
    try:
        table = np.array([[float(c) for c in r] for r in rows], dtype=float)
    except ValueError as exc:
        raise InputError("file", str(p), f"numeric CSV rows ({exc})") from None
    if table.ndim != 2 or table.shape[0] == 0:
        raise InputError("file", str(p), "a CSV with rows of equal length")
    ncol = table.shape[1]
    if column is not None:
        if isinstance(column, str):
            if header is None or column not in header:
                raise InputError("column", column, f"one of the header names {header}")
            idx = header.index(column)
        else:
            idx = int(column)
            if not 0 <= idx < ncol:
                raise InputError("column", column, f"an index in [0, {ncol - 1}]")
        samples = table[:, idx]
    else:
        samples = table[:, 0] if ncol == 1 else table[:, 1]
    rate = None
    if ncol >= 2 and (column is None or column != 0):
        t = table[:, 0]
        dt = np.diff(t)
        if dt.size and np.all(dt > 0):
            # rate from the span (robust to the print precision of the time column); steps
            # that deviate by more than half a step mean missing or irregular samples
            mean_dt = float(t[-1] - t[0]) / dt.size
            if np.max(np.abs(dt - mean_dt)) > 0.5 * mean_dt:
                raise InputError("file time column", "non-uniform time steps",
                                 "uniform sampling (no gaps)")
            rate = 1.0 / mean_dt
    return samples, rate


# ---------------------------------------------------------------------------
# kurtogram (band selection)
# ---------------------------------------------------------------------------
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


# ---------------------------------------------------------------------------
# envelope spectrum
# ---------------------------------------------------------------------------
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
    spec = np.fft.rfft(arr - arr.mean())
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
    return EnvelopeSpectrum(freq, p, floor, (lo, hi), df, padding, sk)


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


# ---------------------------------------------------------------------------
# cage speed
# ---------------------------------------------------------------------------
def cage_speed_ratio(cage_frequency, shaft_frequency):
    """Cage speed ratio ``CSR = f_cage / f_shaft`` (paper 002 section 4.2), both [Hz]."""
    cage = np.asarray(cage_frequency, dtype=float)
    shaft = np.asarray(shaft_frequency, dtype=float)
    if np.any(~np.isfinite(shaft)) or np.any(shaft <= 0):
        raise InputError("shaft_frequency", shaft_frequency, "a finite frequency > 0 Hz")
    if np.any(~np.isfinite(cage)) or np.any(cage < 0):
        raise InputError("cage_frequency", cage_frequency, "a finite frequency >= 0 Hz")
    out = cage / shaft
    return float(out) if out.ndim == 0 else out


def cage_slip(csr, csr_theoretical):
    """Cage slip ``s_c = 1 - CSR / CSR_th`` [-] (paper 004 eq. 2; < 0 is over-skidding)."""
    th = np.asarray(csr_theoretical, dtype=float)
    if np.any(~np.isfinite(th)) or np.any(th <= 0):
        raise InputError("csr_theoretical", csr_theoretical, "a finite ratio > 0")
    out = 1.0 - np.asarray(csr, dtype=float) / th
    return float(out) if out.ndim == 0 else out


@dataclass(frozen=True)
class DetectedLine:
    """One spectral line of the comb.

    kind : "cage" (k f_c), "ball_pass" (m Z f_c), "ball_pass_sideband" ((Z -+ 1) f_c),
        "sideband" (n f_s + k f_c) or "shaft".
    order : (k, n): multiple of the cage and of the shaft frequency in the line.
    expected : [Hz] from the final estimate; measured : [Hz] sub-bin peak (NaN if weak).
    snr : normalised power (power / local noise mean); detected : snr above threshold.
    """

    kind: str
    order: tuple[int, int]
    expected: float
    measured: float
    snr: float
    detected: bool


@dataclass(frozen=True)
class CageSpeedEstimate:
    """Cage speed measured from a vibration record.

    Attributes
    ----------
    detected : a significant, consistent comb was found. When False, ``cage_frequency``,
        ``csr``, ``slip`` and ``ball_pass_frequency`` are None and ``reason`` says why.
    cage_frequency : [Hz]; csr : cage speed ratio [-]; slip : 1 - CSR/CSR_th [-].
    ball_pass_frequency : Z f_cage [Hz] (BPFO, outer ring fixed).
    shaft_frequency : the shaft frequency used [Hz]; measured_shaft_frequency : sub-bin
        shaft line of the envelope spectrum when significant [Hz], else None.
    csr_theoretical : [-]; confidence : 1 - family-wise false-alarm probability, times the
        fraction of detected lines consistent with the estimate (0 without a fundamental line,
        with fewer than two lines or with all strong lines on shaft harmonics);
        false_alarm_probability.
    lines : the comb lines; spectrum : the envelope spectrum analysed.
    """

    detected: bool
    cage_frequency: float | None
    csr: float | None
    slip: float | None
    ball_pass_frequency: float | None
    shaft_frequency: float
    measured_shaft_frequency: float | None
    csr_theoretical: float
    confidence: float
    false_alarm_probability: float
    consistency: float
    lines: tuple[DetectedLine, ...]
    spectrum: EnvelopeSpectrum = field(repr=False)
    reason: str = ""


def _comb(n_balls: int, cage_h: int, bp_h: int, shaft_h: int) -> list[tuple[str, int, int]]:
    lines = [("cage", k, 0) for k in range(1, cage_h + 1)]
    lines += [("ball_pass", m * n_balls, 0) for m in range(1, bp_h + 1)]
    if n_balls > 2 * cage_h:  # cage modulation of the ball pass: (Z -+ 1) f_c
        lines += [("ball_pass_sideband", n_balls - 1, 0), ("ball_pass_sideband", n_balls + 1, 0)]
    for n in range(1, shaft_h + 1):
        lines += [("sideband", 1, n), ("sideband", -1, n)]
    return lines


def estimate_cage_speed(x, sampling_rate: float, shaft_frequency: float, n_balls: int,
                        csr_theoretical: float, *, band: tuple[float, float] | None = None,
                        search: tuple[float, float] = (0.3, 1.3), cage_harmonics: int = 3,
                        ball_pass_harmonics: int = 3, shaft_sidebands: int = 2,
                        alpha: float = 1e-3, padding: int = 8,
                        n_bands: int = 3) -> CageSpeedEstimate:
    """Cage frequency, CSR and slip from an acceleration record.

    Parameters
    ----------
    x : acceleration samples; sampling_rate : [Hz].
    shaft_frequency : inner-ring rotation frequency [Hz] (tachometer / rpm / 60).
    n_balls : number of rolling elements Z.
    csr_theoretical : pure-rolling cage speed ratio (1 - D cos(alpha)/d_m)/2 [-].
    band : demodulation band [Hz] or None for the kurtogram.
    n_bands : with ``band=None``, the number of disjoint kurtogram cells (largest SK first)
        whose envelope spectra are pooled (:func:`combine_envelope_spectra`).
    search : the cage frequency is sought in ``search * csr_theoretical * shaft_frequency``
        (default: slip from -30 % to +70 %).
    cage_harmonics, ball_pass_harmonics, shaft_sidebands : size of the comb.
    alpha : family-wise false-alarm probability below which the comb counts as detected.

    Raises
    ------
    InputError : bad record (NaN, constant, too short), a band above Nyquist, a sampling
        rate too low for the comb or the band.
    """
    fs = float(sampling_rate)
    arr = check_signal(x, fs)
    for name, v in (("shaft_frequency", shaft_frequency), ("csr_theoretical", csr_theoretical)):
        if not (math.isfinite(float(v)) and float(v) > 0):
            raise InputError(name, v, "a finite value > 0")
    if int(n_balls) != n_balls or n_balls < 1:
        raise InputError("n_balls", n_balls, "an integer >= 1")
    lo_s, hi_s = float(search[0]), float(search[1])
    if not 0 < lo_s < hi_s:
        raise InputError("search", search, "(low, high) with 0 < low < high")
    f_lo = lo_s * csr_theoretical * shaft_frequency
    f_hi = hi_s * csr_theoretical * shaft_frequency
    comb = _comb(int(n_balls), cage_harmonics, ball_pass_harmonics, shaft_sidebands)
    f_top = max(k * f_hi + n * shaft_frequency for _, k, n in comb)
    nyq = fs / 2
    if f_top * 2 > nyq:
        raise InputError("sampling_rate", fs, f"a rate above {4 * f_top:g} Hz for lines up to "
                         f"{f_top:g} Hz (a demodulation band as wide as the lines must fit "
                         "above them)")
    duration = arr.size / fs
    if duration * f_lo < 3:
        raise InputError("signal.duration", duration,
                         f"at least {3 / f_lo:.3g} s (3 cage revolutions at the lowest "
                         "cage frequency searched, so that its line clears the DC bins)")
    if band is not None and (band[1] > nyq or band[0] < 0):
        raise InputError("band", band, f"a band within [0, {nyq:g}] Hz (Nyquist)")
    if band is not None and band[1] - band[0] < f_top:
        raise InputError("band", band, f"a band at least {f_top:g} Hz wide (the envelope "
                         "spectrum of a band of width B only reaches B)")
    f_max = f_top * 1.1 + 2 * fs / arr.size
    if band is not None:
        es = envelope_spectrum(arr, fs, band, max_frequency=f_max, padding=padding)
    else:
        cells = kurtogram_bands(arr, fs, n_bands, min_frequency=f_top, min_bandwidth=f_max)
        parts = [envelope_spectrum(arr, fs, c.band, max_frequency=f_max, padding=padding)
                 for c in cells]
        size = min(e.frequency.size for e in parts)
        parts = [EnvelopeSpectrum(e.frequency[:size], e.power[:size], e.noise_floor[:size],
                                  e.band, e.resolution, e.padding, c.kurtosis)
                 for e, c in zip(parts, cells, strict=True)]
        es = combine_envelope_spectra(parts)
    df = es.resolution
    r = es.normalised
    step = es.frequency[1] - es.frequency[0]
    # max-filter of one native bin so that comb teeth tolerate the candidate grid step
    w = max(1, int(round(0.5 * df / step)))
    rmax = _max_filter(r, w)
    kmax = max(abs(k) for _, k, _ in comb)
    ks = np.array([k for _, k, _ in comb], dtype=float)
    ns = np.array([n for _, _, n in comb], dtype=float)
    f_end = float(es.frequency[-1])
    # primary teeth (cage fundamental, ball-pass harmonics) weigh twice the secondary ones
    # (cage harmonics, modulation and shaft sidebands): a wrong candidate whose secondary
    # teeth happen to fall on ball-pass lines must not outscore the true one
    weights = np.array([1.0 if (kind == "ball_pass" or (kind == "cage" and k == 1)) else 0.5
                        for kind, k, _ in comb])
    n_indep_line = 2 * w + 1
    thresh = math.log(n_indep_line / 0.01)  # per-line false alarm 1 % within its window
    # evidence that decides between candidates: 0.1 % family-wise over all teeth
    strict = math.log(n_indep_line * len(comb) / 1e-3)

    pure = np.array(sorted({abs(k) for _, k, n in comb if n == 0}), dtype=float)

    def teeth(fc: float) -> np.ndarray:
        """Teeth that are multiples of the cage frequency alone (no shaft sidebands)."""
        fl = fc * pure
        return fl[(fl > 2 * df) & (fl < f_end)]

    def off_shaft(fl: np.ndarray) -> np.ndarray:
        """True where a tooth is clear of every shaft harmonic m f_s (those lines belong to
        the shaft: runout, unbalance)."""
        ratio = fl / shaft_frequency
        return np.abs(ratio - np.round(ratio)) * shaft_frequency > 1.5 * df

    def score_at(fcs: np.ndarray) -> np.ndarray:
        fl = fcs[:, None] * ks[None, :] + ns[None, :] * shaft_frequency
        valid = (fl > 2 * df) & (fl < f_end)
        # log-compressed tooth powers: one dominant line must not carry a comb on its own
        vals = np.where(valid, np.log1p(np.interp(fl, es.frequency, rmax)), 0.0)
        wv = valid * weights[None, :]
        return (vals * wv).sum(axis=1) / np.maximum(wv.sum(axis=1), 1e-300)

    def specific_evidence(a: float, b: float) -> bool:
        """A tooth of comb a, away from every tooth of comb b, stands above the noise."""
        ta, tb = teeth(a), teeth(b)
        own = [f for f in ta if np.all(np.abs(tb - f) > df)]
        return bool(own) and float(np.max(np.interp(own, es.frequency, rmax))) > strict

    cand = np.arange(f_lo, f_hi, 0.5 * df / kmax)
    score = score_at(cand)
    f0 = float(cand[int(np.argmax(score))])
    # octave (and twelfth) errors: a multiple m f of the cage frequency has a comb that is a
    # subset of the true one, a sub-multiple f/m a superset. Move to m f when f's own teeth
    # are empty; move to f/m when its own teeth hold a line and it scores comparably.
    for _ in range(4):
        moved = False
        for m in (2, 3):
            up = f0 * m
            if up < f_hi and not specific_evidence(f0, up):
                f0, moved = up, True
                break
            down = f0 / m
            if down > f_lo and specific_evidence(down, f0) and (
                    score_at(np.array([down]))[0] >= 0.7 * score_at(np.array([f0]))[0]):
                f0, moved = down, True
                break
        if not moved:
            break
    # local maximum of the score on the fine grid around f0
    near = np.abs(cand - f0) <= 0.5 * df
    if near.any():
        f0 = float(cand[near][int(np.argmax(score[near]))])
    # refine each line, weighted least squares for f_c
    entries = []
    expected_all = np.array([k * f0 + n * shaft_frequency for _, k, n in comb])
    rank = np.array([_priority(kind, k) for kind, k, _ in comb])
    shared = []
    for i, (kind, k, n) in enumerate(comb):
        fe = expected_all[i]
        if not (2 * df < fe < es.frequency[-1]):
            continue
        close = np.abs(expected_all - fe) < 1.5 * df
        close[i] = False
        if np.any(rank[close] <= rank[i]):
            continue  # a tooth of higher (or equal) rank claims this line
        fm, snr = refine_peak(es, fe, 0.5 * df)
        entries.append((kind, k, n, fm, snr))
        shared.append(bool(close.any()))
    used = [(k, n, fm, snr, sh) for (_, k, n, fm, snr), sh in zip(entries, shared, strict=True)
            if snr > thresh]
    if used:
        # weight: n_c^2 SNR (frequency variance ~ 1/SNR, divided by n_c); a line that a
        # lower-rank tooth could also explain counts a quarter
        wts = np.array([k * k * snr * (0.25 if sh else 1.0) for k, _, _, snr, sh in used])
        est = np.array([(fm - n * shaft_frequency) / k for k, n, fm, _, _ in used])
        fc = float(np.sum(wts * est) / np.sum(wts))
        # refit without the lines that miss the first fit by more than half a bin
        kk = np.array([k for k, *_ in used], dtype=float)
        keep = np.abs(kk * (est - fc)) <= 0.5 * df
        if keep.any() and not keep.all():
            fc = float(np.sum(wts[keep] * est[keep]) / np.sum(wts[keep]))
    else:
        fc = f0
    # significance: Fisher's method over all comb lines, Bonferroni over candidates
    pvals = np.array([min(1.0, n_indep_line * math.exp(-min(snr, 700.0)))
                      for *_, snr in entries])
    pvals = np.clip(pvals, 1e-300, 1.0)
    chi = float(-2.0 * np.sum(np.log(pvals)))
    p_comb = float(stats.chi2.sf(chi, 2 * len(pvals))) if len(pvals) else 1.0
    n_cand = max(1.0, (f_hi - f_lo) / (df / kmax))
    p_fa = min(1.0, p_comb * n_cand)
    consistent = 0
    for k, n, fm, _, _ in used:
        if abs((fm - n * shaft_frequency) - k * fc) <= 0.5 * df:
            consistent += 1
    consistency = consistent / len(used) if used else 0.0
    primary = any(kind == "ball_pass" and k == n_balls or kind == "cage" and k == 1
                  for (kind, k, _n, _fm, snr) in entries if snr > strict)
    # at least one strong line away from every shaft harmonic: a comb that only sits on
    # m f_s is a once-per-revolution signal (runout, unbalance), not a cage
    off = any(snr > strict and off_shaft(np.array([fm]))[0] for _, _, fm, snr, _ in used)
    confidence = (1.0 - p_fa) * consistency if (primary and off and len(used) >= 2) else 0.0
    lines = []
    for (kind, k, n, fm, snr) in entries:
        lines.append(DetectedLine(kind, (k, n), k * fc + n * shaft_frequency,
                                  fm if snr > thresh else math.nan, snr, snr > thresh))
    # the shaft line itself (information only)
    shaft_meas = None
    if shaft_frequency < es.frequency[-1] - df:
        fm, snr = refine_peak(es, shaft_frequency, 0.02 * shaft_frequency + df)
        if snr > math.log(n_indep_line / alpha):
            shaft_meas = fm
        lines.append(DetectedLine("shaft", (0, 1), shaft_frequency,
                                  fm if shaft_meas else math.nan, snr, shaft_meas is not None))
    detected = p_fa < alpha and len(used) >= 2 and consistency >= 0.5 and primary and off
    if not detected:
        reason = (f"no significant cage comb (false-alarm probability {p_fa:.3g} vs alpha "
                  f"{alpha:g}, {len(used)} lines above threshold, consistency "
                  f"{consistency:.2f}, fundamental line {'found' if primary else 'missing'}"
                  f"{'' if off else ', all strong lines on shaft harmonics'})")
        return CageSpeedEstimate(False, None, None, None, None, float(shaft_frequency),
                                 shaft_meas, float(csr_theoretical), float(max(confidence, 0)),
                                 p_fa, consistency, tuple(lines), es, reason)
    csr = cage_speed_ratio(fc, shaft_frequency)
    return CageSpeedEstimate(True, fc, csr, cage_slip(csr, csr_theoretical), n_balls * fc,
                             float(shaft_frequency), shaft_meas, float(csr_theoretical),
                             float(confidence), p_fa, consistency, tuple(lines), es, "")


def _priority(kind: str, k: int) -> int:
    """Rank of a comb tooth when two fall on one line (0 claims first)."""
    if kind == "ball_pass":
        return 0
    if kind == "cage":
        return 1 if k == 1 else 3
    return 2 if kind == "ball_pass_sideband" else 4


def _max_filter(a: np.ndarray, w: int) -> np.ndarray:
    out = a.copy()
    for s in range(1, w + 1):
        out[:-s] = np.maximum(out[:-s], a[s:])
        out[s:] = np.maximum(out[s:], a[:-s])
    return out
