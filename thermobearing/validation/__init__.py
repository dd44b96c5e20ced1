"""Validation against the source papers: discover cases, run them, tabulate the errors.

A case is a folder ``validation/cases/<id>/`` holding

``case.toml``
    ``title``, ``runner`` (a name in :data:`RUNNERS`) and an ``[inputs]`` table (unit
    strings allowed; the runner converts them).
``reference.csv``
    one row per checked quantity with the columns
    ``quantity, unit, reference, kind, tolerance, low, high, gate``:
    ``kind`` is ``rel`` (``|c - r| / |r| <= tolerance``), ``abs`` (``|c - r| <= tolerance``,
    in ``unit``) or ``range`` (``low <= c <= high``); ``gate`` is ``pass`` (the case fails
    if the check fails) or ``report`` (printed beside the reference, e.g. to show a known
    shortcoming of a closed-form model, never gated).
``SOURCE.md``
    the citation, where each number comes from, the tolerance and why.

A case whose ``case.toml`` says ``slow = true`` (minutes to hours of CPU, e.g. the
numerical-EHL drag of paper 000) runs when it is named or when ``include_slow`` is set
(``thermobearing validate --slow``); a run of "all cases" lists it as skipped.

A runner is a registered function ``runner(inputs: dict, case_dir: Path) -> dict`` that
returns SI floats keyed by quantity; the table converts them to the row's unit.
Runner modules are the ``runners_*.py`` files of this package (imported on demand).
"""

from __future__ import annotations

import csv
import importlib
import math
import multiprocessing
import os
import pkgutil
import time
import tomllib
import traceback
from collections.abc import Callable, Iterable
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from ..errors import InputError, UnknownNameError
from ..registry import Registry
from ..units import from_si

Runner = Callable[[dict[str, Any], Path], dict[str, float]]

RUNNERS: Registry[Runner] = Registry("validation", "validation case runners")

_COLUMNS = ("quantity", "unit", "reference", "kind", "tolerance", "low", "high", "gate")


@dataclass(frozen=True)
class Check:
    """One row of a case's ``reference.csv``."""

    quantity: str
    unit: str
    reference: float
    kind: str
    tolerance: float
    low: float
    high: float
    gate: str


@dataclass(frozen=True)
class Record:
    """One row of the validation table (also the ``--json`` record)."""

    case: str
    quantity: str
    unit: str
    reference: float
    computed: float
    error: float
    tolerance: str
    passed: bool
    gated: bool
    note: str = ""


def cases_dir() -> Path:
    """Folder of the validation cases.

    ``$THERMOBEARING_VALIDATION_DIR`` if set, else ``validation/cases`` beside the
    package (a source checkout), else ``./validation/cases``.
    """
    env = os.environ.get("THERMOBEARING_VALIDATION_DIR")
    if env:
        return Path(env)
    here = Path(__file__).resolve().parents[2] / "validation" / "cases"
    if here.is_dir():
        return here
    return Path.cwd() / "validation" / "cases"


def load_runners() -> Registry[Runner]:
    """Import every ``runners_*`` module so that their runners are registered."""
    for info in pkgutil.iter_modules(__path__):
        if info.name.startswith("runners_"):
            importlib.import_module(f"{__name__}.{info.name}")
    return RUNNERS


def case_ids(folder: Path | None = None) -> list[str]:
    """Ids (folder names) of all cases, sorted."""
    folder = folder or cases_dir()
    if not folder.is_dir():
        return []
    return sorted(p.name for p in folder.iterdir() if (p / "case.toml").is_file())


def is_slow(case_id: str, folder: Path | None = None) -> bool:
    """True when the case's ``case.toml`` marks it ``slow = true`` (run only on request)."""
    folder = folder or cases_dir()
    spec = tomllib.loads((folder / case_id / "case.toml").read_text(encoding="utf-8"))
    slow = spec.get("slow", False)
    if not isinstance(slow, bool):
        raise InputError(f"{case_id}/case.toml slow", slow, "true or false")
    return slow


