// Stage 4s of the volume builder (the sub-grid, VolumeBuildOptions::refineSubdivisions = S > 1):
// the refined quads (quads with a boundary edge, refined_cells.h; every one, or the adaptive choice
// below) are cut into S x S sub-cells,
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
//     sheet-depth rule (SheetDepthRule::ofSample, the blur offset added with blur), with a sheet
//     bias keeping only the part of it that a sample at each sub-cell's centre shows is needed
//     (subgrid_bias.h; the discontinuity rule reads the depth with the whole bias);
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
// virtual ones included, and where the lattice ends (an unrefined quad beyond) the texel grid's
// step along that axis divided by S (stepTo): a straight interpolation is flatter than a round object's rim, so a few
// sub-edges just inside a rim are split as surface edges (harmless, as boundary_edges.h says). Folds are prevented as for the
// texel grid (boundary_edges.h, keepWallsUnfolded), per sub-cell. Bisection takes `steps` rays per
// boundary sub-edge, and ambiguous sub-cells (3 or 4 boundary sides) one ray at their centre.
//
// Adaptive (the default; `plain` given): most refined quads along a smooth outline gain nothing
// from the sub-grid but its triangles. The lattice is laid and sampled over every refined quad as
// above, and a quad stays plain (refined_cells.h: one straight wall between its two crossings)
// when it has exactly two boundary sides, neither crossing lies on a lattice node, the outline does
// not bend away from the straight wall (its chord point, refined_cells.h's point where the outline
// crosses the wall's perpendicular bisector, found with K more rays, lies within kChordBendErrors
// times its own bisection error of the wall: a curved outline's sagitta, which the lattice's samples
// alone miss when it falls between them), and every sampled node on its sides and inside it lies
// on its plain triangulation's surface: far where that is far, else within kPlainQuadFootprints
// texel footprints of its depth (perspective-correct interpolation in the footprint triangle
// holding the node) and, with a sheet bias B and no blur, its captured surface (its sample: the rule
// depth less B) not behind that depth: else the plain sheet would pass in front of a lit surface
// (acne; a valley where grazing-lit ground meets an object standing on it, whose step the
// discontinuity rule splits, put up to a third of a texel of lit ground inside the volume). Two
// footprints is the discontinuity
// rule's floor (boundary_edges.h, kJumpFootprints): a smooth rim's curvature moves the depth by
// less than that within a texel, a fold or a receiver seen past an outline by more (on the default
// scene at 256^2, without the chord test, one footprint grids 68 % of the refined quads, two 15 %,
// measured as README "Sub-grid" says;
// the depth tolerance moves the error much less than the chord test does: README "Sub-grid"). A node
// off the surface puts every quad holding it on the sub-grid, so on a side between a plain and a
// gridded quad every sample agreed with the plain quad; its nodes are then put on the plain quad's
// boundary without a ray (between a corner and the crossing's vertex on its side, interpolated as
// the projection does), its sub-edge holding the crossing takes the plain crossing and its
// vertices, and the plain quad's triangle on each piece of the side is split at the nodes
// (splitQuadTriangles), as an unrefined neighbour's is. keepSubCellsUnfolded never clears such a
// preset sub-edge; where a gridded quad has two surface boundary sides towards plain quads (whose
// presets could meet in its corner sub-cell) both plain quads go on the sub-grid. The plain
// crossings of edges between two gridded quads are not used (dropUnusedVertices).
#pragma once

#include <cstdint>
#include <functional>
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

/// How far a sampled lattice node's depth may lie from the plain refined quad's surface there for
/// the adaptive sub-grid to keep that quad plain, in texel footprints (TexelFootprint) at that depth
/// (the header comment says why 2).
inline constexpr double kPlainQuadFootprints = 2.0;

/// How far the outline may bend away from a plain quad's straight wall at its middle for the
/// adaptive sub-grid to keep that quad plain, in bisection errors of the chord point that measures
/// it (its segment's length x 2^-(K+1); see the header comment).
inline constexpr double kChordBendErrors = 2.0;

