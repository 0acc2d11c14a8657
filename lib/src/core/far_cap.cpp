#include "shadowvol/far_cap.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "shadowvol/check.h"

namespace shadowvol {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;  // index into `slots`
using Fbb = CGAL::Triangulation_face_base_with_info_2<int, K>;   // 1 = inside the region
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

// Inside faces: every face on the left of a boundary edge, and every face reachable from one
// without crossing a constrained edge. (Orientation, not nesting parity, so that a cut traversed
// in both directions has the region on both sides.)
void markInside(Cdt& cdt, const std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>>& directed) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 0;
  std::vector<Cdt::Face_handle> stack;
  for (const auto& [from, to] : directed) {
    Cdt::Face_handle f;
    int i = 0;
    const bool isEdge = cdt.is_edge(from, to, f, i);
    SV_CHECK(isEdge);
    // Face f has the edge opposite vertex i, running ccw(i) -> cw(i) counter-clockwise in f.
    if (f->vertex(cdt.ccw(i)) != from) f = f->neighbor(i);
    SV_CHECK(!cdt.is_infinite(f));
    stack.push_back(f);
  }
  while (!stack.empty()) {
    Cdt::Face_handle f = stack.back();
    stack.pop_back();
    if (f->info() == 1) continue;
    f->info() = 1;
    for (int k = 0; k < 3; ++k)
      if (!cdt.is_constrained(Cdt::Edge(f, k))) {
        SV_CHECK(!cdt.is_infinite(f->neighbor(k)));  // the loops are closed
        stack.push_back(f->neighbor(k));
      }
  }
}

// A point of the plane as a hash key (its coordinates' bits; -0 and +0 are one point).
struct PointKey {
  std::uint64_t x, y;
  explicit PointKey(const glm::dvec2& p) : x(bits(p.x)), y(bits(p.y)) {}
  static std::uint64_t bits(double v) {
    v += 0.0;  // -0 -> +0
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  }
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y; }
};
struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const { return std::size_t(k.x * 0x9E3779B97F4A7C15ull ^ k.y); }
};

// b lies on the segment from a to c, strictly between them (exact predicates).
bool strictlyBetween(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const K::Point_2 pa(a.x, a.y), pb(b.x, b.y), pc(c.x, c.y);
  return CGAL::collinear(pa, pb, pc) && CGAL::collinear_are_strictly_ordered_along_line(pa, pb, pc);
}

// Counter-clockwise angle from direction a to direction b, in [0, 2 pi).
double ccwAngle(const glm::dvec2& a, const glm::dvec2& b) {
  double t = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
  if (t < 0.0) t += 2.0 * std::numbers::pi;
  return t;
}

// The flattened cap of one set of closed loops (triangulateCapLoops): corners, their points, the
// collinear runs left out of the CDT, the CDT of the rest, and each inside face split again.
class CapLoops {
 public:
  using Triangle = std::array<std::uint32_t, 3>;

  explicit CapLoops(const std::vector<CapEdge>& edges) {
    collectCorners(edges);
    groupByPoint();
    findAnchors();
  }

  std::vector<Triangle> triangulate() {
    triangulateAnchors();
    for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
      if (f->info() == 1) emitFace(f);
    return std::move(result_);
  }

 private:
  // Per vertex index: its texel and its loop neighbours (for the wedge test at shared texels).
  struct Corner {
    std::uint32_t vertex;
    glm::dvec2 texel, prevTexel, nextTexel;
    std::size_t next = 0;                      // corner at the end of the outgoing edge
    bool anchor = true;                        // kept in the CDT (findAnchors)
    std::size_t anchorNext = 0;                // anchors: the next anchor along the loop
    std::size_t chainBegin = 0, chainEnd = 0;  // anchors: removed corners up to it, in chain_
  };
  using Chain = std::pair<const std::size_t*, const std::size_t*>;  // [begin, end) in chain_

