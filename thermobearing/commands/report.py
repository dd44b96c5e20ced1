"""``thermobearing report DIR``: (re)write the HTML report of a run or a sweep folder.

A run folder (from ``thermobearing run --out DIR``) is re-rendered from its tables,
``scene.toml`` and ``metadata.json`` (its ``loss_breakdown.csv`` rewritten from
``losses.csv``). A sweep folder (``summary.csv`` from ``thermobearing sweep``) gets the
loss by source of every case as stacked bars, what-if curves of every result against each
swept parameter and, with two numeric swept parameters, contour maps of each loss
component (the style of seed paper 002 Figs. 16-17).
"""

from __future__ import annotations

import argparse
import itertools
import json
import re
import sys
from collections.abc import Mapping
from html import escape
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ..errors import InputError

NAME = "report"
HELP = "write report.html for a run folder or a sweep folder"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("folder", help="results folder of `run` or `sweep`")


#: columns the report's figures read from each table of a run folder
_NEEDED = {"temperatures": ("time [s]",), "losses": ("bearing",),
           "kinematics": ("axial load [kN]",)}


def _read_table(path: Path, needed: tuple[str, ...] = ()) -> pd.DataFrame:
    """A results CSV; a file that is not one (unreadable, or missing the columns the report
    needs) is an InputError naming the file."""
    try:
        df = pd.read_csv(path)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        raise InputError(path.name, str(path), f"a CSV table written by thermobearing ({exc})"
                         ) from None
    missing = [c for c in needed if c not in df.columns]
    if missing:
        raise InputError(path.name, str(path), "a table written by `thermobearing run` with "
                         "the columns " + ", ".join(repr(c) for c in missing))
    return df


def _numeric_params(df: pd.DataFrame, params: list[str]) -> pd.DataFrame:
    """Swept values like '15 L/min' -> numbers in a column named 'supply.flow [L/min]'.

    A summary written by this version of ``thermobearing sweep`` already has that column,
    converted to one unit value by value (``15 L/min`` and ``0.5 L/s`` both in L/min): it is
    kept and the text column dropped (the text was re-read with the first row's
    unit for every value). Older summaries are converted from the text as before."""
    out = df.copy()
    for p in params:
        if any(c.startswith(p + " [") for c in out.columns):
            out = out.drop(columns=[p])
            continue
        values = out[p].astype(str)
        m = values.str.extract(r"^\s*([-+0-9.eE]+)\s*(.*)$")
        if m[0].notna().all():
            unit = m[1].iloc[0].strip()
            out[f"{p} [{unit}]" if unit else p] = m[0].astype(float)
            if unit:
                out = out.drop(columns=[p])
    return out


#: loss-map figures per sweep report (one per value combination of the parameters beyond
#: the first two numeric ones)
MAX_MAP_SLICES = 4


