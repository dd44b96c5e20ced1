"""Cage speed from the envelope spectrum of a vibration record (harmonic-comb search).

One job: :func:`estimate_cage_speed` finds the cage rotation frequency, the cage speed ratio
and the cage slip in an acceleration record; :func:`cage_speed_ratio` and :func:`cage_slip`
convert between them. Paper 002 (Gao et al. 2022, ``../shared/seeds/002_0add79adaca5495c.txt``,
section 4.2; CSR = CRF / f_i) and paper 004 (Luo et al. 2022, ``004_0105d7aba121b014.txt``
eq. 2 and eq. 27, BPFO = Z f_cage); see :mod:`thermobearing.signal`.

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
   and the other lacks hold a line above the noise, and a move to ``f / m`` is refused, a
   move to ``m f`` made, when the harmonic family says so: the ball-pass fundamental Z f
   more than ``BALL_PASS_FAMILY_DB`` below the line at m Z f while the cage line at m f is
   there -- harmonics of equal impulses fall with order, so f is then a period-m response
   of a cage at m f; a family leaning less than that is flagged ``ambiguous``), is refined:
   each line's frequency by Gaussian (log-parabolic) interpolation of the zero-padded Hann
   spectrum (sub-bin), then ``f_c`` by weighted least squares over the detected lines.
6. confidence: Fisher's combination of the per-line false-alarm probabilities, Bonferroni
   corrected for the number of independent candidates searched; ``detected`` only when
   the family-wise false-alarm probability is below ``alpha``, at least two lines stand
   above the per-line threshold, at least half of them agree with the estimate within half
   a bin, a fundamental (the ball-pass fundamental ``Z f_c`` or the cage line ``f_c``)
   is among them, and at least one strong line is away from every shaft harmonic ``m f_s``
   (a comb sitting only on shaft harmonics is a once-per-revolution signal). Otherwise the result is
   flagged not detected and carries no frequency (never a made-up one).
7. standard uncertainty of f_c, CSR and slip (:mod:`thermobearing.signal_uncertainty`);
   checks that say what the result rests on: the shaft frequency (an envelope line near
   it that is no cage harmonic, or a pair of shaft sidebands), the element count Z
   (:mod:`thermobearing.signal_checks`).

Conventions: frequencies in Hz, cage speed ratio ``CSR = f_cage / f_shaft`` (outer ring
fixed), cage slip ``s_c = 1 - CSR / CSR_th`` (paper 004 eq. 2; negative = over-skidding).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.special import chdtrc

from .errors import InputError
from .signal_checks import BallCountCheck, ball_count_check
from .signal_envelope import (
    EnvelopeSpectrum,
    combine_envelope_spectra,
    envelope_spectrum,
    refine_peak,
)
from .signal_input import check_signal
from .signal_kurtogram import kurtogram_bands
from .signal_uncertainty import CombinedFrequency, combined_frequency_std, line_frequency_std

#: a sub-multiple f/m of the cage frequency whose own comb lines (those that are no line of
#: the comb at f) all stand more than this many dB below the strongest line of f's comb is
#: taken as a subharmonic of f's comb, not as the cage (a QJ1044 model record over-skidding
#: at CSR 0.4527 carries a full comb at f_c / 2, 15 dB below the ball-pass line Z f_c in
#: its pooled envelope spectrum; a real cage's own lines hold its ball-pass fundamental)
SUBHARMONIC_DB = 10.0
#: a cage reading f whose ball-pass fundamental Z f stands more than this many dB below the
#: line at m Z f (m = 2, 3; the ball-pass fundamental of a cage at m f) is taken as a
#: period-m response of a cage at m f. Harmonics of equal impulses fall with order: with
#: the true reading, 2 Z f stood 0.6-8.8 dB below Z f on every QJ1044 model record (0-5 um
#: oversize ball, CSR 0.18-0.51) and impulse train measured (line levels, ``level``); the
#: half-speed readings of the model records lean 15-91 dB, those of an impulse train whose
#: ball 0 strikes 4 times harder on every other revolution 5.4-6.5 dB
BALL_PASS_FAMILY_DB = 3.0
#: ... and when it stands above it by less than BALL_PASS_FAMILY_DB, the reading is kept and
#: flagged ambiguous (the same train with ball 0 6 or 9 times stronger: 0.4-3.1 dB)
BALL_PASS_LEAN_DB = 0.0
#: a cage comb whose own lines stand more than this many dB (but less than SUBHARMONIC_DB)
#: below the comb at twice (three times) its frequency is kept with a note naming the other
#: reading (the QJ1044 model skidding at CSR 0.44 puts its half-speed comb 8 dB below)
AMBIGUOUS_DB = 3.0


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
    snr : normalised power (power / local noise mean); detected : snr above threshold. The
        shaft line's snr is NaN when the peak in its +-2 % window is a line of the cage comb
        or a cage harmonic (that line's snr is on its own entry).
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
    lines : the comb lines; spectrum : the envelope spectrum analysed (of the record divided
        by its largest magnitude: the analysis is scale-free; ``normalised`` is unaffected).
    notes : what a detected result rests on beyond the comb: the given shaft frequency when
        no envelope line within ``SHAFT_CONFIRM`` of it (plus 1/4 bin) and no pair of shaft
        sidebands f_s -+ f_c confirms it (the CSR then scales with a speed given in the
        wrong unit, at full confidence); a sub-multiple comb read as a subharmonic
        (``SUBHARMONIC_DB``, ``BALL_PASS_FAMILY_DB``), with the CSR and slip it would give;
        an ``AMBIGUOUS:`` note naming the other reading when the harmonic family does not
        decide between f_c and 2 f_c / 3 f_c.
    ambiguous : an AMBIGUOUS note was given.
    cage_frequency_uncertainty [Hz], csr_uncertainty, slip_uncertainty [-]: standard
        uncertainty of the frequency measurement (:mod:`thermobearing.signal_uncertainty`:
        each line's error from its SNR and the record length, combined over the lines,
        times their Birge ratio when above 1); the shaft speed's own error is not in it.
        frequency_fit : the combination (lines used, Birge ratio).
    shaft_confirmed : an envelope line within ``SHAFT_CONFIRM`` of the shaft frequency that
        is no harmonic of the cage frequency, or a pair of shaft sidebands, confirms the
        speed given (else a note says the CSR rests on it alone).
    ball_count : the bearing's element count Z checked against the spectrum
        (:func:`thermobearing.signal_checks.ball_count_check`: "consistent", "contradicted",
        "doubtful" or "not checked"; a note unless consistent, "BEARING: ..." when the
        spectrum contradicts or doubts Z).
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
    notes: tuple[str, ...] = ()
    ambiguous: bool = False
    cage_frequency_uncertainty: float | None = None
    csr_uncertainty: float | None = None
    slip_uncertainty: float | None = None
    frequency_fit: CombinedFrequency | None = None
    shaft_confirmed: bool = False
    ball_count: BallCountCheck | None = None


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
    # the analysis is scale-free (every decision uses power ratios), but the squared
    # envelope's spectrum and the kurtogram's fourth moments hold x^4: a record whose peak
    # is beyond about 1e+-75 over/underflowed and was reported "no significant cage comb"
    # (an impulse train at 1e80 or 1e-80 m/s^2); the record is analysed at unit peak, so the
    # returned spectrum's power is that of x / max|x|
    arr = arr / float(np.max(np.abs(arr)))
    for name, v in (("shaft_frequency", shaft_frequency), ("csr_theoretical", csr_theoretical)):
        if not (math.isfinite(float(v)) and float(v) > 0):
            raise InputError(name, v, "a finite value > 0")
    if not csr_theoretical < 0.5:  # (1 - gamma)/2 with 0 < gamma < 1
        raise InputError("csr_theoretical", csr_theoretical, "a ratio in (0, 0.5): "
                         "(1 - D cos(alpha)/d_m)/2, not a percentage")
    if int(n_balls) != n_balls or n_balls < 1:
        raise InputError("n_balls", n_balls, "an integer >= 1")
    if len(search) != 2:
        raise InputError("search", search, "(low, high) with 0 < low < high")
    lo_s, hi_s = float(search[0]), float(search[1])
    if not 0 < lo_s < hi_s:
        raise InputError("search", search, "(low, high) with 0 < low < high")
    for name, v, low in (("cage_harmonics", cage_harmonics, 1),
                         ("ball_pass_harmonics", ball_pass_harmonics, 0),
                         ("shaft_sidebands", shaft_sidebands, 0), ("padding", padding, 1),
                         ("n_bands", n_bands, 1)):
        if isinstance(v, bool) or not isinstance(v, int | np.integer) or v < low:
            raise InputError(name, v, f"a whole number >= {low}")
    if not 0.0 < alpha < 1.0:
        raise InputError("alpha", alpha, "a false-alarm probability in (0, 1)")
    f_lo = lo_s * csr_theoretical * shaft_frequency
    f_hi = hi_s * csr_theoretical * shaft_frequency
    comb = _comb(int(n_balls), cage_harmonics, ball_pass_harmonics, shaft_sidebands)
    f_top = max(k * f_hi + n * shaft_frequency for _, k, n in comb)
    nyq = fs / 2
    if f_top * 2 > nyq:
        fewer = (f"; or fewer ball-pass harmonics than {ball_pass_harmonics} "
                 "(ball_pass_harmonics, cage-speed --ball-pass-harmonics)"
                 if ball_pass_harmonics > 1 else "")
        raise InputError("sampling_rate", fs, f"a rate above {4 * f_top:g} Hz for lines up to "
                         f"{f_top:g} Hz (a demodulation band as wide as the lines must fit "
                         f"above them){fewer}; the lines follow shaft_frequency = "
                         f"{float(shaft_frequency):g} Hz (r/min / 60)")
    duration = arr.size / fs
    if duration * f_lo < 3:
        raise InputError("signal.duration", duration,
                         f"at least {3 / f_lo:.3g} s (3 cage revolutions at the lowest "
                         "cage frequency searched, so that its line clears the DC bins)")
    if band is not None and not (len(band) == 2 and all(math.isfinite(float(v)) for v in band)
                                 and band[0] < band[1]):
        raise InputError("band", band, "(low, high) in Hz with low < high")
    if band is not None and (band[1] > nyq or band[0] < 0):
        raise InputError("band", band, f"a band within [0, {nyq:g}] Hz (Nyquist)")
    if band is not None and band[1] - band[0] < f_top:
        raise InputError("band", band, f"a band at least {f_top:g} Hz wide (the envelope "
                         "spectrum of a band of width B only reaches B)")
    f_max = f_top * 1.1 + 2 * fs / arr.size
    if band is not None:
        es = envelope_spectrum(arr, fs, band, max_frequency=f_max, padding=padding)
    else:
        try:
            cells = kurtogram_bands(arr, fs, n_bands, min_frequency=f_top,
                                    min_bandwidth=f_max)
        except InputError as exc:
            if exc.field != "band":
                raise
            need = _kurtogram_rate(duration, f_top, f_max, fs)
            raise InputError("sampling_rate", fs, f"a rate of at least {need:.4g} Hz for "
                             f"this record: the demodulation band must lie above the highest "
                             f"line searched ({f_top:.4g} Hz), be at least {f_max:.4g} Hz "
                             f"wide and stay below Nyquist ({nyq:g} Hz); or give a band "
                             "(--band)") from None
        parts = [envelope_spectrum(arr, fs, c.band, max_frequency=f_max, padding=padding)
                 for c in cells]
        size = min(e.frequency.size for e in parts)
        parts = [EnvelopeSpectrum(e.frequency[:size], e.power[:size], e.noise_floor[:size],
                                  e.band, e.resolution, e.padding, c.kurtosis)
                 for e, c in zip(parts, cells, strict=True)]
        es = combine_envelope_spectra(parts)
    # line levels for comparisons between lines (harmonic family, element count): each
    # band's power over one level per band (the median of its local noise floor), not over
    # the local floor, which lines crowd at low frequency (an impulse train at CSR 0.18:
    # the floor under Z f_c 3.8 times that under 2 Z f_c, turning a 0.4 dB fall in power
    # into a 3.5 dB rise)
    level = (np.mean([e.power / np.median(e.noise_floor) for e in parts], axis=0)
             if band is None else es.power / np.median(es.noise_floor))
    df = es.resolution
    r = es.normalised
    step = es.frequency[1] - es.frequency[0]
    # max-filter of one native bin so that comb teeth tolerate the candidate grid step
    w = max(1, int(round(0.5 * df / step)))
    rmax = _max_filter(r, w)
    lmax = _max_filter(level, w)
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

    def own_power(a: float, b: float) -> float:
        """Largest normalised power on a tooth of comb a away from every tooth of comb b
        (0 when there is none)."""
        ta, tb = teeth(a), teeth(b)
        own = [f for f in ta if np.all(np.abs(tb - f) > df)]
        return float(np.max(np.interp(own, es.frequency, rmax))) if own else 0.0

    def specific_evidence(a: float, b: float) -> bool:
        """A tooth of comb a, away from every tooth of comb b, stands above the noise."""
        return own_power(a, b) > strict

    def dominated(a: float, b: float) -> bool:
        """Every own line of the sub-multiple comb a (a tooth that is no tooth of comb b)
        stands more than SUBHARMONIC_DB below the strongest line of comb b: a subharmonic
        of b's comb (a period-doubled response), not a cage turning at a."""
        tb = teeth(b)
        top = float(np.max(np.interp(tb, es.frequency, rmax))) if tb.size else 0.0
        return own_power(a, b) < 10.0 ** (-SUBHARMONIC_DB / 10.0) * top

    def line_power(f: float) -> float:
        """Normalised power of the line at ``f`` [Hz]: its significance (0 outside the
        spectrum)."""
        return float(np.interp(f, es.frequency, rmax)) if 2 * df < f < f_end else 0.0

    def line_level(f: float) -> float:
        """Level of the line at ``f`` [Hz] for comparisons with other lines (``level``;
        1e-300 outside the spectrum)."""
        return float(np.interp(f, es.frequency, lmax)) if 2 * df < f < f_end else 1e-300

    def bp_power(fc: float) -> float:
        """Normalised power at the ball-pass fundamental Z f of a cage at ``fc``."""
        return line_power(n_balls * fc)

    def bp_lean(a: float, m: int) -> float | None:
        """How far [dB] the harmonic family leans from a cage at ``a`` to one at m a: the
        line at m Z a (ball-pass fundamental of m a, m-th ball-pass harmonic of a) over the
        line at Z a, when the first stands above the noise and the cage lines agree: the
        line at m a (cage fundamental of m a) above the noise and not more than
        ``AMBIGUOUS_DB`` below the one at a (a period-m response is not stronger than the
        motion it divides; a big ball striking harder on every other revolution puts equal
        lines at f_c / 2 and f_c). None
        when the family does not lean that way. Without cage lines the ball pass alone
        does not decide: a smooth modulation at the ball pass puts its strongest envelope
        line at 2 Z f_c (the QJ1044 model without an off-size ball at CSR 0.28: 40 f_c
        more than 6 dB above 20 f_c, no cage line)."""
        if bp_power(m * a) <= strict or line_power(m * a) <= strict:
            return None
        if line_level(m * a) < line_level(a) * 10.0 ** (-AMBIGUOUS_DB / 10):
            return None
        return 10.0 * math.log10(line_level(m * n_balls * a) / line_level(n_balls * a))

    def bp_says_up(a: float, m: int) -> float | None:
        """The harmonic family contradicts a cage at ``a`` in favour of m a: it leans that
        way (:func:`bp_lean`) by more than ``BALL_PASS_FAMILY_DB``. The dB or None."""
        db = bp_lean(a, m)
        return db if db is not None and db > BALL_PASS_FAMILY_DB else None

    cand = np.arange(f_lo, f_hi, 0.5 * df / kmax)
    score = score_at(cand)
    f0 = float(cand[int(np.argmax(score))])
    # octave (and twelfth) errors: a multiple m f of the cage frequency has a comb that is a
    # subset of the true one, a sub-multiple f/m a superset. Move to m f when f's own teeth
    # are empty or a subharmonic of m f's comb; move to f/m when its own teeth hold a line
    # that is no subharmonic and it scores comparably. A sub-multiple whose own lines are
    # there but dominated is kept as an alternative (reported, not chosen).
    # The ball-pass family decides first where it is visible: a cage at f has its ball pass
    # at Z f, and the squared envelope of equal impulses has harmonics that fall with order
    # (the spectrum of one impulse's squared envelope is low-pass), so a line at m Z f far
    # above the one at Z f is the ball pass of a cage at m f (f's own lines a period-m
    # response of it: the QJ1044 model with one ball 5 um oversize at CSR 0.44).
    alternative = None
    for _ in range(4):
        moved = False
        for m in (2, 3):
            up = f0 * m
            if up < f_hi and (not specific_evidence(f0, up) or dominated(f0, up)
                              or bp_says_up(f0, m) is not None):
                if specific_evidence(f0, up):
                    alternative = (f0, m)
                f0, moved = up, True
                break
            down = f0 / m
            if down > f_lo and specific_evidence(down, f0) and (
                    score_at(np.array([down]))[0] >= 0.7 * score_at(np.array([f0]))[0]):
                if dominated(down, f0) or bp_says_up(down, m) is not None:
                    alternative = (down, m)
                    continue
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
        if not keep.any():
            keep[:] = True
        # standard uncertainty: each line's Cramer-Rao error over |k|, the scatter between
        # the lines (Birge ratio) when larger (signal_uncertainty)
        sig = np.array([line_frequency_std(1.0 + _line_snr(es, fm), duration) / abs(k)
                        for k, _, fm, _, _ in used])
        ok = keep & np.isfinite(sig)
        unc = (combined_frequency_std(est[ok], sig[ok], wts[ok]) if ok.any() else None)
    else:
        fc = f0
        unc = None
    # significance: Fisher's method over all comb lines, Bonferroni over candidates
    pvals = np.array([min(1.0, n_indep_line * math.exp(-min(snr, 700.0)))
                      for *_, snr in entries])
    pvals = np.clip(pvals, 1e-300, 1.0)
    chi = float(-2.0 * np.sum(np.log(pvals)))
    p_comb = float(chdtrc(2 * len(pvals), chi)) if len(pvals) else 1.0
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
    # the shaft line itself (information only); a peak in its +-2 % window that a line of
    # the cage comb explains (e.g. 2 f_c = 29.5 Hz beside f_s = 30.2 Hz at CSR 0.488), or
    # any harmonic k f_c of the cage frequency (an off-size ball puts all of them in the
    # envelope: with f_s given as 48.1 Hz for a 30 Hz shaft, 4 f_c = 48.0 Hz 'confirmed'
    # it), is that line, not the shaft
    shaft_meas = None
    shaft_harmonic = None
    if shaft_frequency < es.frequency[-1] - df:
        fm, snr = refine_peak(es, shaft_frequency, 0.02 * shaft_frequency + df)
        comb_line = any(abs(fm - (k * fc + n * shaft_frequency)) <= df for k, n, *_ in used)
        k_h = max(1, round(fm / fc)) if math.isfinite(fm) else 0
        if snr > math.log(n_indep_line / alpha) and not comb_line:
            if k_h and abs(fm - k_h * fc) <= df:
                shaft_harmonic = (fm, k_h)
            else:
                shaft_meas = fm
        # a peak the comb or a cage harmonic explains is not the shaft's: its SNR is not
        # reported on the shaft line (it printed 'measured -' beside the 3rd cage harmonic's
        # 'snr 236.9' at 30.45 Hz for a 30.2 Hz shaft)
        own = shaft_meas is not None or not (comb_line or shaft_harmonic is not None)
        lines.append(DetectedLine("shaft", (0, 1), shaft_frequency,
                                  fm if shaft_meas else math.nan, snr if own else math.nan,
                                  shaft_meas is not None))
    detected = p_fa < alpha and len(used) >= 2 and consistency >= 0.5 and primary and off
    strong = any(snr > strict for _, _, _, snr, _ in used)
    if not detected:
        reason = (f"no significant cage comb (false-alarm probability {p_fa:.3g} vs alpha "
                  f"{alpha:g}, {len(used)} lines above threshold, consistency "
                  f"{consistency:.2f}, fundamental line {'found' if primary else 'missing'}"
                  f"{'' if off or not strong else ', all strong lines on shaft harmonics'})")
        return CageSpeedEstimate(False, None, None, None, None, float(shaft_frequency),
                                 shaft_meas, float(csr_theoretical), float(max(confidence, 0)),
                                 p_fa, consistency, tuple(lines), es, reason)
    csr = cage_speed_ratio(fc, shaft_frequency)
    notes = []
    if alternative is not None and abs(alternative[0] * alternative[1] - fc) <= df:
        alt, m = alternative
        top = float(np.max(np.interp(teeth(fc), es.frequency, rmax)))
        notes.append(_subharmonic_note(fc, alt, m, 10.0 * math.log10(
            top / max(own_power(alt, fc), 1e-300)), float(shaft_frequency),
            float(csr_theoretical), bp_says_up(alt, m), int(n_balls)))
    ambiguous = False
    for m in (2, 3):  # the other reading: fc's own lines a subharmonic of a cage at m fc
        up = m * fc
        tu = teeth(up)
        bp_db = bp_says_up(fc, m)
        if bp_db is not None and not up < f_hi:
            ambiguous = True
            notes.append(
                f"AMBIGUOUS: the ball-pass line of a cage at {m} x {fc:.4f} Hz = "
                f"{up:.4f} Hz ({m * n_balls} x {fc:.4f} Hz) stands {bp_db:.0f} dB above the "
                f"ball-pass line {n_balls} x "
                f"{fc:.4f} Hz of the reading: the cage may turn at {up:.4f} Hz (CSR "
                f"{up / shaft_frequency:.4f}), outside the range searched (widen --search)")
            break
        if not up < f_hi or not tu.size:
            continue
        top = float(np.max(np.interp(tu, es.frequency, rmax)))
        own = own_power(fc, up)
        own_db = 10.0 * math.log10(top / own) if own > 0 else -math.inf
        # the ball-pass family leans to m fc when Z fc is weaker than m Z fc (harmonics of
        # equal impulses fall with order) without deciding (BALL_PASS_FAMILY_DB)
        lean = bp_lean(fc, m)
        lean_db = lean if lean is not None else -math.inf
        if top > strict and own > 0 and (own_db > AMBIGUOUS_DB or lean_db > BALL_PASS_LEAN_DB):
            why = []
            if own_db > AMBIGUOUS_DB:
                why.append(f"the lines that only a cage at {fc:.4f} Hz explains stand "
                           f"{own_db:.0f} dB below the strongest line of the comb at {m} x = "
                           f"{up:.4f} Hz")
            if lean_db > BALL_PASS_LEAN_DB:
                why.append(f"the ball-pass fundamental {n_balls} x {fc:.4f} Hz stands "
                           f"{lean_db:.1f} dB below the line at {m * n_balls} x {fc:.4f} Hz "
                           f"(the ball-pass line of a cage at {up:.4f} Hz)")
            notes.append(
                f"AMBIGUOUS: {'; '.join(why)}: the lines at {fc:.4f} Hz may be a subharmonic "
                f"(a period-{m} response) of a cage at {up:.4f} Hz (CSR "
                f"{up / shaft_frequency:.4f}, slip "
                f"{100 * (1 - up / shaft_frequency / csr_theoretical):+.1f} %); they are read "
                f"as the cage while their own lines stand less than {SUBHARMONIC_DB:g} dB "
                f"below and the ball-pass fundamental less than {BALL_PASS_FAMILY_DB:g} dB "
                "below")
            ambiguous = True
            break
    # the first shaft sidebands confirm the shaft frequency as a pair f_s -+ f_c (one line
    # alone can be another component that happens to sit there), neither of them a harmonic
    # of the cage frequency itself; the second pair does not (a model record's envelope is
    # dense with lines: with f_s taken 2 pi too high, 2 f_s -+ f_c fell on two of them)
    pairs = {(k, n) for k, n, fm, _, _ in used
             if n == 1 and abs((fm - n * shaft_frequency) - k * fc) <= 0.5 * df
             and abs(fm - fc * round(fm / fc)) > 0.5 * df}
    sidebands = any((-k, n) in pairs for k, n in pairs)
    # the bearing's element count against the spectrum (signal_checks)
    independent = any(kind in ("cage", "sideband") and snr > strict and math.isfinite(fm)
                      and abs(fm - (k * fc + n * shaft_frequency)) <= 0.5 * df
                      for kind, k, n, fm, snr in entries)
    def peak_power(f: float) -> float:
        """Normalised power of a line peaking within half a bin of ``f`` (0 without)."""
        if not 2 * df < f < f_end:
            return 0.0
        fm, snr = refine_peak(es, f, 0.5 * df)
        return snr if math.isfinite(fm) and abs(fm - f) <= 0.5 * df else 0.0

    z_check = ball_count_check(peak_power, line_level, fc, int(n_balls),
                               float(shaft_frequency), df, strict, f_end, (f_lo, f_hi),
                               independent)
    if z_check.status != "consistent":
        notes.append(("BEARING: " if z_check.status in ("contradicted", "doubtful") else "")
                     + z_check.message)
    shaft_notes = _shaft_notes(float(shaft_frequency), shaft_meas, sidebands, df, fc,
                               shaft_harmonic)
    notes += shaft_notes
    u_fc = unc.std if unc is not None else None
    u_csr = u_fc / float(shaft_frequency) if u_fc is not None else None
    return CageSpeedEstimate(True, fc, csr, cage_slip(csr, csr_theoretical), n_balls * fc,
                             float(shaft_frequency), shaft_meas, float(csr_theoretical),
                             float(confidence), p_fa, consistency, tuple(lines), es, "",
                             tuple(notes), ambiguous, u_fc, u_csr,
                             u_csr / float(csr_theoretical) if u_csr is not None else None,
                             unc, not shaft_notes, z_check)


