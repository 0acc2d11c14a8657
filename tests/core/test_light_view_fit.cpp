// fitLightToView and receiverTexelSize (scene.h, lib/src/core/light_view_fit.cpp), checked from
// the outside: ground points the camera sees are sampled through its pixels and projected into
// the light before and after the fit.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "shadowvol/camera.h"
#include "shadowvol/light.h"
#include "shadowvol/scene.h"

using namespace shadowvol;

namespace {

Scene parse(const std::string& text) { return parseScene(text, "test.json", ".").scene; }

// A small box on a ground `ground` units wide; the camera looks down at the box from 5 up.
std::string wideGround(double ground, const std::string& light) {
  return R"({"objects": [{"type": "plane", "name": "ground", "size": )" + std::to_string(ground) +
         R"(}, {"type": "box", "size": [1, 1, 1], "transform": {"translate": [0, 0.5, 0]}}],
           "light": )" + light + R"(, "camera": {"eye": [0, 5, 4.5], "target": [0, 0.5, 0], "fov": 45,
           "width": 160, "height": 120}})";
}
const std::string kWideSpot = R"({"type": "spot", "position": [40, 90, 30], "target": [0, 0, 0], "fov": 150})";
const std::string kWideSun = R"({"type": "directional", "direction": [-0.6, -1, -0.35]})";

// Points of the ground (y = 0, within +-half) seen through a grid of the camera's pixels.
std::vector<glm::dvec3> visibleGround(const Scene& s, double half) {
  const glm::dmat4 inv = glm::inverse(cameraProjection(s.camera) * cameraView(s.camera));
  std::vector<glm::dvec3> out;
  for (int y = 0; y <= 24; ++y)
    for (int x = 0; x <= 32; ++x) {
      const glm::dvec2 ndc(x / 16.0 - 1.0, y / 12.0 - 1.0);
      const glm::dvec4 a = inv * glm::dvec4(ndc, -1.0, 1.0), b = inv * glm::dvec4(ndc, 1.0, 1.0);
      const glm::dvec3 p0 = glm::dvec3(a) / a.w, p1 = glm::dvec3(b) / b.w;
      if (!((p0.y > 0.0) && (p1.y < 0.0))) continue;
      const glm::dvec3 g = p0 + (p0.y / (p0.y - p1.y)) * (p1 - p0);
      if (std::abs(g.x) <= half && std::abs(g.z) <= half) out.push_back(g);
    }
  return out;
}

// Light NDC (x, y) of a world point; |.| <= 1 inside the light's frustum.
glm::dvec2 lightNdc(const Light& l, const glm::dvec3& p) {
  const glm::dvec4 c = lightProjection(l) * lightView(l) * glm::dvec4(p, 1.0);
  return glm::dvec2(c) / c.w;
}

bool inFrustum(const Light& l, const glm::dvec3& p, double slack = 1e-9) {
  const glm::dvec2 n = lightNdc(l, p);
  return std::abs(n.x) <= 1.0 + slack && std::abs(n.y) <= 1.0 + slack;
}

void expectFitKeepsWhatTheCameraSees(const std::string& light) {
  Scene s = parse(wideGround(500, light));
  const Light before = s.light;
  const LightFitResult r = fitLightToView(s, 256);
  ASSERT_TRUE(r.changed) << r.note;
  EXPECT_LT(r.windowAfter, 0.5 * r.windowBefore) << r.note;
  const auto ground = visibleGround(s, 250);
  ASSERT_GT(ground.size(), 100u);
  for (const glm::dvec3& g : ground) {
    if (!inFrustum(before, g)) continue;
    // Lit before: still inside, and 2 texels (of 256) clear of the edge for the far-plane ring.
    const glm::dvec2 n = lightNdc(s.light, g);
    EXPECT_LE(std::max(std::abs(n.x), std::abs(n.y)), 1.0 - 2.0 * 2.0 / 256.0 + 1e-9) << g.x << " " << g.z;
  }
  // Nothing newly lit: the new frustum's corner rays, at its far plane, lie in the old frustum.
  const glm::dmat4 inv = glm::inverse(lightProjection(s.light) * lightView(s.light));
  for (int k = 0; k < 4; ++k) {
    const glm::dvec4 c = inv * glm::dvec4(k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, 0.999, 1.0);
    EXPECT_TRUE(inFrustum(before, glm::dvec3(c) / c.w, 1e-6)) << k;
  }
  EXPECT_GT(s.light.farPlane, s.light.nearPlane);
  EXPECT_LE(s.light.farPlane, before.farPlane * (1 + 1e-12));
}

}  // namespace

