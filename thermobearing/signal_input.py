"""Vibration records in: reading acceleration files and validating sampled signals.

One job: turn a ``.npy``/``.npz``/``.csv`` file or an array into a checked, uniformly
sampled record (:class:`AccelerationRecord`, :func:`load_acceleration`,
:func:`check_signal`) for the envelope analysis of :mod:`thermobearing.signal`.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import InputError

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
    no_rate = "the file carries no time column"
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
        data, file_rate, why = _read_csv(p, column)
        no_rate = why or no_rate
    else:
        raise InputError("file", str(p), "a .npy, .npz or .csv file")
    if file_rate is not None and sampling_rate is not None:
        if abs(file_rate - sampling_rate) > 1e-4 * sampling_rate:
            raise InputError("sampling_rate", sampling_rate,
                             f"the rate of the file ({file_rate:g} Hz) or none")
    rate = sampling_rate if sampling_rate is not None else file_rate
    if rate is None:
        raise InputError("sampling_rate", None, f"a sampling rate in Hz ({no_rate})")
    arr = check_signal(np.ravel(data) if np.ndim(data) == 2 and 1 in np.shape(data) else data,
                       float(rate), field=p.name)
    return AccelerationRecord(arr, float(rate), str(p))


def _read_csv(p: Path, column: int | str | None
              ) -> tuple[np.ndarray, float | None, str | None]:
    """Samples, the rate from a time column (or None) and why there is no rate (or None)."""
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
    why = None
    if ncol >= 2 and (column is None or column != 0):
        t = table[:, 0]
        dt = np.diff(t)
        if dt.size and not np.all(dt > 0):
            k = int(np.argmax(~(dt > 0)))
            why = (f"the first column is no time column: it does not increase at data row "
                   f"{k + 2} ({t[k + 1]:g} after {t[k]:g})")
        if dt.size and np.all(dt > 0):
            # rate from the span (robust to the print precision of the time column); steps
            # that deviate by more than half a step mean missing or irregular samples
            mean_dt = float(t[-1] - t[0]) / dt.size
            if np.max(np.abs(dt - mean_dt)) > 0.5 * mean_dt:
                raise InputError("file time column", "non-uniform time steps",
                                 "uniform sampling (no gaps)")
            rate = 1.0 / mean_dt
    return samples, rate, why
