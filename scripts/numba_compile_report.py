"""Measure the numba compilations of a command: per kernel, its signatures and compile seconds.

Runs a ``thermobearing`` CLI command (default: ``run --out DIR`` on the embedded default
scene) or a pytest selection in this process, with numba's ``numba:compile`` event recorder
installed, and prints for every dispatcher that was compiled (a cache miss: loading from the
on-disk cache raises no such event) the number of signatures compiled, the compile CPU seconds
including the kernels it compiled on the way (``incl_s``) and excluding them (``self_s``),
and the argument types of each signature. The wall time, CPU time and total compile time of
the command are printed last.

By default the numba cache goes to a new empty temporary folder (``NUMBA_CACHE_DIR``, set
before numba is imported), so every kernel the command needs is compiled: the cost of the
first run on a fresh clone. ``--warm`` keeps the configured cache (next to the modules) and
reports only what it misses.

Usage (from the repository root)::

    python scripts/numba_compile_report.py [--warm] [--json FILE] [--sigs] -- run --out /tmp/x
    python scripts/numba_compile_report.py --pytest -- -x -q tests/unit/skidding
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
import traceback
from dataclasses import dataclass, field


@dataclass
class KernelCompiles:
    """Compilations of one dispatcher: signatures (argument-type strings), CPU seconds with
    and without the kernels compiled inside (``incl_s``, ``self_s``), wall seconds of its
    compilations started from Python (``wall_s``) and the kernels that compiled it."""

    name: str
    signatures: list[str] = field(default_factory=list)
    incl_s: float = 0.0
    self_s: float = 0.0
    wall_s: float = 0.0
    callers: list[str] = field(default_factory=list)


def _dispatcher_name(dispatcher: object) -> str:
    func = getattr(dispatcher, "py_func", None)
    if func is None:
        return repr(dispatcher)
    return f"{func.__module__}.{func.__qualname__}"


def _recording_listener() -> object:
    """A ``numba:compile`` listener whose ``buffer`` keeps (wall, process CPU, event) at each
    start and end: the CPU time of this process is the compile cost free of the machine's
    other load. (numba is imported here, after ``NUMBA_CACHE_DIR`` is set.)"""
    from numba.core import event

    class Recorder(event.Listener):
        def __init__(self) -> None:
            self.buffer: list[tuple[float, float, object]] = []

        def on_start(self, ev: object) -> None:
            self.buffer.append((time.perf_counter(), time.process_time(), ev))

        def on_end(self, ev: object) -> None:
            self.buffer.append((time.perf_counter(), time.process_time(), ev))

    return Recorder()


def collect(buffer: list) -> dict[str, KernelCompiles]:
    """Pair the start/end events of a ``numba:compile`` recording into per-kernel totals.

    Compilations nest (a kernel compiles the kernels it calls, on the same thread under
    numba's global compiler lock): the self time of an event is its span minus the spans of
    the events directly inside it. ``callers`` lists the kernels whose compilation compiled
    this one (``<python>``: called from Python). Seconds are CPU seconds of this process
    (``wall_s``: the wall-clock span of the outermost compilations).
    """
    kernels: dict[str, KernelCompiles] = {}
    stack: list[list] = []  # [name, start CPU, child CPU seconds, signature, start wall]
    for wall, cpu, event in buffer:
        data = event.data
        name = _dispatcher_name(data["dispatcher"])
        if event.is_start:
            sig = ", ".join(str(a) for a in data["args"])
            stack.append([name, cpu, 0.0, sig, wall])
            continue
        top_name, start, child_s, sig, wall0 = stack.pop()
        if top_name != name:
            raise RuntimeError(f"unbalanced compile events: {top_name} ended as {name}")
        span = cpu - start
        entry = kernels.setdefault(name, KernelCompiles(name))
        entry.signatures.append(sig)
        entry.incl_s += span
        entry.self_s += span - child_s
        if stack:
            stack[-1][2] += span
            if stack[-1][0] not in entry.callers:
                entry.callers.append(stack[-1][0])
        else:
            entry.wall_s += wall - wall0
            if "<python>" not in entry.callers:
                entry.callers.append("<python>")
    if stack:
        raise RuntimeError(f"{len(stack)} compile events did not end")
    return kernels


def _print_table(kernels: dict[str, KernelCompiles], show_sigs: bool) -> None:
    rows = sorted(kernels.values(), key=lambda k: k.self_s, reverse=True)
    width = max((len(k.name) for k in rows), default=10)
    print(f"{'kernel':<{width}}  nsig  self_s  incl_s   (CPU seconds)")
    for k in rows:
        print(f"{k.name:<{width}}  {len(k.signatures):4d}  {k.self_s:6.2f}  {k.incl_s:6.2f}")
        if show_sigs or len(k.signatures) > 1:
            for sig in k.signatures:
                print(f"{'':<{width}}    ({sig})")
        if show_sigs:
            print(f"{'':<{width}}    called from: {', '.join(k.callers)}")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--warm", action="store_true", help="keep the configured numba cache")
    parser.add_argument("--pytest", action="store_true", help="run pytest with the arguments")
    parser.add_argument("--json", metavar="FILE", help="also write the per-kernel table as JSON")
    parser.add_argument("--sigs", action="store_true", help="print every signature")
    parser.add_argument("command", nargs="*", help="thermobearing CLI (or pytest) arguments")
    args = parser.parse_args(argv)
    command = args.command or ["run", "--out", tempfile.mkdtemp(prefix="tb_compile_out_")]

    if "numba" in sys.modules:
        raise RuntimeError("numba was imported before the cache folder could be set")
    if not args.warm:
        os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="tb_numba_cold_")
    from numba.core import event

    wall0, cpu0 = time.perf_counter(), time.process_time()
    recorder = _recording_listener()
    with event.install_listener("numba:compile", recorder):
        if args.pytest:
            import pytest

            status = pytest.main(command)
        else:
            from thermobearing.cli import main as cli_main

            try:
                status = cli_main(command)
            except SystemExit as exc:  # argparse and commands may exit
                status = exc.code if isinstance(exc.code, int) else 1
            except Exception:  # the compile table is still worth printing
                traceback.print_exc()
                status = 1
    wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0

    kernels = collect(recorder.buffer)
    _print_table(kernels, args.sigs)
    n_sig = sum(len(k.signatures) for k in kernels.values())
    compile_s = sum(k.self_s for k in kernels.values())
    compile_wall = sum(k.wall_s for k in kernels.values())
    print(
        f"\n{len(kernels)} kernels, {n_sig} compilations, {compile_s:.1f} s CPU "
        f"({compile_wall:.1f} s wall) compiling; command: {wall:.1f} s wall, {cpu:.1f} s CPU "
        f"(exit status {status})"
    )
    if args.json:
        table = {
            "command": command,
            "wall_s": wall,
            "cpu_s": cpu,
            "compile_cpu_s": compile_s,
            "compile_wall_s": compile_wall,
            "kernels": [vars(k) for k in kernels.values()],
        }
        with open(args.json, "w", encoding="utf-8") as fh:
            json.dump(table, fh, indent=1)
    return int(status or 0)


if __name__ == "__main__":
    sys.exit(main())
