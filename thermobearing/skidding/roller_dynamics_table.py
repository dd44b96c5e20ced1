"""Tabulated raceway traction of paper 000's roller model for the coupled roller dynamics.

The coupled all-roller + cage integration of paper 003 (Zhang et al. 2021, seed
``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], eqs. 18-19;
:mod:`~thermobearing.skidding.roller_dynamics_coupled`) needs, for every roller and every
refresh of its traction linearisation, the raceway shear S (roller moment balance / (D/2)
plus the pocket-film friction), the net orbital force F_d, the outer contact load Q_o and
the outer contact's own shear S_o (since 2026-11-23: each contact's spin slope) of
paper 000's closed-form traction model (Li et al. 2018, seed ``000_3b5ca6eed61dd596.txt``
[li2018_nu214_skidding], eqs. 12-15, 20-38, evaluated by
:func:`thermobearing.skidding.roller_residual.evaluate`). Those are per-roller functions of
three variables only -- the roller spin omega_r, its inner contact load N_i and the cage
speed omega_c (which sets both race speeds, the centrifugal outer load and the unbalance's
orbital force) -- because ``evaluate`` treats the rollers independently (the cage equation
is their sum; no whirl, no clearance film in the model the dynamics builds). So instead of
calling ``evaluate`` (~4 ms of Python per call for 24 rollers, three calls per refresh)
the functions are evaluated once, on a grid, by the *same* ``evaluate`` (stacked into one
call per cage-speed layer, ~12 us per grid point), and interpolated inside the jitted time
loop:

* omega_r: uniform grid (default spacing 50 rad/s), Catmull-Rom cubic (local, C1);
* N_i: nodes N_max (k/n)^2, k = 0 (no inner contact: the unloaded-roller model) ... n + 1
  (one node beyond N_max), Catmull-Rom cubic in u = n sqrt(N_i/N_max) (uniform in u; at
  the first interval the missing node u = -1 is the mirror of u = 1, a function smooth in
  N_i being even in u);
* omega_c: layers at omega_ref (1 + k delta), by default k = -1 ... 3 (delta = 2.5 %: the
  integrated cage runs up to ~5 % faster than the quasi-static one it starts from; the
  caller extends the range if the cage leaves it), Catmull-Rom cubic through four layers
  (defined between the second and the second-to-last layer; reproduces quadratics, so
  exact for the centrifugal part of Q_o). Until 2026-11-22 14:00 UTC this was a quadratic
  through the *nearest* layer and its neighbours, which jumps by up to 0.1 N where the
  nearest layer changes (measured at the base case: 0.098 / 0.111 N in S); a refresh whose
  forward difference (0.14 rad/s) straddled such a point got a cage slope ~10x the real one
  (0.7-0.8 against 0.07-0.08 N s/rad) for a whole refresh interval -- the likely trigger
  of the cage-overspeed excursions of the table path (validation case SOURCE.md).

Outside the grid the interpolation returns a status instead of extrapolating; the caller
rebuilds the table around the new state. The interpolation error against direct
``evaluate`` calls is measured in ``tests/unit/test_roller_dynamics_table.py`` and in the
paper 003 validation case's SOURCE.md. Units: SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numba import njit

from ..errors import InputError, check_positive

_ONE = np.int64(1)   # int64 constant for compiled calls (a literal 1 compiles once more)

#: output columns of the table: raceway shear S = S_i + S_o [N], orbital force F_d [N], outer
#: load Q_o [N], outer-contact shear S_o [N] (its own column so that each contact's slope is
#: known: a pocket speed z' changes the two contacts' sliding in opposite senses,
#: :func:`thermobearing.skidding.roller_dynamics_coupled_kernels.spin_pocket_coupling`)
T_SHEAR, T_POCKET, T_OUTER, T_SHEAR_OUTER = 0, 1, 2, 3
#: number of columns of the table
N_COLUMNS = 4

#: default grid: spin spacing [rad/s], number of loaded N_i nodes, cage-speed layer step [-]
DEFAULT_SPIN_STEP = 50.0
DEFAULT_LOAD_NODES = 16
DEFAULT_CAGE_STEP = 0.025


@dataclass(frozen=True)
class TractionTable:
    """Per-roller raceway functions of paper 000's traction model on a grid (SI).

    spin0, spin_step : first node and spacing of the uniform omega_r grid [rad/s].
    loads : (n + 2,) N_i nodes N_max (k/n)^2 [N] (first 0; the last one beyond N_max, the
    cubic's end node).  cage : (n_c,) omega_c layers [rad/s], equally spaced (n_c >= 3).
    values : (n_c, n_N, n_w, 4) S, F_d, Q_o, S_o [N] (columns ``T_*``).
    evaluations : grid points evaluated for this table (reused layers not counted).
    """

    spin0: float
    spin_step: float
    loads: np.ndarray
    cage: np.ndarray
    values: np.ndarray
    evaluations: int

    @property
    def spin_range(self) -> tuple[float, float]:
        """(lowest, highest) omega_r [rad/s] at which the cubic is defined."""
        n_w = self.values.shape[2]
        return self.spin0 + self.spin_step, self.spin0 + (n_w - 2) * self.spin_step

    def __call__(self, spin: Any, load: Any, cage_speed: float) -> np.ndarray:
        """Interpolated (S, F_d, Q_o, S_o) [N] at arrays ``spin`` [rad/s], ``load`` [N] and
        one ``cage_speed`` [rad/s]: shape (..., 4) (columns ``T_*``). ValueError outside
        the grid."""
        w = np.atleast_1d(np.asarray(spin, float))
        n = np.broadcast_to(np.asarray(load, float), w.shape)
        out = np.empty(w.shape + (N_COLUMNS,))
        for idx in np.ndindex(w.shape):
            s, f, q, so, status = table_eval_contacts(
                self.spin0, self.spin_step, self.loads, self.cage, self.values,
                float(w[idx]), float(n[idx]), float(cage_speed))
            if status:
                raise ValueError(f"outside the traction table (status {status}): spin "
                                 f"{w[idx]}, load {n[idx]}, cage speed {cage_speed}")
            out[idx] = (s, f, q, so)
        return out


def build_traction_table(race_model: Any, inner_speed: float, body_force: Any,
                         spin_range: tuple[float, float], max_load: float,
                         cage_speed: float, *, spin_step: float = DEFAULT_SPIN_STEP,
                         load_nodes: int = DEFAULT_LOAD_NODES,
                         cage_step: float = DEFAULT_CAGE_STEP,
                         cage_layers: tuple[int, int] = (-1, 3),
                         previous: TractionTable | None = None) -> TractionTable:
    """Tabulate S, F_d and Q_o of ``race_model`` (:func:`thermobearing.skidding.roller.
    build_model`) with :func:`thermobearing.skidding.roller_residual.evaluate`.

    inner_speed : omega_i [rad/s].  body_force(omega_c) -> outward body force per roller
    without the centrifugal term [N] (the unbalance's orbital force).
    spin_range : (low, high) omega_r [rad/s] to cover.  max_load : largest N_i [N].
    cage_speed : reference omega_c [rad/s]; layers at cage_speed (1 + cage_step k) for k in
    ``cage_layers`` = (first, last) (default -1 ... 3, at least four layers; the cubic is
    defined from the second to the second-to-last layer).
    spin_step [rad/s], load_nodes, cage_step [-]: the grid (module notes).
    previous : a table of the same model on the same spin and load grid whose cage layers
    are reused where they coincide (only the new layers are evaluated).
    """
    from .roller_residual import evaluate

    if getattr(race_model, "clearance_film", False):
        # the clearance film ties each roller to its own radial gap (per roller index): the
        # per-roller functions would then depend on more than (omega_r, N_i, omega_c)
        raise InputError("race_model.clearance_film", True,
                         "False (the table assumes rollers independent given N_i)")
    check_positive("spin_step", spin_step)
    check_positive("cage_step", cage_step)
    check_positive("cage_speed", cage_speed)
    lo, hi = float(spin_range[0]), float(spin_range[1])
    if not hi > lo:
        raise ValueError(f"empty spin range {spin_range}")
    spin0 = lo - 2.0 * spin_step
    n_w = int(math.ceil((hi - spin0) / spin_step)) + 3
    spins = spin0 + spin_step * np.arange(n_w)
    n_l = max(int(load_nodes), 2)
    loads = max(float(max_load), 1.0) * (np.arange(n_l + 2) / n_l) ** 2
    k_lo, k_hi = int(cage_layers[0]), int(cage_layers[1])
    if k_hi - k_lo < 3 or 1.0 + cage_step * k_lo <= 0.0:
        raise ValueError(f"cage_layers {cage_layers}: at least four layers, all > 0")
    cage = cage_speed * (1.0 + cage_step * np.arange(k_lo, k_hi + 1, dtype=float))
    w_all = np.tile(spins, loads.size)
    n_all = np.repeat(loads, n_w)
    zeros = np.zeros(w_all.size)
    values = np.empty((cage.size, loads.size, n_w, N_COLUMNS))
    reuse = (previous is not None and previous.values.shape[1:] == values.shape[1:]
             and previous.spin0 == spin0 and previous.spin_step == spin_step
             and np.array_equal(previous.loads, loads))
    n_new = 0
    for ic, wc in enumerate(cage):
        if reuse:
            hit = np.nonzero(np.abs(previous.cage - wc) <= 1e-12 * wc)[0]
            if hit.size:
                values[ic] = previous.values[hit[0]]
                continue
        n_new += 1
        body = np.full(w_all.size, float(body_force(float(wc))))
        e = evaluate(race_model, float(inner_speed), w_all, float(wc), n_all, body, zeros,
                     (0.0, 0.0))
        for col, arr in ((T_SHEAR, e.roller_eq + e.friction), (T_POCKET, e.pocket),
                         (T_OUTER, e.q_o), (T_SHEAR_OUTER, e.outer.shear_force)):
            values[ic, :, :, col] = np.asarray(arr, float).reshape(loads.size, n_w)
    if not np.all(np.isfinite(values)):
        raise ValueError("traction model returned non-finite values on the table grid")
    return TractionTable(float(spin0), float(spin_step), loads, cage, values,
                         int(w_all.size * n_new))


@njit(cache=True)
def _cubic(v: np.ndarray, i: int, t: float, col: int) -> float:
    """Catmull-Rom cubic through v[i-1..i+2, col] at fraction t of [i, i+1]."""
    p0 = v[i - 1, col]
    p1 = v[i, col]
    p2 = v[i + 1, col]
    p3 = v[i + 2, col]
    return p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3
                                          + t * (3.0 * (p1 - p2) + p3 - p0)))


@njit(cache=True)
def _spin_cubic(v: np.ndarray, i: int, t: float, out: np.ndarray) -> None:
    """out[:] = Catmull-Rom in the spin of every column of v (n_w, n_col)."""
    for col in range(v.shape[1]):
        out[col] = _cubic(v, i, t, col)


@njit(cache=True)
def table_eval(spin0: float, spin_step: float, loads: np.ndarray, cage: np.ndarray,
               values: np.ndarray, w: float, n: float, wc: float
               ) -> tuple[float, float, float, int]:
    """(S, F_d, Q_o [N], status) interpolated at spin ``w`` [rad/s], inner load ``n`` [N],
    cage speed ``wc`` [rad/s] (module notes). status 0 ok, 1 spin, 2 load, 3 cage speed
    outside the grid (values then 0)."""
    s, f, q, _, status = table_eval_contacts(spin0, spin_step, loads, cage, values, w, n,
                                             wc)
    return s, f, q, status


@njit(cache=True)
def table_eval_contacts(spin0: float, spin_step: float, loads: np.ndarray, cage: np.ndarray,
                        values: np.ndarray, w: float, n: float, wc: float
                        ) -> tuple[float, float, float, float, int]:
    """(S, F_d, Q_o, S_o [N], status): :func:`table_eval` with the outer contact's shear S_o
    (column ``T_SHEAR_OUTER``; the inner one's is S - S_o)."""
    n_w = values.shape[2]
    n_col = values.shape[3]
    x = (w - spin0) / spin_step
    i = int(math.floor(x))
    if i < 1 or i > n_w - 3:
        return 0.0, 0.0, 0.0, 0.0, 1
    t = x - i
    n_l = loads.shape[0] - 2          # loads[k] = N_max (k / n_l)^2, k = 0 .. n_l + 1
    n_max = loads[n_l]
    if n < 0.0 or n > n_max:
        return 0.0, 0.0, 0.0, 0.0, 2
    u = n_l * math.sqrt(n / n_max)
    il = min(int(math.floor(u)), n_l - 1)
    tl = u - il
    n_c = cage.shape[0]
    dc = cage[1] - cage[0]
    xc = (wc - cage[0]) / dc
    jc = int(math.floor(xc))
    if jc < 1 or jc > n_c - 3:
        return 0.0, 0.0, 0.0, 0.0, 3
    tc = xc - jc
    # Catmull-Rom in the cage speed through layers jc-1 .. jc+2 (C1: value and slope
    # continuous across layers -- the refresh's forward-difference slopes need it)
    layer = np.zeros((4, n_col))
    nodes = np.zeros((4, n_col))
    for ic in range(4):
        for k in range(4):
            kk = il - 1 + k
            if kk >= 0:
                _spin_cubic(values[jc - 1 + ic, kk], i, t, nodes[k])
        if il == 0:
            for col in range(n_col):
                nodes[0, col] = nodes[2, col]
        for col in range(n_col):
            p0 = nodes[0, col]
            p1 = nodes[1, col]
            p2 = nodes[2, col]
            p3 = nodes[3, col]
            layer[ic, col] = p1 + 0.5 * tl * (p2 - p0 + tl * (
                2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + tl * (3.0 * (p1 - p2) + p3 - p0)))
    res = np.zeros(n_col)
    for col in range(n_col):
        res[col] = _cubic(layer, _ONE, tc, col)   # int64, not Literal[int](1): one compile
    return res[0], res[1], res[2], res[3], 0


__all__ = ["DEFAULT_CAGE_STEP", "DEFAULT_LOAD_NODES", "DEFAULT_SPIN_STEP", "N_COLUMNS",
           "T_OUTER", "T_POCKET", "T_SHEAR", "T_SHEAR_OUTER", "TractionTable",
           "build_traction_table", "table_eval", "table_eval_contacts"]
