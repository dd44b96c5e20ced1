"""Pieces shared by the ball and roller bearing classes: kind names, the characteristic-frequency
record, envelope checks and the epicyclic kinematics of pure rolling.

Kinematic conventions (outer ring fixed unless an outer speed is given):

- gamma = D cos(alpha) / d_m (Harris & Kotzalas 2007, vol. 1 ch. 2; ``harris_kotzalas2007``).
- Epicyclic cage speed ratio with equal contact angles, CSR = (1 - gamma)/2; paper 000 eq. 40
  (``li2018_nu214_skidding``) for rollers, paper 004 section 2, omega_ct
  (``luo2022_cage_slip_vibration``) for balls. With unequal inner/outer angles the
  race-control forms of :mod:`thermobearing.kinematics` are used.
- Characteristic frequencies: BPFO = Z f_cage, BPFI = Z (f_shaft - f_cage); with cage slip
  s_c, f_cage = (1 - s_c) f_cage,th (paper 004, the f_bpo rule after its Fig. 11).

Everything is SI (m, rad, Hz).
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np

from .errors import InputError, check_positive, check_range

BALL_KINDS = ("deep_groove", "angular_contact", "four_point")
ROLLER_KINDS = ("cylindrical",)
RACES = ("inner", "outer")


class CharacteristicFrequencies(NamedTuple):
    """Characteristic frequencies [Hz] (outer ring fixed unless stated).

    shaft: inner-ring rotation frequency; cage: cage (fundamental train) frequency;
    bpfo / bpfi: ball (roller) pass frequency over a point of the outer / inner ring;
    ball_spin: rotation frequency of an element about its own axis relative to the cage.
    """

    shaft: float
    cage: float
    bpfo: float
    bpfi: float
    ball_spin: float



def _check_envelope(prefix: str, bore: float, outer: float, width: float, element: float,
                    element_name: str, n: int, pitch: float, count_name: str) -> None:
    for name, value in (("bore", bore), ("outer_diameter", outer), ("width", width),
                        (element_name, element), ("pitch_diameter", pitch)):
        check_positive(f"{prefix}.{name}", value)
    if outer <= bore:
        raise InputError(f"{prefix}.outer_diameter", outer, f"a value > bore = {bore}")
    section = 0.5 * (outer - bore)
    if element >= section:
        raise InputError(f"{prefix}.{element_name}", element,
                         f"a value smaller than the radial section (D - d)/2 = {section:.6g} m")
    if not bore < pitch < outer:
        raise InputError(f"{prefix}.pitch_diameter", pitch,
                         f"a value between bore {bore:.6g} m and outer diameter {outer:.6g} m")
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 3:
        raise InputError(f"{prefix}.{count_name}", n, "an integer >= 3")
    if n * element >= math.pi * pitch:
        raise InputError(f"{prefix}.{count_name}", n,
                         f"at most {int(math.pi * pitch / element)} elements of diameter "
                         f"{element:.6g} m on the pitch circle (they would overlap)")


def _check_rings(bearing: Any) -> None:
    """The raceways must lie inside the ring envelope (rings of positive thickness)."""
    if bearing.inner_raceway_diameter <= bearing.bore:
        raise InputError("bearing.pitch_diameter", bearing.pitch_diameter,
                         f"a value leaving an inner ring: raceway diameter "
                         f"{bearing.inner_raceway_diameter:.6g} m <= bore {bearing.bore:.6g} m")
    if bearing.outer_raceway_diameter >= bearing.outer_diameter:
        raise InputError("bearing.pitch_diameter", bearing.pitch_diameter,
                         f"a value leaving an outer ring: raceway diameter "
                         f"{bearing.outer_raceway_diameter:.6g} m >= outer diameter "
                         f"{bearing.outer_diameter:.6g} m")


def _ring_surface(bearing: Any, side: str) -> tuple[float, str, bool]:
    """The ``side`` ("inner" | "outer") ring's surface nearest the cage: (diameter [m],
    what it is, whether it is the ring's land itself).

    A roller bearing's ribbed ring with ``rib_height`` given: its ribs, d_i + 2 h_f or
    d_o - 2 h_f; a roller bearing's ring without ribs: its raceway, which is its whole
    cylindrical surface; a ball bearing's ring with its shoulder diameter given: that
    shoulder. Otherwise the raceway diameter (land False): the ring's land lies somewhere
    nearer the cage than it, and an estimated rib height or shoulder is no ground to refuse
    a bearing."""
    race = bearing.inner_raceway_diameter if side == "inner" else bearing.outer_raceway_diameter
    ribbed = getattr(bearing, "ribbed_ring", None)
    if ribbed is not None:
        if ribbed not in (side, "both"):
            return float(race), (f"the {side} raceway diameter, the bore of a ring without "
                                 f"ribs (bearing.ribbed_ring = {ribbed!r})"
                                 if side == "outer" else
                                 f"the {side} raceway diameter, the outside of a ring "
                                 f"without ribs (bearing.ribbed_ring = {ribbed!r})"), True
        if getattr(bearing, "rib_height", None) is not None:
            land = bearing.inner_land_diameter if side == "inner" else bearing.outer_land_diameter
            form = "d_i + 2 h_f" if side == "inner" else "d_o - 2 h_f"
            return float(land), (f"the {side} ribs' {'diameter' if side == 'inner' else 'bore'}"
                                 f" {form} (bearing.ribbed_ring = {ribbed!r}, rib_height = "
                                 f"{bearing.rib_height * 1e3:.6g} mm)"), True
    else:
        given = getattr(bearing, f"{side}_shoulder_diameter", None)
        if given is not None:
            return float(given), f"bearing.{side}_shoulder_diameter", True
    return float(race), f"the {side} raceway diameter", False


def _check_guide_land(bearing: Any, side: str, surface: float, what: str, land: bool
                      ) -> float:
    """The guide land of a cage guided by the ``side`` ring must be a surface of that ring:
    its land (:func:`_ring_surface`) to within half the guide clearance (the cage's radial
    play on it; the raceway moves with ``diametral_clearance`` and so does a rib), or, where
    the land is not given, a diameter inside the raceway (no surface of a ring lies beyond
    its raceway, and a land at the raceway of a ribbed ring or a ball groove would be the
    path of the elements). Returns the guide land diameter [m]; else InputError naming
    ``cage.guide_land_diameter``, the value and the ring surface."""
    cage = bearing.cage
    guide = float(cage.guide_land_diameter)
    tol = 0.5 * float(cage.guide_clearance)
    shown = f"{guide * 1e3:.6g} mm"
    if land:
        if abs(guide - surface) > tol:
            raise InputError(
                "cage.guide_land_diameter", shown,
                f"the land of the {side} ring that guides the cage (cage.guidance = "
                f"{cage.guidance!r}): {what} = {surface * 1e3:.6g} mm, within half the guide "
                f"clearance ({tol * 1e3:.6g} mm); no surface of the ring lies at {shown}")
    elif (guide >= surface) if side == "outer" else (guide <= surface):
        raise InputError(
            "cage.guide_land_diameter", shown,
            f"a land of the {side} ring that guides the cage (cage.guidance = "
            f"{cage.guidance!r}) {'below' if side == 'outer' else 'above'} {what}, "
            f"{surface * 1e3:.6g} mm: the ring's lands lie "
            f"{'inside' if side == 'outer' else 'outside'} its raceway")
    return guide


def _cage_bounds(bearing: Any, side: str) -> list[tuple[float, str]]:
    """The diameters [m] the cage must clear on the ``side`` ring, with what each is: the
    guide land first where that ring guides the cage (after :func:`_check_guide_land`),
    then the ring's surface nearest the cage (:func:`_ring_surface`)."""
    surface, what, land = _ring_surface(bearing, side)
    bounds = [(surface, what)]
    if bearing.cage.guidance == f"{side}_ring":
        guide = _check_guide_land(bearing, side, surface, what, land)
        bounds.insert(0, (guide, "cage.guide_land_diameter, the land it runs on"))
    return bounds


