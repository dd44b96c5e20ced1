"""Results of the paper 003 roller dynamics: :class:`RollerResponse` and the post-processing of
a sampled trajectory into PV, rib heat, slip and cage-bar statistics (:func:`_post`,
:func:`_response`).

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], eqs. 21-25,
with the rib forces of :func:`thermobearing.rib.rib_forces` and the cage bars of
:mod:`~thermobearing.skidding.roller_dynamics_pocket`.

Outputs (paper 003 eqs. 21-25): PV per end face = time mean of P |v_i - v_r| over the
periodic state [Pa m/s] (also its peak and its mean over the time in contact); slip speed =
time mean of |V_roll|, V_roll = (omega_i - omega_c) d_i/2 - omega_r D_w/2. Eq. 25 as printed,
abs[(omega_ix d_i/2 - omega_rxj)(R_ro - omega_rsxj D_w/2)], multiplies a speed by a length
difference; with the parentheses moved, |(omega_ix - omega_rxj)(R_ro - D_w/2) -
omega_rsxj D_w/2| with omega_rxj the roller's orbital speed (= omega_c), R_ro - D_w/2 =
d_i/2 and omega_rsxj its spin, it is exactly |V_roll|, the rolling slip at the inner
raceway. The full sliding magnitude with the skew-induced parts,
sqrt(V_roll^2 + s_i^2 + (alpha' L_e)^2/12), is ``surface_slip_speed``. Units: SI.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..rib import SIGN_REGULARISATION, RibGeometry, rib_forces, squeeze_forces
from .roller_dynamics_model import DynamicsModel
from .roller_dynamics_pocket import bar_forces, extra_pocket_friction


@dataclass(frozen=True)
class RollerResponse:
    """PV and slip of one roller over the periodic state (paper 003 eqs. 21-25), SI.

    pv_left, pv_right : time-mean P |v| per end face [Pa m/s]; pv_peak_* the maxima.
    slip_speed : time mean of the slip speed of eq. 25, |V_roll| at the inner contact [m/s].
    rolling_slip_speed : the same (kept for existing callers) [m/s].
    surface_slip_speed : time mean of the full sliding-speed magnitude of the inner contact,
        sqrt(V_roll^2 + s_i^2 + (alpha' L_e)^2/12), skew-induced parts included [m/s].
    rib_heat_left, rib_heat_right : time-mean friction power per face [W]: the work rate
        of the rib forces the dynamics apply (Coulomb part mu Q v^2 / sqrt(v^2 + v_s^2)
        with the regularising speed v_s = ``SIGN_REGULARISATION`` of the integrator, i.e.
        mu Q |v| within 0.1 % for |v| > 1 m/s, plus the drag F_G tanh(v_g/v_s) v_g), plus
        the rib-gap squeeze film's dissipation with the model's ``rib_squeeze`` option.
    max_skew : max |alpha| [rad].  rib_contact_fraction : share of time with a rib force.
    mean_spin_moment : time-mean rib moment about the roller axis [N m].
    model : "full" | "reduced".  cost_s : CPU time of this process [s] (shared machine).
    n_rhs : right-hand-side calls.
    pv_contact_left, pv_contact_right : mean P |v| over the time the face is in contact
        [Pa m/s] (= pv_* / that face's contact fraction).
    contact_slide_speed : mean |v_i - v_r| (eq. 24) of the faces while in contact [m/s].
    pocket_friction_extra : time-mean cage-bar film friction of the rattling roller beyond
        what the quasi-static model counts at its steady pocket force [N] (orbit mean).
    bar_contact_fraction : share of time a cage bar touches the roller (elastic contact).
    bar_force_mean : time mean of the front + rear bar forces [N].
    """

    pv_left: float
    pv_right: float
    pv_peak_left: float
    pv_peak_right: float
    slip_speed: float
    rolling_slip_speed: float
    rib_heat_left: float
    rib_heat_right: float
    max_skew: float
    rib_contact_fraction: float
    mean_spin_moment: float
    model: str
    cost_s: float
    n_rhs: int
    series: dict[str, np.ndarray] = field(default_factory=dict, repr=False)
    surface_slip_speed: float = 0.0
    pv_contact_left: float = 0.0
    pv_contact_right: float = 0.0
    contact_slide_speed: float = 0.0
    pocket_friction_extra: float = 0.0
    bar_contact_fraction: float = 0.0
    bar_force_mean: float = 0.0

    @property
    def pv(self) -> float:
        """Larger of the two end faces' mean PV [Pa m/s]."""
        return max(self.pv_left, self.pv_right)

    @property
    def rib_heat(self) -> float:
        """Mean rib friction heat of one roller, both faces [W]."""
        return self.rib_heat_left + self.rib_heat_right


def _post(m: DynamicsModel, t: np.ndarray, x: np.ndarray, xd: np.ndarray, a: np.ndarray,
          ad: np.ndarray, spin: np.ndarray, z: np.ndarray | None = None,
          zd: np.ndarray | None = None, steady_pocket: Any = 0.0) -> dict[str, np.ndarray]:
    """PV, heat, slip and cage-bar forces along a sampled trajectory (exact sign of eq. 13).
    ``steady_pocket``: the quasi-static pocket force F_d [N] of the trajectory (scalar or
    per sample) for the extra pocket friction."""
    g = m.geom
    z = np.zeros_like(t) if z is None else z
    zd = np.zeros_like(t) if zd is None else zd
    _, _, front, rear = bar_forces(z, zd, a, 0.5 * g.roller_length, m.pocket_clearance,
                                   m.pocket_stiffness, m.pocket_viscosity,
                                   0.5 * g.roller_diameter, m.squeeze_floor)
    elastic = bar_forces(z, 0.0, a, 0.5 * g.roller_length, m.pocket_clearance,
                         m.pocket_stiffness, 0.0, 0.5 * g.roller_diameter, m.squeeze_floor)
    f_extra = 0.0
    # without the pocket DOF the roller is held centred: its bar force is not the cage's
    # reaction to F_d, so no extra friction is derived from it
    if m.pocket_dof and m.pocket_viscosity > 0.0 and m.pocket_length > 0.0:
        fd_ss = np.broadcast_to(np.asarray(steady_pocket, float), t.shape)
        f_extra = extra_pocket_friction(front - rear, t, spin, fd_ss, g.roller_diameter,
                                        m.pocket_length, m.pocket_viscosity,
                                        m.pocket_clearance)
    rf = rib_forces(g, a, x, inner_speed=m.inner_speed, cage_speed=m.cage_speed,
                    roller_spin=spin, skew_rate=ad, axial_speed=xd,
                    friction_coefficient=m.rib_friction,
                    mixture_viscosity=m.mixture_viscosity, smooth_sign=SIGN_REGULARISATION)
    heat_l, heat_r = rf.heat_left, rf.heat_right
    if getattr(m, "rib_squeeze", False):
        # the rib-gap squeeze film's dissipation is heat of the rib gap too
        _, _, sq_l, sq_r = squeeze_forces(g, a, x, ad, xd, m.mixture_viscosity,
                                          m.squeeze_floor)
        heat_l, heat_r = heat_l + sq_l, heat_r + sq_r
    wc = m.cage_speed
    u_i = (m.inner_speed - wc) * 0.5 * g.inner_raceway_diameter
    v_roll = u_i - spin * 0.5 * g.roller_diameter
    s_ax = -u_i * np.sin(a) - xd
    slip = np.sqrt(v_roll**2 + s_ax**2 + (ad * m.effective_length) ** 2 / 12.0)
    return {"pv_left": rf.pv_left, "pv_right": rf.pv_right, "heat_left": heat_l,
            "heat_right": heat_r, "slip": slip, "v_roll": np.abs(v_roll),
            "contact": (rf.normal_left + rf.normal_right) > 0, "skew": a,
            "contact_left": (rf.normal_left > 0).astype(float),
            "contact_right": (rf.normal_right > 0).astype(float),
            "slide_in_contact": (np.where(rf.normal_left > 0, rf.slide_speed_left, 0.0)
                                 + np.where(rf.normal_right > 0, rf.slide_speed_right, 0.0)),
            "spin_moment": rf.spin_moment, "tangential_force": rf.tangential_force, "t": t,
            "bar_force": front + rear,
            "bar_contact": ((elastic[2] + elastic[3]) > 0).astype(float),
            "pocket_extra": np.full(t.shape, f_extra)}


def _mean(v: np.ndarray, t: np.ndarray) -> float:
    span = t[-1] - t[0]
    return float(np.trapezoid(v, t) / span) if span > 0 else float(np.mean(v))


def _response(post: dict[str, np.ndarray], model: str, cost: float, n_rhs: int,
              g: RibGeometry, weights: list[tuple[float, dict]] | None = None
              ) -> RollerResponse:
    if weights is None:
        weights = [(1.0, post)]
    keys = ("pv_left", "pv_right", "heat_left", "heat_right", "slip", "v_roll",
            "spin_moment", "contact_left", "contact_right", "slide_in_contact",
            "pocket_extra", "bar_contact", "bar_force")
    mean = {k: sum(w * _mean(p[k], p["t"]) for w, p in weights) for k in keys}
    contact = sum(w * _mean(p["contact"].astype(float), p["t"]) for w, p in weights)
    f_l, f_r = mean["contact_left"], mean["contact_right"]
    return RollerResponse(
        pv_contact_left=mean["pv_left"] / f_l if f_l > 0 else 0.0,
        pv_contact_right=mean["pv_right"] / f_r if f_r > 0 else 0.0,
        contact_slide_speed=(mean["slide_in_contact"] / (f_l + f_r)
                             if f_l + f_r > 0 else 0.0),
        pv_left=mean["pv_left"], pv_right=mean["pv_right"],
        pocket_friction_extra=mean["pocket_extra"], bar_contact_fraction=mean["bar_contact"],
        bar_force_mean=mean["bar_force"],
        pv_peak_left=max(float(np.max(p["pv_left"])) for _, p in weights),
        pv_peak_right=max(float(np.max(p["pv_right"])) for _, p in weights),
        slip_speed=mean["v_roll"], rolling_slip_speed=mean["v_roll"],
        surface_slip_speed=mean["slip"],
        rib_heat_left=mean["heat_left"], rib_heat_right=mean["heat_right"],
        max_skew=max(float(np.max(np.abs(p["skew"]))) for _, p in weights),
        rib_contact_fraction=contact, mean_spin_moment=mean["spin_moment"],
        model=model, cost_s=cost, n_rhs=n_rhs,
        series={k: v for k, v in weights[0][1].items()} if model == "full" else {})
