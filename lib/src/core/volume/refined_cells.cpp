#include "volume/refined_cells.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/triangulation.h"
#include "volume/cell_triangulator.h"
#include "volume/quad_codes.h"

namespace shadowvol::volume {

RefinedQuads findRefinedQuads(const BoundaryEdges& boundary, int width, int height,
                              std::span<const std::uint32_t> hidden) {
  const int qw = width - 1, qh = height - 1;
  std::vector<std::pair<std::uint32_t, std::uint8_t>> touched;
  touched.reserve(2 * boundary.edges.size() + hidden.size());
  for (std::uint32_t q : hidden) touched.push_back({q, std::uint8_t(0)});
  auto touch = [&](int qi, int qj, int side) {
    if (qi >= 0 && qj >= 0 && qi < qw && qj < qh) touched.push_back({std::uint32_t(qj) * std::uint32_t(qw) + qi, std::uint8_t(1 << side)});
  };
  for (const BoundaryEdge& e : boundary.edges) {
    if (e.axis == 0) {
      touch(e.i, e.j - 1, 2);
      touch(e.i, e.j, 0);
    } else {
      touch(e.i - 1, e.j, 1);
      touch(e.i, e.j, 3);
    }
  }
  std::sort(touched.begin(), touched.end());
  RefinedQuads result;
  for (const auto& [quad, bit] : touched) {
    if (result.quads.empty() || result.quads.back() != quad) {
      result.quads.push_back(quad);
      result.sides.push_back(0);
    }
    result.sides.back() |= bit;
  }
  for (std::size_t q = 0; q < result.quads.size(); ++q) {
    const int n = std::popcount(unsigned(result.sides[q]));
    if (n >= 3)
      result.centres.push_back({double(result.quads[q] % std::uint32_t(qw)) + 0.5, double(result.quads[q] / std::uint32_t(qw)) + 0.5});
  }
  return result;
}

namespace {

// The boundary sides of a quad, in order; returns their number.
int splitSides(std::uint8_t sides, int* split) {
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (sides >> k & 1) split[n++] = k;
  return n;
}

}  // namespace

void assembleCell(int qi, int qj, std::uint8_t sides, const SheetDepths& sheet, const BoundaryEdges& boundary,
                  const Refinement& refinement, const TexelUnprojector& unproject, const std::uint32_t* const* idx,
                  std::uint32_t crossingBase, RefinedCell& cell) {
  const int w = sheet.map().width;
  const double farPlane = sheet.rule().farPlane;
  for (int k = 0; k < 4; ++k) {
    const int i = qi + kCornerDi[k], j = qj + kCornerDj[k];
    CellVertex& c = cell.corners[k];
    c.depth = sheet.at(i, j);
    c.far = c.depth == farPlane;
    c.id = (idx && !c.far) ? idx[kCornerDj[k]][i] : kNone;
    SV_CHECK(!idx || c.far == (c.id == kNone));  // refinement: the used texels are the non-far ones
    c.texel = {double(i), double(j)};
    c.lv = unproject.lightViewPoint(i, j, c.depth);
    c.cap = {std::uint32_t(j * w + i), CapPoint::Kind::Texel};
    if (!(sides >> k & 1)) continue;
    const SideEdge s = sideEdge(qi, qj, k);
    const std::size_t e = boundary.find(s.i, s.j, s.axis);
    SV_CHECK_LT(e, boundary.edges.size());
    const BoundaryEdge& edge = boundary.edges[e];
    const Crossing& x = refinement.crossings[e];
    CellVertex nearV, farV;
    nearV.texel = farV.texel = Crossing::texel(edge, x.s);
    nearV.depth = x.nearDepth, farV.depth = x.farDepth;
    nearV.id = nearVertex(crossingBase, e), farV.id = farVertex(crossingBase, e);
    farV.far = !edge.surface;
    nearV.lv = unproject.lightViewPoint(nearV.texel.x, nearV.texel.y, nearV.depth);
    farV.lv = unproject.lightViewPoint(farV.texel.x, farV.texel.y, farV.depth);
    nearV.cap = farV.cap = {std::uint32_t(e), CapPoint::Kind::Edge};
    // Corner k's side of the edge: its P end when the side runs forward.
    const bool cornerIsNear = s.forward == edge.nearAtP;
    cell.a[k] = cornerIsNear ? nearV : farV;
    cell.b[k] = cornerIsNear ? farV : nearV;
  }
}


bool ChordPoints::bends(std::size_t k, glm::dvec2 x, glm::dvec2 y) const {
  if (!(bendFloor > 0.0)) return true;
  const glm::dvec2 d = y - x;
  const double length = std::hypot(d.x, d.y);
  if (length == 0.0) return false;
  const double off = std::abs(cross2(d, texel(k) - x)) / length;
  const BisectionSegment& g = segments[k];
  return off > bendFloor * glm::length(g.farPoint - g.nearPoint) * std::ldexp(1.0, -(steps + 1));
}

ChordPoints planChordPoints(const RefinedQuads& quads, const SheetDepths& sheet, const BoundaryEdges& boundary,
                            const Refinement& refinement) {
  const int qw = sheet.map().width - 1;
  const double farPlane = sheet.rule().farPlane;
  const TexelUnprojector unproject(sheet.map());
  ChordPoints out;
  out.ofQuad.assign(quads.quads.size(), ChordPoints::kNone);
  for (std::size_t q = 0; q < quads.quads.size(); ++q) {
    int split[4];
    if (splitSides(quads.sides[q], split) != 2) continue;
    const int qi = int(quads.quads[q] % std::uint32_t(qw)), qj = int(quads.quads[q] / std::uint32_t(qw));
    RefinedCell cell;
    assembleCell(qi, qj, quads.sides[q], sheet, boundary, refinement, unproject, nullptr, 0, cell);
    const int s0 = split[0], s1 = split[1];
    const glm::dvec2 x = cell.a[s0].texel, y = cell.a[s1].texel, mid = 0.5 * (x + y);
    const glm::dvec2 normal(-(y - x).y, (y - x).x);
    // The perpendicular bisector through the quad: t in [lo, hi] (mid is inside, so lo < 0 < hi).
    double lo = -1e300, hi = 1e300;
    const glm::dvec2 box0(qi, qj), box1(qi + 1, qj + 1);
    for (int k = 0; k < 2; ++k) {
      if (normal[k] == 0.0) continue;
      const double t0 = (box0[k] - mid[k]) / normal[k], t1 = (box1[k] - mid[k]) / normal[k];
      lo = std::max(lo, std::min(t0, t1));
      hi = std::min(hi, std::max(t0, t1));
    }
    const glm::dvec2 endLo = mid + lo * normal, endHi = mid + hi * normal;
    // The near component's side of the chord: where its first corner lies.
    const bool c0Near = cell.b[s0].depth < cell.a[s0].depth;
    const glm::dvec2 nearCorner = cell.corners[((c0Near ? s0 : s1) + 1) % 4].texel;
    const bool hiNear = (cross2(y - x, nearCorner - x) > 0.0) == (cross2(y - x, endHi - x) > 0.0);
    BisectionSegment g;
    g.nearPoint = hiNear ? endHi : endLo;
    g.farPoint = hiNear ? endLo : endHi;
    const CellVertex &xNear = c0Near ? cell.b[s0] : cell.a[s0], &xFar = c0Near ? cell.a[s0] : cell.b[s0];
    const CellVertex &yNear = c0Near ? cell.a[s1] : cell.b[s1], &yFar = c0Near ? cell.b[s1] : cell.a[s1];
    g.surface = !xFar.far;  // both sides are of one kind: a far component borders far edges only
    g.nearDepth = g.nearFallback = 0.5 * (xNear.depth + yNear.depth);
    g.farDepth = g.surface ? 0.5 * (xFar.depth + yFar.depth) : farPlane;
    out.ofQuad[q] = out.segments.size();
    out.segments.push_back(g);
  }
  return out;
}

RefinedCells triangulateRefinedCells(const RefinedQuads& quads, const TexelUse& use, const SheetVertices& vertices,
                                     const SheetDepths& sheet, const BoundaryEdges& boundary,
                                     const Refinement& refinement, const ChordPoints* chords, bool perfect, bool exact,
                                     std::uint32_t crossingBase, std::uint32_t chordBase) {
  const DepthMap& map = sheet.map();
  const int w = map.width, qw = w - 1, qh = map.height - 1;
  const double farPlane = sheet.rule().farPlane;
  const TexelUnprojector unproject(map);
  // Ambiguous quads' centre depths, in quad order.
  std::vector<std::size_t> centreOf(quads.quads.size(), 0);
  for (std::size_t q = 0, c = 0; q < quads.quads.size(); ++q)
    if (std::popcount(unsigned(quads.sides[q])) >= 3) centreOf[q] = c++;

  // Quads per quad row.
  std::vector<std::size_t> rowStart(std::size_t(qh) + 1, 0);
  for (std::uint32_t quad : quads.quads) ++rowStart[quad / std::uint32_t(qw) + 1];
  for (int qj = 0; qj < qh; ++qj) rowStart[qj + 1] += rowStart[qj];
  struct RowOut {
    std::vector<Tri> triangles;
    std::vector<CapEdge> capEdges;
    std::vector<std::array<CapPoint, 3>> footprint;
    std::vector<std::uint32_t> perQuad;  // kept triangles of each of the row's quads
    std::size_t bends = 0;
  };
  std::vector<RowOut> rows(qh);
  tbb::parallel_for(tbb::blocked_range<int>(0, qh, 4), [&](const tbb::blocked_range<int>& range) {
    std::vector<std::uint8_t> used(w);
    std::vector<std::uint32_t> idx[2] = {std::vector<std::uint32_t>(w, kNone), std::vector<std::uint32_t>(w, kNone)};
    std::vector<LocalTri> tris;
    for (int qj = range.begin(); qj != range.end(); ++qj) {
      if (rowStart[qj] == rowStart[qj + 1]) continue;
      for (int r = 0; r < 2; ++r) {  // vertex indices of texel rows qj and qj + 1 (read for used texels only)
        const auto [b, e] = use.row(qj + r, used.data());
        numberRow(used.data() + b, idx[r].data() + b, e - b, std::uint32_t(vertices.rowVerts[qj + r]), kNone);
      }
      const std::uint32_t* rowsIdx[2] = {idx[0].data(), idx[1].data()};
      RowOut& out = rows[qj];
      for (std::size_t q = rowStart[qj]; q < rowStart[qj + 1]; ++q) {
        const int qi = int(quads.quads[q] % std::uint32_t(qw));
        RefinedCell cell;
        assembleCell(qi, qj, quads.sides[q], sheet, boundary, refinement, unproject, rowsIdx, crossingBase, cell);
        const bool ambiguous = std::popcount(unsigned(quads.sides[q])) >= 3;
        const double centre = ambiguous ? refinement.centreDepths[centreOf[q]] : farPlane;
        CellVertex mNear, mFar;  // the chord point's vertices, if any
        std::size_t k = chords ? chords->ofQuad[q] : ChordPoints::kNone;
        if (k != ChordPoints::kNone) {
          int split[4];
          splitSides(quads.sides[q], split);
          if (!chords->bends(k, cell.a[split[0]].texel, cell.a[split[1]].texel)) k = ChordPoints::kNone;  // straight
        }
        if (k != ChordPoints::kNone) {
          const Crossing& x = chords->crossings[k];
          mNear.texel = mFar.texel = chords->texel(k);
          mNear.depth = x.nearDepth, mFar.depth = x.farDepth;
          mNear.id = nearVertex(chordBase, k), mFar.id = farVertex(chordBase, k);
          mFar.far = !chords->segments[k].surface;
          mNear.lv = unproject.lightViewPoint(mNear.texel.x, mNear.texel.y, mNear.depth);
          mFar.lv = unproject.lightViewPoint(mFar.texel.x, mFar.texel.y, mFar.depth);
          mNear.cap = mFar.cap = {std::uint32_t(k), CapPoint::Kind::Chord};
        }
        out.bends += k != ChordPoints::kNone;
        tris.clear();
        CellTriangulator(perfect, tris)
            .run(cell.corners, cell.a, cell.b, quads.sides[q], centre, farPlane, k != ChordPoints::kNone ? &mNear : nullptr,
                 k != ChordPoints::kNone ? &mFar : nullptr);
        const std::size_t before = out.triangles.size();
        keepCellTriangles(tris, exact, out.triangles, out.capEdges, &out.footprint);
        out.perQuad.push_back(std::uint32_t(out.triangles.size() - before));
      }
    }
  });
  RefinedCells result;
  result.firstTriangle.reserve(quads.quads.size() + 1);
  result.firstTriangle.push_back(0);
  for (RowOut& row : rows) {
    for (std::uint32_t n : row.perQuad) result.firstTriangle.push_back(result.firstTriangle.back() + n);
    result.bends += row.bends;
    result.triangles.insert(result.triangles.end(), row.triangles.begin(), row.triangles.end());
    result.capEdges.insert(result.capEdges.end(), row.capEdges.begin(), row.capEdges.end());
    result.footprint.insert(result.footprint.end(), row.footprint.begin(), row.footprint.end());
  }
  return result;
}

void emitCrossingVertices(const DepthMap& map, const BoundaryEdges& boundary, const Refinement& refinement,
                          const ChordPoints* chords, std::uint32_t crossingBase, std::uint32_t chordBase,
                          VolumeMesh& mesh) {
  const TexelUnprojector unproject(map);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, boundary.edges.size(), 512),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t e = r.begin(); e != r.end(); ++e) {
                        const Crossing& x = refinement.crossings[e];
                        const glm::dvec2 t = Crossing::texel(boundary.edges[e], x.s);
                        mesh.positions[nearVertex(crossingBase, e)] = unproject.worldPoint(t.x, t.y, x.nearDepth);
                        mesh.positions[farVertex(crossingBase, e)] = unproject.worldPoint(t.x, t.y, x.farDepth);
                      }
                    });
  if (!chords) return;
  for (std::size_t k = 0; k < chords->crossings.size(); ++k) {
    const glm::dvec2 t = chords->texel(k);
    mesh.positions[nearVertex(chordBase, k)] = unproject.worldPoint(t.x, t.y, chords->crossings[k].nearDepth);
    mesh.positions[farVertex(chordBase, k)] = unproject.worldPoint(t.x, t.y, chords->crossings[k].farDepth);
  }
}

}  // namespace shadowvol::volume
