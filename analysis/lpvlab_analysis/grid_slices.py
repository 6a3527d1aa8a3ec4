"""Slices through a run's light grid (`lpvlab run --dump-grid`: grid.npy and grid.json), as the
thesis shows the grid in figs. 8.9/8.10: per cell the DC term of the RGB SH coefficients, c_0 Y_00,
which is the radiant intensity averaged over all directions (W/sr), as luminance
(0.2126 R + 0.7152 G + 0.0722 B), through the middle of the finest level along each axis.
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


def load(run_dir):
    """(array, description) of the run's grid dump, or None when the run has none."""
    npy, described = os.path.join(run_dir, "grid.npy"), os.path.join(run_dir, "grid.json")
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
    for ax, (axis, cells), (down, across) in zip(axes, slices.items(), (("z", "y"), ("z", "x"), ("y", "x"))):
        image = ax.imshow(cells, origin="lower", cmap="magma", vmin=0.0, vmax=top if top > 0 else 1.0,
                          interpolation="nearest")
        ax.set_title(f"{axis} = middle cell", fontsize=8)
        ax.set_xlabel(f"{across} (cells)", fontsize=8)
        ax.set_ylabel(f"{down} (cells)", fontsize=8)
    bar = fig.colorbar(image, ax=list(axes), shrink=0.85)
    bar.set_label("mean radiant intensity c0 Y00, W/sr (luminance)", fontsize=8)
    level = description.get("levels", [{}])[0]
    fig.suptitle(f"light grid, finest level (cell {level.get('cell_size_m', float('nan')):.3g} m, "
                 f"SH order {description.get('sh_order', '?')}), middle slices", fontsize=9)
    fsutil.write_with(out_png, lambda tmp: fig.savefig(tmp, dpi=100, bbox_inches="tight", format="png"))
    plt.close(fig)
    return out_png
