"""Hand check of the loss shares at the over-skidding peak (evidence for SOURCE.md).

Run from the checkout: ``python validation/cases/paper002_loss_ratios/diagnose.py``
(``--load 4`` kN is the peak step of the validation run, ``--sensitivity`` adds the
cage-land / pocket-friction sweep). Not a test: it prints the numbers quoted in SOURCE.md.

Same inputs as the case's runner at its peak step (default scene, one QJ1044, calibrated
ball parameters and clearance of configs/bearings/QJ1044.calibration.toml, ISO VG 46 at the
35 degC inlet temperature everywhere, 1800 r/min, 33 L/min, 1 kN radial load): the direct
solve reproduces the runner's per-source losses to the watt.

Prints
1. the magnitudes by hand: pocket normal forces, sliding speed at the pocket, the land
   film shear (Petroff) of the cage guide;
2. the steady-state identity of the cage torque balance (paper 002 eqs. 8 and 19):
   Q_bp = k * circulation * (Q_cg + Q_ch,c), k = mu_p omega_r D_b / (omega_c D_m);
3. the shares as this model books them (every watt = a force times a sliding speed) and as
   paper 002 books them (ball churning by its eq. 16 in SI instead of the eq. 10 drag power,
   cage guide by its eq. 18, mu_c |F_cg| D_m (omega_g - omega_c) / 2, with the land carrying
   the cage weight), and the energy each bookkeeping leaves out.
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np

RPM = math.pi / 30.0
G = 9.80665


def _peak(load_kn: float):
    from thermobearing.validation.paper002_peak import solve_rig

    return solve_rig(load_kn * 1e3, 1800 * RPM, 33.0 / 6e4)


def _shares(heat: dict[str, float]) -> str:
    tot = sum(heat.values())
    churn = heat["churning_elements"] + heat["churning_cage"] + heat["churning_inner_ring"]
    pocket, guide = heat["pocket_friction"], heat["cage_guide"]
    rows = [f"    {k:22s} {v:8.1f} W  {v / tot:6.3f}" for k, v in heat.items()]
    rows.append(f"    {'total':22s} {tot:8.1f} W")
    rows.append(f"    pocket share {pocket / tot:.3f} (asked 0.20-0.40), churning share "
                f"{churn / tot:.3f} (0.55-0.85), cage guide / pocket {guide / pocket:.2f} "
                "(0.1-0.4)")
    return "\n".join(rows)


def main(argv=None) -> int:
    from thermobearing.heat_sources.pocket import pocket_circulation, steady_pocket_drag_ratio

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--load", type=float, default=4.0, help="axial load [kN] (peak step: 4)")
    ap.add_argument("--mu-c", type=float, default=0.1,
                    help="paper 002 eq. 18 hydrodynamic friction coefficient (not given)")
    ap.add_argument("--sensitivity", action="store_true")
    a = ap.parse_args(argv)
    state = _peak(a.load)
    bearing, lub, params, t, res = (state.bearing, state.lubricant, state.params,
                                    state.temperature, state.result)
    wc, wi = res.cage_speed, res.inner_speed
    eta = float(lub.dynamic_viscosity(t))
    print(f"QJ1044, 1800 r/min, 33 L/min, Fr 1 kN, Fa {a.load:g} kN, oil {t - 273.15:.0f} degC "
          f"(eta {eta:.4f} Pa s); CSR {res.cage_speed_ratio:.4f}, over-skid "
          f"{100 * res.over_skid:.2f} %")
    from thermobearing.heat_sources import evaluate
    from thermobearing.losses import paper002_bookkeeping
    from thermobearing.simulation import BALL_SOURCES

    ctx = state.context
    heat = {r.source: r.total for r in evaluate(BALL_SOURCES, ctx)}
    print("1. magnitudes by hand")
    qp = res.pocket_force
    rp = res.ball_r
    print(f"  pocket normal force per ball {np.min(qp):.2f} .. {np.max(qp):.2f} N, sum |F| "
          f"{np.abs(qp).sum():.1f} N; cage torque they carry sum F r = "
          f"{-np.sum(qp * rp):.3f} N m")
    t_guide = heat["cage_guide"] / wc
    t_churn = heat["churning_cage"] / wc
    print(f"  cage drag torque: land {t_guide:.3f} N m + churning {t_churn:.3f} N m = "
          f"{t_guide + t_churn:.3f} N m")
    v = res.kinematic_state.pocket_sliding_speed
    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    print(f"  ball spin rel. cage {np.mean(res.spin_speed):.0f} rad/s -> surface speed "
          f"omega_r D/2 = {np.mean(res.spin_speed) * d / 2:.2f} m/s (solver: {np.mean(v):.2f} "
          f"m/s); cage pitch speed omega_c D_m/2 = {wc * dm / 2:.2f} m/s")
    mu_p = params.pocket_friction
    print(f"  pocket heat mu F v = {mu_p:.3f} x {np.abs(qp).sum():.1f} N x {np.mean(v):.2f} m/s"
          f" = {mu_p * np.sum(np.abs(qp) * v):.1f} W (source: {heat['pocket_friction']:.1f} W)")
    cage = bearing.cage
    c = 0.5 * cage.guide_clearance
    dv = wc * cage.guide_land_diameter / 2
    tau = eta * dv / c
    area = math.pi * cage.guide_land_diameter * cage.land_width
    print(f"  land film: c = {c * 1e3:.2f} mm radial, B = {cage.land_width * 1e3:.0f} mm, "
          f"D_g = {cage.guide_land_diameter * 1e3:.0f} mm: tau = eta dv/c = {tau:.0f} Pa, "
          f"force {tau * area:.1f} N, power {tau * area * dv:.1f} W "
          f"(source: {heat['cage_guide']:.1f} W)")
    print("2. steady-state identity (cage torque balance, paper 002 eqs. 8 and 19)")
    k = float(np.mean(steady_pocket_drag_ratio(mu_p, res.spin_speed, d, wc, dm)))
    circ = pocket_circulation(qp)
    pred = k * circ * (heat["cage_guide"] + heat["churning_cage"]) * np.mean(rp) / (dm / 2)
    print(f"  k = mu_p omega_r D_b/(omega_c D_m) = {k:.3f} (mu_p (1+gamma) = "
          f"{mu_p * (1 + d * math.cos(bearing.contact_angle) / dm):.3f} at pure rolling); "
          f"circulation sum|F|/|sum F| = {circ:.3f}")
    print(f"  Q_bp = k circ (Q_cg + Q_ch,c) = {pred:.1f} W (computed "
          f"{heat['pocket_friction']:.1f} W)")
    kk = k * circ
    print(f"  so guide/pocket >= 1/(k circ) - Q_ch,c/Q_cg; pocket share >= 0.2 with guide/pocket"
          f" <= 0.4 needs Q_ch,c >= {0.2 * (1 - 0.4 * kk) / kk:.2f} of the total (model: "
          f"{heat['churning_cage'] / sum(heat.values()):.3f})")
    print("3a. shares as this model books them (energy-consistent)")
    print(_shares(heat))
    print(f"    solver shaft power minus booked heat: "
          f"{res.shaft_torque * wi - sum(heat.values()):+.2f} W")
    m_cage = cage.effective_mass(d, bearing.n_balls)
    pheat = paper002_bookkeeping(ctx, guide_friction=a.mu_c, guide_load=m_cage * G)
    print(f"3b. shares as paper 002 books them (eq. 16 SI for the balls, eq. 18 with mu_c "
          f"{a.mu_c:g} and the land carrying the cage weight {m_cage * G:.1f} N)")
    print(_shares(pheat))
    print(f"    dissipated (shaft power) but not booked: "
          f"{res.shaft_torque * wi - sum(pheat.values()):.1f} W of {res.shaft_torque * wi:.1f} W")
    from thermobearing.heat_sources.pocket import pocket_shear_damping

    x_oil = ctx.options["churning_cage"]["oil_fraction"]
    r_b = float(np.mean(rp))
    cmat = pocket_shear_damping(eta, d, 0.5 * cage.pocket_clearance,
                                0.5 * cage.inner_diameter - r_b, 0.5 * cage.outer_diameter - r_b)
    shear = float(np.einsum("ji,ik,jk->", res.spin, cmat, res.spin))
    print(f"4. not modelled (nor in paper 002): Couette shear of a flooded pocket by the spinning "
          f"ball (pocket.pocket_shear_damping): {shear / bearing.n_balls:.1f} W per pocket, "
          f"{shear:.0f} W in all at eta = {eta:.4f} Pa s; {x_oil * shear:.0f} W with the mixture "
          f"viscosity X eta (X = {x_oil:.3f}); fully flooded: pocket share "
          f"{(heat['pocket_friction'] + shear) / (sum(heat.values()) + shear):.3f}, guide/pocket "
          f"{heat['cage_guide'] / (heat['pocket_friction'] + shear):.2f}")
    if a.sensitivity:
        from thermobearing.skidding import solve
        from thermobearing.validation.paper002_peak import RADIAL_LOAD

        print("5. sensitivity at this load (solver re-run): land clearance, land width, mu_p")
        for cl, lw, mu in [(0.6, 10, None), (0.3, 10, None), (1.2, 10, None), (2.4, 10, None),
                           (0.6, 5, None), (0.6, 20, None), (0.6, 10, 0.1)]:
            cg = dataclasses.replace(cage, guide_clearance=cl * 1e-3, land_width=lw * 1e-3,
                                     outer_diameter=cage.guide_land_diameter - cl * 1e-3)
            b2 = dataclasses.replace(bearing, cage=cg)
            p2 = params if mu is None else params.with_(pocket_friction=mu)
            r2 = solve(b2, lub, 1800 * RPM, RADIAL_LOAD, a.load * 1e3, t, supply=state.supply,
                       params=p2, oil_temperature=t)
            h = r2.heat
            print(f"  guide clearance {cl:3.1f} mm, land {lw:2d} mm, mu_p {p2.pocket_friction:.2f}"
                  f": over-skid {100 * r2.over_skid:5.2f} %, pocket share "
                  f"{h['ball_pocket'] / h['total']:.3f}, guide/pocket "
                  f"{h['cage_guide'] / h['ball_pocket']:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
