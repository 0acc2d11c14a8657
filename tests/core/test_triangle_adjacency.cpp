// Edge neighbours for the silhouette walk (triangle_adjacency.h): closed, open, soup, non-manifold
// and inconsistently oriented meshes.
#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include "shadowvol/primitives.h"
#include "shadowvol/triangle_adjacency.h"

namespace shadowvol {
namespace {

// Every neighbour link is mutual: t's edge k has n, and one of n's edges has t.
void expectMutual(const std::vector<std::int32_t>& n) {
  for (std::size_t s = 0; s < n.size(); ++s) {
    if (n[s] == kNoNeighbour) continue;
    const std::int32_t flag = n[s] & kFlippedNeighbour, t = std::int32_t(s / 3) | flag;
    const std::size_t u = std::size_t(n[s] & ~kFlippedNeighbour);
    EXPECT_TRUE(n[3 * u] == t || n[3 * u + 1] == t || n[3 * u + 2] == t);
  }
}

TEST(TriangleAdjacency, ClosedBoxHasANeighbourAcrossEveryEdge) {
  const TriangleMesh box = makeBox(1.0, 2.0, 3.0);
  const auto n = triangleNeighbours(box);
  ASSERT_EQ(n.size(), 3 * box.triangleCount());
  for (std::int32_t v : n) EXPECT_NE(v, kNoNeighbour);
  expectMutual(n);
}

TEST(TriangleAdjacency, SoupIsWeldedByPosition) {
  const TriangleMesh box = makeBox(1.0, 2.0, 3.0);
  TriangleMesh soup;  // every triangle with its own three vertices
  for (const auto& t : box.triangles) {
    const auto base = std::uint32_t(soup.positions.size());
    for (auto v : t) soup.positions.push_back(box.positions[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_EQ(triangleNeighbours(soup), triangleNeighbours(box));
}

TEST(TriangleAdjacency, OpenSheetHasNoneAcrossItsBorder) {
  const TriangleMesh plane = makePlane(2.0, 2.0, 3);  // 3 x 3 quads: 12 border edges
  const auto n = triangleNeighbours(plane);
  std::size_t none = 0;
  for (std::int32_t v : n) none += v == kNoNeighbour;
  EXPECT_EQ(none, 12u);
  expectMutual(n);
}

TEST(TriangleAdjacency, NonManifoldEdgesHaveNoneAndMisorientedOnesAreFlagged) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  // Three triangles on edge 0-1: none of them has a neighbour there.
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
  auto n = triangleNeighbours(m);
  EXPECT_EQ(n[0], kNoNeighbour);
  EXPECT_EQ(n[3], kNoNeighbour);
  EXPECT_EQ(n[6], kNoNeighbour);
  // Two triangles using edge 0-1 in the same direction: wound oppositely, a flipped link.
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  n = triangleNeighbours(m);
  EXPECT_EQ(n[0], 1 | kFlippedNeighbour);
  EXPECT_EQ(n[3], 0 | kFlippedNeighbour);
  // Opposite directions: neighbours.
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  n = triangleNeighbours(m);
  EXPECT_EQ(n[0], 1);
  EXPECT_EQ(n[3], 0);
  // A triangle with a repeated (welded) vertex has no neighbours, and gives none.
  m.positions.push_back({1, 0, 0});  // vertex 5 = vertex 1's position
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 5, 2}};
  n = triangleNeighbours(m);
  EXPECT_EQ(n[6], kNoNeighbour);
  EXPECT_EQ(n[7], kNoNeighbour);
  EXPECT_EQ(n[8], kNoNeighbour);
  EXPECT_EQ(n[1], kNoNeighbour);  // edge 1-2 of the first triangle: only it (the degenerate one gives nothing)
}

// The one closedness test of the scene's warnings and the orientation on loading (they once had
// three, which disagreed on a degenerate triangle).
TEST(TriangleAdjacency, ClosedAsStoredOrOnceWelded) {
  const TriangleMesh box = makeBox(1.0, 1.0, 1.0);
  EXPECT_TRUE(isClosedSurface(box));
  TriangleMesh soup;
  for (const auto& t : box.triangles) {
    const auto base = std::uint32_t(soup.positions.size());
    for (auto v : t) soup.positions.push_back(box.positions[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_TRUE(isClosedSurface(soup));
  TriangleMesh sliver = box;
  sliver.triangles.push_back({2, 2, 5});  // degenerate: bounds nothing
  EXPECT_TRUE(isClosedSurface(sliver));
  EXPECT_TRUE(closedByNeighbours(sliver, triangleNeighbours(sliver)));
  // Two boxes stored apart that touch along a face: closed as stored, not once welded.
  TriangleMesh pair = box;
  TriangleMesh second = box;
  for (auto& p : second.positions) p.x += 1.0f;
  pair.append(second);
  EXPECT_TRUE(isClosedSurface(pair));
  EXPECT_FALSE(closedByNeighbours(pair, triangleNeighbours(pair)));
  TriangleMesh open = box;
  open.triangles.pop_back();
  EXPECT_FALSE(isClosedSurface(open));
  EXPECT_FALSE(isClosedSurface(TriangleMesh{}));
}

// A closed tetrahedron with corners that float cannot hold exactly, and the midpoint of its edge
// 0-1 (rounded to float: a hair off the line) as vertex 4.
TriangleMesh awkwardTetrahedron() {
  TriangleMesh m;
  m.positions = {{0.1f, 0.7f, 0.3f}, {1.3f, -0.2f, 2.9f}, {-1.1f, 0.4f, 1.7f}, {0.3f, 2.3f, 1.1f}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  const glm::dvec3 mid = 0.5 * (glm::dvec3(m.positions[0]) + glm::dvec3(m.positions[1]));
  m.positions.push_back(glm::vec3(mid));
  return m;
}

// A fourteenth probe's inside-out mesh with one flat triangle (a, b, midpoint) on a closed edge,
// or every face twice, was called open and left inside out: such triangles are left out. A flat
// triangle that zips a T-junction, a repeat wound the other way (a two-sided sheet) and a lone
// triangle with area stay.
TEST(TriangleAdjacency, ExtraTrianglesThatOnlyKeepAMeshOpenAreLeftOut) {
  TriangleMesh stray = awkwardTetrahedron();
  stray.triangles.push_back({0, 1, 4});  // on the closed edge 0-1: three uses there
  EXPECT_FALSE(isClosedSurface(stray));
  const ExtraTriangles e = removeExtraTriangles(stray);
  EXPECT_EQ(e.flat, 1u);
  EXPECT_EQ(e.duplicates, 0u);
  EXPECT_EQ(stray.triangles, awkwardTetrahedron().triangles);

  TriangleMesh zipped = awkwardTetrahedron();  // face 0 split at the midpoint, the split zipped shut
  zipped.triangles[0] = {0, 4, 2};
  zipped.triangles.push_back({4, 1, 2});
  zipped.triangles.push_back({0, 1, 4});  // the flat triangle pairs 0-1, 0-4 and 4-1
  EXPECT_TRUE(isClosedSurface(zipped));
  EXPECT_EQ(removeExtraTriangles(zipped).total(), 0u);
  EXPECT_EQ(zipped.triangles.size(), 6u);

  TriangleMesh twice = awkwardTetrahedron();
  twice.triangles.push_back({1, 2, 0});  // triangle 0 again, rotated
  twice.triangles.push_back({2, 3, 0});  // triangle 3 again
  EXPECT_FALSE(isClosedSurface(twice));
  EXPECT_EQ(removeExtraTriangles(twice).duplicates, 2u);
  EXPECT_EQ(twice.triangles, awkwardTetrahedron().triangles);
  EXPECT_TRUE(isClosedSurface(twice));

  TriangleMesh sheet = awkwardTetrahedron();
  sheet.triangles = {{0, 1, 2}, {0, 2, 1}};  // two-sided
  EXPECT_EQ(removeExtraTriangles(sheet).total(), 0u);
  TriangleMesh lone = awkwardTetrahedron();
  lone.triangles = {{0, 1, 2}};
  EXPECT_EQ(removeExtraTriangles(lone).total(), 0u);
  TriangleMesh flatBeside = awkwardTetrahedron();
  flatBeside.triangles = {{0, 1, 2}, {0, 3, 4}};  // a flat one beside a lone triangle, sharing no edge
  EXPECT_EQ(removeExtraTriangles(flatBeside).flat, 0u);  // 0-3-4 is not flat: 3 lies off the line
  flatBeside.triangles = {{0, 1, 2}, {0, 1, 4}};  // flat, on the lone triangle's open edge: it pairs
  EXPECT_EQ(removeExtraTriangles(flatBeside).flat, 1u);  // that one and opens two, adding no surface
  TriangleMesh flatAlone = awkwardTetrahedron();
  flatAlone.triangles = {{0, 1, 4}};  // nothing else: left whole (emptied, it would lose its warnings)
  EXPECT_EQ(removeExtraTriangles(flatAlone).total(), 0u);
  EXPECT_EQ(flatAlone.triangles.size(), 1u);

  // Judged one by one (a second reader's findings): of a flat zip and its reverse, one goes and the
  // mesh closes; two stray flat triangles on one closed edge both go.
  TriangleMesh zippedTwice = zipped;
  zippedTwice.triangles.push_back({0, 4, 1});
  EXPECT_EQ(removeExtraTriangles(zippedTwice).flat, 1u);
  EXPECT_TRUE(isClosedSurface(zippedTwice));
  TriangleMesh twoStray = awkwardTetrahedron();
  const glm::dvec3 a(twoStray.positions[0]), b(twoStray.positions[1]);
  twoStray.positions.push_back(glm::vec3(a + 0.25 * (b - a)));  // vertex 5, a quarter along 0-1
  twoStray.triangles.push_back({0, 1, 4});
  twoStray.triangles.push_back({1, 0, 5});
  EXPECT_EQ(removeExtraTriangles(twoStray).flat, 2u);
  EXPECT_EQ(twoStray.triangles, awkwardTetrahedron().triangles);
  // Closed already: nothing to lose, even a face repeated once welded (two boxes stored apart that
  // touch, one inside out).
  TriangleMesh touching = makeBox(1.0, 1.0, 1.0), second = makeBox(1.0, 1.0, 1.0);
  for (auto& p : second.positions) p.x += 1.0f;
  for (auto& t : second.triangles) std::swap(t[1], t[2]);
  touching.append(second);
  ASSERT_TRUE(isClosedSurface(touching));
  EXPECT_EQ(removeExtraTriangles(touching).total(), 0u);
}

}  // namespace
}  // namespace shadowvol
