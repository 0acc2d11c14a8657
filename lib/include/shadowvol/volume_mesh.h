// The explicit shadow volume: a closed, consistently oriented triangle mesh in world space.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/default_init_allocator.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// Vertices and triangles of a shadow volume, world space, double precision.
/// Triangles are counter-clockwise seen from outside (outward normals), so the sheet faces the
/// light and the far cap faces away from it. Vertices are not tied to texel centres: a vertex
/// is just a point (later refinements may move sheet vertices off texel centres).
/// The vectors use DefaultInitAllocator: resize(n) without a value leaves the new elements
/// unwritten (the builder fills them in parallel); resize(n, value) and push_back are as usual.
struct VolumeMesh {
  std::vector<glm::dvec3, DefaultInitAllocator<glm::dvec3>> positions;
  std::vector<std::array<std::uint32_t, 3>, DefaultInitAllocator<std::array<std::uint32_t, 3>>> triangles;
  /// The positions are relative to this point: world = position + origin (the depth map's origin,
  /// see Scene::origin; 0 for a scene near the world origin).
  glm::dvec3 origin{0.0};
  /// Where each closed part after the first begins: triangles [partStarts[k], partStarts[k + 1])
  /// (the last to the end) are a closed volume of their own, which may overlap the others (the
  /// refined volume's face prisms, docs/volume.md "Face prisms"); the triangles before
  /// partStarts[0] are the first part. Empty: one part. The shadow is their union: a point is in
  /// shadow iff its winding number summed over the parts is non-zero (z-fail counts add up), so a
  /// renderer draws them all as one mesh; mesh checks and crossing counts take each part alone
  /// (partMesh), since overlapping parts cross each other and may share coincident faces. A part
  /// after the first is a union of solids that may overlap each other (the prisms behind faces
  /// that overlap as seen from the light): outward there means every connected component's
  /// signed volume is positive (checkMesh), not the first part's nesting rule.
  std::vector<std::size_t> partStarts;

  std::size_t vertexCount() const { return positions.size(); }
  std::size_t triangleCount() const { return triangles.size(); }
  std::size_t partCount() const { return partStarts.size() + 1; }
  /// Part k (0 <= k < partCount()) alone: its triangles and the vertices they use, renumbered in
  /// order of first use; the same origin, no parts.
  VolumeMesh partMesh(std::size_t k) const;
  /// Single-precision copy (for OpenGL upload, Embree, and the mesh writers).
  TriangleMesh toTriangleMesh() const;
  /// Puts the triangles in one order whatever order they came in: each rotated to begin at its
  /// smallest index (the winding kept), then sorted. For a mesh listed by parallel GPU passes,
  /// whose order changes from run to run, so that what is computed from it (the signed volume, a
  /// written file) does not. Parts stay parts: each is sorted within its own range.
  void sortTriangles();
};

/// The winding number of a closed, outward mesh at `p` (the mesh's own coordinates: relative to
/// its origin): the signed crossings of the ray from p along kParityRayDirection (ray_parity.h),
/// +1 where it leaves through a triangle. 1 inside a simple solid, 0 outside; where the parts of a
/// mesh or the prisms of its face-prism part overlap (VolumeMesh::partStarts), the number of them
/// holding p, which a parity test would call outside at 2. In double, O(triangles).
int windingNumber(const VolumeMesh& mesh, const glm::dvec3& p);

}  // namespace shadowvol
