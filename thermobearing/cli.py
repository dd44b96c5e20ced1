"""The ``thermobearing`` command.

Sub-commands are the modules of :mod:`thermobearing.commands`: each defines ``NAME``,
``HELP``, ``add_arguments(parser)`` and ``run(args) -> int``. Adding a module adds a
command; there is no list to keep in step here.
"""

from __future__ import annotations

import os

# One BLAS thread per process unless the user says otherwise: the package's matrices are
# small (networks of 4-100 nodes, banded EHL systems), where a threaded BLAS on a shared
# machine was measured ~20x slower (a 254 x 254 solve: 29 ms vs 1.3 ms on 2 busy cores),
# and sweeps already run one process per core. Set before numpy is first imported.
for _var in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import importlib  # noqa: E402
import pkgutil  # noqa: E402
import sys  # noqa: E402
from collections.abc import Sequence  # noqa: E402

from . import __version__, commands  # noqa: E402
from .errors import ThermobearingError  # noqa: E402


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every discovered sub-command."""
    parser = argparse.ArgumentParser(
        prog="thermobearing",
        description="Power losses, skidding and temperatures of rolling bearings.",
    )
    parser.add_argument("--version", action="version", version=f"thermobearing {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for info in sorted(pkgutil.iter_modules(commands.__path__), key=lambda i: i.name):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"{commands.__name__}.{info.name}")
        p = sub.add_parser(module.NAME, help=module.HELP, description=module.HELP)
        module.add_arguments(p)
        p.set_defaults(_run=module.run)
    return parser


def _value_options(parser: argparse.ArgumentParser) -> set[str]:
    """The option strings of every sub-command that take a value (``--temperatures``)."""
    out: set[str] = set()
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                out |= _value_options(sub)
        elif action.option_strings and action.nargs != 0:
            out.update(action.option_strings)
    return out


def join_negative_values(argv: Sequence[str], options: set[str]) -> list[str]:
    """``--temperatures -20,0,20`` as ``--temperatures=-20,0,20``: argparse takes a value
    starting with ``-`` that is not one plain negative number for an option and stopped
    with "expected one argument" (only ``--temperatures=-20,0,20`` worked)."""
    out: list[str] = []
    i = 0
    while i < len(argv):
        token = argv[i]
        nxt = argv[i + 1] if i + 1 < len(argv) else ""
        if token in options and len(nxt) > 1 and nxt[0] == "-" and (
                nxt[1].isdigit() or nxt[1] == "."):
            out.append(f"{token}={nxt}")
            i += 2
            continue
        out.append(token)
        i += 1
    return out


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the console script; returns the process exit code."""
    parser = build_parser()
    argv = list(sys.argv[1:] if argv is None else argv)
    args = parser.parse_args(join_negative_values(argv, _value_options(parser)))
    if not getattr(args, "_run", None):
        parser.print_help()
        return 2
    try:
        return int(args._run(args) or 0)
    except ThermobearingError as exc:
        print(f"thermobearing {args.command}: error: {exc}", file=sys.stderr)
        return 1
    except BrokenPipeError:
        # the output piped into a reader that stopped (``| head``): printed as
        # "error: Broken pipe" before; end quietly, with stdout on the null device so that
        # the interpreter's last flush does not raise again
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141  # 128 + SIGPIPE, as a shell reports a pipe's reader closing early
    except OSError as exc:  # a path the user gave: missing, not a folder, not writable ...
        where = f": {exc.filename}" if exc.filename else ""
        print(f"thermobearing {args.command}: error: {exc.strerror or exc}{where}",
              file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"thermobearing {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
