"""Numerical thermal EHL in the roller-bearing quasi-dynamics (scene ``film = "numerical_tehl"``).

Paper 001 (Shi & Wang 2015, seed ``001_5ba4564faedebfb7.txt``, section 3 and Fig. 3) couples
the quasi-dynamics of a roller bearing with a thermal EHL analysis of its contacts: the
quasi-dynamics give every roller-race contact its load and surface speeds, the TEHL gives
the film that the closed-form film formula (Hamrock-Dowson) got wrong at high speed. Here:

* :class:`TehlFilmModel` is the film model of :func:`thermobearing.skidding.roller.build_model`
  (``film_model=`` callable, ``(u_e, w', R_x, eta0, alpha, E') -> h_c``). It answers from one
  :class:`~thermobearing.ehl.cache.FilmTable` per contact radius (inner and outer race) over
  (load per length, entrainment speed, slide-to-roll ratio, inlet temperature): the thermal
  solver (:func:`~thermobearing.ehl.cache.numerical_tehl`) runs only at table nodes it has
  not solved before, so a transient or a load sweep re-uses what it knows. The instance is
  the memo; its owner (the :class:`~thermobearing.simulation.Simulation` of a scene) decides
  its lifetime.
* :func:`tehl_contact_forces` is the roller drag model ``"numerical_tehl"`` of
  :data:`thermobearing.skidding.roller_fluid.ROLLER_DRAG`. It computes the slide-to-roll
  ratio ``(u_race - u_roller)/u_e`` of every loaded contact and the inlet temperature, hands
  them to the film model for the duration of the call (a :class:`contextvars.ContextVar`:
  the film callable of ``build_model`` carries only ``(u_e, w')``). Contacts that slide
  grossly (``|SRR|`` above twice ``max_slide_to_roll``; the Newton iterates of the
  quasi-dynamics pass through such states, with cage speeds anywhere between 0 and the
  shaft's) get the isothermal closed-form film without a thermal solve, blended smoothly
  into the thermal one (:meth:`TehlFilmModel.films`). It returns the
  closed-form line-contact forces of :func:`~thermobearing.skidding.roller_fluid.
  closed_form_contact_forces` evaluated on the TEHL central film (Hertz-zone traction law
  and inlet/outlet Couette shear on the thermal film), with the Poiseuille (rolling) force
  of paper 000 eq. 5, ``-int (h/2) dp/dx dx``, taken from the thermal solution.
* :func:`solve_roller_tehl` drives the skidding solve with that drag model, solving table
  nodes only around the converged state; it is registered as the ``"numerical_tehl"``
  driver of :data:`thermobearing.kinematic_models.TABLE_FILM_DRIVERS`, through which the
  scene's skidding kinematics reach it (a table-backed film declares its driver there).

Light loads: below Moes ``M = min_moes_m`` (default 1, the rigid/elastic transition) the
thermal solver needs very long inlet domains (thousands of nodes) and the contact carries
little; there the film is the closed-form Moes film (:func:`thermobearing.film.
moes_line_central`, which spans the rigid-isoviscous regime) times the thermal reduction
``h_TEHL / h_Moes`` of the table at ``M = min_moes_m`` (same speed, sliding and
temperature), which is continuous at the boundary; the rolling force there stays the closed
form's. The Couette stress in the Hertz zone is the skidding solver's traction law (limiting
shear stress), not the stress of the thermal solution (Newtonian: unbounded at GPa pressures).

Hertz-zone pressure: the traction law is evaluated under the film pressure of
:func:`thermobearing.skidding.roller_pressure.hertz_zone_pressure` with the model
``"regime_min"`` (default of :func:`tehl_contact_forces`' ``film_pressure``): the
semi-elliptic shape with the peak ``min(p_H, p_rig)``, ``p_rig`` the rigid-isoviscous
(Martin) peak, as the isothermal closed-form drag does with ``build_model(...,
film_pressure="regime_min")``. Before, this drag sheared the Hertz zone at ``p_H`` at every
load. Why: the lightly loaded rollers of paper 001's bearing (outside the load zone, a few
to a few hundred newtons; Moes M < 1 at 53 m/s) are in the rigid regime. The numerical
line-contact solution of this package at L = 31.8 (paper 001's inner contact) puts the
pressure peak at 0.035 / 0.10 / 0.34 p_H for M = 0.05 / 0.14 / 0.4, against Martin's
0.035 / 0.095 / 0.29 p_H (piezoviscous rise within 20 %), and carries only 3-14 % of the load
inside |x| < b; shearing that zone at eta(p_H) overstated its traction by the factor
exp(alpha (p_H - p)) (x8 at 113 MPa with paper 001's oil). Paper 001 (its eq. 1) balances
the roller with the traction T_jk of the film itself, i.e. at the film pressure, which is
what this does. For M >~ 1.4 ``p_rig > p_H`` and the peak stays ``p_H`` (the numerical
pressure there spreads over the Hertz zone; its mean over |x| < b is 0.5-0.6 p_H at M = 1.4).

Failures: where a table node's thermal solve fails (fixed point not converged, out of the
solver's range) the node is remembered as failed, the contact gets the closed-form film and
a ValidityWarning names the state (the Simulation collects it among the scene's warnings).
The cage-speed search of the roller solver passes through such states (e.g. outer-race
entrainment near 100 m/s); a failure at the converged state shows in the warnings.

Cost: a plain skidding solve (``thermobearing.skidding.solve(..., drag_model=
"numerical_tehl")``) fills the table at every near-rolling state its Newton iterates pass
through, including the abandoned cold starts: D1842926, OIL_4109 at 30 degC, 13218 r/min,
24 kN, clearance 40 um asked for 342 nodes (5-20 s CPU each; 246 of them from the two cold
starts, outer-race entrainment 11-55 m/s). Two things bound it:

* each table's temperature nodes sit at ``T_first + k temperature_step`` (``T_first`` the
  first inlet temperature it is asked for): a solve at a fixed inlet temperature needs one
  temperature node per cell corner, not two (342 -> 171 nodes);
* :func:`solve_roller_tehl` solves in passes that admit only the nodes of the previous
  pass's converged contacts (:attr:`TehlFilmModel.admitted`); the other unsolved nodes
  take stand-in values (the closed form times the table's mean thermal corrections, fixed
  for the pass) in the same interpolation, so the film stays continuous (171 -> 48 nodes,
  counted with a closed-form stand-in for the thermal solve, tests/unit/test_tehl_cost19.py).
  Its returned state's films are all the table's.

See benchmarks/README.md, section BM-6.

Units: SI (m, N/m, m/s, K, Pa).
"""

