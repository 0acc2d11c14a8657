#include "shadowvol/volume_mesh.h"

#include <algorithm>

namespace shadowvol {

TriangleMesh VolumeMesh::toTriangleMesh() const {
  TriangleMesh mesh;
  mesh.positions.reserve(positions.size());
  for (const glm::dvec3& p : positions) mesh.positions.emplace_back(p);
  mesh.triangles.assign(triangles.begin(), triangles.end());
  return mesh;
}

void VolumeMesh::sortTriangles() {
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
}

}  // namespace shadowvol
