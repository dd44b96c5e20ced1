"""Layout of a rig's thermocouple file: separator, header row, cells of a row, units row.

One job for :mod:`thermobearing.measured`: find the header row (the row with the scene's
``time_column``) and the separator, then split every row into cells the same way.

Separators: tab, semicolon, comma (quoted cells may hold them), or spaces. A file whose
columns are separated by spaces is read by one rule:

- the header row is split at runs of **two or more** spaces when that gives a cell equal
  to ``time_column`` (names with single spaces inside, ``Time [s]   TC 1 outer ring``, as a
  fixed-width export or an aligned table writes them), else at every run of spaces;
- a data row is split the same way (runs of 2+ spaces, else every run) when that gives as
  many cells as the header; a row of more pieces whose first column is the time joins its
  first pieces into the time cell (``2026-11-23 10:15:30 35.2 35.0``); otherwise (a blank
  cell, or one space between two cells) each piece of the row goes to the header name it
  lies under (its characters overlap that name's, or it is nearest to it): blank cells of
  a fixed-width export are then gaps. Two pieces under one name is an error naming the
  row.
"""

from __future__ import annotations

import csv
import difflib
import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from .errors import InputError
from .signal_input import guess_separator, is_units_row
from .text_files import text_encoding

__all__ = ["Layout", "NAME_UNITS", "TEMPERATURE_UNITS", "bracket_unit", "closest_name",
           "file_encoding", "find_layout", "is_time_format", "looks_like_units",
           "non_temperature_units", "slash_unit", "stated_units"]

SPACES = "spaces"
_SEPARATORS = ("\t", ";", ",", SPACES)
_WIDE = re.compile(r"\s{2,}")
_ANY = re.compile(r"\s+")
#: unit texts of a units row or a column name's brackets -> the reader's unit names
TEMPERATURE_UNITS = {"degc": "degC", "°c": "degC", "c": "degC", "celsius": "degC",
                     "k": "K", "kelvin": "K", "degf": "degF", "°f": "degF", "f": "degF",
                     "fahrenheit": "degF", "deg c": "degC", "deg f": "degF", "℃": "degC",
                     "deg. c": "degC", "deg. f": "degF", "°k": "K", "℉": "degF"}
#: units a logger writes for channels that are no temperature (a thermocouple's raw
#: voltage, a pressure, a speed, a humidity), recognised in a column name's brackets or
#: after its slash (case-sensitive). Single letters (``V``, ``A``) and words that are also
#: position labels (``in``: inlet, ``out``) are left out there: ``T_oil (in)`` is a label;
#: a units row, where every cell is a unit, is checked with pint instead
NAME_UNITS = frozenset({
    "mV", "µV", "μV", "uV", "kV", "mA", "µA", "μA", "uA", "%", "%RH", "% RH", "bar", "mbar",
    "hPa", "kPa", "MPa", "Pa", "psi", "Ohm", "ohm", "Ω", "kOhm", "kΩ", "rpm", "r/min",
    "1/min", "Hz", "kHz", "Nm", "N m", "kN", "mm/s", "m/s", "m/s²", "m/s^2", "L/min", "l/min",
    "W", "kW"})


def _pieces(line: str, pattern: re.Pattern) -> list[tuple[str, int, int]]:
    """The non-blank pieces of ``line`` between matches of ``pattern``: (text, start, end)."""
    out, pos = [], 0
    for m in pattern.finditer(line):
        if m.start() > pos:
            out.append((line[pos:m.start()], pos, m.start()))
        pos = m.end()
    if pos < len(line):
        out.append((line[pos:], pos, len(line)))
    return [(t.strip(), a, b) for t, a, b in out if t.strip()]


