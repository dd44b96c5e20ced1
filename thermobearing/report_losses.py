"""The power-loss breakdown of a run, as a reader of the report sees it.

The ``losses`` table of a run is long form (one row per step, bearing, source and
component, ``power [W]``). This module turns it into what a bearing engineer reads:

- :func:`breakdown_by_source`: one row per operating point and bearing, one ``<source> [W]``
  column per heat source, the load-dependent / load-independent split and the total
  (written by :meth:`thermobearing.results.Results.write` as ``loss_breakdown.csv``);
- :func:`breakdown_by_destination`: the same points, one column per component the heat
  goes to (inner ring, outer ring, rolling elements, cage, oil), when the table has the
  ``role`` column;
- :func:`fig_loss_bars`: stacked bars per operating point, one panel per bearing, the
  sources in one fixed order and colour in every figure of every report
  (:func:`source_colours`), named in words (:data:`SOURCE_LABELS`).

Only bookkeeping: no physics here, the powers are the heat sources' own.
"""

from __future__ import annotations

import io
import math
from collections.abc import Iterable, Mapping
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .errors import InputError  # noqa: E402

#: registered heat-source name -> what the loss is, in a bearing engineer's words; the
#: order is the order of the stacked bars and of the breakdown tables (load-dependent
#: contact friction first, then the cage, then the oil drag)
SOURCE_LABELS: dict[str, str] = {
    "raceway_traction": "raceway contacts (rolling and sliding shear)",
    "ehl_rolling_resistance": "EHL rolling resistance",
    "rib_friction": "roller end / rib friction",
    "pocket_friction": "cage pockets (element / pocket friction)",
    "cage_guide": "cage guide land (film shear)",
    "churning_elements": "oil drag on the rolling elements (churning)",
    "churning_cage": "oil drag on the cage (churning)",
    "churning_inner_ring": "oil drag on the inner ring (churning)",
    "global_friction": "whole bearing (catalogue friction model)",
}

#: node role of the heat -> the component it heats, in words
ROLE_LABELS: dict[str, str] = {
    "inner_ring": "inner ring",
    "outer_ring": "outer ring",
    "elements": "rolling elements",
    "cage": "cage",
    "oil": "oil",
}

#: loss class of the losses table -> words (FVA split of the frictional moment, losses.py)
CLASS_LABELS: dict[str, str] = {"load_dependent": "load-dependent",
                                "load_independent": "load-independent"}

#: the columns of a breakdown table that are not a source
_NOT_SOURCES = frozenset({"total [W]", "unclassified [W]",
                          *(f"{label} [W]" for label in CLASS_LABELS.values())})

#: operating-point columns of the losses / kinematics tables, in display order
OPERATING = ("speed [rpm]", "radial load [kN]", "axial load [kN]")

_PALETTE = tuple(plt.get_cmap("tab10").colors) + tuple(plt.get_cmap("Dark2").colors)


def source_label(name: str) -> str:
    """The words for heat source ``name`` (a plug-in source: its name, underscores as
    spaces)."""
    return SOURCE_LABELS.get(name, name.replace("_", " "))


def source_order(names: Iterable[str]) -> list[str]:
    """``names`` (each once) in the fixed display order: the known sources in the order of
    :data:`SOURCE_LABELS`, then any other (plug-in) source alphabetically."""
    known = list(SOURCE_LABELS)
    unique = set(names)
    return ([n for n in known if n in unique]
            + sorted(n for n in unique if n not in SOURCE_LABELS))


def source_colours(names: Iterable[str]) -> dict[str, Any]:
    """One colour per source that depends on the source alone: a known source has the
    colour of its place in :data:`SOURCE_LABELS` in every figure; other sources take the
    colours after those, in alphabetical order."""
    known = list(SOURCE_LABELS)
    out: dict[str, Any] = {}
    others = sorted(n for n in set(names) if n not in SOURCE_LABELS)
    for n in set(names):
        i = known.index(n) if n in SOURCE_LABELS else len(known) + others.index(n)
        out[n] = _PALETTE[i % len(_PALETTE)]
    return out


