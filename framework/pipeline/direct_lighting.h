#pragma once
// Direct light: Lambertian, shadow-mapped, plus emission (shaders/lighting/direct.comp).

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/frame.h"

namespace lpvlab {

struct ShadowSettings {
  float normalOffsetTexels = 1.5f;  // move the lookup point this many shadow texels along n
  float depthBias = 2e-5f;          // window-depth units subtracted before comparing
};

class DirectLighting {
public:
  DirectLighting(ShaderCompiler& shaders, ShadowSettings settings);
  void render(const GBuffer& gbuffer, const LightMaps& maps, gl::Texture& direct);

private:
  Program program_;
  ShadowSettings settings_;
};


}  // namespace lpvlab