/// The plain refinement of the same quads, for the adaptive sub-grid: the texel grid's boundary
/// edges and their crossings (vertices numbered from crossingBase, as refined_cells.h numbers them).
struct PlainRefinement {
  const BoundaryEdges& edges;
  const Refinement& refinement;
  std::uint32_t crossingBase = 0;
  const ChordPoints* chords = nullptr;  ///< one per quad with two boundary edges (planChordPoints), bisected
  int steps = 1;                        ///< K: the rays per crossing and per chord point
};

struct SubgridOptions {
  int subdivisions = 4;  ///< S, a power of two >= 2
  int steps = 4;         ///< bisection rays per boundary sub-edge
  bool blur = false;
  bool perfect = true;   ///< the diagonal rule in sub-cells without a boundary side
  bool exact = true;     ///< drop triangles with three far vertices (the sub-grid needs the exact cap)
  const SurfaceEndOracle* ends = nullptr;  ///< snap the sub-edges' crossings (crossing_snap.h); null: no snap
  bool rimBias = false;                    ///< with the snap: the near vertices at rimVertexDepth (rim_bias.h)
};

/// One side of an unrefined quad that carries virtual nodes: its corner vertices and the nodes'
/// vertices from `from` to `to`.
struct SideSplit {
  std::uint32_t quad = 0;  ///< the unrefined (or plain refined) quad's index qj * (W - 1) + qi
  std::uint32_t from = 0, to = 0;
  std::vector<std::uint32_t> points;
};

struct SubgridCells {
  std::vector<Tri> triangles;            ///< kept triangles, in quad order
  std::vector<CapEdge> capEdges;         ///< the far cap's boundary edges
  std::vector<glm::dvec3> positions;     ///< world positions of the vertices from firstVertex on
  std::vector<SideSplit> splits;         ///< in order of the unrefined quad, then of discovery
  std::vector<SideSplit> plainSplits;    ///< the same for sides of plain refined quads (adaptive)
  std::vector<std::uint8_t> gridded;     ///< per quad of `quads`: 1 when it is on the sub-grid
  std::size_t griddedQuads = 0;          ///< quads on the sub-grid
  std::size_t samples = 0;               ///< lattice nodes sampled by the oracle
  std::size_t biasSamples = 0;           ///< sub-cell centres sampled for the nodes' bias (subgrid_bias.h)
  std::size_t boundaryEdges = 0;         ///< boundary sub-edges (bisected)
  std::size_t farBoundaryEdges = 0;      ///< of which one end is far
  std::size_t ambiguousCells = 0;        ///< sub-cells with 3 or 4 boundary sides
  std::size_t footprintTriangles = 0;    ///< kept triangles that are not walls
  std::size_t raysCast = 0;              ///< oracle queries: samples, bias samples, bisection, snap, centres
  std::size_t snapped = 0;               ///< boundary sub-edges' crossings snapped (crossing_snap.h)
  std::size_t rimCrossings = 0;          ///< of which near vertices moved towards the rim (rim_bias.h)
  double msRays = 0.0;                   ///< time inside the oracle (ms)
};

/// Refines the quads of `quads` on the sub-grid (see the header comment): every one when `plain` is
/// null, else the adaptive choice (see the header comment), the others left to refined_cells.h. The
/// new vertices are numbered from `firstVertex` (their positions in the result); the hit corners
/// keep their sheet vertex (`use`, `vertices`), the plain crossings theirs.
SubgridCells buildSubgridCells(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices,
                               const SheetDepths& sheet, const DepthOracle& oracle, const SubgridOptions& options,
                               std::uint32_t firstVertex, const PlainRefinement* plain = nullptr);

/// The mesh triangles of one quad: `count` from `first`.
struct QuadSlots {
  std::size_t first = 0, count = 0;
};

/// After the sheet is emitted: each triangle of a split's quad (slotsOf(quad)) with a side in
/// `splits` becomes a fan from a new vertex at its centroid over its corners and the side's points,
/// in the triangle's own plane and winding (the first triangle of the fan takes its place, the
/// others are appended).
void splitQuadTriangles(const std::vector<SideSplit>& splits, const std::function<QuadSlots(std::uint32_t)>& slotsOf,
                        VolumeMesh& mesh);

}  // namespace shadowvol::volume
