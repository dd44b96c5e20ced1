"""Figures and the self-contained HTML report of a run.

Figures (PNG bytes, matplotlib with the Agg backend):

- temperatures against time, measured data overlaid, with per-sensor RMSE / max error
  and the measured file's notes (:mod:`.report_measured`); steady-state temperatures per
  operating point (``mode = "steady"``);
- stacked power-loss bars per operating point (in the style of seed paper 002 Fig. 15);
- cage speed ratio against axial load with the theoretical ratio (paper 002 Fig. 10);
- speed x load maps of each loss component and oil-flow what-if curves (from a sweep
  summary, paper 002 Figs. 16-17).

:func:`html_report` writes one HTML file with every figure embedded as base64: the bearing
and its operating points, the loss breakdown (:mod:`.report_sections`,
:mod:`.report_losses`, :mod:`.report_context`), the validity warnings, the model chain that
ran with the validity ranges of its models, the energy audit, the estimated inputs, the
tables, the scene and its citations.
"""

from __future__ import annotations

import base64
import dataclasses
import html
import io
import math
import re
import textwrap
import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from .errors import InputError  # noqa: E402
from .operating_checks import CheckLimits  # noqa: E402
from .report_losses import (  # noqa: E402
    fig_destinations,
    fig_loss_bars,
    network_heat_check,
)
from .report_measured import (  # noqa: E402  (re-exported: the report's public names)
    COMPARISON_CSV,
    comparison_notes,
    comparison_table,
    fig_temperatures,
    temperature_errors,
)
from .results import Results  # noqa: E402
from .warning_groups import merge_twin_bearings  # noqa: E402

#: the sections every report has (with a scene also "Bearing and operating points")
SECTIONS = ("Loss breakdown", "Figures", "Validity warnings", "Model chain", "Energy audit",
            "Estimated inputs", "Tables", "Scene", "Citations")


def _png(fig: plt.Figure) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def steady_with_operating(steady: pd.DataFrame, points: pd.DataFrame | None
                          ) -> pd.DataFrame:
    """The steady table with the operating columns (speed, radial and axial load) per step.

    ``steady_temperatures.csv`` carries them itself (since 2026-11-24); only the ones it
    lacks are taken from ``points`` (older run folders), so no column is doubled with a
    ``_x`` / ``_y`` suffix that would hide the operating axis.
    """
    if points is None or "step" not in points or "step" not in steady:
        return steady
    cols = ["step"] + [c for c, _ in _OPERATING if c in points and c not in steady]
    if len(cols) == 1:
        return steady
    return steady.merge(points[cols].drop_duplicates("step"), on="step", how="left")


