#pragma once
// The strategy interfaces of the LPV pipeline's stages. A variant implements one of these in
// variants/<stage>/<name>.cpp, reads its parameters in its constructor (from the experiment's
// [<stage>] table: unread keys are errors), and registers itself:
//   LPVLAB_REGISTER(PropagationStrategy, "standard", "one-line description", StandardPropagation);
// The pipeline allocates what the strategies declare (Requirements) and calls them in order:
//   injection -> propagation -> rendering.

#include <string>

#include "framework/core/registry.h"

namespace lpvlab {

struct Frame;
class ShaderCompiler;
struct GridGeometry;

// What a composition of strategies needs; the pipeline allocates only that.
struct Requirements {
  int shOrder = 1;  // SH bands - 1 of the light grid: order 1 = 4 coefficients per channel
};

class Strategy {
public:
  virtual ~Strategy() = default;
  // Adds this strategy's needs to what the others declared.
  virtual void declare(Requirements& requirements) const { (void)requirements; }
  // Compiles kernels and allocates the strategy's own buffers, once per run, after the grid's
  // placement is known; `requirements` is the merged result of every strategy's declare().
  virtual void prepare(ShaderCompiler& shaders, const GridGeometry& grid,
                       const Requirements& requirements) = 0;
  // Bytes of GPU memory this strategy allocated itself (for the manifest).
  virtual std::size_t memoryBytes() const { return 0; }
};

// Fills frame.lightGrid.current with the injected intensity (reflected light of the RSM texels).
class InjectionStrategy : public Strategy {
public:
  virtual void inject(Frame& frame) = 0;
};

// Spreads frame.lightGrid.current through the grid, accumulating into lightGrid.accumulated
// (which the pipeline initialises with the injected grid).
class PropagationStrategy : public Strategy {
public:
  virtual void propagate(Frame& frame) = 0;
  virtual int iterations() const = 0;  // for the throughput figure: cells * iterations / time
};

// Writes the indirect radiance seen through each G-buffer pixel into frame.indirect.
class RenderingStrategy : public Strategy {
public:
  virtual void render(Frame& frame) = 0;
};

}  // namespace lpvlab
