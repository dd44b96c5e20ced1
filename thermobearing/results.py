"""Results of a run: tidy pandas tables with units in the column names, plus metadata.

Tables (all optional; a scene fills only what its outputs need):

``temperatures``
    one row per output time: ``time [s]``, ``time [min]``, then ``<node> [degC]`` per node.
``steady_temperatures``
    one row per operating point of a steady run: ``step``, then ``<node> [degC]`` per node.
``losses``
    long form, one row per (step, bearing, source, component, role): ``step``,
    ``time [s]`` (transient runs only: a steady run's or an operating point's rows have no
    time), ``bearing``, ``speed [rpm]``, ``radial load [kN]``, ``axial load [kN]``,
    ``source``, ``component``, ``role`` (where that part of the component's heat goes:
    inner_ring, outer_ring, elements, cage or oil), ``power [W]``, ``load dependence``.
    A component's rows add up to its power, a source's to its loss. Folders of earlier
    versions have no ``role`` (one row per component); the report then leaves out the heat
    per receiving component.
``loss_breakdown`` (written from ``losses``, not kept in :attr:`Results.tables`)
    one row per (step, bearing) with its speed and loads, one ``<source> [W]`` column per
    heat source, ``load-dependent [W]``, ``load-independent [W]`` and ``total [W]`` (the
    sum of the sources): :func:`thermobearing.report_losses.breakdown_by_source`.
``kinematics``
    one row per (step, bearing): speeds, loads, ``cage speed ratio [-]``,
    ``theoretical cage speed ratio [-]``, ``over-skidding [%]``, the contact angles of ball
    bearings, checks, and solver statistics ``converged``, ``residual [-]``,
    ``iterations [-]`` (:func:`thermobearing.simulation_tables.kinematics_columns`: values
    below a stated noise floor around zero are written as 0).
``rib`` (runs with the ``rib_friction`` heat source and a loss table)
    one row per loss-table operating point and bearing with that source, beside its loss
    rows and from the same heat evaluation (the numbers the heat was computed from, no
    second solve): the step columns as in ``losses``, then ``rib model``, ``roller
    dynamics``, ``friction coefficient [-]``, ``elements temperature [degC]``, the thrust
    share (``thrust normal force [N]`` per roller, ``thrust max pressure [MPa]``, ``thrust
    contact area [mm^2]``, ``thrust slide speed [m/s]``, ``thrust PV [MPa m/s]``, ``thrust
    heat [W]``), ``drag heat [W]``, per end face ``left / right face PV [MPa m/s]`` and
    ``left / right face heat [W]`` (paper 003 eqs. 21-24, the roller dynamics' time and
    roller means), ``rib slide speed [m/s]``, ``dynamics orbits [-]``, ``slip speed [m/s]``
    (eq. 25), ``rib heat [W]`` (= the rib_friction rows of ``losses``) and ``heat to
    rollers [-]``; empty cells where the model has no such number
    (:func:`thermobearing.simulation_tables.rib_columns`).
``energy``
    one row per output time: cumulative ``generated [J]``, ``stored [J]``,
    ``to ambient [J]``, ``to oil [J]``, ``imbalance [J]``.
``measured_vs_predicted`` (written with the report of a scene with ``[measured]``)
    one row per sensor and measured time inside the run: the reading, the predicted node
    temperature there and their difference (:func:`thermobearing.report_measured.
    comparison_table`).

:class:`ResultsWriter` appends rows to the CSV files as they are computed, so an
interrupted run keeps everything finished so far.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

TABLES = ("temperatures", "steady_temperatures", "losses", "kinematics", "energy", "film",
          "rib")


@dataclass
class Results:
    """Everything a run produced.

    Attributes
    ----------
    tables : name -> DataFrame (see the module docstring).
    scene_toml : the resolved scene as TOML text.
    chain : the models that ran, in order, as (family, name) pairs.
    citations : formatted references of the models that ran.
    warnings : validity warnings collected during the run.
    stats : solver statistics (steps, Newton iterations, re-solves, wall time...).
    check_limits : the thresholds the validity warnings applied
        (``operating_checks.CheckLimits.as_dict``: skid limit [-], stress limits [Pa] per
        bearing family, minimum film parameter [-], and their source); empty when no
        state was checked or unknown (film-only runs check the stress and film parameter
        of their film table's rows).
    estimated : the input values no source gives, with their reasoning: what -> field ->
        reasoning (``Simulation.estimated_inputs``: per bearing and the lubricant).
    flagged : the steps the operating checks flag, per bearing:
        ``{bearing: {"skid": [steps], "stress": [...], "film": [...]}}``
        (``CheckLog.flagged_step_indices``); empty when nothing was checked.
    """

    tables: dict[str, pd.DataFrame] = field(default_factory=dict)
    scene_toml: str = ""
    chain: list[tuple[str, str]] = field(default_factory=list)
    citations: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    stats: dict[str, Any] = field(default_factory=dict)
    figures: dict[str, bytes] = field(default_factory=dict)
    check_limits: dict[str, Any] = field(default_factory=dict)
    estimated: dict[str, dict[str, str]] = field(default_factory=dict)
    flagged: dict[str, dict[str, list[int]]] = field(default_factory=dict)

    def __getitem__(self, name: str) -> pd.DataFrame:
        return self.tables[name]

    def write(self, out_dir: Path | str) -> Path:
        """Write every table as CSV (and Parquet when pyarrow is present), the loss
        breakdown per operating point (``loss_breakdown.csv``, one column per source), the
        resolved scene, the metadata and the figures to ``out_dir``; returns the folder.

        Results with tables replace what an earlier run left in the folder under the names
        a run writes (:meth:`_remove_stale`); results without tables (the metadata of a run
        stopped before its end, whose step tables the :class:`ResultsWriter` wrote) add to
        the folder."""
        out = _results_folder(out_dir)
        if self.tables:
            self._remove_stale(out)
        try:
            import pyarrow  # noqa: F401

            parquet = True
        except ImportError:
            parquet = False
        for name, df in self.tables.items():
            df.to_csv(out / f"{name}.csv", index=False)
            if parquet:
                df.to_parquet(out / f"{name}.parquet", index=False)
        losses = self.tables.get("losses")
        if losses is not None and not losses.empty and "source" in losses:
            from .report_losses import breakdown_by_source

            breakdown_by_source(losses).to_csv(out / "loss_breakdown.csv", index=False)
        if self.scene_toml:
            (out / "scene.toml").write_text(self.scene_toml, encoding="utf-8")
        meta = {
            "chain": [list(x) for x in self.chain],
            "citations": self.citations,
            "warnings": self.warnings,
            "stats": _jsonable(self.stats),
        }
        if self.check_limits:
            meta["check_limits"] = _jsonable(self.check_limits)
        if self.estimated:
            meta["estimated"] = _jsonable(self.estimated)
        if self.flagged:
            meta["flagged_steps"] = _jsonable(self.flagged)
        (out / "metadata.json").write_text(json.dumps(meta, indent=1), encoding="utf-8")
        for name, png in self.figures.items():
            (out / f"{name}.png").write_bytes(png)
        return out


    def _remove_stale(self, out: Path) -> None:
        """Remove the tables, figures and report an earlier run left in ``out`` that these
        results do not write again. (``Simulation(scene).run().write(folder)`` of a
        losses-only scene into the folder of a transient run kept that run's
        ``temperatures.csv``, ``energy.csv`` and figures: ``thermobearing report folder``
        then drew the old temperatures and energy audit beside the new losses and said
        the losses were evaluated at those temperatures.) Other files stay."""
        from .report import FIGURE_CAPTIONS

        stale = [f"{t}.{ext}" for t in TABLES if t not in self.tables
                 for ext in ("csv", "parquet")]
        if "losses" not in self.tables:
            stale.append("loss_breakdown.csv")
        # written by the report of a scene with [measured] readings, after this
        stale += ["measured_vs_predicted.csv", "report.html"]
        stale += [f"{name}.png" for name in FIGURE_CAPTIONS if name not in self.figures]
        for path in out.glob("*.png"):
            if path.stem.startswith("loss_maps") and path.stem not in self.figures:
                stale.append(path.name)
        for name in stale:
            path = out / name
            if path.is_file():
                path.unlink()


def _jsonable(obj: Any) -> Any:
    if isinstance(obj, Mapping):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list | tuple):
        return [_jsonable(v) for v in obj]
    if hasattr(obj, "item"):
        return obj.item()
    return obj


def _results_folder(out_dir: Path | str) -> Path:
    """``out_dir`` created as a folder; an existing file there is an :class:`InputError`
    (was a bare FileExistsError)."""
    from .errors import InputError

    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError("out_dir", str(out), "a results folder (new or existing); this is a "
                         "file")
    out.mkdir(parents=True, exist_ok=True)
    return out


class ResultsWriter:
    """Append-as-you-go CSV writer: each table's rows land on disk as soon as they exist.

    Parameters
    ----------
    out_dir : folder to write to (created).
    """

    def __init__(self, out_dir: Path | str) -> None:
        self.out = _results_folder(out_dir)
        self._columns: dict[str, list[str]] = {}
        # the tables of an earlier run in the folder (and the breakdown derived from its
        # losses) must not pass for this run's
        for name in (*TABLES, "loss_breakdown", "measured_vs_predicted"):
            path = self.out / f"{name}.csv"
            if path.exists():
                path.unlink()

    def append(self, table: str, rows: Sequence[Mapping[str, Any]]) -> None:
        """Append rows (dicts) to ``<table>.csv``; the first call fixes the columns."""
        if not rows:
            return
        path = self.out / f"{table}.csv"
        cols = self._columns.get(table)
        new = cols is None
        if new:
            cols = list(rows[0].keys())
            for r in rows[1:]:
                cols.extend(k for k in r if k not in cols)
            self._columns[table] = cols
        buf = io.StringIO()
        writer = csv.DictWriter(buf, fieldnames=cols, extrasaction="ignore")
        if new:
            writer.writeheader()
        writer.writerows(rows)
        with path.open("a", encoding="utf-8", newline="") as fh:
            fh.write(buf.getvalue())
            fh.flush()

    def files(self) -> list[Path]:
        return sorted(self.out / f"{t}.csv" for t in self._columns)
