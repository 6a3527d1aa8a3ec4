"""Animated configurations in a report: their figures per frame, and their video.

Read from each run's manifest.json (sequence.frame_records, written by `lpvlab run` on an
animated experiment; framework/experiment/sequence.h), not from summary.csv, whose rows are the
frames too but whose aggregation takes one value per configuration. Per sequence:

- the error of each frame against its own path-traced reference: RMSE and FLIP of every
  comparison pair (reference.comparison.<pair>.metrics);
- the temporal figures (framework/experiment/sequence_temporal.h): the relative change of each
  LPV output from the frame before at the same surface points (filled markers: frames at rest,
  where only the camera moved, so the change is flicker) and the relative temporal error of each
  pair, the reference's noise removed;
- the video (video.mp4) beside them, when the run made one.
"""
import json
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import fsutil  # noqa: E402
from . import templating  # noqa: E402


def read_records(run_dir):
    """The frame records of a run's manifest, or None when the run is not a sequence (or its
    manifest is missing or unreadable)."""
    try:
        with open(os.path.join(run_dir, "manifest.json"), encoding="utf-8") as f:
            manifest = json.load(f)
    except (OSError, ValueError):
        return None
    seq = manifest.get("sequence") if isinstance(manifest, dict) else None
    records = seq.get("frame_records") if isinstance(seq, dict) else None
    if not isinstance(records, list) or len(records) < 2:
        return None
    return [r for r in records if isinstance(r, dict)]


def _number(value):
    return float(value) if isinstance(value, (int, float)) and math.isfinite(value) else None


def frame_series(records):
    """{(panel, label): [(frame, value), ...]} for the panels 'error' (per-frame metrics against
    the reference) and 'temporal' (relative change and temporal error), plus the frames at rest."""
    series, at_rest = {}, set()
    for r in records:
        frame = r.get("frame")
        if not isinstance(frame, int):
            continue
        comparison = (r.get("reference") or {}).get("comparison") or {}
        for pair, entry in comparison.items():
            metrics = (entry or {}).get("metrics") or {}
            for metric in ("rmse", "flip"):
                v = _number(metrics.get(metric))
                if v is not None:
                    series.setdefault(("error", f"{metric} {pair}"), []).append((frame, v))
        temporal = r.get("temporal") or {}
        if temporal.get("at_rest"):
            at_rest.add(frame)
        for group, label in (("change", "change"), ("error", "temporal error")):
            for name, figures in (temporal.get(group) or {}).items():
                v = _number((figures or {}).get("relative"))
                if v is not None:
                    series.setdefault(("temporal", f"{label} {name}"), []).append((frame, v))
    return series, at_rest


def per_frame_plot(series, at_rest, path, title):
    """One PNG with the error panel (when there are references) above the temporal panel; None
    when there is nothing to draw."""
    panels = [p for p in ("error", "temporal") if any(k[0] == p for k in series)]
    if not panels:
        return None
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 3.2 * len(panels)), sharex=True,
                             squeeze=False)
    ylabels = {"error": "RMSE against the reference",
               "temporal": "relative to the frame's mean"}
    for ax, panel in zip(axes[:, 0], panels):
        # FLIP is in [0, 1], RMSE in radiance units: FLIP gets an axis of its own, on the right.
        flip_ax = ax.twinx() if any(k[0] == panel and k[1].startswith("flip") for k in series) else None
        if flip_ax is not None:
            flip_ax.set_ylabel("FLIP (dashed)")
        for (p, label), points in sorted(series.items()):
            if p != panel:
                continue
            frames = [f for f, _ in points]
            values = [v for _, v in points]
            on_flip = flip_ax is not None and label.startswith("flip")
            line, = (flip_ax if on_flip else ax).plot(frames, values, label=label, linewidth=1.2,
                                                      linestyle="--" if on_flip else "-")
            if panel == "temporal" and label.startswith("change"):
                rest = [(f, v) for f, v in points if f in at_rest]
                if rest:
                    ax.plot([f for f, _ in rest], [v for _, v in rest], "o", color=line.get_color(),
                            markersize=3)
        ax.set_ylabel(ylabels[panel])
        ax.grid(alpha=0.3)
        handles, labels = ax.get_legend_handles_labels()
        if flip_ax is not None:
            more = flip_ax.get_legend_handles_labels()
            handles, labels = handles + more[0], labels + more[1]
        ax.legend(handles, labels, fontsize=8)
    axes[-1, 0].set_xlabel("frame")
    axes[0, 0].set_title(title, fontsize=9, wrap=True)
    fsutil.write_with(path, lambda tmp: fig.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
    plt.close(fig)
    return path


def sequence_section(configurations, img_dir, out_dir):
    """The report's part (templates/sequences.html.j2) for the sequences among `configurations`,
    a list of (name, id, run_dir): per sequence its per-frame plot, its video and how many frame
    changes were at rest. Empty when none is a sequence."""
    sequences = []
    for name, config_id, run_dir in configurations:
        records = read_records(run_dir)
        if records is None:
            continue
        series, at_rest = frame_series(records)
        safe = "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in str(config_id))
        plot = per_frame_plot(series, at_rest, os.path.join(img_dir, f"frames_{safe}.png"),
                              f"{name}: {len(records)} frames")
        video = os.path.join(run_dir, "video.mp4")
        sequences.append({"name": str(name), "plot": os.path.relpath(plot, out_dir) if plot else None,
                          "video": os.path.relpath(video, out_dir) if os.path.isfile(video) else None,
                          "at_rest": len(at_rest), "changes": len(records) - 1})
    return [templating.render("sequences.html.j2", sequences=sequences)] if sequences else []
