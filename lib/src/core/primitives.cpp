#include "shadowvol/primitives.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <glm/geometric.hpp>

#include "shadowvol/check.h"

namespace shadowvol {
namespace {

using Tri = std::array<std::uint32_t, 3>;

std::uint32_t addVertex(TriangleMesh& m, double x, double y, double z) {
  m.positions.emplace_back(float(x), float(y), float(z));
  return static_cast<std::uint32_t>(m.positions.size() - 1);
}

// Grid of (segments) x (rings + 1) points on a surface of revolution around Y, poles shared.
// profile(k) gives (radius, y) for ring k = 0..rings; radius 0 at an end makes a shared pole.
template <typename Profile>
TriangleMesh revolve(int segments, int rings, Profile profile) {
  TriangleMesh m;
  std::vector<std::vector<std::uint32_t>> ring(rings + 1);
  for (int k = 0; k <= rings; ++k) {
    const auto [r, y] = profile(k);
    if (r == 0.0) {
      ring[k].assign(segments, addVertex(m, 0.0, y, 0.0));
      continue;
    }
    for (int s = 0; s < segments; ++s) {
      const double a = 2.0 * std::numbers::pi * double(s) / double(segments);
      ring[k].push_back(addVertex(m, r * std::cos(a), y, -r * std::sin(a)));
    }
  }
  // Ring k is above ring k + 1 (profile runs top to bottom). Counter-clockwise from outside.
  for (int k = 0; k < rings; ++k) {
    for (int s = 0; s < segments; ++s) {
      const int s1 = (s + 1) % segments;
      const std::uint32_t a = ring[k][s], b = ring[k + 1][s], c = ring[k + 1][s1], d = ring[k][s1];
      if (a != d) m.triangles.push_back(Tri{a, b, d});
      if (b != c) m.triangles.push_back(Tri{b, c, d});
    }
  }
  return m;
}

void addFan(TriangleMesh& m, const std::vector<std::uint32_t>& rim, double y, bool facingUp) {
  const std::uint32_t centre = addVertex(m, 0.0, y, 0.0);
  const std::size_t n = rim.size();
  for (std::size_t s = 0; s < n; ++s) {
    const std::uint32_t a = rim[s], b = rim[(s + 1) % n];
    // rim runs counter-clockwise seen from +Y (angle grows, z = -r sin a).
    if (facingUp) m.triangles.push_back(Tri{centre, a, b});
    else m.triangles.push_back(Tri{centre, b, a});
  }
}

}  // namespace

TriangleMesh makePlane(double sizeX, double sizeZ, int subdivisions) {
  SV_CHECK_GE(subdivisions, 1);
  TriangleMesh m;
  const int n = subdivisions;
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n; ++i)
      addVertex(m, (double(i) / n - 0.5) * sizeX, 0.0, (double(k) / n - 0.5) * sizeZ);
  auto v = [n](int i, int k) { return static_cast<std::uint32_t>(k * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i) {
      // Seen from +Y, x right and z down the screen: (i,k+1) (i+1,k+1) (i+1,k) is counter-clockwise.
      m.triangles.push_back(Tri{v(i, k), v(i, k + 1), v(i + 1, k + 1)});
      m.triangles.push_back(Tri{v(i, k), v(i + 1, k + 1), v(i + 1, k)});
    }
  return m;
}

TriangleMesh makeUvSphere(double radius, int segments, int rings) {
  SV_CHECK_GE(segments, 3);
  SV_CHECK_GE(rings, 2);
  return revolve(segments, rings, [&](int k) {
    const double phi = std::numbers::pi * double(k) / double(rings);
    const double r = (k == 0 || k == rings) ? 0.0 : radius * std::sin(phi);
    return std::pair{r, radius * std::cos(phi)};
  });
}

TriangleMesh makeIcoSphere(double radius, int detail) {
  SV_CHECK_GE(detail, 0);
  SV_CHECK_LE(detail, 8);
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<glm::dvec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& q : p) q = glm::normalize(q);
  std::vector<Tri> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                        {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < detail; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(glm::normalize(p[a] + p[b]));
      const auto id = static_cast<std::uint32_t>(p.size() - 1);
      mid.emplace(key, id);
      return id;
    };
    std::vector<Tri> next;
    next.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const auto a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f = std::move(next);
  }
  TriangleMesh m;
  for (const auto& q : p) addVertex(m, q.x * radius, q.y * radius, q.z * radius);
  m.triangles = std::move(f);
  return m;
}

TriangleMesh makeBox(double sx, double sy, double sz) {
  TriangleMesh m;
  const double x = sx / 2, y = sy / 2, z = sz / 2;
  for (int k = 0; k < 8; ++k) addVertex(m, (k & 1) ? x : -x, (k & 2) ? y : -y, (k & 4) ? z : -z);
  // Faces as counter-clockwise quads seen from outside.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.triangles.push_back(Tri{std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
    m.triangles.push_back(Tri{std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  }
  return m;
}

TriangleMesh makeCylinder(double radius, double height, int segments) {
  SV_CHECK_GE(segments, 3);
  TriangleMesh m = revolve(segments, 1, [&](int k) { return std::pair{radius, k == 0 ? height / 2 : -height / 2}; });
  std::vector<std::uint32_t> top(segments), bottom(segments);
  for (int s = 0; s < segments; ++s) {
    top[s] = std::uint32_t(s);
    bottom[s] = std::uint32_t(segments + s);
  }
  addFan(m, top, height / 2, true);
  addFan(m, bottom, -height / 2, false);
  return m;
}

TriangleMesh makeHemisphere(double radius, int segments, int rings) {
  SV_CHECK_GE(segments, 3);
  SV_CHECK_GE(rings, 1);
  TriangleMesh m = revolve(segments, rings, [&](int k) {
    const double phi = 0.5 * std::numbers::pi * double(k) / double(rings);
    return std::pair{k == 0 ? 0.0 : radius * std::sin(phi), k == rings ? 0.0 : radius * std::cos(phi)};
  });
  std::vector<std::uint32_t> rim(segments);
  for (int s = 0; s < segments; ++s) rim[s] = std::uint32_t(1 + (rings - 1) * segments + s);
  addFan(m, rim, 0.0, false);
  return m;
}

TriangleMesh makeTree(double trunkRadius, double trunkHeight, double crownRadius, int detail) {
  TriangleMesh trunk = makeCylinder(trunkRadius, trunkHeight, 16);
  for (auto& p : trunk.positions) p.y += float(trunkHeight / 2);
  TriangleMesh crown = makeIcoSphere(crownRadius, detail);
  for (auto& p : crown.positions) p.y += float(trunkHeight + 0.6 * crownRadius);
  trunk.append(crown);
  return trunk;
}

}  // namespace shadowvol