def _check(losses: pd.DataFrame, needed: Iterable[str]) -> None:
    missing = [c for c in needed if c not in losses.columns]
    if missing:
        raise InputError("losses table columns", list(losses.columns),
                         "a losses table of `thermobearing run` with "
                         + ", ".join(repr(c) for c in missing))


def point_keys(losses: pd.DataFrame) -> list[str]:
    """The columns that identify one operating point of one bearing in ``losses``: step and
    bearing (those present), the time when one step has rows at several times, and the
    speed and loads (constant within a step, kept for the reader)."""
    keys = [c for c in ("step", "bearing") if c in losses]
    if "time [s]" in losses and "step" in losses:
        if (losses.groupby("step")["time [s]"].nunique() > 1).any():
            keys.append("time [s]")
    keys += [c for c in OPERATING if c in losses]
    if not keys:
        raise InputError("losses table columns", list(losses.columns),
                         "a step, bearing or operating-point column")
    return keys


def breakdown_by_source(losses: pd.DataFrame) -> pd.DataFrame:
    """One row per operating point and bearing: ``<source> [W]`` per heat source (the sum of
    its components, in :func:`source_order`), ``load-dependent [W]`` and
    ``load-independent [W]`` when the table has the ``load dependence`` column (and
    ``unclassified [W]`` when some component has no class), and ``total [W]``, the sum of
    the source columns. A source without rows at a point (it does not run on that bearing)
    is left empty there.

    ``losses``: the long ``losses`` table (``source``, ``power [W]`` and the point columns
    of :func:`point_keys`).
    """
    _check(losses, ("source", "power [W]"))
    keys = point_keys(losses)
    # a source that did not run on a bearing (another kind's source on a mixed shaft) has
    # no rows there: its cell stays empty (NaN), not 0 W, and the sums skip it
    pivot = losses.pivot_table(index=keys, columns="source", values="power [W]",
                               aggfunc="sum", sort=False)
    order = source_order(pivot.columns)
    out = pivot[order].rename(columns={s: f"{s} [W]" for s in order})
    if "load dependence" in losses:
        cls = losses.pivot_table(index=keys, columns="load dependence", values="power [W]",
                                 aggfunc="sum", fill_value=0.0, sort=False)
        for c, label in CLASS_LABELS.items():
            out[f"{label} [W]"] = cls[c] if c in cls else 0.0
        # a component its source gives no class (empty cell): shown, so that the classes
        # still add up to the total
        rest = pivot[order].sum(axis=1) - sum(out[f"{label} [W]"]
                                               for label in CLASS_LABELS.values())
        if (rest.abs() > 1e-9 * pivot[order].sum(axis=1).abs().clip(lower=1.0)).any():
            out["unclassified [W]"] = rest
    out["total [W]"] = pivot[order].sum(axis=1)
    out.columns.name = None
    return out.reset_index()


def breakdown_by_destination(losses: pd.DataFrame) -> pd.DataFrame | None:
    """One row per operating point and bearing: the heat each component receives,
    ``<component> [W]`` (inner ring, outer ring, rolling elements, cage, oil: the ``role``
    column, :data:`ROLE_LABELS`), and ``total [W]``; None when the table has no ``role``
    column (then the heat sources' split over the components was not recorded)."""
    if "role" not in losses:
        return None
    _check(losses, ("power [W]",))
    keys = point_keys(losses)
    pivot = losses.pivot_table(index=keys, columns="role", values="power [W]",
                               aggfunc="sum", fill_value=0.0, sort=False)
    roles = [r for r in ROLE_LABELS if r in pivot.columns] + sorted(
        r for r in pivot.columns if r not in ROLE_LABELS)
    out = pivot[roles].rename(columns={r: f"{ROLE_LABELS.get(r, r)} [W]" for r in roles})
    out["total [W]"] = pivot[roles].sum(axis=1)
    out.columns.name = None
    return out.reset_index()


