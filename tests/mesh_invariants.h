// A combinatorial check of closed volumes shared by the test folders (no CGAL needed).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "shadowvol/ray_parity.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol::test {

// Closed, consistently oriented 2-manifold: every directed edge once and its opposite once, each
// vertex a single fan, no isolated vertex, finite, positive signed volume (divergence theorem).
inline ::testing::AssertionResult closedOrientedManifold(const VolumeMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  std::vector<std::map<std::uint32_t, std::uint32_t>> link(mesh.vertexCount());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      if (a >= mesh.vertexCount()) return ::testing::AssertionFailure() << "index out of range";
      if (++edges[{a, b}] > 1) return ::testing::AssertionFailure() << "directed edge used twice " << a << "->" << b;
      link[a][b] = c;
    }
  for (const auto& [e, n] : edges)
    if (!edges.count({e.second, e.first}))
      return ::testing::AssertionFailure() << "boundary edge " << e.first << "->" << e.second;
  for (std::size_t v = 0; v < link.size(); ++v) {
    if (link[v].empty()) return ::testing::AssertionFailure() << "isolated vertex " << v;
    std::uint32_t at = link[v].begin()->first;
    std::size_t steps = 0;
    do {
      auto it = link[v].find(at);
      if (it == link[v].end()) return ::testing::AssertionFailure() << "broken fan at " << v;
      at = it->second;
      ++steps;
    } while (at != link[v].begin()->first && steps <= link[v].size());
    if (steps != link[v].size()) return ::testing::AssertionFailure() << "vertex " << v << " has several fans";
  }
  double volume = 0.0;
  for (const auto& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return ::testing::AssertionFailure() << "non-finite vertex";
  for (const auto& t : mesh.triangles) {
    const auto &p = mesh.positions[t[0]], &q = mesh.positions[t[1]], &r = mesh.positions[t[2]];
    if (glm::length(glm::cross(q - p, r - p)) == 0.0) return ::testing::AssertionFailure() << "zero-area triangle";
    volume += glm::dot(p, glm::cross(q, r)) / 6.0;
  }
  if (!mesh.triangles.empty() && !(volume > 0.0))
    return ::testing::AssertionFailure() << "signed volume " << volume << " not positive";
  return ::testing::AssertionSuccess();
}

/// The two meshes are identical (positions to the bit, triangles in order).
inline ::testing::AssertionResult sameMesh(const VolumeMesh& a, const VolumeMesh& b) {
  if (!std::equal(a.positions.begin(), a.positions.end(), b.positions.begin(), b.positions.end()))
    return ::testing::AssertionFailure() << "positions differ";
  if (!std::equal(a.triangles.begin(), a.triangles.end(), b.triangles.begin(), b.triangles.end()))
    return ::testing::AssertionFailure() << "triangles differ";
  return ::testing::AssertionSuccess();
}

// Inside the closed volume by the parity of a ray's crossings (shadowvol/ray_parity.h).
inline bool insideVolume(const VolumeMesh& m, const glm::dvec3& p) {
  bool in = false;
  for (const auto& t : m.triangles) in ^= parityRayCrosses(p, m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
  return in;
}

// The winding number (the library's rule, volume_mesh.h).
inline int windingNumber(const VolumeMesh& m, const glm::dvec3& p) { return shadowvol::windingNumber(m, p); }

}  // namespace shadowvol::test
