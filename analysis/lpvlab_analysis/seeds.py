"""Is a stochastic method's image mean unbiased? (issue 41; docs/experiments.md#bias-over-seeds)

Configurations that differ only in a swept seed (a parameter named `seed` or ending in `.seed`)
are independent draws of one estimator. A group's draws are the ratios r_k of the run's image
mean to the reference's (metric.<pair>.ratio_of_means, every pixel and channel), and the test
is whether their expectation is 1:

    z = (mean r_k - 1) / sqrt(s^2 / K + e^2)

with K the draws, s their sample standard deviation, and e the reference mean's relative
standard error (metric.<pair>.mean_reference_relative_standard_error), since every draw shares
the same reference. The verdict is at the 1% level, two-sided (|z| < 2.576). s is estimated from
the draws, so with few of them (under about 16) the test rejects more often than 1%.

A heavy-tailed estimator (instant radiosity's VPLs near a surface) has a median well below its
mean: most draws are low and a few are very high. One run then looks biased when it is not. The
table gives both, and the plot shows every draw. Where the tail is so heavy that the variance is
infinite (unclamped VPLs in a corner: G grows as 1/d^2), s understates the spread and the test
rejects too often; "largest share" (the largest draw over their sum; 1/K for equal draws) shows
how much one draw decides the mean.
"""
import math

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from . import plots  # noqa: E402
from . import sections  # noqa: E402
from . import summary as S  # noqa: E402
from . import tables  # noqa: E402

Z_1_PERCENT = 2.5758  # two-sided 1% critical value of the standard normal
RATIO, REFERENCE_ERROR = "ratio_of_means", "mean_reference_relative_standard_error"


def seed_params(agg):
    return [p for p in S.swept_params(agg) if p == "param.seed" or p.endswith(".seed")]


def _pair(agg, metric):
    """The output pair of `metric` (metric.<pair>.<name>) whose ratio of means the sweep has."""
    pair = metric.split(".")[1] if metric and metric.count(".") >= 2 else "indirect_vs_indirect1"
    return pair if f"metric.{pair}.{RATIO}" in agg.columns else None


def groups(agg, metric):
    """One row per group of configurations that differ only in their seeds (at least 2 of them):
    the other swept parameters' values, the draws and the test."""
    seeds, pair = seed_params(agg), _pair(agg, metric)
    if not seeds or pair is None:
        return pd.DataFrame()
    others = [p for p in S.swept_params(agg) if p not in seeds]
    ratio, error = f"metric.{pair}.{RATIO}", f"metric.{pair}.{REFERENCE_ERROR}"
    rows = []
    keyed = S.ordered_by_swept(agg)
    # Grouped by the other swept parameters' values (a tuple per group, whatever their number).
    keys = keyed[others].apply(tuple, axis=1) if others else pd.Series([()] * len(keyed), index=keyed.index)
    for key in dict.fromkeys(keys):
        g = keyed[keys.map(lambda k, key=key: k == key)]
        draws = g[ratio].astype(float).dropna().values
        if len(draws) < 2:
            continue
        reference = float(np.nanmean(g[error].astype(float))) if error in g.columns else 0.0
        mean, sd = float(np.mean(draws)), float(np.std(draws, ddof=1))
        spread = math.sqrt(sd * sd / len(draws) + reference * reference)
        z = (mean - 1.0) / spread if spread > 0 else (0.0 if mean == 1.0 else math.inf)
        row = {plots._pname(p): v for p, v in zip(others, key)}
        row.update({"pair": pair, "draws": len(draws), "mean ratio": mean,
                    "median ratio": float(np.median(draws)), "lowest": float(np.min(draws)),
                    "highest": float(np.max(draws)),
                    "largest share": float(np.max(draws) / np.sum(draws)) if np.sum(draws) > 0 else 0.0,
                    "standard error": spread, "z": z,
                    "unbiased at 1%": "yes" if abs(z) < Z_1_PERCENT else "no (biased)",
                    "_draws": draws})
        rows.append(row)
    return pd.DataFrame(rows)