def shares(breakdown: pd.DataFrame) -> pd.DataFrame:
    """Each ``<source> [W]`` column of :func:`breakdown_by_source` as a share of the
    point's total, ``<source> [%]`` (0 where the total is 0)."""
    cols = [c for c in breakdown.columns if c.endswith(" [W]") and c not in _NOT_SOURCES]
    keys = [c for c in breakdown.columns if not c.endswith(" [W]")]
    total = breakdown["total [W]"].where(breakdown["total [W]"] > 0, np.nan)
    out = breakdown[keys].copy()
    for c in cols:
        out[c[:-4] + " [%]"] = (100.0 * breakdown[c] / total).fillna(0.0)
    return out


def map_axes(breakdown: pd.DataFrame) -> tuple[str, str] | None:
    """The two operating quantities of a speed x load map, when the points of
    :func:`breakdown_by_source` cover one: the speed and the one load that vary, each with
    at least two values (a contour needs 2 x 2 points); None otherwise (one quantity
    varies, or both loads vary with the speed)."""
    varying = [c for c in OPERATING if c in breakdown and breakdown[c].nunique() > 1]
    if len(varying) != 2 or "speed [rpm]" not in varying:
        return None
    return varying[0], varying[1]


#: the least share of a speed x load grid's combinations that a run's steps must cover
#: for its loss map: below it most of the contoured area would be interpolated over
#: combinations no step ran
MAP_MIN_FILLED = 0.5


def map_coverage(breakdown: pd.DataFrame, x: str, y: str) -> tuple[int, int, int]:
    """How the points of a breakdown cover the grid of their ``x`` and ``y`` values:
    (combinations that ran, combinations of the grid, complete cells). A cell is a block
    of two neighbouring ``x`` values by two neighbouring ``y`` values; ``contourf`` draws
    only inside the complete ones (a protocol raising speed and load together, 900 r/min
    at 5 kN, 1500 at 15, 1800 at 25, covers 3 of 9 combinations and no cell)."""
    xs = sorted(set(breakdown[x].to_numpy(float)))
    ys = sorted(set(breakdown[y].to_numpy(float)))
    ran = set(zip(breakdown[x].to_numpy(float), breakdown[y].to_numpy(float), strict=True))
    cells = sum(all(p in ran for p in ((a, c), (b, c), (a, d), (b, d)))
                for a, b in zip(xs, xs[1:], strict=False)
                for c, d in zip(ys, ys[1:], strict=False))
    return len(ran), len(xs) * len(ys), cells


def map_gap(breakdown: pd.DataFrame, x: str, y: str) -> str | None:
    """Why the points of a breakdown over ``x`` and ``y`` (:func:`map_axes`) give no
    contour map, in words; None when they do: at least one complete cell of the grid
    (:func:`map_coverage`) and at least :data:`MAP_MIN_FILLED` of its combinations ran."""
    ran, total, cells = map_coverage(breakdown, x, y)
    if cells and ran >= MAP_MIN_FILLED * total:
        return None
    nx, ny = breakdown[x].nunique(), breakdown[y].nunique()
    what = f"{ran} of the {total} combinations of their {nx} speeds and {ny} {_words(y)}s"
    if not cells:
        together = " (each speed ran at one load)" if ran == nx == ny else ""
        why = (f"not one 2 x 2 block of neighbouring ones{together}: a contour needs "
               "the four corners of a block, so a map would show the points and no contour")
    else:
        why = (f"less than {100 * MAP_MIN_FILLED:.0f} % of them: most of a map would be "
               "interpolated over combinations no step ran")
    return f"the steps ran {what}, {why}"


def _words(column: str) -> str:
    """``radial load [kN]`` -> ``radial load``."""
    return column.split(" [", 1)[0]


