"""Coupled kinematics -> heat sources -> thermal network runs (transient and steady).

Used by :class:`thermobearing.simulation.Simulation` when a scene asks for temperatures
(see its module docstring for the algorithm). Kept apart so that the orchestrator stays
short; it holds no physics: heat comes from the registered heat sources, temperatures
from the network stepper.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np
import pandas as pd

from .coupled_secant import KINEMATIC_ROLES, PROBE_DT, KinematicSecant
from .errors import ConvergenceError, InputError, UnknownNameError
from .operating_checks import check_state
from .results import ResultsWriter
from .scene import Step

if TYPE_CHECKING:  # pragma: no cover
    from .simulation import Simulation
    from .simulation_bearings import _Bearing

ROLES = ("inner_ring", "outer_ring", "elements", "cage", "oil")
#: relative disagreement of a node's two one-sided heat slopes above which the chunk
#: model's linearisation reads a jump or kink within +-dT (:meth:`Coupler.linearize`)
KINK_RATIO = 0.5


def build_network(sim: Simulation) -> Any:
    """The scene's thermal network: one template instance per bearing (group = bearing
    name, node names prefixed ``<bearing>.``), sharing the ambient and oil-inlet boundaries,
    and the ``[network] shaft_link`` edges between the ``shaft`` nodes of bearings on one
    shaft (:mod:`.network.shaft`).

    ``[network] parameters`` are the template's parameters (unit strings allowed, converted
    with the units the template registers); the ambient and oil-inlet temperatures and the
    oil flow come from the scene's environment and supply. Each shaft link, and two or more
    bearings left thermally independent (no link), are added to ``sim.notes`` (printed by
    ``thermobearing check``).
    """
    from .errors import InputError
    from .network.templates import TEMPLATES
    from .units import to_si

    scene = sim.scene
    spec = dict(scene.network)
    name = spec.pop("template", "four_node_paper002")
    raw = dict(spec.pop("parameters", {}))
    shafts = spec.pop("shaft_link", None)
    if spec:
        key = next(iter(spec))
        raise InputError(f"network.{key}", spec[key],
                         "the keys 'template', 'parameters' and 'shaft_link'")
    entry = TEMPLATES.entry(name)
    params: dict[str, Any] = {}
    for key, value in raw.items():
        unit = entry.parameters.get(key)
        if unit is None:
            raise InputError(f"network.parameters.{key}", value,
                             f"a parameter of template {name!r}: "
                             + ", ".join(sorted(entry.parameters)))
        if isinstance(value, str) and unit == "-":
            params[key] = value
        else:
            params[key] = to_si(value, unit if unit != "-" else "dimensionless",
                                field=f"network.parameters.{key}")
    for key in ("ambient_temperature", "oil_inlet_temperature", "oil_flow"):
        if key in params:
            raise InputError(f"network.parameters.{key}", raw[key],
                             "set in [environment] / [supply], not in the network")
    net = None
    for b in sim.bearings:
        try:
            net = entry.obj(b.bearing, sim.lubricant, network=net, group=b.name,
                            prefix=f"{b.name}.",
                            ambient_temperature=scene.environment.ambient_temperature,
                            oil_inlet_temperature=scene.supply.inlet_temperature,
                            oil_flow=scene.supply.flow, **params)
        except InputError as exc:
            # name the scene field: the parameter itself where the template's field ends in
            # its name (value as written), else the template's own field under [network]
            key = str(exc.field).rsplit(".", 1)[-1]
            if key in raw and isinstance(exc, UnknownNameError):  # a misspelt material ...
                raise UnknownNameError(f"network.parameters.{key}", raw[key],
                                       exc.known) from None
            if key in raw and type(exc) is InputError:
                raise InputError(f"network.parameters.{key}", raw[key],
                                 f"{exc.allowed} (template {name!r}, checked in SI: "
                                 f"{exc.value!r})") from None
            raise InputError(f"network (template {name!r}, bearing {b.name!r}): {exc.field}",
                             exc.value, f"{exc.allowed}; set by [network] parameters "
                             f"{', '.join(sorted(raw)) or '(none)'} or the template's "
                             "defaults") from None
    _link_shafts(sim, net, name, shafts, params)
    try:
        net.validate()
    except InputError as exc:
        if type(exc) is not InputError:
            raise
        # an isolated node names no scene field: say which settings built it (a zero
        # conductance set by [network] parameters, or the template's defaults)
        zero = sorted(k for k, v in params.items()
                      if isinstance(v, (int, float)) and not isinstance(v, bool) and v == 0)
        raise InputError(f"network (template {name!r}): {exc.field}", exc.value,
                         f"{exc.allowed}; the network is built from [network] parameters "
                         f"{', '.join(sorted(raw)) or '(none)'} and the template's defaults"
                         + (f" (set to 0: {', '.join(zero)})" if zero else "")) from None
    return net


def _link_shafts(sim: Simulation, net: Any, template: str, shafts: Any,
                 params: Mapping[str, Any]) -> None:
    """The scene's shaft links on ``net`` (``shafts``: the ``shaft_link`` value or None) and
    their notes (each link; bearings left thermally independent) on ``sim.notes`` and
    ``sim.warnings`` (the run's report lists them with the scene's other notes)."""
    from .errors import InputError
    from .network.shaft import independence_note, link_shafts, parse_shaft_links
    from .network.templates import shaft_segment

    names = [b.name for b in sim.bearings]
    links, notes = [], []
    if shafts is not None:
        try:
            segments = {b.name: shaft_segment(b.bearing, **params) for b in sim.bearings}
        except TypeError:
            raise InputError("network.shaft_link", shafts,
                             f"a template whose shaft piece is known (template {template!r} "
                             "has no housing_length / shaft_length parameter)") from None
        links, notes = link_shafts(net, parse_shaft_links(shafts), names, segments, template)
    alone = independence_note(names, links)
    if alone:
        notes.append(alone)
    # the run's notes and, like the scene's other notes, its report (Results.warnings)
    for attr in ("notes", "warnings"):
        held = getattr(sim, attr, None)
        if held is not None:
            held.extend(n for n in notes if n not in held)


@dataclass
class _Linear:
    """Heat model over the state nodes for one coupling chunk, quadratic in each read node:

    q(T) = q0 + J (T - T0) + 1/2 H (T - T0)^2   (the square taken elementwise),

    J the Jacobian dq/dT at T0 and H the second derivatives d2q_i/dT_j^2 (diagonal in j:
    the mixed derivatives of two read nodes are left out), both from central differences
    (:meth:`Coupler.linearize`); beyond ``reach`` from T0 the quadratic term is continued
    linearly. The curvature matters: right after a load step the oil
    node moves by ~0.5 K within a chunk, and an affine model (H = 0) put 0.01-0.09 W of
    heat error on the housing there, 5e-5 to 2.6e-4 K of temperature error over the
    protocol against the exact heat (BM-E2E); with H the chunk's heat error is O(dT^3).

    The model never goes below ``min(q0, 0)`` per node: the sources' heat is a loss (>= 0),
    but where it falls steeply with temperature (a cold start at high speed: the viscous
    losses drop as the oil thins) the affine model turns negative within a chunk, and a
    negative heat cools a node below every sink. A fuzzed 6304 at 42000 r/min started at
    7.8 degC had its inner ring at -36 degC after one 0.1 s chunk (at -1681 degC after
    11 s); clamped rows have a zero Jacobian row.

    ``K``, ``c``: the held kinematic states' temperature dependence, K T - c [W] added to
    the heat and K [W/K] to its Jacobian (:class:`.coupled_secant.KinematicSecant`: the
    heat at fixed kinematics above misses how the state itself moves as the oil thins).
    """

    q0: np.ndarray
    J: np.ndarray
    T0: np.ndarray
    H: np.ndarray | None = None
    #: half-width [K] of the curvature's trust region: beyond |T_j - T0_j| > reach the
    #: quadratic term is continued linearly (C1), so that a large excursion (a thermal
    #: runaway) is not extrapolated with a parabola fitted over +-dT
    reach: float = 2.0
    #: the held kinematic states' temperature dependence (:class:`.coupled_secant.
    #: KinematicSecant`): K T - c is added to the heat, K [W/K] to its Jacobian (None: none)
    K: np.ndarray | None = None
    c: np.ndarray | None = None

    def __post_init__(self) -> None:
        self._floor = np.minimum(self.q0, 0.0)
        # the read columns (H is zero elsewhere): the model is evaluated hundreds of times
        # per run by the stepper, so the curvature term loops over these few columns only
        # (scalar loops: cheaper than numpy's fancy indexing for a handful of columns)
        self._cols: tuple[tuple[int, np.ndarray], ...] = (
            () if self.H is None else
            tuple((int(j), self.H[:, j].copy()) for j in np.flatnonzero(self.H.any(axis=0))))

    def heat(self, t: float, T: np.ndarray) -> np.ndarray:
        """q(T) [W] at state nodes T [K] (the chunk model does not depend on time)."""
        d = T - self.T0
        q = self.q0 + self.J @ d
        r = self.reach
        for j, h in self._cols:
            dj = float(d[j])
            c = r if dj > r else -r if dj < -r else dj
            q += (c * dj - 0.5 * c * c) * h
        if self.K is not None:
            q += self.K @ T - self.c
        return np.maximum(q, self._floor, out=q)

    def _jac_model(self, T: np.ndarray) -> np.ndarray:
        """dq/dT [W/K] of the unclamped model at T [K] without the kinematic term (a copy
        only when changed)."""
        if not self._cols:
            return self.J
        out = self.J.copy()
        r = self.reach
        for j, h in self._cols:
            dj = float(T[j] - self.T0[j])
            out[:, j] += (r if dj > r else -r if dj < -r else dj) * h
        return out

    def jac(self, t: float, T: np.ndarray) -> np.ndarray:
        """dq/dT [W/K] at T [K] (zero rows where the heat is clamped at its floor)."""
        return self.heat_and_jac(t, T)[1]

    def heat_and_jac(self, t: float, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(q [W], dq/dT [W/K]) at T [K] in one pass (the steppers' heat_with_jacobian)."""
        d = T - self.T0
        q = self.q0 + self.J @ d
        out = self.J
        if self._cols:
            out = self.J.copy()
            r = self.reach
            for j, h in self._cols:
                dj = float(d[j])
                c = r if dj > r else -r if dj < -r else dj
                q += (c * dj - 0.5 * c * c) * h
                out[:, j] += c * h
        if self.K is not None:
            q += self.K @ T - self.c
            out = out + self.K
        low = q < self._floor
        if low.any():
            q[low] = self._floor[low]
            out = out.copy() if out is self.J else out
            out[low, :] = 0.0
        return q, out

    def moved(self, q: np.ndarray, T: np.ndarray) -> _Linear:
        """The same model re-centred at T with the exact heat q there (a later chunk on
        the same kinematic state): the Jacobian is the model's own at T (unclamped), H is
        kept."""
        return _Linear(q, self._jac_model(T), T.copy(), self.H, self.reach)

    def with_kinematics(self, K: np.ndarray | None, c: np.ndarray | None) -> _Linear:
        """The same model with the held kinematic states' term K T - c [W] (None: none)."""
        return _Linear(self.q0, self.J, self.T0, self.H, self.reach, K, c)


