// A point light's dual-paraboloid shadow map on the GPU (dual_paraboloid.h): both hemispheres'
// maps side by side in one DEPTH_COMPONENT32F texture of 2 side x side texels (front on the
// left), drawn by shaders/light_paraboloid.vert and .geom. Internal to the renderer (Renderer::Impl, renderer_impl.h, owns one
// per context).
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/gl/gl_objects.h"
#include "shadowvol/gl/shader_program.h"

namespace shadowvol::gl {

class DualParaboloidPass {
 public:
  DualParaboloidPass() = default;
  explicit DualParaboloidPass(const ShaderLibrary& shaders);

  /// Draws both maps of `dp` (cleared to 0 = nothing seen; the nearest surface for
  /// CaptureMode::Front, the nearest back face for Back; Midpoint is the caller's to refuse).
  /// `drawScene` draws the scene's triangles with the current program; the caller has reset the
  /// GL state (reversed Z, depth test GREATER) before.
  /// `subdivision` (1, 2, 4, 8): light_paraboloid.geom's largest cut per triangle side.
  void draw(const DualParaboloid& dp, CaptureMode mode, int subdivision, const std::function<void()>& drawScene);

  /// The texture (valid after draw) and its side.
  const Texture& texture() const { return texture_; }
  int side() const { return side_; }

  /// The drawn maps read back as distances from the light (world units; +infinity where nothing
  /// was drawn), map h's texel (i, j) at [h][j * side + i].
  std::array<std::vector<float>, 2> readDistances(const DualParaboloid& dp) const;

  /// Sets paraboloid.glsl's uniforms of `program` (in use) for `dp`.
  static void setUniforms(const Program& program, const DualParaboloid& dp);

 private:
  Program program_;
  Texture texture_;
  Framebuffer framebuffer_;
  int side_ = 0;
};

}  // namespace shadowvol::gl