TEST(LightViewFit, SpotOverWideGroundNarrowsAndKeepsWhatTheCameraSees) {
  expectFitKeepsWhatTheCameraSees(kWideSpot);
}

TEST(LightViewFit, DirectionalOverWideGroundShrinksAndKeepsWhatTheCameraSees) {
  expectFitKeepsWhatTheCameraSees(kWideSun);
}

TEST(LightViewFit, TexelOnTheReceiversShrinksWithTheFit) {
  for (const std::string& light : {kWideSpot, kWideSun}) {
    Scene s = parse(wideGround(500, light));
    const auto before = receiverTexelSize(s, 256);
    ASSERT_TRUE(before);
    fitLightToView(s, 256);
    const auto after = receiverTexelSize(s, 256);
    ASSERT_TRUE(after);
    EXPECT_LT(after->second, 0.25 * before->second);
    EXPECT_LE(after->first, after->second);
  }
  // A directional light's texel is its window over the map, wherever the receivers are.
  Scene sun = parse(wideGround(500, kWideSun));
  const auto t = receiverTexelSize(sun, 100);
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(t->first, 2.0 * sun.light.halfExtent / 100.0);
  EXPECT_DOUBLE_EQ(t->second, t->first);
}

TEST(LightViewFit, SpotStraightDownOverFlatGroundHasTheTexelOfItsHeight) {
  Scene s = parse(R"({"objects": [{"type": "plane", "size": 4}],
    "light": {"type": "spot", "position": [0, 10, 0], "target": [0, 0, 0], "fov": 30},
    "camera": {"eye": [0, 8, 0.01], "target": [0, 0, 0], "fov": 20, "width": 100, "height": 100}})");
  const auto t = receiverTexelSize(s, 200);
  ASSERT_TRUE(t);
  const double expected = 2.0 * std::tan(15.0 * std::numbers::pi / 180.0) * 10.0 / 200.0;
  EXPECT_NEAR(t->first, expected, 1e-9);
  EXPECT_NEAR(t->second, expected, 1e-9);
}

TEST(LightViewFit, UnchangedWhenTheViewFillsTheFrustumOrSeesNothingLit) {
  // The camera sees the whole lit ground: nothing to gain.
  Scene all = parse(R"({"objects": [{"type": "plane", "size": 4}],
    "light": {"type": "spot", "position": [0, 10, 0], "target": [0, 0, 0], "fov": 20},
    "camera": {"eye": [0, 30, 0.01], "target": [0, 0, 0], "fov": 60, "width": 100, "height": 100}})");
  const Light before = all.light;
  const LightFitResult r = fitLightToView(all, 256);
  EXPECT_FALSE(r.changed) << r.note;
  EXPECT_EQ(all.light.fovYDegrees, before.fovYDegrees);
  EXPECT_EQ(all.light.direction, before.direction);
  // The camera looks away from everything the light sees.
  Scene away = parse(R"({"objects": [{"type": "plane", "size": 4}],
    "light": {"type": "spot", "position": [0, 10, 0], "target": [0, 0, 0], "fov": 20},
    "camera": {"eye": [0, 1, 0], "target": [0, 5, 0.01], "fov": 30, "width": 100, "height": 100}})");
  const LightFitResult none = fitLightToView(away, 256);
  EXPECT_FALSE(none.changed);
  EXPECT_NE(none.note.find("sees none"), std::string::npos) << none.note;
  EXPECT_FALSE(receiverTexelSize(away, 256));
}

TEST(LightViewFit, SecondFitChangesLittle) {
  Scene s = parse(wideGround(500, kWideSpot));
  fitLightToView(s, 256);
  const double fov = s.light.fovYDegrees;
  fitLightToView(s, 256);
  EXPECT_LE(s.light.fovYDegrees, fov * (1 + 1e-9));
  EXPECT_GT(s.light.fovYDegrees, 0.8 * fov);
}

TEST(LightViewFit, ParsesItsNames) {
  LightFit f = LightFit::Scene;
  EXPECT_TRUE(parseLightFit("view", f));
  EXPECT_EQ(f, LightFit::View);
  EXPECT_STREQ(toString(f), "view");
  EXPECT_FALSE(parseLightFit("camera", f));
}
