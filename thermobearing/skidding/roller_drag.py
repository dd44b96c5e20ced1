"""Oil drag of a cylindrical roller bearing in the roller skidding balance (paper 002 models).

One job: the drags the roller skidding solver (paper 000 Z + 1 equations, Li, Chen, Zhang,
Wang 2018, seed ``000_3b5ca6eed61dd596.txt``) balances when it is given an oil supply
(``skidding.solve(..., supply=...)``, every scene), built from the functions of
:mod:`thermobearing.heat_sources.churning` and :mod:`thermobearing.heat_sources.cage_guide`
(one code path, the same defaults) so that the scene's heat sources book exactly them:

- roller drag, paper 002 (seed ``002_0add79adaca5495c.txt``) eq. 10 (Harris & Kotzalas):
  F = (1/2) c_d rho_e u^2 A on each roller centre against its orbital velocity
  u = omega_c d_m / 2 (no oil swirl), A = D l, c_d = 1.0 (cylinder plateau, the
  ``churning_elements`` default for rollers). It acts in each roller's orbital force balance
  (paper 000 eqs. 21/24): the pocket passes it to the cage (cage equation, eq. 32). The
  source models no moment about the roller axis, so none enters the spin balance;
- cage churning, paper 002 eqs. 12-15: M_c = -Q_c / omega_c on the cage;
- cage-guide land, paper 002 eq. 5 (Petroff, centred cage, radial clearance), for a ring-
  guided cage: M_g = pi eta D_g^3 (omega_g - omega_c) B / (4 c) on the cage, its reaction on
  the guiding ring (the inner ring: in the shaft torque);
- inner-ring churning, paper 002 eq. 17: M_i = -Q_i / omega_i on the inner ring: shaft
  torque only (the ring speed is given).

Oil-air mixture: rho_e = X rho at each body's radius, X from the supply as the sources take
it (:func:`~thermobearing.heat_sources.churning.supply_oil_fraction`: Parker for jets and
circulation, the bath level model, 0 for grease), rho and nu (eta for the land) at the oil
temperature. The converged state carries the moments and forces (kinematic state extras
``solver_drag``) and the sources book their power (:class:`RollerDrag` returns them).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..errors import InputError, check_positive

#: c_d of the roller drag (paper 002 eq. 10): the ``churning_elements`` default for rollers
DEFAULT_ROLLER_DRAG_COEFFICIENT = 1.0

#: K of Parker's oil-fraction correlation: the ``churning_*`` sources' default
DEFAULT_PARKER_CONSTANT = 1.46e7


@dataclass(frozen=True)
class RollerDrag:
    """The oil drag of one roller bearing at one oil state (SI; built by :func:`build_drag`).

    Attributes
    ----------
    pitch_diameter : d_m [m].  element_area : A = D l [m^2].
    drag_coefficient : c_d [-].  element_density : X rho at d_m/2 [kg/m^3].
    kinematic_viscosity : nu of the oil [m^2/s].  dynamic_viscosity : eta [Pa s].
    cage_diameter, cage_width, cage_gap : D_c, B_c, c of eq. 15 [m].
    cage_density : X rho at D_c/2 [kg/m^3].
    inner_diameter, inner_arc, inner_shoulder, inner_gap : D_Li, B_arc, B_Li, c of
        eq. 17 [m].  inner_density : X rho at D_Li/2 [kg/m^3].
    guidance : "outer_ring", "inner_ring" or "rolling_element" (no land).
    guide_diameter, guide_width, guide_clearance : D_g, B, radial c of eq. 5 [m] (0 without
        a land).
    oil_fractions : X at the rollers, the cage and the inner ring [-].
    """

    pitch_diameter: float
    element_area: float
    drag_coefficient: float
    element_density: float
    kinematic_viscosity: float
    dynamic_viscosity: float
    cage_diameter: float
    cage_width: float
    cage_gap: float
    cage_density: float
    inner_diameter: float
    inner_arc: float
    inner_shoulder: float
    inner_gap: float
    inner_density: float
    guidance: str
    guide_diameter: float
    guide_width: float
    guide_clearance: float
    oil_fractions: tuple[float, float, float]
    #: K of Parker's correlation the oil fractions were taken with [-]
    parker_constant: float = DEFAULT_PARKER_CONSTANT

    def element_force(self, cage_speed: float) -> float:
        """Drag on each roller along its orbit [N] (negative: against the motion), paper 002
        eq. 10 at u = omega_c d_m / 2."""
        from ..heat_sources.churning import drag_force

        u = 0.5 * self.pitch_diameter * cage_speed
        f = float(drag_force(self.drag_coefficient, self.element_density, self.element_area, u))
        return -math.copysign(f, u) if u != 0.0 else 0.0

    def cage_churning_moment(self, cage_speed: float) -> float:
        """Churning moment on the cage [N m], -Q/omega_c of paper 002 eqs. 12-15."""
        from ..heat_sources.churning import cage_churning_power, viscous_friction_coefficient

        if cage_speed == 0.0 or self.cage_density == 0.0:
            return 0.0
        reg = viscous_friction_coefficient(0.5 * self.cage_diameter, float(cage_speed),
                                           self.cage_gap, self.kinematic_viscosity)
        q = float(cage_churning_power(self.cage_density, float(reg.mu_v), cage_speed,
                                      self.cage_width, self.cage_diameter))
        return -q / cage_speed

    def guide_moment(self, inner_speed: float, cage_speed: float) -> float:
        """Land moment on the cage [N m] (paper 002 eq. 5, centred cage; positive drives the
        cage), 0 for a rolling-element-guided cage. Outer ring fixed."""
        if self.guidance not in ("outer_ring", "inner_ring"):
            return 0.0
        from ..heat_sources.cage_guide import land_drag_torque

        omega_g = inner_speed if self.guidance == "inner_ring" else 0.0
        return float(land_drag_torque(self.dynamic_viscosity, self.guide_diameter, omega_g,
                                      cage_speed, self.guide_width, self.guide_clearance, 0.0))

    def cage_moment(self, inner_speed: float, cage_speed: float) -> float:
        """Every oil moment on the cage [N m]: churning plus the guide land."""
        return self.cage_churning_moment(cage_speed) + self.guide_moment(inner_speed,
                                                                         cage_speed)

    def inner_ring_moment(self, inner_speed: float) -> float:
        """Churning moment on the inner ring [N m], -Q/omega_i of paper 002 eq. 17."""
        from ..heat_sources.churning import (
            inner_ring_churning_power,
            viscous_friction_coefficient,
        )

        if inner_speed == 0.0 or self.inner_density == 0.0:
            return 0.0
        reg = viscous_friction_coefficient(0.5 * self.inner_diameter, float(inner_speed),
                                           self.inner_gap, self.kinematic_viscosity)
        q = float(inner_ring_churning_power(self.inner_density, float(reg.mu_v), inner_speed,
                                            self.inner_arc, self.inner_shoulder,
                                            self.inner_diameter))
        return -q / inner_speed

    def shaft_moment(self, inner_speed: float, cage_speed: float) -> float:
        """Torque the shaft adds for the oil [N m]: minus the inner ring's churning moment,
        plus the land moment an inner-ring-guided cage takes from the ring."""
        extra = -self.inner_ring_moment(inner_speed)
        if self.guidance == "inner_ring":
            extra += self.guide_moment(inner_speed, cage_speed)
        return extra

    def state(self, inner_speed: float, cage_speed: float) -> dict[str, Any]:
        """The forces and moments at a state (kinematic state extras ``solver_drag``, read by
        the ``churning_*`` and ``cage_guide`` heat sources) [N, N m]."""
        x_e, x_c, x_i = self.oil_fractions
        return {"element_force": self.element_force(cage_speed),
                "cage_churning_moment": self.cage_churning_moment(cage_speed),
                "cage_guide_moment": self.guide_moment(inner_speed, cage_speed),
                "inner_ring_moment": self.inner_ring_moment(inner_speed),
                "guidance": self.guidance, "drag_coefficient": self.drag_coefficient,
                "element_oil_fraction": x_e, "cage_oil_fraction": x_c,
                "inner_ring_oil_fraction": x_i, "parker_constant": self.parker_constant}


def build_drag(bearing: Any, lubricant: Any, supply: Any, inner_speed: float,
               oil_temperature: float, *,
               drag_coefficient: float = DEFAULT_ROLLER_DRAG_COEFFICIENT,
               parker_constant: float = DEFAULT_PARKER_CONSTANT) -> RollerDrag:
    """:class:`RollerDrag` of ``bearing`` (RollerBearing) in ``lubricant`` at the oil
    temperature [K] with the oil fraction of ``supply`` (OilSupply) at the inner-ring speed
    [rad/s] (Parker's correlation depends on it), as the heat sources' defaults take them
    (module docstring)."""
    from ..heat_sources import churning as ch

    if not 0.0 < drag_coefficient < 10.0:
        raise InputError("drag_coefficient", drag_coefficient,
                         "a value in (0, 10) (1.0: cylinder plateau)")
    check_positive("parker_constant", parker_constant)
    t = float(oil_temperature)
    rho = float(lubricant.density(t))
    eta = float(lubricant.dynamic_viscosity(t))
    check_positive("lubricant density", rho)
    check_positive("lubricant dynamic_viscosity", eta)
    d_m = float(bearing.pitch_diameter)
    d_c, gap_c = ch.cage_churning_geometry(bearing)
    d_in, arc, shoulder, gap_i = ch.inner_ring_churning_geometry(bearing)

    def fraction(radius: float) -> float:
        return float(ch.supply_oil_fraction(supply, bearing, radius, inner_speed,
                                            parker_constant))

    x_e, x_c, x_i = fraction(0.5 * d_m), fraction(0.5 * d_c), fraction(0.5 * d_in)
    cage = bearing.cage
    guidance = str(cage.guidance)
    d_g = b_g = c_g = 0.0
    if guidance in ("outer_ring", "inner_ring"):
        if cage.guide_clearance is None or cage.guide_land_diameter is None:
            raise InputError("bearing.cage.guide_clearance/guide_land_diameter",
                             (cage.guide_clearance, cage.guide_land_diameter),
                             "both given for a ring-guided cage")
        d_g = float(cage.guide_land_diameter)
        b_g = float(cage.land_width if cage.land_width is not None else cage.width)
        c_g = 0.5 * float(cage.guide_clearance)
    return RollerDrag(
        pitch_diameter=d_m, element_area=float(ch.element_frontal_area(bearing)),
        drag_coefficient=float(drag_coefficient), element_density=x_e * rho,
        kinematic_viscosity=eta / rho, dynamic_viscosity=eta,
        cage_diameter=float(d_c), cage_width=float(cage.width), cage_gap=float(gap_c),
        cage_density=x_c * rho, inner_diameter=float(d_in), inner_arc=arc,
        inner_shoulder=float(shoulder), inner_gap=float(gap_i), inner_density=x_i * rho,
        guidance=guidance, guide_diameter=d_g, guide_width=b_g, guide_clearance=c_g,
        oil_fractions=(x_e, x_c, x_i), parker_constant=float(parker_constant))
