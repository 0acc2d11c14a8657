#include "mesh_readers/polygon_triangulation.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

// Why by hand and not with CGAL (Polygon_triangulation_decomposition_2): a file's polygons may be
// self-intersecting, non-planar or repeat corners, which CGAL's preconditions refuse; ear clipping
// with a fan to fall back on takes anything, deterministically.

namespace shadowvol::mesh_readers {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The polygon's corners, read back from its fan (c0, c[k], c[k+1]).
std::vector<std::uint32_t> cornersOf(const ParsedMesh& mesh, const ParsedMesh::Polygon& p) {
  const Triangle& t0 = mesh.triangles[p.first];
  std::vector<std::uint32_t> c = {t0[0], t0[1], t0[2]};
  for (std::uint32_t k = 1; k < p.count; ++k) c.push_back(mesh.triangles[p.first + k][2]);
  return c;
}

// The corners in the plane of the polygon's Newell normal (computed from corner 0, so far from the
// origin as near), oriented so that the polygon's own winding is counter-clockwise; empty for a
// polygon without area.
std::vector<glm::dvec2> projected(const ParsedMesh& mesh, const std::vector<std::uint32_t>& c) {
  const glm::dvec3 o = mesh.positions[c[0]];
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const glm::dvec3 a = mesh.positions[c[i]] - o, b = mesh.positions[c[(i + 1) % c.size()]] - o;
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const glm::dvec3 m = glm::abs(n);
  const int drop = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  if (!(m[drop] > 0.0)) return {};
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double flip = n[drop] > 0.0 ? 1.0 : -1.0;  // (u, v, drop) is right-handed: area sign = n[drop]'s
  std::vector<glm::dvec2> q;
  q.reserve(c.size());
  for (const std::uint32_t i : c) {
    const glm::dvec3 p = mesh.positions[i] - o;
    q.emplace_back(p[u], flip * p[v]);
  }
  return q;
}

double turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool convex(const std::vector<glm::dvec2>& q) {
  const std::size_t n = q.size();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(q[(i + n - 1) % n], q[i], q[(i + 1) % n]) < 0.0) return false;
  return true;
}

// Whether p lies in the closed counter-clockwise triangle abc.
bool inTriangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

// Ear clipping of the counter-clockwise polygon q (corner indices c), n - 2 triangles into `out`;
// `work` counts the steps and stops the clipping (the rest fanned) when it runs out.
void clipEars(const std::vector<glm::dvec2>& q, const std::vector<std::uint32_t>& c, std::int64_t& work,
              std::vector<Triangle>& out) {
  std::vector<std::size_t> left(q.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;
  std::size_t j = 0;
  while (left.size() > 3 && work > 0) {
    bool clipped = false;
    for (std::size_t tries = 0; tries < left.size() && !clipped && work > 0; ++tries, j = (j + 1) % left.size()) {
      const std::size_t m = left.size();
      const std::size_t a = left[(j + m - 1) % m], b = left[j], e = left[(j + 1) % m];
      work -= std::int64_t(m);
      if (!(turn(q[a], q[b], q[e]) > 0.0)) continue;  // reflex or flat: not an ear
      bool blocked = false;
      for (const std::size_t k : left)
        if (k != a && k != b && k != e && inTriangle(q[k], q[a], q[b], q[e])) {
          blocked = true;
          break;
        }
      if (blocked) continue;
      out.push_back({c[a], c[b], c[e]});
      left.erase(left.begin() + std::ptrdiff_t(j));
      j = j % left.size();
      clipped = true;
    }
    if (!clipped) break;  // no ear: self-intersecting or degenerate
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k) out.push_back({c[left[0]], c[left[k]], c[left[k + 1]]});
}

}  // namespace

std::size_t triangulateNonConvexPolygons(ParsedMesh& mesh) {
  // At most about 64 steps a triangle plus 2^24 in all (each step a corner visited): a file of
  // ordinary non-convex polygons stays far below; a hostile one (a polygon with no ear, circling
  // twice) stops there, the rest fanned, within about a second here.
  std::int64_t work = 64 * std::int64_t(mesh.triangles.size()) + (std::int64_t(1) << 24);
  std::size_t recut = 0;
  std::vector<Triangle> cut;
  for (const ParsedMesh::Polygon& p : mesh.polygons) {
    if (work <= 0) break;
    const std::vector<std::uint32_t> c = cornersOf(mesh, p);
    const std::vector<glm::dvec2> q = projected(mesh, c);
    work -= std::int64_t(c.size());
    if (q.empty() || convex(q)) continue;
    cut.clear();
    clipEars(q, c, work, cut);
    for (std::uint32_t k = 0; k < p.count; ++k) mesh.triangles[p.first + k] = cut[k];
    ++recut;
  }
  return recut;
}

}  // namespace shadowvol::mesh_readers
