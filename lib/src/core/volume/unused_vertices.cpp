#include "volume/unused_vertices.h"

#include <vector>

#include "volume/build_buffers.h"

namespace shadowvol::volume {

std::size_t dropUnusedVertices(VolumeMesh& mesh, std::uint32_t from) {
  if (from >= mesh.positions.size()) return 0;
  std::vector<std::uint32_t> renumber(mesh.positions.size() - from, kNone);
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v >= from) renumber[v - from] = 0;
  std::uint32_t next = from;
  for (std::size_t k = 0; k < renumber.size(); ++k) {
    if (renumber[k] == kNone) continue;
    renumber[k] = next;
    mesh.positions[next++] = mesh.positions[from + k];
  }
  const std::size_t dropped = mesh.positions.size() - next;
  if (dropped == 0) return 0;
  mesh.positions.resize(next);
  for (auto& t : mesh.triangles)
    for (std::uint32_t& v : t)
      if (v >= from) v = renumber[v - from];
  return dropped;
}

}  // namespace shadowvol::volume
