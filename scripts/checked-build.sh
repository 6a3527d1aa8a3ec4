#!/usr/bin/env bash
# The checked build (docs/testing.md): clang with AddressSanitizer, UndefinedBehaviorSanitizer and
# libFuzzer's coverage into build-checked/, then its unit tests under the sanitizers and every fuzz
# target for LPVLAB_FUZZ_SECONDS (default 15) each. `scripts/lpvlab.sh test` runs it after the
# main tests; run by hand after `scripts/install-deps.sh --tests`.
#   scripts/checked-build.sh            configure, build, run what CI runs (below)
#   scripts/checked-build.sh --build    configure and build only
#   scripts/checked-build.sh --all      configure, build, run every test under the sanitizers
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
jobs="$(nproc)"
# -O0: the dual-number kernels take minutes per file to optimise (16 s at -O0 against over 10 min
# at -O1 for standard_cpu.cpp); the sanitizers need no optimisation. -g1 (line tables): reports
# name file and line, and the build is faster than with full debug information.
cmake -S . -B build-checked -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O0 -g1" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DLPVLAB_SANITIZE=address,undefined -DLPVLAB_FUZZ=ON \
  -DLPVLAB_FUZZ_SECONDS="${LPVLAB_FUZZ_SECONDS:-15}" >/dev/null
if [ -z "${1:-}" ]; then
  # What CI runs needs only target lpvlab_checked (tests/CMakeLists.txt): not the end-to-end
  # pipeline tests, the command line or the benchmarks, about a third of the build.
  cmake --build build-checked -j "$jobs" --target lpvlab_checked
else
  cmake --build build-checked -j "$jobs"
fi
[ "${1:-}" = --build ] && exit 0
cd build-checked
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Leaks inside Mesa, LLVM and Assimp are theirs (the file says which and why).
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
if [ "${1:-}" = --all ]; then
  # Every test but the Slurm and browser ones (processes outside lpvlab): about 12 min of
  # the pipeline's end-to-end runs at -O0 under the sanitizers.
  exec ctest --output-on-failure -j "$jobs" -E "^(slurm_cluster|report_browser|fuzz)$"
fi
# What CI runs (about 6 min): the unit tests of the modules below the pipeline and the CPU
# kernels' tests against GL on llvmpipe (label `checked`: core, math, scene, io, metrics, gl,
# reference, animation, kernels), the fuzz targets' kept inputs and a short fuzzing of each, and
# the frames on dual numbers. The pipeline's and the fit's other end-to-end tests run with --all.
ctest --output-on-failure -j "$jobs" -L checked
ctest --output-on-failure -j "$jobs" -R "^FrameDerivatives\."
