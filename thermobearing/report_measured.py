"""Measured temperatures beside the prediction of a run.

- :func:`temperature_errors`: per-sensor RMSE, max |error| and mean error (predicted -
  measured: negative, the model runs cold) of the predicted node temperature at the
  measured times; a sensor that cannot be compared keeps its row with
  the reason (no sample inside the run, all readings gaps, a node the run does not
  have);
- :func:`comparison_table`: every compared reading beside its prediction, one row per
  sensor and measured time (``measured_vs_predicted.csv`` of a run folder);
- :func:`comparison_notes`: what the reader left out or decided
  (:func:`thermobearing.measured.measured_notes`: gaps per sensor and cause, averaged
  rows, mixed units) and how the file covers the run
  (:func:`thermobearing.measured.coverage_notes`), plus the sensors without a sample
  inside the run: listed under "measured vs predicted" in the report and, shortened, by
  ``thermobearing run``;
- :func:`fig_temperatures`: node temperatures against time with the measured points, each
  sensor in the colour of its node's line with a marker of its own, the axes limited to
  the run and to the readings it is compared with.

Only bookkeeping and drawing: the numbers are the run's and the file's.
"""

from __future__ import annotations

import io
import math
from collections.abc import Mapping, Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

#: the errors-table note of a sensor with no finite reading inside the run
NO_SAMPLE = "no sample inside the run"
#: the errors-table note of a sensor whose every reading is a gap (NaN): none to compare,
#: wherever the file's times lie (it was said as :data:`NO_SAMPLE`)
ALL_GAPS = "all readings are gaps"

#: file name of :func:`comparison_table` in a run folder
COMPARISON_CSV = "measured_vs_predicted.csv"

#: markers of the measured sensors, one per sensor in the order of the column map
_MARKERS = ("o", "s", "^", "D", "v", "P", "X", "<", ">", "h", "*", "p")
_STYLES = ("-", "--", ":", "-.")


def _run_span(temps: pd.DataFrame) -> tuple[float, float]:
    t = temps["time [s]"].to_numpy(float)
    return float(t[0]), float(t[-1])


def _inside(measured: pd.DataFrame, sensor: str, t0: float, t1: float) -> np.ndarray:
    """Mask of the sensor's finite readings inside the run [t0, t1] [s]."""
    t = measured["time [s]"].to_numpy(float)
    values = measured[sensor].to_numpy(float)
    return (t >= t0) & (t <= t1) & np.isfinite(values)


def _all_gaps(measured: pd.DataFrame, sensor: str) -> bool:
    """Whether every reading of the sensor is a gap (no finite value in the file)."""
    return not np.isfinite(measured[sensor].to_numpy(float)).any()


def largest_error(errors: np.ndarray) -> float:
    """The error [K] of the largest magnitude, with its sign (predicted - measured: negative
    where the model runs cold); NaN for no errors."""
    e = np.asarray(errors, float)
    return float(e[np.argmax(np.abs(e))]) if e.size else math.nan


def temperature_errors(temps: pd.DataFrame, measured: pd.DataFrame,
                       column_map: Mapping[str, str]) -> pd.DataFrame:
    """Per-sensor RMSE, max error and mean error [K] of the predicted node temperature
    at the measured times (linear interpolation in time; measured gaps -- NaN -- and
    samples outside the run are left out, ``points`` counts the samples used). The mean
    error is predicted - measured (the sign of ``thermobearing calibrate``'s residuals):
    an offset the RMSE cannot tell from scatter, negative when the model runs cold. The
    max error is the error of the largest magnitude with its sign (:func:`largest_error`:
    -2.5 K where the model is 2.5 K cold; it was unsigned beside the signed mean).

    ``temps`` has ``time [s]`` and ``<node> [degC]`` columns; ``measured`` has ``time [s]``
    and one column per sensor in degC; ``column_map`` maps sensor -> node. A sensor that
    cannot be compared keeps its row, errors NaN, 0 points, and a ``note`` column says why
    (:data:`NO_SAMPLE`, :data:`ALL_GAPS`, or a node the run's temperatures do not have);
    the column is there
    only when some row has a note.
    """
    rows = []
    t_model = temps["time [s]"].to_numpy(float)
    t0, t1 = _run_span(temps)
    for sensor, node in column_map.items():
        col = f"{node} [degC]"
        if sensor not in measured:
            continue  # the reader refuses a mapped column the file lacks
        row = {"sensor": sensor, "node": node, "RMSE [K]": math.nan,
               "max error [K]": math.nan, "mean error [K]": math.nan, "points": 0}
        if col not in temps:
            row["note"] = f"the run has no node {node!r}"
            rows.append(row)
            continue
        inside = _inside(measured, sensor, t0, t1)
        if not inside.any():
            row["note"] = ALL_GAPS if _all_gaps(measured, sensor) else NO_SAMPLE
            rows.append(row)
            continue
        t = measured["time [s]"].to_numpy(float)[inside]
        pred = np.interp(t, t_model, temps[col].to_numpy(float))
        err = pred - measured[sensor].to_numpy(float)[inside]
        row.update({"RMSE [K]": float(np.sqrt(np.mean(err**2))),
                    "max error [K]": largest_error(err),
                    "mean error [K]": float(np.mean(err)), "points": int(err.size)})
        rows.append(row)
    out = pd.DataFrame(rows)
    if "note" in out:
        out["note"] = out["note"].fillna("")
    return out


