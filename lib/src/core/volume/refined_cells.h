// Stage 4r of the volume builder (silhouette refinement): the quads with a boundary edge, each
// triangulated with walls on the light's rays through its edges' crossings, marching-squares
// style. The quad's boundary loop is its corners, with each boundary edge's wall edge (the
// crossing's near and far vertex, on one light ray) inserted between the edge's two corners, the
// near vertex on the near end's side. The n boundary edges cut the loop into n components, runs of
// corners joined by continuous edges; each component is closed by the chord between its two
// crossings and triangulated as its own polygon (a triangle, a quad by the diagonal rule, a
// pentagon by a fan from its middle corner). What is left between the chords:
//   n = 1 (only a surface edge, whose jump fades inside the quad): the wall tapers from its
//         crossing to the opposite corner across the quad;
//   n = 2: one wall between the two crossings' wall edges: with chord points (refineChords) it
//         bends at one more crossing M inside the quad, found by bisection on the chord's
//         perpendicular bisector between the cell's boundary on either side (so the contour
//         follows a curved or cornered outline instead of cutting it straight); each component is
//         then fanned from M;
//   n = 3, 4: a middle polygon through one vertex per crossing, picked by one more ray at the
//         quad's centre (the near vertex of a far edge when the centre ray hits, its far vertex
//         when not; of a surface edge, the vertex whose depth is closer to the centre's), fanned
//         from its first vertex, and a wall piece under each of its sides. This decides the
//         ambiguous saddle (two diagonal corners hit): near vertices join the hit corners across
//         the centre, far vertices join the no-hit corners.
// With the exact cap a triangle with three vertices on the far plane is dropped; the far edges of
// the walls that border a dropped triangle are the far cap's boundary (CapEdge, region on the left).
// Every boundary edge's crossing is strictly inside it, so no two crossings coincide, polygons are
// convex in texel space with no three corners on a line, every wall has a nonzero height, and no
// triangle is degenerate.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/far_cap.h"
#include "shadowvol/silhouette_refinement.h"
#include "shadowvol/volume_mesh.h"
#include "volume/cell_triangulator.h"
#include "volume/grid_unprojector.h"
#include "volume/sheet_depths.h"
#include "volume/sheet_vertices.h"

namespace shadowvol::volume {

/// The refined quads, in quad order, with the centre points of the ambiguous ones (3 or 4
/// boundary edges; texel coordinates).
struct RefinedQuads {
  std::vector<std::uint32_t> quads;     ///< quad indices qj * (W - 1) + qi
  std::vector<std::uint8_t> sides;      ///< per quad: bit k set when side k is a boundary edge
  std::vector<glm::dvec2> centres;      ///< one per ambiguous quad, in quad order
};
/// The quads the boundary edges touch, and the `hidden` quads (sorted quad indices, sides 0: the
/// sub-grid's quads refined for a hidden surface alone, nearer_surfaces.h).
RefinedQuads findRefinedQuads(const BoundaryEdges& edges, int width, int height,
                              std::span<const std::uint32_t> hidden = {});

struct RefinedCells {
  std::vector<Tri> triangles;                     ///< kept triangles, in quad order
  std::vector<std::uint32_t> firstTriangle;       ///< per quad: its first triangle; one more entry at the end
  std::vector<CapEdge> capEdges;                  ///< the far cap's boundary edges, in quad order
  std::vector<std::array<CapPoint, 3>> footprint; ///< triangles that are not walls (counter-clockwise
                                                  ///< in texel space): what the mirrored cap mirrors
  std::size_t bends = 0;                          ///< quads whose wall bends at a chord point
};

/// The loop of one refined quad: its corners A B C D, and for each boundary side k its crossing's
/// vertices on corner k's side (a[k]) and corner k + 1's side (b[k]).
struct RefinedCell {
  CellVertex corners[4], a[4], b[4];
};

/// Fills the cell of quad (qi, qj) whose boundary sides are `sides`. Vertex ids come from idx[0]
/// and idx[1] (the vertex numbers of texel rows qj and qj + 1) when given, else they are kNone.
void assembleCell(int qi, int qj, std::uint8_t sides, const SheetDepths& sheet, const BoundaryEdges& boundary,
                  const Refinement& refinement, const TexelUnprojector& unproject, const std::uint32_t* const* idx,
                  std::uint32_t crossingBase, RefinedCell& cell);

/// The vertex indices of crossing (or chord point) e: base + 2 e (near vertex), base + 2 e + 1 (far).
inline std::uint32_t nearVertex(std::uint32_t base, std::size_t e) { return base + 2u * std::uint32_t(e); }
inline std::uint32_t farVertex(std::uint32_t base, std::size_t e) { return base + 2u * std::uint32_t(e) + 1u; }

/// The chord points of the quads with two boundary edges: where to look (segments, for
/// bisectSegments), and what was found (crossings, filled in by the caller).
struct ChordPoints {
  static constexpr std::size_t kNone = std::size_t(-1);
  std::vector<std::size_t> ofQuad;          ///< per refined quad: its chord point, or kNone
  std::vector<BisectionSegment> segments;   ///< in quad order
  std::vector<Crossing> crossings;          ///< one per segment (bisectSegments)
  /// A chord point bends the wall only where it lies off the straight wall between the quad's two
  /// crossings by more than bendFloor times its own bisection error (its segment's length x
  /// 2^-(steps + 1)); 0: always (refineChords).
  double bendFloor = 0.0;
  int steps = 0;
  glm::dvec2 texel(std::size_t k) const {
    const BisectionSegment& g = segments[k];
    return g.nearPoint + crossings[k].s * (g.farPoint - g.nearPoint);
  }
  /// Whether chord point k bends the wall between crossings x and y (texel coordinates).
  bool bends(std::size_t k, glm::dvec2 x, glm::dvec2 y) const;
};

/// The adaptive sub-grid's plain quads bend their walls at their chord points (measured by the
/// choice, within kChordBendErrors of the straight wall, or the quad is cut) beyond a quarter of
/// the chord point's bisection error: a straight outline (a box's edge, whose snapped crossings and
/// chord point lie on one line) keeps its straight wall, whose sheet the fan from a chord point
/// would tilt between the wall and a corner close to it.
inline constexpr double kPlainChordBendFloor = 0.25;

/// Plans one chord point per quad with exactly two boundary edges (see the header comment).
ChordPoints planChordPoints(const RefinedQuads& quads, const SheetDepths& sheet, const BoundaryEdges& edges,
                            const Refinement& refinement);

/// Triangulates every refined quad (see the header comment). `crossingBase` / `chordBase` are the
/// first crossing / chord-point vertex indices; `chords` may be null (no chord points).
RefinedCells triangulateRefinedCells(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices,
                                     const SheetDepths& sheet, const BoundaryEdges& edges, const Refinement& refinement,
                                     const ChordPoints* chords, bool perfect, bool exact, std::uint32_t crossingBase,
                                     std::uint32_t chordBase);

/// World positions of every crossing's two vertices, into mesh.positions from crossingBase, and
/// of every chord point's from chordBase.
void emitCrossingVertices(const DepthMap& map, const BoundaryEdges& edges, const Refinement& refinement,
                          const ChordPoints* chords, std::uint32_t crossingBase, std::uint32_t chordBase,
                          VolumeMesh& mesh);

}  // namespace shadowvol::volume
