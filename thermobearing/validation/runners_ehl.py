"""Validation runners of the numerical EHL solver.

``ehl_moes_line``: isothermal central film of the line-contact solver against the Moes (1992)
formula over a grid of Moes parameters M, L.

``paper001_tehl_film``: paper 001 (Shi & Wang 2015) D1842926 at 13218 r/min and 8/12/18/24 kN:
thermal EHL minimum film at the most loaded roller-inner race contact against the paper's
0.514/0.490/0.471/0.445 um, with Hamrock-Dowson beside it. The roller loads come from the
quasi-static roller load distribution of :mod:`thermobearing.loads_roller`
(Harris & Kotzalas 2007 vol. 1 ch. 7 with the roller centrifugal force at the epicyclic cage
speed, vol. 2 ch. 2).
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ValidityWarning
from ..units import to_si
from . import RUNNERS


@RUNNERS.register("ehl_moes_line", references=["moes1992", "venner_lubrecht2000"])
def ehl_moes_line(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Numerical central film (Richardson-extrapolated from n/2 and n) vs the Moes formula."""
    from ..ehl.line import moes_dimensionless, solve_dimensionless

    out: dict[str, float] = {}
    n = int(inputs.get("n", 1024))
    for M in inputs["M"]:
        for L in inputs["L"]:
            nn = n * (4 if M >= 300 else 1)
            sol = solve_dimensionless(float(M), float(L), n=nn)
            tag = f"M{M:g}_L{L:g}"
            h_num = 8.0 * M / math.pi * sol.central_film_extrapolated
            out[f"central_film_{tag}"] = h_num
            out[f"moes_{tag}"] = moes_dimensionless(float(M), float(L))
            out[f"ratio_{tag}"] = h_num / out[f"moes_{tag}"]
            out[f"grid_error_{tag}"] = sol.error_estimate
    return out


def most_loaded_inner_contact(bearing, radial_load: float, inner_speed: float) -> dict:
    """Most loaded roller-inner race contact: load [N], loaded rollers, entrainment [m/s].

    Load distribution by :func:`thermobearing.loads_roller.roller_load_distribution`
    (Palmgren contact stiffness from :func:`thermobearing.hertz.line_contact_stiffness`,
    roller centrifugal force from :func:`thermobearing.loads_roller.roller_body_force` at the
    epicyclic cage speed). Entrainment speed of the inner contact in pure rolling:
    ``u = (d_i/2)(omega_i - omega_c)``.
    """
    from ..hertz import line_contact_stiffness
    from ..loads_roller import roller_body_force, roller_load_distribution

    z = bearing.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    w_c = inner_speed * bearing.theoretical_cage_speed_ratio()
    length = bearing.roller_effective_length
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ValidityWarning)
        k = float(line_contact_stiffness(length, bearing.effective_modulus))
    body = roller_body_force(bearing.roller_mass, bearing.pitch_diameter, w_c, psi)
    dist = roller_load_distribution(z, bearing.diametral_clearance, radial_load, k, k,
                                    body_force=body, azimuth=psi)
    q = np.asarray(dist.inner_load)
    u = 0.5 * bearing.inner_raceway_diameter * (inner_speed - w_c)
    return {"load": float(q.max()), "loaded": float(np.count_nonzero(q > 0)),
            "entrainment_speed": float(u), "centrifugal_force": float(body[0])}


@RUNNERS.register(
    "paper001_tehl_film",
    references=["shi2015_tehl_roller", "yang_wen1990", "hamrock_dowson1977",
                "harris_kotzalas2007"],
)
def paper001_tehl_film(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Thermal-EHL minimum film of D1842926 (paper 001 Fig. 5) at the most loaded roller."""
    from ..ehl.thermal import SolidThermal, solve_thermal_line_contact
    from ..film import equivalent_ellipticity_of_roller, hamrock_dowson_1977_minimum
    from ..geometry import load_bearing
    from ..hertz import line_contact
    from ..lubricant import load_lubricant
    from ..materials import get_material

    bearing = load_bearing(inputs.get("bearing", "D1842926"))
    lub = load_lubricant(inputs.get("lubricant", "OIL_4109"))
    temp = to_si(inputs["temperature"], "temperature", field="temperature")
    w_i = to_si(inputs["inner_speed"], "angular_speed", field="inner_speed")
    srr = float(inputs.get("slide_to_roll", 0.0))
    n = int(inputs.get("n", 512))
    steel = SolidThermal.of(get_material(bearing.roller_material))
    rx, _ = bearing.curvature("inner")
    length = bearing.roller_effective_length
    e_prime = bearing.effective_modulus
    eta = float(lub.dynamic_viscosity(temp))
    alpha = float(lub.pressure_viscosity_coefficient(temp))
    out: dict[str, float] = {}
    mins = []
    for text in inputs["radial_loads"]:
        f_r = to_si(text, "force", field="radial_loads")
        tag = f"{f_r / 1000:g}kN"
        c = most_loaded_inner_contact(bearing, f_r, w_i)
        sol = solve_thermal_line_contact(c["load"] / length, rx, e_prime,
                                         c["entrainment_speed"], srr, lub, temp,
                                         solid1=steel, n=n)
        lc = line_contact(c["load"], length, rx, e_prime)
        k_eq = float(equivalent_ellipticity_of_roller(lc.half_width, length))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            h_hd = float(hamrock_dowson_1977_minimum(
                c["entrainment_speed"], eta, alpha, c["load"], rx, ellipticity=k_eq,
                effective_modulus=e_prime))
        out[f"tehl_min_{tag}"] = sol.minimum_film
        out[f"tehl_central_{tag}"] = sol.central_film
        out[f"isothermal_min_{tag}"] = sol.isothermal.minimum_film
        out[f"hamrock_dowson_min_{tag}"] = h_hd
        out[f"hd_minus_tehl_min_{tag}"] = h_hd - sol.minimum_film
        out[f"max_temperature_rise_{tag}"] = sol.max_temperature - temp
        out[f"max_roller_load_{tag}"] = c["load"]
        out[f"loaded_rollers_{tag}"] = c["loaded"]
        out[f"M_{tag}"] = sol.isothermal.M
        out[f"L_{tag}"] = sol.isothermal.L
        out["entrainment_speed"] = c["entrainment_speed"]
        mins.append(sol.minimum_film)
    out["tehl_min_falls_with_load"] = float(all(a > b for a, b in zip(mins, mins[1:],
                                                                      strict=False)))
    return out
