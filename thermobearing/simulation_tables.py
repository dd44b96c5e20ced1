"""Rows of the result tables of a run: the columns that identify an operating step, the
kinematics columns of a solved state, and the contact / film table of film-only scenes
(closed-form, or the numerical film model beside it).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from .kinematic_models import KinematicsResult, contact_temperature
from .operating_checks import check_state, composite_roughness
from .scene import Step
from .simulation_bearings import _Bearing
from .state import OperatingPoint
from .units import from_si


def step_columns(index: int, time_s: float | None, bearing: str, step: Step,
                 record: _Bearing | None = None) -> dict[str, Any]:
    """The columns that identify one operating step in the tables (the loads are those of
    the bearing ``record`` when given: its ``load_share`` of the schedule's).

    ``time_s`` [s]: the time of the row in a transient run; None for an operating point
    that has no time (steady runs, losses / kinematics / film at the initial
    temperature): no ``time [s]`` column then (it was written as 0 s).

    The speed is the step's set value converted from rad/s to r/min and rounded to
    :data:`SET_VALUE_DIGITS` significant digits: the conversion's round-off (1500 r/min
    read back as ``1500.0000000000002``) is not part of the value a user set."""
    radial, axial = ((step.radial_load, step.axial_load) if record is None
                     else record.loads(step))
    timed = {} if time_s is None else {"time [s]": time_s}
    return {"step": index, **timed, "bearing": bearing,
            "speed [rpm]": set_value(from_si(step.speed, "rpm")),
            "radial load [kN]": radial / 1e3,
            "axial load [kN]": axial / 1e3}


def operating_columns(step: Step) -> dict[str, float]:
    """The schedule step's operating point as table columns: ``speed [rpm]`` (a set value,
    :func:`set_value`), ``radial load [kN]``, ``axial load [kN]`` (the schedule's, i.e. the
    shaft's loads; the per-bearing tables give each bearing's share). A steady run's
    ``steady_temperatures`` rows carry them: without, a row named only its step and the
    operating point had to be looked up in the scene's protocol."""
    return {"speed [rpm]": set_value(from_si(step.speed, "rpm")),
            "radial load [kN]": step.radial_load / 1e3,
            "axial load [kN]": step.axial_load / 1e3}


#: significant digits of a set value (speed) written to the tables: far more than any
#: rig sets, far fewer than the 15-17 at which unit-conversion round-off shows
SET_VALUE_DIGITS = 12


def set_value(x: float) -> float:
    """``x`` rounded to :data:`SET_VALUE_DIGITS` significant digits (non-finite values and
    zero unchanged)."""
    x = float(x)
    if not math.isfinite(x) or x == 0.0:
        return x
    return float(f"{x:.{SET_VALUE_DIGITS}g}")


#: over-skidding [%] below which (in magnitude) the table writes 0: a cage speed ratio
#: equal to its theoretical value to 1e-9, the skidding solvers' tolerance on their scaled
#: residual. Race control on a deep-groove 6206 wrote -1.11e-14 % (the double round-off of
#: CSR / CSR_th - 1 where the two are equal)
OVER_SKID_FLOOR = 1e-7
#: load-weighted contact angle [deg] below which the table writes 0: 1.7e-8 rad, an axial
#: offset of the ball of ~1e-11 m between groove centres 0.4 mm apart. A 6206 without axial
#: load (0 deg by symmetry) wrote 1.9e-15 deg (skidding solver) and 2e-10 to 8e-8 deg (race
#: control: its load distribution's tolerance, 1 N to 20 kN radial); 1 mN of axial load
#: against 2 kN radial gives 2.5e-5 deg, well above the floor
CONTACT_ANGLE_FLOOR = 1e-6


def zero_below(x: float, floor: float) -> float:
    """``x``, or 0.0 where ``|x| < floor`` (solver noise around a value that is zero; NaN
    unchanged)."""
    return 0.0 if abs(x) < floor else x


