#pragma once
// Owned GL objects (move-only RAII), created with direct state access. Sizes are in bytes unless
// stated. Each object carries a label that GL debug output and lpvlab's errors name.
//
// Without GL (gl.backend = "none", context.h) buffers and textures still exist, on the host: a
// buffer keeps its bytes in memory (upload, download, zero and copies work, so DualBuffer's GL
// side does too), a texture is its size and a name unique in the process (what HostReadback keys
// its images by); binding either for a GL kernel, and any framebuffer, is an Error saying that
// the run has no GL.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glad/gl.h>

namespace lpvlab {
namespace gl {

class Buffer {
public:
  Buffer() = default;
  // Immutable-storage buffer of `bytes` (> 0), zero-filled unless `data` is given.
  Buffer(std::size_t bytes, const std::string& label, const void* data = nullptr);
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer();

  GLuint id() const { return id_; }
  std::size_t size() const { return bytes_; }
  const std::string& label() const { return label_; }
  // These four wait for earlier shader writes to the buffer (a memory barrier) and throw an
  // Error naming the label when the range does not fit.
  void zero();                                                 // clears to 0
  void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
  void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
  // Copies `source` (of this buffer's size, else an Error) on the GPU, after its shader writes.
  void copyFrom(const Buffer& source);
  void bindStorage(GLuint binding) const;                      // GL_SHADER_STORAGE_BUFFER
  void bindUniform(GLuint binding) const;                      // GL_UNIFORM_BUFFER

private:
  void requireRange(std::size_t bytes, std::size_t offset, const char* what) const;
  GLuint id_ = 0;
  std::size_t bytes_ = 0;
  std::string label_;
  std::vector<unsigned char> host_;  // the bytes without GL (onHost_)
  bool onHost_ = false;
};

class Texture {
public:
  Texture() = default;
  // target: GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_3D; depth = layers or slices (1 for
  // 2D). Sampling starts as linear (nearest for integer formats) without mipmaps unless
  // levels > 1, clamped to the edge: GL's own default (mipmapped filtering) would leave a
  // single-level texture incomplete, and an incomplete texture samples as black, silently.
  Texture(GLenum target, GLenum internalFormat, int width, int height, int depth,
          const std::string& label, int levels = 1);
  Texture(Texture&& other) noexcept;
  Texture& operator=(Texture&& other) noexcept;
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;
  ~Texture();

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int depth() const { return depth_; }
  GLenum format() const { return format_; }
  const std::string& label() const { return label_; }
  std::size_t bytes() const;  // of level 0, for the memory report

  // Bytes per texel of an internal format; throws an Error for formats lpvlab does not use.
  static std::size_t texelBytes(GLenum internalFormat);

private:
  GLuint id_ = 0;  // without GL: a name no GL object has (never passed to GL)
  GLenum target_ = 0, format_ = 0;
  int width_ = 0, height_ = 0, depth_ = 0;
  std::string label_;
  bool onHost_ = false;
};

// glMemoryBarrier(bits) and glFinish(), where CPU code waits for GL's writes; nothing without GL
// (nothing was written on GL).
void barrier(GLbitfield bits);
void finish();

// Without GL: the Error for `what` ("drawing the scene", "compiling direct.comp") needing it.
[[noreturn]] void noGl(const std::string& what);
// Names for GL objects made without GL, unique in the process.
GLuint hostObjectName();

class Framebuffer {
public:
  Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept;
  Framebuffer& operator=(Framebuffer&& other) noexcept;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;
  ~Framebuffer();
  GLuint id() const { return id_; }
  // Attach a 2D texture, or one layer of an array texture (layer >= 0). Colour attachment i
  // becomes the draw buffer of fragment output location i (GL would draw into attachment 0
  // alone), so an RSM's position, normal and flux targets are all written.
  void attach(GLenum attachment, const Texture& texture, int layer = -1);
  // Throws an Error naming `label` unless complete.
  void checkComplete(const std::string& label) const;
  void bind() const;

private:
  GLuint id_ = 0;
  std::vector<GLenum> drawBuffers_;  // index: fragment output location
};

}  // namespace gl

// Throws an Error naming `where` when glGetError reports an error; the message carries the GL
// debug output since the last check, where the driver says which call failed and why.
void checkGl(std::string_view where);

}  // namespace lpvlab
