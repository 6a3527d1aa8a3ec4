#pragma once
// Scenes from files (glTF 2.0 .gltf/.glb, OBJ/MTL, through Assimp) and the built-in Cornell box.

#include <string>

#include "framework/scene/scene.h"

namespace lpvlab {

// Loads a scene file. Throws an Error naming the file and the problem when the file is missing,
// unreadable, malformed, has no triangles, or has a light lpvlab cannot use (e.g. an area light).
Scene loadScene(const std::string& path);

// "builtin:cornell_box" or a path.
Scene loadSceneByName(const std::string& nameOrPath);

// Cornell's published measured box (metres), with a spot light under the ceiling pointing down
// (120 degree cone, so the ceiling receives only indirect light) and the standard camera.
Scene makeCornellBox();

// A hash of everything in the scene that affects an image: geometry, materials, texture
// contents, lights and cameras.
std::string sceneHash(const Scene& scene);

}  // namespace lpvlab
