"""Particle systems' runs of a sweep (issue 19, docs/particles.md): frame time and error against
the number of particles alive, after seed 002's chapter 5.2 (FPS against particle count and
light-field resolution), with the error against the path-traced reference the seed could not
measure.

summary.csv's particles.alive (summed over a run's systems at frame 0), particles.triangles and
the configuration's drawing (param.particles[0].draw where a sweep sets it, "geometry" else) give
one line per drawing and scene.
"""
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from . import equal_time as ET  # noqa: E402
from . import plots  # noqa: E402
from . import tables  # noqa: E402

ALIVE_COL = "particles.alive"
TRIANGLES_COL = "particles.triangles"
DRAW_COL = "param.particles[0].draw"


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
                     "triangles": number(TRIANGLES_COL), "frame ms": number(ET.TIME_COL),
                     "error": number(metric)})
    t = pd.DataFrame(rows, columns=["configuration", "scene", "drawing", "particles", "triangles",
                                    "frame ms", "error"])
    return t.sort_values(["scene", "drawing", "particles"], kind="mergesort").reset_index(drop=True)


_FORMATS = {"particles": "{:.0f}", "triangles": "{:.0f}", "frame ms": "{:.1f}", "error": "{:.4g}"}


def to_markdown(agg, metric):
    title = f"Particles: frame time and {metric} against the particles alive"
    return tables.markdown_table(title, table(agg, metric), _FORMATS)


def to_html(agg, metric):
    return tables.html_table(table(agg, metric), _FORMATS)


def plot(agg, path, metric):
    """Frame time (left) and error (right) against the particles alive, log-log, one line per
    drawing and scene. None without particle runs."""
    t = table(agg, metric)
    t = t[t["particles"] > 0]
    if t.empty:
        return None
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    colours = plots._colours(set(t["drawing"]))
    markers = dict(zip(sorted(set(t["scene"])), "osDv^<>p"))
    for (drawing, scene), g in t.groupby(["drawing", "scene"], sort=True):
        label = drawing + (f" ({scene})" if len(markers) > 1 else "")
        for ax, col in ((left, "frame ms"), (right, "error")):
            ok = g[col].notna() & (g[col] > 0)
            if ok.any():
                ax.plot(g["particles"][ok], g[col][ok], marker=markers[scene], color=colours[drawing],
                        label=label, lw=1)
    for ax, ylabel in ((left, "frame time (ms, gpu_ms.total)"),
                       (right, metric[len("metric."):] + " (lower is better)" if metric.startswith("metric.") else metric)):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("particles alive")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3, which="both")
    left.set_title("Frame time against particle count")
    right.set_title("Error against particle count")
    handles, labels = left.get_legend_handles_labels()
    if handles:
        left.legend(fontsize=7)
    return plots._save(fig, path)