def fig_steady_temperatures(steady: pd.DataFrame, points: pd.DataFrame | None = None
                            ) -> bytes:
    """Steady-state node temperatures [degC] per step (``mode = "steady"``), one line per
    node (colour per node kind, line style per bearing as in :func:`fig_temperatures`);
    the axis is the swept quantity of ``points`` (a table with ``step`` and the operating
    columns, e.g. the kinematics table), else the step."""
    nodes = [c[:-len(" [degC]")] for c in steady.columns if c.endswith(" [degC]")]
    df = steady_with_operating(steady, points)
    key, pos, labels, xlabel = operating_axis(df)
    df = df.assign(_x=[pos[k] for k in df[key]]).sort_values("_x")
    groups = list(dict.fromkeys(n.split(".", 1)[0] for n in nodes if "." in n))
    kinds = list(dict.fromkeys(n.split(".", 1)[-1] for n in nodes))
    palette = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    styles = ("-", "--", ":", "-.")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for n in nodes:
        g = n.split(".", 1)[0] if "." in n else ""
        ax.plot(df["_x"], df[f"{n} [degC]"], "o", label=n, ms=4,
                color=palette[kinds.index(n.split(".", 1)[-1]) % len(palette)],
                ls=styles[groups.index(g) % len(styles)] if g in groups else "-")
    ax.set_xticks(np.arange(len(labels)), labels, rotation=90 if len(labels) > 8 else 0,
                  fontsize=7)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("steady-state temperature [degC]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    return _png(fig)


_OPERATING = (("speed [rpm]", "r/min"), ("radial load [kN]", "kN radial"),
              ("axial load [kN]", "kN axial"))


def operating_axis(df: pd.DataFrame) -> tuple[str, dict[Any, float], list[str], str]:
    """How to lay the operating points of a losses / kinematics table along an axis.

    Returns (key column, position of each key value, tick labels, axis label). When one
    of speed, radial load and axial load varies and the steps have distinct values of it
    (a load or speed sweep), the axis is that quantity; otherwise (several vary, or a
    value repeats) it is the step, labelled with the quantities that vary.
    """
    cols = [c for c, _ in _OPERATING if c in df]
    key = "step" if "step" in df else (cols[-1] if cols else None)
    if key is None:
        raise InputError("table", list(df.columns), "a step or an operating-point column")
    points = df.drop_duplicates(key).sort_values(key)
    varying = [c for c in cols if points[c].nunique() > 1]
    if len(varying) == 1 and points[varying[0]].is_unique:
        col = varying[0]
        order = points.sort_values(col)
        pos = {k: float(i) for i, k in enumerate(order[key])}
        return key, pos, [f"{v:g}" for v in order[col]], col
    pos = {k: float(i) for i, k in enumerate(points[key])}
    units = dict(_OPERATING)
    labels = [" / ".join(f"{row[c]:g} {units[c]}" for c in varying) or f"{row[key]}"
              for _, row in points.iterrows()]
    return key, pos, labels, "step" if key == "step" else key


def fig_csr(kin: pd.DataFrame) -> bytes:
    """Cage speed ratio against the swept quantity (paper 002 Fig. 10: axial load, one line
    per speed when the protocol repeats the load sweep at several speeds), with the
    theoretical (epicyclic) ratio dashed; against the step when other quantities vary."""
    fig, ax = plt.subplots(figsize=(7, 4.2))
    points = kin.drop_duplicates("step") if "step" in kin else kin
    varying = {c for c, _ in _OPERATING if c in kin and points[c].nunique() > 1}
    per_speed = varying == {"speed [rpm]", "axial load [kN]"}
    groups = kin.groupby(["bearing", "speed [rpm]"] if per_speed else ["bearing"])
    labels: list[str] = []
    for name, g in groups:
        name = name if isinstance(name, tuple) else (name,)
        if per_speed:
            g = g.sort_values("axial load [kN]").assign(_x=lambda d: d["axial load [kN]"])
            xlabel = "axial load [kN]"
        else:
            key, pos, labels, xlabel = operating_axis(g)
            g = g.assign(_x=[pos[k] for k in g[key]]).sort_values("_x")
        label = name[0] if len(name) == 1 else f"{name[0]}, {name[1]:.0f} r/min"
        # a step at rest has no cage speed ratio: no point, so no legend entry ("test,
        # 0 r/min" named an empty line)
        csr = pd.to_numeric(g["cage speed ratio [-]"], errors="coerce").to_numpy(float)
        if per_speed and (name[1] == 0.0 or not np.isfinite(csr).any()):
            continue
        ax.plot(g["_x"], g["cage speed ratio [-]"], "o-", ms=3,
                label=label if np.isfinite(csr).any() else None)
        if "theoretical cage speed ratio [-]" in g:
            # named once in the legend: the PNG file is read without the report's caption
            named = "theoretical (epicyclic) CSR" not in ax.get_legend_handles_labels()[1]
            ax.plot(g["_x"], g["theoretical cage speed ratio [-]"], "k--", lw=0.8,
                    label="theoretical (epicyclic) CSR" if named else None)
    if labels:
        every = max(1, math.ceil(len(labels) / 30))
        ax.set_xticks(np.arange(0, len(labels), every), labels[::every], rotation=90,
                      fontsize=7)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("cage speed ratio CSR [-]")
    ax.grid(alpha=0.3)
    handles, names = ax.get_legend_handles_labels()
    order = sorted(range(len(names)), key=lambda i: names[i] == "theoretical (epicyclic) CSR")
    ax.legend([handles[i] for i in order], [names[i] for i in order], fontsize=7)
    return _png(fig)


#: under the kinematics table of a transient run: which state its rows are
KINEMATICS_ROWS_NOTE = ("one row per step and bearing: the state solved at the step's start "
                        "(its time [s]); the kinematics are re-solved within a step as the "
                        "temperatures move, and the skid warnings take the worst of those "
                        "states")

#: above the validity warnings of a steady run: which states they are
STEADY_WARNINGS_NOTE = ("a steady run: the warnings and operating checks are those of each "
                        "step's steady state; the fixed-point iterates on the way to it are "
                        "no states the bearing runs in and are not reported")

#: the sign of the measured-vs-predicted table's mean error, said under the table
MEAN_ERROR_NOTE = ("errors are predicted - measured at the measured times: a negative mean "
                   "error is a model that runs colder than the sensor")

#: the loss-map note on a grid point without a result: a sweep's case that failed or has
#: not run yet, or a speed x load combination that no step of a run ran
NOT_RUN = "failed or not run"
NOT_A_STEP = "no step of this run"


def fig_loss_maps(summary: pd.DataFrame, x: str, y: str,
                  components: Sequence[str],
                  ranges: Mapping[str, tuple[float, float]] | None = None,
                  titles: Mapping[str, str] | None = None,
                  missing: str = NOT_RUN) -> bytes:
    """Contour maps of each loss component over two swept quantities (paper 002 Fig. 17);
    a component whose table has one value of ``x`` or ``y`` is drawn as a curve over the
    other (a contour needs at least 2 x 2 points); missing combinations (a sweep still
    running) are left blank. ``ranges``: component -> (low, high) of its colour scale, so
    that the maps of several slices of a sweep (one per value of a third parameter) share
    one scale and can be compared by colour (default: each map its own range). ``titles``:
    component -> panel title (default the column name), e.g. the loss in words.
    ``missing``: why a grid point has no result, in the note under a panel with crosses
    (:data:`NOT_RUN` in a sweep, :data:`NOT_A_STEP` in a run's maps).

    The computed points are dotted (the contours between them are interpolated), a grid
    point without a result (a failed case) is a red cross with a note under the panel, and
    a component with one value everywhere (0 W of an absent cage land) is written, not
    contoured."""
    n = len(components)
    cols = min(3, n)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 3.3 * rows), squeeze=False,
                             layout="constrained")
    for ax, comp in zip(axes.flat, components, strict=False):
        pv = summary.pivot_table(index=y, columns=x, values=comp, aggfunc="mean")
        ax.set_title(textwrap.fill((titles or {}).get(comp, comp), 45), fontsize=8)
        if pv.empty:  # no case has this component (yet)
            ax.text(0.5, 0.5, "no values", ha="center", va="center", transform=ax.transAxes)
            ax.set_axis_off()
            continue
        if min(pv.shape) < 2:
            # one value of x or of y (e.g. --set supply.inlet_temperature=35): no area to
            # contour, so the component is drawn as a curve over the parameter that varies
            along, other = (x, y) if pv.shape[1] >= pv.shape[0] else (y, x)
            line = pv.iloc[0] if along == x else pv.iloc[:, 0]
            fixed = pv.index[0] if along == x else pv.columns[0]
            ax.plot(line.index.to_numpy(float), line.to_numpy(float), "o-",
                    label=f"{other} = {_fmt_value(fixed)}")
            ax.set_xlabel(along, fontsize=8)
            # the title names the loss (in words); the axis gives its unit, as the colour
            # bar of a contoured panel does (it repeated the registered name,
            # "raceway_traction [W]", under the title "raceway contacts (...) [W]")
            ax.set_ylabel("W" if comp.endswith("[W]") else comp, fontsize=8)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
            continue
        xs, ys = pv.columns.to_numpy(float), pv.index.to_numpy(float)
        values = pv.to_numpy(float)
        lo, hi = (ranges or {}).get(comp, (math.nan, math.nan))
        ax.set_xlabel(x, fontsize=8)
        ax.set_ylabel(y, fontsize=8)
        if not hi > lo and _constant(values):
            # one value everywhere (a cage guide land of an element-guided cage books 0 W):
            # contourf would draw a colour bar of round-off levels (+-2e-14 W); say the value
            ax.set_xlim(xs.min(), xs.max())
            ax.set_ylim(ys.min(), ys.max())
            unit = " W" if comp.endswith("[W]") else ""
            ax.text(0.5, 0.5, f"{_fmt_value(float(np.nanmax(values)))}{unit} at every "
                    "point", ha="center", va="center", transform=ax.transAxes, fontsize=9,
                    zorder=4, bbox={"facecolor": "white", "edgecolor": "none", "pad": 2})
            # (boxed over the computed points: a 3 x 3 grid's middle dot crossed the text)
        else:
            levels = map_levels(lo, hi) if hi > lo else 12
            cs = ax.contourf(xs, ys, values, levels=levels)
            fig.colorbar(cs, ax=ax, label="W" if comp.endswith("[W]") else None)
        _mark_points(ax, xs, ys, values, missing)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    return _png(fig)


