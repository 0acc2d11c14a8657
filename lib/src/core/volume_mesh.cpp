#include "shadowvol/volume_mesh.h"

namespace shadowvol {

TriangleMesh VolumeMesh::toTriangleMesh() const {
  TriangleMesh mesh;
  mesh.positions.reserve(positions.size());
  for (const glm::dvec3& p : positions) mesh.positions.emplace_back(p);
  mesh.triangles.assign(triangles.begin(), triangles.end());
  return mesh;
}

}  // namespace shadowvol
