"""``thermobearing rib-map``: PV and slip maps of a cylindrical roller bearing (paper 003).

Sweeps radial load, speed, axial clearance, cage-pocket circumferential clearance, rib
angle and end-face crown radius around a base point -- ``--speed`` and ``--radial-load``
(default paper 003's 30000 r/min and 3000 N) and the bearing's own axial clearance, pocket
clearance, rib angle and crown radius (the default bearing CRB_50x75x16 has paper 003's
C_a 0.03 mm, pocket 0.2 mm, rib angle 0.3 deg, crown radius 300 mm) -- for several roller
unbalance masses, with :func:`thermobearing.skidding.roller_dynamics.pv_slip_map`. Writes
``<out>/rib_map_<parameter>.csv`` (units in the column names: the parameter in its display
unit, masses in g, PV in MPa m/s, speeds in m/s) and a two-panel PNG per
parameter in the style of paper 003 Figs. 7-12 (a: PV of the left and right end faces,
b: slip speed), with ``rib_map_<parameter>_settings.json`` (bearing, oil, model and base
point of that map; one per map, so maps of other runs in the folder keep theirs). Default
model: the coupled all-roller + cage integration
(:mod:`thermobearing.skidding.roller_dynamics_coupled`). ``--cost`` prints the CPU time of
one base-case point with the coupled, the one-roller full and the reduced model and the
estimated CPU of the map asked, and stops. ``--keep-going`` maps the other points when one
fails (listed at the end, exit status 1).

Example: ``thermobearing rib-map --param rib_angle --values "0.3,0.45,0.55,0.7 deg"
--unbalance "0.06,0.11 g" --out ribmap``.
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import sys
import warnings
from pathlib import Path

from ..errors import InputError, ThermobearingError
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

#: display label of each map parameter (axis labels, messages)
LABELS = {"radial_load": "radial load", "speed": "speed", "axial_clearance": "axial clearance",
          "pocket_clearance": "pocket clearance", "rib_angle": "rib angle",
          "crown_radius": "end-face crown radius"}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.epilog = ("writes <out>/rib_map_<parameter>.csv (one row per value and unbalance "
                     "mass, units in the column names: PV in MPa m/s, speeds in m/s) and a "
                     "two-panel PNG per parameter, each with rib_map_<parameter>_settings.json "
                     "(bearing, oil, model, base point). Each map varies one parameter about the "
                     "base point: --speed, --radial-load and the bearing's own rib angle, "
                     "end-face crown radius, axial and pocket clearance (printed at the "
                     "start and above the figures); every point is checked before the "
                     "first solve. One progress line per point on stderr; "
                     "Ctrl-C keeps the rows finished so far. All six maps with the default "
                     "coupled model: 123 points of 1.2-1.5 s CPU each, 5-6 s where a new "
                     "speed or load builds its traction table (measured 2026-11-24 on the "
                     "shared build machine; --cost estimates a map); --model reduced about "
                     "0.08 s per point. "
                     "Example: thermobearing rib-map --param rib_angle --values "
                     "'0.3,0.45,0.55 deg' --unbalance '0.06,0.11 g' --out ribmap")
    parser.add_argument("--bearing", default="CRB_50x75x16",
                        help="cylindrical roller bearing preset or TOML with rib geometry "
                             "(end_face_crown_radius, rib_height); its rib angle, crown "
                             "radius, axial and pocket clearances are the map's base point "
                             "(default: %(default)s, paper 003's bearing)")
    parser.add_argument("--lubricant", default="MIL_PRF_23699",
                        help="lubricant preset (default: %(default)s)")
    parser.add_argument("--temperature", default="80 degC",
                        help="oil and roller temperature with its unit (default: "
                             "%(default)s)")
    parser.add_argument("--speed", default="30000 rpm",
                        help="inner-ring speed of the base point, with its unit (default: "
                             "%(default)s, paper 003's test speed)")
    parser.add_argument("--radial-load", default="3000 N", dest="radial_load",
                        help="radial load of the base point (default: %(default)s; a bare "
                             "number is in N)")
    parser.add_argument("--param", action="append", dest="params", default=None,
                        choices=sorted(DEFAULT_SWEEPS), help="parameter(s) to sweep "
                        "(repeatable; default: all six), each over paper 003's values "
                        "unless --values: " + "; ".join(
                            f"{p} {','.join(f'{v:g}' for v in vals)} {unit}"
                            for p, (unit, vals) in DEFAULT_SWEEPS.items()))
    parser.add_argument("--values", default=None,
                        help="sweep values with one unit, e.g. '0.3,0.5,0.7 deg' or "
                             "'0.03 0.05 mm' (only with a single --param; a negative first "
                             "value: --values=\"-0.01,0.03 mm\")")
    parser.add_argument("--unbalance", default="0.06,0.08,0.11 g",
                        help="roller unbalance masses, e.g. '0.06,0.11 g' (default: "
                             "%(default)s, paper 003's; each below the roller's mass)")
    parser.add_argument("--model", default="coupled", choices=("reduced", "full", "coupled"),
                        help="coupled (default: all rollers + cage, spins and cage speed "
                             "integrated, paper 003 eqs. 18-19; ~1.3 s CPU per point), "
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
                             "full and reduced model) and the estimated CPU of the map "
                             "asked, then stop without mapping")
    parser.add_argument("--out", default="rib_map", help="output folder (default: "
                        "%(default)s)")
    parser.add_argument("--no-plot", action="store_true", help="CSV only")
    parser.add_argument("--keep-going", action="store_true", dest="keep_going",
                        help="map the other points when one fails (the coupled motion with "
                             "an unbalance can run away: paper 003 row of the README); the "
                             "failed points are listed at the end, exit status 1")
    parser.add_argument("--quiet", action="store_true",
                        help="no progress line per point (on stderr)")


#: one value with its own unit: a number, then a unit that starts with a letter, ° or µ
_VALUE_WITH_UNIT = re.compile(r"^([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*"
                              r"([A-Za-z°µ%].*)$")


def _parse_list(text: str, kind: str, field: str, example_unit: str,
                bare_ok: bool = False) -> list[float]:
    """SI values of a list like ``'0.3,0.5,0.7 deg'`` or ``'0.3 0.5 0.7 deg'`` (one unit at
    the end, commas and/or spaces between the numbers). Bare numbers are refused unless
    ``bare_ok`` (the display unit is the SI one): ``'0.01,0.03'`` for an axial clearance
    would be 10 and 30 mm. Each value may also carry its own unit (``'0.3 deg, 0.5 deg'``,
    ``'20000rpm,25000rpm'``), as ``sweep --set`` reads them; it was refused as "numbers
    ... then one unit"."""
    items = [t for t in re.split(r"\s*[,;]\s*", text.strip()) if t]
    each = [_VALUE_WITH_UNIT.match(t) for t in items]
    if len(items) > 1 and all(each):
        return [to_si(f"{m.group(1)} {m.group(2)}", kind, field=field) for m in each]
    tokens = [t for t in re.split(r"[,;\s]+", text.strip()) if t]
    if not tokens:
        raise InputError(field, text, f"a list of values with a unit, e.g. '1,2 {example_unit}'")
    unit = ""
    try:
        float(tokens[-1])
    except ValueError:
        unit = tokens.pop()
    for tok in tokens:
        try:
            float(tok)
        except ValueError:
            raise InputError(field, text, f"numbers separated by commas or spaces, then one "
                             f"unit, e.g. '1,2 {example_unit}', or each value with its "
                             f"unit, '1 {example_unit}, 2 {example_unit}'") from None
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


