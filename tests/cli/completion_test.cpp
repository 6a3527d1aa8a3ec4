// `lpvlab completion bash`: the script, sourced by bash, completes what lpvlab parses: every
// command `lpvlab --help` lists as the first word, a command's own options after it, and file
// names elsewhere. Completions are asked as bash asks them (COMP_WORDS, COMP_CWORD, the function).

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "executable_support.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

// The words bash would offer for the command line `words` (the last one being completed).
std::set<std::string> completions(const test::TempDir& dir, const std::string& script,
                                  const std::string& words) {
  const std::string command = "bash -c " + test::quoted("source " + test::quoted(script) +
                                                        " && COMP_WORDS=(" + words +
                                                        ") && COMP_CWORD=$((${#COMP_WORDS[@]} - 1))"
                                                        "; _lpvlab; printf '%s\\n' \"${COMPREPLY[@]}\"") +
                              " > " + test::quoted(dir.file("words.txt")) + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(dir.file("words.txt"));
  std::set<std::string> out;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.insert(line);
  return out;
}

TEST(Completion, BashCompletesTheCommandsAndEachCommandsOptions) {
  test::TempDir dir;
  const test::LpvlabResult script = test::runLpvlab("completion bash", dir.path(), dir.path());
  ASSERT_EQ(script.exitCode, 0) << script.err;
  { std::ofstream(dir.file("lpvlab.bash")) << script.out; }
  const std::string path = dir.file("lpvlab.bash");

  // Every command of `lpvlab --help` (its "Subcommands:" section: "  name  description").
  const test::LpvlabResult help = test::runLpvlab("--help", dir.path(), dir.path());
  ASSERT_EQ(help.exitCode, 0) << help.err;
  const std::set<std::string> first = completions(dir, path, "lpvlab ''");
  const auto section = help.out.find("Subcommands:");
  ASSERT_NE(section, std::string::npos) << help.out;
  std::istringstream lines(help.out.substr(section));
  std::string line;
  std::getline(lines, line);
  int listed = 0;
  while (std::getline(lines, line) && !line.empty()) {
    std::string name;
    std::istringstream(line) >> name;
    EXPECT_TRUE(first.count(name)) << name << " is not completed";
    ++listed;
  }
  EXPECT_GE(listed, 10);
  EXPECT_EQ(completions(dir, path, "lpvlab sw"), (std::set<std::string>{"sweep"}));

  // A command's own options: sweep's --jobs, report's --time; not another command's.
  EXPECT_EQ(completions(dir, path, "lpvlab sweep --j"), (std::set<std::string>{"--jobs"}));
  EXPECT_EQ(completions(dir, path, "lpvlab report --ti"), (std::set<std::string>{"--time"}));
  EXPECT_TRUE(completions(dir, path, "lpvlab run --j").empty());
  // File names where no option is being typed.
  { std::ofstream(dir.file("experiment_one.toml")) << ""; }
  EXPECT_EQ(completions(dir, path, "lpvlab run " + test::quoted(dir.file("experiment_o"))),
            (std::set<std::string>{dir.file("experiment_one.toml")}));
}

}  // namespace
}  // namespace lpvlab
