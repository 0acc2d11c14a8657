// The lighting model (docs/gpu.md): colour = albedo * (ambient + diffuse * max(N.L, 0) * lit), a spot
// light lights only inside its frustum; and the per-pass timing report.
#include <gtest/gtest.h>

#include <glm/matrix.hpp>

#include "gl_test_support.h"
#include "shadowvol/light.h"

using namespace shadowvol;

namespace {

/// World point of the ground (y = 0, |x|, |z| < 9.9) seen through window position (wx, wy), or
/// nullopt when the ray misses it or may touch the sphere of defaultScene() (centre (0, 2, 0),
/// radius 1, tested with a margin).
std::optional<glm::dvec3> groundPoint(const Camera& cam, double wx, double wy) {
  const glm::dmat4 inv = glm::inverse(cameraProjection(cam) * cameraView(cam));
  const double nx = wx / cam.width * 2.0 - 1.0, ny = wy / cam.height * 2.0 - 1.0;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
  const glm::dvec3 o = glm::dvec3(a) / a.w, dir = glm::normalize(glm::dvec3(b) / b.w - o);
  if (!(dir.y < 0.0)) return std::nullopt;
  const glm::dvec3 g = o + (-o.y / dir.y) * dir;
  if (std::abs(g.x) > 9.9 || std::abs(g.z) > 9.9) return std::nullopt;
  const glm::dvec3 c(0.0, 2.0, 0.0);
  const double tc = glm::dot(c - o, dir);
  if (glm::length(o + tc * dir - c) < 1.1) return std::nullopt;
  return g;
}

}  // namespace

TEST(GlShading, GroundMatchesTheLightingModelAndTheSpotFrustum) {
  const Scene scene = defaultScene();
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  gl::RenderOptions o;
  o.method = gl::ShadowMethod::None;
  o.imageWidth = 160;
  o.imageHeight = 120;
  const gl::RenderResult res = r.render(o);
  Camera cam = scene.camera;
  cam.width = 160;
  cam.height = 120;
  const glm::dmat4 lightClip = lightProjection(scene.light, 1.0) * lightView(scene.light);
  auto insideFrustum = [&](const glm::dvec3& p) {
    const glm::dvec4 c = lightClip * glm::dvec4(p, 1.0);
    return c.w > 0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && std::abs(c.z) <= c.w;
  };
  const glm::dvec3 albedo(0.85, 0.85, 0.80);
  std::size_t lit = 0, unlit = 0, worst = 0;
  for (int row = 0; row < cam.height; ++row)
    for (int x = 0; x < cam.width; ++x) {
      const double wx = x + 0.5, wy = cam.height - 1 - row + 0.5;
      const auto g = groundPoint(cam, wx, wy);
      if (!g) continue;
      bool uniform = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto n = groundPoint(cam, wx + dx, wy + dy);
          uniform = uniform && n && insideFrustum(*n) == insideFrustum(*g);
        }
      if (!uniform) continue;
      const bool in = insideFrustum(*g);
      const double ndl = in ? std::max(glm::normalize(scene.light.position - *g).y, 0.0) : 0.0;
      const glm::dvec3 expected = albedo * (o.ambient + o.diffuse * ndl) * 255.0;
      for (int k = 0; k < 3; ++k) {
        const double got = res.rgba[(std::size_t(row) * cam.width + x) * 4 + k];
        worst = std::max(worst, std::size_t(std::abs(got - expected[k])));
      }
      (in ? lit : unlit) += 1;
    }
  std::printf("ground pixels: %zu lit, %zu outside the spot frustum, worst channel error %zu\n", lit, unlit, worst);
  EXPECT_GT(lit, 2000u);
  EXPECT_GT(unlit, 200u);
  EXPECT_LE(worst, 2u);
}

TEST(GlShading, ShadowedGroundIsAmbientOnly) {
  const Scene scene = defaultScene();
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(scene);
  gl::RenderOptions o;
  o.imageWidth = 160;
  o.imageHeight = 120;
  o.depthWidth = o.depthHeight = 128;
  const gl::RenderResult res = r.render(o);
  Camera cam = scene.camera;
  cam.width = 160;
  cam.height = 120;
  const double ambient = 0.85 * o.ambient * 255.0;
  std::size_t shadowedGround = 0;
  for (int row = 0; row < cam.height; ++row)
    for (int x = 0; x < cam.width; ++x) {
      const std::size_t k = std::size_t(row) * cam.width + x;
      if (res.stencil[k] == 0 || !groundPoint(cam, x + 0.5, cam.height - 1 - row + 0.5)) continue;
      ++shadowedGround;
      EXPECT_NEAR(res.rgba[k * 4], ambient, 1.5);
    }
  EXPECT_GT(shadowedGround, 100u);
}

