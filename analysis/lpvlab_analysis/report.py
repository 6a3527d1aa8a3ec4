"""Build <out>/index.html for a sweep directory.

The page comes from the Jinja2 template templates/report.html.j2 (autoescaped; templating.py),
filled with the data this module gathers; the sections' tables come from templates/table.html.j2
(html_table.py) and the sequences from sequences.html.j2. It is self-contained HTML+CSS;
images are PNG files referenced by
relative paths (plots and tone-mapped images in <out>/img/, error maps and
combined.png linked from the run directories). Sections: sweep overview,
speed/accuracy plot with Pareto front, ablation table, each configuration against the
baseline series at equal settings and equal time (equal_time.py), time per stage and
error against each swept numeric parameter, the estimated time of each
counted stage on named GPUs beside the time measured here (gpu_estimate.py:
an estimate from the cost counters, labelled as one), trends against the
thesis's tables (when the sweep varies their parameter) with the estimate on
the thesis's GPUs, then per configuration the reference, result and error map
side by side; for animated configurations, their figures per frame and their video
(sequences.py).

Errors the user can fix (missing directory, missing/empty summary.csv)
raise summary.SummaryError with a message naming the file.
"""
import datetime
import json
import os
import sys

import numpy as np
import pandas as pd

from . import equal_time as ET
from . import fsutil
from . import gpu_estimate as G
from . import explain
from . import grid_slices
from . import images
from . import plots
from . import sections as SC
from . import sequences
from . import summary as S
from . import tables
from . import templating
from . import thesis_tables as T
from . import tuning

# Every table's columns sort by a click on their header (numbers numerically, then text; a second
# click reverses), dependency-free. The header is the table's <thead> row, else its first row.
SORTABLE_TABLES_JS = """
document.querySelectorAll('table').forEach(function (table) {
  var head = table.tHead ? table.tHead.rows[0] : table.rows[0];
  if (!head) return;
  Array.prototype.forEach.call(head.cells, function (th, col) {
    th.classList.add('sortable');
    th.addEventListener('click', function () {
      var rows = Array.prototype.filter.call(table.rows, function (r) {
        return r !== head && r.parentNode.tagName !== 'THEAD';
      });
      var up = th.getAttribute('aria-sort') !== 'ascending';
      function key(r) {
        var t = r.cells[col] ? r.cells[col].textContent.trim() : '';
        var n = /^[-+]?(\\d|\\.\\d)/.test(t) ? parseFloat(t) : NaN;
        return [isNaN(n) ? null : n, t];
      }
      rows.sort(function (a, b) {
        var ka = key(a), kb = key(b), c;
        if (ka[0] !== null && kb[0] !== null) c = ka[0] - kb[0];
        else if (ka[0] !== null) c = -1;
        else if (kb[0] !== null) c = 1;
        else c = ka[1].localeCompare(kb[1]);
        return up ? c : -c;
      });
      rows.forEach(function (r) { r.parentNode.appendChild(r); });
      Array.prototype.forEach.call(head.cells, function (h) { h.removeAttribute('aria-sort'); });
      th.setAttribute('aria-sort', up ? 'ascending' : 'descending');
    });
  });
});
"""

# The images of a configuration: a click on the result flips it with the reference (same
# exposure), a double click zooms any image 4x with its pixels as squares (in its own scroll box).
IMAGE_CONTROLS_JS = """
document.querySelectorAll('img.flip').forEach(function (img) {
  var caption = img.parentNode.querySelector('figcaption');
  var own = [img.getAttribute('src'), caption.textContent];
  var other = [img.dataset.flip, img.dataset.flipCaption + ' (click: back to the result)'];
  img.addEventListener('click', function () {
    var to = img.getAttribute('src') === own[0] ? other : own;
    img.setAttribute('src', to[0]);
    caption.textContent = to[1];
  });
});
document.querySelectorAll('.trio img').forEach(function (img) {
  img.addEventListener('dblclick', function () {
    var zoomed = img.classList.toggle('zoomed');
    img.style.width = zoomed ? (4 * img.naturalWidth) + 'px' : '';
  });
});
"""

