#pragma once
// Where lpvlab's own files are at run time, so that one binary works from its build tree, from an
// installed prefix and from the portable bundle (scripts/bundle.sh):
//
//   build tree   the source tree it was built from (LPVLAB_SOURCE_DIR): shaders/, analysis/, ...
//   installed    <prefix>/bin/lpvlab beside <prefix>/share/lpvlab/{shaders, experiments, analysis}
//   bundle       the same layout; its bin/lpvlab is a script that runs the real binary through
//                the bundle's own dynamic loader and sets LPVLAB_EXECUTABLE and LPVLAB_DATA_DIR
//
// Environment overrides, for all three: LPVLAB_DATA_DIR (the folder holding shaders/ and
// analysis/), LPVLAB_SHADER_DIR (shaders/ alone), LPVLAB_EXECUTABLE (what a sweep runs for each
// configuration).

#include <filesystem>
#include <string>

namespace lpvlab {

// The command that runs this lpvlab again (a sweep's children, a Slurm job's): LPVLAB_EXECUTABLE,
// else /proc/self/exe.
std::filesystem::path executablePath();

// The folder with shaders/ and analysis/: LPVLAB_DATA_DIR; else <executable>/../share/lpvlab
// where it holds shaders/; else the source tree the binary was built from.
std::filesystem::path dataDirectory();

// True when dataDirectory() is the source tree (a build tree's binary, no override).
bool runsFromSourceTree();

// LPVLAB_SHADER_DIR, else dataDirectory()/shaders.
std::filesystem::path shaderDirectory();

}  // namespace lpvlab
