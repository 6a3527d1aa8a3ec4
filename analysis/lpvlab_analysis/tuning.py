"""The page of a tune (`lpvlab tune` wrote DIR/tune.json and DIR/pareto.csv; `lpvlab report DIR`
builds DIR/report/index.html from them): error against time for every candidate at every rung,
the Pareto front of the last rung, the budget, the chosen configuration and the baseline; the
last rung's table; the held-out views (docs/tuning.md)."""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import fsutil  # noqa: E402


def is_page_of(directory):
    """Whether `directory` holds what this page shows."""
    return os.path.isfile(os.path.join(directory, "tune.json"))


def load(directory):
    return fsutil.load_json(directory, "tune.json", "rungs", "lpvlab tune")


def name_of(result, cid):
    overrides = result.get("candidates", {}).get(cid, [])
    return ", ".join(overrides) if overrides else "baseline (the file as it is)"


def pareto(points):
    """The (ms, error, id) points no other is both faster and more accurate than, by time."""
    front = []
    for p in sorted(points):
        if not front or p[1] < front[-1][1]:
            front.append(p)
    return front


def is_estimated(result):
    """Whether the tune's times are the GPU estimate (time = "gpu-estimate"), not measured."""
    return result.get("time") == "gpu-estimate"


def time_label(result):
    """The time axis: what was timed, how, and where; or that it is an estimate, and of what."""
    if is_estimated(result):
        return f"GPU-estimated method time per frame on {result.get('gpu', '?')} (ms; an estimate, not a measurement)"
    return f"median {result['time']} time per frame (ms; each run's own clock, on {result['host']['cpu']})"


def time_note(result):
    """The page's sentence on the times."""
    if is_estimated(result):
        return f"Times: {result['clock']}. The runs themselves ran on {result['host']['cpu']}"
    return f"Times: {result['clock']}, on {result['host']['cpu']}"


def figure(result):
    """Error against time: every rung's candidates (lighter for earlier rungs), the last rung's
    Pareto front, the budget, the chosen configuration and the baseline."""
    fig, ax = plt.subplots(figsize=(8, 5))
    rungs = result["rungs"]
    for i, rung in enumerate(rungs):
        xs = [r["ms"] for r in rung["results"]]
        ys = [r["error"] for r in rung["results"]]
        ax.scatter(xs, ys, s=18 + 10 * i, alpha=0.35 + 0.65 * (i + 1) / len(rungs),
                   label=f"rung {i + 1}: {rung['samples']} spp references ({len(xs)} configurations)")
    last = rungs[-1]["results"]
    front = pareto([(r["ms"], r["error"], r["id"]) for r in last])
    ax.plot([p[0] for p in front], [p[1] for p in front], "k--", linewidth=1, label="Pareto front (last rung)")
    if rungs[-1].get("budget_ms"):
        ax.axvline(rungs[-1]["budget_ms"], color="#d62728", linewidth=1, label="time budget")
    for r in last:
        if r["id"] == "baseline":
            ax.scatter([r["ms"]], [r["error"]], marker="s", s=90, facecolors="none", edgecolors="k", label="baseline")
    if result.get("chosen"):
        c = result["chosen"]
        ax.scatter([c["ms"]], [c["error"]], marker="*", s=220, color="#ff7f0e", edgecolors="k", label="chosen")
    ax.set_xlabel(time_label(result))
    ax.set_ylabel(f"{result['metric']} (lower is better)")
    ax.set_title(result["goal"], fontsize=10)
    ax.legend(fontsize=8)
    return fig


def build_page(directory, out_dir, css, js):
    """Write <out_dir>/index.html for the tune in `directory`; returns its path."""
    from . import templating
    import datetime
    result = load(directory)
    img_dir = os.path.join(out_dir, "img")
    os.makedirs(img_dir, exist_ok=True)
    plot = os.path.join(img_dir, "pareto.png")
    fig = figure(result)
    fsutil.write_with(plot, lambda tmp: fig.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
    plt.close(fig)
    last = sorted(result["rungs"][-1]["results"], key=lambda r: (not r["feasible"], r["error"], r["ms"]))
    rows = [{"id": r["id"], "error": r["error"], "ms": r["ms"], "feasible": r["feasible"],
             "name": name_of(result, r["id"])} for r in last]
    links = [(os.path.relpath(os.path.join(directory, n), out_dir), n)
             for n in ("tune.json", "pareto.csv", "chosen.toml") if os.path.isfile(os.path.join(directory, n))]
    page = templating.environment().get_template("tune.html.j2").render(
        css=css, js=js, result=result, rows=rows, time_note=time_note(result),
        time_column="GPU-estimated ms" if is_estimated(result) else f"{result['time']} ms", plot=os.path.relpath(plot, out_dir), links=links,
        chosen_name=name_of(result, result["chosen"]["id"]) if result.get("chosen") else None,
        directory=os.path.abspath(directory),
        generated=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"))
    index = os.path.join(out_dir, "index.html")
    fsutil.write_text(index, page)
    return index
