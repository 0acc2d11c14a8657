#include "mesh_readers/polygon_fan.h"

namespace shadowvol::mesh_readers {

void appendPolygon(std::span<const std::uint32_t> corners, ParsedMesh& mesh) {
  if (corners.size() > 3)
    mesh.polygons.push_back({std::uint64_t(mesh.triangles.size()), std::uint32_t(corners.size() - 2)});
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
}

}  // namespace shadowvol::mesh_readers
