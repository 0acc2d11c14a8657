// Inside or outside a closed surface by the parity of a ray's crossings: the rule that the scene's
// warnings (a light or camera inside a closed mesh) and the orientation on loading (a part inside
// another, mesh_orientation.h) share. In double; the ray leaves in one fixed skewed direction, so
// that it seldom meets an edge or a vertex of an axis-aligned or regular mesh exactly.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace shadowvol {

/// The direction of every parity ray (unit length).
inline const glm::dvec3 kParityRayDirection = glm::normalize(glm::dvec3(0.5377, 0.8421, 0.0419));

/// Whether the ray from `origin` along kParityRayDirection crosses triangle (a, b, c) at a
/// positive distance (Moller-Trumbore; a triangle parallel to the ray is not crossed).
inline bool parityRayCrosses(const glm::dvec3& origin, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3& dir = kParityRayDirection;
  const glm::dvec3 e1 = b - a, e2 = c - a, h = glm::cross(dir, e2);
  const double det = glm::dot(e1, h);
  if (det == 0.0) return false;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, h) / det;
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 g = glm::cross(s, e1);
  const double v = glm::dot(dir, g) / det;
  if (v < 0.0 || u + v > 1.0) return false;
  return glm::dot(e2, g) / det > 0.0;
}

}  // namespace shadowvol
