#pragma once
// A composition of strategies, one per stage (several for injection and rendering), and the check that they
// can run together: their merged Requirements, or an Error naming the strategy that refuses.

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "framework/pipeline/strategy.h"

namespace lpvlab {

// LPV's strategies, one per stage (variants/methods/lpv runs them).
struct Strategies {
  std::vector<std::unique_ptr<InjectionStrategy>> injection;  // run in order, adding to the grid
  std::unique_ptr<OcclusionStrategy> occlusion;
  std::unique_ptr<PropagationStrategy> propagation;
  std::vector<std::unique_ptr<RenderingStrategy>> rendering;  // run in order, adding to `indirect`

  // Every strategy with the experiment-file table it came from, e.g. ("propagation", strategy).
  std::vector<std::pair<std::string, Strategy*>> all() const;
};

// The stage whose time a strategy's work shows in, from its experiment table (Strategies::all):
// "injection.also[0]" -> "injection", "rendering" -> "indirect".
std::string stageOfTable(const std::string& table);

// Who declared which uses of resources, e.g. ("[propagation] type = \"directed\"", its uses).
using DeclaredUses = std::vector<std::pair<std::string, ResourceUses>>;

// The resources a run has, from who declared what: each one produced and used (consumed or read)
// by someone, with its first producer's allocator. A consumed resource that nobody produces is an
// Error naming the consumer and the resource.
std::map<std::string, ResourceAllocator> resolveResources(const DeclaredUses& declared);

// Every strategy's declare() resolved (resolveResources), with `alsoDeclared`, the uses of others
// than the strategies (a sky brighter than 0 consumes the sky's light, which some injection
// strategy must produce: variants/resources/sky_light.h), and the raster passes as the producers
// of the raster inputs (raster_inputs.h, which are left out of the resources allocated), starting
// from the grid's SH order and cascade levels, after checking that each strategy handles that
// order and has no refusal.
// With ComputeBackend::Cpu, a strategy without a CPU kernel for the composition is an Error.
// Without GL (`gl` false) the backend is Cpu, and a strategy that draws with GL
// (Strategy::drawsWithGl) or has no CPU kernel is an Error naming its table and type.
Requirements resolveRequirements(const Strategies& strategies, int shOrder,
                                 const DeclaredUses& alsoDeclared = {}, int cascadeLevels = 1,
                                 ComputeBackend backend = ComputeBackend::Gl, bool gl = true);

// "gl", "cpu" or "auto" ([compute] backend) as the backend a run uses, given the GL renderer's
// name: "auto" is CpuWherePossible on a software renderer (llvmpipe, softpipe), else Gl.
ComputeBackend resolveBackend(const std::string& requested, const std::string& glRenderer);
// The backend's name for manifests: "gl", "cpu", "cpu where possible".
std::string backendName(ComputeBackend backend);

}  // namespace lpvlab
