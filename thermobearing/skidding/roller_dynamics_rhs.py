"""Right-hand side of one roller's axial, skew and pocket motion (paper 003 eq. 18): the
parameter vector of a model (:func:`_params`) and the compiled kernels :func:`_rhs` (inner ring
fixed) and :func:`_rhs_ring` (inner ring moving axially), also called from the compiled loops of
:mod:`~thermobearing.skidding.roller_dynamics_integrate` and
:mod:`~thermobearing.skidding.roller_dynamics_coupled`.

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], eq. 18, with
the rib contact of :mod:`thermobearing.rib` (eqs. 1-17); what the model leaves out is said in
:mod:`thermobearing.skidding.roller_dynamics`.

Rib contact: both end faces through the jitted kernel :func:`thermobearing.rib.face_contact`
(the same code as :func:`~thermobearing.rib.rib_forces`): the contact point moves
circumferentially with the skew (about z_K = (R_s - L_r/2) sin alpha for the paper's
spherical end face), the normal force acts along the rib cone's normal there (rib.py,
"Contact normal"), the friction along the full sliding velocity at that point (eq. 24 as a
vector), so its radial part brakes the roller spin (M_rib,x below) and its circumferential
part turns the roller about the skew axis.

Equations (cage frame, signs as in :mod:`thermobearing.rib`)::

    m X''      = Q_ez^X + N_i mu(s_i) + N_o mu(s_o)                       (eq. 18, line 1)
    J_t alpha'' = M_unb + M_rib + M_race + M_pocket                        (eq. 18, skew line)
    T_j(omega_r, omega_c) + <M_rib,x> = 0, cage balance + sum <F_rib,z> = 0   (couple_spins)

* unbalance (paper sec. 4; its refs [16,17] [cui2017_roller_unbalance] were not seen, so the
  force is derived from rigid-body kinematics): a mass m_u at axial position x_u and radius
  e_u rotating with the roller: F_cv = m_u e_u (omega_r - omega_c)^2 (absolute spin rate),
  circumferential component F_cv sin(psi), psi' = omega_r; skew moment
  M_unb = -x_u F_cv sin(psi). Its radial component (tilt, raceway load ripple) is not
  followed here; the coupled model's option ``tilt`` adds the radial position and the
  tilt (:mod:`~thermobearing.skidding.roller_dynamics_tilt`): an unloaded roller is held
  on the outer raceway by its centrifugal force only (79 N at the base case, a tilt
  stiffness of ~420 N m/rad up to the ~0.07 N m at which an end lifts), and the rib
  impacts' own tilt moments (~0.5 N m at 300 N) and the unbalance's (0.12 N m at 0.11 g)
  swing it within the radial play: tilt rms ~1.4 mrad over the orbit (validation case
  SOURCE.md, "Tilt and radial play").
* raceway axial sliding of a skewed roller s_i = -u_i sin(alpha) - X', s_o = u_o sin(alpha)
  - X' (u_i = (omega_i - omega_c) d_i/2, u_o = omega_c d_o/2) with a regularised Coulomb
  traction mu(s) = mu_t tanh(s/s_0) (the shape of an EHL traction curve,
  [johnson_tevaarwerk1977_traction]; mu_t, s_0 estimated); the skew rate's sliding -alpha' x
  along the line gives M_race = -sum N mu_t tanh(alpha' l/s_0) l, l = L_e/(2 sqrt 3) (the
  rms arm of a uniform line load).
* pocket (paper 003 eq. 18 lines 2-3: N^c, F^c and the unbalance forces move the roller
  centre): a point mass at the chamfer is not only a couple -- its rotating force F_cv acts
  on the roller centre too. Circumferentially
  m z'' = F_d + F_cv sin(psi) + F_rib,z - c_z z' + F_bar(z, z', alpha),
  F_d the quasi-static pocket force (the raceways' net forward force), c_z = k_omega/(D/2)^2
  the raceway damping of the same traction model, F_bar the two cage bars as Winkler line
  springs with a squeeze film (:mod:`~thermobearing.skidding.roller_dynamics_pocket`), which
  also limit the skew. At the base case the free rattle amplitude F_cv/(m omega_r^2) is
  0.08 mm (0.06 g) to 0.14 mm (0.11 g) against a half clearance of 0.1 mm: the roller
  hits the bars every spin period. ``pocket_dof=False`` holds z = 0 (the bars then act on
  the skew only, as before 2026-11-22).

numba's cache does not notice edits of compiled callees in other files (rib.py,
roller_dynamics_pocket.py): :func:`thermobearing.contact_traction.refresh_stale_caches`.
Units: SI.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numba import njit

from ..contact_traction import refresh_stale_caches
from ..rib import (
    _G_N,
    F_FX,
    F_FZ,
    F_MSKEW,
    F_MSPIN,
    SIDE_LEFT,
    SIDE_RIGHT,
    SIGN_REGULARISATION,
    face_squeeze,
    face_values,
    lubricant_drag,
)
from .roller_dynamics_model import DynamicsModel
from .roller_dynamics_pocket import pocket_force_z

# parameter vector of the jitted right-hand side: the rib geometry vector
# (RibGeometry.params, _G_N entries) followed by these dynamics scalars (indices)
(_FG, _SREG, _MU, _UI, _UO, _LARM, _OM, _WC, _HL, _MUT, _S0, _CP, _KC, _MUE, _XU, _MASS,
 _JT, _ETA, _RAD, _FLOOR, _PDOF, _VEC, _ETR, _NP) = range(_G_N, _G_N + 24)


def _params(m: DynamicsModel) -> np.ndarray:
    """Scalars of the rib contact, raceways, cage and unbalance, computed once per model."""
    g = m.geom
    f_g = 0.0
    if m.mixture_viscosity > 0.0 and g.axial_clearance > 0.0:
        f_g = abs(float(lubricant_drag(g, m.inner_speed, m.cage_speed,
                                       m.mixture_viscosity)[0]))
    wc = m.cage_speed
    p = np.zeros(_NP)
    p[:_G_N] = g.params()
    p[_FG] = f_g
    p[_SREG] = SIGN_REGULARISATION
    p[_MU] = m.rib_friction
    p[_UI] = (m.inner_speed - wc) * 0.5 * g.inner_raceway_diameter
    p[_UO] = wc * 0.5 * m.outer_raceway_diameter
    p[_LARM] = m.effective_length / (2.0 * math.sqrt(3.0))
    p[_OM] = m.inner_speed - wc
    p[_WC] = wc
    p[_HL] = 0.5 * g.roller_length
    p[_MUT] = m.traction_limit
    p[_S0] = m.traction_speed
    p[_CP] = m.pocket_clearance
    p[_KC] = m.pocket_stiffness
    p[_MUE] = m.unbalance.mass * m.unbalance.radius
    p[_XU] = m.unbalance.axial_position
    p[_MASS] = m.roller_mass
    p[_JT] = m.transverse_inertia
    p[_ETA] = m.pocket_viscosity
    p[_RAD] = 0.5 * g.roller_diameter
    p[_FLOOR] = m.squeeze_floor
    p[_PDOF] = 1.0 if m.pocket_dof else 0.0
    p[_VEC] = 1.0 if m.raceway_traction == "isotropic" else 0.0
    # rib-gap squeeze film (rib.face_squeeze): the gap's oil/air mixture of eq. 14, the
    # cage-bar film's floor
    p[_ETR] = m.mixture_viscosity if m.rib_squeeze else 0.0
    return p


@njit(cache=True)
def _axial_share(s: float, v: float, s0: float) -> float:
    """tanh(|u|/s0) s/|u| [-] for the slide vector u = (v, s) [m/s] (v rolling, s axial;
    s0 [m/s]): the axial share of a traction law mu_t tanh(|u|/s0) directed along u, the
    shear stress of a film being collinear with its sliding velocity
    [johnson_tevaarwerk1977_traction] (``raceway_traction="isotropic"`` of
    :func:`build_model`); s/s0 at |u| -> 0."""
    r = math.sqrt(s * s + v * v)
    if r < 1e-9 * s0:
        return s / s0
    return math.tanh(r / s0) * s / r


@njit(cache=True)
def _rhs(p: np.ndarray, x: float, xd: float, a: float, ad: float, z: float, zd: float,
         n_i: float, n_o: float, spin: float, psi: float, f_d: float, c_z: float
         ) -> tuple[float, float, float, float, float, float, float]:
    """(X', X'', alpha', alpha'', z', z'', rib spin moment) with the inner ring fixed:
    :func:`_rhs_ring` at zero ring speed."""
    r = _rhs_ring(p, x, xd, a, ad, z, zd, n_i, n_o, spin, psi, f_d, c_z, 0.0)
    return r[0], r[1], r[2], r[3], r[4], r[5], r[6]


@njit(cache=True)
def _rhs_ring(p: np.ndarray, x: float, xd: float, a: float, ad: float, z: float, zd: float,
              n_i: float, n_o: float, spin: float, psi: float, f_d: float, c_z: float,
              xd_ring: float, x_tilt: float = 0.0, xd_tilt: float = 0.0,
              dca: float = 0.0, dca_rate: float = 0.0
              ) -> tuple[float, float, float, float, float, float, float, float, float,
                         float]:
    """(X', X'', alpha', alpha'', z', z'', rib spin moment, axial force on the inner ring):
    both faces of
    :func:`thermobearing.rib.face_values` (the kernel of :func:`~thermobearing.rib.rib_forces`)
    plus raceway, cage-bar (:func:`~thermobearing.skidding.roller_dynamics_pocket.pocket_force_z`)
    and unbalance terms (module notes). z: circumferential position in the pocket [m];
    f_d: quasi-static pocket force [N] (the raceways' net forward force on the roller);
    c_z: raceway damping of z [N s/m]. With the pocket DOF off, z stays 0.
    x, xd: axial position and speed of the roller *relative to the inner ring* [m, m/s]
    (rib contact, inner raceway slide); xd_ring: the inner ring's axial speed [m/s] (outer
    raceway slide: the outer ring is fixed); X'' is the roller's absolute axial
    acceleration (paper 003 eq. 18 line 1); the eighth entry is minus the rib and inner-
    raceway axial forces on the roller, i.e. their reaction on the inner ring (eq. 20
    line 1) [N], the ninth the rib faces' axial force on the roller [N], the tenth the
    right face's axial force minus the left face's [N].
    x_tilt, xd_tilt, dca, dca_rate: the tilt's equivalent axial shift t_q alpha_e [m], its
    rate [m/s], its symmetric share of the approach [m] and that share's rate [m/s]
    (:mod:`~thermobearing.skidding.roller_dynamics_tilt`): the rib faces see X + x_tilt,
    the clearance less dca and the axial speed X' + xd_tilt -+ dca_rate (left / right: the
    contact point's own axial speed); the raceways X' (0 without tilt)."""
    gp = p[:_G_N]
    xf = x + x_tilt
    xdf = xd + xd_tilt
    fl = face_values(gp, -1, a, xf, ad, spin, p[_OM], xdf - dca_rate, p[_MU], p[_FG],
                     p[_SREG], dca)
    fr = face_values(gp, 1, a, xf, ad, spin, p[_OM], xdf + dca_rate, p[_MU], p[_FG],
                     p[_SREG], dca)
    sl = face_squeeze(gp, SIDE_LEFT, a, xf, ad, xdf - dca_rate, p[_ETR], p[_FLOOR], dca)
    sr = face_squeeze(gp, SIDE_RIGHT, a, xf, ad, xdf + dca_rate, p[_ETR], p[_FLOOR], dca)
    m_rib = fl[F_MSKEW] + fr[F_MSKEW] + sl[2] + sr[2]
    f_rib = fl[F_FX] + fr[F_FX] + sl[1] + sr[1]
    m_spin = fl[F_MSPIN] + fr[F_MSPIN]
    mu_t = p[_MUT]
    s0 = p[_S0]
    sa = math.sin(a)
    s_i = -p[_UI] * sa - xd
    s_o = p[_UO] * sa - xd - xd_ring
    arm = p[_LARM]
    if p[_VEC] > 0.5:
        # isotropic film: the tanh law on the resultant slide, its axial share s/|s|
        v_i = p[_UI] - spin * p[_RAD]
        v_o = p[_UO] - spin * p[_RAD]
        f_inner = mu_t * n_i * _axial_share(s_i, v_i, s0)
        f_race = f_inner + mu_t * n_o * _axial_share(s_o, v_o, s0)
        m_race = -mu_t * (n_i * _axial_share(ad * arm, v_i, s0)
                          + n_o * _axial_share(ad * arm, v_o, s0)) * arm
    else:
        f_inner = mu_t * n_i * math.tanh(s_i / s0)
        f_race = f_inner + mu_t * n_o * math.tanh(s_o / s0)
        m_race = -(n_i + n_o) * mu_t * math.tanh(ad * arm / s0) * arm
    fz_bar, m_pocket, _, _ = pocket_force_z(z, zd, a, p[_HL], p[_CP], p[_KC], p[_ETA],
                                            p[_RAD], p[_FLOOR])
    f_cv = p[_MUE] * (spin - p[_WC]) ** 2
    sp = math.sin(psi)
    m_unb = -p[_XU] * f_cv * sp
    xdd = (f_rib + f_race) / p[_MASS]
    add = (m_rib + m_race + m_pocket + m_unb) / p[_JT]
    zdd = 0.0
    if p[_PDOF] > 0.5:
        zdd = (f_d + f_cv * sp + fl[F_FZ] + fr[F_FZ] - c_z * zd + fz_bar) / p[_MASS]
    return (xd, xdd, ad, add, zd, zdd, m_spin, -(f_rib + f_inner), f_rib,
            fr[F_FX] + sr[1] - fl[F_FX] - sl[1])


def _roller_rhs(m: DynamicsModel, c: np.ndarray, y: Any, n_i: float, n_o: float,
                spin: float, psi: float, f_d: float = 0.0, c_z: float = 0.0
                ) -> tuple[float, float, float, float, float, float, float]:
    """Python entry to the jitted right-hand side (``c`` = :func:`_params` of ``m``);
    ``y`` = (X, X', alpha, alpha'[, z, z'])."""
    z, zd = (float(y[4]), float(y[5])) if len(y) > 4 else (0.0, 0.0)
    return _rhs(c, float(y[0]), float(y[1]), float(y[2]), float(y[3]), z, zd, float(n_i),
                float(n_o), float(spin), float(psi), float(f_d), float(c_z))


_consts = _params


def _refresh_caches() -> None:
    """Flush the kernels' numba caches when rib.py or roller_dynamics_pocket.py (inlined
    callees) changed (:func:`thermobearing.contact_traction.refresh_stale_caches`)."""
    from .. import rib
    from . import roller_dynamics_pocket

    refresh_stale_caches("roller_dynamics_rhs", (_axial_share, _rhs, _rhs_ring),
                         (rib, roller_dynamics_pocket))


_refresh_caches()
