// The bias of a snapped crossing's near vertex with the sub-grid and front capture
// (crossing_snap.h, rimVertexDepth), and the depth a triangle shows on a light ray
// (triangle_exit.h, triangleDepthAt), which the surface-end oracle gives at the rim.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "shadowvol/crossing_snap.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/triangle_exit.h"
#include "test_util.h"

namespace shadowvol {
namespace {

// Depth along a segment under the map's projection for a surface with depths z0 at s = 0 and z1
// at s = 1 that is a plane (linear for a directional light, its inverse linear for a spot light).
double onPlane(double z0, double z1, double s, bool perspective) {
  return perspective ? 1.0 / ((1.0 - s) / z0 + s / z1) : (1.0 - s) * z0 + s * z1;
}

struct RimCase {
  DepthMap map;
  SheetDepthRule rule;
  BisectionSegment segment;
  bool perspective = false;
};

RimCase rimCase(const Light& light, double bias) {
  RimCase c;
  c.map = makeDepthMap(light, 64, 64, CaptureMode::Front);
  c.rule = SheetDepthRule(c.map, bias, 0.0);
  c.segment.nearPoint = {20.0, 30.0};
  c.segment.farPoint = {21.0, 30.0};
  c.perspective = light.type == LightType::Spot;
  return c;
}

// The bracket [lo, hi] whose lo sample lies on the rim's plane (depths z0 -> z1 over the segment).
BisectionBracket bracketOn(const RimCase& c, double z0, double z1, double lo, double hi) {
  BisectionBracket b;
  b.lo = lo, b.hi = hi;
  b.dLo = c.rule.ofSample(onPlane(z0, z1, lo, c.perspective), false);
  b.dHi = c.rule.farPlane;
  return b;
}

TEST(RimBias, ThePlaneOfTheRimSetsWhatTheNearVertexKeeps) {
  for (const Light& light : {test::directionalDown(12.0), test::refinementSpot()}) {
    const double bias = 0.08, z0 = 5.0, z1 = 5.4, lo = 0.6, sExit = 0.61;
    RimCase c = rimCase(light, bias);
    const double rim = onPlane(z0, z1, sExit, c.perspective);
    const BisectionBracket b = bracketOn(c, z0, z1, lo, 0.625);
    // One plane from the near end to the rim: the floor alone.
    c.segment.nearDepth = z0 + bias;
    EXPECT_NEAR(rimVertexDepth(c.map, c.segment, b, sExit, rim, c.rule), rim + kRimBiasFloor * bias, 1e-9);
    // The near end 0.02 in front of the rim's plane carried back (the surface bends away between):
    // the floor plus those 0.02.
    c.segment.nearDepth = z0 - 0.02 + bias;
    EXPECT_NEAR(rimVertexDepth(c.map, c.segment, b, sExit, rim, c.rule), rim + kRimBiasFloor * bias + 0.02, 1e-6);
    // Behind it (a fold towards the silhouette): the floor.
    c.segment.nearDepth = z0 + 0.3 + bias;
    EXPECT_NEAR(rimVertexDepth(c.map, c.segment, b, sExit, rim, c.rule), rim + kRimBiasFloor * bias, 1e-9);
    // Far in front: never more than the whole bias, nor beyond d(lo).
    c.segment.nearDepth = z0 - 1.0 + bias;
    EXPECT_NEAR(rimVertexDepth(c.map, c.segment, b, sExit, rim, c.rule), std::min(rim + bias, b.dLo), 1e-9);
  }
}

TEST(RimBias, WithoutWhatTheRuleNeedsTheNearVertexStaysAtItsSample) {
  const Light light = test::directionalDown(12.0);
  const double z0 = 5.0, z1 = 5.4, lo = 0.6, sExit = 0.61, rim = onPlane(z0, z1, sExit, false);
  RimCase c = rimCase(light, 0.0);
  c.segment.nearDepth = z0;
  BisectionBracket b = bracketOn(c, z0, z1, lo, 0.625);
  EXPECT_EQ(rimVertexDepth(c.map, c.segment, b, sExit, rim, c.rule), b.dLo);  // no bias (back capture)
  c = rimCase(light, 0.08);
  c.segment.nearDepth = z0 + 0.08;
  b = bracketOn(c, z0, z1, lo, 0.625);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(rimVertexDepth(c.map, c.segment, b, sExit, nan, c.rule), b.dLo);  // no triangle at the rim
  // lo and the rim within kRimBaseTexels: the plane cannot be carried back; the whole bias, or d(lo).
  const double close = lo + 0.5 * kRimBaseTexels;
  EXPECT_EQ(rimVertexDepth(c.map, c.segment, b, close, onPlane(z0, z1, close, false), c.rule),
            std::min(b.dLo, onPlane(z0, z1, close, false) + 0.08));
  // The near end on the far plane: the whole bias.
  c.segment.nearDepth = c.rule.farPlane;
  EXPECT_NEAR(rimVertexDepth(c.map, c.segment, b, sExit, rim, c.rule), std::min(b.dLo, rim + 0.08), 1e-12);
}

TEST(RimBias, ATriangleShowsTheDepthOfItsPlaneOnTheLightRay) {
  for (const Light& light : {test::directionalDown(12.0), test::refinementSpot()}) {
    const DepthMap map = makeDepthMap(light, 64, 64, CaptureMode::Front);
    const TexelUnprojector unproject(map);
    // A plane tilted against the light: y = 0.5 + 0.3 x.
    const std::array<glm::dvec3, 3> tilted = {glm::dvec3(-2, -0.1, -2), glm::dvec3(2, 1.1, -2), glm::dvec3(0, 0.5, 2)};
    for (const glm::dvec2 at : {glm::dvec2(31.5, 31.5), glm::dvec2(20.25, 40.75), glm::dvec2(70.0, 12.0)}) {
      const double d = triangleDepthAt(map, tilted, at);  // also outside the triangle's image
      ASSERT_TRUE(std::isfinite(d)) << at.x << " " << at.y;
      const glm::dvec3 p = unproject.worldPoint(at.x, at.y, d);
      EXPECT_NEAR(p.y, 0.5 + 0.3 * p.x, 1e-9) << at.x << " " << at.y;
    }
  }
  // Edge-on to a light shining straight down (the plane x = 0.3): no depth.
  const DepthMap down = makeDepthMap(test::directionalDown(12.0), 64, 64, CaptureMode::Front);
  const std::array<glm::dvec3, 3> edgeOn = {glm::dvec3(0.3, 0, -1), glm::dvec3(0.3, 1, 0), glm::dvec3(0.3, 0, 1)};
  EXPECT_TRUE(std::isnan(triangleDepthAt(down, edgeOn, {31.5, 31.5})));
}

}  // namespace
}  // namespace shadowvol