// The stencil methods shade in one scene pass (the lit colour, and the ambient term kept aside)
// and put the ambient term back where the stencil is not 0, inside the light frustum's rectangle
// on the image: pixel for pixel the unshadowed frame where the stencil is 0 (the sky too), and
// that frame's ambient term elsewhere. Spot lights seen from outside their frustum and a
// directional light's box that reaches behind the camera (the whole image).
TEST(GlShading, StencilMethodsAreTheUnshadowedFrameWhereLitAndAmbientWhereShadowed) {
  gl::Renderer& r = gltest::sharedRenderer();
  for (const Scene& scene : {defaultScene(), gltest::clutterScene(), gltest::plateScene()}) {
    r.setScene(scene);
    gl::RenderOptions o;
    o.imageWidth = 160;
    o.imageHeight = 120;
    o.depthWidth = o.depthHeight = 128;
    o.method = gl::ShadowMethod::None;
    const gl::RenderResult unshadowed = r.render(o);
    gl::RenderOptions ambientOnly = o;
    ambientOnly.diffuse = 0.0;
    const gl::RenderResult ambient = r.render(ambientOnly);
    for (const gl::ShadowMethod m : {gl::ShadowMethod::Hybrid, gl::ShadowMethod::Silhouette}) {
      o.method = m;
      const gl::RenderResult res = r.render(o);
      ASSERT_EQ(res.stencil.size(), std::size_t(160 * 120));
      std::size_t lit = 0, shadowed = 0, wrong = 0;
      for (std::size_t k = 0; k < res.stencil.size(); ++k) {
        const gl::RenderResult& want = res.stencil[k] == 0 ? unshadowed : ambient;
        (res.stencil[k] == 0 ? lit : shadowed) += 1;
        for (int c = 0; c < 4; ++c) wrong += res.rgba[k * 4 + c] != want.rgba[k * 4 + c];
      }
      EXPECT_EQ(wrong, 0u) << scene.source << ", " << toString(m);
      EXPECT_GT(lit, 5000u) << scene.source << ", " << toString(m);
      EXPECT_GT(shadowed, 300u) << scene.source << ", " << toString(m);
    }
  }
}

TEST(GlTiming, EveryPassIsTimedAndNamed) {
  gl::Renderer& r = gltest::sharedRenderer();
  r.setScene(defaultScene());
  gl::RenderOptions o;
  o.imageWidth = 128;
  o.imageHeight = 96;
  o.depthWidth = o.depthHeight = 64;
  o.volumeOptions.blur = true;
  gl::RenderResult res = r.render(o);
  std::vector<std::string> names;
  double sum = 0.0;
  for (const auto& p : res.passes) {
    names.push_back(p.name);
    EXPECT_GE(p.ms, 0.0) << p.name;
    sum += p.ms;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"light", "resolve", "blur", "camera", "volume", "lighting"}));
  EXPECT_NEAR(res.totalMs, sum, 1e-9);
  if (!r.info().timerQueries || r.info().softwareRenderer) {
    EXPECT_EQ(res.timing, gl::TimingMethod::WallClock);
  }

  o.method = gl::ShadowMethod::Pcf3;
  o.forceWallClock = true;
  res = r.render(o);
  ASSERT_EQ(res.passes.size(), 2u);
  EXPECT_EQ(res.passes[0].name, "light");
  EXPECT_EQ(res.passes[1].name, "shade");
  EXPECT_EQ(res.timing, gl::TimingMethod::WallClock);
  EXPECT_TRUE(res.stencil.empty());

  o.method = gl::ShadowMethod::Hybrid;
  o.volume = gl::VolumeSource::Explicit;
  res = r.render(o);
  names.clear();
  for (const auto& p : res.passes) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"light", "readback", "build", "upload", "camera", "volume", "lighting"}));
  ASSERT_TRUE(res.depthMap.has_value());
  EXPECT_EQ(res.depthMap->width, 64 + 2 * kVolumeGuardTexels);  // the volume's map has its guard band (light.h)
}
