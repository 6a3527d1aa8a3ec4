#!/bin/sh
# A portable lpvlab: a relocatable folder (and, with --archive, a compressed archive of it split
# into parts) that runs on any x86-64 Linux without root and without apt (docs/bundle.md).
#
#   scripts/bundle.sh [--build DIR] [--out DIR] [--archive] [--level N] [--part-size SIZE]
#                     [--no-osmesa] [--no-build]
#
#   --build DIR       the build tree whose lpvlab is bundled (default: build; built first)
#   --out DIR         where the folder lpvlab-<version>-x86_64/ goes (default: dist)
#   --archive         also write lpvlab-<version>-x86_64.tar.zst split into parts
#                     (.part-00, .part-01, ...) of at most --part-size (default 40M: the GPU
#                     machines this project reaches take 64 MiB per transfer, checkout included)
#   --level N         zstd level of the archive (default 19; 1-3 for a quick one)
#   --no-osmesa       leave out libOSMesa and its LLVM (117 MB): for GPU machines, and for CPU
#                     machines, where runs go without GL (gl.backend = "none")
#   --no-build        bundle the build tree's lpvlab as it is (the tests: they must not rebuild
#                     the tree they test)
#
# The folder:
#   bin/lpvlab              a script that runs the binary through the bundle's own dynamic
#                           loader with the bundle's libraries, so the host's glibc and
#                           libraries do not matter
#   bin/gpu-check           scripts/gpu-check.sh: the whole program checked on a GPU
#   libexec/lpvlab          the binary, stripped
#   lib/                    every shared library it needs, glibc's loader included; glvnd's
#                           vendor-neutral libEGL/libGL/libGLX/libGLdispatch (OpenCV links
#                           libGL); and libOSMesa with its own (opened at run time for
#                           gl.backend = "osmesa" and as "auto"'s last resort)
#   share/lpvlab/           shaders/, experiments/, analysis/ (the report's Python package),
#                           REVISION, README.md
# Not in it: the GPU vendor's GL and EGL implementations (libEGL_nvidia, libEGL_mesa, ...), which
# glvnd finds on the host through its vendor files (a driver must match its kernel module);
# Python and its packages for `lpvlab report` (the host's: LPVLAB_PYTHON names one); ffmpeg for
# videos; scenes other than the built-in Cornell box (LPVLAB_SHARED_DIR).
set -eu

source_dir=$(cd "$(dirname "$0")/.." && pwd)
build=build out=dist archive=0 level=19 part_size=40M osmesa=1 rebuild=1
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --archive) archive=1; shift ;;
    --level) level=$2; shift 2 ;;
    --part-size) part_size=$2; shift 2 ;;
    --no-osmesa) osmesa=0; shift ;;
    --no-build) rebuild=0; shift ;;
    -h|--help) sed -n '2,33p' "$0"; exit 0 ;;
    *) echo "bundle.sh: error: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
case $build in /*) ;; *) build=$source_dir/$build ;; esac
case $out in /*) ;; *) out=$(pwd)/$out ;; esac
for tool in ldd strip tar; do
  command -v "$tool" >/dev/null || { echo "bundle.sh: error: '$tool' is needed" >&2; exit 1; }
done
if [ "$archive" = 1 ] && ! command -v zstd >/dev/null; then
  echo "bundle.sh: error: --archive needs zstd (Debian: apt-get install zstd)" >&2; exit 1
fi

start=$(date +%s)
if [ "$rebuild" = 1 ]; then
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo
  fi
  cmake --build "$build" -j "$(nproc)" --target lpvlab
fi
[ -x "$build/lpvlab" ] || { echo "bundle.sh: error: $build/lpvlab is missing (build it, or drop --no-build)" >&2; exit 1; }
version=$(sed -n 's/^project(lpvlab VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
name=lpvlab-$version-$(uname -m)
folder=$out/$name
partial=$out/.$name.partial
rm -rf "$partial"
mkdir -p "$partial/bin" "$partial/libexec" "$partial/lib" "$partial/share/lpvlab"

# The binary, and the shared libraries it (and libOSMesa, and glvnd's libEGL) need, as the loader
# resolves them here. The GPU vendors' implementations stay the host's: glvnd loads them there.
strip --strip-unneeded -o "$partial/libexec/lpvlab" "$build/lpvlab"
host_only='^(linux-vdso|libEGL_|libGLX_|libnvidia|libcuda)'
closure() {  # the resolved library paths `ldd $1` names, the loader included
  ldd "$1" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3} $1 ~ /^\// {print "ld", $1}'
}
{
  closure "$partial/libexec/lpvlab"
  # glvnd's libEGL, opened at run time, with the libGLdispatch that OpenCV's libGL brings: one
  # glvnd, so that its libraries agree on their private interfaces.
  egl_path=$(ldconfig -p | awk '/libEGL\.so\.1 / && /x86-64/ {print $NF; exit}')
  if [ -n "$egl_path" ]; then
    echo "libEGL.so.1 $egl_path"
    closure "$egl_path"
  fi
  if [ "$osmesa" = 1 ]; then
    osmesa_path=$(ldconfig -p | awk '/libOSMesa\.so\.8 / && /x86-64/ {print $NF; exit}')
    [ -n "$osmesa_path" ] || { echo "bundle.sh: error: libOSMesa.so.8 not found (Debian: libosmesa6), or --no-osmesa" >&2; exit 1; }
    echo "libOSMesa.so.8 $osmesa_path"
    closure "$osmesa_path"
  fi
} | sort -u | while read -r soname path; do
  if [ "$soname" = ld ]; then
    cp -L "$path" "$partial/lib/ld-linux-x86-64.so.2"
    continue
  fi
  if echo "$soname" | grep -Eq "$host_only"; then continue; fi
  [ -f "$partial/lib/$soname" ] || cp -L "$path" "$partial/lib/$soname"
done
[ -f "$partial/lib/ld-linux-x86-64.so.2" ] || { echo "bundle.sh: error: no dynamic loader found by ldd" >&2; exit 1; }
# Debug sections are most of some libraries' size; the loader and libc keep theirs (gdb and
# valgrind want them, and they are small).
for lib in "$partial"/lib/*.so*; do
  case ${lib##*/} in ld-linux*|libc.so*) continue ;; esac
  chmod u+w "$lib"
  strip --strip-unneeded "$lib" 2>/dev/null || true
