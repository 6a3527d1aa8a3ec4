#include "framework/scene/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/core/error.h"
#include "framework/scene/assimp_import.h"

namespace lpvlab {

std::string lowercaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

namespace {

// Assimp loads an OBJ whose material library (`mtllib`) is missing or unreadable without a word,
// every material becoming its default (albedo 0.6): the Cornell box's walls lose their colour.
// So every library an OBJ names must be there; an OBJ without `mtllib` uses the default on
// purpose.
void checkObjMaterialLibraries(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) || keyword != "mtllib") continue;
    // The rest of the line is one file name, as Assimp reads it (it may hold spaces).
    std::string name;
    std::getline(words >> std::ws, name);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
    if (name.empty()) continue;
    {
      const std::filesystem::path library = std::filesystem::path(path).parent_path() / name;
      std::error_code ignored;
      const bool readable = std::filesystem::is_regular_file(library, ignored) &&
                            std::ifstream(library).good();
      if (!readable)
        throwAt(path + ":" + std::to_string(number),
                "material library '" + name + "' cannot be read (" + library.string() +
                    "): its materials would all become the default (albedo 0.6); restore it, or "
                    "remove the mtllib line to use the default on purpose");
    }
  }
}

}  // namespace

Scene loadScene(const std::string& path) {
  // Checked here because Assimp says only "Unable to open file" or "No suitable reader found".
  std::error_code ignored;
  const std::filesystem::file_status status = std::filesystem::status(path, ignored);
  if (!std::filesystem::exists(status)) throwAt(path, "no such file");
  if (std::filesystem::is_directory(status)) throwAt(path, "is a directory, not a scene file");
  const std::string extension = lowercaseExtension(path);
  if (extension != ".gltf" && extension != ".glb" && extension != ".obj")
    throwAt(path, "unsupported scene format " +
                      (extension.empty() ? "(no file extension)" : "'" + extension + "'") +
                      " (lpvlab reads glTF 2.0 .gltf/.glb and OBJ .obj)");

  if (extension == ".obj") checkObjMaterialLibraries(path);
  Scene scene = importWithAssimp(path);
  if (scene.triangleCount() == 0) throwAt(path, "no triangles in the scene");
  return scene;
}

Scene loadSceneByName(const std::string& nameOrPath) {
  if (nameOrPath == "builtin:cornell_box") return makeCornellBox();
  if (nameOrPath.starts_with("builtin:"))
    throwAt(nameOrPath, "no such built-in scene (there is builtin:cornell_box)");
  return loadScene(nameOrPath);
}

}  // namespace lpvlab