def turning_points(breakdown: pd.DataFrame) -> pd.DataFrame:
    """The rows of a breakdown at a speed other than 0 (a step at rest, a stop in a rig
    protocol, books 0 W and is no point of a speed map)."""
    if "speed [rpm]" not in breakdown:
        return breakdown
    return breakdown[breakdown["speed [rpm]"].to_numpy(float) != 0.0]


def summary_lines(breakdown: pd.DataFrame) -> list[str]:
    """One sentence per bearing of a :func:`breakdown_by_source` table: the range of its
    total loss over the operating points (naming the points) and the largest source at the
    point of the highest loss, with its power and share. Steps at rest (0 r/min, 0 W) are
    left out of the range and named ("total loss 0 W (step 4, 0 r/min) to 400 W" said
    nothing of the turning steps' smallest loss)."""
    sources = [c for c in breakdown.columns if c.endswith(" [W]") and c not in _NOT_SOURCES]
    groups = breakdown.groupby("bearing", sort=False) if "bearing" in breakdown else \
        [(None, breakdown)]
    lines = []
    for name, g in groups:
        # steps at rest book 0 W: the range is that of the turning steps (as the
        # catalogue cross-check leaves them out), the steps at rest named after it
        turning = turning_points(g)
        span = turning if len(turning) else g
        rest = g.drop(index=turning.index) if len(turning) else g.iloc[:0]
        lo = span.loc[span["total [W]"].idxmin()]
        hi = span.loc[span["total [W]"].idxmax()]
        who = f"bearing {name}: " if name is not None else ""
        if len(span) == 1:
            text = f"{who}total loss {fmt_power(hi['total [W]'])} W ({_point(hi)})"
        else:
            text = (f"{who}total loss {fmt_power(lo['total [W]'])} W ({_point(lo)}) to "
                    f"{fmt_power(hi['total [W]'])} W ({_point(hi)})")
        if len(rest):
            which = (", ".join(f"{s}" for s in rest["step"]) if "step" in rest else "")
            text += (f" over the turning steps (at rest, 0 r/min and no loss, left out: "
                     f"step{'s' if len(rest) > 1 else ''} {which})" if which else
                     " over the turning steps (those at rest, 0 r/min, left out)")
        if sources and hi["total [W]"] > 0:
            top = max(sources, key=lambda c: hi[c])
            text += (f"; the largest source there is {source_label(top[:-4])}, "
                     f"{fmt_power(hi[top])} W ({100.0 * hi[top] / hi['total [W]']:.0f} %)")
        lines.append(text)
    return lines


def _point(row: pd.Series) -> str:
    units = {"speed [rpm]": "r/min", "radial load [kN]": "kN radial",
             "axial load [kN]": "kN axial"}
    where = [f"{row[c]:g} {u}" for c, u in units.items() if c in row]
    step = f"step {row['step']}" if "step" in row else ""
    return ", ".join([step] + where) if step else ", ".join(where)


def fmt_power(v: Any) -> str:
    """A power [W] rounded for a reader: whole watts from 10 W, one decimal from 1 W,
    two significant digits below (losses carry model errors of several per cent)."""
    if not isinstance(v, (int, float, np.number)) or isinstance(v, bool):
        return str(v)
    v = float(v)
    if not math.isfinite(v):
        return str(v)
    a = abs(v)
    if a == 0.0:
        return "0"
    if a >= 10.0:
        return f"{v:,.0f}"
    if a >= 1.0:
        return f"{v:.1f}"
    return f"{v:.2g}"


def readable(table: pd.DataFrame) -> pd.DataFrame:
    """A breakdown table with its source columns named in words (``<label> [W]`` or
    ``[%]``) for the report; the CSV keeps the registered names."""
    names = {}
    for c in table.columns:
        for unit in (" [W]", " [%]"):
            if c.endswith(unit) and c[:-len(unit)] in SOURCE_LABELS:
                names[c] = source_label(c[:-len(unit)]) + unit
    return table.rename(columns=names)


