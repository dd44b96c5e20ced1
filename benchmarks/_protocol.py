"""Shared helpers of BM-7 (fidelity ladder) and BM-E2E (end-to-end protocol timing).

Both benchmarks run the default scene (``configs/scenes/qj1044_rig.toml``: two QJ1044
bearings, 1800 r/min, 33 L/min, 22 axial-load steps of 3 min) or a shortened copy of it
(``--quick``: every 6th load step); BM-7 also runs a roller-bearing problem
(:data:`ROLLER_SCENE`, :func:`roller_scene`). Runs are compared on a common grid:

- temperatures of every network node at the end of every load step (a grid every chunk
  size used here divides, so no interpolation is involved), error = max |T - T_ref| [K];
- the total power loss of every bearing at the end of every load step (the loss table
  of :class:`thermobearing.simulation.Simulation`, evaluated at the end-of-step node
  temperatures), error = max |P - P_ref| / P_ref [-].

Level L0 (a global friction model, no kinematics) is not a model the package can run
from a scene, so :func:`run_l0` drives the scene's own thermal network
(:func:`thermobearing.coupled.build_network`) and stepper
(:class:`thermobearing.network.TransientStepper`) with the total loss of
:func:`thermobearing.global_friction.global_friction` (SKF four-term or Palmgren), the
oil's kinematic viscosity taken at the bearing's oil-node temperature and the whole loss
put on that oil node.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

QUICK_STRIDE = 6
#: BM-7's roller-bearing problem: D1842926 (paper 001), OIL_4109, three 2-min steps
ROLLER_SCENE = "paper001_ladder"


def default_scene(quick: bool = False, stride: int | None = None) -> Any:
    """The default scene; with ``quick`` only every ``QUICK_STRIDE``-th load step
    (0, 12, 24, 36 kN: four steps of 3 min)."""
    from thermobearing.scene import Schedule, load_scene

    scene = load_scene()
    step = stride if stride is not None else (QUICK_STRIDE if quick else 1)
    if step > 1:
        scene = replace(scene, schedule=Schedule(steps=scene.schedule.steps[::step]))
    return scene


def roller_scene(steps: int | None = None) -> Any:
    """BM-7's roller-bearing problem (``configs/scenes/paper001_ladder.toml``), with only its
    first ``steps`` load steps when given."""
    from thermobearing.errors import InputError
    from thermobearing.scene import Schedule, load_scene

    scene = load_scene(ROLLER_SCENE)
    if steps is not None:
        if not 1 <= steps <= len(scene.schedule.steps):
            raise InputError("steps", steps,
                             f"1 to {len(scene.schedule.steps)} (the scene's load steps)")
        scene = replace(scene, schedule=Schedule(steps=scene.schedule.steps[:steps]))
    return scene


def with_solver(scene: Any, **changes: Any) -> Any:
    """A copy of the scene with ``[solver]`` fields replaced (SI values)."""
    return replace(scene, solver=replace(scene.solver, **changes))


def with_models(scene: Any, **changes: Any) -> Any:
    """A copy of the scene with ``[models]`` entries replaced."""
    models = dict(scene.models)
    models.update(changes)
    return replace(scene, models=models)


def step_end_times(scene: Any) -> np.ndarray:
    """End time [s] of every load step."""
    return np.cumsum([s.duration for s in scene.schedule.steps])


@dataclass
class ProtocolRun:
    """Outcome of one run of the protocol, reduced to the comparison grid.

    time_s : wall time of the run [s]; cpu_s : CPU time of the process over the run [s]
    (less sensitive than wall time to other jobs on a shared machine); nodes : network
    state-node names;
    temperatures : (n_steps, n_nodes) [K] at the step ends; losses : (n_steps, n_bearings)
    total power loss [W] at the step ends; kinematics_solves : number of kinematics solves
    (0 at L0); extra : anything else worth printing.
    """

    label: str
    time_s: float
    nodes: list[str]
    temperatures: np.ndarray
    losses: np.ndarray
    kinematics_solves: int = 0
    extra: dict[str, Any] = field(default_factory=dict)
    cpu_s: float = math.nan


def errors(run: ProtocolRun, ref: ProtocolRun) -> tuple[float, float]:
    """(max |T - T_ref| [K] over nodes and step ends, max |P - P_ref|/P_ref [-])."""
    if run.nodes != ref.nodes or run.temperatures.shape != ref.temperatures.shape:
        raise ValueError(f"{run.label} and {ref.label} are not on the same grid")
    dT = float(np.max(np.abs(run.temperatures - ref.temperatures)))
    dP = float(np.max(np.abs(run.losses - ref.losses) / np.abs(ref.losses)))
    return dT, dP


def reduce_results(label: str, scene: Any, results: Any, time_s: float) -> ProtocolRun:
    """A :class:`ProtocolRun` from a :class:`thermobearing.results.Results` table set."""
    temps = results.tables["temperatures"]
    cols = [c for c in temps.columns if c.endswith(" [degC]")]
    nodes = [c[: -len(" [degC]")] for c in cols]
    t = temps["time [s]"].to_numpy()
    rows = []
    for te in step_end_times(scene):
        j = int(np.argmin(np.abs(t - te)))
        if abs(t[j] - te) > 1e-6 * max(1.0, te):
            raise ValueError(f"{label}: no temperature row at the step end {te} s")
        rows.append(temps[cols].iloc[j].to_numpy(dtype=float) + 273.15)
    losses = results.tables["losses"]
    per = losses.groupby(["step", "bearing"], sort=False)["power [W]"].sum().unstack()
    bearings = [b.name for b in scene.bearings]
    P = per[bearings].sort_index().to_numpy(dtype=float)
    stats = dict(results.stats)
    extra = {"energy_imbalance": stats.get("relative_energy_imbalance", math.nan),
             "linearizations": stats.get("linearizations", 0)}
    # numerical_tehl: the film table's node solves, queries and CPU per bearing
    extra.update({k: v for k, v in stats.items() if k.endswith(": film table")})
    return ProtocolRun(label, time_s, nodes, np.array(rows), P,
                       int(stats.get("kinematics_solves", 0)), extra)


def run_l1(label: str, scene: Any) -> ProtocolRun:
    """The package's own coupled transient (``Simulation(scene).run()``), timed."""
    from thermobearing.simulation import Simulation

    t0, c0 = time.perf_counter(), time.process_time()
    sim = Simulation(scene, progress=False)
    res = sim.run()
    dt, cpu = time.perf_counter() - t0, time.process_time() - c0
    run = reduce_results(label, scene, res, dt)
    run.cpu_s = cpu
    # numerical_tehl: the grid its film model solves on ([models] film_options.grid_points)
    grids = {b.name: b.kin_options["film_model"].n for b in sim.bearings
             if hasattr(b.kin_options.get("film_model"), "n")}
    if grids:
        run.extra["film grid points"] = grids
    return run


