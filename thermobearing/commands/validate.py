"""``thermobearing validate [CASE ...] [--json] [--report FILE]``: run the validation cases
against the papers (``--report`` also writes them as a Markdown page,
:mod:`thermobearing.validation.report`)."""

from __future__ import annotations

import argparse
import contextlib
import json
import sys

from .. import validation

NAME = "validate"
HELP = "run the validation cases against the source papers and print the error table"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("cases", nargs="*", help="case ids (default: all)")
    parser.add_argument("--json", action="store_true", help="print JSON records instead")
    parser.add_argument("--list", action="store_true", help="list the case ids and exit")
    parser.add_argument("--jobs", "-j", type=int, default=1,
                        help="run the cases in this many processes (default 1)")
    parser.add_argument("--slow", action="store_true",
                        help="also run the cases marked slow (skipped by default when no "
                             "case is named)")
    parser.add_argument("--quiet", action="store_true",
                        help="no progress lines on stderr")
    parser.add_argument("--report", metavar="FILE", default=None,
                        help="also write the records as a Markdown page (one section per "
                             "case, failing rows first, links to each case's SOURCE.md)")


def run(args: argparse.Namespace) -> int:
    if args.list:
        print("\n".join(cid + ("  (slow: run by name or with --slow)"
                                if validation.is_slow(cid) else "")
                                for cid in validation.case_ids()))
        return 0
    def progress(line: str) -> None:
        print(line, file=sys.stderr, flush=True)

    kwargs = {"jobs": args.jobs, "progress": None if args.quiet else progress,
              "include_slow": args.slow}
    if args.json:  # anything a model prints goes to stderr: stdout is the JSON document
        with contextlib.redirect_stdout(sys.stderr):
            records = validation.run_cases(args.cases or None, **kwargs)
    else:
        records = validation.run_cases(args.cases or None, **kwargs)
    if args.json:
        print(json.dumps(validation.records_as_dicts(records), indent=1))
    else:
        print(validation.format_table(records))
    if args.report:
        from pathlib import Path

        from .. import __version__
        from ..validation.report import markdown_report

        path = Path(args.report)
        command = "thermobearing validate " + " ".join(
            [*args.cases, *(["--slow"] if args.slow else [])])
        path.write_text(markdown_report(records, link_base=path.resolve().parent,
                                        version=__version__, command=command.strip()),
                        encoding="utf-8")
        print(f"report written to {path}", file=sys.stderr)
    failed = [r for r in records if r.gated and not r.passed]
    return 1 if failed else 0
