// Sub-texel silhouette refinement: where along each boundary edge (boundary_edges.h) the near
// surface ends, found with a few rays of the map's own capture rule (depth_oracle.h).
//
// Along the edge from its near end N to its far end R (texel coordinates), bisection keeps a
// bracket [lo, hi] of the edge parameter s (0 at N, 1 at R), starting at [0, 1], and asks the
// oracle at its middle m, `steps` times. The sample belongs to the near surface when its sheet
// depth (SheetDepthRule::fromStored of the oracle's depth, plus the blur offset when blurring) is
//   far edge:     short of the far plane (any hit);
//   surface edge: short of the far plane and nearer than the middle of the bracket ends' depths
//                 (d(lo) + d(hi)) / 2 (both updated as the bracket shrinks, so a sloped surface
//                 is followed).
// Near: lo = m (and d(lo) = its depth), else hi = m (and, for a hit, d(hi) = its depth). The crossing
// is the middle of the last bracket, s = (lo + hi) / 2: where the surface ends, within 2^-(steps+1)
// of a texel, when it ends once along the edge; a dyadic fraction, so its texel coordinate is exact
// in double. Its wall stands on the light ray through that point: the near vertex at d(lo) (the
// near end's own sheet depth when no sample was near), the far vertex at the far plane (far edge)
// or at d(hi) (surface edge). The batches go level by level: one oracle call per step for every
// edge at once. The same bisection serves any segment of the image plane (bisectSegments): the
// builder's chord points use it too.
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/depth_oracle.h"
#include "shadowvol/sheet_depth.h"

