"""Each configuration of a sweep against the standard method, at equal settings and at equal time.

A sweep marks its baseline series with the top-level experiment key `series = "baseline"`
(swept, so summary.csv has a param.series column): the standard method with nothing else
changed, at several grid resolutions. Every other configuration is compared with

  * equal settings: the baseline configuration at the same grid.resolution (the ratio
    error / baseline error says what the extension changes, whatever it costs);
  * equal time: the baseline's error at the configuration's time (the report's speed axis: by
    default the indirect method's own stages, summary.S.with_speed), interpolated
    linearly in (log time, log error) between the two baseline points bracketing that time
    (the baseline sorted by time). A time outside the baseline's range is "out of range" and
    gets no value: extrapolating a power law past its last point would be a guess. A ratio
    below 1 means the extension beats simply spending its time on a finer standard grid.

Baselines are per scene (param.scene.file when present), so a sweep over several scenes compares
each configuration with its own scene's series, and per clock (the speed axis's: GL timer queries
or the CPU's wall clock), so a time taken on one backend is never compared with another's. Baseline points without a finite positive time
and error cannot be placed on log axes and are left out of the series.
"""
import bisect
import math

import pandas as pd

from . import summary as S

SERIES_COL = "param.series"
BASELINE = "baseline"
RESOLUTION_COL = "param.grid.resolution"
SCENE_COL = "param.scene.file"
METRIC_NAMES = ("rmse", "flip")
OUT_OF_RANGE = "out of range"


def is_baseline(agg):
    """Boolean Series: the configurations of the baseline series."""
    if SERIES_COL not in agg.columns:
        return pd.Series([False] * len(agg), index=agg.index)
    return agg[SERIES_COL].astype(str) == BASELINE


def _usable(t, e):
    return all(isinstance(v, (int, float)) and math.isfinite(v) and v > 0 for v in (t, e))


def baseline_points(times, errors):
    """(time, error) pairs usable on log axes, sorted by time (then error)."""
    pts = [(float(t), float(e)) for t, e in zip(times, errors)]
    return sorted(p for p in pts if _usable(*p))


def error_at_time(points, t):
    """(error, status) of a baseline series at time t.

    points: sorted (time, error) pairs from baseline_points. status is "" for a value,
    OUT_OF_RANGE when t lies outside [first time, last time] (also for an empty series),
    "no time" when t is not a finite positive number. A t equal to a point's time takes
    that point's error (the first such point when several share the time).
    """
    t = float(t)
    if not (math.isfinite(t) and t > 0):
        return math.nan, "no time"
    if not points or t < points[0][0] or t > points[-1][0]:
        return math.nan, OUT_OF_RANGE
    times = [p[0] for p in points]
    i = bisect.bisect_left(times, t)
    if times[i] == t:
        return points[i][1], ""
    (ta, ea), (tb, eb) = points[i - 1], points[i]  # ta < t < tb: t is inside and no point's time
    w = (math.log(t) - math.log(ta)) / (math.log(tb) - math.log(ta))
    return math.exp(math.log(ea) + w * (math.log(eb) - math.log(ea))), ""


def _name(row):
    series = row.get(SERIES_COL, "")
    series = "" if series is None or (isinstance(series, float) and math.isnan(series)) else str(series)
    if series in ("", "nan"):
        return str(row["config_name"])
    return f"{series} {row[RESOLUTION_COL]:g}" if series == BASELINE and RESOLUTION_COL in row else series


def _ratio(a, b):
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b) or b == 0:
        return math.nan
    return a / b


def _groups(agg):
    """(scene, rows) per scene and clock of the speed axis: baselines never cross either."""
    keys = []
    if SCENE_COL in agg.columns:
        keys.append(agg[SCENE_COL].astype(str))
    clock = S.speed_clock_col(agg)
    if clock:
        keys.append(agg[clock].fillna("").astype(str))
    if not keys:
        return [("", agg)]
    scenes = agg[SCENE_COL].astype(str) if SCENE_COL in agg.columns else pd.Series([""] * len(agg), index=agg.index)
    return [(scenes.loc[g.index[0]], g) for _, g in agg.groupby(keys, sort=False)]


def compare(agg, metric):
    """One row per configuration (baseline ones included, their ratios at equal settings are 1):

    scene, config_id, config_name, name (the series label, else config_name), baseline (bool),
    resolution, time ms (the speed axis's, summary.speed_col), propagation ms, error,
    settings error (the baseline's at the same resolution; NaN when the series lacks it),
    settings ratio, time error (the baseline's at equal time), time ratio, time status
    ("" or why there is no value). Empty DataFrame when the metric or time column is absent.
    """
    cols = ["scene", "config_id", "config_name", "name", "baseline", "resolution", "time ms", "propagation ms",
            "error", "settings error", "settings ratio", "time error", "time ratio", "time status"]
    time_col = S.speed_col(agg)
    if metric not in agg.columns or time_col not in agg.columns:
        return pd.DataFrame(columns=cols)
    base_mask = is_baseline(agg)
    rows = []
    for scene, g in _groups(agg):
        base = g[base_mask.loc[g.index]]
        points = baseline_points(base[time_col].astype(float), base[metric].astype(float))
        by_res = {}
        if RESOLUTION_COL in base.columns:
            for _, b in base.iterrows():
                by_res.setdefault(b[RESOLUTION_COL], float(b[metric]))
        for idx, r in g.iterrows():
            err = float(r[metric])
            res = r[RESOLUTION_COL] if RESOLUTION_COL in g.columns else math.nan
            s_err = by_res.get(res, math.nan)
            if base.empty:
                t_err, status = math.nan, "no baseline"
            else:
                t_err, status = error_at_time(points, r[time_col])
            rows.append({
                "scene": scene, "config_id": str(r["config_id"]), "config_name": str(r["config_name"]),
                "name": _name(r),
                "baseline": bool(base_mask.loc[idx]), "resolution": res,
                "time ms": float(r[time_col]),
                "propagation ms": float(r.get(S.time_col("propagation"), math.nan)),
                "error": err, "settings error": s_err, "settings ratio": _ratio(err, s_err),
                "time error": t_err, "time ratio": _ratio(err, t_err), "time status": status})
    return pd.DataFrame(rows, columns=cols)