def sweep_report(folder: Path) -> Path:
    """Write ``folder/report.html`` for a sweep folder: the base scene's bearing and
    conditions (when the folder has the sweep's ``scene.toml``), the loss by source of every
    case as stacked bars, what-if curves, loss maps (sources named in words, in the order
    of the run reports) and the summary table (powers rounded for a reader)."""
    from ..report import fig_loss_maps, fig_whatif, figure_html, sort_cases
    from ..report_losses import fig_sweep_breakdown, readable, source_label, summary_sources
    from ..report_sections import html_table
    from ..simulation_summary import MEAN_TOTAL_LOSS, current_result_name
    from ..sweep_store import base_scene_mode, planned_cases
    from .sweep import slip_columns

    df = _read_table(folder / "summary.csv", ("case",))
    # a folder written before the summary's rename (total loss [W], rise <node> [K])
    steady = base_scene_mode(folder) == "steady"
    df = df.rename(columns={c: current_result_name(c, steady) for c in df.columns
                            if current_result_name(c, steady) not in df.columns})
    store = folder / "cases.jsonl"
    try:
        records = [json.loads(line) for line in
                   store.read_text(encoding="utf-8").splitlines() if line.strip()]
        params = list(records[0]["params"])
    except (IndexError, json.JSONDecodeError, KeyError, TypeError):
        raise InputError("cases.jsonl", str(store), "the case store of `thermobearing "
                         "sweep` (one JSON record with 'params' per line)") from None
    df = _numeric_params(df, params)
    pcols = [c for c in df.columns if any(c == p or c.startswith(p + " [") for p in params)]
    results = [c for c in df.columns if c not in pcols and c != "case"]
    # the source columns in the order and words of every other loss table
    front = [c for c in results if c not in {f"{s} [W]" for s in summary_sources(results)}
             and c.endswith(" [W]")]
    ordered = front + [f"{s} [W]" for s in summary_sources(results)]
    df = df[["case", *pcols, *ordered, *(c for c in results if c not in ordered)]]
    # the rows in the order of the swept values, oils by viscosity, as the figures draw
    # them (they stood in the order typed: 33, 5, 10 L/min; ISO_VG68 before ISO_VG32)
    df = sort_cases(df, pcols)
    results = [c for c in df.columns if c not in pcols and c != "case"]
    figs: dict[str, bytes] = {}
    totals = [c for c in results if c.startswith("mean total loss") and c.endswith("[W]")]
    # the protocol means of the totals are no source (summary_sources knows the other sums)
    bars = fig_sweep_breakdown(df.drop(columns=totals), pcols)
    if bars is not None:
        figs["loss by source [W] of every case (all bearings, protocol average)"] = bars
    sources = summary_sources([c for c in results if c not in totals])
    losses = totals + [f"{s} [W]" for s in sources]
    titles = {f"{s} [W]": f"{source_label(s)} [W]" for s in sources}
    temps = [c for c in results if c.startswith("final") or c.startswith("rise")]
    # the housing node first: it is where a rig's thermocouple sits (paper 002 Fig. 19)
    temps.sort(key=lambda c: ".housing" not in c)
    # the what-if curves: the first housing's final temperature and its rise, and the
    # oil outlet (the first bearing's oil node), which a flow or inlet what-if is about
    curves = temps[:2] + [c for c in results if c.startswith("final")
                          and c.endswith(".oil [degC]")][:1]
    curves += film_curves(df, results)
    # race control rolls the cage by construction: an over-skidding panel of zeros says
    # nothing (a CRB sweep drew one flat line at 0 %); a note says why it is left out
    rolls = _race_control_zero_skid(folder, df, params)
    for x in pcols:
        if df[x].nunique() < 2:
            continue  # a parameter held at one value draws no curve
        # a text x (oil grade) is drawn at one position per value by fig_whatif
        group = [p for p in pcols if p != x]
        ys = [c for c in [MEAN_TOTAL_LOSS] if c in df]
        # a cage slower than epicyclic (skidding: a lightly loaded roller bearing) shows in
        # the smallest over-skidding, not in the largest, which stays near 0
        # (one-step cases have min = max: the max panel shows it already)
        low, high = "min over-skidding [%]", "max over-skidding [%]"
        slips = [] if rolls else [c for c in (high, low) if c in df]
        if low in slips and high in slips:
            lo = pd.to_numeric(df[low], errors="coerce").to_numpy(float)
            hi = pd.to_numeric(df[high], errors="coerce").to_numpy(float)
            if not (lo < 0.0).any() or np.allclose(lo, hi, rtol=0.0, atol=1e-9,
                                                   equal_nan=True):
                slips.remove(low)
            else:
                # the terminal's rule: an extreme below 1 % of the other's magnitude is
                # noise (a skidding NU 214: max -0.005 to -0.02 % beside min -20 to -41 %)
                slips = slip_columns(df, slips)
        ys += slips
        ys += curves
        if ys:
            figs[f"what-if: {x}"] = fig_whatif(df, x, ys, group=group)
    numeric = [c for c in pcols if pd.api.types.is_numeric_dtype(df[c])]
    notes: list[str] = []
    if len(numeric) >= 2 and losses:
        x, y = numeric[:2]
        rest = [c for c in pcols if c not in (x, y)]
        slices = list(df.groupby(rest)) if rest else [((), df)]
        # one colour scale per component across the slices (comparable by colour)
        ranges = {c: (float(df[c].min()), float(df[c].max())) for c in losses
                  if df[c].notna().any()}
        for key, sub in slices[:MAX_MAP_SLICES]:
            key = key if isinstance(key, tuple) else (key,)
            where = ", ".join(f"{c} = {v}" for c, v in zip(rest, key, strict=True))
            figs[f"loss maps ({where})" if where else "loss maps"] = \
                fig_loss_maps(sub, x, y, losses, ranges=ranges, titles=titles)
        if len(slices) > MAX_MAP_SLICES:
            notes.append(f"loss maps drawn for the first {MAX_MAP_SLICES} of {len(slices)} "
                         f"combinations of {', '.join(rest)}; every case is in the summary")
    notes += missing_cases(folder, df, pcols) + flagged_cases(
        df, pcols, bearings=_bearing_count(folder / "scene.toml"))
    notes += _source_notes(folder, df, params)
    notes += outside_data_notes(folder, records)
    start = fixed_start_note(folder, params)
    if start:
        notes.append(start)
    if rolls:
        notes.append("over-skidding 0 % in every case: race control (kinematics = "
                     "\"race_control\") rolls the cage at its theoretical speed by "
                     "construction, so no what-if panel draws it; cage slip needs the "
                     "skidding solver (kinematics = \"skidding\")")
    html = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>sweep report</title>",
            "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
            "img{max-width:100%}table{font-size:12px;border-collapse:collapse}"
            "td,th{padding:2px 6px;border-bottom:1px solid #ddd}td{text-align:right}"
            ".note{color:#555;font-size:12px}</style></head><body>",
            f"<h1>Sweep report: {escape(folder.name)}</h1>",
            _base_scene_html(folder),
            f"<p>{escape(case_count_text(df, planned_cases(folder)))}; swept: "
            f"{escape(', '.join(params))}. Losses in W: each case's loss of all its "
            "bearings, averaged over its protocol (steps weighted by their duration)"
            + ("; <code>mean total loss &lt;bearing&gt; [W]</code> per bearing"
               if per_bearing_totals(df.columns) else "") + ".</p>",
            *(f"<p>{escape(n)}</p>" for n in notes),
            "<h2>Figures</h2>",
            "<p class='note'>each figure is also in the folder as a PNG file: "
            + escape(", ".join(sweep_figure_file(k) for k in figs)) + "</p>" if figs else "",
            *(figure_html(k, v) for k, v in figs.items()),
            _crosscheck_html(folder, df, records),
            "<h2>Summary</h2>",
            "<p>the sources named in words; summary.csv has their registered names:</p>",
            html_table(pd.DataFrame({"in summary.csv": [f"{s} [W]" for s in sources],
                                     "loss": [source_label(s) for s in sources]}))
            if sources else "",
            html_table(readable(df), max_rows=500, csv_name="summary.csv"),
            _chain_html(folder, params),
            "</body></html>"]
    out = folder / "report.html"
    out.write_text("\n".join(html), encoding="utf-8")
    _write_sweep_pngs(folder, figs)
    return out


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def case_count_text(df: pd.DataFrame, planned: list[str] | None) -> str:
    """The sweep report's count of its cases: ``"9 cases"`` (``"1 case"``); with the
    folder's record of the planned cases (:func:`thermobearing.sweep_store.planned_cases`)
    and some of them not finished, ``"1 of 9 planned cases finished"`` and why the others
    are missing (an interrupted sweep said "1 cases" and nothing of the 8 not run). A
    folder without the record (written before it existed) is counted as before."""
    rows = len(df)
    if planned is None:
        return _plural(rows, "case")
    ids = set(planned)
    finished = int(df["case"].astype(str).isin(ids).sum()) if rows else 0
    if finished >= len(ids):
        text = f"{_plural(finished, 'case')} (every planned case finished)"
    else:
        text = (f"{finished} of {_plural(len(ids), 'planned case')} finished (the sweep "
                "was stopped before the others ran, or they failed under --keep-going; "
                "rerunning the same `thermobearing sweep` command runs them)")
    other = rows - finished
    if other > 0:
        text += (f"; the summary also has {_plural(other, 'case')} of an earlier sweep "
                 "in this folder")
    return text