from __future__ import annotations

import math
import warnings
from contextvars import ContextVar
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import ConvergenceError, InputError, ValidityWarning, check_positive
from .cache import FilmTable

#: Per-call data the drag model hands to the film model: slide-to-roll ratios and inlet
#: temperature of the contacts being evaluated, and (out) the table answers.
_CALL: ContextVar[dict[str, Any] | None] = ContextVar("tehl_contact_call", default=None)


@dataclass(frozen=True)
class TehlFilms:
    """Table answers for a set of contacts (arrays, SI): central_film, minimum_film [m],
    rolling_traction [N/m] (Poiseuille force per length, >= 0; NaN where ``table_share``
    is 0), max_temperature_rise [K], numerical (bool: from the TEHL table alone, False:
    closed form x thermal reduction, or blended with it), table_share (0..1: weight of the
    table's rolling traction against the closed form's, :func:`tehl_contact_forces`)."""

    central_film: np.ndarray
    minimum_film: np.ndarray
    rolling_traction: np.ndarray
    max_temperature_rise: np.ndarray
    numerical: np.ndarray
    table_share: np.ndarray


class TehlFilmModel:
    """Tabulated thermal-EHL film of roller-race line contacts (see the module docstring).

    Parameters
    ----------
    lubricant : :class:`thermobearing.lubricant.Lubricant`.
    race_solid, roller_solid : thermal properties of the race (surface 1) and the roller
        (surface 2): :class:`~thermobearing.ehl.thermal.SolidThermal` or a
        :class:`~thermobearing.materials.Material`.
    n : minimum number of pressure nodes of a thermal solve (raised for light loads).
    load_step, speed_step : ratio between neighbouring table values of w' and u_e (> 1).
    srr_step : table spacing of the slide-to-roll ratio [-]; temperature_step [K].
    mode : FilmTable interpolation (``"linear"`` or ``"nearest"``).
    min_moes_m : smallest Moes M solved numerically (see the module docstring) [-].
    max_slide_to_roll : slide-to-roll ratios are clipped to +-this [-] (see below).
    eyring_stress : Ree-Eyring stress tau0 of the film [Pa] (None: Newtonian, paper 001);
        default 5 MPa, the ball skidding solver's value (Johnson & Tevaarwerk 1977 range).

    Sliding: the Newtonian film of paper 001 cannot carry sliding at Hertzian pressures and
    tens of m/s (the shear heating runs the film viscosity out of the Roelands range), and
    even the Eyring film heats by hundreds of kelvin at SRR = 0.2 and 53 m/s (paper 001's
    inner contact), where the fixed point fails. Loaded rollers of a converged quasi-dynamic
    state slide little, so the table covers ``|SRR| <= max_slide_to_roll`` (default 0.05)
    and larger ratios (Newton's intermediate iterates, gross skidding) are evaluated at the
    clip: their film is then overestimated (sliding heats and thins it).
    **solver_kwargs : passed to the thermal solver (``nz``, ``ns``, ``tol_temperature``...).
    """

    def __init__(self, lubricant: Any, race_solid: Any, roller_solid: Any = None, *,
                 n: int = 512, load_step: float = 1.5, speed_step: float = 1.25,
                 srr_step: float = 0.05, temperature_step: float = 5.0,
                 mode: str = "linear", min_moes_m: float = 1.0,
                 max_slide_to_roll: float = 0.05, eyring_stress: float | None = 5.0e6,
                 **solver_kwargs: Any) -> None:
        from .thermal import SolidThermal

        check_positive("min_moes_m", min_moes_m)
        if not 0.0 <= max_slide_to_roll < 2.0:
            raise InputError("max_slide_to_roll", max_slide_to_roll, "0 <= value < 2")
        self.lubricant = lubricant
        s1 = race_solid if isinstance(race_solid, SolidThermal) else SolidThermal.of(race_solid)
        s2 = roller_solid if roller_solid is not None else s1
        s2 = s2 if isinstance(s2, SolidThermal) else SolidThermal.of(s2)
        self.solids = (s1, s2)
        self.table_options = {"load_step": load_step, "speed_step": speed_step,
                              "srr_step": srr_step, "temperature_step": temperature_step,
                              "mode": mode}
        self.n = int(n)
        self.min_moes_m = float(min_moes_m)
        self.max_srr = float(max_slide_to_roll)
        if eyring_stress is not None:
            check_positive("eyring_stress", eyring_stress)
        self.solver_kwargs = {"eyring_stress": eyring_stress, **solver_kwargs}
        self.tables: dict[tuple[float, float], FilmTable] = {}
        self.failures = 0
        self._warned: set[tuple[float, ...]] = set()
        #: per table key, the stand-in scales of this pass (:meth:`_stand_in_scales`)
        self._frozen: dict[tuple[float, float], tuple[float, float, float, float, float]] = {}
        #: per table key, the stand-in values of this pass by node
        self._stand_in_memo: dict[tuple[float, float], dict[tuple[int, ...], Any]] = {}
        self._admitted: set[tuple[Any, ...]] | None = None
        #: answers that used a stand-in node (see :attr:`admitted`)
        self.provisional = 0

    # ----------------------------------------------------------------- tables
    def table(self, radius: float, effective_modulus: float,
              temperature: float | None = None) -> FilmTable:
        """The table of one contact geometry (created on first use, with a temperature node
        at ``temperature`` [K], the first inlet temperature it is asked for: a solve at a
        fixed inlet temperature then needs one temperature node, not two)."""
        key = (float(radius), float(effective_modulus))
        tab = self.tables.get(key)
        if tab is None:
            origin = 0.0 if temperature is None else float(temperature)
            tab = FilmTable("numerical_tehl", key[0], key[1], lubricant=self.lubricant,
                            solid=self.solids[0], solid2=self.solids[1], n=self.n,
                            temperature_origin=origin,
                            **self.table_options, **self.solver_kwargs)
            self.tables[key] = tab
        return tab

    @property
    def solves(self) -> int:
        """Thermal EHL solves run so far (all tables)."""
        return sum(t.solves for t in self.tables.values())

    @property
    def queries(self) -> int:
        """Table queries answered so far (all tables)."""
        return sum(t.queries for t in self.tables.values())

    @property
    def solve_time(self) -> float:
        """CPU seconds spent in thermal solves so far (all tables); each solve is also an
        INFO record of the ``thermobearing.ehl`` logger (progress for a front end)."""
        return sum(t.solve_time for t in self.tables.values())

    def temperature_of(self, eta0: float) -> float:
        """Inlet temperature [K] at which the lubricant has viscosity ``eta0`` [Pa s]
        (bisection on the monotone viscosity law; used when no temperature is given)."""
        lo, hi = 200.0, 600.0
        f = self.lubricant.dynamic_viscosity
        if not float(f(hi)) <= eta0 <= float(f(lo)):
            raise InputError("eta0", eta0, "a viscosity of the lubricant between 200 and 600 K")
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if float(f(mid)) > eta0:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)

    def _w_min(self, ue: float, radius: float, e_prime: float, eta0: float) -> float:
        """Load per length at Moes M = min_moes_m [N/m]: w' = M sqrt(2U) E' R."""
        two_u = 2.0 * eta0 * ue / (e_prime * radius)
        return self.min_moes_m * math.sqrt(two_u) * e_prime * radius

    def _query(self, tab: FilmTable, w: float, u: float, srr: float, T: float,
               stand_in: Any = None) -> Any:
        """One table query (``stand_in``: see :meth:`FilmTable.__call__`), or None where a
        table node's thermal solve failed (the contact then gets the closed-form film; a
        ValidityWarning names the state, once per node set, and :attr:`failures` counts
        them)."""
        try:
            return tab(w, u, srr, T, stand_in=stand_in)
        except (InputError, ConvergenceError) as err:
            self.failures += 1
            key = (round(math.log(w), 1), round(math.log(u), 1), round(srr, 2), round(T))
            if key not in self._warned:
                self._warned.add(key)
                warnings.warn(
                    f"numerical_tehl: thermal EHL failed near w'={w:.4g} N/m, u_e={u:.4g} m/s,"
                    f" SRR={srr:.3g}, T_in={T:.1f} K ({str(err)[:160]}); the closed-form "
                    "(isothermal Moes) film is used for this contact state",
                    ValidityWarning, stacklevel=3)
            return None

    def films(self, load_per_length: Any, entrainment_speed: Any, slide_to_roll: Any,
              temperature: float, radius: float, effective_modulus: float) -> TehlFilms:
        """Films of contacts (arrays over contacts; loads > 0), SI.

        Per contact, with the closed-form (isothermal Moes) film ``h_cf`` and the thermal
        reduction ``phi = h_TEHL/h_cf`` from the table (at ``M = min_moes_m`` for lighter
        loads): ``h = h_cf [(1 - s) phi + s]``, where the sliding weight ``s`` rises smoothly
        from 0 at ``|SRR| = max_slide_to_roll`` to 1 at twice that, and ``s = 1`` outside the
        solver's range (``M > 3000`` or ``L > 40``). Grossly sliding contacts (which the
        Newton iterates of the quasi-dynamics visit on their way) thus get the isothermal
        closed-form film without a thermal solve; near-rolling contacts the thermal one.
        ``table_share`` is ``1 - s`` where the contact is solved numerically (M >=
        ``min_moes_m``), else 0. In a pass of :func:`solve_roller_tehl` (:attr:`admitted`
        set) unsolved nodes outside the admitted cells take stand-in values
        (:meth:`_stand_in`) in the same interpolation.
        """
        from ..film import moes_line_central
        from .line import L_RANGE, M_RANGE

        w = np.atleast_1d(np.asarray(load_per_length, dtype=float))
        ue = np.maximum(np.broadcast_to(np.asarray(entrainment_speed, dtype=float), w.shape),
                        1e-6)
        srr_raw = np.broadcast_to(np.asarray(slide_to_roll, dtype=float), w.shape)
        T = float(temperature)
        tab = self.table(radius, effective_modulus, T)
        eta0 = float(self.lubricant.dynamic_viscosity(T))
        alpha = float(self.lubricant.pressure_viscosity_coefficient(T))
        h_cf = np.asarray(moes_line_central(ue, eta0, alpha, w, 1.0, radius,
                                            effective_modulus=effective_modulus), dtype=float)
        if self.max_srr > 0.0:
            t = np.clip(np.abs(srr_raw) / self.max_srr - 1.0, 0.0, 1.0)
        else:
            t = np.where(srr_raw == 0.0, 0.0, 1.0)
        weight = t * t * (3.0 - 2.0 * t)  # smoothstep
        two_u = 2.0 * eta0 * ue / (effective_modulus * radius)
        moes_m = w / (effective_modulus * radius) / np.sqrt(two_u)
        moes_l = alpha * effective_modulus * two_u**0.25
        weight = np.where((moes_m > M_RANGE[1]) | (moes_l > L_RANGE[1]), 1.0, weight)
        srr = np.clip(srr_raw, -self.max_srr, self.max_srr)
        out = np.zeros((6, w.size))
        out[0] = out[1] = h_cf
        out[2] = math.nan
        used = [False]
        stand_in = None if self.admitted is None else self._stand_in(tab, used)
        for j in range(w.size):
            if weight[j] >= 1.0:
                continue
            wj, uj, sj = float(w[j]), float(ue[j]), float(srr[j])
            w_min = self._w_min(uj, radius, effective_modulus, eta0)
            numerical = wj >= w_min
            w_q = wj if numerical else w_min
            used[0] = False
            p = self._query(tab, w_q, uj, sj, T, stand_in)
            self.provisional += int(used[0])
            if p is None:
                continue
            h_q = h_cf[j] if numerical else float(moes_line_central(
                uj, eta0, alpha, w_q, 1.0, radius, effective_modulus=effective_modulus))
            phi = (1.0 - weight[j]) * p.central_film / h_q + weight[j]
            out[0, j] = phi * h_cf[j]
            out[1, j] = out[0, j] * p.minimum_film / p.central_film
            out[2, j] = abs(p.rolling_traction) if numerical else math.nan
            out[3, j] = p.max_temperature_rise
            out[4, j] = 1.0 if (numerical and weight[j] == 0.0) else 0.0
            out[5, j] = 1.0 - weight[j] if numerical else 0.0
        return TehlFilms(out[0], out[1], out[2], out[3], out[4].astype(bool), out[5])

    @property
    def admitted(self) -> set[tuple[Any, ...]] | None:
        """None: every query solves the nodes it needs. A set (see :func:`solve_roller_tehl`):
        only nodes of these cells ``(table key, node)`` are solved; any other unsolved node a
        query needs gets a stand-in value (:meth:`_stand_in`) and the query counts in
        :attr:`provisional`. Setting it starts a new pass: the stand-in values are fixed
        again from the nodes solved by then."""
        return self._admitted

    @admitted.setter
    def admitted(self, value: set[tuple[Any, ...]] | None) -> None:
        self._admitted = value
        self._frozen = {}
        self._stand_in_memo = {}

    def _stand_in(self, tab: FilmTable, used: list[bool]) -> Any:
        """``stand_in(node)`` for :meth:`FilmTable.__call__` in a pass of
        :func:`solve_roller_tehl`: None for a node that is solved or admitted (the table
        solves it), else the node's stand-in :class:`~thermobearing.ehl.cache.FilmPoint`
        (:meth:`_stand_in_point`; ``used[0]`` is set).

        Why node values and not a film for the whole contact: before, a contact whose cell
        had one unadmitted, unsolved corner got the closed-form film times the table's mean
        thermal reduction, every other contact the table's film. The film then jumped where
        a contact crossed into such a cell. D1842926, 13218 r/min, 8 kN after 24 kN with one
        table: the outer race's most loaded cell had its SRR 0 and +0.05 nodes solved (from
        24 kN) but not -0.05, and the outer film jumped by 22 % where the outer slide-to-roll
        ratio crossed 0, at the root (-5e-5): Newton, the bracketed and the slide solves all
        failed (residual 3e-4, energy gaps 0.025). With one value per node the film is the
        same multilinear interpolation everywhere, continuous across cells."""
        key = (tab.rx, tab.ep)
        admitted = self._admitted if self._admitted is not None else set()

        memo = self._stand_in_memo.setdefault(key, {})

        def stand_in(idx: tuple[int, ...]) -> Any:
            if (key, idx) in admitted:
                return None
            used[0] = True
            got = memo.get(idx)
            if got is None:
                got = memo[idx] = self._stand_in_point(tab, idx)
            return got

        return stand_in

    def _stand_in_scales(self, tab: FilmTable) -> tuple[float, float, float, float, float]:
        """(thermal reduction ``h_c / h_Moes``, ``h_min / h_c``, ``|F_R| / F_R,DH``, sign of
        the rolling traction, temperature rise [K]) of the stand-in values: the geometric
        means (the arithmetic mean of the rise) over the table's solved nodes, fixed for the
        pass at the first stand-in the table gives in it (so that every node keeps one value
        during a pass); (1, 1, 1, -1, 0) while it has none (the isothermal closed form; the
        thermal solver's rolling traction on surface 1 opposes the entrainment: negative).
        ``F_R,DH``: Dowson-Higginson's Poiseuille force per length and surface (paper 000
        eq. 35 halved, :func:`~thermobearing.skidding.roller_fluid.
        dowson_higginson_rolling_force`). Measured on D1842926's nodes (OIL_4109, 30 degC,
        44-56 m/s, 57-650 kN/m): reductions 0.12-0.24, rolling tractions 180-245 N/m."""
        key = (tab.rx, tab.ep)
        got = self._frozen.get(key)
        if got is not None:
            return got
        from ..film import moes_line_central
        from ..skidding.roller_fluid import dowson_higginson_rolling_force

        red, ratio, roll, rise, sign = [], [], [], [], 0.0
        for idx, p in tab.solved_nodes().items():
            w_n, u_n, _s, t_n = tab.node_point(idx)
            eta = float(self.lubricant.dynamic_viscosity(t_n))
            alpha = float(self.lubricant.pressure_viscosity_coefficient(t_n))
            red.append(p.central_film / float(moes_line_central(
                u_n, eta, alpha, w_n, 1.0, tab.rx, effective_modulus=tab.ep)))
            ratio.append(p.minimum_film / p.central_film)
            f_dh = 0.5 * float(dowson_higginson_rolling_force(u_n, eta, alpha, tab.ep, tab.rx))
            if p.rolling_traction != 0.0:
                roll.append(abs(p.rolling_traction) / f_dh)
            rise.append(p.max_temperature_rise)
            sign += p.rolling_traction

        def gmean(v: list[float]) -> float:
            return float(np.exp(np.mean(np.log(v)))) if v else 1.0

        got = (gmean(red), gmean(ratio), gmean(roll), 1.0 if sign > 0.0 else -1.0,
               float(np.mean(rise)) if rise else 0.0)
        self._frozen[key] = got
        return got

    def _stand_in_point(self, tab: FilmTable, idx: tuple[int, ...]) -> Any:
        """Stand-in :class:`~thermobearing.ehl.cache.FilmPoint` of an unsolved node: the
        isothermal closed form at the node (Moes central film, Dowson-Higginson rolling
        traction, Hertz pressure) times the pass's scales (:meth:`_stand_in_scales`). Its
        ``traction`` is the rolling traction (the Couette part is not estimated; the
        quasi-dynamics take the Hertz-zone shear from their traction law). Never the film of
        a state :func:`solve_roller_tehl` returns."""
        from ..film import moes_line_central
        from ..hertz import line_contact
        from ..skidding.roller_fluid import dowson_higginson_rolling_force
        from .cache import FilmPoint

        red, ratio, roll, sign, rise = self._stand_in_scales(tab)
        w_n, u_n, _s, t_n = tab.node_point(idx)
        eta = float(self.lubricant.dynamic_viscosity(t_n))
        alpha = float(self.lubricant.pressure_viscosity_coefficient(t_n))
        h_c = red * float(moes_line_central(u_n, eta, alpha, w_n, 1.0, tab.rx,
                                            effective_modulus=tab.ep))
        f_r = sign * roll * 0.5 * float(dowson_higginson_rolling_force(u_n, eta, alpha,
                                                                       tab.ep, tab.rx))
        p_h = float(line_contact(w_n, 1.0, tab.rx, tab.ep).max_pressure)
        return FilmPoint(h_c, ratio * h_c, p_h, f_r, f_r, rise)

    def state_cells(self, load_per_length: Any, entrainment_speed: Any, slide_to_roll: Any,
                    temperature: float, radius: float, effective_modulus: float
                    ) -> set[tuple[Any, ...]]:
        """Table nodes ``(table key, node)`` the film of these contacts is built from (the
        same queries as :meth:`films`), for both signs of each slide-to-roll ratio: near
        rolling the Newton polish crosses SRR = 0, and a stand-in film on the other side
        (a different film than the table's) stalled it (stand-in test, D1842926 24 kN)."""
        from .line import L_RANGE, M_RANGE

        T = float(temperature)
        tab = self.table(radius, effective_modulus, T)
        eta0 = float(self.lubricant.dynamic_viscosity(T))
        alpha = float(self.lubricant.pressure_viscosity_coefficient(T))
        out: set[tuple[Any, ...]] = set()
        for wj, uj, sj in zip(*(np.atleast_1d(np.asarray(v, dtype=float)) for v in
                                (load_per_length, entrainment_speed, slide_to_roll)),
                              strict=True):
            uj = max(float(uj), 1e-6)
            gross = abs(sj) >= 2.0 * self.max_srr if self.max_srr > 0.0 else sj != 0.0
            if wj <= 0.0 or gross:
                continue
            two_u = 2.0 * eta0 * uj / (effective_modulus * radius)
            if (wj / (effective_modulus * radius) / math.sqrt(two_u) > M_RANGE[1]
                    or alpha * effective_modulus * two_u**0.25 > L_RANGE[1]):
                continue
            w_q = max(float(wj), self._w_min(uj, radius, effective_modulus, eta0))
            s = min(abs(float(sj)), self.max_srr)
            for sgn in (s, -s):
                out.update(((tab.rx, tab.ep), c) for c in tab.corners(w_q, uj, sgn, T))
        return out

    # --------------------------------------------------- film_model protocol
    def __call__(self, entrainment_speed: Any, load_per_length: Any, radius: float,
                 eta0: float, alpha: float, effective_modulus: float) -> np.ndarray:
        """Central film h_c [m] (the ``film_model`` callable of the roller solver).

        Slide-to-roll ratio and inlet temperature come from the drag model's call
        (:func:`tehl_contact_forces`); called outside one, pure rolling at the temperature
        of ``eta0`` is assumed. ``alpha`` is not used (the table's solver takes the
        lubricant's own pressure-viscosity law).
        """
        w = np.atleast_1d(np.asarray(load_per_length, dtype=float))
        ctx = _CALL.get()
        if ctx is None:
            return self.films(w, entrainment_speed, np.zeros(w.shape),
                              self.temperature_of(float(eta0)), radius,
                              effective_modulus).central_film
        res = self.films(w, entrainment_speed, ctx["slide_to_roll"], ctx["temperature"],
                         radius, effective_modulus)
        ctx["result"] = res
        return res.central_film


