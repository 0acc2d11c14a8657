#include "dual_paraboloid_pass.h"

#include <limits>

#include <glm/mat4x4.hpp>

#include "shadowvol/check.h"
#include "shadowvol/gl/gl_error.h"

namespace shadowvol::gl {

DualParaboloidPass::DualParaboloidPass(const ShaderLibrary& shaders)
    : program_(shaders, {"version_330.glsl", "paraboloid.glsl", "light_paraboloid.vert"},
               {"version_330.glsl", "paraboloid.glsl", "light_paraboloid.geom"}, {"depth_only.frag"}) {}

void DualParaboloidPass::setUniforms(const Program& program, const DualParaboloid& dp) {
  program.set("paraboloidToFront", glm::mat4(glm::dmat4(dp.toFront)));
  program.set("paraboloidRange", glm::vec2(float(dp.nearDistance), float(dp.farDistance)));
}

void DualParaboloidPass::draw(const DualParaboloid& dp, CaptureMode mode, int subdivision,
                              const std::function<void()>& drawScene) {
  SV_CHECK(!usesTwoLayers(mode));
  SV_CHECK(subdivision == 1 || subdivision == 2 || subdivision == 4 || subdivision == 8);
  if (dp.side != side_) {
    texture_ = makeTexture();
    SV_GL(glBindTexture(GL_TEXTURE_2D, texture_.id()));
    SV_GL(glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 2 * dp.side, dp.side, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                       nullptr));
    SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0));
    SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
    SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST));
    SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE));
    SV_GL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE));
    SV_GL(glBindTexture(GL_TEXTURE_2D, 0));
    framebuffer_ = makeFramebuffer();
    SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id()));
    SV_GL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture_.id(), 0));
    SV_GL(glDrawBuffer(GL_NONE));
    SV_GL(glReadBuffer(GL_NONE));
    checkFramebufferComplete("dual-paraboloid map");
    side_ = dp.side;
  }
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id()));
  SV_GL(glViewport(0, 0, 2 * side_, side_));
  SV_GL(glClearDepth(0.0));  // reversed: 0 = nothing seen
  SV_GL(glClear(GL_DEPTH_BUFFER_BIT));
  // The disc's x runs against the light's own left-right (a right-handed frame looking along +z),
  // so a face toward the light is clockwise in the map: back capture culls GL_BACK.
  if (mode == CaptureMode::Back) {
    SV_GL(glEnable(GL_CULL_FACE));
    SV_GL(glCullFace(GL_BACK));
  }
  SV_GL(glEnable(GL_CLIP_DISTANCE0));
  program_.use();
  setUniforms(program_, dp);
  program_.set("lightPosition", glm::vec3(dp.position));
  program_.set("maxSubdivision", subdivision);
  program_.set("subdivisionAngle", float(kParaboloidSubdivisionAngle));
  for (int h = 0; h < 2; ++h) {
    SV_GL(glViewport(h * side_, 0, side_, side_));
    program_.set("hemisphere", h);
    drawScene();
  }
  SV_GL(glDisable(GL_CLIP_DISTANCE0));
  SV_GL(glDisable(GL_CULL_FACE));
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

std::array<std::vector<float>, 2> DualParaboloidPass::readDistances(const DualParaboloid& dp) const {
  SV_CHECK_EQ(dp.side, side_);
  const std::size_t w = 2 * std::size_t(side_), n = std::size_t(side_);
  std::vector<float> stored(w * n);
  SV_GL(glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id()));
  SV_GL(glReadPixels(0, 0, GLsizei(w), GLsizei(n), GL_DEPTH_COMPONENT, GL_FLOAT, stored.data()));
  SV_GL(glBindFramebuffer(GL_READ_FRAMEBUFFER, 0));
  std::array<std::vector<float>, 2> out;
  for (int h = 0; h < 2; ++h) {
    out[h].resize(n * n);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        const double s = stored[j * w + std::size_t(h) * n + i];
        out[h][j * n + i] = s <= 0.0 ? std::numeric_limits<float>::infinity()
                                     : float(dp.nearDistance + (1.0 - s) * (dp.farDistance - dp.nearDistance));
      }
  }
  return out;
}

}  // namespace shadowvol::gl
