// The search for hidden surfaces (the sub-grid's VolumeBuildOptions::nearerSurfaces; docs/volume.md
// "Hidden surfaces"): which quads of a depth map's grid hold part of a surface that the capture
// would record nearer than a given depth, found from the triangles' projections, without rays.
//
// A map samples the scene once per texel centre. An occluder thinner than a texel (a limb, a wire,
// a ridge on a shell) can lie between the centres: no sample sees it, so no boundary edge, refined
// quad or sub-grid node does either, and its shadow is lost. Every triangle the capture could
// record (back capture: facing away from the light, as the GPU's front-face culling and Embree's
// back-face filter decide; front and midpoint capture: any; entry capture: those facing away and
// every triangle of a closed mesh, whose faces towards the light have a back face behind them) is
// clipped to the light-view depth range
// [near, far], projected into texel coordinates, and clipped against each quad square its image
// overlaps (quad (qi, qj) is the square between texel centres (qi, qj) and (qi + 1, qj + 1)); the
// quad is flagged when a point of the clipped polygon lies nearer than the quad's limit. The depth
// is exact at the polygon's corners and its extremes lie there: along a straight line of the image
// the light-view depth is linear (directional light) or its inverse is (spot light).
//
// Conservative where it matters: a triangle that reaches into a quad's closed square is seen there
// however thin, so an occluder that crosses the side between two quads is found in both. Midpoint
// capture records the middle of two surfaces, which lies behind the first: the first surface's
// depth counts, which can flag a quad whose midpoint sample would not be nearer (harmless: the
// sub-grid then samples it and finds nothing new).
//
// The open rims (findOpenRims): an open mesh's border (a hole in a shell, the edge of a cloth or a
// sheet) can lie between the centres too: every corner of a quad records the surface, and the gap
// in it, where light passes, is lost. The rims are the mesh's edges without a neighbour
// (triangleNeighbours: welded by position; an edge of three or more triangles counts as well); a
// quad is flagged when a point of a rim within [near, far] in its closed square lies nearer than its
// limit, clipped as the triangles are.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/depth_map.h"
#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

/// Triangles as the ray tracer stores them: xyz triples (the map's coordinates, as its rays) and
/// index triples into them.
struct TriangleSoup {
  std::span<const float> xyz;
  std::span<const std::uint32_t> indices;
  /// A closed surface (isClosedSurface): entry capture records its faces towards the light too.
  bool closed = false;
  /// The open rims (openRims: vertex index pairs, two per edge) for findOpenRims; empty: none.
  std::span<const std::uint32_t> rims;
  /// The edge neighbours (triangleNeighbours, triangle_adjacency.h) of these triangles, for
  /// findCasterFaces (caster_faces.h), which finds them itself where this is empty.
  std::span<const std::int32_t> neighbours;
};

/// Rims closer than this share of a mesh's bounding-box diagonal to another (a seam of a soup whose
/// copies of a vertex differ by round-off) are sealed: no light passes there that a sub-grid could see.
inline constexpr double kRimSealShare = 1e-4;

/// The edges of `mesh` without a neighbour (triangleNeighbours' rule: an open border, an edge of
/// three or more triangles), as pairs of vertex indices (two entries per edge), in the order of
/// their welded ends (deterministic); left out: the edges of triangles with two equal corners (no
/// area), and those sealed by another rim: both ends within kRimSealShare of the mesh's diagonal of
/// the other's ends (a soup's seam, the copies of a non-manifold edge), or shorter than that. Empty
/// for a closed mesh (isClosedSurface), without welding when it is closed as stored (closedAsStored:
/// two closed parts that touch along an edge have no rim there). Not sealed: a seam along a
/// T-junction, where one rim meets two. Sets `*closed` (when given) to isClosedSurface(mesh),
/// found on the way.
std::vector<std::uint32_t> openRims(const TriangleMesh& mesh, bool* closed = nullptr);

/// The soup view of a mesh (no copy; valid while the mesh is); `closed` as isClosedSurface(mesh).
TriangleSoup soupOf(const TriangleMesh& mesh);
/// A copy of the soup's triangles as a mesh (for the rules written for meshes: openRims,
/// triangleNeighbours).
TriangleMesh meshOf(const TriangleSoup& soup);

/// The capture's facing rule, for every stage that asks it: how the triangle with light-view
/// corners a, b, c (counter-clockwise seen from its front) faces the light. +1 towards it (the
/// normal of the front points against the ray from the apex through a; for a directional light,
/// `perspective` false, against the light's -z), -1 away from it (back capture records only
/// these), 0 edge-on or without area (the cosine of normal and ray within 1e-9: its image has no
/// area; no capture records it), and 0 for non-finite corners.
int lightFacing(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool perspective);

/// For each quad q = qj * (W - 1) + qi of the map's grid, sets flags[q] = 1 when a triangle of
/// `meshes` that the map's capture mode can record has a point in the quad's square, within the map's
/// [near, far], whose light-view depth is below limit[q] (see the header comment); other flags are
/// left as they are. limit and flags hold (W - 1) * (H - 1) entries; a limit at or below the near
/// plane (or NaN) finds nothing. Parallel over triangles, deterministic. Indices out of range are
/// a logic error (SV_CHECK).
void findNearerSurfaces(const DepthMap& map, std::span<const TriangleSoup> meshes, std::span<const float> limit,
                        std::span<std::uint8_t> flags);

/// As findNearerSurfaces for the meshes' rims (TriangleSoup::rims, any capture mode): sets
/// flags[q] |= kRimFlag where a point of a rim within [near, far] in quad q's closed square lies
/// nearer than limit[q]. Parallel over rims, deterministic; indices out of range: SV_CHECK.
inline constexpr std::uint8_t kRimFlag = 2;
void findOpenRims(const DepthMap& map, std::span<const TriangleSoup> meshes, std::span<const float> limit,
                  std::span<std::uint8_t> flags);

}  // namespace shadowvol
