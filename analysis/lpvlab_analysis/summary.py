"""Load a sweep's summary.csv and aggregate its repeats per configuration.

summary.csv (written by `lpvlab sweep`) has one row per configuration and
repeat: config_id, config_name, repeat, run_dir, param.<key>..., time.<stage>.ms (each stage's
time by its clock), time.<stage>.clock (gl_timer_query: GL timestamp queries on the GL renderer
timed_on.gl; cpu_wall_clock: the steady clock on the CPU timed_on.cpu, for a stage on the CPU
backend), wall_ms.<stage>, memory_bytes, cells, work.<stage>.<...>, metric.<pair>.<metric>. Timings vary
between repeats, so they are summarised by their median (robust to the odd
slow frame); parameters, memory and image metrics describe the configuration
and are taken from its first row that has them.
"""
import math
import os

import numpy as np
import pandas as pd

TYPE_PARAMS = ["param.injection.type", "param.occlusion.type", "param.propagation.type",
               "param.rendering.type"]
# [indirect] method: "lpv" (the strategies above) or another indirect-light method, whose rows
# have no LPV type columns.
METHOD_PARAM = "param.indirect.method"
HIGHER_IS_BETTER = {"psnr", "ssim"}
DEFAULT_METRIC = "metric.indirect_vs_indirect1.rmse"
# What each clock of time.<stage>.clock measured, for the report's words and axes.
CLOCK_WORDS = {"gl_timer_query": "GL timer queries", "cpu_wall_clock": "CPU wall clock",
               "mixed": "GL timer queries and CPU wall clock, summed"}
# summary.csv before stage times were labelled by their clock: gpu_ms.<stage>, whatever the clock.
LEGACY_TIME_PREFIX = "gpu_ms."


def time_col(stage):
    """The column of a stage's median time by its clock: 'time.<stage>.ms'."""
    return f"time.{stage}.ms"


def clock_col(stage):
    """The column naming how a stage was timed: 'time.<stage>.clock'."""
    return f"time.{stage}.clock"


TIME_COL = time_col("total")

# The speed axis (`lpvlab report --time`): the time that the speed/accuracy plot, its Pareto
# front, the equal-time comparisons and the tables use, per configuration in column SPEED_COL
# (aggregate adds it). "method": the indirect method's own stages (time.method.ms: LPV's clear,
# occlusion, injection, propagation and indirect; another method's stages), what differs between
# a sweep's configurations; "total": the whole frame (time.total.ms), the raster passes and direct
# light, which every configuration pays alike, included; "gpu-estimate": the method's counted GL
# kernels on a named GPU (gpu_estimate.py: calibrated where its kernel family was measured, else
# the roofline bound), an estimate and labelled one. A run that did not record which stages are
# the method's (summaries before 2026-11) falls back to its total, and SPEED_SOURCE_COL says so.
SPEEDS = ("method", "total", "gpu-estimate")
DEFAULT_GPU = "h100_sxm"  # gpus.toml's key for --time gpu-estimate without --gpu
# The pipeline's own stages (Pipeline::stageNames, framework/pipeline/pipeline.cpp): a run's other
# counted stages are its indirect method's.
PIPELINE_STAGES = ("shadow_maps", "rsm", "gbuffer", "direct")
GPU_ESTIMATE_SOURCE = "gpu_estimate"  # SPEED_SOURCE_COL's prefix: gpu_estimate:<key>:<kind>
SPEED_GPU_COL = "speed.gpu"           # the GPU's name, for the words
DEFAULT_SPEED = "method"
SPEED_COL = "speed.ms"
SPEED_CLOCK_COL = "speed.clock"
SPEED_SOURCE_COL = "speed.source"
_SPEED_WORDS = {time_col("method"): "the indirect method's own stages (time.method.ms)",
                time_col("total"): "the whole frame (time.total.ms)"}


def is_time_col(col):
    return col.startswith("time.") and col.endswith(".ms")


# Sums over stages that summary.csv has beside the stages (time.method.ms, time.shared.ms).
STAGE_SUMS = ("method", "shared")


def stages(df):
    """The stages of the summary's time.<stage>.ms columns, in their column order: the order the
    runs ran them (lpvlab summary merges the manifests' timing.stage_order), "total" last; the
    partial sums (STAGE_SUMS) left out."""
    return [c[len("time."):-len(".ms")] for c in df.columns
            if is_time_col(c) and c[len("time."):-len(".ms")] not in STAGE_SUMS]


