"""``thermobearing bench [NAME ...] [--full] [--json]``: run the benchmark scripts.

Each script in ``benchmarks/bm*.py`` runs ours and its anchor in the same process and
prints records (benchmark, case, method, setting, time_s, error, ratio_vs_anchor) with
``--json``. This command runs them one after the other (``--quick`` unless ``--full``),
collects the records and prints one ratio table (or all records as JSON).
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

from ..errors import UnknownNameError

NAME = "bench"
HELP = "run the speed-vs-error benchmarks and print their ratio tables"


def benchmarks_dir() -> Path:
    return Path(__file__).resolve().parents[2] / "benchmarks"


def available() -> dict[str, Path]:
    folder = benchmarks_dir()
    return {p.stem: p for p in sorted(folder.glob("bm*.py"))}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("names", nargs="*", help="benchmark script names (default: all)")
    parser.add_argument("--full", action="store_true", help="full runs instead of --quick")
    parser.add_argument("--json", action="store_true", help="print every record as JSON")


def _parse_records(stdout: str) -> list[dict]:
    """Benchmark records from a script's stdout: a JSON array (possibly followed or
    preceded by a printed table) or one JSON object per line."""
    decoder = json.JSONDecoder()
    records: list[dict] = []
    for i, line in enumerate(stdout.splitlines(keepends=True)):
        text = line.lstrip()
        if not text.startswith(("[", "{")):
            continue
        start = sum(len(x) for x in stdout.splitlines(keepends=True)[:i]) + (
            len(line) - len(text))
        try:
            value, _ = decoder.raw_decode(stdout[start:])
        except json.JSONDecodeError:
            continue
        if isinstance(value, list):
            records.extend(v for v in value if isinstance(v, dict))
            if records:
                return records
        elif isinstance(value, dict):
            records.append(value)
    return records


def run(args: argparse.Namespace) -> int:
    scripts = available()
    names = args.names or list(scripts)
    for n in names:
        if n not in scripts:
            raise UnknownNameError("benchmark", n, scripts)
    all_records: list[dict] = []
    failed = []
    for n in names:
        cmd = [sys.executable, str(scripts[n]), "--json"] + ([] if args.full else ["--quick"])
        if not args.json:
            print(f"== {n}", flush=True)
        proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
        if proc.returncode != 0:
            failed.append(n)
            print(f"{n} failed (exit {proc.returncode}):\n{proc.stderr[-2000:]}",
                  file=sys.stderr)
            continue
        recs = _parse_records(proc.stdout)
        all_records.extend(recs)
        if not args.json:
            for r in recs:
                print(record_line(r))
    if args.json:
        print(json.dumps(json_ready(all_records), indent=1, allow_nan=False))
    return 1 if failed else 0


def _number(v: object, fmt: str) -> str:
    """A record's number as text, ``-`` where it has none (None, NaN, not a number)."""
    try:
        x = float(v)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return "-"
    return "-" if math.isnan(x) else format(x, fmt)


def record_line(r: dict) -> str:
    """One benchmark record of the table: case, method, setting, time, error, ratio, and
    the record's note, which says why a setting has no time or ratio ("none within
    target") -- the table printed ``time nan s ... ratio nan`` without it. A record with
    a CPU time (``cpu_s``: BM-7, BM-E2E, whose ratios are formed from it) shows that one as
    ``cpu``; its ``time_s`` is wall time there, which the table showed beside a ratio of CPU
    times."""
    err = r.get("max_error_K", r.get("error"))
    ratio = r.get("ratio_vs_anchor")
    clock = ("cpu", r["cpu_s"]) if r.get("cpu_s") is not None else ("time", r.get("time_s"))
    line = (f"  {r.get('case', '')!s:28} {r.get('method', '')!s:22} "
            f"{r.get('setting', '')!s:14} {clock[0]} {_number(clock[1], '.4g')} s"
            + (f"  error {_number(err, '.3g')}" if err is not None else "")
            + (f"  ratio {_number(ratio, '.3g')}" if ratio is not None else ""))
    note = r.get("note")
    return line + (f"  ({note})" if note else "")


def json_ready(records: list[dict]) -> list[dict]:
    """The records with NaN and infinite numbers as ``null`` (as ``validate --json`` writes
    them): the scripts' own JSON carries ``NaN`` for a setting with no time or error, which
    is not JSON (RFC 8259) and which strict readers (JavaScript's ``JSON.parse``, Python's
    ``json.loads(..., parse_constant=...)``) refuse."""
    def clean(v: object) -> object:
        if isinstance(v, float) and not math.isfinite(v):
            return None
        if isinstance(v, dict):
            return {k: clean(x) for k, x in v.items()}
        if isinstance(v, list):
            return [clean(x) for x in v]
        return v

    return [clean(r) for r in records]
