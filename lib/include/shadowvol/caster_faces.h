// The casters' own faces where a depth map's sheet cannot follow them (the refined volume's face
// prisms, VolumeBuildOptions::facePrisms; docs/volume.md "Face prisms").
//
// Why these faces: every point behind a face along the light's rays is in shadow or inside the
// mesh (its ray to the light crosses the face), so the prism a face sweeps from itself to the far
// plane holds nothing lit (its near cap, the face itself, is lit, and counts as outside by the
// camera depth test's rule, below), and neither does a union of such prisms. Behind a closed
// occluder its shadow and its inside are exactly the union of the prisms of its faces turned
// towards the light (a light ray enters a closed mesh through such a face). Taking those faces wherever the depth
// map's sheet may be wrong, in the columns of the quads that refinement works on (the points whose
// light ray passes through such a quad's square), gives the mesh's own shadow there, as a
// silhouette volume would.
//
// Why the faces towards the light, each region of them whole: the prisms' near caps then lie on the
// lit surface itself, at the camera pass's own depths (volume.vert's invariant position), so the
// stencil's depth test decides every lit pixel of them as it does for a silhouette volume's light
// cap; and their walls stand only where the region ends: on silhouette edges (where a face towards
// the light meets one turned away or edge-on), not across a lit surface, where a wall hanging from
// an edge between two lit faces meets the surface at the camera's depth, a tie decided by round-off.
// (A region also ends where faces leave the near-far range or the window, and at an edge without a
// neighbour link: there a wall may cross a lit surface.) Measured on issue 10's 48 closed-mesh
// scenes at 256², five frames each, against the silhouette volumes' 303 wrong pixels
// (docs/results/tie-noise): the faces turned away from the light in the flagged columns gave 311,
// within 1.5x of the silhouette volume's count on 42 of the scenes (their near caps are not the lit
// surface); the faces towards the light in those columns only, 344 (the walls across lit
// surfaces); these, 319, the silhouette volume's own count in every frame on 46 of the scenes and
// within 1.5x of it on all 48 (15 of the 16 more on the coupling, whose silhouette volume has 208).
//
// Selection: every triangle of a closed mesh (TriangleSoup::closed) that faces the light (the
// capture's facing rule, lightFacing in nearer_surfaces.h: the normal of the counter-clockwise
// front points against the ray from the apex through the triangle, the light's -z for a
// directional light; edge-on, cosine below 1e-9, is left out), whose three corners lie strictly
// between the map's near and far planes (light-view depth) and whose image's bounding box (texel
// coordinates) lies inside the map's window [-0.5, W - 0.5] x [-0.5, H - 0.5] (so that every prism
// stays inside the light's frustum, where the z-pass rule of zpass.h assumes the volume is): such
// a face is eligible. Taken: each eligible face whose image's bounding box reaches the closed
// square of a flagged quad, and every eligible face connected to one across edges between eligible
// faces (TriangleSoup::neighbours; a link between faces wound against each other is not crossed).
// The cost is the taken faces': a closed mesh whose lit side is one region (a sphere, a closed
// slab under the caster) is taken whole once any of it reaches a flagged quad. Open meshes give no
// face here: behind them the shadow is the prisms of their faces of either facing (left for later).
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
/// findCasterFaces takes each of its faces towards the light whose image reaches a flagged quad
/// (only edge-on faces, which hold no volume, are left out). Empty meshes: false.
bool handedToPrisms(const DepthMap& map, const TriangleSoup& mesh);

}  // namespace shadowvol