def per_bearing_totals(columns: Any) -> list[str]:
    """The summary's per-bearing totals (``mean total loss <bearing> [W]``, written for a
    scene of more than one bearing), beside the all-bearing ``mean total loss [W]``."""
    from ..simulation_summary import MEAN_TOTAL_LOSS

    return [c for c in columns if str(c).startswith("mean total loss ")
            and str(c).endswith(" [W]") and c != MEAN_TOTAL_LOSS]


def film_curves(df: pd.DataFrame, results: list[str]) -> list[str]:
    """The what-if curves of the film: the first bearing's rolling-element temperature
    (``final <bearing>.rollers`` / ``.balls [degC]``) and the smallest film parameter
    Lambda (``min film parameter [-]``), when the summary has them with a number: with
    the housing and oil temperatures, a hotter inlet shows as a thinner film."""
    elements = [c for c in results if c.startswith("final")
                and c.endswith((".rollers [degC]", ".balls [degC]"))][:1]
    out = []
    for c in [*elements, "min film parameter [-]"]:
        if c in df and pd.to_numeric(df[c], errors="coerce").notna().any():
            out.append(c)
    return out


def sweep_figure_file(title: str) -> str:
    """The PNG file name of a sweep report figure: ``sweep_loss_by_source.png``,
    ``sweep_whatif_<parameter>.png``, ``sweep_loss_maps[_<held values>].png``."""
    def slug(text: str) -> str:
        return re.sub(r"[^A-Za-z0-9.=+-]+", "_", text).strip("_")

    if title.startswith("what-if: "):
        return f"sweep_whatif_{slug(title[len('what-if: '):])}.png"
    if title.startswith("loss maps"):
        held = title[len("loss maps"):].strip().strip("()").replace(" = ", "=")
        return f"sweep_loss_maps{'_' + slug(held) if held else ''}.png"
    if title.startswith("loss by source"):
        return "sweep_loss_by_source.png"
    return f"sweep_{slug(title)}.png"


