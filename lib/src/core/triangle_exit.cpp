#include "shadowvol/triangle_exit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace shadowvol {

double triangleExit(const DepthMap& map, const std::array<glm::dvec3, 3>& corners, glm::dvec2 from, glm::dvec2 to) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  const glm::dvec2 dir = to - from;
  if (!(dir.x != 0.0 || dir.y != 0.0)) return none;
  std::array<glm::dvec2, 3> image;
  for (int k = 0; k < 3; ++k) {
    if (map.lightType != LightType::Directional && !(map.viewDepthOf(corners[k]) > 1e-9 * map.farPlane)) return none;
    image[k] = map.texelOf(corners[k]);
  }
  const glm::dvec2 ab = image[1] - image[0], ac = image[2] - image[0];
  const double area2 = ab.x * ac.y - ab.y * ac.x;
  double longest = 0.0;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 e = image[(k + 1) % 3] - image[k];
    longest = std::max(longest, glm::dot(e, e));
  }
  if (!(std::abs(area2) > 1e-12 * longest)) return none;
  // Cyrus-Beck: each side's outward normal n; the path leaves the side's half-plane at
  // n . (a - from) / n . dir where it heads outwards (n . dir > 0); the first such is the exit.
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 a = image[k], e = image[(k + 1) % 3] - a;
    const glm::dvec2 n = area2 > 0.0 ? glm::dvec2(e.y, -e.x) : glm::dvec2(-e.y, e.x);
    const double rate = glm::dot(n, dir);
    if (rate > 0.0) t = std::min(t, glm::dot(n, a - from) / rate);
  }
  if (!std::isfinite(t)) return none;  // cannot happen for a triangle of positive area
  return std::max(t, 0.0);
}

double triangleDepthAt(const TexelUnprojector& unproject, const std::array<glm::dvec3, 3>& corners, glm::dvec2 at) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  const TexelUnprojector::Ray ray = unproject.ray(at.x, at.y);  // t = light-view depth
  const glm::dvec3 n = glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
  const double along = glm::dot(n, ray.direction);
  if (!(std::abs(along) > 1e-12 * glm::length(n) * glm::length(ray.direction))) return none;
  const double t = glm::dot(n, corners[0] - ray.origin) / along;
  return t > 0.0 ? t : none;
}

}  // namespace shadowvol