def _unique(df, col):
    if col not in df.columns:
        return []
    return sorted({str(v) for v in df[col].dropna() if str(v) not in ("", "nan")})


def timed_on(df, stage="total"):
    """How the sweep's `stage` times were taken and where, in words for a label: 'CPU backend on
    <CPU>', 'GL on <renderer>', both (per configuration, or summed over a frame's stages), or that
    the summary does not say (one written before times were labelled)."""
    clocks = _unique(df, clock_col(stage))
    if not clocks:
        return "clock not recorded (rebuild summary.csv with `lpvlab summary DIR`)"
    cpu = " / ".join(_unique(df, "timed_on.cpu")) or "an unnamed CPU"
    gl = " / ".join(_unique(df, "timed_on.gl")) or "an unnamed GL renderer"
    words = {"cpu_wall_clock": f"CPU backend on {cpu} (wall clock)",
             "gl_timer_query": f"GL on {gl} (timer queries)",
             "mixed": f"GL stages on {gl}, CPU stages on {cpu}"}
    return " or ".join(words.get(c, c) for c in clocks)


class SummaryError(Exception):
    """A sweep directory or its summary.csv cannot be used (message names the file)."""


def _numeric_prefixes():
    return ("wall_ms.", "metric.", "memory_bytes.", "work.", "gpu_work.")


def load_summary(path):
    """Read summary.csv into a DataFrame; numeric columns as floats ("inf" -> inf).

    Raises SummaryError naming the file when it is missing, unreadable or has
    no data rows.
    """
    if not os.path.isfile(path):
        raise SummaryError(f"{path}: no such file (expected the sweep's summary.csv)")
    try:
        df = pd.read_csv(path, keep_default_na=True,
                         dtype={"config_id": str, "config_name": str, "run_dir": str})
    except pd.errors.EmptyDataError:
        raise SummaryError(f"{path}: empty summary (no header, no rows)")
    except Exception as exc:  # parser errors: report the file, not a traceback
        raise SummaryError(f"{path}: cannot parse CSV: {exc}")
    if df.empty:
        raise SummaryError(f"{path}: empty summary (header but no rows)")
    # A summary written before stage times were labelled: the same times, no clock.
    df = df.rename(columns={c: time_col(c[len(LEGACY_TIME_PREFIX):]) for c in df.columns
                            if c.startswith(LEGACY_TIME_PREFIX)})
    missing = [c for c in ("config_id", "config_name") if c not in df.columns]
    if missing:
        raise SummaryError(f"{path}: missing column(s) {', '.join(missing)}")
    for c in df.columns:
        if c.startswith(_numeric_prefixes()) or is_time_col(c) or c in ("memory_bytes", "cells", "repeat"):
            df[c] = to_float(df[c])
    # Parameters: numeric where every value is numeric, otherwise strings.
    for c in param_columns(df):
        conv = pd.to_numeric(df[c], errors="coerce")
        if conv.notna().sum() == df[c].notna().sum():
            df[c] = conv
        else:
            df[c] = df[c].astype(str)
    df["config_id"] = df["config_id"].astype(str)
    return df


def to_float(series):
    """Convert a column to float, accepting "inf", "+inf", "-inf", "nan" and blanks."""
    def conv(v):
        if isinstance(v, (int, float, np.floating, np.integer)):
            return float(v)
        if v is None:
            return math.nan
        s = str(v).strip().lower()
        if s in ("", "nan", "none", "null", "-"):
            return math.nan
        if s in ("inf", "+inf", "infinity", "+infinity"):
            return math.inf
        if s in ("-inf", "-infinity"):
            return -math.inf
        try:
            return float(s)
        except ValueError:
            return math.nan
    return series.map(conv).astype(float)


def param_columns(df):
    return [c for c in df.columns if c.startswith("param.")]


# Beside the metrics in summary.csv but no error of the run: metric.<pair>.pixels counts the
# compared pixels, metric.<pair>.noise_floor_rmse is the reference's own noise as an RMSE,
# ratio_of_means the run's image mean over the reference's, and
# mean_reference_relative_standard_error that mean's standard error over the mean.
NOT_METRICS = ("pixels", "noise_floor_rmse", "ratio_of_means", "mean_reference_relative_standard_error")


def metric_columns(df):
    """The error metric columns (NOT_METRICS left out)."""
    return [c for c in df.columns if c.startswith("metric.") and metric_name(c) not in NOT_METRICS]


def metric_name(col):
    """'metric.indirect_vs_indirect1.rmse' -> 'rmse'."""
    return col.rsplit(".", 1)[-1]


