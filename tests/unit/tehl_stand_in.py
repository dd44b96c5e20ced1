"""Closed-form stand-in for the thermal-EHL solve of the film table (test helper, not a test
module): the Moes central film times 0.2, so that tests count the table nodes the roller
quasi-dynamics asks for in milliseconds; it changes the physics, not which cells are visited.
Imported by the unit tests of ``ehl.coupling`` (pytest puts ``tests/unit`` on the path)."""

from __future__ import annotations

from thermobearing.ehl import cache
from thermobearing.film import moes_line_central


def stand_in_film(w, rx, ep, u, s, T, *, lubricant, **_kw):
    """FilmPoint of the stand-in (the FilmTable solver's signature)."""
    eta0 = float(lubricant.dynamic_viscosity(T))
    alpha = float(lubricant.pressure_viscosity_coefficient(T))
    h = 0.2 * float(moes_line_central(u, eta0, alpha, w, 1.0, rx, effective_modulus=ep))
    return cache.FilmPoint(h, 0.8 * h, 1.0e9, 0.0, 1.0e-4 * w, 10.0)


class CheapTable(cache.FilmTable):
    """A FilmTable whose node solves are the stand-in."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.solver = stand_in_film
