"""Repeated validity warnings of a run merged into one line each.

A model that is used outside its fitted range warns at every call (e.g. the film formula at
every contact set, step and heat evaluation), each time with slightly different numbers; a
spindle run-up listed 38 such lines for one bearing. :class:`WarningGroups` keeps one line per
bearing and message *shape* (the message with its numbers masked): the first message, with
every "in [lo, hi]" interval widened to the envelope of all repeats, the steps it came from
and how many times it was raised. The lines live in the caller's list (the run's warnings),
so other notes appended there keep their order.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

_NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
_INTERVAL = re.compile(r"in \[([^,\]]+), ([^\]]+)\]")


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

    def merge(self, message: str, step: int | None) -> None:
        self.count += 1
        if step is not None:
            self.steps.add(step)
        for i, m in enumerate(_INTERVAL.finditer(message)):
            if i >= len(self.lows):
                break
            lo, hi = _float(m.group(1)), _float(m.group(2))
            if lo is not None and self.lows[i] is not None:
                self.lows[i] = min(self.lows[i], lo)
            if hi is not None and self.highs[i] is not None:
                self.highs[i] = max(self.highs[i], hi)

    def line(self) -> str:
        k = iter(range(len(self.lows)))

        def widened(m: re.Match) -> str:
            i = next(k)
            lo, hi = self.lows[i], self.highs[i]
            if lo is None or hi is None:
                return m.group(0)
            return f"in [{lo:.3g}, {hi:.3g}]"

        text = _INTERVAL.sub(widened, self.message) if self.count > 1 else self.message
        steps = sorted(self.steps)
        where = self.bearing
        if len(steps) == 1:
            where += f", step {steps[0]}"
        elif steps:
            where += f", steps {steps[0]}-{steps[-1]}"
        if self.count > 1:
            at = f" at {len(steps)} steps" if len(steps) > 1 else ""
            envelope = "; intervals are the envelope of all" if self.lows else ""
            text += f" [raised {self.count} times{at}{envelope}]"
        return f"{where}: {text}"


class WarningGroups:
    """One line per (bearing, message shape) in ``lines``; at most ``cap`` lines in all."""

    def __init__(self, lines: list[str], cap: int = 200) -> None:
        self.lines = lines
        self.cap = cap
        self._groups: dict[tuple[str, str], _Group] = {}

    def add(self, message: str, bearing: str, step: int | None = None) -> None:
        """Record one warning ``message`` of ``bearing`` (at schedule ``step`` if known)."""
        key = (bearing, _NUMBER.sub("#", message))
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
        self._groups[key] = group
        self.lines.append(group.line())