# What each image metric is measured in (framework/metrics/metrics.h), for axis labels.
METRIC_UNITS = {
    "mae": "radiance, W/(m² sr)",
    "rmse": "radiance, W/(m² sr)",
    "rel_mse": "relative: (t − r)² / (r² + ε)",
    "psnr": "dB",
    "ssim": "0–1, of the display images",
    "flip": "0–1, of the display images",
    "hdr_flip": "0–1, over the reference's exposures",
    "block_nrmse": "8×8 blocks, over the reference's mean",
}


def metric_axis_label(col):
    """'indirect_vs_indirect1 rmse (radiance, W/(m² sr); lower is better)' for a metric column."""
    parts = col.split(".")
    pair = parts[1] if len(parts) > 2 else ""
    name = metric_name(col)
    unit = METRIC_UNITS.get(name)
    better = "higher is better" if higher_is_better(col) else "lower is better"
    return f"{pair} {name}".strip() + f" ({unit + '; ' if unit else ''}{better})"


def higher_is_better(col):
    """PSNR and SSIM grow with quality; every other metric is an error."""
    return metric_name(col) in HIGHER_IS_BETTER


def swept_params(df):
    """param.* columns that take more than one value in the sweep (in column order)."""
    return [c for c in param_columns(df) if df[c].nunique(dropna=False) > 1]


def is_numeric_param(df, col):
    return pd.api.types.is_numeric_dtype(df[col])


def ordered_by_swept(df):
    """df's rows ordered by their swept parameters' values, the parameters in column order:
    numbers numerically (so 4 before 16), anything else as text; ties by config_name. Stable."""
    keys = swept_params(df) + (["config_name"] if "config_name" in df.columns else [])
    if not keys:
        return df

    def key(col):
        if col.name != "config_name" and is_numeric_param(df, col.name):
            return pd.to_numeric(col, errors="coerce")
        return col.astype(str)
    return df.sort_values(keys, key=key, kind="mergesort", na_position="last")


def variant_label(row, categorical_swept):
    """Label of the algorithm variant of a configuration.

    injection/occlusion/propagation/rendering types joined by '/' (another indirect method: its
    name, param.indirect.method), followed by the
    swept parameters that are categorical (strings), e.g.
    'rsm_vpl/none/standard/trilinear scene.file=a.obj'. Swept *numeric* parameters
    (iterations, grid resolution, ...) are left out on purpose: they are the
    x axes of the plots, and points of one variant share a colour across them.
    """
    method = row.get(METHOD_PARAM)
    if isinstance(method, str) and method not in ("", "lpv", "nan"):
        label = method
    else:
        parts = [str(row.get(c, "?")) for c in TYPE_PARAMS if c in row.index]
        label = "/".join(parts) if parts else "default"
    # A whole [indirect] table swept (a JSON object per row) is the method's settings: named by
    # the method and the series, not spelled out in the legend.
    extra = [f"{c[len('param.'):]}={row[c]}" for c in categorical_swept
             if c not in TYPE_PARAMS and c != METHOD_PARAM and not str(row[c]).startswith("{")]
    return " ".join([label] + extra)


def config_label(row, swept):
    """Short label naming all swept parameter values of a configuration."""
    parts = [f"{c[len('param.'):]}={row[c]}" for c in swept]
    return ", ".join(parts) if parts else str(row.get("config_name", row.get("config_id")))


def with_speed(agg, speed=DEFAULT_SPEED, gpu=None):
    """agg with the speed axis's time per configuration (SPEED_COL), its clock (SPEED_CLOCK_COL)
    and the column it came from (SPEED_SOURCE_COL): `speed` one of SPEEDS; "gpu-estimate" needs
    `gpu`, a gpu_estimate.Gpu."""
    if speed not in SPEEDS:
        raise SummaryError(f"--time {speed}: expected one of {', '.join(SPEEDS)}")
    if speed == "gpu-estimate":
        return _with_gpu_estimate(agg, gpu)
    out = agg.copy()
    times, clocks, sources = [], [], []
    for _, r in out.iterrows():
        source = TIME_COL
        method = r.get(time_col("method"), math.nan)
        if speed == "method" and isinstance(method, (int, float)) and not math.isnan(method):
            source = time_col("method")
        stage = source[len("time."):-len(".ms")]
        times.append(float(r.get(source, math.nan)) if source in out.columns else math.nan)
        clock = r.get(clock_col(stage), "")
        clocks.append(clock if isinstance(clock, str) else "")
        sources.append(source)
    out[SPEED_COL] = pd.Series(times, index=out.index, dtype=float)
    out[SPEED_CLOCK_COL] = pd.Series(clocks, index=out.index, dtype=object)
    out[SPEED_SOURCE_COL] = pd.Series(sources, index=out.index, dtype=object)
    return out


