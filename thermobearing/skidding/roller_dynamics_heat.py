"""Time-mean rib friction power of the roller dynamics, cached per operating state.

What the rib heat source (:mod:`thermobearing.heat_sources.rib`) needs from the roller
dynamics of paper 003 (Zhang et al. 2021, seed ``003_743e023ae6e45686.txt``
[zhang2021_abnormal_wear], eqs. 1-17 rib contact, 18-19 roller and cage, 21-24 PV): the
time-mean friction power of each end face of a roller, averaged over all rollers, at one
operating state (speed, radial load, temperature, unbalance). Two models:

* ``"coupled"``: all Z rollers and the cage integrated together
  (:func:`~thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`, started from the
  uncoupled quasi-static state, as the validation case ``paper003_pv_slip_trends`` runs it);
  ~1.1-1.7 s CPU per state at paper 003's base case (0.11 g), ~0.6 s at 20000 r/min
  without unbalance (the running-mean stop, "Where the integration stops" below).
* ``"reduced"``: one roller at the orbit's frozen load states with the quasi-static coupled
  spins (:func:`~thermobearing.skidding.roller_dynamics.simulate_reduced`), ~0.1 s plus
  ~0.1-0.2 s of the quasi-static rib coupling; its time-mean PV is 29 % below the coupled
  model's at the base case and its rib heat about half (SOURCE.md of the case).

Heat = the work rate of the rib forces the integrator applies (``RollerResponse.rib_heat_*``:
Coulomb friction mu Q along the tangential slide v of eq. 24 -- power mu Q v^2 /
sqrt(v^2 + v_s^2), v_s the integrator's 0.05 m/s direction regularisation -- plus the
lubricant drag of eq. 14 times its sliding speed), so it is energy consistent with the
model's forces; per roller, both faces separately, averaged over rollers and time [W].

Cache: an operating state is keyed by the bearing and lubricant (their ``repr``), speed,
radial load, unbalance, the model and its settings, and the temperature *node* of a grid
of step ``temperature_step`` [K] (default :data:`DEFAULT_TEMPERATURE_STEP`). A temperature
between two nodes gets the linear interpolation of the two nodes' results (each computed
once), so the heat is continuous in temperature (the coupled transient differentiates it
by finite differences) and a transient re-runs the dynamics only when the temperature
enters a new grid cell. Measured at the base case (0.11 g; 2026-11-22): the coupled rib
heat moves by +1.8 % / -1.3 % from 353 to 358 / 363 K, inside the +-1.5 % scatter of the
chaotic impacting motion (the slip scatter over step sizes, SOURCE.md); the drag-only heat
(no unbalance) falls by 10 % per 5 K (the oil viscosity), whose linear interpolation over a
5 K cell errs by <= (ln 1.1)^2 / 8 = 0.11 %: a 5 K grid keeps the interpolation error
below 1 % (a 10 K grid: 0.5 % for the drag, but two scatter samples 10 K apart).
At 0.11 g the node values scatter by about +-4 % (69-75 W per roller over 350-390 K and
step sizes; the chaotic motion), after the traction table was made C1 in the cage speed
(before, some runs entered a cage-overspeed excursion with twice the heat; SOURCE.md of
the case, "Cage excursions"). The cache is bounded (:data:`CACHE_SIZE` states, least recently used
dropped) and holds only results of deterministic runs; :func:`clear_cache` empties it,
:func:`cache_info` counts hits and runs.

Where the integration stops (2026-11-23, issue 9 cost): the coupled model integrated a fixed
2 warm-up + 3 statistics cage orbits per node; a scene fuzzer's coupled rib_friction
scenes timed out (all 12 timeouts of a session). Measured
(``benchmarks/bm_rib_friction.py``: CRB 50x75x16 in MIL-PRF-23699, steps 20000 r/min /
3 kN, 5000 / 2 kN, 10000 / 6 kN of 10 s, 0.2 kN axial, no unbalance): 11 nodes in a
21-26 s CPU scene run, the time loop kernel 78 % of it (1.0-1.2 / 3.0-3.5 / 1.6-1.9 s per
node at 20000 / 5000 / 10000 r/min: ~1.5 us steps, the rib contact's 1/omega_rib), the
quasi-static set-up ~0.19 s, the traction table ~0.09 s and the post-processing ~0.11 s
per node, numba's cached kernels 0.5-0.6 s once per process. Without an unbalance the
motion settles within ~1-1.5 orbits (the roller-mean heat of quarter orbits constant to
1e-4 after that). The coupled model now stops at the running-mean criterion of
:mod:`~thermobearing.skidding.roller_dynamics_convergence` at ``convergence``
(default :data:`DEFAULT_CONVERGENCE` = 0.5 % on the heat and on the rib slide speed; None
or the source option ``convergence = 0``: the fixed window): 1.5-2.0 orbits per node
there, scene CPU x 2.2-2.6 lower over three runs of the benchmark (25.5 -> 10.8 s; the
kernel 19.8 -> 6.6 s), heat per node within 0.21 %, rib slide within 0.10 %, booked
rib_friction power at the step ends within 0.09 %, final roller temperature -0.004 K
(the heat is there mostly the thrust share mu Q |v|); the fuzzer's CRB scene at 2545 r/min,
18.9 kN (PAPER000_OIL) 29.4 -> 10.5 s CPU (4 nodes). Not every settled run stops early:
at 30000 r/min, 3 kN, 400 K (no unbalance) the cage speed still creeps after 6 orbits
(1311 -> 1342 rad/s, e-folding ~2 orbits; the fixed window itself averages over +0.8 % of
it) and the rib slide with it, so the test runs the whole fixed window there
(``configs/scenes/crb_rib_example.toml``: 15 nodes, 0.6-0.7 s each at 20000 r/min,
1.1-1.3 s at 30000; 15.3 s CPU for the scene). Since 2026-11-23 (night) the coupled runs
first warm up until the orbit-mean cage speed changes by <= ``settle`` (default
:data:`~thermobearing.skidding.roller_dynamics_convergence.DEFAULT_SETTLE` = 0.1 %) per
orbit (roller_dynamics_coupled notes, "Cage settling"), then the running-mean test runs
from the last warm-up orbit on: at that 400 K state rib heat 0.05923 -> 0.05828 W per
roller (settled fixed window 0.05822; the 20-orbit slip 5.952 m/s), slip 6.236 -> 5.976
m/s, 7 orbits, 1.51 -> 1.34 s CPU; 3000 N, 80 degC: 0.1254 -> 0.1244 W (the test had
stopped after 2 orbits, slip 4.707 -> 4.593 m/s), 4 orbits, 0.56 -> 0.95 s; 1000 N,
80 degC: 0.2521 -> 0.2381 W (settled 0.2378), 11 orbits, 1.32 -> 2.40 s; 20000 r/min,
3 kN, 375 K (settled within 2 orbits): 2.0 -> 3.0 orbits, 0.50 -> 0.66 s, heat 0.03515
-> 0.035132 W (fixed window 0.035133). Only without an unbalance: with 0.06 g (20000
r/min, 3 kN, 375 K) the settling test passed only after 5 orbits on the chaotic cage
speed, the run took 7 orbits and met a cage runaway (one table retry), 4.66 s CPU against
1.32 s for the 5-orbit fixed window (rib heat 21.89 against 20.27 W per roller: two
trajectories of the chaotic motion); at paper 003's base case the unbalanced runs' cage is
within 0.5 % of its 35-orbit mean from orbit 2 on (validation case SOURCE.md).
With an unbalance (chaotic impacting motion, block scatter ~5 %) no window converges to
0.5 % before the fixed window's end, so those runs are the fixed window's (after the
settling warm-up, which passes there after 2-3 orbits on a chance agreement or runs to its
cap), unchanged by the test (test). There the cost was the cage
runaway's evaluate-path re-run (6-25x a table run): the benchmark with ``--unbalance 0.06
--quick --duration 5`` (20000 r/min / 3 kN and 5000 / 2 kN, 19 nodes) spent 240 of its
284 s CPU outside the table-path kernel, 6 nodes re-run on the evaluate path (19-23 s
each at 20000 r/min, 72-75 s at 5000) and 2 that ran away on both paths and borrowed a
neighbour. With ``table_retries`` (default :data:`DEFAULT_TABLE_RETRIES`; other
trajectories on the table path first, roller_dynamics_coupled "Retries on the table
path"): 79 s CPU (x 3.6), 7 of 8 such nodes finished on a table retry (1-2 retries,
2.0-5.9 s), 1 on the evaluate path after 3 retries, none borrowed a neighbour. Nodes
without a runaway are identical; the re-run nodes are other trajectories of the chaotic
motion (their heat moved by up to 10.4 %, inside the 19.8-22.7 W per roller the other
nodes of that step scatter over; same population: module notes of
roller_dynamics_coupled), the booked rib_friction at the step ends by -3.0 % (20000
r/min, 681 -> 661 W) and -0.03 % (5000 r/min), the final roller temperature by -0.09 K.

Warm start (2026-11-24, issue 9 cost). Without an unbalance (deterministic motion that
settles to one steady state) a coupled node starts from the end state of the nearest node
of its operating state already run (``warm_start_nodes``, default
:data:`DEFAULT_WARM_START_NODES` grid steps at most, the cooler of two equally near; the
state of every roller, the cage angle and speed: :class:`CoupledStart`,
``simulate_coupled(start=...)``), and its quasi-static solve (still needed: the cage band,
the load states and the table are centred on it) starts its Newton from that node's
quasi-static state. With an unbalance every node keeps its cold start (the chaotic motion's
value would depend on which node ran first). A warm-started run that stops with a
ConvergenceError is run again cold. Measured (MIL-PRF-23699, 3 kN, no unbalance, the
defaults, against a 20 + 10-orbit reference at the node):

* 30000 r/min, 400 K (the slow cage creep): cold 7.0 orbits, 1.28-1.42 s CPU, rib heat
  +0.19 %, slip +0.40 %, cage -0.07 %; from the 395 K node's end state 2.0 orbits, 0.46 s,
  heat -0.28 %, slip -0.70 %, cage +0.08 %; from 405 K 3.0 orbits, 0.62 s, heat +0.23 %.
  Both starts leave the settling test's creep residue (settle r/(1 - r), r ~ 0.56 per
  orbit here), of opposite signs; a tighter ``settle`` cuts both (3e-4: cold 9 orbits,
  +0.058 %; warm 4-5 orbits, -0.073 / +0.070 %; 1e-4: cold 11, warm 6-7 orbits, <=
  0.023 %).
* 20000 r/min, 375 K: cold 3.0 orbits, heat -0.013 %; warm from 370 / 380 K 2.0 orbits,
  -0.028 / +0.033 %. 5000 r/min, 2 kN, 375 K: 3.0 -> 2.0 orbits, heat within 2e-6.
* Hotter, the creep is slower still (r nearer 1) and the orbit-to-orbit test leaves more
  of it on either side: 440 K against a 25 + 10-orbit reference (0.042047 W per roller),
  cold 10 orbits +0.74 % (settle 3e-4: the 12-orbit cap, +0.41 %), from the 435 K node 2
  orbits -0.39 % (3e-4: the same); 425 K cold +0.48 %. In the example scene
  (``configs/scenes/crb_rib_example.toml``: 20000 / 30000 r/min steps, 14 nodes, nodes
  chained by warm starts) the scene's dynamics CPU fell 1.63x (19.2 -> 11.5 s scene CPU),
  the 20000 r/min nodes moved by <= 0.03 %, the 30000 r/min nodes at 380-440 K by -0.4 to
  -1.5 % (425 / 440 K: -1.0 / -1.5 %, i.e. from +0.48 / +0.74 % to -0.51 / -0.72 % of the
  reference), the booked rib_friction at the 30000 r/min step end by -0.73 %, the final
  roller temperature by -0.25 K. (These numbers are the orbit-to-orbit settling test's.)
* Since 2026-11-24 the settling test extrapolates the creep from three half-orbit-spaced
  orbit means, floored by the cage mode's decay, and refuses a turning point
  (roller_dynamics_coupled notes, "Settling test"), against the same references: 400 K
  cold 8.0 orbits +0.11 %, warm 4.0 orbits -0.085 %; 440 K cold 15.0 orbits +0.17 %, warm
  4.0 orbits -0.29 % (the heat moves ~3x the cage speed's remainder, which the test bounds
  to ``settle``); 20000 r/min, 353 K unchanged (3.0 / 2.0 orbits, <= 0.002 %). The
  example scene (as above): scene CPU cold 19.2 -> 23.9 s, warm-started (default) 11.5 ->
  14.9 s; 425 / 440 K nodes cold +0.16 / +0.17 %, warm -0.16 / -0.20 % of the references
  (were +0.48 / +0.74 and -0.51 / -0.72 %); booked rib_friction at the 30000 r/min step end
  cold 634.2 -> 632.4 W, warm 629.6 -> 631.3 W (cold - warm 0.73 -> 0.18 %), final roller
  temperature cold - warm 0.25 -> 0.07 K.

Why the cage creeps at 30000 r/min in hot oil (roller_dynamics_coupled notes, "Cage
settling"): the cage's orbital mode (the cage and the rollers it carries) is damped only by
the loaded rollers' raceway traction, through the slope of their net orbital force with the
cage speed, dF_d/d omega_c, which the Newtonian film sets (~ oil viscosity). At the settled
state (from the traction model, the table's linearisation at each roller): 400 K (eta 2.96
mPa s) sum dF_d/d omega_c = -0.187 N s/rad, damping D = 5.8e-3 N m s against the cage +
carried rollers' inertia I = 8.2e-5 kg m^2 (J_c 5.0e-5, Z m (d_m/2)^2 3.1e-5): I/D = 14 ms,
3 orbits; at 353 K (eta 7.56 mPa s) -0.63 N s/rad, I/D = 4.2 ms, under one 4.6 ms orbit.
The creep measured from the cold start falls by ~0.56 per orbit at 400 K (e-folding 8 ms,
the unloaded rollers' drag adds damping the estimate leaves out). And the start is far
from where it settles: the quasi-static cage speed is 2.4 % below the settled one at 400 K
(1311.3 against 1343.7 rad/s; 0.8 % at 353 K), with the spins first coming up over ~3
orbits. So both apply: a 3.4x weaker damping and a 3x larger start offset. A better cage
speed alone does not help (the spins' transient first drags the cage down, case SOURCE.md
"Cage settling"); the whole settled state of a neighbouring node does.

Cost of the quasi-static start (2026-11-24): cProfile put the quasi-static set-up
(``build_model``: :func:`~thermobearing.skidding.roller.solve_roller`) at ~0.17-0.21 s of a
~0.8 s node at 20000 r/min, but the profiler inflates that Python-heavy code (~86000 calls)
about 4x. Timed without it (``time.process_time`` around the calls): 0.046-0.055 s of
0.63-0.67 s per node (7-8 %; the table 0.07-0.08 s, the kernel 0.47-0.51 s); at 5000 r/min
0.04-0.08 s of 1.8-1.9 s. Its Newton from the neighbouring node's quasi-static state takes
3-4 iterations instead of 9-11 (0.026-0.044 s instead of 0.057-0.127 s), to the same state
within 2e-8 of the roller speeds.
Units: SI.
"""

