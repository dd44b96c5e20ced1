"""The time column of a rig's thermocouple file, in elapsed seconds.

One job for :mod:`thermobearing.measured`: read the time cells (numbers in a unit, elapsed
``hh:mm:ss``, timestamps of the usual logger layouts, Excel serial day numbers, Unix
seconds, or a ``strptime`` pattern the scene gives) as seconds from the time zero, and
refuse times that step back with an error naming the row and the size of the step (a
clock-time column ``hh:mm:ss`` passing midnight gets 24 h added from there, noted).

Excel serial dates (``46349.4375`` = a day number plus the fraction of the day) are read
as such only with a clear sign: ``time_format = "excel"`` (or ``"excel_1904"``), or a
time column named as a date (``Date``, ``DateTime``, ``Date/Time``, ``Datum``, ``Excel
time``; no unit in its name or the units row) whose first cell is a number in the
day-number range of the years 1950-2099 (18264-73050). Any other column of numbers without
a unit (``Time``, ``Timestamp``: a seconds counter or seconds since midnight look the same)
stays seconds; when its first cell lies in that range the notes say so and name the
option.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from datetime import datetime, timedelta

import numpy as np

from .errors import InputError

__all__ = ["DATE_NAMES", "EXCEL_RANGE", "TIME_FORMATS", "parse_times"]

#: time column names (case-insensitive, without a bracketed unit) that say "a date"
#: (``Timestamp`` is not among them: DAQ programs also name a seconds counter so)
DATE_NAMES = frozenset({
    "date", "datetime", "date time", "date/time", "date_time", "date-time", "date&time",
    "datum", "datum/uhrzeit", "datum uhrzeit", "excel time", "excel date"})
#: Excel serial day numbers (1900 date system) of 1950-01-01 and 2099-12-31: the range in
#: which a date-named column of numbers is read as Excel dates without ``time_format``
EXCEL_RANGE = (18264.0, 73050.0)
#: named values of ``time_format`` (besides a strptime pattern with ``%``)
TIME_FORMATS = {
    "excel": "Excel/LibreOffice serial day numbers, 1900 date system (46349.4375)",
    "excel_1904": "Excel serial day numbers, 1904 date system (old Mac Excel)",
    "unix": "Unix time: seconds since 1970-01-01 00:00 UTC",
}
_EXCEL_EPOCH = datetime(1899, 12, 30)  # serial 61 = 1900-03-01 (Excel's 1900-02-29 skipped)
_EPOCHS = {"excel": (_EXCEL_EPOCH, 86400.0), "excel_1904": (datetime(1904, 1, 1), 86400.0),
           "unix": (datetime(1970, 1, 1), 1.0)}
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
_KNOWN = ("numbers (in the unit of the column name's brackets or the units row), elapsed "
          "hh:mm:ss / mm:ss, or timestamps yyyy-mm-dd hh:mm:ss (ISO 8601, T allowed), "
          "dd.mm.yyyy hh:mm:ss, yyyy/mm/dd hh:mm:ss, dd/mm/yyyy hh:mm:ss (or set the "
          "scene's measured time_format: excel, excel_1904, unix or a strptime pattern such "
          "as \"%d/%m/%Y %H:%M:%S\")")


def number(cell: str, decimal: str) -> float | None:
    """The finite number in ``cell`` (decimal mark ``decimal``), or None."""
    c = cell.strip()
    if decimal == ",":
        c = c.replace(",", ".")
    try:
        x = float(c)
    except ValueError:
        return None
    return x if np.isfinite(x) else None


def elapsed(cell: str) -> float | None:
    """Seconds of an elapsed ``hh:mm:ss[.f]`` or ``mm:ss[.f]`` cell, or None."""
    m = _ELAPSED.match(cell.strip())
    if m is None:
        return None
    a, b, c, frac = m.groups()
    if c is None:  # mm:ss
        if int(b) >= 60:
            return None
        seconds = int(a) * 60 + int(b)
    else:
        if int(b) >= 60 or int(c) >= 60:
            return None
        seconds = int(a) * 3600 + int(b) * 60 + int(c)
    return seconds + (float("0." + frac) if frac else 0.0)


def elapsed_hours(cell: str) -> float | None:
    """Seconds of an elapsed ``h:mm[.f]`` cell (hours and minutes, the fraction of a
    minute) or ``hh:mm:ss[.f]`` cell, or None: the reading of a two-field time column
    whose name or units row says ``h:mm`` / ``hh:mm`` (``elapsed`` reads two fields as
    minutes and seconds, which made ``0:10`` of a ``time [h:mm]`` column 10 s)."""
    m = _ELAPSED.match(cell.strip())
    if m is None:
        return None
    a, b, c, frac = m.groups()
    if c is not None:
        return elapsed(cell)
    if int(b) >= 60:
        return None
    return int(a) * 3600 + int(b) * 60 + (float("0." + frac) * 60.0 if frac else 0.0)


#: units of a time column of two-field cells read as hours and minutes
HOURS_MINUTES = ("h:mm", "hh:mm", "h:min", "hh:min", "hours:minutes")


def _strptime(cell: str, fmt: str) -> datetime | None:
    c = cell.strip()
    frac = 0.0
    m = re.match(r"^(.*:\d{2})[.,](\d+)(\s*[AaPp][Mm])?$", c)  # 10:15:30.250 [AM]
    if m and "%S" in fmt:
        c, frac = m.group(1) + (m.group(3) or ""), float("0." + m.group(2))
    try:
        return datetime.strptime(c, fmt) + timedelta(seconds=frac)
    except ValueError:
        return None


def _iso(cell: str) -> datetime | None:
    c = cell.strip()
    if not re.match(r"^\d{4}-\d{2}-\d{2}", c):
        return None
    try:
        return datetime.fromisoformat(c)
    except ValueError:
        return None


def _stamp_parser(first: str, cells: list[str], name: str
                  ) -> tuple[Callable[[str], datetime | None] | None, str]:
    """A parser str -> datetime | None for the timestamp layout of ``first`` (None if it
    is no timestamp); the description of that layout."""
    if _iso(first) is not None:
        return _iso, "ISO 8601 yyyy-mm-dd hh:mm:ss"
    text = first.strip()
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
                             "apart (write yyyy-mm-dd or dd.mm.yyyy, or set the scene's "
                             "measured time_format, e.g. \"%d/%m/%Y %H:%M:%S\")")
        candidates = ok or candidates
    fmt, desc = candidates[0]
    return (lambda c: _strptime(c, fmt)), desc


def _any_stamp(text: str) -> datetime | None:
    """A timestamp of any known layout (for a ``time_zero`` given as a date)."""
    got = _iso(text)
    if got is not None:
        return got
    for fmt, _ in _STAMP_FORMATS:
        got = _strptime(text, fmt)
        if got is not None:
            return got
    return None


def _serial_parser(fmt: str, decimal: str) -> Callable[[str], datetime | None]:
    epoch, scale = _EPOCHS[fmt]

    def parse(c: str) -> datetime | None:
        x = number(c, decimal)
        if x is None or (fmt == "excel" and x < 61.0):  # before 1900-03-01: Excel's bug
            return None
        try:  # whole milliseconds: Excel's clock resolution (and exports' last digits)
            return epoch + timedelta(seconds=round(x * scale, 3))
        except OverflowError:
            return None
    return parse


def check_time_format(time_format: str | None, field: str) -> None:
    """``time_format`` must be None, ``"auto"``, a name of :data:`TIME_FORMATS` or a
    strptime pattern (with ``%``)."""
    if time_format is None or time_format == "auto" or time_format in TIME_FORMATS:
        return
    if isinstance(time_format, str) and "%" in time_format:
        return
    raise InputError(f"{field}.time_format", time_format,
                     "auto, " + ", ".join(f"{k} ({v})" for k, v in TIME_FORMATS.items())
                     + ", or a strptime pattern such as \"%d/%m/%Y %H:%M:%S\"")


def parse_times(cells: list[str], tunit: str | None, decimal: str, time_zero: str | None,
                time_column: str, field: str, at: list[int], *,
                time_format: str | None = None, notes: list[str] | None = None
                ) -> tuple[np.ndarray, str]:
    """Elapsed seconds of the time cells (the format of the first row for all rows) and
    the description of the format read.

    ``tunit``: the unit of a number column (from its name or the units row); None when
    neither gives one (seconds, or Excel dates for a date-named column, see the module
    docstring). The times may repeat (the caller averages such rows) but never step back:
    that is an error naming the row, the step and its likely cause.
    """
    check_time_format(time_format, field)
    name = f"measured column {time_column!r}"
    first = cells[0].strip()
    fmt = None if time_format in (None, "auto") else time_format
    parse: Callable[[str], object]
    x0 = number(first, decimal)
    day_numbers = x0 is not None and tunit is None and EXCEL_RANGE[0] <= x0 <= EXCEL_RANGE[1]
    if fmt is None and day_numbers:
        if _date_named(time_column):
            fmt = "excel"  # a date column of day numbers: the clear sign (module docstring)
        elif notes is not None:
            notes.append(f"time column {time_column!r}: numbers without a unit, read as "
                         f"seconds; row 1 ({first}) is also an Excel day number "
                         f"({_EXCEL_EPOCH + timedelta(days=x0):%Y-%m-%d %H:%M}): if the "
                         "column holds Excel dates, set measured time_format = \"excel\"")
    if fmt in _EPOCHS:
        kind, desc, parse = "stamp", TIME_FORMATS[fmt], _serial_parser(fmt, decimal)
    elif fmt is not None:
        kind, desc = "stamp", f"the pattern {fmt!r}"

        def parse(c: str) -> datetime | None:
            return _strptime(c, fmt)
    elif number(first, decimal) is not None:
        scale = _time_scale(tunit, time_column, field)
        kind, desc = "number", f"numbers in {tunit or 's'}"

        def parse(c: str) -> float | None:
            x = number(c, decimal)
            return None if x is None else x * scale
    elif (tunit or "").strip().lower() in HOURS_MINUTES and elapsed_hours(first) is not None:
        kind, desc, parse = "elapsed", f"elapsed h:mm (hours:minutes, as {tunit!r} says)", \
            elapsed_hours
    elif elapsed(first) is not None:
        kind, desc, parse = "elapsed", "elapsed hh:mm:ss or mm:ss", elapsed
    else:
        stamp, desc = _stamp_parser(first, cells, name)
        if stamp is None:
            raise InputError(name, f"row 1: {first!r} (line {at[0]})", _KNOWN)
        kind, parse = "stamp", stamp
    values: list = []
    for k, c in enumerate(cells):
        v = parse(c) if c.strip() else None
        if v is None:
            again = c.strip().lower() == time_column.replace(" + ", " ").strip().lower()
            raise InputError(name, f"row {k + 1}: {c!r} (line {at[k]})",
                             f"a time in every row, in the format of row 1 ({desc})" + (
                                 "; this is the header row again: a second recording "
                                 "appended to the file? Give each recording its own file"
                                 if again else ""))
        values.append(v)
    if kind == "stamp":
        aware = [v.tzinfo is not None for v in values]
        if len(set(aware)) > 1:
            k = aware.index(not aware[0])
            raise InputError(name, f"row {k + 1}: {cells[k]!r} (line {at[k]})",
                             "timestamps all with or all without a UTC offset")
    if kind == "elapsed":
        values = _past_midnight(values, at, notes)
    zero = _time_zero(time_zero, values, parse, kind, desc, field)
    if kind == "stamp":
        t = np.array([(v - zero).total_seconds() for v in values])
    else:
        t = np.asarray(values, dtype=float) - float(zero)
    _check_increasing(t, cells, at, name, kind, aware=kind == "stamp" and aware[0])
    return t, desc


def _time_scale(tunit: str | None, time_column: str, field: str) -> float:
    """Seconds per unit of a time column of numbers (``tunit`` from its name or the units
    row; None: seconds). A unit that is no time is an error naming the column and the
    unit (it said ``measured.time_column = '1 m'``, the probe it converted); ``m`` is
    metres, so it names ``min``."""
    from .units import to_si

    try:
        return to_si(f"1 {tunit or 's'}", "time", field=f"{field}.time_column")
    except InputError:
        hint = ("; 'm' is metres: write min for minutes" if (tunit or "").strip() == "m"
                else "")
        raise InputError(f"{field}.time_column", time_column,
                         f"a time unit for its numbers, in the name's brackets, after a slash "
                         f"or in the units row: s, min, h or ms (the file gives {tunit!r}"
                         f"{hint}); elapsed hh:mm:ss cells need no unit") from None


def _date_named(time_column: str) -> bool:
    bare = re.sub(r"[\[(][^\])]*[\])]\s*$", "", time_column).strip().lower()
    return bare in DATE_NAMES


def _past_midnight(values: list[float], at: list[int], notes: list[str] | None
                   ) -> list[float]:
    """A time-of-day column (``hh:mm:ss`` below 24 h) crossing midnight: 24 h added from
    each row where the clock falls back by one day less the sampling step (noted)."""
    v = np.asarray(values, dtype=float)
    if v.size < 2 or v.max() >= 86400.0:
        return values
    steps = np.diff(v)
    ahead = steps[steps > 0]
    usual = float(np.median(ahead)) if ahead.size else 0.0
    wrap = np.flatnonzero((steps < 0) & (np.abs(-steps + usual - 86400.0) <= max(60.0, usual)))
    if not wrap.size:
        return values
    days = np.zeros(v.size)
    for k in wrap:
        days[k + 1:] += 86400.0
    if notes is not None:
        notes.append(f"the clock times pass midnight {wrap.size} time(s) (first at line "
                     f"{at[int(wrap[0]) + 1]}): 24 h added from there")
    return list(v + days)


def _check_increasing(t: np.ndarray, cells: list[str], at: list[int], name: str,
                      kind: str, aware: bool) -> None:
    """Equal times are allowed (averaged by the caller); a step back is an error."""
    steps = np.diff(t)
    if not steps.size or (steps >= 0).all():
        return
    k = int(np.flatnonzero(steps < 0)[0]) + 1
    back = float(-steps[k - 1])
    why = ""
    ahead = steps[steps > 0]
    usual = float(np.median(ahead)) if ahead.size else 0.0
    # a clock set back one hour jumps back by 1 h less the sampling step
    if kind == "stamp" and not aware and abs(back + usual - 3600.0) <= max(60.0, usual):
        why = (": a daylight-saving change (local clock set back one hour)? Log in UTC or "
               "with a UTC offset (ISO 8601 2026-10-25T02:30:00+01:00), or cut the file "
               "there")
    elif float(t[k]) <= float(t[0]) + 1e-9 * max(1.0, abs(float(t[0]))):
        why = (": the logger restarted (its clock began again)? Give each run its own "
               "file, or cut the file there")
    raise InputError(name, f"row {k + 1}: {cells[k].strip()} after {cells[k - 1].strip()} "
                     f"(line {at[k]})",
                     f"strictly increasing times (rows with the same time are averaged); "
                     f"the time steps back by {back:g} s{why}")


def _quantity_seconds(text: str) -> float | None:
    """Seconds of a time with its unit (``"5 min"``, ``"300 s"``), None for other text."""
    from .units import to_si

    if not re.search(r"[A-Za-z]", text):
        return None
    try:
        return float(to_si(text, "time", field="measured.time_zero"))
    except InputError:
        return None


def _time_zero(time_zero: str | None, values: list, parse: Callable[[str], object],
               kind: str, desc: str, field: str):
    if time_zero is None:
        return values[0] if kind == "stamp" else 0.0
    if str(time_zero).strip().lower() == "first":
        return values[0]
    zero = parse(str(time_zero))
    if zero is None and kind == "stamp":  # Excel / Unix / pattern: a date is fine too
        zero = _any_stamp(str(time_zero))
    if zero is None and kind != "stamp":
        # numbers or elapsed times (seconds here): a unit string, as the scene writes its
        # other times ("5 min"; it was refused, only a bare 5 in the column's unit read)
        zero = _quantity_seconds(str(time_zero))
    if zero is None:
        raise InputError(f"{field}.time_zero", time_zero, f"\"first\" or a time in the format "
                         f"of the file's time column ({desc})"
                         + ("" if kind == "stamp" else ", or with a unit (\"5 min\")"))
    if kind == "stamp" and (zero.tzinfo is None) != (values[0].tzinfo is None):
        raise InputError(f"{field}.time_zero", time_zero, "a timestamp with a UTC offset "
                         "exactly when the file's timestamps have one")
    return zero
