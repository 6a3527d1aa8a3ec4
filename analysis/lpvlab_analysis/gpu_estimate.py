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

The calibrated estimate divides that bound by the efficiency a GPU's kernels were measured to
reach (gpus.toml's [[<gpu>.measured]]: measured units per second over the roofline's, for the
measured configuration's counts). A stage's efficiency is the median over the measurements of its
kernel family at the row's SH order (all orders where none matches), with their minimum and
maximum as its range; a GPU with no measurements borrows those of `calibrate_like`, else takes
the range over every measured GPU of the family. What the calibration assumes: that a kernel's
efficiency carries over from the measured configuration to the estimated one (another grid, the
GV, another variant of the family), which the spread between the measured grids bounds only
roughly: read the range, not the middle.

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


class Measured:
    """One measured throughput of a kernel family on a GPU, with the counts of what was measured."""

    def __init__(self, family, sh_order, units_per_s, multiply_adds_per_unit, bytes_per_unit, source):
        self.family, self.sh_order, self.units_per_s = family, sh_order, units_per_s
        self.multiply_adds_per_unit, self.bytes_per_unit = multiply_adds_per_unit, bytes_per_unit
        self.source = source


class Gpu:
    def __init__(self, key, name, fma_per_s, bytes_per_s, thesis_setup=None, measured=(),
                 calibrate_like=None):
        self.key, self.name = key, name
        self.fma_per_s, self.bytes_per_s = fma_per_s, bytes_per_s
        self.thesis_setup = thesis_setup
        self.measured = list(measured)
        self.calibrate_like = calibrate_like

    def efficiency_of(self, m):
        """Measured units per second over the roofline's for the measured counts."""
        roofline_s = max(m.multiply_adds_per_unit / self.fma_per_s, m.bytes_per_unit / self.bytes_per_s)
        return m.units_per_s * roofline_s


def _positive(path, key, field, v):
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
        raise GpuTableError(f"{path}: [{key}] {field} = {v!r} is not a positive number")
    return float(v)


def _measured(path, key, entries):
    if not isinstance(entries, list):
        raise GpuTableError(f"{path}: [{key}] measured must be an array of tables ([[{key}.measured]])")
    out = []
    for i, e in enumerate(entries):
        where = f"{key}.measured[{i}]"
        if not isinstance(e, dict):
            raise GpuTableError(f"{path}: [{where}] is not a table")
        for field in ("family", "sh_order", "units_per_s", "multiply_adds_per_unit", "bytes_per_unit", "source"):
            if field not in e:
                raise GpuTableError(f"{path}: [{where}] has no '{field}'")
        out.append(Measured(str(e["family"]), int(e["sh_order"]),
                            _positive(path, where, "units_per_s", e["units_per_s"]),
                            _positive(path, where, "multiply_adds_per_unit", e["multiply_adds_per_unit"]),
                            _positive(path, where, "bytes_per_unit", e["bytes_per_unit"]),
                            str(e["source"])))
    return out


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
        gpus.append(Gpu(key, str(entry["name"]), _positive(path, key, "fma_per_s", entry["fma_per_s"]),
                        _positive(path, key, "bytes_per_s", entry["bytes_per_s"]),
                        entry.get("thesis_setup"), _measured(path, key, entry.get("measured", [])),
                        entry.get("calibrate_like")))
    if not gpus:
        raise GpuTableError(f"{path}: no GPUs")
    keys = {g.key for g in gpus}
    for g in gpus:
        if g.calibrate_like is not None and g.calibrate_like not in keys:
            raise GpuTableError(f"{path}: [{g.key}] calibrate_like = {g.calibrate_like!r} names no GPU "
                                f"of the table")
    return gpus


def efficiency(gpu, gpus, family, sh_order):
    """(median, low, high, basis) of the efficiency of `family` on `gpu` at `sh_order` (see the
    module's docstring); None without any measurement of the family. basis says whose: "measured",
    "like <name>" or "every measured GPU"."""
    by_key = {g.key: g for g in gpus}

    def of(g):
        ms = [m for m in g.measured if m.family == family]
        same = [m for m in ms if m.sh_order == sh_order]
        return [g.efficiency_of(m) for m in (same or ms)]

    values, basis = of(gpu), "measured"
    if not values and gpu.calibrate_like in by_key:
        values, basis = of(by_key[gpu.calibrate_like]), f"like {by_key[gpu.calibrate_like].name}"
    if not values:
        values = [v for g in gpus for v in of(g)]
        basis = "every measured GPU"
    if not values:
        return None
    values = sorted(values)
    middle = len(values) // 2
    median = values[middle] if len(values) % 2 else 0.5 * (values[middle - 1] + values[middle])
    return median, values[0], values[-1], basis


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


CALIBRATED = "gpu_calibrated_ms."


def with_estimates(df, gpus):
    """df with, per GPU and counted stage, the roofline bound gpu_estimate_ms.<gpu>.<stage> (and
    .total, the sum over the counted stages), and where the stage's kernel family has a measured
    efficiency (efficiency()) the calibrated estimate gpu_calibrated_ms.<gpu>.<stage>, its range
    .<stage>.low and .<stage>.high, and .<stage>.basis (whose measurements)."""
    out = df.copy()
    stages = counted_stages(df)
    orders = (df["param.grid.sh_order"] if "param.grid.sh_order" in df.columns
              else pd.Series([1] * len(df), index=df.index))
    for gpu in gpus:
        total = pd.Series([0.0] * len(df), index=df.index)
        for stage in stages:
            madds = _column(df, f"gpu_work.{stage}.multiply_adds")
            nbytes = _column(df, f"gpu_work.{stage}.bytes")
            ms = pd.Series([stage_ms(m, b, gpu) for m, b in zip(madds, nbytes)], index=df.index)
            out[f"{PREFIX}{gpu.key}.{stage}"] = ms
            total = total + ms.fillna(0.0)
            calibrated = {"": [], ".low": [], ".high": [], ".basis": []}
            for bound, order in zip(ms, orders):
                try:
                    order = int(order)
                except (TypeError, ValueError):
                    order = 1
                e = efficiency(gpu, gpus, stage, order)
                if e is None or math.isnan(bound):
                    for k in calibrated:
                        calibrated[k].append("" if k == ".basis" else math.nan)
                    continue
                median, low, high, basis = e
                calibrated[""].append(bound / median)
                calibrated[".low"].append(bound / high)
                calibrated[".high"].append(bound / low)
                calibrated[".basis"].append(basis)
            if any(b for b in calibrated[".basis"]):
                for k, values in calibrated.items():
                    out[f"{CALIBRATED}{gpu.key}.{stage}{k}"] = pd.Series(values, index=df.index)
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
