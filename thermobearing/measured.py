"""Thermocouple files in: reading a test rig's measured temperatures for a scene.

One job: turn the file of a scene's ``[measured]`` table, as a data logger, a rig PLC or a
LabVIEW/DAQ program writes it, into ``time [s]`` + one degC column per mapped sensor
(:func:`read_measured_file`), and say what was left out (:func:`measured_notes`) and how
the file's time span meets a run's (:func:`coverage_notes`).
:func:`thermobearing.report.read_measured`,
:func:`thermobearing.scene_checks.check_measured_file` and
:func:`thermobearing.calibrate_model.measured_table` all read through it.

The layout (separator, header row found by the scene's ``time_column``, fixed-width
columns, units row) is :mod:`thermobearing.measured_layout`; the time column
:mod:`thermobearing.measured_time`.
"""

from __future__ import annotations

import math
import re
import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from .errors import InputError
from .measured_layout import (
    closest_name,
    file_encoding,
    find_layout,
    looks_like_units,
    non_temperature_units,
    stated_units,
)
from .measured_time import parse_times
from .signal_input import guess_decimal_mark, read_text_lines

__all__ = ["ABSOLUTE_ZERO_C", "DROPOUT_FLAGS", "OVERLOAD_CODE", "RANGE_ENDS_C",
           "THERMOCOUPLE_MAX_C",
           "coverage_notes", "interval_note", "measured_notes", "read_measured_file",
           "read_scene_measured"]

#: cell texts (case-insensitive, after stripping) that mark a broken or overloaded sensor:
#: read as NaN (a gap), like an empty cell. Runs of two or more dashes or stars count too.
DROPOUT_FLAGS = frozenset({
    "ovl", "ovr", "over", "overload", "overrange", "over range", "under", "underrange",
    "unl", "open", "oc", "o.c.", "open circuit", "err", "error", "fault", "nan", "n/a",
    "na", "#n/a", "null", "none", "inf", "-inf", "+inf", "invalid", "?", "burnout",
    "burn out", "b.o.", "+over", "-over", "+ovl", "-ovl", "overflow", "underflow",
    "#value!", "#div/0!", "#num!", "-nan", "+nan",
})
_DASHES = re.compile(r"^(-{2,}|\+{2,}|\*{2,}|-?\*+-?)$")
#: |value| at or above this is an overload code, not a temperature (Keysight/Agilent DAQs
#: write +9.9E+37 for an open thermocouple): read as a gap
OVERLOAD_CODE = 1e30
#: absolute zero [degC]: a reading below it is no temperature (a code such as -999)
ABSOLUTE_ZERO_C = -273.15
#: top of the IEC 60584-1:2013 thermocouple reference tables [degC] (type B, the highest
#: of the standard types): a reading above it is no thermocouple temperature (9999.9)
THERMOCOUPLE_MAX_C = 1820.0
#: ends of the IEC 60584-1:2013 reference tables of thermocouple types K, J, T, E, N
#: [degC]: where many loggers pin an open or shorted thermocouple (noted, not dropped)
RANGE_ENDS_C = {-270.0: "K, T, E, N", -210.0: "J", 1372.0: "K", 1200.0: "J", 400.0: "T",
                1000.0: "E", 1300.0: "N"}
_PLAIN = re.compile(r"^[+-]?\d*[.,]?\d+$")
_PROBE_ROWS = 500
_TO_C = {"degC": lambda x: x, "K": lambda x: x - 273.15,
         "degF": lambda x: (x - 32.0) * 5.0 / 9.0}