def _write_sweep_pngs(folder: Path, figs: Mapping[str, bytes]) -> None:
    """The sweep report's figures as PNG files beside it (the run report writes its
    figures so; a sweep's were only inside report.html), replacing the ``sweep_*.png``
    of an earlier report (a slice or parameter no longer swept leaves none behind)."""
    for old in folder.glob("sweep_*.png"):
        old.unlink()
    for title, png in figs.items():
        (folder / sweep_figure_file(title)).write_bytes(png)


def missing_cases(folder: Path, df: pd.DataFrame, pcols: list[str]) -> list[str]:
    """A note naming the planned cases of the sweep folder that have no row in the summary
    (not run yet, or failed under ``--keep-going``), from ``planned_cases.json``; for a
    folder without that record, :func:`missing_combinations`. Tour E: a flow x inlet sweep
    stopped after 11 of 32 cases said "3 of 14 combinations ... have no result": the
    values no finished case had (55 degC, 40 and 60 L/min) were not counted."""
    from ..sweep_store import planned_params

    planned = planned_params(folder)
    if planned is None or df.empty:
        return missing_combinations(df, pcols)
    have = set(df["case"].astype(str))
    missing = [values for case, values in planned if case not in have]
    if not missing:
        return []
    shown = "; ".join(", ".join(f"{k} = {_fmt(v)}" for k, v in values.items())
                      for values in missing[:10])
    more = f" and {len(missing) - 10} more" if len(missing) > 10 else ""
    return [f"{len(missing)} of {len(planned)} planned cases have no result (not run yet, "
            f"or failed under --keep-going: `thermobearing sweep` printed why; rerunning it "
            f"runs them); the loss maps mark those inside their axes with a red cross: "
            f"{shown}{more}"]


def missing_combinations(df: pd.DataFrame, pcols: list[str]) -> list[str]:
    """A note naming the combinations of the swept values that have no row in the summary
    (a case that failed under ``--keep-going``, or one not run yet), when some do; empty
    when the summary covers the product of its swept values. A value whose every case
    failed does not appear in the summary at all, so it cannot be named here."""
    if len(pcols) < 2 or df.empty:
        return []
    values = [list(dict.fromkeys(df[c].tolist())) for c in pcols]
    have = set(map(tuple, df[pcols].itertuples(index=False, name=None)))
    missing = [combo for combo in itertools.product(*values) if combo not in have]
    if not missing:
        return []
    shown = "; ".join(", ".join(f"{c} = {_fmt(v)}" for c, v in zip(pcols, combo,
                                                                     strict=True))
                      for combo in missing[:10])
    more = f" and {len(missing) - 10} more" if len(missing) > 10 else ""
    return [f"{len(missing)} of {len(have) + len(missing)} combinations of the swept values "
            f"have no result (a case that failed under --keep-going, or one not run yet: "
            f"`thermobearing sweep` printed why; rerunning it tries them again); the loss "
            f"maps mark them with a red cross: {shown}{more}"]


#: the sweep summary's counts of flagged steps -> what they flag, in words
_FLAGS = {"steps over skid limit [-]": "cage skidding or over-skidding beyond the skid limit",
          "steps over stress limit [-]": "a Hertz pressure above the stress limit",
          "steps under film limit [-]": "a film parameter Lambda below the film limit"}


