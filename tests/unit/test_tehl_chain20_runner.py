"""The paper001_tehl_film runner takes its films from the integrated quasi-dynamic +
thermal-EHL chain (issue 7): per load :func:`~thermobearing.ehl.coupling.solve_roller_tehl`
with one film table for every load, the film of the solved state's most loaded inner
contact. The thermal solve of the table is the graded closed-form stand-in of
tests/unit/tehl_stand_in.py (the validation case itself runs the thermal solver)."""

from __future__ import annotations

import numpy as np
import pytest
from tehl_stand_in import GradedTable

from thermobearing.ehl import coupling
from thermobearing.geometry import load_bearing
from thermobearing.validation.runners_ehl import paper001_tehl_film

INPUTS = {"bearing": "D1842926", "lubricant": "OIL_4109", "inner_speed": "13218 rpm",
          "temperature": "30 degC", "radial_loads": ["8 kN", "12 kN"], "n": 512}


def test_runner_reports_the_chain_state_films(monkeypatch, tmp_path):
    monkeypatch.setattr(coupling, "FilmTable", GradedTable)
    made, states = [], []
    make, solve = coupling.roller_film_model, coupling.solve_roller_tehl

    def make_spy(*args, **kwargs):
        made.append(make(*args, **kwargs))
        return made[-1]

    def solve_spy(*args, **kwargs):
        states.append((solve(*args, **kwargs), kwargs["film_model"]))
        return states[-1][0]

    monkeypatch.setattr(coupling, "roller_film_model", make_spy)
    monkeypatch.setattr(coupling, "solve_roller_tehl", solve_spy)
    out = paper001_tehl_film(INPUTS, tmp_path)
    assert len(made) == 1 and len(states) == 2
    assert all(fm is made[0] for _, fm in states)  # one film table for both loads
    res, fm = states[0]  # 8 kN
    bearing, t_in = load_bearing("D1842926"), 303.15
    j = int(np.argmax(res.inner_load))
    ue = abs(float(res.inner_entrainment_speed[j]))
    srr = float(res.inner_sliding_speed[j]) / ue
    films = fm.films(np.array([res.inner_load[j] / res.extras["contact_length"]]),
                     np.array([ue]), np.array([srr]), t_in, res.extras["radius_inner"],
                     bearing.effective_modulus)
    assert films.numerical[0]
    assert out["tehl_min_8kN"] == pytest.approx(films.minimum_film[0], rel=1e-6)
    assert out["max_roller_load_8kN"] == pytest.approx(res.inner_load[j], rel=1e-9)
    assert out["cage_sliding_ratio_8kN"] == pytest.approx(res.slip, rel=1e-6)
    assert out["slide_to_roll_8kN"] == pytest.approx(srr, rel=1e-6, abs=1e-12)
    # rows the case gates: falling with load, Hamrock-Dowson above the chain's film
    assert out["tehl_min_falls_with_load"] == 1.0
    assert out["tehl_min_8kN"] > out["tehl_min_12kN"]
    for tag in ("8kN", "12kN"):
        assert out[f"hd_minus_tehl_min_{tag}"] == pytest.approx(
            out[f"hamrock_dowson_min_{tag}"] - out[f"tehl_min_{tag}"])
        assert out[f"hd_minus_tehl_min_{tag}"] > 0.0
        assert out[f"isothermal_min_{tag}"] > out[f"tehl_min_{tag}"]
    # the chain's loads are the quasi-static distribution's here (cage within 1e-4 of the
    # epicyclic speed: the same centrifugal forces)
    assert out["max_roller_load_8kN"] == pytest.approx(out["quasi_static_roller_load_8kN"],
                                                       rel=1e-3)