def over_skidding_range(kin: pd.DataFrame, checks: Mapping[str, Any]
                        ) -> tuple[float, float] | None:
    """Largest and smallest over-skidding [%], 100 (CSR / CSR_th - 1), of every solved
    state of a run: the kinematics table's rows (each step's first state) and the states
    re-solved within a step as the temperatures moved, which the run's operating checks
    record (``checks``: bearing -> :class:`.operating_checks.CheckLog`) and whose worst
    their warnings name. None when the table has no over-skidding (kinematics ``"none"``,
    every step at rest). The default rig's step 2 starts at +8.72 % and reaches +8.78 %;
    an NU 214 at 8000 r/min starts at -37.8 % and skids to -44.7 % as its oil warms."""
    table = kin["over-skidding [%]"].to_numpy(dtype=float) if "over-skidding [%]" in kin \
        else np.array([])
    table = table[np.isfinite(table)]
    if table.size == 0:
        return None
    states = [zero_below(100.0 * (c.csr / c.csr_th - 1.0), OVER_SKID_FLOOR)
              for log in checks.values() for cs in log.steps.values() for c in cs
              if math.isfinite(c.csr) and c.csr_th > 0.0]
    values = np.concatenate([table, np.asarray(states, dtype=float)])
    values = values[np.isfinite(values)]
    return float(values.max()), float(values.min())


def kinematics_columns(kin: KinematicsResult, bearing: Any) -> dict[str, Any]:
    """Kinematics table columns of one result, with the largest Hertz pressure and the
    smallest film parameter of its loaded contacts (:mod:`.operating_checks`; NaN when
    the bearing gives no roughness).

    Over-skidding below :data:`OVER_SKID_FLOOR` and contact angles below
    :data:`CONTACT_ANGLE_FLOOR` are written as 0 (solver noise around a value zero by
    symmetry; every other value as computed). ``residual [-]``: the skidding solver's
    residual norm, its force and moment balances over its force scale (dimensionless; 0
    for race control and "none", which iterate on no balance); ``iterations [-]``: its
    iteration count."""
    check = check_state(bearing, kin)
    angles = {k: zero_below(v, CONTACT_ANGLE_FLOOR)
              for k, v in contact_angle_columns(kin, bearing).items()}
    return {"cage speed ratio [-]": kin.cage_speed_ratio,
            "theoretical cage speed ratio [-]": kin.theoretical_cage_speed_ratio,
            "over-skidding [%]": zero_below(100.0 * kin.over_skid, OVER_SKID_FLOOR),
            **angles,
            # a state without contact sets (kinematics "none": the global friction model
            # solves no contacts) has no contact pressure to report, not 0 MPa
            "max contact pressure [MPa]": (check.max_pressure / 1e6 if kin.state.contacts
                                           else math.nan),
            "min film parameter [-]": (math.nan if check.film_parameter is None
                                       else check.film_parameter),
            "converged": kin.converged, "residual [-]": kin.residual_norm,
            "iterations [-]": kin.iterations}


def contact_angle_columns(kin: KinematicsResult, bearing: Any) -> dict[str, float]:
    """Load-weighted mean contact angle of the inner and of the outer raceway [deg] of a
    ball bearing's state: sum(Q alpha) / sum(Q) over every loaded contact of the ring (both
    arcs of a gothic-arch ring). At speed the balls' centrifugal force turns the outer
    angle down and the inner one up, which is what lifts the rolling cage speed ratio
    above CSR_th in angular-contact bearings. NaN for a ring with no loaded contact (above
    1 uN; race control without load on that ring); no columns for roller
    bearings (their raceway contacts have no contact angle)."""
    if not hasattr(bearing, "ball_diameter"):
        return {}
    out = {}
    # a contact counts as loaded above 1 uN: contacts of an unloaded state carry round-off
    # loads (3e-10 N under race control without load), whose angles mean nothing
    floor = 1e-6
    for ring in ("inner", "outer"):
        q_sum = qa_sum = 0.0
        for cs in kin.state.contacts:
            if cs.race.split("_")[0] != ring or cs.contact_angle is None:
                continue
            q = np.asarray(cs.normal_load, float)
            a = np.broadcast_to(np.asarray(cs.contact_angle, float), q.shape)
            loaded = q > floor
            q_sum += float(np.sum(q[loaded]))
            qa_sum += float(np.sum(q[loaded] * np.abs(a[loaded])))
        out[f"{ring} contact angle [deg]"] = (math.degrees(qa_sum / q_sum) if q_sum > 0
                                              else math.nan)
    return out