done

cat > "$partial/bin/lpvlab" <<'WRAPPER'
#!/bin/sh
# lpvlab from the portable bundle: the binary runs through the bundle's own dynamic loader with the
# bundle's libraries (the host's glibc does not matter); a sweep's configurations run through this
# script again (LPVLAB_EXECUTABLE), and shaders and the report come from share/lpvlab.
self=$(readlink -f -- "$0")
root=${self%/bin/*}
export LPVLAB_EXECUTABLE="$self"
export LPVLAB_DATA_DIR="${LPVLAB_DATA_DIR:-$root/share/lpvlab}"
exec "$root/lib/ld-linux-x86-64.so.2" --library-path "$root/lib" --argv0 "$0" \
  "$root/libexec/lpvlab" "$@"
WRAPPER
chmod +x "$partial/bin/lpvlab"
# The whole-program check for a GPU machine (docs/gpu.md): bin/gpu-check runs bin/lpvlab.
cp "$source_dir/scripts/gpu-check.sh" "$partial/bin/gpu-check"

cp -r "$source_dir/shaders" "$source_dir/experiments" "$partial/share/lpvlab/"
mkdir -p "$partial/share/lpvlab/analysis"
cp "$source_dir/analysis/report.py" "$source_dir/analysis/gpu_estimate.py" "$partial/share/lpvlab/analysis/"
cp -r "$source_dir/analysis/lpvlab_analysis" "$partial/share/lpvlab/analysis/"
find "$partial/share/lpvlab" -name __pycache__ -type d -prune -exec rm -rf {} +
cp "$source_dir/README.md" "$partial/share/lpvlab/"
revision=$(git -C "$source_dir" rev-parse HEAD 2>/dev/null || echo unknown)
if [ "$revision" != unknown ] && [ -n "$(git -C "$source_dir" status --porcelain 2>/dev/null)" ]; then
  revision=$revision-dirty
fi
echo "$revision" > "$partial/share/lpvlab/REVISION"

rm -rf "$folder"
mv "$partial" "$folder"
echo "bundle.sh: $folder: $(du -sh "$folder" | cut -f1) ($(ls "$folder/lib" | wc -l) libraries), revision $revision"

if [ "$archive" = 1 ]; then
  tarball=$out/$name.tar.zst
  rm -f "$tarball" "$tarball".part-*
  tar -C "$out" -cf - "$name" | zstd -q -"$level" --long=27 -T0 -o "$tarball.tmp"
  mv "$tarball.tmp" "$tarball"
  split -b "$part_size" -d -a 2 "$tarball" "$tarball.part-"
  (cd "$out" && sha256sum "$name.tar.zst" "$name".tar.zst.part-* > "$name.sha256")
  echo "bundle.sh: $tarball: $(du -h "$tarball" | cut -f1) (zstd -$level), in $(ls "$tarball".part-* | wc -l) parts of at most $part_size:"
  ls -l "$tarball".part-* | awk '{print "  " $NF ": " $5 " bytes"}'
  echo "  unpack: cat $name.tar.zst.part-* | zstd -d --long=27 | tar -x"
fi
echo "bundle.sh: done in $(( $(date +%s) - start )) s"
