"""``thermobearing lubricant [NAME|PATH]``: property table of a lubricant preset or TOML file."""

from __future__ import annotations

import argparse
import math
import warnings

import numpy as np

from ..errors import InputError
from ..lubricant import load_lubricant, preset_names
from ..units import to_si

NAME = "lubricant"
HELP = "print viscosity, density, pressure-viscosity and thermal properties of a lubricant"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("name", nargs="?", help="preset name or TOML path (default: list presets)")
    parser.add_argument(
        "--temperatures",
        default="20,40,60,80,100,120",
        help="comma-separated temperatures in degC (default 20,40,60,80,100,120)",
    )
    parser.add_argument("--pressure", default="0 Pa",
                        help="gauge pressure for the viscosity/density columns, e.g. '1 GPa'")


def _temperatures(text: str) -> np.ndarray:
    """``--temperatures``: numbers in degC or unit strings ('300 K'), comma-separated [K]."""
    out = []
    allowed = "temperatures above absolute zero: numbers in degC or unit strings ('350 K')"
    for item in (t.strip() for t in text.split(",")):
        if not item:
            continue
        try:
            kelvin = float(item) + 273.15
        except ValueError:
            kelvin = to_si(item, "temperature", field="--temperatures")
        if not (math.isfinite(kelvin) and kelvin > 0):
            raise InputError("--temperatures", item, allowed)
        out.append(kelvin)
    if not out:
        raise InputError("--temperatures", text, allowed)
    return np.array(out)


def run(args: argparse.Namespace) -> int:
    if not args.name:
        print("lubricant presets: " + ", ".join(preset_names()))
        return 0
    lub = load_lubricant(args.name)
    T = _temperatures(str(args.temperatures))
    temps_c = [float(t) - 273.15 for t in T]
    p = to_si(args.pressure, "Pa", field="--pressure")
    print(f"{lub.name} ({lub.kind})")
    print(f"  source: {lub.source}")
    print(f"  viscosity law: {lub.viscosity_law}; pressure law: {lub.pressure_law}; "
          f"density: {lub.density_temperature_law} / {lub.density_pressure_law}; "
          f"thermal: {lub.thermal_model}")
    for key, why in lub.estimated.items():
        print(f"  estimated {key}: {why}")
    header = (f"{'T [degC]':>9} {'nu [mm2/s]':>11} {'eta [mPa s]':>12} {'rho [kg/m3]':>12} "
              f"{'alpha [1/GPa]':>13} {'z [-]':>7} {'cp [J/kgK]':>11} {'k [W/mK]':>9}")
    if p:
        header += f"   at p = {p:.4g} Pa: eta [Pa s], rho [kg/m3]"
    print(header)
    # the laws' validity warnings once each, under the table: Python's warning stream
    # printed each law's warning once per property it feeds (five times for -60 degC),
    # each with the source line that raised it
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        nu = np.atleast_1d(lub.kinematic_viscosity(T))
        eta = np.atleast_1d(lub.dynamic_viscosity(T))
        rho = np.atleast_1d(lub.density(T))
        alpha = np.atleast_1d(lub.pressure_viscosity_coefficient(T))
        z = np.atleast_1d(lub.roelands_index(T))
        cp = np.atleast_1d(lub.specific_heat(T))
        k = np.atleast_1d(lub.thermal_conductivity(T))
        eta_p = np.atleast_1d(lub.dynamic_viscosity(T, p)) if p else None
        rho_p = np.atleast_1d(lub.density(T, p)) if p else None
    for i, tc in enumerate(temps_c):
        line = (f"{tc:9.1f} {nu[i] * 1e6:11.4g} {eta[i] * 1e3:12.4g} {rho[i]:12.1f} "
                f"{alpha[i] * 1e9:13.4g} {z[i]:7.3f} {cp[i]:11.1f} {k[i]:9.4f}")
        if eta_p is not None and rho_p is not None:
            line += f"   {eta_p[i]:.4g}  {rho_p[i]:.1f}"
        print(line)
    for text in dict.fromkeys(str(w.message) for w in caught):
        print(f"  warning: {text}")
    return 0
