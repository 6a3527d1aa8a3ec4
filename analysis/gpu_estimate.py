#!/usr/bin/python3
"""Command line entry: the GPU estimate of single runs, for `lpvlab tune` (time = "gpu-estimate").

    /usr/bin/python3 analysis/gpu_estimate.py ROWS.csv --gpu KEY --out OUT.json

See lpvlab_analysis/run_estimates.py. Installed with the package as `lpvlab-gpu-estimate`.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

try:
    from lpvlab_analysis.run_estimates import main  # noqa: E402
except ImportError as missing:  # a Python without the analysis's packages (a bundle's host, say)
    print(f"lpvlab: error: gpu estimate: {sys.executable} lacks the Python package "
          f"'{missing.name}' that the estimate needs (Debian: scripts/install-deps.sh; elsewhere: "
          f"pip install numpy pandas; or set LPVLAB_PYTHON to a Python that has them)", file=sys.stderr)
    sys.exit(2)

if __name__ == "__main__":
    sys.exit(main())
