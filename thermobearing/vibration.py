"""Lumped-parameter vibration model of a radially loaded ball bearing with cage slip.

Model of Luo et al. 2022 (seed paper 004, ``../shared/seeds/004_0105d7aba121b014.txt``):

* inner ring: two translations x, y (mass m_i, support damping c), radial load W along +x;
* every ball j: radial displacement d_j (mass m_r, damping c) and spin omega_j (inertia J_r);
* balls at theta_j = 2 pi (j - 1)/Z + omega_ca t (eq. 12), omega_ca = (1 - s_c) omega_ct
  (eqs. 1-3), i.e. the cage speed is *given* (from a slip or from the skidding solver);
* Hertz contacts with clearance and loss of contact (eqs. 11-16):
  delta_in = x cos theta + y sin theta - d_j - P_d/2, delta_out = d_j - P_d/2,
  Q = K max(delta, 0)^1.5 for each contact separately;
* sliding speeds (eqs. 4-8): dv_i = (omega_s - omega_ca) d_m (1 - gamma)/2 - omega_j r,
  dv_o = omega_ca d_m (1 + gamma)/2 - omega_j r, r = D cos(alpha)/2;
* friction F = mu(|dv|) Q sign(dv) (eqs. 9-10) with a traction law of
  :mod:`thermobearing.traction` (paper 004: ``linear_saturating``, Fig. 3);
* equations of motion (eqs. 17-22):
  m_i x'' + c x' + sum Q_in cos theta - sum F_in sin theta = W,
  m_i y'' + c y' + sum Q_in sin theta + sum F_in cos theta = 0,
  m_r d_j'' + c d_j' + Q_out - Q_in = 0,   J_r omega_j' = (F_in + F_out) D/2.

Sign note (eqs. 18-20): the friction on the ball at the inner contact points along the
orbital direction e_theta = (-sin theta, cos theta) when Delta v_i > 0; its reaction drags the
ring, F_in (sin theta, -cos theta). That is eq. 19 (N_x - F_x with F_x = sum F_in sin theta)
and eq. 20 with F_y = -sum F_in cos theta; the consistent form is used here. The seed's text
drops every minus sign (eq. 1 reads "(1 D/d_m cos alpha)"), so whether the paper prints
F_y = + or - sum F_in cos theta cannot be told from it. ``simulate(..., eq20_as_text=True)``
takes the + sign (the friction then pushes the ring along the rolling direction: physically
inconsistent) as a diagnostic only: with it, the kurtosis rises with slip and with mu_m as
paper 004's Fig. 12 says, and with the consistent sign it does not (measured,
``validation/cases/paper004_vibration_stats/SOURCE.md``).

Contact switch (eq. 15): the paper writes one coefficient lambda_j = 1 only if BOTH
deformations are positive. Read literally, a ball that is not already pressed into the outer
race is never loaded: from the paper's start (everything at zero) no contact ever closes and the
ring falls through the bearing (measured with an independent script, SOURCE.md). Each contact
is therefore switched on its own (delta > 0), which is what eq. 15's sentence "contact
deformation is not allowed to be below zero" asks for.

Optional extensions (off by default, so the paper's model is the default): per-ball diameter
deviations (off-size balls, paper 004 introduction refs 10-14: they put the cage frequency
into the signal), a rotating unbalance force at the shaft frequency and the centrifugal
force of the balls.

Integrators
-----------
``rk4``: classical Runge-Kutta at a fixed step (the paper's method, 1e-5 s).
``split``: Strang splitting (Strang 1968, SIAM J. Numer. Anal. 5: 506): the ball-spin
equations, the stiff part, are advanced over half steps by their *exact* solution with the
contact loads frozen (the torque is piecewise linear in omega_j because the traction law
is tabulated piecewise linearly, so the flow is a chain of exponentials); the mechanical
degrees of freedom take a full RK4 step with the spins frozen. Stability argument: the spin
relaxation rate lambda = (d mu/d dv)(Q_in + Q_out) r D/(2 J_r) reaches 1e6-1e7 1/s for the
paper's bearing (|lambda| h = 10-100 at 1e-5 s, outside RK4's stability interval
[-2.79, 0]), so plain RK4 at 1e-5 s chatters in the spins unless the traction slope is
small; the exact sub-flow is unconditionally stable and monotone. The remaining explicit
part is oscillatory with the largest frequency of the ball between its two contacts
(``stability_report``); RK4 is stable for omega h < 2.83. The scheme is second order
overall. Both share one right-hand side (numba).

Measured (``benchmarks/bm8_vibration.py``, SKF 6304, 2000 r/min, 2000 N, s_c = 5 %): RK4 at the
paper's 1e-5 s diverges (ball radial mode, omega h = 2.9). With the paper's mild slope (mu_m =
0.01, dv_m = 0.1 m/s) both schemes are limited by the same mechanical error and RK4 is 1.3-1.4
times cheaper at equal accuracy (the cost of the exact spin flows); with a steep slope (mu_m =
0.05, dv_m = 0.01 m/s) RK4 needs 3e-7 s and the split scheme is 4-7 times cheaper at errors of
1e-4-1e-3 (CPU time, one run; the ratios move by some 20 % between runs on a shared machine).
``method="auto"`` picks between them from :func:`stability_report`.

Example (issue 8's loop: simulate a slipping bearing, measure its cage speed back)::

    from thermobearing import signal as S, vibration as V
    from thermobearing.traction import make_traction_law
    p = V.paper004_parameters(ball_diameter_deviation=(2e-6,) + (0.0,) * 6)  # one big ball
    law = make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)
    r = V.simulate(p, 188.5, 2000.0, traction=law, cage_slip=0.08, duration=2.0,
                   sampling_rate=25600.0, anti_alias=True)  # 1800 r/min, 2000 N, as a DAQ
    r.statistics_x  # PTP, RMS, kurtosis [m/s^2, m/s^2, -] (paper 004 Table 2's indicators)
    est = S.estimate_cage_speed(r.acceleration_x, r.sampling_rate, 30.0, p.n_balls,
                                p.theoretical_cage_speed_ratio)
    est.csr, est.slip  # 0.3383, 0.080 ((1 - 0.08) x 0.3677)
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass, field, fields
from typing import Any, NamedTuple

import numba
import numpy as np

from .errors import (
    InputError,
    UnknownNameError,
    ValidityWarning,
    check_positive,
    check_range,
)

__all__ = [
    "StabilityReport",
    "VibrationParameters",
    "VibrationResult",
    "VibrationStatistics",
    "amplitude_spectrum",
    "paper004_parameters",
    "simulate",
    "simulate_sunnersjo",
    "simulate_with_skidding",
    "stability_report",
    "statistics",
    "traction_table",
]

METHODS = ("auto", "split", "rk4")


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
        ``radial_clearance`` defaults to half the diametral clearance.
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


# ---------------------------------------------------------------------------
# compiled kernel
# ---------------------------------------------------------------------------
# P layout
_Z, _D, _DM, _COSA, _PD, _KI, _KO, _MI, _MR, _J, _C, _CB, _WS, _WC, _W, _UNB, _CF, _FYS = range(18)


@numba.njit(cache=True)
def _mu_signed(v, tv, tmu):
    a = abs(v)
    n = tv.size
    if a >= tv[n - 1]:
        m = tmu[n - 1]
    else:
        lo = 0
        hi = n - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if tv[mid] <= a:
                lo = mid
            else:
                hi = mid
        m = tmu[lo] + (tmu[hi] - tmu[lo]) * (a - tv[lo]) / (tv[hi] - tv[lo])
    if v > 0.0:
        return m
    if v < 0.0:
        return -m
    return 0.0


@numba.njit(cache=True)
def _loads(t, y, P, dev, qi, qo, cth, sth):
    """Contact loads (eqs. 11-16) and cos/sin of the ball angles (eq. 12, by recurrence)."""
    z = int(P[_Z])
    half = 0.5 * P[_PD]
    c = math.cos(P[_WC] * t)
    s = math.sin(P[_WC] * t)
    dc = math.cos(2.0 * math.pi / z)
    ds = math.sin(2.0 * math.pi / z)
    for j in range(z):
        cth[j] = c
        sth[j] = s
        dr = y[0] * c + y[1] * s
        d = y[4 + j]
        din = dr - d - half + 0.5 * dev[j]
        dout = d - half + 0.5 * dev[j]
        qi[j] = P[_KI] * din * math.sqrt(din) if din > 0.0 else 0.0
        qo[j] = P[_KO] * dout * math.sqrt(dout) if dout > 0.0 else 0.0
        c, s = c * dc - s * ds, s * dc + c * ds


@numba.njit(cache=True)
def _rhs(t, y, P, dev, tv, tmu, qi, qo, cth, sth, dy):
    """Full right-hand side; also leaves the contact loads in qi, qo."""
    z = int(P[_Z])
    ws = P[_WS]
    wc = P[_WC]
    gam = P[_D] * P[_COSA] / P[_DM]
    r = 0.5 * P[_D] * P[_COSA]
    ai = 0.5 * (ws - wc) * P[_DM] * (1.0 - gam)
    ao = 0.5 * wc * P[_DM] * (1.0 + gam)
    _loads(t, y, P, dev, qi, qo, cth, sth)
    fx = P[_W] - P[_C] * y[2]
    fy = -P[_C] * y[3]
    if P[_UNB] != 0.0:
        fx += P[_UNB] * ws * ws * math.cos(ws * t)
        fy += P[_UNB] * ws * ws * math.sin(ws * t)
    cf = P[_CF] * P[_MR] * wc * wc * 0.5 * P[_DM]
    for j in range(z):
        c = cth[j]
        s = sth[j]
        w = y[4 + 2 * z + j]
        fin = qi[j] * _mu_signed(ai - r * w, tv, tmu) if qi[j] > 0.0 else 0.0
        fout = qo[j] * _mu_signed(ao - r * w, tv, tmu) if qo[j] > 0.0 else 0.0
        fx += -qi[j] * c + fin * s
        fy += -qi[j] * s - P[_FYS] * fin * c  # P[_FYS] = 1 (consistent) or -1 (eq20_as_text)
        dy[4 + j] = y[4 + z + j]
        dy[4 + z + j] = (qi[j] - qo[j] + cf - P[_CB] * y[4 + z + j]) / P[_MR]
        dy[4 + 2 * z + j] = 0.5 * P[_D] * (fin + fout) / P[_J]
    dy[0] = y[2]
    dy[1] = y[3]
    dy[2] = fx / P[_MI]
    dy[3] = fy / P[_MI]


@numba.njit(cache=True)
def _torque(w, a_i, a_o, q_i, q_o, r, half_d, tv, tmu):
    return half_d * (q_i * _mu_signed(a_i - r * w, tv, tmu)
                     + q_o * _mu_signed(a_o - r * w, tv, tmu))


@numba.njit(cache=True)
def _spin_flow(w0, tau, a_i, a_o, q_i, q_o, r, half_d, jr, tv, tmu):
    """Exact solution of J w' = T(w) over tau with frozen loads (T piecewise linear)."""
    if q_i <= 0.0 and q_o <= 0.0:
        return w0
    w = w0
    rem = tau
    for _ in range(4 * tv.size + 16):
        t0 = _torque(w, a_i, a_o, q_i, q_o, r, half_d, tv, tmu)
        if t0 == 0.0 or rem <= 0.0:
            return w
        direction = 1.0 if t0 > 0.0 else -1.0
        # nearest kink of T ahead: w where a contact's sliding speed a - r w = +-tv[k]
        bp = math.inf
        dist = math.inf
        eps = 1e-12 * (abs(w) + 1.0)
        for k in range(tv.size):
            for m in range(4):
                if m < 2:
                    if q_i <= 0.0:
                        continue
                    wb = (a_i - tv[k]) / r if m == 0 else (a_i + tv[k]) / r
                else:
                    if q_o <= 0.0:
                        continue
                    wb = (a_o - tv[k]) / r if m == 2 else (a_o + tv[k]) / r
                dd = (wb - w) * direction
                if eps < dd < dist:
                    dist = dd
                    bp = wb
        probe = w + direction * (0.5 * dist if dist < math.inf else 1.0)
        b = (_torque(probe, a_i, a_o, q_i, q_o, r, half_d, tv, tmu) - t0) / (probe - w)
        if b == 0.0:
            t_bp = jr * dist / abs(t0) if dist < math.inf else math.inf
            if t_bp >= rem:
                return w + t0 * rem / jr
            w = bp
            rem -= t_bp
            continue
        wstar = w - t0 / b  # root of the segment's line
        if b < 0.0 and (wstar - w) * direction <= dist:
            return wstar + (w - wstar) * math.exp(b * rem / jr)
        ratio = (bp - wstar) / (w - wstar) if dist < math.inf else math.inf
        t_bp = jr / b * math.log(ratio) if ratio > 0.0 and ratio < math.inf else math.inf
        if t_bp >= rem or t_bp <= 0.0:
            return wstar + (w - wstar) * math.exp(b * rem / jr)
        w = bp
        rem -= t_bp
    return w


