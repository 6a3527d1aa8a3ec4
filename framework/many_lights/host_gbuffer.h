#pragma once
// A frame's G-buffer on the host, for the many-light methods' CPU gathers (HostImages: RGBA,
// bottom row first; read back once per frame by HostReadback).

#include "framework/pipeline/frame.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

struct HostGBuffer {
  const HostImage& position;  // world position, w = 1 where a surface was hit
  const HostImage& normal;    // unit normal facing the camera
  const HostImage& albedo;
};

inline HostGBuffer hostGBuffer(HostReadback& host, const GBuffer& gbuffer) {
  return {host.image(gbuffer.position), host.image(gbuffer.normal), host.image(gbuffer.albedo)};
}

}  // namespace lpvlab
