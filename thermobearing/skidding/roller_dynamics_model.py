"""The dynamics model of one roller of paper 003: :class:`DynamicsModel` (the orbit's
per-azimuth load state from the quasi-static skidding solution, inertias, unbalance, raceway
traction and pocket parameters, with periodic interpolation in azimuth), the roller's
:class:`Unbalance` and the orbit's distinct load states (:func:`load_states`).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], sec. 4 and 8
(unbalance at the chamfer); model notes in :mod:`thermobearing.skidding.roller_dynamics`.
Built by :func:`thermobearing.skidding.roller_dynamics_setup.build_model`. Units: SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import InputError, check_range
from ..rib import DEFAULT_RIB_FRICTION, RibGeometry, unbalance_check
from .roller_dynamics_pocket import DEFAULT_SQUEEZE_FLOOR

#: raceway traction limit mu_t [-] (estimated: typical EHL traction plateau 0.03-0.08)
DEFAULT_TRACTION_LIMIT = 0.05
#: slide speed s_0 of the traction curve's initial slope [m/s] (estimated)
DEFAULT_TRACTION_SPEED = 0.5
#: cage-bar contact stiffness [N/m] (estimated: brass bar, line contact over the roller length)
DEFAULT_POCKET_STIFFNESS = 2.0e7
#: oil volume fraction of the oil/air mixture at the rib (estimated, jet lubrication)
DEFAULT_OIL_FRACTION = 0.05


@dataclass(frozen=True)
class Unbalance:
    """Dynamic unbalance of a roller: mass [kg] at axial position x_u [m] (+ right end) and
    radius e_u [m] from the roller axis (paper 003 sec. 8: at the right chamfer)."""

    mass: float
    axial_position: float
    radius: float

    @property
    def moment_coefficient(self) -> float:
        """m_u e_u x_u [kg m^2] (a product of inertia)."""
        return self.mass * self.radius * self.axial_position


def chamfer_unbalance(bearing: Any, mass: float, side: int = +1,
                      chamfer: float = 0.5e-3) -> Unbalance:
    """Unbalance ``mass`` [kg] at the chamfer of the ``side`` end (+1 right, -1 left)."""
    unbalance_check(mass, bearing.roller_mass)
    if side not in (-1, 1):
        raise InputError("side", side, "+1 (right) or -1 (left)")
    check_range("chamfer", chamfer, 0.0, 0.5 * bearing.roller_diameter)
    return Unbalance(mass, side * (0.5 * bearing.roller_length - chamfer),
                     0.5 * bearing.roller_diameter - chamfer)


@dataclass(frozen=True)
class DynamicsModel:
    """Everything the roller integrators need (SI).

    Per-azimuth arrays come from the quasi-static skidding solution (``azimuth`` sorted,
    one orbit): ``inner_load``, ``outer_load`` [N], ``spin`` omega_qs [rad/s].
    """

    geom: RibGeometry
    inner_speed: float
    cage_speed: float
    azimuth: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    spin: np.ndarray
    roller_mass: float
    transverse_inertia: float
    polar_inertia: float
    effective_length: float
    outer_raceway_diameter: float
    pocket_clearance: float
    unbalance: Unbalance
    rib_friction: float = DEFAULT_RIB_FRICTION
    mixture_viscosity: float = 0.0
    traction_limit: float = DEFAULT_TRACTION_LIMIT
    traction_speed: float = DEFAULT_TRACTION_SPEED
    pocket_stiffness: float = DEFAULT_POCKET_STIFFNESS
    extras: dict[str, Any] = field(default_factory=dict)
    spin_k: np.ndarray | None = None
    spin_bias: np.ndarray | None = None
    pocket_force: np.ndarray | None = None
    pocket_viscosity: float = 0.0
    pocket_length: float = 0.0
    squeeze_floor: float = DEFAULT_SQUEEZE_FLOOR
    pocket_dof: bool = True
    pocket_friction: np.ndarray | None = None
    raceway_traction: str = "componentwise"
    #: squeeze film of the rib gaps (:func:`thermobearing.rib.face_squeeze`; an option,
    #: not paper 003's model: it keeps the rollers off the ribs, validation case SOURCE.md)
    rib_squeeze: bool = False
    #: the roller's radial position and tilt as degrees of freedom of the coupled model
    #: (:mod:`~thermobearing.skidding.roller_dynamics_tilt`; paper 003 eq. 18's 6 DOF)
    tilt: bool = False
    #: normal damping of the 6-DOF roller's raceway slices
    #: (:mod:`~thermobearing.skidding.roller_dynamics_raceway_film`): the squeeze film's
    #: smallest gap per race (outer, inner) [m], the rolling contacts' central film
    #: thickness; None: the cage bars' ``squeeze_floor`` (the estimate before session 24)
    raceway_film: tuple[float, float] | None = None
    #: False: the raceway slices are elastic only (no squeeze film; a sensitivity)
    raceway_squeeze: bool = True

    def pocket_force_at(self, phi: float) -> float:
        """Quasi-static pocket force F_d [N] (positive: the roller pushes the cage
        forward) at azimuth ``phi``, interpolated like :meth:`at` (0 without data)."""
        return self._interp(self.pocket_force, phi)

    def _interp(self, arr: np.ndarray | None, phi: float) -> float:
        if arr is None:
            return 0.0
        p = phi % (2.0 * math.pi)
        az = np.append(self.azimuth, self.azimuth[0] + 2.0 * math.pi)
        v = np.append(arr, arr[0])
        return float(np.interp(p if p >= az[0] else p + 2.0 * math.pi, az, v))

    def circumferential_damping(self, k: float) -> float:
        """c_z = k_omega / (D/2)^2 [N s/m]: the raceway tractions' resistance to a
        circumferential slide of the roller centre, from the spin stiffness k_omega
        [N m s] of the same traction model (both contacts' dT/dV; notes of
        :mod:`~thermobearing.skidding.roller_dynamics_rhs`)."""
        r = 0.5 * self.geom.roller_diameter
        return k / (r * r)

    def at(self, phi: float) -> tuple[float, float, float]:
        """(N_i, N_o, omega_qs) at azimuth ``phi`` [rad] (periodic linear interpolation)."""
        p = phi % (2.0 * math.pi)
        az = self.azimuth
        n = len(az)
        j = int(np.searchsorted(az, p, side="right")) - 1
        j0 = j % n
        j1 = (j + 1) % n
        a0 = az[j0] if j >= 0 else az[-1] - 2.0 * math.pi
        a1 = az[j1] + (2.0 * math.pi if j1 <= j0 and j >= 0 else 0.0)
        w = (p - a0) / (a1 - a0) if a1 > a0 else 0.0
        return tuple(float(arr[j0] + w * (arr[j1] - arr[j0]))
                     for arr in (self.inner_load, self.outer_load, self.spin))

    def spin_stiffness(self, n_i: float, n_o: float) -> float:
        """k_omega = (D/2)^2 (N_i + N_o) mu_t / s_0 [N m s] (fallback when the model
        carries no ``spin_k`` of the quasi-static traction model)."""
        r = 0.5 * self.geom.roller_diameter
        return r * r * (n_i + n_o) * self.traction_limit / self.traction_speed

    def bias_at(self, phi: float) -> float:
        """Mean rib moment [N m] that the spins of a coupled model already balance
        (:func:`couple_spins`; 0 without coupling), interpolated at azimuth ``phi``."""
        if self.spin_bias is None:
            return 0.0
        p = phi % (2.0 * math.pi)
        az = np.append(self.azimuth, self.azimuth[0] + 2.0 * math.pi)
        b = np.append(self.spin_bias, self.spin_bias[0])
        return float(np.interp(p if p >= az[0] else p + 2.0 * math.pi, az, b))

    def stiffness_at(self, phi: float) -> float:
        """Spin stiffness k_omega [N m s] at azimuth ``phi``: ``spin_k`` interpolated like
        :meth:`at`, else :meth:`spin_stiffness`."""
        if self.spin_k is None:
            n_i, n_o, _ = self.at(phi)
            return self.spin_stiffness(n_i, n_o)
        p = phi % (2.0 * math.pi)
        az = np.append(self.azimuth, self.azimuth[0] + 2.0 * math.pi)
        k = np.append(self.spin_k, self.spin_k[0])
        return float(np.interp(p if p >= az[0] else p + 2.0 * math.pi, az, k))


def load_states(m: DynamicsModel, decimals: int = 6
                ) -> list[tuple[float, float, float, float, float, float]]:
    """Distinct (N_i, N_o, omega, weight, k_omega, F_d) states of the orbit (weights sum
    to 1; k_omega the spin stiffness [N m s] and F_d the quasi-static pocket force [N] of the
    state's first roller)."""
    states: dict[tuple[float, float, float], list[int]] = {}
    for j, (n_i, n_o, w) in enumerate(zip(m.inner_load, m.outer_load, m.spin, strict=True)):
        key = (round(float(n_i), 3), round(float(n_o), 3), round(float(w), 3))
        states.setdefault(key, []).append(j)
    n = len(m.azimuth)
    out = []
    for idx in states.values():
        j = idx[0]
        k = (float(m.spin_k[j]) if m.spin_k is not None
             else m.spin_stiffness(float(m.inner_load[j]), float(m.outer_load[j])))
        f_d = float(m.pocket_force[j]) if m.pocket_force is not None else 0.0
        out.append((float(m.inner_load[j]), float(m.outer_load[j]), float(m.spin[j]),
                    len(idx) / n, k, f_d))
    return out
