#!/bin/sh
# The portable bundle (scripts/bundle.sh) on other distributions: bare mmdebstrap roots of Debian 11
# (glibc 2.31, older than the build's) and Debian 13 (2.41, newer), minbase, with no -dev package
# and no GL. In each it runs the built-in Cornell box and Crytek Sponza under the sun, and each
# image must equal the build tree's to the bit (the same CPU; OSMesa in both: the roots have no
# EGL vendor, so "auto" ends at the bundle's OSMesa, as the manifest must say). A bundle without
# Mesa (--no-osmesa: no OSMesa, no LLVM) runs the Cornell box there too: no GL context can be made,
# so "auto" runs without GL (gl.backend = "none"), and its image equals the build tree's run
# with gl.backend = "none" to the bit.
#
#   foreign_roots_test.sh BUILD_DIR/lpvlab
#
# Needs root (mmdebstrap, chroot, mounts) and mmdebstrap; exits 77 (skipped) without them, except
# under CI. A suite the package registry does not serve is named and left out; none served fails.
set -eu

lpvlab=$(readlink -f "$1")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
shared=${LPVLAB_SHARED_DIR:-$(cd "$source_dir/.." && pwd)/shared}

skip() {
  if [ -n "${CI:-}" ]; then echo "error: $1" >&2; exit 1; fi
  echo "skipped: $1"; exit 77
}
[ "$(id -u)" = 0 ] || skip "making Debian roots needs root (mmdebstrap, chroot)"
command -v mmdebstrap >/dev/null || skip "mmdebstrap is not installed (scripts/install-deps.sh --tests)"
[ -f "$shared/scenes/sponza/Sponza.gltf" ] || skip "$shared/scenes/sponza is missing"

# The mirror this machine's apt uses (its sources name only its own suite), else Debian's.
mirror=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources \
           2>/dev/null | grep -v '^ *#' | grep -oE 'https?://[^ ]*/debian/?( |$)' | head -1 | tr -d ' ')
[ -n "$mirror" ] || mirror=http://deb.debian.org/debian

tmp=$(mktemp -d "${TMPDIR:-/var/tmp}/lpvlab-foreign.XXXXXX")
# The roots' mounts are made directly, not in a private mount namespace: under CI this test runs
# in a chroot whose / is no mount point, where `unshare --propagation private` fails (EINVAL).
# They are undone on every exit; --one-file-system keeps rm out of any one left behind.
mounted=""
cleanup() {
  for m in $mounted; do umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || true; done
  rm -rf --one-file-system "$tmp"
}
trap cleanup EXIT
"$source_dir/scripts/bundle.sh" --build "$(dirname "$lpvlab")" --out "$tmp/dist" --no-build | tail -2
bundle=$(ls -d "$tmp"/dist/lpvlab-*-x86_64)
"$source_dir/scripts/bundle.sh" --build "$(dirname "$lpvlab")" --out "$tmp/dist-cpu" --no-build --no-osmesa | tail -1
cpu_bundle=$(ls -d "$tmp"/dist-cpu/lpvlab-*-x86_64)
if find "$cpu_bundle" -name 'libOSMesa*' -o -name 'libLLVM*' -o -name 'libgallium*' | grep -q .; then
  echo "FAIL: the bundle without Mesa carries Mesa or LLVM"; exit 1
fi

small="-s output.width=96 -s output.height=64 -s timing.warmup=0 -s timing.repeats=1 -s grid.resolution=16 -s light_maps.rsm_resolution=64 -s light_maps.shadow_resolution=256"
cp "$source_dir/experiments/sponza_sun.toml" "$tmp/sponza_sun.toml"
# shellcheck disable=SC2086
"$lpvlab" run --out "$tmp/host/cornell" $small -s 'gl.backend="osmesa"' > "$tmp/host.log" 2>&1
# shellcheck disable=SC2086
"$lpvlab" run --out "$tmp/host/cornell-cpu" $small -s 'gl.backend="none"' >> "$tmp/host.log" 2>&1
# shellcheck disable=SC2086
LPVLAB_SHARED_DIR=$shared "$lpvlab" run "$tmp/sponza_sun.toml" --out "$tmp/host/sponza" $small \
  -s 'gl.backend="osmesa"' >> "$tmp/host.log" 2>&1

