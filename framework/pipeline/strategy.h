#pragma once
// The strategy interfaces of the LPV pipeline's stages. A variant implements one of these in
// variants/<stage>/<name>.cpp, reads its parameters in its constructor (from the experiment's
// [<stage>] table: unread keys are errors), and registers itself:
//   LPVLAB_REGISTER(PropagationStrategy, "standard", "one-line description", StandardPropagation);
// The pipeline asks every strategy which resources it produces and consumes (declare,
// named_resources.h), refuses compositions that cannot work (a consumed resource nobody produces,
// maxShOrder, refusal), allocates only the resources that are produced and used, lets each
// strategy prepare once with the scene known (prepare), and calls the strategies in order:
//   occlusion -> injection(s) -> propagation -> rendering.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "framework/core/registry.h"
#include "framework/pipeline/named_resources.h"

namespace lpvlab {

struct Frame;
struct DualFrame;
class ShaderCompiler;
class SceneGpu;
struct GridGeometry;
struct LightMaps;

// Where the strategies' kernels run ([compute] backend). The raster passes (shadow maps, RSMs,
// G-buffer) run on GL or by ray casting on the CPU ([compute] raster, host_raster.h).
//   Gl                every strategy on GL
//   Cpu               every strategy on the CPU: one without a CPU kernel for the composition is
//                     refused, saying so
//   CpuWherePossible  "auto" on a software GL renderer (llvmpipe): each strategy on the CPU if it
//                     has a CPU kernel for the composition, else on GL
enum class ComputeBackend { Gl, Cpu, CpuWherePossible };

// What a stage does per frame, apart from the machine that does it (so methods can be compared
// by their work as well as their time): `units` of `unit` ("cell-iteration", "VPL", "pixel"),
// and per unit the kernel's own count of multiply-adds and of bytes read and written (its
// algorithmic traffic, not what reaches DRAM after caches). 0 per unit: not modelled.
struct WorkCount {
  std::string unit;
  double units = 0.0;
  double multiplyAddsPerUnit = 0.0;
  double bytesPerUnit = 0.0;
};

// The sizes of one frame that a strategy's work depends on.
struct FrameShape {
  double cells = 0.0;     // light-grid cells of one level
  int levels = 1;         // cascade levels
  int coefficients = 4;   // SH coefficients per channel
  double rsmTexels = 0.0; // RSM texels over every light view
  double pixels = 0.0;    // output pixels
};

// What a composition of strategies needs; the pipeline allocates only that.
struct Requirements {
  int shOrder = 1;        // SH order of the light grid ([grid] sh_order): (order+1)^2
                          // coefficients per channel
  int cascadeLevels = 1;  // light grids in the cascade ([cascades] levels); every resource
                          // exists once per level
  ComputeBackend backend = ComputeBackend::Gl;
  bool gl = true;  // the run has GL (PipelineSettings::gl); without it the backend is Cpu
  // The resources the run has: produced by one strategy and used by another, each with the
  // producer's allocator (named_resources.h).
  std::map<std::string, ResourceAllocator> resources;

