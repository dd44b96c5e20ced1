"""Newton solvers of the dimensionless line-contact EHL problem (Reynolds + film + load balance).

Equations (paper 000, seed ``000_3b5ca6eed61dd596.txt``, eqs. 7-11, dimensionless)::

    d/dX( eps dP/dX ) - d(rho_t H)/dX = 0,     eps = f_e rho H^3 / (eta lam)            (7)
    H = H0 + X^2/2 - (1/pi) int P(S) ln|X - S| dS                                          (8)
    int P dX = pi/2                                                                         (11)

with ``lam = 12 u_m eta0 R^2 / (b^3 p_H)`` (``u_m`` the entrainment = mean surface speed;
paper 000 writes ``zeta = 3 pi^2 U / (4 W^2)``, the same number), ``eta = eta/eta0`` and
``rho = rho/rho0`` functions of ``P`` (Roelands eq. 9 or Barus, Dowson-Higginson eq. 10), and
``f_e``, ``f_r`` node-wise factors that are 1 in the isothermal case and carry the
effective-viscosity / effective-density integrals of the generalized Reynolds equation in
the thermal case (paper 001, seed ``001_5ba4564faedebfb7.txt``, eq. 6; see
:mod:`thermobearing.ehl.thermal`), ``rho_t = f_r rho``.

Cavitation: the Reynolds condition ``P = dP/dX = 0`` at a free outlet boundary is imposed as the
complementarity problem ``P >= 0, -R(P) >= 0, P * R(P) = 0`` at every node (the variational form
of the Reynolds condition), written as the Fischer-Burmeister equation
``phi(P_i, s_i) = P_i + s_i - sqrt(P_i^2 + s_i^2) = 0`` with ``s_i = -R_i / c_i`` (``c_i`` the
magnitude of the Jacobian diagonal), and solved by semismooth Newton with an Armijo line search
(Fischer 1992; De Luca, Facchinei & Kanzow 1996).

Discretisation: nodes ``X_0..X_{n-1}`` on ``[x_in, x_out]``, ``P_0 = P_{n-1} = 0``; the Poiseuille
term by the conservative central difference with ``eps_{i+1/2} = (eps_i + eps_{i+1})/2``, the wedge
term by the second-order upwind difference (first-order at the first interior node), the load
integral by the trapezoidal rule: second order in ``dX`` away from the free boundary.

Two linear solvers for the Newton step, same residual and Jacobian:

``"dense"`` -- the full Jacobian with the dense influence matrix, LU (LAPACK): the baseline,
    O(n^3) per step.
``"krylov"`` -- GMRES on the exact Jacobian applied matrix-free with the DC-FFT deformation
    (O(n log n) per product), preconditioned by the two-level near/far split of
    :mod:`thermobearing.ehl.precond` (banded near field within ``band`` nodes, the smooth far
    field of the log kernel on a coarse grid, combined exactly by Sherman-Morrison-Woodbury);
    the bordered load-balance row is eliminated by a Schur complement inside the
    preconditioner.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import lapack

from ..errors import ConvergenceError
from . import reynolds
from .kernel import LogKernel
from .precond import TwoLevelPreconditioner

#: Roelands reference pressure p0 [Pa] (paper 000 eq. 9 writes 5.1e-9 1/Pa = 1/p0).
ROELANDS_P0 = 1.96e8


@dataclass(frozen=True)
class Rheology:
    """Dimensionless pressure dependence of viscosity and density.

    Attributes
    ----------
    law : ``"barus"`` (``eta = exp(alpha_bar P)``) or ``"roelands"``
        (``eta = exp(A [(1 + P p_H/p0)^z - 1])``, ``A = ln(eta0/Pa s) + 9.67``; paper 000 eq. 9,
        whose printed exponent "2" is the Roelands index ``z``).
    alpha_bar : ``alpha * p_H`` [-] (Barus).
    roelands_a : ``ln(eta0) + 9.67`` with eta0 in Pa s [-].
    roelands_z : Roelands pressure-viscosity index z [-].
    hertz_pressure : ``p_H`` [Pa], needed by Roelands and Dowson-Higginson.
    compressible : apply the Dowson-Higginson density (paper 000 eq. 10), else ``rho = 1``.
    """

    law: str = "barus"
    alpha_bar: float = 0.0
    roelands_a: float = 0.0
    roelands_z: float = 0.0
    hertz_pressure: float = 1.0
    compressible: bool = True

    def viscosity(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``eta/eta0`` and its derivative with respect to ``P`` (negative P clipped to 0)."""
        Pc = np.maximum(P, 0.0)
        pos = P > 0.0
        if self.law == "barus":
            eta = np.exp(self.alpha_bar * Pc)
            return eta, np.where(pos, self.alpha_bar * eta, 0.0)
        c = self.hertz_pressure / ROELANDS_P0
        base = 1.0 + c * Pc
        powz = base**self.roelands_z
        eta = np.exp(self.roelands_a * (powz - 1.0))
        deta = eta * self.roelands_a * self.roelands_z * powz / base * c
        return eta, np.where(pos, deta, 0.0)

    def density(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``rho/rho0`` (Dowson-Higginson, paper 000 eq. 10) and its derivative in ``P``."""
        if not self.compressible:
            return np.ones_like(P), np.zeros_like(P)
        p = np.maximum(P, 0.0) * self.hertz_pressure
        rho = 1.0 + 0.6e-9 * p / (1.0 + 1.7e-9 * p)
        drho = np.where(P > 0.0, 0.6e-9 * self.hertz_pressure / (1.0 + 1.7e-9 * p) ** 2, 0.0)
        return rho, drho


@dataclass
class NewtonReport:
    """Statistics of one Newton solve (``local_iterations``: local smoothing steps of
    :func:`smooth_spike` before it, counted apart)."""

    iterations: int
    residual: float
    linear_iterations: int
    converged: bool
    local_iterations: int = 0


class LineProblem:
    """Discrete dimensionless line-contact problem on a uniform grid.

    Parameters
    ----------
    n : number of nodes (>= 16).
    x_in, x_out : inlet and outlet of the domain [Hertz half-widths].
    lam : ``12 u_m eta0 R^2 / (b^3 p_H)`` [-].
    rheology : :class:`Rheology`.
    f_e, f_r : node-wise factors on ``eps`` and on the wedge density (thermal EHL), default 1.
    """

    def __init__(
        self,
        n: int,
        x_in: float,
        x_out: float,
        lam: float,
        rheology: Rheology,
        f_e: np.ndarray | None = None,
        f_r: np.ndarray | None = None,
    ) -> None:
        self.n = int(n)
        self.x = np.linspace(x_in, x_out, self.n)
        self.dx = float(self.x[1] - self.x[0])
        self.lam = float(lam)
        self.rheology = rheology
        self.kernel = LogKernel(self.n, self.dx)
        self.f_e = np.ones(self.n) if f_e is None else np.asarray(f_e, float)
        self.f_r = np.ones(self.n) if f_r is None else np.asarray(f_r, float)
        self.x2 = 0.5 * self.x**2
        #: per-grid data reused between Newton iterations (preconditioner geometry)
        self.cache: dict = {}
        #: implicit (backward Euler) squeeze term: time step [b/u_m] and the old rho*H
        self.dt: float | None = None
        self.q_old: np.ndarray | None = None
        # upwind wedge weights: row i uses q_i, q_{i-1}, q_{i-2}
        m = self.n - 2
        self.w0 = np.full(m, 1.5 / self.dx)
        self.w1 = np.full(m, -2.0 / self.dx)
        self.w2 = np.full(m, 0.5 / self.dx)
        self.w0[0], self.w1[0], self.w2[0] = 1.0 / self.dx, -1.0 / self.dx, 0.0

    # ------------------------------------------------------------------ state
    def film(self, P: np.ndarray, H0: float) -> np.ndarray:
        """Film ``H`` at all nodes for the full pressure vector ``P`` (length n)."""
        return H0 + self.x2 + self.kernel.apply(P)

    def evaluate(self, P: np.ndarray, H0: float, jacobian: bool = True) -> dict | None:
        """Residual (and Jacobian pieces) at full pressure ``P``; None if the film is <= 0.

        The node loops are compiled (:mod:`thermobearing.ehl.reynolds`). Face values of
        ``eps`` are arithmetic means (Venner & Lubrecht 2000); the geometric mean was tried
        as well: it is consistent too but its minimum film converges erratically at the exit
        constriction, where eps jumps by ten decades.
        """
        H = self.film(P, H0)
        if not np.all(H > 0.0):
            return None
        eta, deta = self.rheology.viscosity(P)
        rho, drho = self.rheology.density(P)
        inv_dt = 0.0 if self.dt is None else 1.0 / self.dt
        q_old = H if self.q_old is None else self.q_old
        R, eps = reynolds.residual(P, H, eta, rho, self.f_e, self.f_r, self.lam, self.dx,
                                   self.w0, self.w1, self.w2, inv_dt, q_old)
        out = {"P": P, "H": H, "R": R, "eps": eps, "eta": eta, "rho": rho, "deta": deta,
               "drho": drho}
        if jacobian:
            self.add_jacobian(out)
        return out

    def add_jacobian(self, st: dict) -> dict:
        """Add the Jacobian pieces to a residual evaluation ``st`` of :meth:`evaluate`:
        ``s``, ``b`` (rows = offsets -2, -1, 0, +1; ``S`` on interior pressures, ``B`` on node
        films), ``b_sum`` (the ``H0`` column) and ``scale`` (|diagonal|)."""
        inv_dt = 0.0 if self.dt is None else 1.0 / self.dt
        K = self.kernel.coeffs
        s, b, b_sum, scale = reynolds.jacobian_pieces(
            st["P"], st["H"], st["eps"], st["eta"], st["deta"], st["rho"], st["drho"],
            self.f_r, self.dx, self.w0, self.w1, self.w2, inv_dt, K[0], K[1], K[2])
        st.update(s=s, b=b, b_sum=b_sum, scale=scale)
        return st

    # --------------------------------------------------------------- products
    def apply_b(self, b: tuple, v_full: np.ndarray) -> np.ndarray:
        """``B @ v`` for the banded coefficient matrix on node values ``v_full`` (length n);
        the numpy reference of the compiled Newton product :func:`.reynolds.newton_matvec`."""
        b_m2, b_m1, b_0, b_p1 = b
        vm2 = np.concatenate(([0.0], v_full[:-3]))
        return b_m2 * vm2 + b_m1 * v_full[:-2] + b_0 * v_full[1:-1] + b_p1 * v_full[2:]

    def apply_s(self, s: tuple, v: np.ndarray) -> np.ndarray:
        """``S @ v`` for the sparse part on interior values ``v`` (length n-2); the numpy
        reference of the compiled Newton product :func:`.reynolds.newton_matvec`."""
        s_m2, s_m1, s_0, s_p1 = s
        out = s_0 * v
        out[1:] += s_m1[1:] * v[:-1]
        out[2:] += s_m2[2:] * v[:-2]
        out[:-1] += s_p1[:-1] * v[1:]
        return out

    def dense_jacobian_r(self, st: dict) -> np.ndarray:
        """Full ``dR/dP`` over interior nodes (dense; baseline), compiled
        (:func:`thermobearing.ehl.reynolds.dense_jacobian`)."""
        return reynolds.dense_jacobian(np.asarray(st["s"]), np.asarray(st["b"]),
                                       self.kernel.coeffs)

    def banded_jacobian_r(
        self, st: dict, band: int, row_scale: np.ndarray, diag_add: np.ndarray,
        coeffs: np.ndarray | None = None,
    ) -> tuple[np.ndarray, int, int]:
        """``diag(row_scale) dR/dP + diag(diag_add)`` with the influence matrix truncated to
        ``|i-j| <= band``, in LAPACK band storage (``A[i, j]`` at ``ab[kl + ku + i - j, j]``).
        ``coeffs`` replaces the influence coefficients (e.g. the near part of a split)."""
        K = self.kernel.coeffs if coeffs is None else coeffs
        kl, ku = band + 2, band + 1
        offs = np.arange(-kl, ku + 1)
        d = np.array([-2, -1, 0, 1])
        dist = np.abs(d[None, :] - offs[:, None])
        kd = np.where(dist <= band, K[np.minimum(dist, len(K) - 1)], 0.0)  # (nb, 4)
        ab = reynolds.banded_values(np.asarray(st["s"]), np.asarray(st["b"]), kd,
                                    row_scale, diag_add, kl, ku)
        return ab, kl, ku


#: GMRES iteration limit per Newton step (no restarts; the two-level preconditioner needs
#: 2-6 iterations on BM-6; an unconverged step is still used, the line search judges it).
GMRES_MAX_ITERATIONS = 60


def _gmres(matvec, prec, rhs: np.ndarray, rtol: float, max_it: int) -> tuple[np.ndarray, int]:
    """Right-preconditioned GMRES (Saad & Schultz 1986, SIAM J. Sci. Stat. Comput. 7:856-869).

    Arnoldi with classical Gram-Schmidt applied twice (numerically as stable as modified
    Gram-Schmidt, and two matrix-vector products per step instead of a Python loop) and
    Givens rotations; stops when the residual norm ``|rhs - A x|`` (exact in exact arithmetic
    for right preconditioning) is below ``rtol |rhs|``. Returns ``x`` and the iteration
    count. Written out instead of ``scipy.sparse.linalg.gmres`` to save its per-call and
    per-iteration overhead (~2 ms per Newton step at the 1024-node BM-6 solves).
    """
    beta = float(np.linalg.norm(rhs))
    if beta == 0.0:
        return np.zeros_like(rhs), 0
    N = rhs.shape[0]
    V = np.empty((max_it + 1, N))
    Z = np.empty((max_it, N))
    Hh = np.zeros((max_it + 1, max_it))
    cs = np.zeros(max_it)
    sn = np.zeros(max_it)
    g = np.zeros(max_it + 1)
    g[0] = beta
    V[0] = rhs / beta
    k = 0
    for k in range(max_it):  # noqa: B007 - k is used after the loop
        Z[k] = prec(V[k])
        w = matvec(Z[k])
        h = V[: k + 1] @ w
        w = w - h @ V[: k + 1]
        h2 = V[: k + 1] @ w
        w = w - h2 @ V[: k + 1]
        h = h + h2
        hn = float(np.linalg.norm(w))
        col = np.empty(k + 2)
        col[: k + 1] = h
        col[k + 1] = hn
        for j in range(k):  # previous rotations
            a, b = col[j], col[j + 1]
            col[j] = cs[j] * a + sn[j] * b
            col[j + 1] = -sn[j] * a + cs[j] * b
        r = math.hypot(col[k], col[k + 1])
        if r == 0.0:
            cs[k], sn[k] = 1.0, 0.0
        else:
            cs[k], sn[k] = col[k] / r, col[k + 1] / r
        col[k] = r
        col[k + 1] = 0.0
        Hh[: k + 2, k] = col
        g[k + 1] = -sn[k] * g[k]
        g[k] = cs[k] * g[k]
        if abs(g[k + 1]) <= rtol * beta or hn == 0.0:
            break
        V[k + 1] = w / hn
    kk = k + 1
    y = np.linalg.solve(np.triu(Hh[:kk, :kk]), g[:kk]) if kk > 1 else g[:1] / Hh[0, 0]
    return y @ Z[:kk], kk


def newton_solve(
    prob: LineProblem,
    P: np.ndarray,
    H0: float,
    *,
    linear: str = "krylov",
    tol: float = 1e-9,
    max_iter: int = 60,
    band: int | None = None,
    gmres_rtol: float = 1e-2,
    max_dp: float = 0.3,
    reuse_gmres: int = 12,
    preconditioner_memo: dict | None = None,
) -> tuple[np.ndarray, float, NewtonReport]:
    """Semismooth Fischer-Burmeister Newton with Armijo line search on ``0.5 |F|^2``.

    The step is capped to ``max |dP| <= max_dp`` and accepted by a non-monotone Armijo
    test against the largest of the last six merits (Grippo, Lampariello & Lucidi 1986).
    From a poor initial guess use :func:`time_march` first.

    Parameters
    ----------
    prob : the discrete problem.
    P : initial pressure at all n nodes [-] (end values are forced to 0).
    H0 : initial rigid-body film constant [-].
    linear : ``"krylov"`` (GMRES + DC-FFT + two-level preconditioner) or ``"dense"`` (LU).
    tol : convergence tolerance on ``max |F|`` (FB residuals and load balance) [-].
    max_iter : Newton iteration limit.
    band : near-field half-width (nodes) of the two-level preconditioner
        (:class:`thermobearing.ehl.precond.TwoLevelPreconditioner`; its far field is carried
        on a coarse grid of spacing ``band/2``). Default ``max(16, n // 64)``: BM-6 at 2048
        nodes, median 92 ms with 32 against 134 ms with 16 (the coarse grid and
        its dense parts halve); at 1024 nodes 16 and 32 were within the timing noise.
    gmres_rtol : relative tolerance of the inner GMRES solve (an inexact Newton forcing
        term, Dembo, Eisenstat & Steihaug 1982): 1e-2 left the Newton iteration counts of
        BM-6 unchanged (+-1) and cut its GMRES iterations by about a quarter against 1e-4.
        (An Eisenstat-Walker adaptive forcing term was tried: the same Newton
        iteration counts, 305 against 306 over BM-6 at N = 1024 -- the last iterations are
        slowed by the degenerate complementarity node at the film rupture, not by GMRES.)
    reuse_gmres : the far-field (coarse) part of the preconditioner, its costly part, is
        kept from one Newton iteration to the next while the last GMRES solve took at most
        this many iterations; the banded near field is refactored at every iteration (it
        follows the local changes at the exit spike and the rupture point). BM-6 at N = 1024
       : 369 GMRES iterations over the 9 cases with the near field refreshed,
        812 with the whole preconditioner lagged; the far field was rebuilt only once per
        grid level.
    preconditioner_memo : a dict the caller keeps between calls on the same problem (the
        outer fixed point of :func:`thermobearing.ehl.thermal.solve_thermal_line_contact`):
        the preconditioner of the last call is stored there and the next call starts from
        it with the near field refreshed (the rule of ``reuse_gmres`` then applies). The
        full setup was 64 % of a thermal solve's CPU (D1842926 inner contact, n = 1024:
        18 of 28 s in 50 setups, one per outer iteration, each Newton converging in one or
        two steps). The preconditioner changes only the GMRES iterations, not the solution.

    Raises
    ------
    ConvergenceError : no convergence within ``max_iter`` or a line-search failure.
    """
    P = np.array(P, dtype=float)
    P[0] = P[-1] = 0.0
    n = prob.n
    if band is None:
        band = max(16, n // 64)
    m = n - 2
    dx = prob.dx
    half_pi = 0.5 * math.pi
    lin_its = 0

    def merit(Pv, H0v, scale):
        st = prob.evaluate(Pv, H0v, jacobian=False)
        if st is None:
            return math.inf, None
        phi = reynolds.fischer_burmeister(Pv[1:-1], -st["R"] / scale)[0]
        g = dx * np.sum(Pv[1:-1]) - half_pi
        return 0.5 * (float(phi @ phi) + g * g), st

    st = prob.evaluate(P, H0)
    if st is None:
        raise ConvergenceError(
            "ehl.newton", math.inf, "initial film is not positive", {"H0": H0, "n": n}
        )
    res = math.inf
    history: list[float] = []
    factor = None  # the preconditioner, reused while GMRES converges fast
    if preconditioner_memo is not None and preconditioner_memo.get("n") == n \
            and preconditioner_memo.get("problem") is prob:
        factor = preconditioner_memo.get("factor")
    factorizations = 0
    last_gmres = 0
    for it in range(1, max_iter + 1):
        scale = st["scale"]
        s = -st["R"] / scale
        phi, da, db = reynolds.fischer_burmeister(P[1:-1], s)
        g = dx * np.sum(P[1:-1]) - half_pi
        F = np.empty(m + 1)
        F[:m] = phi
        F[m] = g
        res = float(np.max(np.abs(F)))
        if res < tol:
            return P, H0, NewtonReport(it - 1, res, lin_its, True)
        beta = -db / scale  # d phi / d R
        col_h0 = beta * st["b_sum"]
        if linear == "dense":
            A = np.empty((m + 1, m + 1))
            A[:m, :m] = beta[:, None] * prob.dense_jacobian_r(st)
            A[np.arange(m), np.arange(m)] += da
            A[:m, m] = col_h0
            A[m, :m] = dx
            A[m, m] = 0.0
            _lu, _piv, step, info = lapack.dgesv(A, -F, overwrite_a=True)
            if info != 0:
                raise ConvergenceError("ehl.newton", res, "singular Newton matrix",
                                       {"iteration": it, "n": n})
        else:
            if factor is None or last_gmres > reuse_gmres:
                factor = TwoLevelPreconditioner(prob, st, beta, da, col_h0, width=band)
                factorizations += 1
                if preconditioner_memo is not None:
                    preconditioner_memo.update(factor=factor, n=n, problem=prob)
            else:
                factor.refresh_near(st, beta, da, col_h0)
            prec = factor

            s_b = (np.asarray(st["s"]), np.asarray(st["b"]))

            def matvec(v, s_b=s_b, beta=beta, da=da, col_h0=col_h0):
                full = np.zeros(n)
                full[1:-1] = v[:m]
                return reynolds.newton_matvec(v, prob.kernel.apply(full), s_b[0], s_b[1],
                                              beta, da, col_h0, dx)

            step, count = _gmres(matvec, prec, -F, gmres_rtol, GMRES_MAX_ITERATIONS)
            lin_its += count
            last_gmres = count
        # Armijo line search on 0.5|F|^2 (the Newton direction is a descent direction);
        f0 = 0.5 * float(F @ F)
        history.append(f0)
        fref = max(history[-6:])  # non-monotone reference (Grippo et al. 1986)
        t = min(1.0, max_dp / max(float(np.max(np.abs(step[:m]))), 1e-300))
        accepted = False
        for _ in range(30):
            Pt = P.copy()
            Pt[1:-1] += t * step[:m]
            H0t = H0 + t * step[m]
            ft, st_t = merit(Pt, H0t, scale)
            if ft <= fref - 1e-4 * t * 2.0 * f0:
                accepted = True
                break
            t *= 0.5
        if not accepted:
            raise ConvergenceError(
                "ehl.newton", res, "line search failed", {"iteration": it, "n": n, "H0": H0}
            )
        P, H0 = Pt, H0t
        st = prob.add_jacobian(st_t)
    raise ConvergenceError(
        "ehl.newton", res, f"no convergence in {max_iter} Newton iterations", {"n": n}
    )


#: Local smoothing of a prolongated start (:func:`smooth_spike`): half-width of the window
#: [nodes] and number of local Newton steps (BM-6, see the function).
SPIKE_WINDOW = 16
SPIKE_ITERATIONS = 4
#: ... only where the start's largest scaled residual exceeds this (a spike far off) [-]
SPIKE_THRESHOLD = 0.1


def smooth_spike(
    prob: LineProblem,
    P: np.ndarray,
    H0: float,
    *,
    half_width: int | None = None,
    iterations: int | None = None,
    max_dp: float = 0.3,
) -> tuple[np.ndarray, int]:
    """A few local semismooth Newton steps on the nodes around the largest residual (the exit
    pressure spike of a start interpolated from a coarser grid), the rest of the pressure and
    ``H0`` held; returns the smoothed pressure and the number of local steps taken.

    Why: the spike is one or two nodes wide and its height is set by the grid (M = 10,
    L = 20: 1.48 / 1.96 / 3.02 p_H at 128 / 512 / 1024 nodes), so the start interpolated
    from the coarser grid is far off there and nowhere else. The global Newton step overshoots
    at the spike (``exp(alpha_bar P)``, ``alpha_bar = 25`` in that case), the step cap binds
    and 6-7 global iterations (each with a GMRES solve over the whole grid) go into moving
    the spike. The same semismooth Newton (Fischer-Burmeister rows, dense Jacobian block of
    the window with the local influence coefficients, capped step, Armijo on the window's
    merit) on ``2 half_width + 1`` nodes costs one residual evaluation per step. A few steps
    only: the local problem with the held surroundings is not the global one, and solving
    it to convergence made the global Newton slower (BM-6, M = 10, L = 20 at 1024 nodes:
    10 global iterations without, 6-7 after 2-4 local steps, 11 after 6, 23 after local
    convergence). Newton with line search: the relaxation is a nonlinear local smoother in
    the sense of Venner & Lubrecht (2000, ch. 4), applied once, where the error is.
    Paper 000 (seed ``000_3b5ca6eed61dd596.txt``) eqs. 7-11 are the discrete equations.
    """
    half_width = SPIKE_WINDOW if half_width is None else int(half_width)
    iterations = SPIKE_ITERATIONS if iterations is None else int(iterations)
    m = prob.n - 2
    st = prob.evaluate(P, H0)
    if st is None:
        return P, 0
    phi, _, _ = reynolds.fischer_burmeister(P[1:-1], -st["R"] / st["scale"])
    c0 = int(np.argmax(np.abs(phi)))
    if abs(phi[c0]) <= SPIKE_THRESHOLD:
        return P, 0
    r0, r1 = max(0, c0 - half_width), min(m, c0 + half_width + 1)
    K = prob.kernel.coeffs
    P = P.copy()
    done = 0
    for _ in range(iterations):
        scale = st["scale"]
        phi, da, db = reynolds.fischer_burmeister(P[1:-1], -st["R"] / scale)
        loc = phi[r0:r1]
        f0 = 0.5 * float(loc @ loc)
        if f0 == 0.0:
            break
        J = reynolds.window_jacobian(np.asarray(st["s"]), np.asarray(st["b"]), K, r0, r1)
        A = (-db[r0:r1] / scale[r0:r1])[:, None] * J
        A[np.arange(r1 - r0), np.arange(r1 - r0)] += da[r0:r1]
        try:
            d = np.linalg.solve(A, -loc)
        except np.linalg.LinAlgError:
            break
        t = min(1.0, max_dp / max(float(np.max(np.abs(d))), 1e-300))
        accepted = None
        for _ in range(20):
            Pt = P.copy()
            Pt[1 + r0:1 + r1] += t * d
            st_t = prob.evaluate(Pt, H0, jacobian=False)
            if st_t is not None:
                ph = reynolds.fischer_burmeister(Pt[1:-1], -st_t["R"] / scale)[0][r0:r1]
                if 0.5 * float(ph @ ph) <= f0 * (1.0 - 1e-4 * t):
                    accepted = (Pt, st_t)
                    break
            t *= 0.5
        if accepted is None:
            break
        P, st = accepted[0], prob.add_jacobian(accepted[1])
        done += 1
    return P, done


def time_march(
    prob: LineProblem,
    P: np.ndarray,
    H0: float,
    *,
    linear: str = "dense",
    dt0: float = 0.05,
    dt_final: float = 1e4,
    max_steps: int = 100,
    tol: float = 1e-8,
    band: int | None = None,
    step_tol: float = 1e-5,
) -> tuple[np.ndarray, float, NewtonReport]:
    """Reach the steady solution from a poor guess by implicit time stepping of the transient
    Reynolds equation (squeeze term ``d(rho H)/dT``, ``T = t u_m / b``), load balanced at every
    step; the step grows geometrically, so the march ends as Newton on the steady problem.

    This is the physical globalisation of Newton for EHL: each backward-Euler step is a small
    change that Newton solves in a few iterations, and the transient decays as the oil crosses
    the contact (a few ``b/u_m``).

    The transient steps are solved to ``step_tol`` only (they are a path to the steady state,
    not a result: at 1e-8 the Fischer-Burmeister Newton often spent its 12 iterations at a
    residual of 1e-5 near the exit spike and the step was rejected); the final steady Newton
    solve goes to ``tol``. ``max_steps`` bounds the accepted plus rejected steps (a march
    that succeeds takes 10-30; one that oscillates between growing and cut steps, e.g. a
    heavily loaded contact on a grid too coarse for its exit spike, M = 1000 on 256 nodes,
    then fails in about a second instead of running on).
    """
    dt = dt0
    steps = its = lin = rejected = 0
    last_res = math.nan
    try:
        while dt < dt_final:
            if steps + rejected > max_steps:
                raise ConvergenceError(
                    "ehl.time_march", last_res,
                    f"too many time steps ({steps} accepted, {rejected} rejected; dt = {dt:.3g})",
                    {"n": prob.n})
            prob.dt = dt
            prob.q_old = prob.f_r * prob.rheology.density(P)[0] * prob.film(P, H0)
            try:
                Pn, H0n, rep = newton_solve(
                    prob, P, H0, linear=linear, max_iter=12, tol=max(tol, step_tol), band=band
                )
            except ConvergenceError as err:
                rejected += 1
                last_res = err.residual
                dt *= 0.3
                if dt < 1e-6:
                    raise ConvergenceError(
                        "ehl.time_march", err.residual, "time step collapsed", {"n": prob.n}
                    ) from err
                continue
            P, H0 = Pn, H0n
            steps += 1
            its += rep.iterations
            lin += rep.linear_iterations
            dt *= 3.0 if rep.iterations <= 4 else 1.5
    finally:
        prob.dt = None
        prob.q_old = None
    P, H0, rep = newton_solve(prob, P, H0, linear=linear, tol=tol, band=band)
    return P, H0, NewtonReport(its + rep.iterations, rep.residual, lin + rep.linear_iterations,
                               True)
