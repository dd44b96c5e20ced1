"""Thermocouple files in: reading a test rig's measured temperatures for a scene.

One job: turn the file of a scene's ``[measured]`` table, as a data logger, a rig PLC or a
LabVIEW/DAQ program writes it, into ``time [s]`` + one degC column per mapped sensor
(:func:`read_measured_file`). :func:`thermobearing.report.read_measured`,
:func:`thermobearing.scene_checks.check_measured_file` and
:func:`thermobearing.calibrate_model.measured_table` all read through it.

The layout detection (BOM, CRLF, ``#`` comment lines, separator guess, decimal mark, units
row) is that of the accelerometer files (:mod:`thermobearing.signal_input`); the header row
is found by the scene's ``time_column`` name, so metadata lines above it (logger name, date,
channel list) and free-text columns (a quoted comment column) do not disturb it.
"""

from __future__ import annotations

import csv
import math
import re
from collections.abc import Mapping, Sequence
from datetime import datetime, timedelta
from pathlib import Path

import numpy as np
import pandas as pd

from .errors import InputError
from .signal_input import guess_decimal_mark, guess_separator, is_units_row, read_text_lines

__all__ = ["DROPOUT_FLAGS", "OVERLOAD_CODE", "read_measured_file"]

#: cell texts (case-insensitive, after stripping) that mark a broken or overloaded sensor:
#: read as NaN (a gap), like an empty cell. Runs of two or more dashes or stars count too.
DROPOUT_FLAGS = frozenset({
    "ovl", "ovr", "over", "overload", "overrange", "over range", "under", "underrange",
    "unl", "open", "oc", "o.c.", "open circuit", "err", "error", "fault", "nan", "n/a",
    "na", "#n/a", "null", "none", "inf", "-inf", "+inf", "invalid", "?", "burnout",
    "burn out", "b.o.", "+over", "-over", "+ovl", "-ovl", "overflow", "underflow",
})
_DASHES = re.compile(r"^(-{2,}|\+{2,}|\*{2,}|-?\*+-?)$")
#: |value| at or above this is an overload code, not a temperature (Keysight/Agilent DAQs
#: write +9.9E+37 for an open thermocouple): read as a gap
OVERLOAD_CODE = 1e30
_TEMPERATURE_UNITS = {"degc": "degC", "°c": "degC", "c": "degC", "celsius": "degC",
                      "k": "K", "kelvin": "K", "degf": "degF", "°f": "degF", "f": "degF",
                      "fahrenheit": "degF", "deg c": "degC", "deg f": "degF", "℃": "degC"}
_SEPARATORS = ("\t", ";", ",", r"\s+")
_PLAIN = re.compile(r"^[+-]?\d*[.,]?\d+$")
_PROBE_ROWS = 500
_ELAPSED = re.compile(r"^(\d+):(\d{1,2})(?::(\d{1,2}))?(?:[.,](\d+))?$")
#: timestamp layouts tried in order (after ISO 8601 ``2026-11-23T10:15:30`` /
#: ``2026-11-23 10:15:30``, read by datetime.fromisoformat)
_STAMP_FORMATS = (
    ("%d.%m.%Y %H:%M:%S", "dd.mm.yyyy hh:mm:ss"), ("%d.%m.%Y %H:%M", "dd.mm.yyyy hh:mm"),
    ("%Y/%m/%d %H:%M:%S", "yyyy/mm/dd hh:mm:ss"), ("%Y/%m/%d %H:%M", "yyyy/mm/dd hh:mm"),
    ("%d/%m/%Y %H:%M:%S", "dd/mm/yyyy hh:mm:ss"), ("%m/%d/%Y %H:%M:%S", "mm/dd/yyyy hh:mm:ss"),
    ("%d/%m/%Y %H:%M", "dd/mm/yyyy hh:mm"), ("%m/%d/%Y %H:%M", "mm/dd/yyyy hh:mm"),
    ("%m/%d/%Y %I:%M:%S %p", "mm/dd/yyyy hh:mm:ss AM/PM"),
    ("%d/%m/%Y %I:%M:%S %p", "dd/mm/yyyy hh:mm:ss AM/PM"),
    ("%m/%d/%y %I:%M:%S %p", "mm/dd/yy hh:mm:ss AM/PM"),
    ("%d/%m/%y %I:%M:%S %p", "dd/mm/yy hh:mm:ss AM/PM"),
)


