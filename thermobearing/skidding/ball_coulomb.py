"""Diagnosis of a ball skidding failure in oil so cold that the traction is a Coulomb step.

One job: say, when every fallback of :func:`~thermobearing.skidding.ball.solve_ball` has
failed, whether the loaded contacts are beyond what the traction model can resolve in double
precision (:func:`coulomb_traction_note`), so that the error tells the user why and what to
change instead of only a residual.

The solver's traction law (Eyring with a limiting shear stress, paper 002 eq. 11 bounded;
:class:`thermobearing.traction.EyringLimitingShearTraction`) gives at a node of pressure p,
film h and sliding speed s

    tau_E = tau0 asinh(eta(T, p) s / (tau0 h)),  capped by Lambda p,

so tau_E reaches half the limiting shear stress at

    s_half = (tau0 h / eta(T, p)) sinh(Lambda p / (2 tau0)).

The sliding speed of a node is a difference of surface speeds of the order of the
entrainment speed u_e, known to about eps u_e (eps = 2.2e-16, double precision). Where
s_half < eps u_e the traction jumps from about 0 to Lambda p between neighbouring
representable slips: at every quadrature node it is a Coulomb step, and the traction
integrated over the n_major x n_minor nodes of a contact jumps by about Lambda p pi a b /
(n_major n_minor) each time the slip of one node changes sign as the ball's spin moves (a
continuous contact would smooth that out). Whether a state within a tolerance far below the
jump lies between the steps is then chance: QJ1044 under 4 kN axial at -37 degC in ISO VG100
converges to 1e-10 although its contacts are in this regime, while the catalogue 6206 at
1132 r/min and 322 N radial with its contacts at -38 degC in ISO VG46 (eta0 = 59 Pa s,
s_half ~ 1e-27 m/s against eps u_e = 6e-16 m/s, node jumps up to 0.27 N) stopped at 3.5e-2
to 1.5e-1 from every start and fallback. The same bearing has s_half / (eps u_e) >= 1 at
-10 and -20 degC and converges (at -20 degC accepted at its round-off floor,
:mod:`~thermobearing.skidding.ball_round_off`); -30 degC is in the regime and is accepted at
its round-off floor with a residual of 1.8e-3 (a solution to the resolution of the traction:
its ring and cage equations hold to < 1e-10 and its CSR is that of solves converged with
other contact quadratures to 3e-5, :mod:`~thermobearing.skidding.ball_round_off`). So the
note is only added to the error of a solve that failed, judged at the race-control start of
that solve. Units: SI.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..traction import EYRING
from .ball_residual_kernels import G_A, G_B, G_P0, G_Q, G_UE

__all__ = ["coulomb_traction_note"]

#: double-precision unit roundoff: the relative resolution of a sliding speed
EPS = float(np.finfo(float).eps)


def coulomb_traction_note(system, X: np.ndarray, G: np.ndarray) -> str | None:
    """A sentence for the error of a failed solve when the loaded contacts' traction is a
    Coulomb step in double precision at the state (X, G) (module docstring; judged at the
    loaded contact that is best resolved), else None (also for traction laws other than
    Eyring with limiting shear, or without a film model).
    ``system``: the :class:`~thermobearing.skidding.ball_residual.ball_residual_system`."""
    models = system.models
    law = models.traction_law
    try:
        law_id, params = law.kernel
    except AttributeError:
        return None
    if law_id != EYRING or not params[1] > 0.0 or models.film_thickness is None:
        return None
    lam, tau0 = float(params[0]), float(params[1])
    try:
        _, _, _, fields = system.evaluate_fields(np.asarray(X, float), np.asarray(G, float))
    except (InputError, FloatingPointError, ValueError):
        return None
    geo, film = fields[0], fields[5]
    if film is None:
        return None
    Q = geo[G_Q]
    loaded = Q > 0.05 * float(np.max(Q)) if np.max(Q) > 0.0 else None
    if loaded is None:
        return None
    T = float(models.temperature)
    worst = None
    for j, k in zip(*np.nonzero(loaded), strict=True):
        p0, ue, h = float(geo[G_P0, j, k]), abs(float(geo[G_UE, j, k])), float(film[j, k])
        if not (p0 > 0.0 and ue > 0.0 and h > 0.0):
            continue
        try:
            ln_eta = math.log(float(law.lubricant.dynamic_viscosity(T, p0)))
        except (InputError, OverflowError, ValueError):
            ln_eta = math.inf                    # the law overflows: beyond any resolution
        x = lam * p0 / (2.0 * tau0)
        ln_sinh = (math.log(x) if x < 1e-6
                   else x + math.log1p(-math.exp(-2.0 * x)) - math.log(2.0))
        ln_half = math.log(tau0 * h) - ln_eta + ln_sinh
        ratio = ln_half - math.log(EPS * ue)       # ln(s_half / (eps u_e))
        if worst is None or ratio > worst[0]:      # the best-resolved loaded contact
            jump = lam * p0 * math.pi * float(geo[G_A, j, k]) * float(geo[G_B, j, k]) / (
                models.n_major * models.n_minor)
            worst = (ratio, ln_eta, p0, ln_half, EPS * ue, jump)
    if worst is None or not worst[0] < 0.0:
        return None
    ratio, ln_eta, p0, ln_half, res, jump = worst
    eta_txt = "beyond the largest double" if math.isinf(ln_eta) else \
        f"{_exp10(ln_eta)} Pa s"
    return (f"contact temperature {T - 273.15:.4g} degC ({T:.6g} K) is below the range of the "
            f"traction model: at the loaded contacts (Hertz pressure up to "
            f"{p0 / 1e9:.3g} GPa, eta there {eta_txt}) the Eyring traction reaches half its "
            f"limiting shear within {_exp10(ln_half)} m/s of slip, below the {res:.2g} m/s "
            f"resolution of a sliding speed in double precision, so it is a Coulomb step at "
            f"every quadrature node and the integrated traction jumps by up to {jump:.3g} N "
            f"({jump / system.F_s:.2g} of the residual's force scale) when a node's slip "
            f"changes sign; the solve stopped above the tolerance, as it can between such "
            f"steps. The model resolves the traction again where that slip exceeds the "
            f"resolution (warmer contacts or a thinner oil)")


def _exp10(ln_value: float) -> str:
    """exp(ln_value) as text without overflow ('1.7e+47')."""
    if ln_value < 700.0:
        return f"{math.exp(ln_value):.2g}"
    dec = ln_value / math.log(10.0)
    e = math.floor(dec)
    return f"{10.0 ** (dec - e):.2g}e+{e}"
