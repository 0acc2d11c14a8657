// RenderResult::visibility (RenderOptions::readVisibility): the method's own shadow test per pixel.
// The square-plate scene: ground pixels whose exact shadow (a ray toward the light hits the plate)
// is the same over a neighbourhood of a few texels get 0 (shadowed) or 255 (lit) from shadowmap,
// pcf3 and pcf5; hybrid gives exactly stencil == 0; none gives 255; off by default.
#include <gtest/gtest.h>

#include <optional>

#include <glm/matrix.hpp>

#include "gl_test_support.h"

using namespace shadowvol;

namespace {

bool rayHitsPlate(const glm::dvec3& o, const glm::dvec3& dir) { return gltest::rayThroughPlate(o, dir, 0.0).has_value(); }

/// Per image pixel (rows top first): -1 = not a ground pixel with a clear answer, 0 = the ground
/// point and every point within `margin` world units of it (x, z) are in the exact shadow of the
/// plate, 1 = all of them are lit.
std::vector<int> exactGroundShadow(const Scene& scene, double margin) {
  const Camera& cam = scene.camera;
  const glm::dmat4 inv = glm::inverse(cameraProjection(cam) * cameraView(cam));
  const glm::dvec3 toLight = -glm::normalize(scene.light.direction);
  std::vector<int> out(std::size_t(cam.width) * cam.height, -1);
  for (int row = 0; row < cam.height; ++row)
    for (int x = 0; x < cam.width; ++x) {
      const double nx = (x + 0.5) / cam.width * 2.0 - 1.0, ny = (cam.height - 1 - row + 0.5) / cam.height * 2.0 - 1.0;
      const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 o = glm::dvec3(a) / a.w, dir = glm::dvec3(b) / b.w - o;
      if (!(dir.y < 0.0)) continue;
      const glm::dvec3 g = o + (-o.y / dir.y) * dir;
      if (std::abs(g.x) > 4.5 || std::abs(g.z) > 4.5 || rayHitsPlate(o, dir)) continue;
      int seen = -1;
      bool uniform = true;
      for (int dz = -2; dz <= 2 && uniform; ++dz)
        for (int dx = -2; dx <= 2 && uniform; ++dx) {
          const int lit = rayHitsPlate(g + glm::dvec3(dx * margin / 2, 0.0, dz * margin / 2), toLight) ? 0 : 1;
          if (seen >= 0 && lit != seen) uniform = false;
          seen = lit;
        }
      if (uniform) out[std::size_t(row) * cam.width + x] = seen;
    }
  return out;
}

}  // namespace

TEST(GlVisibility, ShadowMapsAndPcfOnThePlate) {
  const Scene scene = gltest::plateScene();
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  const int res = 128;
  const double texel = 2.0 * scene.light.halfExtent / res;
  const std::vector<int> exact = exactGroundShadow(scene, 4.0 * texel);  // PCF 5x5 reaches 2 texels
  for (auto method : {gl::ShadowMethod::ShadowMap, gl::ShadowMethod::Pcf3, gl::ShadowMethod::Pcf5}) {
    gl::RenderOptions o;
    o.method = method;
    o.depthWidth = o.depthHeight = res;
    o.readVisibility = true;
    const gl::RenderResult out = r.render(o);
    ASSERT_EQ(out.visibility.size(), exact.size()) << gl::toString(method);
    std::size_t shadowed = 0, lit = 0, wrong = 0, fractional = 0;
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const std::uint8_t v = out.visibility[k];
      fractional += v != 0 && v != 255;
      if (exact[k] < 0) continue;
      (exact[k] ? lit : shadowed) += 1;
      wrong += v != (exact[k] ? 255 : 0);
    }
    std::printf("%s: %zu shadowed and %zu lit ground pixels tested, %zu wrong; %zu fractional pixels\n",
                gl::toString(method), shadowed, lit, wrong, fractional);
    EXPECT_GT(shadowed, 200u) << gl::toString(method);
    EXPECT_GT(lit, 3000u) << gl::toString(method);
    EXPECT_EQ(wrong, 0u) << gl::toString(method);
    if (method == gl::ShadowMethod::ShadowMap)
      EXPECT_EQ(fractional, 0u);
    else
      EXPECT_GT(fractional, 20u) << gl::toString(method);  // the PCF penumbra around the plate
  }
}

TEST(GlVisibility, HybridIsStencilZero) {
  gl::Renderer& r = gltest::sharedRenderer();
  for (const Scene& scene : {gltest::plateScene(), gltest::clutterScene()}) {
    r.setScene(scene);
    for (auto source : {gl::VolumeSource::Gpu, gl::VolumeSource::Explicit}) {
      gl::RenderOptions o;
      o.volume = source;
      o.depthWidth = o.depthHeight = 96;
      o.readVisibility = true;
      const gl::RenderResult out = r.render(o);
      ASSERT_EQ(out.visibility.size(), out.stencil.size());
      std::size_t shadowed = 0, mismatched = 0;
      for (std::size_t k = 0; k < out.stencil.size(); ++k) {
        shadowed += out.visibility[k] == 0;
        mismatched += out.visibility[k] != (out.stencil[k] == 0 ? 255 : 0);
      }
      EXPECT_EQ(mismatched, 0u) << scene.source;
      EXPECT_GT(shadowed, 100u) << scene.source;
      o.readStencil = false;  // visibility alone still works
      const gl::RenderResult alone = r.render(o);
      EXPECT_TRUE(alone.stencil.empty());
      EXPECT_EQ(alone.visibility, out.visibility) << scene.source;
    }
  }
}

TEST(GlVisibility, NoneIsAllLitAndOffByDefault) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(gltest::plateScene());
  gl::RenderOptions o;
  o.method = gl::ShadowMethod::None;
  o.readVisibility = true;
  const gl::RenderResult none = r.render(o);
  ASSERT_EQ(none.visibility.size(), std::size_t(none.width) * none.height);
  for (auto v : none.visibility) ASSERT_EQ(v, 255);
  for (auto method : {gl::ShadowMethod::Hybrid, gl::ShadowMethod::Pcf3, gl::ShadowMethod::None}) {
    gl::RenderOptions d;
    d.method = method;
    EXPECT_TRUE(r.render(d).visibility.empty()) << gl::toString(method);
  }
}

// Asking for the visibility must not change the image.
TEST(GlVisibility, DoesNotChangeTheImage) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(gltest::clutterScene());
  for (auto method : {gl::ShadowMethod::Pcf5, gl::ShadowMethod::Hybrid}) {
    gl::RenderOptions o;
    o.method = method;
    const auto plain = r.render(o);
    o.readVisibility = true;
    const auto with = r.render(o);
    EXPECT_EQ(plain.rgba, with.rgba) << gl::toString(method);
  }
}
