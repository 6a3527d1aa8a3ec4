#!/bin/sh
# scripts/gpu-check.sh on this machine's GL through EGL (llvmpipe here and in CI; a GPU wherever
# there is one): every configuration's GL kernels match its CPU kernels within the script's
# tolerances, and the check can fail: with zero tolerances the GL and CPU images, which differ in
# float rounding, are reported as differing and the exit status is 1.
#
#   gpu_check_test.sh BUILD_DIR/lpvlab
set -u
lpvlab=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lpvlab-gpu-check.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
status=0

"$source_dir/scripts/gpu-check.sh" --lpvlab "$lpvlab" --out "$tmp/all" --size 32 --grid 8
[ $? -eq 0 ] || { echo "FAIL: gpu-check on this machine's GL"; status=1; }

"$source_dir/scripts/gpu-check.sh" --lpvlab "$lpvlab" --out "$tmp/strict" --size 64 --grid 16 \
  --only cornell --mean 0 --p99 0 > "$tmp/strict.txt" 2>&1
strict=$?
if [ $strict -ne 1 ] || ! grep -q "^cornell  *DIFFER" "$tmp/strict.txt"; then
  echo "FAIL: with zero tolerances gpu-check must report cornell as DIFFER and exit 1 (got $strict):"
  cat "$tmp/strict.txt"
  status=1
fi
[ $status -eq 0 ] && echo "gpu-check test: passed"
exit $status
