"""Fresh look at the paper 000 load and viscosity directions (NU214, 5000 r/min).

Run from the checkout: ``python validation/cases/paper000_nu214_cage_speed/diagnose_fresh_look.py``
(``--part`` balance | rigid | mixed | eq9 | thin | whirl | all; default all, about 1 min).
Not a test: it prints the numbers of the section "Fresh look (2026-11-24)" in SOURCE.md.
Same inputs as the case (``case.toml``): PAPER000_OIL with eq. 9's alpha(eta0), Newtonian
cap 1.0, film-supported ring, regime_min Hertz-zone pressure, two-face pocket film; static
(no whirl), roller 0 under the load, unless a part says otherwise. Conditions in the order
100 / 150 / 200 N at 0.08 Pa s, 150 N at 0.06 / 0.10 Pa s.

Parts
- balance: the cage equation at the paper's 150 N cage speed (1233.7 r/min) split by
  ``cage_force_terms`` (rollers in moment balance): 2 x inner shear, inner pressure share,
  outer pressure share (rolling force), pocket friction; the surplus; the model's cage
  stiffness d(surplus)/dn and the surplus changes Tables 2-3 would need.
- rigid: sec. 1's "rigid contact" read literally (line-contact stiffness x 1e6, dry load
  zone): one roller (roller 0 under the load) or two (half a pitch off) carry F_r.
- mixed: eqs. 33-35 as printed: the Poiseuille shear from the film (here the case's
  regime-minimum rolling force / 2, load dependent) but the pressure force Q_x from eq. 35
  (Dowson-Higginson, load independent), film-supported ring and dry load zone.
- eq9: eq. 9 with its printed exponent 2 instead of z = 0.602 (alpha x 2/0.602).
- thin: the film-supported ring with a uniform oil layer of 2.5 / 4 um (the film a Hertz-
  scaled numerical inlet leaves at these loads): driven rollers and directions.
- whirl: the whirl mean (e = 6e-5 m, 36 samples) against the static solution at 100 and
  200 N, and (min + max)/2 against the mean.
"""

from __future__ import annotations

import argparse
import dataclasses
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from thermobearing.geometry import load_bearing
from thermobearing.lubricant import load_lubricant
from thermobearing.skidding.roller import build_model, solve_model, solve_roller
from thermobearing.skidding.roller_diagnostics import cage_force_balance, cage_force_terms
from thermobearing.skidding.whirl import Whirl
from thermobearing.validation.runners_roller_skidding import paper000_eq9_lubricant

RPM = math.pi / 30.0
OMEGA = 5000.0 * RPM
T = 313.15
CASE = {"limiting_shear_coefficient": 1.0, "ring_support": "films",
        "film_pressure": "regime_min", "pocket_film": "two_faces"}
#: (F_r [N], eta0 [Pa s]) -> paper 000 Tables 2-3 mean cage speed [r/min]
PAPER = {(100.0, 0.08): 1292.78, (150.0, 0.08): 1233.70, (200.0, 0.08): 1195.46,
         (150.0, 0.06): 1050.79, (150.0, 0.10): 1331.10}
BEARING = load_bearing("NU214")
OIL = load_lubricant("PAPER000_OIL")


def model(cond: tuple[float, float], alpha_factor: float = 1.0, **options: Any) -> Any:
    """The case's roller model at one condition (eq. 9 alpha at its eta0)."""
    lub = paper000_eq9_lubricant(OIL, cond[1], T)
    if alpha_factor != 1.0:
        params = dict(lub.pressure_parameters)
        params["alpha"] = params["alpha"] * alpha_factor
        lub = dataclasses.replace(lub, pressure_parameters=params)
    return build_model(BEARING, lub, T, viscosity=cond[1], **{**CASE, **options})


def row(label: str, change: Callable[[Any], Any] = lambda m: m, azimuth: Any = None,
        alpha_factor: float = 1.0, **options: Any) -> dict:
    """Static cage speeds at the five conditions, errors, directions, driven rollers."""
    speeds, driven = {}, []
    for cond in PAPER:
        m = change(model(cond, alpha_factor, **options))
        r = solve_model(m, OMEGA, cond[0], azimuth=azimuth)
        speeds[cond] = r.cage_speed / RPM
        driven.append(int(np.count_nonzero(r.inner_load > 0.0)))
    text = " / ".join(f"{n:.1f} ({100.0 * (n / PAPER[c] - 1.0):+.1f} %)"
                      for c, n in speeds.items())
    load = speeds[(200.0, 0.08)] - speeds[(100.0, 0.08)]
    visc = speeds[(150.0, 0.10)] - speeds[(150.0, 0.06)]
    print(f"{label}: {text}; 100->200 N {load:+.1f}, 0.06->0.10 Pa s {visc:+.1f} r/min; "
          f"rollers with an inner contact {driven}", flush=True)
    return speeds