def read_measured_file(path: str | Path, time_column: str | Sequence[str],
                       columns: Mapping[str, str] | list,
                       unit: str = "degC", *, time_zero: str | None = None,
                       time_format: str | None = None,
                       missing_values: Sequence[float | str] | None = None,
                       field: str = "measured") -> pd.DataFrame:
    """Read a rig's thermocouple file: ``time [s]`` + one degC column per sensor.

    Formats accepted
    ----------------
    - **Layout**: comma, semicolon or tab separated, or columns separated by spaces (an
      aligned or fixed-width export whose names hold single spaces, ``Time [s]   TC 1 outer
      ring``, is split at runs of two or more spaces; blank cells under a name are gaps:
      rule in :mod:`thermobearing.measured_layout`); UTF-8 with or without BOM, or
      Windows-1252; LF or CRLF line ends; ``#`` comment lines anywhere; any metadata lines
      above the header row (the first row with a cell equal to ``time_column``,
      case-insensitive as a fallback); quoted cells; columns not mapped are ignored.
    - **Units row**: a row right under the header whose cells are units (``s;degC;degC``,
      ``[min],[°C]``, ``hh:mm:ss``). It gives the time unit when ``time_column`` has no
      ``[unit]`` (nor ``/unit``: ``t/min``, ``Zeit / s``). A temperature unit the file
      gives a sensor column (units row, or the name's brackets ``TC1 [degF]``, ``TC1 (K)``,
      or after a slash ``T1/°C``; a bare ``(C)`` / ``(F)`` is no unit): when every such
      unit is the same and not ``unit``, an error (set ``unit``); when the
      file gives different units to different columns, each column is read in its own
      (columns without one in ``unit``) and the notes say so.
    - **Decimal mark**: ``.``, or ``,`` with a semicolon, tab or space separator.
    - **Time column**: numbers in the unit of ``time_column``'s brackets (``time [min]``,
      ``Time (s)``), of its ``/unit`` ending, of the units row or of a word of its name
      that is a time unit (``Minutes``, ``Time_min``, ``t_s``; seconds without any);
      elapsed ``hh:mm:ss[.f]`` or ``mm:ss[.f]`` (clock times passing midnight: +24 h from
      there, noted);
      timestamps ``2026-11-23 10:15:30`` / ISO 8601 (``T``, fraction, UTC offset),
      ``23.11.2026 10:15:30``, ``2026/11/23 10:15:30``, ``23/11/2026
      10:15:30`` or ``11/23/2026 10:15:30`` (day or month first decided by a field > 12;
      all <= 12 is an error), seconds optional, 12-hour ``AM/PM``; Excel serial day
      numbers and Unix seconds (``time_format``; Excel also for a date-named column, see
      :mod:`thermobearing.measured_time`). Timestamps count from the first row; numbers
      and ``hh:mm:ss`` are taken as they are (both unless ``time_zero``).
    - **Repeated times** (a logger writing whole seconds at 2 Hz, a line written twice):
      rows with the same time as the row before are averaged (gaps left out), noted.
      A time that steps back (a daylight-saving change, a logger restart) is an error
      naming the row and the step.
    - **Sensor cells**: numbers in ``unit``. Gaps (NaN, counted per sensor and cause in
      the notes): empty cells, dropout flags (:data:`DROPOUT_FLAGS`: ``OVL``, ``+OVER``,
      ``Burnout``, ``----``, ``Err``, ``NaN``, ...), overload codes (|value| >=
      :data:`OVERLOAD_CODE`, ``+9.9E+37``) and the codes of ``missing_values``. Any other
      reading at or below absolute zero (0 K) or above :data:`THERMOCOUPLE_MAX_C` is an
      error (a logger's numeric code such as -999 or 9999.9 is never dropped unless
      listed).
      Readings of exactly a thermocouple range end (:data:`RANGE_ENDS_C`: 1372 degC,
      -270 degC for type K, where loggers pin an open thermocouple) stay, with a note.

    Parameters
    ----------
    path : the file.
    time_column : header name of the time column (``"time [min]"``), or the names of a
        date column and a time-of-day column (``["Datum", "Uhrzeit"]``: their cells are
        joined with a space and read as timestamps).
    columns : the mapped sensor columns (header names; a mapping's keys).
    unit : temperature unit of the sensor columns: ``degC``, ``K`` or ``degF``.
    time_zero : the scene's time zero, in the time column's own format (a timestamp, an
        ``hh:mm:ss``, or a number in the column's unit; a timestamp also for Excel / Unix
        times), or ``"first"`` (the first row). None: the first row for timestamps, else
        the values as they are.
    time_format : None / ``"auto"`` (the formats above), ``"excel"``, ``"excel_1904"``,
        ``"unix"``, or a strptime pattern (``"%d/%m/%Y %H:%M:%S"``: settles day/month).
    missing_values : the logger's codes for "no reading", numbers in the file's unit
        (``[-999, 9999.9]``: cells equal to one are gaps) or extra texts (``"S.C."``).
    field : scene table named in the errors.

    Returns
    -------
    DataFrame with ``time [s]`` (strictly increasing) and one column per sensor [degC];
    ``attrs["notes"]`` (list of str: averaged rows, mixed units, Excel dates, readings at
    a thermocouple range end, a degC column whose readings all exceed 273.15) and
    ``attrs["gaps"]`` ({sensor: {cause: count}}), ``attrs["rows"]`` (the file's data
    rows), ``attrs["units"]`` ({sensor: the unit its readings were converted from, degC,
    K or degF}); :func:`measured_notes` words them.

    Raises
    ------
    InputError naming the field, the data row (1 = first data row), the file line and the
    value: a missing file or column (with the nearest header name), a time that steps
    back, a time cell of another format than the first row's or of no known format, a
    text cell in a sensor column that is no dropout flag, a reading that is no
    temperature, a unit the file gives that contradicts ``unit``, no data rows.
    """
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{field}.file", str(path), f"an existing CSV file (looked at {p})")
    sensors = list(columns)
    if unit not in _TO_C:
        raise InputError(f"{field}.unit", unit, "degC, K or degF")
    codes, texts = _missing(missing_values, field)
    lines = read_text_lines(p, encoding=file_encoding(p))
    if not lines:
        raise InputError(f"{field}.file", str(path), "a CSV file with a header row and data")
    tnames = [time_column] if isinstance(time_column, str) else [str(c) for c in time_column]
    if not 1 <= len(tnames) <= 2:
        raise InputError(f"{field}.time_column", time_column, "a column name, or the names "
                         "of a date column and a time-of-day column")
    layout, h, header = find_layout(lines, tnames[0], [*tnames[1:], *sensors])
    if h is None:
        raise InputError(f"{field}.time_column", time_column, "a column of the file: "
                         + ", ".join(header) + closest_name(tnames[0], header))
    names = [c.lower() for c in header]
    tcols = [_index(header, names, c) for c in tnames]
    if None in tcols:
        miss = next(c for c, j in zip(tnames, tcols, strict=True) if j is None)
        raise InputError(f"{field}.time_column", time_column, "columns of the file: "
                         + ", ".join(header) + closest_name(miss, header))
    tcol = tcols[0]
    idx = {}
    for col in sensors:
        j = _index(header, names, col)
        if j is None:
            # the nearest name among the columns no other sensor maps (a typo of TC4 was
            # told 'did you mean TC3?', the column mapped on the line above)
            taken = {c.lower() for c in sensors if c != col}
            raise InputError(f"{field}.columns[{col!r}]", col, "a column of the file: "
                             + ", ".join(header) + closest_name(
                                 col, [c for k, c in enumerate(header) if k not in tcols
                                       and c.lower() not in taken]))
        if j in tcols:
            # the time column mapped to a node was compared as temperatures (0-50 "degC"
            # of a time in minutes against the shaft)
            raise InputError(f"{field}.columns[{col!r}]", col,
                             "a sensor column; this is the time column "
                             f"({field}.time_column): map the thermocouple columns, "
                             + ", ".join(c for k, c in enumerate(header) if k not in tcols))
        idx[col] = j
    at = [i + 1 for i, _ in lines[h + 1:]]  # file line of each row, for the errors
    rows = [layout.split(ln, f"line {a}") for a, (_, ln) in zip(at, lines[h + 1:],
                                                                strict=True)]
    units = None
    if rows and looks_like_units(rows[0], tcols):
        units = rows.pop(0)
        at.pop(0)
    notes: list[str] = []
    rows, at = _drop_empty_rows(rows, at, notes)
    if not rows:
        raise InputError(f"{field}.file", str(path), f"data rows under the header row "
                         f"({', '.join(header)})")
    need = max([*tcols, *idx.values()]) + 1
    short = 0
    for k, r in enumerate(rows):
        if len(r) < need:
            if len(r) <= max(tcols):  # not even the time
                raise InputError(f"{field}.file",
                                 f"row {k + 1}: {' | '.join(r)!r} (line {at[k]})",
                                 f"at least {need} cells separated by {layout.name!r} "
                                 f"(as in the header row: {', '.join(header)})")
            # a logger that leaves out the empty cells at the end of a row (a channel that
            # dropped out): they are gaps, like empty cells; the row was refused
            r.extend([""] * (need - len(r)))
            short += 1
    if short:
        notes.append(f"{short} row{'s' if short > 1 else ''} shorter than the header row: "
                     "the missing cells at the end are read as gaps (empty cells)")
    stated = stated_units(units, header, idx)
    _refuse_other_units(non_temperature_units(units, header, idx, stated), field)
    col_units = _column_units(stated, unit, field, notes)
    notes += _letter_notes(sensors, stated, col_units, unit, field)
    cells = {col: [r[j] for r in rows] for col, j in idx.items()}
    # decimal mark from the sensor cells and plain-number time cells of the first rows
    # (timestamps such as 23.11.2026 would look like decimal points)
    probe = [c for v in cells.values() for c in v[:_PROBE_ROWS]]
    probe += [r[tcol] for r in rows[:_PROBE_ROWS] if _PLAIN.match(r[tcol].strip())]
    decimal = guess_decimal_mark(probe, layout.sep)
    tunit = _time_unit(tnames[0], units[tcol] if units is not None else "")
    tcells = [" ".join(r[j] for j in tcols) for r in rows]
    times, desc = parse_times(tcells, tunit, decimal, time_zero, " + ".join(tnames), field,
                              at, time_format=time_format, notes=notes)
    if time_format in (None, "auto") and desc.startswith("Excel"):
        notes.append(f"time column {tnames[0]!r} read as {desc}: a date-named column of "
                     "day numbers (set measured time_format to read it otherwise)")
    out = pd.DataFrame({"time [s]": times})
    gaps = {}
    for col in sensors:
        raw, gaps[col] = _parse_readings(cells[col], decimal, col, at, codes, texts)
        out[col] = _to_celsius(raw, col_units.get(col, unit), col, cells[col], at)
        notes += _range_end_notes(out[col].to_numpy(float), col, at)
        if col_units.get(col, unit) == "degC" and col not in stated:
            notes += _kelvin_note(out[col].to_numpy(float), col)
    out = _average_repeats(out, at, notes)
    out.attrs["notes"] = notes
    out.attrs["gaps"] = gaps
    out.attrs["rows"] = len(rows)  # data rows of the file (before averaging repeats)
    out.attrs["units"] = {col: col_units.get(col, unit) for col in sensors}
    # how the time column was read (``numbers in min``, ``elapsed hh:mm:ss or mm:ss``):
    # ``check`` prints it, so a reading the user did not mean shows before a run
    out.attrs["time_read_as"] = desc
    # the file's other columns (an extra channel, a logger's status column): ``check``
    # names them, so a thermocouple left out of the column map shows before a run
    out.attrs["unmapped"] = [c for k, c in enumerate(header)
                             if k not in tcols and k not in idx.values() and c.strip()]
    return out


