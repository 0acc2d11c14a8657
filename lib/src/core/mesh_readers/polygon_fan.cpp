#include "mesh_readers/polygon_fan.h"

namespace shadowvol::mesh_readers {

void appendFan(std::span<const std::uint32_t> corners, std::vector<std::array<std::uint32_t, 3>>& triangles) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) triangles.push_back({corners[0], corners[k], corners[k + 1]});
}

}  // namespace shadowvol::mesh_readers
