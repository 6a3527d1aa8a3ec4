#!/usr/bin/env bash
# Runs every fuzz target of an LPVLAB_FUZZ build (or those named) for SECONDS each, one after
# another, each with its own corpus folder under WORKDIR (default: ./fuzz-runs), and reports
# executions, coverage and the time per target. Exits non-zero after the first target that finds
# a crash, a leak, a sanitizer report, a timeout or an out-of-memory; libFuzzer leaves the input
# as WORKDIR/<target>/crash-* (or leak-, timeout-, oom-): put it under
# tests/fuzz/regressions/<target>/, fix the bug, and test_fuzz replays it in every build.
#   tests/fuzz/run_fuzzers.sh build-fuzz/tests/fuzz_lpvlab 3600          an hour per target
#   tests/fuzz/run_fuzzers.sh build-fuzz/tests/fuzz_lpvlab 60 scene_file
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: tests/fuzz/run_fuzzers.sh FUZZ_LPVLAB SECONDS [TARGET...]" >&2
  exit 2
fi
fuzzer="$(realpath "$1")"
seconds="$2"
shift 2
workdir="${WORKDIR:-$PWD/fuzz-runs}"
targets=("$@")
[ ${#targets[@]} -gt 0 ] || mapfile -t targets < <("$fuzzer" -lpvlab_list)
# Leak detection stays on; leaks inside Assimp are its own (tests/sanitizers/lsan.supp says which).
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(cd "$(dirname "$0")/../sanitizers" && pwd)/lsan.supp:print_suppressions=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
for target in "${targets[@]}"; do
  mkdir -p "$workdir/$target/corpus"
  cd "$workdir/$target"
  echo "fuzz: $target for $seconds s"
  set +e
  "$fuzzer" -lpvlab_target="$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 \
    -max_len=65536 -print_final_stats=1 corpus >"log.txt" 2>&1
  status=$?
  set -e
  grep -E "^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)|^#[0-9]+.*DONE" log.txt \
    | sed "s/^/  $target: /" || true
  echo "  $target: corpus of $(ls corpus | wc -l) inputs; log: $workdir/$target/log.txt"
  if [ $status -ne 0 ]; then
    echo "fuzz: $target FAILED (exit $status):" >&2
    tail -n 40 log.txt >&2
    exit 1
  fi
done
echo "fuzz: ${#targets[@]} targets, $seconds s each, no failure"