class Coupler:
    """Evaluates every bearing's heat on the network's state vector (public: outside
    integrators, e.g. the solve_ivp driver of ``benchmarks/bm_e2e.py``, use it)."""

    def __init__(self, sim: Simulation, net: Any) -> None:
        self.sim = sim
        self.net = net
        #: node temperature [K] at which the run stops as a thermal runaway (the
        #: pressure-viscosity law's range counts where the chain computes contacts)
        self.runaway_limit = lubricant_temperature_limit(
            sim.lubricant, pressure=any(link.family == "pressure_viscosity"
                                        for link in getattr(sim, "chain", ())))
        self.names = list(net.state_nodes)
        self.index = {n: i for i, n in enumerate(self.names)}
        self.role_nodes: dict[str, dict[str, list[int]]] = {}
        #: heat evaluations of one bearing (memoised sources included): the coupling's cost
        #: in heat-source calls, comparable with an outside integrator's right-hand sides
        self.bearing_evaluations = 0
        #: kinematics solves of :meth:`probe_kinematics` (one per bearing and schedule step)
        self.kinematic_probes = 0
        self._probes: dict[tuple, Any] = {}
        for b in sim.bearings:
            roles = net.roles(b.name)
            self.role_nodes[b.name] = {r: [self.index[n] for n in roles.get(r, [])]
                                       for r in ROLES}
            missing = [r for r in ROLES if not self.role_nodes[b.name][r]]
            if missing:
                from .errors import InputError

                raise InputError(f"network group {b.name!r} roles", missing,
                                 "a node for every heat-source role "
                                 "(inner_ring, outer_ring, elements, cage, oil)")

    def role_temperatures(self, b: _Bearing, T: np.ndarray) -> dict[str, float]:
        """Mean temperature [K] of each role's nodes."""
        out = {}
        for r, idx in self.role_nodes[b.name].items():
            out[r] = float(T[idx[0]]) if len(idx) == 1 else float(np.mean(T[idx]))
        return out

    def kinematics(self, step_index: int, step: Step, T: np.ndarray) -> None:
        for b in self.sim.bearings:
            self.sim.solve_kinematics(b, step_index, step, self.role_temperatures(b, T))

    def viscosity_drift(self, T: np.ndarray, start: np.ndarray | None = None) -> float:
        """Largest relative change, over the bearings, of the contact viscosity between the
        kinematic state in use and the temperatures ``T`` [-]: |eta(T_c(T)) / eta_kin - 1|,
        T_c the kinematics' contact temperature (``kinematic_models.contact_temperature``)
        and eta_kin the viscosity the state was solved at. Bearings at rest (no contact
        heat) are left out. A bearing with the global friction model (kinematics "none")
        holds no kinematic state, its viscosity follows the nodes; what it holds over a
        chunk is the chunk's heat model (:class:`_Linear`, a Taylor model about the chunk
        start): with ``start`` (the chunk's initial temperatures [K]) its drift is
        |eta(T_c(T)) / eta(T_c(start)) - 1|, so a chunk over which its viscosity moves
        beyond the limit is repeated shorter as well (without ``start`` it is left out).

        Temperatures outside the viscosity law's range give ``inf`` (the chunk is rejected
        and repeated shorter): a chunk's heat model extrapolated far from its state -- a
        cold start at high speed, where the losses fall steeply as the oil warms, so the
        affine heat model turns negative within a long chunk -- sent the inner ring of a
        6304 at 42000 r/min to -1681 degC in one 11 s chunk, and the drift check itself
        stopped the run ('temperature = 23.3 K is not allowed', fuzz case) instead of
        repeating the chunk."""
        from .kinematic_models import contact_temperature

        worst = 0.0
        for b in self.sim.bearings:
            if b.last is None or getattr(b.last.state, "origin", "") == "standstill":
                continue
            global_model = b.kinematics_name == "none"
            if global_model and start is None:
                continue
            try:
                eta = float(self.sim.lubricant.dynamic_viscosity(
                    contact_temperature(self.role_temperatures(b, T))))
                ref = (float(self.sim.lubricant.dynamic_viscosity(
                    contact_temperature(self.role_temperatures(b, start))))
                    if global_model else b.last_viscosity)
            except InputError:  # outside the law's range (only its temperature is checked)
                return math.inf
            if not math.isfinite(ref):
                continue
            worst = max(worst, abs(eta / ref - 1.0))
        return worst

    def _bearing_heat(self, b: _Bearing, step: Step, T: np.ndarray, kin: Any = None
                      ) -> tuple[np.ndarray, frozenset[str]]:
        """One bearing's heat [W] on the state nodes at T [K] on its held kinematic state
        (or ``kin``), and the roles its sources read."""
        self.bearing_evaluations += 1
        q = np.zeros(len(self.names))
        ev = self.sim.evaluate_heat(b, step, b.last if kin is None else kin,
                                    self.role_temperatures(b, T))
        return self.net.distribute(ev.by_role, group=b.name, out=q), ev.reads

    def probe_kinematics(self, b: _Bearing, step: Step, T: np.ndarray
                         ) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """Bearing ``b``'s kinematics solved once more with the nodes they read
        (:data:`.coupled_secant.KINEMATIC_ROLES`) warmer by :data:`.coupled_secant.PROBE_DT`,
        warm-started from its held state and recorded nowhere (no table row, no check, no
        warning: a probe, not a state the bearing runs in): (those temperatures [K], the
        probe state's heat there [W], the held state's heat there [W]) for
        :meth:`.coupled_secant.KinematicSecant.restart`. None where there is nothing to
        probe (no kinematic state: global friction, a bearing at rest) or the solver
        refuses (the secant then starts from zero). Counted in ``kinematic_probes``."""
        import warnings

        from .kinematic_models import KINEMATICS, contact_temperature

        if (b.last is None or b.kinematics_name == "none"
                or getattr(b.last.state, "origin", "") == "standstill"):
            return None
        Tp = np.array(T, dtype=float)
        for r in KINEMATIC_ROLES:
            Tp[self.role_nodes[b.name][r]] = T[self.role_nodes[b.name][r]] + PROBE_DT
        temps = self.role_temperatures(b, Tp)
        # twin bearings (same record key, one shared state): one probe, each bearing's
        # heat of it at its own temperatures
        key = (b.key, id(b.last))
        res = self._probes.get(key)
        if res is not None:
            return Tp, self._bearing_heat(b, step, Tp, res)[0], self._bearing_heat(b, step, Tp)[0]
        fn = KINEMATICS.get(b.kinematics_name)
        self.kinematic_probes += 1
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                res = fn(b.bearing, self.sim.lubricant, self.sim._operating(step, b),
                         contact_temperature=contact_temperature(temps),
                         oil_temperature=temps["oil"], supply=self.sim.supply, guess=b.last,
                         options=b.kin_options)
            except (ConvergenceError, InputError):
                return None
        if not res.converged:
            return None
        self._probes.clear()  # one operating point's probes: the last solve's twins only
        self._probes[key] = res
        return Tp, self._bearing_heat(b, step, Tp, res)[0], self._bearing_heat(b, step, Tp)[0]

    def heat(self, step: Step, T: np.ndarray) -> np.ndarray:
        return sum((self._bearing_heat(b, step, T)[0] for b in self.sim.bearings),
                   np.zeros(len(self.names)))

    def linearize(self, step: Step, T: np.ndarray, dT: float = 0.5) -> _Linear:
        """Heat, its Jacobian and its second derivatives by central differences: each
        bearing's heat is differentiated in the nodes of the temperature roles its sources
        read (two evaluations per node, at T +- dT [K]; a role no source read cannot
        change the heat at a fixed kinematic state). See :class:`_Linear`.

        Kinks: where a node's two one-sided slopes of the bearing's total heat disagree by
        more than half the larger (:data:`KINK_RATIO`), the heat has a jump or a kink inside
        +-dT -- a source switching regime, e.g. paper 002's inner-ring churning at its
        flow-regime boundary, 92.6 -> 118.3 W within 0.4 K of oil temperature. The
        difference quotients there are not derivatives: the curvature (26 W over 0.5 K
        read as H = 112 W/K^2) extrapolated to 6.7 kW at +13 K against the true 0.8 kW
        and put a 44 degC spike on the oil node of a cold start. Such a column takes the
        one-sided slope of the smaller magnitude and no curvature."""
        n = len(T)
        q0 = np.zeros(n)
        J = np.zeros((n, n))
        H = np.zeros((n, n))
        for b in self.sim.bearings:
            qb, reads = self._bearing_heat(b, step, T)
            q0 += qb
            nodes = self.role_nodes[b.name]
            cols = sorted({i for role in reads for i in nodes[role]})
            for j in cols:
                Tp = T.copy()
                Tp[j] += dT
                qp = self._bearing_heat(b, step, Tp)[0]
                Tp[j] = T[j] - dT
                qm = self._bearing_heat(b, step, Tp)[0]
                up, down = (qp - qb) / dT, (qb - qm) / dT
                a, c = float(up.sum()), float(down.sum())
                if abs(a - c) > KINK_RATIO * max(abs(a), abs(c)) + 1e-9:
                    J[:, j] += up if abs(a) < abs(c) else down
                    continue
                J[:, j] += (qp - qm) / (2.0 * dT)
                H[:, j] += (qp - 2.0 * qb + qm) / (dT * dT)
        return _Linear(q0, J, T.copy(), H, reach=4.0 * dT)

    def loss_rows(self, step_index: int, time_s: float | None, step: Step,
                  T: np.ndarray, details: dict[str, list[dict[str, Any]]] | None = None
                  ) -> list[dict[str, Any]]:
        """The loss table's rows of every bearing at temperatures ``T`` [K] (``time_s`` [s]
        None: a steady operating point, no time column). ``details``: given, it receives
        the rows of the sources' detail tables (table -> rows, the ``rib`` table) of the
        same evaluations."""
        from .simulation import step_columns

        rows = []
        for b in self.sim.bearings:
            ev = self.sim.evaluate_heat(b, step, b.last, self.role_temperatures(b, T),
                                        with_rows=True)
            base = step_columns(step_index, time_s, b.name, step, b)
            rows.extend({**base, **r} for r in ev.rows)
            if details is not None:
                for name, extra in ev.tables.items():
                    details.setdefault(name, []).extend({**base, **r} for r in extra)
        return rows


