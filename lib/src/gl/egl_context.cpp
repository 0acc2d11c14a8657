#include "shadowvol/gl/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <atomic>
#include <map>
#include <mutex>
#include <sstream>
#include <string>

#include <unistd.h>

#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"

namespace shadowvol::gl {
namespace {

// eglTerminate ends a display for every user in the process (Mesa hands out one EGLDisplay per
// platform), so displays are reference counted here and terminated with their last context.
std::mutex& displayMutex() {
  static std::mutex m;
  return m;
}
std::map<EGLDisplay, int>& displayRefs() {
  static std::map<EGLDisplay, int> refs;
  return refs;
}
void releaseDisplay(EGLDisplay display) {
  std::lock_guard<std::mutex> lock(displayMutex());
  auto& refs = displayRefs();
  auto it = refs.find(display);
  if (it == refs.end()) return;
  if (--it->second == 0) {
    eglTerminate(display);
    refs.erase(it);
  }
}

// The process that first initialised an EGL display in this image, 0 before that. A child forked
// after it inherits Mesa's displays and screens without the driver's threads: a fifteenth probe's
// forked Python workers got a frame with nothing drawn (a FAILED verdict on a right method) or "out
// of memory" on their first GL call. Such a child is refused GL (refuseForkedChild).
std::atomic<pid_t> eglUser{0};

void refuseForkedChild() {
  const pid_t first = eglUser.load();
  if (first != 0 && first != ::getpid())
    throw GlError("EGL and OpenGL were used in the parent of this forked process (pid " + std::to_string(first) +
                  "), whose driver state a fork does not carry over whole: no GL here (its first frame can be "
                  "wrong); use GL only in processes started afresh (Python multiprocessing's 'spawn' or "
                  "'forkserver' start method), or use it in the parent only after forking its workers");
}

std::string eglErrorName(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    default: {
      std::ostringstream s;
      s << "EGL error 0x" << std::hex << e;
      return s.str();
    }
  }
}

std::string str(const void* p) {
  return p ? std::string(static_cast<const char*>(p)) : std::string();
}

struct Candidate {
  std::string platform;
  std::string device;
  EGLDisplay display = EGL_NO_DISPLAY;
};

}  // namespace

struct EglContext::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface surface = EGL_NO_SURFACE;  // a 1x1 pbuffer only where surfaceless contexts are missing
  ContextInfo info;

  ~State() {
    if (display == EGL_NO_DISPLAY) return;
    if (eglGetCurrentContext() == context) eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
    if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
    releaseDisplay(display);
  }
};

namespace {

/// Tries to initialise `display` and create a core context on it; fills state on success.
bool tryDisplay(const Candidate& c, EglContext::State*& out, std::vector<std::string>& attempts);

}  // namespace

EglContext::EglContext(std::unique_ptr<State> state) : state_(std::move(state)) {}
EglContext::EglContext(EglContext&&) noexcept = default;
EglContext& EglContext::operator=(EglContext&&) noexcept = default;
EglContext::~EglContext() = default;

const ContextInfo& EglContext::info() const {
  return state_->info;
}

void EglContext::makeCurrent() const {
  if (!eglMakeCurrent(state_->display, state_->surface, state_->surface, state_->context))
    throw GlError("eglMakeCurrent failed: " + eglErrorName(eglGetError()));
}

