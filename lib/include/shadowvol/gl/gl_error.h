// Errors of the GL stack: no EGL display, no suitable context, a shader that does not compile,
// an incomplete framebuffer, a GL error caught by SV_GL in a debug build. Thrown, never aborted:
// the command line prints what() and exits non-zero.
#pragma once

#include <stdexcept>
#include <string>

namespace shadowvol::gl {

class GlError : public std::runtime_error {
 public:
  explicit GlError(const std::string& what) : std::runtime_error(what) {}
};

namespace detail {
/// Throws GlError naming the call and location if glGetError() reports anything (drains all).
void checkGlError(const char* call, const char* file, int line);
}  // namespace detail

}  // namespace shadowvol::gl

// SV_GL(call): the call, followed in debug builds (NDEBUG unset) by a glGetError check that throws
// GlError naming the call, file and line. Release builds run the call only.
#ifdef NDEBUG
#define SV_GL(call) call
#else
#define SV_GL(call)                                                   \
  do {                                                                \
    call;                                                             \
    ::shadowvol::gl::detail::checkGlError(#call, __FILE__, __LINE__); \
  } while (0)
#endif