namespace shadowvol {

struct Crossing {
  double s = 0.5;           ///< edge (or segment) parameter from the near end, in (0, 1)
  double nearDepth = 0.0;   ///< light-view depth of the wall's near vertex (world units)
  double farDepth = 0.0;    ///< light-view depth of the wall's far vertex (the far plane for far edges)
  // (The three above first: aggregate initialisers {s, near, far} fill them.)
  /// Where the sub-grid's rim bias moved nearDepth (volume/rim_bias.h): the depth it had, the
  /// near sample's, which the discontinuity rule reads (sampleNearDepth()); NaN otherwise.
  double nearSample = std::numeric_limits<double>::quiet_NaN();
  /// Snapped (crossing_snap.h): the triangle recorded on the near side, which ends at the crossing
  /// (the map's coordinates); NaN corners otherwise. The sub-grid's rim bias reads it (rim_bias.h).
  std::array<glm::dvec3, 3> rim = {glm::dvec3(std::numeric_limits<double>::quiet_NaN()),
                                   glm::dvec3(std::numeric_limits<double>::quiet_NaN()),
                                   glm::dvec3(std::numeric_limits<double>::quiet_NaN())};
  bool hasRim() const { return !std::isnan(rim[0].x); }
  /// The near side's sample depth (with the bias), as the discontinuity rule reads it.
  double sampleNearDepth() const { return std::isnan(nearSample) ? nearDepth : nearSample; }
  /// Texel coordinates (i, j) of the crossing on edge e.
  static glm::dvec2 texel(const BoundaryEdge& e, double s);
};

struct Refinement {
  std::vector<Crossing> crossings;  ///< one per boundary edge, in the same order
  std::vector<double> centreDepths; ///< sheet depth at each requested point (`centres`), the far
                                    ///< plane where nothing short of it is hit
  std::size_t raysCast = 0;         ///< oracle queries
  double msRays = 0.0;              ///< time inside the oracle (ms), or the crossing source's
  std::size_t fallbacks = 0;        ///< CrossingSource only: edges whose crossing it could not find
                                    ///< (walk_crossings.h: they get the middle of the edge)
  std::size_t snapped = 0;          ///< crossings snapped to where their triangle ends (crossing_snap.h)
};

/// Where refinement's crossings can come from instead of bisection with a depth oracle
/// (VolumeBuildOptions::crossingSource; the renderer's GPU silhouette walk, walk_crossings.h):
/// one Crossing per edge of `edges` (in order) and the sheet depth at each of `centres` (texel
/// coordinates), with the same meaning as refineBoundaryEdges' result.
using CrossingSource = std::function<Refinement(const DepthMap& map, const BoundaryEdges& edges,
                                                const SheetDepthRule& rule, bool blur,
                                                std::span<const double> blurredSheetDepths,
                                                std::span<const glm::dvec2> centres)>;

/// A segment of the image plane to bisect (texel coordinates): from a point on the near surface to
/// a point off it, by the rule of the header comment (far: off = no hit; surface: off = nearer the
/// far depth than the near one).
struct BisectionSegment {
  glm::dvec2 nearPoint{0.0}, farPoint{0.0};
  bool surface = false;       ///< a surface segment (both ends hit), else a far one
  double nearDepth = 0.0;     ///< sheet depth at nearPoint (d(lo) to start with; may be the far plane)
  double farDepth = 0.0;      ///< surface segments: sheet depth at farPoint (d(hi) to start with)
  double nearFallback = 0.0;  ///< the near vertex's depth when no sample short of the far plane was near
};

/// The segment of boundary edge e, from its near end to its far end, with the ends' depths as
/// refinement takes them: SheetDepthRule::ofSample of the stored depths (the ring on the far
/// plane), the far plane for a far edge's far end, and as nearFallback the near end's final sheet
/// depth from `blurredSheetDepths` where the blur offset puts its sample on the far plane (read
/// with blur only).
BisectionSegment edgeSegment(const DepthMap& map, const BoundaryEdge& e, const SheetDepthRule& rule, bool blur,
                             std::span<const double> blurredSheetDepths);

/// How close to a texel-grid point a crossing may come, in texels, for its world position to stay
/// apart from that point's in float: kFloatSafeSpacings spacings of float at the largest coordinate
/// of the map's frustum (the light's apex or window, and the far plane's corners, in the map's own
/// coordinates) over the texel footprint at the near plane (the smallest, at the map's centre).
double floatSafeTexels(const DepthMap& map);
inline constexpr double kFloatSafeSpacings = 4.0;

/// Moves crossing c at least `safeTexels` (floatSafeTexels), and at most a quarter of the segment,
/// from the ends of its segment of `length` texels. Every crossing goes through it, bisected or
/// from a crossing source (the GPU's rays or walk), whose crossings can lie on an end: two cap
/// corners at one point, which the far cap cannot triangulate.
void keepApartFromEnds(Crossing& c, double length, double safeTexels);

/// Rays spent, and the time inside the oracle (ms).
struct RayBudget {
  std::size_t rays = 0;
  double ms = 0.0;
};

/// Where bisection samples: depth[k] = what the map's capture stores (depth_map.h) at parameter
/// s[k] of segment k, for every segment; `step` counts the batches from 0.
using SegmentSampler = std::function<void(int step, std::span<const double> s, std::span<float> depth)>;

/// A segment's last bisection bracket: the parameters lo (near side) and hi (off it), and the
/// sheet depths d(lo), d(hi) of the header comment.
struct BisectionBracket {
  double lo = 0.0, hi = 1.0, dLo = 0.0, dHi = 0.0;
};

/// The brackets of the header comment's bisection on any segments: `steps` >= 1 batches of
/// `sample`; the segments' points are not read (the sampler places the parameters).
std::vector<BisectionBracket> bisectBrackets(std::span<const BisectionSegment> segments, const SheetDepthRule& rule,
                                             bool blur, int steps, const SegmentSampler& sample);

/// The crossing of the header comment from a segment's bracket: the bracket's middle, the near
/// vertex at d(lo) (the segment's nearFallback where that is the far plane), the far vertex at d(hi)
/// (surface segment) or the far plane.
Crossing bracketCrossing(const BisectionSegment& segment, const BisectionBracket& bracket, double farPlane);

/// bisectBrackets, each bracket's crossing (bracketCrossing). bisectSegments samples texel points of
/// one map with its oracle; a point light's cube samples directions (cube_refinement.h).
std::vector<Crossing> bisectWith(std::span<const BisectionSegment> segments, const SheetDepthRule& rule, bool blur,
                                 int steps, const SegmentSampler& sample);

/// Where each crossing found by bisection goes next (crossing_snap.h): nowhere (the bracket's
/// middle), or to where the triangle recorded on its near side ends.
struct CrossingSnap {
  const SurfaceEndOracle* ends = nullptr;  ///< unset: no snap
  std::size_t* snapped = nullptr;          ///< if set, incremented for each crossing snapped
};

/// Bisects every segment with `steps` >= 1 rays (one oracle batch per step for all of them); the
/// crossings' s run from nearPoint to farPoint. The `extra` points (texel coordinates) are sampled
/// in the first batch, their sheet depths (the far plane where nothing short of it is hit) written
/// to *extraDepths. Adds what it spends to `budget`.
/// With `snap.ends`, each crossing is then snapped (crossing_snap.h), its rays in `budget` too.
/// Every crossing is kept floatSafeTexels(map) from its segment's ends (in texels, as s times the
/// segment's length), so that the volume's float copy (VolumeMesh::toTriangleMesh, the writers)
/// never puts it on an end's vertex: that takes K = 16 on a sub-grid's 1/8-texel sub-edges at 512^2.
std::vector<Crossing> bisectSegments(const DepthMap& map, std::span<const BisectionSegment> segments,
                                     const SheetDepthRule& rule, bool blur, const DepthOracle& oracle, int steps,
                                     RayBudget& budget, std::span<const glm::dvec2> extra = {},
                                     std::vector<double>* extraDepths = nullptr, const CrossingSnap& snap = {});

/// Refines every edge of `edges` with `steps` >= 1 bisection rays each (the header comment), and
/// samples the sheet depth at the extra points `centres` (texel coordinates) in the first batch.
/// The near and far ends' depths come from the unblurred rule (SheetDepthRule::ofSample); `blur`
/// adds rule.blurOffset to them and to the oracle's depths, as the blur adds it to the sheet's. A
/// near vertex never lands on the far plane: where the unblurred rule puts the near end there
/// (possible only with blur), it takes the end's final sheet depth from `blurredSheetDepths` (as
/// for findBoundaryEdges; not read without blur).
Refinement refineBoundaryEdges(const DepthMap& map, const BoundaryEdges& edges, const SheetDepthRule& rule, bool blur,
                               std::span<const double> blurredSheetDepths, const DepthOracle& oracle, int steps,
                               std::span<const glm::dvec2> centres = {}, const CrossingSnap& snap = {});

}  // namespace shadowvol