@dataclass(frozen=True)
class Layout:
    """How the rows of one file split into cells.

    ``sep``: ``"\\t"``, ``";"``, ``","`` or ``"spaces"``; ``spans``: character spans of the
    header names (spaces only: where the cells of a fixed-width row lie); ``wide``: the
    header was split at runs of two or more spaces; ``time_first``: the time column is the
    first (spaces only: a row with more pieces than names joins its first pieces, a
    timestamp such as ``2026-11-23 10:15:30`` with single spaces around it).
    """

    sep: str
    spans: tuple[tuple[int, int], ...] = ()
    wide: bool = False
    time_first: bool = False

    @property
    def name(self) -> str:
        return {"\t": "tab", SPACES: "spaces"}.get(self.sep, self.sep)

    def header(self, line: str) -> list[str]:
        if self.sep == SPACES:
            return [t for t, _, _ in _pieces(line, _WIDE if self.wide else _ANY)]
        return split_delimited(line, self.sep)

    def split(self, line: str, row: str = "") -> list[str]:
        """The cells of a data row (``row`` names it in an error: ``row 3 (line 7)``)."""
        if self.sep != SPACES:
            return split_delimited(line, self.sep)
        n = len(self.spans)
        for pattern in ((_WIDE, _ANY) if self.wide else (_ANY,)):
            cells = [t for t, _, _ in _pieces(line, pattern)]
            if len(cells) == n:
                return cells
        if self.time_first and len(cells) > n and not _is_number(cells[0]):
            # a timestamp with a space in column 1 (a time of numbers holds none)
            extra = len(cells) - n
            return [" ".join(cells[:extra + 1]), *cells[extra + 1:]]
        return self._by_position(line, row)

    def _by_position(self, line: str, row: str) -> list[str]:
        """Fixed-width row: each piece (split at 2+ spaces) under the header name it
        overlaps most, or the nearest one."""
        cells = [""] * len(self.spans)
        for text, a, b in _pieces(line, _WIDE):
            overlap = [max(0, min(b, e) - max(a, s)) for s, e in self.spans]
            if max(overlap) > 0:
                k = overlap.index(max(overlap))
            else:
                mid = (a + b) / 2.0
                dist = [min(abs(mid - s), abs(mid - e)) for s, e in self.spans]
                k = dist.index(min(dist))
            if cells[k]:
                raise InputError("measured.file", f"{row}: {line.strip()!r}",
                                 "cells separated by two or more spaces, or each under its "
                                 f"column name (two cells lie under column {k + 1})")
            cells[k] = text
        return cells


def split_delimited(line: str, sep: str) -> list[str]:
    try:
        return [c.strip() for c in next(csv.reader([line], delimiter=sep, quotechar='"'),
                                         [])]
    except csv.Error as exc:  # e.g. a NUL byte: not a text file
        raise InputError("measured.file", line[:60], f"lines of text ({exc})") from None


def file_encoding(p: Path) -> str:
    """UTF-8 (BOM or not) when the file decodes as UTF-8, UTF-16 after its byte-order mark
    (Excel's "Unicode text"), else Windows-1252: loggers on Windows write ``°C`` and
    umlauts in the ANSI code page (:func:`thermobearing.text_files.text_encoding`)."""
    return text_encoding(p)


def _has(cells: Sequence[str], name: str) -> bool:
    return name in cells or name.strip().lower() in (c.lower() for c in cells)


def find_layout(lines: list[tuple[int, str]], time_column: str, want: Sequence[str] = ()
                ) -> tuple[Layout, int | None, list[str]]:
    """Layout, index (in ``lines``) and cells of the header row: the first row with a cell
    equal to ``time_column`` (case-insensitive as a fallback) and to every name of
    ``want`` (a metadata line ``Time;10:15:30`` above the header is passed over), else the
    first with ``time_column`` alone; under the guessed separator, then under the others
    (spaces: runs of 2+ spaces first, see the module docstring). When none has it: the
    guessed layout and the widest of the first rows (for the error)."""
    body = [ln for _, ln in lines[:200]]
    guess = guess_separator(body)
    guess = SPACES if guess == r"\s+" else guess
    for names in ((time_column, *want), (time_column,)) if want else ((time_column,),):
        for sep in (guess, *(s for s in _SEPARATORS if s != guess)):
            for k, (_, ln) in enumerate(lines[:200]):
                if sep != SPACES:
                    cells = split_delimited(ln, sep)
                    if all(_has(cells, n) for n in names):
                        return Layout(sep), k, cells
                    continue
                for wide in (True, False):
                    pieces = _pieces(ln, _WIDE if wide else _ANY)
                    cells = [t for t, _, _ in pieces]
                    if all(_has(cells, n) for n in names):
                        spans = tuple((a, b) for _, a, b in pieces)
                        return (Layout(SPACES, spans, wide, _has(cells[:1], time_column)), k,
                                cells)
    layout = Layout(guess)
    widest = max((layout.header(ln) for ln in body[:50]), key=len)
    return layout, None, widest


def closest_name(name: str, names: Sequence[str]) -> str:
    """`` (did you mean 'TC2'?)`` for a near miss among ``names`` (a typo), else ""."""
    lowered = {n.lower(): n for n in names}
    hit = difflib.get_close_matches(name.lower(), list(lowered), n=1, cutoff=0.6)
    return f" (did you mean {lowered[hit[0]]!r}?)" if hit else ""


def is_time_format(cell: str) -> bool:
    c = cell.strip().strip("[]()").lower()
    return c in ("hh:mm:ss", "h:mm:ss", "mm:ss", "hh:mm:ss.s", "hh:mm:ss.ss", "hh:mm:ss.sss",
                 "date", "datetime", "timestamp", "yyyy-mm-dd hh:mm:ss", "dd.mm.yyyy hh:mm:ss",
                 "yyyy-mm-dd", "dd.mm.yyyy", "mm/dd/yyyy", "dd/mm/yyyy", "time", "clock")


