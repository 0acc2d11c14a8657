#include "shadowvol/boundary_edges.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "volume/sheet_depths.h"

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
// self-intersecting). Both edges are made continuous instead. That can leave a neighbour in the
// same state, so this goes in rounds: each round finds every quad that folds in the edges left by
// the round before and makes all their edges continuous at once (independent of the order of the
// quads, so the GPU's boundary_unfold.comp runs the same rounds in parallel), up to
// kMaxUnfoldRounds rounds.
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
  std::vector<BoundaryEdge*> dying;
  for (int round = 0; round < kMaxUnfoldRounds; ++round) {
    dying.clear();
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
      dying.push_back(side[split[0]]);
      dying.push_back(side[split[1]]);
    }
    if (dying.empty()) break;
    for (BoundaryEdge* e : dying) {
      if (splitBits) splitBits[std::size_t(e->j) * w + e->i] &= std::uint8_t(~(1 << e->axis));
      alive[std::size_t(e->j)][std::size_t(e - rows[std::size_t(e->j)].data())] = 0;
    }
    any = true;
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
                                std::span<const double> blurredSheetDepths, std::uint8_t* splitBits, bool ring) {
  const int w = map.width, h = map.height;
  SV_CHECK(!blur || blurredSheetDepths.size() == std::size_t(w) * std::size_t(h));
  const double farPlane = rule.farPlane;
  const TexelFootprint footprint = TexelFootprint::of(map);
  // Per texel row: u, the depth without the blur's averaging (the ring and invalid depths are the
  // far plane), and whether the final sheet depth is the far plane.
  struct Row {
    std::vector<double> u;
    std::vector<std::uint8_t> far;
    int first = 0, last = -1;  // texels whose final depth is short of the far plane lie in [first, last]
  };
  auto fill = [&](int j, Row& r) {
    r.u.resize(std::size_t(w));
    r.far.resize(std::size_t(w));
    if (j < 0 || j >= h) {
      std::fill(r.u.begin(), r.u.end(), farPlane);
      std::fill(r.far.begin(), r.far.end(), std::uint8_t(1));
      r.first = w, r.last = -1;
      return;
    }
    const float* src = map.depth.data() + std::size_t(j) * w;
    double* u = r.u.data();
    const int b = ring ? 1 : 0, e = ring ? w - 1 : w;  // the texels off the ring
    if (ring && (j == 0 || j == h - 1)) {
      std::fill(r.u.begin(), r.u.end(), farPlane);
    } else if (blur) {
      for (int i = b; i < e; ++i) u[i] = rule.ofSample(src[i], true);
    } else {
      volume::sheetDepthSpan(src, u, b, e, rule);  // the builder's row kernel (vectorised)
    }
    if (ring) u[0] = u[w - 1] = farPlane;
    volume::farFlags(blur ? blurredSheetDepths.data() + std::size_t(j) * w : u, r.far.data(), w, farPlane);
    std::tie(r.first, r.last) = volume::nearSpan(r.far.data(), w);
  };
  std::vector<std::vector<BoundaryEdge>> rows(h);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& range) {
    // Rolling rows j - 1 .. j + 2 (the vertical steps beyond each end of an up edge).
    Row ring[4];
    for (int k = 0; k < 4; ++k) fill(range.begin() - 1 + k, ring[k]);
    for (int j = range.begin(); j != range.end(); ++j) {
      if (j != range.begin()) {
        std::swap(ring[0], ring[1]);
        std::swap(ring[1], ring[2]);
        std::swap(ring[2], ring[3]);
        fill(j + 2, ring[3]);
      }
      const Row &below = ring[0], &row = ring[1], &above = ring[2], &above2 = ring[3];
      if (splitBits) std::memset(splitBits + std::size_t(j) * w, 0, std::size_t(w));
      // The step beyond an end: |u(end) - u(next)|, or -1 when the next texel is far or off the grid.
      auto step = [&](double uEnd, const Row& r, int i) {
        return (i < 0 || i >= w || r.far[std::size_t(i)] || r.u[std::size_t(i)] == farPlane) ? -1.0
                                                                                             : std::abs(uEnd - r.u[std::size_t(i)]);
      };
      auto consider = [&](int i, int axis, bool farP, bool farQ, double uP, double uQ, double gP, double gQ) {
        if (farP && farQ) return;
        BoundaryEdge e{i, j, std::uint8_t(axis), !farP, false};
        if (farP == farQ) {  // both hit: a surface edge?
          if (uP == farPlane || uQ == farPlane) return;
          if (!(std::abs(uQ - uP) > kJumpFootprints * footprint.at(std::min(uP, uQ)))) return;  // quick reject
          if (!discontinuous(uP, uQ, gP, gQ, footprint)) return;
          e.surface = true;
          e.nearAtP = uP < uQ;
        }
        rows[j].push_back(e);
        if (splitBits) splitBits[std::size_t(j) * w + i] |= std::uint8_t(1 << axis);
      };
      // Edges from row j can be boundary edges only next to a non-far texel of rows j, j + 1.
      const int b = std::max(0, std::min(row.first, above.first) - 1), e = std::min(w - 1, std::max(row.last, above.last) + 1);
      for (int i = b; i <= e; ++i) {
        const std::size_t k = std::size_t(i);
        if (i + 1 < w && !(row.far[k] && row.far[k + 1])) {
          const double uP = row.u[k], uQ = row.u[k + 1];
          consider(i, 0, row.far[k], row.far[k + 1], uP, uQ, step(uP, row, i - 1), step(uQ, row, i + 2));
        }
        if (j + 1 < h && !(row.far[k] && above.far[k])) {
          const double uP = row.u[k], uQ = above.u[k];
          consider(i, 1, row.far[k], above.far[k], uP, uQ, step(uP, below, i), step(uQ, above2, i));
        }
      }
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

BoundaryEdges boundaryEdgesFromFlags(int width, int height, std::span<const std::uint32_t> flags,
                                     std::uint8_t* splitBits) {
  SV_CHECK(width > 0 && height > 0);
  SV_CHECK_EQ(flags.size(), std::size_t(width) * std::size_t(height));
  BoundaryEdges result;
  result.rowStart.assign(std::size_t(height) + 1, 0);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t t = std::size_t(j) * std::size_t(width) + std::size_t(i);
      std::uint8_t bits = 0;
      for (int axis = 0; axis < 2; ++axis) {
        const std::uint32_t f = flags[t] >> axis;
        if (!(f & kFlagBoundary)) continue;
        SV_CHECK(axis == 0 ? i + 1 < width : j + 1 < height);  // an edge to a texel off the grid
        result.edges.push_back({i, j, std::uint8_t(axis), bool(f & kFlagNearAtP), bool(f & kFlagSurface)});
        bits |= std::uint8_t(1 << axis);
      }
      if (splitBits) splitBits[t] = bits;
    }
    result.rowStart[std::size_t(j) + 1] = result.edges.size();
  }
  return result;
}

std::size_t differingBoundaryEdges(const BoundaryEdges& a, const BoundaryEdges& b) {
  const auto before = [](const BoundaryEdge& x, const BoundaryEdge& y) {
    return std::tie(x.j, x.i, x.axis) < std::tie(y.j, y.i, y.axis);
  };
  std::size_t differing = 0, k = 0, l = 0;
  while (k < a.edges.size() || l < b.edges.size()) {
    if (l == b.edges.size() || (k < a.edges.size() && before(a.edges[k], b.edges[l]))) {
      ++differing, ++k;
    } else if (k == a.edges.size() || before(b.edges[l], a.edges[k])) {
      ++differing, ++l;
    } else {
      const BoundaryEdge &x = a.edges[k++], &y = b.edges[l++];
      differing += x.nearAtP != y.nearAtP || x.surface != y.surface;
    }
  }
  return differing;
}

}  // namespace shadowvol
