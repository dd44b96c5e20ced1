"""Paper 002 (QJ1044 rig): CSR-vs-axial-load curves, calibration on one condition, Fig. 10 plot.

Calibration (issue 5, "calibration is allowed, honestly"): the parameters paper 002 does not
give are fitted with :func:`scipy.optimize.least_squares` on ONE condition, 1800 r/min and
33 L/min, and stored with that condition in ``configs/bearings/QJ1044.calibration.toml``;
every other speed and the 15 L/min flow are predictions. Fitted parameters:

- ``parker_constant``: constant of Parker's oil-fraction correlation (sets the oil volume
  fraction of the drag models and its dependence on flow and speed, X ~ Q^0.37 / n);
- ``pocket_friction``: ball-pocket friction coefficient;
- ``limiting_shear_coefficient``: Lambda of the traction law;
- ``diametral_clearance``: the mounted diametral clearance of the QJ1044 (the free contact
  angle is held at the paper's 40 deg by moving the gothic-arch offset; see
  :func:`with_clearance`). The bearing preset's 0.10 mm is an estimate (configs/bearings).

Targets at 1800 r/min, 33 L/min, F_r = 1 kN (paper 002 section 4.1): CSR = 0.22 at F_a = 0
(point 1 of Fig. 10(a)), the largest CSR/CSR_th - 1 between 0.5 and 6 kN = 12 % (the peak
"near 3 kN"), CSR = CSR_th at 36 kN (point 3, pure rolling). The measured CSR = 0.501 at
1 kN (point 2) is NOT a target: the model cannot hold it together with CSR(0) = 0.22 (an
earlier fit with it left both 0.11 off); it is reported by the validation case.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ConvergenceError, InputError
from ..toml_files import read_toml
from .ball import solve_ball, theoretical_csr
from .ball_models import BallParameters, default_ball_models

__all__ = ["CSRCurve", "calibrate", "csr_curve", "load_calibration", "paper002_curves",
           "paper002_figure10", "plot_csr_vs_axial_load", "with_clearance", "CALIBRATION_FILE"]

RPM = math.pi / 30.0
LPM = 1.0 / 60000.0
CALIBRATION_FILE = "QJ1044.calibration.toml"
#: axial loads of the paper's protocol: 0-42 kN in 2 kN steps, plus 0.5 and 1 kN [N]
PROTOCOL_LOADS = np.concatenate([[0.0, 500.0, 1000.0], np.arange(2000.0, 42001.0, 2000.0)])


def with_clearance(bearing, diametral_clearance: float):
    """A copy of a four-point bearing with another diametral clearance, same free angle.

    The gothic-arch offset is recomputed so that the unloaded diagonal contact angle stays at
    the bearing's free angle: for equal conformities from cos(theta_s) = cos(alpha_f) +
    P_d/(2A), A = (f_i + f_o - 1) D (the relation of
    ``geometry.BallBearing.free_contact_angle_for``); for unequal ones by the bearing's own
    solve of that relation (``BallBearing._derive_offset``: the closed form holds for
    f_i = f_o only and gave an offset the bearing refused, e.g. f_i = 0.52, f_o = 0.545:
    free angle 26.3 deg instead of 40 deg at 20 um).
    """
    if bearing.kind != "four_point":
        return dataclasses.replace(bearing, diametral_clearance=diametral_clearance)
    if bearing.inner_conformity != bearing.outer_conformity:
        derived = dataclasses.replace(bearing, diametral_clearance=diametral_clearance,
                                      contact_angle=bearing.free_contact_angle,
                                      gothic_arch_offset=None)
        return dataclasses.replace(bearing, diametral_clearance=diametral_clearance,
                                   gothic_arch_offset=derived.gothic_arch_offset)
    big_a = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * bearing.ball_diameter
    c = math.cos(bearing.free_contact_angle) + diametral_clearance / (2.0 * big_a)
    if not 0.0 < c < 1.0:
        raise InputError("diametral_clearance", diametral_clearance,
                         "a clearance that leaves a shim angle > 0")
    theta = math.acos(c)
    s = (2.0 * bearing.inner_conformity - 1.0) * bearing.ball_diameter * math.sin(theta)
    return dataclasses.replace(bearing, diametral_clearance=diametral_clearance,
                               gothic_arch_offset=s)


@dataclass(frozen=True)
class CSRCurve:
    """CSR against axial load at one speed and flow (arrays over ``axial_load``)."""

    speed: float
    flow: float
    axial_load: np.ndarray
    cage_speed_ratio: np.ndarray
    theoretical: np.ndarray
    kinematic: np.ndarray
    iterations: np.ndarray
    wall_time: np.ndarray
    converged: np.ndarray
    results: tuple = ()

    @property
    def over_skid(self) -> np.ndarray:
        return self.cage_speed_ratio / self.theoretical - 1.0


def csr_curve(bearing, lubricant, speed: float, flow: float, axial_loads, params,
              *, radial_load: float = 1000.0, temperature: float = 318.15,
              keep_results: bool = False) -> CSRCurve:
    """Solve the ball skidding state along an axial-load sweep (high load first, warm starts).

    Failed points (ConvergenceError) are NaN and flagged in ``converged`` (never silent).
    """
    from ..state import OilSupply

    loads = np.asarray(axial_loads, float)
    order = np.argsort(-loads)
    supply = OilSupply("jet", flow, min(temperature, 313.15))
    models = default_ball_models(bearing, lubricant, temperature=temperature, speed=speed,
                                 supply=supply, params=params)
    n = loads.size
    csr, th, kin = np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan)
    its, wall, ok = np.zeros(n, int), np.zeros(n), np.zeros(n, bool)
    res: list[Any] = [None] * n
    prev = None
    for k in order:
        th[k] = theoretical_csr(bearing, radial_load, loads[k])
        try:
            r = solve_ball(bearing, models, speed, radial_load, loads[k], guess=prev,
                           theoretical_reference=th[k])
        except ConvergenceError:
            prev = None
            continue
        prev = r
        csr[k], kin[k] = r.cage_speed_ratio, r.kinematic_cage_speed_ratio
        its[k], wall[k], ok[k] = r.iterations, r.wall_time, True
        if keep_results:
            res[k] = r
    return CSRCurve(speed, flow, loads, csr, th, kin, its, wall, ok, tuple(res))


# ---------------------------------------------------------------------------------------------
def _config_path(path: str | Path | None) -> Path:
    if path is not None:
        return Path(path)
    from ..geometry import configs_dir

    return Path(configs_dir()) / "bearings" / CALIBRATION_FILE


def load_calibration(path: str | Path | None = None) -> dict[str, Any]:
    """Read ``QJ1044.calibration.toml``: {"params": BallParameters, "diametral_clearance",
    "condition", "raw"}; InputError if the file is missing."""
    from ..units import to_si

    p = _config_path(path)
    if not p.exists():
        raise InputError("calibration file", str(p), "an existing QJ1044.calibration.toml "
                         "(run thermobearing.skidding.qj1044.calibrate)")
    raw = read_toml(p)
    cal = raw["calibrated"]
    params = BallParameters(
        limiting_shear_coefficient=float(cal["limiting_shear_coefficient"]),
        pocket_friction=float(cal["pocket_friction"]),
        parker_constant=float(cal["parker_constant"]),
        drag_coefficient=float(cal.get("drag_coefficient", 0.45)),
        source=f"calibrated at {raw['condition']['speed']}, {raw['condition']['flow']}")
    return {"params": params,
            "diametral_clearance": to_si(cal["diametral_clearance"], "length"),
            "temperature": to_si(raw["condition"]["temperature"], "temperature"),
            "condition": raw["condition"], "raw": raw}


#: calibration targets at 1800 r/min, 33 L/min (paper 002 section 4.1): CSR at F_a = 0,
#: the largest over-skid for 0.5 kN <= F_a <= 6 kN, the over-skid at 36 kN
TARGETS = {"csr_fa0": 0.22, "overskid_peak": 0.12, "overskid_36kN": 0.0}
_LOADS = np.array([36000.0, 10000.0, 6000.0, 4000.0, 3000.0, 2000.0, 1000.0, 500.0, 0.0])


def calibration_residuals(curve: CSRCurve) -> np.ndarray:
    """Residuals of a 1800 r/min / 33 L/min curve against :data:`TARGETS` (NaN -> 1)."""
    fa, os_ = curve.axial_load, curve.over_skid
    i0 = np.flatnonzero(fa == 0.0)[0]
    i36 = np.flatnonzero(fa == 36000.0)[0]
    win = (fa >= 500.0) & (fa <= 6000.0)
    peak = np.nanmax(os_[win]) if np.any(np.isfinite(os_[win])) else np.nan
    out = np.array([curve.cage_speed_ratio[i0] - TARGETS["csr_fa0"],
                    peak - TARGETS["overskid_peak"], os_[i36] - TARGETS["overskid_36kN"]])
    return np.where(np.isfinite(out), out, 1.0)


def calibrate(bearing=None, lubricant=None, *, temperature: float = 318.15,
              x0=(1.5e7, 0.2, 0.04, 0.3e-3), write: str | Path | None = None,
              max_nfev: int = 40, verbose: int = 0) -> dict[str, Any]:
    """Fit (parker_constant, pocket_friction, Lambda, P_d) at 1800 r/min, 33 L/min.

    Residuals: :func:`calibration_residuals` (CSR at F_a = 0, the over-skid peak in
    0.5-6 kN, the over-skid at 36 kN). Bounds: K in [5e5, 5e7], mu_p in [0, 0.3],
    Lambda in [0.02, 0.12], P_d in [0.05, 0.40] mm. Returns the fitted values, residuals and
    cost; writes the calibration TOML to ``write`` if given.
    """
    from scipy.optimize import least_squares

    from ..geometry import load_bearing
    from ..lubricant import load_lubricant

    base = bearing or load_bearing("QJ1044")
    lub = lubricant or load_lubricant("ISO_VG46")
    speed, flow = 1800 * RPM, 33 * LPM
    scale = np.array([1e7, 0.1, 0.1, 1e-4])

    def unpack(y):
        v = y * scale
        return BallParameters(parker_constant=v[0], pocket_friction=v[1],
                              limiting_shear_coefficient=v[2]), v[3]

    def residual(y):
        params, pd = unpack(y)
        try:
            b = with_clearance(base, pd)
        except InputError:
            return np.full(3, 10.0)
        cur = csr_curve(b, lub, speed, flow, _LOADS, params, temperature=temperature)
        out = calibration_residuals(cur)
        if verbose:
            print(params.parker_constant, params.pocket_friction,
                  params.limiting_shear_coefficient, pd, np.round(out, 4), flush=True)
        return out

    y0 = np.asarray(x0, float) / scale
    lo = np.array([0.05e7, 0.0, 0.02, 0.05e-3]) / scale
    hi = np.array([5e7, 0.3, 0.12, 0.4e-3]) / scale
    sol = least_squares(residual, y0, bounds=(lo, hi), diff_step=2e-3, max_nfev=max_nfev,
                        x_scale="jac")
    params, pd = unpack(sol.x)
    out = {"params": params, "diametral_clearance": pd, "residuals": sol.fun,
           "cost": float(sol.cost), "nfev": int(sol.nfev), "temperature": temperature,
           "status": sol.message}
    if write is not None:
        write_calibration(out, write)
    return out


def write_calibration(out: dict[str, Any], path: str | Path | None = None) -> Path:
    """Write the calibration TOML (every value with its source)."""
    p = _config_path(path)
    pr = out["params"]
    res = ", ".join(f"{r:+.4f}" for r in out["residuals"])
    text = f'''# Calibrated parameters of the ball skidding solver for the QJ1044 of seed paper 002.
# Written by thermobearing.skidding.qj1044.calibrate (owner G1). Fitted on ONE condition only;
# all other speeds and the 15 L/min flow are predictions (validation case
# paper002_csr_vs_axial_load).
source = "least-squares fit (scipy.optimize.least_squares, trf) on paper 002 section 4.1 targets"

[condition]
source = "seed paper 002 section 4.1 and Fig. 10(a): 1800 r/min, 33 L/min, radial load about 1 kN"
speed = "1800 rpm"
flow = "33 L/min"
radial_load = "1 kN"
lubricant = "ISO_VG46"
temperature = "{out['temperature'] - 273.15:.2f} degC"
targets = "CSR(0 kN) = 0.22; max over 0.5-6 kN of CSR/CSR_th - 1 = 0.12; CSR(36 kN) = CSR_th"
residuals = "{res}"

[calibrated]
source = "fitted at [condition]; cost {out['cost']:.3e}, {out['nfev']} residual evaluations"
status = "{out.get('status', '')}"
bounds = "K 5e5-5e7; mu_p 0-0.3; Lambda 0.02-0.12; P_d 0.05-0.40 mm (see SOURCE.md)"
parker_constant = {pr.parker_constant:.6g}
pocket_friction = {pr.pocket_friction:.6g}
limiting_shear_coefficient = {pr.limiting_shear_coefficient:.6g}
diametral_clearance = "{out['diametral_clearance'] * 1e3:.5f} mm"
drag_coefficient = {pr.drag_coefficient:.6g}

[estimated]
drag_coefficient = "0.45, sphere drag plateau (Harris & Kotzalas 2007), not fitted"
eyring_stress = "5 MPa (Johnson & Tevaarwerk 1977 order for mineral oils), not fitted"
temperature = """oil/contact temperature of the CSR runs: 45 degC, an estimate between the \
35 degC inlet and the outer-ring temperatures of paper 002 Fig. 18"""
diametral_clearance = """fitted instead of the preset's estimated 0.10 mm: with 0.10 mm the outer \
contact angle is held at the 37.8 deg shim angle and the over-skid cannot exceed about 4 %; the \
free contact angle is kept at 40 deg by moving the gothic-arch offset"""
'''
    p.write_text(text)
    return p


# ---------------------------------------------------------------------------------------------
def plot_csr_vs_axial_load(curves, path: str | Path, *, measured: dict | None = None,
                           title: str = "QJ1044: CSR vs axial load (paper 002 Fig. 10 style)"):
    """Write a PNG of CSR vs axial load for several speeds (style of paper 002 Fig. 10).

    curves : iterable of :class:`CSRCurve`; measured : optional {label: (Fa [N], CSR)} points.
    Returns the path.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 4.8))
    for c in curves:
        n = c.speed / RPM
        lbl = f"{n:.0f} r/min, {c.flow / LPM:.0f} L/min"
        ax.plot(c.axial_load / 1e3, c.cage_speed_ratio, "o-", ms=3, label=lbl)
        ax2.plot(c.axial_load / 1e3, 100 * c.over_skid, "o-", ms=3, label=lbl)
    c0 = list(curves)[0]
    ax.plot(c0.axial_load / 1e3, c0.theoretical, "k--", lw=1, label="CSR_th")
    if measured:
        for lbl, (fa, csr) in measured.items():
            ax.plot(np.asarray(fa) / 1e3, csr, "r*", ms=10, label=lbl)
    ax.set_xlabel("axial load F_a [kN]")
    ax.set_ylabel("cage speed ratio CSR [-]")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax2.axhline(0, color="k", lw=0.8)
    for y, lab in ((12, "12 %"), (10, "10 %"), (8.5, "8.5 %")):
        ax2.axhline(y, color="grey", ls=":", lw=0.8)
        ax2.text(41, y, lab, fontsize=7, va="bottom", ha="right")
    ax2.set_xlabel("axial load F_a [kN]")
    ax2.set_ylabel("over-skid CSR/CSR_th - 1 [%]")
    ax2.set_ylim(-15, 20)
    ax2.grid(alpha=0.3)
    fig.tight_layout()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def paper002_curves(speeds=(600, 900, 1200, 1500, 1800), flows=(33, 15), axial_loads=None,
                    *, radial_load: float = 1000.0, calibration=None,
                    lubricant: str | None = None) -> dict[tuple[int, int], CSRCurve]:
    """CSR curves of the calibrated QJ1044 at speeds [r/min] and flows [L/min].

    Keys are (speed in r/min, flow in L/min). ``axial_loads`` [N] default: the paper's
    protocol (0-42 kN in 2 kN steps) plus 0.5 and 1 kN.
    """
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant

    cal = load_calibration(calibration)
    bearing = with_clearance(load_bearing("QJ1044"), cal["diametral_clearance"])
    lub = load_lubricant(lubricant or cal["condition"].get("lubricant", "ISO_VG46"))
    loads = PROTOCOL_LOADS if axial_loads is None else np.asarray(axial_loads, float)
    out = {}
    for q in flows:
        for n in speeds:
            out[(int(round(n)), int(round(q)))] = csr_curve(
                bearing, lub, n * RPM, q * LPM, loads, cal["params"], radial_load=radial_load,
                temperature=cal["temperature"])
    return out


def paper002_figure10(path: str | Path, flow: float = 33, curves=None, **kwargs) -> Path:
    """Compute (or reuse ``curves``) and plot CSR vs F_a at the five speeds (paper 002 Fig. 10).

    The measured points quoted in the paper's text are overlaid: CSR = 0.22 at 0 kN,
    0.501 at 1 kN and CSR_th (0.452) at 36 kN, 1800 r/min.
    """
    if curves is None:
        curves = paper002_curves(flows=(flow,), **kwargs)
    sel = [c for (n, q), c in sorted(curves.items()) if q == int(round(flow))]
    measured = {"paper 002, 1800 r/min (text)": ([0.0, 1000.0, 36000.0], [0.22, 0.501, 0.4526])}
    return plot_csr_vs_axial_load(sel, path, measured=measured,
                                  title=f"QJ1044, {flow:g} L/min: CSR vs axial load "
                                        "(model; paper 002 Fig. 10 style)")
