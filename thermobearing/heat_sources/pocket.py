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

Steady-state identity (derived here from paper 002 eqs. 8 and 19): in a steady state the
cage torque balance (eq. 8) makes the pocket forces carry exactly the cage's drag torque,
sum_j F_bp,j D_m/2 = M_drag (cage-guide land + cage churning), so when every pocket pushes
the same way

    Q_bp = mu * omega_r D_b / (omega_c D_m) * P_drag,   P_drag = M_drag omega_c,

about mu (1 + gamma) P_drag at pure rolling (omega_r / omega_c = (D_m / D_b)(1 + gamma)).
Pocket forces that alternate in sign around the bearing (balls with different free orbital
speeds) add to Q_bp without adding to P_drag; :func:`pocket_circulation` measures that.
:func:`steady_pocket_drag_ratio` gives the factor; the ``details`` of the source carry both.
"""

from __future__ import annotations

import math

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


def steady_pocket_drag_ratio(friction_coefficient, spin_speed, element_diameter, cage_speed,
                             pitch_diameter):
    """Pocket heat per watt of cage drag when all pockets push one way [-] (module docstring).

    k = mu |omega_r| D_b / (|omega_c| D_m): friction_coefficient mu [-], spin_speed omega_r
    [rad/s] (element spin relative to the cage), element_diameter D_b [m], cage_speed
    omega_c [rad/s] (> 0 in magnitude), pitch_diameter D_m [m]. Derived from paper 002
    eqs. 8 and 19 (steady cage torque balance); vectorised over the spin speed.
    """
    wc = abs(float(cage_speed))
    if wc == 0.0:
        raise InputError("cage_speed", cage_speed, "a non-zero cage speed")
    check_range("friction_coefficient", friction_coefficient, 0.0, 1.0)
    return (float(friction_coefficient) * np.abs(np.asarray(spin_speed, float))
            * float(element_diameter) / (wc * float(pitch_diameter)))


def pocket_circulation(normal_force) -> float:
    """sum_j |F_j| / |sum_j F_j| [-] of signed pocket normal forces (>= 1; inf if they cancel).

    1 when every pocket pushes the cage the same way (the pocket forces then carry only the
    cage's drag torque); larger when balls push and brake the cage at the same time.
    """
    f = np.asarray(normal_force, float)
    net = abs(float(np.sum(f)))
    total = float(np.sum(np.abs(f)))
    if total == 0.0:
        return 1.0
    return total / net if net > 0.0 else math.inf


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
        details={"friction_coefficient": mu, "regime": regime,
                 "normal_force_sum": float(np.sum(np.abs(force))),
                 "mean_sliding_speed": float(np.mean(np.abs(v))),
                 "sliding_over_cage_speed": (float(np.mean(np.abs(v))) / abs(
                     0.5 * ctx.bearing.pitch_diameter * kin.cage_speed)
                     if kin.cage_speed != 0 else math.inf)})
