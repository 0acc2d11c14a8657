#include "capture_device.h"

#include "cli_common.h"
#include "cli_verbosity.h"
#include "shadowvol/embree/depth_capture.h"
#include "shadowvol/error.h"
#ifdef SHADOWVOL_WITH_GL
#include "shadowvol/gl/renderer.h"
#endif

namespace shadowvol::cli {

void addCaptureDeviceOptions(CLI::App& cmd, CaptureDeviceOptions& o) {
  cmd.add_option("--device", o.device,
                 "Where the depth map is captured: cpu (Embree ray casting through the texel centres) or gpu (the "
                 "light pass rendered through EGL + OpenGL and read back: the same depths within 1e-4 relative, "
                 "docs/gpu.md 'Passes of one frame')")
      ->check(CLI::IsMember({"cpu", "gpu"}))
      ->capture_default_str();
  addPlatformOption(cmd, o.platform, "With --device gpu: ");
}

DepthMap captureOnDevice(const CaptureDeviceOptions& o, const Scene& scene, int width, int height, CaptureMode mode) {
  if (o.device == "cpu") {
    DepthMap map = captureDepthEmbree(scene, width, height, mode);
    verboseNote("depth captured on the CPU (Embree): %dx%d %s, %zu texels hit", width, height, toString(mode),
                map.hitCount());
    return map;
  }
#ifdef SHADOWVOL_WITH_GL
  gl::RendererOptions ro;
  ro.context.platform = o.platform;
  gl::Renderer renderer(ro);
  verboseNote("GL context: %s, %s (EGL platform %s)", renderer.info().glRenderer.c_str(),
              renderer.info().glVersion.c_str(), renderer.info().platform.c_str());
  renderer.setScene(scene);
  DepthMap map = renderer.captureDepth(width, height, mode);
  verboseNote("depth captured on the GPU: %dx%d %s, %zu texels hit", width, height, toString(mode), map.hitCount());
  return map;
#else
  throw InputError("command line", "--device", o.device, "this shadowvol was built without GL (SHADOWVOL_BUILD_GL=OFF)");
#endif
}

}  // namespace shadowvol::cli
