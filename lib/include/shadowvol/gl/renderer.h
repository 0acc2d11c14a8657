// The GPU production path: a renderer that keeps an EGL context, its programs and
// framebuffers alive between frames (style.md point 3).
//
// Passes of one frame (docs/gpu.md has the full story):
//   light     the scene's depth from the light into a W x H DEPTH_COMPONENT32F texture, culling
//             per CaptureMode (front: none; back: front faces; midpoint: two layers by peeling);
//   resolve   (gpu volume, or midpoint shadow maps) the depth texture(s) -> light-view depth
//             (R32F, world units) and, for midpoint, the mean's window depth for the shadow maps;
//   blur      (gpu volume with blur) the 9-sample depth blur of volume_builder.h, R32F -> R32F;
//   camera    depth, the lit colour and (stencil methods) the ambient term aside, the scene drawn
//             once from the camera;
//   volume    (hybrid) the shadow volume (gpu: a geometry shader expands one point per quad of the
//             depth texture), two-sided stencil z-fail with depth clamp;
//   silhouette (silhouette) the classic object-space volume (silhouette_volume.h, built on the CPU
//             each frame: passes connectivity (first frame after setScene only), build, upload),
//             drawn with the same stencil state as `volume`; no light pass;
//   lighting  (hybrid, silhouette) one full-screen triangle puts the ambient term back where the
//             stencil is not 0;
//   shade     (shadowmap, pcf3, pcf5, none) ambient + diffuse x visibility in one pass.
// Albedo: light grey for planes and objects named "ground", else a fixed palette in object order.
// Lighting: colour = albedo * (ambient + diffuse * max(dot(N, L), 0) * lit), N the flat face
// normal turned toward the camera, L toward the light; lit = 0 outside the light's frustum
// (a spot light lights only inside its pyramid between its near and far planes; a directional
// light only inside its box; a point light between its near and far cubes), in shadow (stencil
// != 0, or the shadow-map test failing), and 1 otherwise. A point light's frame (docs/gpu.md
// "Point lights"): six light passes, then the explicit cube volume, silhouette volumes or a cube
// shadow map.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "shadowvol/cube_map.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/frame.h"
#include "shadowvol/gl/egl_context.h"
#include "shadowvol/scene.h"
#include "shadowvol/volume_builder.h"
#include "shadowvol/volume_mesh.h"
#include "shadowvol/walk_crossings.h"

namespace shadowvol::gl {

// The frame types (frame.h) under their old names in shadowvol::gl.
using shadowvol::ExplicitDepth;
using shadowvol::chooseExplicitDepth;
using shadowvol::GpuVolumeDraw;
using shadowvol::parseShadowMethod;
using shadowvol::parseVolumeCount;
using shadowvol::parseVolumeSource;
using shadowvol::PassTime;
using shadowvol::RenderOptions;
using shadowvol::RenderResult;
using shadowvol::ShadowMethod;
using shadowvol::TimingMethod;
using shadowvol::toString;
using shadowvol::VolumeCount;
using shadowvol::VolumeSource;
using shadowvol::RefineCrossings;

struct RendererOptions {
  ContextOptions context;           ///< which EGL platform (auto = device, surfaceless, default)
  std::filesystem::path shaderDir;  ///< empty = $SHADOWVOL_SHADER_DIR if set, else embedded shaders
};

/// Owns the context, programs, samplers and framebuffers; reuse it for many frames. Not thread
/// safe; all calls on the creating thread.
class Renderer {
 public:
  /// Creates the EGL context and compiles every program. Throws GlError (no display, no context,
  /// a shader error with the file name and log).
  explicit Renderer(const RendererOptions& options = {});
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const ContextInfo& info() const;

  /// Uploads the scene's triangles (world space) and keeps its light and camera. The light and
  /// camera must have their near/far planes set (loadScene and defaultScene fit them). Keeps a
  /// copy of the scene for the silhouette method, whose connectivity is built on its first frame
  /// (so a non-manifold object is reported by render(), only for that method).
  void setScene(const Scene& scene);

  /// Light pass + read-back: the same quantity as captureDepthEmbree (depth_map.h: light-view
  /// depth, kNoHit where the light sees nothing, row 0 at the bottom). Window depth is converted
  /// in double. Throws InputError for a size below 2 or too large for the GL implementation.
  /// `guard` > 0: the map of the light widened by that many texels a side (guardedLight, light.h),
  /// (width + 2 guard) x (height + 2 guard), as captureDepthEmbree's.
  DepthMap captureDepth(int width, int height, CaptureMode mode, int guard = 0);

  /// A point light's cube map (cube_map.h): six light passes, one per face's spot light
  /// (cubeFaceLight), each read back as captureDepth does. The scene's light must be a point light.
  CubeDepthMap captureCube(int n, CaptureMode mode);

  /// A point light's dual-paraboloid maps as ShadowMethod::Dpsm draws them for a cube face side
  /// of `cubeFaceSide` (dual_paraboloid.h), read back as distances from the light (world units;
  /// +infinity where nothing was drawn), map h's texel (i, j) at distance[h][j * side + i].
  /// Back or front capture; `subdivision` as RenderOptions::paraboloidSubdivision. The scene's
  /// light must be a point light.
  struct DualParaboloidCapture {
    DualParaboloid frame;
    std::array<std::vector<float>, 2> distance;
  };
  DualParaboloidCapture captureDualParaboloid(int cubeFaceSide, CaptureMode mode, int subdivision = 1);

  /// Debug path of the silhouette walk (RefineCrossings::GpuWalk, walk_crossings.h): the light pass
  /// at width x height with `mode` and its triangle record, then the walk's raw answers to
  /// `queries`, in order, for a sheet with `bias` (a far edge's walk stops where depth + bias
  /// reaches the far plane). With midpoint capture it walks the first layer (render() refuses the
  /// walk there). Throws InputError for a bad size, a query outside the map or without OpenGL 4.3.
  std::vector<WalkResult> walkSilhouettes(int width, int height, CaptureMode mode, std::span<const WalkQuery> queries,
                                          double bias = 0.0);

  /// One frame with the scene's camera. Throws InputError on bad options, GlError on GL failure.
  RenderResult render(const RenderOptions& options);

  /// Hybrid frame with a caller-built volume (world space, outward-facing triangles) instead of
  /// one derived from the depth map; options.method/volume are ignored.
  RenderResult renderWithVolume(const RenderOptions& options, const VolumeMesh& volume);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowvol::gl
