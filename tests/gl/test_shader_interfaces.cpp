// Every binding point, uniform location, vertex attribute and work-group size of lpvlab's shaders
// is a named constant of an interface file (shaders/<stage>/<name>_interface.glsl), which the
// C++ that binds, sets or dispatches includes: no number is typed twice. This test fails on any
// layout qualifier under shaders/ that spells one as a literal (the interface files themselves are
// compiled as C++ by the code that binds them).

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

// "file:line: text" of every layout qualifier that gives a binding, a uniform's or a vertex
// input's location, or a work-group size as a number.
std::vector<std::string> literalLayouts(const fs::path& root) {
  const std::regex binding(R"(layout\s*\([^)]*\b(binding|local_size_[xyz])\s*=\s*[0-9])");
  const std::regex location(R"(layout\s*\([^)]*\blocation\s*=\s*[0-9])");
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const fs::path& path = entry.path();
    const bool vertex = path.extension() == ".vert";
    std::ifstream in(path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const std::string code = line.substr(0, line.find("//"));
      // A location between shader stages (a fragment shader's inputs, any outputs) is GLSL's
      // alone; a uniform's or a vertex attribute's is C++'s too.
      const bool cppLocation = code.find(" uniform ") != std::string::npos ||
                               (vertex && code.find(") in ") != std::string::npos);
      if (std::regex_search(code, binding) || (cppLocation && std::regex_search(code, location)))
        found.push_back(path.string() + ":" + std::to_string(number) + ": " + line);
    }
  }
  return found;
}

TEST(ShaderInterfaces, NoBindingLocationOrWorkGroupSizeIsALiteral) {
  const std::vector<std::string> literals = literalLayouts(fs::path(LPVLAB_SOURCE_DIR) / "shaders");
  std::string list;
  for (const std::string& l : literals) list += "\n  " + l;
  EXPECT_TRUE(literals.empty()) << "name these in the shader's _interface.glsl:" << list;
}

// The check itself finds what it should: a literal binding, uniform location and group size in a
// shader of its own, but not a fragment input's location.
TEST(ShaderInterfaces, TheCheckFindsLiteralsAndOnlyThem) {
  const fs::path dir = fs::temp_directory_path() / "lpvlab_shader_interface_test";
  fs::create_directories(dir);
  std::ofstream(dir / "probe.comp") << "layout(local_size_x = 8) in;\n"
                                       "layout(std430, binding = 2) buffer B { float b[]; };\n"
                                       "layout(location = 3) uniform float u;\n"
                                       "layout(location = SOME_NAME) uniform float v;\n";
  std::ofstream(dir / "probe.frag") << "layout(location = 0) in vec3 worldPosition;\n"
                                       "layout(location = 0) out vec4 colour;\n";
  const std::vector<std::string> found = literalLayouts(dir);
  fs::remove_all(dir);
  ASSERT_EQ(found.size(), 3u);
  EXPECT_NE(found[0].find("probe.comp:1"), std::string::npos);
}

}  // namespace