def _with_gpu_estimate(agg, gpu):
    """with_speed for "gpu-estimate": per configuration the sum over its indirect method's counted
    stages of the calibrated estimate on `gpu`, or of the roofline bound for a stage without one;
    NaN for a configuration with no counted method stage (nothing to estimate)."""
    from . import gpu_estimate as G  # (it does not import this module)
    if gpu is None:
        raise SummaryError("--time gpu-estimate: no GPU named (--gpu KEY, a key of gpus.toml)")
    est = G.with_estimates(agg, [gpu])
    stages = [s for s in G.counted_stages(agg) if s not in PIPELINE_STAGES]
    if not stages:
        raise SummaryError("--time gpu-estimate: no indirect-method stage has counted GL-kernel work "
                           "(gpu_work.<stage>.* in summary.csv): nothing to estimate")
    times, sources = [], []
    for i in est.index:
        total, kinds = 0.0, set()
        for stage in stages:
            calibrated = est.at[i, f"{G.CALIBRATED}{gpu.key}.{stage}"] if f"{G.CALIBRATED}{gpu.key}.{stage}" in est.columns else math.nan
            bound = est.at[i, f"{G.PREFIX}{gpu.key}.{stage}"]
            if not math.isnan(calibrated):
                total, kinds = total + calibrated, kinds | {"calibrated"}
            elif not math.isnan(bound):
                total, kinds = total + bound, kinds | {"roofline"}
        times.append(total if kinds else math.nan)
        kind = kinds.pop() if len(kinds) == 1 else ("mixed" if kinds else "none")
        sources.append(f"{GPU_ESTIMATE_SOURCE}:{gpu.key}:{kind}")
    out = agg.copy()
    out[SPEED_COL] = pd.Series(times, index=out.index, dtype=float)
    out[SPEED_CLOCK_COL] = pd.Series([f"{GPU_ESTIMATE_SOURCE}:{gpu.key}"] * len(out), index=out.index, dtype=object)
    out[SPEED_SOURCE_COL] = pd.Series(sources, index=out.index, dtype=object)
    out[SPEED_GPU_COL] = pd.Series([gpu.name] * len(out), index=out.index, dtype=object)
    return out


def _gpu_estimate_words(df):
    kinds = {s.rsplit(":", 1)[1] for s in df[SPEED_SOURCE_COL]}
    how = {"calibrated": "calibrated by measured kernels", "roofline": "the roofline bound",
           "mixed": "calibrated where measured, else the roofline bound",
           "none": "nothing counted"}
    words = ", ".join(how[k] for k in sorted(kinds))
    gpu = " / ".join(_unique(df, SPEED_GPU_COL))
    return (f"the indirect method's GL kernels estimated on {gpu} ({words}; an estimate from "
            "counted work, not a measurement)")


def speed_col(df):
    """The speed axis's column: SPEED_COL where aggregate() added it, else time.total.ms (a frame
    made by hand, or by a caller that did not aggregate)."""
    return SPEED_COL if SPEED_COL in df.columns else TIME_COL


def speed_clock_col(df):
    """The column naming how the speed axis's times were taken (gl_timer_query, cpu_wall_clock,
    mixed), or None when the frame does not say."""
    if SPEED_CLOCK_COL in df.columns:
        return SPEED_CLOCK_COL
    return clock_col("total") if clock_col("total") in df.columns else None


def speed_words(df):
    """What the speed axis measures, in words for a label: the method's stages, the whole frame,
    or the method's stages with the total where a run did not record them."""
    if SPEED_SOURCE_COL not in df.columns or not len(df):
        return _SPEED_WORDS[TIME_COL]
    sources = set(df[SPEED_SOURCE_COL])
    if all(s.startswith(GPU_ESTIMATE_SOURCE + ":") for s in sources):
        return _gpu_estimate_words(df)
    if sources == {time_col("method")}:
        return _SPEED_WORDS[time_col("method")]
    if sources == {TIME_COL}:
        return _SPEED_WORDS[TIME_COL]
    return (_SPEED_WORDS[time_col("method")] + "; the whole frame (time.total.ms) for the runs "
            "that did not record the method's stages")