@numba.njit(cache=True)
def _spin_sub(t, y, tau, P, dev, tv, tmu, qi, qo, cth, sth):
    """Spin sub-flow over tau with the loads of (t, y) frozen."""
    z = int(P[_Z])
    ws = P[_WS]
    wc = P[_WC]
    gam = P[_D] * P[_COSA] / P[_DM]
    r = 0.5 * P[_D] * P[_COSA]
    ai = 0.5 * (ws - wc) * P[_DM] * (1.0 - gam)
    ao = 0.5 * wc * P[_DM] * (1.0 + gam)
    _loads(t, y, P, dev, qi, qo, cth, sth)
    for j in range(z):
        k = 4 + 2 * z + j
        y[k] = _spin_flow(y[k], tau, ai, ao, qi[j], qo[j], r, 0.5 * P[_D], P[_J], tv, tmu)


@numba.njit(cache=True)
def _integrate(method, y, t0, h, sub, n_out, P, dev, tv, tmu, ax, ay, xs, ys, q0, f0):
    """Advance y in place; record n_out samples every `sub` steps of size h.

    method 0: RK4 on all equations. method 1: Strang splitting, spin(h/2) - mechanics RK4(h)
    - spin(h/2); the two spin half-flows that meet between steps inside an output interval
    use the same frozen loads and are merged into one flow over h (exactly equivalent).
    """
    n = y.size
    z = int(P[_Z])
    nmech = 4 + 2 * z
    m = nmech if method == 1 else n
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    tmp = np.empty(n)
    dy = np.empty(n)
    qi = np.empty(z)
    qo = np.empty(z)
    cth = np.empty(z)
    sth = np.empty(z)
    t = t0
    evals = 0
    gam = P[_D] * P[_COSA] / P[_DM]
    r = 0.5 * P[_D] * P[_COSA]
    ai = 0.5 * (P[_WS] - P[_WC]) * P[_DM] * (1.0 - gam)
    for i in range(n_out):
        _rhs(t, y, P, dev, tv, tmu, qi, qo, cth, sth, dy)
        evals += 1
        ax[i] = dy[2]
        ay[i] = dy[3]
        xs[i] = y[0]
        ys[i] = y[1]
        q0[i] = qi[0]
        f0[i] = qi[0] * _mu_signed(ai - r * y[4 + 2 * z], tv, tmu)
        for step in range(sub):
            if method == 1:
                _spin_sub(t, y, 0.5 * h if step == 0 else h, P, dev, tv, tmu, qi, qo, cth,
                          sth)
            _rhs(t, y, P, dev, tv, tmu, qi, qo, cth, sth, k1)
            for q in range(m):
                tmp[q] = y[q] + 0.5 * h * k1[q]
            for q in range(m, n):
                tmp[q] = y[q]
            _rhs(t + 0.5 * h, tmp, P, dev, tv, tmu, qi, qo, cth, sth, k2)
            for q in range(m):
                tmp[q] = y[q] + 0.5 * h * k2[q]
            _rhs(t + 0.5 * h, tmp, P, dev, tv, tmu, qi, qo, cth, sth, k3)
            for q in range(m):
                tmp[q] = y[q] + h * k3[q]
            _rhs(t + h, tmp, P, dev, tv, tmu, qi, qo, cth, sth, k4)
            for q in range(m):
                y[q] += h / 6.0 * (k1[q] + 2.0 * k2[q] + 2.0 * k3[q] + k4[q])
            evals += 4
            t += h
        if method == 1:
            _spin_sub(t, y, 0.5 * h, P, dev, tv, tmu, qi, qo, cth, sth)
    return evals


