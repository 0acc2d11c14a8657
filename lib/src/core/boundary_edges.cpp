#include "shadowvol/boundary_edges.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"

namespace shadowvol {

TexelFootprint TexelFootprint::of(const DepthMap& map) {
  // Lateral distance between the rays of two neighbouring texel centres at the map's centre, at
  // two depths; linear in depth for both light types.
  const TexelUnprojector unproject(map);
  const double ci = 0.5 * (map.width - 1), cj = 0.5 * (map.height - 1);
  auto footprint = [&](double d) {
    const glm::dvec3 c = unproject.lightViewPoint(ci, cj, d);
    return std::max(glm::length(unproject.lightViewPoint(ci + 1.0, cj, d) - c),
                    glm::length(unproject.lightViewPoint(ci, cj + 1.0, d) - c));
  };
  const double d0 = map.nearPlane > 0.0 ? map.nearPlane : 0.5 * map.farPlane, d1 = map.farPlane;
  const double f0 = footprint(d0), f1 = footprint(d1);
  TexelFootprint f;
  f.b = (f1 - f0) / (d1 - d0);
  f.a = f0 - f.b * d0;
  return f;
}

bool discontinuous(double uP, double uQ, double gP, double gQ, const TexelFootprint& footprint) {
  const double jump = std::abs(uQ - uP);
  double slope = 0.0;  // the smaller step beyond the ends that exist
  if (gP >= 0.0 && gQ >= 0.0) slope = std::min(gP, gQ);
  else if (gP >= 0.0) slope = gP;
  else if (gQ >= 0.0) slope = gQ;
  return jump > std::max(kJumpFootprints * footprint.at(std::min(uP, uQ)), kJumpSlope * slope);
}

namespace {

// A quad with exactly two boundary sides, both surface edges, whose two sides disagree on which
// of its two components is the near one (the near surface at one crossing is the far one at the
// other: the surfaces cross inside the quad) would get a wall folded onto itself (a bow-tie,
// self-intersecting). Both edges are made continuous instead; that can leave a neighbour in the
// same state, so this repeats until no quad is (serially, in quad order: deterministic).
void keepWallsUnfolded(std::vector<std::vector<BoundaryEdge>>& rows, int w, int h, std::uint8_t* splitBits) {
  const int qw = w - 1, qh = h - 1;
  std::vector<std::vector<std::uint8_t>> alive(rows.size());
  for (std::size_t j = 0; j < rows.size(); ++j) alive[j].assign(rows[j].size(), 1);
  // The live edge from texel (i, j) along axis, or null.
  auto find = [&](int i, int j, int axis) -> BoundaryEdge* {
    if (j < 0 || j >= h) return nullptr;
    auto& row = rows[std::size_t(j)];
    const auto it = std::lower_bound(row.begin(), row.end(), std::pair<int, int>{i, axis},
                                     [](const BoundaryEdge& e, std::pair<int, int> k) {
                                       return e.i != k.first ? e.i < k.first : e.axis < k.second;
                                     });
    if (it == row.end() || it->i != i || it->axis != axis || !alive[std::size_t(j)][std::size_t(it - row.begin())])
      return nullptr;
    return &*it;
  };
  // Quads next to a surface edge: the only ones that can fold.
  std::vector<std::uint64_t> quads;
  for (int j = 0; j < h; ++j)
    for (const BoundaryEdge& e : rows[std::size_t(j)])
      if (e.surface) {
        const int qi[2] = {e.i - (e.axis == 1), e.i}, qj[2] = {e.j - (e.axis == 0), e.j};
        for (int k = 0; k < 2; ++k)
          if (qi[k] >= 0 && qj[k] >= 0 && qi[k] < qw && qj[k] < qh) quads.push_back(std::uint64_t(qj[k]) * qw + qi[k]);
      }
  std::sort(quads.begin(), quads.end());
  quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
  bool any = false;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::uint64_t q : quads) {
      const int qi = int(q % std::uint64_t(qw)), qj = int(q / std::uint64_t(qw));
      // Sides 0..3 (A->B, B->C, C->D, D->A); the first two run from their edge's P end.
      BoundaryEdge* side[4] = {find(qi, qj, 0), find(qi + 1, qj, 1), find(qi, qj + 1, 0), find(qi, qj, 1)};
      int split[4], n = 0;
      for (int k = 0; k < 4; ++k)
        if (side[k]) split[n++] = k;
      if (n != 2 || !side[split[0]]->surface || !side[split[1]]->surface) continue;
      auto nearAtStart = [&](int k) { return k < 2 ? side[k]->nearAtP : !side[k]->nearAtP; };
      if (nearAtStart(split[0]) != nearAtStart(split[1])) continue;  // one component near at both
      for (int k : {split[0], split[1]}) {
        const BoundaryEdge& e = *side[k];
        if (splitBits) splitBits[std::size_t(e.j) * w + e.i] &= std::uint8_t(~(1 << e.axis));
        auto& row = rows[std::size_t(e.j)];
        alive[std::size_t(e.j)][std::size_t(&e - row.data())] = 0;
      }
      changed = any = true;
    }
  }
  if (!any) return;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    std::size_t out = 0;
    for (std::size_t k = 0; k < rows[j].size(); ++k)
      if (alive[j][k]) rows[j][out++] = rows[j][k];
    rows[j].resize(out);
  }
}

}  // namespace