def _cage_land(bearing: Any, side: str) -> tuple[float, str]:
    """The diameter [m] the cage must clear on the ``side`` ("inner" | "outer") ring, the
    nearest of :func:`_cage_bounds` to the cage, and what it is."""
    pick = max if side == "inner" else min
    return pick(_cage_bounds(bearing, side), key=lambda b: b[0])


def _check_cage_between_rings(bearing: Any) -> None:
    """The cage runs between the rings clear of their surfaces: its bore above the inner
    ring's land (rib, shoulder) or raceway and its outside diameter below the outer ring's
    (:func:`_ring_surface`), and on the side of a ring-guided cage also clear of the guide
    land, which must be a surface of that ring (:func:`_check_guide_land`); else an
    InputError naming the cage field and the diameters. A cage across a land is a part that
    cannot be assembled (CRB_50x75x16 with ``ribbed_ring = "both"``: the 66 mm cage across
    the 65.515 mm bore of the outer ribs; D1842926 as estimated before: a 170 mm guide land
    beyond the 167.03 mm outer raceway and the 169.6 mm cage across it)."""
    cage = bearing.cage
    for bound, what in _cage_bounds(bearing, "inner"):
        if not cage.inner_diameter > bound:
            raise InputError("cage.inner_diameter", f"{cage.inner_diameter * 1e3:.6g} mm",
                             f"a bore above {bound * 1e3:.6g} mm, {what}: the cage would "
                             "cross the inner ring")
    for bound, what in _cage_bounds(bearing, "outer"):
        if not cage.outer_diameter < bound:
            raise InputError("cage.outer_diameter", f"{cage.outer_diameter * 1e3:.6g} mm",
                             f"an outside diameter below {bound * 1e3:.6g} mm, {what}: the "
                             "cage would cross the outer ring")


