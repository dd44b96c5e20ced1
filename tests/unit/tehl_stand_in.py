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


def graded_film(w, rx, ep, u, s, T, *, lubricant, **_kw):
    """FilmPoint of a stand-in whose thermal reduction falls with load and speed as the
    thermal solve's does for D1842926 with OIL_4109 at 30 degC (0.24 at 57 kN/m and 44 m/s,
    0.12 at 650 kN/m and 56 m/s: ``0.24 (w/57 kN/m)^-0.18 (u/44 m/s)^-1.15``), and whose
    rolling traction is the thermal solve's 220 N/m (negative on surface 1). Unlike
    :func:`stand_in_film`, the mean reduction of a set of nodes then differs from the
    reduction at most nodes."""
    eta0 = float(lubricant.dynamic_viscosity(T))
    alpha = float(lubricant.pressure_viscosity_coefficient(T))
    red = 0.24 * (w / 5.7e4) ** -0.18 * (u / 44.0) ** -1.15
    h = red * float(moes_line_central(u, eta0, alpha, w, 1.0, rx, effective_modulus=ep))
    return cache.FilmPoint(h, 0.99 * h, 1.0e9, -220.0, -220.0, 100.0)


class GradedTable(cache.FilmTable):
    """A FilmTable whose node solves are :func:`graded_film`."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.solver = graded_film
