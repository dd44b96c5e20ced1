"""``thermobearing rib-map``: PV and slip maps of a cylindrical roller bearing (paper 003).

Sweeps radial load, speed, axial clearance, cage-pocket circumferential clearance, rib
angle and end-face crown radius around the paper 003 base case (30000 r/min, 3000 N,
C_a 0.03 mm, pocket 0.2 mm, rib angle 0.3 deg, crown radius 300 mm) for several roller
unbalance masses, with :func:`thermobearing.skidding.roller_dynamics.pv_slip_map`. Writes
``<out>/rib_map_<parameter>.csv`` (SI columns plus PV in MPa m/s) and a two-panel PNG per
parameter in the style of paper 003 Figs. 7-12 (a: PV of the left and right end faces,
b: slip speed). Default model: the coupled all-roller + cage integration
(:mod:`thermobearing.skidding.roller_dynamics_coupled`). ``--cost`` prints the CPU time of
one base-case point with the coupled, the one-roller full and the reduced model.

Example: ``thermobearing rib-map --param rib_angle --values "0.3,0.45,0.55,0.7 deg"
--unbalance "0.06,0.11 g" --out ribmap``.
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import sys
from pathlib import Path

from ..errors import InputError
from ..units import to_si

NAME = "rib-map"
HELP = "roller end-face PV and slip-speed maps (paper 003 Figs. 7-12), CSV + PNG"

#: default sweep values per parameter (display unit, values) -- the ranges of Figs. 7-12
DEFAULT_SWEEPS = {
    "radial_load": ("N", [1000, 2000, 3000, 5000, 7000, 9000]),
    "speed": ("rpm", [10000, 15000, 20000, 25000, 30000, 35000]),
    "axial_clearance": ("mm", [0.01, 0.02, 0.03, 0.04, 0.05, 0.07, 0.09]),
    "pocket_clearance": ("mm", [0.05, 0.1, 0.2, 0.3, 0.35, 0.4, 0.5]),
    "rib_angle": ("deg", [0.3, 0.4, 0.45, 0.5, 0.55, 0.6, 0.7, 0.8]),
    "crown_radius": ("mm", [300, 400, 450, 500, 550, 600, 700]),
}
KINDS = {"radial_load": "force", "speed": "angular_speed", "axial_clearance": "length",
         "pocket_clearance": "length", "rib_angle": "angle", "crown_radius": "length"}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.epilog = ("writes <out>/rib_map_<parameter>.csv (one row per value and unbalance "
                     "mass, units in the column names: PV in MPa m/s, speeds in m/s) and a "
                     "two-panel PNG per parameter; one progress line per point on stderr; "
                     "Ctrl-C keeps the rows finished so far. All six maps with the default "
                     "coupled model: 123 points of 2-5 s CPU each (measured on the shared "
                     "build machine); --model reduced about 0.2 s per point. "
                     "Example: thermobearing rib-map --param rib_angle --values "
                     "'0.3,0.45,0.55 deg' --unbalance '0.06,0.11 g' --out ribmap")
    parser.add_argument("--bearing", default="CRB_50x75x16", help="bearing preset or TOML")
    parser.add_argument("--lubricant", default="MIL_PRF_23699", help="lubricant preset")
    parser.add_argument("--temperature", default="80 degC", help="oil/roller temperature")
    parser.add_argument("--param", action="append", dest="params", default=None,
                        choices=sorted(DEFAULT_SWEEPS), help="parameter(s) to sweep "
                        "(repeatable; default: all six)")
    parser.add_argument("--values", default=None,
                        help="sweep values with one unit, e.g. '0.3,0.5,0.7 deg' or "
                             "'0.03 0.05 mm' (only with a single --param; a negative first "
                             "value: --values=\"-0.01,0.03 mm\")")
    parser.add_argument("--unbalance", default="0.06,0.08,0.11 g",
                        help="roller unbalance masses, e.g. '0.06,0.11 g'")
    parser.add_argument("--model", default="coupled", choices=("reduced", "full", "coupled"),
                        help="coupled (default: all rollers + cage, spins and cage speed "
                             "integrated, paper 003 eqs. 18-19; ~1.5 s CPU per point), "
                             "reduced (frozen load states, quasi-static spins) or full (one "
                             "roller over an orbit, quasi-static spins)")
    parser.add_argument("--orbits", default="2,3",
                        help="coupled model: warm-up and statistics cage orbits (default 2,3)")
    parser.add_argument("--ring-axial", action="store_true", dest="ring_axial",
                        help="coupled model: inner ring free axially (paper 003 eq. 20 line 1)")
    parser.add_argument("--raceway-traction", default="componentwise",
                        choices=("componentwise", "isotropic"), dest="raceway_traction",
                        help="skew's axial raceway traction: tanh law on the axial slide "
                             "(default) or along the resultant of the axial and rolling "
                             "slides (sensitivity)")
    parser.add_argument("--spin", default="skidding", choices=("skidding", "rolling"),
                        help="roller spins from the quasi-static skidding solver (default) or "
                             "pure rolling for every roller (sensitivity)")
    parser.add_argument("--coupling", default=None, choices=("rib", "none"),
                        help="feed the mean rib moments back into the quasi-static roller "
                             "spins and cage speed (default for the reduced and full models) "
                             "or keep the quasi-static solver's (default for the coupled "
                             "model, which integrates them)")
    parser.add_argument("--end-face", default="sphere", choices=("sphere", "cap"),
                        dest="end_face",
                        help="roller end face: the paper's whole sphere (default) or the sphere "
                             "cap with a chamfer blend (thermobearing.rib notes)")
    parser.add_argument("--slide", default="offset", choices=("offset", "radial_plane"),
                        help="end-face sliding speed at the skew-offset contact point "
                             "(default) or in the roller's radial plane, circumferential "
                             "only (paper 003 eqs. 11-13, 16; thermobearing.rib notes)")
    parser.add_argument("--no-pocket-dof", action="store_true", dest="no_pocket_dof",
                        help="hold the roller centred in its pocket (no rattling between "
                             "the cage bars under the unbalance force)")
    parser.add_argument("--cost", action="store_true",
                        help="print the cost of one base-case point (coupled, one-roller "
                             "full and reduced model)")
    parser.add_argument("--out", default="rib_map", help="output folder")
    parser.add_argument("--no-plot", action="store_true", help="CSV only")
    parser.add_argument("--quiet", action="store_true",
                        help="no progress line per point (on stderr)")


def _parse_list(text: str, kind: str, field: str, example_unit: str,
                bare_ok: bool = False) -> list[float]:
    """SI values of a list like ``'0.3,0.5,0.7 deg'`` or ``'0.3 0.5 0.7 deg'`` (one unit at
    the end, commas and/or spaces between the numbers). Bare numbers are refused unless
    ``bare_ok`` (the display unit is the SI one): ``'0.01,0.03'`` for an axial clearance
    would be 10 and 30 mm."""
    tokens = [t for t in re.split(r"[,;\s]+", text.strip()) if t]
    if not tokens:
        raise InputError(field, text, f"a list of values with a unit, e.g. '1,2 {example_unit}'")
    unit = ""
    try:
        float(tokens[-1])
    except ValueError:
        unit = tokens.pop()
    if not unit and not bare_ok:
        from ..units import SI_UNITS

        raise InputError(field, text, f"values with a unit, e.g. '{','.join(tokens)} "
                         f"{example_unit}' (bare numbers would be in {SI_UNITS[kind]}, "
                         "the SI unit)")
    out = []
    for tok in tokens:
        try:
            float(tok)
        except ValueError:
            raise InputError(field, text, f"numbers separated by commas or spaces, then one "
                             f"unit, e.g. '1,2 {example_unit}'") from None
        out.append(to_si(f"{tok} {unit}", kind, field=field) if unit else float(tok))
    if not out:
        raise InputError(field, text, f"a list of values with a unit, e.g. '1,2 {example_unit}'")
    return out


def _plot(rows: list[dict], parameter: str, unit: str, scale: float, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    masses = sorted({r["unbalance_mass"] for r in rows})
    for i, mu in enumerate(masses):
        sel = [r for r in rows if r["unbalance_mass"] == mu]
        x = [r["value"] / scale for r in sel]
        color = f"C{i}"
        ax1.plot(x, [r["pv_left"] / 1e6 for r in sel], "o--", color=color,
                 label=f"left face, m_u {mu * 1e3:.2f} g")
        ax1.plot(x, [r["pv_right"] / 1e6 for r in sel], "s-", color=color,
                 label=f"right face, m_u {mu * 1e3:.2f} g")
        ax2.plot(x, [r["slip_speed"] for r in sel], "o-", color=color,
                 label=f"m_u {mu * 1e3:.2f} g")
    ax1.set_xlabel(f"{parameter} [{unit}]")
    ax1.set_ylabel("PV of the roller end face [MPa m/s]")
    ax1.set_title("(a) PV value")
    ax2.set_xlabel(f"{parameter} [{unit}]")
    ax2.set_ylabel("roller slip speed [m/s]")
    ax2.set_title("(b) slip speed")
    ax1.legend(fontsize=7)
    ax2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def run(args: argparse.Namespace) -> int:
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding import roller_dynamics as rd

    bearing = load_bearing(args.bearing)
    lubricant = load_lubricant(args.lubricant)
    temperature = to_si(args.temperature, "temperature", field="--temperature")
    masses = _parse_list(args.unbalance, "mass", "--unbalance", "g")
    params = args.params or list(DEFAULT_SWEEPS)
    if args.values is not None and len(params) != 1:
        raise InputError("--values", args.values, "exactly one --param with --values")
    out = Path(args.out)
    cache: dict = {}
    try:
        warm, stats = (float(v) for v in args.orbits.split(","))
    except ValueError as exc:
        raise InputError("--orbits", args.orbits, "two numbers 'warm-up,statistics'") from exc
    coupled_options = {"warmup_orbits": warm, "n_orbits": stats,
                       "ring_axial": bool(args.ring_axial)}
    coupling = args.coupling or ("none" if args.model == "coupled" else "rib")
    options = {"spin": args.spin, "pocket_dof": not args.no_pocket_dof,
               "raceway_traction": args.raceway_traction}
    sweeps = {p: (_parse_list(args.values, KINDS[p], "--values", unit, bare_ok=unit == "N")
                  if args.values is not None
                  else [to_si(f"{v} {unit}", KINDS[p], field=p) for v in defaults])
              for p, (unit, defaults) in ((p, DEFAULT_SWEEPS[p]) for p in params)}
    from ..skidding.roller_dynamics_map import PAPER003_BASE, check_map_points

    for p, vals in sweeps.items():  # every point checked before the first (long) solve
        check_map_points(bearing, p, vals, masses, dict(PAPER003_BASE),
                         end_face=args.end_face, slide=args.slide)
    if args.cost:
        from ..skidding.roller_dynamics_coupled import simulate_coupled

        rib = {"end_face": args.end_face, "slide": args.slide}
        base = (bearing, lubricant, rd.PAPER003_BASE["speed"], rd.PAPER003_BASE["radial_load"],
                max(masses))
        m = rd.build_model(*base, temperature=temperature, rib=rib, coupling="rib", **options)
        full, red = rd.simulate_full(m), rd.simulate_reduced(m)
        mc = rd.build_model(*base, temperature=temperature, rib=rib, coupling="none",
                            quasi_static=m.extras["quasi_static"], **options)
        cpl = simulate_coupled(mc, bearing, lubricant, **coupled_options)
        print(f"cost of one base-case point (CPU): coupled {cpl.cost_s:.2f} s, one-roller full "
              f"{full.cost_s:.2f} s ({full.n_rhs} rhs), reduced {red.cost_s:.2f} s "
              f"({red.n_rhs} rhs; its quasi-static rib coupling not counted)")
        for r in (cpl, full, red):
            print(f"  {r.model:8s} PV L/R {r.pv_left / 1e6:.4g}/{r.pv_right / 1e6:.4g} MPa m/s,"
                  f" slip {r.slip_speed:.4g} m/s")
    out.mkdir(parents=True, exist_ok=True)
    total = sum(len(v) for v in sweeps.values()) * len(masses)
    done = [0]
    if not args.quiet:
        print(f"rib-map: {total} points ({len(params)} parameter(s) x values x "
              f"{len(masses)} unbalance mass(es)), model {args.model}; one line per point "
              f"on stderr, rows written to {out} as they finish", file=sys.stderr)
    for p in params:
        unit = DEFAULT_SWEEPS[p][0]
        values = sweeps[p]
        scale = to_si(f"1 {unit}", KINDS[p], field=p)
        path = out / f"rib_map_{p}.csv"
        with path.open("w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow([f"{p} [{unit}]", "unbalance_mass [g]", "pv_left [MPa m/s]",
                        "pv_right [MPa m/s]", "pv_peak_left [MPa m/s]",
                        "pv_peak_right [MPa m/s]", "pv_contact_left [MPa m/s]",
                        "pv_contact_right [MPa m/s]", "contact_slide_speed [m/s]",
                        "slip_speed [m/s]", "surface_slip_speed [m/s]", "max_skew [deg]",
                        "rib_contact_fraction [-]", "rib_heat_per_roller [W]",
                        "bar_contact_fraction [-]", "pocket_friction_extra [N]",
                        "cage_speed [rad/s]", "cost [s]"])
            fh.flush()

            def write_row(r: dict, w=w, fh=fh, scale=scale, p=p, unit=unit) -> None:
                w.writerow([f"{r['value'] / scale:.6g}", f"{r['unbalance_mass'] * 1e3:.4g}",
                            f"{r['pv_left'] / 1e6:.6g}", f"{r['pv_right'] / 1e6:.6g}",
                            f"{r['pv_peak_left'] / 1e6:.6g}", f"{r['pv_peak_right'] / 1e6:.6g}",
                            f"{r['pv_contact_left'] / 1e6:.6g}",
                            f"{r['pv_contact_right'] / 1e6:.6g}",
                            f"{r['contact_slide_speed']:.6g}", f"{r['slip_speed']:.6g}",
                            f"{r['surface_slip_speed']:.6g}",
                            f"{math.degrees(r['max_skew']):.5g}",
                            f"{r['rib_contact_fraction']:.4g}", f"{r['rib_heat']:.5g}",
                            f"{r['bar_contact_fraction']:.4g}",
                            f"{r['pocket_friction_extra']:.5g}", f"{r['cage_speed']:.6g}",
                            f"{r['cost_s']:.3g}"])
                fh.flush()  # every point is on disk as soon as it is computed
                done[0] += 1
                if not args.quiet:
                    print(f"[{done[0]}/{total}] {p} {r['value'] / scale:.4g} {unit}, m_u "
                          f"{r['unbalance_mass'] * 1e3:.3g} g: PV L/R "
                          f"{r['pv_left'] / 1e6:.4g}/{r['pv_right'] / 1e6:.4g} MPa m/s, slip "
                          f"{r['slip_speed']:.4g} m/s ({r['cost_s']:.2g} s CPU)",
                          file=sys.stderr, flush=True)

            try:
                rows = rd.pv_slip_map(bearing, lubricant, p, values, masses, model=args.model,
                                      temperature=temperature, cache=cache,
                                      end_face=args.end_face, coupling=coupling,
                                      slide=args.slide, coupled_options=coupled_options,
                                      on_row=write_row, **options)
            except KeyboardInterrupt:
                fh.flush()
                print(f"interrupted while mapping {p}: the points finished so far are in "
                      f"{path} (and the parameters before it in {out}); rerun with --param "
                      "to map the rest", file=sys.stderr)
                return 130
        print(f"{p}: {path}")
        for r in rows:
            print(f"  {r['value'] / scale:8.4g} {unit:4s} m_u {r['unbalance_mass'] * 1e3:.3g} g"
                  f"  PV L {r['pv_left'] / 1e6:8.4g}  R {r['pv_right'] / 1e6:8.4g} MPa m/s"
                  f"  slip {r['slip_speed']:.4g} m/s")
        if not args.no_plot:
            _plot(rows, p, unit, scale, out / f"rib_map_{p}.png")
    return 0
