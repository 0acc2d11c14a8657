// The search for hidden surfaces (nearer_surfaces.h): which quads' squares hold part of a surface
// the capture records nearer than a limit, from the triangles' projections. Checked against the
// analytic scenes' own capture (every texel centre the capture hits lies in the squares of its quads,
// on the surface it records), on a bar that no texel centre sees, per capture mode's facing rule, at
// the limit itself, at the depth range's ends and for any thread count.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include "analytic_scene.h"
#include "shadowvol/nearer_surfaces.h"
#include "shadowvol/primitives.h"
#include "test_util.h"

namespace shadowvol {
namespace {

using test::AnalyticScene;

std::vector<std::uint8_t> search(const DepthMap& map, const TriangleMesh& mesh, const std::vector<float>& limit) {
  std::vector<std::uint8_t> flags(limit.size(), 0);
  const TriangleSoup soup = soupOf(mesh);
  findNearerSurfaces(map, std::span<const TriangleSoup>(&soup, 1), limit, flags);
  return flags;
}

std::vector<float> limits(const DepthMap& map, float value) {
  return std::vector<float>(std::size_t(map.width - 1) * std::size_t(map.height - 1), value);
}

// A bar 0.08 wide between two columns of texel centres (32 x 32 over [-4, 4]: centres at
// +-(k + 0.5) * 0.25), 2 long, under a directional light straight down.
AnalyticScene thinBar() {
  AnalyticScene s;
  s.boxes.push_back({{0.05, 1.5, 0.3}, {0.04, 0.05, 1.0}, 0.0});
  return s;
}

TEST(NearerSurfaces, ABarBetweenTexelCentresFlagsExactlyTheQuadsItsImageOverlaps) {
  const AnalyticScene s = thinBar();
  const TriangleMesh mesh = s.mesh();
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
    const DepthMap map = s.depthMap(test::directionalDown(6.0), 32, 32, mode);
    ASSERT_EQ(map.hitCount(), 0u);  // no texel centre sees it
    double i0 = 1e300, i1 = -1e300, j0 = 1e300, j1 = -1e300;
    for (const glm::vec3& p : mesh.positions) {
      const glm::dvec2 t = map.texelOf(glm::dvec3(p));
      i0 = std::min(i0, t.x), i1 = std::max(i1, t.x), j0 = std::min(j0, t.y), j1 = std::max(j1, t.y);
    }
    ASSERT_EQ(std::floor(i0), std::floor(i1));  // one column of quads
    const std::vector<std::uint8_t> flags = search(map, mesh, limits(map, float(map.farPlane)));
    std::size_t flagged = 0;
    for (int qj = 0; qj < 31; ++qj)
      for (int qi = 0; qi < 31; ++qi) {
        const bool overlaps = qi <= i1 && qi + 1 >= i0 && qj <= j1 && qj + 1 >= j0;
        EXPECT_EQ(flags[std::size_t(qj) * 31 + qi] != 0, overlaps) << qi << " " << qj << " " << toString(mode);
        flagged += flags[std::size_t(qj) * 31 + qi];
      }
    EXPECT_GE(flagged, 8u);  // 2 long: 8 texels and a part
  }
}

// Back capture records surfaces facing away from the light only: a square facing the light (an
// open ground plane) is never a hidden surface for it; front and midpoint capture record it.
TEST(NearerSurfaces, BackCaptureSkipsSurfacesFacingTheLight) {
  TriangleMesh square = makePlane(1.0, 1.0, 1);
  for (glm::vec3& p : square.positions) p.y += 1.0f;
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
    const DepthMap map = makeDepthMap(test::directionalDown(6.0), 32, 32, mode);
    const std::vector<std::uint8_t> flags = search(map, square, limits(map, float(map.farPlane)));
    const auto n = std::count(flags.begin(), flags.end(), std::uint8_t(1));
    if (mode == CaptureMode::Back)
      EXPECT_EQ(n, 0) << toString(mode);
    else
      EXPECT_EQ(n, 25) << toString(mode);  // texel coordinates 13.5 to 17.5 each way: quads 13 to 17
    // Turned over (facing away from the light), back capture records it too.
    TriangleMesh flipped = square;
    for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
    const std::vector<std::uint8_t> back = search(map, flipped, limits(map, float(map.farPlane)));
    EXPECT_EQ(std::count(back.begin(), back.end(), std::uint8_t(1)), 25) << toString(mode);
  }
}

