"""The held kinematic states' temperature dependence in a transient's chunk heat model.

A coupling chunk holds each bearing's kinematic state (cage and element speeds, sliding,
drag) solved at the temperatures of its last kinematics solve; the chunk's heat model
(:class:`thermobearing.coupled._Linear`) follows the node temperatures only at that fixed
state. As the bearing warms the oil thins and the state the kinematics would give moves:
held, its heat stays that of the cooler, more viscous oil until the next solve, where it
drops at once. On the NU 214 tour scene (5 kN, 6000 r/min after 3000 r/min, ISO VG 32 on a
1 L/min jet at 40 degC, default solver) the roller node fell 0.21 K within the last 9.4 s
chunk of each step and ran up to 0.96 K above a run with 1 s chunks and a 0.1 % kinematics
tolerance: a saw-tooth of one drop per solve.

Each bearing's kinematic heat dependence is estimated by a secant (Broyden's update) between
its consecutive kinematics solves within a schedule step: with s the change of the node
temperatures its kinematics read (the nodes of its rings, elements and oil) since the last
solve and y the heat the new state gives there minus what the model predicted (the old
state's heat plus the secant term),

    K <- K + y s^T / (s^T s),        q(T) = q_held(T) + K (T - T_solve)

so the model carries the heat's change with temperature through the kinematic state along
the direction the bearing warms (orthogonal directions are left as they were: zero after a
step change). A step's first solve starts from K = 0 (another speed or load); where its
kinematics are re-solved at the end of the step's first chunk, that chunk is repeated on the
new state with the chord secant of the two solves (``coupled.chord_first_chunk``). Units:
T [K], q [W], K [W/K].
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

#: the roles whose temperatures the kinematics are solved at (the contact temperature of
#: the rings and elements, the oil's drag: ``kinematic_models.contact_temperature``)
KINEMATIC_ROLES = ("inner_ring", "outer_ring", "elements", "oil")

#: warming [K] of a kinematics probe (the first secant of an operating point): the chunk
#: heat model's own finite-difference step (``Coupler.linearize``, dT = 0.5 K)
PROBE_DT = 0.5


@dataclass
class _BearingSecant:
    nodes: np.ndarray  #: indices of the nodes its kinematics read
    K: np.ndarray  #: (n, n) [W/K], non-zero columns on ``nodes`` only
    origin: np.ndarray  #: node temperatures [K] of the held state's solve


class KinematicSecant:
    """Per bearing, the secant estimate K of the heat's dependence on temperature through
    its kinematic state (module docstring); ``n`` state nodes, ``nodes`` per bearing name
    the indices of the nodes its kinematics read."""

    def __init__(self, n: int, nodes: Mapping[str, Sequence[int]]) -> None:
        self.n = n
        self.bearings = {name: _BearingSecant(np.array(sorted(set(idx)), dtype=int),
                                              np.zeros((n, n)), np.zeros(n))
                         for name, idx in nodes.items()}

    def restart(self, name: str, T: np.ndarray,
                probe: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> None:
        """A new operating point (a schedule step's first kinematics solve, at node
        temperatures T [K]): the secant of the last one does not hold. ``probe``
        (``Coupler.probe_kinematics``): (Tp [K], the heat [W] of the state solved at Tp, the
        new state's heat at Tp [W]) gives the first secant K = y s^T / (s^T s), s = Tp - T
        on the bearing's kinematic nodes, y the heat difference; without, K = 0."""
        b = self.bearings[name]
        b.K[:] = 0.0
        b.origin = np.array(T, dtype=float)
        if probe is not None:
            Tp, q_probe, q_held = probe
            self._update(b, np.asarray(Tp, float) - b.origin,
                         np.asarray(q_probe, float) - np.asarray(q_held, float))

    def resolved(self, name: str, T: np.ndarray, q_new: np.ndarray, q_old: np.ndarray
                 ) -> None:
        """Bearing ``name``'s kinematics were re-solved at T [K]: ``q_new`` its heat [W] on
        the new state at T, ``q_old`` on the state it replaces (without the secant term)."""
        b = self.bearings[name]
        d = np.asarray(T, dtype=float) - b.origin
        self._update(b, d, np.asarray(q_new, float) - (np.asarray(q_old, float) + b.K @ d))
        b.origin = np.array(T, dtype=float)

    def _update(self, b: _BearingSecant, d: np.ndarray, y: np.ndarray) -> None:
        """Broyden's update of ``b.K`` by the heat error y [W] over the temperature change
        d [K] (its part on the kinematic nodes; none when they did not move)."""
        s = np.zeros(self.n)
        s[b.nodes] = d[b.nodes]
        ss = float(s @ s)
        if ss > 0.0:
            b.K += np.outer(y, s) / ss

    def terms(self) -> tuple[np.ndarray, np.ndarray] | tuple[None, None]:
        """(K [W/K], c = sum_b K_b T_solve,b [W]) for the chunk model's K T - c, or
        (None, None) while every K is zero."""
        if not any(b.K.any() for b in self.bearings.values()):
            return None, None
        K = sum((b.K for b in self.bearings.values()), np.zeros((self.n, self.n)))
        c = sum((b.K @ b.origin for b in self.bearings.values()), np.zeros(self.n))
        return K, c
