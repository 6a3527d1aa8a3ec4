"""Synthetic sweep directories for the tests (no rendering needed).

make_sweep(root) writes summary.csv with 2 variants x 3 iteration counts x
2 repeats, run directories with manifest.json, tiny combined.png and
error_indirect.png, and (when OIIO is available) tiny images.exr files for
the runs and a shared reference so the tone-mapping path is exercised.
"""
import csv
import json
import os

import numpy as np

STAGES = ["shadow_maps", "rsm", "gbuffer", "direct", "clear", "injection", "propagation", "indirect", "total"]
PAIRS = ["direct_vs_direct", "indirect_vs_indirect1"]
METRICS = ["mae", "rmse", "rel_mse", "psnr", "ssim", "flip", "hdr_flip"]


def _png(path, value):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    img = np.zeros((8, 8, 3), dtype=np.uint8)
    img[..., 0] = value
    img[::2, ::2, 1] = 255
    plt.imsave(path, img)


def _exr(path, aovs):
    import OpenImageIO as oiio
    names, planes = [], []
    for aov, val in aovs.items():
        for i, c in enumerate("RGB"):
            names.append(f"{aov}.{c}")
            planes.append(np.full((8, 8), val * (i + 1), dtype=np.float32))
    px = np.stack(planes, axis=-1)
    spec = oiio.ImageSpec(8, 8, len(names), oiio.FLOAT)
    spec.channelnames = tuple(names)
    out = oiio.ImageOutput.create(path)
    out.open(path, spec)
    out.write_image(px)
    out.close()


def make_sweep(root, with_exr=True, with_metrics=True):
    try:
        import OpenImageIO  # noqa: F401
        have = True
    except Exception:
        have = False
    with_exr = with_exr and have
    ref_dir = os.path.join(root, "refcache")
    os.makedirs(ref_dir, exist_ok=True)
    if with_exr:
        _exr(os.path.join(ref_dir, "images.exr"), {"direct": 0.2, "indirect1": 0.05})
    header = ["config_id", "config_name", "repeat", "run_dir",
              "param.injection.type", "param.propagation.type", "param.rendering.type",
              "param.grid.resolution", "param.propagation.iterations", "param.scene.file"]
    header += [f"time.{s}.ms" for s in STAGES] + [f"time.{s}.clock" for s in STAGES]
    header += [f"wall_ms.{s}" for s in STAGES] + ["timed_on.gl", "timed_on.cpu"]
    header += ["memory_bytes", "cells"]
    # The GL kernels' counted work (what a GPU would run): propagation's, per cell-iteration.
    header += ["gpu_work.propagation.multiply_adds", "gpu_work.propagation.bytes"]
    if with_metrics:
        header += [f"metric.{p}.{m}" for p in PAIRS for m in METRICS]
    rows = []
    k = 0
    for prop in ("standard", "occlusion"):
        for it in (1, 4, 16):
            cid = f"{k:03d}"
            name = f"{prop}_it{it}"
            run_dir = os.path.join(root, cid)
            os.makedirs(run_dir, exist_ok=True)
            _png(os.path.join(run_dir, "combined.png"), 40 * k)
            _png(os.path.join(run_dir, "error_indirect.png"), 200)
            if with_exr:
                _exr(os.path.join(run_dir, "images.exr"), {"direct": 0.2, "indirect": 0.01 * it})
            man = {"configuration": {"propagation": {"type": prop, "iterations": it}},
                   "reference": {"directory": ref_dir}, "outputs": {}, "timing": {}}
            with open(os.path.join(run_dir, "manifest.json"), "w") as f:
                json.dump(man, f)
            for rep in range(2):
                r = [cid, name, rep, cid, "rsm_vpl", prop, "trilinear", 32, it, "builtin:cornell_box"]
                stage = {s: 1.0 + rep for s in STAGES}
                stage["propagation"] = it * (2.0 if prop == "occlusion" else 1.0) + rep
                stage["total"] = sum(v for s, v in stage.items() if s != "total")
                # Propagation on the CPU backend, the rest on GL: the total sums both clocks.
                clock = {s: "gl_timer_query" for s in STAGES}
                clock["propagation"], clock["total"] = "cpu_wall_clock", "mixed"
                r += [stage[s] for s in STAGES] + [clock[s] for s in STAGES]
                r += [stage[s] * 1.1 for s in STAGES] + ["llvmpipe (LLVM 15.0.6, 256 bits)", "Test CPU 9000"]
                r += [1048576 * (2 if prop == "occlusion" else 1), 32768]
                r += [it * 32768 * 150.0, it * 32768 * 500.0]
                if with_metrics:
                    err = 0.1 / it * (0.5 if prop == "occlusion" else 1.0)
                    for p in PAIRS:
                        r += [err, err * 1.5, err * 2, "inf" if (p == "direct_vs_direct") else 20 + it, 0.9, err,
                              err * 1.2]
                rows.append(r)
            k += 1
    with open(os.path.join(root, "summary.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    return root