def read_scene_measured(scene: Any) -> pd.DataFrame | None:
    """The ``[measured]`` file of ``scene`` read with every option of its section
    (time column, unit, ``time_zero``, ``time_format``, ``missing_values``): the one call
    that ``check``, the report and ``calibrate`` share. None when the scene has none.

    Raises InputError naming ``measured.file`` when the file does not exist, and the
    reader's errors otherwise."""
    m = scene.measured
    if m is None:
        return None
    path = scene.resolve_path(m.file)
    if not path.is_file():
        raise InputError("measured.file", m.file, f"an existing data file (looked at {path})")
    return read_measured_file(path, m.time_column, m.columns, m.unit,
                              time_zero=getattr(m, "time_zero", None),
                              time_format=getattr(m, "time_format", None),
                              missing_values=getattr(m, "missing_values", None))


def measured_notes(measured: pd.DataFrame) -> list[str]:
    """What the reader left out or decided, one line each: per sensor the gaps by cause
    (``TC1: 3 of 120 readings are gaps (2 dropout flags, 1 missing_values code)``), rows
    averaged, mixed units, Excel dates. Empty when the file had nothing of the kind."""
    out = list(measured.attrs.get("notes", []))
    n = measured.attrs.get("rows", len(measured))
    for col, causes in measured.attrs.get("gaps", {}).items():
        total = sum(causes.values())
        if total:
            parts = ", ".join(f"{k} {c[:-1] if k == 1 and c.endswith('s') else c}"
                              for c, k in causes.items() if k)
            if total >= n:  # nothing left to compare with
                out.append(f"{col}: every reading ({n}) is a gap ({parts}); this sensor is "
                           "not compared with the model")
            else:
                out.append(f"{col}: {total} of {n} readings are gaps ({parts})")
    return out