#: a shaft line within this fraction (plus a quarter bin: the line is refined below a bin)
#: of the given shaft frequency confirms it
SHAFT_CONFIRM = 0.005


def _subharmonic_note(fc: float, alt: float, m: int, db: float, fs_hz: float,
                      csr_th: float, bp_db: float | None = None, n_balls: int = 0) -> str:
    """What the printout says about a sub-multiple comb taken as a subharmonic: why (its own
    lines far below the comb, or its ball-pass fundamental far below the ball-pass line)."""
    csr_alt = alt / fs_hz
    why = (f"the strongest stands {db:.0f} dB below the comb's strongest line"
           if db > SUBHARMONIC_DB else "")
    if bp_db is not None:
        why += ("; " if why else "") + (
            f"the ball-pass fundamental a cage at {alt:.4f} Hz would have ({n_balls} x "
            f"{alt:.4f} = {n_balls * alt:.3f} Hz) stands {bp_db:.0f} dB below the ball-pass "
            f"line {n_balls} x {fc:.4f} = {n_balls * fc:.3f} Hz")
    return (f"the record also holds lines at multiples of {alt:.4f} Hz (1/{m} of the cage "
            f"frequency) that are no line of the cage comb; {why}, so they are read as a "
            f"subharmonic (a period-{m} response), not as a cage at {alt:.4f} Hz (that would "
            f"be CSR {csr_alt:.4f}, slip {100 * (1 - csr_alt / csr_th):+.1f} %)")


