"""Ablation table: one row per configuration, best value of each metric in bold.

Rows are sorted by the speed axis's median time (fastest first, ties by name;
summary.with_speed: by default the indirect method's own stages), so the table
reads as "what each extra millisecond buys". Columns: config_name, variant,
median method ms (where the summary has it), median total ms, median
propagation ms, memory MB, then every metric.* column present. For each metric column the best value (lowest
error, or highest PSNR/SSIM) is bold; ties are all bold.
"""
import math

import pandas as pd

from . import html_table as H
from . import summary as S


def ablation_table(agg):
    """Return (DataFrame of raw values, list of metric column names) in display order."""
    def column(col):
        return agg.get(col, pd.Series([math.nan] * len(agg))).astype(float).values

    t = pd.DataFrame({"config_name": agg["config_name"].astype(str), "variant": agg["variant"].astype(str)})
    if S.time_col("method") in agg.columns:
        t["method ms"] = column(S.time_col("method"))
    t["total ms"] = column(S.TIME_COL)
    t["propagation ms"] = column(S.time_col("propagation"))
    t["memory MB"] = (agg["memory_bytes"].astype(float) / 2**20).values if "memory_bytes" in agg else math.nan
    metrics = S.metric_columns(agg)
    for m in metrics:
        t[m] = agg[m].astype(float).values
    t["_speed"] = column(S.speed_col(agg))
    t = t.sort_values(["_speed", "config_name"], na_position="last", kind="mergesort").reset_index(drop=True)
    return t.drop(columns="_speed"), metrics


def best_mask(values, higher_better):
    """Booleans marking the best finite-or-inf value(s) of a column (NaN never best)."""
    vals = [float(v) for v in values]
    cand = [v for v in vals if not math.isnan(v)]
    if not cand:
        return [False] * len(vals)
    best = max(cand) if higher_better else min(cand)
    return [(not math.isnan(v)) and v == best for v in vals]


def fmt(v):
    """Numbers with 4 significant digits; inf as 'inf'; NaN as '-'."""
    if isinstance(v, str):
        return v
    v = float(v)
    if math.isnan(v):
        return "-"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return f"{v:.4g}"


def short_metric(col):
    """'metric.indirect_vs_indirect1.rmse' -> 'indirect rmse' for headers."""
    parts = col.split(".")
    pair = parts[1].split("_vs_")[0] if len(parts) > 2 else col
    return f"{pair} {parts[-1]}"


def _cells(t, metrics):
    bold = {m: best_mask(t[m].values, S.higher_is_better(m)) for m in metrics}
    for i in range(len(t)):
        row = []
        for c in t.columns:
            s = fmt(t.iloc[i][c])
            row.append((s, c in bold and bold[c][i]))
        yield row


def to_markdown(agg):
    """Markdown ablation table (GitHub pipe syntax), best metric values in **bold**."""
    t, metrics = ablation_table(agg)
    headers = [short_metric(c) if c in metrics else c for c in t.columns]
    lines = ["| " + " | ".join(headers) + " |",
             "|" + "|".join("---" if c in ("config_name", "variant") else "---:" for c in t.columns) + "|"]
    for row in _cells(t, metrics):
        cells = [(f"**{s}**" if b else s).replace("|", "\\|") for s, b in row]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def to_html(agg):
    """The same table in HTML (html_table.py), best metric values in bold; each metric's heading
    says which way is better and shows the full column name on hover."""
    t, metrics = ablation_table(agg)
    headers = [H.header(short_metric(c) if c in metrics else c, title=c,
                                 arrow=("up" if S.higher_is_better(c) else "down") if c in metrics else "")
               for c in t.columns]
    rows = [[H.cell(s, bold=b, num=c not in ("config_name", "variant")) for (s, b), c in zip(row, t.columns)]
            for row in _cells(t, metrics)]
    return H.render(headers, rows, css_class="ablation")


def formatted_cells(t, formats, default="{:.4g}"):
    """Each row of `t` as strings: strings as they are, numbers by formats[column] (else
    `default`), NaN and None as ""."""
    out = []
    for _, r in t.iterrows():
        cells = []
        for c in t.columns:
            v = r[c]
            if isinstance(v, str):
                cells.append(v)
            else:
                missing = v is None or (isinstance(v, float) and math.isnan(v))
                cells.append("" if missing else formats.get(c, default).format(v))
        out.append(cells)
    return out


def markdown_table(title, t, formats):
    """A titled markdown table of `t` (formatted_cells)."""
    out = [title, "", "| " + " | ".join(t.columns) + " |", "|" + "---|" * len(t.columns)]
    out += ["| " + " | ".join(c) + " |" for c in formatted_cells(t, formats)]
    return "\n".join(out) + "\n"


def html_table(t, formats):
    """An HTML table of `t` (formatted_cells; html_table.py)."""
    return H.render(list(t.columns), formatted_cells(t, formats))
