// Internal to the scene code: the depth range a box spans along an axis (scene.cpp's warnings and
// scene_fit.cpp's near/far fitting share it).
#pragma once

#include <algorithm>
#include <utility>

#include <glm/geometric.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol::detail {

/// Smallest and largest dot(corner - origin, axis) over the box's 8 corners.
inline std::pair<double, double> depthRange(const Bounds3& b, const glm::dvec3& origin, const glm::dvec3& axis) {
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 c((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
    const double d = glm::dot(c - origin, axis);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

}  // namespace shadowvol::detail