from __future__ import annotations

import math
import time
import warnings
from collections import OrderedDict
from dataclasses import dataclass, replace
from typing import Any, NamedTuple

import numpy as np

from ..errors import ConvergenceError, InputError, ValidityWarning, check_positive, check_range
from ..rib import DEFAULT_RIB_FRICTION, rib_geometry, rib_sliding_speed
from .roller_dynamics_convergence import DEFAULT_SETTLE

#: models of the rib heat (see the module notes)
MODELS = ("coupled", "reduced")
#: temperature grid step of the cache [K] (module notes: measured < 1 % interpolation error)
DEFAULT_TEMPERATURE_STEP = 5.0
#: warm-up and statistics orbits of the coupled model (those of the validation case)
DEFAULT_WARMUP_ORBITS = 2.0
DEFAULT_ORBITS = 3.0
#: relative tolerance of the coupled model's running-mean stop (module notes, "Where the
#: integration stops"); None: the fixed window of DEFAULT_WARMUP_ORBITS + DEFAULT_ORBITS
DEFAULT_CONVERGENCE = 0.005
#: other table-path trajectories the coupled model tries before its evaluate-path re-run
#: when a run enters the cage runaway (module notes, "Where the integration stops")
DEFAULT_TABLE_RETRIES = 3
#: operating states kept in the cache
CACHE_SIZE = 64
#: a coupled run without unbalance starts from the end state of the nearest temperature node
#: of its operating state already run, at most this many grid steps away (module notes,
#: "Warm start"); 0: every node from the quasi-static state
DEFAULT_WARM_START_NODES = 4


