// Lossless flattening of the far cap: a constrained Delaunay triangulation (CGAL, exact predicates)
// of the planar region bounded by closed loops of edges, in texel coordinates (grid edges between
// texel centres, or, with silhouette refinement, the walls' far edges between crossing points).
// Vertices in the middle of straight runs (alone at their point, on the segment between their
// loop neighbours) are left out of the CDT and put back by fanning each face over the runs on its
// sides (no Steiner points, no zero-area triangles), since lattice points on lines are the CDT's
// most degenerate and slowest input.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace shadowvol {

/// One directed boundary edge of a planar region: the region lies on its left (counter-clockwise
/// in texel space, i right, j up). `from` / `to` are mesh vertex indices, the texels their texel
/// coordinates (integers for texel centres; dyadic fractions for refined crossings, exact in
/// double). Several vertices may share a point (a pinch, see buildVolume): each vertex index must
/// have exactly one outgoing and one incoming edge, so the edges form loops.
struct CapEdge {
  std::uint32_t from = 0, to = 0;
  glm::dvec2 fromTexel{0.0}, toTexel{0.0};
};

/// Triangulates the region on the left of the loops (holes and islands by orientation; an edge
/// present in both directions is a cut with the region on both sides) with only the
/// loops' vertices (no Steiner points), so every boundary vertex and edge is kept and the result
/// closes with whatever shares those edges. Triangles are counter-clockwise in texel space, as mesh
/// vertex indices; where several vertices share a point, each triangle gets the one whose wedge
/// (between its incoming and outgoing edge) contains it. No triangle has zero area.
/// Edges must not cross or overlap (grid edges of one planar triangulation never do, nor do the
/// walls' far edges of a refined volume).
std::vector<std::array<std::uint32_t, 3>> triangulateCapLoops(const std::vector<CapEdge>& edges);

}  // namespace shadowvol