def flagged_cases(df: pd.DataFrame, pcols: list[str], *, bearings: int = 1) -> list[str]:
    """One note per operating check that flags steps in some cases (the summary's
    ``steps over skid limit [-]`` and its stress and film siblings), naming how many cases
    and the first few by their swept values (when every case is flagged, how many steps
    each: a list of the first six of 20 flagged cases said nothing): the losses of those
    points are of a bearing outside the check's limit (a skidding cage, an overloaded
    contact, a thin film).

    ``bearings``: the base scene's bearings. The summary counts each schedule step once
    however many bearings it flags (:func:`thermobearing.simulation_summary.
    flagged_step_counts`), so with more than one bearing the note says so: the counts are
    at most the protocol's steps. (Sweep folders written before that summed the counts
    over the bearings: "4 to 6 steps each" of a 3-step protocol on two bearings.)"""
    notes = []
    per = (f" (a step flagged at several of the {bearings} bearings counts once)"
           if bearings > 1 else "")
    for col, what in _FLAGS.items():
        if col not in df:
            continue
        hit = df[pd.to_numeric(df[col], errors="coerce").fillna(0) > 0]
        if hit.empty:
            continue
        named = "; ".join(", ".join(f"{c} = {_fmt(v)}" for c, v in zip(
            pcols, row, strict=True)) for row in hit[pcols].itertuples(index=False,
                                                                       name=None))
        if len(hit) == len(df) > 1:
            # every case: naming the first six of them says nothing
            counts = pd.to_numeric(hit[col], errors="coerce")
            named = (f"every case, {_fmt(counts.min())} to {_fmt(counts.max())} steps each"
                     if counts.min() != counts.max() else
                     f"every case, {_fmt(counts.min())} "
                     f"{'step' if counts.min() == 1 else 'steps'} each") + per
        elif len(hit) > 6:
            named = "; ".join(named.split("; ")[:6]) + f" and {len(hit) - 6} more"
        has = "has steps" if len(hit) == 1 else "have steps"
        notes.append(f"{len(hit)} of {_plural(len(df), 'case')} {has} with {what} (summary "
                     f"column '{col}'; limits from the scene's [checks], else the defaults): "
                     f"{named}")
    return notes


def _bearing_count(path: Path) -> int:
    """The number of bearings of the sweep's base scene (``path``: the folder's
    ``scene.toml``); 1 when the folder has none or it cannot be read (the report says
    why elsewhere)."""
    if not path.is_file():
        return 1
    try:
        return max(1, len(_folder_scene(path).bearings))
    except (InputError, OSError):
        return 1


def _fmt(v: object) -> str:
    return f"{v:g}" if isinstance(v, (int, float)) else str(v)


def _crosscheck_html(folder: Path, df: pd.DataFrame, records: list[dict]) -> str:
    """The sweep's catalogue cross-check section (SKF four-term and Palmgren per case,
    :func:`report_context.sweep_catalogue_crosscheck`); a note when the folder does not
    allow it (no base scene, or losses at the network's temperatures)."""
    from ..report_context import sweep_catalogue_crosscheck
    from ..report_sections import html_table

    head = ("<h2>Catalogue cross-check</h2><p>each case's total loss (all bearings, "
            "protocol average) beside the whole-bearing estimates of the SKF four-term "
            "model and Palmgren's M0 + M1 at the same speeds, loads, lubrication method "
            "and oil temperature, averaged over the protocol in the same way "
            "(thermobearing.global_friction), and the total of a case turning at one "
            "speed as the frictional moment a catalogue quotes, M = P / omega. Both are "
            "catalogue-level models, fitted to "
            "catalogue bearings in standard conditions: an order-of-magnitude check, not "
            "a reference</p>")
    path = folder / "scene.toml"
    if not path.is_file():
        return head + "<p class='note'>(not available: the folder has no scene.toml)</p>"
    try:
        base = _folder_scene(path)
        # in the summary's order (cases.jsonl has them in the order they finished: a
        # parallel sweep's cross-check rows read 2000/1, 2000/5, 5000/1, 2000/10 ...)
        order = {case: i for i, case in enumerate(df["case"])}
        table, notes = sweep_catalogue_crosscheck(base, sorted(
            (r for r in records if r.get("case") in order), key=lambda r: order[r["case"]]))
    except InputError as exc:
        return head + f"<p class='note'>(not available: {escape(str(exc))})</p>"
    return (head + (html_table(table, max_rows=500) if not table.empty else "")
            + "".join(f"<p class='note'>{escape(n)}</p>" for n in notes))


