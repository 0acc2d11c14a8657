// The dual-paraboloid map's conventions (dual_paraboloid.h): frame, projection and its inverse,
// texel centres, stored depth, and the texels' solid angles against the cube map's.
#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/dual_paraboloid.h"
#include "shadowvol/error.h"

namespace shadowvol {
namespace {

constexpr double kPi = 3.14159265358979323846;

Light point() {
  Light l;
  l.type = LightType::Point;
  l.position = {1.0, 2.0, -3.0};
  l.nearPlane = 0.05;
  l.farPlane = 20.0;
  return l;
}

Bounds3 box(const glm::dvec3& lo, const glm::dvec3& hi) {
  Bounds3 b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

TEST(DualParaboloid, FrontLooksAtTheScenesCentreInARightHandedFrame) {
  const DualParaboloid dp = makeDualParaboloid(point(), box({4, 2, -3}, {6, 2, -3}), 64);  // centre +X of the light
  const ParaboloidPoint c = paraboloidProject(dp, {5, 2, -3});
  EXPECT_EQ(c.hemisphere, 0);
  EXPECT_NEAR(glm::length(c.xy), 0.0, 1e-12);
  EXPECT_NEAR(c.distance, 4.0, 1e-12);
  const ParaboloidPoint b = paraboloidProject(dp, {-3, 2, -3});  // straight behind: the back map's centre
  EXPECT_EQ(b.hemisphere, 1);
  EXPECT_NEAR(glm::length(b.xy), 0.0, 1e-12);
  const glm::dmat3 f = glm::transpose(dp.toFront);  // columns x, y, axis
  EXPECT_NEAR(glm::dot(glm::cross(f[0], f[1]), f[2]), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(f[0], f[1]), 0.0, 1e-12);
  EXPECT_NEAR(f[1].y, 1.0, 1e-12);  // lightUp's world +Y
  // The light at the bounds' centre: the front looks down.
  const DualParaboloid down = makeDualParaboloid(point(), box({0, 1, -4}, {2, 3, -2}), 64);
  EXPECT_NEAR(paraboloidDirection(down, 0, {0, 0}).y, -1.0, 1e-12);
  EXPECT_NEAR(paraboloidDirection(down, 1, {0, 0}).y, 1.0, 1e-12);
  EXPECT_NEAR(down.farDistance, 20.0 * std::sqrt(3.0), 1e-12);
}

TEST(DualParaboloid, ProjectionAndDirectionAreInverses) {
  const DualParaboloid dp = makeDualParaboloid(point(), box({-5, -1, -9}, {3, 0, 1}), 101);
  for (int h = 0; h < 2; ++h)
    for (double x = -0.95; x <= 0.95; x += 0.19)
      for (double y = -0.95; y <= 0.95; y += 0.19) {
        if (x * x + y * y > 1.0) continue;
        const glm::dvec3 d = paraboloidDirection(dp, h, {x, y});
        EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
        const ParaboloidPoint p = paraboloidProject(dp, dp.position + 2.5 * d);
        // The rim (r = 1) is the seam: either map may take it.
        if (x * x + y * y < 0.999) {
          EXPECT_EQ(p.hemisphere, h);
        }
        if (p.hemisphere != h) continue;
        EXPECT_NEAR(p.xy.x, x, 1e-12);
        EXPECT_NEAR(p.xy.y, y, 1e-12);
        EXPECT_NEAR(p.distance, 2.5, 1e-12);
      }
  const ParaboloidPoint self = paraboloidProject(dp, dp.position);
  EXPECT_EQ(self.hemisphere, 0);
  EXPECT_EQ(self.distance, 0.0);
  EXPECT_TRUE(std::isfinite(self.xy.x) && std::isfinite(self.xy.y));
}

TEST(DualParaboloid, TexelCentresSideAndStoredDepth) {
  EXPECT_EQ(dualParaboloidSide(256), 443);  // 2 x 443^2 = 392498 ~ 6 x 256^2 = 393216
  EXPECT_EQ(dualParaboloidSide(1), 2);
  EXPECT_NEAR(paraboloidTexelCentre(4, 0, 3).x, -0.75, 1e-15);
  EXPECT_NEAR(paraboloidTexelCentre(4, 0, 3).y, 0.75, 1e-15);
  const DualParaboloid dp = makeDualParaboloid(point(), Bounds3{}, 8);
  EXPECT_NEAR(paraboloidStoredDepth(dp, dp.nearDistance), 1.0, 1e-15);
  EXPECT_NEAR(paraboloidStoredDepth(dp, dp.farDistance), 0.0, 1e-15);
  Light spot = point();
  spot.type = LightType::Spot;
  EXPECT_THROW(makeDualParaboloid(spot, Bounds3{}, 8), InputError);
}

TEST(DualParaboloid, TexelSolidAnglesAgainstTheCubeMaps) {
  // Both maps cover the sphere: the texels in use sum to about 4 pi.
  const int n = 128, m = dualParaboloidSide(n);
  const TexelSolidAngles c = cubeTexelSolidAngles(n), p = paraboloidTexelSolidAngles(m);
  // The cube's centre texel against its corner: (1 + 1 + 1)^(3/2) = 5.196 in the limit.
  EXPECT_NEAR(c.largest / c.smallest, 3.0 * std::sqrt(3.0), 0.1);
  EXPECT_NEAR(c.largest, std::pow(2.0 / n, 2), 1e-3 * std::pow(2.0 / n, 2));
  // The paraboloid's element 4 / (1 + r^2)^2: 4 at the centre, 1 at the rim.
  EXPECT_NEAR(p.largest / p.smallest, 4.0, 0.15);
  EXPECT_NEAR(p.largest, 4.0 * std::pow(2.0 / m, 2), 1e-3 * 4.0 * std::pow(2.0 / m, 2));
  EXPECT_NEAR(p.usedFraction, kPi / 4.0, 0.01);
  EXPECT_EQ(c.usedFraction, 1.0);
  // At the same texel count the paraboloid's coarsest texel is 4/3 of the cube's.
  EXPECT_NEAR(p.largest / c.largest, 4.0 / 3.0, 0.01);
}

}  // namespace
}  // namespace shadowvol