def metrics_present(agg):
    """RMSE and FLIP of every pair comparing the LPV's indirect light: indirect_vs_indirect1 (what
    one LPV bounce approximates) first, then e.g. indirect_vs_indirect (all bounces) or
    indirect_vs_direct (sky light, which the reference has as direct light)."""
    pairs = sorted({c.split(".")[1] for c in agg.columns
                    if c.startswith("metric.indirect_vs_") and c.count(".") == 2},
                   key=lambda p: (p != "indirect_vs_indirect1", p))
    return [f"metric.{p}.{m}" for p in pairs for m in METRIC_NAMES if f"metric.{p}.{m}" in agg.columns]


def to_markdown(agg):
    """Markdown tables, one per metric of metrics_present: every configuration with its error at
    equal settings and at equal time (baseline rows first, then by time)."""
    from .tables import fmt
    out = []
    for m, t in _comparisons(agg):
        out.append(f"### {_title(m)}\n")
        out.append("| scene | configuration | baseline | res | time ms | propagation ms | error | "
                   "baseline error, equal settings | ratio | baseline error, equal time | ratio |")
        out.append("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        for _, r in t.iterrows():
            time_err = r["time status"] or fmt(r["time error"])
            cells = [r["scene"], r["config_name"], "yes" if r["baseline"] else "", fmt(r["resolution"]),
                     fmt(r["time ms"]), fmt(r["propagation ms"]), fmt(r["error"]), fmt(r["settings error"]),
                     fmt(r["settings ratio"]), time_err, fmt(r["time ratio"])]
            out.append("| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |")
        out.append("")
    return "\n".join(out)


def compact_markdown(agg):
    """One table per scene with every metric of metrics_present side by side, configurations
    named by their series label (baseline rows first, then by time): for each metric the
    error, the ratio at equal settings, the baseline's error at equal time and the ratio."""
    from .tables import fmt
    metrics = metrics_present(agg)
    tables = {m: compare(agg, m) for m in metrics}
    tables = {m: t for m, t in tables.items() if not t.empty}
    if not tables:
        return ""
    first = _ordered(next(iter(tables.values())))
    out = []
    for scene, g in first.groupby("scene", sort=False):
        head = ["configuration", "res", "time ms", "propagation ms"]
        for m in tables:
            short = f"{S.metric_name(m).upper()} {m.split('.')[1].split('_vs_')[1]}"
            head += [short, "ratio, equal settings", "baseline, equal time", "ratio, equal time"]
        if scene:
            out.append(f"Scene `{scene}`:\n")
        out.append("| " + " | ".join(head) + " |")
        out.append("|---|" + "---:|" * (len(head) - 1))
        for idx, r in g.iterrows():
            cells = [r["name"], fmt(r["resolution"]), fmt(r["time ms"]), fmt(r["propagation ms"])]
            for t in tables.values():
                q = t.loc[idx]
                cells += [fmt(q["error"]), fmt(q["settings ratio"]), q["time status"] or fmt(q["time error"]),
                          fmt(q["time ratio"])]
            out.append("| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |")
        out.append("")
    return "\n".join(out)


def _title(metric):
    """'metric.indirect_vs_indirect1.rmse' -> 'RMSE of indirect vs indirect1'."""
    return f"{S.metric_name(metric).upper()} of {metric.split('.')[1].replace('_vs_', ' vs ')}"


def _ordered(t):
    return t.sort_values(["scene", "baseline", "time ms"], ascending=[True, False, True], kind="mergesort")


def _comparisons(agg):
    """(metric, its comparison table in row order) for every metric that has one."""
    for m in metrics_present(agg):
        t = compare(agg, m)
        if not t.empty:
            yield m, _ordered(t)


_HTML_HEADERS = ["scene", "configuration", "baseline", "res", "time ms", "propagation ms", "error",
                 "baseline error, equal settings", "ratio", "baseline error, equal time", "ratio"]


def to_html(agg):
    """The same tables in HTML (html_table.py), one per metric under its title; ratios below 1 in
    bold (the configuration wins)."""
    from . import html_table as H
    from . import templating
    from .tables import fmt

    def num(v, bold=False):
        return H.cell(fmt(v), bold=bold, num=True)

    sections = []
    for m, t in _comparisons(agg):
        rows = []
        for _, r in t.iterrows():
            tr, sr = r["time ratio"], r["settings ratio"]
            time_err = H.cell(r["time status"], num=True) if r["time status"] else num(r["time error"])
            rows.append([r["scene"], r["config_name"], "yes" if r["baseline"] else "", num(r["resolution"]),
                         num(r["time ms"]), num(r["propagation ms"]), num(r["error"]), num(r["settings error"]),
                         num(sr, not math.isnan(sr) and sr < 1), time_err, num(tr, not math.isnan(tr) and tr < 1)])
        sections.append({"title": _title(m), "table": H.render(_HTML_HEADERS, rows, css_class="equal_time")})
    return templating.render("titled_tables.html.j2", sections=sections)
