// Stage 4s of the volume builder (the sub-grid, VolumeBuildOptions::refineSubdivisions = S > 1):
// every refined quad (a quad with a boundary edge, refined_cells.h) is cut into S x S sub-cells,
// the depth is sampled at their corners with the depth oracle, and each sub-cell is refined as a
// refined quad is (boundary sub-edges by the discontinuity rule with the texel footprint divided by
// S, bisection along them, cell_triangulator.h), so the contour follows an outline that bends or
// turns inside a texel.
//
// The lattice: node (a, b) of quad (qi, qj) lies at texel coordinates (qi + a / S, qj + b / S),
// a, b = 0..S; nodes are shared between quads, so neighbouring refined quads agree on every node and
// sub-edge of the side between them. Its depth:
//   corners (texel centres): the sheet depth, as every other stage sees it;
//   inside a refined quad, or on a side between two refined quads: the oracle's sample by the
//     sheet-depth rule (SheetDepthRule::ofSample, the blur offset added with blur);
//   on a side whose other quad is not refined ("virtual" nodes): no ray. That side is continuous
//     (a hit-far or discontinuous side is a boundary edge, whose quads are both refined), so its
//     corners are both far (the nodes are far, and no triangle keeps them) or both hit (one
//     surface, or a jump whose surface edges were removed against a fold): the nodes then lie on the sheet triangle's edge between the corners (the depth
//     interpolated as the projection does: linearly for a directional light, its inverse linearly
//     for a spot light), and that triangle of the unrefined quad is split at them
//     (splitSheetTriangles), so the mesh has no T-junction and the sheet keeps its shape.
// A sub-edge along such a side (between its virtual nodes and corners) is never a boundary edge.
// As in boundary_edges.h, the rule reads depths without the blur's averaging (a corner's own
// sample, a virtual node's interpolation of those); the blurred depths only place vertices.
// The discontinuity rule's steps beyond a sub-edge's ends are those to the next lattice nodes,
// virtual ones included: a straight interpolation is flatter than a round object's rim, so a few
// sub-edges just inside a rim are split as surface edges (harmless, as boundary_edges.h says). Folds are prevented as for the
// texel grid (boundary_edges.h, keepWallsUnfolded), per sub-cell. Bisection takes `steps` rays per
// boundary sub-edge, and ambiguous sub-cells (3 or 4 boundary sides) one ray at their centre.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "shadowvol/depth_oracle.h"
#include "shadowvol/far_cap.h"
#include "shadowvol/volume_mesh.h"
#include "volume/build_buffers.h"
#include "volume/refined_cells.h"
#include "volume/sheet_depths.h"
#include "volume/sheet_vertices.h"

namespace shadowvol::volume {

struct SubgridOptions {
  int subdivisions = 4;  ///< S, a power of two >= 2
  int steps = 4;         ///< bisection rays per boundary sub-edge
  bool blur = false;
  bool perfect = true;   ///< the diagonal rule in sub-cells without a boundary side
  bool exact = true;     ///< drop triangles with three far vertices (the sub-grid needs the exact cap)
};

/// One side of an unrefined quad that carries virtual nodes: its corner vertices and the nodes'
/// vertices from `from` to `to`.
struct SideSplit {
  std::uint32_t quad = 0;  ///< the unrefined quad's index qj * (W - 1) + qi
  std::uint32_t from = 0, to = 0;
  std::vector<std::uint32_t> points;
};

struct SubgridCells {
  std::vector<Tri> triangles;            ///< kept triangles, in quad order
  std::vector<CapEdge> capEdges;         ///< the far cap's boundary edges
  std::vector<glm::dvec3> positions;     ///< world positions of the vertices from firstVertex on
  std::vector<SideSplit> splits;         ///< in order of the unrefined quad, then of discovery
  std::size_t samples = 0;               ///< lattice nodes sampled by the oracle
  std::size_t boundaryEdges = 0;         ///< boundary sub-edges (bisected)
  std::size_t farBoundaryEdges = 0;      ///< of which one end is far
  std::size_t ambiguousCells = 0;        ///< sub-cells with 3 or 4 boundary sides
  std::size_t footprintTriangles = 0;    ///< kept triangles that are not walls
  std::size_t raysCast = 0;              ///< oracle queries: samples, bisection, centres
  double msRays = 0.0;                   ///< time inside the oracle (ms)
};

/// Refines every quad of `quads` on the sub-grid (see the header comment). The new vertices are
/// numbered from `firstVertex` (their positions in the result); the hit corners keep their sheet
/// vertex (`use`, `vertices`).
SubgridCells buildSubgridCells(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices,
                               const SheetDepths& sheet, const DepthOracle& oracle, const SubgridOptions& options,
                               std::uint32_t firstVertex);

/// After the sheet is emitted: each sheet triangle with a side in `splits` becomes a fan from a new
/// vertex at its centroid over its corners and the side's points, in the triangle's own plane and
/// winding (the first triangle of the fan takes its place, the others are appended).
void splitSheetTriangles(const std::vector<SideSplit>& splits, const Scratch<std::uint32_t>& quadTri,
                         VolumeMesh& mesh);

}  // namespace shadowvol::volume
