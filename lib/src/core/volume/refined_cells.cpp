#include "volume/refined_cells.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadowvol/check.h"
#include "shadowvol/triangulation.h"
#include "volume/quad_codes.h"

namespace shadowvol::volume {
namespace {

// One vertex of a refined quad's loop.
struct CellVertex {
  std::uint32_t id = kNone;
  bool far = false;       // on the far plane
  glm::dvec2 texel{0.0};  // texel coordinates
  glm::dvec3 lv{0.0};     // light-view point (diagonal rule)
  double depth = 0.0;     // light-view depth
  CapPoint cap;
};

// The boundary edge on side k of a quad and its direction: sides 0, 1 run from the edge's P end
// (forward), sides 2, 3 towards it.
struct SideEdge {
  int i, j, axis;
  bool forward;
};
constexpr SideEdge sideEdge(int qi, int qj, int k) {
  switch (k) {
    case 0: return {qi, qj, 0, true};
    case 1: return {qi + 1, qj, 1, true};
    case 2: return {qi, qj + 1, 0, false};
    default: return {qi, qj, 1, false};
  }
}

// A local triangle of one quad, before the cap's drop rule.
struct LocalTri {
  const CellVertex* v[3];
  bool footprint;  // not a wall
};

// Triangulates one refined quad's loop into `tris` (see refined_cells.h).
class CellTriangulator {
 public:
  CellTriangulator(bool perfect, std::vector<LocalTri>& tris) : perfect_(perfect), tris_(tris) {}

  // corners[k]: the quad's corners A B C D; a[k], b[k]: side k's crossing vertices on corner k's
  // and corner k + 1's side (unused where side k has no boundary edge); `centre`: the sheet depth at
  // the quad's centre (3 or 4 boundary edges).
  // `chordNear`, `chordFar`: the chord point's two vertices (n = 2 only; null: a straight wall).
  void run(const CellVertex* corners, const CellVertex* a, const CellVertex* b, std::uint8_t sides, double centre,
           double farPlane, const CellVertex* chordNear = nullptr, const CellVertex* chordFar = nullptr) {
    int split[4], n = 0;
    for (int k = 0; k < 4; ++k)
      if (sides >> k & 1) split[n++] = k;
    SV_CHECK_GE(n, 1);
    if (n == 1) return taper(corners, a[split[0]], b[split[0]], split[0]);
    if (n == 2 && chordNear) return bentWall(corners, a, b, split[0], split[1], chordNear, chordFar);
    // The components: corners k + 1 .. k' between consecutive boundary sides k and k'.
    for (int m = 0; m < n; ++m) {
      const int s = split[m], s2 = split[(m + 1) % n];
      const CellVertex* poly[5];
      int count = 0;
      poly[count++] = &b[s];
      for (int c = (s + 1) % 4;; c = (c + 1) % 4) {
        poly[count++] = &corners[c];
        if (c == s2) break;
      }
      poly[count++] = &a[s2];
      component(poly, count);
    }
    if (n == 2) return wall(&a[split[0]], &b[split[0]], &a[split[1]], &b[split[1]]);
    // Middle polygon: one vertex per crossing, by the centre ray; but where that would fold a
    // wall piece onto itself (surface edges whose near sides disagree), the vertex on each
    // crossing's second side, which makes every piece a triangle.
    const CellVertex* mid[4];
    for (int m = 0; m < n; ++m) mid[m] = pick(a[split[m]], b[split[m]], centre, farPlane);
    for (int m = 0; m < n; ++m) {
      const int s = split[m], s2 = split[(m + 1) % n];
      const bool quadPiece = mid[m] == &a[s] && mid[(m + 1) % n] == &b[s2];
      // The piece's component side runs b[s] -> a[s2], its middle side a[s] -> b[s2]: they cross
      // when their depth order flips between the two crossings.
      if (quadPiece && (b[s].depth - a[s].depth) * (a[s2].depth - b[s2].depth) < 0.0) {
        for (int k = 0; k < n; ++k) mid[k] = &b[split[k]];
        break;
      }
    }
    for (int m = 1; m + 1 < n; ++m) add(mid[0], mid[m], mid[m + 1], true);
    // A wall piece under each side of it: the loop from mid[m] to mid[m + 1], closed by that side.
    for (int m = 0; m < n; ++m) {
      const int s = split[m], s2 = split[(m + 1) % n];
      const CellVertex* path[4];
      int count = 0;
      if (mid[m] == &a[s]) path[count++] = &a[s];
      path[count++] = &b[s];
      path[count++] = &a[s2];
      if (mid[(m + 1) % n] == &b[s2]) path[count++] = &b[s2];
      if (count == 3) add(path[0], path[1], path[2], false);
      if (count == 4) wall(path[0], path[1], path[2], path[3]);
    }
  }