def tehl_contact_forces(load: Any, length: float, radius: float, effective_modulus: float,
                        u_race: Any, u_roller: Any, *, eta0: float, alpha: float,
                        film: Any, traction_law: Any, temperature: float,
                        rolling_force: str = "regime_min", oil_layer: float | None = None,
                        film_pressure: str = "regime_min"):
    """Roller-race fluid forces with the tabulated thermal-EHL film (module docstring).

    Signature of :func:`thermobearing.skidding.roller_fluid.closed_form_contact_forces`;
    ``film`` must be the roller solver's wrapper of a :class:`TehlFilmModel`
    (``solve_roller(..., film_model=TehlFilmModel(...), drag_model="numerical_tehl")``).
    ``film_pressure``: pressure under which the Hertz-zone oil is sheared, ``"regime_min"``
    (default: the smaller of the Hertz and the rigid-isoviscous peak, module docstring) or
    ``"hertz"`` (p_H at every load, the earlier model); the Hertz-zone integral is
    then :func:`thermobearing.skidding.roller_maxwell.maxwell_contact_forces` with a viscous
    film (the traction law point by point), the code path of the isothermal option.
    """
    from ..skidding.roller_fluid import LineContactForces, closed_form_contact_forces
    from ..skidding.roller_pressure import FILM_PRESSURE_MODELS

    if film_pressure not in FILM_PRESSURE_MODELS:
        raise InputError("film_pressure", film_pressure, FILM_PRESSURE_MODELS)

    q, ur, uro = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, dtype=float))
                                       for v in (load, u_race, u_roller)))
    idx = np.nonzero(q > 0.0)[0]
    usum = ur + uro
    sign = np.where(usum >= 0.0, 1.0, -1.0)
    z = q.shape
    if idx.size == 0:
        zero = np.zeros(z)
        return LineContactForces(zero, zero.copy(), zero.copy(), zero.copy(), sign,
                                 np.full(z, np.inf), zero.copy(), zero.copy(), zero.copy())
    ue = np.maximum(0.5 * np.abs(usum[idx]), 1e-6)
    srr = (ur[idx] - uro[idx]) / ue
    ctx: dict[str, Any] = {"slide_to_roll": srr, "temperature": float(temperature)}
    token = _CALL.set(ctx)
    try:
        h = np.asarray(film(ue, q[idx] / length), dtype=float)
    finally:
        _CALL.reset(token)
    res: TehlFilms | None = ctx.get("result")
    if res is None:
        raise InputError("film_model", film,
                         "a thermobearing.ehl.coupling.TehlFilmModel with "
                         "drag_model='numerical_tehl'")
    base = closed_form_contact_forces
    if film_pressure != "hertz":
        from ..skidding.roller_maxwell import maxwell_contact_forces

        base = maxwell_contact_forces(closed_form_contact_forces, None, film_pressure)
    sub = base(
        q[idx], length, radius, effective_modulus, ur[idx], uro[idx], eta0=eta0, alpha=alpha,
        film=lambda _ue, _w: h, traction_law=traction_law, temperature=temperature,
        rolling_force=rolling_force, oil_layer=oil_layer)
    # the table's rolling traction blended into the closed form's by the sliding weight
    # (it switched at |SRR| = max_slide_to_roll before: a jump in the roller balances)
    share = res.table_share
    table_poise = np.where(share > 0.0, res.rolling_traction, 0.0) * length
    poise = share * table_poise + (1.0 - share) * sub.poiseuille
    roll = share * 2.0 * table_poise + (1.0 - share) * sub.rolling_force

    def full(a: np.ndarray, fill: float) -> np.ndarray:
        o = np.full(z, fill)
        o[idx] = a
        return o

    return LineContactForces(
        traction=full(sub.traction, 0.0), dtraction_dslide=full(sub.dtraction_dslide, 0.0),
        poiseuille=full(poise, 0.0), rolling_force=full(roll, 0.0), entrainment_sign=sign,
        film_thickness=full(sub.film_thickness, np.inf), half_width=full(sub.half_width, 0.0),
        max_pressure=full(sub.max_pressure, 0.0),
        hertz_traction=full(sub.hertz_traction, 0.0))