# ---------------------------------------------------------------------------
# results and statistics
# ---------------------------------------------------------------------------
class VibrationStatistics(NamedTuple):
    """Statistical indicators of an acceleration record (paper 004 section 4.3)."""

    ptp: float  #: peak-to-peak [m/s^2]
    rms: float  #: root mean square [m/s^2]
    kurtosis: float  #: Pearson kurtosis [-] (3 for Gaussian)


def statistics(acceleration: Any) -> VibrationStatistics:
    """Peak-to-peak, RMS and kurtosis of a record (paper 004 section 4.3, Table 2).

    PTP = max - min; RMS = sqrt(mean(a^2)) (about zero, as a vibration level);
    kurtosis = mean((a - mean)^4) / var^2 (Pearson's, 3 for a Gaussian signal).
    """
    a = np.asarray(acceleration, dtype=float)
    if a.ndim != 1 or a.size < 4 or not np.all(np.isfinite(a)):
        raise InputError("acceleration", f"shape {a.shape}", "a finite 1-D record")
    d = a - a.mean()
    var = float(np.mean(d * d))
    if var <= 0.0:
        raise InputError("acceleration", "a constant record", "a varying record")
    return VibrationStatistics(float(a.max() - a.min()), float(np.sqrt(np.mean(a * a))),
                               float(np.mean(d**4) / var**2))


