#include "shadowvol/volume_mesh.h"

#include <algorithm>
#include <limits>

#include "shadowvol/check.h"
#include "shadowvol/ray_parity.h"

namespace shadowvol {

TriangleMesh VolumeMesh::toTriangleMesh() const {
  TriangleMesh mesh;
  mesh.positions.reserve(positions.size());
  for (const glm::dvec3& p : positions) mesh.positions.emplace_back(p);
  mesh.triangles.assign(triangles.begin(), triangles.end());
  return mesh;
}

void VolumeMesh::sortTriangles() {
  SV_CHECK(std::is_sorted(partStarts.begin(), partStarts.end()));
  SV_CHECK(partStarts.empty() || partStarts.back() <= triangles.size());
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::size_t begin = 0;
  for (std::size_t k = 0; k < partCount(); ++k) {
    const std::size_t end = k + 1 < partCount() ? partStarts[k] : triangles.size();
    std::sort(triangles.begin() + std::ptrdiff_t(begin), triangles.begin() + std::ptrdiff_t(end));
    begin = end;
  }
}

int windingNumber(const VolumeMesh& mesh, const glm::dvec3& p) {
  int w = 0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    if (parityRayCrosses(p, a, b, c)) w += glm::dot(glm::cross(b - a, c - a), kParityRayDirection) > 0.0 ? 1 : -1;
  }
  return w;
}

VolumeMesh VolumeMesh::partMesh(std::size_t k) const {
  SV_CHECK_LT(k, partCount());
  const std::size_t begin = k == 0 ? 0 : partStarts[k - 1];
  const std::size_t end = k + 1 < partCount() ? partStarts[k] : triangles.size();
  SV_CHECK(begin <= end && end <= triangles.size());
  VolumeMesh part;
  part.origin = origin;
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> index(positions.size(), kUnset);
  for (std::size_t t = begin; t < end; ++t) {
    std::array<std::uint32_t, 3> tri = triangles[t];
    for (std::uint32_t& v : tri) {
      if (v >= index.size()) {  // out of range: kept out of range, for checkMesh to report
        v = std::uint32_t(positions.size() + part.positions.size());
        continue;
      }
      if (index[v] == kUnset) {
        index[v] = std::uint32_t(part.positions.size());
        part.positions.push_back(positions[v]);
      }
      v = index[v];
    }
    part.triangles.push_back(tri);
  }
  return part;
}

}  // namespace shadowvol
