// Silhouette refinement of a point light's cube volume (cube_volume.h): the rules of one map
// (boundary_edges.h, silhouette_refinement.h, refined_cells.h) on the cube's closed grid
// (shadowvol/cube_grid.h), so that the walls stand on the light's rays through the silhouette
// instead of slanting across a texel.
//   - Boundary edges. Inside each face: findBoundaryEdges of the face's map without the border
//     ring (the face's own steps beyond each end, its unfolding rounds). Across the cube's edges
//     (a border texel and the texel it pairs with: the sides of the edge quads and corner
//     triangles that join two faces): a far edge by the same rule; a surface edge by the jump
//     alone, J > kJumpFootprints F (no step beyond either end is looked up across the seam, so a
//     steep continuous surface there may be split: harmless, boundary_edges.h). Then one map's
//     unfolding rounds (boundary_edges.cpp) on every cell of the cube: a cell with exactly two
//     boundary sides, both surface edges, whose near sides disagree would fold its wall onto
//     itself, so both are made continuous, up to kMaxUnfoldRounds rounds.
//   - Crossings. Bisection (bisectWith) along the edge's rays: the ray at parameter s has the
//     direction (1 - s) dN + s dF, dN and dF the ends' texel directions (cubeTexelDirection, each
//     at its own face's depth 1), so inside a face s is one map's texel-space parameter. Each
//     sample asks the face whose pyramid holds its direction (cubeLookup) for the depth there: that
//     face's view depth, the cube depth of the point, the convention of every texel's depth. The
//     crossing's near and far vertices lie on its ray (the far vertex of a far edge on the far cube).
//   - Cells. Every cell with a boundary side is triangulated by CellTriangulator (a corner triangle
//     by its three-corner rules); one with 3 or 4 boundary sides is decided by one more ray at the
//     mean of its corners' directions.
// Not here: chord points, the sub-grid and crossing sources (the GPU walk) of one map.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/cube_grid.h"
#include "shadowvol/cube_map.h"
#include "shadowvol/depth_oracle.h"
#include "shadowvol/sheet_depth.h"
#include "shadowvol/silhouette_refinement.h"
#include "volume/cell_triangulator.h"

namespace shadowvol::cube {

struct BoundaryEdge {
  std::uint32_t nearTexel = 0, farTexel = 0;  ///< texel ids (cube_grid.h) of the near and the far end
  bool surface = false;                       ///< both ends hit, else a far edge
  bool inFace = false;                        ///< both ends on one face
};

/// The depths the cube's capture stores along light-relative directions (any scale): one oracle
/// batch per face, each direction asked of the face whose pyramid holds it. Adds to `budget`.
void sampleDirections(const CubeDepthMap& cube, std::span<const glm::dvec3> directions, const DepthOracle& oracle,
                      std::span<float> depth, RayBudget& budget);

/// The key of the grid edge between texels a and b, either order.
inline std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

struct CubeRefinement {
  static constexpr std::uint32_t kNoEdge = UINT32_MAX;
  std::vector<BoundaryEdge> edges;      ///< each face's in findBoundaryEdges' order, then the seams' in cell order
  std::vector<Crossing> crossings;      ///< one per edge
  std::vector<glm::dvec3> directions;   ///< per edge: its crossing's ray, scaled to cube depth 1
  std::vector<glm::dvec2> faceTexel;    ///< per in-face edge: the crossing's texel coordinates on its face
  RayBudget budget;                     ///< the oracle's rays and time
  /// The boundary edge between texels a and b (either order), or kNoEdge.
  std::uint32_t find(std::uint32_t a, std::uint32_t b) const {
    const auto it = index_.find(edgeKey(a, b));
    return it == index_.end() ? kNoEdge : it->second;
  }
  /// Texels that end a boundary edge (one byte per texel id): cells without one are not looked up.
  std::vector<std::uint8_t> touched;
  /// The cells with a boundary side (Grid indices, sorted): the refined cells.
  std::vector<std::uint32_t> cells;

  void add(const BoundaryEdge& e);
  /// Keeps only the edges with keep[e] set, in order.
  void keepOnly(const std::vector<std::uint8_t>& keep);

 private:
  std::unordered_map<std::uint64_t, std::uint32_t> index_;
};

/// The boundary edges and their crossings (`steps` >= 1 bisection rays each). `finalDepths` are
/// the texels' sheet depths (ring-free, blurred when `blur`), by texel id. InputError (naming the
/// refine steps) when the volume's vertices would not fit 32-bit indices.
CubeRefinement refineCube(const CubeDepthMap& cube, const Grid& cells, const SheetDepthRule& rule, bool blur,
                          std::span<const double> finalDepths, const DepthOracle& oracle, int steps);

/// The sides of cell `cell` (corners A B C D, or A B D of a corner triangle) that are boundary
/// edges: bit k for the side from corner k to corner k + 1; 0 when none is.
std::uint8_t boundarySides(const Cell& cell, const CubeRefinement& r);

/// One refined cell's loop (refined_cells.h's RefinedCell, on the cube): its corners and each
/// boundary side's crossing vertices on corner k's side (a[k]) and corner k + 1's (b[k]). Ids:
/// corners their texel ids, crossing e's near vertex crossingBase + 2 e, its far one + 1.
struct CubeCell {
  volume::CellVertex corners[4], a[4], b[4];
  int count = 4;
  std::uint8_t sides = 0;
};

/// Fills the loop of `cell`; `depth(id)` gives each texel's sheet depth.
template <class Depth>
CubeCell assembleCubeCell(const Cell& cell, std::uint8_t sides, const CubeRefinement& r, double farPlane, int n,
                          std::uint32_t crossingBase, const Depth& depth) {
  CubeCell c;
  c.count = cell.cornerCount();
  c.sides = sides;
  std::uint32_t ids[4];
  for (int k = 0; k < c.count; ++k) ids[k] = cell.corner(k);
  for (int k = 0; k < c.count; ++k) {
    volume::CellVertex& v = c.corners[k];
    v.id = ids[k];
    v.depth = depth(ids[k]);
    v.far = v.depth == farPlane;
    v.lv = v.depth * texelDirection(n, ids[k]);
  }
  for (int k = 0; k < c.count; ++k) {
    if (!(sides >> k & 1)) continue;
    const std::uint32_t e = r.find(ids[k], ids[(k + 1) % c.count]);
    const BoundaryEdge& edge = r.edges[e];
    const Crossing& x = r.crossings[e];
    volume::CellVertex nearV, farV;
    nearV.id = crossingBase + 2 * e, farV.id = crossingBase + 2 * e + 1;
    nearV.depth = x.nearDepth, farV.depth = x.farDepth;
    farV.far = !edge.surface;
    nearV.lv = x.nearDepth * r.directions[e];
    farV.lv = x.farDepth * r.directions[e];
    const bool cornerIsNear = edge.nearTexel == ids[k];
    c.a[k] = cornerIsNear ? nearV : farV;
    c.b[k] = cornerIsNear ? farV : nearV;
  }
  return c;
}

/// The direction of a cell's centre ray: the mean of its corners' texel directions.
glm::dvec3 cellCentreDirection(const Cell& cell, int n);

}  // namespace shadowvol::cube
