// Indexed triangle soup in world space: what the scene hands to Embree and OpenGL.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace shadowvol {

/// Axis-aligned bounding box in world space. Empty when min > max on any axis.
struct Bounds3 {
  glm::dvec3 min{1e300};
  glm::dvec3 max{-1e300};
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void extend(const glm::dvec3& p);
  void extend(const Bounds3& b);
  glm::dvec3 center() const { return 0.5 * (min + max); }
  double radius() const;  ///< half the diagonal; 0 for an empty box
};

/// Triangles as indices into positions. Counter-clockwise seen from outside = front face
/// (OpenGL's default), so for a closed mesh cross(p1 - p0, p2 - p0) points outward.
struct TriangleMesh {
  std::vector<glm::vec3> positions;                  ///< world units
  std::vector<std::array<std::uint32_t, 3>> triangles;

  std::size_t triangleCount() const { return triangles.size(); }
  Bounds3 bounds() const;
  /// Appends another mesh (its indices are offset).
  void append(const TriangleMesh& other);
  /// Removes the positions no triangle uses, keeping the others' order (indices renumbered);
  /// returns how many were removed.
  std::size_t removeUnusedVertices();
};

}  // namespace shadowvol
