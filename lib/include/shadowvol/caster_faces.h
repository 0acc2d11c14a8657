// The casters' own faces where a depth map's sheet cannot follow them (the refined volume's face
// prisms, VolumeBuildOptions::facePrisms; docs/volume.md "Face prisms").
//
// Why these faces: every point behind a face along the light's rays is in shadow (its ray to the
// light crosses the face), so the prism a face sweeps from itself to the far plane holds shadow
// only, and so does the union of any set of them. Behind a closed occluder the shadow is exactly
// the union of the prisms of its faces turned away from the light (a light ray leaves a closed
// mesh through such a face). Taking those faces wherever the depth map's sheet may be wrong, in the
// columns of the quads that refinement works on (the points whose light ray passes through such a
// quad's square), gives the mesh's own shadow there, as a silhouette volume would, at a cost set
// by the faces in those columns.
//
// Selection: every triangle of a closed mesh (TriangleSoup::closed) that faces away from the
// light (the capture's facing rule, nearer_surfaces.h: the normal of the counter-clockwise front
// along the ray from the apex through the triangle, -z for a directional light; edge-on, cosine
// below 1e-9, is left out), whose three corners lie strictly between the map's near and far planes
// (light-view depth), whose image's bounding box (texel coordinates) lies inside the map's window
// [-0.5, W - 0.5] x [-0.5, H - 0.5] (so that every prism stays inside the light's frustum, where
// the z-pass rule of zpass.h assumes the volume is) and reaches the closed square of a flagged
// quad. Open meshes give no face here: behind them the shadow is the prisms of their
// faces of either facing, and a face towards the light would put its prism's near cap on a lit
// surface, a tie that the camera's depth test decides by round-off (left for later).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/nearer_surfaces.h"

namespace shadowvol {

/// The faces selected (see the header comment) from `meshes` for the quads with quads[q] != 0
/// (q = qj * (W - 1) + qi; (W - 1) * (H - 1) entries): each face's corners in the mesh's own order
/// and coordinates (the map's, as its rays; float values held in double), meshes in order and faces
/// in index order within each (deterministic). Indices out of range are a logic error (SV_CHECK).
std::vector<std::array<glm::dvec3, 3>> findCasterFaces(const DepthMap& map, std::span<const TriangleSoup> meshes,
                                                      std::span<const std::uint8_t> quads);
/// Whether the prisms can hold `mesh`'s whole shadow in any column of the map (the sheet's hand-over
/// to the prisms, VolumeBuildOptions::withoutCasters): a closed mesh every vertex of which lies
/// strictly between the near and far planes with its image inside the map's window, so that
/// findCasterFaces takes each of its faces turned away from the light whose image reaches a
/// flagged quad (only edge-on faces, which hold no volume, are left out). Empty meshes: false.
bool handedToPrisms(const DepthMap& map, const TriangleSoup& mesh);

}  // namespace shadowvol
