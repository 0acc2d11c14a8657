#include "shadowvol/silhouette_refinement.h"

#include <algorithm>
#include <chrono>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/crossing_snap.h"

namespace shadowvol {

glm::dvec2 Crossing::texel(const BoundaryEdge& e, double s) {
  // s runs from the near end; the edge runs from P = (i, j) along its axis.
  const double t = e.nearAtP ? s : 1.0 - s;
  return {e.i + (e.axis == 0 ? t : 0.0), e.j + (e.axis == 1 ? t : 0.0)};
}

std::vector<BisectionBracket> bisectBrackets(std::span<const BisectionSegment> segments, const SheetDepthRule& rule,
                                             bool blur, int steps, const SegmentSampler& sample) {
  SV_CHECK_GE(steps, 1);
  const std::size_t n = segments.size();
  const double farPlane = rule.farPlane;
  std::vector<BisectionBracket> brackets(n);
  for (std::size_t k = 0; k < n; ++k) {
    brackets[k].dLo = segments[k].nearDepth;
    brackets[k].dHi = segments[k].surface ? segments[k].farDepth : farPlane;
  }
  std::vector<double> middle(n);
  std::vector<float> depth;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t k = 0; k < n; ++k) middle[k] = 0.5 * (brackets[k].lo + brackets[k].hi);
    depth.assign(n, DepthMap::kNoHit);
    sample(step, middle, depth);
    for (std::size_t k = 0; k < n; ++k) {
      BisectionBracket& b = brackets[k];
      const double m = middle[k];
      const double d = rule.ofSample(depth[k], blur);
      const bool hit = d != farPlane;
      const bool nearSide = hit && (!segments[k].surface || d < 0.5 * (b.dLo + b.dHi));
      if (nearSide) {
        b.lo = m, b.dLo = d;
      } else {
        b.hi = m;
        if (hit && segments[k].surface) b.dHi = d;
      }
    }
  }
  return brackets;
}

Crossing bracketCrossing(const BisectionSegment& segment, const BisectionBracket& b, double farPlane) {
  Crossing c;
  c.s = 0.5 * (b.lo + b.hi);
  // Never on the far plane: the segment's fallback (short of it) stands in.
  c.nearDepth = b.dLo != farPlane ? b.dLo : segment.nearFallback;
  c.farDepth = segment.surface ? b.dHi : farPlane;
  // Bisection keeps d(lo) < d(hi): a surface segment starts with them in that order, both short
  // of the far plane, and each step moves one end strictly between them.
  SV_CHECK_LT(c.nearDepth, c.farDepth);
  return c;
}