  void collectCorners(const std::vector<CapEdge>& edges) {
    std::unordered_map<std::uint32_t, std::size_t> cornerOf;
    cornerOf.reserve(edges.size() * 2);
    corners_.reserve(edges.size());
    auto cornerFor = [&](std::uint32_t v, glm::dvec2 texel) -> std::size_t {
      auto [it, inserted] = cornerOf.try_emplace(v, corners_.size());
      if (inserted) corners_.push_back({v, texel, texel, texel});
      SV_CHECK(corners_[it->second].texel == texel);
      return it->second;
    };
    for (const CapEdge& e : edges) {
      const std::size_t from = cornerFor(e.from, e.fromTexel), to = cornerFor(e.to, e.toTexel);
      corners_[from].nextTexel = e.toTexel;
      corners_[from].next = to;
      corners_[to].prevTexel = e.fromTexel;
    }
  }

  // Points (slots) with one or more vertex indices.
  void groupByPoint() {
    std::unordered_map<PointKey, int, PointKeyHash> slotOfTexel;
    slotOfTexel.reserve(corners_.size());
    slotOfCorner_.resize(corners_.size());
    for (std::size_t c = 0; c < corners_.size(); ++c) {
      auto [it, inserted] = slotOfTexel.try_emplace(PointKey(corners_[c].texel), int(slots_.size()));
      if (inserted) slots_.emplace_back();
      slots_[std::size_t(it->second)].push_back(c);
      slotOfCorner_[c] = it->second;
    }
  }

  // Collinear runs. A corner alone at its point that lies strictly between its loop neighbours on
  // their segment (exact predicates; for grid edges: the same step in and out, a straight run
  // axis-parallel or diagonal) leaves the CDT: the loops are triangulated through their remaining
  // corners (anchors) only, and each face is then split again through the removed corners on its
  // edges (emitFace). Grid-aligned runs are the most degenerate input a Delaunay triangulation can
  // get (every four lattice points of a square are cocircular), so this keeps the cap's cost to
  // its corners, and the result is the same kind of triangulation: every boundary vertex and edge
  // kept, no Steiner point, no zero-area triangle.
  void findAnchors() {
    for (std::size_t c = 0; c < corners_.size(); ++c) {
      const Corner& k = corners_[c];
      corners_[c].anchor =
          slots_[std::size_t(slotOfCorner_[c])].size() > 1 || !strictlyBetween(k.prevTexel, k.texel, k.nextTexel);
    }
    chain_.reserve(corners_.size());
    for (std::size_t c = 0; c < corners_.size(); ++c) {
      if (!corners_[c].anchor) continue;
      corners_[c].chainBegin = chain_.size();
      std::size_t n = corners_[c].next, steps = 0;
      while (!corners_[n].anchor) {
        chain_.push_back(n);
        n = corners_[n].next;
        SV_CHECK_LE(++steps, corners_.size());  // a loop always turns somewhere
      }
      corners_[c].chainEnd = chain_.size();
      corners_[c].anchorNext = n;
    }
  }

