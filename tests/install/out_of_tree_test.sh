#!/bin/sh
# `cmake --install` to a prefix, and a propagation strategy outside the tree built against it
# (docs/examples/out_of_tree_strategy): the installed lpvlab runs from anywhere with its share/
# (the revision from share/lpvlab/REVISION); the example's executable lists its strategy and runs
# it; and its image equals the installed lpvlab's standard propagation at zero iterations (the
# injected light alone, which is what the example's strategy renders), to the bit.
#
#   out_of_tree_test.sh BUILD_DIR
set -eu
build=$(readlink -f "$1")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lpvlab-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
[ -x "$tmp/prefix/bin/lpvlab" ] || fail "no bin/lpvlab"
for f in share/lpvlab/shaders share/lpvlab/experiments share/lpvlab/analysis/report.py \
         share/lpvlab/REVISION lib/cmake/lpvlab/lpvlabConfig.cmake include/lpvlab/framework/pipeline/strategy.h \
         include/lpvlab/glad/gl.h; do
  [ -e "$tmp/prefix/$f" ] || fail "the prefix has no $f"
done

mkdir "$tmp/work"
cd "$tmp/work"
small="-s output.width=32 -s output.height=32 -s timing.warmup=0 -s timing.repeats=1 -s grid.resolution=8"
version=$(env -u LPVLAB_DATA_DIR "$tmp/prefix/bin/lpvlab" --version)
echo "$version" | grep -q "$(cat "$tmp/prefix/share/lpvlab/REVISION")" ||
  fail "installed --version ($version) does not name share/lpvlab/REVISION"

cmake -S "$source_dir/docs/examples/out_of_tree_strategy" -B "$tmp/example" \
  -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release > "$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log"; fail "the example does not configure against the prefix"; }
cmake --build "$tmp/example" -j 2 > "$tmp/build.log" 2>&1 ||
  { tail -30 "$tmp/build.log"; fail "the example does not build against the prefix"; }

export LPVLAB_DATA_DIR="$tmp/prefix/share/lpvlab"
"$tmp/example/my_lpvlab" list | grep -q "injected_only: no propagation" ||
  fail "my_lpvlab list does not list the example's strategy"
# shellcheck disable=SC2086
"$tmp/example/my_lpvlab" run --out "$tmp/example_run" $small -s 'propagation.type="injected_only"' \
  > "$tmp/run.log" 2>&1 || { cat "$tmp/run.log"; fail "my_lpvlab does not run injected_only"; }
grep -q '"type": "injected_only"' "$tmp/example_run/manifest.json" || fail "the manifest names another propagation"
# shellcheck disable=SC2086
"$tmp/prefix/bin/lpvlab" run --out "$tmp/zero" $small -s propagation.iterations=0 > /dev/null 2>&1 ||
  fail "the installed lpvlab does not run"
"$tmp/prefix/bin/lpvlab" compare "$tmp/example_run" "$tmp/zero" --aov indirect > "$tmp/compare.txt"
awk '$1 == "indirect" {exit !($2 == 0 && $4 == 0)}' "$tmp/compare.txt" ||
  { cat "$tmp/compare.txt"; fail "injected_only differs from standard propagation at 0 iterations"; }
echo "install and out-of-tree strategy: passed"
