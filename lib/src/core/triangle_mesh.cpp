#include "shadowvol/triangle_mesh.h"

#include <vector>

#include <glm/geometric.hpp>

namespace shadowvol {

void Bounds3::extend(const glm::dvec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

void Bounds3::extend(const Bounds3& b) {
  if (b.empty()) return;
  extend(b.min);
  extend(b.max);
}

double Bounds3::radius() const { return empty() ? 0.0 : 0.5 * glm::length(max - min); }

Bounds3 TriangleMesh::bounds() const {
  Bounds3 b;
  for (const auto& p : positions) b.extend(glm::dvec3(p));
  return b;
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<std::uint32_t>(positions.size());
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

std::size_t TriangleMesh::removeUnusedVertices() {
  constexpr std::uint32_t kUnused = ~std::uint32_t(0);
  std::vector<std::uint32_t> renumber(positions.size(), kUnused);
  for (const auto& t : triangles)
    for (const std::uint32_t i : t) renumber[i] = 0;
  std::uint32_t kept = 0;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (renumber[i] != kUnused) {
      renumber[i] = kept;
      positions[kept++] = positions[i];
    }
  const std::size_t removed = positions.size() - kept;
  if (removed == 0) return 0;
  positions.resize(kept);
  for (auto& t : triangles)
    for (std::uint32_t& i : t) i = renumber[i];
  return removed;
}

}  // namespace shadowvol