def _wants_loss_table(scene: Any) -> bool:
    """Whether the run must tabulate the losses per step (asked, or the report shows them)."""
    want = scene.outputs.want
    return "losses" in want or "report" in want


def _sample_times(t: float, h: float, interval: float | None) -> np.ndarray | None:
    """Multiples of ``interval`` [s] strictly inside the chunk (t, t + h) (the chunk ends
    have their own rows), or None."""
    if interval is None:
        return None
    tol = 1e-9 * max(1.0, t + h)
    k0 = math.floor((t + tol) / interval) + 1
    times = interval * np.arange(k0, math.ceil((t + h - tol) / interval))
    times = times[(times > t + tol) & (times < t + h - tol)]
    return times if times.size else None


#: shortest coupling chunk [s] the viscosity-drift control halves down to
MIN_CHUNK = 0.1

#: node temperature [K] above which a run is stopped as a thermal runaway (300 degC: beyond
#: the service range of bearing steels and lubricants)
RUNAWAY_TEMPERATURE = 573.15


def lubricant_temperature_limit(lubricant: Any, pressure: bool = True) -> float:
    """The runaway limit of a run with this lubricant [K]: :data:`RUNAWAY_TEMPERATURE`, or
    lower where the lubricant's viscosity or (``pressure``: the run computes contacts)
    pressure-viscosity law ends before it (to 0.5 K; Roelands' alpha needs
    eta > 6.31e-5 Pa s: OIL_4109 ends near 226 degC). A run heading for a runaway with such
    an oil stopped at the next kinematics solve with ``eta0 = 1.76e-05 is not allowed``
    from the law, naming no scene field (fuzz case: a D1842926 at 7118 r/min and 68 kN on a
    0.003 L/min jet, steady passes at 86, 186 and 286 degC). A chain without contacts
    (kinematics "none", global friction) uses no pressure-viscosity law."""
    import warnings

    def usable(T: float) -> bool:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                lubricant.dynamic_viscosity(T)
                if pressure:
                    lubricant.pressure_viscosity_coefficient(T)
        except InputError:
            return False
        return True

    lo, hi = 273.15, RUNAWAY_TEMPERATURE
    if usable(hi) or not usable(lo):
        return RUNAWAY_TEMPERATURE
    while hi - lo > 0.5:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if usable(mid) else (lo, mid)
    return lo


