"""Vibration records in: reading acceleration files and validating sampled signals.

One job: turn a ``.npy``/``.npz``/``.csv`` file or an array into a checked, uniformly
sampled record (:class:`AccelerationRecord`, :func:`load_acceleration`,
:func:`check_signal`) for the envelope analysis of :mod:`thermobearing.signal`.
The layout detection of delimited DAQ exports (:func:`read_text_lines`,
:func:`guess_separator`, :func:`guess_decimal_mark`, :func:`split_cells`,
:func:`is_units_row`) is shared with :mod:`thermobearing.measured` (thermocouple files).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .errors import InputError
from .text_files import text_encoding

#: minimum number of samples an analysis accepts.
MIN_SAMPLES = 256


@dataclass(frozen=True)
class AccelerationRecord:
    """A uniformly sampled acceleration record.

    Attributes
    ----------
    data : samples [m/s^2] (or any consistent unit: the analysis is scale-free).
    sampling_rate : [Hz].
    source : file name or description.
    channel : the column (header name, ``column k`` or ``[:, k]``) the samples come from,
        "" for a one-channel file; n_channels : channels in the file (time column excluded).
    gaps_filled : missing samples filled by interpolation (``load_acceleration(fill_gaps=True)``).
    """

    data: np.ndarray
    sampling_rate: float
    source: str = ""
    channel: str = ""
    n_channels: int = 1
    gaps_filled: int = 0

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
    try:
        arr = np.asarray(x, dtype=float)
    except (TypeError, ValueError):  # a VibrationResult, a file name...: say what is expected
        raise InputError(field, type(x).__name__, "a one-dimensional record of samples (of a "
                         "VibrationResult: its acceleration_x; a file: load_acceleration)"
                         ) from None
    if arr.ndim != 1:
        raise InputError(f"{field}.shape", arr.shape, "a one-dimensional record")
    if arr.size < MIN_SAMPLES:
        raise InputError(f"{field}.length", arr.size, f"at least {MIN_SAMPLES} samples")
    bad = ~np.isfinite(arr)
    if bad.any():
        raise InputError(f"{field}", f"{int(bad.sum())} NaN/inf samples (first at index "
                         f"{int(np.argmax(bad))})", "finite samples only (the analysis needs a "
                         "gap-free record: cut it before the first bad sample or fill short "
                         "gaps: load_acceleration(fill_gaps=True), cage-speed --fill-gaps)")
    spread = float(np.ptp(arr))
    scale = max(float(np.max(np.abs(arr))), 1e-300)
    if spread <= 1e-12 * scale or spread == 0.0:
        raise InputError(f"{field}", "a constant signal", "a signal that varies in time")
    return arr


def load_acceleration(path: str | Path, sampling_rate: float | None = None,
                      column: int | str | None = None, *,
                      fill_gaps: bool = False) -> AccelerationRecord:
    """Read an acceleration record from ``.npy``, ``.npz``, ``.csv``, ``.tsv`` or ``.txt``.

    Parameters
    ----------
    path : file. ``.npy``: a 1-D array, or a 2-D array of channels in columns (pick one
        with ``column``); ``sampling_rate`` required. ``.npz``: arrays ``acceleration`` (or
        ``data``/``x``) and ``sampling_rate`` (or ``fs``). ``.wav``: the rate from the file,
        channels in columns (pick one with ``column``). ``.csv``/``.tsv``/``.txt`` as
        data-acquisition software exports them: comma, semicolon, tab or space separated,
        decimal commas (with a semicolon, tab or space separator), a header row of channel
        names (more text rows above it and a units row below it are skipped), ``#`` comment
        lines. A first column that increases uniformly is a time column [s] (``Time [ms]``
        or a units row ``ms`` gives its unit): the rate is (n - 1) / time span and every
        step must be within half a step of the mean (no gaps); a sample counter 0, 1, 2, ...
        is no time column. Without ``column`` the samples are the second column (the first
        after the time), or the only one. Empty cells are missing samples: an error that
        says where (the analysis needs a gap-free record).
    sampling_rate : [Hz]; overrides nothing: if the file carries a rate that differs by
        more than 1e-4 relative, that is an error.
    column : column (index or header name, also a name of the units row) holding the
        samples; for a 2-D ``.npy``/``.npz`` the column index.
    fill_gaps : fill isolated missing samples (NaN, empty cells: DAQ dropouts) by linear
        interpolation between their neighbours, when each gap is at most
        ``MAX_GAP_SAMPLES`` samples and all together at most ``MAX_GAP_FRACTION`` of the
        record (else the error stands); the count is in ``gaps_filled``. Default False: a
        missing sample is an error that says where.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError("file", str(p),
                         "an existing .npy, .npz or .csv file (or .wav, .tsv, .txt)")
    suffix = p.suffix.lower()
    file_rate: float | None = None
    no_rate = "the file carries no time column"
    channel, n_channels = "", 1
    if suffix in (".npy", ".npz", ".wav"):
        if suffix == ".npy":
            data = _np_load(p)
        elif suffix == ".wav":
            from scipy.io import wavfile

            try:
                wav_rate, data = wavfile.read(p)
            except ValueError as exc:
                raise InputError("file", str(p), f"a PCM or float WAV file ({exc})") from None
            file_rate = float(wav_rate)
        else:
            with _np_load(p) as z:
                key = next((k for k in ("acceleration", "data", "x") if k in z), None)
                if key is None:
                    raise InputError("file", str(p), "an .npz with an 'acceleration' array")
                data = _np_array(z, key, p)
                rk = next((k for k in ("sampling_rate", "fs") if k in z), None)
                file_rate = _npz_rate(_np_array(z, rk, p), p, rk) if rk else None
        if np.iscomplexobj(data):
            raise InputError("file", str(p), f"real samples (the array is {data.dtype}: "
                             "save its real part, or its magnitude)")
        if np.ndim(data) == 2 and 1 in np.shape(data):
            data = np.ravel(data)
        elif np.ndim(data) == 2:
            n_channels = int(np.shape(data)[1])
            if column is None or isinstance(column, str) or not (
                    0 <= int(column) < n_channels):
                raise InputError("column", column, f"a column index in [0, {n_channels - 1}] "
                                 f"(the array has {n_channels} channels in columns, shape "
                                 f"{np.shape(data)})")
            channel = f"[:, {int(column)}]"
            data = np.asarray(data)[:, int(column)]
        elif column is not None:
            raise InputError("column", column, "nothing: the array holds one channel")
    elif suffix in (".csv", ".txt", ".tsv", ".dat"):
        data, file_rate, why, channel, n_channels = _read_csv(p, column)
        no_rate = why or no_rate
    else:
        raise InputError("file", str(p), "a .npy, .npz, .wav, .csv, .tsv or .txt file")
    if file_rate is not None and sampling_rate is not None:
        if abs(file_rate - sampling_rate) > 1e-4 * sampling_rate:
            raise InputError("sampling_rate", sampling_rate,
                             f"the rate of the file ({file_rate:g} Hz) or none")
    rate = sampling_rate if sampling_rate is not None else file_rate
    if rate is None:
        raise InputError("sampling_rate", None, f"a sampling rate in Hz ({no_rate})")
    filled = 0
    if fill_gaps:
        data, filled = _fill_gaps(np.asarray(data, dtype=float), p.name)
    try:
        arr = check_signal(data, float(rate), field=p.name)
    except InputError as exc:
        if n_channels < 2 or not channel:
            raise
        # a dead channel of several (a constant or NaN column): name it and the way out
        raise InputError(f"{p.name} channel {channel!r}", exc.value,
                         f"{exc.allowed}; the file has {n_channels} channels: pick another "
                         "with column= (cage-speed --column)") from None
    return AccelerationRecord(arr, float(rate), str(p), channel, n_channels, filled)


