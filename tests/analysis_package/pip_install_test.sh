#!/bin/sh
# The analysis package pip-installed into a fresh virtual environment (analysis/pyproject.toml):
# offline, over Debian's numpy, pandas and matplotlib (--system-site-packages). Its command
# lpvlab-report is on PATH, and `lpvlab report` runs it when LPVLAB_PYTHON is not set: with a data
# folder that has no analysis/ at all, the report of a small sweep is still written.
#
#   pip_install_test.sh BUILD_DIR/lpvlab
set -eu
lpvlab=$(readlink -f "$1")
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/lpvlab-pip.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# From a copy: pip builds in the folder it installs from.
cp -r "$source_dir/analysis" "$tmp/analysis"
rm -rf "$tmp/analysis/tests"
/usr/bin/python3 -m venv --system-site-packages "$tmp/venv"
"$tmp/venv/bin/pip" install --quiet --no-index --no-deps --no-build-isolation "$tmp/analysis"
"$tmp/venv/bin/lpvlab-report" --help > /dev/null
"$tmp/venv/bin/lpvlab-gpu-estimate" --help > /dev/null
"$tmp/venv/bin/python" -c "import lpvlab_analysis.gpu_estimate as g, os; assert os.path.isfile(g.DEFAULT_TABLE)"

cat > "$tmp/s.toml" <<'TOML'
[sweep.product]
"propagation.iterations" = [1, 2]
TOML
"$lpvlab" sweep "$tmp/s.toml" --out "$tmp/swept" -s output.width=16 -s output.height=16 \
  -s timing.warmup=0 -s timing.repeats=1 -s grid.resolution=8 > "$tmp/sweep.log" 2>&1
mkdir -p "$tmp/data-without-analysis/shaders"
env -u LPVLAB_PYTHON PATH="$tmp/venv/bin:/usr/bin:/bin" LPVLAB_DATA_DIR="$tmp/data-without-analysis" \
  "$lpvlab" report "$tmp/swept" > "$tmp/report.log" 2>&1 || { cat "$tmp/report.log"; exit 1; }
[ -f "$tmp/swept/report/index.html" ] || { echo "FAIL: no report/index.html"; cat "$tmp/report.log"; exit 1; }
echo "pip install test: passed"
