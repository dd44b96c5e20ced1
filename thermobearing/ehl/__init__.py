"""Numerical (thermal) EHL of line contacts.

Public API
----------
:func:`solve_dimensionless` (Moes M, L), :func:`solve_line_contact` (dimensional, isothermal),
:func:`solve_thermal_line_contact` (thermal, paper 001), :class:`FilmTable` (cache /
interpolation table for transients), :class:`TehlFilmModel` (the table-backed film model of
the roller quasi-dynamics, scene ``film = "numerical_tehl"``, see :mod:`.coupling`),
registry :data:`EHL_SOLVERS` (``"numerical_ehl"``, ``"numerical_tehl"``). Importing the
package registers the roller drag models ``"numerical_ehl"`` and ``"numerical_tehl"`` and the
latter's skidding driver (:data:`thermobearing.kinematic_models.TABLE_FILM_DRIVERS`).
See :mod:`.line`, :mod:`.thermal`, :mod:`.solver`, :mod:`.kernel`,
:mod:`.cache`.
"""

from .cache import EHL_SOLVERS, FilmPoint, FilmTable, numerical_ehl, numerical_tehl
from .coupling import TehlFilmModel, roller_film_model, tehl_contact_forces  # "numerical_tehl"
from .drag import NumericalRollerDrag  # registers "numerical_ehl" in ROLLER_DRAG (skidding)
from .line import (
    LineContactCase,
    LineEHLSolution,
    Traction,
    line_contact_case,
    moes_dimensionless,
    solve_dimensionless,
    solve_line_contact,
)
from .thermal import SolidThermal, ThermalLineEHLSolution, solve_thermal_line_contact

__all__ = [
    "EHL_SOLVERS", "NumericalRollerDrag", "FilmPoint", "FilmTable", "LineContactCase",
    "LineEHLSolution",
    "SolidThermal", "TehlFilmModel", "ThermalLineEHLSolution", "Traction",
    "line_contact_case", "roller_film_model", "tehl_contact_forces",
    "moes_dimensionless", "numerical_ehl", "numerical_tehl", "solve_dimensionless",
    "solve_line_contact", "solve_thermal_line_contact",
]
