"""Particle systems' runs of a sweep (issue 19, docs/particles.md): frame time and error against
the number of particles alive, after seed 002's chapter 5.2 (FPS against particle count and
light-field resolution), with the error against the path-traced reference the seed could not
measure.

summary.csv's particles.alive (summed over a run's systems at frame 0), particles.triangles and
the configuration's drawing (param.particles[0].draw where a sweep sets it, "geometry" else) give
one line per drawing and scene. A sweep over the light field's resolution (param.particles[0].
resolution, with its view grid and blending where swept) gets frame time and error against the
texels per view side, one line per view grid and blending (seed 002, chapter 5.2.2).
"""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from . import equal_time as ET  # noqa: E402
from . import summary as S  # noqa: E402
from . import plots  # noqa: E402
from . import sections  # noqa: E402
from . import tables  # noqa: E402

ALIVE_COL = "particles.alive"
TRIANGLES_COL = "particles.triangles"
DRAW_COL = "param.particles[0].draw"
RESOLUTION_COL = "param.particles[0].resolution"
AZIMUTHS_COL = "param.particles[0].azimuths"
ELEVATIONS_COL = "param.particles[0].elevations"
INTERPOLATE_COL = "param.particles[0].interpolate"


def has_particles(agg):
    return ALIVE_COL in agg.columns and bool(agg[ALIVE_COL].notna().any())


def _drawings(agg):
    if DRAW_COL not in agg.columns:
        return pd.Series(["geometry"] * len(agg), index=agg.index)
    return agg[DRAW_COL].fillna("geometry").astype(str).replace({"nan": "geometry", "": "geometry"})


def _scenes(agg):
    if ET.SCENE_COL not in agg.columns:
        return pd.Series([""] * len(agg), index=agg.index)
    return agg[ET.SCENE_COL].fillna("").astype(str).map(os.path.basename)


def table(agg, metric):
    """One row per configuration with particles, by drawing, scene and particle count."""
    runs = agg[agg[ALIVE_COL].notna()] if has_particles(agg) else agg.iloc[0:0]
    drawings, scenes = _drawings(agg), _scenes(agg)
    rows = []
    for idx, r in runs.iterrows():
        def number(col):
            return float(r[col]) if col in agg.columns and pd.notna(r.get(col)) else math.nan
        rows.append({"configuration": str(r["config_name"]), "scene": scenes.loc[idx],
                     "drawing": drawings.loc[idx], "particles": number(ALIVE_COL),
                     "triangles": number(TRIANGLES_COL), "frame ms": number(S.TIME_COL),
                     "error": number(metric)})
    t = pd.DataFrame(rows, columns=["configuration", "scene", "drawing", "particles", "triangles",
                                    "frame ms", "error"])
    return t.sort_values(["scene", "drawing", "particles"], kind="mergesort").reset_index(drop=True)


# Both tables' columns.
_FORMATS = {"particles": "{:.0f}", "triangles": "{:.0f}", "texels": "{:.0f}", "frame ms": "{:.1f}",
            "error": "{:.4g}"}


def to_markdown(agg, metric):
    title = f"Particles: frame time and {metric} against the particles alive"
    return tables.markdown_table(title, table(agg, metric), _FORMATS)


def to_html(agg, metric):
    return tables.html_table(table(agg, metric), _FORMATS)


