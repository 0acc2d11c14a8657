// Edge neighbours of a triangle mesh: for every triangle and each of its three edges, the triangle
// on the other side, or kNoNeighbour. The GPU's silhouette walk (gl/renderer.h, RefineCrossings::
// GpuWalk) steps across these edges from the triangle a texel recorded until it leaves its surface.
//
// The rule: vertices are welded by exactly equal positions first (an STL file or a triangle soup
// repeats them), then edge k of triangle t (from its vertex k to vertex k + 1 mod 3) has a
// neighbour when exactly two triangles use that welded edge. When they use it in the same
// direction (one of them is wound the other way, as in a mesh with shuffled orientations) the link
// carries kFlippedNeighbour, so that the walk compares their facing the other way round. An open
// edge, an edge of three or more triangles, and every edge of a triangle with a repeated welded
// vertex have none: the walk treats them as the end of the surface. Deterministic (sorted, not
// hashed).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

inline constexpr std::int32_t kNoNeighbour = -1;
/// Set in a link whose two triangles use their edge in the same direction (wound oppositely).
inline constexpr std::int32_t kFlippedNeighbour = 1 << 30;

/// neighbours[3 t + k]: the triangle across edge k of triangle t (| kFlippedNeighbour when wound the
/// other way), or kNoNeighbour (the rule above). Throws InputError for a mesh with 2^30 or more
/// triangles (the index and the flag share a signed 32-bit word).
std::vector<std::int32_t> triangleNeighbours(const TriangleMesh& mesh);

/// Closed (edge-manifold, without border) by the rule above: every edge of every triangle that is
/// not degenerate (a repeated welded vertex) has a neighbour. `neighbours` is triangleNeighbours(mesh).
/// The orientation on loading takes this one (it walks the links).
bool closedByNeighbours(const TriangleMesh& mesh, const std::vector<std::int32_t>& neighbours);

/// Closed as stored: every edge of the vertex indices, in the triangles without a repeated index,
/// used by exactly two triangles (and at least one such triangle). No welding: one sort of the
/// edges, cheaper than triangleNeighbours; memory linear in `vertices`, the number of vertices the
/// indices address (an index at or above it is a logic error, SV_CHECK).
bool closedAsStored(std::span<const std::array<std::uint32_t, 3>> triangles, std::size_t vertices);
inline bool closedAsStored(const TriangleMesh& mesh) {
  return closedAsStored(std::span(mesh.triangles), mesh.positions.size());
}

/// Closed as stored (closedAsStored), or after welding equal positions (closedByNeighbours: STL and
/// soups store every corner apart). The scene's warnings take this one: two closed parts that
/// touch along a face are closed as stored, though not once welded.
bool isClosedSurface(const TriangleMesh& mesh);

/// What removeExtraTriangles left out.
struct ExtraTriangles {
  std::size_t flat = 0;        ///< flat triangles that only made their edges odd
  std::size_t duplicates = 0;  ///< repeats of another triangle's welded corners, wound the same way
  std::size_t total() const { return flat + duplicates; }
};

/// Leaves out, in place (the others keep their order), the triangles that bound nothing and only
/// keep a mesh from being closed (a fourteenth probe's inside-out mesh stayed inside out, called
/// open, for one such triangle), welded by exact position as above:
///   - a repeat of an earlier triangle's welded corners in the same cyclic order (it covers the
///     same points, facing the same way; one wound the other way is kept: with it, the pair is a
///     two-sided sheet);
///   - a flat triangle (its corners on a line: its height over its longest side under 1e-6 of that
///     side, or under 4 steps of 2^-24 of its corners' magnitude, so that a corner rounded to float
///     still counts) at least two of whose edges are used an odd number of times, itself included:
///     leaving it out evens more of its edges than it unevens. Judged in index order, each without
///     the flat triangles left out before it. A flat triangle that zips a T-junction pairs its edges
///     and is kept; of a zip and its reverse, one goes.
/// A mesh that is closed already (isClosedSurface) loses nothing, nor does one that would lose every
/// triangle. Triangles with a repeated welded vertex stay (they have no neighbours already).
ExtraTriangles removeExtraTriangles(TriangleMesh& mesh);

}  // namespace shadowvol
