// One quad's triangles between walls, marching-squares style (refined_cells.h's header comment
// says how): the triangulator of a quad whose boundary sides carry crossings, shared by the
// refined quads of the texel grid (refined_cells.h) and the sub-cells of the sub-grid
// (subgrid_cells.h), and the rule that keeps its triangles and finds the far cap's edges.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "shadowvol/check.h"
#include "shadowvol/far_cap.h"
#include "shadowvol/triangulation.h"
#include "volume/build_buffers.h"

namespace shadowvol::volume {

/// A vertex of the mirrored (unflattened) cap: the far-plane point under a texel, a boundary
/// edge's crossing or a chord point.
struct CapPoint {
  enum class Kind : std::uint8_t { Texel, Edge, Chord };
  std::uint32_t index = 0;  ///< texel index (j * W + i), boundary-edge index or chord-point index
  Kind kind = Kind::Texel;
};

// The z component of u x v (texel space).
inline double cross2(const glm::dvec2& u, const glm::dvec2& v) { return u.x * v.y - u.y * v.x; }

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
  // `cornerCount` 3: a triangular cell A B C (a point light's cube corner, cube_refinement.h),
  // by the same rules: side k from corner k to corner k + 1 (mod 3), no chord point.
  void run(const CellVertex* corners, const CellVertex* a, const CellVertex* b, std::uint8_t sides, double centre,
           double farPlane, const CellVertex* chordNear = nullptr, const CellVertex* chordFar = nullptr,
           int cornerCount = 4) {
    SV_CHECK(cornerCount == 4 || (cornerCount == 3 && !chordNear));
    m_ = cornerCount;
    int split[4], n = 0;
    for (int k = 0; k < m_; ++k)
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
      for (int c = (s + 1) % m_;; c = (c + 1) % m_) {
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
  // One boundary side k (a surface edge whose jump fades inside the cell): the loop is
  // [b, corner k + 1, ..., corner k, a]; the wall tapers from the crossing to the apex, the
  // corner before corner k (corner k + 3 of a quad, diagonally opposite corner k + 1; corner
  // k + 2 of a triangle): a fan from b over the corners up to the apex, the wall b, apex, a, and
  // the triangle a, apex, corner k.
  void taper(const CellVertex* corners, const CellVertex& a, const CellVertex& b, int k) {
    const int apex = (k + m_ - 1) % m_;
    for (int c = (k + 1) % m_; c != apex; c = (c + 1) % m_) add(&b, &corners[c], &corners[(c + 1) % m_], true);
    add(&b, &corners[apex], &a, false);
    add(&a, &corners[apex], &corners[k], true);
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
  int m_ = 4;  // corners of the cell being triangulated
};


/// Appends the kept triangles of one cell's `tris` to `triangles` (the exact cap drops those with
/// three far vertices), to `capEdges` the far edges of kept ones across from a dropped one (the
/// cap's boundary, region on the left), and to `footprint` (if given) the kept ones that are not walls.
void keepCellTriangles(const std::vector<LocalTri>& tris, bool exact, std::vector<Tri>& triangles,
                       std::vector<CapEdge>& capEdges, std::vector<std::array<CapPoint, 3>>* footprint);

}  // namespace shadowvol::volume
