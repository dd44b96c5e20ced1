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
import json
from html import escape
from pathlib import Path

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
    from ..report import fig_loss_maps, fig_whatif, figure_html
    from ..report_losses import fig_sweep_breakdown, readable, source_label, summary_sources
    from ..report_sections import html_table

    df = _read_table(folder / "summary.csv", ("case",))
    store = folder / "cases.jsonl"
    try:
        first = json.loads(store.read_text(encoding="utf-8").splitlines()[0])
        params = list(first["params"])
    except (IndexError, json.JSONDecodeError, KeyError, TypeError):
        raise InputError("cases.jsonl", str(store), "the case store of `thermobearing "
                         "sweep` (one JSON record with 'params' per line)") from None
    df = _numeric_params(df, params)
    pcols = [c for c in df.columns if any(c == p or c.startswith(p + " [") for p in params)]
    results = [c for c in df.columns if c not in pcols and c != "case"]
    figs: dict[str, bytes] = {}
    bars = fig_sweep_breakdown(df, pcols)
    if bars is not None:
        figs["loss by source [W] of every case (all bearings, protocol average)"] = bars
    sources = summary_sources(results)
    totals = [c for c in results if c.startswith("total loss") and c.endswith("[W]")]
    losses = totals + [f"{s} [W]" for s in sources]
    titles = {f"{s} [W]": f"{source_label(s)} [W]" for s in sources}
    temps = [c for c in results if c.startswith("final") or c.startswith("rise")]
    # the housing node first: it is where a rig's thermocouple sits (paper 002 Fig. 19)
    temps.sort(key=lambda c: ".housing" not in c)
    # the what-if curves: the first housing's final temperature and its rise, and the
    # oil outlet (the first bearing's oil node), which a flow or inlet what-if is about
    curves = temps[:2] + [c for c in results if c.startswith("final")
                          and c.endswith(".oil [degC]")][:1]
    for x in pcols:
        if df[x].nunique() < 2:
            continue  # a parameter held at one value draws no curve
        # a text x (oil grade) is drawn at one position per value by fig_whatif
        group = [p for p in pcols if p != x]
        ys = [c for c in ["total loss [W]", "max over-skidding [%]"] if c in df] + curves
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
    html = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>sweep report</title>",
            "<style>body{font-family:sans-serif;max-width:1100px;margin:auto}"
            "img{max-width:100%}table{font-size:12px;border-collapse:collapse}"
            "td,th{padding:2px 6px;border-bottom:1px solid #ddd}td{text-align:right}"
            ".note{color:#555;font-size:12px}</style></head><body>",
            f"<h1>Sweep report: {escape(folder.name)}</h1>",
            _base_scene_html(folder),
            f"<p>{len(df)} cases; swept: {escape(', '.join(params))}. Losses in W: each "
            "case's loss of all its bearings, averaged over its protocol (steps weighted by "
            "their duration); <code>total loss &lt;bearing&gt; [W]</code> per bearing.</p>",
            *(f"<p>{escape(n)}</p>" for n in notes),
            "<h2>Figures</h2>", *(figure_html(k, v) for k, v in figs.items()),
            "<h2>Summary</h2>",
            "<p>the sources named in words; summary.csv has their registered names</p>",
            html_table(readable(df), max_rows=500, csv_name="summary.csv"),
            "</body></html>"]
    out = folder / "report.html"
    out.write_text("\n".join(html), encoding="utf-8")
    return out


def _base_scene_html(folder: Path) -> str:
    """The sweep's base scene (``scene.toml`` in the folder): its title, bearings and
    conditions; a note when the folder does not record it."""
    path = folder / "scene.toml"
    if not path.is_file():
        return ("<p class='note'>(this sweep folder has no scene.toml: its base scene, the "
                "bearing and the conditions not swept, are not recorded here)</p>")
    from ..report_context import bearing_table, load_scene_bearings, supply_text
    from ..report_sections import html_table
    from ..scene import loads_scene

    scene = loads_scene(path.read_text(encoding="utf-8"), base_dir=folder, source=str(path))
    bearings, notes = load_scene_bearings(scene)
    parts = [f"<h2>Base scene: {escape(scene.title)}</h2>",
             html_table(bearing_table(scene, bearings)),
             f"<p>{escape(supply_text(scene, None))} (values the sweep sets replace "
             "these)</p>"]
    parts += [f"<p class='note'>{escape(n)}</p>" for n in notes]
    return "\n".join(parts)


def run_report(folder: Path) -> Path:
    from ..report import attach_figures, write_report
    from ..results import TABLES, Results
    from ..scene import loads_scene

    scene_toml = (folder / "scene.toml").read_text(encoding="utf-8")
    scene = loads_scene(scene_toml, base_dir=folder, source=str(folder / "scene.toml"))
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
                      estimated=meta.get("estimated", {}))
    losses = tables.get("losses")
    if losses is not None and not losses.empty and "source" in losses:
        # a folder of an older version has no breakdown CSV; the report refers to it
        from ..report_losses import breakdown_by_source

        breakdown_by_source(losses).to_csv(folder / "loss_breakdown.csv", index=False)
    attach_figures(results, scene)
    return write_report(results, scene, folder / "report.html")


def run(args: argparse.Namespace) -> int:
    folder = Path(args.folder)
    if (folder / "summary.csv").is_file() and (folder / "cases.jsonl").is_file():
        out = sweep_report(folder)
    elif (folder / "scene.toml").is_file():
        out = run_report(folder)
    else:
        raise InputError("folder", str(folder),
                         "a folder written by `thermobearing run` (scene.toml) or "
                         "`thermobearing sweep` (summary.csv, cases.jsonl)")
    print(f"report written to {out}")
    return 0