def coverage_notes(measured: pd.DataFrame, t_start: float, t_end: float) -> list[str]:
    """How the measured times meet a run from ``t_start`` to ``t_end`` [s]: samples before
    or after the run (left out of the errors), a run longer than the file, or no overlap
    at all (a wrong time unit, ``time_zero`` or ``time_format``?). Empty when the file
    spans exactly the run."""
    t = measured["time [s]"].to_numpy(float)
    if t.size == 0:
        return []
    span = (f"measured {minutes_span(t[0], t[-1])}, "
            f"run {minutes_span(t_start, t_end)}")
    if t[-1] < t_start or t[0] > t_end:
        return [f"no measured time inside the run ({span}): check the time column's unit, "
                "measured time_zero or time_format"]
    out = []
    before, after = int((t < t_start).sum()), int((t > t_end).sum())
    if before or after:
        n = before + after
        out.append(f"{n} measured sample{'s' if n != 1 else ''} outside the run "
                   f"{'are' if n != 1 else 'is'} left out ({before} before, {after} after; "
                   f"{span})")
    if t[0] > t_start or t[-1] < t_end:
        out.append(f"the run is compared with measured data only where the file has "
                   f"them ({span})")
    return out


def interval_note(measured: pd.DataFrame, chunk: float, interval: float | None
                  ) -> list[str]:
    """A note when the file samples more than twice as often as a transient run writes
    temperature rows: without ``[outputs] interval`` the rows are the coupling chunk ends
    (``chunk`` [s] apart at most), and each reading is compared with a straight line
    between two of them. A QJ1044 rig log every 30 s against 43-s chunk ends: the oil
    sensor's RMSE 0.79 K, 0.37 K with ``interval = "1 min"``, the same model. Empty with
    an interval, or when the file samples no faster than half the chunk."""
    if interval is not None:
        return []
    t = measured["time [s]"].to_numpy(float)
    if t.size < 3:
        return []
    step = float(np.median(np.diff(t)))
    if not 0.0 < step < 0.5 * chunk:
        return []
    shown = f"{step:.3g} s" if step < 120.0 else f"{step / 60.0:.3g} min"
    return [f"the file samples every {shown} (median); the run writes temperature rows at "
            f"its coupling chunk ends only (up to {chunk:g} s apart, [solver] chunk), and "
            "each reading is compared with a straight line between two of them: set "
            f"[outputs] interval = \"{shown}\" to compare with the model's curve"]


