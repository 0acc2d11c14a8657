#include "clip_volume.h"

#include <algorithm>
#include <array>

#include <glm/vec4.hpp>

namespace shadowvol::detail {

bool outsideClipVolume(const glm::dmat4& worldToClip, const TriangleMesh& mesh) {
  if (mesh.positions.empty()) return false;
  std::array<bool, 6> allBeyond;  // x > w, -x > w, y > w, -y > w, z > w (far), -z > w (near)
  allBeyond.fill(true);
  for (const auto& p : mesh.positions) {
    const glm::dvec4 c = worldToClip * glm::dvec4(glm::dvec3(p), 1.0);
    const std::array<bool, 6> beyond = {c.x > c.w, -c.x > c.w, c.y > c.w, -c.y > c.w, c.z > c.w, -c.z > c.w};
    for (std::size_t k = 0; k < beyond.size(); ++k) allBeyond[k] = allBeyond[k] && beyond[k];
  }
  return std::any_of(allBeyond.begin(), allBeyond.end(), [](bool b) { return b; });
}

}  // namespace shadowvol::detail
