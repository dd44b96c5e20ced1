"""Repeated validity warnings of a run merged into one line each.

A model that is used outside its fitted range warns at every call (e.g. the film formula at
every contact set, step and heat evaluation), each time with slightly different numbers; a
spindle run-up listed 38 such lines for one bearing. :class:`WarningGroups` keeps one line per
bearing and message *shape* (the message with its numbers masked): the first message, with
every "in [lo, hi]" interval widened to the envelope of all repeats, the steps it came from
and how many times it was raised. A range warning of a model (``"name: X in [lo, hi] outside
[a, b]; Y in ..."``, as :mod:`thermobearing.film` words them) is one line per bearing
and model, whichever of its variables left the range at each call: each variable keeps its
own envelope, in the order they first appeared (the default rig had listed three film-formula
lines per bearing, for U and W together, W alone and U alone). The lines live in the caller's
list (the run's warnings), so other notes appended there keep their order.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
_INTERVAL = re.compile(r"in \[([^,\]]+), ([^\]]+)\]")
#: one variable of a model's range warning: name, its interval, the allowed interval
_RANGE = re.compile(r"(\S+) in \[([^,\]]+), ([^\]]+)\] (outside \[[^\]]+\])")


def _float(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


@dataclass
class _Group:
    index: int
    bearing: str
    message: str
    steps: set[int] = field(default_factory=set)
    count: int = 1
    lows: list[float | None] = field(default_factory=list)
    highs: list[float | None] = field(default_factory=list)
    #: a model's range warning: its name and, per variable, [lo, hi, "outside [a, b]",
    #: lo and hi as written] (a bound written once keeps its text)
    model: str | None = None
    ranges: dict[str, list] = field(default_factory=dict)

    def merge(self, message: str, step: int | None) -> None:
        self.count += 1
        if step is not None:
            self.steps.add(step)
        if self.model is not None:
            parsed = _range_warning(message)
            if parsed is None:
                return
            for (name, (lo, hi, allowed)), (lo_t, hi_t) in zip(
                    parsed[1].items(), _interval_texts(message), strict=True):
                cur = self.ranges.setdefault(name, [lo, hi, allowed, lo_t, hi_t])
                if lo < cur[0]:
                    cur[0], cur[3] = lo, lo_t
                if hi > cur[1]:
                    cur[1], cur[4] = hi, hi_t
            return
        for i, m in enumerate(_INTERVAL.finditer(message)):
            if i >= len(self.lows):
                break
            lo, hi = _float(m.group(1)), _float(m.group(2))
            if lo is not None and self.lows[i] is not None:
                self.lows[i] = min(self.lows[i], lo)
            if hi is not None and self.highs[i] is not None:
                self.highs[i] = max(self.highs[i], hi)

    def line(self) -> str:
        if self.model is not None:
            text = f"{self.model}: " + "; ".join(
                f"{name} in [{r[3]}, {r[4]}] {r[2]}" for name, r in self.ranges.items())
            return self._located(text, "; intervals are the envelope of all")
        k = iter(range(len(self.lows)))

        def widened(m: re.Match) -> str:
            i = next(k)
            lo, hi = self.lows[i], self.highs[i]
            if lo is None or hi is None:
                return m.group(0)
            return f"in [{lo:.3g}, {hi:.3g}]"

        text = _INTERVAL.sub(widened, self.message) if self.count > 1 else self.message
        return self._located(text, "; intervals are the envelope of all" if self.lows else "")

    def _located(self, text: str, envelope: str) -> str:
        """``text`` after the bearing and steps, with the repeat count."""
        steps = sorted(self.steps)
        where = self.bearing
        if len(steps) == 1:
            where += f", step {steps[0]}"
        elif steps:
            where += f", steps {steps[0]}-{steps[-1]}"
        if self.count > 1:
            at = f" at {len(steps)} steps" if len(steps) > 1 else ""
            text += f" [raised {self.count} times{at}{envelope}]"
        return f"{where}: {text}"


def _range_warning(message: str) -> tuple[str, dict[str, tuple[float, float, str]]] | None:
    """``(model, {variable: (lo, hi, "outside [a, b]")})`` of a model's range warning
    ``"model: X in [lo, hi] outside [a, b]; Y in ..."``; None for any other message."""
    model, sep, rest = message.partition(": ")
    if not sep or not rest:
        return None
    out: dict[str, tuple[float, float, str]] = {}
    for part in rest.split("; "):
        m = _RANGE.fullmatch(part)
        lo, hi = (_float(m.group(2)), _float(m.group(3))) if m else (None, None)
        if m is None or lo is None or hi is None or m.group(1) in out:
            return None
        out[m.group(1)] = (lo, hi, m.group(4))
    return model, out


def _interval_texts(message: str) -> list[tuple[str, str]]:
    """The (lo, hi) texts of each variable of a range warning, as written."""
    return [(m.group(2), m.group(3)) for m in _RANGE.finditer(message)]


class WarningGroups:
    """One line per (bearing, message shape) in ``lines``; at most ``cap`` lines in all."""

    def __init__(self, lines: list[str], cap: int = 200) -> None:
        self.lines = lines
        self.cap = cap
        self._groups: dict[tuple[str, str], _Group] = {}

    def add(self, message: str, bearing: str, step: int | None = None) -> None:
        """Record one warning ``message`` of ``bearing`` (at schedule ``step`` if known)."""
        parsed = _range_warning(message)
        key = (bearing, "range: " + parsed[0] if parsed else _NUMBER.sub("#", message))
        group = self._groups.get(key)
        if group is not None:
            group.merge(message, step)
            self.lines[group.index] = group.line()
            return
        if len(self.lines) >= self.cap:
            return
        bounds = [(_float(m.group(1)), _float(m.group(2)))
                  for m in _INTERVAL.finditer(message)]
        group = _Group(index=len(self.lines), bearing=bearing, message=message,
                       steps=set() if step is None else {step},
                       lows=[b[0] for b in bounds], highs=[b[1] for b in bounds])
        if parsed:
            group.model = parsed[0]
            group.ranges = {k: [lo, hi, allowed, t[0], t[1]] for (k, (lo, hi, allowed)), t
                            in zip(parsed[1].items(), _interval_texts(message), strict=True)}
        self._groups[key] = group
        self.lines.append(group.line())


def merge_twin_bearings(lines: list[str], bearings: list[str]) -> list[str]:
    """The warning ``lines`` of a run with the lines that differ only in their bearing
    merged into one, for a reader: ``"drive_end, steps 0-21: <text>"`` and
    ``"non_drive_end, steps 0-21: <text>"`` (two identical, identically loaded bearings,
    as on the default rig: every film-range and skid line twice) become ``"drive_end and
    non_drive_end (each), steps 0-21: <text>"`` at the first one's place (its counts are
    each bearing's). A line is a bearing's
    when it starts with one of ``bearings`` followed by ``", "`` or ``": "``; other lines
    and bearings whose text differs are kept as they are. The run's own list
    (``Results.warnings``, ``metadata.json``) keeps one line per bearing."""
    names = sorted((b for b in bearings if b), key=len, reverse=True)
    owners: dict[str, list[str]] = {}  # the text after the bearing -> its bearings
    keyed: list[tuple[str | None, str]] = []
    for line in lines:
        name = next((b for b in names if line.startswith(b + ", ")
                     or line.startswith(b + ": ")), None)
        if name is None:
            keyed.append((None, line))
            continue
        rest = line[len(name):]
        if name not in owners.setdefault(rest, []):
            owners[rest].append(name)
        keyed.append((rest, line))
    out: list[str] = []
    done: set[str] = set()
    for rest, line in keyed:
        if rest is None:
            out.append(line)
        elif rest not in done:
            done.add(rest)
            who = owners[rest]
            joined = who[0] if len(who) == 1 else (", ".join(who[:-1]) + " and " + who[-1]
                                                   + " (each)")
            out.append(joined + rest)
    return out
