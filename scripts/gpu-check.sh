#!/bin/sh
# The whole program checked on a GPU (docs/gpu.md): each configuration below runs twice through
# EGL, once with every strategy's GL kernels (compute.backend = "gl") and once with their CPU
# kernels (compute.backend = "cpu"; the raster passes stay on GL, compute.raster = "gl" in both, so
# that only the kernels differ), and the GL run's `direct` and
# `indirect` must match the CPU run's: the mean and the 99th percentile of the relative difference
# (`lpvlab compare`: |gl - cpu| / (|cpu| + 1e-3 mean |cpu|) over the pixels with a surface) within
# the tolerances. Ends with a table; exits 1 if any configuration fails or differs beyond them.
#
#   scripts/gpu-check.sh [--lpvlab PATH] [--out DIR] [--backend egl|osmesa] [--size N]
#                        [--grid N] [--only NAME[,NAME...]] [--mean TOL] [--p99 TOL]
#
#   --lpvlab PATH   the lpvlab to check (default: the bundle's bin/lpvlab beside this script, else
#                   build/lpvlab of the source tree)
#   --out DIR       where each configuration's runs and logs go (default: gpu-check-<UTC time>)
#   --backend       the GL context (default egl: the GPU, or Mesa's software device where there
#                   is none, which is how CI runs it on llvmpipe)
#   --size N        image width and height (default 256); --grid N: grid resolution (default 32)
#   --only          the configurations to run, by name (default: all)
#   --mean, --p99   the tolerances (defaults 1e-3 and 2e-2; see docs/gpu.md)
#
# Per configuration, DIR/<name>/gl.log holds the GL run's per-stage times (GL timer queries) and
# DIR/<name>/compare.txt the differences; DIR/summary.txt the table.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
lpvlab="" out="gpu-check-$(date -u +%Y%m%dT%H%M%SZ)" backend=egl size=256 grid=32 only=""
tol_mean=1e-3 tol_p99=2e-2
while [ $# -gt 0 ]; do
  case $1 in
    --lpvlab) lpvlab=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --backend) backend=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --grid) grid=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --mean) tol_mean=$2; shift 2 ;;
    --p99) tol_p99=$2; shift 2 ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "gpu-check: error: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
# The experiments: the bundle's share/lpvlab, or the source tree's.
if [ -d "$here/../share/lpvlab/experiments" ]; then
  experiments=$here/../share/lpvlab/experiments
  [ -n "$lpvlab" ] || lpvlab=$here/lpvlab
else
  experiments=$here/../experiments
  [ -n "$lpvlab" ] || lpvlab=$here/../build/lpvlab
fi
[ -x "$lpvlab" ] || { echo "gpu-check: error: $lpvlab is not an executable lpvlab (--lpvlab)" >&2; exit 2; }
mkdir -p "$out"

small="-s output.width=$size -s output.height=$size -s timing.warmup=1 -s timing.repeats=3 -s grid.resolution=$grid"
# name | experiment file ("-": the built-in Cornell box) | overrides | image compared
configurations() {
  cat <<EOF
cornell|-||
directed|-|-s propagation.type="directed"|
tetrahedral|-|-s propagation.type="tetrahedral"|
sh_order_2|-|-s grid.sh_order=2|
sh_order_3|-|-s grid.sh_order=3|
geometry_volume|-|-s occlusion.type="geometry_volume"|
scatter|-|-s propagation.method="scatter"|
tiled|-|-s propagation.gpu_kernel="tiled"|
directed_tiled|-|-s propagation.type="directed" -s propagation.gpu_kernel="tiled"|
tiled_sh_order_3_gv|-|-s propagation.gpu_kernel="tiled" -s grid.sh_order=3 -s occlusion.type="geometry_volume"|
glossy|-|-s rendering.type="glossy" -s rendering.specular_albedo=0.5|
cascades|-|-s cascades.levels=3|
sponza_sun|sponza_sun.toml||
radiosity_hemicube|-|-s indirect.method="radiosity" -s indirect.form_factors="hemicube"|
instant_radiosity|-|-s indirect.method="instant_radiosity" -s indirect.visibility="shadow_maps"|
imperfect_shadow_maps|-|-s indirect.method="imperfect_shadow_maps"|
particles|particles_cornell.toml|-s animation.frames=2 -s animation.video=false|frames/frame_0001.exr
sequence|cornell_box_moving_block.toml|-s animation.frames=3 -s animation.video=false|frames/frame_0002.exr
EOF
}

