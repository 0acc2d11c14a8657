#include "shadowvol/crossing_snap.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "shadowvol/check.h"

namespace shadowvol {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::vector<Crossing> snapCrossings(const DepthMap& map, std::span<const BisectionSegment> segments,
                                    std::span<const BisectionBracket> brackets, const SheetDepthRule& rule, bool blur,
                                    int steps, const DepthOracle& oracle, const SurfaceEndOracle& ends,
                                    RayBudget& budget, std::size_t& snapped) {
  SV_CHECK_EQ(segments.size(), brackets.size());
  SV_CHECK(bool(oracle) && bool(ends));
  const double farPlane = rule.farPlane, margin = std::ldexp(1.0, -(steps + 2));
  std::vector<BisectionBracket> b(brackets.begin(), brackets.end());
  std::vector<Crossing> out(segments.size());
  std::vector<std::size_t> active;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    out[k] = bracketCrossing(segments[k], b[k], farPlane);
    active.push_back(k);
  }
  auto point = [&](std::size_t k, double s) {
    const BisectionSegment& g = segments[k];
    const glm::dvec2 t = g.nearPoint + s * (g.farPoint - g.nearPoint);
    return map.texelNdc(t.x, t.y);
  };
  // The crossing moved to s where the triangle `rim` ends; its near vertex stays at the bracket's
  // d(lo), its far vertex (surface segments) goes to the probe's surface (`probeDepth` stored;
  // kNoHit: d(hi) stays).
  auto snap = [&](std::size_t k, double s, float probeDepth, const std::array<glm::dvec3, 3>& rim) {
    Crossing& c = out[k];
    c.s = std::clamp(s, margin, 1.0 - margin);
    c.rim = rim;
    const double beyond = rule.ofSample(probeDepth, blur);
    if (segments[k].surface && beyond != farPlane && beyond > c.nearDepth) c.farDepth = beyond;
    ++snapped;
  };
  std::vector<glm::dvec2> from, to, probe;
  std::vector<double> t, sExit, sProbe;
  std::vector<std::array<glm::dvec3, 3>> triangle;
  const std::array<glm::dvec3, 3> kNoTriangle = Crossing().rim;  // NaN corners
  std::vector<float> probeDepth;
  std::vector<std::size_t> next, probing;
  for (int round = 0; round < kSnapRounds && !active.empty(); ++round) {
    // Where each active segment's triangle at lo ends on the way to hi.
    from.resize(active.size()), to.resize(active.size());
    for (std::size_t q = 0; q < active.size(); ++q) from[q] = point(active[q], b[active[q]].lo), to[q] = point(active[q], b[active[q]].hi);
    t.assign(active.size(), 0.0);
    triangle.assign(active.size(), kNoTriangle);
    auto t0 = std::chrono::steady_clock::now();
    ends(map, from, to, t, triangle);
    budget.ms += msSince(t0);
    budget.rays += active.size();
    // A probe just beyond each end that lies inside its bracket; an end at hi needs none (hi is
    // off the near side already).
    probing.clear(), probe.clear(), sExit.clear(), sProbe.clear();
    for (std::size_t q = 0; q < active.size(); ++q) {
      const std::size_t k = active[q];
      // Past hi by more than rounding: the capture at hi records a nearer surface; keep the middle.
      if (!(t[q] >= 0.0 && t[q] <= 1.0 + kSnapEndSlack)) continue;
      const BisectionBracket& br = b[k];
      const double se = std::min(br.lo + t[q] * (br.hi - br.lo), br.hi);
      if (se == br.hi) {
        snap(k, se, DepthMap::kNoHit, triangle[q]);
        continue;
      }
      const double length = glm::length(segments[k].farPoint - segments[k].nearPoint);
      const double sp = se + std::min(kSnapProbeTexels / length, 0.5 * (br.hi - se));
      if (!(sp > se && sp < br.hi)) continue;
      probing.push_back(q), sExit.push_back(se), sProbe.push_back(sp), probe.push_back(point(k, sp));
    }
    if (probing.empty()) break;
    probeDepth.assign(probing.size(), DepthMap::kNoHit);
    t0 = std::chrono::steady_clock::now();
    oracle(map, probe, probeDepth);
    budget.ms += msSince(t0);
    budget.rays += probing.size();
    next.clear();
    for (std::size_t p = 0; p < probing.size(); ++p) {
      const std::size_t q = probing[p], k = active[q];
      const BisectionSegment& g = segments[k];
      BisectionBracket& br = b[k];
      const double d = rule.ofSample(probeDepth[p], blur);
      const bool hit = d != farPlane;
      if (hit && (!g.surface || d < 0.5 * (br.dLo + br.dHi))) {  // the surface goes on: walk on from the probe
        br.lo = sProbe[p], br.dLo = d;
        out[k] = bracketCrossing(g, br, farPlane);
        // Its middle, margin from the ends as a snapped one (the bracket can shrink onto hi: a probe's
        // finding, a degenerate wall on the GPU, which does the same).
        out[k].s = std::clamp(out[k].s, margin, 1.0 - margin);
        next.push_back(k);
        continue;
      }
      snap(k, sExit[p], probeDepth[p], triangle[q]);
    }
    active.swap(next);
  }
  return out;
}

}  // namespace shadowvol