def _shaft_notes(fs_hz: float, measured: float | None, sidebands: bool, df: float,
                 fc: float, harmonic: tuple[float, int] | None = None) -> list[str]:
    """A note when nothing in the record confirms the given shaft frequency (CSR =
    f_cage / f_shaft then rests on it alone: a speed in the wrong unit scales the CSR and
    leaves the confidence of the cage comb untouched). ``harmonic``: (frequency, k) of a
    line near f_s that is the k-th cage harmonic (it confirms nothing)."""
    if sidebands or (measured is not None
                     and abs(measured - fs_hz) <= SHAFT_CONFIRM * fs_hz + 0.25 * df):
        return []
    if harmonic is not None:
        fh, k = harmonic
        seen = (f"the envelope line near it, {fh:.4f} Hz, is the cage harmonic {k} x "
                f"{fc:.4f} Hz (within a bin, {df:.3g} Hz), so it cannot tell the shaft")
    elif measured is None:
        seen = "no envelope line near it"
    else:
        seen = (f"the envelope line nearest it is at {measured:.4f} Hz, "
                f"{100 * (measured / fs_hz - 1):+.2f} %, more than {100 * SHAFT_CONFIRM:g} % "
                "off")
    return [f"the record does not confirm the shaft frequency {fs_hz:.4g} Hz ({seen}; no "
            f"pair of shaft sidebands f_s -+ f_cage): CSR = f_cage / f_shaft rests on the "
            f"speed given alone, and the confidence is that of the cage comb at {fc:.4f} Hz. "
            f"A speed in the wrong unit (Hz or rad/s taken as r/min) gives a wrong CSR at "
            f"full confidence: check the speed"]