def film_table(b: _Bearing, lubricant: Any, step: Step,
               temps: Mapping[str, float]) -> tuple[list[dict[str, Any]], float]:
    """Contact and film of the most loaded element per raceway (film-only scenes): race
    control at the contacts' inlet oil temperature
    (:func:`~thermobearing.kinematic_models.contact_temperature`, as the kinematics of a
    run). Returns the rows and the state's cage speed ratio [-]."""
    from .state import race_control_state

    radial, axial = b.operating_loads(step)
    op = OperatingPoint(inner_speed=step.speed, radial_load=radial, axial_load=axial)
    t_c = contact_temperature(temps)
    state = race_control_state(b.bearing, op, lubricant=lubricant, temperature=t_c)
    rows = []
    numerical = _numerical_film_of(b, lubricant)
    for cs in state.contacts:
        q = np.asarray(cs.normal_load)
        j = int(np.argmax(q))
        extra: dict[str, Any] = {}
        # no element touches this raceway (an unloaded inner ring: the centrifugal force
        # holds the balls on the outer one): no contact, so no film -- left empty, not 0 um
        # (Lambda 0 flagged boundary lubrication of a contact that does not exist)
        touching = float(q[j]) > 0.0
        if numerical is not None and touching:
            extra = numerical(cs.race, float(q[j]),
                              float(np.asarray(cs.entrainment_speed)[j]), t_c)
        rows.append({"race": cs.race, "max load [N]": float(q[j]),
                     "max pressure [GPa]": float(np.asarray(cs.max_pressure)[j]) / 1e9,
                     "semi-major a [mm]": float(np.asarray(cs.semi_major)[j]) * 1e3,
                     "semi-minor b [mm]": float(np.asarray(cs.semi_minor)[j]) * 1e3,
                     "contact angle [deg]": math.degrees(float(np.asarray(cs.contact_angle)[j])),
                     "entrainment speed [m/s]": float(np.asarray(cs.entrainment_speed)[j]),
                     "central film [um]": (float(np.asarray(cs.film_thickness)[j]) * 1e6
                                           if cs.film_thickness is not None and touching
                                           else math.nan)})
        if extra:
            row = rows[-1]
            row["closed-form central film [um]"] = row["central film [um]"]
            row["central film [um]"] = extra["numerical central film [um]"]
            row["minimum film [um]"] = extra["numerical minimum film [um]"]
            row["film model"] = extra["film model"]
        sigma = composite_roughness(b.bearing)
        if sigma is not None:  # Lambda of the film the row reports (operating_checks)
            row = rows[-1]
            h = row.get("minimum film [um]", row["central film [um]"])
            row["film parameter [-]"] = h * 1e-6 / sigma
    csr = state.cage_speed / state.inner_speed if state.inner_speed else math.nan
    return rows, float(csr)


def _numerical_film_of(b: _Bearing, lubricant: Any) -> Any:
    """For film-only scenes with a numerical film model: ``f(race, load, u_e, T) -> columns``
    (central and minimum film of the numerical model at pure rolling, the closed-form
    central film beside it), else None."""
    model = b.kin_options.get("film_model")
    drag = b.kin_options.get("drag_model")
    if model is None and drag != "numerical_ehl":
        return None
    bearing = b.bearing
    length = bearing.roller_effective_length
    e_prime = bearing.effective_modulus

    def columns(race: str, load: float, ue: float, temperature: float) -> dict[str, Any]:
        rx, _ = bearing.curvature(race)
        w = load / length
        if model is not None:
            res = model.films(w, ue, 0.0, temperature, rx, e_prime)
            hc, hm = float(res.central_film[0]), float(res.minimum_film[0])
            name = "numerical_tehl"
        else:
            from .ehl import EHL_SOLVERS

            p = EHL_SOLVERS.get("numerical_ehl")(w, rx, e_prime, ue, 0.0, temperature,
                                                 lubricant=lubricant)
            hc, hm, name = p.central_film, p.minimum_film, "numerical_ehl"
        return {"film model": name, "numerical central film [um]": hc * 1e6,
                "numerical minimum film [um]": hm * 1e6}

    return columns