// A plane rising towards +x: its nearest point in a quad is on the quad's side of largest x, and
// the quad is flagged when that depth is below the limit, not when it is above.
TEST(NearerSurfaces, AQuadIsFlaggedWhenTheNearestPointInItsSquareIsBelowTheLimit) {
  TriangleMesh slope = makePlane(20.0, 20.0, 1);
  for (glm::vec3& p : slope.positions) p.y = 1.0f + 0.1f * p.x;
  const DepthMap map = makeDepthMap(test::directionalDown(6.0), 16, 16, CaptureMode::Front);
  for (int qi : {2, 7, 13})
    for (int qj : {3, 11}) {
      const double xMax = std::max(map.worldPoint(qi + 1, qj, 1.0).x, map.worldPoint(qi, qj, 1.0).x);
      const double nearest = map.viewDepthOf({xMax, 1.0 + 0.1 * xMax, 0.0});
      for (double delta : {-1e-4, 1e-4}) {
        std::vector<float> limit = limits(map, -1.0f);
        const std::size_t q = std::size_t(qj) * 15 + std::size_t(qi);
        limit[q] = float(nearest + delta);
        const std::vector<std::uint8_t> flags = search(map, slope, limit);
        EXPECT_EQ(flags[q] != 0, delta > 0.0) << qi << " " << qj << " " << delta;
        EXPECT_EQ(std::count(flags.begin(), flags.end(), std::uint8_t(1)), flags[q]);  // the others: limit -1
      }
    }
}

// The same under a spot light, where the inverse depth is what varies linearly over the image: the
// nearest point of a quad's square lies on one of its corners' rays (found here by intersecting
// each with the plane), and the quad is flagged just below that depth, not just above; in every
// quad the plane's image covers, so that the quads the triangle covers whole (where the search
// reads the plane over the square instead of clipping) and those along its sides are both checked.
TEST(NearerSurfaces, UnderASpotLightAQuadIsFlaggedExactlyAtItsNearestCorner) {
  TriangleMesh slope = makePlane(20.0, 20.0, 1);
  for (glm::vec3& p : slope.positions) p.y = 1.0f + 0.1f * p.x;
  const DepthMap map = makeDepthMap(test::refinementSpot(), 16, 16, CaptureMode::Front);
  const auto planeDepth = [&](double x, double y) {  // the plane's view depth on the ray through (x, y)
    const glm::dvec3 p1 = map.worldPoint(x, y, 1.0), p2 = map.worldPoint(x, y, 2.0);
    const double f1 = p1.y - 1.0 - 0.1 * p1.x, f2 = p2.y - 1.0 - 0.1 * p2.x;
    return 1.0 - f1 / (f2 - f1);
  };
  int checked = 0;
  for (int qj = 0; qj < 15; ++qj)
    for (int qi = 0; qi < 15; ++qi) {
      const double nearest =
          std::min({planeDepth(qi, qj), planeDepth(qi + 1, qj), planeDepth(qi, qj + 1), planeDepth(qi + 1, qj + 1)});
      if (!(nearest > map.nearPlane && nearest < map.farPlane)) continue;
      for (double delta : {-1e-4, 1e-4}) {
        std::vector<float> limit = limits(map, -1.0f);
        const std::size_t q = std::size_t(qj) * 15 + std::size_t(qi);
        limit[q] = float(nearest * (1.0 + delta));
        const std::vector<std::uint8_t> flags = search(map, slope, limit);
        EXPECT_EQ(flags[q] != 0, delta > 0.0) << qi << " " << qj << " " << delta;
        EXPECT_EQ(std::count(flags.begin(), flags.end(), std::uint8_t(1)), flags[q]);  // the others: limit -1
      }
      ++checked;
    }
  EXPECT_EQ(checked, 15 * 15);
}

