#include "mesh_readers/parsed_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "mesh_readers/corner_welder.h"
#include "shadowvol/mesh_io.h"

namespace shadowvol::mesh_readers {

double FloatPlacement::steps() const {
  const double step = reach * std::ldexp(1.0, -23);
  return extent > 0.0 && step > 0.0 ? extent / step : std::numeric_limits<double>::infinity();
}

FloatPlacement FloatPlacement::of(std::span<const glm::dvec3> points) {
  if (points.empty()) return {};
  glm::dvec3 lo = points[0], hi = lo;
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 reach = glm::max(glm::abs(lo), glm::abs(hi));
  return {glm::length(hi - lo), std::max({reach.x, reach.y, reach.z})};
}

FloatPlacement FloatPlacement::worse(const FloatPlacement& a, const FloatPlacement& b) {
  return b.steps() < a.steps() ? b : a;
}

glm::dvec3 storageOrigin(const ParsedMesh& parsed) { return floatStorageOrigin(parsed.positions, parsed.triangles); }

TriangleMesh storedMesh(const ParsedMesh& parsed, const glm::dvec3& origin) {
  TriangleMesh mesh;
  const auto stored = [&](std::uint32_t i) { return glm::vec3(parsed.positions[i] - origin); };
  if (!parsed.weldCorners) {
    mesh.positions.reserve(parsed.positions.size());
    for (std::uint32_t i = 0; i < parsed.positions.size(); ++i) mesh.positions.push_back(stored(i));
    mesh.triangles = parsed.triangles;
    return mesh;
  }
  // Welded in the order of the parsed positions, which come in the order of their first corners
  // (STL: a position per corner; Assimp: welded by their double bits in corner order), so the
  // vertices are numbered by their first corners, as when the readers welded while reading.
  CornerWelder<glm::vec3> weld(mesh.positions);
  std::vector<std::uint32_t> welded(parsed.positions.size());
  for (std::uint32_t i = 0; i < parsed.positions.size(); ++i) welded[i] = weld.vertex(stored(i));
  mesh.triangles.reserve(parsed.triangles.size());
  for (const auto& t : parsed.triangles) mesh.triangles.push_back({welded[t[0]], welded[t[1]], welded[t[2]]});
  return mesh;
}

}  // namespace shadowvol::mesh_readers