def has_groups(agg):
    metric = S.resolve_metric(agg, S.DEFAULT_METRIC, required=False) if len(agg) else None
    return len(groups(agg, metric or S.DEFAULT_METRIC)) > 0


def _shown(agg, metric):
    t = groups(agg, metric)
    return t.drop(columns=["_draws"]) if len(t) else t


_FORMATS = {"draws": "{:.0f}", "mean ratio": "{:.4f}", "median ratio": "{:.4f}", "lowest": "{:.3f}",
            "highest": "{:.3f}", "largest share": "{:.3f}", "standard error": "{:.4f}", "z": "{:+.2f}"}


def to_markdown(agg, metric):
    return tables.markdown_table("Bias over seeds: the run's image mean over the reference's, per group "
                                 "of seeds", _shown(agg, metric), _FORMATS)


def to_html(agg, metric):
    return tables.html_table(_shown(agg, metric), _FORMATS)


def plot(agg, path, metric):
    """Each group's draws (grey), their mean with its 99% interval (z = 2.576) and their median,
    against the first other swept parameter (log scale when it spans a factor of 8), with the
    reference's own 99% band about 1."""
    t = groups(agg, metric)
    if not len(t):
        return None
    others = [plots._pname(p) for p in S.swept_params(agg) if p not in seed_params(agg)]
    numeric = len(others) == 1 and pd.api.types.is_numeric_dtype(t[others[0]])
    xs = t[others[0]].astype(float).values if numeric else np.arange(len(t), dtype=float)
    # The axis shows the means' intervals and the bulk of the draws; a heavy tail's few far draws
    # are drawn at the top edge as triangles, their number beside them.
    top = max(2.0, 1.3 * float(np.max(t["mean ratio"] + Z_1_PERCENT * t["standard error"])))
    fig, ax = plt.subplots(figsize=(8, 4.8))
    for x, draws in zip(xs, t["_draws"]):
        inside = draws[draws <= top]
        ax.scatter(np.full(len(inside), x), inside, s=10, color="grey", alpha=0.5, zorder=1)
        if len(inside) < len(draws):
            ax.scatter([x], [top * 0.98], marker="^", color="grey", zorder=1)
            ax.annotate(f"{len(draws) - len(inside)} above (to {np.max(draws):.3g})", (x, top * 0.98),
                        textcoords="offset points", xytext=(6, -3), fontsize=7, color="dimgrey")
    ax.set_ylim(0.0, top)
    ax.errorbar(xs, t["mean ratio"], yerr=Z_1_PERCENT * t["standard error"], fmt="o-", color="C0",
                capsize=4, zorder=3, label="mean of the draws, 99% interval")
    ax.plot(xs, t["median ratio"], "s--", color="C1", zorder=2, label="median of the draws")
    ax.axhline(1.0, color="black", lw=1, label="the reference (ratio 1)")
    ax.set_ylabel(f"image mean / the reference's ({t['pair'].iloc[0]}; 1 is unbiased)", fontsize=8)
    if numeric:
        if xs.max() >= 8 * xs.min() > 0:
            ax.set_xscale("log")
        ax.set_xlabel(others[0], fontsize=8)
    else:
        ax.set_xticks(xs)
        ax.set_xticklabels([", ".join(f"{o}={r[o]}" for o in others) or "all seeds"
                            for _, r in t.iterrows()], fontsize=7, rotation=20)
        ax.set_xlabel("group of configurations (the swept parameters other than the seed)", fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    return plots._save(fig, path)


sections.register(sections.Section(
    title="Bias over seeds", applies=has_groups, order=16, parts=[sections.Part(
        note="Configurations that differ only in a swept seed are independent draws of one estimator. Each "
             "draw is the run's image mean over the reference's; their mean is tested against 1 (a z-test "
             "with the draws' spread and the reference mean's own standard error, 1% two-sided). A median "
             "far below the mean is a heavy tail: most draws low, a few very high "
             "(docs/experiments.md#bias-over-seeds).",
        plot=plot, html=to_html, markdown=to_markdown,
        image="bias_over_seeds.png", markdown_file="bias_over_seeds.md")]))
