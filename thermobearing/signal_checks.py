"""Check of the bearing's number of rolling elements against an envelope spectrum.

One job: :func:`ball_count_check` asks whether the lines of a squared-envelope spectrum
agree with the rolling-element count Z of the bearing named for the analysis, given the
cage frequency f_c read from it (:mod:`thermobearing.signal_cage`). The cage speed ratio
``CSR = f_c / f_s`` does not need Z when the cage frequency is read from its own lines (the
cage line and its harmonics, shaft sidebands ``f_s -+ f_c``), but the comb search pairs the
ball-pass line with ``Z f_c`` (paper 004 eq. 27, outer ring fixed): a wrong ``--bearing``
moves the cage reading to ``BPFO / Z`` or leaves the ball-pass line unexplained, silently.

Rules (``power(f)`` = line power over the local noise mean [-], the significance of a
line; ``level(f)`` = line power on one scale for all frequencies, for comparisons):

1. the cage frequency is *independent* of Z when a cage line k f_c (k = 1..3) or a shaft
   sideband stands above the noise; then the strongest line at a multiple n f_c
   (n = 4 .. 3 Z + 3, away from shaft harmonics, above the noise) is the ball pass: n = Z
   is consistent; a line at n != Z more than ``BALL_COUNT_DB`` above the one at Z f_c
   contradicts Z (at a multiple n = j Z it may be a strong j-th ball-pass harmonic:
   "doubtful", not "contradicted"); without a line above the noise nothing is checked;
2. when the cage frequency rests on the ball-pass line alone (``f_c = BPFO / Z`` by
   construction), a line in the cage search band at ``f = BPFO / n`` for an integer n != Z,
   above the noise and with at least two lines of its family above the noise (2 f, 3 f,
   the cage modulation sidebands of the ball pass BPFO -+ f), makes Z "doubtful" (the
   record's own cage line would say n elements; not "contradicted": the QJ1044 model
   without an off-size ball, Z right, has such a family at 9.29 Hz = BPFO / 13 at CSR 0.20,
   with BPFO -+ f 11 dB below the ball pass); without one the count cannot be checked from
   the spectrum.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

#: a line at n f_c (n != Z) this many dB above the line at Z f_c contradicts Z: cage
#: harmonics of an off-size ball stand below the ball-pass line that all balls feed (with the
#: right Z, the strongest other multiple stood 0.8 dB above to 37 dB below it over the QJ1044
#: model records (0-5 um oversize ball, CSR 0.18-0.51) and impulse trains with one ball up
#: to 9 times stronger; with Z off by 1-4 for the QJ1044 model it stood 6-30 dB above)
BALL_COUNT_DB = 3.0

STATUSES = ("consistent", "contradicted", "doubtful", "not checked")


@dataclass(frozen=True)
class BallCountCheck:
    """Outcome of :func:`ball_count_check`.

    status : one of ``STATUSES``; spectrum_count : the count the spectrum points to (None
    when it points to none); message : one sentence for the printout.
    """

    status: str
    spectrum_count: int | None
    message: str


def ball_count_check(power: Callable[[float], float], level: Callable[[float], float],
                     cage_frequency: float, n_balls: int,
                     shaft_frequency: float, resolution: float, threshold: float,
                     f_end: float, search_band: tuple[float, float],
                     independent: bool) -> BallCountCheck:
    """Check Z against the spectrum (module rules).

    Parameters
    ----------
    power : normalised power of a line whose peak lies within half a bin of a frequency
        [Hz] (0 without one: the flank of a line a bin away is no line there): the
        significance of a line, compared with ``threshold``.
    level : line power on one scale for all frequencies (not over the local noise floor),
        for the dB comparisons between lines.
    cage_frequency : f_c [Hz]; n_balls : Z; shaft_frequency : f_s [Hz].
    resolution : 1 / T [Hz]; threshold : normalised power that counts as a line (the
        analyser's family-wise 0.1 % level); f_end : top of the spectrum [Hz].
    search_band : (low, high) [Hz] of the cage search; independent : a cage line or a
        shaft sideband was detected (rule 1), else rule 2.
    """
    fc, z, df = float(cage_frequency), int(n_balls), float(resolution)

    def on_shaft(f: float) -> bool:
        m = round(f / shaft_frequency)
        return m >= 1 and abs(f - m * shaft_frequency) <= df

    if independent:
        cands = [n for n in range(4, 3 * z + 4) if n * fc < f_end and not on_shaft(n * fc)]
        strong = [n for n in cands if power(n * fc) > threshold]
        if not strong:
            return BallCountCheck("not checked", None,
                                  f"no ball-pass line above the noise at multiples of "
                                  f"{fc:.4f} Hz: the count Z = {z} could not be checked")
        best = max(strong, key=lambda n: level(n * fc))
        db = 10.0 * math.log10(level(best * fc) / level(z * fc))
        if best == z or db <= BALL_COUNT_DB:
            return BallCountCheck("consistent", z,
                                  f"the ball-pass line {z} x {fc:.4f} Hz = {z * fc:.3f} Hz "
                                  f"agrees with Z = {z}")
        status = "doubtful" if best % z == 0 else "contradicted"
        more = (f" (its {best // z}-th ball-pass harmonic, or a bearing with {best} rolling "
                "elements)" if status == "doubtful" else
                f": a bearing with {best} rolling elements?")
        return BallCountCheck(status, best,
                              f"the strongest line at a multiple of the cage frequency is "
                              f"{best} x {fc:.4f} Hz = {best * fc:.3f} Hz, {db:.0f} dB above "
                              f"the ball-pass line of Z = {z} ({z * fc:.3f} Hz){more}; "
                              "check --bearing")
    # rule 2: f_c = BPFO / Z; the record's own cage line, if any, gives another count
    bpfo = z * fc
    lo, hi = search_band
    found = []
    for n in range(3, 3 * z + 4):
        f = bpfo / n
        if n == z or not lo <= f <= hi or f <= 2 * df or on_shaft(f):
            continue
        p = power(f)
        if p <= threshold:
            continue
        # a cage line has a family: its harmonics and the cage modulation of the ball
        # pass, BPFO -+ f (a model envelope holds lines in the cage band that are no cage
        # line: the QJ1044 model without an off-size ball at CSR 0.20 has one at BPFO / 13)
        family = [g for g in (2 * f, 3 * f, bpfo - f, bpfo + f)
                  if g < f_end and not on_shaft(g) and power(g) > threshold]
        if len(family) >= 2:
            found.append((p, n, f))
    if not found:
        return BallCountCheck("not checked", None,
                              f"the cage frequency rests on the ball-pass line alone "
                              f"(f_c = BPFO / Z with Z = {z} from the bearing) and no cage "
                              "line confirms it: the count could not be checked")
    p, n, f = max(found)
    return BallCountCheck("doubtful", n,
                          f"the cage frequency rests on the ball-pass line alone (BPFO "
                          f"{bpfo:.3f} Hz / Z = {z}) while a line at BPFO / {n} = {f:.4f} Hz "
                          f"stands {10 * math.log10(p):.0f} dB above the noise: a cage at "
                          f"{f:.4f} Hz (CSR {f / shaft_frequency:.4f}) with {n} rolling "
                          "elements? (or a modulation that is no cage: the QJ1044 model "
                          "without an off-size ball has such families) check --bearing")