// Only the part within [near, far] counts: a box beyond the far plane is never hidden surface,
// one reaching across the far plane is where it lies before it. A spot light's plane reaching
// behind its apex is clipped at the near plane (no point at infinity).
TEST(NearerSurfaces, OnlyThePartWithinTheDepthRangeCounts) {
  const DepthMap map = makeDepthMap(test::directionalDown(6.0), 32, 32, CaptureMode::Front);  // far: y = -1
  AnalyticScene below;
  below.boxes.push_back({{0.0, -2.0, 0.0}, {1.0, 0.5, 1.0}, 0.0});
  const std::vector<std::uint8_t> none = search(map, below.mesh(), limits(map, float(map.farPlane)));
  EXPECT_EQ(std::count(none.begin(), none.end(), std::uint8_t(1)), 0);
  // A ramp from y = 1 at x = -1 down to y = -3 at x = 1 crosses the far plane (y = -1) at x = 0.
  TriangleMesh ramp = makePlane(2.0, 2.0, 1);
  for (glm::vec3& p : ramp.positions) p.y = -1.0f - 2.0f * p.x;
  const std::vector<std::uint8_t> part = search(map, ramp, limits(map, float(map.farPlane)));
  for (int qj = 0; qj < 31; ++qj)
    for (int qi = 0; qi < 31; ++qi)
      if (part[std::size_t(qj) * 31 + qi]) {
        EXPECT_LE(std::min(map.worldPoint(qi, qj, 1.0).x, map.worldPoint(qi + 1, qj, 1.0).x), 1e-9) << qi << " " << qj;
      }
  EXPECT_GT(std::count(part.begin(), part.end(), std::uint8_t(1)), 0);

  // y = 5 + 0.5 x meets every ray of the spot light at depths 1.4 to 2.4 and rises behind its apex
  // plane (y = 7 at x = 4): clipped there, it still covers every quad; it faces the light.
  TriangleMesh tilted = makePlane(40.0, 40.0, 1);
  for (glm::vec3& p : tilted.positions) p = glm::vec3(p.x, 5.0f + 0.5f * p.x, p.z + 0.4f);
  for (CaptureMode mode : {CaptureMode::Front, CaptureMode::Back}) {
    const DepthMap spotMap = makeDepthMap(test::refinementSpot(), 16, 16, mode);
    const std::vector<std::uint8_t> flags = search(spotMap, tilted, limits(spotMap, float(spotMap.farPlane)));
    EXPECT_EQ(std::count(flags.begin(), flags.end(), std::uint8_t(1)), mode == CaptureMode::Front ? 15 * 15 : 0);
  }
}

// Every texel centre the capture hits lies on the surface it records, in the closed squares of its
// up to four quads: with each quad's limit just beyond its farthest hit corner, every quad with a
// hit corner is flagged. Spot and directional lights, every capture mode, boxes turned and not over
// the ground (midpoint capture records the middle, behind the first surface the search reads). No
// side of a box lies on a texel centre, where the analytic capture and the float mesh could differ.
TEST(NearerSurfaces, EveryQuadWithACapturedCornerIsFlagged) {
  AnalyticScene s;
  s.boxes.push_back({{0.0, 1.5, 0.0}, {1.3, 0.4, 0.9}, 27.0});
  s.boxes.push_back({{-1.63, 0.65, 1.17}, {0.3, 0.6, 0.2}, 0.0});  // sides off the texel centres
  s.ground = true;
  const TriangleMesh mesh = s.mesh();
  for (const Light& light : {test::directionalDown(6.0), test::refinementSpot()})
    for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Midpoint}) {
      const DepthMap map = s.depthMap(light, 40, 40, mode);
      ASSERT_GT(map.hitCount(), 100u);
      std::vector<float> limit = limits(map, -1.0f);
      std::vector<std::size_t> withHit;
      for (int qj = 0; qj < 39; ++qj)
        for (int qi = 0; qi < 39; ++qi) {
          float farthest = -1.0f;
          for (int c = 0; c < 4; ++c) {
            const float d = map.at(qi + (c & 1), qj + (c >> 1));
            if (!DepthMap::isNoHit(d)) farthest = std::max(farthest, d);
          }
          if (farthest < 0.0f) continue;
          limit[std::size_t(qj) * 39 + qi] = farthest * (1.0f + 1e-5f);
          withHit.push_back(std::size_t(qj) * 39 + qi);
        }
      const std::vector<std::uint8_t> flags = search(map, mesh, limit);
      std::size_t missing = 0;
      for (std::size_t q : withHit) missing += flags[q] == 0;
      EXPECT_EQ(missing, 0u) << (light.type == LightType::Spot ? "spot " : "directional ") << toString(mode);
    }
}