std::vector<Crossing> bisectWith(std::span<const BisectionSegment> segments, const SheetDepthRule& rule, bool blur,
                                 int steps, const SegmentSampler& sample) {
  const std::vector<BisectionBracket> brackets = bisectBrackets(segments, rule, blur, steps, sample);
  std::vector<Crossing> out(segments.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = bracketCrossing(segments[k], brackets[k], rule.farPlane);
  return out;
}

double floatSafeTexels(const DepthMap& map) {
  const TexelUnprojector unproject(map);
  double largest = 0.0;
  for (double d : {map.nearPlane, map.farPlane})
    for (double i : {-0.5, map.width - 0.5})
      for (double j : {-0.5, map.height - 0.5}) largest = std::max(largest, glm::length(unproject.worldPoint(i, j, d)));
  const double nearFootprint = TexelFootprint::of(map).at(map.nearPlane);
  if (!(nearFootprint > 0.0)) return 0.0;
  return kFloatSafeSpacings * largest * std::ldexp(1.0, -23) / nearFootprint;
}

std::vector<Crossing> bisectSegments(const DepthMap& map, std::span<const BisectionSegment> segments,
                                     const SheetDepthRule& rule, bool blur, const DepthOracle& oracle, int steps,
                                     RayBudget& budget, std::span<const glm::dvec2> extra,
                                     std::vector<double>* extraDepths, const CrossingSnap& snap) {
  SV_CHECK(bool(oracle));
  const std::size_t n = segments.size();
  if (extraDepths) extraDepths->assign(extra.size(), rule.farPlane);
  std::vector<glm::dvec2> ndc;
  std::vector<float> depth;
  // The oracle at the segments' texel points, and at the extra points in the first batch.
  auto sample = [&](int step, std::span<const double> s, std::span<float> out) {
    const std::size_t more = step == 0 ? extra.size() : 0;
    ndc.resize(n + more);
    depth.assign(n + more, DepthMap::kNoHit);
    for (std::size_t k = 0; k < n; ++k) {
      const BisectionSegment& g = segments[k];
      const glm::dvec2 t = g.nearPoint + s[k] * (g.farPoint - g.nearPoint);
      ndc[k] = map.texelNdc(t.x, t.y);
    }
    for (std::size_t c = 0; c < more; ++c) ndc[n + c] = map.texelNdc(extra[c].x, extra[c].y);
    if (ndc.empty()) return;
    const auto t0 = std::chrono::steady_clock::now();
    oracle(map, ndc, depth);
    budget.ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    budget.rays += ndc.size();
    std::copy(depth.begin(), depth.begin() + std::ptrdiff_t(n), out.begin());
    for (std::size_t c = 0; c < more; ++c) (*extraDepths)[c] = rule.ofSample(depth[n + c], blur);
  };
  if (n == 0 && !extra.empty()) {  // the extra points alone, in one batch
    sample(0, {}, {});
    return {};
  }
  std::vector<Crossing> out;
  if (!snap.ends) {
    out = bisectWith(segments, rule, blur, steps, sample);
  } else {
    const std::vector<BisectionBracket> brackets = bisectBrackets(segments, rule, blur, steps, sample);
    std::size_t snapped = 0;
    out = snapCrossings(map, segments, brackets, rule, blur, steps, oracle, *snap.ends, budget, snapped);
    if (snap.snapped) *snap.snapped += snapped;
  }
  // Apart from the segments' ends in float as well (the header's floatSafeTexels).
  const double safe = floatSafeTexels(map);
  for (std::size_t k = 0; k < n; ++k)
    keepApartFromEnds(out[k], glm::length(segments[k].farPoint - segments[k].nearPoint), safe);
  return out;
}

void keepApartFromEnds(Crossing& c, double length, double safeTexels) {
  if (!(length > 0.0)) return;
  const double m = std::min(0.25, safeTexels / length);
  if (m > 0.0) c.s = std::clamp(c.s, m, 1.0 - m);
}

BisectionSegment edgeSegment(const DepthMap& map, const BoundaryEdge& e, const SheetDepthRule& rule, bool blur,
                             std::span<const double> blurredSheetDepths) {
  const double farPlane = rule.farPlane;
  auto sample = [&](int i, int j) {
    if (SheetDepthRule::ring(i, j, map.width, map.height)) return farPlane;
    return rule.ofSample(map.at(i, j), blur);
  };
  const glm::ivec2 p(e.i, e.j), q(e.i + (e.axis == 0), e.j + (e.axis == 1));
  const glm::ivec2 a = e.nearAtP ? p : q, f = e.nearAtP ? q : p;
  BisectionSegment g;
  g.nearPoint = glm::dvec2(a), g.farPoint = glm::dvec2(f);
  g.surface = e.surface;
  g.nearDepth = sample(a.x, a.y);
  g.farDepth = e.surface ? sample(f.x, f.y) : farPlane;
  // Without blur the unblurred depth is the final one, so only the blur can put it on the far
  // plane; then the end's final sheet depth stands in.
  if (g.nearDepth == farPlane) SV_CHECK(blur);
  g.nearFallback = g.nearDepth != farPlane ? g.nearDepth : blurredSheetDepths[map.index(a.x, a.y)];
  return g;
}

Refinement refineBoundaryEdges(const DepthMap& map, const BoundaryEdges& boundary, const SheetDepthRule& rule, bool blur,
                               std::span<const double> blurredSheetDepths, const DepthOracle& oracle, int steps,
                               std::span<const glm::dvec2> centres, const CrossingSnap& snap) {
  const std::vector<BoundaryEdge>& edges = boundary.edges;
  std::vector<BisectionSegment> segments(edges.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k)
      segments[k] = edgeSegment(map, edges[k], rule, blur, blurredSheetDepths);
  });
  Refinement result;
  RayBudget budget;
  CrossingSnap counted = snap;
  counted.snapped = &result.snapped;
  result.crossings =
      bisectSegments(map, segments, rule, blur, oracle, steps, budget, centres, &result.centreDepths, counted);
  if (snap.snapped) *snap.snapped += result.snapped;
  result.raysCast = budget.rays;
  result.msRays = budget.ms;
  return result;
}

}  // namespace shadowvol
