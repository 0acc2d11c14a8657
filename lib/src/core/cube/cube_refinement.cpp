#include "cube/cube_refinement.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <set>

#include "shadowvol/boundary_edges.h"
#include "shadowvol/check.h"
#include "shadowvol/error.h"

namespace shadowvol::cube {

void CubeRefinement::add(const BoundaryEdge& e) {
  const auto [it, inserted] = index_.emplace(edgeKey(e.nearTexel, e.farTexel), std::uint32_t(edges.size()));
  SV_CHECK(inserted);
  edges.push_back(e);
  touched[e.nearTexel] = touched[e.farTexel] = 1;
}

void CubeRefinement::keepOnly(const std::vector<std::uint8_t>& keep) {
  std::vector<BoundaryEdge> all = std::move(edges);
  edges.clear();
  index_.clear();
  std::fill(touched.begin(), touched.end(), std::uint8_t(0));
  for (std::size_t e = 0; e < all.size(); ++e)
    if (keep[e]) add(all[e]);
}

void sampleDirections(const CubeDepthMap& cube, std::span<const glm::dvec3> directions, const DepthOracle& oracle,
                      std::span<float> depth, RayBudget& budget) {
  SV_CHECK_EQ(directions.size(), depth.size());
  const int n = cube.size();
  std::array<std::vector<std::size_t>, kCubeFaces> which;
  std::array<std::vector<glm::dvec2>, kCubeFaces> ndc;
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const CubeLookup l = cubeLookup(directions[k], n);
    which[l.face].push_back(k);
    ndc[l.face].push_back(cube.faces[l.face].texelNdc(l.texel.x, l.texel.y));
  }
  std::vector<float> out;
  for (int f = 0; f < kCubeFaces; ++f) {
    if (which[f].empty()) continue;
    out.assign(which[f].size(), DepthMap::kNoHit);
    const auto t0 = std::chrono::steady_clock::now();
    oracle(cube.faces[f], ndc[f], out);
    budget.ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    budget.rays += out.size();
    for (std::size_t k = 0; k < out.size(); ++k) depth[which[f][k]] = out[k];
  }
}

