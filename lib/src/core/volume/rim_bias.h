// The sub-grid's rim bias (docs/volume.md "Sub-grid", step 9): how much of front (or entry)
// capture's bias a snapped crossing's near vertex keeps above the rim, where the recorded surface
// ends.
//
// Front capture holds the whole sheet a texel footprint B behind the surface it records, so that
// the sheet's straight runs between samples never pass in front of a lit surface (acne). Next to
// a silhouette seen from the light, where a surface turns away, B is also what loses the shadows
// that start within it: a model's parts shading each other, the terminator of a faceted curve.
// The snap (crossing_snap.h) knows the triangle that ends at the crossing, so the vertex can stand
// on the rim itself plus what the sheet's run from the crossing's near end needs: that run passes
// in front of the surface between them only where the surface bends away from the light, and then
// by at most how far the rim triangle's plane, carried on to the near end, lies behind the near
// end's sample (the surface lies between the run and that plane); a fold towards the silhouette
// needs nothing. Where the rim lies deeper than the last near sample with the whole bias (a lit
// triangle nearly edge-on to the light, which falls steeply between that sample and where it
// ends: the terminator of a faceted curve, a drafted side), the vertex goes down to it, so the
// sheet no longer passes in front of that triangle's lower part.
#pragma once

#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/depth_map.h"
#include "shadowvol/silhouette_refinement.h"
#include "volume/sheet_depths.h"

namespace shadowvol::volume {

/// The least fraction of the bias B that a near vertex keeps above the rim: for the depth
/// precision and a bend between samples that no plane shows (measured in docs/results/rim-bias).
inline constexpr double kRimBiasFloor = 1.0 / 8.0;

/// The near vertex depth of crossing c at texel point `at` (of the map `unproject` is of), whose
/// segment's near end lies at texel point `nearEnd` with rule depth `nearDepth` (its sample's, with
/// the bias, as the discontinuity rule reads it): with B = rule.bias > 0 and a rim triangle
/// (Crossing::rim), the rim's depth at `at` plus keep = min(B, kRimBiasFloor * B + e), e = max(0, the
/// rim triangle's depth on the near end's light ray - (nearDepth - B)), with the rim's depth no deeper than the
/// triangle's deepest corner. Not nearer the light than c.nearDepth - B (the near sample's own surface: a triangle
/// nearly edge-on, whose plane `at` reaches a little off, cannot pull it further), nor before the near plane; beyond
/// c.nearDepth (d(lo) + B) only where the rim lies deeper, and never past the middle between c.nearDepth and
/// c.farDepth (where the bisection's rule would put a sample on the far side). keep = B where the plane shows no
/// depth there (edge-on). Without B or a rim: c.nearDepth.
double rimVertexDepth(const TexelUnprojector& unproject, const Crossing& c, glm::dvec2 at, glm::dvec2 nearEnd,
                      double nearDepth, const SheetDepthRule& rule);

/// Moves c's near vertex to rimVertexDepth where that differs from it, keeping the depth it had as
/// Crossing::nearSample (what the discontinuity rule reads); returns whether it moved.
bool moveNearVertexToRim(const TexelUnprojector& unproject, Crossing& c, glm::dvec2 at, glm::dvec2 nearEnd,
                         double nearDepth, const SheetDepthRule& rule);

/// The texel grid's crossings (plain refinement, after its chord points and before the sub-grid
/// reads them): moveNearVertexToRim for each snapped crossing, from its edge's near texel; returns
/// how many moved. Sheet depths without blur (the caller's condition).
std::size_t lowerPlainRimVertices(const SheetDepths& sheet, const BoundaryEdges& edges,
                                  std::vector<Crossing>& crossings);

/// The same for the crossings of bisection segments that are no grid edges (the plain quads' chord
/// points with the adaptive sub-grid): from each segment's near point and its near depth.
std::size_t lowerSegmentRimVertices(const SheetDepths& sheet, std::span<const BisectionSegment> segments,
                                    std::vector<Crossing>& crossings);

}  // namespace shadowvol::volume