def _float(text: str, field: str) -> float:
    text = (text or "").strip()
    if text == "":
        return math.nan
    try:
        return float(text)
    except ValueError:
        raise InputError(field, text, "a number") from None


def read_checks(case_dir: Path) -> list[Check]:
    """Parse ``reference.csv`` of a case."""
    path = case_dir / "reference.csv"
    if not path.is_file():
        raise InputError(f"{case_dir.name}/reference.csv", str(path), "an existing file")
    checks = []
    with path.open(newline="", encoding="utf-8") as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    header = tuple(h.strip() for h in rows[0])
    if header != _COLUMNS:
        raise InputError(f"{case_dir.name}/reference.csv header", header, f"{_COLUMNS}")
    for row in rows[1:]:
        rec = dict(zip(header, (c.strip() for c in row), strict=True))
        field = f"{case_dir.name}/reference.csv[{rec['quantity']}]"
        kind = rec["kind"]
        if kind not in ("rel", "abs", "range"):
            raise InputError(field + ".kind", kind, "rel, abs or range")
        if rec["gate"] not in ("pass", "report"):
            raise InputError(field + ".gate", rec["gate"], "pass or report")
        checks.append(
            Check(
                quantity=rec["quantity"],
                unit=rec["unit"],
                reference=_float(rec["reference"], field + ".reference"),
                kind=kind,
                tolerance=_float(rec["tolerance"], field + ".tolerance"),
                low=_float(rec["low"], field + ".low"),
                high=_float(rec["high"], field + ".high"),
                gate=rec["gate"],
            )
        )
    return checks


def evaluate(check: Check, computed_si: float) -> tuple[float, float, bool, str]:
    """(computed in the row's unit, error, passed, tolerance text) of one check."""
    unit = check.unit
    value = computed_si if unit in ("", "-", "1", "dimensionless") else from_si(computed_si, unit)
    ref = check.reference
    if check.kind == "rel":
        error = (value - ref) / abs(ref) if math.isfinite(ref) and ref != 0 else math.nan
        passed = math.isfinite(error) and abs(error) <= check.tolerance
        tol = f"±{100 * check.tolerance:g} %"
    elif check.kind == "abs":
        error = value - ref if math.isfinite(ref) else math.nan
        passed = math.isfinite(error) and abs(error) <= check.tolerance
        tol = f"±{check.tolerance:g} {unit}".rstrip()
    else:
        error = (value - ref) / abs(ref) if math.isfinite(ref) and ref != 0 else math.nan
        passed = math.isfinite(value) and check.low <= value <= check.high
        tol = f"[{check.low:g}, {check.high:g}] {unit}".rstrip()
    return value, error, bool(passed), tol


def run_case(case_id: str, folder: Path | None = None) -> list[Record]:
    """Run one case and return its table rows (an exception becomes failed rows)."""
    folder = folder or cases_dir()
    case_dir = folder / case_id
    if not (case_dir / "case.toml").is_file():
        raise UnknownNameError("validation case", case_id, case_ids(folder))
    spec = tomllib.loads((case_dir / "case.toml").read_text(encoding="utf-8"))
    checks = read_checks(case_dir)
    runners = load_runners()
    note = ""
    try:
        runner = runners.get(spec["runner"])
        computed = runner(dict(spec.get("inputs", {})), case_dir)
    except Exception as exc:  # a failing case is reported, not hidden
        computed = {}
        note = f"{type(exc).__name__}: {exc}"
        if os.environ.get("THERMOBEARING_DEBUG"):
            traceback.print_exc()
    records = []
    for check in checks:
        if check.quantity in computed:
            value, error, passed, tol = evaluate(check, float(computed[check.quantity]))
            row_note = note
        else:
            value, error, passed = math.nan, math.nan, False
            tol = evaluate(check, math.nan)[3]
            row_note = note or "runner returned no value for this quantity"
        records.append(
            Record(
                case=case_id,
                quantity=check.quantity,
                unit=check.unit,
                reference=check.reference,
                computed=value,
                error=error,
                tolerance=tol,
                passed=passed,
                gated=check.gate == "pass",
                note=row_note,
            )
        )
    return records