same_pixels() {  # the EXRs' pixels equal to the bit
  /usr/bin/python3 - "$1" "$2" <<'PYTHON'
import sys
import OpenImageIO as oiio
def pixels(path):
    image = oiio.ImageInput.open(path)
    data = image.read_image("float")
    image.close()
    return data
a, b = pixels(sys.argv[1]), pixels(sys.argv[2])
sys.exit(0 if a.shape == b.shape and (a == b).all() else 1)
PYTHON
}

served=0 failed=0
for suite in bullseye trixie; do
  root=$tmp/$suite
  if ! mmdebstrap --quiet --variant=minbase "$suite" "$root" "$mirror" > "$tmp/$suite.log" 2>&1; then
    echo "$suite: the package registry ($mirror) does not serve it; left out:"
    tail -3 "$tmp/$suite.log"
    continue
  fi
  served=$((served + 1))
  glibc=$(chroot "$root" ldd --version 2>&1 | head -1 | awk '{print $NF}')
  # Hard links where the roots share the bundle's file system: 572 MB is not copied twice.
  cp -al "$bundle" "$root/opt/lpvlab" 2>/dev/null || { rm -rf "$root/opt/lpvlab"; cp -a "$bundle" "$root/opt/lpvlab"; }
  cp -al "$cpu_bundle" "$root/opt/lpvlab-cpu" 2>/dev/null || { rm -rf "$root/opt/lpvlab-cpu"; cp -a "$cpu_bundle" "$root/opt/lpvlab-cpu"; }
  cp "$tmp/sponza_sun.toml" "$root/tmp/"
  mkdir -p "$root/shared"
  mount -t proc proc "$root/proc" || { echo "FAIL: cannot mount /proc in the $suite root"; exit 1; }
  mounted="$root/proc"
  mount --bind -o ro "$shared" "$root/shared" || { echo "FAIL: cannot bind $shared into the $suite root"; exit 1; }
  mounted="$root/shared $root/proc"
  status=0
  chroot "$root" /usr/bin/env -i HOME=/tmp PATH=/usr/bin:/bin LPVLAB_SHARED_DIR=/shared sh -c "
        cd /tmp &&
        /opt/lpvlab/bin/lpvlab run --out /tmp/cornell $small &&
        /opt/lpvlab/bin/lpvlab run /tmp/sponza_sun.toml --out /tmp/sponza $small &&
        /opt/lpvlab-cpu/bin/lpvlab run --out /tmp/cornell-cpu $small" \
      > "$tmp/$suite-run.log" 2>&1 || status=$?
  umount "$root/shared" "$root/proc" && mounted=""
  if [ "$status" != 0 ]; then
    echo "FAIL: $suite (glibc $glibc): the bundle did not run:"; tail -5 "$tmp/$suite-run.log"
    failed=$((failed + 1))
    continue
  fi
  for scene in cornell sponza cornell-cpu; do
    expected=osmesa
    [ "$scene" = cornell-cpu ] && expected=none
    if ! grep -q "\"gl_backend\": \"$expected\"" "$root/tmp/$scene/manifest.json"; then
      echo "FAIL: $suite: $scene ran on $(grep -o '"gl_backend": "[a-z]*"' "$root/tmp/$scene/manifest.json")"
      failed=$((failed + 1))
    elif same_pixels "$tmp/host/$scene/images.exr" "$root/tmp/$scene/images.exr"; then
      echo "$suite (glibc $glibc): $scene equals the build tree's image to the bit"
    else
      echo "FAIL: $suite (glibc $glibc): $scene differs from the build tree's image"
      failed=$((failed + 1))
    fi
  done
done
[ "$served" -gt 0 ] || { echo "FAIL: the package registry serves neither bullseye nor trixie"; exit 1; }
[ "$failed" = 0 ] || exit 1
echo "foreign roots: every check passed"
