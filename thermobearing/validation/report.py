"""The validation report: the records of ``thermobearing validate`` as one Markdown page.

One section per case: what it checks (the first paragraph of its ``SOURCE.md``, linked),
every row with reference, computed value, error, tolerance and verdict, and the case's
notes. Gated rows that fail are listed first in a summary with the line of ``SOURCE.md``
that gives the reason to read. The page is what ``thermobearing validate --report FILE``
writes; it states the date, the package version and the cases run, so a reader knows what
build it describes.
"""

from __future__ import annotations

import datetime as _dt
import math
import os
from collections.abc import Sequence
from pathlib import Path

from . import Record, cases_dir


def _fmt(x: float) -> str:
    return "-" if not math.isfinite(x) else f"{x:.5g}"


def _error(r: Record) -> str:
    if not math.isfinite(r.error):
        return "-"
    if "%" in r.tolerance or r.tolerance.startswith("["):
        return f"{100 * r.error:+.2f} %"
    return f"{r.error:+.4g}"


def _verdict(r: Record) -> str:
    if r.gated:
        return "PASS" if r.passed else "**FAIL**"
    return "in range" if r.passed else "report"


def _summary_line(case_dir: Path) -> tuple[str, str]:
    """(title, first paragraph) of a case's SOURCE.md (empty strings without one)."""
    path = case_dir / "SOURCE.md"
    if not path.is_file():
        return "", ""
    title, para, seen_text = "", [], False
    for line in path.read_text(encoding="utf-8").splitlines():
        s = line.strip()
        if s.startswith("# ") and not title:
            title = s[2:].strip()
            continue
        if not s:
            if seen_text:
                break
            continue
        if s.startswith("#"):
            if seen_text:
                break
            continue
        para.append(s)
        seen_text = True
    return title, " ".join(para)


def markdown_report(records: Sequence[Record], *, folder: Path | None = None,
                    link_base: Path | None = None, version: str = "",
                    command: str = "") -> str:
    """The Markdown page of ``records`` (see the module docstring).

    ``folder``: the cases folder (default :func:`cases_dir`); ``link_base``: the folder the
    page will be written to (links to each ``SOURCE.md`` are made relative to it).
    """
    folder = folder or cases_dir()
    cases = list(dict.fromkeys(r.case for r in records))
    gated = [r for r in records if r.gated]
    failed = [r for r in gated if not r.passed]
    stamp = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# Validation report",
        "",
        f"Written {stamp}" + (f" by thermobearing {version}" if version else "")
        + (f" (`{command}`)" if command else "") + ".",
        "",
        f"{len(cases)} cases, {len(records)} rows: {len(gated) - len(failed)} of "
        f"{len(gated)} gated rows pass, {len(failed)} fail; "
        f"{len(records) - len(gated)} `report` rows are printed beside the paper without a "
        "gate. Each case's `SOURCE.md` says where every number comes from, why the "
        "tolerance is what it is and, for a failing row, what was measured about the cause.",
        "",
    ]

    def link(case: str) -> str:
        target = folder / case / "SOURCE.md"
        if link_base is not None:
            target = Path(os.path.relpath(target, link_base))
        return f"[{case}]({target.as_posix()})"

    if failed:
        lines += ["## Rows that miss the asked accuracy", "",
                  "| case | quantity | reference | computed | error | tolerance |",
                  "|---|---|---|---|---|---|"]
        for r in failed:
            lines.append(f"| {link(r.case)} | {r.quantity} | {_fmt(r.reference)} | "
                         f"{_fmt(r.computed)} | {_error(r)} | {r.tolerance} |")
        lines.append("")
    lines += ["## Cases", "", "| case | gated rows passing | report rows |", "|---|---|---|"]
    for case in cases:
        rs = [r for r in records if r.case == case]
        g = [r for r in rs if r.gated]
        lines.append(f"| {link(case)} | {sum(r.passed for r in g)} / {len(g)} | "
                     f"{len(rs) - len(g)} |")
    lines.append("")
    for case in cases:
        rs = [r for r in records if r.case == case]
        title, para = _summary_line(folder / case)
        lines += [f"### {case}", ""]
        if title and title != case:
            lines += [f"*{title}*", ""]
        if para:
            lines += [para, ""]
        lines += [f"Source and reasons: {link(case)}.", "",
                  "| quantity | unit | reference | computed | error | tolerance | verdict |",
                  "|---|---|---|---|---|---|---|"]
        for r in rs:
            lines.append(f"| {r.quantity} | {r.unit or '-'} | {_fmt(r.reference)} | "
                         f"{_fmt(r.computed)} | {_error(r)} | {r.tolerance} | "
                         f"{_verdict(r)} |")
        notes = sorted({r.note for r in rs if r.note})
        if notes:
            lines += [""] + [f"Note: {n}" for n in notes]
        lines.append("")
    return "\n".join(lines)