def _check_runaway(names: list[str], T: np.ndarray, t: float | None, step: int,
                   lin: _Linear, limit: float = RUNAWAY_TEMPERATURE) -> None:
    """Stop with a clear error when a node runs away thermally (heat in >> heat out): a
    transient state (time ``t`` [s]) or a steady solve's pass or fixed point (``t`` None)
    with a node above ``limit`` (:data:`RUNAWAY_TEMPERATURE`, or the lubricant's own limit,
    :func:`lubricant_temperature_limit`). A steady state at 1200 degC is no
    answer either, and the passes on the way there leave the viscosity laws' range."""
    j = int(np.argmax(T))
    if T[j] > limit:
        why = "" if limit >= RUNAWAY_TEMPERATURE else ": the lubricant's viscosity laws end there"
        what, head, state = (
            ("coupled transient", "thermal runaway", {"time": t, "step": step})
            if t is not None else
            ("coupled steady state", "no steady state below the runaway limit",
             {"step": step}))
        when = "" if t is None else f" at t = {t:.4g} s"
        # the step as the tables number it (from 0): the progress lines count the finished
        # steps from 1, so "step 3/5 done" and then "step=3" read as the same step
        in_step = f", in step {step} (numbered from 0, as in the tables),"
        # a state just past the limit (a crossing located inside a chunk) is told as the
        # limit reached, with how far above it, so that it does not read as below it
        reached = (f"reached {T[j] - 273.15:.0f} degC{when} (limit {limit - 273.15:.0f} "
                   f"degC{why})" if T[j] - limit >= 1.0 else
                   f"reached the limit of {limit - 273.15:.1f} degC{when} "
                   f"({T[j] - limit:.2g} K above it{why})")
        raise ConvergenceError(
            what, float(T[j] - limit),
            f"{head}: node {names[j]!r} {reached}{in_step} with {float(np.sum(lin.q0)):.0f} W "
            "of heat; the losses exceed what the network removes -- check the oil flow, the "
            "cooling paths and the speed/load of the schedule", state)


#: zooms of the search for the first state above the runaway limit inside a coupling
#: chunk (:func:`_first_above_limit`), and the states sampled in each: the crossing is
#: located to the chunk's length / 32**3
RUNAWAY_ZOOMS = 3
RUNAWAY_SAMPLES = 32


def _first_above_limit(net: Any, method: str, solver: Any, lin: _Linear, t0: float,
                       T0: np.ndarray, t1: float, limit: float
                       ) -> tuple[float, np.ndarray] | None:
    """(time [s], temperatures [K]) of the first state above ``limit`` [K] on the chunk
    model's trajectory from ``(t0, T0)`` to ``t1`` [s], or None when no sampled state is
    above it (or the stepper fails before one is).

    Where a runaway starts inside a long coupling chunk the chunk model carries the network
    far beyond the limit before the chunk ends: a fuzzed QJ1044 (global friction, kinematics
    "none", 25 kW at 5000 r/min on a 0.086 L/min jet, a 600 s chunk) had its oil node at
    3.5e5 K when the stepper stopped with an air conductance out of range, 115 s into the
    chunk; its oil crossed the 226 degC limit 1.4 s in. Each zoom integrates the stretch
    known to hold the crossing afresh (stepper ``method``, the scene's tolerances) with
    :data:`RUNAWAY_SAMPLES` states sampled and keeps the stretch between the last state
    below the limit and the first above it."""
    from .network import TransientStepper

    a, Ta, b = t0, T0, t1
    found: tuple[float, np.ndarray] | None = None
    zooms, retries = 0, 0
    while zooms < RUNAWAY_ZOOMS and b > a:
        times = a + (b - a) * np.arange(1, RUNAWAY_SAMPLES + 1) / RUNAWAY_SAMPLES
        stepper = TransientStepper(net, method=method, rtol=solver.rtol, atol=solver.atol,
                                   max_step=solver.max_step)
        try:
            out = stepper.advance(a, Ta, b - a, lin.heat, heat_time_dependent=False,
                                  heat_with_jacobian=lin.heat_and_jac,
                                  sample_times=times[:-1])
        except ConvergenceError as exc:
            tf = exc.state.get("time")
            if isinstance(tf, float) and a < tf < b and retries < 3:
                b = tf  # the trajectory up to the failure is the stepper's own
                retries += 1
                continue
            break
        except InputError:
            break
        states = [*out.samples, out.temperatures]
        k = next((k for k, s in enumerate(states) if not float(np.max(s)) <= limit), None)
        if k is None or not np.all(np.isfinite(states[k])):
            break
        found = (float(times[k]), states[k])
        if k > 0:
            a, Ta = float(times[k - 1]), states[k - 1]
        b = float(times[k])
        zooms += 1
    return found


def _stepper_state_above(exc: ConvergenceError, limit: float
                         ) -> tuple[float, np.ndarray] | None:
    """(time [s], temperatures [K]) where a network stepper stopped, when that state has a
    node above ``limit`` [K] (a runaway within the chunk), else None."""
    t, y = exc.state.get("time"), exc.state.get("temperatures")
    if not isinstance(y, np.ndarray) or not isinstance(t, float):
        return None
    top = float(np.max(y)) if y.size else -math.inf
    return (t, y) if math.isfinite(top) and top > limit else None


def _stop_runaway(net: Any, method: str, solver: Any, lin: _Linear, t0: float,
                  T0: np.ndarray, beyond: tuple[float, np.ndarray], names: list[str],
                  step: int, limit: float) -> None:
    """Stop as a thermal runaway (:func:`_check_runaway`) at the first state above ``limit``
    [K] on the chunk model's trajectory from ``(t0, T0)``, ``beyond`` a (time [s],
    temperatures [K]) the chunk reached past it (its end, or where the stepper stopped);
    that state itself where the crossing cannot be located. Returns only where neither
    state is above the limit (a non-finite chunk end: the caller's own error)."""
    t1, T1 = beyond
    crossing = _first_above_limit(net, method, solver, lin, t0, T0, t1, limit)
    if crossing is not None:
        _check_runaway(names, crossing[1], crossing[0], step, lin, limit)
    if np.all(np.isfinite(T1)):
        _check_runaway(names, T1, t1, step, lin, limit)


def _temperature_row(t: float | None, names: list[str], T: np.ndarray
                     ) -> dict[str, float]:
    """``time [s]``, ``time [min]`` (transient; none for ``t`` None, a steady state) and
    ``<node> [degC]`` per node at temperatures ``T`` [K]."""
    row = {} if t is None else {"time [s]": t, "time [min]": t / 60.0}
    for n, v in zip(names, T, strict=True):
        row[f"{n} [degC]"] = float(v) - 273.15
    return row


