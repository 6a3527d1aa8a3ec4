#include "framework/core/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "io/temp_dir.h"

namespace lpvlab {
namespace {

using Strings = std::vector<std::string>;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(WriteAtomically, WritesATemporaryBesideTheTargetThenRenames) {
  test::TempDir dir;
  const std::string target = dir.file("out.exr");
  std::string temporary;
  writeAtomically(target, [&](const std::string& file) {
    temporary = file;
    EXPECT_FALSE(std::filesystem::exists(target)) << "target visible before the rename";
    std::ofstream(file) << "data";
  });
  const std::filesystem::path t(temporary);
  EXPECT_EQ(t.parent_path(), dir.path());
  EXPECT_EQ(t.extension(), ".exr");  // image writers choose the format by extension
  EXPECT_EQ(t.stem().string().rfind("out.tmp-", 0), 0u) << temporary;
  EXPECT_EQ(contents(target), "data");
  EXPECT_EQ(dir.entries(), Strings{"out.exr"});
}

TEST(WriteAtomically, ExceptionLeavesNeitherTargetNorTemporary) {
  test::TempDir dir;
  const std::string target = dir.file("out.txt");
  EXPECT_THROW(writeAtomically(target,
                               [](const std::string& file) {
                                 std::ofstream(file) << "half";
                                 throw std::runtime_error("writer failed");
                               }),
               std::runtime_error);
  EXPECT_EQ(dir.entries(), Strings{});
}

TEST(WriteAtomically, ExceptionKeepsThePreviousTarget) {
  test::TempDir dir;
  const std::string target = dir.file("out.txt");
  writeTextAtomically(target, "old");
  EXPECT_THROW(writeAtomically(target, [](const std::string&) { throw std::runtime_error("x"); }),
               std::runtime_error);
  EXPECT_EQ(contents(target), "old");
  EXPECT_EQ(dir.entries(), Strings{"out.txt"});
}

TEST(WriteAtomically, ReplacesExistingTargetWhole) {
  test::TempDir dir;
  const std::string target = dir.file("notes.txt");
  writeTextAtomically(target, "a much longer first version\n");
  writeTextAtomically(target, "short\n");
  EXPECT_EQ(contents(target), "short\n");
  EXPECT_EQ(dir.entries(), Strings{"notes.txt"});
}

TEST(WriteAtomically, CreatesParentDirectories) {
  test::TempDir dir;
  const std::string target = dir.file("runs/a/b/manifest.json");
  writeTextAtomically(target, "{}");
  EXPECT_EQ(contents(target), "{}");
}

}  // namespace
}  // namespace lpvlab