#: swept paths that can change the model chain or the sources a bearing runs
_CHAIN_PATHS = ("models.", "bearings.", "outputs.")


def _source_notes(folder: Path, df: pd.DataFrame, params: list[str]) -> list[str]:
    """What the summary's source columns leave out and why (a source at 0 W in every case
    by the model chain, the outer rib of a bearing ribbed on both rings:
    :func:`report_sections.source_notes`), for the folder's base scene; none when the
    folder has no readable base scene or the sweep changes the models or the bearings
    (the reasons would be the base scene's, not every case's)."""
    from ..report_context import load_scene_bearings
    from ..report_sections import source_notes

    path = folder / "scene.toml"
    if not path.is_file() or any(p.startswith(_CHAIN_PATHS) for p in params):
        return []
    try:
        scene = _folder_scene(path)
    except InputError:
        return []
    bearings, _ = load_scene_bearings(scene)
    return source_notes(df, scene, bearings)


def outside_data_notes(folder: Path, records: list[dict]) -> list[str]:
    """What the sweep said before its runs, for the report: the cases' oil temperatures
    (inlet, initial: :data:`thermobearing.sweep.OIL_TEMPERATURE_FIELDS`) outside the
    temperatures their oil's property data cover
    (:func:`thermobearing.lubricant_range.outside_data_note`), one note per field and oil;
    none without a readable base scene (``scene.toml``) or for an oil that does not load."""
    from ..errors import ThermobearingError
    from ..lubricant import load_lubricant
    from ..lubricant_range import data_temperature_range, outside_data_note
    from ..sweep import OIL_TEMPERATURE_FIELDS, scene_oil_temperature
    from ..units import to_si

    path = folder / "scene.toml"
    try:
        base = _folder_scene(path)
    except (InputError, OSError):
        return []
    spec = base.lubricant
    base_oil = spec.get("preset") or str(base.resolve_path(spec["path"]))
    kelvins: dict[tuple[str, str], list[float]] = {}
    for rec in records:
        params = rec.get("params", {})
        oil = str(params.get("lubricant.preset") or params.get("lubricant.path") or base_oil)
        for field in OIL_TEMPERATURE_FIELDS:
            if scene_oil_temperature(base, field) is None:
                continue   # an oil bath without flow: no inlet
            try:
                kelvin = (to_si(params[field], "K", field=field) if field in params
                          else scene_oil_temperature(base, field))
            except InputError:
                continue
            kelvins.setdefault((field, oil), []).append(float(kelvin))
    notes = []
    oils: dict[str, Any] = {}
    for (field, oil), values in kelvins.items():
        if oil not in oils:
            try:
                lub = load_lubricant(oil)
                oils[oil] = (lub, data_temperature_range(lub))
            except (ThermobearingError, OSError):
                oils[oil] = None
        if oils[oil] is not None:
            note = outside_data_note(oils[oil][0], field, values, oils[oil][1])
            if note:
                notes.append(note)
    return notes


def fixed_start_note(folder: Path, params: list[str]) -> str | None:
    """A note when a transient sweep moves the oil inlet but not the start: every case then
    starts at the base scene's initial temperature whatever its inlet, which the 'rise over
    initial' columns count from and the over-skidding extremes (taken over every solved
    state) include. Tour E: the default rig's 0 kN skid stood at -31 % (ISO VG 32) for
    inlets of 35, 45 and 60 degC -- each case's first state, at the 35 degC start -- and
    only the 25 degC inlet, whose oil cooled below the start, moved it."""
    if "supply.inlet_temperature" not in params or any(
            p.startswith(("environment.", "outputs.")) for p in params):
        return None
    try:
        base = _folder_scene(folder / "scene.toml")
    except (InputError, OSError):
        return None
    if base.outputs.mode != "transient" or not {"temperatures", "energy"} & set(
            base.outputs.want):
        return None
    start = base.environment.initial_temperature - 273.15
    return (f"every case starts at the base scene's initial temperature, {start:.4g} degC, "
            "whatever its inlet temperature (environment.initial_temperature is not swept): "
            "the 'rise over initial' columns count from it, and the over-skidding extremes, "
            "taken over every solved state, include the states at that start")


