// Move-only RAII wrappers for GL object names (style.md point 7). Each deletes its name in the
// destructor; the owning context must be current then (the Renderer guarantees it by declaring
// its EglContext first, so it is destroyed last).
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace shadowvol::gl {

/// A GL name with a deleter: Deleter::destroy(GLuint) frees it. 0 is the empty state.
template <typename Deleter>
class GlName {
 public:
  GlName() = default;
  explicit GlName(GLuint id) : id_(id) {}
  GlName(GlName&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlName& operator=(GlName&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;
  ~GlName() { reset(); }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Deleter::destroy(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

struct TextureDeleter {
  static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct BufferDeleter {
  static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct FramebufferDeleter {
  static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct RenderbufferDeleter {
  static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};
struct VertexArrayDeleter {
  static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct SamplerDeleter {
  static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct QueryDeleter {
  static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};
struct ShaderDeleter {
  static void destroy(GLuint id) { glDeleteShader(id); }
};
struct ProgramDeleter {
  static void destroy(GLuint id) { glDeleteProgram(id); }
};

using Texture = GlName<TextureDeleter>;
using Buffer = GlName<BufferDeleter>;
using Framebuffer = GlName<FramebufferDeleter>;
using Renderbuffer = GlName<RenderbufferDeleter>;
using VertexArray = GlName<VertexArrayDeleter>;
using Sampler = GlName<SamplerDeleter>;
using Query = GlName<QueryDeleter>;
using Shader = GlName<ShaderDeleter>;
using ProgramName = GlName<ProgramDeleter>;

Texture makeTexture();
Buffer makeBuffer();
Framebuffer makeFramebuffer();
Renderbuffer makeRenderbuffer();
VertexArray makeVertexArray();
Sampler makeSampler();
Query makeQuery();

/// Throws GlError naming `what` unless the bound GL_FRAMEBUFFER is complete.
void checkFramebufferComplete(const char* what);

}  // namespace shadowvol::gl
