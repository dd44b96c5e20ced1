"""HTML sections of the run report: the operating context and the power-loss breakdown.

:func:`html_table` renders a table for a reader (powers rounded by
:func:`report_losses.fmt_power`, per cent values to three significant digits, other
numbers to four, every number from 1000 on with its thousands grouped; a long table is
cut with a note naming its CSV file). :func:`context_html` says which bearing ran at
which operating points; :func:`losses_html` gives the loss breakdown by source and by
receiving component, the sum check, the loss glossary and the catalogue cross-check
(:func:`report_context.catalogue_crosscheck`).
"""

from __future__ import annotations

import html
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from . import report_context as ctx
from . import report_losses as rl
from .errors import InputError

#: rows of a table shown in the report (the CSV files have all)
MAX_ROWS = 60


def fmt_number(v: float) -> str:
    """Four significant digits; from 1000 to 1e12 a whole number with its thousands
    grouped (a speed of 20000 r/min reads ``20,000``, not ``2e+04``; a torque of 1169 N mm
    reads ``1,169``, as a power of 1031 W beside it reads ``1,031`` by
    :func:`report_losses.fmt_power`: one grouping rule for every number of a table)."""
    if math.isfinite(v) and 1e3 <= abs(v) < 1e12:
        return f"{v:,.0f}"
    return f"{v:.4g}"


def fmt_integer(v: Any) -> str:
    """An integer cell grouped as :func:`fmt_number` groups a float (``1,500`` r/min);
    anything else as text."""
    if isinstance(v, (int, np.integer)) and not isinstance(v, bool):
        return f"{int(v):,}"
    return str(v)


def _formatters(df: pd.DataFrame) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for c in df.columns:
        if pd.api.types.is_bool_dtype(df[c]):
            continue
        if pd.api.types.is_integer_dtype(df[c]):
            out[c] = fmt_integer
        elif not pd.api.types.is_float_dtype(df[c]):
            continue
        elif str(c).endswith("[W]"):
            out[c] = rl.fmt_power
        elif str(c).endswith("[%]"):
            out[c] = lambda v: f"{v:.3g}"
        else:
            out[c] = fmt_number
    return out


