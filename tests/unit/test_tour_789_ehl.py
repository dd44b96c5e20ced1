"""User tour of ``film = "numerical_tehl"`` (issue 7): is the film table's work visible?

Found on the tour: a film-only run of ``configs/scenes/paper001_tehl.toml`` sat for minutes
inside one step (the first 8 kN step: 16 thermal solves, 280 s CPU on the shared machine)
without a sign of life, and nothing in the outputs said whether the table was reused between
steps (it is: steps 8, 8, 9 kN took 16, 0 and 4 solves). The table now counts its CPU time
(``FilmTable.solve_time``, ``TehlFilmModel.solve_time``) and logs every node solve at INFO
on the ``thermobearing.ehl`` logger, so a front end can show progress and the metadata can
record the reuse (the Simulation side is the lead's).
"""

from __future__ import annotations

import logging

from thermobearing.ehl import FilmTable
from thermobearing.lubricant import load_lubricant


def test_table_logs_each_node_solve_and_counts_its_time(caplog):
    lub = load_lubricant("OIL_4109")
    table = FilmTable("numerical_ehl", 0.01, 2.2e11, lubricant=lub, n=256, mode="nearest")
    w, u = 1.25**51, 1.25**7  # on grid nodes: one corner in "nearest" mode
    with caplog.at_level(logging.INFO, logger="thermobearing.ehl"):
        a = table(w, u, 0.0, 313.15)
        b = table(w, u, 0.0, 313.15)  # memo hit: no solve, no record
    assert a == b and table.solves == 1 and table.queries == 2
    assert table.solve_time > 0.0
    records = [r for r in caplog.records if r.name == "thermobearing.ehl"]
    assert len(records) == 1
    msg = records[0].getMessage()
    assert msg.startswith("numerical_ehl table (R_x 0.01 m): node 1,") and "s CPU" in msg