CSS = """
body{font-family:sans-serif;margin:1.5em;max-width:1400px;color:#222}
table{border-collapse:collapse;font-size:13px;margin:.5em 0}
th,td{border:1px solid #ccc;padding:3px 6px}th{background:#f0f0f0}
td.num{text-align:right;font-variant-numeric:tabular-nums}
img.plot{max-width:100%;border:1px solid #ddd;margin:4px}
.trio figure{max-width:100%;overflow:auto}img.zoomed{image-rendering:pixelated;max-width:none}
img.flip{cursor:pointer}th.sortable{cursor:pointer}th[aria-sort=ascending]::after{content:" \\25B2"}th[aria-sort=descending]::after{content:" \\25BC"}
.trio{display:flex;gap:8px;flex-wrap:wrap}.trio figure{margin:0}
.trio img{width:256px;image-rendering:pixelated;border:1px solid #ddd}
figcaption{font-size:12px;color:#555}.note{font-size:12px;color:#666}
.scroll{overflow-x:auto;max-width:100%}
"""


def _log(msg):
    print(f"[report] {msg}", file=sys.stderr, flush=True)


def _rel(path, out_dir):
    return os.path.relpath(path, out_dir).replace(os.sep, "/")


def _safe(name):
    return "".join(ch if ch.isalnum() or ch in "-_." else "_" for ch in str(name))


def resolve_run_dir(sweep_dir, row):
    """The run directory of a configuration: run_dir from the summary when it
    exists (absolute, or relative to the sweep dir), else <sweep>/<config_id>."""
    rd = str(row.get("run_dir", "") or "")
    cands = []
    if rd and rd != "nan":
        cands += [rd] if os.path.isabs(rd) else [os.path.join(sweep_dir, rd), rd]
    cands.append(os.path.join(sweep_dir, str(row["config_id"])))
    for c in cands:
        if os.path.isdir(c):
            return c
    return cands[-1]