def part_balance() -> None:
    wc = PAPER[(150.0, 0.08)] * RPM
    print("cage equation at 1233.7 r/min, sums over the 18 rollers [N]:")
    surplus = {}
    for cond in PAPER:
        t = cage_force_terms(model(cond), OMEGA, cond[0], wc)
        s = {k: float(np.sum(getattr(t, k))) for k in
             ("inner_couette", "inner_poiseuille", "inner_pressure", "outer_pressure",
              "pocket_friction", "reduced", "inner_load")}
        surplus[cond] = s["reduced"]
        print(f"  {cond}: 2 C_i {2 * s['inner_couette']:.3f}, P_i {s['inner_poiseuille']:.3f}, "
              f"s_i Q_xi {s['inner_pressure']:.3f}, s_o Q_xo {s['outer_pressure']:.3f}, "
              f"f_d {s['pocket_friction']:.3f}, surplus {s['reduced']:+.3f}, "
              f"sum Q_i {s['inner_load']:.1f} N")
    m = model((150.0, 0.08))
    lo = cage_force_balance(m, OMEGA, 150.0, wc).residual
    hi = cage_force_balance(m, OMEGA, 150.0, wc + 10.0 * RPM).residual
    k = (hi - lo) / 10.0
    need_load = -(PAPER[(200.0, 0.08)] - PAPER[(100.0, 0.08)]) * k
    need_visc = -(PAPER[(150.0, 0.10)] - PAPER[(150.0, 0.06)]) * k
    print(f"  cage stiffness d(surplus)/dn = {k:.4f} N per r/min (150 N, 0.08 Pa s)")
    d_load = surplus[(200.0, 0.08)] - surplus[(100.0, 0.08)]
    d_visc = surplus[(150.0, 0.10)] - surplus[(150.0, 0.06)]
    print(f"  surplus change 100->200 N: model {d_load:+.3f} N, Table 2 needs {need_load:+.2f}"
          f" N; 0.06->0.10 Pa s: model {d_visc:+.3f} N, Table 3 needs {need_visc:+.2f} N")


def part_rigid() -> None:
    def stiff(m: Any) -> Any:
        return dataclasses.replace(m, k_inner=m.k_inner * 1e6, k_outer=m.k_outer * 1e6)

    row("dry load zone (Hertz stiffness)", ring_support="contacts")
    row("rigid contact, roller under the load", stiff, ring_support="contacts")
    z = BEARING.n_rollers
    row("rigid contact, half a pitch off", stiff, ring_support="contacts",
        azimuth=2.0 * math.pi * (np.arange(z) + 0.5) / z)
    wc = PAPER[(150.0, 0.08)] * RPM
    for load in (100.0, 200.0):
        t = cage_force_terms(stiff(model((load, 0.08), ring_support="contacts")), OMEGA,
                             load, wc)
        on = t.inner_load > 0.0
        print(f"  rigid, {load:g} N at 1233.7 r/min: loaded roller 2 C_i "
              f"{2 * float(np.sum(t.inner_couette[on])):.3f} N, its s_o Q_xo "
              f"{float(np.sum(t.outer_pressure[on])):.3f} N; all rollers s_o Q_xo "
              f"{float(np.sum(t.outer_pressure)):.3f} N, surplus {float(np.sum(t.reduced)):+.3f} N")


def mixed(m: Any) -> Any:
    """Poiseuille shear from the film (the model's rolling force / 2), pressure force Q_x
    from eq. 35 (Dowson-Higginson) at every loaded contact."""
    base = m.contact_forces

    def forces(*args: Any, **kw: Any) -> Any:
        film = base(*args, **kw)
        dh = base(*args, **{**kw, "rolling_force": "dowson_higginson"})
        return dataclasses.replace(film, rolling_force=dh.rolling_force)

    forces.exact_slide = getattr(base, "exact_slide", False)  # type: ignore[attr-defined]
    return dataclasses.replace(m, contact_forces=forces)


def part_mixed() -> None:
    row("case model")
    row("eq. 33 Poiseuille from the film + eq. 35 Q_x", mixed)
    row("the same, dry load zone", mixed, ring_support="contacts")


def part_eq9() -> None:
    row("eq. 9 exponent 2 (alpha x 3.32)", alpha_factor=2.0 / 0.602)
    row("eq. 9 exponent 2, Hertz pressure", alpha_factor=2.0 / 0.602, film_pressure="hertz")


def part_thin() -> None:
    for layer in (2.5e-6, 4e-6):
        row(f"film-supported ring, oil layer {layer * 1e6:g} um", oil_layer=layer)


def part_whirl() -> None:
    for load in (100.0, 200.0):
        lub = paper000_eq9_lubricant(OIL, 0.08, T)
        w = solve_roller(BEARING, lub, OMEGA, load, 0.0, T, viscosity=0.08,
                         whirl=Whirl(6.0e-5, n_samples=36), **CASE)
        s = solve_roller(BEARING, lub, OMEGA, load, 0.0, T, viscosity=0.08, **CASE)
        st = w.cage_speed_stats
        print(f"  {load:g} N: whirl mean {st.mean / RPM:.2f}, static {s.cage_speed / RPM:.2f}, "
              f"(min + max)/2 {(st.minimum + st.maximum) / 2 / RPM:.2f} r/min")


PARTS = {"balance": part_balance, "rigid": part_rigid, "mixed": part_mixed, "eq9": part_eq9,
         "thin": part_thin, "whirl": part_whirl}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--part", choices=[*PARTS, "all"], default="all")
    args = parser.parse_args()
    for name, fn in PARTS.items():
        if args.part in (name, "all"):
            print(f"--- {name}")
            fn()


if __name__ == "__main__":
    main()
