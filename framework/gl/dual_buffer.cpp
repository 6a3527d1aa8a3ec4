#include "framework/gl/dual_buffer.h"

#include <algorithm>

#include "framework/core/error.h"

namespace lpvlab {

DualBuffer::DualBuffer(std::size_t bytes, const std::string& label) : gl_(bytes, label) {
  if (bytes % sizeof(float) != 0)
    throw Error("buffer '" + label + "': " + std::to_string(bytes) + " bytes is not whole floats");
}

void DualBuffer::toGl() const {
  if (latest_ != Latest::Host) return;
  // gl::Buffer::upload is not const: the GL object is written, its handle is unchanged.
  const_cast<gl::Buffer&>(gl_).upload(host_.data(), host_.size() * sizeof(float));
  latest_ = Latest::Both;
}

void DualBuffer::toHost() const {
  if (host_.size() != gl_.size() / sizeof(float)) {
    host_.resize(gl_.size() / sizeof(float));
    if (latest_ == Latest::Both) latest_ = Latest::Gl;  // the new host copy holds nothing yet
  }
  if (latest_ != Latest::Gl) return;
  gl::barrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // after GL's shader writes
  gl_.download(host_.data(), host_.size() * sizeof(float));
  latest_ = Latest::Both;
}

GLuint DualBuffer::id() const {
  toGl();
  latest_ = Latest::Gl;
  return gl_.id();
}

void DualBuffer::bindStorage(GLuint binding) const {
  toGl();
  latest_ = Latest::Gl;
  gl_.bindStorage(binding);
}

void DualBuffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
  if (bytes < gl_.size()) toGl();  // a part: the rest must be current on GL
  gl_.upload(data, bytes, offset);
  latest_ = Latest::Gl;
}

void DualBuffer::download(void* data, std::size_t bytes, std::size_t offset) const {
  if (latest_ == Latest::Host) {
    if (offset + bytes > gl_.size())
      throw Error("buffer '" + gl_.label() + "': reading " + std::to_string(bytes) + " bytes at " +
                  std::to_string(offset) + " from " + std::to_string(gl_.size()));
    const char* from = reinterpret_cast<const char*>(host_.data()) + offset;
    std::copy(from, from + bytes, static_cast<char*>(data));
    return;
  }
  gl_.download(data, bytes, offset);
}

void DualBuffer::zero() {
  gl_.zero();
  if (!host_.empty()) {
    std::fill(host_.begin(), host_.end(), 0.0f);
    latest_ = Latest::Both;
  } else {
    latest_ = Latest::Gl;
  }
}

void DualBuffer::copyFrom(const DualBuffer& other) {
  if (other.size() != size())
    throw Error("buffer '" + gl_.label() + "': copying " + std::to_string(other.size()) +
                " bytes into " + std::to_string(size()));
  if (other.latest_ != Latest::Host) {
    gl_.copyFrom(other.gl_);  // on GL (or, without GL, gl::Buffer's host bytes)
    latest_ = Latest::Gl;
  }
  if (other.latest_ != Latest::Gl) {
    host_ = other.host_;
    latest_ = other.latest_ == Latest::Host ? Latest::Host : Latest::Both;
  }
}

std::vector<float>& DualBuffer::host() {
  toHost();
  latest_ = Latest::Host;
  return host_;
}

const std::vector<float>& DualBuffer::hostRead() const {
  toHost();
  return host_;
}

}  // namespace lpvlab
