"""An estimate of each stage's time on a named GPU, from lpvlab's cost counters. An estimate,
not a measurement: the report labels it as one.

The counters are the GL kernels' (the summary's gpu_work.<stage>.multiply_adds and .bytes:
what a GPU would run, whatever backend the sweep ran on). A stage's estimate is the roofline
bound of its kernels,

    t = max(multiply_adds / fma_per_s, bytes / bytes_per_s),

with the GPU's peak rates from gpus.toml. What it leaves out, so how to read it:
  - the peak multiply-add rate is never reached (occupancy, divergence, the SH evaluations per
    face the counters leave out): the arithmetic term is optimistic;
  - the counted bytes are every read and write a kernel makes, including the neighbours' reads
    that a GPU's caches serve: the memory term is pessimistic where data are re-read;
  - launch and synchronisation costs (one dispatch per propagation step and cascade level) and
    the CPU's overhead are not in it; the thesis's times include them (glFinish and the
    performance counter: about 1-2 ms a frame, thesis 8.1.1).
The raster passes (shadow maps, RSM, G-buffer) have no counted arithmetic (it is the
rasteriser's): no estimate.

thesis_comparison() sets the estimate beside the thesis's measured tables 8.3-8.7 on the GPUs it
ran on (R9 Fury and GTX 960), at the thesis's configuration (a 32^3 grid in four cascade levels,
one RSM tile of the given side per level) with the per-unit counts of the sweep's own rows.
"""
import math
import os
import tomllib

import pandas as pd

from . import thesis_tables as T

DEFAULT_TABLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gpus.toml")
PREFIX = "gpu_estimate_ms."


class GpuTableError(Exception):
    """A malformed GPU table: the message names the file, the GPU and the key."""


class Gpu:
    def __init__(self, key, name, fma_per_s, bytes_per_s, thesis_setup=None):
        self.key, self.name = key, name
        self.fma_per_s, self.bytes_per_s = fma_per_s, bytes_per_s
        self.thesis_setup = thesis_setup


def load_gpus(path=DEFAULT_TABLE):
    """The GPUs of a gpus.toml, in file order."""
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except OSError as exc:
        raise GpuTableError(f"{path}: cannot read the GPU table ({exc.strerror})") from exc
    except tomllib.TOMLDecodeError as exc:
        raise GpuTableError(f"{path}: not valid TOML ({exc})") from exc
    gpus = []
    for key, entry in data.items():
        if not isinstance(entry, dict):
            raise GpuTableError(f"{path}: '{key}' is not a table of a GPU")
        for field in ("name", "fma_per_s", "bytes_per_s"):
            if field not in entry:
                raise GpuTableError(f"{path}: [{key}] has no '{field}'")
        for field in ("fma_per_s", "bytes_per_s"):
            v = entry[field]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
                raise GpuTableError(f"{path}: [{key}] {field} = {v!r} is not a positive number")
        gpus.append(Gpu(key, str(entry["name"]), float(entry["fma_per_s"]), float(entry["bytes_per_s"]),
                        entry.get("thesis_setup")))
    if not gpus:
        raise GpuTableError(f"{path}: no GPUs")
    return gpus


def stage_ms(multiply_adds, bytes_, gpu):
    """The roofline bound (ms) of a stage's counted work on `gpu`; NaN without counts."""
    terms = []
    if multiply_adds is not None and not math.isnan(multiply_adds):
        terms.append(multiply_adds / gpu.fma_per_s)
    if bytes_ is not None and not math.isnan(bytes_):
        terms.append(bytes_ / gpu.bytes_per_s)
    return 1e3 * max(terms) if terms else math.nan


def counted_stages(df):
    """Stages with GL-kernel counts in a summary (gpu_work.<stage>.multiply_adds or .bytes)."""
    stages = []
    for c in df.columns:
        if c.startswith("gpu_work.") and c.endswith((".multiply_adds", ".bytes")):
            stage = c[len("gpu_work."):].rsplit(".", 1)[0]
            if stage not in stages:
                stages.append(stage)
    return stages


def _column(df, name):
    return df[name].astype(float) if name in df.columns else pd.Series([math.nan] * len(df), index=df.index)