def _race_control_zero_skid(folder: Path, df: pd.DataFrame, params: list[str]) -> bool:
    """The base scene runs race control (not swept) and the summary's over-skidding is 0 %
    (to the tables' 1e-7 %) in every case."""
    col = "max over-skidding [%]"
    path = folder / "scene.toml"
    if col not in df or not path.is_file() or any(p.startswith("models.") for p in params):
        return False
    try:
        scene = _folder_scene(path)
    except InputError:
        return False
    values = pd.to_numeric(df[col], errors="coerce").to_numpy(dtype=float)
    values = values[np.isfinite(values)]
    return (scene.models.get("kinematics") == "race_control" and values.size > 0
            and bool(np.all(np.abs(values) <= 1e-7)))


#: what a sweep folder does not keep per case, and where to get it
NOT_KEPT = ("a sweep keeps per case the protocol means of the losses by source and the "
            "numbers of the summary, not the heat received by each component, the validity "
            "warnings nor the per-step tables: run one case's scene (this folder's "
            "scene.toml with the case's values) with `thermobearing run` for them")


def _chain_html(folder: Path, params: list[str]) -> str:
    """'Model chain': the models the base scene runs, with the validity range each states
    (:func:`report_sections.chain_table`, as in a run report), and what the sweep folder
    does not keep (:data:`NOT_KEPT`); a note when the folder has no base scene or it cannot
    be set up."""
    from ..errors import ThermobearingError
    from ..report_sections import chain_table, html_table
    from ..simulation import Simulation

    head = ("<h2>Model chain</h2><p>the models the base scene runs, in order, with the "
            "validity range each states (thermobearing models FAMILY gives their "
            "references)</p>")
    tail = f"<p class='note'>{escape(NOT_KEPT)}</p>"
    path = folder / "scene.toml"
    if not path.is_file():
        return head + "<p class='note'>(not available: the folder has no scene.toml)</p>" \
            + tail
    try:
        sim = Simulation(_folder_scene(path), progress=False)
    except (ThermobearingError, OSError) as exc:
        # a base scene whose files moved, or that a newer version refuses
        return head + f"<p class='note'>(not available: {escape(str(exc))})</p>" + tail
    swept = [p for p in params if p.startswith(_CHAIN_PATHS)]
    note = (f"<p class='note'>the chain of the base scene; the swept {', '.join(swept)} "
            "can change it from case to case</p>" if swept else "")
    return (head + html_table(chain_table([(link.family, link.name) for link in sim.chain]))
            + note + tail)


def _base_scene_html(folder: Path) -> str:
    """The sweep's base scene (``scene.toml`` in the folder): its title, bearings and
    conditions; a note when the folder does not record it."""
    path = folder / "scene.toml"
    if not path.is_file():
        return ("<p class='note'>(this sweep folder has no scene.toml: its base scene, the "
                "bearing and the conditions not swept, are not recorded here)</p>")
    from ..report_context import bearing_table, load_scene_bearings, supply_text
    from ..report_sections import html_table

    scene = _folder_scene(path)
    bearings, notes = load_scene_bearings(scene)
    parts = [f"<h2>Base scene: {escape(scene.title)}</h2>",
             html_table(bearing_table(scene, bearings)),
             f"<p>{escape(supply_text(scene, None))} (values the sweep sets replace "
             "these)</p>"]
    parts += [f"<p class='note'>{escape(n)}</p>" for n in notes]
    return "\n".join(parts)


def _folder_scene(path: Path, text: str | None = None) -> Any:
    """The scene a results folder records (``path``: its ``scene.toml``); a refusal names the
    file, so that a damaged folder is not mistaken for a scene the user wrote."""
    from ..scene import loads_scene

    try:
        return loads_scene(path.read_text(encoding="utf-8") if text is None else text,
                           base_dir=path.parent, source=str(path))
    except InputError as exc:
        if type(exc) is not InputError:
            raise
        raise InputError(f"{path}: {exc.field}", exc.value, exc.allowed) from None


#: where a run folder keeps the readings it compared with the prediction
COMPARISON_NOTE = ("the readings the run compared are in measured_vs_predicted.csv of this "
                   "folder")


