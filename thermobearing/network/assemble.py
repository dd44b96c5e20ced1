"""Assembly: a :class:`~.graph.ThermalNetwork` -> capacity vector and conductance operator.

For the state temperatures T (boundary nodes condensed out) the network's energy balance is

    C dT/dt = f(t, T) = -K T + s + q(t, T)

- ``C`` [J/K]: capacities (0 for algebraic nodes);
- ``K`` [W/K]: the weighted graph Laplacian restricted to the state nodes, plus each
  boundary conductance on the diagonal, plus the streams' upwind terms (row of node k gets
  +W on its diagonal and -W on its upstream node: non-symmetric);
- ``s`` [W]: boundary conductances times boundary temperatures plus W T_inlet of each
  stream into its first node;
- ``q`` [W]: heat sources.

Energy flows for the audit: heat to the boundaries sum G_ib (T_i - T_b) and heat carried
away by each stream W (T_last - T_inlet); their sum equals -sum_i(-K T + s)_i exactly.

Dense ``K`` is used up to :data:`DENSE_LIMIT` state nodes (small dense LU beats sparse LU
there: measured in ``benchmarks/bm1_work_precision.py``), CSC sparse above.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.sparse as sp

from ..errors import InputError
from .graph import ThermalNetwork

#: state-node count up to which the operator is dense
DENSE_LIMIT = 120


@dataclass
class System:
    """Assembled linear part of the network at one set of conductances.

    Attributes
    ----------
    names : state node names (order of every vector).
    C : capacities [J/K], shape (n,).
    K : conductance operator [W/K], (n, n) ndarray or scipy CSC matrix.
    s : boundary source [W], (n,).
    dense : whether K is dense.
    bnd_index, bnd_G, bnd_T : conductive edges to boundaries: state index, G [W/K], T_b [K].
    str_first, str_last, str_W, str_Tin : streams: first and last state index, W [W/K],
        inlet temperature [K].
    var_g : conductances [W/K] of the assembler's temperature-dependent edges at this
        system's temperatures, in the assembler's order (dense systems; None otherwise):
        :meth:`Assembler.drift` works from them.
    """

    names: tuple[str, ...]
    C: np.ndarray
    K: np.ndarray | sp.csc_matrix
    s: np.ndarray
    dense: bool
    bnd_index: np.ndarray
    bnd_G: np.ndarray
    bnd_T: np.ndarray
    str_last: np.ndarray
    str_W: np.ndarray
    str_Tin: np.ndarray
    var_g: np.ndarray | None = None

    @property
    def n(self) -> int:
        return len(self.names)

    def flux(self, T: np.ndarray) -> np.ndarray:
        """-K T + s [W] (the network part of f)."""
        return self.s - self.K @ T

    def to_boundaries(self, T: np.ndarray) -> float:
        """Heat rate [W] conducted into all boundary nodes at state temperatures T."""
        return float(self.bnd_G @ (T[self.bnd_index] - self.bnd_T))

    def to_streams(self, T: np.ndarray) -> float:
        """Heat rate [W] carried away by all streams, sum W (T_last - T_inlet)."""
        return float(self.str_W @ (T[self.str_last] - self.str_Tin))


class Assembler:
    """Builds :class:`System` for a network; constant edges are assembled once.

    Temperature-dependent edges are re-evaluated by :meth:`system` at the temperatures
    given. The steppers assemble K_n = K(y_n) once per step for their linear part (Newton
    matrix, exponential) and add the conductances' change within the step,
    :meth:`drift`, to the heat at every stage value, so the step integrates the exact
    right-hand side s(T) - K(T) T + q(T).
    """

    def __init__(self, network: ThermalNetwork) -> None:
        network.validate()
        self.network = network
        self.revision = network._revision
        names = network.state_nodes
        self.names = names
        self.index = {n: i for i, n in enumerate(names)}
        n = len(names)
        self.n = n
        self.dense = n <= DENSE_LIMIT
        self.dense_limit = DENSE_LIMIT
        self.C = np.array([network.capacity(x) for x in names])
        const_rows: list[int] = []
        const_cols: list[int] = []
        const_vals: list[float] = []
        s = np.zeros(n)
        bnd_i: list[int] = []
        bnd_g: list[float] = []
        bnd_t: list[float] = []
        self.variable: list[tuple[str, str, int, object]] = []
        for a, b, key, model in network.edges():
            if model.temperature_dependent:
                self.variable.append((a, b, key, model))
                continue
            g = network.edge_conductance(a, b, key, 300.0, 300.0)
            self._stamp(a, b, g, const_rows, const_cols, const_vals, s, bnd_i, bnd_g, bnd_t)
        str_last: list[int] = []
        str_w: list[float] = []
        str_tin: list[float] = []
        for st in network.streams.values():
            w = st.capacity_rate
            t_in = network.boundary_temperature(st.path[0])
            first = self.index[st.path[1]]
            s[first] += w * t_in
            prev = first
            const_rows.append(first)
            const_cols.append(first)
            const_vals.append(w)
            for node in st.path[2:]:
                i = self.index[node]
                const_rows += [i, i]
                const_cols += [i, prev]
                const_vals += [w, -w]
                prev = i
            str_last.append(prev)
            str_w.append(w)
            str_tin.append(t_in)
        if self.dense:  # small: stamp directly (scipy's COO -> CSC -> dense costs ~0.2 ms)
            K0 = np.zeros((n, n))
            np.add.at(K0, (np.array(const_rows, dtype=np.intp),
                           np.array(const_cols, dtype=np.intp)), np.array(const_vals, float))
            self.K0 = K0
        else:
            self.K0 = sp.coo_matrix((const_vals, (const_rows, const_cols)),
                                    shape=(n, n)).tocsc()
        self.s0 = s
        self.bnd0 = (bnd_i, bnd_g, bnd_t)
        self._bnd0_arrays = (np.array(bnd_i, dtype=int), np.array(bnd_g, dtype=float),
                             np.array(bnd_t, dtype=float))
        # the temperature-dependent edges, resolved once per revision (a boundary
        # temperature change bumps the revision): (state index of a or -1, of b or -1,
        # fixed temperature of a boundary end, model, edge name for errors)
        self._var_edges: list[tuple[int, int, float, object, str]] = []
        for a, b, _key, model in self.variable:
            ia, ib = self.index.get(a, -1), self.index.get(b, -1)
            t_fixed = (network.boundary_temperature(a) if ia < 0 else
                       network.boundary_temperature(b) if ib < 0 else math.nan)
            self._var_edges.append((ia, ib, t_fixed, model, f"edge {a!r}-{b!r}: conductance"))
        self.str_last = np.array(str_last, dtype=int)
        self.str_W = np.array(str_w)
        self.str_Tin = np.array(str_tin)
        self._constant_system: System | None = None

    def _stamp(self, a, b, g, rows, cols, vals, s, bnd_i, bnd_g, bnd_t) -> None:
        net = self.network
        ka = net.graph.nodes[a]["kind"]
        kb = net.graph.nodes[b]["kind"]
        if ka == "state" and kb == "state":
            i, j = self.index[a], self.index[b]
            rows += [i, j, i, j]
            cols += [i, j, j, i]
            vals += [g, g, -g, -g]
        elif ka == "state" or kb == "state":
            inside, outside = (a, b) if ka == "state" else (b, a)
            i = self.index[inside]
            tb = net.boundary_temperature(outside)
            rows.append(i)
            cols.append(i)
            vals.append(g)
            s[i] += g * tb
            bnd_i.append(i)
            bnd_g.append(g)
            bnd_t.append(tb)
        # an edge between two boundaries carries heat between fixed temperatures only: it
        # does not touch the state equations and is left out of the audit.

    @property
    def temperature_dependent(self) -> bool:
        return bool(self.variable)

    def system(self, T: np.ndarray | None = None) -> System:
        """The assembled system; temperature-dependent edges evaluated at state T [K]."""
        if not self.variable and self._constant_system is not None:
            return self._constant_system
        if self.variable and T is None:
            T = np.full(self.n, 300.0)
        s = self.s0.copy()
        if self.dense:
            # small networks: stamp each temperature-dependent edge into a copy of K0
            # (scalar indexing; no list building, no sparse detour)
            K = self.K0.copy()
            extra_i, extra_g, extra_t = [], [], []
            var_g = np.empty(len(self._var_edges))
            for k, (ia, ib, t_fixed, model, what) in enumerate(self._var_edges):
                Ta = float(T[ia]) if ia >= 0 else t_fixed
                Tb = float(T[ib]) if ib >= 0 else t_fixed
                g = float(model.conductance(Ta, Tb))
                if not math.isfinite(g) or g < 0.0:
                    raise InputError(what, g, "a finite value >= 0 W/K from the conductance "
                                     "model")
                var_g[k] = g
                if ia >= 0 and ib >= 0:
                    K[ia, ia] += g
                    K[ib, ib] += g
                    K[ia, ib] -= g
                    K[ib, ia] -= g
                elif ia >= 0 or ib >= 0:
                    i = ia if ia >= 0 else ib
                    K[i, i] += g
                    s[i] += g * t_fixed
                    extra_i.append(i)
                    extra_g.append(g)
                    extra_t.append(t_fixed)
            b_i, b_g, b_t = self._bnd0_arrays
            if extra_i:
                b_i = np.concatenate((b_i, np.array(extra_i, dtype=int)))
                b_g = np.concatenate((b_g, extra_g))
                b_t = np.concatenate((b_t, extra_t))
            system = System(names=self.names, C=self.C, K=K, s=s, dense=True, bnd_index=b_i,
                            bnd_G=b_g, bnd_T=b_t, str_last=self.str_last, str_W=self.str_W,
                            str_Tin=self.str_Tin, var_g=var_g)
            if not self.variable:
                self._constant_system = system
            return system
        rows: list[int] = []
        cols: list[int] = []
        vals: list[float] = []
        bnd_i, bnd_g, bnd_t = (list(x) for x in self.bnd0)
        net = self.network
        for a, b, key, _model in self.variable:
            Ta = self._temp(a, T)
            Tb = self._temp(b, T)
            g = net.edge_conductance(a, b, key, Ta, Tb)
            self._stamp(a, b, g, rows, cols, vals, s, bnd_i, bnd_g, bnd_t)
        K = self.K0
        if rows:
            K = K + sp.coo_matrix((vals, (rows, cols)), shape=(self.n, self.n)).tocsc()
        system = System(
            names=self.names, C=self.C, K=K, s=s, dense=self.dense,
            bnd_index=np.array(bnd_i, dtype=int), bnd_G=np.array(bnd_g),
            bnd_T=np.array(bnd_t), str_last=self.str_last, str_W=self.str_W,
            str_Tin=self.str_Tin,
        )
        if not self.variable:
            self._constant_system = system
        return system

    def drift(self, reference: System, T: np.ndarray) -> tuple[np.ndarray, float]:
        """(d [W], db [W]): the change of the conductance terms at state T [K] from those
        of ``reference`` (the system a step holds, assembled at its start):
        d = (s(T) - K(T) T) - (s_ref - K_ref T) per node, and db = Q_b(T; K(T)) -
        Q_b(T; K_ref), the change of the heat to the boundaries it stands for. sum(d) = -db:
        an edge between two state nodes moves heat between them only, and the streams'
        capacity rates do not depend on temperature. Zero without temperature-dependent
        edges."""
        if not self.variable:
            return np.zeros(self.n), 0.0
        g_ref = reference.var_g
        if g_ref is None or len(g_ref) != len(self._var_edges):
            sys_t = self.system(T)
            d = (sys_t.s - sys_t.K @ T) - (reference.s - reference.K @ T)
            return d, sys_t.to_boundaries(T) - reference.to_boundaries(T)
        # dense systems: only the temperature-dependent edges change; edge k carries
        # (g(T) - g_ref) (Ta - Tb) more from a to b
        d = np.zeros(self.n)
        db = 0.0
        for k, (ia, ib, t_fixed, model, what) in enumerate(self._var_edges):
            Ta = float(T[ia]) if ia >= 0 else t_fixed
            Tb = float(T[ib]) if ib >= 0 else t_fixed
            g = float(model.conductance(Ta, Tb))
            if not math.isfinite(g) or g < 0.0:
                raise InputError(what, g, "a finite value >= 0 W/K from the conductance model")
            flux = (g - g_ref[k]) * (Ta - Tb)
            if ia >= 0:
                d[ia] -= flux
            else:
                db -= flux   # from the boundary a into the network
            if ib >= 0:
                d[ib] += flux
            else:
                db += flux   # from the network into the boundary b
        return d, db

    def drift_jacobian(self, T: np.ndarray, step: float = 1e-3) -> np.ndarray | sp.csr_matrix:
        """D [W/K], (n, n): the part of the Jacobian of s(T) - K(T) T at state T [K] that the
        held K(T) leaves out, the conductances' own temperature derivatives: for an edge
        of conductance g(Ta, Tb) carrying g (Ta - Tb) from a to b, D[a, a] = -g_a dT,
        D[a, b] = -g_b dT, D[b, a] = g_a dT, D[b, b] = g_b dT (dT = Ta - Tb; rows and
        columns of boundary ends left out), g_a, g_b by central differences of the model
        over +-``step`` [K]. The steppers and the steady Newton add it to the Jacobian so
        that their linear part is the exact linearisation; zero without temperature-
        dependent edges. A dense array for a dense system, else a CSR matrix. Column sums
        are the change of the heat to the boundaries per kelvin (an edge between two state
        nodes contributes none)."""
        rows: list[int] = []
        cols: list[int] = []
        vals: list[float] = []
        for ia, ib, t_fixed, model, what in self._var_edges:
            Ta = float(T[ia]) if ia >= 0 else t_fixed
            Tb = float(T[ib]) if ib >= 0 else t_fixed
            dT = Ta - Tb
            ga = gb = 0.0
            if ia >= 0:
                ga = _derivative(lambda x, m=model, b=Tb: m.conductance(x, b), Ta, step)
            if ib >= 0:
                gb = _derivative(lambda x, m=model, a=Ta: m.conductance(a, x), Tb, step)
            if not (math.isfinite(ga) and math.isfinite(gb)):
                raise InputError(what, (ga, gb), "a conductance model with finite "
                                 "temperature derivatives")
            for i, j, v in ((ia, ia, -ga * dT), (ia, ib, -gb * dT), (ib, ib, gb * dT),
                            (ib, ia, ga * dT)):
                if i >= 0 and j >= 0:
                    rows.append(i)
                    cols.append(j)
                    vals.append(v)
        if self.dense:
            D = np.zeros((self.n, self.n))
            np.add.at(D, (np.array(rows, dtype=int), np.array(cols, dtype=int)), vals)
            return D
        return sp.coo_matrix((vals, (rows, cols)), shape=(self.n, self.n)).tocsr()

    def _temp(self, node: str, T: np.ndarray) -> float:
        i = self.index.get(node)
        if i is None:
            return self.network.boundary_temperature(node)
        return float(T[i])


def _derivative(g: Callable[[float], Any], x: float, step: float) -> float:
    """dg/dx by the central difference over +-``step``; at the edge of the model's range
    (an InputError one side, e.g. air at its 2000 K limit) the one-sided difference on the
    side the model accepts."""
    try:
        return (float(g(x + step)) - float(g(x - step))) / (2.0 * step)
    except InputError:
        pass
    g0 = float(g(x))
    try:
        return (float(g(x + step)) - g0) / step
    except InputError:
        return (g0 - float(g(x - step))) / step


def assembler_for(network: ThermalNetwork) -> Assembler:
    """The :class:`Assembler` of ``network`` at its current revision (cached on the network:
    a network that has not changed since the last call is not walked again; any edit bumps
    the revision). The assembled arrays are shared: treat them as read-only."""
    cached = getattr(network, "_assembler_cache", None)
    if (cached is not None and cached.revision == network._revision
            and cached.dense_limit == DENSE_LIMIT):
        return cached
    asm = Assembler(network)
    network._assembler_cache = asm
    return asm


def assemble(network: ThermalNetwork, T: np.ndarray | None = None) -> System:
    """Assemble ``network`` (temperature-dependent edges at state temperatures ``T`` [K]).
    The arrays of a network without temperature-dependent edges are shared between calls
    (:func:`assembler_for`): do not modify them in place."""
    return assembler_for(network).system(T)
