#include "volume/rim_bias.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/triangle_exit.h"

namespace shadowvol::volume {

double rimVertexDepth(const TexelUnprojector& unproject, const Crossing& c, glm::dvec2 at, glm::dvec2 nearEnd,
                      double nearDepth, const SheetDepthRule& rule) {
  const double bias = rule.bias;
  if (!(bias > 0.0) || !c.hasRim()) return c.nearDepth;
  // The triangle's depth where it ends, never past its deepest corner (a crossing a little off
  // its edge, on a triangle nearly edge-on to the light, cannot carry it further).
  const double deepest = std::max({unproject.viewDepth(c.rim[0]), unproject.viewDepth(c.rim[1]),
                                   unproject.viewDepth(c.rim[2])});
  const double rim = std::min(triangleDepthAt(unproject, c.rim, at), deepest);
  if (!std::isfinite(rim)) return c.nearDepth;
  const double plane = triangleDepthAt(unproject, c.rim, nearEnd);
  const double keep =
      std::isfinite(plane) ? std::min(bias, kRimBiasFloor * bias + std::max(0.0, plane - (nearDepth - bias))) : bias;
  // Never nearer the light than the near sample's own surface (d(lo) less the bias): a triangle
  // nearly edge-on to the light, whose plane `at` reaches a little off, cannot pull it further.
  // Behind d(lo) + B where the rim lies deeper (a lit triangle nearly edge-on to the light falls
  // steeply from the last sample to where it ends), but never past the middle between the near
  // and the far sample's depths, which the bisection would have put on the far side.
  const double deeper = std::max(c.nearDepth, std::min(rim + keep, 0.5 * (c.nearDepth + c.farDepth)));
  return std::min(deeper, std::max({rule.nearPlane, c.nearDepth - bias, rim + keep}));
}

bool moveNearVertexToRim(const TexelUnprojector& unproject, Crossing& c, glm::dvec2 at, glm::dvec2 nearEnd,
                         double nearDepth, const SheetDepthRule& rule) {
  const double d = rimVertexDepth(unproject, c, at, nearEnd, nearDepth, rule);
  if (d == c.nearDepth) return false;
  c.nearSample = c.nearDepth, c.nearDepth = d;
  return true;
}

std::size_t lowerPlainRimVertices(const SheetDepths& sheet, const BoundaryEdges& edges,
                                  std::vector<Crossing>& crossings) {
  const SheetDepthRule& rule = sheet.rule();
  if (!(rule.bias > 0.0)) return 0;
  const TexelUnprojector unproject(sheet.map());
  std::atomic<std::size_t> moved{0};
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, edges.edges.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        std::size_t n = 0;
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
          Crossing& c = crossings[k];
          if (!c.hasRim()) continue;
          const BoundaryEdge& e = edges.edges[k];
          const int ni = e.i + (!e.nearAtP && e.axis == 0 ? 1 : 0), nj = e.j + (!e.nearAtP && e.axis == 1 ? 1 : 0);
          n += moveNearVertexToRim(unproject, c, Crossing::texel(e, c.s), glm::dvec2(ni, nj), sheet.at(ni, nj), rule);
        }
        moved += n;
      });
  return moved.load();
}

std::size_t lowerSegmentRimVertices(const SheetDepths& sheet, std::span<const BisectionSegment> segments,
                                    std::vector<Crossing>& crossings) {
  const SheetDepthRule& rule = sheet.rule();
  if (!(rule.bias > 0.0)) return 0;
  const TexelUnprojector unproject(sheet.map());
  std::size_t moved = 0;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    Crossing& c = crossings[k];
    if (!c.hasRim()) continue;
    const BisectionSegment& g = segments[k];
    moved += moveNearVertexToRim(unproject, c, g.nearPoint + c.s * (g.farPoint - g.nearPoint), g.nearPoint,
                                 g.nearDepth, rule);
  }
  return moved;
}

}  // namespace shadowvol::volume
