// Validity checks of a closed triangle mesh (a shadow volume) with CGAL, and point-in-volume tests.
// Everything is in the mesh's own space (world space for a VolumeMesh); predicates are exact
// (CGAL Epick), so "degenerate" means exactly collinear, not "small".
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/volume_mesh.h"

namespace shadowvol {

struct MeshCheckOptions {
  bool selfIntersections = false;  ///< run CGAL does/self_intersections (slow: use on small meshes)
  /// Optional: a self-intersecting pair whose whole intersection (every point of it) satisfies
  /// this predicate is counted in allowedTouchingPairs instead of selfIntersectingPairs. buildVolume
  /// uses it for the far plane, where the exact volume has zero thickness (see docs/volume.md).
  std::function<bool(const glm::dvec3&)> allowedTouch;
};

/// Result of checkMesh. Counts are 0 for a valid closed volume.
struct MeshCheckReport {
  std::size_t vertices = 0, triangles = 0;
  std::size_t nonFiniteVertices = 0;     ///< any coordinate NaN or infinite
  std::size_t badIndexTriangles = 0;     ///< index out of range or repeated within the triangle
  std::size_t degenerateTriangles = 0;   ///< exactly collinear corners (zero area)
  std::size_t boundaryEdges = 0;         ///< directed edges whose opposite edge is missing
  std::size_t overusedEdges = 0;         ///< directed edges used by more than one triangle
  std::size_t nonManifoldVertices = 0;   ///< vertices whose triangles do not form one fan (closed, or
                                         ///< open at a boundary, whose edges boundaryEdges counts)
  std::size_t isolatedVertices = 0;      ///< vertices used by no triangle
  std::size_t coincidentVertices = 0;    ///< vertices at the same position as an earlier vertex
  /// The following need a closed 2-manifold (closedManifold()); otherwise left at their defaults.
  bool outward = false;                  ///< every connected component's volume signed as its nesting
                                         ///< asks (mesh_check.cpp isOutward; PMP::is_outward_oriented
                                         ///< beyond 4096 components)
  double volume = 0.0;                   ///< CGAL PMP::volume (> 0 when outward)
  std::optional<std::size_t> selfIntersectingPairs;  ///< set when MeshCheckOptions::selfIntersections
  std::size_t allowedTouchingPairs = 0;  ///< pairs accepted by MeshCheckOptions::allowedTouch

  /// Every directed edge exactly once and its opposite exactly once, every vertex one fan.
  bool closedManifold() const {
    return badIndexTriangles == 0 && boundaryEdges == 0 && overusedEdges == 0 && nonManifoldVertices == 0;
  }
  /// closedManifold, outward, finite, no zero-area triangle, no isolated vertex, and no
  /// self-intersection when they were checked. An empty mesh is valid (an empty volume).
  bool valid() const;
  std::string summary() const;  ///< one line with every count, for test failures and the CLI
};

/// Checks a triangle mesh (triangles counter-clockwise seen from outside). A mesh of several
/// parts (VolumeMesh::partStarts) is checked part by part (partMesh), the reports summed
/// (sumReports): each part must be a closed volume on its own; parts may overlap. A part after the
/// first is outward when each of its connected components has a positive signed volume (it may
/// overlap itself, volume_mesh.h), and self-intersections (MeshCheckOptions::selfIntersections)
/// are the first part's alone.
MeshCheckReport checkMesh(const VolumeMesh& mesh, const MeshCheckOptions& options = {});

/// Several meshes' checks as one report: every count summed, outward when every non-empty one is,
/// self-intersections counted when every one was checked.
MeshCheckReport sumReports(const std::vector<MeshCheckReport>& reports);

/// Point-in-volume queries on a closed mesh (CGAL Side_of_triangle_mesh over an AABB tree, built
/// once). The mesh must satisfy MeshCheckReport::closedManifold(); it is copied. A mesh of several
/// parts is their union: inside when inside a part, else on the boundary when on a part's surface.
/// Each part is classified by parity, which takes a point where two solids of a part that overlaps
/// itself (the face prisms) overlap for outside: windingNumber (volume_mesh.h) counts them.
class VolumeClassifier {
 public:
  enum class Side { Inside, Boundary, Outside };
  explicit VolumeClassifier(const VolumeMesh& mesh);
  ~VolumeClassifier();
  VolumeClassifier(VolumeClassifier&&) noexcept;
  VolumeClassifier& operator=(VolumeClassifier&&) noexcept;

  Side classify(const glm::dvec3& point) const;  ///< point in the mesh's space
  bool inside(const glm::dvec3& point) const { return classify(point) == Side::Inside; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace shadowvol