def _np_load(p: Path) -> Any:
    """``np.load`` without pickles; a file NumPy cannot read (not .npy / .npz, cut short,
    an object array that needs pickle) is an InputError naming it."""
    import zipfile

    try:
        return np.load(p, allow_pickle=False)
    except (ValueError, OSError, EOFError, zipfile.BadZipFile) as exc:
        raise InputError("file", str(p), f"a NumPy {p.suffix} file of numbers ({exc})"
                         ) from None


def _np_array(z: Any, key: str, p: Path) -> np.ndarray:
    """Array ``key`` of an .npz (an object array, which needs pickle: an InputError)."""
    try:
        return z[key]
    except ValueError as exc:
        raise InputError(f"{p.name}[{key!r}]", "an object array", f"numbers ({exc})") from None


def _npz_rate(value: np.ndarray, p: Path, key: str) -> float:
    """The sampling rate [Hz] an .npz gives: one real number."""
    arr = np.asarray(value)
    if arr.size != 1 or not np.issubdtype(arr.dtype, np.number) or np.iscomplexobj(arr):
        raise InputError(f"{p.name}[{key!r}]", f"{arr.dtype} array of shape {arr.shape}",
                         "one number: the sampling rate in Hz")
    return float(arr.reshape(()))


def _uniform_ramp(t: np.ndarray) -> bool:
    """A column that increases in steps within half a step of their mean (a time column)."""
    dt = np.diff(t)
    if dt.size < 2 or not np.all(dt > 0):
        return False
    mean = float(t[-1] - t[0]) / dt.size
    return bool(np.max(np.abs(dt - mean)) <= 0.5 * mean)