def read_measured_file(path: str | Path, time_column: str | Sequence[str],
                       columns: Mapping[str, str] | list,
                       unit: str = "degC", *, time_zero: str | None = None,
                       field: str = "measured") -> pd.DataFrame:
    """Read a rig's thermocouple file: ``time [s]`` + one degC column per sensor.

    Formats accepted
    ----------------
    - **Layout**: comma, semicolon or tab separated (or runs of spaces when the time is a
      number or ``hh:mm:ss``); UTF-8 with or without BOM, or Windows-1252 (a file that is
      not valid UTF-8: ``°C`` and umlauts of Windows loggers); LF or CRLF line ends; ``#``
      comment lines anywhere; any metadata lines above the header row (the header row is
      the first row with a cell equal to ``time_column``, case-insensitive as a fallback);
      quoted cells (a comment column may hold separators); columns not mapped are ignored.
    - **Units row**: a row right under the header whose cells are units (``s;degC;degC``,
      ``[min],[°C]``, ``hh:mm:ss``). It gives the time unit when ``time_column`` has no
      ``[unit]``; a temperature unit in it, or in a sensor column's name (``TC1 [K]``,
      ``TC1 (°F)``; a bare ``(C)`` / ``(F)`` there is not read as a unit), that contradicts
      ``unit`` is an error.
    - **Decimal mark**: ``.``, or ``,`` with a semicolon, tab or space separator (detected
      from the sensor cells: some ``35,27`` and no ``35.27``).
    - **Time column**: numbers in the unit of ``time_column``'s brackets (``time [min]``) or
      of the units row (seconds without either); elapsed ``hh:mm:ss[.f]`` or ``mm:ss[.f]``;
      timestamps ``2026-11-23 10:15:30`` / ISO ``2026-11-23T10:15:30[.f][+01:00]``,
      ``23.11.2026 10:15:30``, ``2026/11/23 10:15:30``, ``23/11/2026 10:15:30`` or
      ``11/23/2026 10:15:30`` (day or month first decided by a field > 12; all <= 12 is
      ambiguous: an error), seconds optional; 12-hour ``11/23/2026 10:15:30 AM`` (also
      two-digit years). The time column's unit may also be in parentheses: ``Time (s)``.
      Timestamps count from the first row; numbers and ``hh:mm:ss`` are taken as they are.
    - **Sensor cells**: numbers in ``unit`` (degC, K or degF); empty cells, dropout flags
      (``OVL``, ``+OVER``, ``Burnout``, ``----``, ``+++++``, ``***``, ``Err``, ``open``,
      ``N/A``, ``NaN``, ``inf``, ...: :data:`DROPOUT_FLAGS`) and overload codes
      (|value| >= :data:`OVERLOAD_CODE`, e.g. ``+9.9E+37``) are NaN.

    Parameters
    ----------
    path : the file.
    time_column : header name of the time column (``"time [min]"``), or the names of a
        date column and a time-of-day column (``["Datum", "Uhrzeit"]``: their cells are
        joined with a space and read as timestamps).
    columns : the mapped sensor columns (header names; a mapping's keys).
    unit : temperature unit of the sensor columns: ``degC``, ``K`` or ``degF``.
    time_zero : the scene's time zero, in the time column's own format (a timestamp, an
        ``hh:mm:ss``, or a number in the column's unit), or ``"first"`` (the first row, for
        any format). None: the first row for timestamps, else the values as they are.
    field : scene table named in the errors.

    Returns
    -------
    DataFrame with ``time [s]`` (strictly increasing) and one column per sensor [degC].

    Raises
    ------
    InputError naming the field, the data row (1 = first data row) and the value: a missing
    file or column, a time that does not increase, a time cell of another format than the
    first row's or of no known format, a text cell in a sensor column that is no dropout
    flag, a units row that contradicts ``unit``, a file without data rows.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{field}.file", str(path), f"an existing CSV file (looked at {p})")
    sensors = list(columns)
    if unit not in ("degC", "K", "degF"):
        raise InputError(f"{field}.unit", unit, "degC, K or degF")
    lines = read_text_lines(p, encoding=_encoding(p))
    if not lines:
        raise InputError(f"{field}.file", str(path), "a CSV file with a header row and data")
    tnames = [time_column] if isinstance(time_column, str) else [str(c) for c in time_column]
    if not 1 <= len(tnames) <= 2:
        raise InputError(f"{field}.time_column", time_column, "a column name, or the names "
                         "of a date column and a time-of-day column")
    sep, h, header = _find_header(lines, tnames[0])
    if h is None:
        raise InputError(f"{field}.time_column", time_column,
                         "a column of the file: " + ", ".join(header))
    names = [c.lower() for c in header]
    tcols = [_index(header, names, c) for c in tnames]
    if None in tcols:
        raise InputError(f"{field}.time_column", time_column,
                         "columns of the file: " + ", ".join(header))
    tcol = tcols[0]
    idx = {}
    for col in sensors:
        j = _index(header, names, col)
        if j is None:
            raise InputError(f"{field}.columns[{col!r}]", col,
                             "a column of the file: " + ", ".join(header))
        idx[col] = j
    rows = [_cells(ln, sep) for _, ln in lines[h + 1:]]
    at = [i + 1 for i, _ in lines[h + 1:]]  # file line of each row, for the errors
    units = None
    if rows and _looks_like_units(rows[0], tcols):
        units = rows.pop(0)
        at.pop(0)
    if not rows:
        raise InputError(f"{field}.file", str(path), f"data rows under the header row "
                         f"({', '.join(header)})")
    need = max([*tcols, *idx.values()]) + 1
    for k, r in enumerate(rows):
        if len(r) < need:
            raise InputError(f"{field}.file", f"row {k + 1}: {sep.join(r)!r} (line {at[k]})",
                             f"at least {need} cells separated by {_sep_name(sep)!r} "
                             f"(as in the header row: {', '.join(header)})")
    if units is not None:
        _check_units_row(units, idx, unit, field, "units row")
    # a bare C or F in a name's brackets may be a label (``TC (F)``: front), not a unit
    _check_units_row([u if u.lower() not in ("c", "f") else "" for u in map(_bracket, header)],
                     idx, unit, field, "column name")
    cells = {col: [r[j] for r in rows] for col, j in idx.items()}
    # decimal mark from the sensor cells and plain-number time cells of the first rows
    # (timestamps such as 23.11.2026 would look like decimal points)
    probe = [c for v in cells.values() for c in v[:_PROBE_ROWS]]
    probe += [r[tcol] for r in rows[:_PROBE_ROWS] if _PLAIN.match(r[tcol].strip())]
    decimal = guess_decimal_mark(probe, sep)
    tunit = _time_unit(tnames[0], units[tcol] if units is not None else "")
    tcells = [" ".join(r[j] for j in tcols) for r in rows]
    times = _parse_times(tcells, tunit, decimal, time_zero, " + ".join(tnames),
                         field, at)
    out = pd.DataFrame({"time [s]": times})
    for col in sensors:
        values = _parse_temperatures(cells[col], decimal, col, at)
        if unit == "K":
            values = values - 273.15
        elif unit == "degF":
            values = (values - 32.0) * 5.0 / 9.0
        out[col] = values
    return out


# --------------------------------------------------------------------------- layout
def _encoding(p: Path) -> str:
    """UTF-8 (BOM or not) when the file decodes as UTF-8, else Windows-1252: loggers on
    Windows write ``°C`` and umlauts in the ANSI code page."""
    try:
        p.read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        return "cp1252"
    return "utf-8-sig"


def _sep_name(sep: str) -> str:
    return {"\t": "tab", r"\s+": "spaces"}.get(sep, sep)


def _cells(line: str, sep: str) -> list[str]:
    if sep == r"\s+":
        return line.split()
    try:
        return [c.strip() for c in next(csv.reader([line], delimiter=sep, quotechar='"'),
                                         [])]
    except csv.Error as exc:  # e.g. a NUL byte: not a text file
        raise InputError("measured.file", line[:60], f"lines of text ({exc})") from None


def _index(header: list[str], lowered: list[str], name: str) -> int | None:
    if name in header:
        return header.index(name)
    return lowered.index(name.lower()) if name.lower() in lowered else None


def _find_header(lines: list[tuple[int, str]], time_column: str
                 ) -> tuple[str, int | None, list[str]]:
    """Separator, index (in ``lines``) and cells of the header row: the first row with a
    cell equal to ``time_column`` under the guessed separator, then under the others. When
    none has it: the guessed separator and the widest of the first rows (for the error)."""
    body = [ln for _, ln in lines[:200]]
    guess = guess_separator(body)
    wanted = time_column.strip().lower()
    for sep in (guess, *(s for s in _SEPARATORS if s != guess)):
        for k, (_, ln) in enumerate(lines[:200]):
            cells = _cells(ln, sep)
            if time_column in cells or wanted in (c.lower() for c in cells):
                return sep, k, cells
    widest = max((_cells(ln, guess) for ln in body[:50]), key=len)
    return guess, None, widest


def _is_time_format(cell: str) -> bool:
    c = cell.strip().strip("[]()").lower()
    return c in ("hh:mm:ss", "h:mm:ss", "mm:ss", "hh:mm:ss.s", "hh:mm:ss.ss", "hh:mm:ss.sss",
                 "date", "datetime", "timestamp", "yyyy-mm-dd hh:mm:ss", "dd.mm.yyyy hh:mm:ss",
                 "yyyy-mm-dd", "dd.mm.yyyy", "mm/dd/yyyy", "dd/mm/yyyy", "time", "clock")


def _looks_like_units(cells: list[str], tcols: list[int]) -> bool:
    """A units row: every non-empty cell a unit (the time cell may also be a time format
    such as ``hh:mm:ss``), at least one not empty, and no cell a number."""
    if any(_number(c, ".") is not None or _number(c, ",") is not None for c in cells if c):
        return False
    probe = ["" if (j in tcols and _is_time_format(c)) else c.replace("℃", "degC")
             for j, c in enumerate(cells)]
    if not any(probe):
        return any(cells)
    return is_units_row(probe)


def _bracket(name: str) -> str:
    """The unit in a column name's brackets (``TC1 [K]``, ``Temp (°C)``), or ""."""
    m = re.search(r"[\[(]\s*([^\])]+?)\s*[\])]\s*$", name)
    return m.group(1) if m else ""


