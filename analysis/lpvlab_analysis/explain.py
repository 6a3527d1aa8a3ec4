"""The page of an explanation (`lpvlab explain` wrote DIR/explain.json and DIR/explain.exr;
`lpvlab report DIR` builds DIR/report/index.html from them): per AOV pair, the error budget by
stage as a bar chart and a table, the chain's images (reference, LPV, exact grid, exact gathers)
at one exposure, with the oracles' noise and where the oracles ran (docs/explain.md)."""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from . import fsutil  # noqa: E402
from . import grid_slices  # noqa: E402
from . import images  # noqa: E402

# What each image of the chain is, as the page says it.
IMAGE_WORDS = {
    "method": "the method's own image (LPV, as configured)",
    "grid": "exact grid (no visibility) through LPV's rendering",
    "grid_visible": "exact grid with visibility from the cells through LPV's rendering",
    "gather": "the RSM's VPLs gathered at each pixel, no visibility",
    "gather_visible": "the RSM's VPLs gathered at each pixel with exact visibility",
}
STAGE_WORDS = {
    "propagation": "propagation (LPV's grid against the exact grid)",
    "rendering": "rendering (the grid's interpolation and normal offset)",
    "occlusion": "occlusion (the exact gather without visibility against with it)",
    "injection": "injection (the RSM's VPLs against the path tracer)",
}


def is_page_of(directory):
    """Whether `directory` holds what this page shows."""
    return os.path.isfile(os.path.join(directory, "explain.json"))


def load(directory):
    return fsutil.load_json(directory, "explain.json", "budgets", "lpvlab explain")


def _number(value):
    return float("inf") if value in ("inf", "+inf") else float(value)


def plot_terms(pair, budget, path):
    """The block nRMSE each stage's replacement removes, one bar per stage, as a PNG at `path`."""
    fig = terms_figure(pair, budget)
    fsutil.write_with(path, lambda tmp: fig.savefig(tmp, dpi=110, bbox_inches="tight", format="png"))
    plt.close(fig)
    return path


def terms_figure(pair, budget):
    """plot_terms's figure: a bar per stage, each labelled with its brightness factor."""
    terms = budget["terms"]
    names = [t["stage"] for t in terms]
    removed = [_number(t["block_nrmse_reduction"]) for t in terms]
    fig, ax = plt.subplots(figsize=(7.5, 0.5 * len(terms) + 1.6))
    colours = ["#d62728" if r > 0 else "#2ca02c" for r in removed]
    ax.barh(names[::-1], removed[::-1], color=colours[::-1])
    for y, (r, t) in enumerate(zip(removed[::-1], terms[::-1])):
        ax.annotate(f"{r:.3f}  (brightness x{t['brightness_factor']:.2f})", (max(r, 0), y),
                    xytext=(4, 0), textcoords="offset points", va="center", fontsize=8)
    ax.axvline(0, color="#444", linewidth=0.8)
    ax.set_xlabel("block nRMSE removed (8x8-pixel blocks over the reference mean; unitless)")
    ax.set_ylabel("stage replaced by its exact counterpart")
    ax.set_title(f"{pair}: total block nRMSE {_number(budget['total']['block_nrmse']):.3f}, "
                 f"mean {budget['total']['mean_ratio']:.2f} x the reference", fontsize=10)
    ax.set_xlim(min(0.0, min(removed) * 1.1), max(max(removed), 1e-6) * 1.6)
    return fig


def images_of(directory, budget, reference_aov, img_dir):
    """The chain's images as PNGs at the reference's exposure: [(file, caption)] (empty without
    OpenImageIO or the EXR)."""
    exr = os.path.join(directory, "explain.exr")
    reference = images.read_aov(exr, "reference_" + reference_aov)
    if reference is None:
        return []
    scale = images.exposure_scale(reference)
    out = []
    for name in ["reference_" + reference_aov] + list(budget["chain"]):
        pixels = reference if name.startswith("reference_") else images.read_aov(exr, name)
        if pixels is None:
            continue
        path = os.path.join(img_dir, f"{name}.png")
        images.write_png(path, images.tonemap(pixels, scale))
        words = "the path-traced reference" if name.startswith("reference_") else IMAGE_WORDS.get(name, name)
        out.append((path, f"{name}: {words}"))
    return out


def _table(budget):
    """The chain's images and the stages' terms as two HTML tables (sortable like the report's)."""
    from . import templating
    return templating.render("explain_tables.html.j2", budget=budget, image_words=IMAGE_WORDS,
                             stage_words=STAGE_WORDS, number=_number)


def build_page(directory, out_dir, css, js):
    """Write <out_dir>/index.html for the explanation in `directory`; returns its path."""
    from . import templating
    import datetime
    result = load(directory)
    img_dir = os.path.join(out_dir, "img")
    os.makedirs(img_dir, exist_ok=True)
    pairs = []
    for pair, budget in result["budgets"].items():
        reference_aov = pair.split("_vs_", 1)[1]
        plot = plot_terms(pair, budget, os.path.join(img_dir, f"budget_{pair}.png"))
        shown = [(os.path.relpath(p, out_dir), c) for p, c in images_of(directory, budget, reference_aov, img_dir)]
        # A click on an image of the chain shows the reference in its place (the page's script).
        figures = [{"src": src, "caption": caption,
                    "flip": {"src": shown[0][0], "caption": shown[0][1]} if i > 0 else None}
                   for i, (src, caption) in enumerate(shown)]
        pairs.append({"name": pair, "plot": os.path.relpath(plot, out_dir), "tables": _table(budget),
                      "figures": figures, "leakage": budget["leakage_factor"],
                      "reference_noise": budget.get("reference_noise_block_nrmse")})
    links = [(os.path.relpath(os.path.join(directory, n), out_dir), n)
             for n in ("explain.json", "explain.exr", "grid.npy", "exact_grid.npy")
             if os.path.isfile(os.path.join(directory, n))]
    grids = grid_slices.write_pair_png(directory, os.path.join(img_dir, "grids.png"))
    page = templating.environment().get_template("explain.html.j2").render(
        css=css, js=js, result=result, pairs=pairs, links=links, directory=os.path.abspath(directory),
        grids=os.path.relpath(grids, out_dir) if grids else None,
        generated=datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"))
    index = os.path.join(out_dir, "index.html")
    fsutil.write_text(index, page)
    return index
