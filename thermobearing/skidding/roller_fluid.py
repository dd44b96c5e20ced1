"""Fluid forces on a cylindrical roller: raceway line contacts and the cage pocket.

Closed-form route of paper 000 (Li et al. 2018, seed ``000_3b5ca6eed61dd596.txt``): the
fluid frictional force on a surface of a lubricated line contact is (its eq. 5)

    T = - int h/2 dp/dx dx  +  (u2 - u1) int eta / h dx           (Poiseuille + Couette)

and the roller also feels the rolling-direction component of the film pressure, its
``Q_x`` (eq. 35). The paper gets ``p(x)`` and ``h(x)`` from a numerical (multigrid) EHL
solution; here they come in closed form, per contact:

* Hertz zone |x| < b: semi-elliptic Hertz pressure, film thickness h_c from a closed-form
  central-film formula (:mod:`thermobearing.film`, regime-spanning Moes formula by default),
  shear stress from a traction law of :mod:`thermobearing.traction` (the same law object the
  heat sources use) at the local Hertz pressure.
* Inlet x < -b and outlet x > b: the gap of the elastic line contact outside the Hertz zone
  (the separation outside a 2-D Hertz contact, Johnson 1985; rigid ``x^2/2R`` far away)
  above h_c, ambient viscosity; Newtonian Couette shear ``eta0 (u2 - u1)/h``, the outlet
  cavitated (film fraction h_c/h of the gap carries the shear).
* Rolling (Poiseuille) force: integrating eq. 5's first term by parts gives
  ``-int h/2 dp/dx dx = int p/2 dh/dx dx``; for a cylinder on a plane this is exactly half
  of the pressure's rolling-direction force on the cylinder, ``Q_x/2``, on each surface,
  against the entrainment. ``Q_x`` is the smaller of the rigid-isoviscous value (Martin
  cylinder with Reynolds outlet conditions, coefficients computed below from the Reynolds
  equation) and the piezoviscous-elastic value of paper 000 eq. 35 (Dowson-Higginson
  ``Q_x = 18.4 G^-0.3 U^0.7 E' R l`` for both bodies together, ``U = eta0 u_m / (E' R)``
  with the mean speed ``u_m = (|u_1| + |u_2|)/2``, the Dowson-Higginson convention: the
  paper's eqs. 14 and 18 print U from the sum of the speeds, 2^0.7 = 1.62 times the force,
  and the project's numerical EHL solution of the same contact agrees with the mean reading,
  see ``heat_sources.raceway.rolling_force_paper000``; Martin's rigid form below is written
  for the sum).
  (The factor (1 - D/d_m) of eq. 35 is the roller's share of Q_x: the pressure acts normal to
  both surfaces, so the roller takes R_x/(D/2) of the rolling-direction resultant and the
  raceway the rest; see :meth:`LineContactForces.orbital_force`.) The
  D-H formula is a heavy-load EHL fit and gives rolling forces of the order of the normal
  load at the centrifugal-only loads of an unloaded roller, where the contact is
  rigid-isoviscous; the minimum picks the regime.

Cage pocket (paper 000 eqs. 37-38): a rigid roller turning at ``omega_r`` against a flat
pocket face, isoviscous, Reynolds outlet condition. The garbled printed form
(``2.447 eta/omega (D x/2)^2 / sqrt(h0)``) is read as the Martin load
``w = 2.448 eta U R / h0`` (U = sum of the surface speeds = omega_r D/2, R = D/2), which is
the coefficient printed, and a friction force ``~ eta U sqrt(R/h0)``: the normal force
``F_d`` fixes the film ``h0`` and the friction follows, ``f_d ~ sqrt(eta U R F_d l)``.
The film is capped by the pocket clearance ``c_p``: ``1/h0 = F_d/(k_w eta U R l) + 1/c_p``.
The pocket laws are in :mod:`~thermobearing.skidding.roller_pocket_film` and the Martin
coefficients in :mod:`~thermobearing.skidding.roller_fluid_coefficients`; both are
re-exported here.

All functions are vectorised over rollers; SI units throughout.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.special import roots_legendre

from ..errors import UnknownNameError
from ..hertz import line_contact
from ..registry import Registry
from .roller_fluid_coefficients import _pi_function as _pi_function
from .roller_fluid_coefficients import martin_coefficients as martin_coefficients
from .roller_fluid_coefficients import rigid_starved_film as rigid_starved_film
from .roller_fluid_coefficients import starved_coefficients as starved_coefficients
from .roller_pocket_film import POCKET_FILM_MODELS as POCKET_FILM_MODELS
from .roller_pocket_film import PocketForces as PocketForces
from .roller_pocket_film import pocket_forces as pocket_forces
from .roller_pocket_film import pocket_forces_two_faces as pocket_forces_two_faces

ROLLING_FORCE_MODELS = ("regime_min", "dowson_higginson", "rigid_isoviscous")

#: Drag models of the roller skidding solver: name -> factory (no arguments) returning a
#: callable with the signature of :func:`closed_form_contact_forces`::
#:
#:     contact_forces(load, length, radius, effective_modulus, u_race, u_roller, *, eta0,
#:                    alpha, film, traction_law, temperature, rolling_force, oil_layer)
#:         -> LineContactForces
#:
#: (arrays over rollers; a model may ignore the keywords it does not need). A numerical
#: line-contact EHL (thermobearing.ehl) registers here with its Couette force (``traction``,
#: ``dtraction_dslide``), Poiseuille force per surface (``poiseuille``) and the pressure's
#: rolling resultant (``rolling_force`` = int p dh/dx dx) and is selected with
#: ``solve_roller(..., drag_model="<name>")``.
ROLLER_DRAG: Registry[Callable[..., Any]] = Registry(
    "roller_drag", "fluid forces of roller-raceway line contacts for the roller skidding solver")


@dataclass(frozen=True)
class LineContactForces:
    """Fluid forces of one set of roller-raceway contacts (arrays over rollers).

    Sign convention: the contact axis points along the *race* surface velocity relative to
    the cage; ``u_race`` and ``u_roller`` are the surface speeds along it.

    Attributes
    ----------
    traction : Couette (shear) force on the roller along the axis [N], sign of V = u_race -
        u_roller (Hertz zone by the traction law, inlet/outlet Newtonian).
    dtraction_dslide : d traction / d V [N s/m].
    poiseuille : Poiseuille (rolling) shear force on each surface [N], >= 0, acting against
        the entrainment direction.
    rolling_force : Q_x = int p dh/dx dx, the rolling-direction resultant of the film
        pressure on both bodies [N] (>= 0, along the entrainment); the roller takes the
        share R_x/(D/2) of it (:meth:`orbital_force`).
    entrainment_sign : sign of (u_race + u_roller) (+1 or -1).
    film_thickness : central film h_c [m] (inf where unloaded).
    half_width, max_pressure : Hertz b [m], p_H [Pa].
    hertz_traction : part of ``traction`` carried by the Hertz zone [N].
    """

    traction: np.ndarray
    dtraction_dslide: np.ndarray
    poiseuille: np.ndarray
    rolling_force: np.ndarray
    entrainment_sign: np.ndarray
    film_thickness: np.ndarray
    half_width: np.ndarray
    max_pressure: np.ndarray
    hertz_traction: np.ndarray

    @property
    def shear_force(self) -> np.ndarray:
        """Total shear force on the roller surface along the axis [N] (torque-producing)."""
        return self.traction - self.poiseuille * self.entrainment_sign

    def orbital_force(self, roller_share: float) -> np.ndarray:
        """Fluid force on the roller along the axis: shear + its share of the pressure [N].

        The film pressure acts normal to both surfaces; its rolling-direction resultant
        ``Q_x = int p dh/dx dx`` splits between the bodies in proportion to their surface
        slopes, so the roller takes ``roller_share = R_x / (D/2)`` of it (1 - D/d_m at the
        inner race, 1 + D/d_m at the outer: the factor of paper 000 eq. 35) and the raceway the
        rest. Both shares pass through the body's centre (roller axis, bearing axis), which
        keeps the film free of torque about the bearing axis.
        """
        return self.shear_force + roller_share * self.rolling_force * self.entrainment_sign

    @property
    def race_shear_force(self) -> np.ndarray:
        """Shear force of the film on the raceway, against the axis [N] (Couette + Poiseuille).

        The raceway gets ``-(C + Q_x/2)`` along the axis: the torque the ring must be driven
        with is (raceway radius) x this force.
        """
        return self.traction + self.poiseuille * self.entrainment_sign

    def combined(self, other: LineContactForces) -> LineContactForces:
        """Sum of two force sets acting on the same contacts (same speeds, so the same
        entrainment sign): forces add, film/Hertz data are taken where this set has a load
        (finite film), else from ``other``."""
        own = np.isfinite(self.film_thickness)
        return LineContactForces(
            traction=self.traction + other.traction,
            dtraction_dslide=self.dtraction_dslide + other.dtraction_dslide,
            poiseuille=self.poiseuille + other.poiseuille,
            rolling_force=self.rolling_force + other.rolling_force,
            entrainment_sign=self.entrainment_sign,
            film_thickness=np.where(own, self.film_thickness, other.film_thickness),
            half_width=self.half_width, max_pressure=self.max_pressure,
            hertz_traction=self.hertz_traction)


def clearance_film_forces(gap: Any, length: float, radius: float, u_race: Any, u_roller: Any,
                          eta0: float, floor: float = 1e-6, slide: Any = None
                          ) -> tuple[LineContactForces, np.ndarray]:
    """Hydrodynamic forces of the oil film across the radial gap of an unloaded roller.

    A roller outside the load zone rides on the outer race (centrifugal force) and faces
    the inner raceway across the gap ``h0`` = -(delta_r . e_j - P_d/2) (diametral clearance
    minus the ring displacement toward it). The flooded rigid-isoviscous cylinder-on-plane
    film of that gap (Martin 1916; the coefficients of :func:`martin_coefficients`, the
    same Reynolds solution as the pocket film of paper 000 eqs. 37-38) gives, per contact,

    * Couette (drive) force on the roller  ``C = k_c eta0 l sqrt(R/h0) (u_race - u_roller)``
      (paper 000 eq. 5, second term),
    * rolling force ``Q_x = k_q eta0 l sqrt(R/h0) (u_race + u_roller)`` (eq. 5, first term;
      ``Q_x/2`` Poiseuille shear on each surface),
    * film normal force ``w = k_w eta0 (u_race + u_roller) R l / h0`` pressing the roller
      onto the outer race.

    Paper 000 keeps its unloaded rollers rolling on the outer race (sec. 1) without naming
    what spins them; this film is that drive (the inner ring across the clearance).

    Parameters
    ----------
    gap : (Z,) gap h0 [m]; ``inf`` where the roller has a Hertz contact instead (no
        clearance-film force there). Gaps below ``floor`` [m] are raised to it (keeps 1/h0
        finite at the edge of the load zone; 0.2-3 um changes nothing in paper 000's cases).
    length : l [m].  radius : reduced radius R_x [m].
    u_race, u_roller : (Z,) surface speeds along the contact axis [m/s] (cage frame).
    eta0 : dynamic viscosity [Pa s].
    slide : (Z,) V = u_race - u_roller [m/s] when known more exactly than the difference
        of the two speeds (None: that difference; see :func:`closed_form_contact_forces`).

    Returns
    -------
    (LineContactForces, w (Z,) [N])

    Validity: flooded film, h0 << R, isoviscous (film pressures w / (l sqrt(R h0)) of a few
    MPa), no elastic deformation; the ring equilibrium does not include w (see the case
    SOURCE.md).
    """
    g = np.asarray(gap, dtype=float)
    ur, uro = np.broadcast_arrays(np.asarray(u_race, float), np.asarray(u_roller, float))
    active = np.isfinite(g)
    h0 = np.where(active, np.maximum(g, floor), 1.0)
    k_w, k_q, k_c, _ = martin_coefficients()
    root = np.where(active, length * np.sqrt(radius / h0), 0.0)
    slide = ur - uro if slide is None else np.broadcast_to(np.asarray(slide, float), ur.shape)
    usum = ur + uro
    c = k_c * eta0 * root
    qx = k_q * eta0 * root * np.abs(usum)
    w = np.where(active, k_w * eta0 * np.abs(usum) * radius * length / h0, 0.0)
    zero = np.zeros(g.shape)
    forces = LineContactForces(
        traction=c * slide, dtraction_dslide=c, poiseuille=0.5 * qx, rolling_force=qx,
        entrainment_sign=np.where(usum >= 0.0, 1.0, -1.0),
        film_thickness=np.where(active, h0, np.inf), half_width=zero, max_pressure=zero,
        hertz_traction=zero)
    return forces, w


def outer_gap(X: np.ndarray) -> np.ndarray:
    """Separation outside the Hertz zone of a line contact, in units of b^2 / R.

    g(X) = (|X| sqrt(X^2 - 1) - arccosh |X|) / 2 for |X| >= 1 (0 inside), which tends to
    X^2/2 (the rigid gap x^2/(2R)) far from the contact. Johnson 1985, Contact Mechanics
    (surface displacements of a two-dimensional Hertz contact).
    """
    ax = np.maximum(np.abs(X), 1.0)
    return 0.5 * (ax * np.sqrt(ax * ax - 1.0) - np.arccosh(ax))


_N_HERTZ = 24
_N_SIDE = 24


@functools.lru_cache(maxsize=4)
def _nodes(n: int) -> tuple[np.ndarray, np.ndarray]:
    x, w = roots_legendre(n)
    return x, w


def dowson_higginson_rolling_force(entrainment_speed: Any, eta0: float, alpha: float,
                                   effective_modulus: float, radius: float) -> Any:
    """Rolling-direction resultant of the film pressure per unit length, both bodies
    together [N/m]: paper 000 eq. 35 (Dowson & Higginson),
    ``Q_x / l = 18.4 G^-0.3 U^0.7 E' R`` with ``G = alpha E'`` and
    ``U = eta0 u_m / (E' R)``, ``u_m`` the entrainment (mean rolling) speed [m/s];
    eta0 [Pa s], alpha [1/Pa], E' [Pa], R = R_x [m]. Each surface takes the Poiseuille
    shear ``Q_x / 2``."""
    big_u = eta0 * np.asarray(entrainment_speed, dtype=float) / (effective_modulus * radius)
    return 18.4 * (alpha * effective_modulus)**-0.3 * big_u**0.7 * effective_modulus * radius


def closed_form_contact_forces(
    load: Any,
    length: float,
    radius: float,
    effective_modulus: float,
    u_race: Any,
    u_roller: Any,
    *,
    eta0: float,
    alpha: float,
    film: Callable[[np.ndarray, np.ndarray], np.ndarray],
    traction_law: Any,
    temperature: float,
    rolling_force: str = "regime_min",
    oil_layer: float | None = None,
    slide: Any = None,
    inlet_heating: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray] | None = None,
) -> LineContactForces:
    """Fluid forces of roller-raceway line contacts, closed form (module docstring).

    Parameters
    ----------
    load : (Z,) normal loads Q [N] (0: no contact, all forces 0).
    length : effective contact length l [m].  radius : reduced radius R_x [m].
    effective_modulus : E' [Pa].
    u_race, u_roller : (Z,) surface speeds along the contact axis [m/s] (race relative to the
        cage, roller surface relative to its centre).
    eta0 : ambient dynamic viscosity [Pa s].  alpha : pressure-viscosity coefficient [1/Pa].
    film : ``film(entrainment_speed [m/s], load_per_length [N/m]) -> h_c [m]``.
    traction_law : object with ``shear_stress(slide_speed, pressure, film_thickness,
        temperature) -> (stress, dstress)`` (:mod:`thermobearing.traction`).
    temperature : contact temperature [K].
    rolling_force : "regime_min" (default: min of rigid-isoviscous and Dowson-Higginson),
        "dowson_higginson" (paper 000 eq. 35 at every loaded contact) or "rigid_isoviscous".
    oil_layer : available oil layer at the inlet, both surfaces together [m] (None: fully
        flooded). Starvation: the inlet meniscus sits where the gap holds this layer; the
        rigid-isoviscous film, load and rolling-force coefficients follow
        (:func:`rigid_starved_film`), the inlet Couette integral ends at the meniscus, and the
        closed-form film h_c is scaled by the rigid starved/flooded film ratio (an
        approximation for elastic contacts, where that ratio is close to 1 unless the oil
        layer is comparable with the film).
    slide : (Z,) sliding speed V = u_race - u_roller [m/s] given exactly (None: that
        difference of the two speeds). Near pure rolling the difference of two surface
        speeds is a multiple of one ulp of them (1.8e-15 m/s at 8 m/s) while a cold film
        under load shears stiffly enough to carry hundreds of N within one such ulp; the
        slide-variable solve (:mod:`~thermobearing.skidding.roller_slides`) passes V
        itself, so that the traction resolves slides far below the speeds' round-off.
    inlet_heating : None (isothermal rolling force) or the film thermal-reduction factor
        ``phi_T(u_e [m/s], |V|/u_e [-], p_H [Pa])`` of the solver's option
        ``thermal_reduction`` (:func:`~thermobearing.skidding.roller_thermal.
        inlet_heating_factor`, the heat source's factor): the rolling force Q_x (both closed
        forms, flooded or starved) is evaluated at the inlet viscosity
        ``eta0 phi_T^(1/0.7)``, as ``heat_sources.raceway.ehl_rolling_resistance`` does:
        eq. 35 x phi_T, Martin's rigid force x phi_T^(5/7). Film and shear keep eta0.

    Returns
    -------
    LineContactForces
    """
    if rolling_force not in ROLLING_FORCE_MODELS:
        raise UnknownNameError("rolling_force", rolling_force, ROLLING_FORCE_MODELS)
    q, ur, uro = np.broadcast_arrays(*(np.asarray(v, dtype=float)
                                       for v in (load, u_race, u_roller)))
    slide = ur - uro if slide is None else np.broadcast_to(np.asarray(slide, float), ur.shape)
    if q.ndim == 1 and 0 < np.count_nonzero(q > 0.0) < q.size:
        # evaluate the loaded contacts only, zeros elsewhere
        idx = np.nonzero(q > 0.0)[0]
        sub = closed_form_contact_forces(
            q[idx], length, radius, effective_modulus, ur[idx], uro[idx], eta0=eta0,
            alpha=alpha, film=film, traction_law=traction_law, temperature=temperature,
            rolling_force=rolling_force, oil_layer=oil_layer, slide=slide[idx],
            inlet_heating=inlet_heating)

        def full(a: np.ndarray, fill: float) -> np.ndarray:
            out = np.full(q.shape, fill)
            out[idx] = a
            return out

        return LineContactForces(
            traction=full(sub.traction, 0.0), dtraction_dslide=full(sub.dtraction_dslide, 0.0),
            poiseuille=full(sub.poiseuille, 0.0), rolling_force=full(sub.rolling_force, 0.0),
            entrainment_sign=np.where(ur + uro >= 0.0, 1.0, -1.0),
            film_thickness=full(sub.film_thickness, np.inf),
            half_width=full(sub.half_width, 0.0), max_pressure=full(sub.max_pressure, 0.0),
            hertz_traction=full(sub.hertz_traction, 0.0))
    usum = ur + uro
    sign = np.where(usum >= 0.0, 1.0, -1.0)
    loaded = q > 0.0
    w = np.where(loaded, q / length, 0.0)
    hz = line_contact(q, length, radius, effective_modulus)  # Hertz b, p_H (straight roller)
    b = np.asarray(hz.half_width, dtype=float)
    p_h = np.where(loaded, np.asarray(hz.max_pressure, dtype=float), 0.0)
    ue = np.maximum(0.5 * np.abs(usum), 1e-6)
    w_safe = np.where(loaded, w, 1.0)
    h_flooded = np.where(loaded, film(ue, w_safe), np.inf)
    # rigid-isoviscous film, flooded and starved (the starved/flooded ratio scales h_c)
    h_r, k_wr, k_qr = rigid_starved_film(w_safe, 2.0 * ue, radius, eta0, oil_layer)
    if oil_layer is not None:
        h_r_flood = martin_coefficients()[0] * eta0 * 2.0 * ue * radius / w_safe
        h_flooded = h_flooded * np.minimum(1.0, h_r / h_r_flood)
    h_c = h_flooded
    hc_safe = np.where(loaded, h_c, 1.0)

    # --- Hertz zone: traction law at the local Hertz pressure ----------------------------
    xg, wg = _nodes(_N_HERTZ)
    pres = p_h[..., None] * np.sqrt(1.0 - xg**2)
    speed = np.abs(slide)[..., None] * np.ones_like(xg)
    # a scalar temperature stays scalar: the lubricant then memoises its atmospheric
    # viscosity and Roelands index (an array of equal temperatures recomputed them at every
    # node of every call: ~60 % of a residual evaluation)
    stress, dstress = traction_law.shear_stress(
        speed, pres, hc_safe[..., None] * np.ones_like(xg),
        float(temperature) if np.ndim(temperature) == 0 else temperature * np.ones_like(pres))
    dx_w = (b[..., None] * wg) * length
    f_hz = np.sum(np.asarray(stress) * dx_w, axis=-1)
    df_hz = np.sum(np.asarray(dstress) * dx_w, axis=-1)

    # --- inlet and outlet: Newtonian, ambient viscosity ----------------------------------
    # outlet (and flooded inlet): x = b + L t/(1-t), t in (0,1); L = sqrt(2 R h_c) is the
    # rigid length scale. Starved inlet: x = b + s_m t^2 up to the meniscus, where the
    # (rigid) gap holds the oil layer, s_m = sqrt(2 R (h_oil - h_c)).
    lsc = np.sqrt(2.0 * radius * hc_safe)
    ts, wt = _nodes(_N_SIDE)
    t = 0.5 * (ts + 1.0)
    wt = 0.5 * wt
    s = lsc[..., None] * t / (1.0 - t)
    ds = lsc[..., None] * wt / (1.0 - t) ** 2
    if oil_layer is None:
        s_in, ds_in = s, ds
    else:
        s_m = np.sqrt(2.0 * radius * np.maximum(oil_layer - hc_safe, 0.0))
        s_in = s_m[..., None] * t * t
        ds_in = 2.0 * s_m[..., None] * t * wt
    b_safe = np.where(b > 0, b, 1.0)

    def film_gap(sv: np.ndarray) -> np.ndarray:
        xx = np.where(b[..., None] > 0, 1.0 + sv / b_safe[..., None], np.inf)
        g = np.where(b[..., None] > 0,
                     (b_safe**2 / radius)[..., None] * outer_gap(np.minimum(xx, 1e150)),
                     sv * sv / (2.0 * radius))
        g = np.where(np.isfinite(g), g, sv * sv / (2.0 * radius))
        return hc_safe[..., None] + g

    h = film_gap(s)
    inlet = np.sum(ds_in / film_gap(s_in), axis=-1)
    outlet = np.sum(ds * hc_safe[..., None] / h**2, axis=-1)
    c_side = np.where(loaded, eta0 * length * (inlet + outlet), 0.0)
    traction = np.where(loaded, f_hz * np.sign(slide) + c_side * slide, 0.0)
    dtraction = np.where(loaded, df_hz + c_side, 0.0)

    # --- rolling force Q_x: min(rigid-isoviscous, Dowson-Higginson eq. 35) --------------
    usum_abs = np.abs(usum)
    eta_roll: Any = eta0
    if inlet_heating is not None and np.any(loaded):
        # inlet shear heating: the rolling force at the effective inlet viscosity
        # eta0 phi_T^(1/0.7) (roller_thermal module docstring); the starved rigid film is
        # solved again at that viscosity (its meniscus moves with the film)
        from .roller_thermal import viscosity_exponent

        phi = inlet_heating(ue, np.abs(slide) / ue, p_h)
        eta_roll = eta0 * np.where(loaded, phi, 1.0) ** (1.0 / viscosity_exponent())
        if oil_layer is None:
            h_r = h_r * (eta_roll / eta0)
        else:
            h_r, _, k_qr = rigid_starved_film(w_safe, 2.0 * ue, radius, eta_roll, oil_layer)
    qx_rigid = k_qr * eta_roll * usum_abs * length * np.sqrt(radius / h_r)
    qx_dh = dowson_higginson_rolling_force(0.5 * usum_abs, eta_roll, alpha, effective_modulus,
                                           radius) * length
    if rolling_force == "regime_min":
        qx = np.minimum(qx_rigid, qx_dh)
    elif rolling_force == "dowson_higginson":
        qx = qx_dh
    else:
        qx = qx_rigid
    qx = np.where(loaded, qx, 0.0)
    return LineContactForces(
        traction=traction, dtraction_dslide=dtraction, poiseuille=0.5 * qx, rolling_force=qx,
        entrainment_sign=sign, film_thickness=h_c, half_width=b, max_pressure=p_h,
        hertz_traction=np.where(loaded, f_hz * np.sign(slide), 0.0),
    )


def starved_film(film: Callable[[np.ndarray, np.ndarray], np.ndarray], radius: float,
                 eta0: float, oil_layer: float | None
                 ) -> Callable[[np.ndarray, np.ndarray], np.ndarray]:
    """The central film ``h(u_e, w)`` [m] of :func:`closed_form_contact_forces` with a finite
    inlet oil layer, as a function (for the film-supported load distribution).

    ``h = film(u_e, w) min(1, h_r(h_oil) / h_r(flooded))``: the flooded closed-form film
    scaled by the ratio of the rigid-isoviscous starved and flooded films
    (:func:`rigid_starved_film`; the inlet meniscus where the gap holds the oil layer), the
    same expression the contact forces use, so the load distribution and the drag see one
    film. ``oil_layer=None`` returns ``film`` unchanged. u_e [m/s], w [N/m] (> 0), radius
    R_x [m], eta0 [Pa s], oil_layer (both surfaces together) [m].

    Reference: paper 000 eq. 7 on a finite inlet domain [li2018_nu214_skidding]; Hamrock
    et al. 2004 (starved rigid-isoviscous line contact) [hamrock2004].
    """
    if oil_layer is None:
        return film
    k_w0 = martin_coefficients()[0]

    def h(ue: np.ndarray, w: np.ndarray) -> np.ndarray:
        ue = np.asarray(ue, dtype=float)
        w = np.maximum(np.asarray(w, dtype=float), 1e-12)  # (w -> 0: the finite limit)
        h_r, _, _ = rigid_starved_film(w, 2.0 * ue, radius, eta0, oil_layer)
        h_r_flood = k_w0 * eta0 * 2.0 * ue * radius / w
        return np.asarray(film(ue, w)) * np.minimum(1.0, h_r / h_r_flood)

    return h


@ROLLER_DRAG.register(
    "closed_form",
    references=["li2018_nu214_skidding", "martin1916_gear_lubrication", "hamrock2004",
                "johnson1985", "dowson_higginson1966"],
    parameters={},
    validity="steady line contacts, fully flooded inlet; Hertz-zone shear by the given "
             "traction law; rolling force min(rigid-isoviscous, Dowson-Higginson EHL)",
)
def closed_form_drag_model() -> Callable[..., LineContactForces]:
    """Closed-form line-contact fluid forces (paper 000 eqs. 5, 33-35 with a closed-form film)."""
    return closed_form_contact_forces


#: the drag model takes an exact ``slide`` keyword (the slide-variable solve may pass it)
closed_form_contact_forces.exact_slide = True  # type: ignore[attr-defined]
#: the drag model takes the ``inlet_heating`` keyword (option ``thermal_reduction``)
closed_form_contact_forces.thermal_rolling = True  # type: ignore[attr-defined]


def curve_contact_forces(base: Callable[..., LineContactForces], curve: Any
                         ) -> Callable[..., LineContactForces]:
    """A drag model whose Hertz-zone traction is a traction-coefficient curve times the load.

    ``F_hz = mu(s) Q`` with s = V/u_e the slide-to-roll ratio (V = u_race - u_roller,
    u_e = |u_race + u_roller|/2) and ``mu`` from ``curve.traction(s, Q, u_e, R_x, E', T)``
    (:mod:`thermobearing.traction_curve`: a disk-machine fit of the oil, the law of
    quasi-dynamic codes such as paper 001's school, Yan et al. 2025 eq. 15). Everything else
    (film, inlet/outlet Newtonian Couette shear, Poiseuille and rolling forces, Hertz b and
    p_H) comes from ``base`` (signature of :func:`closed_form_contact_forces`) with a zero
    Hertz-zone shear. ``dtraction_dslide`` adds ``Q dmu/ds / u_e`` (at fixed u_e).
    ``temperature`` is passed to the curve as the oil (inlet) temperature [K].
    """
    from .roller_maxwell import _NoHertzShear

    null_law = _NoHertzShear()

    @functools.wraps(base)
    def forces(load: Any, length: float, radius: float, effective_modulus: float,
               u_race: Any, u_roller: Any, *, traction_law: Any, temperature: float,
               slide: Any = None, **kw: Any) -> LineContactForces:
        if slide is not None:
            kw["slide"] = slide
        side = base(load, length, radius, effective_modulus, u_race, u_roller,
                    traction_law=null_law, temperature=temperature, **kw)
        q = np.asarray(load, dtype=float)
        ur = np.asarray(u_race, dtype=float)
        uro = np.asarray(u_roller, dtype=float)
        q, ur, uro = np.broadcast_arrays(q, ur, uro)
        v = ur - uro if slide is None else np.broadcast_to(np.asarray(slide, float), ur.shape)
        ue = np.maximum(0.5 * np.abs(ur + uro), 1e-6)
        loaded = q > 0.0
        f_hz = np.zeros(q.shape)
        df_hz = np.zeros(q.shape)
        if np.any(loaded):
            s = v[loaded] / ue[loaded]
            mu, dmu = curve.traction(s, q[loaded], ue[loaded], radius, effective_modulus,
                                     temperature)
            f_hz[loaded] = mu * q[loaded]
            df_hz[loaded] = dmu * q[loaded] / ue[loaded]
        return LineContactForces(
            traction=side.traction + f_hz, dtraction_dslide=side.dtraction_dslide + df_hz,
            poiseuille=side.poiseuille, rolling_force=side.rolling_force,
            entrainment_sign=side.entrainment_sign, film_thickness=side.film_thickness,
            half_width=side.half_width, max_pressure=side.max_pressure, hertz_traction=f_hz)

    forces.exact_slide = getattr(base, "exact_slide", False)  # type: ignore[attr-defined]
    forces.thermal_rolling = getattr(  # type: ignore[attr-defined]
        base, "thermal_rolling", False)
    return forces