def run_coupled(sim: Simulation, writer: ResultsWriter | None
                ) -> tuple[dict[str, pd.DataFrame], dict[str, Any]]:
    """Transient or steady coupled run of the whole schedule (see Simulation)."""
    net = build_network(sim)
    sim.network = net
    measured = sim.scene.measured
    if measured is not None:
        for column, node in measured.columns.items():
            if node not in net.state_nodes:
                from .errors import InputError
                from .measured_layout import closest_name

                raise InputError(f"measured.columns[{column!r}]", node,
                                 "a node of the network: " + ", ".join(net.state_nodes)
                                 + closest_name(str(node), list(net.state_nodes)))
    import warnings

    from .errors import ValidityWarning

    # the network's own correlations (Churchill-Chu's Rayleigh range, Whitaker's Re / Pr
    # range in conductances.py) warn outside the kinematics and heat evaluations, whose
    # warnings are caught there: without this they reached Python's warning stream only,
    # never the run's warnings and report
    with warnings.catch_warnings(record=True) as caught:
        try:
            if sim.scene.outputs.mode == "steady":
                return _run_steady(sim, net, writer)
            return _run_transient(sim, net, writer)
        finally:
            for w in caught:
                if issubclass(w.category, ValidityWarning):
                    sim._warn(str(w.message), "network")
                else:  # anything else goes on as it came
                    warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)


def new_secant(coupler: Coupler) -> KinematicSecant:
    """An empty :class:`.coupled_secant.KinematicSecant` over ``coupler``'s state nodes, each
    bearing on the nodes its kinematics read (:data:`.coupled_secant.KINEMATIC_ROLES`)."""
    return KinematicSecant(len(coupler.names), {
        b.name: [j for r in KINEMATIC_ROLES for j in coupler.role_nodes[b.name][r]]
        for b in coupler.sim.bearings})


def kinematics_with_secant(coupler: Coupler, secant: KinematicSecant, step_index: int,
                           step: Step, T: np.ndarray, first: bool) -> bool:
    """The kinematics at a chunk start (:meth:`Coupler.kinematics`: re-solved where the
    viscosity rule asks) and each bearing's secant kept with them: restarted on a step's
    first chunk (``first``) or a bearing's first state, updated by Broyden's rule where a
    state was re-solved (its heat at T [K] on the new state against the replaced one).
    Returns True where a secant was restarted. Shared by the coupled transient and the
    BM-E2E solve_ivp driver (the same chain)."""
    held = [b.last for b in coupler.sim.bearings]
    coupler.kinematics(step_index, step, T)
    restarted = False
    for b, old in zip(coupler.sim.bearings, held, strict=True):
        if first or old is None:
            secant.restart(b.name, T)
            restarted = True
        elif b.last is not old:
            secant.resolved(b.name, T, coupler._bearing_heat(b, step, T)[0],
                            coupler._bearing_heat(b, step, T, old)[0])
    return restarted


def _probed(coupler: Coupler, secant: KinematicSecant, lin: _Linear, step: Step,
            T: np.ndarray) -> _Linear:
    """The chunk model ``lin`` with each bearing's first secant of the operating point from a
    kinematics probe at T [K] (:meth:`Coupler.probe_kinematics`). Only where a step's first
    chunk is repeated shorter (its contact viscosity moved beyond the chunk limit: the held
    state goes stale fast). A probe at every step of the QJ1044 rig protocol (22 load steps,
    29 kinematics solves, no chunk repeated) added 42 solves for nothing (largest ball error
    against 2 s chunks 0.10 K, 0.08 K without); the NU 214 speed step's first 9.4 s chunk
    held the roller node 1.3 K too warm without it (0.25 K with)."""
    for b in coupler.sim.bearings:
        secant.restart(b.name, T, coupler.probe_kinematics(b, step, T))
    return lin.with_kinematics(*secant.terms())


def chord_first_chunk(coupler: Coupler, secant: KinematicSecant, step_index: int, step: Step,
                      T_start: np.ndarray, T_end: np.ndarray) -> bool:
    """After a schedule step's first chunk, from T_start to T_end [K]: the kinematics
    re-solved at T_end where the viscosity rule asks (:func:`kinematics_with_secant`), each
    re-solved bearing's secant updated with the chord between the step's first solve and
    this one. True where a state was re-solved: the caller then repeats the chunk from
    T_start on the states solved at T_end, with the chord secant (K (T - T_end) carries
    the heat back to the first state's at T_start). False (nothing solved) where the chunk
    moved the contact viscosity beyond ``solver.chunk_viscosity_limit`` (it is repeated
    shorter instead) or out of the viscosity law's range.

    Why: a step's first held state has no secant (K = 0: a new operating point, no two
    solves yet), so over the first chunk its heat is that of the oil at the step's start.
    On an NU 214 rig (ISO VG 32 jet 2 L/min at 40 degC; 2000 -> 3000 -> 4000 r/min,
    4 -> 6 -> 8 kN; default solver: 90-s chunks, tolerance 0.03) the first chunks moved the
    contact viscosity by 15-18 %, under the 25 % chunk limit, and the rollers ended them
    1.18 K (3000 r/min) and 1.21 K (4000 r/min) warmer than a run with 5-s chunks and a
    0.003 tolerance, then dropped 0.7 K at the re-solve; repeated on the chord, the rollers
    stay within 0.22 K of that run over the protocol (housing 0.23 -> 0.065 K). The
    re-solve is the one the next chunk's start made anyway: the cost is one chunk
    integration and one linearisation per step."""
    if not coupler.viscosity_drift(T_end, T_start) <= coupler.sim.scene.solver \
            .chunk_viscosity_limit:
        return False
    held = [b.last for b in coupler.sim.bearings]
    kinematics_with_secant(coupler, secant, step_index, step, T_end, first=False)
    return any(b.last is not old for b, old in zip(coupler.sim.bearings, held, strict=True))