class CoupledStart(NamedTuple):
    """Where a coupled run may start (module notes, "Warm start"), from a run of the same
    bearing, lubricant, speed and load at a nearby temperature.

    quasi_static : that run's quasi-static state, (omega_r (Z,), omega_c) [rad/s] in the
        skidding solver's order (the Newton start of this run's quasi-static solve).
    state : that run's end state (``series["end_state"]`` of
        :func:`~thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`).
    temperature : its temperature [K].
    """

    quasi_static: np.ndarray
    state: np.ndarray
    temperature: float


class RibDynamicsHeat(NamedTuple):
    """Time-mean rib quantities of one roller (mean over rollers and time), SI.

    heat_left, heat_right : friction power of the left / right end-face contact, drag
        included [W] (module notes).
    pv_left, pv_right : time-mean P |v| (paper 003 eqs. 21-24) [Pa m/s].
    slip_speed : time-mean rolling slip at the inner raceway |V_roll| (eq. 25) [m/s].
    rib_slide_speed : time- and roller-mean |v_i - v_r| at the eq. 11 contact point of an
        unskewed roller with the model's spins and cage speed (the slide a thrust share
        would have) [m/s].
    temperature : where it was evaluated (interpolated) [K].  cost_s : CPU time of the
        runs it needed [s] (0 if all were cached).  runs : dynamics runs it needed.
    model : "coupled" | "reduced".
    warm_starts : coupled runs (of those this value rests on) started from a neighbouring
        node's end state (module notes, "Warm start").
    fallbacks : coupled runs (of those this value rests on, cached ones included) whose
        table path left the cage band and were re-run (other table-path trajectories,
        then the ``"evaluate"`` traction path;
        :func:`~thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`).
    orbits : cage orbits the coupled runs it rests on integrated (mean over its nodes; 0
        for the reduced model).
    """

    heat_left: float
    heat_right: float
    pv_left: float
    pv_right: float
    slip_speed: float
    rib_slide_speed: float
    temperature: float
    cost_s: float
    runs: int
    model: str
    fallbacks: int = 0
    orbits: float = 0.0
    warm_starts: int = 0

    @property
    def heat(self) -> float:
        """Both end faces of one roller [W]."""
        return self.heat_left + self.heat_right


