#include "framework/io/provenance.h"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "io/temp_dir.h"

namespace lpvlab {
namespace {

// Runs a shell command in `dir`, returning its trimmed stdout; fails the test on a non-zero exit.
std::string run(const test::TempDir& dir, const std::string& command) {
  const std::string full = "cd '" + dir.path().string() + "' && " + command + " 2>&1";
  FILE* pipe = ::popen(full.c_str(), "r");
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  EXPECT_EQ(::pclose(pipe), 0) << command << ": " << output;
  while (!output.empty() && std::isspace(static_cast<unsigned char>(output.back())))
    output.pop_back();
  return output;
}

TEST(GitRevision, UnknownOutsideARepository) {
  test::TempDir dir;
  EXPECT_EQ(gitRevision(dir.path().string()), "unknown");
  EXPECT_EQ(gitRevision(dir.file("does-not-exist")), "unknown");
}

TEST(GitRevision, CommitShaThenDirty) {
  test::TempDir dir;
  std::ofstream(dir.file("a.txt")) << "one\n";
  run(dir,
      "git init -q . && git add a.txt && "
      "git -c user.name=test -c user.email=test@example.com commit -q -m first");
  const std::string sha = run(dir, "git rev-parse HEAD");
  ASSERT_EQ(sha.size(), 40u) << sha;
  EXPECT_EQ(gitRevision(dir.path().string()), sha);

  std::ofstream(dir.file("a.txt")) << "two\n";
  EXPECT_EQ(gitRevision(dir.path().string()), sha + "-dirty");
}

TEST(LibraryVersions, NamesOpenImageIO) {
  const nlohmann::json versions = libraryVersions();
  ASSERT_TRUE(versions.contains("openimageio"));
  EXPECT_TRUE(
      std::regex_match(versions["openimageio"].get<std::string>(), std::regex(R"(\d+\.\d+\.\d+)")))
      << versions.dump();
  EXPECT_TRUE(versions.contains("compiler"));
}

TEST(HostInfo, HasPositiveCoreCountAndNames) {
  const nlohmann::json host = hostInfo();
  EXPECT_GT(host.at("logical_cores").get<int>(), 0);
  EXPECT_FALSE(host.at("hostname").get<std::string>().empty());
  EXPECT_FALSE(host.at("os").get<std::string>().empty());
}

TEST(UtcTimestamp, IsIso8601) {
  EXPECT_TRUE(std::regex_match(utcTimestamp(), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << utcTimestamp();
}

}  // namespace
}  // namespace lpvlab
