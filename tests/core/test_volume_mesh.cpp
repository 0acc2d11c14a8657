// VolumeMesh::sortTriangles: one order of the triangles whatever order they came in (a GPU
// listing's changes from run to run), with each triangle's winding kept.
#include <algorithm>
#include <array>
#include <set>

#include <gtest/gtest.h>

#include "shadowvol/volume_mesh.h"

namespace shadowvol {
namespace {

// An octahedron's eight outward triangles, listed in another order and each started at another
// corner, sorts to the same list; every sorted triangle is a rotation of one given (no triangle
// flipped), and its smallest index comes first.
TEST(VolumeMesh, SortTrianglesGivesOneOrderAndKeepsTheWinding) {
  VolumeMesh a;
  a.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  a.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  VolumeMesh b = a;
  std::reverse(b.triangles.begin(), b.triangles.end());
  for (std::size_t k = 0; k < b.triangles.size(); ++k) {
    auto& t = b.triangles[k];
    std::rotate(t.begin(), t.begin() + k % 3, t.end());
  }
  const auto given = a.triangles;
  a.sortTriangles();
  b.sortTriangles();
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_TRUE(std::is_sorted(a.triangles.begin(), a.triangles.end()));

  auto rotations = [](std::array<std::uint32_t, 3> t) {
    std::set<std::array<std::uint32_t, 3>> r;
    for (int k = 0; k < 3; ++k, std::rotate(t.begin(), t.begin() + 1, t.end())) r.insert(t);
    return r;
  };
  std::set<std::array<std::uint32_t, 3>> allowed;
  for (const auto& t : given)
    for (const auto& r : rotations(t)) allowed.insert(r);
  for (const auto& t : a.triangles) {
    EXPECT_TRUE(allowed.count(t)) << t[0] << " " << t[1] << " " << t[2] << " is not a rotation of a given triangle";
    EXPECT_EQ(t[0], std::min({t[0], t[1], t[2]}));
  }
  ASSERT_EQ(a.triangles.size(), given.size());
}

// A mesh of two parts (VolumeMesh::partStarts): partMesh gives each alone with its vertices
// renumbered in order of first use, and sortTriangles keeps each part's triangles in its range.
TEST(VolumeMesh, PartsAreTakenAndSortedEachAlone) {
  VolumeMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2},   // a tetrahedron
                 {6, 7, 5}, {4, 6, 5}, {4, 5, 7}, {4, 7, 6}};  // another, as the second part
  m.partStarts = {4};
  EXPECT_EQ(m.partCount(), 2u);
  const VolumeMesh second = m.partMesh(1);
  EXPECT_EQ(second.positions.size(), 4u);
  EXPECT_EQ(second.positions[0], glm::dvec3(5, 1, 0));  // vertex 6, the first used
  EXPECT_EQ(second.triangles.size(), 4u);
  EXPECT_TRUE(second.partStarts.empty());
  m.sortTriangles();
  for (std::size_t t = 0; t < 4; ++t) EXPECT_LT(*std::max_element(m.triangles[t].begin(), m.triangles[t].end()), 4u);
  for (std::size_t t = 4; t < 8; ++t) EXPECT_GE(*std::min_element(m.triangles[t].begin(), m.triangles[t].end()), 4u);
  EXPECT_TRUE(std::is_sorted(m.triangles.begin() + 4, m.triangles.end()));
}

}  // namespace
}  // namespace shadowvol
