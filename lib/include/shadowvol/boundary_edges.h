// Boundary edges of a depth map: the grid edges between neighbouring texel centres where the
// captured surface is discontinuous, so that silhouette refinement (silhouette_refinement.h)
// puts a wall across them. Two kinds:
//   far:     one end hit, the other on the far plane (no hit, beyond far, or the border ring);
//   surface: both ends hit, on surfaces too far apart in depth to be one (an occluder over a
//            receiver, a fold of one mesh).
// The discontinuity rule for a surface edge P-Q along one axis, on the sheet depths without the
// blur's averaging u = SheetDepthRule::ofSample (world units; the blur moves sheet vertices, it
// does not decide where surfaces end; both ends need u short of the far plane):
//   J  = |u(Q) - u(P)|, the jump;
//   gP = |u(P) - u(P')|, gQ = |u(Q') - u(Q)|, the steps just beyond each end along the same axis
//        (P' before P, Q' after Q; a neighbour that is far or off the grid gives no step);
//   F  = the texel footprint at the nearer end's depth: the light-view distance between the rays of
//        neighbouring texel centres at that depth, at the map's centre (TexelFootprint);
//   discontinuous iff J > max(kJumpFootprints * F, kJumpSlope * min(gP, gQ)), the min over the
//   steps that exist, 0 when none does.
// A continuous surface tilted away from the light changes its depth by about the same step texel
// after texel, so J stays near min(gP, gQ): it is not split, however steep. Towards the rim of a
// round object the steps grow, but by at most 1 + sqrt(2) = 2.41 from one texel to the next (the
// depth goes as the square root of the distance to the rim), below kJumpSlope = 3. At an edge over
// a receiver at least one side is flatter than the jump, so the min is small. kJumpFootprints = 2
// keeps surfaces tilted less than atan(2) = 63 degrees from facing the light continuous even where
// no neighbour tells their slope. A false split on a continuous surface is harmless: bisection then
// stands a wall where the depth crosses the middle of the step, a sub-texel change of the sheet.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "shadowvol/depth_map.h"
#include "shadowvol/sheet_depth.h"

namespace shadowvol {

inline constexpr double kJumpFootprints = 2.0;  ///< see the header comment
inline constexpr double kJumpSlope = 3.0;       ///< see the header comment
/// Rounds of findBoundaryEdges' unfolding: a fold that survives them keeps its edges (its wall
/// crosses itself; the volume stays closed).
inline constexpr int kMaxUnfoldRounds = 4;

/// The texel footprint of a map as a function of light-view depth: F(d) = a + b * d (exact for
/// orthographic (b = 0) and perspective (a = 0) lights; measured at the map's centre, where a
/// spot light's texels are smallest).
struct TexelFootprint {
  double a = 0.0, b = 0.0;
  static TexelFootprint of(const DepthMap& map);
  double at(double depth) const { return a + b * depth; }
};

/// The rule of the header comment for a surface edge; gP, gQ < 0 mean "no step on that side".
bool discontinuous(double uP, double uQ, double gP, double gQ, const TexelFootprint& footprint);

struct BoundaryEdge {
  int i = 0, j = 0;          ///< texel P, the edge's lower end
  std::uint8_t axis = 0;     ///< 0: Q = (i + 1, j); 1: Q = (i, j + 1)
  bool nearAtP = false;      ///< P is the near end (the hit end, or the smaller depth)
  bool surface = false;      ///< both ends hit (a surface edge), else a far edge
};

/// Every boundary edge of a map, sorted by (j, i, axis).
struct BoundaryEdges {
  std::vector<BoundaryEdge> edges;
  std::vector<std::size_t> rowStart;  ///< height + 1 entries: row j's edges (P in row j) start here
  /// Index of the edge from texel (i, j) along `axis`, or edges.size() when it is not a boundary edge.
  std::size_t find(int i, int j, int axis) const;
};

/// The boundary edges of `map` under `rule`: far edges where exactly one end's final sheet depth
/// (sheetDepthOf: ring, blur when `blur`, bias) is the far plane, surface edges by the rule above on
/// the unblurred depths u = SheetDepthRule::ofSample(stored, blur) (with the blur offset). With
/// blur, `blurredSheetDepths` holds every texel's final sheet depth (DepthMap layout; the builder's
/// materialised grid); without, it is not read (the final depth is u, the ring aside).
/// Row-parallel, deterministic. When splitBits is given (one byte per texel), bit 0 / bit 1 of
/// texel (i, j) are set when its edge along +i / +j is a boundary edge, and every other bit is
/// cleared. Quads whose two boundary sides would give a folded wall are made continuous, in rounds
/// independent of the quads' order (see the implementation's keepWallsUnfolded). Without `ring`
/// the border texels keep their own depths (a point light's cube face, which has no ring:
/// cube_refinement.h); blurredSheetDepths then holds the final depths without the ring too.
BoundaryEdges findBoundaryEdges(const DepthMap& map, const SheetDepthRule& rule, bool blur,
                                std::span<const double> blurredSheetDepths = {}, std::uint8_t* splitBits = nullptr,
                                bool ring = true);

/// The refined GPU volume's boundary flags (refine_common.glsl), one word per texel t = j W + i:
/// bit `axis` = the edge from t along axis is a boundary edge, bit 2 + axis = its near end is P,
/// bit 4 + axis = a surface edge. The shader's constants are checked against these by
/// tests/core/test_shader_constants.cpp.
inline constexpr std::uint32_t kFlagBoundary = 1, kFlagNearAtP = 4, kFlagSurface = 16;

/// The boundary edges that the flags of a width x height map name (the GPU's own edge set, so that
/// a CPU mesh of the GPU's crossings has the walls the GPU drew), in findBoundaryEdges' order, and
/// splitBits (one byte per texel, optional) as it writes them. Other bits of a word are ignored.
BoundaryEdges boundaryEdgesFromFlags(int width, int height, std::span<const std::uint32_t> flags,
                                     std::uint8_t* splitBits = nullptr);

/// How many edges two edge sets of one map disagree on: in one and not the other, or in both with
/// another near end or kind.
std::size_t differingBoundaryEdges(const BoundaryEdges& a, const BoundaryEdges& b);

/// Where refinement's boundary edges can come from instead of findBoundaryEdges
/// (VolumeBuildOptions::boundaryEdgeSource): the edges of `map`, with splitBits (one byte per
/// texel) written as findBoundaryEdges writes them. The arguments are findBoundaryEdges' own, so a
/// source can run the rule as well (to compare).
using BoundaryEdgeSource = std::function<BoundaryEdges(const DepthMap& map, const SheetDepthRule& rule, bool blur,
                                                       std::span<const double> blurredSheetDepths,
                                                       std::uint8_t* splitBits)>;

}  // namespace shadowvol
