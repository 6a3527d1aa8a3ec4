"""Slices through a run's light grid (`lpvlab run --dump-grid`: grid.npy and grid.json), as the
thesis shows the grid in figs. 8.9/8.10: per cell the DC term of the RGB SH coefficients, c_0 Y_00,
which is the radiant intensity averaged over all directions (W/sr), as luminance
(0.2126 R + 0.7152 G + 0.0722 B), through the middle of the finest level along each axis.
`lpvlab explain` writes the method's grid beside the exact one (exact_grid.npy, docs/explain.md):
write_pair_png draws both on one colour scale.
"""
import json
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import fsutil  # noqa: E402

Y00 = 0.5 / math.sqrt(math.pi)
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])
AXES = ("level", "channel", "coefficient", "z", "y", "x")


class GridDumpError(Exception):
    """A grid dump that cannot be read (the message names the file)."""


def load(run_dir, stem="grid"):
    """(array, description) of the run's grid dump <stem>.npy and <stem>.json, or None when the
    run has none."""
    npy, described = os.path.join(run_dir, stem + ".npy"), os.path.join(run_dir, stem + ".json")
    if not os.path.isfile(npy):
        return None
    try:
        with open(described) as f:
            description = json.load(f)
        grid = np.load(npy)
    except (OSError, ValueError) as exc:
        raise GridDumpError(f"{npy}: cannot be read ({exc})") from exc
    if tuple(description.get("axes", ())) != AXES or list(grid.shape) != description.get("shape"):
        raise GridDumpError(f"{described}: axes {description.get('axes')} and shape "
                            f"{description.get('shape')} are not the grid's {list(grid.shape)} in {AXES}")
    return grid, description


def mean_intensity(grid, level=0):
    """The level's mean radiant intensity per cell (W/sr, luminance), indexed [z, y, x]."""
    dc = grid[level, :, 0] * Y00  # [channel, z, y, x]
    return np.tensordot(LUMINANCE, dc, axes=(0, 0))


def middle_slices(grid, level=0):
    """{"x": [z, y], "y": [z, x], "z": [y, x]}: the level's mean intensity through its middle cell
    along each axis."""
    cells = mean_intensity(grid, level)
    nz, ny, nx = cells.shape
    return {"x": cells[:, :, nx // 2], "y": cells[:, ny // 2, :], "z": cells[nz // 2, :, :]}


def _draw_row(axes, slices, top):
    """One grid's three middle slices into `axes`, on the colour scale 0..top; the last image."""
    image = None
    for ax, (axis, cells), (down, across) in zip(axes, slices.items(), (("z", "y"), ("z", "x"), ("y", "x"))):
        image = ax.imshow(cells, origin="lower", cmap="magma", vmin=0.0, vmax=top if top > 0 else 1.0,
                          interpolation="nearest")
        ax.set_title(f"{axis} = middle cell", fontsize=8)
        ax.set_xlabel(f"{across} (cells)", fontsize=8)
        ax.set_ylabel(f"{down} (cells)", fontsize=8)
    return image


def _write(fig, axes, image, out_png, title):
    bar = fig.colorbar(image, ax=list(np.ravel(axes)), shrink=0.85)
    bar.set_label("mean radiant intensity c0 Y00, W/sr (luminance)", fontsize=8)
    fig.suptitle(title, fontsize=9)
    fsutil.write_with(out_png, lambda tmp: fig.savefig(tmp, dpi=100, bbox_inches="tight", format="png"))
    plt.close(fig)
    return out_png


def _describe(description):
    level = description.get("levels", [{}])[0]
    return (f"finest level (cell {level.get('cell_size_m', float('nan')):.3g} m, "
            f"SH order {description.get('sh_order', '?')})")


def write_png(run_dir, out_png):
    """The three middle slices of the finest level side by side with one colour bar; None when the
    run has no grid dump."""
    loaded = load(run_dir)
    if loaded is None:
        return None
    grid, description = loaded
    slices = middle_slices(grid)
    top = max(float(np.max(s)) for s in slices.values())
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.4), constrained_layout=True)
    image = _draw_row(axes, slices, top)
    return _write(fig, axes, image, out_png, f"light grid, {_describe(description)}, middle slices")


def write_pair_png(directory, out_png):
    """The method's grid (grid.npy, top row) and the exact grid (exact_grid.npy, bottom row), the
    middle slices of the finest level on one colour scale; None unless both are there."""
    method, exact = load(directory), load(directory, "exact_grid")
    if method is None or exact is None:
        return None
    if method[0].shape != exact[0].shape:
        raise GridDumpError(f"{directory}: grid.npy {method[0].shape} and exact_grid.npy "
                            f"{exact[0].shape} differ in shape")
    rows = [middle_slices(method[0]), middle_slices(exact[0])]
    top = max(float(np.max(s)) for row in rows for s in row.values())
    fig, axes = plt.subplots(2, 3, figsize=(11, 6.6), constrained_layout=True)
    image = None
    for row_axes, slices, name in zip(axes, rows, ("LPV's grid", "the exact grid")):
        image = _draw_row(row_axes, slices, top)
        row_axes[0].annotate(name, (0, 1.18), xycoords="axes fraction", fontsize=9, weight="bold")
    return _write(fig, axes, image, out_png,
                  f"light grids, {_describe(method[1])}, middle slices: LPV's (top), exact (bottom)")
