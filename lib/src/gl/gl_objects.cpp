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
  GLenum error = GL_NO_ERROR, latest;  // errors of the storage calls before this check (a few flags at most)
  for (int k = 0; k < 16 && (latest = glGetError()) != GL_NO_ERROR; ++k)
    if (error != GL_OUT_OF_MEMORY) error = latest;
  if (status == GL_FRAMEBUFFER_COMPLETE && error == GL_NO_ERROR) return;
  std::ostringstream s;
  if (error == GL_OUT_OF_MEMORY)
    s << "out of memory: the GL driver could not allocate the " << what
      << " framebuffer's storage (GL_OUT_OF_MEMORY); a smaller size needs less";
  else
    s << "the " << what << " framebuffer is incomplete (status 0x" << std::hex << status << ", GL error 0x" << error
      << "; a size the driver cannot allocate does this)";
  throw GlError(s.str());
}

}  // namespace shadowvol::gl
