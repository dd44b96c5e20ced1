"""Validation runner for the closed-form film case of paper 001.

``paper001_film_closed_form``: Hamrock-Dowson (1977) and Dowson-Higginson minimum films at the
most loaded roller-inner race contact of the D1842926 preset, 8/12/18/24 kN, 13218 r/min, oil
4109, printed beside paper 001's TEHL minimum films 0.514/0.490/0.471/0.445 um (its Fig. 5).

Paper 001's Fig. 4 (roller loads and entrainment speeds from the quasi-dynamic analysis of its
Ref. 23) is only a plot; the loads are therefore recomputed here with a quasi-static roller
load distribution (rigid rings, Palmgren contact law, diametral clearance, roller centrifugal
force at the epicyclic cage speed; Harris & Kotzalas 2007 vol. 1 ch. 7) -- see SOURCE.md.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from typing import Any

import numpy as np
from scipy.optimize import brentq

from ..errors import ConvergenceError, ValidityWarning
from ..film import (
    dowson_higginson_minimum,
    equivalent_ellipticity_of_roller,
    hamrock_dowson_1977_minimum,
    pan_hamrock_minimum,
    wilson_sheu_1983,
)
from ..geometry import RollerBearing, load_bearing
from ..hertz import line_contact, palmgren_approach
from ..lubricant import load_lubricant
from ..units import to_si
from . import RUNNERS


def _roller_loads(bearing: RollerBearing, radial_load: float, inner_speed: float
                  ) -> tuple[np.ndarray, np.ndarray, float]:
    """Inner-contact roller loads [N] at the azimuths psi_j (psi = 0 most loaded).

    Rigid rings displaced by delta_r; roller j closes the gap delta_r cos(psi_j) - P_d/2 with
    Palmgren approaches at both contacts, delta_i(Q_i) + delta_o(Q_i + F_c) (outer contact also
    carries the centrifugal force F_c = m d_m w_c^2 / 2 of an epicyclic cage); radial balance
    sum Q_i cos(psi) = F_r solved for delta_r.
    """
    z = bearing.n_rollers
    psi = 2.0 * math.pi * np.arange(z) / z
    length = bearing.roller_effective_length
    w_c = inner_speed * bearing.theoretical_cage_speed_ratio()
    f_c = 0.5 * bearing.roller_mass * bearing.pitch_diameter * w_c**2
    c_half = 0.5 * bearing.diametral_clearance
    base = float(palmgren_approach(f_c, length))  # outer approach of an unloaded roller

    def q_inner(gap: float) -> float:
        if gap <= 0.0:
            return 0.0
        def f(q: float) -> float:
            return float(palmgren_approach(q, length) + palmgren_approach(q + f_c, length)) - (
                gap + base)
        hi = 1.0
        while f(hi) < 0:
            hi *= 2.0
        return brentq(f, 0.0, hi, xtol=1e-9)

    def loads(delta_r: float) -> np.ndarray:
        return np.array([q_inner(delta_r * c - c_half) for c in np.cos(psi)])

    def balance(delta_r: float) -> float:
        return float(np.sum(loads(delta_r) * np.cos(psi))) - radial_load

    hi = c_half + 1e-6
    while balance(hi) < 0:
        hi *= 1.5
        if hi > 1e-2:
            raise ConvergenceError("roller load distribution", balance(hi),
                                   "no displacement balances the load")
    delta_r = brentq(balance, c_half, hi, xtol=1e-14)
    return loads(delta_r), psi, f_c


@RUNNERS.register("paper001_film_closed_form",
                  references=["shi2015_tehl_roller", "hamrock_dowson1977",
                              "dowson_higginson1966", "pan_hamrock1989", "wilson_sheu1983",
                              "palmgren1959"])
def paper001_film_closed_form(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Closed-form minimum films at the most loaded inner contact of D1842926 (paper 001)."""
    bearing = load_bearing(inputs.get("bearing", "D1842926"))
    lub = load_lubricant(inputs.get("lubricant", "OIL_4109"))
    temp = to_si(inputs["temperature"], "temperature", field="temperature")
    w_i = to_si(inputs["inner_speed"], "angular_speed", field="inner_speed")
    eta = float(lub.dynamic_viscosity(temp))
    alpha = float(lub.pressure_viscosity_coefficient(temp))
    beta = float(inputs.get("temperature_viscosity_coefficient", 0.032))
    k_f = float(lub.thermal_conductivity(temp))
    e_prime = bearing.effective_modulus
    rx, _ = bearing.curvature("inner")
    length = bearing.roller_effective_length
    csr = bearing.theoretical_cage_speed_ratio()
    u = 0.5 * (1.0 - csr) * w_i * (bearing.pitch_diameter - bearing.roller_diameter)
    out: dict[str, float] = {"entrainment_speed": u, "viscosity": eta}
    for text in inputs["radial_loads"]:
        f_r = to_si(text, "force", field="radial_loads")
        tag = f"{f_r / 1000:g}kN"
        q, _, f_c = _roller_loads(bearing, f_r, w_i)
        q_max = float(np.max(q))
        lc = line_contact(q_max, length, rx, e_prime)
        k_eq = float(equivalent_ellipticity_of_roller(lc.half_width, length))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ValidityWarning)  # outside the fits: that is the point
            h_hd = float(hamrock_dowson_1977_minimum(
                u, eta, alpha, q_max, rx, ellipticity=k_eq, effective_modulus=e_prime))
            h_dh = float(dowson_higginson_minimum(u, eta, alpha, q_max, length, rx,
                                                  effective_modulus=e_prime))
            h_ph = float(pan_hamrock_minimum(u, eta, alpha, q_max, length, rx,
                                             effective_modulus=e_prime))
            phi = float(wilson_sheu_1983(u, eta, beta, k_f, slide_to_roll=0.0))
        out[f"max_roller_load_{tag}"] = q_max
        out[f"loaded_rollers_{tag}"] = float(np.count_nonzero(q > 0))
        out[f"hamrock_dowson_min_{tag}"] = h_hd
        out[f"dowson_higginson_min_{tag}"] = h_dh
        out[f"pan_hamrock_min_{tag}"] = h_ph
        out[f"hamrock_dowson_wilson_sheu_min_{tag}"] = h_hd * phi
        out["roller_centrifugal_force"] = f_c
        out["wilson_sheu_factor"] = phi
    return out