@dataclass
class _Cache:
    """Bounded least-recently-used memo of dynamics runs (module notes)."""

    size: int = CACHE_SIZE
    hits: int = 0
    runs: int = 0

    def __post_init__(self) -> None:
        self.store: OrderedDict[tuple, RibDynamicsHeat] = OrderedDict()
        # coupled runs' end states per operating state (the key without its node) and node
        self.starts: OrderedDict[tuple, dict[int, CoupledStart]] = OrderedDict()

    def start_near(self, base: tuple, node: int, reach: int) -> CoupledStart | None:
        """The stored end state of the nearest other node of ``base`` at most ``reach``
        nodes away (the cooler one of two equally near), or None."""
        nodes = self.starts.get(base)
        if not nodes or reach <= 0:
            return None
        near = [(abs(k - node), k) for k in nodes if k != node and abs(k - node) <= reach]
        return nodes[min(near)[1]] if near else None

    def keep_start(self, base: tuple, node: int, start: CoupledStart) -> None:
        self.starts.setdefault(base, {})[node] = start
        self.starts.move_to_end(base)
        while len(self.starts) > self.size:
            self.starts.popitem(last=False)

    def get(self, key: tuple) -> RibDynamicsHeat | None:
        found = self.store.get(key)
        if found is not None:
            self.store.move_to_end(key)
            self.hits += 1
        return found

    def put(self, key: tuple, value: RibDynamicsHeat) -> None:
        self.runs += 1
        self.store[key] = value
        self.store.move_to_end(key)
        while len(self.store) > self.size:
            self.store.popitem(last=False)