def _timed_case(case_id: str, folder: Path) -> tuple[list[Record], float]:
    t0 = time.perf_counter()
    records = run_case(case_id, folder)
    return records, time.perf_counter() - t0


def run_cases(ids: Iterable[str] | None = None, folder: Path | None = None, *,
              jobs: int = 1, progress: Callable[[str], None] | None = None,
              include_slow: bool = False) -> list[Record]:
    """Run the given cases (all when ``ids`` is None), in the order given.

    With ``ids`` None the cases marked ``slow = true`` are skipped (``progress`` says so)
    unless ``include_slow``; named cases always run.

    ``jobs`` > 1 runs the cases in that many worker processes (the paper 002 protocols
    take minutes each); ``progress`` receives one line per finished case (its verdict and
    wall time) as soon as it finishes.
    """
    folder = folder or cases_dir()
    chosen = list(ids) if ids else case_ids(folder)
    for cid in chosen:  # unknown ids fail before any work starts
        if not (folder / cid / "case.toml").is_file():
            raise UnknownNameError("validation case", cid, case_ids(folder))
    if isinstance(jobs, bool) or not isinstance(jobs, int) or jobs < 1:
        raise InputError("jobs", jobs, "an integer >= 1")
    if not ids and not include_slow:
        skipped = [cid for cid in chosen if is_slow(cid, folder)]
        chosen = [cid for cid in chosen if cid not in skipped]
        if progress is not None:
            for cid in skipped:
                progress(f"[{cid}] skipped: slow case (run it by name or with --slow)")

    def report(cid: str, records: list[Record], wall: float) -> None:
        if progress is not None:
            failed = sum(r.gated and not r.passed for r in records)
            verdict = f"{failed} gated check(s) FAIL" if failed else "ok"
            progress(f"[{cid}] {verdict} ({wall:.1f} s)")

    results: dict[str, list[Record]] = {}
    if jobs == 1 or len(chosen) <= 1:
        for cid in chosen:
            results[cid], wall = _timed_case(cid, folder)
            report(cid, results[cid], wall)
    else:
        ctx = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=min(jobs, len(chosen)), mp_context=ctx) as pool:
            futures = {pool.submit(_timed_case, cid, folder): cid for cid in chosen}
            for fut in as_completed(futures):
                cid = futures[fut]
                results[cid], wall = fut.result()
                report(cid, results[cid], wall)
    return [r for cid in chosen for r in results[cid]]


def format_table(records: list[Record]) -> str:
    """Plain-text table: case, quantity, reference, computed, error, tolerance, pass."""
    head = ("case", "quantity", "unit", "reference", "computed", "error", "tolerance", "pass")
    rows = [head]
    for r in records:
        err = "" if not math.isfinite(r.error) else (
            f"{100 * r.error:+.2f} %" if "%" in r.tolerance or r.tolerance.startswith("[")
            else f"{r.error:+.4g}"
        )
        verdict = ("PASS" if r.passed else "FAIL") if r.gated else (
            "in range" if r.passed else "report")
        rows.append((
            r.case, r.quantity, r.unit or "-", f"{r.reference:.5g}", f"{r.computed:.5g}",
            err, r.tolerance, verdict,
        ))
    widths = [max(len(str(row[i])) for row in rows) for i in range(len(head))]
    lines = ["  ".join(str(c).ljust(w) for c, w in zip(row, widths, strict=True)) for row in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    notes = sorted({f"{r.case}: {r.note}" for r in records if r.note})
    if notes:
        lines.append("")
        lines.extend("note " + n for n in notes)
    return "\n".join(lines)


def records_as_dicts(records: list[Record]) -> list[dict[str, Any]]:
    """JSON-ready records (NaN -> None)."""
    out = []
    for r in records:
        d = asdict(r)
        for k, v in d.items():
            if isinstance(v, float) and not math.isfinite(v):
                d[k] = None
        d["tolerance"] = r.tolerance
        out.append(d)
    return out
