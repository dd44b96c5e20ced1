"""Parameter sweeps over a scene: cartesian products, run locally or on dask, resumable.

``thermobearing sweep SCENE --set supply.flow=15,20,25,33 --set schedule.speed=600:1800:300``
expands every combination of the ``--set`` values into one case, checks every case as a
scene that can run (:func:`check_cases`: preset and model names, network values, the
measured file) before the first one runs, runs each case with a runner (by default
:func:`thermobearing.simulation.summarize_scene`), and appends each finished case to
``DIR/cases.jsonl`` the moment it completes; ``DIR/summary.csv`` is rewritten after each
case; ``DIR/scene.toml`` records the base scene (:func:`record_base_scene`). Rerunning the
same command (in any order of its ``--set`` options) skips the cases already in
``cases.jsonl``, so an interrupted sweep resumes where it stopped; values given in other
units (``500 N`` after ``0.5 kN``) are the same cases, and new ones are written in the unit
the folder first recorded for that field (:func:`thermobearing.sweep_params.in_store_units`).

The sweep is split by job: the ``--set`` language (paths, values and units) is in
:mod:`thermobearing.sweep_params`, the cases (the cartesian product, each as a scene) in
:mod:`thermobearing.sweep_cases`, the results store (``cases.jsonl``, ``summary.csv``,
``scene.toml``) in :mod:`thermobearing.sweep_store`; this module checks the cases and runs
them, and every public name of the sweep is importable from here.

Executors: a local process pool (default), serial (``workers=1``), or an existing
dask.distributed scheduler (``scheduler="tcp://host:8786"``). A malformed address is an
InputError; an unreachable scheduler (or a server that does not answer as one within
three times ``connect_timeout``) is :class:`SchedulerUnreachable` unless
``fallback_local=True``.
"""

from __future__ import annotations

import math
import sys
import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import Any

import pandas as pd

from .errors import InputError, ThermobearingError
from .scene import Scene, loads_scene
from .sweep_cases import Case, expand, match_finished, scene_from_case
from .sweep_params import (
    DISPLAY_UNITS,
    PATH_UNITS,
    SweepParameter,
    assign_path,
    bearing_file_value,
    check_path,
    get_path,
    in_store_units,
    parse_set,
)
from .sweep_store import (
    _append,
    _record,
    _store_path,
    _write_summary,
    counted,
    finished_cases,
    kept_text,
    record_base_scene,
    record_planned_cases,
    summary_frame,
)

__all__ = [
    "DISPLAY_UNITS", "PATH_UNITS", "Case", "Runner", "SchedulerUnreachable", "SweepParameter",
    "assign_path", "bearing_file_value", "check_cases", "check_path",
    "check_scheduler_address", "expand", "finished_cases", "get_path", "parse_set",
    "record_base_scene", "run_sweep", "scene_from_case", "summary_frame",
]

Runner = Callable[[str], Mapping[str, float]]


class SchedulerUnreachable(ThermobearingError):
    """The dask scheduler given for a sweep cannot be reached."""


def check_scheduler_address(scheduler: str) -> None:
    """InputError unless ``scheduler`` reads as a dask.distributed scheduler address
    (``tcp://host:8786``, ``host:8786``, ``tls://...``, ``inproc://...``): a typo is named
    at once instead of failing inside dask with a traceback."""
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import backends

    allowed = ("a dask scheduler address such as tcp://host:8786 or host:8786 (schemes: "
               + ", ".join(sorted(backends)) + ")")
    if not isinstance(scheduler, str) or not scheduler.strip():
        raise InputError("--scheduler", scheduler, allowed)
    try:
        scheme, loc = parse_address(scheduler.strip())
    except (ValueError, TypeError):
        raise InputError("--scheduler", scheduler, allowed) from None
    if scheme not in backends:
        raise InputError("--scheduler", scheduler, allowed)
    if scheme in ("tcp", "tls", "ws", "wss", "ucx"):
        try:
            host, port = parse_host_port(loc)
        except (ValueError, TypeError):
            raise InputError("--scheduler", scheduler, allowed) from None
        if not host or not 0 < int(port) < 65536:
            raise InputError("--scheduler", scheduler, allowed)