  // CDT of the anchors' texels; each CDT vertex stores its slot. Points are inserted as one range
  // (spatially sorted by CGAL), then the constraints; the faces inside the loops marked.
  void triangulateAnchors() {
    std::vector<std::pair<K::Point_2, int>> points;
    for (std::size_t s = 0; s < slots_.size(); ++s)
      if (corners_[slots_[s][0]].anchor) {
        const glm::dvec2 t = corners_[slots_[s][0]].texel;
        points.emplace_back(K::Point_2(t.x, t.y), int(s));
      }
    cdt_.insert(points.begin(), points.end());
    std::vector<Cdt::Vertex_handle> handleOfSlot(slots_.size());
    for (auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
      handleOfSlot[std::size_t(v->info())] = v;
    auto handleOf = [&](std::size_t corner) { return handleOfSlot[std::size_t(slotOfCorner_[corner])]; };
    std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>> directed;
    directed.reserve(points.size());
    for (std::size_t c = 0; c < corners_.size(); ++c) {
      if (!corners_[c].anchor) continue;
      directed.emplace_back(handleOf(c), handleOf(corners_[c].anchorNext));
      cdt_.insert_constraint(directed.back().first, directed.back().second);
    }
    markInside(cdt_, directed);
  }

  // The corner of face f at its vertex k: the slot's only one, or of several vertices at this
  // texel the one whose wedge (from its outgoing edge counter-clockwise to its incoming edge)
  // contains the face's direction from the texel.
  std::size_t faceCorner(Cdt::Face_handle f, int k) const {
    const auto& slot = slots_[std::size_t(f->vertex(k)->info())];
    if (slot.size() == 1) return slot[0];
    const K::Point_2& p = f->vertex(k)->point();
    const K::Point_2& q = f->vertex((k + 1) % 3)->point();
    const K::Point_2& r = f->vertex((k + 2) % 3)->point();
    const glm::dvec2 m(0.5 * (q.x() + r.x()) - p.x(), 0.5 * (q.y() + r.y()) - p.y());
    for (std::size_t c : slot) {
      const Corner& corner = corners_[c];
      if (ccwAngle(corner.nextTexel - corner.texel, m) <
          ccwAngle(corner.nextTexel - corner.texel, corner.prevTexel - corner.texel))
        return c;
    }
    SV_CHECK(false);  // the wedges at a point cover every direction
    return slot[0];
  }

  // An inside face's triangles: itself, or, where its sides carry removed corners (an edge that
  // is a shortened constraint, from an anchor to its next anchor with the face on its left,
  // carries that anchor's chain), split through them (splitFace).
  void emitFace(Cdt::Face_handle f) {
    const std::size_t fc[3] = {faceCorner(f, 0), faceCorner(f, 1), faceCorner(f, 2)};
    Chain side[3];
    bool chained = false;
    for (int k = 0; k < 3; ++k) {
      const Corner& c = corners_[fc[k]];
      const bool carries = c.anchorNext == fc[(k + 1) % 3] && c.chainEnd > c.chainBegin;
      side[k] = carries ? Chain{chain_.data() + c.chainBegin, chain_.data() + c.chainEnd} : Chain{nullptr, nullptr};
      chained = chained || carries;
    }
    if (!chained) return emit(fc[0], fc[1], fc[2]);
    splitFace(fc[0], fc[1], fc[2], side[0], side[1], side[2]);
  }

  // Triangulates the counter-clockwise face X Y Z whose sides carry removed corners (chains, in
  // side order) without zero-area triangles: fan from the opposite corner over a side with a
  // chain; the fan's first and last triangles keep the other two sides, handled the same way.
  // Every triangle has two vertices on one side and the third off that side's line: positive area.
  void splitFace(std::size_t x, std::size_t y, std::size_t z, Chain xy, Chain yz, Chain zx) {
    for (int turn = 0; turn < 3 && xy.first == xy.second; ++turn) {  // put a chain on side X Y
      std::swap(x, y), std::swap(y, z);
      std::swap(xy, yz), std::swap(yz, zx);
    }
    if (xy.first == xy.second) return emit(x, y, z);
    const Chain none{nullptr, nullptr};
    const std::size_t first = *xy.first, last = *(xy.second - 1);
    splitFace(x, first, z, none, none, zx);
    for (const std::size_t* p = xy.first; p + 1 < xy.second; ++p) emit(p[0], p[1], z);
    splitFace(last, y, z, none, yz, none);
  }

  void emit(std::size_t a, std::size_t b, std::size_t c) {
    result_.push_back({corners_[a].vertex, corners_[b].vertex, corners_[c].vertex});
  }

  std::vector<Corner> corners_;
  std::vector<std::vector<std::size_t>> slots_;  // the corners at each point
  std::vector<int> slotOfCorner_;
  std::vector<std::size_t> chain_;  // removed corners, grouped per anchor
  Cdt cdt_;
  std::vector<Triangle> result_;
};

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulateCapLoops(const std::vector<CapEdge>& edges) {
  if (edges.empty()) return {};
  return CapLoops(edges).triangulate();
}

}  // namespace shadowvol