def with_estimates(df, gpus):
    """df with a gpu_estimate_ms.<gpu>.<stage> column per GPU and counted stage, and
    gpu_estimate_ms.<gpu>.total (their sum: the stages with counts only)."""
    out = df.copy()
    stages = counted_stages(df)
    for gpu in gpus:
        total = pd.Series([0.0] * len(df), index=df.index)
        for stage in stages:
            madds = _column(df, f"gpu_work.{stage}.multiply_adds")
            nbytes = _column(df, f"gpu_work.{stage}.bytes")
            ms = pd.Series([stage_ms(m, b, gpu) for m, b in zip(madds, nbytes)], index=df.index)
            out[f"{PREFIX}{gpu.key}.{stage}"] = ms
            total = total + ms.fillna(0.0)
        out[f"{PREFIX}{gpu.key}.total"] = total
    return out


# ---- against the thesis ------------------------------------------------------------------------

THESIS_GRID_CELLS = 32 ** 3
THESIS_LEVELS = 4

# Per thesis table: the stage, its unit, the units at x (per frame, every cascade level), and
# the thesis column of each setup to compare (the compute-shader kernels, as lpvlab's).
_THESIS_UNITS = {
    "injection": ("VPLs", lambda side: THESIS_LEVELS * side * side),
    "propagation": ("cell-iterations", lambda iterations: THESIS_LEVELS * THESIS_GRID_CELLS * iterations),
}


def _thesis_column(table, setup, method):
    if table.stage == "injection":
        return f"{setup} CS"
    return f"{setup} CS {method}"


def thesis_comparison(agg, gpus):
    """Rows (dict) comparing the estimate with the thesis's measured times: per applicable table
    (8.3-8.7), lpvlab variant (and method) and thesis GPU, the per-x thesis ms, estimate ms and
    their ratio, and the per-step slopes (propagation: (t(64) - t(1)) / 63; injection: between
    the largest two RSM sides), which leave the fixed costs out."""
    rows = []
    thesis_gpus = [g for g in gpus if g.thesis_setup]
    for table, matching in T.applicable_tables(agg):
        if table.stage not in _THESIS_UNITS:
            continue
        unit, units_at = _THESIS_UNITS[table.stage]
        units_col = f"gpu_work.{table.stage}.{unit}"
        if units_col not in matching.columns:
            continue
        # Propagation: per lpvlab variant and method (the thesis's gather and scatter columns);
        # injection: per injection strategy (its counts depend on nothing else).
        if table.stage == "propagation":
            methods = (matching["param.propagation.method"].astype(str)
                       if "param.propagation.method" in matching.columns
                       else pd.Series(["gather"] * len(matching), index=matching.index))
            keys = [matching["variant"], methods]
        else:
            injection = (matching["param.injection.type"].astype(str)
                         if "param.injection.type" in matching.columns
                         else pd.Series(["injection"] * len(matching), index=matching.index))
            keys = [injection, pd.Series([""] * len(matching), index=matching.index)]
        for (variant, method), group in matching.groupby(keys, sort=True):
            units = _column(group, units_col)
            madds = _column(group, f"gpu_work.{table.stage}.multiply_adds") / units
            nbytes = _column(group, f"gpu_work.{table.stage}.bytes") / units
            ok = units > 0
            if not ok.any():
                continue
            # Per unit: the GL kernels' counts are linear in units, so any row's ratio is the figure.
            per_madd, per_byte = float(madds[ok].median()), float(nbytes[ok].median())
            for gpu in thesis_gpus:
                column = _thesis_column(table, gpu.thesis_setup, method)
                if column not in table.columns:
                    continue
                measured = table.columns[column]
                estimate = [stage_ms(per_madd * units_at(x), per_byte * units_at(x), gpu) for x in table.x]
                if table.stage == "propagation":
                    i0, i1 = table.x.index(1), len(table.x) - 1
                else:
                    i0, i1 = len(table.x) - 2, len(table.x) - 1
                span = table.x[i1] - table.x[i0] if table.stage == "propagation" else 1
                rows.append({
                    "table": table.number, "variant": str(variant), "method": method, "gpu": gpu.name,
                    "thesis_column": column, "x_label": table.x_label, "x": list(table.x),
                    "thesis_ms": list(measured), "estimate_ms": estimate,
                    "ratio": [m / e if e > 0 else math.nan for m, e in zip(measured, estimate)],
                    "thesis_slope_ms": (measured[i1] - measured[i0]) / span,
                    "estimate_slope_ms": (estimate[i1] - estimate[i0]) / span,
                })
    return rows
