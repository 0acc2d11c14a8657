// The bias of a snapped crossing's near vertex with the sub-grid and front capture
// (volume/rim_bias.h, rimVertexDepth), and the depth a triangle shows on a light ray
// (triangle_exit.h, triangleDepthAt), from the triangle the surface-end oracle gives.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "shadowvol/depth_map.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/triangle_exit.h"
#include "test_util.h"
#include "volume/rim_bias.h"

namespace shadowvol {
namespace {

// A plane tilted against the light, y = 0.5 + 0.3 x, as the rim's triangle.
const std::array<glm::dvec3, 3> kTilted = {glm::dvec3(-3, -0.4, -3), glm::dvec3(3, 1.4, -3), glm::dvec3(0, 0.5, 3)};

TEST(RimBias, ThePlaneOfTheRimSetsWhatTheNearVertexKeeps) {
  for (const Light& light : {test::directionalDown(12.0), test::refinementSpot()}) {
    const DepthMap map = makeDepthMap(light, 64, 64, CaptureMode::Front);
    const TexelUnprojector unproject(map);
    const double bias = 0.08;
    const SheetDepthRule rule(map, bias, 0.0);
    const glm::dvec2 nearEnd(20.0, 30.0), at(20.6, 30.0);
    const double rim = triangleDepthAt(unproject, kTilted, at), plane = triangleDepthAt(unproject, kTilted, nearEnd);
    Crossing c;
    c.rim = kTilted;
    c.nearDepth = triangleDepthAt(unproject, kTilted, {20.59, 30.0}) + bias;  // d(lo): a sample with the bias
    const double floor = volume::kRimBiasFloor * bias;
    // One plane from the near end to the rim: the floor alone.
    EXPECT_NEAR(volume::rimVertexDepth(unproject, c, at, nearEnd, plane + bias, rule), rim + floor, 1e-9);
    // The near end 0.02 in front of the rim's plane (the surface bends away between): the floor plus
    // those 0.02.
    EXPECT_NEAR(volume::rimVertexDepth(unproject, c, at, nearEnd, plane - 0.02 + bias, rule), rim + floor + 0.02, 1e-9);
    // Behind it (a fold towards the silhouette): the floor.
    EXPECT_NEAR(volume::rimVertexDepth(unproject, c, at, nearEnd, plane + 0.3 + bias, rule), rim + floor, 1e-9);
    // A rim far nearer the light than the near sample (a plane that reaches off): never nearer than
    // the sample's own surface, d(lo) less the bias.
    Crossing high = c;
    high.nearDepth = rim + 0.5 + bias;
    EXPECT_NEAR(volume::rimVertexDepth(unproject, high, at, nearEnd, plane + bias, rule), rim + 0.5, 1e-9);
    // Far in front: never more than the whole bias, nor beyond d(lo).
    EXPECT_NEAR(volume::rimVertexDepth(unproject, c, at, nearEnd, plane - 1.0 + bias, rule),
                std::min(rim + bias, c.nearDepth), 1e-9);
  }
}

TEST(RimBias, ARimBehindTheSampleTakesTheNearVertexDownToIt) {
  for (const Light& light : {test::directionalDown(12.0), test::refinementSpot()}) {
    const DepthMap map = makeDepthMap(light, 64, 64, CaptureMode::Front);
    const TexelUnprojector unproject(map);
    const double bias = 0.08, floor = volume::kRimBiasFloor * bias;
    const SheetDepthRule rule(map, bias, 0.0);
    const glm::dvec2 nearEnd(20.0, 30.0), at(20.6, 30.0);
    const double rim = triangleDepthAt(unproject, kTilted, at), plane = triangleDepthAt(unproject, kTilted, nearEnd);
    // The last near sample 0.3 in front of the rim (the triangle falls steeply to where it ends).
    Crossing c;
    c.rim = kTilted;
    c.nearDepth = rim - 0.3 + bias;
    c.farDepth = rim + 2.0;
    EXPECT_NEAR(volume::rimVertexDepth(unproject, c, at, nearEnd, plane + bias, rule), rim + floor, 1e-9);
    // Never past the middle between the near and the far sample.
    Crossing close = c;
    close.farDepth = c.nearDepth + 0.2;
    EXPECT_NEAR(volume::rimVertexDepth(unproject, close, at, nearEnd, plane + bias, rule), c.nearDepth + 0.1, 1e-9);
    // Nor past the triangle's deepest corner, (-3, -0.4, -3): the plane 0.3 below it, off the
    // triangle, does not count.
    const glm::dvec2 off = map.texelOf(glm::dvec3(-4.0, -0.7, -2.9));
    const double corner = unproject.viewDepth(kTilted[0]);
    ASSERT_GT(triangleDepthAt(unproject, kTilted, off), corner + 0.1);
    Crossing beyond = c;
    beyond.nearDepth = corner - 0.3 + bias;
    EXPECT_NEAR(volume::rimVertexDepth(unproject, beyond, off, off - glm::dvec2(0.6, 0.0),
                                       triangleDepthAt(unproject, kTilted, off - glm::dvec2(0.6, 0.0)) + bias, rule),
                corner + floor, 1e-9);
  }
}

TEST(RimBias, WithoutWhatTheRuleNeedsTheNearVertexStaysAtItsSample) {
  const DepthMap map = makeDepthMap(test::directionalDown(12.0), 64, 64, CaptureMode::Front);
  const TexelUnprojector unproject(map);
  const glm::dvec2 nearEnd(20.0, 30.0), at(20.6, 30.0);
  const double plane = triangleDepthAt(unproject, kTilted, nearEnd);
  Crossing c;
  c.nearDepth = triangleDepthAt(unproject, kTilted, {20.59, 30.0}) + 0.08;
  EXPECT_FALSE(c.hasRim());  // not snapped
  EXPECT_EQ(volume::rimVertexDepth(unproject, c, at, nearEnd, plane + 0.08, SheetDepthRule(map, 0.08, 0.0)),
            c.nearDepth);
  c.rim = kTilted;
  EXPECT_EQ(volume::rimVertexDepth(unproject, c, at, nearEnd, plane, SheetDepthRule(map, 0.0, 0.0)),
            c.nearDepth);  // no bias (back capture)
  // A rim triangle edge-on to the light shining straight down (the plane x = 0.3): no depth there.
  c.rim = {glm::dvec3(0.3, 0, -1), glm::dvec3(0.3, 1, 0), glm::dvec3(0.3, 0, 1)};
  EXPECT_EQ(volume::rimVertexDepth(unproject, c, at, nearEnd, plane + 0.08, SheetDepthRule(map, 0.08, 0.0)),
            c.nearDepth);
}

TEST(RimBias, ATriangleShowsTheDepthOfItsPlaneOnTheLightRay) {
  for (const Light& light : {test::directionalDown(12.0), test::refinementSpot()}) {
    const DepthMap map = makeDepthMap(light, 64, 64, CaptureMode::Front);
    const TexelUnprojector unproject(map);
    // A plane tilted against the light: y = 0.5 + 0.3 x.
    const std::array<glm::dvec3, 3> tilted = {glm::dvec3(-2, -0.1, -2), glm::dvec3(2, 1.1, -2), glm::dvec3(0, 0.5, 2)};
    for (const glm::dvec2 at : {glm::dvec2(31.5, 31.5), glm::dvec2(20.25, 40.75), glm::dvec2(70.0, 12.0)}) {
      const double d = triangleDepthAt(unproject, tilted, at);  // also outside the triangle's image
      ASSERT_TRUE(std::isfinite(d)) << at.x << " " << at.y;
      const glm::dvec3 p = unproject.worldPoint(at.x, at.y, d);
      EXPECT_NEAR(p.y, 0.5 + 0.3 * p.x, 1e-9) << at.x << " " << at.y;
    }
  }
  // Edge-on to a light shining straight down (the plane x = 0.3): no depth.
  const DepthMap down = makeDepthMap(test::directionalDown(12.0), 64, 64, CaptureMode::Front);
  const std::array<glm::dvec3, 3> edgeOn = {glm::dvec3(0.3, 0, -1), glm::dvec3(0.3, 1, 0), glm::dvec3(0.3, 0, 1)};
  EXPECT_TRUE(std::isnan(triangleDepthAt(TexelUnprojector(down), edgeOn, {31.5, 31.5})));
}

}  // namespace
}  // namespace shadowvol
