#include "framework/gl/shader_includer.h"

#include <fstream>
#include <sstream>

namespace lpvlab {

std::optional<std::string> readTextFile(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

ShaderIncluder::IncludeResult* ShaderIncluder::open(const std::filesystem::path& candidate) const {
  const std::filesystem::path name = candidate.lexically_normal();
  std::optional<std::string> text = readTextFile(root_ / name);
  if (!text) return nullptr;
  // The result points into the string it owns through userData; releaseInclude frees both.
  auto* owned = new std::string(std::move(*text));
  return new IncludeResult(name.generic_string(), owned->data(), owned->size(), owned);
}

ShaderIncluder::IncludeResult* ShaderIncluder::includeLocal(const char* header,
                                                            const char* includer,
                                                            size_t depth) {
  if (depth > kMaxDepth) return nullptr;
  const std::filesystem::path besideIncluder =
      std::filesystem::path(includer).parent_path() / header;
  if (IncludeResult* found = open(besideIncluder)) return found;
  // On nullptr glslang goes on to includeSystem, which searches the root (and fails deep ones).
  return nullptr;
}

ShaderIncluder::IncludeResult* ShaderIncluder::includeSystem(const char* header,
                                                             const char* includer,
                                                             size_t depth) {
  if (depth > kMaxDepth)
    return failure("nested more than " + std::to_string(kMaxDepth) +
                   " deep (an include cycle? guard shared files with #ifndef)");
  if (IncludeResult* found = open(header)) return found;
  return failure("not found (searched beside " + std::string(includer) +
                 ", then in the shader root " + root_.string() + ")");
}

ShaderIncluder::IncludeResult* ShaderIncluder::failure(const std::string& why) {
  // An empty name marks failure; glslang puts the text into its error at the #include line.
  auto* message = new std::string(why);
  return new IncludeResult("", message->data(), message->size(), message);
}

void ShaderIncluder::releaseInclude(IncludeResult* result) {
  if (!result) return;
  delete static_cast<std::string*>(result->userData);
  delete result;
}

}  // namespace lpvlab
