"""Validation runners of the numerical EHL solver.

``ehl_moes_line``: isothermal central film of the line-contact solver against the Moes (1992)
formula over a grid of Moes parameters M, L.

``paper001_tehl_film``: paper 001 (Shi & Wang 2015) D1842926 at 13218 r/min and 8/12/18/24 kN:
minimum film at the most loaded roller-inner race contact of the integrated quasi-dynamic +
thermal-EHL chain (:func:`thermobearing.ehl.coupling.solve_roller_tehl`: the roller skidding
solve of paper 000 whose contact films and rolling forces come from the thermal-EHL table)
against the paper's 0.514/0.490/0.471/0.445 um, with Hamrock-Dowson beside it. The
quasi-static roller load of :mod:`thermobearing.loads_roller` (Harris & Kotzalas 2007 vol. 1
ch. 7 with the roller centrifugal force at the epicyclic cage speed, vol. 2 ch. 2) is
reported beside the chain's.
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
                "harris_kotzalas2007", "li2018_nu214_skidding"],
)
def paper001_tehl_film(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Minimum film of D1842926 (paper 001 Fig. 5) from the integrated quasi-dynamic +
    thermal-EHL chain (:func:`thermobearing.ehl.coupling.solve_roller_tehl`), one film table
    shared by the loads, at the most loaded roller-inner (and roller-outer) race contact of
    the solved state; Hamrock-Dowson, the isothermal numerical film and the quasi-static
    roller load beside it."""
    from ..ehl.cache import numerical_ehl
    from ..ehl.coupling import roller_film_model, solve_roller_tehl
    from ..ehl.line import line_contact_case
    from ..film import equivalent_ellipticity_of_roller, hamrock_dowson_1977_minimum
    from ..geometry import load_bearing
    from ..hertz import line_contact
    from ..lubricant import load_lubricant

    bearing = load_bearing(inputs.get("bearing", "D1842926"))
    lub = load_lubricant(inputs.get("lubricant", "OIL_4109"))
    temp = to_si(inputs["temperature"], "temperature", field="temperature")
    w_i = to_si(inputs["inner_speed"], "angular_speed", field="inner_speed")
    n = int(inputs.get("n", 512))
    length = bearing.roller_effective_length
    e_prime = bearing.effective_modulus
    eta = float(lub.dynamic_viscosity(temp))
    alpha = float(lub.pressure_viscosity_coefficient(temp))
    fm = roller_film_model(bearing, lub, n=n)  # one table for every load
    out: dict[str, float] = {}
    mins = []
    for text in inputs["radial_loads"]:
        f_r = to_si(text, "force", field="radial_loads")
        tag = f"{f_r / 1000:g}kN"
        res = solve_roller_tehl(bearing, lub, w_i, f_r, 0.0, temp, film_model=fm)
        for race, suffix in (("inner", ""), ("outer", "_outer")):
            c = _most_loaded(fm, res, race, temp, e_prime)
            out[f"tehl_min{suffix}_{tag}"] = c["minimum_film"]
            out[f"tehl_central{suffix}_{tag}"] = c["central_film"]
            out[f"max_roller_load{suffix}_{tag}"] = c["load"]
            out[f"slide_to_roll{suffix}_{tag}"] = c["slide_to_roll"]
            if race == "inner":
                inner = c
        rx = float(res.extras["radius_inner"])
        q, u = inner["load"], inner["entrainment_speed"]
        lc = line_contact(q, length, rx, e_prime)
        k_eq = float(equivalent_ellipticity_of_roller(lc.half_width, length))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)
            h_hd = float(hamrock_dowson_1977_minimum(u, eta, alpha, q, rx, ellipticity=k_eq,
                                                     effective_modulus=e_prime))
            iso = numerical_ehl(q / length, rx, e_prime, u, 0.0, temp, lubricant=lub, n=n)
        case = line_contact_case(q / length, rx, e_prime, u, eta,
                                 roelands_z=float(lub.roelands_index(temp)))
        out[f"isothermal_min_{tag}"] = iso.minimum_film
        out[f"hamrock_dowson_min_{tag}"] = h_hd
        out[f"hd_minus_tehl_min_{tag}"] = h_hd - inner["minimum_film"]
        out[f"max_temperature_rise_{tag}"] = inner["max_temperature_rise"]
        out[f"loaded_rollers_{tag}"] = float(np.count_nonzero(np.asarray(res.inner_load) > 0))
        out[f"quasi_static_roller_load_{tag}"] = most_loaded_inner_contact(
            bearing, f_r, w_i)["load"]
        out[f"cage_sliding_ratio_{tag}"] = float(res.slip)
        out[f"M_{tag}"] = case.M
        out[f"L_{tag}"] = case.L
        out[f"entrainment_speed_{tag}"] = u
        out["entrainment_speed"] = u
        mins.append(inner["minimum_film"])
    out["tehl_min_falls_with_load"] = float(all(a > b for a, b in zip(mins, mins[1:],
                                                                      strict=False)))
    return out


def _most_loaded(fm: Any, res: Any, race: str, temperature: float,
                 effective_modulus: float) -> dict[str, float]:
    """Load [N], entrainment speed [m/s], slide-to-roll ratio and the table's films [m] and
    temperature rise [K] of the most loaded contact of one race of a solved roller state
    (:meth:`thermobearing.ehl.coupling.TehlFilmModel.films`: the same answer the solve
    balanced, every node solved). ConvergenceError when that film is not the thermal table's
    (a contact sliding beyond the table's slide-to-roll range or failed table nodes)."""
    from ..errors import ConvergenceError

    q = np.asarray(getattr(res, f"{race}_load"), dtype=float)
    j = int(np.argmax(q))
    u = abs(float(np.asarray(getattr(res, f"{race}_entrainment_speed"))[j]))
    srr = float(np.asarray(getattr(res, f"{race}_sliding_speed"))[j]) / u
    films = fm.films(np.array([q[j] / res.extras["contact_length"]]), np.array([u]),
                     np.array([srr]), temperature, float(res.extras[f"radius_{race}"]),
                     effective_modulus)
    if not bool(films.numerical[0]):
        raise ConvergenceError(
            "paper001_tehl_film", float(srr),
            f"the most loaded {race} contact's film is not the thermal table's (slide-to-roll "
            "ratio beyond the table or failed table nodes)", {"load": float(q[j])})
    return {"load": float(q[j]), "entrainment_speed": u, "slide_to_roll": srr,
            "minimum_film": float(films.minimum_film[0]),
            "central_film": float(films.central_film[0]),
            "max_temperature_rise": float(films.max_temperature_rise[0])}
