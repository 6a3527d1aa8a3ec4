#pragma once
// Running another program (the report's Python, ffmpeg for a sequence's video) without a shell:
// the arguments go to it as given, so paths with spaces or quotes need no escaping.

#include <string>
#include <vector>

namespace lpvlab {

// Runs args[0] (searched on PATH when it has no '/') with the arguments args[1..] and waits for
// it. Returns its exit status; 127 if it could not be started, 128 + N if signal N ended it.
int runProgram(const std::vector<std::string>& args);

// The path of `name` on PATH, or "" when there is none.
std::string findProgram(const std::string& name);

}  // namespace lpvlab
