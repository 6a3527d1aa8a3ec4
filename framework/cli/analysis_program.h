#pragma once
// How lpvlab runs a program of the analysis package (analysis/, Python): `lpvlab report` runs
// analysis/report.py, `lpvlab tune` with time = "gpu-estimate" analysis/gpu_estimate.py. The
// first of:
//   LPVLAB_PYTHON               that Python running the data folder's analysis/<script>.py
//                               (install_layout.h);
//   lpvlab-<name> on PATH       the analysis package pip-installed: its command runs in the
//                               interpreter it was installed into (a virtual environment);
//   /usr/bin/python3            Debian's Python, which sees the python3-* packages (another
//                               python3 on PATH may not), running analysis/<script>.py;
//   python3 on PATH             elsewhere (a bundle's host).

#include <string>
#include <vector>

namespace lpvlab::cli {

// Runs the analysis program `name` ("report", "gpu-estimate") with `arguments`; returns its exit
// status. An Error naming what is missing where neither the program nor a Python can be started.
int runAnalysisProgram(const std::string& name, const std::vector<std::string>& arguments);

}  // namespace lpvlab::cli
