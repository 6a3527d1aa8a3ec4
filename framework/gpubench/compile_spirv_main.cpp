// lpvlab-compile-spirv SHADER_ROOT OUT_DIR: every compute shader under SHADER_ROOT compiled to
// SPIR-V as lpvlab compiles it at run time (ShaderCompiler::compileToSpirv), written to
// OUT_DIR/<path>.spv. The build runs it for lpvlab-gpubench, which loads that SPIR-V
// (ShaderCompiler::precompiled) and so needs no glslang; specialisation still happens at run time.

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "framework/core/atomic_file.h"
#include "framework/gl/shader_compiler.h"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc != 3) {
    std::cerr << "usage: lpvlab-compile-spirv SHADER_ROOT OUT_DIR\n";
    return 2;
  }
  const fs::path root = argv[1], out = argv[2];
  try {
    lpvlab::ShaderCompiler compiler(root);
    std::vector<std::string> paths;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root))
      if (entry.is_regular_file() && entry.path().extension() == ".comp")
        paths.push_back(fs::relative(entry.path(), root).generic_string());
    std::size_t bytes = 0;
    for (const std::string& path : paths) {
      const std::vector<std::uint32_t> spirv = compiler.compileToSpirv(path);
      const std::string text(reinterpret_cast<const char*>(spirv.data()), spirv.size() * 4);
      lpvlab::writeTextAtomically((out / (path + ".spv")).string(), text);
      bytes += text.size();
    }
    std::printf("lpvlab-compile-spirv: %zu compute shaders, %zu bytes of SPIR-V in %s\n",
                paths.size(), bytes, out.string().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "lpvlab-compile-spirv: error: " << e.what() << "\n";
    return 1;
  }
}
