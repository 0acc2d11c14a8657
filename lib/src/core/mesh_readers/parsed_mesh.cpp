#include "mesh_readers/parsed_mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "mesh_readers/corner_welder.h"

namespace shadowvol::mesh_readers {

glm::dvec3 storageOrigin(const ParsedMesh& parsed) {
  if (parsed.positions.empty()) return glm::dvec3(0.0);
  glm::dvec3 lo = parsed.positions[0], hi = lo;
  for (const glm::dvec3& p : parsed.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 reach = glm::max(glm::abs(lo), glm::abs(hi));
  const double step = std::max({reach.x, reach.y, reach.z}) * std::ldexp(1.0, -23);  // float's spacing there, at most
  const double extent = glm::length(hi - lo);
  if (step == 0.0 || extent >= kMinStoredSteps * step) return glm::dvec3(0.0);
  return 0.5 * lo + 0.5 * hi;  // (lo + hi) / 2 without overflow near the float range
}

TriangleMesh storedMesh(const ParsedMesh& parsed, const glm::dvec3& origin) {
  TriangleMesh mesh;
  const auto stored = [&](std::uint32_t i) { return glm::vec3(parsed.positions[i] - origin); };
  if (!parsed.weldCorners) {
    mesh.positions.reserve(parsed.positions.size());
    for (std::uint32_t i = 0; i < parsed.positions.size(); ++i) mesh.positions.push_back(stored(i));
    mesh.triangles = parsed.triangles;
    return mesh;
  }
  mesh.triangles.reserve(parsed.triangles.size());
  CornerWelder weld(mesh);
  for (const auto& t : parsed.triangles) mesh.triangles.push_back({weld.vertex(stored(t[0])), weld.vertex(stored(t[1])), weld.vertex(stored(t[2]))});
  return mesh;
}

}  // namespace shadowvol::mesh_readers
