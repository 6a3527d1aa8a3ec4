#!/usr/bin/env bash
# The path tracer's tests (build/tests/test_reference) under Valgrind's memcheck, with origins
# tracked for uninitialised values (docs/testing.md). Not in CI: memcheck runs them ~50x slower.
# Valgrind 3.19 cannot execute Debian 12's libhwy (an RDTSCP in its static initialiser, reached
# through OpenImageIO -> libjxl), so a stand-in built from tests/sanitizers/valgrind_hwy_stub.cpp
# is loaded in its place. Valgrind emulates no AVX-512: Embree's AVX-512 tests report that the
# CPU lacks it, and the other instruction sets run. Extra arguments go to the test binary
# (e.g. --gtest_filter=Isa/CornellBoxDeterminism.*).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
stub="$root/build/valgrind"
mkdir -p "$stub"
printf 'HWY_0 { global: *; };\n' > "$stub/hwy.map"
g++ -std=c++17 -O1 -shared -fPIC -Wl,-soname,libhwy.so.1 -Wl,--version-script="$stub/hwy.map" \
  "$root/tests/sanitizers/valgrind_hwy_stub.cpp" -o "$stub/libhwy.so.1"
cd "$root/build"
LD_LIBRARY_PATH="$stub" valgrind --tool=memcheck --track-origins=yes --error-exitcode=1 \
  --num-callers=30 ./tests/test_reference "$@"