def _check_units_row(units: list[str], idx: Mapping[str, int], unit: str, field: str,
                     where: str) -> None:
    """A temperature unit given by the file (units row or column name) must be ``unit``."""
    for col, j in idx.items():
        if j >= len(units):
            continue
        said = _TEMPERATURE_UNITS.get(units[j].strip().strip("[]()").lower())
        if said is not None and said != unit:
            raise InputError(f"{field}.unit", unit, f"{said!r}, the unit the file's {where} "
                             f"gives for column {col!r} (set unit = \"{said}\")")


def _time_unit(time_column: str, units_cell: str) -> str:
    m = re.search(r"[\[(]\s*([^\])]+?)\s*[\])]", time_column)
    if m:
        return m.group(1)
    cell = units_cell.strip().strip("[]()")
    return cell if cell and not _is_time_format(cell) else "s"


# --------------------------------------------------------------------------- cells
def _number(cell: str, decimal: str) -> float | None:
    c = cell.strip()
    if decimal == ",":
        c = c.replace(",", ".")
    try:
        x = float(c)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


def _is_dropout(cell: str) -> bool:
    c = cell.strip().lower()
    return c == "" or c in DROPOUT_FLAGS or bool(_DASHES.match(c))


def _parse_temperatures(cells: list[str], decimal: str, col: str, at: list[int]
                        ) -> np.ndarray:
    text = [c.replace(",", ".") for c in cells] if decimal == "," else cells  # stripped
    out = np.asarray(pd.to_numeric(np.asarray(text, dtype=object), errors="coerce"),
                     dtype=float)
    with np.errstate(invalid="ignore"):
        overload = np.abs(out) >= OVERLOAD_CODE  # +9.9E+37 and the like: a gap
    for k in np.flatnonzero(~np.isfinite(out) & ~overload):  # text, nan, inf: flag or error
        c = cells[k]
        if not _is_dropout(c):
            raise InputError(f"measured column {col!r}", f"row {k + 1}: {c!r} (line {at[k]})",
                             "numbers (an empty cell or a dropout flag such as OVL, "
                             "----, Err, N/A is a gap)")
        out[k] = math.nan
    out[overload] = math.nan
    return out