def comparison_table(temps: pd.DataFrame, measured: pd.DataFrame,
                     column_map: Mapping[str, str]) -> pd.DataFrame:
    """Every reading compared by :func:`temperature_errors`, beside its prediction: one
    row per sensor and measured time inside the run, ``time [s]``, ``time [min]``,
    ``sensor``, ``node``, ``measured [degC]``, ``predicted [degC]`` (the node's
    temperature linearly interpolated to the measured time) and ``error [K]`` (predicted -
    measured). Gaps (NaN readings), samples outside the run and sensors whose node the run
    lacks are left out, so the RMSE of a sensor's ``error [K]`` is its RMSE in the
    errors table. Empty (with these columns) when nothing can be compared."""
    cols = ["time [s]", "time [min]", "sensor", "node", "measured [degC]",
            "predicted [degC]", "error [K]"]
    t_model = temps["time [s]"].to_numpy(float)
    t0, t1 = _run_span(temps)
    parts = []
    for sensor, node in column_map.items():
        col = f"{node} [degC]"
        if sensor not in measured or col not in temps:
            continue
        inside = _inside(measured, sensor, t0, t1)
        if not inside.any():
            continue
        t = measured["time [s]"].to_numpy(float)[inside]
        value = measured[sensor].to_numpy(float)[inside]
        pred = np.interp(t, t_model, temps[col].to_numpy(float))
        parts.append(pd.DataFrame({"time [s]": t, "time [min]": t / 60.0, "sensor": sensor,
                                   "node": node, "measured [degC]": value,
                                   "predicted [degC]": pred, "error [K]": pred - value}))
    if not parts:
        return pd.DataFrame(columns=cols)
    return pd.concat(parts, ignore_index=True)[cols]


def comparison_notes(measured: pd.DataFrame, temps: pd.DataFrame,
                     column_map: Mapping[str, str]) -> list[str]:
    """The reader's notes on the file (gaps per sensor and cause, averaged rows, mixed
    units, ...), how its times cover the run (samples before or after it, a run longer
    than the file, no overlap at all), and each mapped sensor without a reading inside the
    run (once: a sensor the reader's notes name as all gaps is not named again). Empty
    when there is nothing to say."""
    from .measured import coverage_notes, measured_notes

    t0, t1 = _run_span(temps)
    notes = measured_notes(measured) + coverage_notes(measured, t0, t1)
    t = measured["time [s]"].to_numpy(float)
    overlap = t.size and not (t[-1] < t0 or t[0] > t1)
    if overlap:  # without any overlap coverage_notes said it for every sensor at once
        # a sensor whose every reading the reader counted as a gap has its note from
        # measured_notes already (it was said twice, "every reading (4) is a gap (4
        # empty cells) ..." and "all readings are gaps (left out of the errors)")
        notes += [f"{s}: {ALL_GAPS if _all_gaps(measured, s) else NO_SAMPLE} (left out "
                  "of the errors)" for s in column_map
                  if s in measured and not _inside(measured, s, t0, t1).any()
                  and not _reader_said_all_gaps(measured, s)]
    return notes


def _reader_said_all_gaps(measured: pd.DataFrame, sensor: str) -> bool:
    """Whether :func:`thermobearing.measured.measured_notes` says the sensor's every
    reading is a gap: the reader counted gaps (``attrs["gaps"]``) in all the file's data
    rows (``attrs["rows"]``), its condition for that note."""
    causes = measured.attrs.get("gaps", {}).get(sensor, {})
    total = sum(causes.values())
    return bool(total) and total >= measured.attrs.get("rows", len(measured))


def short_notes(notes: Sequence[str], limit: int = 6, width: int = 160) -> list[str]:
    """At most ``limit`` notes, each cut to ``width`` characters, and a last line saying
    how many more the report lists (for the terminal)."""
    out = [n if len(n) <= width else n[:width - 3] + "..." for n in notes[:limit]]
    if len(notes) > limit:
        out.append(f"... {len(notes) - limit} more in the report")
    return out