def run_l0(label: str, scene: Any, model: str = "skf_four_term", **options: Any) -> ProtocolRun:
    """Level L0: global friction model, no kinematics, heat on the oil node.

    Per bearing the loss is P(T_oil) = M(nu(T_oil), n, F_r, F_a) * omega from
    :func:`thermobearing.global_friction.global_friction` (``model`` = ``skf_four_term``
    or ``palmgren``, ``options`` passed to it, e.g. the SKF ``series``; lubrication
    method from the scene's supply), with the lubricant's
    kinematic viscosity at the bearing's oil-node temperature, all of it on that node.
    The heat is the exact nonlinear function of the node temperatures (cheap: no
    linearisation per chunk is needed), integrated by the scene's stepper with its
    tolerances, restarted at every load step.
    """
    from thermobearing.coupled import build_network
    from thermobearing.global_friction import global_friction
    from thermobearing.network import TransientStepper
    from thermobearing.simulation import Simulation

    t_start, c_start = time.perf_counter(), time.process_time()
    sim = Simulation(with_models(scene, kinematics="race_control"), progress=False)
    net = build_network(sim)
    names = list(net.state_nodes)
    index = {n: i for i, n in enumerate(names)}
    oil = {b.name: [index[n] for n in net.roles(b.name)["oil"]] for b in sim.bearings}
    solver = scene.solver

    def loss(b: Any, step: Any, T: np.ndarray) -> float:
        t_oil = float(np.mean(T[oil[b.name]]))
        return global_friction(model, b.bearing, sim.lubricant, t_oil, step.speed,
                               step.radial_load, step.axial_load, supply=sim.supply,
                               **options).power

    def heat_for(step: Any):
        def heat(t: float, T: np.ndarray) -> np.ndarray:
            q = np.zeros(len(names))
            for b in sim.bearings:
                net.distribute({"oil": loss(b, step, T)}, group=b.name, out=q)
            return q
        return heat

    stepper = TransientStepper(net, method=solver.stepper, rtol=solver.rtol, atol=solver.atol,
                               max_step=solver.max_step)
    T = np.full(len(names), scene.environment.initial_temperature)
    t = 0.0
    temps, losses = [], []
    for step in scene.schedule.steps:
        out = stepper.advance(t, T, step.duration, heat_for(step), heat_time_dependent=False)
        T, t = out.temperatures, out.time
        temps.append(T.copy())
        losses.append([loss(b, step, T) for b in sim.bearings])
    dt, cpu = time.perf_counter() - t_start, time.process_time() - c_start
    return ProtocolRun(label, dt, names, np.array(temps), np.array(losses), 0,
                       {"stepper": stepper.stats}, cpu)


def fmt_err(x: float) -> str:
    return "     -    " if x is None or not math.isfinite(x) else f"{x:10.3g}"
