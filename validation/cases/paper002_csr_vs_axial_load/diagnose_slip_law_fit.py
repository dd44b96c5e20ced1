"""Would a pressure-proportional slip law, calibrated the documented way, give paper 002's speeds?

Run from the checkout:
``python validation/cases/paper002_csr_vs_axial_load/diagnose_slip_law_fit.py`` (a few
minutes). Not a test and not the model: an experiment for SOURCE.md, "Fresh look
(2026-11-24)". The raceway traction law of the ball solver (Eyring with limiting shear) is
replaced by the ADORE-form slip law tau = mu(u) p (``traction.four_parameter`` with mu_0 = 0
and a flat top mu from u_m = 0.02 m/s on), and the four calibrated quantities are refitted
exactly as ``thermobearing.skidding.qj1044.calibrate`` does (1800 r/min, 33 L/min, the same
three targets, ``least_squares`` trf, the same bounds) with mu in place of Lambda. The fitted
set then predicts the 0.5-6 kN over-skid peaks at 900 / 1200 / 1500 r/min and the CSR at
1 kN, 1800 r/min (paper: < 1 / 8.5 / 10 %, 0.501).
"""

from __future__ import annotations

import numpy as np
from diagnose_attitude import LOADS, WINDOW, _law_curve, _setup

TARGETS = (0.22, 0.12, 0.0)
UM = 0.02


def _law(mu: float):
    from thermobearing.traction import make_traction_law

    return make_traction_law("four_parameter", mu_zero=0.0, mu_max=1.001 * mu,
                             slip_speed_at_max=UM, mu_infinity=mu)


def _curve(base, lub, params, pd, mu, n, temperature):
    from thermobearing.skidding.ball import theoretical_csr
    from thermobearing.skidding.qj1044 import with_clearance

    b = with_clearance(base, pd)
    os_, beta, failed = _law_curve(b, lub, params, n, temperature, _law(mu))
    th0 = theoretical_csr(b, 1000.0, 0.0)
    th1 = theoretical_csr(b, 1000.0, 1000.0)
    return os_, beta, failed, th0, th1


def main() -> None:
    from scipy.optimize import least_squares

    from thermobearing.geometry import load_bearing
    from thermobearing.skidding.ball_models import BallParameters

    _, lub, cal_params, temperature = _setup()
    base = load_bearing("QJ1044")
    scale = np.array([1e7, 0.1, 0.1, 1e-4])
    i0, i36 = int(np.flatnonzero(LOADS == 0.0)[0]), int(np.flatnonzero(LOADS == 36000.0)[0])

    def unpack(y):
        v = y * scale
        return BallParameters(parker_constant=v[0], pocket_friction=v[1],
                              drag_coefficient=cal_params.drag_coefficient), v[2], v[3]

    def residual(y):
        params, mu, pd = unpack(y)
        os_, _, _, th0, _ = _curve(base, lub, params, pd, mu, 1800, temperature)
        peak = np.nanmax(np.where(WINDOW, os_, np.nan))
        out = np.array([(1.0 + os_[i0]) * th0 - TARGETS[0], peak - TARGETS[1],
                        os_[i36] - TARGETS[2]])
        out = np.where(np.isfinite(out), out, 1.0)
        print("  ", np.round(y * scale, 6), np.round(out, 4), flush=True)
        return out

    x0 = np.array([cal_params.parker_constant, cal_params.pocket_friction, 0.06, 0.4e-3])
    lo = np.array([0.05e7, 0.0, 0.02, 0.05e-3])
    hi = np.array([5e7, 0.3, 0.12, 0.4e-3])
    x0 = np.clip(x0, lo, hi * (1 - 1e-9))
    print(f"fit at 1800 r/min, 33 L/min, tau = mu(u) p with u_m = {UM} m/s")
    sol = least_squares(residual, x0 / scale, bounds=(lo / scale, hi / scale), diff_step=2e-3,
                        max_nfev=40, x_scale="jac")
    params, mu, pd = unpack(sol.x)
    print(f"fitted: parker_constant {params.parker_constant:.4g}, pocket_friction "
          f"{params.pocket_friction:.4g}, mu {mu:.4g}, P_d {pd * 1e3:.4g} mm; residuals "
          f"{np.round(sol.fun, 4)}, cost {sol.cost:.3e}, {sol.nfev} evaluations")
    for n in (600, 900, 1200, 1500, 1800):
        os_, beta, failed, th0, th1 = _curve(base, lub, params, pd, mu, n, temperature)
        k = int(np.nanargmax(np.where(WINDOW, os_, -np.inf)))
        i1 = int(np.flatnonzero(LOADS == 1000.0)[0])
        print(f"  {n} r/min: peak {100 * os_[k]:6.2f} % at {LOADS[k] / 1e3:g} kN (median "
              f"attitude {beta[k]:4.1f} deg), CSR(0) {(1 + os_[i0]) * th0:.3f}, CSR(1 kN) "
              f"{(1 + os_[i1]) * th1:.3f}, over-skid at 36 kN {100 * os_[i36]:.2f} %, "
              f"failed {failed}")


if __name__ == "__main__":
    main()