def _elapsed(cell: str) -> float | None:
    m = _ELAPSED.match(cell.strip())
    if m is None:
        return None
    a, b, c, frac = m.groups()
    if c is None:  # mm:ss
        seconds = int(a) * 60 + int(b)
        if int(b) >= 60:
            return None
    else:
        if int(b) >= 60 or int(c) >= 60:
            return None
        seconds = int(a) * 3600 + int(b) * 60 + int(c)
    return seconds + (float("0." + frac) if frac else 0.0)


def _stamp_parser(first: str, cells: list[str], name: str):
    """A parser str -> datetime | None for the timestamp layout of ``first`` (None if it
    is no timestamp); the description of that layout."""
    text = first.strip()
    try:
        datetime.fromisoformat(text)
        if re.match(r"^\d{4}-\d{2}-\d{2}", text):
            def iso(c: str) -> datetime | None:
                try:
                    return datetime.fromisoformat(c.strip())
                except ValueError:
                    return None
            return iso, "ISO 8601 yyyy-mm-dd hh:mm:ss"
    except ValueError:
        pass
    candidates = [(f, d) for f, d in _STAMP_FORMATS if _strptime(text, f) is not None]
    if not candidates:
        return None, ""
    if len(candidates) > 1:
        # several layouts read the first row (01/02/2026: day or month first?): keep those
        # that read every row; if they still disagree on some row, it is ambiguous
        rest = [c for c in cells if c.strip()]
        parsed = {f: [_strptime(c, f) for c in rest] for f, _ in candidates}
        ok = [(f, d) for f, d in candidates if None not in parsed[f]]
        if len(ok) > 1 and any(parsed[f] != parsed[ok[0][0]] for f, _ in ok[1:]):
            raise InputError(name, f"row 1: {first!r}", "an unambiguous date: every "
                             "dd/mm and mm/dd field <= 12, so day and month cannot be told "
                             "apart (write yyyy-mm-dd or dd.mm.yyyy)")
        candidates = ok or candidates
    fmt, desc = candidates[0]
    return (lambda c: _strptime(c, fmt)), desc