def _dask_client(scheduler: str, timeout: float = 5.0):
    """A dask Client connected to ``scheduler``, or SchedulerUnreachable.

    dask's own ``timeout`` bounds the TCP connection only; a server that accepts the
    connection but never answers the handshake (another service on that port, e.g. the
    scheduler's web dashboard) would block forever, and one that answers with something
    else (an SSH server's banner) fails inside dask's message decoding with an arbitrary
    exception (a MemoryError for a frame length of exabytes read from the banner). The
    connection is therefore made in a helper thread with an overall deadline of three
    times ``timeout``, and every failure is reported as unreachable; a client whose start
    failed is closed at once (left to the garbage collector, its close waited 10 s on a
    dead connection at interpreter exit and printed a traceback).
    """
    import threading

    from distributed import Client

    check_scheduler_address(scheduler)
    box: dict[str, Any] = {}

    make: Any = Client
    if isinstance(Client, type):
        class _TrackedClient(Client):
            """Client that leaves a reference to itself before it connects, so a failed
            start can be closed."""

            def __init__(self, *args: Any, **kwargs: Any) -> None:
                box["started"] = self
                super().__init__(*args, **kwargs)

        make = _TrackedClient

    def connect() -> None:
        try:
            box["client"] = make(scheduler, timeout=f"{timeout}s", set_as_default=False)
        except Exception as exc:  # noqa: BLE001 - any failure: reported as unreachable
            if isinstance(exc, OSError | TimeoutError):
                box["error"] = str(exc)
            else:
                detail = f"{type(exc).__name__}: {exc}"
                detail = detail if len(detail) <= 160 else detail[:157] + "..."
                box["error"] = (
                    "something answered there, but not as a dask scheduler (is that the "
                    "scheduler's port, usually 8786, and not another service's?); dask "
                    f"could not read its reply: {detail}")
            failed = box.pop("started", None)
            if failed is not None:
                with suppress(Exception):
                    failed.close(timeout=1)

    worker = threading.Thread(target=connect, name="thermobearing-dask-connect", daemon=True)
    worker.start()
    worker.join(3.0 * timeout)
    advice = ("; start it (dask scheduler) or give its right address, or ask for a local "
              "run instead (--fallback-local, fallback_local=True)")
    if worker.is_alive():
        raise SchedulerUnreachable(
            f"cannot reach the dask scheduler at {scheduler!r}: something accepted the "
            f"connection but did not answer as a dask scheduler within {3.0 * timeout:g} s "
            "(is that the scheduler's port, usually 8786, and not its dashboard's, 8787?)"
            + advice)
    if "error" in box:
        raise SchedulerUnreachable(
            f"cannot reach the dask scheduler at {scheduler!r}: {box['error']}" + advice)
    return box["client"]


def _require_workers(client: Any, scheduler: str, timeout: float) -> None:
    """SchedulerUnreachable (the client closed) unless the scheduler has a worker within
    ``timeout`` seconds: a scheduler started without workers accepts the cases and never
    runs them, and the sweep would wait forever."""
    try:
        client.wait_for_workers(1, timeout=timeout)
    except (TimeoutError, OSError):
        client.close()
        raise SchedulerUnreachable(
            f"the dask scheduler at {scheduler!r} has no workers (none joined within "
            f"{timeout:g} s): start some (dask worker {scheduler}), or ask for a local run "
            "instead (--fallback-local, fallback_local=True)") from None