def _cage_ratio(gamma: Any) -> Any:
    """Epicyclic cage/inner-ring speed ratio (1 - gamma)/2 (outer ring fixed)."""
    return 0.5 * (1.0 - gamma)


def _frequencies(shaft_hz: float, gamma: float, n: int, pitch: float, element: float,
                 cage_slip: float, outer_hz: float) -> CharacteristicFrequencies:
    """Frequencies of an epicyclic set with cage slip (paper 004, f_bpo with (1 - s_c)).

    f_cage = (1 - s_c) [f_i (1 - gamma) + f_o (1 + gamma)] / 2; BPFO = Z |f_cage - f_o|;
    BPFI = Z |f_i - f_cage|; element spin relative to the cage from rolling on the outer race
    (which the cage slip leaves intact in paper 004's picture): f_spin = |f_cage - f_o| d_m
    (1 + gamma) / D; with s_c = 0 this is Harris's (d_m / 2D) f_i (1 - gamma^2).
    """
    check_range("cage_slip", cage_slip, -1.0, 1.0, low_inclusive=False, high_inclusive=False)
    check_positive("shaft_speed_hz", shaft_hz, allow_zero=True)
    cage = (1.0 - cage_slip) * 0.5 * (shaft_hz * (1.0 - gamma) + outer_hz * (1.0 + gamma))
    bpfo = n * abs(cage - outer_hz)
    bpfi = n * abs(shaft_hz - cage)
    spin = abs(cage - outer_hz) * pitch * (1.0 + gamma) / element
    return CharacteristicFrequencies(shaft_hz, cage, bpfo, bpfi, spin)


def _check_roughness(bearing: Any) -> None:
    """``raceway_roughness`` and ``element_roughness`` [m] (RMS, Rq): both given or both
    absent, each >= 0 and not both zero (the film parameter divides by their composite)."""
    r, e = bearing.raceway_roughness, bearing.element_roughness
    if r is None and e is None:
        return
    for name, value in (("raceway_roughness", r), ("element_roughness", e)):
        if value is None:
            raise InputError(f"bearing.{name}", None, "a value when the other surface's "
                             "roughness is given (RMS Rq [m])")
        check_positive(f"bearing.{name}", value, allow_zero=True)
    if r == 0.0 and e == 0.0:
        raise InputError("bearing.raceway_roughness", r, "a roughness > 0 on at least one "
                         "surface")

