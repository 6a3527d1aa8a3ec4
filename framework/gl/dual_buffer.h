#pragma once
// A buffer of floats that lives on GL, on the host, or on both: the light grid's storage on a
// backend that mixes GL and CPU kernels. Each side is brought up to date when a kernel of that
// side asks for it, so a frame whose kernels all run on the CPU moves no light grid between GL
// and the host (injection, propagation and rendering hand it over on the host), and one whose
// kernels all run on GL never allocates the host copy.
//
// The GL side has gl::Buffer's interface, so GL kernels and tests use it unchanged; binding it
// for a kernel counts as a write on GL (the kernel may write), so the next host access reads it
// back. The host side is host() (read and write) and hostRead() (read only).

#include <cstddef>
#include <string>
#include <vector>

#include "framework/gl/resources.h"

namespace lpvlab {

class DualBuffer {
public:
  DualBuffer() = default;
  DualBuffer(std::size_t bytes, const std::string& label);

  // GL side: each brings GL up to date first (uploads the host's values if the host wrote last).
  GLuint id() const;                                       // GL may write through it
  void bindStorage(GLuint binding) const;                  // GL may write
  void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
  // Reads the up-to-date side, whichever it is.
  void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
  void zero();                                             // both sides 0
  // This buffer becomes a copy of `other` (the same size), on the side(s) `other` is up to date.
  void copyFrom(const DualBuffer& other);
  std::size_t size() const { return gl_.size(); }

  // Host side: read back first if GL wrote last.
  std::vector<float>& host();             // the host may write: GL is out of date after
  const std::vector<float>& hostRead() const;

  // Bytes allocated on GL and on the host.
  std::size_t memoryBytes() const { return gl_.size() + host_.capacity() * sizeof(float); }

private:
  enum class Latest { Both, Gl, Host };
  void toGl() const;
  void toHost() const;

  gl::Buffer gl_;
  mutable std::vector<float> host_;    // allocated on the first host access
  mutable Latest latest_ = Latest::Gl;  // a new buffer: zeros on GL
};

}  // namespace lpvlab