std::size_t BoundaryEdges::find(int i, int j, int axis) const {
  const auto first = edges.begin() + std::ptrdiff_t(rowStart[std::size_t(j)]);
  const auto last = edges.begin() + std::ptrdiff_t(rowStart[std::size_t(j) + 1]);
  const auto it = std::lower_bound(first, last, std::pair<int, int>{i, axis}, [](const BoundaryEdge& e, std::pair<int, int> k) {
    return e.i != k.first ? e.i < k.first : e.axis < k.second;
  });
  return (it != last && it->i == i && it->axis == axis) ? std::size_t(it - edges.begin()) : edges.size();
}

BoundaryEdges findBoundaryEdges(const DepthMap& map, const SheetDepthRule& rule, bool blur,
                                std::span<const double> sheetDepths, std::uint8_t* splitBits) {
  const int w = map.width, h = map.height;
  SV_CHECK_EQ(sheetDepths.size(), std::size_t(w) * std::size_t(h));
  const double farPlane = rule.farPlane;
  const TexelFootprint footprint = TexelFootprint::of(map);
  // The depth without the blur's averaging (the rule's unblurred sample; the ring is far).
  auto u = [&](int i, int j) {
    if (SheetDepthRule::ring(i, j, w, h)) return farPlane;
    return rule.ofSample(map.at(i, j), blur);
  };
  auto isFar = [&](int i, int j) { return sheetDepths[map.index(i, j)] == farPlane; };
  // The step beyond texel (i, j) away from its neighbour, along (di, dj); -1 when there is none.
  auto step = [&](int i, int j, int di, int dj, double ui) {
    const int ni = i + di, nj = j + dj;
    if (ni < 0 || nj < 0 || ni >= w || nj >= h) return -1.0;
    const double un = u(ni, nj);
    return (un == farPlane || isFar(ni, nj)) ? -1.0 : std::abs(ui - un);
  };
  std::vector<std::vector<BoundaryEdge>> rows(h);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& range) {
    for (int j = range.begin(); j != range.end(); ++j)
      for (int i = 0; i < w; ++i) {
        std::uint8_t bits = 0;
        for (int axis = 0; axis < 2; ++axis) {
          const int di = axis == 0 ? 1 : 0, dj = 1 - di;
          const int qi = i + di, qj = j + dj;
          if (qi >= w || qj >= h) continue;
          const bool farP = isFar(i, j), farQ = isFar(qi, qj);
          if (farP && farQ) continue;
          BoundaryEdge e{i, j, std::uint8_t(axis), !farP, false};
          if (farP == farQ) {  // both hit: a surface edge?
            const double uP = u(i, j), uQ = u(qi, qj);
            if (uP == farPlane || uQ == farPlane) continue;
            if (!discontinuous(uP, uQ, step(i, j, -di, -dj, uP), step(qi, qj, di, dj, uQ), footprint)) continue;
            e.surface = true;
            e.nearAtP = uP < uQ;
          }
          rows[j].push_back(e);
          bits |= std::uint8_t(1 << axis);
        }
        if (splitBits) splitBits[map.index(i, j)] = bits;
      }
  });
  keepWallsUnfolded(rows, w, h, splitBits);
  BoundaryEdges result;
  result.rowStart.assign(std::size_t(h) + 1, 0);
  for (int j = 0; j < h; ++j) result.rowStart[j + 1] = result.rowStart[j] + rows[j].size();
  result.edges.reserve(result.rowStart[h]);
  for (auto& row : rows) result.edges.insert(result.edges.end(), row.begin(), row.end());
  return result;
}

}  // namespace shadowvol