def _run_transient(sim: Simulation, net: Any, writer: ResultsWriter | None
                   ) -> tuple[dict[str, pd.DataFrame], dict[str, Any]]:
    from tqdm.auto import tqdm

    from .network import TransientStepper
    from .network.audit import EnergyAudit, roundoff_floor
    from .simulation import kinematics_columns, step_columns

    scene = sim.scene
    solver = scene.solver
    coupler = Coupler(sim, net)
    names = coupler.names
    T = np.full(len(names), scene.environment.initial_temperature)
    stepper = TransientStepper(net, method=solver.stepper, rtol=solver.rtol, atol=solver.atol,
                               max_step=solver.max_step)
    chunk = solver.chunk
    secant = new_secant(coupler)
    interval = scene.outputs.interval
    # the loss table (one more evaluation of every source per step) only when it is output
    want_losses = _wants_loss_table(scene)
    t = 0.0
    temp_rows = [_temperature_row(t, names, T)]
    if writer:
        writer.append("temperatures", temp_rows)
    kin_rows: list[dict[str, Any]] = []
    loss_rows: list[dict[str, Any]] = []
    detail_rows: dict[str, list[dict[str, Any]]] = {}
    energy_rows: list[dict[str, Any]] = []
    audits: list[EnergyAudit] = []
    cum = dict.fromkeys(("generated", "stored", "to_boundaries", "to_streams"), 0.0)
    relinearizations = 0
    rejected_chunks = 0
    chord_chunks = 0
    fallback_used = False
    method = solver.stepper
    lin: _Linear | None = None
    probed = False
    last_kin: tuple[int, ...] = ()
    steps = scene.schedule.steps
    bar = tqdm(total=scene.schedule.duration, disable=not sim.progress, desc="protocol",
               unit="s", bar_format="{l_bar}{bar}| {n:.0f}/{total:.0f} s [{elapsed}]")
    try:
        for i, step in enumerate(steps):
            n_chunks = max(1, math.ceil(step.duration / chunk - 1e-9))
            h_nominal = step.duration / n_chunks
            t_end = t + step.duration
            h_try = h_nominal
            k = 0
            retry = False
            chorded = False
            while t_end - t > 1e-9 * h_nominal:
                # the last chunk of the step ends on the step's end (no sliver left)
                h = h_try if t_end - t - h_try > 1e-6 * h_nominal else t_end - t
                if not retry:
                    # a new operating point restarts the secant (probed if its first
                    # chunk is repeated shorter, below)
                    if kinematics_with_secant(coupler, secant, i, step, T, first=k == 0):
                        probed = False
                    if k == 0:
                        for b in sim.bearings:
                            row = {**step_columns(i, t, b.name, step, b),
                                   **kinematics_columns(b.last, b.bearing)}
                            kin_rows.append(row)
                            if writer:
                                writer.append("kinematics", [row])
                    kin_id = tuple(id(b.last) for b in sim.bearings)
                    if lin is None or k == 0 or kin_id != last_kin:
                        lin = coupler.linearize(step, T)
                        relinearizations += 1
                    else:
                        # same kinematic state: fresh heat at T, the last model's Jacobian
                        # and curvature re-centred at T (they change only slowly)
                        lin = lin.moved(coupler.heat(step, T), T)
                    last_kin = kin_id
                    lin = lin.with_kinematics(*secant.terms())
                retry = False
                samples = _sample_times(t, h, interval)
                try:
                    try:
                        out = stepper.advance(t, T, h, lin.heat, heat_time_dependent=False,
                                              heat_with_jacobian=lin.heat_and_jac,
                                              sample_times=samples)
                    except ConvergenceError as exc:
                        if solver.stepper != "exprb43" or fallback_used \
                                or _stepper_state_above(exc, coupler.runaway_limit) is not None:
                            raise
                        # the exponential method refuses near-defective Jacobians (e.g.
                        # equal nodes on an oil stream without conduction): go on with
                        # TR-BDF2
                        fallback_used = True
                        sim.warnings.append(
                            f"stepper exprb43 failed at t = {t:.0f} s ({exc}); the run "
                            "continues with tr_bdf2 (set [solver] stepper = \"tr_bdf2\" to "
                            "use it throughout)")
                        method = "tr_bdf2"
                        stepper = TransientStepper(net, method=method, rtol=solver.rtol,
                                                   atol=solver.atol, max_step=solver.max_step)
                        out = stepper.advance(t, T, h, lin.heat, heat_time_dependent=False,
                                              heat_with_jacobian=lin.heat_and_jac,
                                              sample_times=samples)
                except ConvergenceError as exc:
                    # a runaway inside the chunk: the stepper stopped with the network far
                    # beyond the runaway limit (conductances or the oil's laws out of their
                    # range at 1e4-1e6 K)
                    failed = _stepper_state_above(exc, coupler.runaway_limit)
                    if failed is None:
                        raise
                    if h > MIN_CHUNK * (1.0 + 1e-9) and coupler.viscosity_drift(
                            failed[1], T) > solver.chunk_viscosity_limit:
                        # the held kinematic state's heat is what ran away: shorter chunks
                        # first, as for a chunk that ends too far from it
                        h_try = max(0.5 * h, MIN_CHUNK)
                        rejected_chunks += 1
                        retry = True
                        if k == 0 and not probed:
                            probed = True
                            lin = _probed(coupler, secant, lin, step, T)
                        continue
                    _stop_runaway(net, method, solver, lin, t, T, failed, names, i,
                                  coupler.runaway_limit)
                    raise
                drift = coupler.viscosity_drift(out.temperatures, T)
                if drift > solver.chunk_viscosity_limit and h > MIN_CHUNK * (1.0 + 1e-9) \
                        and np.all(np.isfinite(out.temperatures)):
                    # the temperatures left the held kinematic state's viscosity by more
                    # than the limit within the chunk: repeat it shorter (the kinematics
                    # are re-solved at the new chunk ends as the tolerance asks)
                    h_try = max(0.5 * h, MIN_CHUNK)
                    rejected_chunks += 1
                    retry = True
                    if k == 0 and not probed:
                        # the step's first held state goes stale within its first chunk:
                        # its temperature dependence probed for the repeat and the chunks
                        # up to the next solve (coupled_secant, KinematicSecant.restart)
                        probed = True
                        lin = _probed(coupler, secant, lin, step, T)
                    continue
                # a runaway within the chunk stops the run where it crossed the limit
                # (the sampled rows beyond it are not written)
                ends = [*(() if out.samples is None else out.samples), out.temperatures]
                if any(not float(np.max(e)) <= coupler.runaway_limit for e in ends):
                    _stop_runaway(net, method, solver, lin, t, T,
                                  (out.time, out.temperatures), names, i,
                                  coupler.runaway_limit)
                if not math.isfinite(drift):
                    j = int(np.argmax(np.abs(out.temperatures - T)))
                    raise ConvergenceError(
                        "coupled transient", float(abs(out.temperatures[j] - T[j])),
                        f"a coupling chunk of the {MIN_CHUNK:g} s minimum at t = {t:.1f} s "
                        f"(step {i}) moves node {names[j]!r} from {T[j] - 273.15:.1f} to "
                        f"{out.temperatures[j] - 273.15:.1f} degC, out of the viscosity "
                        "law's range (residual: that change [K]); the heat changes too fast "
                        "with temperature for the chunk model", {"time": t, "step": i})
                if (k == 0 and not chorded and np.all(np.isfinite(out.temperatures))
                        and chord_first_chunk(coupler, secant, i, step, T,
                                              out.temperatures)):
                    # the step's first held state went stale within its first chunk (its
                    # kinematics are re-solved at the chunk end): the chunk is repeated on
                    # the state solved there with the secant of the two solves (its chord)
                    chorded = True
                    chord_chunks += 1
                    lin = coupler.linearize(step, T).with_kinematics(*secant.terms())
                    relinearizations += 1
                    last_kin = tuple(id(b.last) for b in sim.bearings)
                    h_try = h
                    retry = True
                    continue
                if drift > solver.chunk_viscosity_limit:
                    note = (f"coupling chunks at their {MIN_CHUNK:g} s minimum still change "
                            "the contact viscosity by more than "
                            f"{solver.chunk_viscosity_limit:.0%} (step {i}, t = {t:.1f} s: "
                            f"{drift:.0%}); the kinematic state lags the temperatures there")
                    if not any(w.startswith("coupling chunks at their") for w in sim.warnings):
                        sim.warnings.append(note)
                k += 1
                if h_try < h_nominal:
                    h_try = min(h_nominal, 2.0 * h_try)
                audits.append(out.audit)
                if out.samples is not None:
                    rows_in = [_temperature_row(ts, names, Ts)
                               for ts, Ts in zip(samples, out.samples, strict=True)]
                    temp_rows.extend(rows_in)
                    if writer:
                        writer.append("temperatures", rows_in)
                T, t = out.temperatures, out.time
                if not np.all(np.isfinite(T)):
                    raise ConvergenceError("coupled transient", math.inf,
                                           "non-finite temperature", {"time": t, "step": i})
                row = _temperature_row(t, names, T)
                temp_rows.append(row)
                a = out.audit
                for key in cum:
                    cum[key] += float(np.sum(getattr(a, key)))
                e_row = {"time [s]": t, "generated [J]": cum["generated"],
                         "stored [J]": cum["stored"], "to ambient [J]": cum["to_boundaries"],
                         "to oil [J]": cum["to_streams"],
                         "imbalance [J]": cum["generated"] - cum["stored"]
                         - cum["to_boundaries"] - cum["to_streams"]}
                energy_rows.append(e_row)
                if writer:
                    writer.append("temperatures", [row])
                    writer.append("energy", [e_row])
                bar.update(h)
            if want_losses:
                extra: dict[str, list[dict[str, Any]]] = {}
                rows = coupler.loss_rows(i, t, step, T, extra)
                loss_rows.extend(rows)
                if writer:
                    writer.append("losses", rows)
                _add_detail_rows(detail_rows, extra, writer)
            sim.log_step(i, t)
    finally:
        bar.close()
    # the floor: a run with no heat from equilibrium has round-off flows only
    caps = np.array([net.capacity(name) for name in net.state_nodes])
    audit = replace(EnergyAudit.concatenate(audits), floor=roundoff_floor(caps, solver.atol))
    stats = {"steps": len(steps), "linearizations": relinearizations,
             "rejected_chunks": rejected_chunks, "chord_chunks": chord_chunks,
             "kinematic_probes": coupler.kinematic_probes,
             "heat_evaluations": coupler.bearing_evaluations // max(1, len(sim.bearings)),
             "relative_energy_imbalance": audit.relative_imbalance(),
             **{f"stepper_{k}": v for k, v in stepper.stats.items()}}
    tables = {"temperatures": pd.DataFrame(temp_rows), "kinematics": pd.DataFrame(kin_rows),
              "energy": pd.DataFrame(energy_rows)}
    if want_losses:
        tables["losses"] = pd.DataFrame(loss_rows)
    tables.update({name: pd.DataFrame(r) for name, r in detail_rows.items()})
    return tables, stats


