#include "framework/scene/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/scene/assimp_import.h"

namespace lpvlab {

std::string lowercaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

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