_CACHE = _Cache()


def cache_info() -> dict[str, int]:
    """{"hits", "runs", "size"}: cache hits and dynamics runs since the last clear."""
    return {"hits": _CACHE.hits, "runs": _CACHE.runs, "size": len(_CACHE.store)}


def clear_cache() -> None:
    """Empty the cache and reset its counters."""
    _CACHE.store.clear()
    _CACHE.starts.clear()
    _CACHE.hits = 0
    _CACHE.runs = 0


def run_dynamics(bearing: Any, lubricant: Any, speed: float, radial_load: float,
                 temperature: float, unbalance_mass: float = 0.0, *, model: str = "coupled",
                 friction_coefficient: float = DEFAULT_RIB_FRICTION,
                 oil_fraction: float = 0.05, warmup_orbits: float = DEFAULT_WARMUP_ORBITS,
                 orbits: float = DEFAULT_ORBITS,
                 convergence: float | None = DEFAULT_CONVERGENCE,
                 table_retries: int = DEFAULT_TABLE_RETRIES,
                 settle: float | None = DEFAULT_SETTLE,
                 start: CoupledStart | None = None
                 ) -> tuple[RibDynamicsHeat, Any]:
    """One (uncached) run of the roller dynamics at an operating state.

    speed : inner-ring speed relative to the outer ring [rad/s].  radial_load [N].
    temperature [K] (oil viscosities).  unbalance_mass [kg] at the right chamfer (paper 003
    sec. 8).  model : "coupled" | "reduced".  friction_coefficient : mu of eq. 12 [-].
    oil_fraction : oil volume fraction of the rib-gap mixture (eq. 14) [-].
    warmup_orbits, orbits : coupled model's discarded and averaged cage orbits (the fixed
    window; with ``convergence`` the most it integrates).  convergence : relative tolerance
    of the coupled model's running-mean stop (module notes; None: the fixed window).
    table_retries : other table-path trajectories before the evaluate-path re-run of a run
    that entered the cage runaway (0: straight to the evaluate path, as before 2026-11-23).
    settle : the coupled model's warm-up settling tolerance (orbit-to-orbit change of the
    orbit-mean cage speed, before the running-mean test; module notes, "Cage settling";
    None: no settling warm-up, as before 2026-11-23 evening); used without unbalance only
    (the chaotic motion with one has no steady cage speed to settle to).
    start : the coupled model's warm start (:class:`CoupledStart`, module notes "Warm
    start"): its quasi-static state starts the quasi-static solve's Newton, its end state
    the integration (None: the quasi-static state, cold).
    Returns (:class:`RibDynamicsHeat`, the model's ``RollerResponse``; a coupled run's
    ``series["quasi_static_state"]`` holds its quasi-static (omega_r, omega_c), the
    :class:`CoupledStart` of a later run with ``series["end_state"]``).
    """
    from .roller_dynamics import build_model, simulate_reduced

    if model not in MODELS:
        raise InputError("model", model, MODELS)
    check_positive("speed", speed)
    check_positive("temperature", temperature)
    t0 = time.process_time()
    geom = rib_geometry(bearing)
    if model == "coupled":
        from .roller import solve_roller
        from .roller_dynamics_coupled import simulate_coupled

        qs = solve_roller(bearing, lubricant, speed, radial_load, 0.0, temperature,
                          x0=None if start is None else start.quasi_static)
        m = build_model(bearing, lubricant, speed, radial_load, unbalance_mass,
                        temperature=temperature, rib_friction=friction_coefficient,
                        oil_fraction=oil_fraction, coupling="none", quasi_static=qs)
        resp = simulate_coupled(m, bearing, lubricant, n_orbits=orbits,
                                warmup_orbits=warmup_orbits, converge=convergence,
                                table_retries=table_retries,
                                settle=settle if unbalance_mass == 0.0 else None,
                                start=None if start is None else start.state)
        s = dict(resp.series)
        s["quasi_static_state"] = np.append(np.asarray(qs.roller_speed, float),
                                            float(qs.cage_speed))
        resp = replace(resp, series=s)
        n_orbits = float(s["simulated_orbits"][0])
        v = rib_sliding_speed(geom, speed, s["cage_speed"][:, None], s["spin"])
        slide = float(np.mean(np.abs(v)))
        fallbacks = int(s.get("traction_fallback", np.zeros(1))[0])
    else:
        fallbacks, n_orbits = 0, 0.0
        m = build_model(bearing, lubricant, speed, radial_load, unbalance_mass,
                        temperature=temperature, rib_friction=friction_coefficient,
                        oil_fraction=oil_fraction)
        resp = simulate_reduced(m)
        slide = float(np.mean(np.abs(rib_sliding_speed(geom, speed, m.cage_speed, m.spin))))
    out = RibDynamicsHeat(float(resp.rib_heat_left), float(resp.rib_heat_right),
                          float(resp.pv_left), float(resp.pv_right), float(resp.slip_speed),
                          slide, float(temperature), time.process_time() - t0, 1, model,
                          fallbacks, n_orbits, int(start is not None))
    return out, resp