def _add_detail_rows(tables: dict[str, list[dict[str, Any]]],
                     rows: Mapping[str, list[dict[str, Any]]], writer: Any) -> None:
    """The detail tables' ``rows`` (table -> rows, :meth:`Coupler.loss_rows`) added to
    ``tables`` and appended to the writer's CSV files (if any) as they come."""
    for name, extra in rows.items():
        tables.setdefault(name, []).extend(extra)
        if writer:
            writer.append(name, extra)


#: half-width [K] of the trust region of a steady pass whose chunk model has no steady
#: state (:class:`_HeldBeyond`)
STEADY_TRUST_REGION = 10.0
#: largest node temperature change [K] of one outer pass of a steady run
STEADY_MAX_PASS_CHANGE = 100.0
#: outer passes (kinematics updates) of one steady operating point
STEADY_MAX_PASSES = 30
#: a steady operating point is converged when no node moves by more than this [K] in a pass
STEADY_TOLERANCE = 1e-3
#: halvings of an outer update whose state a model refuses, per operating point
STEADY_MAX_BACKTRACKS = 8
#: pseudo-time spans [s] of the relaxation of a steady pass (:func:`_steady_pass`): 10 s,
#: then each twice the last, 31 spans (to ~1e10 s, beyond any bearing network's time
#: constant); the state is checked against the runaway limit after each
STEADY_RELAX_SPANS = tuple(10.0 * 2.0 ** k for k in range(31))


