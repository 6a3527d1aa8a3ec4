#include "framework/gl/resources.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <utility>

#include "framework/core/error.h"
#include "framework/gl/context.h"

namespace lpvlab {
namespace {

const char* glErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_CONTEXT_LOST: return "GL_CONTEXT_LOST";
    default: return "unknown GL error";
  }
}

const char* framebufferStatusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT (nothing attached)";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
      return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default: return "unknown framebuffer status";
  }
}

bool isIntegerFormat(GLenum format) {
  switch (format) {
    case GL_R32UI: case GL_R32I: case GL_RG32UI: case GL_RGBA32UI: return true;
    default: return false;
  }
}

// Shader writes to a buffer reach glBufferSubData, glGetBufferSubData and glClearBufferData only
// after this barrier (GL 4.5, 7.13.2).
void awaitShaderWrites() { glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); }

}  // namespace

namespace gl {

// --- Buffer ---

Buffer::Buffer(std::size_t bytes, const std::string& label, const void* data)
    : bytes_(bytes), label_(label), onHost_(!GlContext::glLoaded()) {
  if (bytes == 0) throwAt(label, "a buffer of 0 bytes");
  if (onHost_) {
    id_ = hostObjectName();
    host_.assign(bytes, 0);
    if (data) std::memcpy(host_.data(), data, bytes);
    return;
  }
  glCreateBuffers(1, &id_);
  glObjectLabel(GL_BUFFER, id_, -1, label.c_str());
  glNamedBufferStorage(id_, GLsizeiptr(bytes), data, GL_DYNAMIC_STORAGE_BIT);
  try {
    checkGl(label);
  } catch (...) {
    glDeleteBuffers(1, &id_);
    throw;
  }
  if (!data) zero();
}

Buffer::Buffer(Buffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)),
      bytes_(std::exchange(other.bytes_, 0)),
      label_(std::move(other.label_)),
      host_(std::move(other.host_)),
      onHost_(other.onHost_) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(bytes_, other.bytes_);
  std::swap(label_, other.label_);
  std::swap(host_, other.host_);
  std::swap(onHost_, other.onHost_);
  return *this;
}

Buffer::~Buffer() {
  if (id_ && !onHost_) glDeleteBuffers(1, &id_);
}

void Buffer::requireRange(std::size_t bytes, std::size_t offset, const char* what) const {
  if (offset > bytes_ || bytes > bytes_ - offset)
    throwAt(label_, std::string(what) + " of " + std::to_string(bytes) + " bytes at offset " +
                        std::to_string(offset) + " overruns the buffer's " +
                        std::to_string(bytes_) + " bytes");
}

