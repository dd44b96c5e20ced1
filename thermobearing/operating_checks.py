"""Validity checks of a solved operating state: cage skidding, contact stress, film parameter.

A run records, per bearing and schedule step, the worst of three quantities of every
kinematic state it solved, and its report lists the steps where one of them leaves the
range in which the bearing (and the models) run as intended:

- **Cage skidding / over-skidding.** s = CSR / CSR_th - 1 [-], the cage speed against the
  epicyclic (pure-rolling) cage speed at the quasi-static contact angles. Beyond
  ``SKID_LIMIT`` (5 %) the elements slide grossly on the raceways (skidding, s < 0: the
  light-load, high-speed damage mode of paper 000; over-skidding, s > 0: paper 002's
  large angular-contact bearings). The 5 % threshold is this product's choice, not a
  standard: a normally loaded bearing departs from the epicyclic speed by the rolling-radius
  and gyroscopic effects only (< 1-2 %, paper 002 Fig. 10 at 36 kN and above).
- **Contact stress.** The largest Hertz pressure p0 [Pa] of the loaded contacts against the
  stress at which ISO 76 (static load ratings) sets the basic static load rating: 4200 MPa
  for ball bearings (4600 MPa self-aligning), 4000 MPa for roller bearings, the stress that
  leaves a permanent deformation of about 1e-4 of the element diameter (ISO 76:2006
  Rolling bearings -- Static load ratings; the values are recalled, not checked against
  the standard's text).
- **Film parameter.** Lambda = h / sigma [-] with the contact's film thickness h from the
  scene's film model (central film unless a minimum-film model is named) and the composite
  RMS roughness sigma = (Rq_race^2 + Rq_element^2)^(1/2) of the bearing
  (``raceway_roughness``, ``element_roughness``; :func:`thermobearing.film.film_parameter`).
  Lambda < 1 means boundary lubrication, where the EHL film and traction models that
  computed the losses do not hold (Hamrock, Schmid & Jacobson 2004, ch. 3, the bands of
  :func:`thermobearing.film.film_parameter`).

Units SI. Pure functions; :class:`CheckLog` accumulates one bearing's steps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

#: |CSR / CSR_th - 1| above which a step is reported as skidding / over-skidding [-]
SKID_LIMIT = 0.05
#: ISO 76 stress of the basic static load rating [Pa], by bearing family
ISO76_STRESS = {"ball": 4.2e9, "self_aligning_ball": 4.6e9, "roller": 4.0e9}
#: film parameter below which the contacts run in boundary lubrication [-]
LAMBDA_BOUNDARY = 1.0


@dataclass(frozen=True)
class StateCheck:
    """The checked quantities of one kinematic state.

    slip : CSR / CSR_th - 1 [-] (negative: skidding). csr, csr_th : the two ratios [-].
    max_pressure : largest Hertz pressure of the loaded contacts [Pa]; stress_limit : ISO 76
    stress of the bearing's family [Pa]. film_parameter : smallest Lambda of the loaded
    contacts [-], None when the bearing gives no roughness or the state no film; race : the
    raceway where it occurs.
    """

    slip: float
    csr: float
    csr_th: float
    max_pressure: float
    stress_limit: float
    film_parameter: float | None
    race: str = ""


def composite_roughness(bearing: Any) -> float | None:
    """sigma = (Rq_race^2 + Rq_element^2)^(1/2) [m], or None when the bearing gives none."""
    r = getattr(bearing, "raceway_roughness", None)
    e = getattr(bearing, "element_roughness", None)
    if r is None or e is None:
        return None
    return math.hypot(r, e)


def stress_limit(bearing: Any) -> float:
    """ISO 76 static-rating contact stress [Pa] of the bearing's family (module docstring)."""
    if hasattr(bearing, "ball_diameter"):
        kind = "self_aligning_ball" if getattr(bearing, "kind", "") == "self_aligning" \
            else "ball"
        return ISO76_STRESS[kind]
    return ISO76_STRESS["roller"]


def check_state(bearing: Any, kin: Any) -> StateCheck:
    """The checked quantities of a solved state (``kinematic_models.KinematicsResult``)."""
    sigma = composite_roughness(bearing)
    p_max = 0.0
    lam_min, race_min = math.inf, ""
    for cs in kin.state.contacts:
        q = np.atleast_1d(np.asarray(cs.normal_load, dtype=float))
        loaded = q > 0.0
        if not loaded.any():
            continue
        p = np.broadcast_to(np.asarray(cs.max_pressure, dtype=float), q.shape)[loaded]
        p_max = max(p_max, float(np.max(p)))
        if sigma is not None and cs.film_thickness is not None:
            h = np.broadcast_to(np.asarray(cs.film_thickness, dtype=float), q.shape)[loaded]
            lam = float(np.min(h)) / sigma
            if lam < lam_min:
                lam_min, race_min = lam, cs.race
    return StateCheck(
        slip=float(kin.over_skid), csr=float(kin.cage_speed_ratio),
        csr_th=float(kin.theoretical_cage_speed_ratio), max_pressure=p_max,
        stress_limit=stress_limit(bearing),
        film_parameter=None if math.isinf(lam_min) else lam_min, race=race_min)