failed=0
printf '%-22s %-6s %10s %12s %12s %12s %12s\n' configuration result "GL ms" "direct mean" "direct p99" \
  "indir. mean" "indir. p99" > "$out/summary.txt"
renderer=""
while IFS='|' read -r name file overrides image; do
  if [ -n "$only" ] && ! echo ",$only," | grep -q ",$name,"; then continue; fi
  dir=$out/$name
  rm -rf "$dir"
  mkdir -p "$dir"
  set --
  [ "$file" = - ] || set -- "$experiments/$file"
  if [ "$name" = sponza_sun ] && [ -z "${LPVLAB_SHARED_DIR:-}" ] && [ ! -d "$here/../../shared/scenes" ]; then
    printf '%-22s %-6s (no scenes: set LPVLAB_SHARED_DIR)\n' "$name" skip >> "$out/summary.txt"
    continue
  fi
  result=ok
  for compute in gl cpu; do
    # shellcheck disable=SC2086
    if ! "$lpvlab" run "$@" --out "$dir/$compute" $small $overrides -s "gl.backend=\"$backend\"" \
        -s "compute.backend=\"$compute\"" -s 'compute.raster="gl"' > "$dir/$compute.log" 2>&1; then
      result=FAIL
      echo "gpu-check: $name ($compute) failed: $(tail -1 "$dir/$compute.log")" >&2
    fi
  done
  gl_ms=- dm=- dp=- im=- ip=-
  if [ "$result" = ok ]; then
    renderer=$(sed -n 's/^lpvlab: .* on \(.*\) ([a-z]*), .*/\1/p' "$dir/gl.log" | head -1)
    gl_ms=$(awk '$1 == "total" {print $2}' "$dir/gl.log")
    target=${image:-images.exr}
    if "$lpvlab" compare "$dir/gl/$target" "$dir/cpu/$target" > "$dir/compare.txt" 2>&1; then
      dm=$(awk '$1 == "direct" {print $2}' "$dir/compare.txt")
      dp=$(awk '$1 == "direct" {print $3}' "$dir/compare.txt")
      im=$(awk '$1 == "indirect" {print $2}' "$dir/compare.txt")
      ip=$(awk '$1 == "indirect" {print $3}' "$dir/compare.txt")
      if ! awk -v a="$dm" -v b="$dp" -v c="$im" -v d="$ip" -v m="$tol_mean" -v p="$tol_p99" \
          'BEGIN { exit !(a + 0 <= m + 0 && c + 0 <= m + 0 && b + 0 <= p + 0 && d + 0 <= p + 0) }'; then
        result=DIFFER
      fi
    else
      result=FAIL
      echo "gpu-check: $name: compare failed: $(tail -1 "$dir/compare.txt")" >&2
    fi
  fi
  [ "$result" = ok ] || failed=$((failed + 1))
  printf '%-22s %-6s %10s %12s %12s %12s %12s\n' "$name" "$result" "$gl_ms" "$dm" "$dp" "$im" "$ip" \
    >> "$out/summary.txt"
  echo "gpu-check: $name: $result" >&2
done <<EOF
$(configurations)
EOF

{
  echo "gpu-check: $lpvlab on ${renderer:-?} (gl.backend = $backend), ${size}x$size, grid $grid;"
  echo "GL kernels against CPU kernels, tolerances: mean <= $tol_mean, p99 <= $tol_p99"
} | tee "$out/header.txt"
cat "$out/summary.txt"
if [ "$failed" -gt 0 ]; then
  echo "gpu-check: $failed configurations failed or differ beyond the tolerances (see $out)"
  exit 1
fi
echo "gpu-check: every configuration matches (see $out)"
