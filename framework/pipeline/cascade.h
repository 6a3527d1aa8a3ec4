#pragma once
// Cascaded light grids (thesis 5.1, [cascades] in an experiment): the levels' placement is
// framework/math/cascade_placement.h; this file has what the pipeline and rendering kernels do with
// them. The pipeline runs occlusion, injection and propagation once per level (each level is an
// independent LPV of its region, with its own GV and normal grid when those exist), optionally
// carries each level's injected light into its parent before propagation, and calls rendering
// strategies once: they read every level (Frame::renderedLevels) and weight each by
// shaders/common/cascade_blend.glsl, whose uniforms setCascadeBlendUniforms binds.

#include <vector>

#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/kernel_work.h"
#include "framework/pipeline/light_grid.h"

namespace lpvlab {

struct Frame;

// Where the finer levels are centred (framework/math/cascade_placement.h).
enum class CascadePlacement {
  Eye,    // the eye moved viewShift of the level's extent along the view direction
  Depth,  // what the camera sees: the median of the G-buffer's positions, read back every frame
};

struct CascadeSettings {
  int levels = 1;           // 1: one grid, fitted to the scene (no camera following)
  float blendCells = 2.0f;  // width of the band, in cells of the finer level, where two levels mix
  CascadePlacement placement = CascadePlacement::Eye;
  float viewShift = 0.25f;  // "eye" placement (and "depth" when the camera sees nothing): a finer
                            // level's centre is the eye moved this fraction of its extent ahead
  bool carry = true;        // parents propagate their children's injected light (restrict.comp)
  bool snap = true;         // finer levels start on whole cells of their parents: they stay put
                            // under camera moves that cross no cell (off: an ablation; no carry)
};

// Binds the uniforms of shaders/common/cascade_blend.glsl for a kernel (in use) that renders
// `level` of frame.renderedLevels().
void setCascadeBlendUniforms(const Frame& frame, int level);

// Replaces the injected light (`current`) of `parent` inside `child` by the child's, summed over
// each parent cell's 2x2x2 children (shaders/cascade/restrict.glsl), on GL (restrict.comp) or, on
// the CPU backend, on both grids' host sides.
// The GL carry's work per parent cell written (the parent cells inside the child: half the child's
// cells along each axis), with N coefficients per channel: 8 child cells' 3N floats read and 3N
// written; 8 adds per coefficient.
inline KernelWork cascadeCarryGlWork(int coefficients) {
  const double n = coefficients;
  return {8 * 3 * n, 4 * (8 * 3 * n + 3 * n)};
}

class CascadeCarry {
public:
  CascadeCarry(ShaderCompiler& shaders, int shOrder, bool onCpu);
  void carry(const LightGrid& child, LightGrid& parent);

private:
  void carryOnCpu(const LightGrid& child, LightGrid& parent, const glm::ivec3& offset);

  Program program_;
  int coefficients_;
  bool onCpu_;
};

}  // namespace lpvlab