def _operating_axis(df: pd.DataFrame) -> tuple[str, dict[Any, float], list[str], str]:
    from .report import operating_axis

    return operating_axis(df)


#: width of a bar panel of :func:`_stacked_panels` left of the legend [pt] (9 in figure)
_PANEL_WIDTH_PT = 430.0
#: mean width of a character of the 7-pt tick labels [pt] (DejaVu Sans)
_CHAR_PT = 4.3


def tick_layout(labels: list[str], width_pt: float) -> tuple[list[str], int]:
    """Tick labels of ``len(labels)`` evenly spaced bars over ``width_pt`` points, and their
    rotation [deg], laid out so that neighbours do not overlap: as given when they fit,
    else each ``a / b`` label on lines of its own (``1500 r/min`` over ``3 kN radial``),
    else the one-line labels turned upright (90 deg)."""
    if not labels:
        return labels, 0
    room = 0.9 * width_pt / len(labels)
    if max(len(s) for s in labels) * _CHAR_PT <= room:
        return labels, 0
    stacked = [s.replace(" / ", "\n") for s in labels]
    widest = max(len(line) for s in stacked for line in s.split("\n"))
    lines = max(s.count("\n") + 1 for s in stacked)
    if widest * _CHAR_PT <= room and lines <= 3:
        return stacked, 0
    return labels, 90


def _stacked_panels(losses: pd.DataFrame, column: str, order: list[str],
                    colours: Mapping[str, Any], label_of: Any, ylabel: str,
                    legend_title: str) -> bytes:
    """Stacked bars of ``power [W]`` per operating point, one bar segment per value of
    ``column`` (in ``order``, then any other value alphabetically), one panel per bearing,
    one legend for all panels (top of the stack first, as the bars read)."""
    names = list(dict.fromkeys(losses["bearing"])) if "bearing" in losses else [None]
    fig, axes = plt.subplots(len(names), 1, figsize=(9, 3.6 * len(names) + 0.8),
                             squeeze=False, sharey=True, layout="constrained")
    for ax, name in zip(axes[:, 0], names, strict=True):
        df = losses if name is None else losses[losses["bearing"] == name]
        key, pos, labels, xlabel = _operating_axis(df)
        pivot = df.pivot_table(index=key, columns=column, values="power [W]",
                               aggfunc="sum").fillna(0.0)
        x = np.array([pos[k] for k in pivot.index])
        bottom = np.zeros(len(pivot))
        for value in order + sorted(set(pivot.columns) - set(order)):
            if value not in pivot:
                continue
            ax.bar(x, pivot[value].to_numpy(), bottom=bottom, color=colours.get(value),
                   label=label_of(value))
            bottom += pivot[value].to_numpy()
        every = max(1, math.ceil(len(labels) / 30))
        shown, rotation = tick_layout(labels[::every], _PANEL_WIDTH_PT)
        ax.set_xticks(np.arange(0, len(labels), every), shown, rotation=rotation,
                      fontsize=7)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        if name is not None:
            ax.set_title(f"bearing {name}", fontsize=9)
        ax.grid(axis="y", alpha=0.3)
    handles, labels_ = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles[::-1], labels_[::-1], loc="outside right upper", fontsize=7,
               title=legend_title, title_fontsize=7)
    return _png(fig)


def fig_loss_bars(losses: pd.DataFrame, bearing: str | None = None) -> bytes:
    """Stacked power-loss bars [W] per operating point, one colour per source (paper 002
    Fig. 15), one panel per bearing (``bearing``: that one only). The sources are stacked
    in :func:`source_order` with the colours of :func:`source_colours`, so every figure of
    every report shows a source in the same place and colour; the axis is the swept
    quantity, or the step labelled with what varies (``report.operating_axis``)."""
    _check(losses, ("source", "power [W]"))
    if bearing is not None:
        losses = losses[losses["bearing"] == bearing]
    order = source_order(losses["source"])
    return _stacked_panels(losses, "source", order, source_colours(order), source_label,
                           "power loss [W]", "loss source")