def speed_stage(df):
    """The stage whose clock the speed axis's times carry ("method" or "total"), for timed_on."""
    if SPEED_SOURCE_COL in df.columns and len(df) and set(df[SPEED_SOURCE_COL]) == {time_col("method")}:
        return "method"
    return "total"


def is_estimated_speed(df):
    """Whether the speed axis holds estimates (--time gpu-estimate), not times."""
    return (SPEED_SOURCE_COL in df.columns and len(df) > 0 and
            all(str(s).startswith(GPU_ESTIMATE_SOURCE + ":") for s in df[SPEED_SOURCE_COL]))


def speed_axis_label(df):
    """The speed axis's label: what it measures, in ms, and how the times were taken and where
    (or that they are estimates)."""
    if is_estimated_speed(df):
        return f"{speed_words(df)}: ms"
    return f"{speed_words(df)}: ms, median; {timed_on(df, speed_stage(df))}"


def aggregate(df, speed=DEFAULT_SPEED, gpu=None):
    """One row per configuration (ordered by first appearance).

    Columns: config_id, config_name, run_dir, repeats, param.*, median
    time.*.ms/wall_ms.*, memory_bytes, cells, metric.*, plus 'variant', 'label' and the speed
    axis's time (with_speed: SPEED_COL, by `speed`). Timings are medians over repeats (NaN repeats ignored); metric.*,
    temporal.* and method.* figures their means (a sequence's frames differ; a
    static run's repeats share the run's); other columns take the first
    non-missing value of the configuration.
    """
    timing = [c for c in df.columns if is_time_col(c) or c.startswith("wall_ms.")]
    rows = []
    for cid, g in df.groupby("config_id", sort=False):
        r = {"config_id": cid, "repeats": len(g)}
        for c in df.columns:
            if c in ("config_id", "repeat"):
                continue
            if c in timing:
                r[c] = float(np.nanmedian(g[c].values)) if g[c].notna().any() else math.nan
            elif c.startswith(("metric.", "temporal.", "method.")) and pd.api.types.is_numeric_dtype(g[c]):
                # A sequence's rows are its frames, each with its own figures: their mean (a
                # static run's repeats all have the run's). An infinite PSNR stays infinite.
                r[c] = float(np.nanmean(g[c].values)) if g[c].notna().any() else math.nan
            else:
                nn = g[c].dropna()
                r[c] = nn.iloc[0] if len(nn) else (math.nan if pd.api.types.is_numeric_dtype(g[c]) else "")
        rows.append(r)
    agg = pd.DataFrame(rows)
    for c in param_columns(df):
        if pd.api.types.is_numeric_dtype(df[c]):
            agg[c] = pd.to_numeric(agg[c], errors="coerce")
    swept = swept_params(agg)
    categorical = [c for c in swept if not is_numeric_param(agg, c)]
    agg["variant"] = [variant_label(row, categorical) for _, row in agg.iterrows()]
    agg["label"] = [config_label(row, swept) for _, row in agg.iterrows()]
    return with_speed(agg, speed, gpu)


def one_at_a_time(agg, param):
    """Rows of agg in which every swept numeric parameter other than param sits
    at its most common value, so that a plot against param is not a mixture
    of unrelated settings (a one-factor-at-a-time slice of a grid sweep)."""
    sel = agg
    for c in swept_params(agg):
        if c == param or not is_numeric_param(agg, c):
            continue
        mode = agg[c].mode(dropna=True)
        if len(mode):
            sel = sel[sel[c] == mode.iloc[0]]
    return sel.sort_values(param)


def resolve_metric(agg, name, required=False):
    """Accept a full column name, 'pair.metric' or a bare metric ('rmse' ->
    the indirect_vs_indirect1 column when present). A name the sweep does not have is a
    SummaryError listing the metrics it has when `required` (the user named it); the default
    metric is returned unchanged instead (a sweep without that comparison: the plot then says
    there is no data)."""
    if name in agg.columns:
        return name
    for cand in (f"metric.{name}", f"metric.indirect_vs_indirect1.{name}", f"metric.direct_vs_direct.{name}"):
        if cand in agg.columns:
            return cand
    if required:
        have = metric_columns(agg)
        if not have:
            raise SummaryError(f"--metric {name}: this sweep has no error metrics (its runs compared "
                               "nothing with a reference: reference.compare = true)")
        raise SummaryError(f"--metric {name}: not a metric of this sweep; it has "
                           + ", ".join(c[len("metric."):] for c in have))
    return name
