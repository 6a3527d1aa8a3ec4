#pragma once
// `lpvlab completion bash`: a bash completion script generated from the command line's own
// definitions (main.cpp), so it offers exactly the commands and options lpvlab parses.

#include <string>

namespace CLI {
class App;
}

namespace lpvlab::cli {

// The script: a completion function for `lpvlab` offering the commands as the first word, each
// command's options after it (and --help), and file names elsewhere.
std::string bashCompletion(const CLI::App& app);

}  // namespace lpvlab::cli
