"""Cached / tabulated numerical EHL films for the quasi-dynamics, and the ``ehl_solver`` registry.

A roller-bearing transient calls the film model for every loaded contact at every step; the
numerical (T)EHL solve costs seconds. :class:`FilmTable` answers from a table over
(load per length, entrainment speed, slide-to-roll ratio, inlet temperature): each query is
located in a grid cell (log-spaced in load and speed, uniform in slide-to-roll ratio and
temperature); the solver runs only at cell corners it has not seen before, and the answer is
the multilinear interpolation of ``ln h`` (films vary as powers of load and speed, so the
interpolation is linear in ``ln w``, ``ln u``) and of the other outputs. ``mode="nearest"``
returns the nearest corner (one solve per new cell, coarser).

The registry :data:`EHL_SOLVERS` holds the numerical line-contact models under the names a
scene uses (``film = "numerical_ehl"`` or ``"numerical_tehl"``); they are kept out of
:data:`thermobearing.film.FILM` because they need a lubricant object and an inlet temperature
rather than the closed-form keyword set.
"""

from __future__ import annotations

import itertools
import logging
import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..errors import (
    ConvergenceError,
    InputError,
    check_finite,
    check_positive,
    check_range,
    check_temperature,
)
from ..registry import Registry

#: one INFO record per table-node solve (a front end can show it as progress: the first
#: query of a new cell costs up to 16 solves of seconds each)
LOG = logging.getLogger("thermobearing.ehl")

EHL_SOLVERS: Registry[Callable[..., object]] = Registry(
    "ehl_solver", "numerical line-contact EHL film and traction (isothermal or thermal)"
)

_PARAMS = {
    "load_per_length": "N/m", "reduced_radius_x": "m", "effective_modulus": "Pa",
    "entrainment_speed": "m/s", "slide_to_roll": "-", "inlet_temperature": "K",
}


#: distance [cells] within which a grid coordinate is taken as its node (round-off of the
#: log/exp round trip of a node's own coordinates is ~1e-15; the interpolation error this
#: admits is <= 1e-9 of one cell's change)
SNAP = 1e-9


@dataclass(frozen=True)
class FilmPoint:
    """Outputs of one line-contact solve (SI): central_film [m], minimum_film [m],
    max_pressure [Pa], traction [N/m] (film force per unit length on surface 1, rolling
    direction), rolling_traction [N/m] (its Poiseuille part), max_temperature_rise [K]."""

    central_film: float
    minimum_film: float
    max_pressure: float
    traction: float
    rolling_traction: float
    max_temperature_rise: float


@EHL_SOLVERS.register(
    "numerical_ehl",
    references=["li2018_nu214_skidding", "venner_lubrecht2000", "liu_wang_liu2000_dcfft",
                "fischer1992"],
    parameters=_PARAMS,
    validity="1 <= M <= 3000, 0 <= L <= 40 (Moes); isothermal Newtonian; errors outside",
)
def numerical_ehl(load_per_length: float, reduced_radius_x: float, effective_modulus: float,
                  entrainment_speed: float, slide_to_roll: float, inlet_temperature: float,
                  *, lubricant, n: int = 512,
                  limiting_shear_coefficient: float | None = None) -> FilmPoint:
    """Isothermal numerical line-contact EHL at the inlet temperature (paper 000 eqs. 5, 7-11).

    Viscosity at ``inlet_temperature`` from ``lubricant`` (Roelands index or Barus alpha),
    Dowson-Higginson density. Traction by paper 000 eq. 5 (optional limiting shear stress).
    """
    from .line import solve_line_contact

    check_finite("slide_to_roll", slide_to_roll)  # a NaN gave traction = NaN silently
    T = float(inlet_temperature)
    eta = float(lubricant.dynamic_viscosity(T))
    if getattr(lubricant, "pressure_law", "roelands") == "barus":
        kw = {"alpha": float(lubricant.pressure_viscosity_coefficient(T))}
    else:
        kw = {"roelands_z": float(lubricant.roelands_index(T))}
    sol = solve_line_contact(load_per_length, reduced_radius_x, effective_modulus,
                             entrainment_speed, eta, n=n, **kw)
    tr = sol.traction(slide_to_roll, limiting_shear_coefficient)
    return FilmPoint(sol.central_film, sol.minimum_film, sol.max_pressure, tr.total,
                     tr.poiseuille, 0.0)


