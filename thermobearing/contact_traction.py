"""Traction force, moments and shear heat of element-raceway contacts (one code path).

:func:`integrate` integrates a traction law (:mod:`thermobearing.traction`) over the Hertz
contact area with the sliding-velocity field of the relative rigid-body motion of element
and race, vectorised over any number of contacts. The skidding solver calls exactly this
function, and the raceway heat source calls it on the solver's (or race control's) state,
so the heat of a contact is, to round-off, the power of its traction forces:

    heat = -(F_x V_x + F_y V_y + M_x Omega_x + M_y Omega_y + M_z Omega_z)  >= 0.

How to use it (for the skidding solver)
---------------------------------------
Work in each contact's frame: ``x`` along the major axis a (transverse), ``y`` along the
rolling direction (minor axis b), ``z`` the contact normal pointing from the race into the
element. Give the element's motion *relative to the race* (element minus race):

- V_x, V_y: sliding velocity of the element surface over the race at the contact centre
  [m/s] (``transverse_sliding_speed``, ``sliding_speed``);
- Omega_x, Omega_y, Omega_z: relative angular velocity [rad/s] (``roll_speed`` about the
  major axis, ``tilt_speed`` about the rolling axis, ``spin_speed`` about the normal).

At a point (x, y) of the deformed surface z = x^2 / (2 R_d) the slip is V + Omega x r:

    dv_x = V_x + Omega_y z - Omega_z y
    dv_y = V_y + Omega_z x - Omega_x z        (the Omega_x z term is Heathcote slip)

and the local shear stress tau(|dv|, p, h, T) acts on the element against dv. Returned
forces and moments act ON THE ELEMENT, in the contact frame, moments about the contact
centre; the race gets the opposite. The moment about the element centre is
r_(centre->contact) x F + M (add it yourself in your ball frame).

The generalized force vector Q = (F_x, F_y, M_x, M_y, M_z) is conjugate to
q = (V_x, V_y, Omega_x, Omega_y, Omega_z); with ``jacobian=True`` you also get dQ/dq
(shape ``(..., 5, 5)``, analytic, same quadrature) and d(heat)/dq. Dependence on normal
load, ellipse size, film and temperature is not differentiated (finite-difference those).

Quadrature
----------
Point contacts: x = a xi, y = b sqrt(1 - xi^2) eta, with Gauss-Jacobi rules of weight
(1 - xi^2) in xi (``n_major`` nodes) and sqrt(1 - eta^2) in eta (``n_minor`` nodes): the
semi-elliptical Hertz pressure p0 sqrt(1 - xi^2) sqrt(1 - eta^2) times the area element
is carried exactly by the weights, so the node loads add up to Q exactly and a
pressure-proportional law (tau = mu p) is integrated to the accuracy of mu(x, y) alone.
This is the strip method of primer over-skidding 3.5 (strips along the major axis, each
with load (3Q/4)(1 - xi^2) dxi) with Gauss rules inside each strip.
Line contacts (``kind="line"``): uniform load along the length (Gauss-Legendre in xi),
Hertz half-ellipse across the width. p0 is taken as 3Q/(2 pi a b) (point) or Q/(pi a b)
(line, a = half length) so that the pressures are consistent with the loads.
Zero-slip lines (spin, Heathcote) make the integrand kinked (or, for laws with tau(0) > 0,
discontinuous); the error then falls as O(n^-2) (O(n^-1)) in the node count. Measured on
a spinning ball contact with Heathcote slip (tests): the default 16 x 8 nodes give the heat
and the spin moment within about 0.5 % of a 256 x 64 rule; the net rolling force, a small
difference of large opposing tractions, converges less regularly (errors up to ~1 %). The
power identity above holds exactly at any node count.

References: Johnson 1985 (Contact Mechanics, ch. 8, spin and Heathcote slip); Harris &
Kotzalas 2007 (deformed-surface radius, spinning moment 3 mu Q a E(k) / 8); seed paper 002
(002_0add79adaca5495c.txt) eq. 11 (shear heat over the ellipse; bounded here by the law).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.special import roots_jacobi, roots_legendre

from .errors import InputError
from .state import ContactSet
from .traction import TractionLaw

GENERALIZED = ("transverse_force", "rolling_force", "moment_transverse", "moment_rolling",
               "moment_normal")


@dataclass(frozen=True)
class ContactTraction:
    """Result of :func:`integrate` (arrays of the broadcast input shape ``S``).

    Attributes
    ----------
    transverse_force : F_x on the element [N].
    rolling_force : F_y on the element [N].
    moment_transverse : M_x about the contact centre [N m] (from the Heathcote lever z).
    moment_rolling : M_y about the contact centre [N m].
    moment_normal : M_z about the contact normal [N m] (spin moment).
    heat : integral of tau |dv| over the contact [W] (>= 0).
    jacobian : dQ/dq, shape S + (5, 5), or None.
    heat_gradient : d heat / dq, shape S + (5,), or None.
    """

    transverse_force: np.ndarray
    rolling_force: np.ndarray
    moment_transverse: np.ndarray
    moment_rolling: np.ndarray
    moment_normal: np.ndarray
    heat: np.ndarray
    jacobian: np.ndarray | None = None
    heat_gradient: np.ndarray | None = None

    @property
    def generalized_force(self) -> np.ndarray:
        """Q = (F_x, F_y, M_x, M_y, M_z), shape S + (5,)."""
        return np.stack([getattr(self, n) for n in GENERALIZED], axis=-1)


@functools.lru_cache(maxsize=64)
def _rule(kind: str, n_major: int, n_minor: int) -> tuple[np.ndarray, ...]:
    """Nodes (xi, eta_scaled, pressure shape, area weight/(a b), load weight/(p0 a b))."""
    eta, weta = roots_jacobi(n_minor, 0.5, 0.5)
    if kind == "point":
        xi, wxi = roots_jacobi(n_major, 1.0, 1.0)
        sx = np.sqrt(1.0 - xi * xi)
    else:
        xi, wxi = roots_legendre(n_major)
        sx = np.ones_like(xi)
    se = np.sqrt(1.0 - eta * eta)
    xg = np.repeat(xi, n_minor)
    yg = np.repeat(sx, n_minor) * np.tile(eta, n_major)  # y / b
    shape = np.repeat(sx, n_minor) * np.tile(se, n_major)  # p / p0
    load_w = np.outer(wxi, weta).ravel()  # p * dA / (p0 a b)
    if kind == "point":
        area_w = load_w / shape  # dA / (a b)
    else:
        area_w = load_w / np.tile(se, n_major)
    for arr in (xg, yg, shape, area_w):
        arr.flags.writeable = False
    return xg, yg, shape, area_w


@functools.lru_cache(maxsize=64)
def _bases(kind: str, n_major: int, n_minor: int) -> tuple[np.ndarray, ...]:
    """xg^2 and the node-vector bases (1, xg^2, yg), (1, xg^2, xg) of the moment sums."""
    xg, yg, _, _ = _rule(kind, n_major, n_minor)
    xg2 = xg * xg
    base_x = np.ascontiguousarray(np.stack([np.ones_like(xg), xg2, yg], axis=1))
    base_y = np.ascontiguousarray(np.stack([np.ones_like(xg), xg2, xg], axis=1))
    for arr in (xg2, base_x, base_y):
        arr.flags.writeable = False
    return xg2, base_x, base_y


def integrate(
    law: TractionLaw,
    *,
    normal_load: Any,
    semi_major: Any,
    semi_minor: Any,
    sliding_speed: Any = 0.0,
    transverse_sliding_speed: Any = 0.0,
    spin_speed: Any = 0.0,
    roll_speed: Any = 0.0,
    tilt_speed: Any = 0.0,
    deformed_radius: Any = np.inf,
    film_thickness: Any = None,
    temperature: Any = None,
    kind: str = "point",
    n_major: int = 16,
    n_minor: int = 8,
    jacobian: bool = False,
) -> ContactTraction:
    """Traction forces, moments and shear heat of contacts (see the module docstring).

    Parameters
    ----------
    law : a traction law (:func:`thermobearing.traction.make_traction_law`).
    normal_load : Q [N] (>= 0; 0 gives zeros).
    semi_major, semi_minor : a (transverse; half length for a line) and b (rolling) [m].
    sliding_speed, transverse_sliding_speed : V_y, V_x, element minus race [m/s].
    spin_speed, roll_speed, tilt_speed : Omega_z, Omega_x, Omega_y, element minus race [rad/s].
    deformed_radius : R_d, transverse radius of the deformed surface [m] (inf: flat).
    film_thickness : central film thickness [m], needed by film laws (else InputError).
    temperature : contact temperature [K], needed by film laws.
    kind : "point" or "line".
    n_major, n_minor : quadrature nodes along a and along b.
    jacobian : also return dQ/dq and d heat/dq.

    All array arguments broadcast together to a shape S (e.g. (Z,) or (n_contacts, Z)).

    Returns
    -------
    ContactTraction
    """
    if kind not in ("point", "line"):
        raise InputError("contact_traction.kind", kind, "'point' or 'line'")
    if n_major < 2 or n_minor < 1:
        raise InputError("contact_traction.n_major/n_minor", (n_major, n_minor),
                         "n_major >= 2 and n_minor >= 1")
    if getattr(law, "requires_film", False) and film_thickness is None:
        raise InputError(f"traction law {type(law).__name__}.film_thickness", None,
                         "a film thickness [m]: this law shears a fluid film")
    arrays = np.broadcast_arrays(
        *(np.asarray(v, dtype=float) for v in (
            normal_load, semi_major, semi_minor, sliding_speed, transverse_sliding_speed,
            spin_speed, roll_speed, tilt_speed, deformed_radius)))
    q_load, a, b, vy, vx, wz, wx, wy, rd = arrays
    for name, arr in (("normal_load", q_load), ("semi_major", a), ("semi_minor", b)):
        if np.any(arr < 0) or not np.all(np.isfinite(arr)):
            raise InputError(f"contact_traction.{name}", "negative or non-finite values",
                             "values >= 0")
    for name, arr in (("sliding speeds/angular speeds", np.stack([vy, vx, wz, wx, wy])),):
        if not np.all(np.isfinite(arr)):
            raise InputError(f"contact_traction.{name}", "non-finite values", "finite values")
    if np.any(np.isnan(rd)) or np.any(rd <= 0):
        raise InputError("contact_traction.deformed_radius", "values <= 0 or NaN",
                         "radii > 0 (inf: flat)")
    curvature = np.where(np.isinf(rd), 0.0, 1.0 / np.where(np.isinf(rd), 1.0, rd))
    h = None
    if film_thickness is not None:
        h = np.broadcast_to(np.asarray(film_thickness, dtype=float), q_load.shape)
        if np.any(h[(q_load > 0) & (a > 0) & (b > 0)] <= 0):
            raise InputError("contact_traction.film_thickness", "values <= 0 at loaded contacts",
                             "a film thickness > 0 [m]")
    return _integrate_core(law, q_load, a, b, vy, vx, wz, wx, wy, curvature, h, temperature,
                           kind, int(n_major), int(n_minor), jacobian)


def _integrate_core(law: TractionLaw, q_load: np.ndarray, a: np.ndarray, b: np.ndarray,
                    vy: np.ndarray, vx: np.ndarray, wz: np.ndarray, wx: np.ndarray,
                    wy: np.ndarray, curvature: np.ndarray, h: np.ndarray | None,
                    temperature: Any, kind: str, n_major: int, n_minor: int,
                    jacobian: bool) -> ContactTraction:
    """Unchecked core of :func:`integrate` (the one code path of the contact integration).

    All arrays are float and broadcast to the contact shape S; ``curvature`` = 1/R_d [1/m]
    (0: flat); ``h`` the film thickness (> 0 at loaded contacts) or None. The skidding
    solvers call this directly inside their residuals after validating their inputs once;
    :func:`integrate` validates and calls it.
    """
    shape_s = np.broadcast_shapes(q_load.shape, a.shape, b.shape)
    q_load = np.broadcast_to(q_load, shape_s)
    xg, yg, pshape, area_w = _rule(kind, n_major, n_minor)

    loaded = (q_load > 0) & (a > 0) & (b > 0)
    ab = a * b
    safe_ab = np.where(loaded, ab, 1.0)
    if kind == "point":
        p0 = np.where(loaded, 3.0 * q_load / (2.0 * np.pi * safe_ab), 0.0)
    else:
        p0 = np.where(loaded, q_load / (np.pi * safe_ab), 0.0)

    e = (...,) + (None,)
    xg2, base_x, base_y = _bases(kind, n_major, n_minor)
    # node (x, y, z) = (a xg, b yg, a2c xg^2) with z = x^2 / (2 R_d): per-contact
    # coefficients times fixed node vectors
    a2c = 0.5 * np.asarray(curvature) * a * a
    dvx = vx[e] + (wy * a2c)[e] * xg2 - (wz * b)[e] * yg
    dvy = vy[e] + (wz * a)[e] * xg - (wx * a2c)[e] * xg2
    speed = np.sqrt(dvx * dvx + dvy * dvy)
    pressure = p0[e] * pshape
    weight = np.where(loaded, ab, 0.0)[e] * area_w  # dA [m^2]

    h_nodes = None
    if h is not None:
        h_nodes = np.where(loaded, h, 1.0)[e]  # shape S + (1,): broadcast over the nodes
    t_nodes = None
    if temperature is not None:
        # per-contact temperature, shape S + (1,): the law evaluates the temperature part of
        # the viscosity once per contact and broadcasts it over the nodes
        t_nodes = np.broadcast_to(np.asarray(temperature, dtype=float), shape_s)[e]
    core = getattr(law, "_stress", None)   # unchecked core of the law's shear_stress
    if core is not None:
        tau, dtau = core(speed, pressure, h_nodes, t_nodes, derivative=jacobian)
    else:
        tau, dtau = law.shear_stress(speed, pressure, h_nodes, t_nodes)
    tau = np.broadcast_to(np.asarray(tau, dtype=float), speed.shape)

    moving = speed > 0.0
    safe_speed = np.where(moving, speed, 1.0)
    tw = tau * weight                               # |traction| per node [N]
    per_speed = np.where(moving, tw / safe_speed, 0.0)
    # traction on the element per node: t = -per_speed dv (against the slip); its sums and
    # first moments over the nodes as two small matrix products with the node vectors
    sx = (per_speed * dvx) @ base_x               # (sum, sum xg^2, sum yg) of -t_x
    sy = (per_speed * dvy) @ base_y               # (sum, sum xg^2, sum xg) of -t_y
    fx = -sx[..., 0]
    fy = -sy[..., 0]
    mx = a2c * sy[..., 1]                         # -sum z t_y
    my = -a2c * sx[..., 1]                        # sum z t_x
    mz = b * sx[..., 2] - a * sy[..., 2]          # sum (x t_y - y t_x)
    heat = (tw * speed).sum(-1)

    jac = grad = None
    if jacobian:
        dtau = np.broadcast_to(np.asarray(dtau, dtype=float), speed.shape)
        x = a[e] * xg
        y = b[e] * yg
        z = a2c[e] * xg2
        ex = np.where(moving, dvx / safe_speed, 0.0)
        ey = np.where(moving, dvy / safe_speed, 0.0)
        # d t / d dv = -[tau' e e^T + (tau/s)(I - e e^T)] (per unit area)
        ratio = np.where(moving, tau / safe_speed, dtau)
        axx = -(dtau * ex * ex + ratio * (1.0 - ex * ex)) * weight
        ayy = -(dtau * ey * ey + ratio * (1.0 - ey * ey)) * weight
        axy = -(dtau - ratio) * ex * ey * weight
        # J_ij = sum_k gx_i (A gx_j + B gy_j) + gy_i (B gx_j + C gy_j) with
        # gx = d dv_x/dq = (1, 0, 0, z, -y), gy = d dv_y/dq = (0, 1, -z, 0, x); written out
        # entry by entry (symmetric) to avoid (..., K, 5) temporaries
        a_, b_, c_ = axx, axy, ayy
        az, bz, cz = a_ * z, b_ * z, c_ * z
        t4x = -a_ * y + b_ * x  # (A gx + B gy)_4
        t4y = -b_ * y + c_ * x  # (B gx + C gy)_4
        entries = {
            (0, 0): a_, (0, 1): b_, (0, 2): -bz, (0, 3): az, (0, 4): t4x,
            (1, 1): c_, (1, 2): -cz, (1, 3): bz, (1, 4): t4y,
            (2, 2): cz * z, (2, 3): -bz * z, (2, 4): -z * t4y,
            (3, 3): az * z, (3, 4): z * t4x,
            (4, 4): -y * t4x + x * t4y,
        }
        jac = np.empty(shape_s + (5, 5))
        for (i, j), term in entries.items():
            jac[..., i, j] = jac[..., j, i] = term.sum(-1)
        dheat = (dtau * speed + tau) * weight  # d(tau s)/ds * dA
        hx, hy = dheat * ex, dheat * ey
        grad = np.stack([hx.sum(-1), hy.sum(-1), -(hy * z).sum(-1), (hx * z).sum(-1),
                         (-hx * y + hy * x).sum(-1)], axis=-1)
    return ContactTraction(fx, fy, mx, my, mz, heat, jac, grad)


def integrate_contact_set(law: TractionLaw, contacts: ContactSet, *, n_major: int = 16,
                          n_minor: int = 8, jacobian: bool = False) -> ContactTraction:
    """:func:`integrate` over all elements of a :class:`~thermobearing.state.ContactSet`."""
    return integrate(
        law,
        normal_load=contacts.normal_load,
        semi_major=contacts.semi_major,
        semi_minor=contacts.semi_minor,
        sliding_speed=contacts.sliding_speed,
        transverse_sliding_speed=contacts.transverse_sliding_speed,
        spin_speed=contacts.spin_speed,
        roll_speed=contacts.roll_speed,
        tilt_speed=contacts.tilt_speed,
        deformed_radius=contacts.deformed_radius,
        film_thickness=contacts.film_thickness,
        temperature=contacts.temperature,
        kind=contacts.kind,
        n_major=n_major,
        n_minor=n_minor,
        jacobian=jacobian,
    )


def spin_moment_harris(mu: Any, normal_load: Any, semi_major: Any, semi_minor: Any) -> np.ndarray:
    """Spinning moment of a pure-spin point contact with constant mu: 3 mu Q a E(k) / 8 [N m].

    E(k) is the complete elliptic integral of the second kind with k^2 = 1 - (b/a)^2
    (Harris & Kotzalas 2007, spinning-friction moment; exact for tau = mu p over a Hertz
    ellipse). Used to check :func:`integrate`.
    """
    from scipy.special import ellipe

    a = np.asarray(semi_major, dtype=float)
    b = np.asarray(semi_minor, dtype=float)
    m = 1.0 - (b / a) ** 2
    return 3.0 * np.asarray(mu) * np.asarray(normal_load) * a * ellipe(m) / 8.0
