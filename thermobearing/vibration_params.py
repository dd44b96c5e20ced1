"""Parameters of the lumped vibration model of :mod:`thermobearing.vibration`.

One job: the parameter set of paper 004's model (:class:`VibrationParameters`, built from a
:class:`thermobearing.geometry.BallBearing` by :meth:`VibrationParameters.from_bearing`),
the SKF 6304 set of paper 004 Table 1 (:func:`paper004_parameters`) and the tabulation of a
traction law for the compiled kernels (:func:`traction_table`).

Sources: Luo et al. 2022 (seed paper 004, ``../shared/seeds/004_0105d7aba121b014.txt``):
eqs. 1-3 (cage speed), 13-14 (clearance), 27 (BPFO), Table 1; Hertz stiffness by Hamrock &
Brewe 1983 / Harris & Kotzalas 2007 (:func:`thermobearing.hertz.point_contact_stiffness`).
Split out of ``vibration.py`` (names re-exported there). Units: SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from .errors import InputError, UnknownNameError, check_positive, check_range

__all__ = ["VibrationParameters", "paper004_parameters", "traction_table"]


# ---------------------------------------------------------------------------
# parameters
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class VibrationParameters:
    """Parameters of the lumped model (SI).

    Attributes
    ----------
    n_balls : Z. ball_diameter : D [m]. pitch_diameter : d_m [m].
    contact_angle : alpha [rad] (kinematics only; paper 004: 0).
    radial_clearance : P_d of paper 004 eqs. 13-14 [m]: the total radial play, split
        equally between the inner and the outer contact.
    inner_stiffness, outer_stiffness : K_i, K_o [N/m^1.5] (Q = K delta^1.5).
    inner_ring_mass : m_i [kg] (with the shaft). ball_mass : m_r [kg].
    ball_inertia : J_r [kg m^2].
    support_damping : c of the ring [N s/m]. ball_damping : c of the ball radial motion
        [N s/m] (paper 004 uses the same c).
    ball_diameter_deviation : per-ball D_j - D [m] (empty: all nominal).
    unbalance : m_u e of the rotor [kg m] (a force m_u e omega_s^2 rotating with the shaft).
    centrifugal : include m_r omega_c^2 d_m/2 on the balls (paper 004 neglects it).
    source : where the values come from.
    """

    n_balls: int
    ball_diameter: float
    pitch_diameter: float
    radial_clearance: float
    inner_stiffness: float
    outer_stiffness: float
    inner_ring_mass: float
    ball_mass: float
    ball_inertia: float
    support_damping: float
    ball_damping: float
    contact_angle: float = 0.0
    ball_diameter_deviation: tuple[float, ...] = ()
    unbalance: float = 0.0
    centrifugal: bool = False
    source: str = ""

    def __post_init__(self) -> None:
        if int(self.n_balls) != self.n_balls or self.n_balls < 3:
            raise InputError("vibration.n_balls", self.n_balls, "an integer >= 3")
        for name in ("ball_diameter", "pitch_diameter", "inner_stiffness", "outer_stiffness",
                     "inner_ring_mass", "ball_mass", "ball_inertia"):
            check_positive(f"vibration.{name}", getattr(self, name))
        for name in ("radial_clearance", "support_damping", "ball_damping", "unbalance"):
            check_positive(f"vibration.{name}", getattr(self, name), allow_zero=True)
        check_range("vibration.contact_angle", self.contact_angle, 0.0, math.pi / 2,
                    high_inclusive=False, unit="rad")
        if self.ball_diameter >= self.pitch_diameter:
            raise InputError("vibration.ball_diameter", self.ball_diameter,
                             f"less than the pitch diameter {self.pitch_diameter:g} m")
        dev = tuple(float(v) for v in self.ball_diameter_deviation)
        if dev and len(dev) != self.n_balls:
            raise InputError("vibration.ball_diameter_deviation", len(dev),
                             f"{self.n_balls} values (one per ball) or none")
        for v in dev:
            if not math.isfinite(v) or abs(v) > 0.01 * self.ball_diameter:
                raise InputError("vibration.ball_diameter_deviation", v,
                                 "finite deviations below 1 % of the ball diameter")
        object.__setattr__(self, "ball_diameter_deviation", dev)

    @property
    def gamma(self) -> float:
        """D cos(alpha)/d_m [-]."""
        return self.ball_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    @property
    def theoretical_cage_speed_ratio(self) -> float:
        """(1 - gamma)/2, paper 004 eq. 1 (outer ring fixed)."""
        return 0.5 * (1.0 - self.gamma)

    def ball_pass_frequency_outer(self, shaft_speed_hz: float, cage_slip: float = 0.0) -> float:
        """f_bpo = Z (1 - s_c)(1 - gamma) f_s / 2 [Hz], paper 004 eq. 27."""
        return self.n_balls * (1.0 - cage_slip) * self.theoretical_cage_speed_ratio * (
            shaft_speed_hz)

    @classmethod
    def from_bearing(cls, bearing: Any, *, inner_ring_mass: float, support_damping: float,
                     ball_damping: float | None = None, radial_clearance: float | None = None,
                     contact_angle: float = 0.0, ball_inertia: float | None = None,
                     **extra: Any) -> VibrationParameters:
        """Parameters of a :class:`thermobearing.geometry.BallBearing`.

        K_i, K_o from :func:`thermobearing.hertz.point_contact_stiffness` with the reduced
        radii of ``bearing.curvature(race, contact_angle)`` and ``bearing.effective_modulus``
        (Harris & Kotzalas 2007 / Hamrock & Brewe 1983, as ref. [33] of paper 004 says).
        ``radial_clearance`` defaults to half the diametral clearance. ``contact_angle``
        defaults to 0 (paper 004's planar model), not to the bearing's nominal angle: for an
        angular-contact bearing the model's pure-rolling ratio (1 - gamma)/2 and its
        ``cage_slip`` then differ from those of ``thermobearing cage-speed``, which uses the
        nominal angle (QJ1044: 0.4376 at 0 deg against 0.4522 at 40 deg, so a record
        simulated at zero slip reads as +3.2 % slip there); pass
        ``contact_angle=bearing.contact_angle`` to simulate on the analyser's terms.
        """
        from .hertz import point_contact_stiffness

        if not hasattr(bearing, "n_balls"):
            raise InputError("bearing", getattr(bearing, "name", type(bearing).__name__),
                             "a ball bearing (paper 004's model has Hertz point contacts and "
                             "ball spins; a roller bearing is not modelled)")
        from_geometry = ("n_balls", "ball_diameter", "pitch_diameter", "inner_stiffness",
                         "outer_stiffness", "ball_mass", "source")
        known = [f.name for f in fields(cls) if f.name not in from_geometry]
        for key, value in extra.items():
            if key in from_geometry:
                raise InputError(f"vibration.{key}", value, "nothing: it follows from the "
                                 "bearing geometry (change the bearing or its overrides)")
            if key not in known:
                raise UnknownNameError(f"vibration.{key}", key, known)
        ki = float(point_contact_stiffness(*bearing.curvature("inner", contact_angle),
                                           bearing.effective_modulus))
        ko = float(point_contact_stiffness(*bearing.curvature("outer", contact_angle),
                                           bearing.effective_modulus))
        return cls(
            n_balls=int(bearing.n_balls), ball_diameter=float(bearing.ball_diameter),
            pitch_diameter=float(bearing.pitch_diameter),
            radial_clearance=(0.5 * bearing.diametral_clearance if radial_clearance is None
                              else float(radial_clearance)),
            inner_stiffness=ki, outer_stiffness=ko, inner_ring_mass=float(inner_ring_mass),
            ball_mass=float(bearing.ball_mass),
            ball_inertia=float(bearing.ball_inertia if ball_inertia is None else ball_inertia),
            support_damping=float(support_damping),
            ball_damping=float(support_damping if ball_damping is None else ball_damping),
            contact_angle=float(contact_angle), source=f"bearing {bearing.name}", **extra)


def paper004_parameters(**overrides: Any) -> VibrationParameters:
    """SKF 6304 with paper 004 Table 1: m_i = 0.4 kg, J_r = 3.18e-8 kg m^2, c = 350 N s/m,
    P_d = 15 um, alpha = 0, D = 9.525 mm, d_m = 36 mm, Z = 7, E = 207 GPa, nu = 0.3.

    Geometry, conformities and stiffness come from the ``SKF6304`` preset of
    :func:`thermobearing.geometry.load_bearing` (the paper gives no groove radii); Table 1
    values override the preset where the paper gives them.
    """
    from .geometry import load_bearing

    bearing = load_bearing("SKF6304")
    kw: dict[str, Any] = dict(inner_ring_mass=0.4, support_damping=350.0,
                              radial_clearance=15e-6, contact_angle=0.0, ball_inertia=3.18e-8)
    kw.update(overrides)
    p = VibrationParameters.from_bearing(bearing, **kw)
    if abs(p.ball_diameter - 9.525e-3) > 1e-9 or abs(p.pitch_diameter - 36e-3) > 1e-9 or (
            p.n_balls != 7):
        raise InputError("SKF6304 preset", (p.ball_diameter, p.pitch_diameter, p.n_balls),
                         "paper 004 Table 1: D = 9.525 mm, d_m = 36 mm, Z = 7")
    return p


# ---------------------------------------------------------------------------
# traction law -> piecewise-linear table used by the compiled kernel
# ---------------------------------------------------------------------------
def traction_table(law: Any, max_speed: float, n: int = 96) -> tuple[np.ndarray, np.ndarray]:
    """Nodes (|dv| [m/s], mu [-]) of a pressure-independent traction law.

    The law must offer ``coefficient(slide_speed)`` (``linear_saturating``,
    ``four_parameter`` of :mod:`thermobearing.traction`); laws that need a film and a
    temperature (``eyring_limiting_shear``) are refused: paper 004's lumped model has no
    film. ``linear_saturating`` is represented exactly by the nodes (0, dv_m); other laws
    by ``n`` nodes (denser at small slip) up to ``max_speed`` and constant beyond.
    """
    if getattr(law, "requires_film", False) or not hasattr(law, "coefficient"):
        raise InputError("vibration.traction", type(law).__name__,
                         "a pressure-independent law with coefficient(dv) "
                         "(linear_saturating or four_parameter)")
    vm = getattr(law, "slip_speed_max", None)
    if type(law).__name__ == "LinearSaturatingTraction" and vm is not None:
        nodes = np.array([0.0, float(vm)])
    else:
        nodes = np.unique(np.concatenate([[0.0], np.geomspace(1e-4, max_speed, n - 1)]))
    mu = np.asarray(law.coefficient(nodes), dtype=float)
    if not np.all(np.isfinite(mu)) or np.any(mu < 0):
        raise InputError("vibration.traction", type(law).__name__, "finite mu >= 0")
    return nodes.astype(float), mu
