#include "shadowvol/gl/gl_objects.h"

#include <sstream>

#include "shadowvol/gl/gl_error.h"

namespace shadowvol::gl {

namespace detail {
void checkGlError(const char* call, const char* file, int line) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  std::ostringstream s;
  s << "OpenGL error";
  while (e != GL_NO_ERROR) {
    s << " 0x" << std::hex << e << std::dec;
    e = glGetError();
  }
  s << " after " << call << " at " << file << ":" << line;
  throw GlError(s.str());
}
}  // namespace detail

namespace {
template <typename T, typename Gen>
T make(Gen gen) {
  GLuint id = 0;
  gen(1, &id);
  if (id == 0) throw GlError("OpenGL could not create an object (out of memory or no current context)");
  return T(id);
}
}  // namespace

Texture makeTexture() {
  return make<Texture>(glGenTextures);
}
Buffer makeBuffer() {
  return make<Buffer>(glGenBuffers);
}
Framebuffer makeFramebuffer() {
  return make<Framebuffer>(glGenFramebuffers);
}
Renderbuffer makeRenderbuffer() {
  return make<Renderbuffer>(glGenRenderbuffers);
}
VertexArray makeVertexArray() {
  return make<VertexArray>(glGenVertexArrays);
}
Sampler makeSampler() {
  return make<Sampler>(glGenSamplers);
}
Query makeQuery() {
  return make<Query>(glGenQueries);
}

void checkFramebufferComplete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  std::ostringstream s;
  s << "the " << what << " framebuffer is incomplete (status 0x" << std::hex << status << ")";
  throw GlError(s.str());
}

}  // namespace shadowvol::gl
