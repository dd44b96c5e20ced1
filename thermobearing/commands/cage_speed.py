"""``thermobearing cage-speed FILE --rpm 1800 --bearing QJ1044``: cage speed from vibration.

Reads an acceleration record (``.csv`` with a time column, or ``.npy``/one-column ``.csv``
with ``--fs``), finds the cage frequency in its envelope spectrum (paper 002 section 4.2,
:func:`thermobearing.signal.estimate_cage_speed`), prints the cage speed ratio, the cage slip
against the bearing's pure-rolling ratio and the confidence of the detection, and writes the
spectrum plot. Exit code 0 when a cage comb is detected, 3 when it is not (then no frequency
is printed).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import InputError
from ..units import to_si

if TYPE_CHECKING:  # pragma: no cover
    from .. import signal as S

NAME = "cage-speed"
HELP = "measure the cage speed ratio and slip from a vibration record (envelope spectrum)"

EXIT_NOT_DETECTED = 3


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.epilog = ("exit status: 0 cage line detected (CSR and slip with their standard "
                     "uncertainty, confidence, the element count checked against the "
                     "spectrum; 'note' lines say what the result rests on: a shaft frequency "
                     "the record does not confirm, lines read as a subharmonic, an AMBIGUOUS "
                     "reading, a BEARING whose element count the spectrum contradicts), "
                     "3 not detected (the "
                     "reason printed, no frequency), 1 bad input. "
                     "Example: thermobearing cage-speed rig.csv --rpm 1800 --bearing QJ1044")
    parser.add_argument("file", help="acceleration record: .csv/.tsv/.txt as a DAQ exports it "
                        "(time column first, then channels; comma, semicolon or tab separated, "
                        "decimal commas, header and units rows), .wav, .npy or .npz")
    parser.add_argument("--rpm", required=True,
                        help="inner-ring (shaft) speed (tachometer): a bare number is r/min; "
                             "or with a unit: '30.2 Hz' (revolutions per second), "
                             "'189.8 rad/s', '1812 rpm'")
    parser.add_argument("--bearing", required=True, help="bearing preset name or TOML path")
    parser.add_argument("--fs", default=None,
                        help="sampling rate (e.g. 25600 or '25.6 kHz'); needed unless the "
                             "file has a time column or a rate")
    parser.add_argument("--column", default=None,
                        help="column of the samples (header name, or 0-based index counting "
                             "the time column; default: the first after the time column); "
                             "for a 2-D .npy / .npz the column index")
    parser.add_argument("--contact-angle", default=None,
                        help="contact angle for the pure-rolling ratio (e.g. '40 deg'; "
                             "default: the bearing's nominal angle)")
    parser.add_argument("--band", nargs=2, type=float, metavar=("LOW", "HIGH"),
                        help="demodulation band in Hz (default: kurtogram)")
    parser.add_argument("--search", nargs=2, type=float, default=(0.3, 1.3),
                        metavar=("LOW", "HIGH"),
                        help="search range of CSR / CSR_th (default 0.3 1.3)")
    parser.add_argument("--fill-gaps", action="store_true", dest="fill_gaps",
                        help="interpolate over short dropouts (NaN / empty samples: runs of "
                             "at most 5 samples, 0.1 %% of the record in all); default: "
                             "an error that says where")
    parser.add_argument("--ball-pass-harmonics", type=int, default=None,
                        dest="ball_pass_harmonics", metavar="N",
                        help="ball-pass harmonics in the comb (default: 3, or fewer when the "
                             "sampling rate cannot carry them; the printout says so)")
    parser.add_argument("--plot", default=None,
                        help="PNG path of the spectrum plot (default: <file>_cage_speed.png)")
    parser.add_argument("--no-plot", action="store_true", help="do not write the plot")
    parser.add_argument("--json", action="store_true", help="print a JSON record instead")


def run(args: argparse.Namespace) -> int:
    from .. import signal as S  # noqa: F811  (imported here: the parser stays light)
    from ..geometry import load_bearing

    rpm = shaft_rpm(args.rpm)
    fs = None
    if args.fs is not None:
        try:
            fs = float(args.fs)  # a bare number is in Hz
        except ValueError:
            fs = to_si(args.fs, "frequency", field="--fs")
    column = args.column
    if column is not None and column.isdigit():
        column = int(column)
    if fs is not None and not (math.isfinite(fs) and fs > 0):
        raise InputError("--fs", args.fs, "a sampling rate > 0 Hz (e.g. 25600 or '25.6 kHz')")
    try:
        record = S.load_acceleration(args.file, sampling_rate=fs, column=column,
                                     fill_gaps=args.fill_gaps)
    except InputError as exc:
        if exc.field in ("column", "sampling_rate"):
            raise InputError("--column" if exc.field == "column" else "--fs", exc.value,
                             exc.allowed) from None
        raise
    bearing = load_bearing(args.bearing)
    angle = (bearing.contact_angle if args.contact_angle is None
             else _contact_angle(args.contact_angle))
    csr_th = float(bearing.theoretical_cage_speed_ratio(angle))
    n_elem = int(bearing.n_elements)
    shaft_hz = rpm / 60.0
    # the comb holds 3 ball-pass harmonics; a fast bearing with many elements puts the third
    # above what the rate allows (D1842926 at 13218 r/min: 11.9 kHz, a 47.6 kHz rate): then
    # fewer, unless the user fixed the number
    tries = ([args.ball_pass_harmonics] if args.ball_pass_harmonics is not None
             else [3, 2, 1])
    for harmonics in tries:
        try:
            est = S.estimate_cage_speed(record.data, record.sampling_rate, shaft_hz, n_elem,
                                        csr_th, band=tuple(args.band) if args.band else None,
                                        search=tuple(args.search),
                                        ball_pass_harmonics=harmonics)
            break
        except InputError as exc:
            if exc.field != "sampling_rate" or harmonics == tries[-1]:
                raise _as_option(exc, args, record) from None
    plot_path = None
    if not args.no_plot:
        plot_path = Path(args.plot) if args.plot else Path(args.file).with_name(
            Path(args.file).stem + "_cage_speed.png")
        _plot(est, record, plot_path, bearing.name)
    if args.json:
        rec = _record(est, record, bearing.name, plot_path)
        rec["ball_pass_harmonics"] = harmonics
        print(json.dumps(rec, indent=1))
    else:
        _print(est, record, bearing.name, plot_path,
               element="ball" if hasattr(bearing, "n_balls") else "roller")
        if args.ball_pass_harmonics is None and harmonics < 3:
            print(f"note        comb reduced to {harmonics} ball-pass harmonic(s): "
                  f"{record.sampling_rate:g} Hz cannot carry 3 of this bearing at this speed")
    return 0 if est.detected else EXIT_NOT_DETECTED


#: fraction of samples at the record's extremes above which the printout says "clipped"
CLIP_NOTE = 1e-3


def clipped_fraction(x) -> float:
    """Fraction of the samples that sit at the record's maximum or minimum (within 1e-9 of
    the range): a clipped (saturated) record has a run of them, an unclipped one about
    2 / n."""
    import numpy as np

    a = np.asarray(x, dtype=float)
    lo, hi = float(a.min()), float(a.max())
    tol = 1e-9 * max(hi - lo, 1e-300)
    return float(np.count_nonzero((a >= hi - tol) | (a <= lo + tol))) / a.size


def _as_option(exc: InputError, args: argparse.Namespace,
               record: S.AccelerationRecord) -> InputError:
    """The analyser's error named by the command's option (``band`` -> ``--band``); a rate
    read from the file says so (an .npz rate in kHz, 25.6, is read as Hz)."""
    if exc.field == "sampling_rate" and args.fs is None:
        return InputError(f"sampling rate of {Path(record.source).name}", exc.value,
                          f"{exc.allowed} (the rate is the file's: its time column, WAV "
                          "header or .npz 'sampling_rate' / 'fs' array, in Hz)")
    if exc.field == "signal.duration":
        hint = ""
        try:
            bare = float(args.rpm)
        except ValueError:
            pass
        else:  # a short record refused for a slow shaft: the speed may be in Hz
            if bare < 600.0:
                hint = (f"; --rpm {args.rpm} is read as r/min ({bare / 60:.4g} Hz shaft): "
                        f"if {args.rpm} is in Hz, write --rpm '{args.rpm} Hz'")
        return InputError(f"duration of {Path(record.source).name}", f"{exc.value:.4g} s",
                          f"{exc.allowed}; or a higher --search LOW (default 0.3: "
                          f"the cage searched from 0.3 CSR_th f_shaft up){hint}")
    option = {"sampling_rate": "--fs", "band": "--band", "search": "--search",
              "ball_pass_harmonics": "--ball-pass-harmonics"}.get(exc.field)
    if option == "--fs":
        return InputError(option, args.fs, f"{exc.allowed}; a bare --fs is in Hz (25.6 kHz: "
                          "--fs 25600 or --fs '25.6 kHz')")
    return InputError(option, exc.value, exc.allowed) if option else exc


def shaft_rpm(text) -> float:
    """--rpm [r/min]: a bare number is r/min; a unit string converts, a frequency without
    an angle (``30.2 Hz``, ``1/s``) counting revolutions per second (pint alone reads
    ``30.2 Hz`` as 30.2 rad/s)."""
    from ..units import cycles_per_time, quantity_unit

    allowed = ("a shaft speed > 0: r/min as a bare number, or with a unit: '1812 rpm', "
               "'30.2 Hz' (revolutions per second), '189.8 rad/s'")
    try:
        rpm = float(text)
    except ValueError:
        unit = quantity_unit(text)
        try:
            if unit and cycles_per_time(unit):
                rpm = 60.0 * to_si(text, "frequency", field="--rpm")
            else:
                rpm = to_si(text, "angular_speed", field="--rpm") * 30.0 / math.pi
        except InputError:
            raise InputError("--rpm", text, allowed) from None
    if not (math.isfinite(rpm) and rpm > 0):
        raise InputError("--rpm", text, allowed)
    return rpm


def _contact_angle(text: str) -> float:
    """--contact-angle [rad] from '40 deg' (a unit is required: a bare 40 would be 40 rad,
    which gave CSR_th 0.5416 instead of 0.4522 for the QJ1044); 0 <= angle < 90 deg."""
    try:
        float(text)
    except ValueError:
        pass
    else:
        raise InputError("--contact-angle", text, f"an angle with a unit, e.g. '{text} deg'")
    angle = to_si(text, "angle", field="--contact-angle")
    if not 0.0 <= angle < 0.5 * math.pi:
        raise InputError("--contact-angle", text, "an angle in [0, 90) deg")
    return angle


def _record(est: S.CageSpeedEstimate, record: S.AccelerationRecord, name: str,
            plot: Path | None) -> dict:
    return {
        "file": record.source, "channel": record.channel or None,
        "gaps_filled": record.gaps_filled,
        "sampling_rate_hz": record.sampling_rate,
        "duration_s": record.duration, "bearing": name,
        "shaft_frequency_hz": est.shaft_frequency,
        "measured_shaft_frequency_hz": est.measured_shaft_frequency,
        "csr_theoretical": est.csr_theoretical, "detected": est.detected,
        "cage_frequency_hz": est.cage_frequency, "csr": est.csr, "slip": est.slip,
        "ball_pass_frequency_hz": est.ball_pass_frequency,
        "cage_frequency_uncertainty_hz": est.cage_frequency_uncertainty,
        "csr_uncertainty": est.csr_uncertainty, "slip_uncertainty": est.slip_uncertainty,
        "uncertainty_birge_ratio": (est.frequency_fit.birge if est.frequency_fit is not None
                                    else None),
        "ambiguous": est.ambiguous, "shaft_confirmed": est.shaft_confirmed,
        "ball_count_check": est.ball_count.status if est.ball_count else None,
        "ball_count_in_spectrum": est.ball_count.spectrum_count if est.ball_count else None,
        "ball_count_message": est.ball_count.message if est.ball_count else None,
        "confidence": est.confidence,
        "false_alarm_probability": est.false_alarm_probability,
        "bands_hz": list(est.spectrum.bands or (est.spectrum.band,)), "reason": est.reason,
        "lines": [{"kind": ln.kind, "order": list(ln.order), "expected_hz": ln.expected,
                   "measured_hz": None if math.isnan(ln.measured) else ln.measured,
                   "snr": None if math.isnan(ln.snr) else ln.snr,
                   "detected": ln.detected} for ln in est.lines],
        "plot": str(plot) if plot else None,
        "clipped_fraction": clipped_fraction(record.data),
        "notes": list(est.notes),
    }


def _print(est: S.CageSpeedEstimate, record: S.AccelerationRecord, name: str,
           plot: Path | None, element: str = "ball") -> None:
    bands = ", ".join(f"{lo:.0f}-{hi:.0f} Hz" for lo, hi in
                      (est.spectrum.bands or (est.spectrum.band,)))
    chan = f" [{record.channel}]" if record.channel else ""
    more = (f"; channel {record.channel!r} of {record.n_channels} (--column picks another)"
            if record.n_channels > 1 else "")
    print(f"record      {record.source}{chan}: {record.data.size} samples at "
          f"{record.sampling_rate:g} Hz ({record.duration:.3g} s){more}")
    meas = est.measured_shaft_frequency
    print(f"bearing     {name}: CSR_th = {est.csr_theoretical:.4f}; shaft "
          f"{est.shaft_frequency:.4g} Hz = {60 * est.shaft_frequency:.5g} r/min" + (
              f" (envelope line at {meas:.4f} Hz, "
              f"{100 * (meas / est.shaft_frequency - 1):+.2f} %)" if meas else ""))
    print(f"bands       {bands}")
    if record.gaps_filled:
        print(f"note        {record.gaps_filled} missing sample(s) filled by linear "
              "interpolation (--fill-gaps)")
    clip = clipped_fraction(record.data)
    if clip > CLIP_NOTE:
        print(f"note        the record looks clipped: {100 * clip:.2g} % of the samples sit at "
              "its extreme values (input range of the DAQ?); the frequencies are still "
              "measured, amplitudes are not")
    if est.detected:
        u_fc, u_csr, u_slip = (est.cage_frequency_uncertainty, est.csr_uncertainty,
                               est.slip_uncertainty)
        print(f"cage        {est.cage_frequency:.4f} Hz{_pm(u_fc, ' Hz')}   "
              f"({element} pass {est.ball_pass_frequency:.3f} Hz = BPFO)")
        print(f"CSR         {est.csr:.4f}{_pm(u_csr)}" + (
            "  (+- one standard uncertainty of the frequency measurement, from the lines' "
            "SNR and the record length; the shaft speed's own error is not in it)"
            if u_csr is not None else ""))
        pct = 100 * est.slip if round(100 * est.slip, 2) != 0 else 0.0  # no "-0.00"
        kind = "pure rolling" if pct == 0 else "over-skidding" if pct < 0 else "skidding"
        print(f"slip        {pct:+.2f} %{_pm(None if u_slip is None else 100 * u_slip, ' %')}"
              f"  ({kind}; s = 1 - CSR/CSR_th)")
        print(f"confidence  {est.confidence:.3f}  (false-alarm probability "
              f"{est.false_alarm_probability:.2g}, of the cage comb)"
              + ("; AMBIGUOUS: see the notes" if est.ambiguous else ""))
        bc = est.ball_count
        if bc is not None:
            z = est.ball_pass_frequency / est.cage_frequency
            print(f"elements    Z = {z:.0f}: " + (
                f"consistent with the spectrum ({bc.message})" if bc.status == "consistent"
                else f"{bc.status.upper()} by the spectrum (see the note)"
                if bc.status in ("contradicted", "doubtful")
                else "not checked (see the note)"))
        for note in est.notes:
            print(f"note        {note}")
    else:
        print(f"cage        NOT DETECTED: {est.reason}")
    print("lines:")
    for ln in est.lines:
        meas = "-" if math.isnan(ln.measured) else f"{ln.measured:.4f}"
        snr = "-" if math.isnan(ln.snr) else f"{ln.snr:.1f}"
        print(f"  {ln.kind:<19} k={ln.order[0]:<3} n={ln.order[1]}  expected "
              f"{ln.expected:9.4f} Hz  measured {meas:>10}  snr {snr:>8}"
              f"{'  *' if ln.detected else ''}")
    if plot:
        print(f"plot        {plot}")


def _pm(u: float | None, unit: str = "") -> str:
    """`` +- u`` with two significant digits (empty without an uncertainty)."""
    return "" if u is None else f" +- {u:.2g}{unit}"


def _peak_hold(f, a, points: int = 6000):
    """At most ~``points`` (f, max of a) pairs: a long record's spectrum has millions of bins
    (60 s at 51.2 kHz: 1.5 M), more than a figure shows and slow to draw; the maximum
    over each group of bins keeps every line visible."""
    import numpy as np

    k = max(1, int(np.ceil(a.size / points)))
    if k == 1:
        return f, a
    m = a.size // k
    return f[:m * k:k], a[:m * k].reshape(m, k).max(axis=1)


def _plot(est: S.CageSpeedEstimate, record: S.AccelerationRecord, path: Path,
          name: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    es = est.spectrum
    fig, (ax0, ax1) = plt.subplots(2, 1, figsize=(9, 7), constrained_layout=True)
    x = record.data - record.data.mean()
    win = np.hanning(x.size)
    a = np.abs(np.fft.rfft(x * win)) * 2.0 / win.sum()
    f = np.fft.rfftfreq(x.size, 1.0 / record.sampling_rate)
    f, a = _peak_hold(f, a)
    ax0.semilogy(f, np.maximum(a, 1e-300), lw=0.6)
    ax0.set_xlabel("frequency [Hz]")
    ax0.set_ylabel("amplitude [unit of the record]")
    ax0.set_title(f"{Path(record.source).name}: spectrum ({name})")
    for lo, hi in es.bands or (es.band,):
        ax0.axvspan(lo, hi, color="tab:orange", alpha=0.2)
    fe, re_ = _peak_hold(es.frequency, es.normalised)
    ax1.semilogy(fe, np.maximum(re_, 1e-2), lw=0.7, color="k")
    ax1.set_ylim(bottom=0.1)
    ax1.set_xlim(0.0, float(es.frequency[-1]))
    ax1.set_xlabel("frequency [Hz]")
    ax1.set_ylabel("envelope power / noise floor [-]")
    colours = {"cage": "tab:red", "ball_pass": "tab:blue", "ball_pass_sideband": "tab:cyan",
               "sideband": "tab:green", "shaft": "tab:purple"}
    for ln in est.lines:
        if ln.detected:
            ax1.axvline(ln.measured, color=colours.get(ln.kind, "grey"), lw=0.8, ls="--",
                        alpha=0.8, label=ln.kind)
    handles, labels = ax1.get_legend_handles_labels()
    uniq = dict(zip(labels, handles, strict=True))
    if uniq:
        ax1.legend(uniq.values(), uniq.keys(), loc="upper right", fontsize=8)
    title = (f"CSR = {est.csr:.4f}{_pm(est.csr_uncertainty)}, slip {100 * est.slip:+.2f} %, "
             f"confidence "
             f"{est.confidence:.2f}" if est.detected else "cage line not detected")
    ax1.set_title("squared-envelope spectrum: " + title)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
