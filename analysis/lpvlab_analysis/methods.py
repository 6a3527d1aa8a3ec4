"""The indirect-light methods of a sweep side by side (issue 17, docs/methods.md).

A sweep over `[indirect] method` (LPV and the many-light methods of seed 001) gets a section of
its own: every configuration on one speed/accuracy plot, coloured by method (LPV's variants by
their strategies), and a table with each configuration's time (the report's speed axis: by
default the method's own stages, summary.with_speed), error, the ratio of its
error to the LPV baseline's at equal time (equal_time.py: interpolated between the two baseline
points around its time, never extrapolated) and what the method did (VPLs, gathered pairs, the
share of the light its clamp removed; summary.csv's method.* columns).
"""
import math
import os

import pandas as pd

from . import equal_time as ET
from . import html_table as H
from . import plots
from . import sections
from . import summary as S

METHOD_COL = S.METHOD_PARAM
FIGURES = [("method.vpls", "VPLs", "{:.0f}"),
           ("method.gathered_pairs", "gathered pairs", "{:.3g}"),
           ("method.clamp.removed_fraction", "clamp removed", "{:.2%}")]


def methods_of(agg):
    """The methods of the sweep's configurations ("lpv" where the column is missing)."""
    if METHOD_COL not in agg.columns:
        return pd.Series(["lpv"] * len(agg), index=agg.index)
    return agg[METHOD_COL].fillna("lpv").astype(str).replace({"nan": "lpv", "": "lpv"})


def has_methods(agg):
    """Whether the sweep compares another method with LPV (or methods with each other)."""
    methods = set(methods_of(agg))
    return len(methods) > 1 or methods != {"lpv"}


def by_method(agg):
    """A copy of agg whose 'variant' is the method (LPV's rows keep their strategies' label,
    without the swept extras), for a plot coloured by method."""
    out = agg.copy()
    methods = methods_of(agg)
    out["variant"] = [("LPV " + str(v).split(" ")[0]) if m == "lpv" else m
                      for m, v in zip(methods, agg["variant"])]
    return out


def table(agg, metric):
    """One row per configuration, fastest first: configuration, method, series, time ms (the speed
    axis's), error,
    equal-time error ratio against the LPV baseline (with why it is missing), and the figures;
    with several scenes a first column names each row's scene (the rows sorted by it first)."""
    compared = ET.compare(agg, metric).set_index("config_id") if metric in agg.columns else None
    # Per scene, the baseline's fastest time and its smallest and largest errors: where a
    # configuration lies outside the baseline's times, what can still be said of it.
    baselines = {}
    if compared is not None:
        for scene, g in compared[compared["baseline"]].groupby("scene"):
            baselines[str(scene)] = (g["time ms"].min(), g["time ms"].max(), g["error"].min(), g["error"].max())
    methods = methods_of(agg)
    rows = []
    for idx, r in agg.iterrows():
        cid = str(r["config_id"])
        row = {"configuration": str(r["config_name"]), "method": methods.loc[idx],
               "series": str(r.get(ET.SERIES_COL, "")),
               "time ms": float(r.get(S.speed_col(agg), math.nan)),
               "error": float(r.get(metric, math.nan)) if metric in agg.columns else math.nan,
               "equal-time ratio": math.nan, "why no ratio": ""}
        if compared is not None and cid in compared.index:
            c = compared.loc[cid]
            row["equal-time ratio"] = float(c["time ratio"])
            row["why no ratio"] = str(c["time status"]) if not bool(c["baseline"]) else "baseline"
            if row["why no ratio"] == ET.OUT_OF_RANGE:
                row["why no ratio"] = _beyond(row, baselines.get(str(c["scene"])))
        for col, name, _ in FIGURES:
            row[name] = float(r[col]) if col in agg.columns and pd.notna(r.get(col)) else math.nan
        rows.append(row)
    t = pd.DataFrame(rows)
    # Several scenes (a report of several sweeps): a column naming each row's, sorted by it first.
    if ET.SCENE_COL in agg.columns and agg[ET.SCENE_COL].nunique() > 1:
        t.insert(0, "scene", [os.path.basename(str(v)) for v in agg[ET.SCENE_COL]])
        return t.sort_values(["scene", "time ms", "configuration"], na_position="last",
                             kind="mergesort").reset_index(drop=True)
    return t.sort_values(["time ms", "configuration"], na_position="last", kind="mergesort").reset_index(drop=True)


def _beyond(row, baseline):
    """Why a configuration outside the baseline's times has no equal-time ratio, and how it
    stands against every baseline point."""
    if baseline is None or not math.isfinite(row["error"]):
        return ET.OUT_OF_RANGE
    fastest, slowest, best, worst = baseline
    faster = row["time ms"] < fastest
    side = "faster than the fastest" if faster else "slower than the slowest"
    if row["error"] < best:
        verdict = "more accurate than every"
    elif row["error"] > worst:
        verdict = "less accurate than every"
    else:
        verdict = "within the errors of the"
    return f"{side} LPV run; {verdict} LPV run"


def _cell(value, fmt="{:.4g}"):
    if isinstance(value, str):
        return value
    return "" if value is None or (isinstance(value, float) and math.isnan(value)) else fmt.format(value)


def _formatted(t):
    formats = {"time ms": "{:.1f}", "error": "{:.4g}", "equal-time ratio": "{:.3f}"}
    formats.update({name: fmt for _, name, fmt in FIGURES})
    return [[_cell(r[c], formats.get(c, "{:.4g}")) for c in t.columns] for _, r in t.iterrows()]


def to_markdown(agg, metric):
    t = table(agg, metric)
    out = [f"Methods: {metric} (time: {S.speed_words(agg)}; equal-time ratio: error / LPV baseline's "
           "error at the same time)", "",
           "| " + " | ".join(t.columns) + " |", "|" + "---|" * len(t.columns)]
    out += ["| " + " | ".join(cells) + " |" for cells in _formatted(t)]
    return "\n".join(out) + "\n"


def to_html(agg, metric):
    """The table in HTML (html_table.py); an equal-time ratio below 1 (the method wins) in bold."""
    t = table(agg, metric)
    rows = []
    for (_, r), cells in zip(t.iterrows(), _formatted(t)):
        wins = isinstance(r["equal-time ratio"], float) and r["equal-time ratio"] < 1.0
        rows.append([H.cell(s, bold=c == "equal-time ratio" and wins) for c, s in zip(t.columns, cells)])
    return H.render(list(t.columns), rows)


def _plot(agg, path, metric):
    return plots.speed_accuracy(by_method(agg), path, metric=metric)


sections.register(sections.Section(
    title="Methods", applies=has_methods, order=10, parts=[sections.Part(
        note="Every indirect-light method of the sweep on one speed/accuracy plot (coloured by method; "
             "LPV by its strategies), and each configuration's error against the LPV baseline series at "
             "equal time (ratio below 1, bold: the method beats spending that time on LPV; the time is the "
             "report's speed axis, named on the plot). Each "
             "method's images are under <i>Images per configuration</i>: the reference, the result and the "
             "error map side by side.",
        plot=_plot, html=to_html, markdown=to_markdown,
        image="methods_speed_accuracy.png", markdown_file="methods.md")]))