namespace {

// Each face's boundary edges by one map's rule without the ring.
void addFaceEdges(const CubeDepthMap& cube, const SheetDepthRule& rule, bool blur, std::span<const double> finalDepths,
                  CubeRefinement& r) {
  const int n = cube.size();
  const std::size_t nn = std::size_t(n) * std::size_t(n);
  for (int f = 0; f < kCubeFaces; ++f) {
    const std::span<const double> faceDepths = blur ? finalDepths.subspan(f * nn, nn) : std::span<const double>();
    const BoundaryEdges found = findBoundaryEdges(cube.faces[f], rule, blur, faceDepths, nullptr, false);
    for (const shadowvol::BoundaryEdge& e : found.edges) {
      const std::uint32_t p = texelId(n, f, e.i, e.j);
      const std::uint32_t q = texelId(n, f, e.i + (e.axis == 0), e.j + (e.axis == 1));
      r.add({e.nearAtP ? p : q, e.nearAtP ? q : p, e.surface, true});
    }
  }
}

// The edges between two faces: the seam cells' sides whose ends lie on different faces, by the
// rule of the header comment.
void addSeamEdges(const CubeDepthMap& cube, const Grid& cells, const SheetDepthRule& rule, bool blur,
                  std::span<const double> finalDepths, CubeRefinement& r) {
  const int n = cube.size();
  const std::uint32_t nn = std::uint32_t(n) * std::uint32_t(n);
  const double farPlane = rule.farPlane;
  const TexelFootprint footprint = TexelFootprint::of(cube.faces[0]);
  auto stored = [&](std::uint32_t id) { return double(cube.faces[id / nn].depth[id % nn]); };
  std::set<std::uint64_t> seen;
  for (std::size_t c = innerQuadCount(n); c < cells.size(); ++c) {
    const Cell cell = cells[c];
    const int count = cell.cornerCount();
    for (int k = 0; k < count; ++k) {
      const std::uint32_t p = cell.corner(k), q = cell.corner((k + 1) % count);
      if (p / nn == q / nn) continue;  // in one face: its own finder's
      if (!seen.insert(edgeKey(p, q)).second) continue;
      const bool farP = finalDepths[p] == farPlane, farQ = finalDepths[q] == farPlane;
      if (farP && farQ) continue;
      if (farP != farQ) {
        r.add({farP ? q : p, farP ? p : q, false, false});
        continue;
      }
      const double uP = rule.ofSample(stored(p), blur), uQ = rule.ofSample(stored(q), blur);
      if (uP == farPlane || uQ == farPlane || !discontinuous(uP, uQ, -1.0, -1.0, footprint)) continue;
      r.add({uP < uQ ? p : q, uP < uQ ? q : p, true, false});
    }
  }
}

// The two cells on either side of a grid edge, found without looking at every cell: inner quads
// from the texel coordinates, seam cells (12 (N - 1) quads and 8 triangles) from their sides.
class EdgeCells {
 public:
  explicit EdgeCells(const Grid& cells, int n) : n_(n) {
    for (std::size_t c = innerQuadCount(n); c < cells.size(); ++c) {
      const Cell cell = cells[c];
      for (int k = 0; k < cell.cornerCount(); ++k)
        seamSides_.push_back({edgeKey(cell.corner(k), cell.corner((k + 1) % cell.cornerCount())), std::uint32_t(c)});
    }
    std::sort(seamSides_.begin(), seamSides_.end());
  }
  /// Appends the cells with the edge between texels a and b as a side (two: the grid is closed).
  void append(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& out) const {
    const std::size_t before = out.size();
    const std::uint32_t nn = std::uint32_t(n_) * std::uint32_t(n_), q = std::uint32_t(n_ - 1);
    if (a / nn == b / nn) {  // inner quads of the face on either side, where they exist
      const std::uint32_t f = a / nn, lo = std::min(a, b) % nn, hi = std::max(a, b) % nn;
      const int i = int(lo % std::uint32_t(n_)), j = int(lo / std::uint32_t(n_));
      const bool alongI = hi == lo + 1;  // else along j
      const int qi[2] = {alongI ? i : i - 1, i}, qj[2] = {alongI ? j - 1 : j, j};
      for (int k = 0; k < 2; ++k)
        if (qi[k] >= 0 && qj[k] >= 0 && qi[k] < int(q) && qj[k] < int(q))
          out.push_back(std::uint32_t(innerQuadIndex(n_, int(f), qi[k], qj[k])));
    }
    const auto [first, last] = std::equal_range(seamSides_.begin(), seamSides_.end(), std::pair{edgeKey(a, b), 0u},
                                                [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto it = first; it != last; ++it) out.push_back(it->second);
    SV_CHECK_EQ(out.size() - before, 2u);
  }

 private:
  int n_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> seamSides_;
};

// The cells with edge e (of `edges`, where `select` holds) as a side, sorted, once each.
template <class Select>
std::vector<std::uint32_t> cellsOfEdges(const EdgeCells& lookup, const std::vector<BoundaryEdge>& edges,
                                        const Select& select) {
  std::vector<std::uint32_t> out;
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (select(e)) lookup.append(edges[e].nearTexel, edges[e].farTexel, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The unfolding rounds of the header comment, on the cells that have a surface side.
void unfoldWalls(const Grid& cells, const EdgeCells& lookup, CubeRefinement& r) {
  const std::vector<std::uint32_t> candidates =
      cellsOfEdges(lookup, r.edges, [&](std::size_t e) { return r.edges[e].surface; });
  std::vector<std::uint8_t> keep(r.edges.size(), 1);
  bool any = false;
  for (int round = 0; round < kMaxUnfoldRounds; ++round) {
    std::vector<std::uint32_t> dying;
    for (std::uint32_t c : candidates) {
      const Cell cell = cells[c];
      const int count = cell.cornerCount();
      std::uint32_t side[4];
      int split[4], n = 0;
      for (int k = 0; k < count; ++k) {
        side[k] = r.find(cell.corner(k), cell.corner((k + 1) % count));
        if (side[k] != CubeRefinement::kNoEdge && keep[side[k]]) split[n++] = k;
      }
      if (n != 2 || !r.edges[side[split[0]]].surface || !r.edges[side[split[1]]].surface) continue;
      auto nearAtStart = [&](int k) { return r.edges[side[k]].nearTexel == cell.corner(k); };
      if (nearAtStart(split[0]) != nearAtStart(split[1])) continue;  // one component near at both
      dying.push_back(side[split[0]]);
      dying.push_back(side[split[1]]);
    }
    if (dying.empty()) break;
    for (std::uint32_t e : dying) keep[e] = 0;
    any = true;
  }
  if (any) r.keepOnly(keep);
}

}  // namespace

CubeRefinement refineCube(const CubeDepthMap& cube, const Grid& cells, const SheetDepthRule& rule, bool blur,
                          std::span<const double> finalDepths, const DepthOracle& oracle, int steps) {
  SV_CHECK(bool(oracle));
  const int n = cube.size();
  const std::uint32_t nn = std::uint32_t(n) * std::uint32_t(n);
  const double farPlane = rule.farPlane;
  CubeRefinement r;
  r.touched.assign(finalDepths.size(), 0);
  addFaceEdges(cube, rule, blur, finalDepths, r);
  addSeamEdges(cube, cells, rule, blur, finalDepths, r);
  const EdgeCells lookup(cells, n);
  unfoldWalls(cells, lookup, r);
  r.cells = cellsOfEdges(lookup, r.edges, [](std::size_t) { return true; });
  // Point ids: texels, then two per crossing; the volume's vertices at most two per point.
  if (2 * (std::uint64_t(finalDepths.size()) + 2 * std::uint64_t(r.edges.size())) >= std::uint64_t(UINT32_MAX))
    throw InputError("volume options", "refine steps", std::to_string(steps),
                     "the refined cube volume of " + std::to_string(n) + " texels a side with " +
                         std::to_string(r.edges.size()) + " boundary edges would need more vertices than 32-bit "
                         "indices address: use a smaller cube map");

  // The segments, as edgeSegment's of one map: the ends' depths without the blur's averaging, the
  // near end's final depth standing in where the blur offset puts its sample on the far plane.
  auto stored = [&](std::uint32_t id) { return double(cube.faces[id / nn].depth[id % nn]); };
  const std::size_t m = r.edges.size();
  std::vector<BisectionSegment> segments(m);
  std::vector<glm::dvec3> dNear(m), dFar(m);
  for (std::size_t e = 0; e < m; ++e) {
    const BoundaryEdge& edge = r.edges[e];
    BisectionSegment& g = segments[e];
    g.surface = edge.surface;
    g.nearDepth = rule.ofSample(stored(edge.nearTexel), blur);
    g.farDepth = edge.surface ? rule.ofSample(stored(edge.farTexel), blur) : farPlane;
    if (g.nearDepth == farPlane) SV_CHECK(blur);
    g.nearFallback = g.nearDepth != farPlane ? g.nearDepth : finalDepths[edge.nearTexel];
    dNear[e] = texelDirection(n, edge.nearTexel);
    dFar[e] = texelDirection(n, edge.farTexel);
  }
  std::vector<glm::dvec3> rays(m);
  auto sample = [&](int, std::span<const double> s, std::span<float> depth) {
    for (std::size_t e = 0; e < m; ++e) rays[e] = dNear[e] + s[e] * (dFar[e] - dNear[e]);
    sampleDirections(cube, rays, oracle, depth, r.budget);
  };
  r.crossings = bisectWith(segments, rule, blur, steps, sample);
  // Apart from the edges' ends in float (silhouette_refinement.h's floatSafeTexels; every edge,
  // across a face's seam too, joins neighbouring texels about one texel apart).
  const double safe = std::min(0.25, floatSafeTexels(cube.faces[0]));
  for (Crossing& c : r.crossings) c.s = std::clamp(c.s, safe, 1.0 - safe);
  r.directions.resize(m);
  r.faceTexel.assign(m, glm::dvec2(0.0));
  auto texel = [&](std::uint32_t id) {  // texel coordinates on its face
    return glm::dvec2(double(id % nn % std::uint32_t(n)), double(id % nn / std::uint32_t(n)));
  };
  for (std::size_t e = 0; e < m; ++e) {
    const glm::dvec3 ray = dNear[e] + r.crossings[e].s * (dFar[e] - dNear[e]);
    r.directions[e] = ray / cubeDepth(ray);
    if (!r.edges[e].inFace) continue;
    const glm::dvec2 a = texel(r.edges[e].nearTexel), b = texel(r.edges[e].farTexel);
    r.faceTexel[e] = a + r.crossings[e].s * (b - a);
  }
  return r;
}

std::uint8_t boundarySides(const Cell& cell, const CubeRefinement& r) {
  const int count = cell.cornerCount();
  bool any = false;
  for (int k = 0; k < count; ++k) any = any || r.touched[cell.corner(k)];
  if (!any) return 0;
  std::uint8_t sides = 0;
  for (int k = 0; k < count; ++k)
    if (r.find(cell.corner(k), cell.corner((k + 1) % count)) != CubeRefinement::kNoEdge) sides |= std::uint8_t(1 << k);
  return sides;
}

glm::dvec3 cellCentreDirection(const Cell& cell, int n) {
  glm::dvec3 sum(0.0);
  for (int k = 0; k < cell.cornerCount(); ++k) sum += texelDirection(n, cell.corner(k));
  return sum / double(cell.cornerCount());
}

}  // namespace shadowvol::cube
