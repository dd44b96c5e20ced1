"""Thermal EHL of a line contact: film energy equation with solid conduction, generalized Reynolds.

Paper 001 (Shi & Wang 2015, seed ``001_5ba4564faedebfb7.txt``) solves the generalized Reynolds
equation (its eq. 6, after Yang & Wen 1990) with the film energy equation (its eq. 8) by column
scanning. Here the same in line-contact form, steady state:

Film (0 <= z <= h), paper 001 eq. 8 without the y-terms::

    rho c u dT/dx - k d2T/dz2 = -(T/rho)(d rho/dT) u dp/dx + tau^2/eta,   tau = eta du/dz

The vertical convection term ``-q dT/dz`` of eq. 8 is dropped (it is small where ``w = dz/dt``
is small, i.e. everywhere except the steep exit constriction); this is stated, not hidden.
Solids (moving with their surface speed ``u_s``, semi-infinite, T = T_in at depth and inlet)::

    rho_s c_s u_s dT/dx = k_s d2T/dz_s2

with continuity of temperature and heat flux at the two surfaces. Velocity and shear stress
across the film for a viscosity varying with z (Yang & Wen 1990)::

    F0(z) = int_0^z dz'/eta,  F1(z) = int_0^z z' dz'/eta
    u(z) = u_a + dp/dx (F1(z) - F1(h) F0(z)/F0(h)) + (u_b - u_a) F0(z)/F0(h)
    tau(z) = dp/dx (z - F1(h)/F0(h)) + (u_b - u_a)/F0(h)

Effective quantities (paper 001 below eq. 6)::

    eta_e = h/F0(h), eta_e' = h^2/F1(h), rho_e = (1/h) int rho dz,
    rho_e' = (1/h^2) int rho F0 dz, rho_e'' = (1/h^3) int rho F1 dz
    (rho/eta)_e = 12 (eta_e rho_e'/eta_e' - rho_e'')

Mass flux ``q = -(h^3/12) (rho/eta)_e dp/dx + h [rho_e u_a + eta_e rho_e' (u_b - u_a)]``.
Paper 001 writes the Couette part as ``12 U ... rho* h`` with ``rho* = 2(rho_e - eta_e rho_e')``,
which is this expression for ``u_b = 0`` only; the general form above is used (it reduces to
``rho u_m h`` in the isothermal limit). Both enter the Reynolds solver as node-wise factors
``f_e`` and ``f_r`` on the isothermal coefficients (:mod:`thermobearing.ehl.solver`).

Coupling: fixed point on (pressure, temperature) with under-relaxed temperatures (the first
update at most ``MAX_FIRST_TEMPERATURE_STEP``); each outer step solves the Reynolds problem by
Newton from the previous pressure and the energy equation by column scanning (upwind in x,
implicit tridiagonal in z per column, sweeps alternating downstream and upstream for the reverse
flow of the inlet, :func:`_column_scan`). The column sweep is the one numba loop of this
package's EHL code.
Viscosity, density, c and k come from :class:`thermobearing.lubricant.Lubricant`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..errors import (
    ConvergenceError,
    InputError,
    check_positive,
    check_range,
    check_temperature,
)
from .line import (
    LineEHLSolution,
    line_contact_case,
    nodes_for,
    solve_dimensionless,
)
from .solver import LineProblem, newton_solve, time_march

#: Largest temperature change of the first outer iteration [K] (its relaxed update is scaled
#: down to it; the fixed point is unchanged). The first iteration heats the film at the
#: viscosity of the cold inlet: D1842926's most loaded inner contact (430 kN/m, 44 m/s, SRR
#: 0.05, Eyring 5 MPa) then jumped by 196 K, beyond the oil's viscosity law, once the column
#: scan converged its inlet (below); limited, it converges (Tmax 414 K). Only the first: a
#: limit on every iteration also kept a Newtonian sliding film (which runs away, see
#: ``eyring_stress``) oscillating for all ``max_outer`` iterations instead of failing at once.
#: 4 D1842926 nodes (n = 512-2048, tolerance 0.03 K): 40 / 80 / 120 K take 24-34 / 26-30 /
#: 25-28 outer iterations, films within 1e-3 of each other.
MAX_FIRST_TEMPERATURE_STEP = 80.0
#: The column scan of an outer iteration stops when a sweep changes the temperatures by less
#: than this fraction of the previous outer iteration's change (at most 1 K, at least 1e-4 K):
#: early outer iterations, which move the field by tens of kelvin, need no 1e-4 K inner
#: solve. 8 D1842926 nodes: scan CPU 2.5x smaller, the same outer iterations (+-1), films
#: and forces within 1.1e-3 of the fixed point as with 1e-4 K throughout (0.05: 4x smaller,
#: still within 1e-3).
INNER_TOLERANCE_FRACTION = 0.01


@dataclass(frozen=True)
class SolidThermal:
    """Thermal properties of a solid body: density [kg/m^3], specific_heat [J/(kg K)],
    thermal_conductivity [W/(m K)]."""

    density: float
    specific_heat: float
    thermal_conductivity: float

    @classmethod
    def of(cls, material) -> SolidThermal:
        """From a :class:`thermobearing.materials.Material` (or any object with the fields)."""
        return cls(float(material.density), float(material.specific_heat),
                   float(material.thermal_conductivity))


@dataclass(frozen=True)
class ThermalLineEHLSolution:
    """Thermal EHL solution of a line contact (SI).

    Attributes
    ----------
    x : nodes [m]; pressure [Pa]; film [m];
    temperature : (n, nz) film temperature [K], z from surface 1 (index 0) to surface 2;
    mid_temperature, surface1_temperature, surface2_temperature : (n,) [K];
    central_film, minimum_film [m], max_pressure [Pa], max_temperature [K];
    isothermal : the isothermal solution at the inlet temperature (same grid);
    thermal_reduction : central_film / isothermal central film [-];
    shear_force : film shear force per unit length on surface 1, ``int tau(z=0) dx`` [N/m]
        (rolling direction; Newtonian, temperature-dependent viscosity);
    rolling_force : its Poiseuille (pressure-gradient) part ``-int (h/2) dp/dx dx`` [N/m];
    outer_iterations, temperature_change (last max |dT| [K]), seconds.
    """

    x: np.ndarray
    pressure: np.ndarray
    film: np.ndarray
    temperature: np.ndarray
    mid_temperature: np.ndarray
    surface1_temperature: np.ndarray
    surface2_temperature: np.ndarray
    central_film: float
    minimum_film: float
    max_pressure: float
    max_temperature: float
    isothermal: LineEHLSolution
    thermal_reduction: float
    shear_force: float
    rolling_force: float
    outer_iterations: int
    temperature_change: float
    seconds: float


@njit(cache=True)
def _column_scan(T, u, adv, g, src, lin, dx, t_in, sweeps, tol):  # pragma: no cover - numba
    """Upwind-in-x, implicit-in-z sweeps of the steady energy equation (in place).

    T (n, nc): temperatures, column 0 and the two deep nodes are Dirichlet (t_in).
    u (n, nc): velocity [m/s]; adv (n, nc): rho c times control length [J/(m^2 K)];
    g (n, nc-1): conductance k/dz between nodes c and c+1 [W/(m^2 K)];
    src (n, nc): heat source times control length [W/m^2]; lin (n, nc): linear source
    coefficient times control length [W/(m^2 K)] (source = lin * T).

    Block Gauss-Seidel by columns (one tridiagonal solve in z per column), the sweeps
    alternating in direction: odd sweeps run downstream (i increasing), even ones upstream,
    so that the reverse flow of the inlet (u < 0, upwind node i + 1) gets its upstream value
    within one sweep too (a downstream-only sweep carried it one column per sweep: the
    2048-node inlet of a light contact never converged in 50 sweeps). The column matrices do
    not change between sweeps: their LU factors are computed once per call.
    Returns the last sweep's max |dT| [K].
    """
    n, nc = T.shape
    coef = np.zeros((n, nc))
    upi = np.zeros((n, nc), dtype=np.int64)  # upwind column of each node
    mult = np.zeros((n, nc))  # Thomas multipliers
    inv = np.ones((n, nc))  # 1 / pivots
    cc = np.zeros((n, nc))  # super-diagonal
    for i in range(1, n):
        piv = 1.0  # row 0 is Dirichlet (b = 1, c = 0)
        for k in range(1, nc - 1):
            ck = adv[i, k] * abs(u[i, k]) / dx
            if u[i, k] >= 0.0:
                upi[i, k] = i - 1
            elif i < n - 1:
                upi[i, k] = i + 1
            else:
                upi[i, k] = i
                ck = 0.0
            coef[i, k] = ck
            cc_prev = cc[i, k - 1]
            m = -g[i, k - 1] / piv
            piv = g[i, k - 1] + g[i, k] + ck - lin[i, k] - m * cc_prev
            mult[i, k] = m
            inv[i, k] = 1.0 / piv
            cc[i, k] = -g[i, k]
        # last row Dirichlet: a = 0, b = 1
        inv[i, nc - 1] = 1.0
    d = np.empty(nc)
    change = 0.0
    for sweep in range(sweeps):
        change = 0.0
        for j in range(1, n):
            i = j if sweep % 2 == 0 else n - j
            d[0] = t_in
            for k in range(1, nc - 1):
                d[k] = src[i, k] + coef[i, k] * T[upi[i, k], k] - mult[i, k] * d[k - 1]
            d[nc - 1] = t_in
            new = d[nc - 1]
            dtk = abs(new - T[i, nc - 1])
            if dtk > change:
                change = dtk
            T[i, nc - 1] = new
            for k in range(nc - 2, -1, -1):
                new = (d[k] - cc[i, k] * T[i, k + 1]) * inv[i, k]
                dtk = abs(new - T[i, k])
                if dtk > change:
                    change = dtk
                T[i, k] = new
        if change < tol:
            break
    return change


def _solid_grid(depth: float, ns: int, first: float) -> np.ndarray:
    """Depths (0 at the surface) of ``ns`` nodes, geometric from ``first`` to ``depth``."""
    if ns < 3:
        raise InputError("ns", ns, "at least 3 nodes in each solid")
    # find ratio r with first * (r^(ns-1) - 1)/(r - 1) = depth
    lo, hi = 1.0 + 1e-9, 10.0
    for _ in range(200):
        r = 0.5 * (lo + hi)
        total = first * (r ** (ns - 1) - 1.0) / (r - 1.0)
        if total > depth:
            hi = r
        else:
            lo = r
    steps = first * r ** np.arange(ns - 1)
    return np.concatenate(([0.0], np.cumsum(steps) * depth / np.sum(steps)))


def _couette_eyring_stress(eta, h, zeta, du, tau0):
    """Couette shear stress [Pa] of a Ree-Eyring film column, signed like ``du``.

    Uniform stress across the film, strain rate ``(tau0/eta) sinh(tau/tau0)`` (Johnson &
    Tevaarwerk 1977): ``int_0^h (tau0/eta) sinh(tau/tau0) dz = |du|`` gives
    ``tau = tau0 asinh(|du| / (tau0 F0(h)))`` with ``F0(h) = int_0^h dz/eta``.
    ``eta`` (n, nz) [Pa s], ``h`` (n,) [m], ``du`` (n,) [m/s].
    """
    dzeta = np.diff(zeta)
    f0 = np.sum(0.5 * (1.0 / eta[:, 1:] + 1.0 / eta[:, :-1]) * dzeta[None, :], axis=1) * h
    return np.sign(du) * tau0 * np.arcsinh(np.abs(du) / (tau0 * f0))


def _film_fields(lub, T, p, h, zeta, dpdx, ua, ub, eyring_stress=None):
    """Viscosity, density, velocity, shear stress and the effective integrals (n, nz).

    With ``eyring_stress`` tau0 [Pa] the viscosity is the Ree-Eyring effective viscosity of
    the column's Couette stress tau_c, ``eta x/sinh(x)``, ``x = tau_c/tau0``
    (:func:`_couette_eyring_stress`), so that the Couette flow still carries the surface speed
    difference; in pure rolling (``ua == ub``) this is the Newtonian field.
    """
    eta = np.asarray(lub.dynamic_viscosity(T, p[:, None] * np.ones_like(T)), dtype=float)
    rho = np.asarray(lub.density(T, p[:, None] * np.ones_like(T)), dtype=float)
    if eyring_stress is not None and np.any(ub != ua):
        du = np.broadcast_to(np.asarray(ub - ua, dtype=float), h.shape)
        tc = np.abs(_couette_eyring_stress(eta, h, zeta, du, eyring_stress))
        x = np.minimum(tc / eyring_stress, 700.0)
        fac = np.where(x > 1e-8, x / np.sinh(np.maximum(x, 1e-8)), 1.0)
        eta = eta * fac[:, None]
    z = h[:, None] * zeta[None, :]
    dzeta = np.diff(zeta)

    def cumint(f):
        mid = 0.5 * (f[:, 1:] + f[:, :-1]) * dzeta[None, :] * h[:, None]
        return np.concatenate((np.zeros((f.shape[0], 1)), np.cumsum(mid, axis=1)), axis=1)

    F0 = cumint(1.0 / eta)
    F1 = cumint(z / eta)
    F0h, F1h = F0[:, -1], F1[:, -1]
    u = (ua + dpdx[:, None] * (F1 - (F1h / F0h)[:, None] * F0)
         + (ub - ua) * F0 / F0h[:, None])
    tau = dpdx[:, None] * (z - (F1h / F0h)[:, None]) + ((ub - ua) / F0h)[:, None]
    eta_e = h / F0h
    eta_e1 = h**2 / F1h
    # outer integrals by Simpson's rule (exact for the quadratic rho*F1 of a uniform film)
    nz = zeta.size
    wts = np.ones(nz)
    wts[1:-1:2], wts[2:-1:2] = 4.0, 2.0
    wts *= (zeta[1] - zeta[0]) / 3.0
    rho_e = (rho @ wts)
    rho_e1 = ((rho * F0) @ wts) / h
    rho_e2 = ((rho * F1) @ wts) / h**2
    rho_over_eta_e = 12.0 * (eta_e * rho_e1 / eta_e1 - rho_e2)
    couette = rho_e * ua + eta_e * rho_e1 * (ub - ua)
    return eta, rho, u, tau, rho_over_eta_e, couette


def solve_thermal_line_contact(
    load_per_length: float,
    radius: float,
    effective_modulus: float,
    entrainment_speed: float,
    slide_to_roll: float,
    lubricant,
    inlet_temperature: float,
    *,
    solid1: SolidThermal,
    solid2: SolidThermal | None = None,
    n: int = 512,
    nz: int = 11,
    ns: int = 14,
    relax: float = 0.6,
    max_outer: int = 120,
    tol_temperature: float = 0.03,
    max_grid_error: float = 0.05,
    eyring_stress: float | None = None,
) -> ThermalLineEHLSolution:
    """Thermal Newtonian EHL of a line contact (paper 001 eqs. 6 and 8, line-contact form).

    Parameters
    ----------
    load_per_length : w' [N/m]; radius : R_x [m]; effective_modulus : E' [Pa];
    entrainment_speed : u_m = (u1 + u2)/2 [m/s]; slide_to_roll : (u1 - u2)/u_m [-]
        (|SRR| < 2: both surfaces move in +x);
    lubricant : :class:`thermobearing.lubricant.Lubricant` (viscosity(T, p), density(T, p),
        specific_heat(T), thermal_conductivity(T), roelands_index(T) or Barus alpha);
    inlet_temperature : oil and solid bulk temperature [K];
    solid1, solid2 : thermal properties of the two bodies (surface 1 moves at u1 and sits at
        z = 0); solid2 defaults to solid1;
    n : pressure/temperature nodes in x (minimum; raised by :func:`.line.nodes_for` for light
        loads); nz : nodes across the film; ns : nodes in each solid;
    relax : under-relaxation of the temperature update (0.6: 8 D1842926 table nodes, n =
        512-2048, converge to 0.03 K in 19-30 outer iterations; 5 of them take 30-34 at 0.5,
        21-29 at 0.7 and 22-64 at 0.8); max_outer : fixed-point limit;
    tol_temperature : convergence on max |dT| between outer iterations [K]. The films, forces
        and temperatures of those 8 nodes at the default 0.03 K differ from the fixed point
        (solved to 1e-3 K) by at most 9e-4 (films), 1e-3 (shear force), 3e-4 (rolling force),
        1e-4 (maximum pressure) relative and 0.05 K (maximum temperature); at 0.1 K by up to
        2.7e-3 (films) and 2e-3 (shear force).
    eyring_stress : None (Newtonian, paper 001) or the Eyring stress tau0 [Pa] of a
        Ree-Eyring film (Johnson & Tevaarwerk 1977; typically 2-10 MPa): the Couette flow of a
        sliding contact then shears at the Eyring effective viscosity (see
        :func:`_film_fields`). Newtonian sliding at Hertzian pressures and tens of m/s gives a
        shear heating that the fixed point cannot carry (the film viscosity runs away below
        the Roelands range and the solver raises); pure rolling is the same in both.

    Raises
    ------
    InputError : bad input (and the isothermal solver's range errors).
    ConvergenceError : the coupled fixed point did not converge (residual = last max |dT|).
    """
    t0 = time.perf_counter()
    check_temperature("inlet_temperature", inlet_temperature)
    if nz < 5 or nz % 2 == 0:
        raise InputError("nz", nz, "an odd number >= 5 (Simpson's rule across the film)")
    check_positive("entrainment_speed", entrainment_speed)
    if not abs(slide_to_roll) < 2.0:
        raise InputError("slide_to_roll", slide_to_roll, "|SRR| < 2 (both surfaces moving)")
    # fixed-point settings: relax 0 would return the isothermal film as if converged,
    # tol_temperature 0 drove the iteration into the lubricant's viscosity range error
    check_range("relax", relax, 0.0, 1.0, low_inclusive=False)
    check_positive("tol_temperature", tol_temperature)
    if isinstance(max_outer, bool) or not isinstance(max_outer, int | np.integer) \
            or max_outer < 1:
        raise InputError("max_outer", max_outer, "a whole number of fixed-point sweeps >= 1")
    solid2 = solid2 or solid1
    T_in = float(inlet_temperature)
    eta0 = float(lubricant.dynamic_viscosity(T_in))
    rho0 = float(lubricant.density(T_in))
    if getattr(lubricant, "pressure_law", "roelands") == "barus":
        case = line_contact_case(load_per_length, radius, effective_modulus, entrainment_speed,
                                 eta0, alpha=float(lubricant.pressure_viscosity_coefficient(T_in)))
    else:
        case = line_contact_case(load_per_length, radius, effective_modulus, entrainment_speed,
                                 eta0, roelands_z=float(lubricant.roelands_index(T_in)))
    rheo = case.rheology(compressible=True)
    b, pH = case.half_width, case.hertz_pressure
    n = nodes_for(case.M, n, case.L)
    iso = solve_dimensionless(case.M, case.L, n=n, rheology=rheo, max_grid_error=max_grid_error,
                              reference=(radius, b, pH, eta0))
    from dataclasses import replace

    iso = replace(iso, entrainment_speed=float(entrainment_speed))
    um = float(entrainment_speed)
    ua = um * (1.0 + 0.5 * slide_to_roll)
    ub = um * (1.0 - 0.5 * slide_to_roll)
    x_in, x_out = float(iso.X[0]), float(iso.X[-1])
    prob = LineProblem(n, x_in, x_out, 3.0 * math.pi**2 / (8.0 * case.M**2), rheo)
    P, X = iso.P.copy(), iso.X
    H0 = float(iso.H[0] - prob.x2[0] - prob.kernel.apply(P)[0])
    x = X * b
    dx = float(x[1] - x[0])
    zeta = np.linspace(0.0, 1.0, nz)
    c_f = float(lubricant.specific_heat(T_in))
    k_f = float(lubricant.thermal_conductivity(T_in))
    # solid grids: resolve the thermal boundary layer sqrt(kappa L / u)
    grids = []
    for solid, us in ((solid1, ua), (solid2, ub)):
        kappa = solid.thermal_conductivity / (solid.density * solid.specific_heat)
        delta = math.sqrt(kappa * (x_out - x_in) * b / max(abs(us), 1e-12))
        depth = min(max(12.0 * delta, 0.05 * b), 3.15 * b)
        grids.append(_solid_grid(depth, ns, min(0.02 * delta, depth / (4 * ns))))
    za, zb = grids
    nc = 2 * ns + nz - 2
    T = np.full((n, nc), T_in)
    dTdT = 0.05
    memo: dict = {}  # the Newton preconditioner, kept across outer iterations
    change = math.inf
    outer = 0
    for outer in range(1, max_outer + 1):  # noqa: B007 - used after the loop
        p = P * pH
        h = prob.film(P, H0) * b * b / radius
        dpdx = np.gradient(p, x)
        Tf = T[:, ns - 1: ns - 1 + nz]
        eta, rho, u, tau, roe, couette = _film_fields(lubricant, Tf, p, h, zeta, dpdx, ua, ub,
                                                      eyring_stress)
        if outer > 1:
            # pressure gradient consistent with the flow the Reynolds solve balanced: at a
            # fixed flux deficit dp/dx scales with 1/(rho/eta)_e, so a hotter, thinner oil
            # carries a smaller gradient (without this the lagged gradient drives a spurious
            # runaway of the Poiseuille heating tau^2/eta)
            eta_c, _ = rheo.viscosity(P)
            rho_c, _ = rheo.density(P)
            roe_used = prob.f_e * (rho_c / eta_c) * (rho0 / eta0)
            dpdx = dpdx * np.minimum(1.0, roe_used / roe)
            eta, rho, u, tau, roe, couette = _film_fields(lubricant, Tf, p, h, zeta, dpdx, ua,
                                                          ub, eyring_stress)
        # ---- energy equation -------------------------------------------------
        rho_t = np.asarray(lubricant.density(Tf + dTdT, p[:, None] * np.ones_like(Tf)))
        drho_dT = (rho_t - rho) / dTdT
        dzf = h / (nz - 1)
        # column arrays: solid a (deep -> surface), film, solid b (surface -> deep)
        ucol = np.empty((n, nc))
        adv = np.zeros((n, nc))
        src = np.zeros((n, nc))
        lin = np.zeros((n, nc))
        g = np.empty((n, nc - 1))
        dsa = np.diff(za)[::-1]  # spacing between consecutive solid-a nodes (deep first)
        dsb = np.diff(zb)
        ucol[:, :ns] = ua
        ucol[:, ns - 1: ns - 1 + nz] = u
        ucol[:, ns - 2 + nz:] = ub
        vol_f = np.outer(dzf, np.ones(nz))
        vol_f[:, 0] *= 0.5
        vol_f[:, -1] *= 0.5
        heat = tau**2 / eta
        comp = -(drho_dT / rho) * u * dpdx[:, None]  # source = comp * T
        sl = slice(ns - 1, ns - 1 + nz)
        adv[:, sl] += rho * c_f * vol_f
        src[:, sl] += heat * vol_f
        # compression heating (comp > 0) explicit, expansion cooling (comp < 0) implicit
        lin[:, sl] += np.minimum(comp, 0.0) * vol_f
        src[:, sl] += np.maximum(comp, 0.0) * vol_f * Tf
        # solid a control lengths
        va = np.zeros(ns)
        va[:-1] += 0.5 * dsa
        va[1:] += 0.5 * dsa
        vb = np.zeros(ns)
        vb[1:] += 0.5 * dsb
        vb[:-1] += 0.5 * dsb
        adv[:, :ns] += solid1.density * solid1.specific_heat * va[None, :]
        adv[:, ns - 2 + nz:] += solid2.density * solid2.specific_heat * vb[None, :]
        g[:, : ns - 1] = solid1.thermal_conductivity / dsa[None, :]
        g[:, ns - 1: ns - 2 + nz] = k_f / dzf[:, None]
        g[:, ns - 2 + nz:] = solid2.thermal_conductivity / dsb[None, :]
        T_old = T.copy()
        _column_scan(T, ucol, adv, g, src, lin, dx, T_in, 50,
                     max(1e-4, INNER_TOLERANCE_FRACTION * min(change, 100.0)))
        step = relax * (T - T_old)
        change = float(np.max(np.abs(step)))
        if outer == 1 and change > MAX_FIRST_TEMPERATURE_STEP:
            step *= MAX_FIRST_TEMPERATURE_STEP / change
        T = T_old + step
        # ---- generalized Reynolds with the new temperatures ------------------
        Tf = T[:, ns - 1: ns - 1 + nz]
        try:
            eta, rho, u, tau, roe, couette = _film_fields(lubricant, Tf, p, h, zeta, dpdx, ua,
                                                          ub, eyring_stress)
        except InputError as exc:  # the fixed point's own temperatures, not the caller's
            hint = ("a Newtonian film sheared at Hertzian pressure heats without bound: give "
                    "eyring_stress (Ree-Eyring, typically 2-10 MPa)" if eyring_stress is None
                    else "use thermobearing.film with a thermal reduction factor instead")
            raise ConvergenceError(
                "ehl.thermal", change,
                f"the film temperature ran away to {float(Tf.max()):.4g} K at outer iteration "
                f"{outer}, beyond the lubricant's laws ({exc}); {hint}",
                {"M": case.M, "L": case.L, "max_temperature": float(Tf.max())}) from None
        eta_iso, _ = rheo.viscosity(P)
        rho_iso, _ = rheo.density(P)
        f_e = (roe / (rho0 / eta0)) / (rho_iso / eta_iso)
        f_r = (couette / (rho0 * um)) / rho_iso
        # relax the factors geometrically (they span decades where the film heats)
        prob.f_e = np.exp(np.log(prob.f_e) + relax * (np.log(f_e) - np.log(prob.f_e)))
        prob.f_r = prob.f_r + relax * (f_r - prob.f_r)
        try:
            P, H0, _rep = newton_solve(prob, P, H0, linear="krylov", tol=1e-8,
                                       preconditioner_memo=memo)
        except ConvergenceError:
            P, H0, _rep = time_march(prob, P, H0, linear="krylov", dt0=0.5)
        if change < tol_temperature:
            break
    else:
        raise ConvergenceError(
            "ehl.thermal", change,
            f"thermal EHL fixed point did not converge in {max_outer} iterations "
            f"(M={case.M:.4g}, L={case.L:.4g}); use thermobearing.film with a thermal "
            "reduction factor (THERMAL_FILM) instead", {"M": case.M, "L": case.L},
        )
    p = P * pH
    H = prob.film(P, H0)
    h = H * b * b / radius
    dpdx = np.gradient(p, x)
    Tf = T[:, ns - 1: ns - 1 + nz]
    eta, rho, u, tau, roe, couette = _film_fields(lubricant, Tf, p, h, zeta, dpdx, ua, ub,
                                                      eyring_stress)
    pos = np.nonzero(P > 0)[0]
    fill = np.ones(n)
    if pos.size and pos[-1] + 1 < n:
        k = pos[-1] + 1
        fill[k:] = np.minimum(1.0, h[k] / h[k:])
    # force of the film on surface 1 = +tau(z=0) (paper 000 eq. 5 in the thermal case)
    shear = float(np.trapezoid(tau[:, 0] * fill, x))
    rolling = -float(np.trapezoid(0.5 * h * dpdx, x))
    hc = float(np.interp(0.0, x, h))
    return ThermalLineEHLSolution(
        x=x, pressure=p, film=h, temperature=Tf.copy(), mid_temperature=Tf[:, nz // 2].copy(),
        surface1_temperature=Tf[:, 0].copy(), surface2_temperature=Tf[:, -1].copy(),
        central_film=hc, minimum_film=float(h.min()), max_pressure=float(p.max()),
        max_temperature=float(Tf.max()), isothermal=iso,
        thermal_reduction=hc / iso.central_film, shear_force=shear, rolling_force=rolling,
        outer_iterations=outer, temperature_change=change,
        seconds=time.perf_counter() - t0,
    )
