#include <gtest/gtest.h>

#include <glm/vec4.hpp>

#include "shadowvol/camera.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/light.h"

namespace shadowvol {
namespace {

TEST(LightMatrices, SpotLookingStraightDownMatchesHandComputedValues) {
  Light l;
  l.type = LightType::Spot;
  l.position = {0, 10, 0};
  l.direction = {0, -1, 0};
  l.fovYDegrees = 90;
  l.nearPlane = 1;
  l.farPlane = 3;
  // Up falls back to -Z (direction parallel to Y): view x = world x, view y = -world z,
  // view z = world y - 10.
  EXPECT_EQ(lightUp(l), glm::dvec3(0, 0, -1));
  const glm::dvec4 v = lightView(l) * glm::dvec4(1, 2, 3, 1);
  EXPECT_NEAR(v.x, 1, 1e-12);
  EXPECT_NEAR(v.y, -3, 1e-12);
  EXPECT_NEAR(v.z, -8, 1e-12);
  // Perspective, fov 90, aspect 1, n = 1, f = 3: diag(1, 1, -(f+n)/(f-n) = -2), P[3][2] = -2fn/(f-n) = -3.
  const glm::dmat4 p = lightProjection(l);
  EXPECT_NEAR(p[0][0], 1, 1e-12);
  EXPECT_NEAR(p[1][1], 1, 1e-12);
  EXPECT_NEAR(p[2][2], -2, 1e-12);
  EXPECT_NEAR(p[3][2], -3, 1e-12);
  EXPECT_NEAR(p[2][3], -1, 1e-12);
  EXPECT_NEAR(p[3][3], 0, 1e-12);
}

TEST(LightMatrices, DirectionalIsOrthographic) {
  Light l;
  l.type = LightType::Directional;
  l.position = {0, 0, 0};
  l.direction = {0, 0, -1};
  l.halfExtent = 2;
  l.nearPlane = 1;
  l.farPlane = 5;
  EXPECT_EQ(lightUp(l), glm::dvec3(0, 1, 0));
  const glm::dmat4 p = lightProjection(l);
  EXPECT_NEAR(p[0][0], 0.5, 1e-12);
  EXPECT_NEAR(p[1][1], 0.5, 1e-12);
  EXPECT_NEAR(p[2][2], -0.5, 1e-12);
  EXPECT_NEAR(p[3][2], -1.5, 1e-12);
  EXPECT_NEAR(p[2][3], 0, 1e-12);
  EXPECT_NEAR(p[3][3], 1, 1e-12);
  // The light at the origin looking down -Z: view space is world space.
  const glm::dmat4 v = lightView(l);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(v[c][r], c == r ? 1.0 : 0.0, 1e-12);
}

TEST(CameraMatrices, LookAtAndPerspective) {
  Camera c;
  c.eye = {0, 0, 5};
  c.target = {0, 0, 0};
  c.up = {0, 1, 0};
  c.fovYDegrees = 90;
  c.width = 200;
  c.height = 100;
  c.nearPlane = 1;
  c.farPlane = 3;
  const glm::dvec4 v = cameraView(c) * glm::dvec4(1, 2, 3, 1);
  EXPECT_NEAR(v.x, 1, 1e-12);
  EXPECT_NEAR(v.y, 2, 1e-12);
  EXPECT_NEAR(v.z, -2, 1e-12);
  const glm::dmat4 p = cameraProjection(c);
  EXPECT_NEAR(p[0][0], 0.5, 1e-12);  // 1 / (aspect * tan(45))
  EXPECT_NEAR(p[1][1], 1.0, 1e-12);
}

class DepthMapSpaces : public ::testing::TestWithParam<LightType> {};

Light slantedLight(LightType type) {
  Light l;
  l.type = type;
  l.position = {1, 7, -2};
  l.direction = glm::normalize(glm::dvec3(0.2, -1, 0.3));
  l.fovYDegrees = 40;
  l.halfExtent = 3;
  l.nearPlane = 0.5;
  l.farPlane = 20;
  return l;
}

TEST_P(DepthMapSpaces, TexelUnprojectionRoundTrips) {
  const Light l = slantedLight(GetParam());
  const DepthMap map = makeDepthMap(l, 17, 9, CaptureMode::Front);
  const TexelUnprojector u(map);
  for (double i : {0.0, 3.0, 16.0, 7.25})
    for (double j : {0.0, 4.0, 8.0})
      for (double d : {0.5, 3.0, 20.0}) {
        const glm::dvec3 w = u.worldPoint(i, j, d);
        EXPECT_NEAR(map.viewDepthOf(w), d, 1e-12 * 20);
        const glm::dvec2 t = map.texelOf(w);
        EXPECT_NEAR(t.x, i, 1e-9);
        EXPECT_NEAR(t.y, j, 1e-9);
        EXPECT_NEAR(glm::length(w - map.worldPoint(i, j, d)), 0.0, 1e-12);
      }
  // Texel centres: texel 0 sits half a texel inside the window edge.
  EXPECT_NEAR(map.texelNdc(0, 0).x, -1.0 + 1.0 / 17, 1e-15);
  EXPECT_NEAR(map.texelNdc(16, 8).y, 1.0 - 1.0 / 9, 1e-15);
}

// A volume map's guard band (guardedLight, light.h): the (W + 2g) x (H + 2g) map of the widened
// light has the W x H map's texel centres at (i + g, j + g), at every depth, on a map wider than
// tall too; its border texels lie g texels past the window's edge; guard 0 is the light itself.
TEST_P(DepthMapSpaces, GuardedLightKeepsTheWindowsTexelCentres) {
  const Light l = slantedLight(GetParam());
  for (int g : {0, 2, 5}) {
    const Light guarded = guardedLight(l, 17, 9, g);
    EXPECT_EQ(guarded.position, l.position);
    EXPECT_EQ(guarded.nearPlane, l.nearPlane);
    const DepthMap window = makeDepthMap(l, 17, 9, CaptureMode::Front);
    const DepthMap band = makeDepthMap(guarded, 17 + 2 * g, 9 + 2 * g, CaptureMode::Front);
    const TexelUnprojector u(window), v(band);
    for (double i : {0.0, 3.0, 16.0, 7.25})
      for (double j : {0.0, 4.0, 8.0})
        for (double d : {0.5, 3.0, 20.0})
          EXPECT_NEAR(glm::length(u.worldPoint(i, j, d) - v.worldPoint(i + g, j + g, d)), 0.0, 1e-12 * 20)
              << g << " " << i << " " << j << " " << d;
    // The band's first texel centre, g texels outside the window's first.
    EXPECT_NEAR(window.texelOf(band.worldPoint(0, 0, 3.0)).x, -double(g), 1e-9);
    if (g == 0) EXPECT_EQ(band.lightProjection, window.lightProjection);
  }
}

INSTANTIATE_TEST_SUITE_P(BothLights, DepthMapSpaces, ::testing::Values(LightType::Spot, LightType::Directional));

}  // namespace
}  // namespace shadowvol
