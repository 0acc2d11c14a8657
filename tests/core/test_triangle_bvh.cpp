// The hierarchy the GPU's bisection rays walk (triangle_bvh.h): every triangle in exactly one leaf,
// every box around what it holds, and a ray walked through it on the CPU, as
// shaders/silhouette_rays.comp walks it, finds the nearest hit that a test of every triangle finds.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "shadowvol/primitives.h"
#include "shadowvol/triangle_bvh.h"

namespace shadowvol {
namespace {

// A soup of small random triangles (a fixed LCG: deterministic), some degenerate, some coincident.
TriangleMesh randomSoup(std::size_t n, std::uint64_t seed) {
  auto next = [&] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return float((seed >> 33) % 100000) / 100000.0f;
  };
  TriangleMesh m;
  for (std::size_t t = 0; t < n; ++t) {
    const glm::vec3 c(next() * 10.0f, next() * 10.0f, next() * 10.0f);
    for (int k = 0; k < 3; ++k)
      m.positions.push_back(t % 17 == 0 ? c : c + glm::vec3(next() - 0.5f, next() - 0.5f, next() - 0.5f));
    m.triangles.push_back({std::uint32_t(3 * t), std::uint32_t(3 * t + 1), std::uint32_t(3 * t + 2)});
    if (t % 29 == 0) m.triangles.push_back(m.triangles.back());  // the same triangle twice
  }
  return m;
}

bool inside(const BvhNode& n, const glm::vec3& p) {
  for (int a = 0; a < 3; ++a)
    if (p[a] < n.lo[a] || p[a] > n.hi[a]) return false;
  return true;
}

void expectWellFormed(const TriangleMesh& mesh, const TriangleBvh& bvh) {
  ASSERT_EQ(bvh.triangles.size(), mesh.triangles.size());
  ASSERT_EQ(bvh.order.size(), mesh.triangles.size());
  std::vector<int> seen(mesh.triangles.size(), 0);
  for (std::size_t k = 0; k < bvh.order.size(); ++k) {
    ++seen.at(bvh.order[k]);
    EXPECT_EQ(bvh.triangles[k], mesh.triangles[bvh.order[k]]);
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
  EXPECT_LE(bvh.depth, kBvhMaxDepth);
  std::vector<int> reached(bvh.triangles.size(), 0);
  std::vector<std::uint32_t> stack = {0};
  while (!stack.empty()) {
    const BvhNode& n = bvh.nodes.at(stack.back());
    stack.pop_back();
    if (n.count == 0) {
      for (std::uint32_t c : {n.first, n.first + 1}) {
        const BvhNode& child = bvh.nodes.at(c);
        EXPECT_TRUE(inside(n, {child.lo[0], child.lo[1], child.lo[2]}) && inside(n, {child.hi[0], child.hi[1], child.hi[2]}));
        stack.push_back(c);
      }
      continue;
    }
    EXPECT_LE(n.count, std::uint32_t(kBvhMaxLeafTriangles));
    for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
      ++reached.at(k);
      for (std::uint32_t v : bvh.triangles[k]) EXPECT_TRUE(inside(n, mesh.positions[v]));
    }
  }
  EXPECT_TRUE(std::all_of(reached.begin(), reached.end(), [](int r) { return r == 1; }));
}

// Moller-Trumbore in double; the parameter of a hit in (0, best), else nullopt.
std::optional<double> hit(const TriangleMesh& m, const std::array<std::uint32_t, 3>& t, glm::dvec3 o, glm::dvec3 d) {
  const glm::dvec3 v0(m.positions[t[0]]), e1 = glm::dvec3(m.positions[t[1]]) - v0, e2 = glm::dvec3(m.positions[t[2]]) - v0;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-15) return std::nullopt;
  const glm::dvec3 s = o - v0, q = glm::cross(s, e1);
  const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det, tt = glm::dot(e2, q) / det;
  if (u < 0 || v < 0 || u + v > 1 || tt <= 0) return std::nullopt;
  return tt;
}

// The nearest hit through the hierarchy (boxes in double, as the shader's slab test).
std::optional<double> nearestThrough(const TriangleMesh& m, const TriangleBvh& bvh, glm::dvec3 o, glm::dvec3 d) {
  std::optional<double> best;
  std::vector<std::uint32_t> stack = {0};
  while (!stack.empty()) {
    const BvhNode& n = bvh.nodes[stack.back()];
    stack.pop_back();
    double enter = 0.0, leave = 1e300;
    for (int a = 0; a < 3; ++a) {
      const double t0 = (n.lo[a] - o[a]) / d[a], t1 = (n.hi[a] - o[a]) / d[a];
      enter = std::max(enter, std::min(t0, t1)), leave = std::min(leave, std::max(t0, t1));
    }
    if (enter > leave || (best && enter > *best)) continue;
    if (n.count == 0) {
      stack.push_back(n.first), stack.push_back(n.first + 1);
      continue;
    }
    for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
      if (auto t = hit(m, bvh.triangles[k], o, d); t && (!best || *t < *best)) best = t;
  }
  return best;
}

TEST(TriangleBvh, EveryTriangleInOneLeafInsideEveryBoxAbove) {
  for (std::size_t n : {std::size_t(1), std::size_t(5), std::size_t(1000)}) {
    const TriangleMesh m = randomSoup(n, 7 + n);
    SCOPED_TRACE(n);
    expectWellFormed(m, buildTriangleBvh(m));
  }
  const TriangleMesh sphere = makeUvSphere(1.0, 48, 24);
  expectWellFormed(sphere, buildTriangleBvh(sphere));
  // Every centroid the same (a pile of one triangle): still split into leaves of at most 4.
  TriangleMesh pile;
  pile.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  pile.triangles.assign(100, {0u, 1u, 2u});
  expectWellFormed(pile, buildTriangleBvh(pile));
  EXPECT_TRUE(buildTriangleBvh(TriangleMesh()).nodes.empty());
}

TEST(TriangleBvh, RaysFindTheNearestHitOfEveryTriangle) {
  const TriangleMesh m = randomSoup(2000, 3);
  const TriangleBvh bvh = buildTriangleBvh(m);
  std::uint64_t seed = 11;
  auto next = [&] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return double((seed >> 33) % 100000) / 100000.0;
  };
  int hits = 0;
  for (int r = 0; r < 500; ++r) {
    const glm::dvec3 o(next() * 10.0, next() * 10.0, -5.0), d(next() - 0.5, next() - 0.5, 1.0);
    std::optional<double> brute;
    for (const auto& t : m.triangles)
      if (auto h = hit(m, t, o, d); h && (!brute || *h < *brute)) brute = h;
    const std::optional<double> through = nearestThrough(m, bvh, o, d);
    ASSERT_EQ(brute.has_value(), through.has_value()) << r;
    if (brute) {
      EXPECT_EQ(*brute, *through) << r;
    }
    hits += brute.has_value();
  }
  EXPECT_GT(hits, 100);  // the rays do meet the soup
}

}  // namespace
}  // namespace shadowvol