def rib_dynamics_heat(bearing: Any, lubricant: Any, speed: float, radial_load: float,
                      temperature: float, unbalance_mass: float = 0.0, *,
                      model: str = "coupled",
                      friction_coefficient: float = DEFAULT_RIB_FRICTION,
                      oil_fraction: float = 0.05,
                      temperature_step: float = DEFAULT_TEMPERATURE_STEP,
                      warmup_orbits: float = DEFAULT_WARMUP_ORBITS,
                      orbits: float = DEFAULT_ORBITS,
                      convergence: float | None = DEFAULT_CONVERGENCE,
                      table_retries: int = DEFAULT_TABLE_RETRIES,
                      settle: float | None = DEFAULT_SETTLE,
                      warm_start_nodes: int = DEFAULT_WARM_START_NODES) -> RibDynamicsHeat:
    """:func:`run_dynamics` through the cache, linearly interpolated between the two
    temperature nodes k dT <= T < (k + 1) dT (dT = ``temperature_step`` [K]; one node if T
    lies on it). Arguments as :func:`run_dynamics`. ``warm_start_nodes``: a coupled run
    without unbalance starts from the end state of the nearest node of the same operating
    state already run at most this many nodes away (module notes, "Warm start"; 0: from the
    quasi-static state). ``cost_s`` / ``runs`` of the result count only the runs this call
    made."""
    if model not in MODELS:
        raise InputError("model", model, MODELS)
    check_positive("temperature_step", temperature_step)
    check_range("temperature", temperature, 150.0, 700.0, unit="K")
    if (isinstance(warm_start_nodes, bool) or not isinstance(warm_start_nodes, int | np.integer)
            or warm_start_nodes < 0):
        raise InputError("warm_start_nodes", warm_start_nodes, "a whole number of nodes >= 0")
    base = (repr(bearing), repr(lubricant), round(float(speed), 9),
            round(float(radial_load), 9), float(unbalance_mass), model,
            float(friction_coefficient), float(oil_fraction), float(warmup_orbits),
            float(orbits), None if convergence is None else float(convergence),
            int(table_retries), None if settle is None else float(settle),
            int(warm_start_nodes))
    # warm starts only for the deterministic motion (the chaotic one with an unbalance keeps
    # its cold start: its value would depend on which node ran first)
    reach = int(warm_start_nodes) if model == "coupled" and unbalance_mass == 0.0 else 0
    k = math.floor(temperature / temperature_step + 1e-12)
    w = temperature / temperature_step - k
    nodes = [(k, 1.0 - w)] + ([(k + 1, w)] if w > 1e-9 else [])
    values = []
    cost = 0.0
    runs = 0
    def run(node: int) -> RibDynamicsHeat:
        start = _CACHE.start_near(base, node, reach)
        t_try = time.process_time()
        kwargs = dict(model=model, friction_coefficient=friction_coefficient,
                      oil_fraction=oil_fraction, warmup_orbits=warmup_orbits, orbits=orbits,
                      convergence=convergence, table_retries=table_retries, settle=settle)
        try:
            out, resp = run_dynamics(bearing, lubricant, speed, radial_load,
                                     node * temperature_step, unbalance_mass, start=start,
                                     **kwargs)
        except ConvergenceError:
            if start is None:
                raise
            # the neighbour's state did not carry over: this node from its quasi-static state
            spent = time.process_time() - t_try
            out, resp = run_dynamics(bearing, lubricant, speed, radial_load,
                                     node * temperature_step, unbalance_mass, **kwargs)
            out = out._replace(cost_s=out.cost_s + spent)
        s = getattr(resp, "series", None) or {}
        if reach > 0 and "end_state" in s and "quasi_static_state" in s:
            _CACHE.keep_start(base, node, CoupledStart(s["quasi_static_state"],
                                                       s["end_state"],
                                                       node * temperature_step))
        return out

    def neighbour(node: int) -> RibDynamicsHeat:
        # a neighbour node's value from the cache (no run: runs and cost 0) or its run,
        # cached under its own key as well
        key = (*base, node, float(temperature_step))
        found = _CACHE.get(key)
        if found is not None:
            return found._replace(runs=0, cost_s=0.0)
        found = run(node)
        _CACHE.put(key, found)
        return found

    for node, weight in nodes:
        key = (*base, node, float(temperature_step))
        found = _CACHE.get(key)
        if found is None:
            try:
                found = run(node)
            except ConvergenceError as exc:
                found = _neighbour_node(neighbour, node, temperature_step, exc)
            _CACHE.put(key, found)
            cost += found.cost_s
            runs += found.runs
        values.append((weight, found))

    def mix(i: int) -> float:
        return float(sum(wt * v[i] for wt, v in values))

    return RibDynamicsHeat(*(mix(i) for i in range(6)), float(temperature), cost, runs, model,
                           sum(v.fallbacks for _, v in values),
                           float(np.mean([v.orbits for _, v in values])),
                           sum(v.warm_starts for _, v in values))