def amplitude_spectrum(x: Any, sampling_rate: float) -> tuple[np.ndarray, np.ndarray]:
    """One-sided amplitude spectrum (Hann window, amplitude-corrected): (f [Hz], |A|)."""
    a = np.asarray(x, dtype=float)
    a = a - a.mean()
    w = np.hanning(a.size)
    spec = np.abs(np.fft.rfft(a * w)) * 2.0 / w.sum()
    return np.fft.rfftfreq(a.size, 1.0 / sampling_rate), spec


@dataclass(frozen=True)
class VibrationResult:
    """Time series of one simulation (after the settling time).

    Attributes
    ----------
    time : [s] (from the start of the simulation). sampling_rate : output rate [Hz].
    acceleration_x, acceleration_y : inner-ring acceleration [m/s^2] (x along the load).
    displacement_x, displacement_y : inner-ring displacement [m].
    first_ball_inner_load, first_ball_inner_friction : Q_in and F_in of ball 1 [N].
    shaft_speed, cage_speed : [rad/s]; cage_slip : s_c [-].
    method, step : integrator and its step [s]; rhs_evaluations; wall_time [s].
    parameters : the :class:`VibrationParameters`.
    """

    time: np.ndarray
    sampling_rate: float
    acceleration_x: np.ndarray
    acceleration_y: np.ndarray
    displacement_x: np.ndarray
    displacement_y: np.ndarray
    first_ball_inner_load: np.ndarray
    first_ball_inner_friction: np.ndarray
    shaft_speed: float
    cage_speed: float
    cage_slip: float
    radial_load: float
    method: str
    step: float
    rhs_evaluations: int
    wall_time: float
    parameters: VibrationParameters = field(repr=False)

    @property
    def statistics_x(self) -> VibrationStatistics:
        """PTP, RMS, kurtosis of the x acceleration (paper 004 Table 2)."""
        return statistics(self.acceleration_x)

    @property
    def ball_pass_frequency_outer(self) -> float:
        """Z omega_c / 2 pi [Hz] of this run (paper 004 eq. 27)."""
        return self.parameters.n_balls * self.cage_speed / (2.0 * math.pi)

    def spectrum(self, component: str = "x") -> tuple[np.ndarray, np.ndarray]:
        """Amplitude spectrum of the ring acceleration ("x" or "y")."""
        a = self.acceleration_x if component == "x" else self.acceleration_y
        return amplitude_spectrum(a, self.sampling_rate)


