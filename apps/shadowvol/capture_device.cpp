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

void checkCaptureDeviceOptions(const CaptureDeviceOptions& o, bool fromFile) {
  const CaptureDeviceOptions defaults;
  if (o.platform != defaults.platform && (fromFile || o.device != "gpu"))
    throw CLI::ValidationError("--platform", std::string("chooses the EGL platform of the GPU's capture; ") +
                                                 (fromFile ? "a depth map read with --depth is not captured"
                                                           : "--device cpu casts Embree's rays") +
                                                 ": leave out --platform, or add --device gpu");
}

namespace {

#ifdef SHADOWVOL_WITH_GL
gl::Renderer rendererFor(const CaptureDeviceOptions& o, const Scene& scene) {
  gl::RendererOptions ro;
  ro.context.platform = o.platform;
  gl::Renderer renderer(ro);
  verboseNote("GL context: %s, %s (EGL platform %s)", renderer.info().glRenderer.c_str(),
              renderer.info().glVersion.c_str(), renderer.info().platform.c_str());
  renderer.setScene(scene);
  return renderer;
}
#endif

#ifndef SHADOWVOL_WITH_GL
[[noreturn]] void noGl(const CaptureDeviceOptions& o) {
  throw InputError("command line", "--device", o.device, "this shadowvol was built without GL (SHADOWVOL_BUILD_GL=OFF)");
}
#endif

}  // namespace

void checkOneMapLight(const Scene& scene, std::size_t light) {
  if (light < scene.lightCount() && scene.lightAt(light).type == LightType::Point)
    throw InputError(scene.source, scene.lightPointer(light) + "/type", "point",
                     "a point light has six depth maps, one per cube face, and this command writes one: build, "
                     "render, validate and bench take point lights");
}

DepthMap captureOnDevice(const CaptureDeviceOptions& o, const Scene& scene, int width, int height, CaptureMode mode,
                         int guard) {
  checkOneMapLight(scene, 0);
  if (o.device == "cpu") {
    DepthMap map = captureDepthEmbree(scene, width, height, mode, guard);
    verboseNote("depth captured on the CPU (Embree): %dx%d %s (a guard band of %d texels a side), %zu texels hit",
                map.width, map.height, toString(mode), guard, map.hitCount());
    return map;
  }
#ifdef SHADOWVOL_WITH_GL
  DepthMap map = rendererFor(o, scene).captureDepth(width, height, mode, guard);
  verboseNote("depth captured on the GPU: %dx%d %s (a guard band of %d texels a side), %zu texels hit", map.width,
              map.height, toString(mode), guard, map.hitCount());
  return map;
#else
  noGl(o);
#endif
}

CubeDepthMap captureCubeOnDevice(const CaptureDeviceOptions& o, const Scene& scene, int n, CaptureMode mode) {
#ifdef SHADOWVOL_WITH_GL
  CubeDepthMap cube = o.device == "cpu" ? captureCubeEmbree(scene, n, mode) : rendererFor(o, scene).captureCube(n, mode);
#else
  if (o.device != "cpu") noGl(o);
  CubeDepthMap cube = captureCubeEmbree(scene, n, mode);
#endif
  std::size_t hits = 0;
  for (const DepthMap& f : cube.faces) hits += f.hitCount();
  verboseNote("cube map captured on the %s: 6 x %dx%d %s, %zu texels hit", o.device == "cpu" ? "CPU (Embree)" : "GPU",
              n, n, toString(mode), hits);
  return cube;
}

}  // namespace shadowvol::cli