def roller_film_model(bearing: Any, lubricant: Any, **options: Any) -> TehlFilmModel:
    """:class:`TehlFilmModel` of a cylindrical roller bearing: race and roller materials
    from the bearing (``ring_material``, ``roller_material``); ``options`` as the class."""
    if getattr(bearing, "kind", None) != "cylindrical":
        raise InputError("bearing", getattr(bearing, "name", bearing),
                         "a cylindrical roller bearing (numerical_tehl is a line-contact model)")
    return TehlFilmModel(lubricant, bearing.ring_material, bearing.roller_material, **options)


def solve_roller_tehl(bearing: Any, lubricant: Any, speed: float, radial_load: float,
                      axial_load: float, temperature: float, *,
                      film_model: TehlFilmModel | None = None, max_passes: int = 6,
                      **options: Any) -> Any:
    """Roller skidding solve with the thermal-EHL film, solving table nodes only near the
    converged state (:func:`thermobearing.skidding.solve` with ``drag_model="numerical_tehl"``).

    Why: the plain solve fills the table at every near-rolling contact state its Newton
    iterates pass through. D1842926, OIL_4109 at 30 degC, 13218 r/min, 24 kN, clearance
    40 um: the cold starts (cage at 0.8 and 0.4 of the epicyclic speed, 2 iterations each,
    both abandoned) asked for 246 of the 342 nodes the solve requested (outer-race
    entrainment 11-55 m/s, loads 25-430 kN/m), at 5-20 s CPU each.

    Passes: the first solve admits no node (unsolved nodes take stand-in values: the
    closed form times the table's mean thermal corrections, :meth:`TehlFilmModel._stand_in`,
    so that a table shared with earlier operating points gives a continuous film); each
    next pass
    admits the nodes of the previous converged state's loaded contacts
    (:meth:`TehlFilmModel.state_cells`) and re-solves from that state. It stops when the
    converged state's nodes were all admitted: every film of the returned state is then
    the table's (same accuracy as the plain solve); else after ``max_passes`` a
    ConvergenceError. ``options`` go to :func:`thermobearing.skidding.solve`. The film
    model keeps its nodes (pass it again for the next operating point).
    """
    from ..skidding import solve

    if isinstance(max_passes, bool) or not isinstance(max_passes, int) or max_passes < 2:
        raise InputError("max_passes", max_passes, "a whole number >= 2")
    fm = film_model if film_model is not None else roller_film_model(bearing, lubricant)
    saved = fm.admitted
    fm.admitted = set()
    missing: set[tuple[Any, ...]] = set()
    try:
        res = None
        for _ in range(max_passes):
            opts = dict(options)
            if res is not None:
                opts["guess"] = res
            res = solve(bearing, lubricant, speed, radial_load, axial_load, temperature,
                        drag_model="numerical_tehl", film_model=fm, **opts)
            missing = _result_cells(fm, res) - fm.admitted
            if not missing and fm.admitted:
                return res
            fm.admitted |= missing
            if not fm.admitted:  # no contact of the state needs the table (all sliding)
                return res
    finally:
        fm.admitted = saved
    raise ConvergenceError(
        "numerical_tehl", float(len(missing)),
        f"the converged state still needed {len(missing)} table nodes that its solve had "
        f"not admitted after {max_passes} passes", {"max_passes": max_passes})