def _kurtogram_rate(duration: float, f_min: float, bandwidth: float, fs: float) -> float:
    """Smallest sampling rate [Hz] (in 1 % steps above ``fs``) at which a record of
    ``duration`` [s] has a kurtogram cell of :func:`kurtogram_bands` (window lengths 8-512,
    cells of width 2 fs / N_w on the STFT bins) above ``f_min`` [Hz], at least ``bandwidth``
    [Hz] wide and below Nyquist."""
    rate = fs
    for _ in range(2000):
        rate *= 1.01
        n = duration * rate
        for nw in (8, 16, 32, 64, 128, 256, 512):
            half = rate / nw
            if nw * 8 > n or 2 * half < bandwidth:
                continue
            k_lo = math.ceil(f_min / half + 1.0 - 1e-12)
            if (k_lo + 1) * half <= rate / 2 and k_lo >= 1:
                return rate
    return rate


def _line_snr(es: EnvelopeSpectrum, frequency: float) -> float:
    """Line power over the noise mean of the spectrum the line is read from, minus the
    noise: ``R - 1`` of one band; for N pooled bands (``power`` = mean normalised power,
    whose noise fluctuates N times less) ``N (mean - 1)``."""
    p = float(np.interp(frequency, es.frequency, es.power if len(es.bands) > 1
                        else es.normalised))
    return max(len(es.bands), 1) * (p - 1.0)


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