 private:
  void add(const CellVertex* p, const CellVertex* q, const CellVertex* r, bool footprint) {
    tris_.push_back({{p, q, r}, footprint});
  }
  // n = 2 with a chord point M: component c0 (the corners after side s0, up to s1) and component
  // c1, each fanned from M's vertex on its side, and the wall in two vertical quads, X -> M and
  // M -> Y (X, Y the crossings of sides s0 and s1). Each component keeps one side of every wall
  // (keepWallsUnfolded), so neither quad folds.
  void bentWall(const CellVertex* corners, const CellVertex* a, const CellVertex* b, int s0, int s1,
                const CellVertex* mNear, const CellVertex* mFar) {
    const bool c0Near = b[s0].depth < a[s0].depth;
    const CellVertex* m0 = c0Near ? mNear : mFar;
    const CellVertex* m1 = c0Near ? mFar : mNear;
    auto fan = [&](const CellVertex* m, int from, int to) {  // [b[from], corners from + 1 .. to, a[to]]
      const CellVertex* path[6];
      int count = 0;
      path[count++] = &b[from];
      for (int c = (from + 1) % 4;; c = (c + 1) % 4) {
        path[count++] = &corners[c];
        if (c == to) break;
      }
      path[count++] = &a[to];
      for (int k = 0; k + 1 < count; ++k) add(m, path[k], path[k + 1], true);
    };
    fan(m0, s0, s1);
    fan(m1, s1, s0);
    wall(&a[s0], &b[s0], m0, m1);
    wall(m1, m0, &a[s1], &b[s1]);
  }
  // A vertical quad p q r s (two wall edges p-q and r-s on light rays): diagonal p-r.
  void wall(const CellVertex* p, const CellVertex* q, const CellVertex* r, const CellVertex* s) {
    add(p, q, r, false);
    add(p, r, s, false);
  }
  // A component polygon: [crossing, 1..3 corners, crossing], counter-clockwise, convex.
  void component(const CellVertex* const* p, int count) {
    if (count == 3) return add(p[0], p[1], p[2], true);
    if (count == 4) {  // as a quad A B C D of triangulation.h: fixed diagonal B-D, or the rule's choice
      if (perfect_ && flipDiagonal(p[0]->lv, p[1]->lv, p[2]->lv, p[3]->lv)) {
        add(p[0], p[1], p[2], true);
        add(p[0], p[2], p[3], true);
      } else {
        add(p[0], p[1], p[3], true);
        add(p[1], p[2], p[3], true);
      }
      return;
    }
    SV_CHECK_EQ(count, 5);  // fan from the middle corner
    add(p[2], p[3], p[4], true);
    add(p[2], p[4], p[0], true);
    add(p[2], p[0], p[1], true);
  }
  // One boundary side k (a surface edge whose jump fades inside the quad): the loop is
  // [b, c1, c2, c3, c4, a] with c1 = corner k + 1 ... c4 = corner k; the wall tapers from the
  // crossing to c3, the corner diagonally opposite c1.
  void taper(const CellVertex* corners, const CellVertex& a, const CellVertex& b, int k) {
    const CellVertex* c1 = &corners[(k + 1) % 4];
    const CellVertex* c2 = &corners[(k + 2) % 4];
    const CellVertex* c3 = &corners[(k + 3) % 4];
    const CellVertex* c4 = &corners[k];
    add(&b, c1, c2, true);
    add(&b, c2, c3, true);
    add(&b, c3, &a, false);
    add(&a, c3, c4, true);
  }
  // The middle polygon's vertex of one crossing (a, b on its two sides).
  static const CellVertex* pick(const CellVertex& a, const CellVertex& b, double centre, double farPlane) {
    const CellVertex& nearV = a.depth < b.depth ? a : b;
    const CellVertex& farV = a.depth < b.depth ? b : a;
    if (farV.far) return centre != farPlane ? &nearV : &farV;  // a far edge: does the centre ray hit?
    return std::abs(farV.depth - centre) < std::abs(nearV.depth - centre) ? &farV : &nearV;
  }

