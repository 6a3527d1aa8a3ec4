"""Side-by-side images of a run: path-traced reference, LPV result, error map.

With OpenImageIO's Python binding (Debian: python3-openimageio) the run's
images.exr 'indirect' AOV and the reference's images.exr 'indirect1' AOV
(the quantity the error map and the indirect metrics compare) are tone-mapped
with the SAME exposure, chosen from the reference (its 99th-percentile
luminance maps to 0.9 before the sRGB curve), so brightness differences are
real differences. Without OIIO (or when the reference EXR is gone) the
report falls back to the run's combined.png and error_indirect.png only.
"""
import os

import numpy as np

from . import fsutil

try:
    import OpenImageIO as oiio  # type: ignore
except Exception:  # pragma: no cover - depends on the machine
    oiio = None


def have_oiio():
    return oiio is not None


def read_aov(path, aov):
    """Read channels '<aov>.R/G/B' of an EXR as float32 HxWx3 (None if missing)."""
    if oiio is None or not os.path.isfile(path):
        return None
    inp = oiio.ImageInput.open(path)
    if inp is None:
        return None
    try:
        spec = inp.spec()
        names = list(spec.channelnames)
        idx = []
        for c in ("R", "G", "B"):
            n = f"{aov}.{c}"
            if n not in names:
                return None
            idx.append(names.index(n))
        px = inp.read_image(0, 0, 0, spec.nchannels, oiio.FLOAT)
    finally:
        inp.close()
    if px is None:
        return None
    px = np.asarray(px, dtype=np.float32).reshape(spec.height, spec.width, spec.nchannels)
    return px[:, :, idx]


def exposure_scale(ref):
    """Linear scale putting the reference's 99th-percentile luminance at 0.9."""
    lum = 0.2126 * ref[..., 0] + 0.7152 * ref[..., 1] + 0.0722 * ref[..., 2]
    lum = lum[np.isfinite(lum) & (lum > 0)]
    if lum.size == 0:
        return 1.0
    p = float(np.percentile(lum, 99))
    return 0.9 / p if p > 0 else 1.0


def tonemap(img, scale):
    """Scale, clip to [0,1], apply the sRGB transfer curve, return uint8 HxWx3."""
    x = np.clip(np.nan_to_num(img * scale, nan=0.0, posinf=1.0, neginf=0.0), 0.0, 1.0)
    x = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    return (np.clip(x, 0, 1) * 255 + 0.5).astype(np.uint8)


def write_png(path, rgb8):
    """Write an 8-bit RGB array as PNG atomically (matplotlib's writer)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fsutil.write_with(path, lambda tmp: plt.imsave(tmp, rgb8, format="png"))
    return path


def tonemapped_pair(run_exr, ref_exr, out_ref, out_run, run_aov="indirect", ref_aov="indirect1"):
    """Write tone-mapped reference and run PNGs with a shared exposure.

    Returns (scale, ref_written) or None when either image cannot be read.
    out_ref may already exist (one reference shared by many runs): then it is
    not rewritten, but the scale is still derived from the reference.
    """
    ref = read_aov(ref_exr, ref_aov)
    run = read_aov(run_exr, run_aov)
    if ref is None or run is None:
        return None
    scale = exposure_scale(ref)
    wrote = False
    if not os.path.exists(out_ref):
        write_png(out_ref, tonemap(ref, scale))
        wrote = True
    write_png(out_run, tonemap(run, scale))
    return scale, wrote
