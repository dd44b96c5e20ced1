"""Validity checks of a solved operating state: cage skidding, contact stress, film parameter.

A run records, per bearing and schedule step, the worst of three quantities of every
kinematic state it solved (a film-only run: of its film table's rows, race control, no
skidding), and its report lists the steps where one of them leaves the range in which the
bearing (and the models) run as intended:

- **Cage skidding / over-skidding.** s = CSR / CSR_roll - 1 [-], the cage speed against
  the cage speed of rolling without slip (outer-race control) at the state's own contact
  angles and loads (:func:`rolling_cage_speed_ratio`) for deep-groove and angular-contact
  ball bearings; for roller and four-point bearings against paper 002's epicyclic CSR_th
  at the zero-speed contact angles. Beyond ``SKID_LIMIT`` (5 %) the elements slide
  grossly on the raceways (skidding, s < 0: the light-load, high-speed damage mode of
  paper 000; over-skidding, s > 0: paper 002's large angular-contact bearings). The 5 %
  threshold is this product's choice, not a standard: a normally loaded bearing departs
  from the epicyclic speed by the rolling-radius and gyroscopic effects only (< 1-2 %,
  paper 002 Fig. 10 at 36 kN and above). The rolling reference matters at high speed
  under a light preload: the balls' centrifugal force turns the outer contact angle down
  and the inner one up (a 15 deg 7014 at 300 N: outer 6 deg, inner 25 deg at 12000
  r/min), which raises the rolling cage speed by several percent above CSR_th without any
  sliding; the kinematics table's ``over-skidding [%]`` (paper 002's measure) includes it,
  and the summary names the share when the two disagree about a step.
- **Contact stress.** The largest Hertz pressure p0 [Pa] of the loaded contacts against the
  stress at which ISO 76 (static load ratings) sets the basic static load rating: 4200 MPa
  for ball bearings (4600 MPa self-aligning), 4000 MPa for roller bearings, the stress that
  leaves a total permanent deformation of about 1e-4 of the element diameter (ISO 76:2006
  Rolling bearings -- Static load ratings, clauses 3.2-3.3: 4200 / 4600 / 4000 MPa for
  radial ball / self-aligning ball / roller bearings, 4200 / 4000 MPa for thrust ball /
  roller bearings; checked against the clause text as reproduced publicly and
  against NSK's bearing handbook, "Static load ratings"; the standard itself is paywalled).
- **Film parameter.** Lambda = h / sigma [-] with the contact's film thickness h from the
  scene's film model (central film unless a minimum-film model is named) and the composite
  RMS roughness sigma = (Rq_race^2 + Rq_element^2)^(1/2) of the bearing
  (``raceway_roughness``, ``element_roughness``; :func:`thermobearing.film.film_parameter`).
  Lambda < 1 means boundary lubrication, where the EHL film and traction models that
  computed the losses do not hold (Hamrock, Schmid & Jacobson 2004, ch. 3, the bands of
  :func:`thermobearing.film.film_parameter`).

The three thresholds are a study's choice: :class:`CheckLimits` holds them (defaults: the
module constants below), a scene sets them in its optional ``[checks]`` table
(:mod:`thermobearing.scene`), and the summary lines name the threshold used and where it
comes from when it is not the default.

Units SI. Pure functions; :class:`CheckLog` accumulates one bearing's steps.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from typing import Any

import numpy as np

from .errors import InputError

#: |CSR / CSR_ref - 1| above which a step is reported as skidding / over-skidding [-]
SKID_LIMIT = 0.05
#: ISO 76 stress of the basic static load rating [Pa], by bearing family
ISO76_STRESS = {"ball": 4.2e9, "self_aligning_ball": 4.6e9, "roller": 4.0e9}
#: film parameter below which the contacts run in boundary lubrication [-]
LAMBDA_BOUNDARY = 1.0
#: the bearing families of the contact-stress limit (keys of ``ISO76_STRESS``)
STRESS_FAMILIES = ("ball", "self_aligning_ball", "roller")
#: smallest contact-stress limit accepted [Pa]: 1 MPa, far below any rolling contact's
#: design stress (steel about 1.5-4.2 GPa, polymer bearings tens of MPa), so that a bare
#: number meant in MPa (``3500``, read as 3500 Pa) is refused, not applied
MIN_STRESS_LIMIT = 1e6
#: where the thresholds of a :class:`CheckLimits` built without a source come from
DEFAULT_LIMITS_SOURCE = "CheckLimits"


@dataclass(frozen=True)
class CheckLimits:
    """The thresholds of the validity checks of one run.

    skid_limit : |CSR / CSR_ref - 1| above which a step is skidding / over-skidding [-]
        (CSR_ref: see :class:`StateCheck` ``slip``),
        in (0, 1) (default ``SKID_LIMIT``, 5 %).
    ball_stress_limit, self_aligning_ball_stress_limit, roller_stress_limit : largest
        admissible Hertz pressure p0 [Pa] of the bearing family (defaults: the ISO 76
        static-rating stresses ``ISO76_STRESS``, 4200 / 4600 / 4000 MPa).
    min_film_parameter : film parameter Lambda [-] below which a step is flagged (default
        ``LAMBDA_BOUNDARY``, 1: boundary lubrication).
    source : where the values that differ from the defaults come from (named in the
        summary lines, e.g. ``"scene [checks]"``). Provenance only: two limit sets with
        the same thresholds compare equal whatever their sources (a scene built in Python
        and the same scene read back from its TOML are equal).

    Every limit must be a finite number > 0, the skid limit < 1, a stress limit at least
    ``MIN_STRESS_LIMIT`` (1 MPa); an :class:`InputError` names the field otherwise. Integers
    are stored as floats.
    """

    skid_limit: float = SKID_LIMIT
    ball_stress_limit: float = ISO76_STRESS["ball"]
    self_aligning_ball_stress_limit: float = ISO76_STRESS["self_aligning_ball"]
    roller_stress_limit: float = ISO76_STRESS["roller"]
    min_film_parameter: float = LAMBDA_BOUNDARY
    source: str = field(default=DEFAULT_LIMITS_SOURCE, compare=False)

    def __post_init__(self) -> None:
        for name in ("skid_limit", *(f"{f}_stress_limit" for f in STRESS_FAMILIES),
                     "min_film_parameter"):
            check_limit_value(name, getattr(self, name), f"CheckLimits.{name}")
            object.__setattr__(self, name, float(getattr(self, name)))
        if not isinstance(self.source, str):
            raise InputError("CheckLimits.source", self.source, "a text (where the limits "
                             "come from)")

    def stress_limit(self, family: str) -> float:
        """Contact-stress limit [Pa] of a bearing family (``STRESS_FAMILIES``)."""
        if family not in STRESS_FAMILIES:
            raise InputError("family", family, "one of " + ", ".join(STRESS_FAMILIES))
        return float(getattr(self, f"{family}_stress_limit"))

    def is_default(self, name: str) -> bool:
        """Whether the limit ``name`` (a field name) has its default value."""
        return getattr(self, name) == _DEFAULT_VALUES[name]

    @property
    def all_default(self) -> bool:
        """Every threshold is the default (the source then does not matter)."""
        return all(self.is_default(n) for n in _DEFAULT_VALUES)

    def describe(self) -> str:
        """One line naming every threshold and whether it is the default or set (for the
        report): ``"skidding |s| > 5% (default); contact stress > 4200 MPa ball, ..."``."""
        def tag(names: tuple[str, ...], default: str) -> str:
            return default if all(self.is_default(n) for n in names) else self.source

        iso = "ISO 76 static-rating stress"
        stress = ", ".join(f"{self.stress_limit(f) / 1e6:.4g} MPa {f.replace('_', '-')}"
                           for f in STRESS_FAMILIES)
        if all(self.is_default(f"{f}_stress_limit") for f in STRESS_FAMILIES):
            stress += f" ({iso})"
        else:  # some families set: the source of each
            stress = ", ".join(
                f"{self.stress_limit(f) / 1e6:.4g} MPa {f.replace('_', '-')} "
                f"({tag((f'{f}_stress_limit',), 'ISO 76')})" for f in STRESS_FAMILIES)
        return (f"cage skidding / over-skidding |CSR/CSR_ref - 1| > {_pct(self.skid_limit)} "
                f"({tag(('skid_limit',), 'default')}; CSR_ref: rolling at the state's contact "
                "angles for angular-contact and deep-groove bearings, CSR_th for others); "
                f"Hertz pressure > {stress}; "
                "film parameter "
                f"Lambda < {self.min_film_parameter:g} "
                f"({tag(('min_film_parameter',), 'default: boundary lubrication')})")

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> CheckLimits:
        """The limits of an :meth:`as_dict` record (a run's ``metadata.json``); unknown keys
        are an :class:`InputError`."""
        known = (*_DEFAULT_VALUES, "source")
        for key in data:
            if key not in known:
                raise InputError(f"check_limits.{key}", data[key],
                                 "a known key: " + ", ".join(known))
        source = str(data.get("source", DEFAULT_LIMITS_SOURCE))
        return cls(**{k: data[k] for k in _DEFAULT_VALUES if k in data}, source=source)

    def as_dict(self) -> dict[str, float | str]:
        """The thresholds in SI (stress [Pa], the others [-]) and their source, for a run's
        results (``Results.check_limits``, ``metadata.json``)."""
        out: dict[str, float | str] = {n: float(getattr(self, n)) for n in _DEFAULT_VALUES}
        out["source"] = "default" if self.all_default else self.source
        return out


def check_limit_value(name: str, value: Any, field_name: str, raw: Any = None) -> None:
    """Raise :class:`InputError` naming ``field_name`` unless ``value`` is a valid threshold
    ``name`` of :class:`CheckLimits` (finite, > 0; the skid limit < 1). ``raw``: the value
    as the user wrote it (default ``value``), shown in the message."""
    shown = value if raw is None else raw
    allowed = {"skid_limit": "a fraction in (0, 1), e.g. 0.02 or \"2 %\"",
               "min_film_parameter": "a film parameter Lambda > 0, e.g. 1.5"}.get(
        name, f"a stress >= {MIN_STRESS_LIMIT / 1e6:g} MPa (a bare number is in Pa), "
        "e.g. \"3500 MPa\"")
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise InputError(field_name, shown, allowed)
    low, high = {"skid_limit": (0.0, 1.0), "min_film_parameter": (0.0, math.inf)}.get(
        name, (MIN_STRESS_LIMIT, math.inf))
    if not (math.isfinite(value) and value > 0.0 and low <= value < high):
        raise InputError(field_name, shown, allowed)


#: the default value of every threshold of :class:`CheckLimits` (field name -> SI value)
_DEFAULT_VALUES: dict[str, float] = {f.name: f.default for f in fields(CheckLimits)
                                     if f.name != "source"}
#: the default thresholds (the module constants)
DEFAULT_LIMITS = CheckLimits()


def _pct(fraction: float) -> str:
    """0.05 -> ``"5%"``, 0.025 -> ``"2.5%"`` (the summary lines' spelling)."""
    return f"{100.0 * fraction:.4g}%"


@dataclass(frozen=True)
class StateCheck:
    """The checked quantities of one kinematic state.

    slip : CSR / CSR_roll - 1 [-] (negative: skidding; CSR / CSR_th - 1 when ``csr_roll``
    is None). csr, csr_th : the cage speed ratio and paper 002's CSR_th [-].
    max_pressure : largest Hertz pressure of the loaded contacts [Pa] (NaN when the state
    has no contacts computed: kinematics ``"none"``, epicyclic speeds only); stress_limit : the
    contact-stress limit of the bearing's family it was checked against [Pa] (the ISO 76
    stress unless :class:`CheckLimits` sets another). film_parameter : smallest Lambda of the
    loaded contacts [-], None when the bearing gives no roughness or the state no film;
    race : the raceway where it occurs. family : the bearing family of the stress limit
    (``STRESS_FAMILIES``; "" when unknown).
    """

    slip: float
    csr: float
    csr_th: float
    max_pressure: float
    stress_limit: float
    film_parameter: float | None
    race: str = ""
    family: str = ""
    #: cage speed ratio of rolling without slip at the state's contact angles [-] (the
    #: reference of ``slip``; None: ``slip`` is against ``csr_th``)
    csr_roll: float | None = None
    #: load-weighted mean inner / outer contact angle of the state [rad] (balls; else None)
    contact_angles: tuple[float, float] | None = None


def composite_roughness(bearing: Any) -> float | None:
    """sigma = (Rq_race^2 + Rq_element^2)^(1/2) [m], or None when the bearing gives none."""
    r = getattr(bearing, "raceway_roughness", None)
    e = getattr(bearing, "element_roughness", None)
    if r is None or e is None:
        return None
    return math.hypot(r, e)


def bearing_family(bearing: Any) -> str:
    """The family of the contact-stress limit (``STRESS_FAMILIES``): ball, self-aligning
    ball (``kind == "self_aligning"``) or roller bearing."""
    if hasattr(bearing, "ball_diameter"):
        return "self_aligning_ball" if getattr(bearing, "kind", "") == "self_aligning" \
            else "ball"
    return "roller"


def stress_limit(bearing: Any, limits: CheckLimits = DEFAULT_LIMITS) -> float:
    """Contact-stress limit [Pa] of the bearing's family: the ISO 76 static-rating stress
    (module docstring) unless ``limits`` sets another."""
    return limits.stress_limit(bearing_family(bearing))


def _loaded_mean(cs: Any) -> float:
    q = np.asarray(cs.normal_load, dtype=float)
    a = np.broadcast_to(np.asarray(cs.contact_angle, dtype=float), q.shape)
    return float(np.sum(q * a) / np.sum(q)) if np.sum(q) > 0 else float(np.mean(a))


def rolling_cage_speed_ratio(bearing: Any, state: Any
                             ) -> tuple[float, tuple[float, float]] | None:
    """Cage speed ratio of rolling without slip at a ball state's own contact angles [-],
    with the load-weighted mean inner and outer contact angles [rad].

    Race-control kinematics with outer-race control (``state.race_control_state``) at the
    state's inner and outer contact loads and angles, so the centrifugal and gyroscopic
    change of the contact angles with speed is in the reference and only sliding is
    left in CSR / CSR_roll - 1. None for roller bearings, four-point bearings (their
    over-skidding is paper 002's, against CSR_th, with which the QJ1044 rig is validated;
    their load moves between two arc pairs) and a state at rest.
    """
    from .state import OperatingPoint, race_control_state

    if (getattr(bearing, "kind", "") not in ("angular_contact", "deep_groove")
            or not hasattr(bearing, "ball_diameter") or state.inner_speed == state.outer_speed):
        return None
    sets = {cs.race: cs for cs in state.contacts}
    inner, outer = sets.get("inner"), sets.get("outer")
    others = [cs for name, cs in sets.items() if name not in ("inner", "outer")]
    if (inner is None or outer is None
            or any(np.any(np.asarray(cs.normal_load, dtype=float) > 0) for cs in others)
            or not np.any(np.asarray(inner.normal_load, dtype=float) > 0)):
        return None
    op = OperatingPoint(inner_speed=state.inner_speed, outer_speed=state.outer_speed)
    rolling = race_control_state(bearing, op, control="outer_race",
                                 inner_load=inner.normal_load, outer_load=outer.normal_load,
                                 contact_angle_i=inner.contact_angle,
                                 contact_angle_o=outer.contact_angle)
    ratio = rolling.cage_speed / state.inner_speed
    if not math.isfinite(ratio) or ratio <= 0.0:
        return None
    return float(ratio), (_loaded_mean(inner), _loaded_mean(outer))


def check_state(bearing: Any, kin: Any, limits: CheckLimits = DEFAULT_LIMITS) -> StateCheck:
    """The checked quantities of a solved state (``kinematic_models.KinematicsResult``);
    ``limits`` gives the stress limit recorded with it (default: ISO 76). The slip is
    against the rolling cage speed at the state's contact angles
    (:func:`rolling_cage_speed_ratio`); a race-control state rolls by construction (slip
    0), a state without that reference is measured against CSR_th."""
    csr = float(kin.cage_speed_ratio)
    rolling = None
    if getattr(kin.state, "origin", "") == "race_control":
        ref = rolling_cage_speed_ratio(bearing, kin.state)
        rolling = (csr, ref[1] if ref else None)
    elif getattr(kin.state, "origin", "") == "skidding":
        ref = rolling_cage_speed_ratio(bearing, kin.state)
        rolling = ref if ref else None
    check = _check_contacts(bearing, kin.state, float(kin.over_skid), csr,
                            float(kin.theoretical_cage_speed_ratio), limits)
    if rolling is None:
        return check
    return replace(check, slip=csr / rolling[0] - 1.0, csr_roll=rolling[0],
                   contact_angles=rolling[1])


def check_film_rows(bearing: Any, rows: Any, cage_speed_ratio: float,
                    limits: CheckLimits = DEFAULT_LIMITS) -> StateCheck:
    """The contact-stress and film checks of a film-only step: its rows of
    ``simulation.film_table`` (the most loaded element per raceway, race control), with
    ``max pressure [GPa]`` and, when the bearing gives its roughness, ``film parameter
    [-]`` (Lambda of the film the row reports: the numerical minimum film when a numerical
    model is named, else the closed-form central film). Race control runs the cage at the
    epicyclic speed, so the slip is 0 by construction (CSR = CSR_th = ``cage_speed_ratio``)."""
    p_max = 0.0
    lam_min, race_min = math.inf, ""
    for row in rows:
        p_max = max(p_max, float(row["max pressure [GPa]"]) * 1e9)
        lam = row.get("film parameter [-]")
        if lam is not None and math.isfinite(lam) and lam < lam_min:
            lam_min, race_min = float(lam), str(row["race"])
    return StateCheck(slip=0.0, csr=cage_speed_ratio, csr_th=cage_speed_ratio,
                      max_pressure=p_max, stress_limit=stress_limit(bearing, limits),
                      film_parameter=None if math.isinf(lam_min) else lam_min,
                      race=race_min, family=bearing_family(bearing))


def _check_contacts(bearing: Any, state: Any, slip: float, csr: float, csr_th: float,
                    limits: CheckLimits) -> StateCheck:
    """Largest Hertz pressure and smallest film parameter of the loaded contacts of a
    ``state.KinematicState`` [Pa, -], with the given slip and cage speed ratios. A turning
    state without contact sets (kinematics ``"none"``) has no pressure computed: NaN, not
    0 Pa (a state at rest without contacts carries no load: 0)."""
    sigma = composite_roughness(bearing)
    p_max = 0.0
    if not state.contacts and getattr(state, "origin", "") == "given":
        p_max = math.nan
    lam_min, race_min = math.inf, ""
    for cs in state.contacts:
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
        slip=slip, csr=csr, csr_th=csr_th, max_pressure=p_max,
        stress_limit=stress_limit(bearing, limits),
        film_parameter=None if math.isinf(lam_min) else lam_min, race=race_min,
        family=bearing_family(bearing))


@dataclass
class CheckLog:
    """The worst checked quantities of one bearing per schedule step (a step's kinematics
    may be re-solved as the temperatures move; the worst state counts).

    bearing : the bearing's name in the scene. roughness : composite RMS roughness [m], None
    when the bearing gives none. limits : the thresholds the summary applies (record states
    made by :func:`check_state` with the same ``limits``: the stress limit is the state's).
    """

    bearing: str
    roughness: float | None
    steps: dict[int, list[StateCheck]] = field(default_factory=dict)
    limits: CheckLimits = DEFAULT_LIMITS

    def record(self, step: int, check: StateCheck) -> None:
        self.steps.setdefault(step, []).append(check)

    def summary(self) -> list[str]:
        """One line per check that some step fails (empty when every step passes), plus a
        line saying the film parameter was not checked when the bearing gives no
        roughness. A threshold that is not the default is named with its source
        (``CheckLimits.source``, e.g. "scene [checks]")."""
        lim = self.limits
        lines: list[str] = []
        skid_limit = lim.skid_limit
        skid_text = _pct(skid_limit) if lim.is_default("skid_limit") \
            else f"{_pct(skid_limit)} ({lim.source})"
        skid = {i: min(c, key=lambda c: c.slip) for i, c in self.steps.items()}
        over = {i: max(c, key=lambda c: c.slip) for i, c in self.steps.items()}
        for name, worst, sign in (("skidding (cage slower than epicyclic)", skid, -1.0),
                                  ("over-skidding (cage faster than epicyclic)", over, 1.0)):
            flagged = _flag(worst, lambda c, s=sign: s * c.slip > skid_limit,
                            lambda c, s=sign: s * c.slip)
            if flagged:
                where, i, c = flagged
                against = (f"{c.csr_th:.4f}" if c.csr_roll is None else
                           f"{c.csr_roll:.4f} of rolling at that step's contact angles; "
                           f"CSR_th {c.csr_th:.4f}")
                lines.append(
                    f"{self.bearing}: cage {name} by more than {skid_text} {where}; "
                    f"largest {100 * c.slip:+.1f} % at step {i} (CSR {c.csr:.4f} against "
                    f"{against}): gross sliding of the elements (smearing risk)")
        shifted = {i: max(cs, key=lambda c: abs(c.csr / c.csr_th - 1.0))
                   for i, cs in self.steps.items()}
        flagged = _flag(shifted, lambda c: (c.csr_roll is not None
                                            and abs(c.csr / c.csr_th - 1.0) > skid_limit
                                            and abs(c.slip) <= skid_limit),
                        lambda c: abs(c.csr / c.csr_th - 1.0))
        if flagged:
            where, i, c = flagged
            angles, why = "", ""
            if c.contact_angles is not None:
                inner, outer = (math.degrees(a) for a in c.contact_angles)
                angles = f" (inner {inner:.1f} deg, outer {outer:.1f} deg)"
                if inner - outer > 1.0:
                    why = ("; the balls' centrifugal force turns the outer contact angle "
                           f"{inner - outer:.1f} deg below the inner one")
            lines.append(
                f"{self.bearing}: cage speed ratio more than {skid_text} from CSR_th "
                f"{where}; largest {100 * (c.csr / c.csr_th - 1.0):+.1f} % at step {i} (the "
                f"kinematics table's over-skidding [%]), without gross sliding: rolling "
                f"at that step's contact angles{angles} gives a cage speed ratio of "
                f"{c.csr_roll:.4f} and the cage runs {100 * c.slip:+.1f} % from it (CSR_th "
                f"is paper 002's ratio at the zero-speed contact angles{why})")
        stress = {i: max(c, key=lambda c: c.max_pressure) for i, c in self.steps.items()}
        flagged = _flag(stress, lambda c: c.max_pressure > c.stress_limit,
                        lambda c: c.max_pressure)
        if flagged:
            lines.append(self._stress_line(*flagged))
        if self.steps and all(math.isnan(c.max_pressure) for cs in self.steps.values()
                              for c in cs):
            lines.append(f"{self.bearing}: contact stress and film parameter Lambda not "
                         "checked: the kinematics model computes no contacts (kinematics = "
                         "\"none\")")
            return lines
        if self.roughness is None:
            lines.append(f"{self.bearing}: film parameter Lambda not checked: the bearing "
                         "gives no raceway_roughness / element_roughness")
            return lines
        lam_min = lim.min_film_parameter
        films = {i: min((c for c in cs if c.film_parameter is not None),
                        key=lambda c: c.film_parameter, default=None)
                 for i, cs in self.steps.items()}
        flagged = _flag(films, lambda c: c.film_parameter < lam_min,
                        lambda c: -c.film_parameter)
        if flagged:
            where, i, c = flagged
            detail = (f"smallest {c.film_parameter:.2f} at step {i} ({c.race} contact; film "
                      f"of the scene's film model over the composite roughness "
                      f"{self.roughness * 1e6:.3g} um)")
            if lim.is_default("min_film_parameter"):
                lines.append(
                    f"{self.bearing}: film parameter Lambda < {lam_min:g} (boundary "
                    f"lubrication) {where}; {detail}: the EHL film and traction "
                    "models do not hold there")
            else:
                lines.append(
                    f"{self.bearing}: film parameter Lambda < {lam_min:g} ({lim.source}) "
                    f"{where}; {detail}: {_film_regime(c.film_parameter)}")
        return lines

    def flagged_steps(self) -> dict[str, int]:
        """How many schedule steps each check flags (the worst state of a step counts, as
        in :meth:`summary`): ``"skid"`` (|CSR/CSR_ref - 1| above the skid limit), ``"stress"``
        (Hertz pressure above the state's stress limit), ``"film"`` (Lambda below the
        minimum; 0 when the bearing gives no roughness)."""
        lim = self.limits
        skid = stress = film = 0
        for cs in self.steps.values():
            skid += any(abs(c.slip) > lim.skid_limit for c in cs)
            stress += any(c.max_pressure > c.stress_limit for c in cs)
            film += any(c.film_parameter is not None
                        and c.film_parameter < lim.min_film_parameter for c in cs)
        return {"skid": int(skid), "stress": int(stress), "film": int(film)}

    def flagged_step_indices(self) -> dict[str, list[int]]:
        """The schedule steps each check flags, as :meth:`flagged_steps` counts them (the
        worst state of a step): ``{"skid": [...], "stress": [...], "film": [...]}``,
        ascending; the report marks those rows of its loss tables."""
        lim = self.limits
        out: dict[str, list[int]] = {"skid": [], "stress": [], "film": []}
        for i, cs in sorted(self.steps.items()):
            if any(abs(c.slip) > lim.skid_limit for c in cs):
                out["skid"].append(int(i))
            if any(c.max_pressure > c.stress_limit for c in cs):
                out["stress"].append(int(i))
            if any(c.film_parameter is not None and c.film_parameter < lim.min_film_parameter
                   for c in cs):
                out["film"].append(int(i))
        return out

    def _stress_line(self, where: str, i: int, c: StateCheck) -> str:
        """The summary line of the contact-stress check (worst state ``c`` at step ``i``)."""
        iso = ISO76_STRESS.get(c.family)
        head = f"{self.bearing}: contact pressure above the "
        tail = f"; largest {c.max_pressure / 1e6:.0f} MPa at step {i}"
        legacy = iso is None and self.limits.all_default  # a state made without a family
        if c.stress_limit == iso or legacy:
            return (f"{head}ISO 76 static-rating stress {c.stress_limit / 1e6:.0f} MPa "
                    f"{where}{tail}: permanent raceway deformation")
        if iso is None:
            effect = ""
        elif c.max_pressure > iso:
            effect = (f": above the ISO 76 static-rating stress {iso / 1e6:.0f} MPa too "
                      "(permanent raceway deformation)")
        else:
            effect = f" (below the ISO 76 static-rating stress {iso / 1e6:.0f} MPa)"
        return (f"{head}stress limit {c.stress_limit / 1e6:.4g} MPa ({self.limits.source}) "
                f"{where}{tail}{effect}")


def _film_regime(lam: float) -> str:
    """The lubrication regime of a film parameter (bands of
    :func:`thermobearing.film.film_parameter`, Hamrock et al. 2004, ch. 3)."""
    if lam < 1.0:
        return ("boundary lubrication (Lambda < 1), where the EHL film and traction models "
                "do not hold")
    if lam < 3.0:
        return "mixed lubrication (1 <= Lambda < 3): the asperities carry part of the load"
    return "full-film lubrication (Lambda >= 3), below the set threshold"


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