  bool perfect_;
  std::vector<LocalTri>& tris_;
};

}  // namespace

RefinedQuads findRefinedQuads(const BoundaryEdges& boundary, int width, int height) {
  const int qw = width - 1, qh = height - 1;
  std::vector<std::pair<std::uint32_t, std::uint8_t>> touched;
  touched.reserve(2 * boundary.edges.size());
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

// The loop of one refined quad: its corners A B C D, and for each boundary side k its crossing's
// vertices on corner k's side (a[k]) and corner k + 1's side (b[k]).
struct Cell {
  CellVertex corners[4], a[4], b[4];
};

// Fills the cell of quad (qi, qj) whose boundary sides are `sides`. Vertex ids come from idx[0]
// and idx[1] (the vertex numbers of texel rows qj and qj + 1) when given.
void assembleCell(int qi, int qj, std::uint8_t sides, const SheetDepths& sheet, const BoundaryEdges& boundary,
                  const Refinement& refinement, const TexelUnprojector& unproject, const std::uint32_t* const* idx,
                  std::uint32_t crossingBase, Cell& cell) {
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

// The boundary sides of a quad, in order; returns their number.
int splitSides(std::uint8_t sides, int* split) {
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (sides >> k & 1) split[n++] = k;
  return n;
}

double cross2(const glm::dvec2& u, const glm::dvec2& v) { return u.x * v.y - u.y * v.x; }

}  // namespace

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
    Cell cell;
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
        Cell cell;
        assembleCell(qi, qj, quads.sides[q], sheet, boundary, refinement, unproject, rowsIdx, crossingBase, cell);
        const bool ambiguous = std::popcount(unsigned(quads.sides[q])) >= 3;
        const double centre = ambiguous ? refinement.centreDepths[centreOf[q]] : farPlane;
        CellVertex mNear, mFar;  // the chord point's vertices, if any
        const std::size_t k = chords ? chords->ofQuad[q] : ChordPoints::kNone;
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
        tris.clear();
        CellTriangulator(perfect, tris)
            .run(cell.corners, cell.a, cell.b, quads.sides[q], centre, farPlane, k != ChordPoints::kNone ? &mNear : nullptr,
                 k != ChordPoints::kNone ? &mFar : nullptr);
        // Drop the triangles on the far plane; the far edges of kept ones across from a dropped
        // one are the cap's boundary.
        auto dropped = [&](const LocalTri& t) { return exact && t.v[0]->far && t.v[1]->far && t.v[2]->far; };
        for (const LocalTri& t : tris) {
          if (dropped(t)) continue;
          out.triangles.push_back({t.v[0]->id, t.v[1]->id, t.v[2]->id});
          if (t.footprint) out.footprint.push_back({t.v[0]->cap, t.v[1]->cap, t.v[2]->cap});
          for (int m = 0; m < 3; ++m) {
            const CellVertex* u = t.v[m];
            const CellVertex* v = t.v[(m + 1) % 3];
            if (!u->far || !v->far) continue;
            const bool acrossDropped = std::any_of(tris.begin(), tris.end(), [&](const LocalTri& o) {
              if (!dropped(o)) return false;
              for (int c = 0; c < 3; ++c)
                if (o.v[c]->id == v->id && o.v[(c + 1) % 3]->id == u->id) return true;
              return false;
            });
            if (acrossDropped) out.capEdges.push_back({u->id, v->id, u->texel, v->texel});
          }
        }
      }
    }
  });
  RefinedCells result;
  for (RowOut& row : rows) {
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
