"""The GPU estimate of single runs, for `lpvlab tune` with time = "gpu-estimate" (docs/tuning.md):

    lpvlab-gpu-estimate --gpu KEY ROWS.csv --out OUT.json     (or analysis/gpu_estimate.py ...)

ROWS.csv has one row per run: `id`, `param.grid.sh_order` and the run's gpu_work.<stage>.*
columns, as summary.csv has them (the tuner writes it from the runs' manifests with the sweep
summary's own code, framework/experiment/work_columns.h). OUT.json:

    {"gpu": "<name>", "words": "<how it was estimated>", "runs": {"<id>": ms or null}}

It is the report's speed axis with `--time gpu-estimate` (summary.with_speed), computed by the same
code: per run the sum over its indirect method's counted stages of the calibrated estimate, or of
the roofline bound where the stage's kernel family was never measured. null: the run has nothing
counted. An estimate from counted work, not a measurement: OUT.json's words say so, and so must
whatever shows the figures.

Exit status 2 with one line naming the file or the key for an unknown GPU, a malformed table or
rows file.
"""
import argparse
import json
import math
import sys

import pandas as pd

from . import fsutil
from . import gpu_estimate as G
from . import summary as S


def estimate(rows, gpu):
    """(ms per id, the words) for `rows`, a DataFrame as ROWS.csv; ms is None where nothing was
    counted."""
    if "id" not in rows.columns:
        raise S.SummaryError("no 'id' column")
    if rows.empty:  # the tuner's check of the GPU's key before anything runs
        return {}, f"estimated on {gpu.name}"
    est = S.with_speed(rows, "gpu-estimate", gpu)
    ms = {str(i): (None if math.isnan(v) else float(v)) for i, v in zip(est["id"], est[S.SPEED_COL])}
    return ms, S.speed_words(est)


def _gpu(key, table):
    gpus = {g.key: g for g in G.load_gpus(table)}
    if key not in gpus:
        raise S.SummaryError(f"--gpu {key}: not a GPU of {table}; it has {', '.join(gpus)}")
    return gpus[key]


def main(argv=None):
    ap = argparse.ArgumentParser(description="The GPU estimate (ms) of single runs from their counted GL-kernel "
                                             "work, as lpvlab report's --time gpu-estimate; for lpvlab tune.")
    ap.add_argument("rows", help="CSV: id, param.grid.sh_order and the runs' gpu_work.<stage>.* columns")
    ap.add_argument("--gpu", default=S.DEFAULT_GPU, help=f"a key of gpus.toml (default {S.DEFAULT_GPU})")
    ap.add_argument("--table", default=G.DEFAULT_TABLE, help="the GPU table (default: the shipped gpus.toml)")
    ap.add_argument("--out", required=True, help="the JSON to write (atomically)")
    a = ap.parse_args(argv)
    try:
        gpu = _gpu(a.gpu, a.table)
        try:
            rows = pd.read_csv(a.rows, dtype={"id": str})
        except (OSError, ValueError) as exc:
            raise S.SummaryError(f"{a.rows}: cannot be read as CSV ({exc})") from exc
        try:
            ms, words = estimate(rows, gpu)
        except S.SummaryError as exc:
            raise S.SummaryError(f"{a.rows}: {exc}") from exc
    except (S.SummaryError, G.GpuTableError) as exc:
        print(f"lpvlab: error: gpu estimate: {exc}", file=sys.stderr)
        return 2
    fsutil.write_text(a.out, json.dumps({"gpu": gpu.name, "gpu_key": gpu.key, "words": words, "runs": ms},
                                        indent=2) + "\n")
    return 0
