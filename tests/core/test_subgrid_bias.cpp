// The sub-grid's bias with front capture (docs/volume.md "Sub-grid", step 8): the rule a sub-cell's
// centre sample sets (volume/subgrid_bias.h), the crease quads (volume/crease_quads.h), and on a
// sphere sunk into the ground (a concave crease round it) that the volume keeps lit surfaces round
// the crease out and more of the contact shadow in than the plain refined sheet does.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "analytic_scene.h"
#include "mesh_invariants.h"
#include "shadowvol/boundary_edges.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/volume_builder.h"
#include "test_util.h"
#include "volume/crease_quads.h"
#include "volume/quad_codes.h"
#include "volume/sheet_depths.h"
#include "volume/subgrid_bias.h"

namespace shadowvol {
namespace {

using volume::kSubgridBiasFloor;
using volume::subCellBias;

TEST(SubgridBias, ACellSampleSetsItsCornersBias) {
  const double b = 0.2, far = 50.0;
  const auto unknown = [] { return std::numeric_limits<double>::infinity(); };
  const double floor = kSubgridBiasFloor * b / 4;
  // On a plane the centre lies on the sheet: the floor.
  EXPECT_NEAR(subCellBias({10.0, 11.0, 12.0, 11.0}, 11.0, unknown, b, 4, false, far), floor, 1e-12);
  // A spot light's plane: the inverse depth is linear; its midpoint is the centre's.
  const double inv[4] = {1.0 / 10.0, 1.0 / 11.0, 1.0 / 12.0, 1.0 / 11.0};
  EXPECT_NEAR(
      subCellBias({1 / inv[0], 1 / inv[1], 1 / inv[2], 1 / inv[3]}, 2.0 / (inv[0] + inv[2]), unknown, b, 4, true, far),
      floor, 1e-12);
  // Behind the sheet by 0.05 (the lower diagonal's midpoint is the sheet): twice that where nothing
  // bounds a fold, the lattice's fold bound where it lies between once and twice, else once.
  EXPECT_NEAR(subCellBias({10.0, 10.0, 10.0, 10.4}, 10.05, unknown, b, 4, false, far), 0.1 + floor, 1e-12);
  EXPECT_NEAR(subCellBias(
                  {10.0, 10.0, 10.0, 10.4}, 10.05, [] { return 0.07; }, b, 4, false, far),
              0.07 + floor, 1e-12);
  EXPECT_NEAR(subCellBias(
                  {10.0, 10.0, 10.0, 10.4}, 10.05, [] { return 0.01; }, b, 4, false, far),
              0.05 + floor, 1e-12);
  // In front of it: the floor; far behind (another surface) or far anywhere: all of the bias.
  EXPECT_NEAR(subCellBias({10.0, 10.0, 10.0, 10.0}, 9.5, unknown, b, 4, false, far), floor, 1e-12);
  EXPECT_EQ(subCellBias({10.0, 10.0, 10.0, 10.0}, 10.0 + 2.5 * b, unknown, b, 4, false, far), b);
  EXPECT_EQ(subCellBias({10.0, 10.0, 10.0, 10.0}, 10.0 + 1.5 * b, unknown, b, 4, false, far), b);  // clamped
  EXPECT_EQ(subCellBias({10.0, far, 10.0, 10.0}, 10.0, unknown, b, 4, false, far), b);
  EXPECT_EQ(subCellBias({10.0, 10.0, 10.0, 10.0}, far, unknown, b, 4, false, far), b);
  // The fold bound is asked for only where the centre lies behind and the bias is not at its cap.
  int calls = 0;
  const auto counted = [&] {
    ++calls;
    return 0.0;
  };
  subCellBias({10.0, 10.0, 10.0, 10.0}, 9.5, counted, b, 4, false, far);
  subCellBias({10.0, 10.0, 10.0, 10.0}, 10.0 + 1.5 * b, counted, b, 4, false, far);
  EXPECT_EQ(calls, 0);
  EXPECT_NEAR(subCellBias({10.0, 10.0, 10.0, 10.4}, 10.05, counted, b, 4, false, far), 0.05 + floor, 1e-12);
  EXPECT_EQ(calls, 1);
  // The floor scales with 1 / S.
  EXPECT_NEAR(subCellBias({10.0, 10.0, 10.0, 10.0}, 10.0, unknown, b, 8, false, far), kSubgridBiasFloor * b / 8, 1e-12);
}

// A directional light from the side and above (not axis-aligned), over an 8 x 8 square.
Light slantedLight() {
  Light light = test::directionalDown(12.0);
  light.direction = glm::normalize(glm::dvec3(-0.6, -1.0, -0.3));
  light.position = -5.0 * light.direction;
  return light;
}

// A spot light aimed at the origin from the side and above.
Light slantedSpot() {
  Light light = test::refinementSpot();
  light.position = {3.0, 3.5, 1.5};
  light.direction = glm::normalize(-light.position);
  return light;
}

// A dome on the ground: a unit sphere whose centre lies 0.4 below it, meeting it on a circle of
// radius sqrt(0.84) round the origin at 66 degrees (a concave crease that the light sees all round).
constexpr double kCentreY = -0.4;
test::AnalyticScene sunkSphere() {
  test::AnalyticScene s;
  s.spheres.push_back({{0.0, kCentreY, 0.0}, 1.0});
  s.ground = true;
  return s;
}
const double kCreaseRadius = std::sqrt(1.0 - kCentreY * kCentreY);

// The crease quads of a map, after its boundary edges (as the builder finds them).
std::vector<std::uint32_t> creaseQuadsOf(const DepthMap& map, double bias, int s) {
  const SheetDepthRule rule(map, bias, 0.0);
  const volume::SheetDepths sheet(map, rule);
  std::vector<std::uint8_t> bits(std::size_t(map.width) * map.height, 0);
  findBoundaryEdges(map, rule, false, {}, bits.data());
  return volume::findCreaseQuads(sheet, s, bits.data());
}

TEST(SubgridBias, CreaseQuadsLieOnTheCrease) {
  for (const Light& light : {slantedLight(), slantedSpot()}) {
    const DepthMap ground = test::AnalyticScene{{}, {}, true}.depthMap(light, 32, 32, CaptureMode::Front);
    EXPECT_TRUE(creaseQuadsOf(ground, defaultBias(ground), 4).empty()) << toString(light.type);  // a plane
    const DepthMap map = sunkSphere().depthMap(light, 32, 32, CaptureMode::Front);
    EXPECT_TRUE(creaseQuadsOf(map, 0.0, 4).empty());  // no bias, nothing to lower
    const std::vector<std::uint32_t> q = creaseQuadsOf(map, defaultBias(map), 4);
    EXPECT_GE(q.size(), 4u) << toString(light.type);
    const TexelUnprojector unproject(map);
    const double texel = 8.0 / 32;
    for (std::uint32_t quad : q) {  // a corner next to a sample by the crease, on the ground 3 texels at most
      const int qi = int(quad % 31), qj = int(quad / 31);
      double nearest = 1e300;
      for (int c = 0; c < 4; ++c) {
        const int i = qi + c % 2, j = qj + c / 2;
        const glm::dvec3 p = unproject.worldPoint(i, j, map.at(i, j));
        nearest = std::min(nearest, std::hypot(std::hypot(p.x, p.z) - kCreaseRadius, p.y));
      }
      EXPECT_LT(nearest, 3.0 * texel) << toString(light.type) << " quad " << qi << " " << qj;
    }
  }
}

// A step between two flat surfaces under a light straight down (the ground's contact with a thin
// open sheet's edge): the sample just beyond it lies half the step behind the chord of its
// neighbours, so a step of more than B / S puts the quads along it on the sub-grid
// (kCreaseChordShare = 1/2), one below B / S does not.
TEST(SubgridBias, AStepOfMoreThanBOverSIsACrease) {
  const Light light = test::directionalDown(12.0);
  const auto stepQuads = [&](double stepInBOverS) {
    DepthMap map = makeDepthMap(light, 32, 32, CaptureMode::Front);
    const double bias = defaultBias(map), step = stepInBOverS * bias / 4.0;
    for (int j = 0; j < map.height; ++j)
      for (int i = 0; i < map.width; ++i) map.depth[map.index(i, j)] = float(i < 16 ? 5.0 - step : 5.0);
    return creaseQuadsOf(map, bias, 4);
  };
  const std::vector<std::uint32_t> q = stepQuads(1.2);
  // The far samples next to the step (column 16, rows 1 to 30 inside the ring) lie behind the
  // chord; the quads holding them are the columns 15 and 16, all but the two rows whose sides
  // touch the ring (far edges: refined quads).
  EXPECT_EQ(q.size(), 2u * 29u);
  for (std::uint32_t quad : q) EXPECT_TRUE(quad % 31 == 15 || quad % 31 == 16) << quad;
  EXPECT_TRUE(stepQuads(0.8).empty());
}

// A step of 1.1 more in ground that falls 0.6 per texel (lit at a grazing angle): the discontinuity
// rule keeps it continuous (1.7 < 3 x 0.6, the steps beside it), so no boundary edge has it, and
// the sample beyond it lies 1.1 / 2 = 0.55 behind the chord, more than 2 B (B about a 0.25
// footprint): before 2026-12-05 that counted as a jump and nothing sampled it. With 2 more (2.6 >
// 1.8) it is a boundary edge, and its quads are refined, not crease quads.
TEST(SubgridBias, AStepTheBoundaryEdgesKeepContinuousIsACrease) {
  const Light light = test::directionalDown(30.0);
  const auto quads = [&](double jump) {
    DepthMap map = makeDepthMap(light, 32, 32, CaptureMode::Front);
    for (int j = 0; j < map.height; ++j)
      for (int i = 0; i < map.width; ++i) map.depth[map.index(i, j)] = float(5.0 + 0.6 * i + (i < 16 ? 0.0 : jump));
    const double bias = defaultBias(map);
    EXPECT_LT(2.0 * bias, 0.5 * jump);
    return creaseQuadsOf(map, bias, 4);
  };
  const std::vector<std::uint32_t> q = quads(1.1);
  EXPECT_EQ(q.size(), 2u * 29u);  // the columns beside the step; the rows next to the ring are refined
  for (std::uint32_t quad : q) EXPECT_TRUE(quad % 31 == 15 || quad % 31 == 16) << quad;
  EXPECT_TRUE(quads(2.0).empty());
}

glm::dvec3 toLight(const Light& light, const glm::dvec3& p) {
  return light.type == LightType::Directional ? -light.direction : glm::normalize(light.position - p);
}

// How far the ray from ground point p to the light passes from the sphere: < 0 where it meets it.
double clearance(const test::AnalyticScene& s, const Light& light, const glm::dvec3& p) {
  const glm::dvec3 u = toLight(light, p);
  const test::AnalyticScene::Sphere& sphere = s.spheres.front();
  const glm::dvec3 c = sphere.centre - p;
  return glm::length(c - std::max(0.0, glm::dot(c, u)) * u) - sphere.radius;
}

// Round the crease: every lit point on the ground or the sphere within a texel of it lies outside
// the volume (no acne), and of the points in shadow the sub-grid's volume holds more than the
// plain refined one, whose sheet keeps the whole bias. Left out: ground points whose ray to the
// light passes within 0.05 texel of the sphere, and sphere points within 3 degrees of its
// terminator (the walls' tolerance round the outline), which leaves out the crease line itself
// (subgrid_bias.h: there the sheet can pass in front of the surface; with the overhead spot at 2 of
// its 360 points).
TEST(SubgridBias, ACreaseKeepsItsLitSurfacesOutAndMoreOfItsShadowIn) {
  const test::AnalyticScene s = sunkSphere();
  for (const Light& light : {slantedLight(), slantedSpot(), test::refinementSpot()}) {
    const bool overhead = light.direction.y < -0.95;  // the dome casts no shadow past its own crease
    const DepthMap map = s.depthMap(light, 32, 32, CaptureMode::Front);
    VolumeBuildOptions o;
    o.refineSteps = 6;
    o.depthOracle = s.oracle();
    const VolumeBuildResult plain = buildVolume(map, o);
    o.refineSubdivisions = 4;  // (no search for hidden surfaces: the analytic sphere has no triangles)
    const VolumeBuildResult grid = buildVolume(map, o);
    const std::string what = toString(light.type);
    ASSERT_TRUE(test::closedOrientedManifold(grid.mesh)) << what;
    EXPECT_GT(grid.stats.creaseQuads, 0u) << what;
    EXPECT_GT(grid.stats.subgridBiasSamples, 0u) << what;
    const double texel = 8.0 / 32;
    std::size_t litPoints = 0, shadowPoints = 0, inGrid = 0, inPlain = 0, creaseLit = 0, creaseAcne = 0;
    for (int a = 0; a < 360; ++a)
      for (int r = 0; r <= 20; ++r) {
        const double phi = a * std::numbers::pi / 180.0, t = (r - 10) * 0.1 * texel;
        glm::dvec3 p;
        const bool ground = t >= 0.0;
        if (ground) {
          p = {(kCreaseRadius + t) * std::cos(phi), 0.0, (kCreaseRadius + t) * std::sin(phi)};  // the ground
        } else {
          const double y = -t;  // up the sphere from the crease
          const double rho = std::sqrt(1.0 - (y - kCentreY) * (y - kCentreY));
          p = {rho * std::cos(phi), y, rho * std::sin(phi)};
        }
        if (r == 10) {  // the crease line itself: counted, not asserted (subgrid_bias.h)
          const glm::dvec3 u = toLight(light, p);
          const auto h = s.hits(p + 1e-9 * u, u);
          if (std::none_of(h.begin(), h.end(), [](const auto& x) { return x.first > 1e-9; })) {
            ++creaseLit;
            creaseAcne += test::insideVolume(grid.mesh, p);
          }
        }
        // A ground point is lit when its ray to the light misses the sphere, a sphere point when it
        // faces the light (cosine > 0).
        const double gap =
            ground ? clearance(s, light, p) : glm::dot(glm::normalize(p - s.spheres.front().centre), toLight(light, p));
        if (std::abs(gap) < (ground ? 0.05 * texel : 0.05)) continue;  // by the shadow's outline
        if (gap > 0.0) {
          ++litPoints;
          EXPECT_FALSE(test::insideVolume(plain.mesh, p)) << what << " lit point " << p.x << " " << p.y << " " << p.z;
          EXPECT_FALSE(test::insideVolume(grid.mesh, p)) << what << " lit point " << p.x << " " << p.y << " " << p.z;
        } else {
          ++shadowPoints;
          inGrid += test::insideVolume(grid.mesh, p);
          inPlain += test::insideVolume(plain.mesh, p);
        }
      }
    EXPECT_GT(litPoints, 1000u) << what;
    if (!overhead) {
      EXPECT_GT(shadowPoints, 200u) << what;
      EXPECT_GT(inGrid, inPlain) << what;
    }
    std::printf(
        "%s: %zu lit points, %zu in shadow: the sub-grid's volume holds %zu, the plain one %zu; on the crease "
        "line %zu of %zu lit points inside\n",
        what.c_str(), litPoints, shadowPoints, inGrid, inPlain, creaseAcne, creaseLit);
  }
}

// A box standing on the ground, turned: its lit sides meet the ground at straight concave creases
// that cross the sub-cells anywhere, not only through their centres. Every lit point on the ground
// or a lit side within a texel of the base, farther than 0.05 texel from the shadow's outline,
// lies outside the volume. (This holds with the centre samples alone too; the fold bound's own
// arithmetic is checked in ACellSampleSetsItsCornersBias, its effect measured in README "Sub-grid
// bias".)
TEST(SubgridBias, ABoxOnTheGroundKeepsItsLitSidesOut) {
  test::AnalyticScene s;
  s.boxes.push_back({{0.1, 0.75, -0.05}, {0.8, 0.75, 0.5}, 25.0});
  s.ground = true;
  const double texel = 8.0 / 32, a = -25.0 * std::numbers::pi / 180.0;
  const auto out = [&](const glm::dvec3& v) {  // out of the box's frame
    return glm::dvec3(std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z) +
           s.boxes[0].centre;
  };
  const auto reaches = [&](const Light& light, const glm::dvec3& p) {  // the light, also 0.05 texel aside
    for (const glm::dvec3 d : {glm::dvec3(0), glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1),
                               glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0)}) {
      const glm::dvec3 q = p + 0.05 * texel * d, u = toLight(light, q);
      for (const auto& h : s.hits(q + 1e-9 * u, u))
        if (h.first > 1e-9) return false;
    }
    return true;
  };
  for (const Light& light : {slantedLight(), slantedSpot()}) {
    const DepthMap map = s.depthMap(light, 32, 32, CaptureMode::Front);
    VolumeBuildOptions o;
    o.refineSteps = 6;
    o.refineSubdivisions = 4;
    o.depthOracle = s.oracle();
    o.nearerSurfaces = s.nearerSurfaces();
    const VolumeBuildResult v = buildVolume(map, o);
    const std::string what = toString(light.type);
    ASSERT_TRUE(test::closedOrientedManifold(v.mesh)) << what;
    EXPECT_GT(v.stats.creaseQuads, 0u) << what;
    std::size_t lit = 0;
    const glm::dvec3 half = s.boxes[0].half;
    for (int side = 0; side < 4; ++side)  // the box's four sides: +x, -x, +z, -z
      for (int k = 1; k < 40; ++k)
        for (int r = 1; r <= 10; ++r) {
          const double f = k / 40.0 * 2.0 - 1.0, d = r * 0.1 * texel;
          const double sx = side == 0 ? 1 : side == 1 ? -1 : 0, sz = side == 2 ? 1 : side == 3 ? -1 : 0;
          const glm::dvec3 along =
              sx != 0 ? glm::dvec3(sx * half.x, 0, f * half.z) : glm::dvec3(f * half.x, 0, sz * half.z);
          const glm::dvec3 normal = out(glm::dvec3(sx, 0, sz)) - out(glm::dvec3(0));
          const glm::dvec3 base = out(along - glm::dvec3(0, half.y, 0));
          for (const glm::dvec3& p : {base + d * normal, base + glm::dvec3(0, d, 0)}) {  // ground, side
            if (p.y > 0.0 && glm::dot(normal, toLight(light, p)) < 0.05) continue;       // a side edge-on or dark
            if (!reaches(light, p)) continue;
            ++lit;
            EXPECT_FALSE(test::insideVolume(v.mesh, p)) << what << " lit point " << p.x << " " << p.y << " " << p.z;
          }
        }
    EXPECT_GT(lit, 500u) << what;
    std::printf("%s: %zu lit points round the base\n", what.c_str(), lit);
  }
}

}  // namespace
}  // namespace shadowvol