@contextmanager
def _naming_case(case: Case, out: Path | None) -> Iterator[None]:
    """A package error raised by one case names the case's values and where the finished
    cases are (the type and fields of the error are kept); ``out`` None: the error comes
    from the check of the cases before any ran."""
    try:
        yield
    except ThermobearingError as exc:
        values = ", ".join(f"{k}={v}" for k, v in case.assignments)
        if out is None:
            where = "no case was run (every case is checked before the first one runs)"
        else:
            n = len(finished_cases(out))
            # a rerun runs this case again first: with the same values it fails the same
            # way, and in a serial sweep the cases after it never run
            where = (f"{kept_text(n)} in {_store_path(out)} (rerunning the "
                     "same command resumes with this case, which fails again with these "
                     "values: run the other cases with --keep-going (keep_going=True), "
                     "or leave these values out of --set)")
        exc.args = (f"sweep case {case.case_id} ({values}): {exc}; {where}", *exc.args[1:])
        raise
    except Exception as exc:
        # not an input or solver error the package names (a bug, a dask worker without
        # thermobearing, ...): the traceback stays, with a note on the case and the store
        values = ", ".join(f"{k}={v}" for k, v in case.assignments)
        kept = "" if out is None else (f"; {kept_text(len(finished_cases(out)))} in "
                                       f"{_store_path(out)}")
        exc.add_note(f"in sweep case {case.case_id} ({values}){kept}")
        raise


def check_cases(cases: Sequence[Case]) -> list[str]:
    """Check every case as a scene that can run, before the first one runs: what
    ``thermobearing check`` checks without solving (model, bearing and lubricant preset
    names, the network template's parameters and values, the measured CSV). A bad value
    (``lubricant.preset=ISO_VG99``) then fails in a second, naming the case, instead of
    after the good cases have run. Costs about 50 ms per case (the default rig; most of it
    reading the scene's unit strings).

    Returns one line per swept path that a case's run says it does not use (the run's
    ``"<path> (...) is not used"`` note, e.g. ``supply.inlet_temperature`` of a scene
    without a thermal network): those cases give the same results whatever the value."""
    return _check_cases(cases)[0]


#: scene temperatures [K] of a case compared with its oil's data range: the oil inlet and
#: the parts' start (the ambient is the air's, checked against the air model)
OIL_TEMPERATURE_FIELDS = ("supply.inlet_temperature", "environment.initial_temperature")


def _check_cases(cases: Sequence[Case]) -> tuple[list[str], list[str]]:
    """:func:`check_cases`, and one line per scene temperature field and oil whose value
    lies outside the temperatures the oil's property data cover in some case
    (:func:`thermobearing.lubricant_range.outside_data_note`: an ISO VG 46 inlet at
    200 degC, beyond the 146 degC where its pressure-viscosity fit's data end), naming the
    values: such cases run, extrapolating the oil's data."""
    from .commands._preflight import preflight
    from .lubricant_range import data_temperature_range, outside_data_note
    from .scene_checks import check_model_names
    from .simulation import Simulation

    unused: dict[str, str] = {}
    ranges: dict[Any, Any] = {}    # lubricant -> its DataRange
    outside: dict[tuple[str, Any], list[float]] = {}    # (field, lubricant) -> kelvin
    #: supply.flow: said only when no case's run reads it (a capped oil fraction is a
    #: property of the value, not of the scene)
    flow_notes: list[str | None] = []
    for case in cases:
        with _naming_case(case, None):
            scene = loads_scene(case.scene_toml)
            check_model_names(scene)
            sim = Simulation(scene, progress=False)
            preflight(sim, build=True)  # includes check_global_friction
        lub = sim.lubricant
        if lub not in ranges:
            ranges[lub] = data_temperature_range(lub)
        for field in OIL_TEMPERATURE_FIELDS:
            kelvin = scene_oil_temperature(scene, field)
            if kelvin is not None and not ranges[lub].contains(kelvin):
                outside.setdefault((field, lub), []).append(kelvin)
        for path, _ in case.assignments:
            if path == "supply.flow":
                flow_notes.append(flow_unused(sim))
                continue
            note = next((n for n in sim.notes if _says_unused(n, path)), None)
            if note is None and path == "environment.ambient_temperature":
                note = _ambient_unused(scene)
            if note is not None and path not in unused:
                unused[path] = (f"sweep: {path} is swept but not used by the runs (their "
                                f"results do not change with it); case {case.case_id}: "
                                f"{note}")
    if flow_notes and all(flow_notes):
        first = next(c for c in cases if any(p == "supply.flow" for p, _ in c.assignments))
        unused["supply.flow"] = (f"sweep: supply.flow is swept but not used by the runs (their "
                                 f"results do not change with it); case {first.case_id}: "
                                 f"{flow_notes[0]}")
    notes = [f"sweep: {outside_data_note(lub, field, values, ranges[lub])}"
             for (field, lub), values in outside.items()]
    return list(unused.values()), notes