@EHL_SOLVERS.register(
    "numerical_tehl",
    references=["shi2015_tehl_roller", "yang_wen1990", "venner_lubrecht2000",
                "johnson_tevaarwerk1977_traction"],
    parameters=_PARAMS,
    validity="1 <= M <= 3000, 0 <= L <= 40 at the inlet temperature; |SRR| < 2; Newtonian "
             "(or Ree-Eyring with eyring_stress)",
)
def numerical_tehl(load_per_length: float, reduced_radius_x: float, effective_modulus: float,
                   entrainment_speed: float, slide_to_roll: float, inlet_temperature: float,
                   *, lubricant, solid, solid2=None, n: int = 512,
                   **solver_kwargs) -> FilmPoint:
    """Thermal numerical line-contact EHL (paper 001 eqs. 6 and 8, line-contact form).

    ``solid``: :class:`thermobearing.ehl.thermal.SolidThermal` of surface 1 (moving at
    ``u_m (1 + SRR/2)``) and, unless ``solid2`` is given, of surface 2 (or a
    :class:`thermobearing.materials.Material`). ``solver_kwargs`` go to
    :func:`thermobearing.ehl.thermal.solve_thermal_line_contact` (``nz``, ``ns``,
    ``tol_temperature``, ...).
    """
    from .thermal import SolidThermal, solve_thermal_line_contact

    s = solid if isinstance(solid, SolidThermal) else SolidThermal.of(solid)
    s2 = None if solid2 is None else (solid2 if isinstance(solid2, SolidThermal)
                                      else SolidThermal.of(solid2))
    sol = solve_thermal_line_contact(load_per_length, reduced_radius_x, effective_modulus,
                                     entrainment_speed, slide_to_roll, lubricant,
                                     inlet_temperature, solid1=s, solid2=s2, n=n,
                                     **solver_kwargs)
    return FilmPoint(sol.central_film, sol.minimum_film, sol.max_pressure, sol.shear_force,
                     sol.rolling_force, sol.max_temperature - float(inlet_temperature))


