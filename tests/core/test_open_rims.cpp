// The open rims (nearer_surfaces.h: openRims, findOpenRims): an open mesh's border edges, and the
// quads whose squares they pass through in front of a limit. On a plate with a hole between the
// texel centres, a closed box, a box stored as a soup, a degenerate triangle, a soup with
// round-off seams and a non-manifold fin.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/depth_map.h"
#include "shadowvol/nearer_surfaces.h"
#include "shadowvol/primitives.h"
#include "test_util.h"

namespace shadowvol {
namespace {

// A 3 x 3 plate at height 1 whose hole [0.16, 0.34]^2 lies between the texel centres of a 32^2 map
// of [-4, 4]^2 (centres at +-(k + 0.5) / 4): 0.72 texel wide, inside one quad.
TriangleMesh plate() { return test::holedPlate(3.0, 1.0, 0.16, 0.34, 0.16, 0.34); }

std::vector<std::uint8_t> rimSearch(const DepthMap& map, const TriangleMesh& mesh, float limit,
                                    std::uint8_t initial = 0) {
  const std::vector<float> limits(std::size_t(map.width - 1) * std::size_t(map.height - 1), limit);
  std::vector<std::uint8_t> flags(limits.size(), initial);
  TriangleSoup soup = soupOf(mesh);
  const std::vector<std::uint32_t> rims = openRims(mesh);
  soup.rims = rims;
  findOpenRims(map, std::span<const TriangleSoup>(&soup, 1), limits, flags);
  return flags;
}

TEST(OpenRims, TheBorderEdgesOfAnOpenMeshAndNoneOfAClosedOne) {
  const TriangleMesh p = plate();
  const std::vector<std::uint32_t> rims = openRims(p);
  ASSERT_EQ(rims.size(), 2u * 16u);  // the outer border: 3 edges a side; the hole's: 4
  for (std::uint32_t k : rims) {
    const glm::vec3 v = p.positions[k];
    const bool outer = std::max(std::abs(v.x), std::abs(v.z)) == 1.5f;
    const bool hole = (v.x == 0.16f || v.x == 0.34f) && (v.z == 0.16f || v.z == 0.34f);
    EXPECT_TRUE(outer || hole) << v.x << " " << v.z;
  }
  EXPECT_TRUE(openRims(makeBox(1.0, 1.0, 1.0)).empty());
  // A soup (every corner stored apart) is welded by position first: closed as a box.
  const TriangleMesh box = makeBox(1.0, 2.0, 3.0);
  TriangleMesh soup;
  for (const auto& t : box.triangles) {
    const auto base = std::uint32_t(soup.positions.size());
    for (int c = 0; c < 3; ++c) soup.positions.push_back(box.positions[t[std::size_t(c)]]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_TRUE(openRims(soup).empty());
  // A triangle with two equal corners has no area and no rim.
  TriangleMesh degenerate = box;
  degenerate.positions.push_back(glm::vec3(5.0f, 0.0f, 0.0f));
  degenerate.triangles.push_back({0, 0, std::uint32_t(degenerate.positions.size() - 1)});
  EXPECT_TRUE(openRims(degenerate).empty());
}

// A soup whose copies of a vertex differ by round-off (here up to 1e-6 of the diagonal) has a seam
// along every edge; each seam's two rims seal each other (kRimSealShare), so only the plate's border
// and its hole stay. So do the copies of a non-manifold edge (three triangles on one edge).
TEST(OpenRims, ASoupsSeamsAndANonManifoldEdgeAreSealed) {
  const TriangleMesh p = plate();
  TriangleMesh soup;
  std::uint32_t jitter = 1;
  for (const auto& t : p.triangles) {
    const auto base = std::uint32_t(soup.positions.size());
    for (int c = 0; c < 3; ++c) {
      jitter = jitter * 1103515245u + 12345u;  // deterministic, +-2e-6 per coordinate
      const float d = (float((jitter >> 16) % 2001) - 1000.0f) * 2e-9f;
      soup.positions.push_back(p.positions[t[std::size_t(c)]] + glm::vec3(d, -d, 0.5f * d));
    }
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const std::vector<std::uint32_t> rims = openRims(soup);
  ASSERT_EQ(rims.size(), 2u * 16u);  // the border's 12 and the hole's 4, as welded
  for (std::uint32_t k : rims) {
    const glm::vec3 v = soup.positions[k];
    const bool outer = std::max(std::abs(v.x), std::abs(v.z)) > 1.4999f;
    const bool hole = std::abs(std::abs(v.x - 0.25f) - 0.09f) < 1e-4f && std::abs(std::abs(v.z - 0.25f) - 0.09f) < 1e-4f;
    EXPECT_TRUE(outer || hole) << v.x << " " << v.z;
  }
  // A fin on the box's top edge: that edge has three triangles, no neighbour, but is no gap.
  TriangleMesh fin = makeBox(1.0, 1.0, 1.0);
  const auto top = std::find_if(fin.triangles.begin(), fin.triangles.end(), [&](const auto& t) {
    return fin.positions[t[0]].y > 0.0f && fin.positions[t[1]].y > 0.0f && fin.positions[t[2]].y > 0.0f;
  });
  ASSERT_NE(top, fin.triangles.end());
  const std::uint32_t a = (*top)[0], b = (*top)[1];
  fin.positions.push_back(0.5f * (fin.positions[a] + fin.positions[b]) + glm::vec3(0.0f, 1.0f, 0.0f));
  fin.triangles.push_back({a, b, std::uint32_t(fin.positions.size() - 1)});
  const std::vector<std::uint32_t> finRims = openRims(fin);
  EXPECT_EQ(finRims.size(), 2u * 2u);  // the fin's two free edges only
}

// The quad whose square holds the point (x, z) of the plate (at height 1).
std::size_t quadAt(const DepthMap& map, double x, double z) {
  const glm::dvec2 t = map.texelOf({x, 1.0, z});
  return std::size_t(std::floor(t.y)) * std::size_t(map.width - 1) + std::size_t(std::floor(t.x));
}

// Light straight down from y = 5: the plate lies at depth 4. Its outer border runs half-way
// between texel centres (texel coordinates 9.5 and 21.5 each way: 48 quads along it), its hole
// inside one quad, which no texel centre tells from the plate. A limit behind the plate finds those
// 49 with kRimFlag and leaves the other bits; one in front of it finds none.
TEST(OpenRims, QuadsWhoseSquareARimCrossesInFrontOfTheLimit) {
  for (CaptureMode mode : {CaptureMode::Back, CaptureMode::Front, CaptureMode::Entry}) {
    const DepthMap map = makeDepthMap(test::directionalDown(6.0), 32, 32, mode);
    const glm::dvec2 corner = map.texelOf({1.5, 1.0, 1.5});
    ASSERT_NEAR(std::abs(corner.x - 15.5), 6.0, 1e-9);
    ASSERT_NEAR(std::abs(corner.y - 15.5), 6.0, 1e-9);
    const std::vector<std::uint8_t> flags = rimSearch(map, plate(), 4.01f, 1);
    EXPECT_EQ(std::count(flags.begin(), flags.end(), std::uint8_t(1 | kRimFlag)), 49) << toString(mode);
    EXPECT_EQ(flags[quadAt(map, 0.25, 0.25)], 1 | kRimFlag) << toString(mode);   // the hole
    EXPECT_EQ(flags[quadAt(map, 0.25, 0.75)], 1) << toString(mode);             // the plate's inside, no rim
    EXPECT_EQ(flags[quadAt(map, 1.49, 0.3)], 1 | kRimFlag) << toString(mode);    // the outer border
    const std::vector<std::uint8_t> none = rimSearch(map, plate(), 3.99f);
    EXPECT_EQ(std::count(none.begin(), none.end(), std::uint8_t(0)), std::ptrdiff_t(none.size())) << toString(mode);
  }
}

// Only the part within [near, far] counts: the plate beyond the far plane has no rim there.
TEST(OpenRims, OnlyThePartWithinTheDepthRangeCounts) {
  const DepthMap map = makeDepthMap(test::directionalDown(3.5), 32, 32, CaptureMode::Front);
  const std::vector<std::uint8_t> flags = rimSearch(map, plate(), 10.0f);
  EXPECT_EQ(std::count(flags.begin(), flags.end(), std::uint8_t(0)), std::ptrdiff_t(flags.size()));
}

}  // namespace
}  // namespace shadowvol
