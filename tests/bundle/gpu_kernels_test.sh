#!/bin/sh
# scripts/gpu-kernels.sh as a GPU machine would run it, on this machine's GL through EGL (llvmpipe
# here and in CI): pack the build tree's lpvlab-gpubench, unpack and run it with an empty
# environment outside the source tree, and find a row with a positive throughput for every case
# it lists; the archive stays under 5 MB.
#
#   gpu_kernels_test.sh BUILD_DIR
set -u
build=$1
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lpvlab-gpu-kernels.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

"$source_dir/scripts/gpu-kernels.sh" pack --build "$build" --out "$tmp/dist" || { echo "FAIL: pack"; exit 1; }
archive=$tmp/dist/lpvlab-gpubench-x86_64.tar.gz
bytes=$(wc -c < "$archive")
[ "$bytes" -lt 5000000 ] || { echo "FAIL: the archive is $bytes bytes (5 MB at most)"; exit 1; }
cp "$source_dir/scripts/gpu-kernels.sh" "$archive" "$tmp/"
mkdir "$tmp/run"
(cd "$tmp/run" && env -i PATH=/usr/bin:/bin OUT=out sh "$tmp/gpu-kernels.sh" run "$tmp/lpvlab-gpubench-x86_64.tar.gz" \
   -- --grids 9 --orders 1,2 --iterations 2 --repeats 1 > "$tmp/log.txt" 2>&1) ||
  { echo "FAIL: run"; cat "$tmp/log.txt"; exit 1; }
/usr/bin/python3 - "$tmp/run/out/gpubench.json" "$tmp/log.txt" <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
log = open(sys.argv[2]).read()
cases = {r["case"] for r in results}
assert len(results) == 2 * len(cases) and len(cases) >= 8, (len(results), cases)
for r in results:
    assert r["units_per_s"] > 0 and r["bytes_per_unit"] > 0 and r["multiply_adds_per_unit"] > 0, r
    assert r["case"] in log, r["case"]
print(f"ok: {len(cases)} cases, {len(results)} rows")
PY
