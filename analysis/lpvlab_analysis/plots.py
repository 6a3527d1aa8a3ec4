"""Figures of a sweep (matplotlib, Agg backend: no display needed).

Every function takes the per-configuration DataFrame from summary.aggregate,
writes one PNG atomically (fsutil.write_with) and returns its path, or None
when the data cannot support the plot (e.g. the metric column is absent).
"""
import math

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import fsutil  # noqa: E402
from . import pareto  # noqa: E402
from . import summary as S  # noqa: E402
from . import thesis_tables as T  # noqa: E402



def _save(fig, path):
    fsutil.write_with(path, lambda tmp: fig.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
    plt.close(fig)
    return path


def _colours(labels):
    cmap = plt.get_cmap("tab10" if len(labels) <= 10 else "tab20")
    return {lab: cmap(i % cmap.N) for i, lab in enumerate(sorted(labels))}


def _pname(col):
    return col[len("param."):] if col.startswith("param.") else col


def speed_accuracy(agg, path, metric=S.DEFAULT_METRIC, time_col=None):
    """The speed axis's median time (summary.with_speed: by default the indirect method's own
    stages; by the clocks that timed it, S.timed_on) vs an image metric, one colour per variant;
    the Pareto front (fast and accurate; for PSNR/SSIM 'accurate' = high) is drawn as a step line
    and its points are ringed. Every point is labelled with its configuration's name (up to 24
    points; beyond, the front's alone, which then stay readable). Infinite metric values (PSNR of identical images) are drawn at the
    top edge with a marker. `time_col`: another time column instead."""
    time_col = time_col or S.speed_col(agg)
    if metric not in agg.columns or time_col not in agg.columns:
        return None
    t = agg[time_col].astype(float).values
    e = agg[metric].astype(float).values
    ok = ~np.isnan(t) & ~np.isnan(e)
    if not ok.any():
        return None
    hib = S.higher_is_better(metric)
    front = pareto.pareto_front(list(zip(t, -e if hib else e)))
    finite = e[ok & np.isfinite(e)]
    top = (finite.max() * 1.1 if len(finite) else 1.0)
    ed = np.where(np.isinf(e), top, e)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    colours = _colours(set(agg["variant"]))
    for v, c in colours.items():
        m = (agg["variant"].values == v) & ok
        ax.scatter(t[m], ed[m], color=c, label=v, s=30, zorder=3)
    if front:
        fx = [t[i] for i in front]
        fy = [ed[i] for i in front]
        ax.step(fx, fy, where="post", color="k", lw=1, ls="--", zorder=2, label="Pareto front")
        ax.scatter(fx, fy, s=120, facecolors="none", edgecolors="k", lw=1.2, zorder=4)
    labelled = [i for i in range(len(t)) if ok[i]] if ok.sum() <= 24 else list(front)
    for i in labelled:
        ax.annotate(str(agg["config_name"].iloc[i]), (t[i], ed[i]), fontsize=6,
                    xytext=(4, 4), textcoords="offset points",
                    fontweight="bold" if i in front else "normal")
    if np.isinf(e[ok]).any():
        ax.axhline(top, color="0.7", lw=0.8)
        ax.text(ax.get_xlim()[0], top, " inf", va="bottom", fontsize=7, color="0.4")
    if time_col == S.speed_col(agg):
        ax.set_xlabel(S.speed_axis_label(agg), fontsize=8)
    else:
        ax.set_xlabel(f"{time_col} (ms, median)", fontsize=8)
    ax.set_ylabel(S.metric_axis_label(metric), fontsize=8)
    ax.set_title("Speed vs accuracy")
    ax.grid(alpha=0.3)
    # Below the axes: variant labels are long, and inside they covered the points.
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.14), frameon=False)
    return _save(fig, path)


