#include "shadowvol/far_cap.h"

#include <cmath>
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

// Counter-clockwise angle from direction a to direction b, in [0, 2 pi).
double ccwAngle(const glm::dvec2& a, const glm::dvec2& b) {
  double t = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
  if (t < 0.0) t += 2.0 * std::numbers::pi;
  return t;
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulateCapLoops(const std::vector<CapEdge>& edges) {
  std::vector<std::array<std::uint32_t, 3>> result;
  if (edges.empty()) return result;

  // Per vertex index: its texel and its loop neighbours (for the wedge test at shared texels).
  struct Corner {
    std::uint32_t vertex;
    glm::ivec2 texel, prevTexel, nextTexel;
  };
  std::unordered_map<std::uint32_t, std::size_t> cornerOf;
  cornerOf.reserve(edges.size() * 2);
  std::vector<Corner> corners;
  corners.reserve(edges.size());
  auto cornerFor = [&](std::uint32_t v, glm::ivec2 texel) -> Corner& {
    auto [it, inserted] = cornerOf.try_emplace(v, corners.size());
    if (inserted) corners.push_back({v, texel, texel, texel});
    SV_CHECK(corners[it->second].texel == texel);
    return corners[it->second];
  };
  for (const CapEdge& e : edges) {
    cornerFor(e.from, e.fromTexel).nextTexel = e.toTexel;
    cornerFor(e.to, e.toTexel).prevTexel = e.fromTexel;
  }

  // Texels (slots) with one or more vertex indices; each CDT vertex stores its slot. Points are
  // inserted as one range (spatially sorted by CGAL), then the constraints.
  std::vector<std::vector<std::size_t>> slots;
  std::vector<std::pair<K::Point_2, int>> points;
  std::unordered_map<std::uint64_t, int> slotOfTexel;
  slotOfTexel.reserve(corners.size());
  std::vector<int> slotOfCorner(corners.size());
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const glm::ivec2 t = corners[c].texel;
    const std::uint64_t key = (std::uint64_t(std::uint32_t(t.x)) << 32) | std::uint32_t(t.y);
    auto [it, inserted] = slotOfTexel.try_emplace(key, int(slots.size()));
    if (inserted) {
      slots.emplace_back();
      points.emplace_back(K::Point_2(t.x, t.y), it->second);
    }
    slots[std::size_t(it->second)].push_back(c);
    slotOfCorner[c] = it->second;
  }
  Cdt cdt;
  cdt.insert(points.begin(), points.end());
  std::vector<Cdt::Vertex_handle> handleOfSlot(slots.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handleOfSlot[std::size_t(v->info())] = v;
  auto handleOf = [&](std::uint32_t vertex) { return handleOfSlot[std::size_t(slotOfCorner[cornerOf.at(vertex)])]; };
  std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>> directed;
  directed.reserve(edges.size());
  for (const CapEdge& e : edges) {
    directed.emplace_back(handleOf(e.from), handleOf(e.to));
    cdt.insert_constraint(directed.back().first, directed.back().second);
  }
  markInside(cdt, directed);

  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() != 1) continue;
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const auto& slot = slots[std::size_t(f->vertex(k)->info())];
      if (slot.size() == 1) {
        tri[k] = corners[slot[0]].vertex;
        continue;
      }
      // Several vertices at this texel: pick the one whose wedge (from its outgoing edge
      // counter-clockwise to its incoming edge) contains the face's direction from the texel.
      const K::Point_2& p = f->vertex(k)->point();
      const K::Point_2& q = f->vertex((k + 1) % 3)->point();
      const K::Point_2& r = f->vertex((k + 2) % 3)->point();
      const glm::dvec2 m(0.5 * (q.x() + r.x()) - p.x(), 0.5 * (q.y() + r.y()) - p.y());
      bool found = false;
      for (std::size_t c : slot) {
        const Corner& corner = corners[c];
        const glm::dvec2 out = glm::dvec2(corner.nextTexel - corner.texel);
        const glm::dvec2 in = glm::dvec2(corner.prevTexel - corner.texel);
        if (ccwAngle(out, m) < ccwAngle(out, in)) {
          tri[k] = corner.vertex;
          found = true;
          break;
        }
      }
      SV_CHECK(found);
    }
    result.push_back(tri);
  }
  return result;
}

}  // namespace shadowvol