def minutes_span(t0: float, t1: float) -> str:
    """``0-50 min`` from times [s]; ``-5 to 50 min`` when the first is negative (a logger
    started before ``time_zero``), which read ``-5-50 min``."""
    a, b = t0 / 60.0, t1 / 60.0
    return f"{a:.6g} to {b:.6g} min" if a < 0 or b < 0 else f"{a:.6g}-{b:.6g} min"


# --------------------------------------------------------------------------- helpers
def _index(header: list[str], lowered: list[str], name: str) -> int | None:
    """Position of ``name`` in the header (exact, else case-insensitive); a name the
    header has twice is an error (which of the two would be a guess)."""
    for cells, key in ((header, name), (lowered, name.lower())):
        at = [j for j, c in enumerate(cells) if c == key]
        if len(at) > 1:
            raise InputError("measured file header", name, "column names that appear once "
                             f"(this one is columns {' and '.join(str(j + 1) for j in at)}: "
                             "rename one in the file)")
        if at:
            return at[0]
    return None


#: words that name a time unit in a time column's name without brackets or slash
#: (``Minutes``, ``Elapsed Minutes``, ``Time_min``, ``t_s``, ``Zeit in Minuten``)
_TIME_WORDS = {"ms": "ms", "msec": "ms", "millisecond": "ms", "milliseconds": "ms",
               "s": "s", "sec": "s", "secs": "s", "second": "s", "seconds": "s",
               "sekunde": "s", "sekunden": "s",
               "min": "min", "mins": "min", "minute": "min", "minutes": "min",
               "minuten": "min",
               "h": "h", "hr": "h", "hrs": "h", "hour": "h", "hours": "h", "stunden": "h",
               "std": "h", "stunde": "h"}


