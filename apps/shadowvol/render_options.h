// Command-line options of the GPU subcommands (render, validate): one definition, one parser.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "cli_common.h"
#include "shadowvol/embree/embree_depth_oracle.h"
#include "shadowvol/gl/renderer.h"

namespace shadowvol::cli {

struct RenderCliOptions {
  SceneOptions scene;
  std::string method = "hybrid";
  std::string volume = "auto";  ///< --volume: auto (gpu) | gpu | explicit
  std::string gpuDraw = "auto";
  std::string count = "auto";  ///< --count: auto | zfail | zpass
  std::string crossings = "auto";  ///< --crossings: auto | rays | gpu-walk
  std::string depthFrom = "auto";  ///< --depth-from: auto | gpu | rays (the explicit volume's depth map)
  int resolution = 512;
  std::string capture = "auto";  ///< --capture: auto | back | front | midpoint
  VolumeCliOptions shape;  ///< triangulation, blur, bias, cap
  std::string size;
  std::optional<double> shadowBias;  ///< unset = the documented default
  double shadowSlope = 1.0;
  int dpsmSubdivide = 1;  ///< --dpsm-subdivide: 1, 2, 4, 8
  std::string platform = "auto";
  std::string shaderDir;
  bool scored = false;  ///< validate, bench: the frame is also scored by ray casting (more memory a pixel)
};

/// Adds --scene, --json, --method, --volume, --gpu-draw, --crossings, --depth-from, --count, --resolution,
/// --capture, --triangulation, --blur, --blur-offset, --bias, --cap, --refine, --size, --shadow-bias,
/// --shadow-slope, --platform, --shader-dir.
void addRenderOptions(CLI::App& cmd, RenderCliOptions& o);

/// Checks the values (InputError naming the option) and fills the renderer's options. --size, when
/// given, replaces the scene camera's width and height; a frame whose buffers would need more than
/// half of the machine's memory (about 28 bytes a pixel, 107 when `scored`) is refused. --capture
/// auto is chosen for `scene` (resolveCapture); `captureAutoReason`, when given, receives why
/// (empty when the mode was given).
gl::RenderOptions toRenderOptions(const RenderCliOptions& o, Scene& scene, std::string* captureAutoReason = nullptr);

gl::RendererOptions toRendererOptions(const RenderCliOptions& o);

/// --depth-from as the frame took it: the explicit hybrid volume's source (auto resolved by the
/// renderer, RenderResult::explicitDepthUsed), else the option as given.
inline std::string depthFromUsed(const RenderCliOptions& o, const gl::RenderOptions& ro, const gl::RenderResult& r) {
  const bool explicitVolume = ro.method == gl::ShadowMethod::Hybrid && ro.volume == gl::VolumeSource::Explicit;
  return explicitVolume ? gl::toString(r.explicitDepthUsed) : o.depthFrom;
}

/// Whether the method captures a depth map (all but silhouette volumes and no shadows), so that
/// --capture and the capture warnings apply.
inline bool capturesMap(const gl::RenderOptions& ro) {
  return ro.method != gl::ShadowMethod::Silhouette && ro.method != gl::ShadowMethod::None;
}

/// Usage errors among the render options that CLI11 cannot see (exit 2): --refine with the GPU
/// volume. Throws CLI::ValidationError; call it from the subcommand's callback.
void checkRenderOptionConflicts(const RenderCliOptions& o);

/// With --volume explicit and --refine with --crossings rays, or --depth-from rays, the scene's Embree depth
/// oracle, set as ro.volumeOptions.depthOracle; keep the returned object alive while rendering. Null otherwise.
std::unique_ptr<EmbreeDepthOracle> attachDepthOracle(const Scene& scene, gl::RenderOptions& ro);


}  // namespace shadowvol::cli
