// `--device cpu|gpu` of `depth` and `build`: where the light's depth map is captured.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "shadowvol/cube_map.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/scene.h"

namespace shadowvol::cli {

struct CaptureDeviceOptions {
  std::string device = "cpu";
  std::string platform = "auto";
};

/// Adds --device (cpu: Embree ray casting; gpu: the light pass through EGL, read back) and
/// --platform (EGL platform for --device gpu).
void addCaptureDeviceOptions(CLI::App& cmd, CaptureDeviceOptions& o);

/// Refuses (CLI::ValidationError, exit 2) --platform where no GL context is made: the CPU capture,
/// or a depth map read from a file (`fromFile`). A probe's finding: it was accepted and ignored.
void checkCaptureDeviceOptions(const CaptureDeviceOptions& o, bool fromFile);

/// The depth map of `scene` at width x height on the chosen device. Throws InputError naming
/// --device when this build has no GL (SHADOWVOL_BUILD_GL=OFF) and gpu was asked for, GlError when
/// no EGL context can be made. A point light's scene is an InputError naming /light/type (it has
/// six maps: captureCubeOnDevice). `guard`: texels of the guard band on every side
/// (captureDepthEmbree; kVolumeGuardTexels for a volume's map).
DepthMap captureOnDevice(const CaptureDeviceOptions& o, const Scene& scene, int width, int height, CaptureMode mode,
                         int guard);

/// Refuses light K of the scene as it was loaded (before chooseLight) when it is a point light,
/// whose six maps a one-map command (depth) cannot write, naming its JSON pointer ("/light" or
/// "/lights/K"). captureOnDevice makes the same check on the light it is given.
void checkOneMapLight(const Scene& scene, std::size_t light);

/// A point light's six N x N cube faces (cube_map.h) on the chosen device.
CubeDepthMap captureCubeOnDevice(const CaptureDeviceOptions& o, const Scene& scene, int n, CaptureMode mode);

}  // namespace shadowvol::cli
