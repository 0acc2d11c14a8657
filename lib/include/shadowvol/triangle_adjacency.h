// Edge neighbours of a triangle mesh: for every triangle and each of its three edges, the triangle
// on the other side, or kNoNeighbour. The GPU's silhouette walk (gl/renderer.h, RefineCrossings::
// GpuWalk) steps across these edges from the triangle a texel recorded until it leaves its surface.
//
// The rule: vertices are welded by exactly equal positions first (an STL file or a triangle soup
// repeats them), then edge k of triangle t (from its vertex k to vertex k + 1 mod 3) has a
// neighbour when exactly two triangles use that welded edge and they use it in opposite directions
// (consistently oriented). An open edge, an edge of three or more triangles, two triangles using
// an edge in the same direction, and every edge of a triangle with a repeated welded vertex have
// none: the walk treats them as the end of the surface. Deterministic (sorted, not hashed).
#pragma once

#include <cstdint>
#include <vector>

#include "shadowvol/triangle_mesh.h"

namespace shadowvol {

inline constexpr std::int32_t kNoNeighbour = -1;

/// neighbours[3 t + k]: the triangle across edge k of triangle t, or kNoNeighbour (the rule above).
/// Throws InputError for a mesh with 2^31 or more triangles (the neighbours are signed 32-bit).
std::vector<std::int32_t> triangleNeighbours(const TriangleMesh& mesh);

}  // namespace shadowvol
