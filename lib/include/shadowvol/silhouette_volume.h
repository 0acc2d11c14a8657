// Classic object-space shadow volumes (the sweep's accuracy baseline): silhouette edges from OpenMesh's
// half-edge connectivity, extruded away from the light, with a light cap and a dark cap. Pure CPU,
// no GL: the renderer draws the result with the same z-fail stencil pass as the hybrid volume.
//
// Which objects cast (the rule, applied to every scene object with triangles that repeat a vertex
// dropped: first to the mesh as stored, so that two vertices of a closed mesh may share a
// position; when that is not a closed 2-manifold, again after welding vertices with exactly equal
// positions, as an STL file or a triangle soup needs):
//   - closed 2-manifold (every edge has exactly two triangles, used once in each direction, every
//     vertex a single fan): a caster;
//   - open sheet (every edge has one or two triangles, consistently oriented, manifold vertices,
//     at least one boundary edge; a ground plane): a receiver only, it casts no shadow and is
//     listed by name (SilhouetteVolume::receiversOnly), so a caller can say so;
//   - anything else (an edge with three or more triangles, two triangles using an edge in the same
//     direction, a vertex where two fans touch): InputError naming the object and the edge or
//     vertex. Nothing is silently rendered wrong.
// Spot lights: a caster entirely behind the light's apex plane (light-view depth <= 0 at every
// vertex) cannot shadow the lit frustum and is skipped; one that straddles the apex plane is an
// InputError naming it (its extrusion is undefined there).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/light.h"
#include "shadowvol/scene.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol {

/// How a scene object takes part in silhouette shadow volumes (see the rule above).
enum class SilhouetteRole {
  Caster,        ///< closed 2-manifold: casts (and receives)
  ReceiverOnly,  ///< open sheet: receives only
};

struct SilhouetteObjectInfo {
  std::string name;  ///< SceneObject::name
  SilhouetteRole role = SilhouetteRole::Caster;
  std::size_t vertices = 0;       ///< as classified (stored, or after welding equal positions)
  std::size_t triangles = 0;      ///< after dropping triangles with a repeated vertex
  std::size_t boundaryEdges = 0;  ///< 0 for a caster
};

/// The scene's objects with half-edge connectivity (OpenMesh), built once and reused for every
/// light position (style.md point 3). World space. Move-only.
class SilhouetteOccluders {
 public:
  /// Classifies and connects every object. Throws InputError (source = scene.source, field =
  /// "/objects/<name>") for an object that is neither closed nor an open sheet.
  explicit SilhouetteOccluders(const Scene& scene);
  ~SilhouetteOccluders();
  SilhouetteOccluders(SilhouetteOccluders&&) noexcept;
  SilhouetteOccluders& operator=(SilhouetteOccluders&&) noexcept;

  const std::string& source() const;                         ///< the scene's source, for messages
  const std::vector<SilhouetteObjectInfo>& objects() const;  ///< in scene order
  std::vector<std::string> receiversOnly() const;            ///< names of the ReceiverOnly objects

  /// Silhouette edges of object `object` (a Caster) for `light`: world-space end points (a, b),
  /// ordered as in the triangle that faces the light (counter-clockwise seen from outside).
  /// A triangle faces the light when dot(cross(p1 - p0, p2 - p0), toLight) > 0 with toLight =
  /// apex - p0 (spot) or -direction (directional), in double; edge-on triangles face away.
  std::vector<std::array<glm::dvec3, 2>> silhouetteEdges(std::size_t object, const Light& light) const;

 private:
  friend struct SilhouetteVolume buildSilhouetteVolume(const SilhouetteOccluders&, const Light&);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// How much farther than its far cube a point light's silhouette volume is extruded (see
/// SilhouetteVolume::extrusionDepth).
inline constexpr double kPointLightExtrusion = 8.0;

struct SilhouetteVolume {
  /// World space, closed, every triangle counter-clockwise seen from outside (like the hybrid
  /// volume): per caster its light cap (the triangles facing the light, the object's own vertices
  /// and winding), one wall quad (two triangles) per silhouette edge, and the dark cap (the
  /// triangles facing away, projected along the light rays to light-view depth extrusionDepth).
  /// Every directed edge appears once and its reverse once. Extruded to a finite depth, not to
  /// infinity: draw it with GL_DEPTH_CLAMP (the renderer does), as the hybrid volume.
  /// Unlike the hybrid volume it is not a simple solid in general: for a non-convex caster the
  /// walls and caps cross each other (winding numbers above 1 where surfaces overlap as seen from
  /// the light), a vertex where the silhouette passes twice can be a pinch, and edge-on or
  /// collinear-with-the-light triangles give zero-area faces. Closed and consistently oriented
  /// always; use winding numbers (z-fail counts, signed crossings), not self-intersection checks.
  VolumeMesh mesh;
  std::size_t silhouetteEdges = 0;         ///< all casters
  std::size_t lightCapTriangles = 0;       ///< all casters
  std::size_t darkCapTriangles = 0;        ///< all casters
  double extrusionDepth = 0.0;             ///< light-view depth of the dark cap, world units: the light's far
                                           ///< plane, or 1.001 x the deepest caster vertex when that is farther;
                                           ///< a point light's (cube depth, cube_map.h) kPointLightExtrusion
                                           ///< times that (its dark cap's triangles are chords of the cube)
  std::vector<std::string> receiversOnly;  ///< open objects that cast nothing, by name
  std::vector<std::string> skipped;        ///< spot: casters entirely behind the apex plane
};

/// The silhouette shadow volume of every caster for `light` (its near/far set, as loadScene and
/// defaultScene fit them). Throws InputError naming an object that straddles a spot light's apex
/// plane. Exact for closed 2-manifold casters: a point is in shadow iff its winding number in
/// the volume is non-zero (z-fail stencil count != 0).
SilhouetteVolume buildSilhouetteVolume(const SilhouetteOccluders& occluders, const Light& light);

/// One shot: SilhouetteOccluders(scene) with scene.light.
SilhouetteVolume buildSilhouetteVolume(const Scene& scene);

}  // namespace shadowvol
