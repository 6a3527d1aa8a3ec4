#!/usr/bin/env bash
# Installs lpvlab's build, test and analysis dependencies from Debian 12 packages, skipping what
# is already installed. Needs root (or sudo) only when something is missing.
#   scripts/install-deps.sh           what building and running lpvlab needs
#   scripts/install-deps.sh --tests   also what only the tests need (a Slurm cluster, a browser,
#                                     clang's sanitizers and libFuzzer)
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libglm-dev                       # vectors and matrices (GLSL-compatible)
  glslang-dev glslang-tools        # GLSL -> SPIR-V at run time (glslang's CMake package names glslangValidator)
  libosmesa6-dev libegl-dev        # offscreen GL 4.5 (llvmpipe); EGL for GPUs
  python3-glad                     # generates the GL loader at build time
  libopenimageio-dev               # textures, EXR and PNG images
  libassimp-dev                    # glTF and OBJ scenes
  libembree-dev                    # ray queries of the reference path tracer
  libtbb-dev                       # oneTBB: threads of the CPU kernels
  libbenchmark-dev                 # Google Benchmark: CPU kernel benchmarks
  libceres-dev                     # Ceres Solver 2.1: `lpvlab fit` (least squares, covariance)
  libcgal-dev                      # CGAL 5.5: Delaunay triangulations (incremental instant radiosity)
  libtomlplusplus-dev              # experiment files
  nlohmann-json3-dev               # manifests
  libcli11-dev                     # command line
  libspdlog-dev                    # messages on stderr by level (-q, -v)
  libgtest-dev                     # tests
  ffmpeg                           # the H.264 video of an animated run (the ffmpeg program)
  python3-numpy python3-pandas python3-matplotlib python3-openimageio  # analysis/ and reports
  python3-jinja2                   # the report's HTML page (analysis/lpvlab_analysis/templates)
)
test_packages=(
  slurm-wlm munge                  # tests/cluster: a single-node Slurm cluster runs an emitted sweep
  chromium chromium-driver python3-selenium  # tests/report: the report in a headless browser
  clang libfuzzer-14-dev libclang-rt-14-dev  # LPVLAB_SANITIZE and LPVLAB_FUZZ builds (tests/fuzz)
  valgrind                         # memcheck of the path tracer's tests (docs/testing.md)
  zstd                             # scripts/bundle.sh --archive, which tests/bundle makes
  mmdebstrap                       # tests/bundle: the bundle in bare Debian 11 and 13 roots
  python3-venv python3-setuptools python3-wheel  # tests/analysis_package: pip install of analysis/ in a venv (wheel: setuptools builds one)
)
case "${1:-}" in
  "") ;;
  --tests) packages+=("${test_packages[@]}") ;;
  *) echo "usage: scripts/install-deps.sh [--tests]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
