// A point light's dual-paraboloid shadow map (dual_paraboloid.h, ShadowMethod::Dpsm) through the
// renderer: the maps the GPU draws (shaders/paraboloid.glsl) against the C++ mirror's directions
// and analytic spheres; frames against the exact shadow; what it refuses.
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/error.h"
#include "shadowvol/gl/renderer.h"
#include "shadowvol/primitives.h"
#include "shadowvol/validate/frame_validation.h"
#include "shadowvol/validate/gl_frame.h"
#include "test_util.h"

namespace shadowvol {
namespace {

gl::Renderer& renderer() {
  static std::unique_ptr<gl::Renderer> r = std::make_unique<gl::Renderer>();
  return *r;
}

struct Ball {
  glm::dvec3 centre;
  double radius;
};

// Two fine spheres around a point light at the origin: one ahead of the front map (the bounds'
// centre lies toward it), one behind, in the back map.
const Ball kBalls[2] = {{{3.0, 0.4, -0.2}, 1.0}, {{-2.0, -0.5, 0.6}, 0.7}};

Scene twoBalls() {
  Scene s = defaultScene();
  s.objects.clear();
  for (const Ball& b : kBalls) {
    SceneObject o;
    o.name = o.type = "sphere";
    o.mesh = makeIcoSphere(b.radius, 5);
    for (auto& p : o.mesh.positions) p += glm::vec3(b.centre);
    s.objects.push_back(o);
  }
  s.light = Light{};
  s.light.type = LightType::Point;
  s.light.position = {0.0, 0.0, 0.0};
  fitLightAndCamera(s);
  return s;
}

// The first (front) or last (back) hit of the ray from the origin along unit d with the balls;
// +infinity for none.
double analyticHit(const glm::dvec3& d, bool last) {
  double best = last ? -1.0 : INFINITY;
  for (const Ball& b : kBalls) {
    const double along = glm::dot(d, b.centre), disc = along * along - glm::dot(b.centre, b.centre) + b.radius * b.radius;
    if (disc < 0.0) continue;
    const double t = last ? along + std::sqrt(disc) : along - std::sqrt(disc);
    if (t > 0.0) best = last ? std::max(best, t) : std::min(best, t);
  }
  return best < 0.0 ? INFINITY : best;
}

// Angle (radians) between d and the nearest ball's outline as seen from the light.
double angleToOutline(const glm::dvec3& d) {
  double best = INFINITY;
  for (const Ball& b : kBalls) {
    const double l = glm::length(b.centre);
    const double toCentre = std::acos(std::clamp(glm::dot(d, b.centre / l), -1.0, 1.0));
    best = std::min(best, std::abs(toCentre - std::asin(b.radius / l)));
  }
  return best;
}

TEST(DualParaboloid, GpuMapsFollowTheirCppMirror) {
  renderer().setScene(twoBalls());
  for (int subdivision : {1, 8}) {
    for (CaptureMode mode : {CaptureMode::Front, CaptureMode::Back}) {
      SCOPED_TRACE("subdivision " + std::to_string(subdivision));
      const gl::Renderer::DualParaboloidCapture c = renderer().captureDualParaboloid(48, mode, subdivision);
      const int side = c.frame.side;
      ASSERT_EQ(side, dualParaboloidSide(48));
      const double texelAngle = 4.0 / side;  // the coarsest texel's
      int hits[2] = {0, 0}, checked = 0;
      for (int h = 0; h < 2; ++h)
        for (int j = 0; j < side; ++j)
          for (int i = 0; i < side; ++i) {
            const glm::dvec2 xy = paraboloidTexelCentre(side, i, j);
            if (glm::length(xy) > 0.98) continue;  // the rim: the clip plane's chords
            const glm::dvec3 d = paraboloidDirection(c.frame, h, xy);
            const double want = analyticHit(d, mode == CaptureMode::Back);
            const float got = c.distance[h][std::size_t(j) * side + i];
            ++checked;
            if (std::isinf(want) != std::isinf(got)) {  // coverage differs only at an outline
              EXPECT_LT(angleToOutline(d), 2.0 * texelAngle) << "map " << h << " texel " << i << "," << j;
              continue;
            }
            if (std::isinf(want)) continue;
            ++hits[h];
            // Depths interpolate straight across a triangle in the disc; the icosphere's
            // triangles span 0.04 rad, so the error stays well under 1 % of the radius but near
            // the outline, where a texel's ray grazes the sphere.
            if (angleToOutline(d) > 2.0 * texelAngle) {
              EXPECT_NEAR(got, want, 0.01) << "map " << h << " texel " << i << "," << j;
            }
          }
      EXPECT_GT(hits[0], 50) << toString(mode);  // each ball fills part of its own map
      EXPECT_GT(hits[1], 20) << toString(mode);
      EXPECT_GT(checked, 2 * side * side / 2);
    }
  }
}

FrameValidation shadowFrame(const Scene& scene, gl::RenderOptions ro) {
  ro.readVisibility = true;
  return validateFrame(scene, DepthMap{}, ro.volumeOptions, toRenderedFrame(renderer().render(ro), ro.method));
}

// The shipped room at 160 x 120.
Scene smallRoom() {
  Scene s = loadScene(test::sourceDir() / "data" / "scenes" / "point" / "room.json").scene;
  s.camera.width = 160;
  s.camera.height = 120;
  return s;
}

// The dual-paraboloid frame's options at n texels a cube face.
gl::RenderOptions dpsmOptions(CaptureMode mode, int n) {
  gl::RenderOptions ro;
  ro.method = gl::ShadowMethod::Dpsm;
  ro.capture = mode;
  ro.depthWidth = ro.depthHeight = n;
  return ro;
}

// The room's walls are a few triangles that span up to 90 degrees: cut into 8 x 8 in the light
// pass, their edges bend far less in the disc, and the frame's error falls (the subdivided pass
// keeps the triangles' winding: back capture still sees the back faces).
TEST(DualParaboloid, SubdivisionStraightensLargeTriangles) {
  const Scene scene = smallRoom();
  renderer().setScene(scene);
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
    gl::RenderOptions ro = dpsmOptions(mode, 256);
    const double tutorial = shadowFrame(scene, ro).methodError.errorFraction();
    ro.paraboloidSubdivision = 8;
    const FrameValidation v = shadowFrame(scene, ro);
    EXPECT_GT(v.exactShadowed, 0u);
    EXPECT_LT(v.methodError.errorFraction(), tutorial) << toString(mode);
  }
  gl::RenderOptions bad;
  bad.method = gl::ShadowMethod::Dpsm;
  bad.paraboloidSubdivision = 3;
  EXPECT_THROW(renderer().render(bad), InputError);
}

TEST(DualParaboloid, FramesFollowTheExactShadow) {
  const Scene scene = smallRoom();
  renderer().setScene(scene);
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
    double previous = 1.0;
    for (int n : {16, 128}) {
      const gl::RenderOptions ro = dpsmOptions(mode, n);
      const FrameValidation v = shadowFrame(scene, ro);
      EXPECT_GT(v.exactShadowed, 0u);
      EXPECT_LT(v.methodError.errorFraction(), previous) << toString(mode) << " " << n;
      previous = v.methodError.errorFraction();
    }
    EXPECT_LT(previous, 0.01) << toString(mode);
  }
}

TEST(DualParaboloid, RefusesWhatItCannotDraw) {
  gl::RenderOptions ro;
  ro.method = gl::ShadowMethod::Dpsm;
  ro.depthWidth = ro.depthHeight = 32;
  renderer().setScene(defaultScene());  // a spot light
  EXPECT_THROW(renderer().render(ro), InputError);
  EXPECT_THROW(renderer().captureDualParaboloid(32, CaptureMode::Back), InputError);
  renderer().setScene(twoBalls());
  ro.capture = CaptureMode::Midpoint;
  EXPECT_THROW(renderer().render(ro), InputError);
  EXPECT_THROW(renderer().captureDualParaboloid(32, CaptureMode::Midpoint), InputError);
  ro.capture = CaptureMode::Back;
  ro.depthWidth = ro.depthHeight = 1 << 14;  // twice round(16384 sqrt 3) is past any texture limit
  EXPECT_THROW(renderer().render(ro), InputError);
}

}  // namespace
}  // namespace shadowvol