#: how many grid nodes to either side a failed node may borrow its value from
NEIGHBOUR_NODES = 2


def _neighbour_node(run: Any, node: int, step: float, exc: Exception) -> RibDynamicsHeat:
    """The value of the nearest node (1, then 2 grid steps away, the cooler side first) whose
    dynamics run, for a node whose run stopped with a ConvergenceError (e.g. the coupled
    model's "unstable coupled motion": the cage runs out of its band at that temperature
    while it settles at the neighbouring ones). The node values scatter by about +-4 %
    between neighbours anyway (chaotic impacting motion, module notes); a ValidityWarning
    names both temperatures. If no neighbour runs either, the first error is raised."""
    runs = 1
    for d in range(1, NEIGHBOUR_NODES + 1):
        for other in (node - d, node + d):
            try:
                found = run(other)
            except ConvergenceError:
                runs += 1
                continue
            warnings.warn(ValidityWarning(
                f"rib_friction: the roller dynamics at {node * step:.2f} K stopped ({exc}); "
                f"the rib heat there is the value of the grid node at {other * step:.2f} K"),
                stacklevel=3)
            return found._replace(runs=runs + found.runs)
    raise exc


__all__ = ["CACHE_SIZE", "DEFAULT_CONVERGENCE", "DEFAULT_TABLE_RETRIES",
           "DEFAULT_TEMPERATURE_STEP", "DEFAULT_WARM_START_NODES", "MODELS", "CoupledStart",
           "RibDynamicsHeat", "cache_info", "clear_cache", "rib_dynamics_heat", "run_dynamics"]