def _time_unit(time_column: str, units_cell: str) -> str | None:
    """The unit of a time column of numbers (its name's brackets, a time unit after a
    slash: ``t/min``, a word of the name that is a time unit: ``Minutes``, ``Time_min``,
    else the units row), None when none gives one."""
    from .measured_layout import is_time_format, slash_unit
    from .units import to_si

    m = re.search(r"[\[(]\s*([^\])]+?)\s*[\])]", time_column)
    if m:  # a word pint does not know (Sekunden, Std) read as the unit it names
        return _TIME_WORDS.get(m.group(1).lower(), m.group(1))
    after = slash_unit(time_column)
    if after:
        try:
            to_si(f"1 {after}", "time")
            return after
        except InputError:
            pass  # Datum/Uhrzeit: no unit
    cell = units_cell.strip().strip("[]()")
    if cell and not is_time_format(cell):
        return cell
    words = {_TIME_WORDS[w] for w in re.split(r"[\s_\-.]+", time_column.strip().lower())
             if w in _TIME_WORDS}
    return words.pop() if len(words) == 1 else None


def _missing(values: Sequence[float | str] | None, field: str
             ) -> tuple[frozenset[float], frozenset[str]]:
    """Numeric codes and texts of ``missing_values``."""
    if values is None:
        return frozenset(), frozenset()
    if isinstance(values, str | int | float):
        values = [values]
    codes, texts = set(), set()
    for v in values:
        if isinstance(v, bool) or not isinstance(v, str | int | float):
            raise InputError(f"{field}.missing_values", values, "a list of the logger's "
                             "codes for no reading: numbers in the file's unit (-999, "
                             "9999.9) or texts (\"S.C.\")")
        try:
            x = float(str(v).strip().replace(",", "."))
        except ValueError:
            texts.add(str(v).strip().lower())
            continue
        if not math.isfinite(x):
            texts.add(str(v).strip().lower())
        else:
            codes.add(x)
    return frozenset(codes), frozenset(texts)


def _column_units(stated: Mapping[str, tuple[str, str]], unit: str, field: str,
                  notes: list[str]) -> dict[str, str]:
    """The unit of each sensor column: the file's when it gives different units to
    different columns (noted); one unit that is not ``unit`` is an error."""
    said = {u for u, _ in stated.values()}
    if len(said) == 1 and unit not in said:
        col, (u, where) = next(iter(stated.items()))
        raise InputError(f"{field}.unit", unit, f"{u!r}, the unit the file's {where} "
                         f"gives for column {col!r} (set unit = \"{u}\")")
    if len(said) > 1:
        notes.append("the file gives the sensor columns different units; each is read in "
                     "its own: " + ", ".join(f"{c} in {u} ({w})" for c, (u, w) in
                                             stated.items()))
        return {c: u for c, (u, _) in stated.items()}
    return {}


