#include "fuzz/fuzz_workspace.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

namespace lpvlab::fuzz {

namespace fs = std::filesystem;

namespace {

// One triangle, in each format the experiments' shared scenes use.
constexpr const char* kObjStandIn = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
constexpr const char* kGltfStandIn =
    R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"scene":0,"nodes":[{"mesh":0}],)"
    R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[{"bufferView":0,)"
    R"("componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"bufferViews":)"
    R"([{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,"uri":"data:application/)"
    R"(octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";

}  // namespace

FuzzWorkspace& FuzzWorkspace::instance() {
  static FuzzWorkspace workspace;
  return workspace;
}

FuzzWorkspace::FuzzWorkspace() {
  dir_ = fs::temp_directory_path() / ("lpvlab-fuzz-" + std::to_string(getpid()));
  fs::remove_all(dir_);
  fs::create_directories(dir_ / "experiments");
  const fs::path shared = dir_ / "shared";
  const std::regex sharedScene("\"shared:([^\"]+\\.(obj|gltf))\"");
  for (const fs::directory_entry& e :
       fs::directory_iterator(fs::path(LPVLAB_SOURCE_DIR) / "experiments")) {
    if (e.path().extension() != ".toml") continue;
    fs::copy_file(e.path(), dir_ / "experiments" / e.path().filename());
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (std::sregex_iterator m(s.begin(), s.end(), sharedScene), end; m != end; ++m) {
      const fs::path scene = shared / (*m)[1].str();
      fs::create_directories(scene.parent_path());
      std::ofstream((scene).string()) << ((*m)[2] == "obj" ? kObjStandIn : kGltfStandIn);
    }
  }
  setenv("LPVLAB_SHARED_DIR", shared.c_str(), 1);
  setenv("LPVLAB_CACHE_DIR", (dir_ / "cache").c_str(), 1);
}

FuzzWorkspace::~FuzzWorkspace() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

std::string FuzzWorkspace::write(const std::string& name, const std::uint8_t* data,
                                 std::size_t size) const {
  const fs::path path = dir_ / name;
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path.string();
}

std::string FuzzWorkspace::write(const std::string& name, const std::string& text) const {
  return write(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

}  // namespace lpvlab::fuzz