@dataclass(frozen=True)
class StabilityReport:
    """Largest rates of the linearised model at the static load [1/s].

    ball_radial : sqrt((k_in + k_out)/m_r) of the most loaded ball [rad/s].
    ring : sqrt(k_ring/m_i), k_ring the radial stiffness of the ring [rad/s].
    spin : (d mu / d dv) (Q_in + Q_out) r D / (2 J_r) of the most loaded ball [1/s].
    damping : c / m_r [1/s]. rk4_max_step : 2.79 / max(|rates|) [s] (RK4 stability bound
    on the real axis; 2.83 on the imaginary axis).
    """

    ball_radial: float
    ring: float
    spin: float
    damping: float
    rk4_max_step: float
    split_max_step: float


def stability_report(params: VibrationParameters, radial_load: float,
                     traction: Any) -> StabilityReport:
    """Stiffness of the model from a static (Stribeck-type) load estimate.

    Q_max ~ 5 W / (Z cos alpha) (Stribeck; Harris & Kotzalas 2007 vol. 1 ch. 7); the contact
    stiffness dQ/d delta = 1.5 K^(2/3) Q^(1/3); the inner and the outer contact act in
    series on the ring and in parallel on the ball.
    """
    check_positive("radial_load", radial_load)
    q = 5.0 * radial_load / (params.n_balls * math.cos(params.contact_angle))
    ki = 1.5 * params.inner_stiffness ** (2 / 3) * q ** (1 / 3)
    ko = 1.5 * params.outer_stiffness ** (2 / 3) * q ** (1 / 3)
    w_ball = math.sqrt((ki + ko) / params.ball_mass)
    k_series = ki * ko / (ki + ko)
    w_ring = math.sqrt(2.0 * k_series / params.inner_ring_mass)
    tv, tmu = traction_table(traction, 10.0)
    slope = float(np.max(np.diff(tmu) / np.diff(tv))) if tv.size > 1 else 0.0
    r = 0.5 * params.ball_diameter * math.cos(params.contact_angle)
    spin = slope * 2.0 * q * r * params.ball_diameter / (2.0 * params.ball_inertia)
    damp = params.ball_damping / params.ball_mass
    rk4 = 2.79 / max(w_ball, spin, damp, w_ring)
    split = 2.79 / max(w_ball, damp, w_ring)
    return StabilityReport(w_ball, w_ring, spin, damp, rk4, split)


