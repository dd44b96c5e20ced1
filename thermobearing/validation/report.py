"""The validation report: the records of ``thermobearing validate`` as one Markdown page.

One section per case: what it checks (the first paragraph of its ``SOURCE.md``, linked),
every row with reference, computed value, error, tolerance and verdict, and the case's
notes. Gated rows that fail are listed first in a summary, each linked to its case's
``SOURCE.md``, which gives the measured reason. A row ``q`` with a companion row
``q_stderr`` of the same case (the standard error of an ensemble estimate, e.g. the
chaotic rib rattle of paper 003) is printed as ``value ± stderr`` on one line and the
companion is not listed again.
The page is what ``thermobearing validate --report FILE`` writes; it states the date, the
package version and the cases run, so a reader knows what build it describes.
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


STDERR_SUFFIX = "_stderr"


def _stderr_map(records: Sequence[Record]) -> dict[tuple[str, str], float]:
    """(case, quantity) -> standard error, from the ``<quantity>_stderr`` companion rows.

    Only companions whose base row exists in the same case are taken.
    """
    names = {(r.case, r.quantity) for r in records}
    out: dict[tuple[str, str], float] = {}
    for r in records:
        if r.quantity.endswith(STDERR_SUFFIX):
            base = (r.case, r.quantity[: -len(STDERR_SUFFIX)])
            if base in names:
                out[base] = r.computed
    return out


def _computed(r: Record, stderr: dict[tuple[str, str], float]) -> str:
    """The computed value, with ``± stderr`` where the row has a companion."""
    se = stderr.get((r.case, r.quantity))
    if se is None or not math.isfinite(r.computed) or not math.isfinite(se):
        return _fmt(r.computed)
    return f"{_fmt(r.computed)} ± {_fmt(se)}"


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
    stderr = _stderr_map(records)
    companions = {(case, q + STDERR_SUFFIX) for case, q in stderr}
    records = [r for r in records if (r.case, r.quantity) not in companions]
    n_se = sum(1 for v in stderr.values() if math.isfinite(v))
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
        "tolerance is what it is and, for a failing row, what was measured about the cause."
        + (f" {n_se} rows estimated from ensembles of trajectories carry their "
           "standard error as `± SE` after the computed value (verdicts use the value)."
           if n_se else ""),
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
                         f"{_computed(r, stderr)} | {_error(r)} | {r.tolerance} |")
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
                         f"{_computed(r, stderr)} | {_error(r)} | {r.tolerance} | "
                         f"{_verdict(r)} |")
        notes = sorted({r.note for r in rs if r.note})
        if notes:
            lines += [""] + [f"Note: {n}" for n in notes]
        lines.append("")
    return "\n".join(lines)
