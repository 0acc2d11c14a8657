#include "shadowvol/walk_crossings.h"

#include <algorithm>
#include <cmath>

#include "shadowvol/check.h"

namespace shadowvol {

std::vector<WalkQuery> walkQueries(const BoundaryEdges& edges, std::span<const glm::dvec2> centres) {
  std::vector<WalkQuery> out;
  out.reserve(edges.edges.size() + centres.size());
  for (const BoundaryEdge& e : edges.edges)
    out.push_back({WalkQuery::kEdge, e.i, e.j,
                   std::uint32_t(e.axis) | (e.nearAtP ? 2u : 0u) | (e.surface ? 4u : 0u)});
  for (const glm::dvec2& c : centres)
    out.push_back({WalkQuery::kCentre, std::int32_t(std::floor(c.x)), std::int32_t(std::floor(c.y)), 0u});
  return out;
}

Refinement refinementFromWalks(const DepthMap& map, const BoundaryEdges& boundary, const SheetDepthRule& rule, bool blur,
                               std::span<const double> blurredSheetDepths, std::span<const WalkResult> answers,
                               std::size_t centres) {
  const std::vector<BoundaryEdge>& edges = boundary.edges;
  SV_CHECK_EQ(answers.size(), edges.size() + centres);
  const double farPlane = rule.farPlane;
  // A walk's depth as a sample of the surface: no hit where it is not a finite depth >= 0.
  auto ofWalk = [&](float d) { return rule.ofSample(std::isfinite(d) && d >= 0.0f ? d : DepthMap::kNoHit, blur); };
  Refinement result;
  result.crossings.resize(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const BoundaryEdge& e = edges[k];
    const BisectionSegment ends = edgeSegment(map, e, rule, blur, blurredSheetDepths);  // as bisection takes them
    const double nearEnd = ends.nearFallback, farEnd = ends.farDepth;
    const WalkResult& w = answers[k];
    Crossing& c = result.crossings[k];
    c = {0.5, nearEnd, farEnd};
    if (w.status != WalkResult::kCrossed || !std::isfinite(w.s)) {
      ++result.fallbacks;
      continue;
    }
    c.s = std::clamp(double(w.s), kWalkEdgeMargin, 1.0 - kWalkEdgeMargin);
    const double nearAt = ofWalk(w.nearDepth);
    if (nearAt != farPlane) c.nearDepth = nearAt;
    if (e.surface) {
      const double farAt = ofWalk(w.farDepth);
      c.farDepth = farAt != farPlane && farAt > c.nearDepth ? farAt : farEnd;
      if (!(c.farDepth > c.nearDepth)) {  // the near vertex came out beyond the far end's depth
        c = {0.5, nearEnd, farEnd};
        ++result.fallbacks;
      }
    }
    SV_CHECK_LT(c.nearDepth, c.farDepth);
  }
  result.centreDepths.resize(centres);
  for (std::size_t c = 0; c < centres; ++c) result.centreDepths[c] = ofWalk(answers[edges.size() + c].nearDepth);
  return result;
}

}  // namespace shadowvol