@dataclass
class CheckLog:
    """The worst checked quantities of one bearing per schedule step (a step's kinematics
    may be re-solved as the temperatures move; the worst state counts)."""

    bearing: str
    roughness: float | None
    steps: dict[int, list[StateCheck]] = field(default_factory=dict)

    def record(self, step: int, check: StateCheck) -> None:
        self.steps.setdefault(step, []).append(check)

    def summary(self) -> list[str]:
        """One line per check that some step fails (empty when every step passes), plus a
        line saying the film parameter was not checked when the bearing gives no
        roughness."""
        lines: list[str] = []
        skid = {i: min(c, key=lambda c: c.slip) for i, c in self.steps.items()}
        over = {i: max(c, key=lambda c: c.slip) for i, c in self.steps.items()}
        for name, worst, sign in (("skidding (cage slower than epicyclic)", skid, -1.0),
                                  ("over-skidding (cage faster than epicyclic)", over, 1.0)):
            flagged = _flag(worst, lambda c, s=sign: s * c.slip > SKID_LIMIT,
                            lambda c, s=sign: s * c.slip)
            if flagged:
                where, i, c = flagged
                lines.append(
                    f"{self.bearing}: cage {name} by more than {SKID_LIMIT:.0%} {where}; "
                    f"largest {100 * c.slip:+.1f} % at step {i} (CSR {c.csr:.4f} against "
                    f"{c.csr_th:.4f}): gross sliding of the elements (smearing risk)")
        stress = {i: max(c, key=lambda c: c.max_pressure) for i, c in self.steps.items()}
        flagged = _flag(stress, lambda c: c.max_pressure > c.stress_limit,
                        lambda c: c.max_pressure)
        if flagged:
            where, i, c = flagged
            lines.append(
                f"{self.bearing}: contact pressure above the ISO 76 static-rating stress "
                f"{c.stress_limit / 1e6:.0f} MPa {where}; largest "
                f"{c.max_pressure / 1e6:.0f} MPa at step {i}: permanent raceway deformation")
        if self.roughness is None:
            lines.append(f"{self.bearing}: film parameter Lambda not checked: the bearing "
                         "gives no raceway_roughness / element_roughness")
            return lines
        films = {i: min((c for c in cs if c.film_parameter is not None),
                        key=lambda c: c.film_parameter, default=None)
                 for i, cs in self.steps.items()}
        flagged = _flag(films, lambda c: c.film_parameter < LAMBDA_BOUNDARY,
                        lambda c: -c.film_parameter)
        if flagged:
            where, i, c = flagged
            lines.append(
                f"{self.bearing}: film parameter Lambda < {LAMBDA_BOUNDARY:g} (boundary "
                f"lubrication) {where}; smallest {c.film_parameter:.2f} at step {i} "
                f"({c.race} contact; film of the scene's film model over the composite "
                f"roughness {self.roughness * 1e6:.3g} um): the EHL film and traction "
                "models do not hold there")
        return lines


def _flag(worst: dict[int, StateCheck | None], failing: Any, score: Any
          ) -> tuple[str, int, StateCheck] | None:
    """For the per-step worst states: ("at k of n steps (ranges)", the failing step of the
    largest ``score``, its state), or None when no step fails."""
    bad = sorted(i for i, c in worst.items() if c is not None and failing(c))
    if not bad:
        return None
    i = max(bad, key=lambda k: score(worst[k]))
    return f"at {len(bad)} of {len(worst)} steps ({_ranges(bad)})", i, worst[i]


def _ranges(steps: list[int]) -> str:
    """``[0, 1, 2, 5]`` -> ``"steps 0-2, 5"``."""
    parts: list[str] = []
    start = prev = steps[0]
    for s in steps[1:] + [None]:
        if s is not None and s == prev + 1:
            prev = s
            continue
        parts.append(f"{start}" if start == prev else f"{start}-{prev}")
        if s is not None:
            start = prev = s
    return ("step " if len(steps) == 1 else "steps ") + ", ".join(parts)
