#!/usr/bin/python3
"""Command line entry: build the HTML report of an lpvlab sweep.

    /usr/bin/python3 analysis/report.py DIR [--metric NAME] [--out DIR/report] [--no-exr]

Writes DIR/report/index.html (plus img/ and ablation.md). Exit status 2 with
a one-line message naming the file when DIR or DIR/summary.csv is missing
or the summary is empty.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

try:
    from lpvlab_analysis.report import main  # noqa: E402
except ImportError as missing:  # a Python without the analysis's packages (a bundle's host, say)
    print(f"lpvlab: error: report: {sys.executable} lacks the Python package "
          f"'{missing.name}' that the report needs (Debian: scripts/install-deps.sh; elsewhere: "
          f"pip install numpy pandas matplotlib jinja2; or set LPVLAB_PYTHON to a Python that has them)",
          file=sys.stderr)
    sys.exit(2)

if __name__ == "__main__":
    sys.exit(main())