def fig_destinations(losses: pd.DataFrame) -> bytes | None:
    """Stacked bars of the heat per receiving component [W] (inner ring, outer ring,
    rolling elements, cage, oil) per operating point, one panel per bearing; None when the
    losses table has no ``role`` column."""
    if "role" not in losses:
        return None
    roles = [r for r in ROLE_LABELS if r in set(losses["role"])]
    colours = dict(zip(ROLE_LABELS, plt.get_cmap("Set2").colors, strict=False))
    return _stacked_panels(losses, "role", roles, colours,
                           lambda r: ROLE_LABELS.get(r, r), "heat received [W]",
                           "heat goes to")


def summary_sources(columns: Iterable[str]) -> list[str]:
    """The heat sources with a ``<source> [W]`` column in a sweep summary or a
    :func:`breakdown_by_source` table, in :func:`source_order` (totals -- the sweep's
    ``mean total loss [W]`` and ``mean total loss <bearing> [W]`` too --, maxima, minima
    and the loss classes are not sources)."""
    names = [c[:-4] for c in columns if str(c).endswith(" [W]") and c not in _NOT_SOURCES
             and not str(c).startswith(("mean total loss", "total loss", "max ", "min "))]
    return source_order(names)


#: cases per row of the sweep's stacked bars (:func:`fig_sweep_breakdown`)
_BARS_PER_ROW = 36


def fig_sweep_breakdown(summary: pd.DataFrame, params: list[str]) -> bytes | None:
    """Stacked bars of the loss by source [W] for every case of a sweep summary (the
    ``<source> [W]`` columns: all bearings, averaged over the protocol), the cases sorted by
    the swept parameters ``params`` and each labelled with its values, in rows of at most
    :data:`_BARS_PER_ROW` cases on one loss scale; the sources in the order and colours of
    every other loss figure. None when the summary has no sources."""
    sources = summary_sources(summary.columns)
    if not sources:
        return None
    from .report import sort_cases  # oils in viscosity order, as in the what-if panels

    df = sort_cases(summary, params) if params else summary
    colours = source_colours(sources)
    # a swept file (lubricant.path, made absolute by the sweep) by its file name: two full
    # paths stood as 45-character upright labels under a plot squeezed to a third
    from .report import category_labels

    shown = {}
    for p in params:
        values = list(dict.fromkeys(df[p].tolist()))
        shown[p] = dict(zip(values, category_labels(values), strict=True))
    labels = [" / ".join(shown[p][row[p]] if isinstance(row[p], str) else _fmt(row[p])
                         for p in params) for _, row in df.iterrows()]
    # rows of at most _BARS_PER_ROW cases, every bar labelled: one row of 72 bars was a
    # 3100 px strip labelling every other case, shrunk to a third in the report
    rows = max(1, math.ceil(len(df) / _BARS_PER_ROW))
    per_row = math.ceil(len(df) / rows)
    fig, axes = plt.subplots(rows, 1, figsize=(max(6.0, 0.35 * per_row + 3.0), 4.2 * rows),
                             sharey=True, squeeze=False, layout="constrained")
    for r, ax in enumerate(axes[:, 0]):
        part = df.iloc[r * per_row:(r + 1) * per_row]
        x = np.arange(len(part))
        bottom = np.zeros(len(part))
        for src in sources:
            values = part[f"{src} [W]"].fillna(0.0).to_numpy(float)
            ax.bar(x, values, bottom=bottom, color=colours[src], label=source_label(src))
            bottom += values
        ax.set_xticks(x, labels[r * per_row:(r + 1) * per_row], rotation=90, fontsize=7)
        ax.set_xlim(-0.6, per_row - 0.4)
        ax.set_ylabel("power loss [W] (all bearings, protocol average)", fontsize=8)
        ax.grid(axis="y", alpha=0.3)
    axes[-1, 0].set_xlabel(" / ".join(params))
    handles, names = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles[::-1], names[::-1], loc="outside right upper", fontsize=7,
               title="loss source", title_fontsize=7)
    return _png(fig)


