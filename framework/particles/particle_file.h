#pragma once
// Reads an experiment's [[particles]] tables (docs/particles.md): the system, its emitters
// ([[particles.emitters]]), its colour and size over the life ([[particles.over_life]]) and
// which model its particles copy. Every value is checked here, with the key named: a missing
// model, a rate or lifetime that is not positive, a speed or lifetime variation larger than its
// mean.

#include <string>
#include <vector>

#include "framework/core/parameters.h"
#include "framework/particles/particle_geometry.h"
#include "framework/particles/particle_system.h"

namespace lpvlab {

struct ParticleSettings {
  ParticleSystem system;
  std::string model;                     // a scene reference, as [scene] file takes
  std::vector<std::string> modelMeshes;  // the model file's meshes to copy; empty: all
  ParticleDrawing drawing;
  Params table;                          // where messages about the model point
};

// `p` is one [[particles]] table, `index` its place among them (the default name).
ParticleSettings readParticleSettings(Params p, int index);

}  // namespace lpvlab
