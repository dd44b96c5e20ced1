"""BM-7's roller ladder with ``[models] film_options``: the --quick settings are a valid
``film_options`` table, and the protocol records the grid the L2 film model solves on (the
thermal solve is the closed-form stand-in of ``tehl_stand_in``: plumbing, not physics)."""

from __future__ import annotations

from tehl_stand_in import CheapTable

from thermobearing.ehl import coupling
from thermobearing.lubricant import load_lubricant
from thermobearing.simulation_chain import plan_chain, scene_film_options


def test_quick_film_options_are_a_valid_scene_table(bm7):
    from _protocol import roller_scene, with_models

    scene = with_models(roller_scene(1), film="numerical_tehl",
                        film_options=dict(bm7.ROLLER_QUICK_FILM_OPTIONS))
    chain = plan_chain(scene, load_lubricant("OIL_4109"), is_ball=False)
    link = next(c for c in chain if c.name == "numerical_tehl")
    assert "grid_points 256" in link.purpose
    assert scene_film_options(scene) == {"n": 256, "temperature_step": 10.0}


def test_protocol_records_the_film_grid_of_l2(monkeypatch, bm7):
    monkeypatch.setattr(coupling, "FilmTable", CheapTable)
    from _protocol import roller_scene, run_l1, with_models

    scene = with_models(roller_scene(1), film="numerical_tehl")
    run = run_l1("L2", scene)
    assert run.extra["film grid points"] == {"mainshaft": 512}  # the model's default
    l1 = run_l1("L1", roller_scene(1))
    assert "film grid points" not in l1.extra
