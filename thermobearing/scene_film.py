"""``[models] film_options``: the settings of the numerical thermal-EHL film of a scene.

A scene with ``[models] film = "numerical_tehl"`` (roller bearings) runs
:class:`thermobearing.ehl.coupling.TehlFilmModel`: an interpolation table over load per
length, entrainment speed, slide-to-roll ratio and inlet temperature whose nodes are thermal
line-contact EHL solves (paper 001 eqs. 6 and 8, line-contact form). ``film_options`` sets the
grid of those solves, the table spacing and the solver tolerances, e.g.::

    [models]
    film = "numerical_tehl"
    film_options = { grid_points = 256, temperature_step = "5 K" }

Each key maps to one keyword of the film model (:data:`FILM_OPTIONS`); values are numbers in
SI or quantity strings (pint), checked against the interval each option documents. Unknown
keys, and ``film_options`` with any other film model (the closed-form films and the isothermal
``numerical_ehl`` have none of these settings in a scene), are refused naming the field.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from .errors import InputError
from .units import to_si

FIELD = "models.film_options"
#: the film model whose settings ``film_options`` holds
FILM_WITH_OPTIONS = "numerical_tehl"


@dataclass(frozen=True)
class FilmOption:
    """One ``film_options`` key: the film-model keyword it sets, its unit (pint spelling or a
    :data:`thermobearing.units.SI_UNITS` kind; "" dimensionless), its interval and why.

    ``low`` is exclusive, ``high`` inclusive; ``powers_of_two``: the value must be a whole
    power of two (the nested multigrid levels of :func:`thermobearing.ehl.line._levels` halve
    the grid)."""

    keyword: str
    unit: str
    low: float
    high: float
    doc: str
    powers_of_two: bool = False

    def allowed(self) -> str:
        """The allowed values, as an error states them."""
        unit = {"temperature_difference": " K", "": ""}.get(self.unit, f" {self.unit}")
        if self.powers_of_two:
            return (f"a whole power of two from {self.low:g} to {self.high:g} "
                    f"(TehlFilmModel {self.keyword}: {self.doc})")
        return (f"a value > {self.low:g} and <= {self.high:g}{unit} "
                f"(TehlFilmModel {self.keyword}: {self.doc})")


#: ``film_options`` key -> :class:`FilmOption`. The defaults are those of TehlFilmModel and
#: of the thermal solver (:func:`thermobearing.ehl.thermal.solve_thermal_line_contact`).
FILM_OPTIONS: dict[str, FilmOption] = {
    "grid_points": FilmOption(
        "n", "", 128, 4096, "minimum pressure nodes of each thermal solve, default 512; the "
        "solver raises it for light loads; the smallest start grid of the multigrid is 128 "
        "and the Richardson error estimate needs n/2 on or above the start grid",
        powers_of_two=True),
    "load_step": FilmOption(
        "load_step", "", 1.0, 4.0, "ratio between neighbouring table loads per length, "
        "default 1.5"),
    "speed_step": FilmOption(
        "speed_step", "", 1.0, 4.0, "ratio between neighbouring table entrainment speeds, "
        "default 1.25"),
    "slide_to_roll_step": FilmOption(
        "srr_step", "", 0.0, 0.05, "table spacing of the slide-to-roll ratio, default 0.05; "
        "the table clips |SRR| to 0.05, so a wider step only adds nodes outside it"),
    "temperature_step": FilmOption(
        "temperature_step", "temperature_difference", 0.0, 50.0, "table spacing of the inlet "
        "temperature, default 5 K"),
    "temperature_tolerance": FilmOption(
        "tol_temperature", "temperature_difference", 0.0, 1.0, "convergence of the film "
        "temperature fixed point on max |dT| between sweeps, default 0.03 K (0.1 K moves "
        "films by up to 0.27 %)"),
    "max_grid_error": FilmOption(
        "max_grid_error", "", 0.0, 0.2, "largest Richardson estimate of the central-film "
        "grid error a solve accepts, default 0.05"),
}


def _allowed_keys() -> str:
    return ", ".join(sorted(FILM_OPTIONS))


def film_options_from_models(models: Mapping[str, Any]) -> dict[str, float | int]:
    """``[models] film_options`` checked and converted: ``{TehlFilmModel keyword: value}``
    in SI (temperatures as differences in K; ``grid_points`` an int). Empty without the key.

    Raises InputError naming ``models.film_options[.key]``: not a table, an unknown key, a
    value out of its interval (the error gives the interval), or ``film_options`` with a
    film model other than ``numerical_tehl``.
    """
    raw = models.get("film_options")
    if raw is None:
        return {}
    if not isinstance(raw, Mapping):
        raise InputError(FIELD, raw, "a table of option = value (" + _allowed_keys() + ")")
    film = models.get("film")
    if raw and film != FILM_WITH_OPTIONS:
        key = next(iter(raw))
        here = (f"the film here is {film!r}" if film is not None
                else "no film model is set (the closed-form default has no options)")
        raise InputError(f"{FIELD}.{key}", raw[key],
                         f"film_options only with [models] film = \"{FILM_WITH_OPTIONS}\" "
                         f"(the numerical thermal EHL film of roller bearings); {here}")
    out: dict[str, float | int] = {}
    for key, value in raw.items():
        field = f"{FIELD}.{key}"
        opt = FILM_OPTIONS.get(key)
        if opt is None:
            raise InputError(field, value, "a setting of the numerical_tehl film: "
                             + _allowed_keys())
        si = to_si(value, opt.unit, field=field)
        read = "" if si == value else f" (read as {si:g})"
        if opt.powers_of_two:
            whole = float(si).is_integer() and si > 0
            if not (whole and opt.low <= si <= opt.high
                    and math.log2(si).is_integer()):
                raise InputError(field, value, opt.allowed() + read)
            out[opt.keyword] = int(si)
            continue
        if not (opt.low < si <= opt.high):
            raise InputError(field, value, opt.allowed() + read)
        out[opt.keyword] = float(si)
    return out


def describe_film_options(models: Mapping[str, Any]) -> str:
    """The scene's ``film_options`` as the chain description shows them ("" if none):
    ``"; settings: grid_points 256, temperature_step 5 K"``."""
    raw = models.get("film_options") or {}
    if not isinstance(raw, Mapping) or not raw:
        return ""
    return "; settings: " + ", ".join(f"{k} {v}" for k, v in raw.items())