def _drop_empty_rows(rows: list[list[str]], at: list[int], notes: list[str]
                     ) -> tuple[list[list[str]], list[int]]:
    """The rows with at least one cell that is not empty, and their file lines; a row of
    separators only (``,,,,``: a spreadsheet saves the rows it has formatted below the
    data so) holds no reading and no time, is left out and counted in a note (it was an
    error asking for a time in every row)."""
    empty = [not any(c.strip() for c in r) for r in rows]
    if not any(empty):
        return rows, at
    n = sum(empty)
    first = empty.index(True)
    notes.append(f"{n} row{'s' if n > 1 else ''} with every cell empty left out (first at "
                 f"line {at[first]}: separators only, as a spreadsheet saves formatted "
                 "empty rows)")
    return ([r for r, e in zip(rows, empty, strict=True) if not e],
            [a for a, e in zip(at, empty, strict=True) if not e])


def _refuse_other_units(other: Mapping[str, tuple[str, str]], field: str) -> None:
    """A mapped sensor column the file gives a unit that is no temperature (``TC3 [mV]``,
    a units row's ``V`` or ``bar``) is an error naming it: read as temperatures, a type K
    thermocouple's 1-4 mV at rig temperatures became 1-4 degC."""
    if not other:
        return
    col, (u, where) = next(iter(other.items()))
    more = [c for c in other if c != col]
    raise InputError(f"{field}.columns[{col!r}]", col,
                     f"a column of temperatures; the file's {where} gives it {u!r}, which is "
                     "no temperature unit (degC, K or degF): convert a thermocouple's voltage "
                     "to temperature in the logger first, or map the column that holds the "
                     "temperatures" + (f" (also {', '.join(map(repr, more))})" if more else ""))


def _letter_notes(sensors: Sequence[str], stated: Mapping[str, tuple[str, str]],
                  col_units: Mapping[str, str], unit: str, field: str) -> list[str]:
    """A note for each sensor column whose name ends in a bare ``(F)`` / ``[C]`` / ``/F``
    that is read as a label (``TC (F)``: front), not a unit, while the column is read in
    another temperature unit: a degF logger's ``TC_DE (F)`` read as degC (95-122 taken as
    degC) said nothing."""
    from .measured_layout import bracket_unit, slash_unit

    letters = {"c": "degC", "f": "degF"}
    out = []
    for col in sensors:
        if col in stated:
            continue
        letter = (bracket_unit(col) or slash_unit(col)).strip().lower()
        read = col_units.get(col, unit)
        if letter in letters and letters[letter] != read:
            out.append(f"column {col!r}: its {letter.upper()!r} is read as a label, not as "
                       f"{letters[letter]}; the readings are taken in {read} ({field}.unit): "
                       f"if they are {letters[letter]}, set unit = \"{letters[letter]}\"")
    return out


def _is_dropout(cell: str) -> bool:
    c = cell.strip().lower()
    return c in DROPOUT_FLAGS or bool(_DASHES.match(c))


def _parse_readings(cells: list[str], decimal: str, col: str, at: list[int],
                    codes: frozenset[float], texts: frozenset[str]
                    ) -> tuple[np.ndarray, dict[str, int]]:
    """The numbers of a sensor column in the file's unit, NaN at gaps; the gap count by
    cause."""
    text = [c.replace(",", ".") for c in cells] if decimal == "," else cells  # stripped
    out = np.asarray(pd.to_numeric(np.asarray(text, dtype=object), errors="coerce"),
                     dtype=float)
    gaps = {"empty cells": 0, "dropout flags": 0, "overload codes": 0,
            "missing_values codes": 0}
    with np.errstate(invalid="ignore"):
        overload = np.abs(out) >= OVERLOAD_CODE  # +9.9E+37 and the like: a gap
    listed = np.isin(out, list(codes)) if codes else np.zeros(out.shape, bool)
    for k in np.flatnonzero(~np.isfinite(out) & ~overload):  # text, nan, inf
        c = cells[k].strip()
        if c == "":
            gaps["empty cells"] += 1
        elif c.lower() in texts:
            gaps["missing_values codes"] += 1
        elif _is_dropout(c):
            gaps["dropout flags"] += 1
        else:
            raise InputError(f"measured column {col!r}", f"row {k + 1}: {c!r} (line {at[k]})",
                             "numbers (an empty cell or a dropout flag such as OVL, "
                             "----, Err, N/A is a gap; other codes: measured missing_values)")
        out[k] = math.nan
    gaps["overload codes"] = int(overload.sum())
    gaps["missing_values codes"] += int((listed & ~overload).sum())
    out[overload | listed] = math.nan
    return out, gaps


