// Stage 7f of the volume build (VolumeBuildOptions::facePrisms; docs/volume.md "Face prisms"): the
// prisms of the casters' faces (caster_faces.h) from each face to the far plane, as one closed part
// of the volume mesh (VolumeMesh::partStarts), its own closed, outward 2-manifold.
//
// The faces are welded by exact position. A face's prism: its near cap is the face itself (turned
// towards the light, its front faces out of the prism, which lies behind it); its far cap the
// face's corners moved along their light rays to the far plane's light-view depth, reversed; a wall
// (two triangles) on each face edge whose reverse is no other face's edge (the patch's border: walls
// between two faces of the patch would cancel). So the part is the patch's silhouette volume: light
// cap, walls on its border, dark cap.
// Where two fans of the patch meet at one vertex (a pinch) the vertex has one copy per fan, near
// and far, so every vertex is one fan (the copies coincide in space). An edge used by more than one
// face in the same direction (two closed parts of a mesh touching along it) gets a wall per use.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/volume_mesh.h"

namespace shadowvol::volume {

struct FacePrismCounts {
  std::size_t faces = 0;      ///< faces taken
  std::size_t walls = 0;      ///< border edges (two wall triangles each)
  std::size_t triangles = 0;  ///< all the part's triangles
};

/// Appends the prisms of `faces` (corners counter-clockwise seen from outside the caster, each face
/// turned towards the light and strictly between the map's near and far planes, the map's
/// coordinates) to `mesh` as a new part (its first triangle recorded in mesh.partStarts); nothing
/// for no face.
FacePrismCounts appendFacePrisms(const DepthMap& map, std::span<const std::array<glm::dvec3, 3>> faces,
                                 VolumeMesh& mesh);

}  // namespace shadowvol::volume
