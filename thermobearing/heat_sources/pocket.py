"""Element-pocket friction: paper 002 eq. 19 (ball pocket) and the roller pocket.

Seed paper 002 (002_0add79adaca5495c.txt) eq. 19:

    Q_bp = sum_j omega_r,j D_b f_bp,j / 2,   f_bp,j = mu F_bp,j

the pocket friction force times the sliding speed of the element surface in the pocket,
omega_r D / 2 (the element spins about its own axis while the pocket wall is still in the
cage frame). The same expression holds for a roller (D = roller diameter, omega_r the
roller speed). The pocket normal force F_bp comes from the kinematic state (skidding
solver; race control gives none, so the source then returns zero); the sliding speed is
the state's ``pocket_sliding_speed`` when given, else |omega_r| D / 2.

Friction coefficient (paper 002: "boundary or hydrodynamic, per the pocket film"):
option ``friction_coefficient`` (a fixed mu in [0, 1]) or, by default, a blend on the
pocket film parameter Lambda = h / sigma (``pocket_film`` [m], ``roughness`` [m] composite
rms): mu = mu_boundary for Lambda <= 1, mu_hydrodynamic for Lambda >= 3, linear between
(the usual mixed-lubrication bounds, Hamrock 2004 ch. 3). Defaults: mu_boundary = 0.1,
mu_hydrodynamic = 0.01, no film given -> boundary. Heat split: paper 002 lists Q_bp in
both the ball (eq. 22) and the oil/cage (eq. 25) balances, which would count it twice; we
send ``element_share`` (default 0.5) to the elements and the rest to the cage.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError, check_range
from . import HEAT_SOURCES, ForcePair, HeatContext, HeatResult


def pocket_friction_coefficient(film_parameter, mu_boundary=0.1, mu_hydrodynamic=0.01):
    """Mixed-lubrication blend of the pocket friction coefficient [-].

    film_parameter Lambda = h / sigma [-]; boundary below 1, hydrodynamic above 3, linear
    in between.
    """
    lam = np.asarray(film_parameter, float)
    w = np.clip((lam - 1.0) / 2.0, 0.0, 1.0)
    return mu_boundary + w * (mu_hydrodynamic - mu_boundary)


def pocket_heat(normal_force, friction_coefficient, sliding_speed):
    """Paper 002 eq. 19 per element: Q_j = mu F_bp,j |v_j| [W] (v = omega_r D / 2)."""
    return (np.asarray(friction_coefficient, float) * np.asarray(normal_force, float)
            * np.abs(np.asarray(sliding_speed, float)))


@HEAT_SOURCES.register(
    "pocket_friction",
    references=["gao2022_overskidding", "hamrock2004"],
    parameters={"friction_coefficient": "-", "mu_boundary": "-", "mu_hydrodynamic": "-",
                "pocket_film": "m", "roughness": "m", "element_share": "-"},
    validity="pocket normal force from the kinematic state; mu in [0, 1]",
)
def pocket_friction(ctx: HeatContext) -> HeatResult:
    """Element-pocket friction heat, paper 002 eq. 19 (balls and rollers)."""
    name = "pocket_friction"
    kin = ctx.kinematics
    d = ctx.bearing.element_diameter
    mu_fixed = ctx.option(name, "friction_coefficient", None)
    if mu_fixed is not None:
        check_range(f"options[{name}].friction_coefficient", mu_fixed, 0.0, 1.0)
        mu = float(mu_fixed)
        regime = "fixed"
    else:
        mu_b = float(ctx.option(name, "mu_boundary", 0.1))
        mu_h = float(ctx.option(name, "mu_hydrodynamic", 0.01))
        check_range(f"options[{name}].mu_boundary", mu_b, 0.0, 1.0)
        check_range(f"options[{name}].mu_hydrodynamic", mu_h, 0.0, 1.0)
        film = ctx.option(name, "pocket_film", None)
        if film is None:
            mu, regime = mu_b, "boundary (no pocket film given)"
        else:
            sigma = ctx.option(name, "roughness", None)
            if sigma is None or sigma <= 0:
                raise InputError(f"options[{name}].roughness", sigma,
                                 "a composite rms roughness > 0 [m] with pocket_film")
            mu = float(pocket_friction_coefficient(float(film) / float(sigma), mu_b, mu_h))
            regime = f"Lambda = {float(film) / float(sigma):.3g}"
    share = float(ctx.option(name, "element_share", 0.5))
    check_range(f"options[{name}].element_share", share, 0.0, 1.0)
    if kin.pocket_sliding_speed is not None:
        v = kin.pocket_sliding_speed
    else:
        v = 0.5 * d * np.abs(kin.element_spin)
    force = kin.pocket_normal_force
    heat_j = pocket_heat(force, mu, v)
    q = float(np.sum(heat_j))
    friction = mu * force  # magnitude, opposes the element surface's sliding in the pocket
    comp = "ball pocket" if hasattr(ctx.bearing, "ball_diameter") else "roller pocket"
    return HeatResult(
        source=name, power_by_role={"elements": share * q, "cage": (1.0 - share) * q},
        components={comp: q}, loss_class={comp: "load_independent"},
        forces={"pocket_friction_force": friction},
        force_pairs=(ForcePair("pocket on element surface", -friction * np.sign(v), v),),
        details={"friction_coefficient": mu, "regime": regime})
