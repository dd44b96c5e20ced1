"""Operating state and kinematic state: what the skidding solver fills and the heat sources read.

Four small frozen dataclasses:

:class:`OilSupply`
    how the oil gets in (method, volume flow, inlet temperature, bath level).
:class:`OperatingPoint`
    ring speeds and external loads.
:class:`ContactSet`
    one raceway's element contacts (per-element arrays): load, Hertz ellipse, film,
    and the *relative rigid-body motion* of the element against the race in the contact
    frame, which is exactly what :func:`thermobearing.contact_traction.integrate` needs.
:class:`KinematicState`
    ring, cage and element speeds plus the contact sets and the cage-pocket forces; it
    comes either from race control (:meth:`KinematicState.from_race_control`) or from the
    skidding solver (``origin="skidding"``).

Contact frame and signs (used throughout, see also :mod:`thermobearing.contact_traction`)
-----------------------------------------------------------------------------------------
Origin at the contact centre; ``x`` along the major axis ``a`` (transverse to rolling,
along the groove), ``y`` along the rolling direction (semi-minor axis ``b``), ``z`` along
the contact normal pointing from the race towards the element's centre. Body 1 is the
rolling element, body 2 the race. Every relative quantity is *element minus race*:

- ``sliding_speed``            V_y = u_element - u_race at the contact centre [m/s]
  (so the slide-to-roll ratio of the contract is ``sliding_speed / entrainment_speed``);
- ``transverse_sliding_speed`` V_x at the contact centre [m/s];
- ``roll_speed``               Omega_x, relative angular velocity about the major axis [rad/s]
  (the rolling rotation; it produces the Heathcote slip on the curved deformed surface);
- ``tilt_speed``               Omega_y, relative angular velocity about the rolling axis [rad/s];
- ``spin_speed``               Omega_z, relative angular velocity about the normal [rad/s].

A point of the deformed contact surface at ``(x, y)`` lies at ``z = x**2 / (2 R_d)``
(``R_d`` = ``deformed_radius``; infinite for a line contact), and the element slides
over the race there at ``V + Omega x r``.
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from typing import Any

import numpy as np

from .errors import (
    InputError,
    UnknownNameError,
    ValidityWarning,
    check_finite,
    check_positive,
    check_temperature,
)

SUPPLY_METHODS = ("jet", "circulation", "oil_bath", "oil_air", "grease")
ORIGINS = ("race_control", "skidding", "given", "standstill")
CONTACT_KINDS = ("point", "line")
RING_ROLES = ("inner_ring", "outer_ring")


# ---------------------------------------------------------------------------
# oil supply and operating point
# ---------------------------------------------------------------------------
@dataclass(frozen=True)
class OilSupply:
    """Oil supply of one bearing.

    Attributes
    ----------
    method : ``"jet" | "circulation" | "oil_bath" | "oil_air" | "grease"``.
    flow_rate : volume flow of oil through the bearing [m^3/s]; > 0, zero allowed only for
        ``oil_bath`` and ``grease``.
    inlet_temperature : oil inlet temperature [K]; an oil bath without flow has no inlet
        (its temperature is the network's oil node), so it is not used there.
    level : static oil level of a bath [m], measured from the lowest point of the outer-ring
        raceway (SKF's ``H``); required for ``oil_bath``, ignored otherwise.
    """

    method: str
    flow_rate: float
    inlet_temperature: float
    level: float | None = None

    def __post_init__(self) -> None:
        if self.method not in SUPPLY_METHODS:
            raise UnknownNameError("supply.method", self.method, SUPPLY_METHODS)
        check_finite("supply.flow_rate", self.flow_rate)
        q = float(self.flow_rate)
        if q < 0.0 or (q == 0.0 and self.method not in ("oil_bath", "grease")):
            raise InputError(
                "supply.flow_rate", self.flow_rate,
                f"a flow > 0 m^3/s for method {self.method!r} (zero only for oil_bath or grease)",
            )
        if self.method == "grease" and q > 0.0:
            raise InputError("supply.flow_rate", self.flow_rate,
                             "0 for a grease fill: grease stays in the bearing, no stream "
                             "carries heat away (a circulating oil is method 'circulation')")
        check_temperature("supply.inlet_temperature", self.inlet_temperature)
        if self.method == "oil_bath":
            if self.level is None:
                raise InputError("supply.level", None, "an oil level [m] for an oil bath")
            check_positive("supply.level", self.level, allow_zero=True)
        object.__setattr__(self, "flow_rate", q)
        object.__setattr__(self, "inlet_temperature", float(self.inlet_temperature))

    @classmethod
    def from_scene(cls, supply: Any) -> OilSupply:
        """Build from :class:`thermobearing.scene.Supply` (fields method, flow, inlet_temperature,
        level)."""
        return cls(method=supply.method, flow_rate=supply.flow,
                   inlet_temperature=supply.inlet_temperature, level=supply.level)


@dataclass(frozen=True)
class OperatingPoint:
    """Ring speeds [rad/s] and external loads [N] of one operating point.

    ``axial_load`` is the magnitude of the thrust (>= 0); ``radial_load`` >= 0.
    """

    inner_speed: float
    outer_speed: float = 0.0
    radial_load: float = 0.0
    axial_load: float = 0.0

    def __post_init__(self) -> None:
        for name in ("inner_speed", "outer_speed"):
            check_finite(f"operating.{name}", getattr(self, name))
        check_positive("operating.radial_load", self.radial_load, allow_zero=True)
        check_positive("operating.axial_load", self.axial_load, allow_zero=True)
        for f in fields(self):
            object.__setattr__(self, f.name, float(getattr(self, f.name)))


# ---------------------------------------------------------------------------
# contact set
# ---------------------------------------------------------------------------
_CONTACT_ARRAYS = (
    "normal_load", "contact_angle", "semi_major", "semi_minor", "max_pressure",
    "entrainment_speed", "sliding_speed", "transverse_sliding_speed", "spin_speed",
    "roll_speed", "tilt_speed", "deformed_radius",
)
_OPTIONAL_ARRAYS = ("film_thickness", "temperature", "reduced_radius_x", "reduced_radius_y")
_RADII = frozenset({"deformed_radius", "reduced_radius_y"})  # inf allowed (flat / straight)
#: fields that must be >= 0, and > 0 (a temperature above absolute zero [K]; the rolling-
#: direction reduced radius R_x = 1/(1/r_element + 1/r_race) > 0 of a Hertz contact, finite:
#: no bearing contact is flat in the rolling direction)
_NON_NEGATIVE = frozenset({"normal_load", "semi_major", "semi_minor", "max_pressure",
                           "film_thickness"})
_POSITIVE = frozenset({"temperature", "reduced_radius_x"})


@functools.lru_cache(maxsize=64)
def _field_masks(names: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Row masks (radii, >= 0, > 0) of a contact-set block with these fields, in order."""
    return (np.array([name in _RADII for name in names], dtype=bool),
            np.array([name in _NON_NEGATIVE for name in names], dtype=bool),
            np.array([name in _POSITIVE for name in names], dtype=bool))


@dataclass(frozen=True)
class PrecomputedTraction:
    """Tractions of a contact set as its producer integrated them (see ContactSet).

    Attributes
    ----------
    law : the traction law object used (identity is what a consumer compares).
    n_major, n_minor : quadrature nodes along a and b.
    result : ``contact_traction.ContactTraction`` with arrays of shape (Z,): forces [N],
        moments [N m], heat [W].
    """

    law: Any
    n_major: int
    n_minor: int
    result: Any

    def matches(self, law: Any, n_major: int, n_minor: int) -> bool:
        """Whether a consumer integrating ``law`` with this quadrature would get this."""
        return self.law is law and self.n_major == n_major and self.n_minor == n_minor


@dataclass(frozen=True)
class ContactSet:
    """The contacts of all elements with one raceway (arrays of shape ``(Z,)``).

    Attributes
    ----------
    race : name of the raceway (``"inner"``, ``"outer"``, ``"inner_2"``... for the second
        half-ring of a four-point bearing).
    ring_role : node role of the ring, ``"inner_ring"`` or ``"outer_ring"`` (default: from
        the race name's prefix).
    kind : ``"point"`` (Hertz ellipse) or ``"line"`` (roller: ``semi_major`` is half the
        effective length, uniform load along it).
    normal_load : Q [N] (>= 0; zero marks an unloaded element).
    contact_angle : operating contact angle [rad] (0 for radial roller contacts).
    semi_major, semi_minor : a, b [m] (transverse and rolling-direction half-axes).
    max_pressure : p0 [Pa].
    entrainment_speed : u = (u_element + u_race)/2 in the rolling direction [m/s].
    sliding_speed : V_y, element minus race, rolling direction, at the centre [m/s].
    transverse_sliding_speed : V_x, element minus race, at the centre [m/s].
    spin_speed : Omega_z, element minus race, about the normal [rad/s].
    roll_speed : Omega_x, element minus race, about the major axis [rad/s] (default 0).
    tilt_speed : Omega_y, element minus race, about the rolling axis [rad/s] (default 0).
    deformed_radius : radius of the deformed contact surface in the transverse plane [m];
        ``inf`` = flat (line contacts). For a ball in a groove of conformity f,
        R_d = 2 f D / (2 f + 1) (Harris & Kotzalas 2007; primer over-skidding 3.5).
    film_thickness : central film thickness h_c [m] or None.
    temperature : lubricant/surface temperature at the contact inlet [K] or None.
    reduced_radius_x, reduced_radius_y : R_x (finite, > 0), R_y (> 0, ``inf`` for a line
        contact) [m] or None (rolling-resistance models).
    traction : the tractions of these contacts as the model that produced the state
        integrated them, or None: a :class:`PrecomputedTraction` (the law, the quadrature
        and a ``contact_traction.ContactTraction`` of shape (Z,)). A heat source that would
        integrate the same law with the same quadrature at the same state uses it instead
        (the skidding solver's converged contact forces). :meth:`with_` drops it unless it
        is passed again, so a changed field never meets stale tractions.
    """

    race: str
    normal_load: Any
    semi_major: Any
    semi_minor: Any
    max_pressure: Any
    contact_angle: Any = 0.0
    entrainment_speed: Any = 0.0
    sliding_speed: Any = 0.0
    transverse_sliding_speed: Any = 0.0
    spin_speed: Any = 0.0
    roll_speed: Any = 0.0
    tilt_speed: Any = 0.0
    deformed_radius: Any = math.inf
    film_thickness: Any = None
    temperature: Any = None
    reduced_radius_x: Any = None
    reduced_radius_y: Any = None
    kind: str = "point"
    ring_role: str = ""
    traction: PrecomputedTraction | None = None

    def __post_init__(self) -> None:
        if self.traction is not None and not isinstance(self.traction, PrecomputedTraction):
            raise InputError(f"contacts[{self.race}].traction", type(self.traction).__name__,
                             "a PrecomputedTraction or None")
        if self.kind not in CONTACT_KINDS:
            raise UnknownNameError(f"contacts[{self.race}].kind", self.kind, CONTACT_KINDS)
        role = self.ring_role or (
            "inner_ring" if self.race.startswith("inner") else
            "outer_ring" if self.race.startswith("outer") else "")
        if role not in RING_ROLES:
            raise InputError(f"contacts[{self.race}].ring_role", self.ring_role,
                             "inner_ring or outer_ring (or a race name starting with "
                             "'inner'/'outer')")
        object.__setattr__(self, "ring_role", role)
        n = np.atleast_1d(np.asarray(self.normal_load, dtype=float)).shape
        if len(n) != 1:
            raise InputError(f"contacts[{self.race}].normal_load", self.normal_load,
                             "a 1-D array (one entry per element)")
        names = tuple(name for name in _CONTACT_ARRAYS + _OPTIONAL_ARRAYS
                      if getattr(self, name) is not None)
        # one block of all fields, checked in a few vectorised operations; the per-field
        # checks below run only when the block fails, to name the offending field
        block = np.empty((len(names), n[0]))
        for k, name in enumerate(names):
            value = getattr(self, name)
            try:
                if (value.ndim if isinstance(value, np.ndarray) else np.ndim(value)) > 1:
                    raise ValueError
                block[k] = value  # broadcasts a scalar or a (1,) array; refuses other shapes
            except (ValueError, TypeError):
                raise InputError(f"contacts[{self.race}].{name}", value,
                                 f"an array broadcastable to shape {n}") from None
        radii, non_negative, positive = _field_masks(names)
        if not (np.isfinite(block[~radii]).all()
                and (block[radii] > 0).all()  # NaN compares False: refused too
                and (block[non_negative] >= 0).all() and (block[positive] > 0).all()):
            self._name_the_bad_field(list(names), block)
        block.flags.writeable = False
        for k, name in enumerate(names):
            object.__setattr__(self, name, block[k])

    def _name_the_bad_field(self, names: list[str], block: np.ndarray) -> None:
        """Raise the :class:`InputError` of the first field that fails its check."""
        for k, name in enumerate(names):
            field, value = f"contacts[{self.race}].{name}", getattr(self, name)
            arr = block[k]
            if name in _RADII:  # inf = flat / straight
                if np.any(np.isnan(arr)) or np.any(arr <= 0):
                    raise InputError(field, value, "radii > 0 [m] (inf for a flat surface)")
            elif name == "temperature":
                check_temperature(field, arr)
            elif name in _POSITIVE:
                check_positive(field, arr)
            elif name in _NON_NEGATIVE:
                check_positive(field, arr, allow_zero=True)
            else:
                check_finite(field, arr)
        raise AssertionError("a contact-set field failed the block check but none alone")

    @property
    def n_elements(self) -> int:
        """Number of elements Z."""
        return int(self.normal_load.shape[0])

    @property
    def slide_to_roll(self) -> np.ndarray:
        """Slide-to-roll ratio V_y / u (0 where u = 0)."""
        u = self.entrainment_speed
        return np.divide(self.sliding_speed, u, out=np.zeros_like(u), where=u != 0)

    def with_(self, **changes: Any) -> ContactSet:
        """A copy with some fields replaced (validated again); precomputed tractions are
        dropped unless ``traction`` is among the changes."""
        changes.setdefault("traction", None)
        return replace(self, **changes)


# ---------------------------------------------------------------------------
# kinematic state
# ---------------------------------------------------------------------------
_ELEMENT_ARRAYS = ("orbital_speed", "element_spin", "attitude_angle", "azimuth",
                   "pocket_normal_force", "pocket_sliding_speed", "element_drag_force")


@dataclass(frozen=True)
class KinematicState:
    """Speeds and contact kinematics of one bearing at one instant.

    Attributes
    ----------
    inner_speed, outer_speed, cage_speed : ring and cage angular speeds [rad/s].
    orbital_speed : (Z,) orbital speed of each element's centre [rad/s].
    element_spin : (Z,) magnitude of each element's angular velocity about its own axis,
        seen from the cage [rad/s] (paper 002's omega_r; the roller speed for rollers).
    attitude_angle : (Z,) attitude (pitch) angle beta of the spin axis [rad] (0 for rollers).
    contacts : the contact sets, one per raceway (two for a ball bearing in two-point
        contact, up to four for a four-point bearing).
    azimuth : (Z,) angular position of each element [rad] (default evenly spaced from 0).
    pocket_normal_force : (Z,) normal force between element and cage pocket [N]
        (default 0: race control knows nothing of the cage).
    pocket_sliding_speed : (Z,) sliding speed of the element surface in the pocket [m/s];
        None -> the pocket source uses |element_spin| * D / 2 (paper 002 eq. 19).
    element_drag_force : (Z,) fluid drag on each element [N] from the solver, or None.
    cage_eccentricity : cage-centre eccentricity ratio epsilon in the guide clearance [-].
    cage_guide_force : cage-land normal force from the solver [N] or None.
    origin : ``"race_control" | "skidding" | "given" | "standstill"`` (both rings at rest:
        :func:`thermobearing.kinematic_models.standstill`).
    """

    inner_speed: float
    outer_speed: float
    cage_speed: float
    orbital_speed: Any
    element_spin: Any
    contacts: tuple[ContactSet, ...]
    attitude_angle: Any = 0.0
    azimuth: Any = None
    pocket_normal_force: Any = 0.0
    pocket_sliding_speed: Any = None
    element_drag_force: Any = None
    cage_eccentricity: float = 0.0
    cage_guide_force: float | None = None
    origin: str = "given"
    extras: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.origin not in ORIGINS:
            raise UnknownNameError("kinematics.origin", self.origin, ORIGINS)
        for name in ("inner_speed", "outer_speed", "cage_speed"):
            check_finite(f"kinematics.{name}", getattr(self, name))
            object.__setattr__(self, name, float(getattr(self, name)))
        orbital = np.atleast_1d(np.asarray(self.orbital_speed, dtype=float))
        if orbital.ndim != 1 or orbital.size == 0:
            raise InputError("kinematics.orbital_speed", self.orbital_speed,
                             "a 1-D array with one entry per element")
        z = orbital.shape
        if self.azimuth is None:
            object.__setattr__(self, "azimuth", 2 * np.pi * np.arange(z[0]) / z[0])
        for name in _ELEMENT_ARRAYS:
            value = getattr(self, name)
            if value is None:
                continue
            try:
                arr = np.array(np.broadcast_to(np.asarray(value, dtype=float), z), dtype=float)
            except ValueError:
                raise InputError(f"kinematics.{name}", value,
                                 f"an array broadcastable to shape {z}") from None
            check_finite(f"kinematics.{name}", arr)
            arr.flags.writeable = False
            object.__setattr__(self, name, arr)
        check_positive("kinematics.pocket_normal_force", self.pocket_normal_force, allow_zero=True)
        check_range_eps = float(self.cage_eccentricity)
        if not 0.0 <= check_range_eps < 1.0:
            raise InputError("kinematics.cage_eccentricity", self.cage_eccentricity,
                             "a ratio in [0, 1)")
        object.__setattr__(self, "cage_eccentricity", check_range_eps)
        contacts = tuple(self.contacts)
        for cs in contacts:
            if not isinstance(cs, ContactSet):
                raise InputError("kinematics.contacts", cs, "ContactSet instances")
            if cs.n_elements != z[0]:
                raise InputError(f"kinematics.contacts[{cs.race}]", cs.n_elements,
                                 f"{z[0]} elements (as orbital_speed)")
        races = [cs.race for cs in contacts]
        if len(set(races)) != len(races):
            raise InputError("kinematics.contacts", races, "distinct race names")
        object.__setattr__(self, "contacts", contacts)

    @property
    def n_elements(self) -> int:
        """Number of rolling elements Z."""
        return int(self.orbital_speed.shape[0])

    @property
    def cage_speed_ratio(self) -> float:
        """Cage speed over inner-ring speed relative to the outer ring (CSR)."""
        rel = self.inner_speed - self.outer_speed
        if rel == 0.0:
            raise InputError("kinematics.inner_speed", self.inner_speed,
                             "an inner-ring speed different from the outer-ring speed")
        return (self.cage_speed - self.outer_speed) / rel

    def contact(self, race: str) -> ContactSet:
        """The contact set of ``race``."""
        for cs in self.contacts:
            if cs.race == race:
                return cs
        raise UnknownNameError("kinematics.contacts race", race, [c.race for c in self.contacts])

    def with_(self, **changes: Any) -> KinematicState:
        """A copy with some fields replaced (validated again)."""
        return replace(self, **changes)

    @classmethod
    def from_race_control(cls, bearing: Any, operating: OperatingPoint, *,
                          control: str = "outer_race", inner_load: Any = None,
                          outer_load: Any = None, contact_angle_i: Any = None,
                          contact_angle_o: Any = None, load_distribution: Any = None,
                          lubricant: Any = None, temperature: float | None = None,
                          ) -> KinematicState:
        """Kinematic state of race control (no centre slip) for the heat sources.

        See :func:`race_control_state` (this is the same function).
        """
        return race_control_state(
            bearing, operating, control=control, inner_load=inner_load, outer_load=outer_load,
            contact_angle_i=contact_angle_i, contact_angle_o=contact_angle_o,
            load_distribution=load_distribution, lubricant=lubricant, temperature=temperature)


RACE_CONTROLS = ("outer_race", "inner_race", "pure_rolling")


def deformed_surface_radius(conformity: float, element_diameter: float) -> float:
    """Transverse radius of the deformed ball-groove contact surface, 2 f D / (2 f + 1) [m].

    Mean of the ball and groove curvatures (equal elastic bodies); Harris & Kotzalas 2007.
    """
    return 2.0 * conformity * element_diameter / (2.0 * conformity + 1.0)


def rewarn_naming_contacts(caught: list[warnings.WarningMessage], contacts: str) -> None:
    """Warn again the warnings ``caught`` around a film formula's call, its range warnings
    (``ValidityWarning`` ``"model: W in [lo, hi] outside [a, b]"``,
    :func:`thermobearing.film._warn_range`) with the ``contacts`` they checked in front:
    ``"roller / inner raceway line contacts, pan_hamrock_central: W in ..."``. The text
    before the model is fixed per contact set, so a run's repeats still merge into one line
    per bearing, model and contact set (:mod:`thermobearing.warning_groups`); other warnings
    unchanged."""
    for w in caught:
        message = w.message
        if issubclass(w.category, ValidityWarning):
            message = ValidityWarning(f"{contacts}, {w.message}")
        warnings.warn(message, stacklevel=3)


def race_control_state(bearing: Any, operating: OperatingPoint, *, control: str = "outer_race",
                       inner_load: Any = None, outer_load: Any = None,
                       contact_angle_i: Any = None, contact_angle_o: Any = None,
                       load_distribution: Any = None, lubricant: Any = None,
                       temperature: float | None = None) -> KinematicState:
    """Build a :class:`KinematicState` from race-control kinematics (``kinematics.py``).

    Parameters
    ----------
    bearing : ``geometry.BallBearing`` or ``geometry.RollerBearing``.
    operating : ring speeds (and loads, used when the distribution is solved here).
    control : "outer_race" | "inner_race" | "pure_rolling" (B's kinematics functions).
    inner_load, outer_load : (Z,) contact normal loads [N]; with
    contact_angle_i, contact_angle_o : (Z,) operating angles [rad] (default nominal).
    load_distribution : instead of the arrays, an object with ``inner_load``,
        ``outer_load`` and (balls) ``inner_contact_angle``, ``outer_contact_angle`` (e.g.
        ``loads.ball_load_distribution`` / ``loads_roller.roller_load_distribution``).
        If neither is given, the quasi-static distribution is solved with the operating
        point's loads (``loads.ball_load_distribution``; for rollers
        ``loads_roller.roller_load_distribution`` with Palmgren line stiffness and the
        centrifugal force at the epicyclic cage speed).
    lubricant, temperature : if both given, the central film thickness (Hamrock-Dowson 1977
        for balls, Pan-Hamrock 1989 for rollers; ``film.py``) and the contact temperature
        [K] are filled in (needed by film traction laws).

    Returns
    -------
    KinematicState with ``origin="race_control"``: rolling at the contact centres
    (sliding_speed = 0), spin and roll from the race-control attitude, Hertz ellipses from
    ``hertz.py``, zero pocket forces (race control knows no cage).
    """
    from . import hertz, kinematics

    if control not in RACE_CONTROLS:
        raise UnknownNameError("race control", control, RACE_CONTROLS)
    is_ball = hasattr(bearing, "ball_diameter")
    if load_distribution is None and inner_load is None:
        if is_ball:
            from .loads import ball_load_distribution

            load_distribution = ball_load_distribution(
                bearing, operating.radial_load, operating.axial_load,
                operating.inner_speed - operating.outer_speed)
        else:
            from .hertz import line_contact_stiffness
            from .loads_roller import roller_body_force, roller_load_distribution

            z = bearing.n_elements
            k = float(line_contact_stiffness(bearing.roller_effective_length,
                                             bearing.effective_modulus))
            cage_ratio = float(bearing.theoretical_cage_speed_ratio())
            w_cage = operating.outer_speed + cage_ratio * (operating.inner_speed
                                                           - operating.outer_speed)
            psi = 2.0 * math.pi * np.arange(z) / z
            load_distribution = roller_load_distribution(
                z, bearing.diametral_clearance, operating.radial_load, k, k,
                body_force=roller_body_force(bearing.roller_mass, bearing.pitch_diameter,
                                             w_cage, psi), azimuth=psi)
    if load_distribution is not None:
        inner_load = load_distribution.inner_load
        outer_load = load_distribution.outer_load
        if is_ball:
            contact_angle_i = load_distribution.inner_contact_angle
            contact_angle_o = load_distribution.outer_contact_angle
    if outer_load is None:
        raise InputError("outer_load", None, "outer contact loads with the inner ones")
    qi = np.asarray(inner_load, dtype=float)
    qo = np.asarray(outer_load, dtype=float)
    z = bearing.n_elements
    if qi.shape != (z,) or qo.shape != (z,):
        raise InputError("inner_load/outer_load", (qi.shape, qo.shape), f"arrays of shape ({z},)")
    if is_ball:
        ai = np.broadcast_to(bearing.contact_angle if contact_angle_i is None
                             else contact_angle_i, (z,)).astype(float)
        ao = np.broadcast_to(ai if contact_angle_o is None else contact_angle_o,
                             (z,)).astype(float)
    else:
        ai = ao = np.zeros(z)
    fn = {"outer_race": kinematics.outer_race_control,
          "inner_race": kinematics.inner_race_control,
          "pure_rolling": kinematics.pure_rolling}[control]
    kin = fn(bearing, operating.inner_speed, ai if is_ball else None,
             ao if is_ball else None, outer_speed=operating.outer_speed)
    e_mod = bearing.effective_modulus
    d = bearing.element_diameter
    sets = []
    for race, q, ang, spin, roll, u in (
            ("inner", qi, ai, kin.spin_inner, kin.roll_inner, kin.entrainment_inner),
            ("outer", qo, ao, kin.spin_outer, kin.roll_outer, kin.entrainment_outer)):
        rx, ry = bearing.curvature(race, ang if is_ball else None)
        rx = np.broadcast_to(np.asarray(rx, dtype=float), (z,))
        ry = np.broadcast_to(np.asarray(ry, dtype=float), (z,))
        if is_ball:
            pc = hertz.point_contact(q, rx, ry, e_mod)
            a, b, p0 = pc.a, pc.b, pc.max_pressure
            conformity = bearing.inner_conformity if race == "inner" else bearing.outer_conformity
            rd = deformed_surface_radius(conformity, d)
            kind = "point"
        else:
            length = bearing.roller_effective_length
            lc = hertz.line_contact(q, length, rx, e_mod, crown_radius=bearing.crown_radius)
            a = 0.5 * np.broadcast_to(np.asarray(lc.contact_length, dtype=float), (z,))
            b, p0 = lc.half_width, lc.max_pressure
            rd = math.inf
            kind = "line"
        film = temp = None
        if lubricant is not None and temperature is not None:
            from . import film as film_mod

            temp = np.full(z, float(temperature))
            eta = lubricant.dynamic_viscosity(temperature)
            alpha = lubricant.pressure_viscosity_coefficient(temperature)
            uu = np.broadcast_to(np.asarray(u, dtype=float), (z,))
            loaded = q > 0
            # unloaded elements go in at 0 N: the film formulas give them +inf (no
            # conjunction to size, replaced by 0 below) and leave them out of their range
            # check (a stand-in load of 1 N here made every roller bearing's race-control run
            # warn of a load parameter W far below the formula's range)
            qq = np.asarray(q, dtype=float)
            if is_ball:
                h = film_mod.hamrock_dowson_1977_central(uu, eta, alpha, qq, rx, ry,
                                                         effective_modulus=e_mod)
            else:
                # the formula's range warning names the contacts it checked (a roller rig
                # listed "pan_hamrock_central: W in [...]" without saying which raceway)
                with warnings.catch_warnings(record=True) as caught:
                    warnings.simplefilter("always", ValidityWarning)
                    h = film_mod.pan_hamrock_central(uu, eta, alpha, qq,
                                                     bearing.roller_effective_length, rx,
                                                     effective_modulus=e_mod)
                rewarn_naming_contacts(caught, f"roller / {race} raceway line contacts")
            film = np.where(loaded, h, 0.0)
        sets.append(ContactSet(
            race=race, kind=kind, normal_load=q, contact_angle=ang, semi_major=a, semi_minor=b,
            max_pressure=p0, entrainment_speed=u, sliding_speed=0.0,
            transverse_sliding_speed=0.0, spin_speed=spin if is_ball else 0.0,
            roll_speed=roll, deformed_radius=rd, film_thickness=film, temperature=temp,
            reduced_radius_x=rx, reduced_radius_y=ry))
    orbital = np.broadcast_to(np.asarray(kin.orbital_speed, dtype=float), (z,))
    return KinematicState(
        inner_speed=operating.inner_speed, outer_speed=operating.outer_speed,
        cage_speed=float(np.mean(orbital)), orbital_speed=orbital,
        element_spin=np.broadcast_to(np.asarray(kin.element_spin, dtype=float), (z,)),
        attitude_angle=np.broadcast_to(np.asarray(kin.attitude_angle, dtype=float), (z,)),
        contacts=tuple(sets), origin="race_control",
        azimuth=getattr(load_distribution, "azimuth", None))
