"""Validation runner of the roller-bearing skidding solver (paper 000, NU214 with whirl).

Case ``paper000_nu214_cage_speed``: Li et al. 2018 (seed ``000_3b5ca6eed61dd596.txt``)
Tables 2-3 (cage speed min/max/mean/fluctuation and slip at n_i = 5000 r/min, e = 6e-5 m,
for F_r = 100/150/200 N at eta0 = 0.08 Pa s and eta0 = 0.06/0.08/0.10 Pa s at 150 N) and
Fig. 4 (fluctuation grows with the whirl radius, F_r = 200 N).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..units import to_si
from . import RUNNERS

#: (radial load [N], eta0 [Pa s]) -> quantity suffix, the conditions of Tables 2-3
CONDITIONS = {
    (100.0, 0.08): "Fr100_eta0.08",
    (150.0, 0.08): "Fr150_eta0.08",
    (200.0, 0.08): "Fr200_eta0.08",
    (150.0, 0.06): "Fr150_eta0.06",
    (150.0, 0.10): "Fr150_eta0.10",
}


def _get(inputs: dict[str, Any], key: str, kind: str) -> float:
    if key not in inputs:
        raise InputError(f"inputs.{key}", None, f"a {kind} quantity")
    return to_si(inputs[key], kind, field=f"inputs.{key}")


#: Roelands reference pressure of paper 000 eq. 9 (5.1e-9 1/Pa = 1/p0) [Pa]
ROELANDS_P0 = 1.0 / 5.1e-9


def paper000_eq9_lubricant(lubricant: Any, eta0: float, temperature: float = 313.15,
                           reference_eta0: float = 0.08) -> Any:
    """The lubricant with the pressure-viscosity coefficient of paper 000 eq. 9 at ``eta0``.

    Eq. 9 (Roelands) is eta/eta0 = exp{(ln eta0 + 9.67)[(1 + p/p0)^z - 1]}, p0 = 1/5.1e-9
    Pa, so its initial slope alpha = z (ln eta0 + 9.67) / p0 [1/Pa] rises with eta0 (the
    printed exponent "2" is read as the Roelands index z, which Table 1's G = alpha E' =
    5000 at eta0 = 0.08 Pa s fixes to z = 0.602). The preset keeps alpha = G/E' for every
    eta0; this returns the preset with alpha (at ``temperature`` [K]) scaled by
    (ln eta0 + 9.67)/(ln reference_eta0 + 9.67). eta0, reference_eta0 [Pa s].
    """
    import dataclasses

    alpha0 = float(lubricant.pressure_viscosity_coefficient(temperature))
    ratio = (math.log(eta0) + 9.67) / (math.log(reference_eta0) + 9.67)
    params = dict(lubricant.pressure_parameters)
    params["alpha"] = alpha0 * ratio
    return dataclasses.replace(lubricant, pressure_parameters=params)


@RUNNERS.register("paper000_nu214_cage_speed",
                  references=["li2018_nu214_skidding", "harris1966_roller_skidding"])
def paper000_nu214_cage_speed(inputs: dict[str, Any], case_dir: Path) -> dict[str, float]:
    """Mean/min/max cage speed and slip along the whirl orbit, and the Fig. 4 trend."""
    from ..geometry import load_bearing
    from ..lubricant import load_lubricant
    from ..skidding.roller import solve_roller
    from ..skidding.whirl import Whirl

    bearing = load_bearing(inputs.get("bearing", "NU214"))
    lubricant = load_lubricant(inputs.get("lubricant", "PAPER000_OIL"))
    speed = _get(inputs, "inner_speed", "angular_speed")
    temperature = _get(inputs, "temperature", "temperature")
    radius = _get(inputs, "whirl_radius", "length")
    n_samples = int(inputs.get("n_samples", 36))
    options = dict(inputs.get("model", {}))
    out: dict[str, float] = {
        "theoretical_cage_speed": speed * bearing.theoretical_cage_speed_ratio(),
    }
    eq9 = bool(inputs.get("paper_eq9_alpha", False))

    def tables(model: dict[str, Any], whirl: dict[str, Any], suffix: str) -> None:
        """Tables 2-3 quantities of one model variant (rows ``<quantity>_<tag><suffix>``)."""
        for (load, eta0), tag in CONDITIONS.items():
            lub = paper000_eq9_lubricant(lubricant, eta0, temperature) if eq9 \
                else lubricant
            res = solve_roller(bearing, lub, speed, load, 0.0, temperature, viscosity=eta0,
                               whirl=Whirl(radius, n_samples=n_samples, **whirl), **model)
            st, sl = res.cage_speed_stats, res.slip_stats
            out[f"mean_cage_speed_{tag}{suffix}"] = st.mean
            out[f"min_cage_speed_{tag}{suffix}"] = st.minimum
            out[f"max_cage_speed_{tag}{suffix}"] = st.maximum
            out[f"cage_speed_fluctuation_{tag}{suffix}"] = st.fluctuation
            out[f"mean_slip_{tag}{suffix}"] = sl.mean
        # directions of change (paper: cage speed falls with load, rises with viscosity)
        out[f"cage_speed_change_Fr100_to_Fr200{suffix}"] = (
            out[f"mean_cage_speed_Fr200_eta0.08{suffix}"]
            - out[f"mean_cage_speed_Fr100_eta0.08{suffix}"])
        out[f"cage_speed_change_eta0.06_to_eta0.10{suffix}"] = (
            out[f"mean_cage_speed_Fr150_eta0.10{suffix}"]
            - out[f"mean_cage_speed_Fr150_eta0.06{suffix}"])

    # named variants of the case's model (sensitivities printed beside the case model):
    # [inputs.variants.NAME] model = {...} (extra solver options), whirl = {...} (Whirl fields)
    variants = {}
    for name, variant in dict(inputs.get("variants", {})).items():
        extra = dict(variant)
        unknown = set(extra) - {"model", "whirl"}
        if unknown:
            raise InputError(f"inputs.variants.{name}", sorted(unknown),
                             "the keys 'model' (solver options) and 'whirl' (Whirl fields)")
        whirl = dict(extra.get("whirl", {}))
        try:  # bad Whirl fields fail here, before any solve
            Whirl(radius, n_samples=n_samples, **whirl)
        except TypeError:
            raise InputError(f"inputs.variants.{name}.whirl", sorted(whirl),
                             "fields of skidding.whirl.Whirl (e.g. radial_inertia)") from None
        variants[name] = ({**options, **dict(extra.get("model", {}))}, whirl)
    tables(options, {}, "")
    for name, (model, whirl) in variants.items():
        tables(model, whirl, f"_{name}")
    # Fig. 4: fluctuation against whirl radius at F_r = 200 N
    fig4_load = _get(inputs, "fig4_radial_load", "force")
    radii = [to_si(r, "length", field="inputs.fig4_whirl_radii")
             for r in inputs.get("fig4_whirl_radii", [])]
    if len(radii) < 2:
        raise InputError("inputs.fig4_whirl_radii", radii, "at least two whirl radii")
    fluct = []
    for e in radii:
        res = solve_roller(bearing, lubricant, speed, fig4_load, 0.0, temperature,
                           viscosity=0.08, whirl=Whirl(e, n_samples=n_samples), **options)
        fluct.append(res.cage_speed_stats.fluctuation)
    growth = min(b / a for a, b in zip(fluct[:-1], fluct[1:], strict=True) if a > 0) \
        if all(f > 0 for f in fluct[:-1]) else math.nan
    out["fig4_fluctuation_growth_ratio_min"] = growth
    out["fig4_fluctuation_smallest_radius"] = fluct[0]
    out["fig4_fluctuation_largest_radius"] = fluct[-1]
    return out