def _strptime(cell: str, fmt: str) -> datetime | None:
    c = cell.strip()
    frac = 0.0
    m = re.match(r"^(.*:\d{2})[.,](\d+)$", c)
    if m and fmt.endswith("%S"):
        c, frac = m.group(1), float("0." + m.group(2))
    try:
        return datetime.strptime(c, fmt) + timedelta(seconds=frac)
    except ValueError:
        return None


def _parse_times(cells: list[str], tunit: str, decimal: str, time_zero: str | None,
                 time_column: str, field: str, at: list[int]) -> np.ndarray:
    """Elapsed seconds of the time cells (the format of the first row for all rows)."""
    from .units import to_si

    name = f"measured column {time_column!r}"
    first = cells[0].strip()
    scale = None
    if _number(first, decimal) is not None:
        scale = to_si(f"1 {tunit}", "time", field=f"{field}.time_column")
        kind, desc = "number", f"numbers in {tunit}"

        def parse(c: str) -> float | None:
            x = _number(c, decimal)
            return None if x is None else x * scale
    elif _elapsed(first) is not None:
        kind, desc, parse = "elapsed", "elapsed hh:mm:ss or mm:ss", _elapsed
    else:
        stamp, desc = _stamp_parser(first, cells, name)
        if stamp is None:
            raise InputError(name, f"row 1: {first!r} (line {at[0]})", "numbers (in the "
                             "unit of the column name's brackets or the units row), "
                             "elapsed hh:mm:ss / mm:ss, or "
                             "timestamps yyyy-mm-dd hh:mm:ss (ISO 8601, T allowed), "
                             "dd.mm.yyyy hh:mm:ss, yyyy/mm/dd hh:mm:ss, dd/mm/yyyy hh:mm:ss")
        kind, parse = "stamp", stamp
    values: list = []
    for k, c in enumerate(cells):
        v = parse(c) if c.strip() else None
        if v is None:
            raise InputError(name, f"row {k + 1}: {c!r} (line {at[k]})",
                             f"a time in every row, in the format of row 1 ({desc})")
        values.append(v)
    if kind == "stamp":
        aware = {v.tzinfo is not None for v in values}
        if len(aware) > 1:
            k = next(i for i, v in enumerate(values) if (v.tzinfo is not None) != (
                values[0].tzinfo is not None))
            raise InputError(name, f"row {k + 1}: {cells[k]!r} (line {at[k]})",
                             "timestamps all with or all without a UTC offset")
    zero = _time_zero(time_zero, values, parse, kind, desc, field)
    if kind == "stamp":
        t = np.array([(v - zero).total_seconds() for v in values])
    else:
        t = np.asarray(values, dtype=float) - float(zero)
    steps = np.diff(t)
    if steps.size and not (steps > 0).all():
        k = int(np.flatnonzero(steps <= 0)[0]) + 1
        raise InputError(name, f"row {k + 1}: {cells[k].strip()} after {cells[k - 1].strip()} "
                         f"(line {at[k]})", "strictly increasing times")
    return t


def _time_zero(time_zero: str | None, values: list, parse, kind: str, desc: str, field: str):
    if time_zero is None:
        return values[0] if kind == "stamp" else 0.0
    if str(time_zero).strip().lower() == "first":
        return values[0]
    zero = parse(str(time_zero))
    if zero is None:
        raise InputError(f"{field}.time_zero", time_zero, f"\"first\" or a time in the format "
                         f"of the file's time column ({desc})")
    if kind == "stamp" and (zero.tzinfo is None) != (values[0].tzinfo is None):
        raise InputError(f"{field}.time_zero", time_zero, "a timestamp with a UTC offset "
                         "exactly when the file's timestamps have one")
    return zero