def _is_number(cell: str) -> bool:
    try:
        return math.isfinite(float(cell.strip().replace(",", ".")))
    except ValueError:
        return False


def looks_like_units(cells: list[str], tcols: list[int]) -> bool:
    """A units row: every non-empty cell a unit (the time cell may also be a time format
    such as ``hh:mm:ss``), at least one not empty, and no cell a number."""
    if any(_is_number(c) for c in cells if c):
        return False
    probe = ["" if (j in tcols and is_time_format(c)) else _unit_text(c)
             for j, c in enumerate(cells)]
    if not any(probe):
        return any(cells)
    return is_units_row(probe)


def _unit_text(cell: str) -> str:
    c = cell.replace("℃", "degC").replace("℉", "degF")
    return "degC" if c.strip().strip("[]()").lower() in ("deg. c", "°k") else c


def bracket_unit(name: str) -> str:
    """The unit in a column name's brackets (``TC1 [K]``, ``Temp (°C)``), or ""."""
    m = re.search(r"[\[(]\s*([^\])]+?)\s*[\])]\s*$", name)
    return m.group(1) if m else ""


def slash_unit(name: str) -> str:
    """The text after the last slash of a name written quantity/unit (DIN 1313:
    ``t/min``, ``Zeit / s``, ``T1/°C``), or "" (the caller checks it is a unit)."""
    m = re.match(r"^.*\S\s*/\s*([^/\s][^/]*?)\s*$", name)
    return m.group(1) if m else ""


def stated_units(units_row: list[str] | None, header: list[str],
                 idx: Mapping[str, int]) -> dict[str, tuple[str, str]]:
    """The temperature unit the file itself gives each mapped column, with where it says
    so: ``{column: (unit, "units row" | "column name")}``. The units row wins over the
    name's brackets, those over a ``/unit`` ending (``T1/°C``); a bare ``C`` / ``F`` in
    a name (``TC (F)``: front, ``TC/F``) is no unit."""
    out: dict[str, tuple[str, str]] = {}
    for col, j in idx.items():
        if units_row is not None and j < len(units_row):
            said = TEMPERATURE_UNITS.get(units_row[j].strip().strip("[]()").lower())
            if said is not None:
                out[col] = (said, "units row")
                continue
        text = bracket_unit(header[j]).lower()
        if text not in ("c", "f") and TEMPERATURE_UNITS.get(text) is not None:
            out[col] = (TEMPERATURE_UNITS[text], "column name")
            continue
        text = slash_unit(header[j]).lower()  # T1/°C; a bare /C or /F may be a label
        if text not in ("c", "f") and TEMPERATURE_UNITS.get(text) is not None:
            out[col] = (TEMPERATURE_UNITS[text], "column name")
    return out


def _units_row_other(cell: str) -> str:
    """The text of a units-row cell that is a unit but no temperature (``mV``, ``%``,
    ``bar``), else "" (empty, ``-``, a temperature, or no unit pint knows)."""
    from .units import unit_registry

    text = cell.strip().strip("[]()").strip()
    if not text or text == "-" or TEMPERATURE_UNITS.get(text.lower()) is not None:
        return ""
    if text.startswith("%"):
        return text
    probe = text.replace("µ", "u").replace("μ", "u").replace("²", "**2")
    try:
        q = unit_registry().parse_expression(probe)
    except Exception:  # noqa: BLE001 - pint raises many kinds for a non-unit word
        return ""
    dims = getattr(q, "dimensionality", None)
    if dims is None or "[temperature]" in dict(dims):
        return ""
    return text


def non_temperature_units(units_row: list[str] | None, header: list[str],
                          idx: Mapping[str, int],
                          stated: Mapping[str, tuple[str, str]]) -> dict[str, tuple[str, str]]:
    """The mapped columns (not in ``stated``) to which the file gives a unit that is no
    temperature: ``{column: (unit text, "units row" | "column name")}``. A units-row cell
    counts when pint reads it as a unit of another dimension (``mV``, ``V``, ``bar``) or
    it is a percentage; a column name's brackets or ``/unit`` ending when the text is one
    of :data:`NAME_UNITS` (``TC3 [mV]``, ``P1/bar``). Such a column read as temperatures
    took a thermocouple's 1-4 mV as 1-4 degC without a word."""
    out: dict[str, tuple[str, str]] = {}
    for col, j in idx.items():
        if col in stated:
            continue
        if units_row is not None and j < len(units_row):
            text = _units_row_other(units_row[j])
            if text:
                out[col] = (text, "units row")
                continue
        for text in (bracket_unit(header[j]), slash_unit(header[j])):
            if text.strip() in NAME_UNITS:
                out[col] = (text.strip(), "column name")
                break
    return out