def _time_and_error(path, metric, lines, x, xlabel, against, log_x, log_y, timed):
    """Frame time (left) and error (right) against column `x`: `lines` yields (rows, label, style)
    with style the plot keywords (colour, marker, line style) of one line; `timed` says how the
    times were taken (summary.timed_on)."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for g, label, style in lines:
        for ax, col in ((left, "frame ms"), (right, "error")):
            ok = g[col].notna() & (g[col] > 0)
            if ok.any():
                ax.plot(g[x][ok], g[col][ok], label=label, lw=1, **style)
    for ax, ylabel in ((left, "frame time (ms)"),
                       (right, metric[len("metric."):] + " (lower is better)" if metric.startswith("metric.") else metric)):
        ax.set_xscale("log", **log_x)
        if log_y:
            ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both")
    left.set_title(f"Frame time against {against}\n{timed}", fontsize=9)
    right.set_title(f"Error against {against}")
    handles, _ = left.get_legend_handles_labels()
    if handles:
        left.legend(fontsize=7)
    return plots._save(fig, path)


def plot(agg, path, metric):
    """Frame time (left) and error (right) against the particles alive, log-log, one line per
    drawing and scene. None without particle runs or where every run has the same count."""
    t = table(agg, metric)
    t = t[t["particles"] > 0]
    if t.empty or t["particles"].nunique() < 2:
        return None
    colours = plots._colours(set(t["drawing"]))
    markers = dict(zip(sorted(set(t["scene"])), "osDv^<>p"))
    lines = ((g, drawing + (f" ({scene})" if len(markers) > 1 else ""),
              {"marker": markers[scene], "color": colours[drawing]})
             for (drawing, scene), g in t.groupby(["drawing", "scene"], sort=True))
    return _time_and_error(path, metric, lines, "particles", "particles alive", "particle count", {}, True,
                           S.timed_on(agg))


def has_resolution_sweep(agg):
    """Light-field runs at more than one resolution."""
    return (has_particles(agg) and RESOLUTION_COL in agg.columns
            and resolution_table(agg, S.TIME_COL)["texels"].nunique() > 1)


def _text(agg, col, default):
    if col not in agg.columns:
        return pd.Series([default] * len(agg), index=agg.index)
    return agg[col].map(lambda v: default if pd.isna(v) or str(v) in ("", "nan") else str(v))


def resolution_table(agg, metric):
    """One row per light-field configuration: its view grid (azimuths x elevations where swept),
    blending, texels per view side, frame time and error, by grid, blending and resolution."""
    runs = agg[(_drawings(agg) == "light_field") & agg[ALIVE_COL].notna()] if has_particles(agg) else agg.iloc[0:0]
    if RESOLUTION_COL not in agg.columns:
        runs = runs.iloc[0:0]
    azimuths, elevations = _text(agg, AZIMUTHS_COL, "?"), _text(agg, ELEVATIONS_COL, "?")
    blending = _text(agg, INTERPOLATE_COL, "true").str.lower().map(
        lambda v: "nearest" if v in ("false", "0", "0.0") else "blended")
    rows = []
    for idx, r in runs.iterrows():
        def number(col):
            return float(r[col]) if col in agg.columns and pd.notna(r.get(col)) else math.nan
        views = f"{azimuths.loc[idx].split('.')[0]} x {elevations.loc[idx].split('.')[0]}"
        rows.append({"configuration": str(r["config_name"]), "views": views, "blending": blending.loc[idx],
                     "texels": number(RESOLUTION_COL), "particles": number(ALIVE_COL),
                     "frame ms": number(S.TIME_COL), "error": number(metric)})
    t = pd.DataFrame(rows, columns=["configuration", "views", "blending", "texels", "particles", "frame ms",
                                    "error"])
    count = t["views"].map(lambda v: tuple(int(x) if x.isdigit() else 0 for x in v.split(" x ")))
    order = t.assign(_views=count).sort_values(["_views", "blending", "texels"], kind="mergesort").index
    return t.loc[order].reset_index(drop=True)


def resolution_markdown(agg, metric):
    title = f"Particles: frame time and {metric} against the light field's resolution"
    return tables.markdown_table(title, resolution_table(agg, metric), _FORMATS)


def resolution_html(agg, metric):
    return tables.html_table(resolution_table(agg, metric), _FORMATS)


def plot_resolution(agg, path, metric):
    """Frame time (left) and error (right) against the texels per view side (log 2), one line per
    view grid and blending. None without light-field runs at two resolutions or more."""
    t = resolution_table(agg, metric)
    t = t[t["texels"] > 0]
    if t.empty or t["texels"].nunique() < 2:
        return None
    colours = plots._colours(set(t["views"]))
    styles = {"blended": "-", "nearest": "--"}
    lines = ((g, f"{views} views, {blending}",
              {"marker": "o", "ls": styles.get(blending, "-"), "color": colours[views]})
             for (views, blending), g in t.groupby(["views", "blending"], sort=True))
    return _time_and_error(path, metric, lines, "texels", "texels per view side", "light-field resolution",
                           {"base": 2}, False, S.timed_on(agg))


sections.register(sections.Section(
    title="Particles", applies=has_particles, order=30, parts=[
        sections.Part(
            note="Runs with particle systems (docs/particles.md): frame time and error against the number "
                 "of particles alive at frame 0, one line per drawing and scene (seed 002, chapter 5.2, "
                 "measured FPS only; here the error against the path-traced reference of the same particles "
                 "too).",
            plot=plot, html=to_html, markdown=to_markdown,
            image="particles_count.png", markdown_file="particles.md"),
        sections.Part(
            note="Light-field particles against the light field's resolution: texels per view side, one "
                 "line per view grid (colour) and view selection (solid: blended, dashed: nearest), seed "
                 "002, chapter 5.2.2.",
            plot=plot_resolution, html=resolution_html, markdown=resolution_markdown,
            image="particles_resolution.png", markdown_file="particles_resolution.md",
            applies=has_resolution_sweep)]))