class FilmTable:
    """Lazily filled interpolation table of a registered EHL solver for one contact geometry.

    Parameters
    ----------
    model : name in :data:`EHL_SOLVERS` (``"numerical_ehl"`` or ``"numerical_tehl"``).
    reduced_radius_x : R_x [m]; effective_modulus : E' [Pa]; lubricant, and for the thermal
        model ``solid``.
    load_step, speed_step : ratio between neighbouring grid values of load and speed (> 1).
    srr_step : grid spacing of the slide-to-roll ratio [-]; temperature_step [K].
    mode : ``"linear"`` (multilinear, up to 16 solves for a new cell) or ``"nearest"``.
    max_failed_weight : a multilinear answer whose failed corners (thermal fixed point not
        converged, e.g. SRR 0.05 at the heaviest load and highest speed of D1842926) carry
        at most this interpolation weight in total is the weighted mean of the solved
        corners (counted in :attr:`partial_answers`); above it the corner's error is raised.
        Default 0.1: a near-rolling contact (SRR 5e-6) of D1842926's most loaded rollers
        put weight 1e-4 on a failed SRR = 0.05 corner, and the whole query fell back to the
        isothermal closed-form film (about 5 times the thermal one).
    temperature_origin : a temperature node [K]; the nodes are ``origin + k temperature_step``
        (a steady solve at the origin's temperature then needs one temperature node per
        corner, not two: half the solves of a cell).
    **solver_kwargs : passed to the solver (``n``, ...).

    The instance is a mutable memo (it is not global state: its owner decides its lifetime).
    A node whose solve failed is remembered too and raises the same error again at once.
    """

    def __init__(self, model: str, reduced_radius_x: float, effective_modulus: float, *,
                 lubricant, load_step: float = 1.25, speed_step: float = 1.25,
                 srr_step: float = 0.02, temperature_step: float = 5.0,
                 mode: str = "linear", temperature_origin: float = 0.0,
                 max_failed_weight: float = 0.1, **solver_kwargs) -> None:
        self.solver = EHL_SOLVERS.get(model)
        self.solver_name = model
        check_positive("reduced_radius_x", reduced_radius_x)
        check_positive("effective_modulus", effective_modulus)
        for name, v in (("load_step", load_step), ("speed_step", speed_step)):
            if not v > 1.0:
                raise InputError(name, v, "a ratio > 1")
        check_positive("srr_step", srr_step)
        check_positive("temperature_step", temperature_step)
        if mode not in ("linear", "nearest"):
            raise InputError("mode", mode, "'linear' or 'nearest'")
        self.rx = float(reduced_radius_x)
        self.ep = float(effective_modulus)
        self.lubricant = lubricant
        self.steps = (math.log(load_step), math.log(speed_step), float(srr_step),
                      float(temperature_step))
        self.mode = mode
        check_finite("temperature_origin", temperature_origin)
        self.t_origin = float(temperature_origin)
        check_range("max_failed_weight", max_failed_weight, 0.0, 1.0, high_inclusive=False)
        self.max_failed_weight = float(max_failed_weight)
        self.partial_answers = 0
        self.kwargs = solver_kwargs
        self._nodes: dict[tuple[int, int, int, int], FilmPoint] = {}
        self._failed: dict[tuple[int, int, int, int], Exception] = {}
        self.solves = 0
        self.queries = 0
        self.solve_time = 0.0  # CPU seconds spent in node solves

    def _coords(self, w: float, u: float, srr: float, T: float) -> np.ndarray:
        """Grid coordinates of a point (node indices at integers). A coordinate within
        :data:`SNAP` of an integer is that integer: a query at a node's own (w', u, SRR, T)
        comes back through log/exp with a round-off of ~1e-15 of a cell, which listed up to
        16 corners with weights ~1e-16 -- each a solve -- for about a third of the nodes."""
        c = np.array([math.log(w), math.log(u), srr, T - self.t_origin]) / np.array(self.steps)
        r = np.rint(c)
        return np.where(np.abs(c - r) < SNAP, r, c)

    def corners(self, w: float, u: float, srr: float, T: float) -> list[tuple[int, ...]]:
        """Nodes (index tuples) an answer at this point is built from (nonzero weights)."""
        c = self._coords(w, u, srr, T)
        if self.mode == "nearest":
            return [tuple(int(v) for v in np.rint(c))]
        lo = np.floor(c).astype(int)
        frac = c - lo
        return [tuple(int(v) for v in lo + np.array(corner))
                for corner in itertools.product((0, 1), repeat=4)
                if all(f > 0.0 or not b for f, b in zip(frac, corner, strict=True))]

    def known(self, idx: tuple[int, ...]) -> bool:
        """Whether node ``idx`` was solved (or failed) already: answering needs no solve."""
        return idx in self._nodes or idx in self._failed

    def node_point(self, idx: tuple[int, ...]) -> tuple[float, float, float, float]:
        """(w', u, SRR, T) of node ``idx`` (SI)."""
        lw, lu, s, t = (i * st for i, st in zip(idx, self.steps, strict=True))
        return math.exp(lw), math.exp(lu), s, t + self.t_origin

    def solved_nodes(self) -> dict[tuple[int, ...], FilmPoint]:
        """The solved nodes (a copy)."""
        return dict(self._nodes)

    def _node(self, idx: tuple[int, int, int, int]) -> FilmPoint:
        got = self._nodes.get(idx)
        if got is None:
            failed = self._failed.get(idx)
            if failed is not None:  # a node that failed once fails again: do not re-solve
                raise failed
            w_n, u_n, s, t = self.node_point(idx)
            lw, lu = math.log(w_n), math.log(u_n)
            self.solves += 1
            t0 = time.process_time()
            try:
                got = self.solver(w_n, self.rx, self.ep, u_n, s, t,
                                  lubricant=self.lubricant, **self.kwargs)
            except (InputError, ConvergenceError) as err:
                self._failed[idx] = err
                self.solve_time += time.process_time() - t0
                LOG.info("%s table (R_x %.4g m): node w' %.4g N/m, u %.4g m/s, SRR %.3g, "
                         "T %.1f K failed after %.1f s CPU", self.solver_name, self.rx,
                         math.exp(lw), math.exp(lu), s, t, time.process_time() - t0)
                raise
            dt = time.process_time() - t0
            self.solve_time += dt
            LOG.info("%s table (R_x %.4g m): node %d, w' %.4g N/m, u %.4g m/s, SRR %.3g, "
                     "T %.1f K: %.1f s CPU (%.0f s in this table)", self.solver_name, self.rx,
                     self.solves, math.exp(lw), math.exp(lu), s, t, dt, self.solve_time)
            self._nodes[idx] = got
        return got

    def __call__(self, load_per_length: float, entrainment_speed: float,
                 slide_to_roll: float, inlet_temperature: float, *,
                 stand_in: Callable[[tuple[int, ...]], FilmPoint | None] | None = None
                 ) -> FilmPoint:
        """Film and traction at one operating point (SI), from the table.

        ``stand_in(node)``: for a node not solved yet, a value to use instead of solving it
        (None: solve it). The answer is then the same interpolation over the nodes' values,
        with the stand-in values at those nodes, so that it stays continuous across cell
        boundaries as long as each node has one value (solved or stand-in); see
        :meth:`thermobearing.ehl.coupling.TehlFilmModel.films`.
        """
        check_positive("load_per_length", load_per_length)
        check_positive("entrainment_speed", entrainment_speed)
        check_finite("slide_to_roll", slide_to_roll)  # NaN became a garbage table index
        check_temperature("inlet_temperature", inlet_temperature)
        self.queries += 1
        c = self._coords(load_per_length, entrainment_speed, slide_to_roll, inlet_temperature)

        def node(idx: tuple[int, ...]) -> FilmPoint:
            if stand_in is not None and not self.known(idx):
                got = stand_in(idx)
                if got is not None:
                    return got
            return self._node(idx)

        if self.mode == "nearest":
            return node(tuple(int(v) for v in np.rint(c)))
        lo = np.floor(c).astype(int)
        frac = c - lo
        acc = np.zeros(6)
        failed_weight, first_error = 0.0, None
        for corner in itertools.product((0, 1), repeat=4):
            wgt = float(np.prod([f if b else 1.0 - f for f, b in zip(frac, corner,
                                                                        strict=True)]))
            if wgt == 0.0:
                continue
            try:
                p = node(tuple(int(v) for v in lo + np.array(corner)))
            except (InputError, ConvergenceError) as err:
                failed_weight += wgt
                first_error = first_error or err
                continue
            acc += wgt * np.array([math.log(p.central_film), math.log(p.minimum_film),
                                   p.max_pressure, p.traction, p.rolling_traction,
                                   p.max_temperature_rise])
        if first_error is not None:
            if failed_weight > self.max_failed_weight:
                raise first_error
            # corners that failed carry little weight: the answer of the solved ones
            self.partial_answers += 1
            acc /= 1.0 - failed_weight
        return FilmPoint(math.exp(acc[0]), math.exp(acc[1]), *acc[2:].tolist())

    def __len__(self) -> int:
        return len(self._nodes)