def _result_cells(fm: TehlFilmModel, res: Any) -> set[tuple[Any, ...]]:
    """Table nodes of a roller skidding result's loaded contacts (both races)."""
    ex = res.extras
    length = float(ex["contact_length"])
    cells: set[tuple[Any, ...]] = set()
    for radius, q, ue, v in ((ex["radius_inner"], res.inner_load, res.inner_entrainment_speed,
                              res.inner_sliding_speed),
                             (ex["radius_outer"], res.outer_load, res.outer_entrainment_speed,
                              res.outer_sliding_speed)):
        keys = [k for k in fm.tables if math.isclose(k[0], float(radius), rel_tol=1e-12)]
        q, ue, v = (np.atleast_1d(np.asarray(a, dtype=float)) for a in (q, ue, v))
        ue_abs = np.maximum(np.abs(ue), 1e-6)
        for key in keys:
            cells |= fm.state_cells(q / length, ue_abs, v / ue_abs, float(res.temperature),
                                    key[0], key[1])
    return cells


def _register() -> None:
    """Register ``"numerical_tehl"`` in the roller drag family (skidding.roller_fluid) and
    its driver, :func:`solve_roller_tehl`, in the table-film drivers of the kinematics
    (:data:`thermobearing.kinematic_models.TABLE_FILM_DRIVERS`)."""
    try:
        from ..skidding.roller_fluid import ROLLER_DRAG
    except ImportError:  # pragma: no cover - the skidding package is part of the product
        return
    if "numerical_tehl" in ROLLER_DRAG:
        return
    from ..kinematic_models import TABLE_FILM_DRIVERS

    @TABLE_FILM_DRIVERS.register(
        "numerical_tehl",
        references=["shi2015_tehl_roller", "li2018_nu214_skidding"],
        summary="Roller skidding solve that solves thermal-EHL table nodes only around the "
                "converged state (solve_roller_tehl).",
    )
    def numerical_tehl_driver(bearing: Any, lubricant: Any, speed: float,
                              radial_load: float, axial_load: float, temperature: float,
                              **options: Any) -> Any:
        """:func:`solve_roller_tehl`, looked up when called (the plain solve asks for the
        table nodes of every Newton iterate: 342 against 48 on D1842926 at 24 kN)."""
        return solve_roller_tehl(bearing, lubricant, speed, radial_load, axial_load,
                                 temperature, **options)

    @ROLLER_DRAG.register(
        "numerical_tehl",
        references=["shi2015_tehl_roller", "yang_wen1990", "li2018_nu214_skidding"],
        parameters={},
        validity="cylindrical roller bearings; film from a TehlFilmModel table "
                 "(Newtonian thermal line-contact EHL, M >= min_moes_m, |SRR| < 2); "
                 "Hertz-zone shear by the given traction law",
    )
    def numerical_tehl_drag_model():
        """Roller-race forces on the tabulated thermal-EHL film (paper 001 Fig. 3 coupling)."""
        return tehl_contact_forces


_register()