def scene_oil_temperature(scene: Scene, field: str) -> float | None:
    """The scene's temperature [K] of ``field`` (:data:`OIL_TEMPERATURE_FIELDS`); None for the
    inlet of an oil bath without flow (no stream enters the bearing)."""
    if field == "supply.inlet_temperature":
        sup = scene.supply
        return None if sup.method == "oil_bath" and sup.flow == 0.0 else sup.inlet_temperature
    return scene.environment.initial_temperature


#: heat sources that read the supply's flow (the churning sources' oil fraction, Parker's
#: correlation for a jet, circulation or oil-air supply)
_FLOW_SOURCES = ("churning_cage", "churning_inner_ring", "churning_elements")


def flow_unused(sim: Any) -> str | None:
    """Why the scene's ``supply.flow`` changes none of the requested results, or None.

    The flow enters a run in two places only: the thermal network's oil stream (m_dot c_p,
    with 'temperatures' or 'energy' in ``[outputs] want``) and, for a jet, circulation or
    oil-air supply, the oil volume fraction X = K Q^0.37 / (n d_m^1.7) of Parker's
    correlation (:func:`thermobearing.heat_sources.churning.parker_oil_fraction`), capped at
    1, that the churning sources and the skidding solvers' drag take. So it is unused
    without a network when the supply is an oil bath (the level sets X) or grease, when no
    churning source runs and the kinematics are not the skidding solvers, or when X is at
    its cap of 1 at every step of every bearing (a flow that floods the bearing: more changes
    nothing). (A sweep of supply.flow = 2, 20 L/min on a losses-only SKF 6304 jet scene at
    3000 r/min gave two identical rows without a word: X = 1 at both.)"""
    from .heat_sources.churning import parker_oil_fraction

    scene = sim.scene
    sup = scene.supply
    if sim.needs.get("network"):
        return None
    head = ("supply.flow is not used: without 'temperatures' or 'energy' in [outputs] want no "
            "thermal network (whose oil stream takes the flow) runs, and ")
    if sup.method in ("oil_bath", "grease"):
        what = ("an oil bath's churning follows supply.level" if sup.method == "oil_bath"
                else "a grease fill churns nothing here")
        return head + what
    if not (sim.needs.get("losses") or sim.needs.get("kinematics")):
        return head + "the films are taken at the run's temperature, whatever the flow"
    skidding = scene.models.get("kinematics", "skidding") == "skidding"
    readers = [b for b in sim.bearings
               if skidding or any(n in _FLOW_SOURCES for n in b.sources)]
    if not readers:
        return head + ("no heat source of this run reads it (the churning sources take it "
                       "through Parker's oil fraction, the skidding solvers for their drag)")
    constants = [1.46e7]
    for name in _FLOW_SOURCES:
        k = sim.source_options.get(name, {}).get("parker_constant")
        if isinstance(k, int | float) and k > 0:
            constants.append(float(k))
    for b in readers:
        k = getattr(b.kin_options.get("params"), "parker_constant", None)
        if isinstance(k, int | float) and k > 0:
            constants.append(float(k))
    steps = scene.schedule.steps
    if all(parker_oil_fraction(sup.flow, step.speed, b.bearing.pitch_diameter, k) >= 1.0
           for b in readers for step in steps for k in constants):
        return head + (f"Parker's oil fraction X = K Q^0.37 / (n d_m^1.7), which the churning "
                       f"and the skidding drag take, is at its cap of 1 at every step at "
                       f"{sup.flow * 6e4:g} L/min (a flooded bearing: more flow changes "
                       "nothing)")
    return None


