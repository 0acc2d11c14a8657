// A headless OpenGL context through EGL: no window, no surface, offscreen framebuffers only.
// Platforms are tried in this order (ContextOptions::platform = "auto"):
//   1. "device": EGL_EXT_platform_device, each EGL device in turn (a GPU server's vendor EGL);
//   2. "surfaceless": EGL_MESA_platform_surfaceless (Mesa, e.g. llvmpipe on a machine without GPU);
//   3. "default": eglGetDisplay(EGL_DEFAULT_DISPLAY).
// On each display an OpenGL core context is requested, 4.5 first, then 4.3, then 3.3 (the
// minimum: every pass of the renderer is GL 3.3 core). Failure everywhere throws GlError listing
// what each attempt answered.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowvol::gl {

struct ContextOptions {
  std::string platform = "auto";  ///< auto | device | surfaceless | default (see above)
};

/// What was used, for the log and the CLI's --json.
struct ContextInfo {
  std::string platform;               ///< "device", "surfaceless" or "default"
  std::string device;                 ///< EGL device (DRM node or extension list) for "device"; else empty
  std::string eglVendor;              ///< EGL_VENDOR
  std::string eglVersion;             ///< EGL_VERSION
  std::string glVendor;               ///< GL_VENDOR
  std::string glRenderer;             ///< GL_RENDERER (for example "llvmpipe (LLVM 15.0.6, 256 bits)")
  std::string glVersion;              ///< GL_VERSION
  std::string glslVersion;            ///< GL_SHADING_LANGUAGE_VERSION
  int glMajor = 0, glMinor = 0;       ///< the context's version
  bool timerQueries = false;          ///< GL_TIME_ELAPSED queries have counter bits > 0
  bool softwareRenderer = false;      ///< llvmpipe, softpipe or swrast: a deferred CPU rasteriser whose
                                      ///< timer queries do not measure the passes (the renderer then
                                      ///< times with glFinish + wall clock)
  std::vector<std::string> attempts;  ///< one line per platform/display tried before success
};

/// The context as JSON (platform, device, vendors, renderer, version): report.json's and the
/// command line's `gl`, the Python module's too.
nlohmann::json describeContext(const ContextInfo& info);

/// Owns an EGL display reference and context; current on the creating thread after create().
/// Move-only. Destruction releases the context and, with the last user, terminates the display.
class EglContext {
 public:
  /// Throws GlError when no platform yields a GL >= 3.3 core context, InputError for an unknown
  /// ContextOptions::platform.
  static EglContext create(const ContextOptions& options = {});

  EglContext(EglContext&&) noexcept;
  EglContext& operator=(EglContext&&) noexcept;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;
  ~EglContext();

  void makeCurrent() const;  ///< makes this context current on the calling thread
  const ContextInfo& info() const;

  struct State;  ///< implementation detail (egl_context.cpp)

 private:
  explicit EglContext(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace shadowvol::gl
