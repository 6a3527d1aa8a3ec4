#!/bin/sh
# lpvlab-gpubench on a GPU machine (docs/gpu.md#gpubench): the strategies' GL kernels timed alone.
# lpvlab-gpubench and its SPIR-V make an archive of under 1 MB that needs no package on the GPU
# machine beyond its driver (GL through EGL, opened at run time, and the C/C++ runtimes).
#
#   scripts/gpu-kernels.sh pack [--build DIR] [--out DIR]
#       makes lpvlab-gpubench-x86_64.tar.gz in --out (default dist/) from the build tree DIR
#       (default build/) and prints its size
#   scripts/gpu-kernels.sh run [ARCHIVE] [-- GPUBENCH OPTIONS]
#       unpacks ARCHIVE (default: the one pack makes) into a temporary folder and runs it there:
#       the table on stdout, JSON in $OUT/gpubench.json (OUT defaults to gpubench-<UTC time>)
#   scripts/gpu-kernels.sh ssh HOST [-- GPUBENCH OPTIONS]
#       packs, copies the archive and this script to HOST and runs them there, in one call;
#       the JSON comes back to gpubench-<UTC time>/gpubench.json
#
# GPUBENCH OPTIONS are lpvlab-gpubench's (its --help): e.g. --grids 32,64,128 --orders 1,3
# --cases standard_gather,standard_gather_tiled. Without them it runs every case at grids 16-128
# and SH orders 1-3, through EGL (--backend egl).
set -eu

here=$(cd "$(dirname "$0")" && pwd)
archive_name=lpvlab-gpubench-x86_64.tar.gz

pack() {
  build=$here/../build dist=$here/../dist
  while [ $# -gt 0 ]; do
    case $1 in
      --build) build=$2; shift 2 ;;
      --out) dist=$2; shift 2 ;;
      *) echo "gpu-kernels: error: pack: unknown argument '$1'" >&2; exit 2 ;;
    esac
  done
  [ -x "$build/lpvlab-gpubench" ] && [ -d "$build/spirv" ] || {
    echo "gpu-kernels: error: $build has no lpvlab-gpubench and spirv/: build the lpvlab-gpubench target" >&2
    exit 2
  }
  stage=$(mktemp -d "${TMPDIR:-/tmp}/lpvlab-gpubench.XXXXXX")
  trap 'rm -rf "$stage"' EXIT
  mkdir -p "$stage/lpvlab-gpubench/bin" "$stage/lpvlab-gpubench/share/lpvlab"
  strip -o "$stage/lpvlab-gpubench/bin/lpvlab-gpubench" "$build/lpvlab-gpubench"
  cp -r "$build/spirv" "$stage/lpvlab-gpubench/share/lpvlab/spirv"
  rm -f "$stage/lpvlab-gpubench/share/lpvlab/spirv/.compiled"
  mkdir -p "$dist"
  out=$(cd "$dist" && pwd)/$archive_name
  tar -C "$stage" -czf "$out.tmp" lpvlab-gpubench
  mv "$out.tmp" "$out"
  echo "gpu-kernels: $out: $(wc -c < "$out") bytes"
}

run() {
  archive=$here/../dist/$archive_name
  if [ $# -gt 0 ] && [ "$1" != "--" ]; then archive=$1; shift; fi
  [ "${1:-}" = "--" ] && shift
  [ -f "$archive" ] || { echo "gpu-kernels: error: no archive $archive (run: $0 pack)" >&2; exit 2; }
  out=${OUT:-gpubench-$(date -u +%Y%m%dT%H%M%SZ)}
  mkdir -p "$out"
  unpacked=$(mktemp -d "${TMPDIR:-/tmp}/lpvlab-gpubench-run.XXXXXX")
  trap 'rm -rf "$unpacked"' EXIT
  tar -C "$unpacked" -xzf "$archive"
  case " $* " in *" --backend "*) backend="" ;; *) backend="--backend egl" ;; esac
  # shellcheck disable=SC2086
  "$unpacked/lpvlab-gpubench/bin/lpvlab-gpubench" $backend --json "$out/gpubench.json" "$@"
  echo "gpu-kernels: results in $out/gpubench.json"
}

remote() {
  host=$1; shift
  [ "${1:-}" = "--" ] && shift
  pack
  remote_dir=lpvlab-gpubench-$$
  ssh "$host" "mkdir -p $remote_dir"
  scp -q "$here/../dist/$archive_name" "$0" "$host:$remote_dir/"
  out=gpubench-$(date -u +%Y%m%dT%H%M%SZ)
  # shellcheck disable=SC2029
  ssh "$host" "cd $remote_dir && OUT=out sh ./gpu-kernels.sh run $archive_name -- $*"
  mkdir -p "$out"
  scp -q "$host:$remote_dir/out/gpubench.json" "$out/"
  ssh "$host" "rm -rf $remote_dir"
  echo "gpu-kernels: $out/gpubench.json"
}

command=${1:-}
[ $# -gt 0 ] && shift
case $command in
  pack) pack "$@" ;;
  run) run "$@" ;;
  ssh) [ $# -gt 0 ] || { echo "gpu-kernels: error: ssh needs a HOST" >&2; exit 2; }; remote "$@" ;;
  -h|--help|"") sed -n '2,20p' "$0"; [ -n "$command" ] || exit 2 ;;
  *) echo "gpu-kernels: error: unknown command '$command' (pack, run or ssh; see --help)" >&2; exit 2 ;;
esac
