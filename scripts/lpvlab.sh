#!/usr/bin/env bash
# The two set-up commands of the README:
#   scripts/lpvlab.sh run [ARGS...]   install what is missing, build, run `lpvlab run ARGS...`
#   scripts/lpvlab.sh test            install what is missing, build, run every test (ctest), then
#                                     the sanitizer and fuzzing build (scripts/checked-build.sh)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

command="${1:-}"
shift || true
case "$command" in
  run|test) ;;
  *) echo "usage: scripts/lpvlab.sh run [ARGS...] | test" >&2; exit 2 ;;
esac

# The test command's steps say when they ended: CI has an hour for all of them (.ci/run).
started=$(date +%s)
step() { echo "lpvlab.sh: $1 after $(( $(date +%s) - started )) s"; }
if [ "$command" = test ]; then
  scripts/install-deps.sh --tests
  step "dependencies installed"
else
  scripts/install-deps.sh
fi
jobs="$(nproc)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null

if [ "$command" = run ]; then
  # Only the lpvlab executable: the tests are built by the test command.
  cmake --build build -j "$jobs" --target lpvlab
  exec build/lpvlab run "$@"
fi
cmake --build build -j "$jobs"
step "built"
status=0
(cd build && ctest --output-on-failure -j "$jobs") || status=$?
step "tests ran"
# Then the checked build (clang, AddressSanitizer, UBSan, libFuzzer) in build-checked/: the unit
# tests under the sanitizers and a short fuzzing of every target (docs/testing.md). It runs
# whatever the first tests said, and the command fails if either failed.
scripts/checked-build.sh || status=$?
step "checked build ran"
exit "$status"