def _bearing_names(results: Results, scene: Any) -> list[str]:
    """The bearings of a run: the scene's, else those its tables name."""
    names = [b.name for b in getattr(scene, "bearings", None) or [] if getattr(b, "name", "")]
    for table in results.tables.values():
        if "bearing" in table:
            names += [str(n) for n in table["bearing"].dropna().unique()]
    return list(dict.fromkeys(names))


def map_levels(lo: float, hi: float, bins: int = 12) -> np.ndarray:
    """Contour levels of a loss map whose colour scale is shared over figures (a sweep's
    maps per value of a third swept field): round steps covering [lo, hi], so the colour
    bar reads 800, 880, 960 ... W (``linspace`` levels read 866.9, 940.1, 1013.4 ...)."""
    from matplotlib.ticker import MaxNLocator

    return MaxNLocator(nbins=bins).tick_values(lo, hi)


def _constant(values: np.ndarray) -> bool:
    """True when the finite ``values`` of a map are one value (to 1e-9 of their size, or
    within 1e-12 of zero)."""
    finite = values[np.isfinite(values)]
    if finite.size == 0:
        return False
    return float(np.ptp(finite)) <= max(1e-9 * float(np.abs(finite).max()), 1e-12)


def _mark_points(ax: Any, xs: np.ndarray, ys: np.ndarray, values: np.ndarray,
                 missing: str = NOT_RUN) -> None:
    """Mark on a loss map where it was computed (black dots: the contours between them are
    interpolated) and the grid points without a result (red crosses: a failed case, or one
    not run yet; in a run's maps a combination no step ran), with a note under the axes
    counting the latter and saying ``missing``."""
    gx, gy = np.meshgrid(xs, ys)
    ok = np.isfinite(values)
    # on the frame at the grid's edges: not clipped, drawn over it
    ax.plot(gx[ok], gy[ok], "o", color="black", markersize=3, clip_on=False, zorder=3)
    if (~ok).any():
        ax.plot(gx[~ok], gy[~ok], "x", color="red", markersize=8, markeredgewidth=1.8,
                clip_on=False, zorder=3)
        ax.text(0.0, -0.3, f"x: no result at {int((~ok).sum())} of {ok.size} grid points "
                f"({missing})", transform=ax.transAxes, fontsize=7, color="red", va="top")