namespace {

bool tryDisplay(const Candidate& c, EglContext::State*& out, std::vector<std::string>& attempts) {
  const std::string label = c.platform + (c.device.empty() ? "" : " (" + c.device + ")");
  if (c.display == EGL_NO_DISPLAY) {
    attempts.push_back(label + ": no display (" + eglErrorName(eglGetError()) + ")");
    return false;
  }
  EGLint major = 0, minor = 0;
  {
    std::lock_guard<std::mutex> lock(displayMutex());
    if (!eglInitialize(c.display, &major, &minor)) {
      attempts.push_back(label + ": eglInitialize failed (" + eglErrorName(eglGetError()) + ")");
      return false;
    }
    ++displayRefs()[c.display];
  }
  auto state = std::make_unique<EglContext::State>();
  state->display = c.display;
  if (!eglBindAPI(EGL_OPENGL_API)) {
    attempts.push_back(label + ": no desktop OpenGL API (" + eglErrorName(eglGetError()) + ")");
    return false;  // state's destructor releases the display
  }
  const bool noConfig = epoxy_has_egl_extension(c.display, "EGL_KHR_no_config_context");
  const bool surfaceless = epoxy_has_egl_extension(c.display, "EGL_KHR_surfaceless_context");
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!noConfig || !surfaceless) {
    const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(c.display, want, &config, 1, &n) || n < 1) {
      attempts.push_back(label + ": no OpenGL pbuffer config");
      return false;
    }
  }
  const int versions[][2] = {{4, 5}, {4, 3}, {3, 3}};
  for (const auto& v : versions) {
    const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           v[0],    EGL_CONTEXT_MINOR_VERSION, v[1], EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    state->context = eglCreateContext(c.display, config, EGL_NO_CONTEXT, attribs);
    if (state->context != EGL_NO_CONTEXT) break;
  }
  if (state->context == EGL_NO_CONTEXT) {
    attempts.push_back(label + ": no OpenGL >= 3.3 core context (" + eglErrorName(eglGetError()) + ")");
    return false;
  }
  if (!surfaceless) {
    const EGLint pb[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    state->surface = eglCreatePbufferSurface(c.display, config, pb);
    if (state->surface == EGL_NO_SURFACE) {
      attempts.push_back(label + ": no pbuffer surface (" + eglErrorName(eglGetError()) + ")");
      return false;
    }
  }
  if (!eglMakeCurrent(c.display, state->surface, state->surface, state->context)) {
    attempts.push_back(label + ": eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
    return false;
  }
  ContextInfo& info = state->info;
  info.platform = c.platform;
  info.device = c.device;
  info.eglVendor = str(eglQueryString(c.display, EGL_VENDOR));
  info.eglVersion = str(eglQueryString(c.display, EGL_VERSION));
  info.glVendor = str(glGetString(GL_VENDOR));
  info.glRenderer = str(glGetString(GL_RENDERER));
  info.glVersion = str(glGetString(GL_VERSION));
  info.glslVersion = str(glGetString(GL_SHADING_LANGUAGE_VERSION));
  glGetIntegerv(GL_MAJOR_VERSION, &info.glMajor);
  glGetIntegerv(GL_MINOR_VERSION, &info.glMinor);
  if (info.glMajor * 10 + info.glMinor < 33) {
    attempts.push_back(label + ": OpenGL " + info.glVersion + " is below 3.3");
    return false;
  }
  GLint bits = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
  info.timerQueries = bits > 0;
  for (const char* sw : {"llvmpipe", "softpipe", "swrast"})
    if (info.glRenderer.find(sw) != std::string::npos) info.softwareRenderer = true;
  while (glGetError() != GL_NO_ERROR) {
  }
  attempts.push_back(label + ": OpenGL " + info.glVersion + " on " + info.glRenderer);
  info.attempts = attempts;
  out = state.release();
  return true;
}

std::string deviceDescription(EGLDeviceEXT device) {
  std::string d;
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_query") ||
      epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_base")) {
    const std::string exts = str(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS));
    if (exts.find("EGL_EXT_device_drm") != std::string::npos)
      d = str(eglQueryDeviceStringEXT(device, EGL_DRM_DEVICE_FILE_EXT));
    if (d.empty() && exts.find("EGL_MESA_device_software") != std::string::npos) d = "Mesa software device";
    if (d.empty()) d = exts.empty() ? "unnamed device" : exts;
  }
  return d;
}

}  // namespace

nlohmann::json describeContext(const ContextInfo& info) {
  return {{"platform", info.platform}, {"device", info.device},         {"eglVendor", info.eglVendor},
          {"glVendor", info.glVendor}, {"glRenderer", info.glRenderer}, {"glVersion", info.glVersion}};
}

EglContext EglContext::create(const ContextOptions& options) {
  const std::string& p = options.platform;
  if (p != "auto" && p != "device" && p != "surfaceless" && p != "default")
    throw InputError("ContextOptions", "platform", p, "expected auto, device, surfaceless or default");
  refuseForkedChild();
  std::vector<std::string> attempts;
  State* state = nullptr;
  // eglGetPlatformDisplayEXT exists only with EGL_EXT_platform_base (epoxy would abort otherwise).
  const bool clientExts = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base");
  const bool enumeration = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") ||
                           epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_base");

  if (p == "auto" || p == "device") {
    if (clientExts && enumeration && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
      EGLint n = 0;
      eglQueryDevicesEXT(0, nullptr, &n);
      std::vector<EGLDeviceEXT> devices(std::size_t(std::max(n, 0)));
      if (n > 0) eglQueryDevicesEXT(n, devices.data(), &n);
      if (n <= 0) attempts.push_back("device: no EGL devices");
      for (EGLint k = 0; k < n && !state; ++k) {
        Candidate c{"device", deviceDescription(devices[std::size_t(k)]), EGL_NO_DISPLAY};
        c.display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(k)], nullptr);
        tryDisplay(c, state, attempts);
      }
    } else {
      attempts.push_back("device: EGL_EXT_platform_device is not available");
    }
  }
  if (!state && (p == "auto" || p == "surfaceless")) {
    if (clientExts && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
      Candidate c{"surfaceless", "", EGL_NO_DISPLAY};
      c.display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      tryDisplay(c, state, attempts);
    } else {
      attempts.push_back("surfaceless: EGL_MESA_platform_surfaceless is not available");
    }
  }
  if (!state && (p == "auto" || p == "default")) {
    Candidate c{"default", "", eglGetDisplay(EGL_DEFAULT_DISPLAY)};
    tryDisplay(c, state, attempts);
  }
  if (!state) {
    std::string msg = "no headless OpenGL >= 3.3 core context through EGL (platform " + p + "); tried:";
    for (const auto& a : attempts) msg += "\n  " + a;
    throw GlError(msg);
  }
  pid_t none = 0;
  eglUser.compare_exchange_strong(none, ::getpid());  // this process has GL now (refuseForkedChild)
  return EglContext(std::unique_ptr<State>(state));
}

}  // namespace shadowvol::gl