def html_table(df: pd.DataFrame | None, max_rows: int = MAX_ROWS, *,
               csv_name: str | None = None, series: bool = False) -> str:
    """A table as HTML for a reader. Longer than ``max_rows``: a time series
    (``series``) shows every k-th row, any other table its first ``max_rows`` rows; either
    way a note says how many rows are shown and where the rest is (``csv_name``)."""
    if df is None or df.empty:
        return "<p>(empty)</p>"
    note = ""
    shown = df
    if len(df) > max_rows:
        where = f"; all {len(df)} in {csv_name}" if csv_name else ""
        if series:
            k = -(-len(df) // max_rows)
            shown = df.iloc[::k]
            note = f"every {k}th of {len(df)} rows shown{where}"
        else:
            shown = df.iloc[:max_rows]
            note = f"first {max_rows} of {len(df)} rows shown{where}"
    # an undefined value (a sensor without samples, the cage speed ratio at rest) reads
    # as a dash, not "NaN"
    text = shown.to_html(index=False, float_format=fmt_number, border=0, na_rep="\u2014",
                         formatters=_formatters(shown))
    return text + (f"<p class='note'>({html.escape(note)})</p>" if note else "")


def context_html(scene: Any, tables: dict[str, pd.DataFrame], bearings: dict[str, Any],
                 lubricant: Any | None, notes: list[str]) -> str:
    """'Bearing and operating points': the bearings, lubricant and supply, the schedule."""
    esc = html.escape
    parts = ["<h2 id='bearing-and-operating-points'>Bearing and operating points</h2>",
             html_table(ctx.bearing_table(scene, bearings)),
             f"<p>{esc(ctx.supply_text(scene, lubricant))}</p>"]
    parts += [f"<p class='warn'>{esc(n)}</p>" for n in notes]
    parts.append("<h3>schedule</h3>" + html_table(ctx.operating_points(scene)))
    return "\n".join(parts)


def no_losses_text(scene: Any) -> str:
    """Why a run report has no loss breakdown: the scene's outputs ask for none, or (a
    scene that books losses) the folder holds no losses table -- a run stopped before its
    first step finished, or a sweep folder whose first case never finished (its
    ``scene.toml`` alone was reported as a run that asked for no losses)."""
    from .simulation_chain import _needs

    try:
        books = scene is not None and _needs(scene)["losses"]
    except (AttributeError, TypeError):
        books = False
    if not books:
        return "no losses table: the scene's outputs ask for no losses"
    return ("no losses table in this folder, although the scene's outputs ask for losses: "
            "no step finished here (a run stopped before its first step, or a sweep "
            "folder with no finished case)")


def losses_html(losses: pd.DataFrame | None, tables: dict[str, pd.DataFrame], scene: Any,
                bearings: dict[str, Any], lubricant: Any | None, *,
                flagged: Mapping[str, Mapping[str, Sequence[int]]] | None = None) -> str:
    """'Loss breakdown': by source [W] and share [%], the glossary, by receiving component,
    the sum check and the catalogue cross-check. ``flagged`` (``Results.flagged``): the
    steps each operating check flags per bearing; the table by source then names them in
    a column ``operating checks`` (the validity warnings list the steps; the rows of the
    losses they apply to said nothing)."""
    esc = html.escape
    parts = ["<h2 id='loss-breakdown'>Loss breakdown</h2>"]
    if losses is None or losses.empty:
        parts.append(f"<p>({esc(no_losses_text(scene))})</p>")
        return "\n".join(parts)
    if scene is not None:
        parts.append(f"<p>{esc(ctx.loss_temperature_note(tables, scene))}</p>")
    by_source = rl.breakdown_by_source(losses)
    parts.append("<ul class='summary'>" + "".join(
        f"<li>{esc(line)}</li>" for line in rl.summary_lines(by_source)) + "</ul>")
    parts += ["<h3>power loss by source [W]</h3>",
              "<p>per operating point and bearing; total = the sum of the sources "
              "(load-dependent + load-independent); the same numbers, registered source "
              "names as columns, are in loss_breakdown.csv</p>",
              html_table(_with_checks(rl.readable(by_source), flagged),
                         csv_name="loss_breakdown.csv"),
              *(["<p class='note'>operating checks: the checks that flag the step for that "
                 "bearing (cage skidding beyond the skid limit, contact stress above the "
                 "stress limit, film parameter below its minimum; the limits and the values "
                 "are under Validity warnings)</p>"]
                if "operating checks" in _with_checks(by_source, flagged) else []),
              "<h3>share of the total by source [%]</h3>",
              html_table(rl.readable(rl.shares(by_source))),
              "<h3>what the sources are</h3>", html_table(rl.glossary(losses)),
              *(f"<p class='note'>{esc(n)}</p>" for n in rl.class_notes(losses)),
              *(f"<p class='note'>{esc(n)}</p>"
                for n in source_notes(by_source, scene, bearings))]
    by_dest = rl.breakdown_by_destination(losses)
    parts.append("<h3>heat received by component [W]</h3>")
    if by_dest is None:
        parts.append("<p>(the losses table has no role column: which component each "
                     "source heats was not recorded in this run)</p>")
    else:
        gap = float((by_dest["total [W]"] - by_source["total [W]"]).abs().max())
        parts += [html_table(by_dest),
                  f"<p>sum check: the totals by component and by source differ by at most "
                  f"{gap:.3g} W</p>"]
    parts.append(_crosscheck_html(losses, tables, scene, bearings, lubricant))
    return "\n".join(parts)


#: the operating checks' keys -> what a flagged row says
_CHECK_WORDS = {"skid": "cage skidding", "stress": "contact stress", "film": "film parameter"}


def _with_checks(table: pd.DataFrame,
                 flagged: Mapping[str, Mapping[str, Sequence[int]]] | None) -> pd.DataFrame:
    """``table`` (rows of step and bearing) with a last column ``operating checks`` naming
    the checks that flag each row's step for its bearing (``-`` none), when any flags
    one; unchanged otherwise."""
    if not flagged or "step" not in table or "bearing" not in table:
        return table
    sets = {(str(b), key): {int(i) for i in steps}
            for b, by in flagged.items() for key, steps in by.items()}
    words = [", ".join(w for key, w in _CHECK_WORDS.items()
                       if int(step) in sets.get((str(bearing), key), set())) or "-"
             for step, bearing in zip(table["step"], table["bearing"], strict=True)]
    if all(w == "-" for w in words):
        return table
    return table.assign(**{"operating checks": words})


def _rolling_notes(by_source: pd.DataFrame, scene: Any) -> list[str]:
    """Why the raceway contacts book 0 W at every point of a race-control run (a roller
    bearing rolls without sliding there: the CRB rib example's 'raceway contacts' column
    read 0 W at 30000 r/min and 3 kN without a word); empty otherwise."""
    col = "raceway_traction [W]"
    models = getattr(scene, "models", None) or {}
    if models.get("kinematics") != "race_control" or col not in by_source:
        return []
    values = by_source[col].to_numpy(dtype=float)
    values = values[np.isfinite(values)]
    if values.size == 0 or np.any(np.abs(values) > 1e-9):
        return []
    return [f"{rl.source_label('raceway_traction')}: 0 W {_every(by_source)}: race control "
            "(kinematics = \"race_control\") rolls the elements without sliding on the "
            "raceways, so the traction law books no shear there; the sliding losses need "
            "the skidding solver (kinematics = \"skidding\")"]


def _every(frame: pd.DataFrame) -> str:
    """``"at every step"`` of a run's loss table, ``"in every case"`` of a sweep's summary
    (its ``case`` column): a sweep report said "0 W at every step" of rows of cases."""
    return "in every case" if "case" in frame.columns else "at every step"


def _all_zero(frame: pd.DataFrame, col: str) -> bool:
    """``col`` is in ``frame`` and books 0 W (to 1e-9 W) at every finite row."""
    if col not in frame:
        return False
    values = pd.to_numeric(frame[col], errors="coerce").to_numpy(dtype=float)
    values = values[np.isfinite(values)]
    return values.size > 0 and not np.any(np.abs(values) > 1e-9)


def _carries_thrust(frame: pd.DataFrame, scene: Any) -> bool:
    """Some row of ``frame`` (a loss table with ``axial load [kN]``, or a sweep summary
    with a swept ``schedule.axial_load [kN]``) or, without such a column, some step of the
    scene has an axial load."""
    cols = [c for c in frame.columns
            if c == "axial load [kN]" or str(c).startswith("schedule.axial_load [")]
    if cols:
        values = frame[cols].apply(pd.to_numeric, errors="coerce").to_numpy(dtype=float)
        if np.any(np.abs(values[np.isfinite(values)]) > 0.0):
            return True
    steps = getattr(getattr(scene, "schedule", None), "steps", None) or ()
    return any(getattr(s, "axial_load", 0.0) for s in steps)


def source_notes(frame: pd.DataFrame, scene: Any, bearings: Mapping[str, Any]) -> list[str]:
    """What the loss columns of ``frame`` (one ``<source> [W]`` column per heat source: the
    breakdown by source of a run, or a sweep's summary) leave out, and why:

    * a source that books 0 W at every row because of the model chain: the raceway
      traction and the pocket friction under race control (the elements roll without
      sliding and the cage gets no pocket force: ``heat_sources/pocket.py``), the cage
      guide land of a cage guided on its rolling elements (no land: ``cage_guide.py``);
      the tables showed these zeros without a word (a CRB run's cage pockets read 0 W);
    * the outer rib of a roller bearing ribbed on both rings under an axial load: the rib
      source books its thrust contact (component "roller end face / outer rib", at the
      kinematic state's spins, :mod:`thermobearing.rib_outer`), but the roller dynamics
      (skew contacts) and the lubricant drag run on the inner ribs only (paper 003's
      geometry; ``heat_sources/rib.py``, Thrust).

    ``bearings``: name -> bearing object (:func:`report_context.load_scene_bearings`)."""
    notes = list(_rolling_notes(frame, scene))
    models = getattr(scene, "models", None) or {}
    race_control = models.get("kinematics") == "race_control"
    if race_control and _all_zero(frame, "pocket_friction [W]"):
        notes.append(f"{rl.source_label('pocket_friction')}: 0 W {_every(frame)}: race "
                     "control gives the cage no pocket forces (the cage turns at the elements' "
                     "orbital speed without a balance of its own), so the pocket friction "
                     "books nothing; the pocket forces need the skidding solver "
                     "(kinematics = \"skidding\")")
    zero = [s for s in ("raceway_traction", "pocket_friction") if _all_zero(frame, f"{s} [W]")]
    rollers = [name for name, b in bearings.items() if getattr(b, "kind", None) == "cylindrical"]
    if race_control and zero and rollers and _carries_thrust(frame, scene):
        # the notes above send the reader to the skidding solver, which refuses a roller
        # bearing under an axial load (it carries no rib thrust)
        notes.append(f"{', '.join(rollers)}: the skidding solver carries no rib thrust, so "
                     "it refuses a cylindrical roller bearing under an axial load; the "
                     f"{' and the '.join(rl.source_label(s) for s in zero)} of this "
                     f"{'sweep' if 'case' in frame.columns else 'run'} are not computed "
                     "(0 W stands for 'not modelled', not for no loss)")
    if _all_zero(frame, "cage_guide [W]"):
        guided = [name for name, b in bearings.items()
                  if getattr(getattr(b, "cage", None), "guidance", None) == "rolling_element"]
        if guided and len(guided) == len(bearings):
            notes.append(f"{rl.source_label('cage_guide')}: 0 W {_every(frame)}: the cage "
                         f"of {', '.join(guided)} is guided on its rolling elements "
                         "(cage guidance = rolling_element), so there is no guide land to "
                         "shear")
    if "rib_friction [W]" in frame and _carries_thrust(frame, scene):
        both = [name for name, b in bearings.items()
                if getattr(b, "ribbed_ring", None) == "both"]
        if both:
            notes.append(f"{rl.source_label('rib_friction')} of {', '.join(both)} (ribs on "
                         "both rings): the outer rib's thrust contact is booked (component "
                         "'roller end face / outer rib', at the kinematic roller spins); the "
                         "skew contacts of the roller dynamics and the lubricant drag are "
                         "modelled at the inner ribs only (paper 003's rib geometry): the "
                         "outer rib's drag and skew contacts are not in the totals")
    return notes


def _crosscheck_html(losses: pd.DataFrame, tables: dict[str, pd.DataFrame], scene: Any,
                     bearings: dict[str, Any], lubricant: Any | None) -> str:
    esc = html.escape
    head = ("<h3>catalogue cross-check</h3><p>the run's total loss beside the whole-bearing "
            "estimates of the SKF four-term model and Palmgren's M0 + M1 at the same speed, "
            "loads, lubrication method and oil temperature (thermobearing.global_friction). "
            "Both are catalogue-level models of the whole bearing, fitted to catalogue "
            "bearings in standard conditions: they see neither the cage nor the skidding "
            "of this run, and of the oil supply only the lubrication method (and, in the "
            "SKF drag term, an oil bath's level; not a jet's or a circulation's flow), so "
            "they are an order-of-magnitude check, not a reference</p>")
    if scene is None or lubricant is None or not bearings:
        return head + "<p>(not available: the scene's bearing or lubricant was not read)</p>"
    try:
        table, notes = ctx.catalogue_crosscheck(losses, tables, scene, bearings, lubricant)
    except InputError as exc:
        return head + f"<p class='warn'>(not available: {esc(str(exc))})</p>"
    return (head + html_table(table)
            + "".join(f"<p class='note'>{esc(n)}</p>" for n in notes))


#: model family -> the module holding its registry (imported on demand; a family not
#: listed is shown without its summary and validity)
_REGISTRY_MODULES = {
    "viscosity_temperature": "thermobearing.viscosity_laws",
    "pressure_viscosity": "thermobearing.viscosity_laws",
    "film": "thermobearing.film",
    "thermal_film": "thermobearing.film",
    "kinematics": "thermobearing.kinematic_models",
    "heat_source": "thermobearing.heat_sources",
    "global_friction": "thermobearing.global_friction",
    "network_template": "thermobearing.network.templates",
    "stepper": "thermobearing.network.steppers",
    "traction": "thermobearing.traction",
    "traction_curve": "thermobearing.traction_curve",
}


def chain_table(chain: list[tuple[str, str]]) -> pd.DataFrame:
    """The models that ran: family, model, what it is and its validity range as its
    registry entry states them (``thermobearing models`` lists the same)."""
    import importlib

    from .registry import Registry

    rows = []
    for family, name in chain:
        summary = validity = ""
        module = _REGISTRY_MODULES.get(family)
        if module is not None:
            for value in vars(importlib.import_module(module)).values():
                if isinstance(value, Registry) and value.family == family and name in value:
                    entry = value.entry(name)
                    summary, validity = entry.summary, entry.validity
                    break
        rows.append({"family": family, "model": name, "what it is": summary,
                     "valid for": validity or "(no range stated)"})
    return pd.DataFrame(rows)