def _fmt(v: Any) -> str:
    return f"{v:g}" if isinstance(v, (int, float, np.number)) else str(v)


def network_heat_check(losses: pd.DataFrame, energy: pd.DataFrame) -> pd.DataFrame | None:
    """The loss breakdown against the heat the thermal network received (energy audit of
    the breakdown): for each time of the losses table (a step's end), the breakdown's total
    over all bearings [W] and the network's mean heat input over the output interval that
    ends there, (generated[k] - generated[k-1]) / (t[k] - t[k-1]) from the ``energy``
    table [W], and their difference [%]. The two agree to the change of the heat over
    that interval (the breakdown is evaluated at its end). None without the columns
    (``time [s]``, ``generated [J]``) or without matching times."""
    if energy is None or energy.empty or "time [s]" not in losses or not {
            "time [s]", "generated [J]"} <= set(energy.columns):
        return None
    t = energy["time [s]"].to_numpy(float)
    gen = energy["generated [J]"].to_numpy(float)
    if t[0] > 0.0:  # the table starts after the first interval: nothing generated at 0
        t, gen = np.concatenate(([0.0], t)), np.concatenate(([0.0], gen))
    keys = ["step", "time [s]"] if "step" in losses else ["time [s]"]
    rows = []
    for key, g in losses.groupby(keys, sort=True):
        key = key if isinstance(key, tuple) else (key,)
        te = float(key[-1])
        k = int(np.argmin(np.abs(t - te)))
        if k == 0 or abs(t[k] - te) > 1e-6 * max(1.0, te):
            continue
        rate = (gen[k] - gen[k - 1]) / (t[k] - t[k - 1])
        total = float(g["power [W]"].sum())
        rows.append({**dict(zip(keys, key, strict=True)), "breakdown total [W]": total,
                     "network heat input [W]": rate,
                     "difference [%]": 100.0 * (rate / total - 1.0) if total else math.nan})
    return pd.DataFrame(rows) if rows else None


def _png(fig: plt.Figure) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def glossary(losses: pd.DataFrame) -> pd.DataFrame:
    """The heat sources of a losses table: registered name (the CSV column), what it is,
    its loss class (load-dependent / load-independent, ``losses.py``) when known, and,
    when the run has points that differ in one load only, how much the source changed
    with the load in this run (:func:`load_response`)."""
    order = source_order(losses["source"])
    out = pd.DataFrame({"in the CSV files": order,
                        "loss": [source_label(s) + _global_model_text(losses, s)
                                 for s in order]})
    classes = loss_class_of(losses)
    if classes:
        out["class"] = [classes.get(s, "") for s in order]
    response = load_response(losses)
    if response:
        out["change with the load in this run"] = [
            _response_text(response[s]) if s in response else "" for s in order]
    return out


#: registered global friction models -> their names in the report
_GLOBAL_MODELS = {"skf_four_term": "SKF four-term", "palmgren": "Palmgren M0 + M1"}


def _global_model_text(losses: pd.DataFrame, source: str) -> str:
    """``: <model>`` for the ``global_friction`` source, the catalogue model(s) its
    components name (``skf_four_term rolling``, ``palmgren M0``); empty otherwise."""
    if source != "global_friction" or "component" not in losses:
        return ""
    comps = losses.loc[losses["source"] == source, "component"].astype(str)
    models = [m for m in _GLOBAL_MODELS if comps.str.startswith(m + " ").any()
              or (comps == m).any()]
    return (": " + ", ".join(_GLOBAL_MODELS[m] for m in models)) if models else ""


#: relative change with the load [-] beyond which a load-independent source is named in
#: :func:`class_notes` (the class is a nominal one; a few per cent come from the
#: kinematics a load moves)
LOAD_CHANGE_NOTE = 0.10