def _plot(rows: list[dict], parameter: str, unit: str, scale: float, path: Path,
          subtitle: str = "") -> None:
    """The two panels of paper 003 Figs. 7-12: (a) the time-mean PV of each end face,
    (b) the roller slip speed, against ``parameter`` in ``unit``, one colour per unbalance
    mass; ``subtitle`` (the bearing, oil and base point the map varies) above them."""
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
    label = LABELS.get(parameter, parameter)
    ax1.set_xlabel(f"{label} [{unit}]")
    ax1.set_ylabel("time-mean PV of the roller end face [MPa m/s]")
    ax1.set_title("(a) PV value")
    ax2.set_xlabel(f"{label} [{unit}]")
    ax2.set_ylabel("roller slip speed [m/s]")
    ax2.set_title("(b) slip speed")
    ax1.legend(fontsize=7)
    ax2.legend(fontsize=7)
    if subtitle:
        import textwrap

        fig.suptitle("\n".join(textwrap.wrap(subtitle, 140)), fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _num(x: float) -> str:
    """``x`` to 4 significant digits without an exponent in the usual range: 20000 rpm was
    printed ``2e+04 rpm`` (``:.4g``)."""
    return f"{x:.4g}" if x == 0 or 1e-3 <= abs(x) < 1e4 else f"{x:.6g}"


def _shown(p: str, value: float) -> str:
    """``value`` [SI] of map parameter ``p`` in its display unit (``'0.3 deg'``)."""
    unit = DEFAULT_SWEEPS[p][0]
    return f"{_num(value / to_si(f'1 {unit}', KINDS[p], field=p))} {unit}"


def _temperature(text: str) -> float:
    """``--temperature`` [K]: a unit is needed (a bare ``80`` was answered "write '80 K'"),
    and the oil must be below the 300 degC runaway limit of a scene (``500 degC`` mapped
    every point)."""
    from ..coupled import RUNAWAY_TEMPERATURE

    try:
        float(text)
    except ValueError:
        pass
    else:
        raise InputError("--temperature", text, f"a temperature with its unit, e.g. "
                         f"'{text} degC'")
    value = to_si(text, "temperature", field="--temperature")
    if value >= RUNAWAY_TEMPERATURE:
        raise InputError("--temperature", text, f"an oil temperature below "
                         f"{RUNAWAY_TEMPERATURE - 273.15:g} degC (the runaway limit of a "
                         "scene's transient)")
    return value


def _one_value(text: str, kind: str, field: str, example_unit: str, bare_ok: bool) -> float:
    """One SI value of an option (``--speed '20000 rpm'``, ``--radial-load 5000``)."""
    values = _parse_list(text, kind, field, example_unit, bare_ok=bare_ok)
    if len(values) != 1:
        raise InputError(field, text, f"one value with its unit, e.g. '1 {example_unit}'")
    return values[0]


def _base_point(bearing, speed: float, radial_load: float) -> dict[str, float]:
    """The map's base point: ``--speed``, ``--radial-load`` and the bearing's own rib angle,
    end-face crown radius, axial clearance and cage pocket clearance (each map varies one of
    them). The command used paper 003's values (0.3 deg, 300 mm, 0.03 mm, 0.2 mm) whatever
    ``--bearing`` said; they are those of its default bearing, CRB_50x75x16."""
    if getattr(bearing, "kind", None) != "cylindrical":
        raise InputError("--bearing", getattr(bearing, "name", bearing),
                         "a cylindrical roller bearing (the rib contact of paper 003)")
    missing = [k for k in ("end_face_crown_radius", "rib_height")
               if getattr(bearing, k, None) is None]
    if missing:
        raise InputError("--bearing", bearing.name, "a cylindrical roller bearing with rib "
                         "geometry: " + " and ".join(missing) + " are not given")
    from ..skidding.roller_dynamics_map import PAPER003_BASE

    _check_at_least("--radial-load", radial_load, 0.0, "N", 1.0)
    base = {"speed": speed, "radial_load": radial_load,
            "axial_clearance": float(bearing.axial_clearance),
            "pocket_clearance": float(bearing.cage.pocket_clearance),
            "rib_angle": float(bearing.rib_angle),
            "crown_radius": float(bearing.end_face_crown_radius)}
    # a value equal to paper 003's but for round-off takes paper 003's float: "30000 rpm"
    # converts to 3141.592653589793 rad/s, one ulp from 30000 pi / 30, and the impacting
    # motion with an unbalance carries that difference to the map (reduced model at the
    # base point, 0.06 g: PV 548.8 / 557.1 against 581.0 / 628.4 MPa m/s), so the default
    # map keeps the numbers of earlier versions
    return {k: (PAPER003_BASE[k] if math.isclose(v, PAPER003_BASE[k], rel_tol=1e-12)
                else v) for k, v in base.items()}


def _check_speed(value: float, field: str) -> None:
    """InputError naming ``field`` unless the speed ``value`` [rad/s] is > 0 (in r/min)."""
    if not value > 0.0:
        raise InputError(field, f"{value * 30.0 / math.pi:.6g} rpm", "a speed > 0")


def _check_at_least(field: str, value: float, low: float, unit: str, scale: float) -> None:
    """InputError naming ``field`` unless ``value`` >= ``low`` (shown in ``unit``)."""
    if not value >= low:
        raise InputError(field, f"{value / scale:.6g} {unit}", f"a value >= {low:g} {unit}")


def _check_points(bearing, sweeps: dict[str, list[float]], masses: list[float],
                  base: dict[str, float], given: bool, end_face: str, slide: str) -> None:
    """Every point of every map checked before the first (long) solve, each refusal naming
    the option that set the value, in its display unit: ``--unbalance`` (each mass below the
    roller's), ``--bearing`` (its own rib geometry at the base point), ``--values`` or the
    parameter's default values (a value at which the roller's end face cannot touch the rib,
    a negative clearance). The errors named the model's fields in SI
    (``rib.rib_height = 0.0015``, ``unbalance_mass = 0.005``, ``pocket_clearance =
    -0.0001``) whatever value of the map had caused them."""
    from ..heat_sources.rib import check_unbalance_option, rib_input_text
    from ..skidding.roller_dynamics_map import check_map_points

    for mass in masses:
        check_unbalance_option(mass, bearing, "--unbalance")
    try:
        check_map_points(bearing, "speed", [base["speed"]], [], dict(base),
                         end_face=end_face, slide=slide)
    except InputError as exc:
        raise InputError("--bearing", bearing.name, "a bearing whose end face touches its "
                         f"rib at the map's base point: {rib_input_text(exc)}") from None
    for p, vals in sweeps.items():
        where = "--values" if given else f"--param {p} (its default values)"
        for v in vals:
            if p in ("axial_clearance", "pocket_clearance", "radial_load") and v < 0:
                model_field = "rib.axial_clearance" if p == "axial_clearance" else p
                raise InputError(where, _shown(p, v), f"{LABELS[p]} values >= 0 "
                                 f"({model_field})")
            if p in ("speed", "crown_radius") and v <= 0:
                raise InputError(where, _shown(p, v), f"{LABELS[p]} values > 0")
            try:
                check_map_points(bearing, p, [v], [], dict(base), end_face=end_face,
                                 slide=slide)
            except InputError as exc:
                hint = "" if given else f"; give --values for {bearing.name}"
                raise InputError(where, _shown(p, v), f"{LABELS[p]} values at which the "
                                 f"end face of {bearing.name} touches its rib; at "
                                 f"{_shown(p, v)}: {rib_input_text(exc)}{hint}") from None


def _write_settings(path: Path, args: argparse.Namespace, bearing, base: dict[str, float],
                    masses: list[float], parameter: str) -> None:
    """What a map's CSV file does not say: the bearing, oil, temperature, model and the
    base point the map varies ``parameter`` of (display units and SI)."""
    import json

    settings = {
        "bearing": bearing.name, "bearing_argument": args.bearing,
        "lubricant": args.lubricant, "temperature": args.temperature, "model": args.model,
        "orbits": args.orbits, "end_face": args.end_face, "slide": args.slide,
        "spin": args.spin, "raceway_traction": args.raceway_traction,
        "pocket_dof": not args.no_pocket_dof, "ring_axial": bool(args.ring_axial),
        "parameter": parameter, "unbalance_mass [g]": [m * 1e3 for m in masses],
        "base_point": {f"{p} [{DEFAULT_SWEEPS[p][0]}]": float(_shown(p, base[p]).split()[0])
                       for p in DEFAULT_SWEEPS},
        "base_point_si": dict(base),
    }
    path.write_text(json.dumps(settings, indent=2) + "\n")


def run(args: argparse.Namespace) -> int:
    """The command; warnings (a contact point beyond the roller radius, a solver's validity
    note) are printed once each as ``rib-map: warning: ...`` lines on stderr. They came in
    Python's format, with the file, the line number and the source line
    (``.../rib.py:346: ValidityWarning: ...`` / ``return RibGeometry(...``), and the
    per-point checks repeated them."""
    seen: set[str] = set()

    def show(message, category, filename, lineno, file=None, line=None) -> None:
        text = str(message)
        if text not in seen:
            seen.add(text)
            print(f"rib-map: warning: {text}", file=sys.stderr, flush=True)

    with warnings.catch_warnings():
        warnings.simplefilter("always")
        warnings.showwarning = show
        return _run(args)


def _run(args: argparse.Namespace) -> int:
    from ..errors import UnknownNameError
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding import roller_dynamics as rd

    try:
        bearing = load_bearing(args.bearing)
    except UnknownNameError as exc:  # was 'bearing preset = ...', no option named
        raise UnknownNameError("--bearing", args.bearing, exc.known) from None
    except InputError as exc:
        if exc.field != "bearing path":
            raise
        raise InputError("--bearing", args.bearing, "a bearing preset name or an existing "
                         f"TOML file (looked at {Path(args.bearing).resolve()})") from None
    try:
        lubricant = load_lubricant(args.lubricant)
    except UnknownNameError as exc:
        raise UnknownNameError("--lubricant", args.lubricant, exc.known) from None
    temperature = _temperature(args.temperature)
    masses = _parse_list(args.unbalance, "mass", "--unbalance", "g")
    speed = _one_value(args.speed, "angular_speed", "--speed", "rpm", bare_ok=False)
    _check_speed(speed, "--speed")
    radial_load = _one_value(args.radial_load, "force", "--radial-load", "N", bare_ok=True)
    base = _base_point(bearing, speed, radial_load)
    params = args.params or list(DEFAULT_SWEEPS)
    if args.values is not None and len(params) != 1:
        raise InputError("--values", args.values, "exactly one --param with --values")
    out = Path(args.out)
    cache: dict = {}
    try:
        warm, stats = (float(v) for v in args.orbits.split(","))
    except ValueError as exc:
        raise InputError("--orbits", args.orbits, "two numbers 'warm-up,statistics'") from exc
    if not (warm >= 0.0 and stats > 0.0 and math.isfinite(warm + stats)):
        # '0,0' mapped every point over no orbit at all
        raise InputError("--orbits", args.orbits, "warm-up orbits >= 0 and statistics "
                         "orbits > 0, e.g. '2,3'")
    coupled_options = {"warmup_orbits": warm, "n_orbits": stats,
                       "ring_axial": bool(args.ring_axial)}
    coupling = args.coupling or ("none" if args.model == "coupled" else "rib")
    options = {"spin": args.spin, "pocket_dof": not args.no_pocket_dof,
               "raceway_traction": args.raceway_traction}
    sweeps = {p: (_parse_list(args.values, KINDS[p], "--values", unit, bare_ok=unit == "N")
                  if args.values is not None
                  else [to_si(f"{v} {unit}", KINDS[p], field=p) for v in defaults])
              for p, (unit, defaults) in ((p, DEFAULT_SWEEPS[p]) for p in params)}
    _check_points(bearing, sweeps, masses, base, args.values is not None, args.end_face,
                  args.slide)
    base_text = (f"{bearing.name}, {args.lubricant} at {args.temperature}; base point "
                 + ", ".join(f"{LABELS[p]} {_shown(p, base[p])}" for p in DEFAULT_SWEEPS))
    if args.cost:
        from ..skidding.roller_dynamics_coupled import simulate_coupled

        rib = {"end_face": args.end_face, "slide": args.slide,
               "axial_clearance": base["axial_clearance"], "rib_angle": base["rib_angle"],
               "crown_radius": base["crown_radius"]}
        point = (bearing, lubricant, base["speed"], base["radial_load"], max(masses))
        m = rd.build_model(*point, temperature=temperature, rib=rib, coupling="rib",
                           pocket_clearance=base["pocket_clearance"], **options)
        full, red = rd.simulate_full(m), rd.simulate_reduced(m)
        mc = rd.build_model(*point, temperature=temperature, rib=rib, coupling="none",
                            pocket_clearance=base["pocket_clearance"],
                            quasi_static=m.extras["quasi_static"], **options)
        cpl = simulate_coupled(mc, bearing, lubricant, **coupled_options)
        print(f"cost of one base-case point (CPU): coupled {cpl.cost_s:.2f} s, one-roller full "
              f"{full.cost_s:.2f} s ({full.n_rhs} rhs), reduced {red.cost_s:.2f} s "
              f"({red.n_rhs} rhs; its quasi-static rib coupling not counted)")
        for r in (cpl, full, red):
            print(f"  {r.model:8s} PV L/R {r.pv_left / 1e6:.4g}/{r.pv_right / 1e6:.4g} MPa m/s,"
                  f" slip {r.slip_speed:.4g} m/s")
        # --cost answers "what will the map cost" and stops: it went on to map all six
        # parameters (123 points with the coupled model) when only the cost was asked
        per = {"coupled": cpl.cost_s, "full": full.cost_s, "reduced": red.cost_s}[args.model]
        n = sum(len(v) for v in sweeps.values()) * len(masses)
        print(f"the map asked ({', '.join(params)}; {len(masses)} unbalance mass(es)): {n} "
              f"points x {per:.2g} s = about {n * per / 60:.2g} min of CPU with the "
              f"{args.model} model (this point's cost; other points may differ several "
              "times); run without --cost to map them")
        return 0
    out.mkdir(parents=True, exist_ok=True)
    total = sum(len(v) for v in sweeps.values()) * len(masses)
    done = [0]
    failed: list[str] = []
    if not args.quiet:
        print(f"rib-map: {total} points ({len(params)} parameter(s) x values x "
              f"{len(masses)} unbalance mass(es)), model {args.model}; one line per point "
              f"on stderr, rows written to {out} as they finish", file=sys.stderr)
        print(f"rib-map: {base_text}", file=sys.stderr)
    for p in params:
        unit = DEFAULT_SWEEPS[p][0]
        values = sweeps[p]
        scale = to_si(f"1 {unit}", KINDS[p], field=p)
        path = out / f"rib_map_{p}.csv"
        _write_settings(out / f"rib_map_{p}_settings.json", args, bearing, base, masses, p)
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
                    print(f"[{done[0]}/{total}] {p} {_num(r['value'] / scale)} {unit}, m_u "
                          f"{r['unbalance_mass'] * 1e3:.3g} g: PV L/R "
                          f"{r['pv_left'] / 1e6:.4g}/{r['pv_right'] / 1e6:.4g} MPa m/s, slip "
                          f"{r['slip_speed']:.4g} m/s ({r['cost_s']:.2g} s CPU)",
                          file=sys.stderr, flush=True)

            rows = []
            for value in values:
                for mass in masses:
                    try:
                        rows += rd.pv_slip_map(
                            bearing, lubricant, p, [value], [mass], model=args.model,
                            base=base, temperature=temperature, cache=cache,
                            end_face=args.end_face, coupling=coupling, slide=args.slide,
                            coupled_options=coupled_options, on_row=write_row, **options)
                    except KeyboardInterrupt:
                        fh.flush()
                        print(f"interrupted while mapping {p}: the points finished so far are "
                              f"in {path} (and the parameters before it in {out}); rerun "
                              "with --param to map the rest", file=sys.stderr)
                        return 130
                    except ThermobearingError as exc:
                        # the solver's error named no point of the map ("[state=...]")
                        fh.flush()
                        what = (f"{LABELS[p]} {_shown(p, value)}, m_u {mass * 1e3:.3g} g "
                                f"({args.model} model)")
                        failed.append(f"{what}: {exc}")
                        if args.keep_going:
                            done[0] += 1
                            print(f"[{done[0]}/{total}] {p} {_shown(p, value)}, m_u "
                                  f"{mass * 1e3:.3g} g: FAILED, no row ({type(exc).__name__})",
                                  file=sys.stderr, flush=True)
                            continue
                        others = " or ".join(f"--model {m}" for m in ("coupled", "reduced")
                                             if m != args.model)
                        print(f"thermobearing rib-map: error: the point {what} failed: {exc}",
                              file=sys.stderr)
                        print(f"the points finished are in {out} ({len(rows)} of {p} in "
                              f"{path}); --keep-going maps the other points, {others} or "
                              "other --values may pass this one", file=sys.stderr)
                        return 1
        print(f"{p}: {path}")
        for r in rows:
            print(f"  {_num(r['value'] / scale):>8s} {unit:4s} m_u "
                  f"{r['unbalance_mass'] * 1e3:.3g} g"
                  f"  PV L {r['pv_left'] / 1e6:8.4g}  R {r['pv_right'] / 1e6:8.4g} MPa m/s"
                  f"  slip {r['slip_speed']:.4g} m/s")
        if not args.no_plot:
            _plot(rows, p, unit, scale, out / f"rib_map_{p}.png",
                  f"{bearing.name}, {args.lubricant} at {args.temperature}; held at "
                  + ", ".join(f"{LABELS[q]} {_shown(q, base[q])}" for q in DEFAULT_SWEEPS
                              if q != p) + f"; model {args.model}")
    if failed:
        print(f"{len(failed)} of {total} points failed (no row):", file=sys.stderr)
        for line in failed:
            print(f"  - {line}", file=sys.stderr)
        return 1
    return 0