def fig_whatif(summary: pd.DataFrame, x: str, ys: Sequence[str],
               group: str | Sequence[str] | None = None) -> bytes:
    """What-if curves: each result in ``ys`` against the swept ``x`` (e.g. oil flow), one
    curve per value combination of the ``group`` column(s) (the other swept parameters).

    The legend names the group columns once (its title) and each curve by its values; up
    to ``_LEGEND_INSIDE`` curves it sits in the first panel, beyond that outside the
    panels on the right (inside, nine curves of a 4 x 3 x 3 sweep hid the first panel's
    data). Beyond ten curves the line style changes with each colour cycle. A text ``x``
    (a lubricant preset) is drawn at one position per value, labelled with it, oils in
    viscosity order (:func:`category_order`). The panels stand in rows of at most three.
    """
    by = [group] if isinstance(group, str) else list(group or [])
    categories: list[Any] = []
    if not pd.api.types.is_numeric_dtype(summary[x]):
        # text values (lubricant presets): one position per value, oils in viscosity order
        # (:func:`category_order`), not in the order typed: "--set lubricant.preset=
        # ISO_VG68,ISO_VG32,ISO_VG46" drew the grades 68, 32, 46 and each curve zigzagged
        categories = category_order(summary[x].tolist(), x)
        summary = summary.assign(**{x: summary[x].map({c: i for i, c in
                                                       enumerate(categories)})})
    # the curves (and the legend) in the order of their values, oils by viscosity (the
    # groupby's text sort put "60, ISO_VG100" before "60, ISO_VG32")
    summary = sort_cases(summary, by)
    groups = list(summary.groupby(by, sort=False)) if by else [((), summary)]
    outside = len(groups) > _LEGEND_INSIDE
    # at most _WHATIF_COLUMNS panels a row: six in one row made a 3000 x 400 px strip that
    # the report shrank to unreadable panels
    ncols = min(len(ys), _WHATIF_COLUMNS)
    nrows = -(-len(ys) // ncols)
    fig, axes = plt.subplots(nrows, ncols, figsize=(4.2 * ncols + (2.2 if outside else 0.0),
                                                    3.3 * nrows),
                             squeeze=False, layout="constrained")
    for ax in axes.flat[len(ys):]:
        ax.set_visible(False)
    styles = ("-", "--", ":", "-.")
    for i, (key, g) in enumerate(groups):
        key = key if isinstance(key, tuple) else (key,)
        label = ", ".join(_fmt_value(v) for v in key)
        g = g.sort_values(x)
        for ax, y in zip(axes.flat[:len(ys)], ys, strict=True):
            ax.plot(g[x], g[y], marker="o", linestyle=styles[(i // 10) % len(styles)],
                    label=label or None)
            ax.set_xlabel(x, fontsize=8)
            ax.set_ylabel(y, fontsize=8)
            ax.grid(alpha=0.3)
            if categories:
                labels = category_labels(categories)
                long = len(categories) > 4 or max(len(t) for t in labels) > 12
                ax.set_xticks(range(len(categories)), labels, fontsize=7,
                              rotation=30 if long else 0, ha="right" if long else "center")
    if len(groups) > 1:
        for ax, y in zip(axes.flat[:len(ys)], ys, strict=True):
            if _curves_coincide(groups, x, y):
                # a result the other swept values do not move (the film parameter over the
                # axial load of a roller bearing): the last curve hid the others, and the
                # legend named curves the panel did not show
                ax.text(0.98, 0.02, f"the {len(groups)} curves coincide", fontsize=7,
                        ha="right", va="bottom", transform=ax.transAxes, color="0.3")
    if by:
        title = ", ".join(by)
        if outside:
            handles, labels = axes.flat[0].get_legend_handles_labels()
            fig.legend(handles, labels, loc="outside right upper", fontsize=7,
                       title=title, title_fontsize=7)
        else:
            axes.flat[0].legend(fontsize=7, title=title, title_fontsize=7)
    return _png(fig)


def _curves_coincide(groups: Sequence[tuple[Any, pd.DataFrame]], x: str, y: str) -> bool:
    """Every curve of ``groups`` gives the same ``y`` (to 1e-9 relative) at the same ``x``
    values: drawn one over the other, only the last is seen."""
    curves = []
    for _, g in groups:
        g = g.sort_values(x)
        xs = pd.to_numeric(g[x], errors="coerce").to_numpy(dtype=float)
        vs = pd.to_numeric(g[y], errors="coerce").to_numpy(dtype=float)
        curves.append((xs, vs))
    first_x, first_y = curves[0]
    if not np.isfinite(first_y).any():
        return False
    return all(xs.shape == first_x.shape and np.array_equal(xs, first_x)
               and np.allclose(vs, first_y, rtol=1e-9, atol=0.0, equal_nan=True)
               for xs, vs in curves[1:])


def category_labels(categories: Sequence[Any]) -> list[str]:
    """Tick labels of text values: a file path (``lubricant.path=my_vg150.toml``, made
    absolute by the sweep) by its file name, unless two values share a name. (The full
    paths of two oil files overlapped under a what-if panel and squeezed the panels.)"""
    texts = [str(c) for c in categories]
    names = [Path(t).name if ("/" in t or "\\" in t) else t for t in texts]
    return names if len(set(names)) == len(names) else texts


def natural_key(value: Any) -> tuple[tuple[int, Any], ...]:
    """Sort key of a text with its digit runs compared as numbers (``"ISO_VG100"`` after
    ``"ISO_VG68"``)."""
    parts = re.split(r"(\d+)", str(value))
    return tuple((0, int(p)) if p.isdigit() else (1, p.lower()) for p in parts if p)


#: reference temperature [K] of the oil order: ISO 3448 grades oils by nu at 40 degC
_GRADE_TEMPERATURE = 313.15


def category_order(values: Sequence[Any], column: str = "") -> list[Any]:
    """The distinct text values of a swept ``column`` in the order the sweep report draws
    and tabulates them: oils (``lubricant.preset``, ``lubricant.path``) by their kinematic
    viscosity at 40 degC, the ISO 3448 grade's reference (thinnest first; the README's
    "viscosity order"), other text in natural order (:func:`natural_key`), as are oils of
    which one cannot be loaded (a moved file). Natural order alone put MIL_PRF_23699
    (27.6 mm^2/s at 40 degC) after ISO_VG46, and the table's text sort put ISO_VG100
    before ISO_VG32."""
    distinct = sorted(dict.fromkeys(values), key=natural_key)
    if not column.startswith("lubricant."):
        return distinct
    from .errors import ThermobearingError
    from .lubricant import load_lubricant

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            nu = {v: float(load_lubricant(str(v)).kinematic_viscosity(_GRADE_TEMPERATURE))
                  for v in distinct}
    except (ThermobearingError, OSError, ValueError):
        return distinct
    return sorted(distinct, key=lambda v: nu[v])   # stable: equal grades stay natural


def sort_cases(summary: pd.DataFrame, params: Sequence[str]) -> pd.DataFrame:
    """The rows of a sweep summary sorted by the swept columns ``params`` in turn: numbers
    ascending, text in :func:`category_order` (oils by viscosity); the index renumbered."""
    params = [p for p in params if p in summary.columns]
    if not params or summary.empty:
        return summary.reset_index(drop=True)
    ranks = {p: {v: i for i, v in enumerate(category_order(summary[p].tolist(), p))}
             for p in params if not pd.api.types.is_numeric_dtype(summary[p])}

    def key(col: pd.Series) -> pd.Series:
        return col.map(ranks[col.name]) if col.name in ranks else col

    return summary.sort_values(params, key=key, kind="stable").reset_index(drop=True)


#: what-if curves up to which the legend sits inside the first panel
_LEGEND_INSIDE = 3
#: what-if panels per row (more results wrap to further rows)
_WHATIF_COLUMNS = 3


def _fmt_value(v: Any) -> str:
    return f"{v:g}" if isinstance(v, (int, float, np.number)) else str(v)


# ---------------------------------------------------------------------------
def figure_html(name: str, png: bytes, caption: str | None = None) -> str:
    """A figure embedded as base64 PNG: ``alt`` is its name (the PNG file's name in a
    run folder), the caption says what it shows (default: the name)."""
    data = base64.b64encode(png).decode("ascii")
    return (f'<figure><img alt="{html.escape(name)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{html.escape(caption or name)}</figcaption></figure>")


def html_report(results: Results, title: str, extra_tables: Mapping[str, pd.DataFrame]
                | None = None, *, scene: Any = None,
                table_notes: Mapping[str, Sequence[str]] | None = None) -> str:
    """The self-contained HTML report (figures embedded as base64 PNG).

    Sections: the bearing and its operating points (with ``scene``), the loss breakdown
    (by source and share, by receiving component, the catalogue cross-check), figures,
    validity warnings, the models that ran with their validity ranges, the energy audit,
    estimated inputs, the tables, the scene as TOML and the citations. ``table_notes``:
    table name -> notes listed under that table (e.g. the measured file's gaps under
    "measured vs predicted")."""
    from .report_sections import chain_table, context_html, html_table, losses_html

    esc = html.escape
    parts = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'>",
        f"<title>{esc(title)}</title>",
        "<style>body{font-family:sans-serif;max-width:1100px;margin:auto;padding:1em}"
        "table{border-collapse:collapse;font-size:12px}td,th{padding:2px 6px;"
        "border-bottom:1px solid #ddd}td{text-align:right}figure{margin:1em 0}"
        "img{max-width:100%}"
        "pre{background:#f6f6f6;padding:0.5em;overflow-x:auto;font-size:12px}"
        ".warn{color:#a40}.note{color:#555;font-size:12px}</style></head><body>",
        f"<h1>{esc(title)}</h1>",
    ]
    stopped = results.stats.get("stopped")
    if stopped:
        # said at the top: it was only the first of the validity warnings, below the
        # breakdown and the figures of a run that reads as finished until there
        parts.append(f"<p class='warn' id='stopped'><b>This run did not finish:</b> "
                     f"{esc(str(stopped))}. The tables and figures cover the steps "
                     "computed before it.</p>")
    bearings: dict[str, Any] = {}
    lubricant = None
    if scene is not None:
        from .report_context import load_scene_bearings, load_scene_lubricant

        bearings, notes = load_scene_bearings(scene)
        try:
            lubricant = load_scene_lubricant(scene)
        except InputError as exc:
            notes.append(f"lubricant: not readable for the report ({exc})")
        parts.append(context_html(scene, results.tables, bearings, lubricant, notes))
    parts.append(losses_html(results.tables.get("losses"), results.tables, scene, bearings,
                             lubricant, flagged=results.flagged))
    parts.append("<h2 id='figures'>Figures</h2>")
    measured = getattr(scene, "measured", None) is not None
    parts += [figure_html(name, png, _caption(name, measured))
              for name, png in results.figures.items()]
    map_notes = loss_map_notes(results.tables.get("losses"))
    if map_notes:
        parts.append("<ul class='notes'>" + "".join(
            f"<li class='note'>{esc(n)}</li>" for n in map_notes) + "</ul>")
    parts.append("<h2 id='validity-warnings'>Validity warnings</h2>")
    if results.check_limits:
        limits = CheckLimits.from_dict(results.check_limits)
        parts.append(f"<p>thresholds of the operating checks: {esc(limits.describe())}</p>")
    if "steady_temperatures" in results.tables:
        parts.append(f"<p>{STEADY_WARNINGS_NOTE}</p>")
    if results.warnings:
        # identical bearings' identical lines once (metadata.json keeps one per bearing)
        merged = merge_twin_bearings(list(results.warnings), _bearing_names(results, scene))
        parts.append("<ul>" + "".join(f"<li class='warn'>{esc(w)}</li>"
                                      for w in merged) + "</ul>")
    else:
        parts.append("<p>none</p>")
    parts.append("<h2 id='model-chain'>Model chain</h2>")
    parts.append("<p>the models that ran, in order, with the validity range each states "
                 "(<code>thermobearing models FAMILY</code> gives their references)</p>")
    parts.append(html_table(chain_table(results.chain)))
    stats = {k: v for k, v in results.stats.items() if not isinstance(v, dict | list)}
    if stats:
        none = _no_kinematics(results)
        parts.append("<p>solver statistics: " + ", ".join(
            esc(_stat_text(k, v, none)) for k, v in stats.items()) + "</p>")
    parts.append("<h2 id='energy-audit'>Energy audit</h2>")
    energy = results.tables.get("energy")
    if energy is not None and not energy.empty:
        last = energy.iloc[-1]
        parts.append(html_table(pd.DataFrame([last])))
        gen = float(last.get("generated [J]", float("nan")))
        imb = float(last.get("imbalance [J]", float("nan")))
        if gen and math.isfinite(gen) and math.isfinite(imb):
            parts.append(f"<p>relative imbalance: {abs(imb) / abs(gen):.3e}</p>")
        losses = results.tables.get("losses")
        check = (network_heat_check(losses, energy)
                 if losses is not None and not losses.empty else None)
        if check is not None:
            worst = float(check["difference [%]"].abs().max())
            parts.append("<h3>loss breakdown vs the heat into the network</h3>"
                         "<p>the breakdown's total (all bearings) at the end of each step "
                         "beside the network's mean heat input over the output interval "
                         "ending there; they differ by the change of the losses over that "
                         f"interval: at most {worst:.3g} % here</p>" + html_table(check))
    else:
        parts.append("<p>(no transient run: no energy audit of the thermal network; the "
                     "loss breakdown's totals are the sums of its sources)</p>")
    parts.append("<h2 id='estimated-inputs'>Estimated inputs</h2>")
    if results.estimated:
        parts.append("<p>input values no source gives, with the reasoning of each (the "
                     "bearing and lubricant configs' <code>estimated</code> tables; "
                     "<code>estimate_missing:</code> marks catalogue-data estimates)</p>")
        for what, entries in results.estimated.items():
            entries = overridden_estimates(what, entries, scene)
            parts.append(f"<h3>{esc(what)}</h3>" + html_table(pd.DataFrame(
                {"field": list(entries), "reasoning": list(entries.values())})))
    else:
        parts.append("<p>none</p>")
    parts.append("<h2 id='tables'>Tables</h2>")
    table_notes = dict(table_notes or {})
    if "kinematics" in results.tables and "temperatures" in results.tables:
        table_notes.setdefault("kinematics", [KINEMATICS_ROWS_NOTE])
    for name, df in {**results.tables, **(extra_tables or {})}.items():
        series = name in ("temperatures", "energy")
        csv = f"{name}.csv" if name in results.tables else None
        parts.append(f"<h3>{esc(name)}</h3>{html_table(df, csv_name=csv, series=series)}")
        notes = (table_notes or {}).get(name)
        if notes:
            parts.append("<ul class='notes'>" + "".join(
                f"<li class='note'>{esc(n)}</li>" for n in notes) + "</ul>")
    parts.append("<h2 id='scene'>Scene</h2>")
    parts.append(f"<pre>{esc(results.scene_toml)}</pre>")
    parts.append("<h2 id='citations'>Citations</h2><ol>")
    parts += [f"<li>{esc(c)}</li>" for c in results.citations]
    parts.append("</ol></body></html>")
    return "\n".join(parts)


#: caption of the temperature figure of a run without a [measured] file
TEMPERATURES_CAPTION = "node temperatures [degC] against time [min]"
#: figure name -> caption in the report
FIGURE_CAPTIONS = {
    "temperatures": f"{TEMPERATURES_CAPTION} (measured points overlaid)",
    "steady_temperatures": "steady-state node temperatures [degC] per operating point",
    "power_losses": "power loss by source [W] per operating point and bearing",
    "heat_destinations": "heat received by each component [W] per operating point and "
                         "bearing",
    # the kinematics table's rows: in a transient each step's first solved state, while
    # the skid warnings take every state re-solved within the step (an NU 214 warming at
    # 8000 r/min: 0.269 drawn, 0.240 at the step's end in the warning)
    "cage_speed_ratio": "cage speed ratio [-] of each step's first solved state, as in the "
                        "kinematics table (theoretical ratio dashed; the skid warnings take "
                        "every state solved within a step)",
}


def overridden_estimates(what: str, entries: Mapping[str, str], scene: Any
                         ) -> dict[str, str]:
    """``entries`` (field -> reasoning of a preset's estimated value, under the heading
    ``what``, ``"bearing <name> (<preset>)"``) with the fields the scene's ``overrides`` of
    that bearing replace marked as such: the report gave the preset's reasoning for a
    value the run did not use (an NU 214 overridden to ``ribbed_ring = "both"`` read "NU
    type: two ribs on the outer ring, none on the inner ring")."""
    specs = {spec.name: spec for spec in getattr(scene, "bearings", None) or ()}
    name = what[len("bearing "):].split(" (", 1)[0] if what.startswith("bearing ") else None
    spec = specs.get(name) if name is not None else None
    overrides = dict(getattr(spec, "overrides", None) or {})
    if not overrides:
        return dict(entries)
    given: dict[str, Any] = {}
    for key, value in overrides.items():
        if isinstance(value, Mapping):  # a table merged key by key (cage = { ... })
            given.update({f"{key}.{k}": v for k, v in value.items()})
        else:
            given[key] = value
    return {field: (f"not used: the scene overrides it ({field} = {given[field]}); the "
                    f"preset's reasoning was: {reason}" if field in given else reason)
            for field, reason in entries.items()}


def _caption(name: str, measured: bool = False) -> str | None:
    """The report's caption of figure ``name``; ``measured``: the scene has a [measured]
    file, whose readings the temperature figure overlays (the caption said "measured
    points overlaid" under the figure of every transient run, with or without readings)."""
    if name == "temperatures" and not measured:
        return TEMPERATURES_CAPTION
    if name.startswith("loss_maps"):
        bearing = name[len("loss_maps_"):]
        return ("power loss maps over speed and load [W]"
                + (f", bearing {bearing}" if bearing else ""))
    return FIGURE_CAPTIONS.get(name)


#: run statistics (Results.stats keys) -> words and unit for the report
_STAT_WORDS = {"wall_time_s": ("wall time", "s"), "kinematics_solves": ("kinematics solves", ""),
               "steps": ("steps", ""), "rejected_chunks": ("rejected coupling chunks", ""),
               "heat_evaluations": ("heat-source evaluations", "")}


def _stat_text(key: str, value: Any, no_kinematics: bool = False) -> str:
    """One run statistic in words with its unit (``wall time 0.6 s``); the kinematics
    solves of a chain without kinematics (``kinematics = "none"``) are said to be none
    (the count is of the pure-rolling states it set, no solve)."""
    words, unit = _STAT_WORDS.get(key, (key.replace("_", " "), ""))
    if key == "kinematics_solves" and no_kinematics:
        return 'kinematics solves: none (kinematics = "none": pure rolling is assumed)'
    return f"{words} {_fmt_stat(value)}" + (f" {unit}" if unit else "")


def _fmt_stat(v: Any) -> str:
    if isinstance(v, float) and not isinstance(v, bool):
        return f"{v:.3g}"
    return str(v)


# ---------------------------------------------------------------------------
def read_measured(scene: Any) -> pd.DataFrame | None:
    """The scene's measured temperatures as ``time [s]`` + one degC column per sensor
    (NaN where the logger wrote an empty cell, a dropout flag or one of the section's
    ``missing_values``): :func:`thermobearing.measured.read_scene_measured` (the formats
    are listed at :func:`thermobearing.measured.read_measured_file`).

    Raises InputError when the file or a mapped column is missing, a time steps back, or a
    cell is not readable (the error names the column, row and value)."""
    from .measured import read_scene_measured

    return read_scene_measured(scene)


def attach_figures(results: Results, scene: Any) -> None:
    """Add the standard figures of a run to ``results.figures`` (what its tables allow)."""
    temps = results.tables.get("temperatures")
    if temps is not None and not temps.empty:
        measured = read_measured(scene)
        cmap = dict(scene.measured.columns) if scene.measured is not None else None
        results.figures["temperatures"] = fig_temperatures(temps, measured, cmap)
    steady = results.tables.get("steady_temperatures")
    if steady is not None and not steady.empty:
        results.figures["steady_temperatures"] = fig_steady_temperatures(
            steady, results.tables.get("kinematics"))
    losses = results.tables.get("losses")
    if losses is not None and not losses.empty:
        results.figures["power_losses"] = fig_loss_bars(losses)
        results.figures.update(_run_loss_maps(losses))
        dest = fig_destinations(losses)
        if dest is not None:
            results.figures["heat_destinations"] = dest
    kin = results.tables.get("kinematics")
    if kin is not None and not kin.empty and len(kin) > 1 and not _no_kinematics(results) \
            and not (("kinematics", "race_control") in [tuple(x)[:2] for x in results.chain]
                     and _rolls_by_construction(kin)):
        results.figures["cage_speed_ratio"] = fig_csr(kin)


def _rolls_by_construction(kin: pd.DataFrame) -> bool:
    """True when every cage speed ratio of the table is its theoretical ratio (to 1e-9);
    checked for race control: on a roller bearing its figure drew the model's input as its
    result
    (the CRB rib example: two identical lines); a ball bearing's race control moves its
    ratio with the contact angles and keeps its figure."""
    cols = ("cage speed ratio [-]", "theoretical cage speed ratio [-]")
    if not all(c in kin for c in cols):
        return False
    csr, theo = (kin[c].to_numpy(dtype=float) for c in cols)
    turning = np.isfinite(csr)
    return bool(turning.any()) and bool(np.all(np.abs(csr[turning] - theo[turning])
                                               <= 1e-9 * np.abs(theo[turning])))


def _no_kinematics(results: Results) -> bool:
    """True when the chain solved no kinematics (``kinematics = "none"``, the global
    friction rung L0): its kinematics table holds the theoretical cage speed ratio, not a
    result, so a cage-speed figure would show a model's input as its prediction."""
    return ("kinematics", "none") in [tuple(x) for x in results.chain]


def _run_loss_maps(losses: pd.DataFrame) -> dict[str, bytes]:
    """Loss maps over speed x load of a run whose steps cover such a grid
    (:func:`_loss_map_plan`; steps at rest left out, :func:`report_losses.
    turning_points`): one figure per bearing (up to four), the total and each source,
    named ``loss_maps_<bearing>``. A combination of the grid that no step ran is crossed
    as "no step of this run" (a rig protocol of a speed ramp and load steps had its
    combinations never run marked "failed or not run", as in a sweep)."""
    from .report_losses import source_label, summary_sources

    maps, _ = _loss_map_plan(losses)
    out = {}
    for name, points, (x, y) in maps:
        sources = summary_sources(points.columns)
        comps = ["total [W]"] + [f"{s} [W]" for s in sources]
        titles = {f"{s} [W]": f"{source_label(s)} [W]" for s in sources}
        out[f"loss_maps_{name}" if name else "loss_maps"] = fig_loss_maps(
            points, x, y, comps, titles=titles, missing=NOT_A_STEP)
    return out


def loss_map_notes(losses: pd.DataFrame | None) -> list[str]:
    """The report's notes on loss maps left out although the run's steps vary the speed
    and a load (:func:`_loss_map_plan`): why, and where the loss of each step is instead
    (bearings with the same reason in one note). Empty when there is nothing to say."""
    if losses is None or losses.empty:
        return []
    _, gaps = _loss_map_plan(losses)
    by_reason: dict[tuple[str, str, str], list[str]] = {}
    for name, (x, y), why in gaps:
        by_reason.setdefault((x, y, why), []).append(name)
    notes = []
    for (x, y, why), names in by_reason.items():
        named = [n for n in names if n]
        who = (f"bearing{'s' if len(named) > 1 else ''} {', '.join(named)}: "
               if named else "")
        notes.append(f"{who}no loss map over {x.split(' [')[0]} and {y.split(' [')[0]}: "
                     f"{why}. The loss of each step, by source, is in the figure "
                     f"'{FIGURE_CAPTIONS['power_losses']}'")
    return notes


def _loss_map_plan(losses: pd.DataFrame) -> tuple[
        list[tuple[str | None, pd.DataFrame, tuple[str, str]]],
        list[tuple[str | None, tuple[str, str], str]]]:
    """Which bearings of a run (up to four) get a loss map: (bearing, its turning points,
    (x, y) axes) for those whose points vary the speed and one load
    (:func:`report_losses.map_axes`) over enough of their grid to contour
    (:func:`report_losses.map_gap`), and (bearing, axes, reason) for those whose points
    vary both but do not (a protocol raising speed and load together got a 3 x 3 map of
    three dots, six crosses and no contour)."""
    from .report_losses import breakdown_by_source, map_axes, map_gap, turning_points

    wide = turning_points(breakdown_by_source(losses))
    names = list(dict.fromkeys(wide["bearing"]))[:4] if "bearing" in wide else [None]
    maps, gaps = [], []
    for name in names:
        points = wide if name is None else wide[wide["bearing"] == name]
        axes = map_axes(points)
        if axes is None:
            continue
        why = map_gap(points, *axes)
        if why is None:
            maps.append((name, points, axes))
        else:
            gaps.append((name, axes, why))
    return maps, gaps


def write_report(results: Results, scene: Any, path: Path | str) -> Path:
    """Write the self-contained HTML report of a run (a run with a kinematics table but
    without recorded check limits, e.g. one read back from an older ``metadata.json``,
    shows the scene's ``[checks]``, else the defaults)."""
    if not results.check_limits and "kinematics" in results.tables:
        limits = getattr(scene, "checks", None) or CheckLimits()
        results = dataclasses.replace(results, check_limits=limits.as_dict())
    extra, notes = {}, {}
    temps = results.tables.get("temperatures")
    if scene.measured is not None and temps is not None and not temps.empty:
        measured = read_measured(scene)
        name = "measured vs predicted"
        extra[name] = temperature_errors(temps, measured, scene.measured.columns)
        # every compared reading beside its prediction, for the user's own plots and stats
        pairs = comparison_table(temps, measured, scene.measured.columns)
        pairs.to_csv(Path(path).parent / COMPARISON_CSV, index=False)
        notes[name] = [MEAN_ERROR_NOTE + f"; every compared reading is in {COMPARISON_CSV}",
                       *comparison_notes(measured, temps, scene.measured.columns)]
    text = html_report(results, scene.title, extra, scene=scene, table_notes=notes)
    out = Path(path)
    out.write_text(text, encoding="utf-8")
    return out