def load_response(losses: pd.DataFrame) -> dict[str, dict[str, Any]]:
    """Per source, the largest relative change of its power [-] between two points of the
    run that differ in one load only (same bearing, speed and other load): ``change``
    (power at the higher load / power at the lower load - 1), ``load`` (the column),
    ``low`` and ``high`` (its values [kN]) and ``speed`` [rpm]. Empty when no two points
    differ in one load only; a source at 0 W at the lower load is left out there."""
    wide = breakdown_by_source(losses)
    sources = summary_sources(wide.columns)
    loads = [c for c in ("radial load [kN]", "axial load [kN]") if c in wide]
    out: dict[str, dict[str, Any]] = {}
    for col in loads:
        fixed = [c for c in ("bearing", "speed [rpm]", *loads) if c in wide and c != col]
        for _key, g in wide.groupby(fixed, sort=False) if fixed else [((), wide)]:
            if g[col].nunique() < 2 or ("speed [rpm]" in g and
                                        float(g["speed [rpm]"].iloc[0]) == 0.0):
                continue
            lo, hi = g.loc[g[col].idxmin()], g.loc[g[col].idxmax()]
            for src in sources:
                a, b = float(lo[f"{src} [W]"]), float(hi[f"{src} [W]"])
                if not (math.isfinite(a) and math.isfinite(b)) or a <= 0.0:
                    continue
                change = b / a - 1.0
                if src not in out or abs(change) > abs(out[src]["change"]):
                    out[src] = {"change": change, "load": col, "low": float(lo[col]),
                                "high": float(hi[col]),
                                "speed": float(lo.get("speed [rpm]", math.nan))}
    return out


def _response_text(r: Mapping[str, Any]) -> str:
    kind = r["load"].split()[0]
    where = f" at {r['speed']:g} r/min" if math.isfinite(r["speed"]) else ""
    return (f"{_percent_change(100.0 * r['change'])} % from {r['low']:g} to {r['high']:g} "
            f"kN {kind}{where}")


def _percent_change(pct: float) -> str:
    """A change in per cent with its sign: whole per cent from 1 %, two significant digits
    below (``-0.11``; ``"-0"`` read as a sign without a change), ``+0`` for none."""
    if pct == 0.0:
        return "+0"
    return f"{pct:+.0f}" if abs(pct) >= 1.0 else f"{pct:+.2g}"


def class_notes(losses: pd.DataFrame) -> list[str]:
    """A note naming each source classed load-independent whose power changed by more than
    :data:`LOAD_CHANGE_NOTE` with the load in this run: the class (the FVA M0 / M1 split,
    ``losses.py``) is the source's nominal one, and the load-dependent / load-independent
    columns follow it, not the run."""
    classes = loss_class_of(losses)
    response = load_response(losses)
    moved = [s for s, c in classes.items() if c == "load-independent" and s in response
             and abs(response[s]["change"]) > LOAD_CHANGE_NOTE]
    if not moved:
        return []
    said = "; ".join(f"{source_label(s)}: {_response_text(response[s])}"
                     for s in source_order(moved))
    return [f"the load-dependent / load-independent split follows each source's nominal "
            f"class (Palmgren's M1 / M0), not this run: sources classed load-independent "
            f"changed with the load here ({said}), so the load-independent column holds "
            f"load-driven loss too"]


def loss_class_of(losses: pd.DataFrame) -> Mapping[str, str]:
    """Source -> its loss class in words (``mixed`` if its components differ); empty
    without the ``load dependence`` column. Rows without a class (an empty cell: the 0 W
    row each source books at a step at rest, or a component its source gives no class)
    do not count; a source with no classed row at all gets an empty string."""
    if "load dependence" not in losses:
        return {}
    out = {}
    for src, g in losses.groupby("source"):
        classes = {CLASS_LABELS.get(c, str(c)) for c in g["load dependence"]
                   if isinstance(c, str) and c}
        out[str(src)] = (classes.pop() if len(classes) == 1
                         else "mixed" if classes else "")
    return out