def _ambient_unused(scene: Scene) -> str | None:
    """Why the scene's ambient temperature changes nothing, or None: without 'temperatures'
    or 'energy' in [outputs] want no thermal network runs, and the operating points are
    taken at the initial temperature the scene gives, or at a fed supply's inlet
    (:func:`thermobearing.unheated.unheated_temperature`); only an initial temperature left
    to its default (the ambient) follows it. (A sweep of the ambient of a losses-only jet
    scene gave identical rows without a word.)"""
    from .unheated import unheated_temperature

    if set(scene.outputs.want) & {"temperatures", "energy"}:
        return None
    t, source = unheated_temperature(scene)
    if source == "environment.initial_temperature" and not scene.environment.initial_given:
        return None
    return (f"environment.ambient_temperature is not used: without 'temperatures' or 'energy' "
            f"in [outputs] want no thermal network runs, and the films, kinematics and "
            f"losses are taken at {source} ({t - 273.15:g} degC)")


def _says_unused(note: str, path: str) -> bool:
    """Whether a run's note says the swept ``path`` is not used: ``"<path> (...) is not
    used"`` or a list of unused settings before ``"not used"`` naming the path or its table
    (``"[network], [solver] are not used"`` for ``network.parameters.h_oil``)."""
    head, sep, _ = note.partition(" not used")
    if not sep:
        return False
    table = f"[{path.split('.', 1)[0]}]"
    return note.startswith(f"{path} (") or table in head.split() or f"{table}," in head \
        or path in head.replace(",", " ").split()


class _CaseLines:
    """The sweep's progress where no bar can be drawn (stderr is a file or a pipe): one
    line per finished case on stderr, ``sweep: 3/12 cases done, 41 s wall`` (a sweep into
    a log file said nothing until its last case)."""

    def __init__(self, total: int, initial: int) -> None:
        self.total, self.n, self.start = total, initial, time.perf_counter()

    def update(self, k: int = 1) -> None:
        self.n += k
        print(f"sweep: {self.n}/{self.total} cases done, "
              f"{time.perf_counter() - self.start:.0f} s wall", file=sys.stderr, flush=True)

    def close(self) -> None:
        """Nothing to close (the tqdm bar's interface)."""


