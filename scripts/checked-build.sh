#!/usr/bin/env bash
# The checked build (docs/testing.md): clang with AddressSanitizer, UndefinedBehaviorSanitizer and
# libFuzzer's coverage into build-checked/, then its unit tests under the sanitizers and every fuzz
# target for LPVLAB_FUZZ_SECONDS (default 20) each. `scripts/lpvlab.sh test` runs it after the
# main tests; run by hand after `scripts/install-deps.sh --tests`.
#   scripts/checked-build.sh            configure, build, test
#   scripts/checked-build.sh --build    configure and build only
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
jobs="$(nproc)"
# -O1 keeps the sanitizers' reports exact and compiles the dual-number kernels far faster than -O2.
cmake -S . -B build-checked -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DLPVLAB_SANITIZE=address,undefined -DLPVLAB_FUZZ=ON \
  -DLPVLAB_FUZZ_SECONDS="${LPVLAB_FUZZ_SECONDS:-20}" >/dev/null
cmake --build build-checked -j "$jobs"
[ "${1:-}" = --build ] && exit 0
cd build-checked
# The tests that drive a GL context through Mesa's llvmpipe are left out: llvmpipe's JIT and
# Mesa's own allocations are not lpvlab's code, and under ASan they take ~10x as long.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --output-on-failure -j "$jobs" -L checked
