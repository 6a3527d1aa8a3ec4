#pragma once
// An RGBA32F 2D image that lives on GL, on the host, or on both: a frame's output images (direct
// and indirect light) on a backend that mixes GL and CPU kernels. As DualBuffer does for the light
// grid, each side is brought up to date only when a kernel of that side asks for it, so a frame
// whose direct light and rendering run on the CPU clears, writes and reads these images on the
// host alone (no GL clear, read-back or upload of 4 MB images each frame), and one whose kernels
// run on GL never allocates the host copy.
//
// zero() is lazy: each side becomes zeros when it is next asked for, so the side nobody uses is
// never written.

#include <string>

#include "framework/gl/resources.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

class DualImage {
public:
  DualImage() = default;
  DualImage(int width, int height, const std::string& label);

  // GL side, up to date (the host's texels uploaded if the host wrote last); GL may write to it,
  // so the host side is out of date after.
  gl::Texture& texture();
  // Host side, up to date (read back if GL wrote last); the host may write to it.
  HostImage& host();
  const HostImage& hostRead() const;
  void zero();

  int width() const { return gl_.width(); }
  int height() const { return gl_.height(); }
  // Bytes allocated on GL and on the host.
  std::size_t memoryBytes() const { return gl_.bytes() + host_.texels.capacity() * sizeof(glm::vec4); }

private:
  enum class Side { Current, Stale, Zero };  // Zero: to be zeroed when next asked for
  void toGl() const;
  void toHost() const;

  gl::Texture gl_;
  mutable HostImage host_;  // allocated on the first host access
  mutable Side glSide_ = Side::Zero;
  mutable Side hostSide_ = Side::Zero;
};

}  // namespace lpvlab
