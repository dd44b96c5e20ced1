"""Why the QJ1044 over-skid has no speed threshold: the ball attitude and its lateral traction.

Run from the checkout: ``python validation/cases/paper002_csr_vs_axial_load/diagnose_attitude.py``
(``--part`` state | lambda | contact | law | falling | oil | guidance | temperature |
all; default all, a few
minutes).
Not a test: it prints the numbers of the section "Fresh look (2026-11-24)" in SOURCE.md.
Same inputs as the case: QJ1044 with the calibrated clearance and ball parameters of
``configs/bearings/QJ1044.calibration.toml``, ISO VG 46, 45 degC contacts, 33 L/min jet,
1 kN radial load, each curve solved from 36 kN downward (warm starts, as the case).

Parts
- state: per ball at 3 kN (the peak region) and 900 / 1200 / 1800 r/min: attitude angle
  beta against the outer-race-control angle tan(beta_ORC) = sin(alpha_o)/(cos(alpha_o) +
  D cos(alpha_o)/d_m) (primer section 2.3), the gyroscopic moment J omega_R omega_c sin(beta)
  the tractions carry and the one race control would need, and the Lambda capacity
  Lambda (Q_i + Q_o) D/2 of the transverse tractions.
- lambda: the 0.5-6 kN over-skid peak at 900-1800 r/min for Lambda = 0.02 ... 0.10 (other
  calibrated values kept).
- contact: one outer contact of the 3 kN state (Hertz ellipse, Hamrock-Dowson film, the
  solver's traction law) integrated with ``contact_traction.integrate``: transverse force
  against transverse slip without spin and with the contact's solved spin; the slip at which
  the Eyring law leaves its Newtonian branch, s* = h tau0 / eta(p0).
- law: the peaks with the traction law replaced by a pressure-proportional slip law
  tau = mu(u) p (``four_parameter``, ADORE form, mu_0 = 0, flat top mu from u_m on) for
  mu = 0.03 ... 0.10 and u_m = 0.02 / 0.3 m/s, the primer's ADORE-style sample curve
  (over-skidding primer 3.6: mu 0.05 at 1 m/s, 0.036 at gross slip), and with the Eyring
  law at Lambda 0.06 and tau0 = 20 MPa (the other calibrated values kept, no recalibration).
- falling: a falling slip law (mu 0 -> 0.06 at u_m = 0.3 m/s, then down to mu_inf at gross
  slip, the thermal fall of EHL traction in ADORE's form), reached at each load by stepping
  mu_inf down from 0.06 (a flat top) to 0.015 from the flat-top solution (continuation in the
  law: the falling law solved cold fails at 2-7 of the 9 loads per speed).
- oil: the peaks with the oil fraction of Parker's correlation (X ~ 1/n) against X held at
  its 1800 r/min value at every speed.
- guidance: the peaks with the cage centred on the inner-ring shoulder (259 mm land, same
  0.6 mm clearance and 10 mm land; the land then drives the cage) next to the preset's
  outer-ring land.
- temperature: the peaks with the contacts and oil at 55 degC at 1800 r/min (the rig runs
  hotter at speed) next to 45 degC.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

RPM = math.pi / 30.0
LPM = 1.0 / 60000.0
LOADS = np.array([36000.0, 10000.0, 6000.0, 4000.0, 3000.0, 2000.0, 1000.0, 500.0, 0.0])
WINDOW = (LOADS >= 500.0) & (LOADS <= 6000.0)


def _setup():
    from thermobearing.geometry import load_bearing
    from thermobearing.lubricant import load_lubricant
    from thermobearing.skidding.qj1044 import load_calibration, with_clearance

    cal = load_calibration()
    bearing = with_clearance(load_bearing("QJ1044"), cal["diametral_clearance"])
    return bearing, load_lubricant("ISO_VG46"), cal["params"], cal["temperature"]


def _peak(bearing, lub, params, n, temperature, keep=False):
    from thermobearing.skidding.qj1044 import csr_curve

    c = csr_curve(bearing, lub, n * RPM, 33 * LPM, LOADS, params, temperature=temperature,
                  keep_results=keep)
    os_ = np.where(WINDOW, c.over_skid, -np.inf)
    k = int(np.nanargmax(os_))
    return c, k


def _state_at(bearing, lub, params, n, temperature, fa=3000.0):
    """Solved state at ``fa`` [N], reached from 36 kN downward as the case does."""
    from thermobearing.skidding.ball import solve_ball, theoretical_csr
    from thermobearing.skidding.ball_models import default_ball_models
    from thermobearing.state import OilSupply

    models = default_ball_models(bearing, lub, temperature=temperature, speed=n * RPM,
                                 supply=OilSupply("jet", 33 * LPM, 313.15), params=params)
    prev = None
    for f in LOADS[LOADS >= fa]:
        prev = solve_ball(bearing, models, n * RPM, 1000.0, f, guess=prev,
                          theoretical_reference=theoretical_csr(bearing, 1000.0, f))
    return prev, models


def part_state(bearing, lub, params, temperature):
    print("== state at 3 kN: attitude vs outer race control, gyroscopic moment vs capacity")
    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    mass = 7850.0 * math.pi / 6.0 * d ** 3       # 52100 steel ball [kg]
    inertia = 0.1 * mass * d * d                 # J = m D^2 / 10 [kg m^2]
    lam = params.limiting_shear_coefficient
    for n in (900, 1200, 1800):
        r, _ = _state_at(bearing, lub, params, n, temperature)
        print(f"{n} r/min: over-skid {100 * r.over_skid:.2f} %, omega_c {r.cage_speed:.1f} "
              "rad/s")
        ratios, gaps, needs = [], [], []
        for j in range(0, bearing.n_balls // 2 + 1, 2):
            q, a = r.normal_load[j], np.degrees(r.contact_angle[j])
            qi, qo = q[r.ring == 0].sum(), q[r.ring == 1].sum()
            ao = abs(a[r.ring == 1][np.argmax(q[r.ring == 1])])
            ai = abs(a[r.ring == 0][np.argmax(q[r.ring == 0])])
            gam = d * math.cos(math.radians(ao)) / dm
            b_orc = math.degrees(math.atan(math.sin(math.radians(ao))
                                           / (math.cos(math.radians(ao)) + gam)))
            beta = math.degrees(r.attitude_angle[j])
            w_r = r.spin_speed[j]
            mg = inertia * w_r * r.cage_speed * math.sin(math.radians(beta))
            mg_orc = inertia * w_r * r.cage_speed * math.sin(math.radians(b_orc))
            cap = lam * (qi + qo) * d / 2.0
            ratios.append(mg / cap)
            needs.append(mg_orc / ((qi + qo) * d / 2.0))
            gaps.append(b_orc - beta)
            print(f"  ball {j:2d}: Q_i {qi:6.1f} N  Q_o {qo:6.1f} N  alpha_i {ai:5.1f}  "
                  f"alpha_o {ao:5.1f}  beta {beta:5.1f} (ORC {b_orc:5.1f}) deg  M_g {mg:.3f} "
                  f"(ORC {mg_orc:.3f}) N m  Lambda cap {cap:.3f} N m  "
                  f"v_transverse {r.transverse_sliding_speed[j, 0]:.3f} m/s")
        print(f"  M_g / Lambda capacity {min(ratios):.2f}-{max(ratios):.2f}; beta below ORC by "
              f"{min(gaps):.1f}-{max(gaps):.1f} deg; traction coefficient race control needs, "
              f"M_g(ORC) / ((Q_i + Q_o) D/2): {min(needs):.3f}-{max(needs):.3f}")


def part_lambda(bearing, lub, params, temperature):
    print("== 0.5-6 kN over-skid peak against Lambda (other calibrated values kept)")
    for lam in (0.02, 0.04, 0.06, 0.08, 0.10):
        p = params.with_(limiting_shear_coefficient=lam)
        row = []
        for n in (900, 1200, 1500, 1800):
            c, k = _peak(bearing, lub, p, n, temperature, keep=True)
            beta = math.degrees(float(np.max(c.results[k].attitude_angle)))
            row.append(f"{n}: {100 * c.over_skid[k]:5.2f} % @{LOADS[k] / 1e3:g} kN "
                       f"(beta_max {beta:4.1f})")
        csr0 = c.cage_speed_ratio[LOADS == 0.0][0]
        print(f"  Lambda {lam:.2f}: " + " | ".join(row) + f" | CSR(0) 1800 {csr0:.3f}")


def _eyring(lub, params, temperature):
    from thermobearing.skidding.ball_models import make_traction

    return make_traction(lub, params.with_(limiting_shear_coefficient=0.06), temperature)


def part_contact(bearing, lub, params, temperature):
    from thermobearing.contact_traction import integrate
    from thermobearing.hertz import point_contact

    print("== one outer contact of the 3 kN state: transverse force against transverse slip")
    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    f_o = bearing.outer_conformity
    for n in (900, 1800):
        r, models = _state_at(bearing, lub, params, n, temperature)
        j = bearing.n_balls // 2                       # ball opposite the radial load
        outer = np.flatnonzero(r.ring == 1)
        k = outer[np.argmax(r.normal_load[j, outer])]
        q = float(r.normal_load[j, k])
        alpha = abs(float(r.contact_angle[j, k]))
        gam = d * math.cos(alpha) / dm
        rx, ry = 0.5 * d * (1.0 + gam), f_o * d / (2.0 * f_o - 1.0)
        hz = point_contact(q, rx, ry, bearing.effective_modulus)
        ue = abs(float(r.entrainment_speed[j, k]))
        h = float(models.film_thickness(ue, q, rx, ry))
        spin = float(r.spin_speed_contact[j, k])
        law = models.traction_law
        eta0 = float(law.lubricant.dynamic_viscosity(temperature, float(hz.max_pressure)))
        s_star = h * params.eyring_stress / eta0
        print(f"{n} r/min ball {j}: Q {q:.1f} N, a {1e3 * hz.a:.2f} mm, b {1e3 * hz.b:.2f} mm, "
              f"p0 {1e-9 * hz.max_pressure:.2f} GPa, h {1e6 * h:.3f} um, eta(p0) {eta0:.3g} Pa s, "
              f"Eyring Newtonian branch below s* = {s_star:.2e} m/s; spin {spin:.0f} rad/s, "
              f"spin slip at the ellipse end |omega_s| a = {abs(spin) * hz.a:.2f} m/s; "
              f"solved transverse slip {float(r.transverse_sliding_speed[j, k]):.3f} m/s")
        vx = np.array([0.01, 0.03, 0.1, 0.3, 1.0, 3.0])
        for w, lw in ((0.0, law), (spin, law), (spin, _eyring(lub, params, temperature))):
            t = integrate(lw, normal_load=q, semi_major=hz.a, semi_minor=hz.b,
                          transverse_sliding_speed=vx, spin_speed=w, film_thickness=h,
                          temperature=temperature, n_major=params.n_major,
                          n_minor=params.n_minor)
            mu = np.abs(t.transverse_force) / q
            lam = 0.06 if lw is not law else params.limiting_shear_coefficient
            tag = f"Lambda {lam:g}"
            print(f"  spin {w:4.0f} rad/s, {tag}: |F_x| / Q at v_x [m/s] = "
                  + ", ".join(f"{v:g}: {m:.4f}" for v, m in zip(vx, mu, strict=True)))


def _law_curve(bearing, lub, params, n, temperature, law):
    """(over-skid array, median attitude [deg] array, failures) along LOADS with ``law``."""
    import dataclasses

    from thermobearing.errors import ConvergenceError
    from thermobearing.skidding.ball import solve_ball, theoretical_csr
    from thermobearing.skidding.ball_models import default_ball_models
    from thermobearing.state import OilSupply

    models = default_ball_models(bearing, lub, temperature=temperature, speed=n * RPM,
                                 supply=OilSupply("jet", 33 * LPM, 313.15), params=params)
    if law is not None:
        models = dataclasses.replace(models, traction_law=law)
    os_, beta = np.full(LOADS.size, np.nan), np.full(LOADS.size, np.nan)
    prev, failed = None, 0
    for i, fa in enumerate(LOADS):
        try:
            prev = solve_ball(bearing, models, n * RPM, 1000.0, fa, guess=prev,
                              theoretical_reference=theoretical_csr(bearing, 1000.0, fa))
        except ConvergenceError:
            prev, failed = None, failed + 1
            continue
        os_[i], beta[i] = prev.over_skid, math.degrees(float(np.median(prev.attitude_angle)))
    return os_, beta, failed


def part_law(bearing, lub, params, temperature):
    from thermobearing.traction import make_traction_law

    print("== traction law: pressure-proportional slip law mu(u) p against the Eyring law")
    cases = [(f"mu(u) p, mu {mu:.2f}, u_m {um:g} m/s",
              make_traction_law("four_parameter", mu_zero=0.0, mu_max=1.001 * mu,
                                slip_speed_at_max=um, mu_infinity=mu), params)
             for mu, um in ((0.03, 0.02), (0.04, 0.02), (0.06, 0.02), (0.10, 0.02),
                            (0.06, 0.3))]
    cases.append(("mu(u) p, the primer's ADORE-style sample (0.05 at 1 m/s, mu_inf 0.036)",
                  make_traction_law("four_parameter", mu_zero=0.0, mu_max=0.05,
                                    slip_speed_at_max=1.0, mu_infinity=0.036), params))
    cases.append(("Eyring, Lambda 0.06, tau0 20 MPa", None,
                  params.with_(limiting_shear_coefficient=0.06, eyring_stress=20e6)))
    for label, law, p in cases:
        row = []
        for n in (900, 1200, 1500, 1800):
            os_, beta, failed = _law_curve(bearing, lub, p, n, temperature, law)
            k = int(np.nanargmax(np.where(WINDOW, os_, -np.inf)))
            row.append(f"{n}: {100 * os_[k]:5.2f} % @{LOADS[k] / 1e3:g} kN (beta_med "
                       f"{beta[k]:4.1f}, failed {failed})")
        print(f"  {label}: " + " | ".join(row) + f" | 1800 r/min CSR(0) / CSR_th(0) - 1 "
              f"{100 * os_[-1]:.1f} %, over-skid at 1 kN {100 * os_[LOADS == 1000.0][0]:.1f} %")


def part_falling(bearing, lub, params, temperature):
    import dataclasses

    from thermobearing.errors import ConvergenceError
    from thermobearing.skidding.ball import solve_ball, theoretical_csr
    from thermobearing.skidding.ball_models import default_ball_models
    from thermobearing.state import OilSupply
    from thermobearing.traction import make_traction_law

    mu_max, u_m = 0.06, 0.3
    steps = (0.05, 0.04, 0.035, 0.03, 0.025, 0.02, 0.015)

    def law(mu_inf):
        top = mu_max if mu_inf < mu_max else 1.001 * mu_max
        return make_traction_law("four_parameter", mu_zero=0.0, mu_max=top,
                                 slip_speed_at_max=u_m, mu_infinity=mu_inf)

    print(f"== falling slip law: mu_max {mu_max} at {u_m} m/s, mu_inf stepped 0.06 -> 0.015 "
          "(over-skid %, median attitude deg)")
    for n in (900, 1200, 1800):
        base = default_ball_models(bearing, lub, temperature=temperature, speed=n * RPM,
                                   supply=OilSupply("jet", 33 * LPM, 313.15), params=params)
        prev = None
        for fa in LOADS:
            th = theoretical_csr(bearing, 1000.0, fa)
            flat = dataclasses.replace(base, traction_law=law(mu_max))
            prev = solve_ball(bearing, flat, n * RPM, 1000.0, fa, guess=prev,
                              theoretical_reference=th)
            row, g = [f"flat {100 * prev.over_skid:6.2f}"], prev
            for mu_inf in steps:
                m = dataclasses.replace(base, traction_law=law(mu_inf))
                try:
                    g = solve_ball(bearing, m, n * RPM, 1000.0, fa, guess=g,
                                   theoretical_reference=th, cold_fallback=False)
                except ConvergenceError:
                    row.append(f"{mu_inf:g}: not converged")
                    break
                if mu_inf in (0.03, 0.015):
                    row.append(f"{mu_inf:g}: {100 * g.over_skid:6.2f} "
                               f"({math.degrees(float(np.median(g.attitude_angle))):4.1f})")
            print(f"  {n} r/min, {fa / 1e3:4g} kN: " + " | ".join(row))


def part_oil(bearing, lub, params, temperature):
    from thermobearing.heat_sources.churning import parker_oil_fraction

    print("== oil fraction: Parker (X ~ 1/n) against X held at its 1800 r/min value")
    x1800 = parker_oil_fraction(33 * LPM, 1800 * RPM, bearing.pitch_diameter,
                                params.parker_constant)
    for label, p in (("Parker", params), (f"X = {x1800:.3f}", params.with_(oil_fraction=x1800))):
        row = []
        for n in (900, 1200, 1500, 1800):
            c, k = _peak(bearing, lub, p, n, temperature)
            row.append(f"{n}: {100 * c.over_skid[k]:5.2f} %")
        print(f"  {label}: " + " | ".join(row))


def part_guidance(bearing, lub, params, temperature):
    import dataclasses

    print("== cage guidance: outer-ring land (preset) against the inner-ring shoulder")
    cage = dataclasses.replace(bearing.cage, guidance="inner_ring",
                               guide_land_diameter=bearing.inner_shoulder_diameter)
    for label, b in (("outer ring", bearing),
                     ("inner ring", dataclasses.replace(bearing, cage=cage))):
        row = []
        for n in (900, 1200, 1500, 1800):
            c, k = _peak(b, lub, params, n, temperature)
            row.append(f"{n}: {100 * c.over_skid[k]:5.2f} %")
        print(f"  {label}: " + " | ".join(row) + f" | CSR(0) 1800 r/min "
              f"{c.cage_speed_ratio[LOADS == 0.0][0]:.3f}")


def part_temperature(bearing, lub, params, temperature):
    print("== contact/oil temperature at 1800 r/min")
    for t in (temperature, temperature + 10.0):
        c, k = _peak(bearing, lub, params, 1800, t)
        print(f"  {t - 273.15:.0f} degC: peak {100 * c.over_skid[k]:.2f} % at "
              f"{LOADS[k] / 1e3:g} kN, CSR(0) {c.cage_speed_ratio[LOADS == 0.0][0]:.3f}")


PARTS = {"state": part_state, "lambda": part_lambda, "contact": part_contact,
         "law": part_law, "falling": part_falling, "oil": part_oil, "guidance": part_guidance,
         "temperature": part_temperature}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--part", choices=[*PARTS, "all"], default="all")
    args = ap.parse_args()
    setup = _setup()
    for name, fn in PARTS.items():
        if args.part in (name, "all"):
            fn(*setup)


if __name__ == "__main__":
    main()