def run_report(folder: Path) -> Path:
    from ..report import attach_figures, write_report
    from ..results import TABLES, Results

    scene_toml = (folder / "scene.toml").read_text(encoding="utf-8")
    scene = _folder_scene(folder / "scene.toml", scene_toml)
    try:
        meta = json.loads((folder / "metadata.json").read_text()) \
            if (folder / "metadata.json").is_file() else {}
    except json.JSONDecodeError as exc:
        raise InputError("metadata.json", str(folder / "metadata.json"),
                         f"the JSON written by `thermobearing run` ({exc})") from None
    tables = {t: _read_table(folder / f"{t}.csv", _NEEDED.get(t, ())) for t in TABLES
              if (folder / f"{t}.csv").is_file()}
    results = Results(tables=tables, scene_toml=scene_toml,
                      chain=[tuple(x) for x in meta.get("chain", [])],
                      citations=meta.get("citations", []), warnings=meta.get("warnings", []),
                      stats=meta.get("stats", {}),
                      check_limits=meta.get("check_limits", {}),
                      estimated=meta.get("estimated", {}),
                      flagged=meta.get("flagged_steps", {}))
    if scene.measured is not None and not scene.resolve_path(scene.measured.file).is_file():
        # the rig's file moved or deleted since the run: the report stopped with "an
        # existing data file" and was not written at all; it is written without the
        # overlay, saying so (the folder's comparison CSV still has the compared readings)
        import dataclasses

        kept = (f"; {COMPARISON_NOTE}" if (folder / "measured_vs_predicted.csv").is_file()
                else "")
        note = (f"measured file {scene.measured.file} is no longer there: this report has "
                f"no measured-vs-predicted section{kept}")
        results.warnings.insert(0, note)
        print(f"note: {note}", file=sys.stderr)
        scene = dataclasses.replace(scene, measured=None)
    losses = tables.get("losses")
    if losses is not None and not losses.empty and "source" in losses:
        # a folder of an older version has no breakdown CSV; the report refers to it
        from ..report_losses import breakdown_by_source

        breakdown_by_source(losses).to_csv(folder / "loss_breakdown.csv", index=False)
    attach_figures(results, scene)
    # the folder's PNG files are the report's figures: rewritten with it (they kept the
    # figures of the run's version while report.html had the new ones)
    for name, png in results.figures.items():
        (folder / f"{name}.png").write_bytes(png)
    # a loss map the report no longer draws (e.g. a protocol whose steps lie on one line)
    # would stay beside a report.html that does not show it
    for old in folder.glob("loss_maps*.png"):
        if old.stem not in results.figures:
            old.unlink()
    return write_report(results, scene, folder / "report.html")


def _planned(folder: Path) -> list[str] | None:
    from ..sweep_store import planned_cases

    return planned_cases(folder)


def run(args: argparse.Namespace) -> int:
    folder = Path(args.folder)
    if folder.is_file():
        # a file of a results folder (its report.html, summary.csv): it was answered "no
        # such folder here" beside the file the user had just opened
        raise InputError("folder", str(folder),
                         f"a results folder, not a file: give the folder holding it, "
                         f"`thermobearing report {folder.parent}`" if (
                             folder.parent / "scene.toml").is_file() else
                         "a results folder, not a file: the --out folder of `thermobearing "
                         "run` or `thermobearing sweep`" + (
                             f" (a scene is run with `thermobearing run {folder} --out DIR`, "
                             "which writes the report there)"
                             if folder.suffix.lower() == ".toml" else ""))
    if not folder.is_dir():
        raise InputError("folder", str(folder),
                         "an existing folder (no such folder here: give the --out folder of "
                         "`thermobearing run` or `thermobearing sweep`; `run` without --out "
                         "writes results/<scene file name>)")
    if (folder / "summary.csv").is_file() and (folder / "cases.jsonl").is_file():
        out = sweep_report(folder)
    elif (planned := _planned(folder)) is not None:
        # a sweep stopped before its first case finished: its scene.toml is the base
        # scene, not a run's (the run report stopped on the missing run tables)
        print(f"report: {folder} is a sweep folder whose sweep stopped before its first "
              f"case finished (0 of {_plural(len(planned), 'planned case')} finished): "
              "no result to report; rerun the same `thermobearing sweep` command to run "
              "the cases", file=sys.stderr)
        return 1
    elif (folder / "scene.toml").is_file():
        out = run_report(folder)
    else:
        raise InputError("folder", str(folder),
                         "a folder written by `thermobearing run` (scene.toml) or "
                         "`thermobearing sweep` (summary.csv, cases.jsonl)")
    print(f"report written to {out}")
    return 0


