"""PV and slip maps of paper 003 Figs. 7-12 with the roller dynamics.

Zhang et al. 2021, seed ``003_743e023ae6e45686.txt`` [zhang2021_abnormal_wear], secs. 9-10;
model in :mod:`thermobearing.skidding.roller_dynamics`. Units: SI.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import InputError, check_positive
from .roller_dynamics_integrate import simulate
from .roller_dynamics_setup import build_model

#: map parameters of paper 003 Figs. 7-12 and their SI units
MAP_PARAMETERS = {"radial_load": "N", "speed": "rad/s", "axial_clearance": "m",
                  "pocket_clearance": "m", "rib_angle": "rad", "crown_radius": "m"}

#: paper 003 base case (sec. 9-10): 30000 r/min, 3000 N, C_a 0.03 mm, pocket 0.2 mm,
#: rib angle 0.3 deg, end-face crown radius 300 mm
PAPER003_BASE = {"speed": 30000.0 * math.pi / 30.0, "radial_load": 3000.0,
                 "axial_clearance": 0.03e-3, "pocket_clearance": 0.2e-3,
                 "rib_angle": math.radians(0.3), "crown_radius": 0.3}


def pv_slip_map(bearing: Any, lubricant: Any, parameter: str, values: Any,
                unbalance_masses: Any, *, base: dict[str, float] | None = None,
                model: str = "reduced", temperature: float = 353.15,
                cache: dict | None = None, end_face: str = "sphere",
                slide: str = "offset", coupled_options: dict[str, Any] | None = None,
                on_row: Any = None, **model_options: Any) -> list[dict[str, float]]:
    """PV and slip of the base case with ``parameter`` swept over ``values`` (SI).

    One row per (value, unbalance mass): the :class:`RollerResponse` fields (pv_left,
    pv_right [Pa m/s], slip_speed [m/s], ...). ``base`` overrides :data:`PAPER003_BASE`.
    ``cache`` (a dict) keeps the quasi-static skidding solutions by (speed, load).
    ``end_face``: "sphere" (paper 003 eqs. 1, 11) or "cap" (:mod:`thermobearing.rib`).
    ``slide``: "offset" or "radial_plane" (:class:`thermobearing.rib.RibGeometry`).
    ``model``: "reduced", "full" (one roller) or "coupled" (all rollers + cage,
    :func:`~thermobearing.skidding.roller_dynamics_coupled.simulate_coupled`, ~1.5 s CPU/point;
    ``coupled_options`` its keyword options, e.g. ``n_orbits``, ``warmup_orbits``).
    ``on_row``: called with each row as soon as it is computed (a caller writes it out, so
    an interrupted map keeps its finished points).
    """
    if parameter not in MAP_PARAMETERS:
        raise InputError("parameter", parameter, tuple(MAP_PARAMETERS))
    cfg = dict(PAPER003_BASE)
    cfg.update(base or {})
    check_map_points(bearing, parameter, values, unbalance_masses, cfg, end_face=end_face,
                     slide=slide)
    cache = {} if cache is None else cache
    rows = []
    for value in np.atleast_1d(np.asarray(values, float)):
        point = dict(cfg)
        point[parameter] = float(value)
        key = (round(point["speed"], 6), round(point["radial_load"], 6))
        for mass in np.atleast_1d(np.asarray(unbalance_masses, float)):
            m = build_model(
                bearing, lubricant, point["speed"], point["radial_load"], float(mass),
                temperature=temperature, pocket_clearance=point["pocket_clearance"],
                rib={"axial_clearance": point["axial_clearance"],
                     "rib_angle": point["rib_angle"], "crown_radius": point["crown_radius"],
                     "end_face": end_face, "slide": slide},
                quasi_static=cache.get(key), **model_options)
            cache[key] = m.extras["quasi_static"]
            if model == "coupled":
                from .roller_dynamics_coupled import simulate_coupled

                r = simulate_coupled(m, bearing, lubricant, **(coupled_options or {}))
            else:
                r = simulate(m, model)
            rows.append({"parameter": parameter, "value": float(value),
                         "unbalance_mass": float(mass), "pv_left": r.pv_left,
                         "pv_right": r.pv_right, "pv_peak_left": r.pv_peak_left,
                         "pv_peak_right": r.pv_peak_right, "pv_contact_left": r.pv_contact_left,
                         "pv_contact_right": r.pv_contact_right,
                         "contact_slide_speed": r.contact_slide_speed,
                         "slip_speed": r.slip_speed,
                         "rolling_slip_speed": r.rolling_slip_speed,
                         "surface_slip_speed": r.surface_slip_speed,
                         "max_skew": r.max_skew, "rib_contact_fraction": r.rib_contact_fraction,
                         "rib_heat": r.rib_heat, "cost_s": r.cost_s,
                         "pocket_friction_extra": r.pocket_friction_extra,
                         "bar_contact_fraction": r.bar_contact_fraction,
                         "cage_speed": (float(np.mean(r.series["cage_speed"]))
                                        if model == "coupled" else m.cage_speed)})
            if on_row is not None:
                on_row(rows[-1])
    return rows


def check_map_points(bearing: Any, parameter: str, values: Any, unbalance_masses: Any,
                     cfg: dict[str, float], *, end_face: str = "sphere",
                     slide: str = "offset") -> None:
    """Check every point of a map before the first solve (a bad value at the end of a long
    map must not surface after minutes of work): speed > 0, radial load >= 0, pocket
    clearance >= 0, the rib geometry of every (axial clearance, rib angle, crown radius)
    (:class:`thermobearing.rib.RibGeometry`: e.g. a rib angle that puts the end-face contact
    off the roller) and every unbalance mass (0 <= m_u < roller mass).
    InputError names the field and the value as given (SI)."""
    from ..rib import rib_geometry, unbalance_check

    for value in np.atleast_1d(np.asarray(values, float)):
        point = dict(cfg)
        point[parameter] = float(value)
        check_positive("speed", point["speed"])
        check_positive("radial_load", point["radial_load"], allow_zero=True)
        check_positive("pocket_clearance", point["pocket_clearance"], allow_zero=True)
        rib_geometry(bearing, axial_clearance=point["axial_clearance"],
                     rib_angle=point["rib_angle"], crown_radius=point["crown_radius"],
                     end_face=end_face, slide=slide)
    for mass in np.atleast_1d(np.asarray(unbalance_masses, float)):
        unbalance_check(float(mass), bearing.roller_mass)
