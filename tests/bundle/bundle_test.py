#!/usr/bin/python3
"""The portable bundle (scripts/bundle.sh, issue 34), made from this build tree and used as a user
on another machine would: unpacked from its archive's parts into a folder of another name, run
with an empty environment from elsewhere.

Checks: the binary links neither libOSMesa nor libEGL (they are opened at run time); the bundle
carries glibc's loader and OSMesa and not the GPU vendors' GL; no part exceeds 40 MiB and the parts
are the archive; the unpacked bundle's Cornell box equals the build tree's to the bit (same CPU,
OSMesa both); "auto" runs; a sweep runs its configurations through the bundle's own script; its
gpu-check runs; the revision is the source tree's.

    bundle_test.py BUILD_DIR/lpvlab
"""
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SMALL = ["-s", "output.width=48", "-s", "output.height=48", "-s", "timing.warmup=0",
         "-s", "timing.repeats=1", "-s", "grid.resolution=8", "-s", "propagation.iterations=4"]
PART_LIMIT = 40 * 1024 * 1024
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message, file=sys.stderr)


def run(args, cwd, env=None):
    result = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True)
    if result.returncode != 0:
        print(" ".join(args), "\n", result.stdout, result.stderr, file=sys.stderr)
    return result


def pixels(run_dir):
    """The run's images.exr pixels (OpenImageIO), else its PNG's bytes."""
    try:
        import OpenImageIO as oiio
        image = oiio.ImageInput.open(os.path.join(run_dir, "images.exr"))
        data = image.read_image("float")
        image.close()
        return data.tobytes()
    except ImportError:
        with open(os.path.join(run_dir, "combined.png"), "rb") as f:
            return f.read()


def main():
    lpvlab = os.path.abspath(sys.argv[1])
    build = os.path.dirname(lpvlab)
    with tempfile.TemporaryDirectory(prefix="lpvlab-bundle-") as tmp:
        dist = os.path.join(tmp, "dist")
        made = run([os.path.join(SOURCE, "scripts", "bundle.sh"), "--build", build, "--out", dist,
                    "--archive", "--level", "1", "--part-size", "40M", "--no-build"], cwd=tmp)
        if made.returncode != 0:
            print("FAIL: bundle.sh failed", file=sys.stderr)
            return 1
        print(made.stdout)
        names = [n for n in os.listdir(dist) if n.startswith("lpvlab-") and os.path.isdir(os.path.join(dist, n))]
        check(len(names) == 1, f"one bundle folder in {dist}: {names}")
        name = names[0]
        folder = os.path.join(dist, name)

        needed = run(["readelf", "-d", os.path.join(folder, "libexec", "lpvlab")], cwd=tmp).stdout
        check("libOSMesa" not in needed and "libEGL" not in needed,
              "the binary links neither libOSMesa nor libEGL (opened at run time)")
        libs = set(os.listdir(os.path.join(folder, "lib")))
        check("ld-linux-x86-64.so.2" in libs and "libc.so.6" in libs, "glibc and its loader are in lib/")
        check("libOSMesa.so.8" in libs, "OSMesa is in lib/")
        check(not any(n.startswith(("libEGL_", "libGLX_", "libnvidia")) for n in libs),
              "the GPU vendors' GL and EGL (the host's, through glvnd) are not in lib/")

        tarball = os.path.join(dist, name + ".tar.zst")
        parts = sorted(p for p in os.listdir(dist) if p.startswith(name + ".tar.zst.part-"))
        check(len(parts) >= 1, "the archive is split into parts")
        joined = hashlib.sha256()
        for part in parts:
            size = os.path.getsize(os.path.join(dist, part))
            check(size <= PART_LIMIT, f"{part}: {size} bytes, at most 40 MiB")
            with open(os.path.join(dist, part), "rb") as f:
                joined.update(f.read())
        with open(tarball, "rb") as f:
            check(joined.hexdigest() == hashlib.sha256(f.read()).hexdigest(), "the parts are the archive")

        # Unpacked from the parts, under another name (relocatable), the build folder gone.
        unpacked = os.path.join(tmp, "elsewhere")
        os.makedirs(unpacked)
        script = f"cat {' '.join(os.path.join(dist, p) for p in parts)} | zstd -d --long=27 | tar -x -C {unpacked}"
        check(subprocess.run(["sh", "-c", script]).returncode == 0, "the parts unpack")
        moved = os.path.join(unpacked, "my-lpvlab")
        os.rename(os.path.join(unpacked, name), moved)
        shutil.rmtree(folder)
        bundled = os.path.join(moved, "bin", "lpvlab")
        home = os.path.join(tmp, "home")
        os.makedirs(home)
        bare = {"PATH": "/usr/bin:/bin", "HOME": home}
        work = os.path.join(tmp, "work")
        os.makedirs(work)

        version = run([bundled, "--version"], cwd=work, env=bare)
        with open(os.path.join(moved, "share", "lpvlab", "REVISION")) as f:
            revision = f.read().strip()
        check(version.returncode == 0 and revision in version.stdout and revision != "unknown",
              f"--version names the bundle's revision {revision}: {version.stdout!r}")

        osmesa = ["-s", 'gl.backend="osmesa"']
        a = run([lpvlab, "run", "--out", os.path.join(tmp, "a")] + SMALL + osmesa, cwd=work)
        b = run([bundled, "run", "--out", os.path.join(tmp, "b")] + SMALL + osmesa, cwd=work, env=bare)
        check(a.returncode == 0 and b.returncode == 0, "the build tree and the bundle run the Cornell box")
        if a.returncode == 0 and b.returncode == 0:
            check(pixels(os.path.join(tmp, "a")) == pixels(os.path.join(tmp, "b")),
                  "the bundle's images equal the build tree's to the bit")
            with open(os.path.join(tmp, "b", "manifest.json")) as f:
                manifest = json.load(f)
            check(manifest["git_revision"] == revision, "the manifest names the bundle's revision")
            check(manifest["libraries"]["gl_backend"] == "osmesa", "the manifest names the backend")

        auto = run([bundled, "run", "--out", os.path.join(tmp, "auto")] + SMALL, cwd=work, env=bare)
        check(auto.returncode == 0, "the bundle runs with gl.backend = auto")

        check_dir = os.path.join(tmp, "gpu-check")
        gpu_check = run([os.path.join(moved, "bin", "gpu-check"), "--only", "cornell,directed",
                         "--size", "32", "--grid", "8", "--out", check_dir], cwd=work, env=bare)
        check(gpu_check.returncode == 0 and "every configuration matches" in gpu_check.stdout,
              "the bundle's gpu-check runs the bundle's lpvlab and passes")

        sweep_file = os.path.join(work, "s.toml")
        with open(sweep_file, "w") as f:
            f.write('[sweep.product]\n"propagation.iterations" = [1, 2]\n')
        sweep = run([bundled, "sweep", sweep_file, "--out", os.path.join(tmp, "swept")] + SMALL,
                    cwd=work, env=bare)
        check(sweep.returncode == 0 and "2 rows from 2 runs" in sweep.stdout,
              "a sweep runs its configurations through the bundle")
    if failures:
        print(f"{len(failures)} checks failed", file=sys.stderr)
        return 1
    print("bundle: every check passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