#: longest run of missing samples ``fill_gaps`` interpolates over
MAX_GAP_SAMPLES = 5
#: largest share of missing samples ``fill_gaps`` accepts
MAX_GAP_FRACTION = 1e-3


def _fill_gaps(x: np.ndarray, name: str) -> tuple[np.ndarray, int]:
    """Linear interpolation over short runs of non-finite samples (see load_acceleration)."""
    bad = ~np.isfinite(x)
    n_bad = int(bad.sum())
    if n_bad == 0 or x.ndim != 1:
        return x, 0
    edges = np.diff(np.concatenate([[0], bad.astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    longest = int(np.max(ends - starts))
    if longest > MAX_GAP_SAMPLES or n_bad > MAX_GAP_FRACTION * x.size or bad[0] or bad[-1]:
        k = int(starts[int(np.argmax(ends - starts))])
        raise InputError(name, f"{n_bad} missing samples, the longest run {longest} at index "
                         f"{k}", f"gaps of at most {MAX_GAP_SAMPLES} samples, "
                         f"{100 * MAX_GAP_FRACTION:g} % of the record in all, not at its ends, "
                         "to be filled (cut the record around longer dropouts)")
    idx = np.arange(x.size)
    out = x.copy()
    out[bad] = np.interp(idx[bad], idx[~bad], x[~bad])
    return out, n_bad


#: header words that mark the first column as a time column
_TIME_WORDS = ("time", "zeit", "temps", "tiempo", "t")
#: header words that mark the first column as a sample counter (not a time)
_INDEX_WORDS = ("sample", "samples", "index", "idx", "n", "no", "nr", "#", "point", "points")
#: lines read to find the layout (delimiter, decimal mark, header and units rows)
_SNIFF_LINES = 200


@dataclass(frozen=True)
class _CsvLayout:
    sep: str  # "," ";" "\t" or r"\s+"
    decimal: str  # "." or ","
    skip: int  # raw lines before the first data row
    header: list[str] | None  # column names (first text row with one cell per column)
    units: list[str] | None  # a second text row with one cell per column (a units row)
    ncol: int


def split_cells(line: str, sep: str) -> list[str]:
    """The cells of one line of a delimited text file, stripped of spaces and quotes
    (``sep``: ``","``, ``";"``, ``"\\t"`` or ``r"\\s+"``; no quoted separators)."""
    cells = line.split() if sep == r"\s+" else line.split(sep)
    return [c.strip().strip('"').strip("'").strip() for c in cells]


_split = split_cells


def read_text_lines(p: Path, max_lines: int | None = None, *,
                    encoding: str = "utf-8-sig") -> list[tuple[int, str]]:
    """The non-blank lines of a text file that are no ``#`` comment, as (0-based line
    index, text without the line end): UTF-8 with or without BOM (or ``encoding``), LF or
    CRLF line ends (undecodable bytes replaced). At most ``max_lines`` lines when given."""
    raw: list[tuple[int, str]] = []
    with p.open(encoding=encoding, errors="replace", newline="") as fh:
        for i, line in enumerate(fh):
            line = line.rstrip("\r\n")
            if line.strip() and not line.lstrip().startswith("#"):
                raw.append((i, line))
            if max_lines is not None and len(raw) >= max_lines:
                break
    return raw


def guess_separator(lines: list[str]) -> str:
    """The column separator of a DAQ export: tab if any line has one, else semicolon,
    else comma, else runs of spaces (``r"\\s+"``)."""
    return "\t" if any("\t" in ln for ln in lines) else ";" if any(";" in ln for ln in lines) \
        else "," if any("," in ln for ln in lines) else r"\s+"


#: magnitude from which a number is an instrument's overload code, not a reading (the
#: +9.9E+37 of Keysight/Agilent DAQs for an open channel; measured.OVERLOAD_CODE)
OVERLOAD_MAGNITUDE = 1e30


def _dot_decimal(cell: str) -> bool:
    """A cell that reads as a number with a decimal point (``12.5``), other than an
    overload code: the instrument writes those with a point in any locale, so a
    ``+9.9E+37`` among ``21,5`` readings is no sign of a decimal point."""
    if not re.match(r"^[+-]?\d*\.\d+", cell):
        return False
    try:
        return abs(float(cell)) < OVERLOAD_MAGNITUDE
    except ValueError:
        return True


def guess_decimal_mark(cells: list[str], sep: str) -> str:
    """``","`` when ``sep`` is not a comma, some cells look like ``12,5`` and none like
    ``12.5`` (an overload code such as ``+9.9E+37`` not counted: :func:`_dot_decimal`);
    else ``"."``."""
    if sep == ",":
        return "."
    num_comma = re.compile(r"^[+-]?\d*,\d+([eE][+-]?\d+)?$")
    if any(num_comma.match(c) for c in cells) and not any(_dot_decimal(c) for c in cells):
        return ","
    return "."


def _is_number(cell: str, decimal: str) -> bool:
    if cell == "":
        return True  # a missing sample (reported as NaN later), not a header cell
    try:
        float(cell.replace(",", ".") if decimal == "," else cell)
    except ValueError:
        return cell.lower() in ("nan", "-nan", "inf", "-inf")
    return True


def _sniff(p: Path) -> _CsvLayout:
    """Delimiter, decimal mark, header/units rows of a DAQ export (first lines only)."""
    raw = read_text_lines(p, _SNIFF_LINES, encoding=text_encoding(p))
    if not raw:
        raise InputError("file", str(p), "a CSV with at least one row of numbers")
    body = [ln for _, ln in raw]
    sep = guess_separator(body)
    decimal = guess_decimal_mark([c for ln in body for c in _split(ln, sep)], sep)
    first_data = next((k for k, ln in enumerate(body)
                       if all(_is_number(c, decimal) for c in _split(ln, sep))
                       and any(c for c in _split(ln, sep))), None)
    if first_data is None:
        raise InputError("file", str(p), f"rows of numbers within its first {_SNIFF_LINES} "
                         f"lines (separator {_sep_name(sep)!r}, decimal mark {decimal!r})")
    ncol = len(_split(body[first_data], sep))
    texts = [_split(ln, sep) for ln in body[:first_data]]
    texts = [t for t in texts if len(t) == ncol]  # metadata lines above have other counts
    # the channel names are the text row next to the data, or the one above a units row
    units = texts.pop() if len(texts) >= 2 and _is_units_row(texts[-1]) else None
    header = texts[-1] if texts else None
    return _CsvLayout(sep, decimal, raw[first_data][0], header, units, ncol)


def is_units_row(cells: list[str]) -> bool:
    """True when every non-empty cell parses as a unit (``s``, ``m/s²``, ``[g]``, ``mV``)
    and at least one is not empty: a units row below the channel names."""
    from .units import unit_registry

    ureg = unit_registry()
    seen = False
    for c in cells:
        c = c.strip().strip("[]()").replace("²", "**2").replace("³", "**3")
        c = re.sub(r"([A-Za-z])([23])\b", r"\1**\2", c.replace("µ", "u").replace("μ", "u"))
        if not c or c in ("-", "%"):
            continue
        try:
            q = ureg.parse_expression(c)
        except Exception:  # noqa: BLE001 - pint raises many kinds for a non-unit word
            return False
        if not hasattr(q, "units") or getattr(q, "magnitude", 1) != 1:
            return False
        seen = True
    return seen


_is_units_row = is_units_row


def _sep_name(sep: str) -> str:
    return {"\t": "tab", r"\s+": "spaces"}.get(sep, sep)


def _time_scale(layout: _CsvLayout, p: Path) -> float | None:
    """Seconds per unit of the first column when its header or units row names a time unit
    (``Time [ms]``, ``t (us)``, a units row ``ms``); 1.0 for a bare ``time``; None when the
    header says nothing about time."""
    unit = None
    name = layout.header[0] if layout.header else ""
    m = re.search(r"[\[(]\s*([^\])]+?)\s*[\])]", name)
    if m:
        unit = m.group(1)
    elif layout.units and layout.units[0]:
        unit = layout.units[0]
    word = re.split(r"[\s\[(_/]", name.strip().lower(), maxsplit=1)[0] if name else ""
    if unit is None:
        return 1.0 if word in _TIME_WORDS else None
    unit = unit.replace("µ", "u").replace("μ", "u")
    try:
        from .units import to_si

        return to_si(f"1 {unit}", "time", field=f"{p.name} time column unit")
    except InputError:
        return 1.0 if word in _TIME_WORDS else None


def _read_csv(p: Path, column: int | str | None
              ) -> tuple[np.ndarray, float | None, str | None, str, int]:
    """Samples, the rate from a time column (or None), why there is no rate (or None), the
    name of the channel read and the number of channels (time column excluded).

    Reads what data-acquisition software exports: comma, semicolon, tab or space separated
    columns, decimal commas (with ``;``/tab/space separators), a header row of channel names,
    more text rows above it or a units row below it (skipped), ``#`` comment lines, empty
    cells (missing samples: NaN, reported by :func:`check_signal`). The first column is a
    time column when it increases uniformly (its unit from ``Time [ms]`` or a units row;
    seconds otherwise); a sample counter (0, 1, 2, ... or 1, 2, 3, ...) is not a time.
    """
    import pandas as pd

    layout = _sniff(p)
    try:
        df = pd.read_csv(p, sep=layout.sep, decimal=layout.decimal, skiprows=layout.skip,
                         header=None, comment="#", skip_blank_lines=True,
                         encoding=text_encoding(p), encoding_errors="replace", engine="c",
                         skipinitialspace=True, na_values=["", "nan", "NaN"],
                         keep_default_na=True)
    except (ValueError, pd.errors.ParserError) as exc:
        raise InputError("file", str(p), f"rows of {layout.ncol} values separated by "
                         f"{_sep_name(layout.sep)!r} ({str(exc).strip()})") from None
    if df.shape[1] > layout.ncol and df.iloc[:, layout.ncol:].isna().all().all():
        df = df.iloc[:, :layout.ncol]  # a trailing separator on every line
    for j in range(df.shape[1]):
        if df.dtypes.iloc[j].kind not in "fiu":
            col = df.iloc[:, j]
            bad = pd.to_numeric(col.astype(str).str.replace(",", ".") if layout.decimal == ","
                                else col, errors="coerce").isna() & col.notna()
            k = int(np.argmax(bad.to_numpy()))
            raise InputError("file", str(p), f"numbers in every data row (data row {k + 1}, "
                             f"column {j + 1}: {col.iloc[k]!r}; separator "
                             f"{_sep_name(layout.sep)!r}, decimal mark {layout.decimal!r})")
    table = df.to_numpy(dtype=float)
    if table.ndim != 2 or table.shape[0] == 0:
        raise InputError("file", str(p), "a CSV with rows of equal length")
    ncol = table.shape[1]
    header = layout.header
    names = header if header is not None and len(header) == ncol else [
        f"column {j}" for j in range(ncol)]
    if column is not None:
        if isinstance(column, str):
            rows = [r for r in (layout.header, layout.units) if r is not None]
            hit = next((r.index(column) for r in rows if column in r), None)
            if hit is None:
                lowered = [[c.lower() for c in r] for r in rows]
                hit = next((r.index(column.lower()) for r in lowered if column.lower() in r),
                           None)
            if hit is None:
                raise InputError("column", column, f"one of the header names {header}"
                                 if header else "a column index (the file has no header row)")
            idx = hit
        else:
            idx = int(column)
            if not 0 <= idx < ncol:
                raise InputError("column", column, f"an index in [0, {ncol - 1}] "
                                 f"(columns: {names})")
    else:
        idx = 0 if ncol == 1 else 1
    if idx == 0 and ncol >= 2 and column is not None and (
            _time_scale(layout, p) is not None or _uniform_ramp(table[:, 0])):
        raise InputError("column", column, f"a channel, not the time column {names[0]!r} "
                         f"(channels: {names[1:]})")
    samples = table[:, idx]
    rate = None
    why = None
    if ncol >= 2 and idx != 0:
        t = table[:, 0]
        dt = np.diff(t)
        scale = _time_scale(layout, p)
        counter = (dt.size > 0 and bool(np.all(dt == 1.0)) and t[0] in (0.0, 1.0)
                   and scale is None) or (header is not None and header[0].strip().lower()
                                          in _INDEX_WORDS)
        if counter:
            why = (f"its first column {names[0]!r} counts samples (0, 1, 2, ...), it is no "
                   "time column")
        elif dt.size and not np.all(dt > 0):
            k = int(np.argmax(~(dt > 0)))
            why = (f"the first column is no time column: it does not increase at data row "
                   f"{k + 2} ({t[k + 1]:g} after {t[k]:g})")
        elif dt.size:
            # rate from the span (robust to the print precision of the time column); steps
            # that deviate by more than half a step mean missing or irregular samples
            mean_dt = float(t[-1] - t[0]) / dt.size
            if np.max(np.abs(dt - mean_dt)) > 0.5 * mean_dt:
                k = int(np.argmax(np.abs(dt - mean_dt)))
                raise InputError("file time column", "non-uniform time steps "
                                 f"({t[k + 1]:g} after {t[k]:g} at data row {k + 2}; mean "
                                 f"step {mean_dt:g})", "uniform sampling (no gaps)")
            rate = 1.0 / (mean_dt * (scale if scale is not None else 1.0))
    n_channels = ncol - 1 if rate is not None else ncol
    return samples, rate, why, (names[idx] if ncol > 1 else ""), n_channels