  template <class T>
  bool has(const ResourceKey<T>& key) const {
    return resources.count(std::string(key.name)) > 0;
  }
};

// What a strategy's prepare() sees: the composition, the grid's placement and, in a run, the
// scene (tests of a single kernel may have no scene: then scene and lightMaps are null).
struct StrategySetup {
  ShaderCompiler& shaders;
  const GridGeometry& grid;           // the light grid (every cascade level has its cell counts)
  const Requirements& requirements;   // the merged result of every strategy's declare()
  const SceneGpu* scene = nullptr;    // the scene the run renders
  const LightMaps* lightMaps = nullptr;  // the light views' maps, allocated (not yet rendered)
  glm::ivec2 imageSize{0};            // output pixels
  glm::vec3 skyRadiance{0.0f};        // constant sky, W/(m^2 sr) ([sky] radiance)
};

class Strategy {
public:
  virtual ~Strategy() = default;
  // The resources this strategy produces and consumes (named_resources.h).
  virtual void declare(ResourceUses& uses) const { (void)uses; }
  // The highest SH order this strategy's kernels handle; a grid of higher order is refused.
  virtual int maxShOrder() const { return 1; }
  // Why this strategy cannot run with what the whole composition requires, or "" if it can
  // (beyond the resources it consumes, which the composition check refuses by name).
  virtual std::string refusal(const Requirements& requirements) const {
    (void)requirements;
    return {};
  }
  // Why this strategy has no CPU kernel for this composition, or "" if it has one. The
  // default: none yet.
  virtual std::string cpuRefusal(const Requirements& requirements) const {
    (void)requirements;
    return "it has no CPU kernel yet";
  }
  // What this strategy draws with GL's rasteriser whatever the backend (a depth map, an RSM of
  // its own), named for a refusal when the run has no GL; "" if nothing.
  virtual std::string drawsWithGl() const { return {}; }
  // Whether this strategy runs on the CPU in this composition (see ComputeBackend).
  bool runsOnCpu(const Requirements& requirements) const {
    return requirements.backend == ComputeBackend::Cpu ||
           (requirements.backend == ComputeBackend::CpuWherePossible &&
            cpuRefusal(requirements).empty());
  }
  // Compiles kernels and allocates the strategy's own buffers, once per run, after the grid's
  // placement, the resources and the scene are known.
  virtual void prepare(const StrategySetup& setup) = 0;
  // What this strategy does per frame (see WorkCount), for the kernels it runs in this
  // composition (`requirements`: the backend among others). Empty: not counted yet.
  virtual std::vector<WorkCount> work(const FrameShape& shape,
                                      const Requirements& requirements) const {
    (void)shape;
    (void)requirements;
    return {};
  }
  // Bytes this strategy allocated itself (for the manifest): GL buffers, and the host buffers of
  // its CPU kernel when it runs on the CPU.
  virtual std::size_t memoryBytes() const { return 0; }

  // Derivatives through a frame (dual_frame.h): the real-valued parameters whose derivatives this
  // strategy's kernels on dual numbers carry (the fit takes central differences for the others).
  virtual std::vector<std::string> differentiableParameters() const { return {}; }

  // What this strategy's parameters make suspect, as sentences for the run's warnings (stderr,
  // the manifest's "warnings", summary.csv's column): a configuration that runs, but whose result
  // is not to be trusted as it stands (standard propagation's face solid angles that gain energy).
  virtual std::vector<std::string> warnings() const { return {}; }

  // Whether what a frame computes depends on the frames before it in this run (a strategy that
  // keeps data between frames, e.g. a GV history). A resumed sequence then renders the frames
  // before its first missing one again, unwritten, so that they match an uninterrupted run.
  virtual bool keepsStateBetweenFrames() const { return false; }

  // The registered name, set by the registry when it creates the strategy.
  const std::string& name() const { return name_; }
  void setRegisteredName(std::string name) { name_ = std::move(name); }

private:
  std::string name_;
};

// Adds light to frame.lightGrid.current (the pipeline clears it first; several injection
// strategies may add to the same grid, e.g. RSM VPLs and sky light).
class InjectionStrategy : public Strategy {
public:
  virtual void inject(Frame& frame) = 0;
};

// Fills the resources it produces (e.g. the geometry volume, cleared by the pipeline) with
// blocking potential, or does nothing ("none"). Runs before injection.
class OcclusionStrategy : public Strategy {
public:
  virtual void inject(Frame& frame) = 0;
  // On dual numbers: sets frame.gvBlocking to the GV with its derivatives when one of
  // differentiableParameters() is seeded (else leaves it empty: the frame's GV is a constant).
  virtual void injectDual(DualFrame& frame) { (void)frame; }
};

// Spreads frame.lightGrid.current through the grid, accumulating into lightGrid.accumulated
// (which the pipeline initialises with the injected grid).
class PropagationStrategy : public Strategy {
public:
  virtual void propagate(Frame& frame) = 0;
  virtual int iterations() const = 0;  // for the throughput figure: cells * iterations / time
  // On dual numbers: frame.accumulated from frame.injected (and frame.gvBlocking, or the frame's
  // GV), as propagate would make it. Only where differentiates().
  virtual bool differentiates() const { return false; }
  virtual void propagateDual(DualFrame& frame);
};

// Adds the indirect radiance seen through each G-buffer pixel to frame.indirect (which the
// pipeline zeroes first; [rendering] and each [[rendering.also]] add their share), reading every
// level of frame.renderedLevels() (see framework/pipeline/cascade.h).
class RenderingStrategy : public Strategy {
public:
  virtual void render(Frame& frame) = 0;
  // On dual numbers: adds to *frame.indirect from frame.accumulated, as render adds. Only where
  // differentiates().
  virtual bool differentiates() const { return false; }
  virtual void renderDual(DualFrame& frame);
};

}  // namespace lpvlab
