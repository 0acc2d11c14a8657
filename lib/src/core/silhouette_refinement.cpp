#include "shadowvol/silhouette_refinement.h"

#include <chrono>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"

namespace shadowvol {

glm::dvec2 Crossing::texel(const BoundaryEdge& e, double s) {
  // s runs from the near end; the edge runs from P = (i, j) along its axis.
  const double t = e.nearAtP ? s : 1.0 - s;
  return {e.i + (e.axis == 0 ? t : 0.0), e.j + (e.axis == 1 ? t : 0.0)};
}

Refinement refineBoundaryEdges(const DepthMap& map, const BoundaryEdges& boundary, const SheetDepthRule& rule, bool blur,
                               std::span<const double> blurredSheetDepths, const DepthOracle& oracle, int steps,
                               std::span<const glm::dvec2> centres) {
  SV_CHECK_GE(steps, 1);
  SV_CHECK(bool(oracle));
  const std::vector<BoundaryEdge>& edges = boundary.edges;
  const std::size_t n = edges.size();
  const double farPlane = rule.farPlane;
  Refinement result;
  result.crossings.resize(n);
  result.centreDepths.resize(centres.size());
  // Per edge: the bracket [lo, hi] of the parameter from the near end, and its ends' depths.
  struct Bracket {
    double lo = 0.0, hi = 1.0, dLo = 0.0, dHi = 0.0;
  };
  std::vector<Bracket> brackets(n);
  auto nearEnd = [](const BoundaryEdge& e) {
    return e.nearAtP ? glm::ivec2(e.i, e.j) : glm::ivec2(e.i + (e.axis == 0), e.j + (e.axis == 1));
  };
  auto farEnd = [](const BoundaryEdge& e) {
    return e.nearAtP ? glm::ivec2(e.i + (e.axis == 0), e.j + (e.axis == 1)) : glm::ivec2(e.i, e.j);
  };
  auto sample = [&](int i, int j) {
    if (SheetDepthRule::ring(i, j, map.width, map.height)) return farPlane;
    return rule.ofSample(map.at(i, j), blur);
  };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const glm::ivec2 a = nearEnd(edges[k]), b = farEnd(edges[k]);
      brackets[k].dLo = sample(a.x, a.y);
      brackets[k].dHi = edges[k].surface ? sample(b.x, b.y) : farPlane;
    }
  });

  std::vector<glm::dvec2> ndc;
  std::vector<float> depth;
  auto toNdc = [&](const glm::dvec2& texel) { return map.texelNdc(texel.x, texel.y); };
  auto ask = [&] {
    const auto t0 = std::chrono::steady_clock::now();
    oracle(map, ndc, depth);
    result.msRays += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    result.raysCast += ndc.size();
  };
  for (int step = 0; step < steps; ++step) {
    const std::size_t extra = step == 0 ? centres.size() : 0;
    ndc.resize(n + extra);
    depth.assign(n + extra, DepthMap::kNoHit);
    for (std::size_t k = 0; k < n; ++k)
      ndc[k] = toNdc(Crossing::texel(edges[k], 0.5 * (brackets[k].lo + brackets[k].hi)));
    for (std::size_t c = 0; c < extra; ++c) ndc[n + c] = toNdc(centres[c]);
    ask();
    for (std::size_t k = 0; k < n; ++k) {
      Bracket& b = brackets[k];
      const double m = 0.5 * (b.lo + b.hi);
      const double d = rule.ofSample(depth[k], blur);
      const bool hit = d != farPlane;
      const bool nearSide = hit && (!edges[k].surface || d < 0.5 * (b.dLo + b.dHi));
      if (nearSide) b.lo = m, b.dLo = d;
      else {
        b.hi = m;
        if (hit && edges[k].surface) b.dHi = d;
      }
    }
    for (std::size_t c = 0; c < extra; ++c) result.centreDepths[c] = rule.ofSample(depth[n + c], blur);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const Bracket& b = brackets[k];
      Crossing& c = result.crossings[k];
      c.s = 0.5 * (b.lo + b.hi);
      const glm::ivec2 a = nearEnd(edges[k]);
      // Never on the far plane: the near end's final sheet depth (short of it) stands in. Without
      // blur the unblurred depth is the final one, so this happens only with blur.
      if (b.dLo == farPlane) SV_CHECK(blur);
      c.nearDepth = b.dLo != farPlane ? b.dLo : blurredSheetDepths[map.index(a.x, a.y)];
      c.farDepth = edges[k].surface ? b.dHi : farPlane;
      // Bisection keeps d(lo) < d(hi): a surface edge starts with u(near) < u(far), both short of the
      // far plane, and each step moves one end strictly between them.
      SV_CHECK_LT(c.nearDepth, c.farDepth);
    }
  });
  return result;
}

}  // namespace shadowvol
