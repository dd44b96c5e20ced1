"""Viscoelastic (Maxwell) shear of the Hertz-zone film of a roller-raceway line contact.

One job: the Hertz-zone traction of a lubricated line contact when the oil's elastic shear
compliance is not negligible (Johnson & Tevaarwerk 1977 [johnson_tevaarwerk1977_traction]),
as an option of the roller skidding solver (``build_model(..., fluid_shear_modulus=G)``).

Why. The closed-form drag of :mod:`thermobearing.skidding.roller_fluid` shears the Hertz
zone with a point-wise flow curve (Newtonian, or Eyring, capped by Lambda p) at the viscosity
of the local Hertz pressure. At the pressures of heavily loaded roller contacts (1-1.5 GPa)
that viscosity is 1e5-1e8 Pa s, and the Newtonian stress eta(p) V / h rises with the roller
load like exp(alpha p_H): a more heavily loaded roller transmits far more traction at the same
sliding. The oil in an EHL contact does not follow that flow curve at small slip: it passes
the contact in 2b/u_e ~ 10 us, much shorter than its relaxation time eta/G, and behaves as an
elastic solid (Deborah number De = eta u_e / (G b) >> 1, Johnson & Tevaarwerk 1977, their
Maxwell model): the shear stress builds up along the contact as G times the accumulated shear
strain, and the traction at small slip is linear in the slide-to-roll ratio with a slope set
by G, not by eta.

Model (Johnson & Tevaarwerk 1977, eq. of the Maxwell element in steady flow through the
contact, fluid carried at the mean surface speed u_e)::

    u_e d tau / ds = G (V / h - gamma_v(tau))         s = distance from the Hertz-zone inlet

with the viscous strain rate gamma_v(tau) the inverse of the steady flow curve tau_ss(V) of the
model's traction law (Newtonian/Eyring with the limiting shear stress Lambda p,
:mod:`thermobearing.traction`) and tau = 0 where the oil enters the Hertz zone (the stress of
the low-pressure inlet relaxes within eta0 u_e / G ~ 1 nm). On a cell of the Hertz zone with
the midpoint pressure the flow curve is replaced by its secant, gamma_v = tau V / (h tau_ss),
so that the cell is a linear Maxwell element with relaxation length
lambda = tau_ss h u_e / (G V) and the exact solution

    tau(s) = tau_ss + (tau_0 - tau_ss) exp(-(s - s_0) / lambda).

This is exact for the Newtonian film (lambda = eta u_e / G) and reaches the limiting shear
stress asymptotically instead of with a kink where the cap applies (secant of the capped
curve). Limits: lambda << b (low pressure, the viscous regime of paper 000's light loads):
tau = tau_ss, the point-wise law; lambda >> b (De >> 1): tau = G V s / (h u_e), the elastic
regime, and the traction of a contact is 2 G l b^2 V / (h u_e) = (16/pi) G R Q V /
(E' h u_e), linear in the roller load Q.

Parameter. G [Pa], the lubricant's elastic shear modulus in the contact. Johnson &
Tevaarwerk (1977) and later traction studies give values of order 0.1-3 GPa rising with
pressure [R: recalled order of magnitude, not checked against their tables]; none of the
seed papers gives G. Results that depend only on the elastic regime scale with 1/G.

All functions are vectorised over rollers; SI units.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import check_positive
from .roller_fluid import LineContactForces

#: cells of the Hertz zone in the Maxwell integration
N_CELLS = 64


@dataclass(frozen=True)
class _NoHertzShear:
    """Traction law with zero stress: lets the base drag model compute only the inlet/outlet
    shear, the Poiseuille and rolling forces (the Hertz zone is added by this module)."""

    requires_film: bool = True

    def shear_stress(self, slide_speed: Any, pressure: Any, film_thickness: Any = None,
                     temperature: Any = None) -> tuple[np.ndarray, np.ndarray]:
        z = np.zeros(np.broadcast(np.asarray(slide_speed), np.asarray(pressure)).shape)
        return z, z


def maxwell_hertz_traction(slide: Any, entrainment_speed: Any, max_pressure: Any,
                           half_width: Any, film_thickness: Any, length: float,
                           traction_law: Any, temperature: float, shear_modulus: float | None,
                           n_cells: int = N_CELLS, pressure: Any = None
                           ) -> tuple[np.ndarray, np.ndarray]:
    """Hertz-zone shear force of Maxwell films (module docstring) and its slope.

    Parameters
    ----------
    slide : (Z,) sliding speed V = u_race - u_roller [m/s] (either sign).
    entrainment_speed : (Z,) u_e = |u_race + u_roller| / 2 [m/s] (> 0).
    max_pressure : (Z,) Hertz p_H [Pa] (0: no contact, force 0).
    half_width : (Z,) Hertz half-width b [m].
    film_thickness : (Z,) central film h_c [m] (finite where loaded).
    length : contact length l [m].
    traction_law : steady flow curve ``shear_stress(slide_speed, pressure, film_thickness,
        temperature) -> (stress [Pa], d stress / d speed [Pa s/m])``
        (:mod:`thermobearing.traction`).
    temperature : film temperature [K].
    shear_modulus : elastic shear modulus of the oil G [Pa] (> 0); None: viscous film (the
        traction law point by point, no elastic build-up).
    n_cells : cells across the Hertz zone.
    pressure : (Z, n_cells) film pressure at the cell midpoints x/b = -1 + (k + 1/2) 2/n,
        upstream first [Pa] (None: the semi-elliptic Hertz pressure;
        :func:`thermobearing.skidding.roller_pressure.hertz_zone_pressure`).

    Returns
    -------
    force : (Z,) shear force on the roller along sign(V) [N].
    dforce : (Z,) d force / d V [N s/m] (>= 0).

    Reference: Johnson & Tevaarwerk 1977 (Maxwell element, steady flow through the contact).
    """
    if shear_modulus is not None:
        check_positive("fluid_shear_modulus", shear_modulus)
    v = np.asarray(slide, dtype=float)
    p_h = np.asarray(max_pressure, dtype=float)
    v, ue, p_h, b, h = np.broadcast_arrays(v, np.asarray(entrainment_speed, dtype=float), p_h,
                                           np.asarray(half_width, dtype=float),
                                           np.asarray(film_thickness, dtype=float))
    loaded = (p_h > 0.0) & (b > 0.0)
    speed = np.abs(v)
    h_s = np.where(loaded & np.isfinite(h), h, 1.0)
    ue_s = np.maximum(ue, 1e-9)
    # cell midpoints from the inlet: x/b = -1 + (k + 1/2) 2/n
    xm = cell_midpoints(n_cells)
    if pressure is None:
        pres = np.where(loaded, p_h, 0.0)[..., None] * np.sqrt(1.0 - xm**2)
    else:
        pres = np.where(loaded[..., None], np.asarray(pressure, dtype=float), 0.0)
    shape = pres.shape
    ss, dss = traction_law.shear_stress(speed[..., None] * np.ones(n_cells), pres,
                                        h_s[..., None] * np.ones(shape),
                                        temperature * np.ones(shape))
    ss = np.asarray(ss, dtype=float)
    dss = np.asarray(dss, dtype=float)
    delta = (2.0 * b / n_cells)[..., None] * np.ones(shape)
    if shear_modulus is None:
        total = np.sum(ss * delta, axis=-1)
        dtotal = np.sum(dss * delta, axis=-1)
        return (np.where(loaded, length * total, 0.0) * np.sign(v),
                np.where(loaded, length * dtotal, 0.0))
    sp = speed[..., None]
    # secant viscous coefficient tau_ss / V [Pa s/m] at every V > 0 (its V -> 0 limit, the
    # slope, at V = 0). Not the slope below 1e-12 m/s: a cold film under load saturates
    # there (eta(p) V / h reaches the limiting stress at ~1e-24 m/s), where the slope is ~0
    # and made the cell viscous: measured, CRB 50x75x16, 20 kN, ISO VG 46 at 20 degC,
    # G = 1 GPa, 276 N of Hertz-zone traction at V = 1e-12 m/s against 2.9e-8 N at 2e-12
    # (the elastic, G-limited value, linear in V). Its derivative is taken as 0 there (the
    # linear flow curve's, cancellation-free)
    zero = sp <= 0.0
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        sec = np.where(zero, dss, ss / np.where(zero, 1.0, sp))
    sec = np.where(np.isfinite(sec), sec, dss)
    tiny = sp <= 1e-12
    dsec = np.where(tiny, 0.0, (dss - sec) / np.where(tiny, 1.0, sp))
    scale = (h_s * ue_s / shear_modulus)[..., None]
    lam = sec * scale  # relaxation length [m]
    dlam = dsec * scale
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        lam_s = np.where(lam > 0.0, lam, 1.0)
        r = np.where(lam > 0.0, delta / lam_s, np.inf)
        fin = np.isfinite(r)
        r_s = np.where(fin, r, 1.0)
        e = np.where(fin, np.exp(-r_s), 0.0)
        # 1 - e and 1 - g without cancellation (g = (1 - e)/r, the mean of exp(-t/lambda)
        # over a cell); series for small r
        om_e = np.where(fin, -np.expm1(-r_s), 1.0)
        om_g = np.where(fin, np.where(r_s < 1e-3, r_s / 2 - r_s**2 / 6 + r_s**3 / 24,
                                      (r_s + np.expm1(-r_s)) / r_s), 1.0)
        g = 1.0 - om_g
        de = np.where(fin, e * r_s / lam_s * dlam, 0.0)
        dg = np.where(fin, (g - e) / lam_s * dlam, 0.0)
    tau = np.zeros(shape[:-1])
    dtau = np.zeros(shape[:-1])
    total = np.zeros(shape[:-1])
    dtotal = np.zeros(shape[:-1])
    for k in range(n_cells):
        s_k, ds_k = ss[..., k], dss[..., k]
        e_k, g_k, de_k, dg_k = e[..., k], g[..., k], de[..., k], dg[..., k]
        diff = tau - s_k
        mean = tau * g_k + s_k * om_g[..., k]
        dmean = ds_k * om_g[..., k] + dtau * g_k + diff * dg_k
        total = total + mean * delta[..., k]
        dtotal = dtotal + dmean * delta[..., k]
        tau, dtau = (tau * e_k + s_k * om_e[..., k],
                     ds_k * om_e[..., k] + dtau * e_k + diff * de_k)
    force = np.where(loaded, length * total, 0.0)
    dforce = np.where(loaded, length * dtotal, 0.0)
    return force * np.sign(v), dforce


def cell_midpoints(n_cells: int = N_CELLS) -> np.ndarray:
    """x/b of the Hertz-zone cell midpoints, upstream first [-]."""
    return -1.0 + (np.arange(n_cells) + 0.5) * 2.0 / n_cells


def maxwell_contact_forces(base: Callable[..., LineContactForces], shear_modulus: float | None,
                           film_pressure: str = "hertz") -> Callable[..., LineContactForces]:
    """A drag model (signature of ``closed_form_contact_forces``) whose Hertz-zone shear is
    computed here: the Maxwell film of :func:`maxwell_hertz_traction` (G [Pa]; None: viscous)
    under the Hertz-zone pressure ``film_pressure`` ("hertz" or "regime_min",
    :func:`thermobearing.skidding.roller_pressure.hertz_zone_pressure`); everything else
    (film, inlet/outlet Newtonian shear, Poiseuille and rolling forces) comes from ``base``.
    An exact sliding speed ``slide`` (keyword of ``base``, the slide-variable solve of
    :mod:`~thermobearing.skidding.roller_slides`) shears the Hertz zone too; the model takes
    it when ``base`` does (``exact_slide``)."""
    from .roller_pressure import FILM_PRESSURE_MODELS, hertz_zone_pressure

    if shear_modulus is not None:
        check_positive("fluid_shear_modulus", shear_modulus)
    if film_pressure not in FILM_PRESSURE_MODELS:
        from ..errors import InputError

        raise InputError("film_pressure", film_pressure, FILM_PRESSURE_MODELS)
    null_law = _NoHertzShear()
    xb = cell_midpoints()

    @functools.wraps(base)
    def forces(load: Any, length: float, radius: float, effective_modulus: float,
               u_race: Any, u_roller: Any, *, traction_law: Any, temperature: float,
               **kw: Any) -> LineContactForces:
        side = base(load, length, radius, effective_modulus, u_race, u_roller,
                    traction_law=null_law, temperature=temperature, **kw)
        ur = np.asarray(u_race, dtype=float)
        uro = np.asarray(u_roller, dtype=float)
        ue = np.maximum(0.5 * np.abs(ur + uro), 1e-6)
        pres = None
        if film_pressure != "hertz":
            pres = hertz_zone_pressure(film_pressure, xb, side.max_pressure, side.half_width,
                                       np.asarray(load, dtype=float) / length, 2.0 * ue,
                                       radius, kw["eta0"])
        # the sliding speed given exactly (the slide-variable solve, ``slide`` of the base
        # model) or the difference of the surface speeds
        slide = kw.get("slide")
        v = ur - uro if slide is None else np.broadcast_to(np.asarray(slide, dtype=float),
                                                           np.broadcast(ur, uro).shape)
        f_hz, df_hz = maxwell_hertz_traction(
            v, ue, side.max_pressure, side.half_width, side.film_thickness, length,
            traction_law, temperature, shear_modulus, pressure=pres)
        return LineContactForces(
            traction=side.traction + f_hz, dtraction_dslide=side.dtraction_dslide + df_hz,
            poiseuille=side.poiseuille, rolling_force=side.rolling_force,
            entrainment_sign=side.entrainment_sign, film_thickness=side.film_thickness,
            half_width=side.half_width, max_pressure=side.max_pressure, hertz_traction=f_hz)

    forces.exact_slide = getattr(base, "exact_slide", False)  # type: ignore[attr-defined]
    forces.thermal_rolling = getattr(  # type: ignore[attr-defined]
        base, "thermal_rolling", False)
    return forces