def rib_columns(bearing: Any, details: Mapping[str, Any]) -> dict[str, Any]:
    """One ``rib`` table row: the rib_friction source's numbers of one heat evaluation
    (``HeatResult.details``, :mod:`thermobearing.heat_sources.rib` "Details"), the ones the
    heat was computed from, in the tables' units:

    ``rib model`` (coupled | reduced: the model that booked the heat), ``roller dynamics``
    (coupled | reduced | none), ``friction coefficient [-]``, ``elements temperature
    [degC]`` (where the models ran); the thrust share: ``thrust normal force [N]`` per
    roller, its Hertz ``thrust max pressure [MPa]`` and ``thrust contact area [mm^2]``
    (:func:`~thermobearing.heat_sources.rib.thrust_contact`, pi a b), ``thrust slide speed
    [m/s]`` (roller mean |v_i - v_r|), ``thrust PV [MPa m/s]`` (pressure x slide speed) and
    ``thrust heat [W]`` (all rollers; = Z mu Q |v| = Z mu (2/3) area x PV); ``drag heat [W]``
    (the lubricant drag of eq. 14 where no dynamics ran; empty where they did: their face
    heats hold it); the dynamics' per end face (right: the unbalance's side) ``left / right
    face PV [MPa m/s]`` (time- and roller-mean P |v|, paper 003 eqs. 21-24) and ``left /
    right face heat [W]`` (all rollers), ``rib slide speed [m/s]``, ``dynamics orbits [-]``
    (empty without dynamics); ``slip speed [m/s]`` (eq. 25, the dynamics' time mean, else
    the kinematic state's); ``rib heat [W]`` (the source's power: thrust + drag + both
    faces + the outer rib) and ``heat to rollers [-]`` (the inner rib's share to the
    "elements" role). A bearing ribbed on both rings under an axial load (NJ / NUP) also
    presses the outer rib: ``outer rib slide speed [m/s]`` (roller mean |v_o|) and ``outer
    rib heat [W]`` (all rollers, its own loss component; :mod:`thermobearing.rib_outer`),
    empty otherwise."""
    from .heat_sources.rib import thrust_contact
    from .rib import rib_geometry

    d = details
    q = float(d.get("thrust_normal_force", 0.0))
    pressure, area = thrust_contact(rib_geometry(bearing), q)
    slide = float(d.get("thrust_slide_speed", math.nan))
    dyn = d.get("dynamics", "none") != "none"

    def dynamic(key: str, scale: float = 1.0) -> float:
        return float(d[key]) * scale if dyn and key in d else math.nan

    temperature = d.get("temperature")
    return {"rib model": d.get("model", ""), "roller dynamics": d.get("dynamics", ""),
            "friction coefficient [-]": float(d.get("friction_coefficient", math.nan)),
            "elements temperature [degC]": (math.nan if temperature is None
                                            else float(temperature) - 273.15),
            "thrust normal force [N]": q,
            "thrust max pressure [MPa]": pressure / 1e6,
            "thrust contact area [mm^2]": area * 1e6,
            "thrust slide speed [m/s]": slide,
            "thrust PV [MPa m/s]": pressure * slide / 1e6,
            "thrust heat [W]": float(d.get("thrust_heat", math.nan)),
            "outer rib slide speed [m/s]": float(d.get("outer_thrust_slide_speed", math.nan)),
            "outer rib heat [W]": float(d.get("outer_thrust_heat", math.nan)),
            "drag heat [W]": math.nan if dyn else float(d.get("drag_heat", math.nan)),
            "left face PV [MPa m/s]": dynamic("pv_left", 1e-6),
            "right face PV [MPa m/s]": dynamic("pv_right", 1e-6),
            "left face heat [W]": dynamic("heat_left"),
            "right face heat [W]": dynamic("heat_right"),
            "rib slide speed [m/s]": dynamic("rib_slide_speed"),
            "dynamics orbits [-]": dynamic("dynamics_orbits"),
            "slip speed [m/s]": float(d.get("slip_speed", math.nan)),
            "rib heat [W]": float(d.get("total_heat", math.nan)),
            "heat to rollers [-]": float(d.get("element_share", math.nan))}


#: the tables of heat-source details a run writes beside its losses: source -> (table,
#: row function of (bearing, ``HeatResult.details``))
DETAIL_TABLES = {"rib_friction": ("rib", rib_columns)}