def run_sweep(
    scene: Scene,
    params: Sequence[SweepParameter],
    out_dir: Path | str,
    *,
    runner: Runner | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    fallback_local: bool = False,
    progress: bool | None = None,
    connect_timeout: float = 5.0,
    check: bool = True,
    keep_going: bool = False,
) -> pd.DataFrame:
    """Run every case not yet in ``out_dir``; returns the summary table of all cases.

    Parameters
    ----------
    scene : the base scene.
    params : swept fields (from :func:`parse_set`).
    out_dir : results folder (``cases.jsonl`` store and ``summary.csv``).
    runner : picklable ``runner(scene_toml) -> {name: float}``; default
        :func:`thermobearing.simulation.summarize_scene`.
    workers : local processes (1 = serial in this process; default: CPU count).
    scheduler : address of a dask.distributed scheduler to run the cases on.
    fallback_local : if the scheduler cannot be reached, run locally instead of failing.
    progress : show a progress bar (default: when stderr is a terminal, else one line per
        finished case, :class:`_CaseLines`; False: nothing).
    connect_timeout : seconds to wait for the scheduler before it counts as unreachable
        (a server that accepts the connection but does not answer as a scheduler: three
        times as long).
    check : check every case not yet run with :func:`check_cases` before the first runs.
    keep_going : a case that fails with a package error (a solver that does not converge,
        an input its run refuses) does not stop the sweep: the other cases run, the failed
        ones stay out of the store (a rerun tries them again) and are listed, one line
        each with the case's values and the error, in the returned table's
        ``attrs["failed"]``. Default: the first failure stops the sweep.
    """
    from tqdm.auto import tqdm

    if not (isinstance(connect_timeout, (int, float)) and not isinstance(connect_timeout, bool)
            and math.isfinite(connect_timeout) and connect_timeout > 0):
        raise InputError("connect_timeout", connect_timeout, "a positive number of seconds")

    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or workers < 1):
        raise InputError("workers", workers, "a whole number of local processes >= 1 "
                         "(1 = serial in this process; default: one per CPU)")
    if scheduler:
        check_scheduler_address(scheduler)
    if runner is None:
        from .simulation import summarize_scene as runner
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError("--out", str(out), "a results folder (new or of this sweep); this "
                         "is a file")
    done = finished_cases(out)
    # one unit per swept field in the folder: a resume in other units (500 N after 0.5 kN)
    # records its new values in the unit of the first run
    params = in_store_units(params, done)
    cases = expand(scene, params)
    for p in params:  # values read in a way the user may not have meant (a bare 313 degC)
        for line in p.notes:
            print(line, file=sys.stderr)
    cases = match_finished(scene, cases, done)  # the same quantities in other units
    todo = [c for c in cases if c.case_id not in done]
    unused, outside = _check_cases(todo) if check else ([], [])
    for line in [*unused, *outside]:  # before the runs, as the CLI's other notes
        print(line, file=sys.stderr)
    resumed = len(cases) - len(todo)
    if resumed and progress is not False:  # a rerun says what it resumed, before the bar
        print(f"sweep: resuming: {resumed} of {counted(len(cases), 'case')} already in "
              f"{_store_path(out)}; {len(todo)} to run", file=sys.stderr)
    out.mkdir(parents=True, exist_ok=True)
    record_base_scene(out, scene)
    record_planned_cases(out, cases)  # before any case runs: a killed sweep keeps its plan
    show = sys.stderr.isatty() if progress is None else progress
    bar: Any = (tqdm(total=len(cases), initial=len(cases) - len(todo), disable=not show,
                     desc="sweep", unit="case")
                if show or progress is not None else _CaseLines(len(cases), len(cases)
                                                               - len(todo)))
    failures: list[str] = []

    def failed(case: Case, exc: BaseException) -> bool:
        """Note a failed case when the sweep keeps going (True); False: stop on it."""
        if not (keep_going and isinstance(exc, ThermobearingError)):
            return False
        values = ", ".join(f"{k}={v}" for k, v in case.assignments)
        failures.append(f"case {case.case_id} ({values}): {exc}")
        bar.update(1)
        return True

    try:
        if todo:
            client = None
            if scheduler:
                try:
                    client = _dask_client(scheduler, connect_timeout)
                    _require_workers(client, scheduler, connect_timeout)
                except SchedulerUnreachable as exc:
                    if not fallback_local:
                        raise
                    client = None
                    why = "has no workers" if "no workers" in str(exc) else "unreachable"
                    print(f"sweep: scheduler {scheduler} {why}, running locally",
                          file=sys.stderr)
            if client is not None:
                from distributed import as_completed as dask_completed

                try:
                    with client.as_current():
                        futures = {client.submit(runner, c.scene_toml, pure=False): c
                                   for c in todo}
                        for fut in dask_completed(list(futures)):
                            try:
                                result = fut.result()
                            except Exception as exc:
                                if failed(futures[fut], exc):
                                    continue
                                with _naming_case(futures[fut], out):
                                    raise
                            rec = _record(futures[fut], result)
                            _append(out, rec)
                            done[rec["case"]] = rec
                            _write_summary(out, cases, done)
                            bar.update(1)
                finally:
                    client.close()
            elif workers == 1 or len(todo) == 1:
                for c in todo:
                    try:
                        result = runner(c.scene_toml)
                    except Exception as exc:
                        if failed(c, exc):
                            continue
                        with _naming_case(c, out):
                            raise
                    rec = _record(c, result)
                    _append(out, rec)
                    done[rec["case"]] = rec
                    _write_summary(out, cases, done)
                    bar.update(1)
            else:
                def keep(case: Case, result: Mapping[str, float]) -> None:
                    rec = _record(case, result)
                    _append(out, rec)
                    done[rec["case"]] = rec
                    _write_summary(out, cases, done)
                    bar.update(1)

                with ProcessPoolExecutor(max_workers=workers) as pool:
                    futs = {pool.submit(runner, c.scene_toml): c for c in todo}
                    try:
                        _run_pool(futs, keep, out, failed)
                    except KeyboardInterrupt:
                        # leaving the with-block would wait for the running and queued
                        # cases (whose results nobody records): stop them
                        _stop_pool(pool)
                        raise
    finally:
        bar.close()
    df = _write_summary(out, cases, done)
    df.attrs["failed"] = failures
    df.attrs["unused"] = unused
    df.attrs["outside_data"] = outside
    said = {line.split(" ", 2)[1] for line in unused}
    df.attrs["identical"] = [line for path, line in identical_results(cases, done).items()
                             if path not in said]
    return df