def terminal_lines(measured: pd.DataFrame, temps: pd.DataFrame,
                   column_map: Mapping[str, str], limit: int = 6) -> list[str]:
    """A few lines for ``thermobearing run``: each sensor's RMSE and mean error (predicted
    - measured; or why it has none) and
    the :func:`comparison_notes`, shortened by :func:`short_notes` (the report lists them
    all)."""
    err = temperature_errors(temps, measured, column_map)
    parts = []
    for _, row in err.iterrows():
        note = row.get("note", "") if "note" in err else ""
        parts.append(f"{row['sensor']} {note}" if note else
                     f"{row['sensor']} RMSE {row['RMSE [K]']:.2f} K ({row['points']} samples)")
    means = [f"{row['sensor']} {row['mean error [K]']:+.2f} K" for _, row in err.iterrows()
             if math.isfinite(row["mean error [K]"])]
    lines = ["measured vs predicted: " + ", ".join(parts)
             + (f"; mean error (predicted - measured): {', '.join(means)}" if means else "")
             ] if parts else []
    notes = comparison_notes(measured, temps, column_map)
    if notes:
        lines.append(f"measured data notes ({len(notes)}):")
        lines += [f"  - {n}" for n in short_notes(notes, limit)]
    return lines


def _png(fig: plt.Figure) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def fig_temperatures(temps: pd.DataFrame, measured: pd.DataFrame | None = None,
                     column_map: Mapping[str, str] | None = None) -> bytes:
    """Node temperatures [degC] against time [min], measured points overlaid.

    Lines: one colour per node kind, one line style per bearing (``<bearing>.<node>``).
    Measured points: each sensor in the colour of its node's line and a marker of its own
    (two sensors on the drive-end and non-drive-end housings share the colour, not the
    marker), named in the legend with its node (and, for a file logged in degF or K, the
    unit its readings were converted from; a sensor whose every reading is a gap has no
    point and no entry); the legend stands beside the axes. The x axis
    is the run; the y axis spans the predicted temperatures and the readings inside the
    run, leaving out readings of
    exactly a thermocouple range end (:data:`thermobearing.measured.RANGE_ENDS_C`, an open
    thermocouple pinned there by the logger), which a note in the figure counts.
    """
    from .measured import RANGE_ENDS_C

    fig, ax = plt.subplots(figsize=(8, 4.5))
    t_min = temps["time [s]"].to_numpy(float) / 60.0
    nodes = [c[:-len(" [degC]")] for c in temps.columns if c.endswith(" [degC]")]
    groups = list(dict.fromkeys(n.split(".", 1)[0] for n in nodes if "." in n))
    kinds = list(dict.fromkeys(n.split(".", 1)[-1] for n in nodes))
    palette = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colour: dict[str, str] = {}
    low, high = math.inf, -math.inf
    for n in nodes:
        g = n.split(".", 1)[0] if "." in n else ""
        colour[n] = palette[kinds.index(n.split(".", 1)[-1]) % len(palette)]
        y = temps[f"{n} [degC]"].to_numpy(float)
        ax.plot(t_min, y, label=n, color=colour[n],
                ls=_STYLES[groups.index(g) % len(_STYLES)] if g in groups else "-")
        finite = y[np.isfinite(y)]
        if finite.size:
            low, high = min(low, float(finite.min())), max(high, float(finite.max()))
    pinned = 0
    if measured is not None and column_map:
        t0, t1 = _run_span(temps)
        sensors = [s for s in column_map if s in measured]
        for k, sensor in enumerate(sensors):
            node = column_map[sensor]
            # the colour of its node's line (a node the run lacks: a colour of its own)
            c = colour.get(node, palette[(len(kinds) + k) % len(palette)])
            marker = _MARKERS[k % len(_MARKERS)]
            t = measured["time [s]"].to_numpy(float)
            values = measured[sensor].to_numpy(float)
            # readings logged in degF or K are drawn converted: the legend says so (a
            # name such as 'TC1 [°F]' on the degC axis read as if the points were in degF)
            logged = measured.attrs.get("units", {}).get(sensor, "degC")
            how = "measured" if logged == "degC" else f"measured in {logged}, shown in degC"
            if not np.isfinite(values).any():
                continue  # every reading a gap: no point, so no legend entry either
            ax.plot(t / 60.0, values, marker, ms=3.5, color=c, mfc="none", ls="none",
                    label=f"{sensor} ({how}, {node})")
            inside = _inside(measured, sensor, t0, t1)
            code = np.zeros_like(inside)
            for end in RANGE_ENDS_C:
                code |= np.abs(values - end) < 1e-6
            pinned += int((inside & code).sum())
            shown = values[inside & ~code]
            if shown.size:
                low, high = min(low, float(shown.min())), max(high, float(shown.max()))
    if t_min.size and t_min[-1] > t_min[0]:
        ax.set_xlim(t_min[0], t_min[-1])
    if math.isfinite(low) and math.isfinite(high):
        pad = 0.05 * (high - low) if high > low else 0.5
        ax.set_ylim(low - pad, high + pad)
    if pinned:
        ax.text(0.01, 0.01, f"{pinned} reading(s) of exactly a thermocouple range end "
                "(open thermocouple?) outside the axes", transform=ax.transAxes,
                fontsize=7, color="#a40")
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature [degC]")
    ax.grid(alpha=0.3)
    # beside the axes, not on them: inside, the legend of a measured overlay covered the
    # readings it names (the overlay's lines are long and the readings span the run)
    entries = len(ax.get_legend_handles_labels()[1])
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0,
              ncol=1 + entries // 24)
    return _png(fig)
