#pragma once
// Rendering "subsurface": the subsurface-scattering LPV (SSLPV; thesis 5.4 and 6.9.4;
// docs/variants/subsurface.md#subsurface), a second, self-contained LPV for translucent materials
// (Material::transmittance > 0, set with [[materials]] in the experiment), meant for
// [[rendering.also]] beside the main rendering. Per frame, inside the pipeline's "indirect" stage:
//   1. its own RSM of every light view (shaders/subsurface/rsm.frag): translucent surfaces store
//      the flux they transmit into their object, other surfaces only occlude;
//   2. injection of those texels as VPLs along the INWARD normal, without the one-cell shift (the
//      RSM injection kernel, "rsm_vpl" with shift 0, on this RSM and grid);
//   3. propagation as "standard" (the same face loop), every step multiplied by the attenuation
//      constant a = exp(-sigma s) of the material (extinction sigma, 1/m; cell size s, m);
//   4. at camera pixels that see a translucent surface (its own camera mask,
//      shaders/subsurface/mask.frag), the light leaving that surface, L_o = <I, cosLobe(n)> /
//      (pi s^2), ADDED to the indirect image (shaders/subsurface/render.comp); other pixels keep
//      exactly what they had.
// On the CPU backend steps 2-4 run on the CPU (its RSM and camera mask are still rasterised on
// GL and read back): the RSM injection's CPU kernel, the standard CPU kernel with a transfer
// scaled by a (linear in it: a max(0, Omega I) = max(0, a Omega I)), and the shading's
// (subsurface_cpu.h, the same shared GLSL as render.comp).
// Its grid is fitted to the translucent materials' triangles. One grid has one attenuation, so
// all translucent materials of a scene must share one extinction. The grid, RSM and mask are
// made in prepare(), which sees the scene, its light views and the image size.
//
// | parameter      | type  | default | meaning                                                  |
// |----------------|-------|---------|----------------------------------------------------------|
// | resolution     | int   | 16      | SSLPV cells along the translucent objects' longest axis  |
// |                |       |         | (2..256)                                                 |
// | margin         | float | 1.0     | empty cells around the translucent objects' bounds       |
// | iterations     | int   | 16      | propagation steps (0..4096); light moves one cell each   |
// | rsm_resolution | int   | 128     | SSLPV RSM texels per side per light view (1..4096)       |

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/light_grid.h"
#include "framework/pipeline/strategy.h"
#include "variants/propagation/standard_cpu_frame.h"

namespace lpvlab {

class Params;
class SceneGpu;
class InjectionStrategy;

class SubsurfaceRendering final : public RenderingStrategy {
public:
  explicit SubsurfaceRendering(Params& params);
  ~SubsurfaceRendering() override;

  int maxShOrder() const override { return 3; }
  std::string cpuRefusal(const Requirements&) const override { return {}; }
  std::string drawsWithGl() const override {
    return "its translucent surfaces' RSM and mask (subsurface/rsm.frag, mask.frag)";
  }
  void prepare(const StrategySetup& setup) override;
  void render(Frame& frame) override;
  std::size_t memoryBytes() const override;

  // The attenuation per propagation step of a medium of extinction sigma (1/m) on cells of size
  // s (m): the light moves one cell per step, so a = exp(-sigma s).
  static float stepAttenuation(float extinction, float cellSize);

  // The steps of render(), for tests.
  // Makes the SSLPV for the scene's translucent materials, its light views and the image size
  // (prepare() does, when it is given a scene); false, and nothing made, when there are none.
  bool setUp(const SceneGpu& scene, const LightMaps& lightMaps, glm::ivec2 imageSize);
  // A grid of this placement with this extinction, without the scene (setUp() calls it).
  void allocateGrid(const GridGeometry& geometry, float extinction);
  void renderRsm(const Frame& frame);
  void inject(const Frame& frame);  // into grid().current and grid().accumulated
  void propagate();                 // iterations() steps
  void shade(Frame& frame);         // the camera mask, then the light added to frame.indirect
  bool onCpu() const { return onCpu_; }

  int iterations() const { return iterations_; }
  const LightGrid& grid() const { return grid_; }
  LightGrid& grid() { return grid_; }
  float attenuation() const { return attenuation_; }
  const LightMaps& rsm() const { return rsm_; }
  const gl::Texture& mask() const { return mask_; }

private:
  int resolution_, iterations_, rsmResolution_;
  float marginCells_;
  int shOrder_ = 1;
  ComputeBackend backend_ = ComputeBackend::Gl;
  bool onCpu_ = false;
  StandardCpuFrame cpu_;  // on the CPU backend: the attenuated transfer
  Program rsmProgram_, maskProgram_, propagateProgram_, renderProgram_;
  std::unique_ptr<InjectionStrategy> injection_;  // "rsm_vpl", shift 0, on rsm_ and grid_
  bool active_ = false;              // the scene has translucent surfaces
  LightGrid grid_;
  DualBuffer scratch_;               // the propagation's ping-pong partner of grid_.current
  float attenuation_ = 1.0f;
  gl::Buffer translucency_;          // per material: rgb transmittance, a extinction
  LightMaps rsm_;
  std::vector<glm::mat4> rsmClipFromWorld_;  // per light view
  std::vector<gl::Framebuffer> rsmFramebuffers_;
  gl::Texture mask_, maskDepth_;
  std::optional<gl::Framebuffer> maskFramebuffer_;
};

}  // namespace lpvlab
