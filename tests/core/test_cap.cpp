// triangulateCapLoops (far_cap.h): lossless flattening of the far cap's boundary loops.
#include <map>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "shadowvol/far_cap.h"

namespace shadowvol {
namespace {

// A closed loop through texels; vertex ids are given explicitly so pinch copies can share a texel.
void addLoop(std::vector<CapEdge>& edges, const std::vector<std::pair<std::uint32_t, glm::ivec2>>& loop) {
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const auto& a = loop[k];
    const auto& b = loop[(k + 1) % loop.size()];
    edges.push_back({a.first, b.first, glm::dvec2(a.second), glm::dvec2(b.second)});
  }
}

struct CapCheck {
  double area = 0.0;       // sum of signed areas (texel units), counter-clockwise positive
  bool allPositive = true;
  bool boundaryOnce = true;
  bool interiorPaired = true;  // every other edge used once in each direction
};

CapCheck check(const std::vector<CapEdge>& edges, const std::vector<std::array<std::uint32_t, 3>>& tris) {
  std::map<std::uint32_t, glm::dvec2> texel;
  for (const auto& e : edges) {
    texel[e.from] = e.fromTexel;
    texel[e.to] = e.toTexel;
  }
  CapCheck c;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> used;
  for (const auto& t : tris) {
    const glm::dvec2 p(texel.at(t[0])), q(texel.at(t[1])), r(texel.at(t[2]));
    const double a = 0.5 * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
    c.area += a;
    c.allPositive = c.allPositive && a > 0.0;
    for (int k = 0; k < 3; ++k) ++used[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& e : edges) c.boundaryOnce = c.boundaryOnce && used[{e.from, e.to}] == 1 && used[{e.to, e.from}] == 0;
  std::set<std::pair<std::uint32_t, std::uint32_t>> boundary;
  for (const auto& e : edges) boundary.insert({e.from, e.to});
  for (const auto& [edge, n] : used)
    if (!boundary.count(edge) && n > 0)
      c.interiorPaired = c.interiorPaired && n == 1 && used.count({edge.second, edge.first}) &&
                         used.at({edge.second, edge.first}) == 1;
  return c;
}

TEST(Cap, SquareWithCollinearBoundaryPointsKeepsThemAll) {
  // A 4 x 3 rectangle traced through every lattice point of its border (14 points).
  std::vector<std::pair<std::uint32_t, glm::ivec2>> loop;
  std::uint32_t id = 0;
  for (int x = 0; x < 4; ++x) loop.push_back({id++, {x, 0}});
  for (int y = 0; y < 3; ++y) loop.push_back({id++, {4, y}});
  for (int x = 4; x > 0; --x) loop.push_back({id++, {x, 3}});
  for (int y = 3; y > 0; --y) loop.push_back({id++, {0, y}});
  std::vector<CapEdge> edges;
  addLoop(edges, loop);
  const auto tris = triangulateCapLoops(edges);
  const CapCheck c = check(edges, tris);
  EXPECT_DOUBLE_EQ(c.area, 12.0);
  EXPECT_TRUE(c.allPositive);
  EXPECT_TRUE(c.boundaryOnce);
  EXPECT_EQ(tris.size(), loop.size() - 2);  // a simple polygon: n - 2 triangles, no Steiner point
}

// Straight runs leave the CDT and come back by fans (far_cap.h): a triangle whose three sides,
// one of them diagonal, are all traced through every lattice point, so the single CDT face has
// runs on every side; and a frame (a square with a square hole) whose loops are all runs.
TEST(Cap, RunsOnEverySideOfAFaceAndAroundAHole) {
  std::vector<std::pair<std::uint32_t, glm::ivec2>> triangle;
  std::uint32_t id = 0;
  for (int x = 0; x < 6; ++x) triangle.push_back({id++, {x, 0}});
  for (int k = 0; k < 6; ++k) triangle.push_back({id++, {6 - k, k}});
  for (int y = 6; y > 0; --y) triangle.push_back({id++, {0, y}});
  std::vector<CapEdge> edges;
  addLoop(edges, triangle);
  auto tris = triangulateCapLoops(edges);
  CapCheck c = check(edges, tris);
  EXPECT_DOUBLE_EQ(c.area, 18.0);
  EXPECT_TRUE(c.allPositive);
  EXPECT_TRUE(c.boundaryOnce);
  EXPECT_TRUE(c.interiorPaired);
  EXPECT_EQ(tris.size(), triangle.size() - 2);  // no Steiner point: n - 2 triangles

  std::vector<std::pair<std::uint32_t, glm::ivec2>> outer, hole;
  for (int x = 0; x < 8; ++x) outer.push_back({id++, {x, 0}});
  for (int y = 0; y < 8; ++y) outer.push_back({id++, {8, y}});
  for (int x = 8; x > 0; --x) outer.push_back({id++, {x, 8}});
  for (int y = 8; y > 0; --y) outer.push_back({id++, {0, y}});
  for (int y = 2; y < 6; ++y) hole.push_back({id++, {2, y}});  // clockwise: the hole
  for (int x = 2; x < 6; ++x) hole.push_back({id++, {x, 6}});
  for (int y = 6; y > 2; --y) hole.push_back({id++, {6, y}});
  for (int x = 6; x > 2; --x) hole.push_back({id++, {x, 2}});
  edges.clear();
  addLoop(edges, outer);
  addLoop(edges, hole);
  tris = triangulateCapLoops(edges);
  c = check(edges, tris);
  EXPECT_DOUBLE_EQ(c.area, 64.0 - 16.0);
  EXPECT_TRUE(c.allPositive);
  EXPECT_TRUE(c.boundaryOnce);
  EXPECT_TRUE(c.interiorPaired);
  EXPECT_EQ(tris.size(), outer.size() + hole.size());  // n + 2 holes - 2
}

TEST(Cap, HoleAndIslandByOrientation) {
  std::vector<CapEdge> edges;
  addLoop(edges, {{0, {0, 0}}, {1, {10, 0}}, {2, {10, 10}}, {3, {0, 10}}});        // outer, CCW
  addLoop(edges, {{4, {2, 2}}, {5, {2, 8}}, {6, {8, 8}}, {7, {8, 2}}});            // hole, CW
  addLoop(edges, {{8, {4, 4}}, {9, {6, 4}}, {10, {6, 6}}, {11, {4, 6}}});          // island, CCW
  const auto tris = triangulateCapLoops(edges);
  const CapCheck c = check(edges, tris);
  EXPECT_DOUBLE_EQ(c.area, 100.0 - 36.0 + 4.0);
  EXPECT_TRUE(c.allPositive);
  EXPECT_TRUE(c.boundaryOnce);
}

TEST(Cap, PinchedRegionsGetTheRightCopy) {
  // Two unit squares touching at texel (1, 1), which has two vertex ids (4 and 5).
  std::vector<CapEdge> edges;
  addLoop(edges, {{0, {0, 0}}, {1, {1, 0}}, {4, {1, 1}}, {2, {0, 1}}});
  addLoop(edges, {{5, {1, 1}}, {6, {2, 1}}, {7, {2, 2}}, {8, {1, 2}}});
  const auto tris = triangulateCapLoops(edges);
  const CapCheck c = check(edges, tris);
  EXPECT_DOUBLE_EQ(c.area, 2.0);
  EXPECT_TRUE(c.allPositive);
  EXPECT_TRUE(c.boundaryOnce);  // each triangle names the copy of its own square
}

TEST(Cap, CutTraversedBothWaysHasTheRegionOnBothSides) {
  // A 2 x 2 square whose middle vertical edge (1, 0)-(1, 2) is a cut, with copies on both sides.
  std::vector<CapEdge> edges;
  addLoop(edges, {{0, {0, 0}}, {1, {1, 0}}, {2, {1, 2}}, {3, {0, 2}}});   // left half
  addLoop(edges, {{4, {1, 0}}, {5, {2, 0}}, {6, {2, 2}}, {7, {1, 2}}});   // right half
  const auto tris = triangulateCapLoops(edges);
  const CapCheck c = check(edges, tris);
  EXPECT_DOUBLE_EQ(c.area, 4.0);
  EXPECT_TRUE(c.allPositive);
  EXPECT_TRUE(c.boundaryOnce);
  EXPECT_EQ(tris.size(), 4u);
  EXPECT_TRUE(triangulateCapLoops({}).empty());
}

}  // namespace
}  // namespace shadowvol