def stage_times(agg, param, path):
    """Median time per stage (each by its clock) against one swept numeric parameter, one panel
    per variant, stages stacked (areas) so the top edge is the summed stage
    time. Other swept numeric parameters are held at their most common value
    (summary.one_at_a_time)."""
    sl = S.one_at_a_time(agg, param)
    col = S.time_col
    # In the order the runs ran them (the summary's column order), the total left out.
    stages = [s for s in S.stages(sl) if s != "total" and sl[col(s)].notna().any()]
    if sl[param].nunique() < 2 or not stages:
        return None
    variants = sorted(set(sl["variant"]))
    fig, axes = plt.subplots(1, len(variants), figsize=(5.5 * len(variants), 4), squeeze=False)
    cmap = plt.get_cmap("tab10")
    for ax, v in zip(axes[0], variants):
        g = sl[sl["variant"] == v].groupby(param)[[col(s) for s in stages]].median().sort_index()
        x = g.index.values.astype(float)
        ys = [np.nan_to_num(g[col(s)].values.astype(float)) for s in stages]
        ax.stackplot(x, *ys, labels=stages, colors=[cmap(i) for i in range(len(stages))], alpha=0.85)
        ax.set_xlabel(_pname(param))
        ax.set_ylabel("median time per stage (ms, stacked)")
        ax.set_title(v, fontsize=9)
        if len(x) and x.min() > 0 and x.max() / x.min() >= 8:
            ax.set_xscale("log", base=2)
        ax.set_xticks(x)
        ax.set_xticklabels([f"{xx:g}" for xx in x], fontsize=7)
        ax.grid(alpha=0.3)
    axes[0][-1].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    fig.suptitle(f"Time per stage vs {_pname(param)}; {S.timed_on(sl)}", fontsize=9)
    return _save(fig, path)


ERROR_PANELS_PER_ROW = 3


def error_vs_param(agg, param, path, metrics=None):
    """Image metric(s) against one swept numeric parameter (e.g.
    propagation.iterations, grid.resolution), one line per variant, other
    swept numeric parameters held at their most common value. A panel per metric, at most
    ERROR_PANELS_PER_ROW to a row (one strip of 14 panels was unreadable at page width), each
    with its metric and unit on its y axis."""
    metrics = [m for m in (metrics or S.metric_columns(agg)) if m in agg.columns and agg[m].notna().any()]
    sl = S.one_at_a_time(agg, param)
    if not metrics or param not in sl.columns or sl[param].nunique() < 2:
        return None
    cols = min(ERROR_PANELS_PER_ROW, len(metrics))
    rows = (len(metrics) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols, 3.4 * rows), squeeze=False)
    for ax in axes.flat[len(metrics):]:
        ax.set_visible(False)
    colours = _colours(set(sl["variant"]))
    for ax, m in zip(axes.flat, metrics):
        for v, c in colours.items():
            g = sl[sl["variant"] == v].groupby(param)[m].median().sort_index()
            y = g.values.astype(float)
            ax.plot(g.index.values, np.where(np.isinf(y), np.nan, y), "o-", color=c, label=v, ms=4)
        ax.set_xlabel(_pname(param), fontsize=8)
        ax.set_ylabel(S.metric_axis_label(m), fontsize=7)
        ax.set_title(m[len("metric."):], fontsize=9)
        x = sl[param].astype(float)
        if x.min() > 0 and x.max() / x.min() >= 8:
            ax.set_xscale("log", base=2)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.suptitle(f"Error vs {_pname(param)}")
    fig.tight_layout()
    return _save(fig, path)


def trend_vs_thesis(tab, measured, path):
    """Thesis table columns and this machine's series, each divided by its
    value at a common x (thesis_tables.reference_x), on log-log axes: equal
    slopes mean the same scaling behaviour regardless of absolute speed.
    Returns (path, x_ref) or (None, None)."""
    x_ref = T.reference_x(tab, measured)
    if x_ref is None:
        return None, None
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, ys in tab.columns.items():
        n = T.normalise(tab.x, ys, x_ref)
        if n:
            ax.plot(tab.x, n, "--", lw=1, alpha=0.7, label=f"thesis {name}")
    for name, (xs, ys) in measured.items():
        n = T.normalise(xs, ys, x_ref)
        if n:
            ax.plot(xs, n, "o-", lw=2.2, label=name)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel(tab.x_label)
    ax.set_ylabel(f"{tab.stage} time / time at x={x_ref:g}")
    ax.set_title(f"Trend vs thesis table {tab.number}", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=6, ncol=2)
    return _save(fig, path), x_ref