@dataclass
class _HeldBeyond:
    """The chunk model's heat with each node temperature held within ``reach`` [K] of the
    linearisation point: q(clip(T, T0 - reach, T0 + reach)), bounded, so the network has a
    steady state whatever the model's slope (its Jacobian is zero on the held columns)."""

    lin: _Linear
    reach: float

    def _clip(self, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        lo, hi = self.lin.T0 - self.reach, self.lin.T0 + self.reach
        return np.clip(T, lo, hi), (T < lo) | (T > hi)

    def heat(self, t: float, T: np.ndarray) -> np.ndarray:
        return self.lin.heat(t, self._clip(T)[0])

    def jac(self, t: float, T: np.ndarray) -> np.ndarray:
        return self.heat_and_jac(t, T)[1]

    def heat_and_jac(self, t: float, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(q [W], dq/dT [W/K]) at T [K] (the transient stepper's heat_with_jacobian)."""
        Tc, held = self._clip(T)
        q, jac = self.lin.heat_and_jac(t, Tc)
        out = np.array(jac, dtype=float, copy=True)
        out[:, held] = 0.0
        return q, out


def coldest_boundary(net: Any) -> float:
    """The lowest boundary temperature [K] of the network (ambient, oil inlet): no steady
    state of a network whose heat is a loss (>= 0) has a node below it (the discrete
    maximum principle: conductances and stream capacity rates are >= 0)."""
    return min(float(net.boundary_temperature(n)) for n in net.boundary_nodes)


def _steady_pass(net: Any, lin: _Linear, T: np.ndarray, floor: float | None,
                 ceiling: float) -> tuple[np.ndarray, Any, str]:
    """Where one outer pass of a steady run goes under its chunk model ``lin``
    (kinematics held at ``T`` [K]): (temperatures [K], the network's SteadyResult or None,
    how), how one of ``"model"``, ``"held"``, ``"relaxed"`` (a steady state of the model)
    or ``"runaway"`` (no steady state below ``ceiling`` [K]: the relaxation's first state
    above it, which the caller's step limit and runaway check handle).

    1. Newton on the chunk model (``network.solve_steady`` from ``T``).
    2. Far from T0 the chunk model's straight-line heat can fall to its floor (a cold
       start: the losses fall steeply as the oil thins) and leave the network without a
       steady state, or Newton's steps probe states no model accepts: the heat held at its
       value on the edge of a trust region of :data:`STEADY_TRUST_REGION` around T0
       (:class:`_HeldBeyond`) always has one, and Newton is tried on it.
    3. Newton on the held model can still step out of the conductance models' range: the
       QJ1044 rig at 4500 r/min, 151 kN axial, on oil-air at 33 L/min from -16 degC puts
       82 kW of outer-ring heat into each housing node, falling by 9.3 kW per kelvin of
       oil; the first Newton step put the housings at -570 degC and the line search
       stopped at -330 degC with the air film refusing 35 K. The held model's transient
       (``TransientStepper``, TR-BDF2) from ``T`` over pseudo-time spans of 10 s, 20 s,
       40 s, ... (:data:`STEADY_RELAX_SPANS`) only visits states between the coldest
       boundary and the held heat's equilibrium; Newton from each span's end polishes the
       steady state (0.02 s CPU in that case).

    A steady state with a node below ``floor`` [K] (the coldest boundary; None where the
    model's heat can be negative) is not taken. ConvergenceError when no way gives a
    state, naming the residual and the pass's start."""
    from .network import TransientStepper, solve_steady

    def physical(res: Any) -> bool:
        v = res.temperatures_vector
        return bool(np.all(np.isfinite(v))) and (floor is None or float(v.min())
                                                 >= floor - 1e-6 * max(1.0, floor))

    why = []
    try:
        res = solve_steady(net, lin.heat, T_guess=T, heat_jacobian=lin.jac)
        if physical(res):
            return res.temperatures_vector, res, "model"
        why.append("the chunk model's steady state lies below the coldest boundary")
    except ConvergenceError as exc:
        why.append(f"chunk model: {exc}")
    held = _HeldBeyond(lin, STEADY_TRUST_REGION)
    try:
        res = solve_steady(net, held.heat, T_guess=T, heat_jacobian=held.jac)
        if physical(res):
            return res.temperatures_vector, res, "held"
        why.append("the held model's steady state lies below the coldest boundary")
    except ConvergenceError as exc:
        why.append(f"held model: {exc}")
    stepper = TransientStepper(net, method="tr_bdf2", rtol=1e-3, atol=1e-2)
    y, t, residual = T.copy(), 0.0, math.inf
    for span in STEADY_RELAX_SPANS:
        try:
            out = stepper.advance(t, y, span, held.heat, heat_time_dependent=False,
                                  heat_with_jacobian=held.heat_and_jac)
        except (ConvergenceError, InputError) as exc:
            why.append(f"relaxation after {t:.3g} s: {exc}")
            break
        y, t = out.temperatures, t + span
        if not np.all(np.isfinite(y)):
            why.append(f"relaxation after {t:.3g} s: non-finite temperatures")
            break
        if float(np.max(y)) > ceiling:
            return y, None, "runaway"
        try:
            res = solve_steady(net, held.heat, T_guess=y, heat_jacobian=held.jac)
        except ConvergenceError as exc:
            residual = min(residual, float(exc.residual))
            continue
        if physical(res):
            return res.temperatures_vector, res, "relaxed"
    raise ConvergenceError(
        "coupled steady state", residual,
        "no steady state of the network under the pass's heat model (residual: the "
        "smallest network residual [W] reached; " + "; ".join(why) + ")",
        {"pass start [degC]": np.round(T - 273.15, 3)})


def _temperatures_state(names: list[str], T: np.ndarray) -> dict[str, float]:
    """Node -> temperature [degC] (rounded to 1 mK) for a ConvergenceError's state."""
    return {n: round(float(v) - 273.15, 3) for n, v in zip(names, T, strict=True)}


def _run_steady(sim: Simulation, net: Any, writer: ResultsWriter | None
                ) -> tuple[dict[str, pd.DataFrame], dict[str, Any]]:
    """Each schedule step as its own steady operating point (coupled fixed point).

    Outer passes: kinematics and the chunk model at the current temperatures T, the
    network's steady state under that model (:func:`_steady_pass`; a Newton step of the
    coupled problem, whose fixed point T = T_new is the same whatever the model's reach),
    then a relaxed update towards it. Every accepted state lies between the coldest
    boundary and the runaway limit: a pass's steady state is refused below the coldest
    boundary, and the update is a convex combination of two such states. A state a model
    refuses (the kinematics or the heat sources raise InputError or ConvergenceError there:
    a viscosity law's range, a stalled skidding solve) is backtracked: the update is halved
    towards the last state the models accepted, at most :data:`STEADY_MAX_BACKTRACKS` times
    per operating point; each backtrack is noted in the run's warnings."""
    from .simulation import kinematics_columns, step_columns
    from .simulation_tables import operating_columns

    coupler = Coupler(sim, net)
    names = coupler.names
    T = np.full(len(names), sim.scene.environment.initial_temperature)
    temp_rows, kin_rows, loss_rows = [], [], []
    detail_rows: dict[str, list[dict[str, Any]]] = {}
    outer_iterations = 0
    backtracks = 0
    passes_by = dict.fromkeys(("model", "held", "relaxed", "runaway"), 0)
    imbalance = 0.0
    floor_T = coldest_boundary(net)
    for i, step in enumerate(sim.scene.schedule.steps):
        omega, r_prev = 1.0, None
        T_ok: np.ndarray | None = None  # the last state whose models answered
        change, step_backtracks = math.inf, 0
        # the validity warnings of the iterates are held back: the step reports its
        # steady state's (sim.record_state_warnings below)
        with sim.held_warnings():
            for _ in range(STEADY_MAX_PASSES):
                try:
                    coupler.kinematics(i, step, T)
                    lin = coupler.linearize(step, T)
                except (InputError, ConvergenceError) as exc:
                    if T_ok is None:
                        raise  # the operating point's start itself: the model's own error
                    if step_backtracks >= STEADY_MAX_BACKTRACKS:
                        raise ConvergenceError(
                            "coupled steady state", change,
                            f"the models refuse the updates of step {i} even after "
                            f"{step_backtracks} halvings towards the last accepted state "
                            f"(residual: that state's largest pass change [K]); last refusal: "
                            f"{exc}", {"step": i, "refused [degC]": _temperatures_state(names, T),
                                       "accepted [degC]": _temperatures_state(names, T_ok)}
                        ) from exc
                    step_backtracks += 1
                    backtracks += 1
                    note = (f"steady step {i}: a model refused an update of the temperatures "
                            f"({exc}); the update was halved towards the last accepted state")
                    if not any(w.startswith(f"steady step {i}: a model refused")
                               for w in sim.warnings):
                        sim.warnings.append(note)
                    T = T_ok + 0.5 * (T - T_ok)
                    r_prev = None
                    continue
                T_ok = T.copy()
                # a cold start may still be below the boundaries: the floor holds for the
                # pass's steady state only where the model's heat is a loss
                floor = floor_T if float(np.min(lin.q0)) >= 0.0 else None
                T_new, res, how = _steady_pass(net, lin, T, floor, coupler.runaway_limit)
                passes_by[how] += 1
                r = T_new - T
                change = float(np.max(np.abs(r)))
                outer_iterations += 1
                if change < STEADY_TOLERANCE and res is not None:
                    T = T_new
                    _check_runaway(names, T, None, i, lin, coupler.runaway_limit)
                    if res.generated > 0.0:
                        imbalance = max(imbalance, abs(res.generated - res.to_boundaries
                                                       - res.to_streams) / res.generated)
                    break
                # Aitken's dynamic relaxation of the outer update (Irons & Tuck): the pass
                # holds the kinematics, whose heat falls as the oil thins, so the plain
                # update overshoots and oscillates (NU 214 at 10000 r/min from 39 degC: 745,
                # 97, 312, 126 ... degC, 20 passes); the relaxation factor from the last two
                # updates damps it, capped to (0.1, 1], and no pass moves a node by more than
                # STEADY_MAX_PASS_CHANGE
                if r_prev is not None:
                    dr = r - r_prev
                    den = float(dr @ dr)
                    if den > 0.0:
                        omega = min(max(-omega * float(r_prev @ dr) / den, 0.1), 1.0)
                r_prev = r
                step_T = omega * r
                big = float(np.max(np.abs(step_T)))
                T = T + (step_T * (STEADY_MAX_PASS_CHANGE / big) if big > STEADY_MAX_PASS_CHANGE
                         else step_T)
                _check_runaway(names, T, None, i, lin, coupler.runaway_limit)
            else:
                j = int(np.argmax(np.abs(T - T_ok))) if T_ok is not None else 0
                raise ConvergenceError(
                    "coupled steady state", change,
                    f"temperatures still move after {STEADY_MAX_PASSES} kinematics updates "
                    f"(residual: the last pass's largest change [K], node {names[j]!r}; "
                    f"converged below {STEADY_TOLERANCE:g} K)",
                    {"step": i, "temperatures [degC]": _temperatures_state(names, T)})
        for b in sim.bearings:
            # the step's validity warnings are its steady state's: its kinematic solve's
            # and its heat sources' at the converged temperatures
            sim.record_state_warnings(b, i, step, coupler.role_temperatures(b, T))
            kin_rows.append({**step_columns(i, None, b.name, step, b),
                             **kinematics_columns(b.last, b.bearing)})
            # the step's checks are its steady state's: the passes before it were iterates
            # of the fixed point, not states the bearing runs in (a QJ1044 at 1800 r/min,
            # 5 kN: the skid warning took an iterate's CSR)
            sim.checks[b.name].steps[i] = [check_state(b.bearing, b.last, sim.check_limits)]
        # a steady state has no time: step, its operating point and the node temperatures
        row = {"step": i, **operating_columns(step), **_temperature_row(None, names, T)}
        temp_rows.append(row)
        extra: dict[str, list[dict[str, Any]]] = {}
        rows = (coupler.loss_rows(i, None, step, T, extra) if _wants_loss_table(sim.scene)
                else [])
        loss_rows.extend(rows)
        if writer:
            writer.append("steady_temperatures", [row])
            writer.append("kinematics", kin_rows[-len(sim.bearings):])
            if rows:
                writer.append("losses", rows)
        _add_detail_rows(detail_rows, extra, writer)
        sim.log_step(i)
    tables = {"steady_temperatures": pd.DataFrame(temp_rows),
              "kinematics": pd.DataFrame(kin_rows)}
    if _wants_loss_table(sim.scene):
        tables["losses"] = pd.DataFrame(loss_rows)
    tables.update({name: pd.DataFrame(r) for name, r in detail_rows.items()})
    return tables, {"steps": len(sim.scene.schedule.steps),
                    "outer_iterations": outer_iterations, "backtracks": backtracks,
                    "held_passes": passes_by["held"], "relaxed_passes": passes_by["relaxed"],
                    "relative_energy_imbalance": imbalance}


def role_map(net: Any, group: str) -> Mapping[str, list[str]]:
    """Role -> nodes of one bearing (for reports)."""
    return net.roles(group)