void Buffer::zero() {
  if (onHost_) return std::fill(host_.begin(), host_.end(), 0);
  awaitShaderWrites();
  // An 8-bit clear value fits buffers of any size, unlike a 32-bit one.
  glClearNamedBufferData(id_, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
  requireRange(bytes, offset, "upload");
  if (onHost_) return void(bytes ? std::memcpy(host_.data() + offset, data, bytes) : nullptr);
  awaitShaderWrites();
  glNamedBufferSubData(id_, GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::download(void* data, std::size_t bytes, std::size_t offset) const {
  requireRange(bytes, offset, "download");
  if (onHost_) return void(bytes ? std::memcpy(data, host_.data() + offset, bytes) : nullptr);
  awaitShaderWrites();
  glGetNamedBufferSubData(id_, GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::copyFrom(const Buffer& source) {
  if (source.size() != bytes_)
    throw Error("GL buffer '" + label_ + "': copying " + std::to_string(source.size()) +
                " bytes of '" + source.label() + "' into " + std::to_string(bytes_));
  if (onHost_ || source.onHost_) {
    if (!(onHost_ && source.onHost_)) noGl("copying '" + source.label() + "' into '" + label_ + "'");
    return void(host_ = source.host_);
  }
  awaitShaderWrites();
  glCopyNamedBufferSubData(source.id(), id_, 0, 0, GLsizeiptr(bytes_));
}

void Buffer::bindStorage(GLuint binding) const {
  if (onHost_) noGl("binding buffer '" + label_ + "' for a GL kernel");
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, id_);
}

void Buffer::bindUniform(GLuint binding) const {
  if (onHost_) noGl("binding buffer '" + label_ + "' for a GL kernel");
  glBindBufferBase(GL_UNIFORM_BUFFER, binding, id_);
}

// --- Texture ---

std::size_t Texture::texelBytes(GLenum internalFormat) {
  switch (internalFormat) {
    case GL_R8: return 1;
    case GL_R16F: case GL_RG8: return 2;
    case GL_R32F: case GL_R32UI: case GL_R32I: case GL_RG16F: case GL_RGBA8:
    case GL_SRGB8_ALPHA8: case GL_R11F_G11F_B10F: case GL_RGB10_A2:
    case GL_DEPTH_COMPONENT32F:
    // Drivers keep 24-bit depth in 32-bit words, with or without stencil in the spare byte.
    case GL_DEPTH_COMPONENT24: case GL_DEPTH24_STENCIL8:
      return 4;
    case GL_RG32F: case GL_RG32UI: case GL_RGBA16F: return 8;
    case GL_RGBA32F: case GL_RGBA32UI: return 16;
    default: {
      char hex[16];
      std::snprintf(hex, sizeof hex, "0x%04X", internalFormat);
      throwAt("texture format " + std::string(hex), "not one lpvlab knows the size of");
    }
  }
}

Texture::Texture(GLenum target, GLenum internalFormat, int width, int height, int depth,
                 const std::string& label, int levels)
    : target_(target), format_(internalFormat), width_(width), height_(height),
      depth_(target == GL_TEXTURE_2D ? 1 : depth), label_(label) {
  try {
    texelBytes(internalFormat);  // unknown formats fail before any GL object exists
  } catch (const Error& e) {
    throwAt(label, e.what());
  }
  if (target != GL_TEXTURE_2D && target != GL_TEXTURE_2D_ARRAY && target != GL_TEXTURE_3D)
    throwAt(label, "texture target must be GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY or GL_TEXTURE_3D");
  if (width < 1 || height < 1 || depth_ < 1 || levels < 1)
    throwAt(label, "texture of " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                       std::to_string(depth) + " texels, " + std::to_string(levels) + " levels");
  if (!GlContext::glLoaded()) {
    onHost_ = true;
    id_ = hostObjectName();
    return;
  }
  glCreateTextures(target, 1, &id_);
  glObjectLabel(GL_TEXTURE, id_, -1, label.c_str());
  if (target == GL_TEXTURE_2D)
    glTextureStorage2D(id_, levels, internalFormat, width, height);
  else
    glTextureStorage3D(id_, levels, internalFormat, width, height, depth_);
  const bool integer = isIntegerFormat(internalFormat);
  const GLint mag = integer ? GL_NEAREST : GL_LINEAR;
  const GLint min = levels > 1 ? (integer ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR)
                               : mag;
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, min);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, mag);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(id_, wrap, GL_CLAMP_TO_EDGE);
  try {
    checkGl(label);
  } catch (...) {
    glDeleteTextures(1, &id_);
    throw;
  }
}

Texture::Texture(Texture&& other) noexcept
    : id_(std::exchange(other.id_, 0)), target_(other.target_), format_(other.format_),
      width_(other.width_), height_(other.height_), depth_(other.depth_),
      label_(std::move(other.label_)), onHost_(other.onHost_) {}

Texture& Texture::operator=(Texture&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(target_, other.target_);
  std::swap(format_, other.format_);
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  std::swap(depth_, other.depth_);
  std::swap(label_, other.label_);
  std::swap(onHost_, other.onHost_);
  return *this;
}

Texture::~Texture() {
  if (id_ && !onHost_) glDeleteTextures(1, &id_);
}

std::size_t Texture::bytes() const {
  if (!id_ || onHost_) return 0;  // without GL a texture holds no texels (its images are the host's)
  return texelBytes(format_) * std::size_t(width_) * std::size_t(height_) * std::size_t(depth_);
}

// --- Framebuffer ---

Framebuffer::Framebuffer() {
  if (!GlContext::glLoaded()) noGl("a framebuffer (drawing with GL)");
  glCreateFramebuffers(1, &id_);
  // Depth-only until a colour attachment arrives (a shadow map has none).
  glNamedFramebufferDrawBuffer(id_, GL_NONE);
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : id_(std::exchange(other.id_, 0)), drawBuffers_(std::move(other.drawBuffers_)) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(drawBuffers_, other.drawBuffers_);
  return *this;
}

Framebuffer::~Framebuffer() {
  if (id_) glDeleteFramebuffers(1, &id_);
}

void Framebuffer::attach(GLenum attachment, const Texture& texture, int layer) {
  if (layer < 0)
    glNamedFramebufferTexture(id_, attachment, texture.id(), 0);
  else
    glNamedFramebufferTextureLayer(id_, attachment, texture.id(), 0, layer);
  if (attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT31) {
    // Fragment output location i goes to colour attachment i, gaps draw nowhere.
    const std::size_t index = attachment - GL_COLOR_ATTACHMENT0;
    if (drawBuffers_.size() <= index) drawBuffers_.resize(index + 1, GL_NONE);
    drawBuffers_[index] = attachment;
    glNamedFramebufferDrawBuffers(id_, GLsizei(drawBuffers_.size()), drawBuffers_.data());
  }
}

void Framebuffer::checkComplete(const std::string& label) const {
  const GLenum status = glCheckNamedFramebufferStatus(id_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throwAt(label, std::string("framebuffer incomplete: ") + framebufferStatusName(status));
}

void Framebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id_); }

// --- errors ---

}  // namespace gl

void gl::barrier(GLbitfield bits) {
  if (GlContext::glLoaded()) glMemoryBarrier(bits);
}

void gl::finish() {
  if (GlContext::glLoaded()) glFinish();
}

void gl::noGl(const std::string& what) {
  throw Error(what + " needs GL, and this run has none (gl.backend = \"none\"): run with a GL "
              "backend, or choose what runs on the CPU");
}

GLuint gl::hostObjectName() {
  static std::atomic<GLuint> next = 0x40000000u;
  return next++;
}

void checkGl(std::string_view where) {
  if (!GlContext::glLoaded()) return;  // no GL: nothing to check
  GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  std::string message;
  // GL keeps one flag per kind of error; read them all so the next check starts clean.
  for (int i = 0; error != GL_NO_ERROR && i < 8; ++i, error = glGetError())
    message += std::string(message.empty() ? "" : ", ") + glErrorName(error);
  for (const std::string& debug : GlContext::takeDebugMessages()) message += "; " + debug;
  throwAt(where, message);
}

}  // namespace lpvlab
