// Internal to the scene code: the depth range a box spans along an axis, and how far out it reaches
// across a view (scene.cpp's warnings and checks and scene_fit.cpp's fitting share them).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol::detail {

/// The box's corner k (0 to 7: bit 0 picks max x, bit 1 max y, bit 2 max z).
inline glm::dvec3 boxCorner(const Bounds3& b, int k) {
  return {(k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z};
}

/// Smallest and largest dot(corner - origin, axis) over the box's 8 corners.
inline std::pair<double, double> depthRange(const Bounds3& b, const glm::dvec3& origin, const glm::dvec3& axis) {
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < 8; ++k) {
    const double d = glm::dot(boxCorner(b, k) - origin, axis);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  return {lo, hi};
}

/// The largest |x| or |y| of the box's 8 corners in `view` (a directional light's view: how far
/// out its window must reach to hold the box).
inline double viewReach(const Bounds3& b, const glm::dmat4& view) {
  double reach = 0.0;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec4 p = view * glm::dvec4(boxCorner(b, k), 1.0);
    reach = std::max({reach, std::abs(p.x), std::abs(p.y)});
  }
  return reach;
}

}  // namespace shadowvol::detail
