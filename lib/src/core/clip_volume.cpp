#include "clip_volume.h"

#include <algorithm>
#include <array>
#include <cstdio>

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

std::string emptyViewWarning(const glm::dmat4& worldToClip, const std::vector<SceneObject>& objects,
                             const std::string& what, double nearPlane, double farPlane,
                             const std::string& consequence) {
  if (!std::all_of(objects.begin(), objects.end(),
                   [&](const SceneObject& o) { return outsideClipVolume(worldToClip, o.mesh); }))
    return {};
  char planes[160];
  std::snprintf(planes, sizeof planes, " (between its near plane at %.6g and its far plane at %.6g world units): ",
                nearPlane, farPlane);
  return "no object lies " + what + planes + consequence;
}

}  // namespace shadowvol::detail