def _to_celsius(values: np.ndarray, unit: str, col: str, cells: list[str],
                at: list[int]) -> np.ndarray:
    """degC of readings in ``unit``; a reading at or below absolute zero (no instrument
    reads 0 K: a code) or above the top of the thermocouple tables is an error (a logger
    code to list in missing_values)."""
    out = _TO_C[unit](values)
    with np.errstate(invalid="ignore"):
        bad = (out <= ABSOLUTE_ZERO_C + 1e-9) | (out > THERMOCOUPLE_MAX_C)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        same = int(np.sum(values[bad] == values[k]))
        raise InputError(f"measured column {col!r}", f"row {k + 1}: {cells[k].strip()!r} "
                         f"(line {at[k]}; {same} reading(s) of this value, {int(bad.sum())} "
                         "out of range in the column)",
                         f"temperatures in {unit} above absolute zero "
                         f"({ABSOLUTE_ZERO_C:g} degC) and up to {THERMOCOUPLE_MAX_C:g} degC "
                         "(top of the IEC 60584-1 thermocouple tables); a logger's code for no "
                         "reading is a gap when listed in measured missing_values, e.g. "
                         f"missing_values = [{cells[k].strip().replace(',', '.')}]")
    return out


def _range_end_notes(values: np.ndarray, col: str, at: list[int]) -> list[str]:
    """A note per thermocouple range end the column reads exactly (an open thermocouple
    pinned there by the logger?); the readings stay (list them in missing_values)."""
    out = []
    for end, types in RANGE_ENDS_C.items():
        hit = np.flatnonzero(np.abs(values - end) < 1e-6)
        if hit.size:
            out.append(f"{col}: {hit.size} reading(s) of exactly {end:g} degC (first at line "
                       f"{at[int(hit[0])]}), the end of the type {types} thermocouple range "
                       "(IEC 60584-1): an open thermocouple? If so, list the code in "
                       "measured missing_values")
    return out


def _kelvin_note(values: np.ndarray, col: str) -> list[str]:
    """A note when a column read as degC (no unit in the file) has every reading above
    273.15: what a thermocouple channel set to K gives at rig temperatures."""
    finite = values[np.isfinite(values)]
    if finite.size and float(finite.min()) > 273.15:
        return [f"{col}: every reading is above 273.15 (lowest {float(finite.min()):g}), read "
                "as degC: a channel logging in K? Then set measured unit = \"K\" or give "
                "the unit in the file (units row, or the column name: [K])"]
    return []


def _average_repeats(out: pd.DataFrame, at: list[int], notes: list[str]) -> pd.DataFrame:
    """Rows with the same time as the row before: one row, the mean of their readings
    (gaps left out; all gaps stay a gap)."""
    t = out["time [s]"].to_numpy(float)
    repeat = np.r_[False, np.diff(t) == 0.0]
    if not repeat.any():
        return out
    group = np.cumsum(~repeat) - 1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # mean of an all-gap group: NaN
        merged = out.groupby(group, sort=False).agg(
            {c: "first" if c == "time [s]" else (lambda s: float(np.nanmean(s)) if
                                                 s.notna().any() else math.nan)
             for c in out.columns}).reset_index(drop=True)
    first = int(np.flatnonzero(repeat)[0])
    notes.append(f"{int(repeat.sum())} row(s) repeat the time of the row before and are "
                 f"averaged with it (first at line {at[first]}, {t[first]:g} s); "
                 f"{len(merged)} of {len(out)} rows kept")
    return merged