def simulate(params: VibrationParameters, shaft_speed: float, radial_load: float, *,
             traction: Any, cage_slip: float = 0.0, cage_speed: float | None = None,
             duration: float = 0.25, settle_time: float = 0.05,
             sampling_rate: float = 100_000.0, method: str = "auto",
             max_step: float | None = None, eq20_as_text: bool = False,
             anti_alias: bool = False) -> VibrationResult:
    """Integrate the paper 004 model and return the ring acceleration.

    Parameters
    ----------
    params : :class:`VibrationParameters`.
    shaft_speed : omega_s of the inner ring [rad/s] (> 0).
    radial_load : W [N] (> 0), along +x.
    traction : a traction law of :mod:`thermobearing.traction` (pressure-independent),
        e.g. ``make_traction_law("linear_saturating", mu_max=0.01, slip_speed_max=0.1)``.
    cage_slip : s_c [-] in (-1, 1) (paper 004 eq. 3: omega_ca = (1 - s_c) omega_ct);
        negative is over-skidding. Ignored when ``cage_speed`` is given.
    cage_speed : omega_ca [rad/s], e.g. from the skidding solver (CSR * omega_s).
    duration : recorded time after settling [s]; settle_time : discarded start [s]
        (the ring starts at rest at x = y = 0, the balls at d = 0 with the spin of eq. 4-8
        balance, as in paper 004 section 4).
    sampling_rate : output rate [Hz]; the step is 1/(sampling_rate k) with the smallest
        integer k that keeps it <= ``max_step`` [s]. The samples are the model state at
        those instants (point sampling, as paper 004's statistics are computed): the
        model rings at the ball's radial frequency between its contacts (tens of kHz,
        :func:`stability_report`), so at a rate below twice that frequency the record holds
        alias lines -- a ``ValidityWarning`` says so. Use ``anti_alias=True`` for a record as
        a data-acquisition system with an anti-aliasing filter takes it (e.g. to feed
        :func:`thermobearing.signal.estimate_cage_speed`: a point-sampled 25.6 kHz record
        of an off-size ball made it report half or a third of the cage speed).
    anti_alias : record at an integer multiple q of ``sampling_rate`` that is at least 2.5
        times the ball's radial frequency and reduce to ``sampling_rate`` with a zero-phase
        low-pass FIR (``scipy.signal.resample_poly``, Kaiser window): accelerations and
        displacements are filtered, the ball-1 load and friction are taken every q-th
        sample. Default False (point sampling, the validated statistics).
    method : "split", "rk4" (paper 004's scheme) or "auto": RK4 when its stability bound
        (:func:`stability_report`) is at least half that of the split scheme (a mild traction
        slope: RK4 is fourth order and cheaper at equal accuracy), else "split" (a steep
        traction slope makes the spin equations stiff; see the module notes and bm8).
    max_step : [s]; None: 1e-5 s (paper 004) or 0.85 times the explicit stability bound of
        :func:`stability_report` for the method, whichever is smaller.
    eq20_as_text : diagnostic only (default False). True reverses the sign of the y component
        of the inner-contact friction on the ring, i.e. eq. 20 read as the seed's text shows it
        (N_y - F_y with F_y = + sum F_in cos theta): the friction then pushes the ring along the
        direction of rolling instead of dragging it, which is physically inconsistent (module
        notes). It exists to measure what paper 004's Fig. 12 trends would be under that
        reading (``validation/cases/paper004_vibration_stats/SOURCE.md``); never use it for
        predictions.

    Raises
    ------
    ConvergenceError : the integration diverged (a step above the stability bound).

    Warns
    -----
    ValidityWarning : a ``max_step`` that makes the step larger than the explicit stability
        bound of the method (:func:`stability_report`): RK4 above its bound for the spin
        equations chatters without diverging (measured: RMS 68 m/s^2 instead of 0.50 with a
        steep traction law at 3.3e-6 s, bound 2.7e-7 s); a point-sampled record below twice
        the ball's radial frequency (see ``sampling_rate``).
    """
    if method not in METHODS:
        raise InputError("method", method, f"one of {METHODS}")
    check_positive("shaft_speed", shaft_speed)
    check_positive("radial_load", radial_load)
    check_positive("duration", duration)
    check_positive("settle_time", settle_time, allow_zero=True)
    check_positive("sampling_rate", sampling_rate)
    rep = stability_report(params, radial_load, traction)
    if method == "auto":
        method = "rk4" if rep.rk4_max_step >= 0.5 * rep.split_max_step else "split"
    if max_step is None:
        max_step = min(1e-5, 0.85 * (rep.split_max_step if method == "split"
                                     else rep.rk4_max_step))
    check_positive("max_step", max_step)
    wct = params.theoretical_cage_speed_ratio * shaft_speed
    if cage_speed is None:
        check_range("cage_slip", cage_slip, -1.0, 1.0, low_inclusive=False,
                    high_inclusive=False)
        wc = (1.0 - cage_slip) * wct
    else:
        check_range("cage_speed", cage_speed, 0.0, shaft_speed, low_inclusive=False,
                    high_inclusive=False, unit="rad/s")
        wc = float(cage_speed)
        cage_slip = 1.0 - wc / wct
    z = params.n_balls
    dev = np.zeros(z) if not params.ball_diameter_deviation else np.array(
        params.ball_diameter_deviation, dtype=float)
    tv, tmu = traction_table(traction, 2.0 * shaft_speed * params.pitch_diameter)
    P = np.array([z, params.ball_diameter, params.pitch_diameter,
                  math.cos(params.contact_angle), params.radial_clearance,
                  params.inner_stiffness, params.outer_stiffness, params.inner_ring_mass,
                  params.ball_mass, params.ball_inertia, params.support_damping,
                  params.ball_damping, shaft_speed, wc, radial_load, params.unbalance,
                  1.0 if params.centrifugal else 0.0, -1.0 if eq20_as_text else 1.0],
                 dtype=float)
    f_ball = rep.ball_radial / (2.0 * math.pi)
    q_rec = 1
    if anti_alias:
        q_rec = max(1, math.ceil(2.5 * f_ball / sampling_rate))
    elif sampling_rate < 2.0 * f_ball:
        warnings.warn(ValidityWarning(
            f"vibration.simulate: the record is point-sampled at {sampling_rate:g} Hz, below "
            f"twice the ball's radial frequency ({f_ball:.4g} Hz, stability_report): model "
            f"content above {sampling_rate / 2:g} Hz aliases into it (alias lines in a "
            "spectrum or an envelope analysis); anti_alias=True records it as a "
            "data-acquisition system with an anti-aliasing filter would"), stacklevel=2)
    dt_out = 1.0 / (sampling_rate * q_rec)
    sub = max(1, math.ceil(dt_out / max_step * (1 - 1e-12)))
    h = dt_out / sub
    bound = rep.split_max_step if method == "split" else rep.rk4_max_step
    if h > bound:
        warnings.warn(ValidityWarning(
            f"vibration.simulate: step {h:.3g} s (max_step {max_step:.3g} s) is above the "
            f"{method} stability bound {bound:.3g} s of this case (ball radial "
            f"{rep.ball_radial:.3g} rad/s, spin relaxation {rep.spin:.3g} 1/s, "
            "stability_report): the integration may diverge or, worse, chatter to a bounded "
            f"but wrong record; use max_step <= {0.85 * bound:.3g} s"
            + (" or method='split'" if method == "rk4" and rep.split_max_step > bound
               else "") + " (max_step=None picks a stable step)"), stacklevel=2)
    y = np.zeros(4 + 3 * z)
    g = params.gamma
    # spin of equal-load balance of eqs. 4-8: dv_i = -dv_o (pure rolling when s_c = 0)
    y[4 + 2 * z:] = params.pitch_diameter * ((shaft_speed - wc) * (1 - g) + wc * (1 + g)) / (
        2.0 * params.ball_diameter * math.cos(params.contact_angle))
    n_settle = int(round(settle_time * sampling_rate)) * q_rec
    n_rec = int(round(duration * sampling_rate))
    if n_rec < 4:
        raise InputError("duration", duration, f"at least 4 samples at {sampling_rate:g} Hz")
    n_rec *= q_rec
    mth = 1 if method == "split" else 0
    start = time.perf_counter()
    evals = 0
    scratch = [np.empty(max(n_settle, 1)) for _ in range(6)]
    if n_settle:
        evals += _integrate(mth, y, 0.0, h, sub, n_settle, P, dev, tv, tmu, *scratch)
    out = [np.empty(n_rec) for _ in range(6)]
    evals += _integrate(mth, y, n_settle * dt_out, h, sub, n_rec, P, dev, tv, tmu, *out)
    wall = time.perf_counter() - start
    if not np.all(np.isfinite(out[0])):
        from .errors import ConvergenceError

        raise ConvergenceError(f"vibration.{method}", math.inf,
                               f"the integration diverged (non-finite acceleration) at step "
                               f"{h:.3g} s; the {method} stability bound of this case is "
                               f"{bound:.3g} s: use max_step <= {0.85 * bound:.3g} s or "
                               "max_step=None", {"step": h, "stability": rep})
    if q_rec > 1:
        from scipy.signal import resample_poly

        out = [resample_poly(a, 1, q_rec, padtype="line") for a in out[:4]] + [
            a[::q_rec] for a in out[4:]]
        n_settle //= q_rec
        n_rec //= q_rec
        dt_out *= q_rec
    t = (n_settle + np.arange(n_rec)) * dt_out
    return VibrationResult(t, float(sampling_rate), out[0], out[1], out[2], out[3], out[4],
                           out[5], float(shaft_speed), float(wc), float(cage_slip),
                           float(radial_load), method, h, int(evals), wall, params)