// A sliver 0.004 wide across the whole map at 45 degrees flags the quads along it: every quad its
// centre line passes through, and none farther from that line than its width allows. (The search
// walks the rows the image crosses, not its bounding box.) A wall edge-on to the light flags
// nothing: no ray of the capture records it, and neither does a triangle without area.
TEST(NearerSurfaces, ASliverAcrossTheMapFlagsTheQuadsAlongItAndAnEdgeOnWallNone) {
  const DepthMap map = makeDepthMap(test::directionalDown(6.0), 256, 256, CaptureMode::Front);
  TriangleMesh sliver;
  sliver.positions = {{-3.9f, 1.0f, -3.9f}, {3.9f, 1.0f, 3.9f}, {3.904f, 1.0f, 3.9f}};
  sliver.triangles = {{0, 1, 2}};
  const std::vector<std::uint8_t> flags = search(map, sliver, limits(map, float(map.farPlane)));
  const glm::dvec2 a = map.texelOf({-3.9, 1.0, -3.9}), b = map.texelOf({3.9, 1.0, 3.9});
  std::vector<std::uint8_t> onLine(flags.size(), 0);
  for (int k = 0; k <= 100000; ++k) {
    const glm::dvec2 t = a + (b - a) * (k / 100000.0);
    onLine[std::size_t(std::floor(t.y)) * 255 + std::size_t(std::floor(t.x))] = 1;
  }
  std::size_t flagged = 0;
  for (int qj = 0; qj < 255; ++qj)
    for (int qi = 0; qi < 255; ++qi) {
      const std::size_t q = std::size_t(qj) * 255 + std::size_t(qi);
      if (onLine[q]) {
        EXPECT_TRUE(flags[q]) << qi << " " << qj;
      }
      flagged += flags[q];
      if (!flags[q]) continue;
      // The square's centre lies within half a diagonal plus the sliver's width of the line.
      const glm::dvec2 c(qi + 0.5, qj + 0.5), d = glm::normalize(b - a);
      const double off = std::abs((c.x - a.x) * d.y - (c.y - a.y) * d.x);
      EXPECT_LE(off, std::sqrt(0.5) + 0.2) << qi << " " << qj;
    }
  EXPECT_LT(flagged, 3u * 255u);  // along the diagonal, not its bounding box (255 x 255)

  TriangleMesh wall;  // the plane x = 0.3 from y = 0 to 2: edge-on to the light straight down
  wall.positions = {{0.3f, 0.0f, -1.0f}, {0.3f, 2.0f, -1.0f}, {0.3f, 2.0f, 1.0f}, {0.3f, 0.0f, 1.0f}};
  wall.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 2, 1}};  // both facings
  const std::vector<std::uint8_t> none = search(map, wall, limits(map, float(map.farPlane)));
  EXPECT_EQ(std::count(none.begin(), none.end(), std::uint8_t(1)), 0);
}

TEST(NearerSurfaces, DeterministicForAnyThreadCount) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f), h(-1.0f, 4.0f);
  TriangleMesh soup;
  for (int t = 0; t < 20000; ++t) {
    const auto base = std::uint32_t(soup.positions.size());
    const glm::vec3 c(u(rng), h(rng), u(rng));
    for (int k = 0; k < 3; ++k) soup.positions.push_back(c + 0.05f * glm::vec3(u(rng), u(rng), u(rng)));
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front}) {
    const DepthMap map = makeDepthMap(test::refinementSpot(), 64, 64, mode);
    std::vector<float> limit = limits(map, 0.0f);
    for (std::size_t q = 0; q < limit.size(); ++q) limit[q] = float(map.nearPlane + (q % 97) * 0.08);
    std::vector<std::uint8_t> one;
    {
      tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
      one = search(map, soup, limit);
    }
    const std::vector<std::uint8_t> many = search(map, soup, limit);
    EXPECT_EQ(one, many) << toString(mode);
    EXPECT_GT(std::count(one.begin(), one.end(), std::uint8_t(1)), 100) << toString(mode);
  }
}

}  // namespace
}  // namespace shadowvol