def _read_manifest(run_dir):
    p = os.path.join(run_dir, "manifest.json")
    try:
        with open(p, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def _config_images(agg, sweep_dir, out_dir, use_exr):
    """Per configuration: list of (caption, relative image path or None, note)."""
    img_dir = os.path.join(out_dir, "img")
    ref_cache = {}
    result = {}
    n = len(agg)
    for k, (_, row) in enumerate(agg.iterrows(), 1):
        _log(f"images {k}/{n}: {row['config_name']}")
        run_dir = resolve_run_dir(sweep_dir, row)
        man = _read_manifest(run_dir)
        trio = []
        done = False
        ref_dir = ((man or {}).get("reference") or {}).get("directory")
        if use_exr and images.have_oiio() and ref_dir:
            ref_exr = os.path.join(ref_dir, "images.exr")
            key = os.path.abspath(ref_dir)
            out_ref = ref_cache.get(key) or os.path.join(img_dir, f"reference_{len(ref_cache)}.png")
            out_run = os.path.join(img_dir, f"result_{_safe(row['config_id'])}.png")
            if key not in ref_cache and os.path.exists(out_ref):
                os.unlink(out_ref)  # stale from an earlier report
            r = images.tonemapped_pair(os.path.join(run_dir, "images.exr"), ref_exr, out_ref, out_run)
            if r is not None:
                ref_cache[key] = out_ref
                trio.append(("reference indirect1 (path traced)", _rel(out_ref, out_dir)))
                trio.append((f"{row['variant']}: indirect (same exposure)", _rel(out_run, out_dir)))
                done = True
        if not done:
            comb = os.path.join(run_dir, "combined.png")
            trio.append(("reference", None))
            trio.append(("result combined.png", _rel(comb, out_dir) if os.path.isfile(comb) else None))
        err = os.path.join(run_dir, "error_indirect.png")
        trio.append(("error map (FLIP, indirect)", _rel(err, out_dir) if os.path.isfile(err) else None))
        # The run's light grid, where it dumped one (lpvlab run --dump-grid).
        grid_png = grid_slices.write_png(run_dir, os.path.join(img_dir, f"grid_{_safe(row['config_id'])}.png"))
        if grid_png:
            trio.append(("light grid: middle slices of the finest level", _rel(grid_png, out_dir)))
        result[row["config_id"]] = (trio, done, run_dir)
    return result


def _figures(trio, flips):
    """The figures of a configuration's images (macros.html.j2's `figure`). With `flips` (a
    tone-mapped reference and result of the same exposure, trio[0] and trio[1]), a click on the
    result shows the reference in its place and back (IMAGE_CONTROLS_JS); a double click on any
    image zooms it 4x with its pixels drawn as squares."""
    figs = []
    for k, (cap, src) in enumerate(trio):
        flip = {"src": trio[0][1], "caption": trio[0][0]} if flips and k == 1 and src else None
        figs.append({"caption": cap, "src": src, "flip": flip})
    return figs


_BASIS_MARK = {"measured": "", "every measured GPU": "†"}


def _calibrated_text(row, gpu, stage):
    """'m (lo-hi)' of the calibrated estimate, marked by whose measurements; '—' without any."""
    key = f"{G.CALIBRATED}{gpu.key}.{stage}"
    value = row.get(key, float("nan"))
    if not isinstance(value, float) or value != value:
        return "—"
    basis = str(row.get(key + ".basis", ""))
    mark = _BASIS_MARK.get(basis, "*")  # "like <GPU>": borrowed from the same chip
    return (f"{tables.fmt(value)} ({tables.fmt(row[key + '.low'])}–{tables.fmt(row[key + '.high'])})"
            f"{mark}")


def _gpu_estimate_section(agg, gpus):
    """Per configuration and counted stage: the time measured here and, per GPU, the roofline
    bound and the calibrated estimate, each labelled (G.with_estimates). The template's data, and
    the same as Markdown; (None, "") without counted stages."""
    stages = G.counted_stages(agg)
    if not stages:
        return None, ""
    est = G.with_estimates(agg, gpus)
    md_head = ("| configuration | stage | measured here (ms) | "
               + " | ".join(f"{g.name} roofline bound (ms) | {g.name} calibrated (range) (ms)" for g in gpus) + " |")
    md = [md_head, "|" + "---|" * (3 + 2 * len(gpus))]
    rows = []
    for _, row in est.iterrows():
        for stage in stages:
            measured = row.get(S.time_col(stage), float("nan"))
            pairs = [(tables.fmt(row[f"{G.PREFIX}{g.key}.{stage}"]), _calibrated_text(row, g, stage)) for g in gpus]
            rows.append({"configuration": str(row["config_name"]), "stage": stage,
                         "measured": tables.fmt(measured), "cells": pairs})
            md.append(f"| {row['config_name']} | {stage} | {tables.fmt(measured)} | "
                      + " | ".join(f"{b} | {c}" for b, c in pairs) + " |")
    note = ("Roofline bound: the fastest the counted work could run. Calibrated: the bound divided by "
            "the efficiency measured for the stage's kernel family (median over the measurements, range "
            "over them); * borrowed from the same chip (calibrate_like), † the range over every measured "
            "GPU, — no measurement of the family. Measurements: gpus.toml.")
    md.append("")
    md.append(note)
    return {"gpus": [g.name for g in gpus], "rows": rows, "note": note}, "\n".join(md) + "\n"


def _thesis_estimate_rows(rows):
    """The estimate on the thesis's GPUs beside its measured tables (G.thesis_comparison), as the
    template's rows: each measured x, then the increment in bold."""
    out = []
    for r in rows:
        name = r["variant"] + (f" ({r['method']})" if r["method"] else "")
        for i, x in enumerate(r["x"]):
            out.append({"table": r["table"], "variant": name, "gpu": f"{r['gpu']} ({r['thesis_column']})",
                        "x": f"{x:g}", "thesis": tables.fmt(r["thesis_ms"][i]),
                        "estimate": tables.fmt(r["estimate_ms"][i]), "ratio": tables.fmt(r["ratio"][i]),
                        "bold": False})
        ratio = r["thesis_slope_ms"] / r["estimate_slope_ms"] if r["estimate_slope_ms"] > 0 else float("nan")
        out.append({"table": r["table"], "variant": name, "gpu": r["gpu"], "x": "increment",
                    "thesis": tables.fmt(r["thesis_slope_ms"]), "estimate": tables.fmt(r["estimate_slope_ms"]),
                    "ratio": tables.fmt(ratio), "bold": True})
    return out


def _thesis_section(agg, img_dir, out_dir):
    """Per thesis table whose parameter this sweep varies: its plot and its series (the thesis's
    and lpvlab's), each value with its normalised one in brackets."""
    trends = []
    for tab, rows in T.applicable_tables(agg):
        measured = T.measured_series(tab, rows)
        if not measured:
            continue
        _log(f"thesis trend table {tab.number}")
        path, x_ref = plots.trend_vs_thesis(tab, measured, os.path.join(img_dir, f"thesis_{tab.number}.png"))
        if path is None:
            continue
        xs = sorted(set(tab.x) | {x for v in measured.values() for x in v[0]})
        allseries = [(f"thesis {k}", tab.x, v) for k, v in tab.columns.items()]
        allseries += [(k, v[0], v[1]) for k, v in measured.items()]
        series = []
        for name, sx, sy in allseries:
            norm = T.normalise(sx, sy, x_ref) or [float("nan")] * len(sy)
            d = {x: (y, nv) for x, y, nv in zip(sx, sy, norm)}
            series.append({"name": name, "bold": name.startswith("lpvlab"),
                           "cells": [f"{tables.fmt(d[x][0])} ({tables.fmt(d[x][1])})" if x in d else None
                                     for x in xs]})
        trends.append({"caption_en": tab.caption_en, "caption": tab.caption, "stage": tab.stage,
                       "x_ref": f"{x_ref:g}", "plot": _rel(path, out_dir), "xs": [f"{x:g}" for x in xs],
                       "series": series})
    return trends


def load_sweeps(sweep_dirs):
    """The summaries of one or several sweep directories as one table. With several, each row's
    run_dir becomes absolute and its config_id is prefixed with its sweep directory's name, so
    configurations stay apart (baselines are per scene: param.scene.file)."""
    frames = []
    for d in sweep_dirs:
        if not os.path.isdir(d):
            raise S.SummaryError(f"{d}: no such sweep directory")
        df = S.load_summary(os.path.join(d, "summary.csv"))
        if len(sweep_dirs) > 1:
            df["run_dir"] = [resolve_run_dir(d, row) for _, row in df.iterrows()]
            df["run_dir"] = [os.path.abspath(r) for r in df["run_dir"]]
            name = os.path.basename(os.path.normpath(d))
            df["config_id"] = name + "/" + df["config_id"].astype(str)
        frames.append(df)
    return frames[0] if len(frames) == 1 else pd.concat(frames, ignore_index=True, sort=False)


def _package():
    """This package, whose modules register the report's sections (sections.py)."""
    return sys.modules[__package__]


def build_report(sweep_dir, out_dir=None, metric=None, use_exr=True,
                 gpu_table=G.DEFAULT_TABLE, speed=S.DEFAULT_SPEED, gpu=S.DEFAULT_GPU):
    """Write <out_dir>/index.html (default <sweep_dir>/report) and return its path. `sweep_dir`
    may be a list of sweep directories: one report of them all, which needs out_dir. The inputs
    (the summaries, the GPU table) are read before anything is written. `speed`: the time of the
    speed axis, plots, Pareto fronts, equal-time comparisons and tables (S.SPEEDS: "method", the
    indirect method's own stages, "total", the whole frame, or "gpu-estimate", the method's GL
    kernels estimated on the GPU of gpus.toml key `gpu`)."""
    sweep_dirs = list(sweep_dir) if isinstance(sweep_dir, (list, tuple)) else [sweep_dir]
    # An explanation (lpvlab explain's directory) and a tune have pages of their own.
    for kind in (explain, tuning):
        if len(sweep_dirs) == 1 and kind.is_page_of(sweep_dirs[0]) and \
                not os.path.isfile(os.path.join(sweep_dirs[0], "summary.csv")):
            index = kind.build_page(sweep_dirs[0], out_dir or os.path.join(sweep_dirs[0], "report"), CSS,
                                    SORTABLE_TABLES_JS + IMAGE_CONTROLS_JS)
            _log(f"wrote {index}")
            return index
    if len(sweep_dirs) > 1 and not out_dir:
        raise S.SummaryError("a report of several sweeps needs --out (where to write it)")
    gpus = G.load_gpus(gpu_table)
    estimated_on = None
    if speed == "gpu-estimate":
        by_key = {g.key: g for g in gpus}
        if gpu not in by_key:
            raise S.SummaryError(f"--gpu {gpu}: not a GPU of {gpu_table} (one of {', '.join(by_key)})")
        estimated_on = by_key[gpu]
    df = load_sweeps(sweep_dirs)
    sweep_dir = sweep_dirs[0]
    summary_path = " + ".join(os.path.join(d, "summary.csv") for d in sweep_dirs)
    out_dir = out_dir or os.path.join(sweep_dir, "report")
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise S.SummaryError(f"--out {out_dir}: is a file, not a directory")
    agg = S.aggregate(df, speed, estimated_on)
    # A metric the user named must exist (before anything is written); the default may not.
    metric = S.resolve_metric(agg, metric or S.DEFAULT_METRIC, required=metric is not None)
    img_dir = os.path.join(out_dir, "img")
    os.makedirs(img_dir, exist_ok=True)
    _log(f"{len(df)} rows from {summary_path}")
    _log(f"{len(agg)} configurations")
    swept = S.swept_params(agg)
    numeric = [p for p in swept if S.is_numeric_param(agg, p)]
    warned = []
    # Runs whose results are suspect (all black, a solve that did not converge): named at the top,
    # so that no figure of theirs is read without the warning.
    if "warnings" in agg.columns:
        warned = [(r["label"], str(r["warnings"])) for _, r in agg.iterrows()
                  if isinstance(r["warnings"], str) and r["warnings"]]

    _log("plot: speed vs accuracy")
    speed_plot = plots.speed_accuracy(agg, os.path.join(img_dir, "speed_accuracy.png"), metric=metric)

    # The sections of the kinds of run this sweep holds (sections.py: methods, radiosity,
    # particles, ... each registered by its own module), each part's table also as Markdown.
    report_sections = []
    for section, parts in SC.applicable(SC.report_modules(_package()), agg):
        _log(f"plot: {section.title.lower()}")
        done = []
        for part in parts:
            p = part.plot(agg, os.path.join(img_dir, part.image), metric)
            fsutil.write_text(os.path.join(out_dir, part.markdown_file), part.markdown(agg, metric))
            done.append({"note": part.note, "plot": _rel(p, out_dir) if p else None,
                         "table": part.html(agg, metric), "markdown": part.markdown_file})
        report_sections.append({"title": section.title, "parts": done})

    fsutil.write_text(os.path.join(out_dir, "ablation.md"), tables.to_markdown(agg))
    equal_time = None
    if ET.is_baseline(agg).any():
        equal_time = ET.to_html(agg)
        fsutil.write_text(os.path.join(out_dir, "equal_time.md"), ET.compact_markdown(agg) + "\n" + ET.to_markdown(agg))

    parameters = []
    for prm in numeric:
        _log(f"plot: stages/error vs {prm[6:]}")
        drawn = [plots.stage_times(agg, prm, os.path.join(img_dir, f"stages_{_safe(prm[6:])}.png"))]
        if prm in ("param.propagation.iterations", "param.grid.resolution") or S.metric_columns(agg):
            drawn.append(plots.error_vs_param(agg, prm, os.path.join(img_dir, f"error_{_safe(prm[6:])}.png")))
        parameters.append({"name": prm[6:], "plots": [_rel(p, out_dir) for p in drawn if p]})

    gpu_estimate, estimate_md = _gpu_estimate_section(agg, gpus)
    if gpu_estimate:
        fsutil.write_text(os.path.join(out_dir, "gpu_estimate.md"), estimate_md)

    trends = _thesis_section(agg, img_dir, out_dir)
    thesis = {"trends": trends, "estimates": _thesis_estimate_rows(G.thesis_comparison(agg, gpus))} if trends else None

    seq = sequences.sequence_section(
        [(row["config_name"], row["config_id"], resolve_run_dir(sweep_dir, row)) for _, row in agg.iterrows()],
        img_dir, out_dir)
    if seq:
        _log("plots: sequences")

    imgs = _config_images(agg, sweep_dir, out_dir, use_exr)
    # In the order of their swept parameters' values, each with links to its run's files.
    configurations = []
    for _, row in S.ordered_by_swept(agg).iterrows():
        trio, done, run_dir = imgs[row["config_id"]]
        links = [(f"{_rel(run_dir, out_dir)}/{name}", label)
                 for name, label in (("images.exr", "EXR"), ("manifest.json", "manifest"))
                 if os.path.isfile(os.path.join(run_dir, name))]
        configurations.append({"name": str(row["config_name"]), "variant": str(row["variant"]),
                               "label": str(row["label"]), "links": links, "figures": _figures(trio, done)})

    page = templating.environment().get_template("report.html.j2").render(
        css=CSS, js=SORTABLE_TABLES_JS + IMAGE_CONTROLS_JS,
        sweeps=", ".join(os.path.abspath(d) for d in sweep_dirs), n_configs=len(agg), n_runs=len(df),
        generated=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        timed_on=S.timed_on(agg), speed_words=S.speed_words(agg), swept=[p[6:] for p in swept],
        warned=warned, speed_plot=_rel(speed_plot, out_dir) if speed_plot else None, metric=metric,
        speed_col=S.speed_col(agg), sections=report_sections, ablation=tables.to_html(agg),
        equal_time=equal_time, out_of_range=ET.OUT_OF_RANGE, parameters=parameters,
        gpu_estimate=gpu_estimate, thesis=thesis, sequences=seq or [],
        tonemapped=images.have_oiio() and use_exr, configurations=configurations)
    index = os.path.join(out_dir, "index.html")
    fsutil.write_text(index, page)
    _log(f"wrote {index}")
    return index


def main(argv=None):
    """CLI: report.py DIR [DIR...] [--metric NAME] [--out DIR/report] [--no-exr]
    [--time method|total|gpu-estimate] [--gpu KEY]. Exit 2 on
    unusable input."""
    import argparse
    ap = argparse.ArgumentParser(description="Build an HTML report (plots, ablation table, images) of an lpvlab sweep.")
    ap.add_argument("dir", nargs="+",
                    help="sweep directory containing summary.csv and one run directory per configuration; "
                         "several: one report of them all (needs --out); or an explanation's directory "
                         "(lpvlab explain: explain.json) or a tune's (lpvlab tune: tune.json)")
    ap.add_argument("--metric", default=None, help=f"error metric column (default {S.DEFAULT_METRIC})")
    ap.add_argument("--out", default=None, help="output directory (default DIR/report)")
    ap.add_argument("--no-exr", action="store_true", help="do not read EXRs; use combined.png and the error map only")
    ap.add_argument("--time", default=S.DEFAULT_SPEED, choices=S.SPEEDS,
                    help="the speed axis: method = the indirect method's own stages (default; what differs "
                         "between configurations), total = the whole frame with the raster passes and direct light, "
                         "gpu-estimate = the method's GL kernels estimated on --gpu (an estimate, labelled)")
    ap.add_argument("--gpu", default=S.DEFAULT_GPU,
                    help=f"with --time gpu-estimate: the GPU, a key of gpus.toml (default {S.DEFAULT_GPU})")
    a = ap.parse_args(argv)
    try:
        idx = build_report(a.dir if len(a.dir) > 1 else a.dir[0], a.out, a.metric, use_exr=not a.no_exr,
                           speed=a.time, gpu=a.gpu)
    except (S.SummaryError, G.GpuTableError, grid_slices.GridDumpError) as exc:
        print(f"lpvlab: error: {exc}", file=sys.stderr)
        return 2
    print(idx)
    return 0
