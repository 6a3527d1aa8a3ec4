#pragma once
// Resolves GLSL `#include "x"` for glslang: relative to the including file first, then relative
// to the shader root (`#include <x>`: the root only). Names handed back to glslang are paths
// relative to the root, and glslang writes them into its `#line` bookkeeping, so its messages
// about an included file read "common/sh.glsl:12: ...".

#include <filesystem>
#include <optional>
#include <string>

#include <glslang/Public/ShaderLang.h>

namespace lpvlab {

class ShaderIncluder : public glslang::TShader::Includer {
public:
  explicit ShaderIncluder(std::filesystem::path root) : root_(std::move(root)) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* result) override;

private:
  // glslang itself follows an include cycle until the process hangs.
  static constexpr std::size_t kMaxDepth = 32;
  // The root-relative name and contents of `candidate` (relative to the root), or nullptr when
  // it is no readable file.
  IncludeResult* open(const std::filesystem::path& candidate) const;
  static IncludeResult* failure(const std::string& why);
  std::filesystem::path root_;
};

// The text of a file, or nothing when it cannot be read.
std::optional<std::string> readTextFile(const std::filesystem::path& path);

}  // namespace lpvlab
