"""Result of the cylindrical-roller skidding solve and the quantities derived from it.

One job: the :class:`RollerSkiddingResult` dataclass of the paper 000 Z + 1 equations (Li,
Chen, Zhang, Wang 2018, seed ``000_3b5ca6eed61dd596.txt`` [li2018_nu214_skidding]) with its
derived shaft torque, power balance and the :class:`thermobearing.state.KinematicState` the
heat sources consume. Solved by :func:`thermobearing.skidding.roller.solve_model`; with the
oil drag of :mod:`thermobearing.skidding.roller_drag` (scenes) the balance, the shaft torque
and the booked heat contain the churning and cage-guide drags of paper 002 too.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .roller_fluid import LineContactForces


@dataclass(frozen=True)
class RollerSkiddingResult:
    """Quasi-static skidding state of a cylindrical roller bearing (SI).

    Attributes
    ----------
    inner_speed : omega [rad/s].  cage_speed : omega_c [rad/s].
    cage_speed_ratio : omega_c / omega [-].
    theoretical_cage_speed_ratio : (1 - D/d_m)/2 (paper 000 eq. 40) [-].
    slip : cage slip fraction s_f = 1 - CSR / CSR_th (paper 000 eq. 39) [-].
    roller_speed : (Z,) roller spin omega_r about its own axis [rad/s] (positive = rolling
        sense, the sense that pure rolling on the inner race gives).
    azimuth : (Z,) roller azimuths [rad].
    inner_load, outer_load : (Z,) [N].
    inner_sliding_speed, outer_sliding_speed : (Z,) V = u_race - u_roller [m/s].
    inner_entrainment_speed, outer_entrainment_speed : (Z,) (u_race + u_roller)/2 [m/s].
    inner, outer : LineContactForces of the two contacts.
    pocket_normal_force : (Z,) F_d [N] (positive: the roller pushes the cage forward).
    pocket_friction : (Z,) f_d [N].
    converged : bool.  residual_norm : scaled residual norm [-].  iterations : Newton steps taken
        (every load-distribution pass and start).
    residual : (Z+1,) force residuals [N] at the solution.
    temperature [K], eta0 [Pa s] used.
    extras : ``method`` ("newton", "newton_round_off", "slides" or "bracketed"), ``start``
        (the start whose Newton converged: "warm", "cold_0.8", "cold_0.4", "pure_rolling",
        "cold_0.8_lag" (``roller.COLD_LAG``), "best_iterate", or "bracketed" / "slides"),
        ``attempts`` (Newton attempts made),
        ``round_off_floor`` [-]: for a bracketed or round-off state the scaled residual norm
        that one-ulp changes of the speeds make there (0 for Newton within ``tol``;
        "newton_round_off": a stalled Newton iterate whose every equation is within 4 times
        its own one-ulp change, see :func:`~thermobearing.skidding.roller.solve_model`).
        Heavy loads near pure rolling (NU214 from ~60 kN) cannot meet ``tol`` in
        double precision: such a state is converged when ``residual_norm`` <= 4 x the floor
        (measured at 1000 r/min, 40 degC: 100 kN -> norm 3.6e-6; 200 kN -> 3.3e-2, the
        tractions change by kN per ulp of the cage speed there), and ``residual_norm`` says
        how far it is from ``tol``. Such a state is accepted only when
        ``shaft_torque * inner_speed`` equals ``power_loss["total"]`` to 1e-6 relative; one
        that does not (cold viscous oil under heavy load: hundreds of N of traction within
        one ulp of a sliding speed, the tractions of the stalled state balancing nothing) is
        solved again with the sliding speeds as unknowns (method "slides",
        :mod:`~thermobearing.skidding.roller_slides`: ``round_off_floor`` 0, the residual
        within ``tol``, the slides resolved below the ulp of the surface speeds).
        ``round_off_equations``: the indices of the equations
        (0..Z-1 the roller moment balances, Z the cage) whose residual is beyond ``tol`` of
        the force scale (empty within ``tol``), and ``residual_note``: what the norm means,
        in words. At such a state the norm is the step the equations make between
        neighbouring floats, not a distance from the root: a catalogue NU 206 at 13 kN,
        20 degC, ISO VG 68 (2000 and 30000 r/min) ends at a norm of 0.10-0.11 of its 4.7 kN
        roller load: its two most loaded rollers roll on the inner race at a slide of one
        ulp of their surface speed (4e-16 m/s), where the saturated traction changes by
        116-480 N per ulp of a speed, and their moment balances (109-250 N) and the cage
        equation (413 N) are within that step; the state is the bracketed solve's to
        1.3e-15 (CSR and every roller speed, benchmarks/bm_roller_cold.py).
        ``drag``: the oil drag the solve balanced (:attr:`drag`; None without one),
        ``cage_drag_torque`` [N m] (the model's constant cage drag), ``pitch_diameter`` [m],
        and the geometry the derived quantities use.
    """

    inner_speed: float
    cage_speed: float
    cage_speed_ratio: float
    theoretical_cage_speed_ratio: float
    slip: float
    roller_speed: np.ndarray
    azimuth: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    inner_sliding_speed: np.ndarray
    outer_sliding_speed: np.ndarray
    inner_entrainment_speed: np.ndarray
    outer_entrainment_speed: np.ndarray
    inner: LineContactForces
    outer: LineContactForces
    pocket_normal_force: np.ndarray
    pocket_friction: np.ndarray
    converged: bool
    residual_norm: float
    iterations: int
    residual: np.ndarray
    temperature: float
    eta0: float
    extras: dict[str, Any] = field(default_factory=dict)

    @property
    def cage_speed_rpm(self) -> float:
        """Cage speed [r/min] (for reports)."""
        return self.cage_speed * 30.0 / math.pi

    @property
    def element_speeds(self) -> np.ndarray:
        """Alias of ``roller_speed`` (the common skidding-result name)."""
        return self.roller_speed

    @property
    def drag(self) -> dict[str, Any] | None:
        """The oil drag the solve balanced (``extras["drag"]``,
        :meth:`thermobearing.skidding.roller_drag.RollerDrag.state`): ``element_force`` on
        each roller along its orbit [N], ``cage_churning_moment`` and ``cage_guide_moment``
        on the cage, ``inner_ring_moment`` on the inner ring [N m], the oil fractions and
        c_d; None without drag (paper 000's direct solve)."""
        return self.extras.get("drag")

    @property
    def shaft_torque(self) -> float:
        """Torque the shaft delivers to the inner ring [N m].

        T = (d_m - D)/2 * sum_j (S_ij + Q_xij): minus the tangential fluid force on the inner
        raceway (shear plus pressure), at the raceway radius of paper 000 eq. 12; with the
        oil drag (:attr:`drag`) also minus the inner ring's churning moment (paper 002
        eq. 17) and, for an inner-ring-guided cage, the land moment the ring gives the cage
        (eq. 5).
        """
        r_i = float(self.extras["raceway_radius_inner"])
        torque = r_i * float(np.sum(self.inner.race_shear_force))
        drag = self.drag
        if drag:
            torque -= float(drag["inner_ring_moment"])
            if drag["guidance"] == "inner_ring":
                torque += float(drag["cage_guide_moment"])
        return torque

    @property
    def power_loss(self) -> dict[str, float]:
        """Power dissipated by mechanism [W] (frame independent, from relative speeds).

        At a raceway contact the film takes ``C V + Q_x u_e`` (Couette force times the sliding
        V = u_race - u_roller, plus the rolling resistance Q_x times the entrainment speed
        u_e = (u_race + u_roller)/2, which is the Poiseuille shear Q_x/2 on each surface);
        in the pocket film ``f_d omega_r D/2``. Keys:
        ``inner_shear``, ``inner_rolling``, ``outer_shear``, ``outer_rolling``, ``pocket``,
        with the oil drag (:attr:`drag`) also ``element_drag`` (sum_j |F_j| omega_c d_m/2,
        paper 002 eq. 10), ``cage_churning`` (|M_c omega_c|, eq. 15), ``cage_guide``
        (|M_g (omega_g - omega_c)|, eq. 5) and ``inner_ring_churning`` (|M_i omega|,
        eq. 17), with a constant ``cage_drag_torque`` T_c also ``cage_drag`` (T_c omega_c),
        and ``total``. In a converged state ``total`` equals ``shaft_torque * inner_speed``
        (energy balance; it follows from the roller moment and cage equations).
        """
        d = float(self.extras["roller_diameter"])
        out = {}
        for race, f, v, ue in (
                ("inner", self.inner, self.inner_sliding_speed, self.inner_entrainment_speed),
                ("outer", self.outer, self.outer_sliding_speed, self.outer_entrainment_speed)):
            out[f"{race}_shear"] = float(np.sum(f.traction * v))
            out[f"{race}_rolling"] = float(np.sum(f.rolling_force * np.abs(ue)))
        out["pocket"] = float(np.sum(self.pocket_friction * np.abs(self.roller_speed) * 0.5 * d))
        out.update(self._drag_power())
        t_c = float(self.extras.get("cage_drag_torque", 0.0))
        if t_c != 0.0:
            out["cage_drag"] = t_c * self.cage_speed
        out["total"] = sum(out.values())
        return out

    def _drag_power(self) -> dict[str, float]:
        """Power of the oil drag the solve balanced [W] (empty without drag): the products
        the ``churning_*`` and ``cage_guide`` heat sources book from the kinematic state."""
        drag = self.drag
        if not drag:
            return {}
        wc, w = self.cage_speed, self.inner_speed
        u = 0.5 * float(self.extras["pitch_diameter"]) * wc
        n = self.roller_speed.size
        omega_g = w if drag["guidance"] == "inner_ring" else 0.0
        return {"element_drag": n * abs(float(drag["element_force"]) * u),
                "cage_churning": abs(float(drag["cage_churning_moment"]) * wc),
                "cage_guide": abs(float(drag["cage_guide_moment"]) * (omega_g - wc)),
                "inner_ring_churning": abs(float(drag["inner_ring_moment"]) * w)}

    @property
    def kinematic_state(self) -> Any:
        """The :class:`thermobearing.state.KinematicState` the heat sources consume.

        Line contacts (``semi_major`` = l/2, ``semi_minor`` = Hertz b); sliding speeds in the
        state's convention (element minus race = -V here); pocket force as a magnitude;
        film thickness 0 where a contact carries no load; origin "skidding".

        The state carries the forces this solve balanced, so that the heat sources book
        exactly them (every watt a force times a sliding speed, and the booked heat of
        ``raceway_traction`` + ``ehl_rolling_resistance`` + ``pocket_friction`` equals
        ``shaft_torque * inner_speed`` to round-off, see :meth:`booked_power`):

        * each contact set's ``traction`` is the solver's Couette force on the roller
          (paper 000 eq. 5 second term, eqs. 33-34: the Hertz zone by the traction law AND
          the Newtonian inlet/outlet shear, plus a clearance film where one is modelled) as a
          :class:`~thermobearing.state.PrecomputedTraction` marked
          :class:`~thermobearing.heat_sources.raceway.SolverContactForces`; its heat is
          C V. Re-integrating the traction law over the Hertz zone (what the source does for a
          state without these forces) leaves the inlet/outlet shear out: 16.8 + 37.5 W of
          272 W at 5000 r/min, 200 N and 27.5 W of 514 W at 3000 r/min, 8 kN (NU 214,
          ISO VG 46 at 320 K);
        * ``extras["raceway_rolling_force"]``: the rolling force Q_x of each raceway
          (paper 000 eq. 35 or its rigid-isoviscous / starved / clearance-film forms, as the
          solve used them, at the inlet viscosity of the solver's ``thermal_reduction``,
          whose name is ``extras["raceway_rolling_thermal_reduction"]``), race name -> (Z,)
          [N];
        * ``extras["pocket_friction"]``: the pocket-film friction f_d (paper 000 eqs. 37-38)
          [N], which the pocket source books as f_d |omega_r| D/2 instead of a boundary
          friction coefficient times F_d;
        * ``extras["solver_drag"]`` (a solve with oil drag, :attr:`drag`): the roller drag
          force, the cage churning and guide-land moments and the inner ring's churning
          moment the balance contains, which ``churning_elements``, ``churning_cage``,
          ``cage_guide`` and ``churning_inner_ring`` book (their heat is then the
          ``element_drag``, ``cage_churning``, ``cage_guide`` and ``inner_ring_churning``
          of :attr:`power_loss`).
        """
        from ..heat_sources.raceway import SolverContactForces
        from ..state import ContactSet, KinematicState, PrecomputedTraction

        length = float(self.extras["contact_length"])
        sets = []
        rolling = {}
        marker = SolverContactForces("roller_skidding")
        for race, f, v, ue, q, rx in (
                ("inner", self.inner, self.inner_sliding_speed, self.inner_entrainment_speed,
                 self.inner_load, self.extras["radius_inner"]),
                ("outer", self.outer, self.outer_sliding_speed, self.outer_entrainment_speed,
                 self.outer_load, self.extras["radius_outer"])):
            loaded = q > 0
            traction = PrecomputedTraction(law=marker, n_major=0, n_minor=0,
                                           result=solver_contact_traction(f, v))
            sets.append(ContactSet(
                race=race, kind="line", normal_load=q,
                semi_major=np.where(loaded, 0.5 * length, 0.0), semi_minor=f.half_width,
                max_pressure=f.max_pressure, entrainment_speed=ue, sliding_speed=-v,
                film_thickness=np.where(loaded, f.film_thickness, 0.0),
                temperature=np.full(q.shape, self.temperature), reduced_radius_x=rx,
                traction=traction))
            rolling[race] = np.asarray(f.rolling_force, float).copy()
        extras = {"pocket_friction": self.pocket_friction, "slip": self.slip,
                  "raceway_rolling_force": rolling,
                  "raceway_rolling_thermal_reduction": str(
                      self.extras.get("thermal_reduction", "none"))}
        drag = self.drag
        element_drag = None
        if drag:
            extras["solver_drag"] = dict(drag)
            element_drag = np.full(self.roller_speed.shape, abs(float(drag["element_force"])))
        return KinematicState(
            inner_speed=self.inner_speed, outer_speed=0.0, cage_speed=self.cage_speed,
            orbital_speed=np.full(self.roller_speed.shape, self.cage_speed),
            element_spin=self.roller_speed, contacts=tuple(sets), attitude_angle=0.0,
            azimuth=self.azimuth, pocket_normal_force=np.abs(self.pocket_normal_force),
            element_drag_force=element_drag, origin="skidding", extras=extras)

    def booked_power(self) -> dict[str, float]:
        """The solver's dissipation by heat source [W]: the heat-source bookkeeping of
        :attr:`power_loss` (same products, grouped as the sources book them).

        ``raceway_traction`` = sum C V over both raceways (paper 000 eq. 5 Couette term),
        ``ehl_rolling_resistance`` = sum Q_x |u_e| (eq. 5 Poiseuille term, Q_x of eq. 35),
        ``pocket_friction`` = sum f_d |omega_r| D/2 (eqs. 37-38), and with the oil drag
        (:attr:`drag`: every scene, ``skidding.solve`` with an oil supply)
        ``churning_elements`` = sum_j |F_j| omega_c d_m/2 (paper 002 eq. 10 on each roller),
        ``churning_cage`` = |M_c omega_c| (eqs. 12-15), ``cage_guide`` =
        |M_g (omega_g - omega_c)| (eq. 5, centred cage; 0 for a rolling-element-guided cage)
        and ``churning_inner_ring`` = |M_i omega| (eq. 17); ``total``. In a converged state
        ``total`` = ``shaft_torque * inner_speed``: the roller moment balances (eqs. 28/31),
        the roller orbital balances with the drag (eqs. 21/24) and the cage equation (eq. 32
        with the pocket-friction term and the oil moments on the cage) make the sum
        telescope to the inner-race torque, to which the shaft torque adds the inner ring's
        churning moment and an inner land's moment; whirl inertia, eqs. 3-4, does no net
        work for evenly spaced rollers: sum_j a_t,j = 0. The scene's sources book these
        products from the kinematic state (extras ``solver_drag``), so their total equals
        the shaft power. Not balanced: rib friction (the source ``rib_friction`` books a
        drag this shaft torque does not contain) and a constant ``cage_drag_torque``
        (0 in scenes; its power is ``power_loss["cage_drag"]``, no source books it).
        Without the oil drag (paper 000's direct ``solve_roller``) only the first three.
        """
        loss = self.power_loss
        out = {"raceway_traction": loss["inner_shear"] + loss["outer_shear"],
               "ehl_rolling_resistance": loss["inner_rolling"] + loss["outer_rolling"],
               "pocket_friction": loss["pocket"]}
        if self.drag:
            out.update({"churning_elements": loss["element_drag"],
                        "churning_cage": loss["cage_churning"],
                        "cage_guide": loss["cage_guide"],
                        "churning_inner_ring": loss["inner_ring_churning"]})
        out["total"] = sum(out.values())
        return out


def solver_contact_traction(forces: LineContactForces, sliding: np.ndarray) -> Any:
    """The solver's Couette force of one raceway as a ``contact_traction.ContactTraction``.

    ``forces.traction`` C is the shear force on the roller along the race velocity, sign of
    V = u_race - u_roller (paper 000 eq. 5 second term: Hertz zone by the traction law,
    Newtonian inlet and outlet, clearance film); in the contact frame of
    :mod:`thermobearing.state` (element minus race = -V) it is the rolling-direction force
    F_y = C on the element, and its power -F_y (-V) = C V [W] is the heat. No transverse
    force or moments (straight rollers). ``sliding``: V (Z,) [m/s].
    """
    from ..contact_traction import ContactTraction

    c = np.asarray(forces.traction, float)
    zero = np.zeros_like(c)
    return ContactTraction(transverse_force=zero, rolling_force=c.copy(),
                           moment_transverse=zero, moment_rolling=zero, moment_normal=zero,
                           heat=c * np.asarray(sliding, float))
