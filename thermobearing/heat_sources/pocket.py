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

Roller skidding states: the roller solver (paper 000, seed 000_3b5ca6eed61dd596.txt) balances
the pocket film friction f_d of its eqs. 37-38 (``skidding.roller_pocket_film``), not mu F_bp;
its kinematic state carries f_d (extras ``pocket_friction``) and the source books
Q = sum_j f_d,j omega_r,j D / 2, the power of that force (the roller moment balance eq. 31 and
the cage equation eq. 32 contain it, so the raceway, rolling and pocket heat add up to the
solver's shaft power). Before, the source booked the boundary mu = 0.1 times F_d there:
12.5 W against the solver's 9.0 W (NU 214, ISO VG 46 at 320 K, 5000 r/min, 200 N) and 7.6
against 10.9 W (3000 r/min, 8 kN). Options that name a friction coefficient
(``friction_coefficient``, ``mu_boundary``, ``mu_hydrodynamic``, ``pocket_film``,
``roughness``) still ask for eq. 19 with mu.

Not in paper 002 and not in the source's heat: the Couette shear of the oil in a flooded
pocket by the spinning element, :func:`pocket_shear_damping` (a damping matrix the ball
solver would need for a consistent spin-damping moment; used by the diagnosis of the
validation case paper002_loss_ratios).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError, check_positive, check_range
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


def pocket_shear_damping(viscosity, ball_diameter, radial_clearance, section_inner,
                         section_outer, n_axial=400, n_around=96) -> np.ndarray:
    """Couette damping matrix C of a ball spinning in a flooded cylindrical pocket [N m s].

    Not in paper 002 (its eq. 19 has only the Coulomb friction of the pocket force): the
    oil in the pocket clearance is sheared by the ball surface even without a normal
    force. Frame of the ball solver: a = bearing axis, r = radial (the pocket bore's
    axis), t = orbital direction. The pocket wall is the cylinder of radius R + c about
    e_r over the cage section x_r in [section_inner, section_outer] (measured from the
    ball centre, m; e.g. cage bore radius minus ball-centre radius and cage outer radius
    minus ball-centre radius). Under the wall point (R_p cos phi, x_r, R_p sin phi) the ball
    surface point is p = (rho cos phi, x_r, rho sin phi), rho = sqrt(R^2 - x_r^2), gap
    h = R + c - rho. With the ball spin Omega relative to the cage, the surface velocity is
    v = Omega x p, its part tangential to the wall v_t = (I - n n^T) v (n = (cos phi, 0,
    sin phi)), the Couette stress on the ball tau = -eta v_t / h, and the moment about the
    centre

        M = int p x tau dA = -C Omega,   C = int (eta / h) S^T (I - n n^T) S dA,

    S = skew(p), dA = R_p dphi dx_r; power Omega^T C Omega >= 0 (derived here; Petroff-type
    estimate: pressure flow and cavitation neglected, pocket fully flooded -- scale
    ``viscosity`` for an oil-air mixture). Gauss-Legendre quadrature in x_r (``n_axial``
    nodes, clustered by x = sqrt(2 R c) sinh(s)) and the trapezoid rule in phi
    (``n_around``).

    Parameters
    ----------
    viscosity : dynamic viscosity of the oil in the pocket [Pa s].
    ball_diameter : D [m]. radial_clearance : c [m] (half the diametral pocket clearance).
    section_inner, section_outer : the cage section relative to the ball centre [m]
        (section_inner < section_outer; clipped to the ball, |x_r| < R).

    Returns
    -------
    (3, 3) symmetric positive semi-definite matrix in the (a, r, t) axes [N m s].
    """
    check_positive("pocket_shear.viscosity", viscosity)
    check_positive("pocket_shear.ball_diameter", ball_diameter)
    check_positive("pocket_shear.radial_clearance", radial_clearance)
    if not section_inner < section_outer:
        raise InputError("pocket_shear.section", (section_inner, section_outer),
                         "section_inner < section_outer [m]")
    r = 0.5 * float(ball_diameter)
    c = float(radial_clearance)
    lo = max(float(section_inner), -0.999 * r)
    hi = min(float(section_outer), 0.999 * r)
    if not lo < hi:
        raise InputError("pocket_shear.section", (section_inner, section_outer),
                         "a cage section that overlaps the ball")
    scale = math.sqrt(2.0 * r * c)
    s_lo, s_hi = math.asinh(lo / scale), math.asinh(hi / scale)
    g, w = np.polynomial.legendre.leggauss(int(n_axial))
    s = 0.5 * (s_hi - s_lo) * g + 0.5 * (s_hi + s_lo)
    x = scale * np.sinh(s)
    wx = w * 0.5 * (s_hi - s_lo) * scale * np.cosh(s)
    phi = np.linspace(0.0, 2.0 * math.pi, int(n_around), endpoint=False)
    wphi = 2.0 * math.pi / int(n_around)
    xx, pp = np.meshgrid(x, phi, indexing="ij")
    rho = np.sqrt(r * r - xx * xx)
    h = r + c - rho
    p = np.stack([rho * np.cos(pp), xx, rho * np.sin(pp)], axis=-1)
    n = np.stack([np.cos(pp), np.zeros_like(pp), np.sin(pp)], axis=-1)
    skew = np.zeros(p.shape + (3,))
    skew[..., 0, 1], skew[..., 0, 2] = -p[..., 2], p[..., 1]
    skew[..., 1, 0], skew[..., 1, 2] = p[..., 2], -p[..., 0]
    skew[..., 2, 0], skew[..., 2, 1] = -p[..., 1], p[..., 0]
    proj = np.eye(3) - n[..., :, None] * n[..., None, :]
    integrand = np.einsum("...ji,...jk,...kl->...il", skew, proj, skew)
    weight = float(viscosity) * (r + c) * wphi * wx[:, None] / h
    cmat = np.einsum("ij,ijkl->kl", weight, integrand)
    return 0.5 * (cmat + cmat.T)


def pocket_heat(normal_force, friction_coefficient, sliding_speed):
    """Paper 002 eq. 19 per element: Q_j = mu F_bp,j |v_j| [W] (v = omega_r D / 2)."""
    return (np.asarray(friction_coefficient, float) * np.asarray(normal_force, float)
            * np.abs(np.asarray(sliding_speed, float)))


@HEAT_SOURCES.register(
    "pocket_friction",
    references=["gao2022_overskidding", "hamrock2004"],
    parameters={"friction_coefficient": "-", "mu_boundary": "-", "mu_hydrodynamic": "-",
                "pocket_film": "m", "roughness": "m", "element_share": "-"},
    limits={"friction_coefficient": "[0, 1]", "mu_boundary": "[0, 1]",
            "mu_hydrodynamic": "[0, 1]", "pocket_film": "[0, inf)", "roughness": "(0, inf)",
            "element_share": "[0, 1]"},
    validity="pocket normal force from the kinematic state; mu in [0, 1]",
)
def pocket_friction(ctx: HeatContext) -> HeatResult:
    """Element-pocket friction heat, paper 002 eq. 19 (balls and rollers)."""
    name = "pocket_friction"
    kin = ctx.kinematics
    solver = _solver_pocket_friction(ctx, name)
    if solver is not None:
        return _solver_pocket_heat(ctx, name, solver)
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
    share, v = _share_and_sliding_speed(ctx, name)
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


_MU_OPTIONS = ("friction_coefficient", "mu_boundary", "mu_hydrodynamic", "pocket_film",
               "roughness")


def _solver_pocket_friction(ctx: HeatContext, name: str):
    """The pocket friction forces f_d (Z,) [N] the skidding solver balanced (kinematic state
    extras ``pocket_friction``, the roller solver's pocket film of paper 000 eqs. 37-38), or
    None: for a state without them (race control, balls) or when the source's options ask
    for the paper 002 eq. 19 friction coefficient on purpose (``friction_coefficient``,
    ``mu_boundary``, ``mu_hydrodynamic``, ``pocket_film``, ``roughness``)."""
    f = ctx.kinematics.extras.get("pocket_friction")
    if f is None:
        return None
    given = ctx.options.get(name) or {}
    if any(k in given for k in _MU_OPTIONS):
        return None
    return np.abs(np.broadcast_to(np.asarray(f, float), np.shape(ctx.kinematics.element_spin)))


def _solver_pocket_heat(ctx: HeatContext, name: str, friction: np.ndarray) -> HeatResult:
    """Pocket heat of the solver's pocket film: Q = sum_j f_d,j |v_j| [W], v = omega_r D/2.

    Paper 002 (seed 002_0add79adaca5495c.txt) eq. 19 with the film friction f_d of paper 000
    (seed 000_3b5ca6eed61dd596.txt) eqs. 37-38 (the Martin film of a roller turning against
    the pocket face, ``skidding.roller_pocket_film``) in place of mu F_bp: the force that the
    roller moment balance (eq. 31) and the cage equation (eq. 32) contain, so the heat is
    the power of that force across the sliding of the roller surface on the (cage-fixed)
    pocket wall. Option ``element_share`` as for the friction-coefficient form.
    """
    kin = ctx.kinematics
    share, v = _share_and_sliding_speed(ctx, name)
    heat_j = friction * np.abs(v)
    q = float(np.sum(heat_j))
    normal = np.abs(np.asarray(kin.pocket_normal_force, float))
    comp = "ball pocket" if hasattr(ctx.bearing, "ball_diameter") else "roller pocket"
    n_sum = float(np.sum(normal))
    return HeatResult(
        source=name, power_by_role={"elements": share * q, "cage": (1.0 - share) * q},
        components={comp: q}, loss_class={comp: "load_independent"},
        forces={"pocket_friction_force": friction},
        force_pairs=(ForcePair("pocket film on element surface", -friction * np.sign(v), v),),
        details={"friction_coefficient": (float(np.sum(friction)) / n_sum if n_sum > 0
                                          else math.inf),
                 "regime": "solver pocket film (paper 000 eqs. 37-38)",
                 "normal_force_sum": n_sum,
                 "mean_sliding_speed": float(np.mean(np.abs(v))),
                 "sliding_over_cage_speed": (float(np.mean(np.abs(v))) / abs(
                     0.5 * ctx.bearing.pitch_diameter * kin.cage_speed)
                     if kin.cage_speed != 0 else math.inf)})


def _share_and_sliding_speed(ctx: HeatContext, name: str) -> tuple[float, np.ndarray]:
    """The pocket heat's element share [-] (option ``element_share``, default 0.5, in
    [0, 1]) and the pocket sliding speed [m/s]: the kinematic state's own, else the
    element's surface speed relative to the cage, (D/2) |omega_spin|."""
    kin = ctx.kinematics
    share = float(ctx.option(name, "element_share", 0.5))
    check_range(f"options[{name}].element_share", share, 0.0, 1.0)
    if kin.pocket_sliding_speed is not None:
        return share, np.asarray(kin.pocket_sliding_speed)
    return share, 0.5 * ctx.bearing.element_diameter * np.abs(kin.element_spin)