def simulate_with_skidding(bearing: Any, lubricant: Any, shaft_speed: float,
                           radial_load: float, temperature: float, *, supply: Any,
                           traction: Any, params: VibrationParameters | None = None,
                           skidding_options: dict | None = None, **simulate_options: Any
                           ) -> tuple[VibrationResult, Any]:
    """Vibration of a bearing whose cage speed comes from the skidding solver.

    Calls :func:`thermobearing.skidding.solve` (quasi-dynamic traction/drag balance, axial
    load 0: the planar model of paper 004 is for radial load) and runs :func:`simulate` with
    ``cage_speed = CSR * shaft_speed``. ``params`` defaults to
    :meth:`VibrationParameters.from_bearing` with paper 004 Table 1's ring mass (0.4 kg) and
    damping (350 N s/m), which are estimates for any other bearing. Returns (vibration result,
    skidding result); raises :class:`~thermobearing.errors.ConvergenceError` when the
    skidding solver did not converge.
    """
    from . import skidding
    from .errors import ConvergenceError

    sk = skidding.solve(bearing, lubricant, shaft_speed, radial_load, 0.0, temperature,
                        supply=supply, **(skidding_options or {}))
    if not getattr(sk, "converged", False):
        raise ConvergenceError("skidding.solve", float(getattr(sk, "residual_norm", math.inf)),
                               "the cage speed for the vibration model is not available")
    if params is None:
        params = VibrationParameters.from_bearing(bearing, inner_ring_mass=0.4,
                                                  support_damping=350.0)
    result = simulate(params, shaft_speed, radial_load, traction=traction,
                      cage_speed=float(sk.cage_speed_ratio) * shaft_speed, **simulate_options)
    return result, sk


# Sunnersjo's 2-DOF reference model lives in vibration_sunnersjo.py (re-exported here)
from .vibration_sunnersjo import simulate_sunnersjo  # noqa: E402
