"""Convergence curves (issue 38; experiments/convergence_*.toml): each method's error against what
it spends, log-log, one curve per series, with the reference's own noise floor drawn and the slope
of each curve fitted.

A method's own budget is the work it counts per frame (summary.csv):
  LPV                     work.propagation.cell-iterations  (cells x iterations)
  light-path methods      method.light_paths                (walks of instant radiosity, ...)
  RSM gathering           method.samples_per_pixel_and_view
  radiosity               method.patches
and its time is the report's speed axis (the method's own stages by default). A consistent method
has a negative slope until it reaches its floor: the reference's noise (metric.<pair>.noise_floor_rmse,
for RMSE) or its own bias. The slope is the least-squares fit of log error against log budget
over a series' points whose error is above twice the floor (at least three of them): -0.5 is
Monte Carlo's rate, 0 a method that does not converge.
"""
import math

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from . import equal_time as ET  # noqa: E402
from . import methods  # noqa: E402
from . import plots  # noqa: E402
from . import sections  # noqa: E402
from . import summary as S  # noqa: E402
from . import tables  # noqa: E402

# (column, what it counts), the first a row has being its budget.
BUDGETS = [("work.propagation.cell-iterations", "cell-iterations"),
           ("method.light_paths", "light paths"),
           ("method.samples_per_pixel_and_view", "RSM samples per pixel"),
           ("method.patches", "patches")]
MIN_POINTS = 3


def budget_of(row):
    """(budget, what it counts) of a configuration, or (nan, "") when it counts none."""
    for col, unit in BUDGETS:
        v = row.get(col, math.nan)
        try:
            v = float(v)
        except (TypeError, ValueError):
            continue
        if math.isfinite(v) and v > 0:
            return v, unit
    return math.nan, ""


def series_of(agg):
    """Each configuration's curve: its `series` where the sweep names one, else its method."""
    named = agg[ET.SERIES_COL].fillna("").astype(str) if ET.SERIES_COL in agg.columns else None
    method = methods.methods_of(agg)
    if named is None:
        return method
    return named.where(named != "", method)


def noise_floor(agg, metric):
    """The reference's noise in the units of `metric` (its RMSE only), the median over the sweep's
    runs; nan for other metrics or without it."""
    if S.metric_name(metric) != "rmse":
        return math.nan
    col = metric.rsplit(".", 1)[0] + ".noise_floor_rmse"
    if col not in agg.columns:
        return math.nan
    v = pd.to_numeric(agg[col], errors="coerce").dropna()
    return float(v.median()) if len(v) else math.nan


def slope(x, y, floor=math.nan):
    """Least-squares slope of log y against log x over the points with y above twice the floor
    (all of them without one); nan with fewer than MIN_POINTS distinct x."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    keep = np.isfinite(x) & np.isfinite(y) & (x > 0) & (y > 0)
    if math.isfinite(floor):
        keep &= y > 2.0 * floor
    if len(set(x[keep])) < MIN_POINTS:
        return math.nan
    return float(np.polyfit(np.log(x[keep]), np.log(y[keep]), 1)[0])


def curves(agg, metric):
    """Per series with at least MIN_POINTS budgets: its points sorted by budget, as a frame with
    budget, unit, time, error."""
    if metric not in agg.columns:
        return {}
    speed = S.speed_col(agg)
    rows = []
    for (_, r), series in zip(agg.iterrows(), series_of(agg)):
        budget, unit = budget_of(r)
        error = float(pd.to_numeric(r.get(metric), errors="coerce"))
        time = float(pd.to_numeric(r.get(speed), errors="coerce")) if speed in agg.columns else math.nan
        if math.isfinite(budget) and math.isfinite(error):
            rows.append({"series": series, "budget": budget, "unit": unit, "time": time, "error": error})
    if not rows:
        return {}
    t = pd.DataFrame(rows)
    out = {}
    for series, g in t.groupby("series", sort=True):
        if g["budget"].nunique() >= MIN_POINTS:
            out[series] = g.sort_values("budget").reset_index(drop=True)
    return out


def has_curves(agg):
    metric = S.resolve_metric(agg, S.DEFAULT_METRIC, required=False) if len(agg) else None
    return bool(metric) and bool(curves(agg, metric))


def table(agg, metric):
    """One row per curve: its budget range, fitted slopes against budget and time, its lowest error."""
    floor = noise_floor(agg, metric)
    rows = []
    for series, g in curves(agg, metric).items():
        rows.append({"series": series, "budget": g["unit"].iloc[0], "points": len(g),
                     "budget range": f"{g['budget'].min():.3g}-{g['budget'].max():.3g}",
                     "slope vs budget": slope(g["budget"], g["error"], floor),
                     "slope vs time": slope(g["time"], g["error"], floor),
                     "lowest error": float(g["error"].min()), "noise floor": floor})
    return pd.DataFrame(rows, columns=["series", "budget", "points", "budget range", "slope vs budget",
                                       "slope vs time", "lowest error", "noise floor"])


_FORMATS = {"points": "{:.0f}", "slope vs budget": "{:+.2f}", "slope vs time": "{:+.2f}",
            "lowest error": "{:.4g}", "noise floor": "{:.3g}"}


def to_markdown(agg, metric):
    title = f"Convergence: {metric} against each method's budget and time (fitted log-log slopes)"
    return tables.markdown_table(title, table(agg, metric), _FORMATS)


def to_html(agg, metric):
    return tables.html_table(table(agg, metric), _FORMATS)


def plot(agg, path, metric):
    """Error against the method's own budget (left) and against time (right), log-log, one line per
    curve labelled with its fitted slope, the reference's noise floor dashed."""
    found = curves(agg, metric)
    if not found:
        return None
    floor = noise_floor(agg, metric)
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.8))
    colours = plots._colours(set(found))
    for series, g in found.items():
        s = slope(g["budget"], g["error"], floor)
        label = f"{series} ({g['unit'].iloc[0]}; slope {s:+.2f})" if math.isfinite(s) else f"{series} ({g['unit'].iloc[0]})"
        left.plot(g["budget"], g["error"], marker="o", color=colours[series], label=label)
        timed = g[g["time"] > 0].sort_values("time")
        if len(timed):
            right.plot(timed["time"], timed["error"], marker="o", color=colours[series], label=series)
    for ax in (left, right):
        if math.isfinite(floor) and floor > 0:
            ax.axhline(floor, color="grey", ls="--", lw=1, label="reference noise (RMSE)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylabel(S.metric_axis_label(metric), fontsize=8, wrap=True)
        ax.grid(alpha=0.3, which="both")
    left.set_xlabel("the method's own budget per frame (LPV: cell-iterations; IR: light paths; RSM gathering: "
                    "samples; radiosity: patches)", fontsize=8, wrap=True)
    right.set_xlabel(S.speed_axis_label(agg), fontsize=8, wrap=True)
    left.set_title("Error against budget", fontsize=9)
    right.set_title("Error against time", fontsize=9)
    left.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.2), frameon=False)
    return plots._save(fig, path)


sections.register(sections.Section(
    title="Convergence", applies=has_curves, order=15, parts=[sections.Part(
        note="Each method's error against what it spends, log-log: left its own budget per frame, right its "
             "time; one curve per series (or method) with at least three budgets, the reference's own noise "
             "dashed. The slope is fitted over the points above twice that floor: negative means the method "
             "converges (Monte Carlo: &minus;0.5), about 0 that more budget buys nothing "
             "(docs/experiments.md#convergence-curves).",
        plot=plot, html=to_html, markdown=to_markdown,
        image="convergence.png", markdown_file="convergence.md")]))
