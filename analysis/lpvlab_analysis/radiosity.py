"""Radiosity's runs of a sweep (issue 18, docs/variants/radiosity.md): what each cost and how close it came.

Radiosity reaches its solution once and then only displays it while nothing moves, so a run has
two times: its frame time (the display, what the Methods plot shows beside LPV, which redoes
everything every frame) and its time to solution (meshing, form factors, the lights' first shot,
the solve and any adaptive passes: summary.csv's method.solution_ms.total). This section plots
the error against the time to solution, with LPV's frame times (LPV's time to solution) beside
them, and tabulates patches, form-factor estimator, solver iterations and the split of the time.
"""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from . import equal_time as ET  # noqa: E402
from . import methods  # noqa: E402
from . import plots  # noqa: E402
from . import sections  # noqa: E402
from . import summary as S  # noqa: E402
from . import tables  # noqa: E402

SOLUTION_COL = "method.solution_ms.total"
COLUMNS = [("method.patches", "patches", "{:.0f}"),
           ("method.patch_size_m", "patch size (m)", "{:.3g}"),
           ("method.form_factors.estimator.resolution", "hemicube px", "{:.0f}"),
           ("method.form_factors.estimator.rays_per_side", "rays per side", "{:.0f}"),
           ("method.adaptive.levels", "adaptive levels", "{:.0f}"),
           ("method.solver.iterations", "solver iterations", "{:.0f}"),
           ("method.solution_ms.form_factors", "form factors ms", "{:.0f}"),
           ("method.solution_ms.solve", "solve ms", "{:.0f}"),
           ("method.solution_ms.refine", "refine ms", "{:.0f}"),
           (SOLUTION_COL, "solution ms", "{:.0f}"),
           (S.TIME_COL, "frame ms", "{:.1f}")]


def is_radiosity(agg):
    return methods.methods_of(agg) == "radiosity"


def has_radiosity(agg):
    return bool(is_radiosity(agg).any())


def table(agg, metric):
    """One row per radiosity configuration, by time to solution."""
    rows = []
    for _, r in agg[is_radiosity(agg)].iterrows():
        row = {"configuration": str(r["config_name"]), "series": str(r.get(ET.SERIES_COL, ""))}
        for col, name, _ in COLUMNS:
            row[name] = float(r[col]) if col in agg.columns and pd.notna(r.get(col)) else math.nan
        row["error"] = float(r[metric]) if metric in agg.columns and pd.notna(r.get(metric)) else math.nan
        rows.append(row)
    t = pd.DataFrame(rows)
    return t.sort_values(["solution ms", "configuration"], na_position="last", kind="mergesort").reset_index(drop=True)


def _formats():
    formats = {name: fmt for _, name, fmt in COLUMNS}
    formats["error"] = "{:.4g}"
    return formats


def to_markdown(agg, metric):
    title = f"Radiosity: {metric} against the time to solution (solution ms) and per frame (frame ms)"
    return tables.markdown_table(title, table(agg, metric), _formats())


def to_html(agg, metric):
    return tables.html_table(table(agg, metric), _formats())


def _scenes(agg):
    """Each row's scene (the file's base name), "" without a scene column."""
    if ET.SCENE_COL not in agg.columns:
        return pd.Series([""] * len(agg), index=agg.index)
    return agg[ET.SCENE_COL].fillna("").astype(str).map(os.path.basename)


def plot(agg, path, metric):
    """Error against time to solution: radiosity's runs by series (labelled with their patch
    counts), LPV's runs at their frame time (LPV solves anew every frame); with several scenes (a
    report of several sweeps) one marker per scene and one LPV line per scene. None without data."""
    if metric not in agg.columns or SOLUTION_COL not in agg.columns:
        return None
    scenes = _scenes(agg)
    several = scenes.nunique() > 1
    markers = dict(zip(sorted(set(scenes)), "osDv^<>p"))
    rad = agg[is_radiosity(agg)]
    points = []
    for idx, r in rad.iterrows():
        t, e = float(r.get(SOLUTION_COL, math.nan)), float(r.get(metric, math.nan))
        if math.isfinite(t) and math.isfinite(e) and t > 0:
            points.append((str(r.get(ET.SERIES_COL, "radiosity")), t, e, r.get("method.patches", math.nan),
                           scenes.loc[idx]))
    if not points:
        return None
    fig, ax = plt.subplots(figsize=(7, 4.5))
    colours = plots._colours({p[0] for p in points})
    for (series, scene) in sorted({(p[0], p[4]) for p in points}):
        mine = [p for p in points if p[0] == series and p[4] == scene]
        label = f"radiosity: {series}" + (f" ({scene})" if several else "")
        ax.scatter([p[1] for p in mine], [p[2] for p in mine], color=colours[series], marker=markers[scene],
                   label=label, s=30, zorder=3)
        for p in mine:
            if isinstance(p[3], float) and math.isfinite(p[3]):
                ax.annotate(f"{p[3]:.0f}", (p[1], p[2]), fontsize=6, xytext=(3, 3), textcoords="offset points")
    lpv = agg[methods.methods_of(agg) == "lpv"]
    # LPV solves every frame: its time to solution is a frame's, on the report's speed axis (by
    # default its own stages, as radiosity's solution time is; summary.with_speed).
    lpv_time = S.speed_col(agg)
    if lpv_time in lpv.columns and len(lpv):
        for scene in sorted(set(scenes.loc[lpv.index])):
            g = lpv[scenes.loc[lpv.index] == scene].sort_values(lpv_time)
            t, e = g[lpv_time].astype(float), g[metric].astype(float)
            ok = t.notna() & e.notna()
            if ok.any():
                ax.plot(t[ok], e[ok], "k--", marker=markers[scene], lw=0.8, ms=5, zorder=2,
                        label=f"LPV (solves every frame: {S.speed_words(lpv)})" + (f" ({scene})" if several else ""))
    ax.set_xscale("log")
    ax.set_xlabel("time to solution (ms; radiosity: method.solution_ms.total)")
    ax.set_ylabel(metric[len("metric."):] + " (lower is better)")
    ax.set_title("Radiosity: error against time to solution (labels: patches)")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.14), frameon=False)
    return plots._save(fig, path)


sections.register(sections.Section(
    title="Radiosity", applies=has_radiosity, order=20, parts=[sections.Part(
        note="Radiosity solves once and then only displays its solution while nothing moves: in the plots "
             "above it stands at its frame time (the display). Here its error stands against its time to "
             "solution (meshing, form factors, the lights' first shot, the solve and adaptive passes), beside "
             "LPV's frame times (LPV solves anew every frame); labels are patch counts.",
        plot=plot, html=to_html, markdown=to_markdown,
        image="radiosity_time_to_solution.png", markdown_file="radiosity.md")]))