def _same(a: Any, b: Any) -> bool:
    """Two result values equal (floats to 1e-12 relative; NaN equals NaN)."""
    if isinstance(a, float) and isinstance(b, float):
        return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=1e-12,
                                                                 abs_tol=0.0)
    return bool(a == b)


def identical_results(cases: Sequence[Case],
                      done: Mapping[str, Mapping[str, Any]]) -> dict[str, str]:
    """Swept path -> a note, for each path whose values changed no result: every set of
    finished cases that differ only in that path (the other paths at the same values) gave
    the same number in every result column. Such a parameter does not affect the requested
    outputs (a flow that floods the bearing, a check threshold no step reaches); the sweep
    says so instead of leaving identical rows to be noticed. Paths with fewer than two
    finished values are not judged."""
    recs = [(c, done[c.case_id]) for c in cases if c.case_id in done]
    paths = list(dict.fromkeys(p for c, _ in recs for p, _ in c.assignments))
    notes: dict[str, str] = {}
    for path in paths:
        groups: dict[str, list[tuple[Any, Mapping[str, Any]]]] = {}
        for case, rec in recs:
            others = repr(sorted((p, repr(v)) for p, v in case.assignments if p != path))
            value = dict(case.assignments).get(path)
            groups.setdefault(others, []).append((value, rec.get("result", {})))
        judged = [g for g in groups.values() if len({repr(v) for v, _ in g}) > 1]
        if not judged:
            continue
        if all(set(r) == set(g[0][1]) and all(_same(r[k], g[0][1][k]) for k in r)
               for g in judged for _, r in g[1:]):
            values = ", ".join(dict.fromkeys(str(v) for v, _ in judged[0]))
            notes[path] = (f"note: {path} changed no result: the cases that differ only in "
                           f"it ({values}) gave the same numbers in every result column of "
                           "summary.csv; the requested outputs do not depend on it here")
    return notes


def _run_pool(futs: Mapping[Any, Case], keep: Callable[[Case, Mapping[str, float]], None],
              out: Path, noted: Callable[[Case, BaseException], bool]) -> None:
    """Keep each case of a process pool as it finishes. A case that fails and is not
    ``noted`` (the sweep keeps going past it) starts no other case: the cases already
    running are waited for and kept, then the failure is raised naming its case (before,
    the pool ran every queued case on leaving and dropped their results)."""
    failed = None
    kept = set()
    for fut in as_completed(futs):
        if fut.exception() is None:
            keep(futs[fut], fut.result())
            kept.add(fut)
            continue
        if noted(futs[fut], fut.exception()):
            continue
        failed = fut
        break
    if failed is None:
        return
    if isinstance(failed.exception(), KeyboardInterrupt):
        raise KeyboardInterrupt  # a worker got the Ctrl-C first
    for fut in futs:
        fut.cancel()  # the queued cases; a running one cannot be cancelled
    rest = [f for f in futs if f is not failed and f not in kept and not f.cancelled()]
    for fut in as_completed(rest):
        if fut.exception() is None:
            keep(futs[fut], fut.result())
    with _naming_case(futs[failed], out):
        failed.result()


def _stop_pool(pool: ProcessPoolExecutor) -> None:
    """Cancel a pool's queued cases and end its worker processes (Ctrl-C): the running
    cases are lost anyway, and a worker that caught the Ctrl-C in its case would go on to
    the next queued one while the command had already said it was interrupted."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in processes:
        if proc.is_alive():
            proc.terminate()
    for proc in processes:
        proc.join(timeout=5.0)
